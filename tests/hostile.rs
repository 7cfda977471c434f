//! Regression tests for what a hostile caller found (each failed before its fix): validation
//! that NaN slipped through, non-finite or corrupt CYCLE600 states accepted, additive chains
//! drifting away from orthonormal, huge angles giving another rotation, -0 from
//! `frame_inverse`, the head table read whole on every call, thin point sets given a wrong
//! plane by `cncrot_probe_plane`.
//!
//! Expected values come from an oracle independent of the library (double-double arithmetic
//! for `MᵀM − I`, Rust's exact `%` for the reduction of angles) or from identities.

mod common;

use cncrot::ffi::*;
use common::Rng;
use std::ptr::{null, null_mut};

const NOT_A_ROTATION: i32 = cncrot_status::NotARotation as i32;
const BAD_STATE: i32 = cncrot_status::BadState as i32;
const OUT_OF_RANGE: i32 = cncrot_status::OutOfRange as i32;
const UNKNOWN_HEAD: i32 = cncrot_status::UnknownHead as i32;
const NOT_FINITE: i32 = cncrot_status::NotFinite as i32;
const BAD_ARGUMENT: i32 = cncrot_status::BadArgument as i32;

/// The tests' shared generator, with the two draws this file needs.
trait Draws {
    fn next(&mut self) -> u64;
    fn sign(&mut self) -> f64;
}

impl Draws for Rng {
    fn next(&mut self) -> u64 {
        self.next_u64()
    }
    fn sign(&mut self) -> f64 {
        if self.next_u64() & 1 == 0 {
            1.0
        } else {
            -1.0
        }
    }
}

fn matrix(intrinsic: i32, seq: i32, a: [f64; 3]) -> [f64; 9] {
    let mut m = [0.0; 9];
    assert_eq!(
        unsafe { cncrot_matrix_from_angles(intrinsic, seq, a.as_ptr(), m.as_mut_ptr()) },
        0
    );
    m
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

// ---- the oracle: max |MᵀM − I| in double-double arithmetic ----------------------------

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn dd_add(x: (f64, f64), y: f64) -> (f64, f64) {
    let (s, e) = two_sum(x.0, y);
    let (hi, lo) = two_sum(s, e + x.1);
    (hi, lo)
}

/// `max |MᵀM − I|` to about 1e-30 relative, for elements of magnitude at most 1.5 (larger
/// ones make a column norm exceed 1.5 and the matrix is no rotation: `None`).
fn oracle_error(m: &[f64; 9]) -> Option<f64> {
    if m.iter().any(|x| x.abs() > 1.5 || x.is_nan()) {
        return None;
    }
    let mut worst: f64 = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            let mut acc = (if i == j { -1.0 } else { 0.0 }, 0.0);
            for k in 0..3 {
                let (a, b) = (m[3 * k + i], m[3 * k + j]);
                let p = a * b;
                let e = a.mul_add(b, -p); // exact error of the product
                acc = dd_add(acc, p);
                acc = dd_add(acc, e);
            }
            worst = worst.max((acc.0 + acc.1).abs());
        }
    }
    Some(worst)
}

fn det(m: &[f64; 9]) -> f64 {
    m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
        + m[2] * (m[3] * m[7] - m[4] * m[6])
}

/// What the oracle says of `m`: a rotation within the tolerance (with a margin either side
/// for the rounding of the library's own check), clearly not one, or at the boundary.
#[derive(PartialEq, Debug)]
enum Verdict {
    Rotation,
    NotARotation,
    Boundary,
}

fn verdict(m: &[f64; 9]) -> Verdict {
    match oracle_error(m) {
        None => Verdict::NotARotation,
        Some(e) if e > CNCROT_ROTATION_TOLERANCE + 1e-15 => Verdict::NotARotation,
        // Orthonormal within 1e-3 means |det| is within 1e-2 of 1: its sign is certain.
        Some(_) if det(m) < 0.0 => Verdict::NotARotation,
        Some(e) if e < CNCROT_ROTATION_TOLERANCE - 1e-15 => Verdict::Rotation,
        Some(_) => Verdict::Boundary,
    }
}

/// Matrices a hostile caller makes: rotations scaled by any power of two or ten, random
/// elements of any magnitude, rotations perturbed up to and past the tolerance, with one
/// element huge, tiny or subnormal, columns of mixed scale, reflections.
fn hostile_matrix(rng: &mut Rng) -> [f64; 9] {
    let r = matrix(
        1,
        57,
        [
            rng.range(-180.0, 180.0),
            rng.range(-180.0, 180.0),
            rng.range(-180.0, 180.0),
        ],
    );
    match rng.next() % 8 {
        0 => {
            let s = 2f64.powi((rng.next() % 2098) as i32 - 1074);
            r.map(|x| x * s)
        }
        1 => {
            let s = 10f64.powf(rng.range(-320.0, 308.0));
            r.map(|x| x * s)
        }
        2 => core::array::from_fn(|_| rng.sign() * 10f64.powf(rng.range(-330.0, 308.2))),
        3 => {
            let d = 10f64.powf(rng.range(-6.0, -2.0));
            let mut m = r;
            for x in &mut m {
                *x += rng.range(-d, d);
            }
            m
        }
        4 => {
            // One column scaled near the tolerance: |MᵀM − I| = |(1 + t)² − 1| on the diagonal.
            let t = rng.range(-1.5e-3, 1.5e-3) / 2.0;
            let c = (rng.next() % 3) as usize;
            let mut m = r;
            for k in 0..3 {
                m[3 * k + c] *= 1.0 + t;
            }
            m
        }
        5 => {
            let mut m = r;
            let v = [1e300, 1e155, 1e-300, 4.9e-324, f64::MAX, 1.0 + 1e-3, 2.0];
            m[(rng.next() % 9) as usize] = rng.sign() * v[(rng.next() % v.len() as u64) as usize];
            m
        }
        6 => {
            // Two columns of a rotation, the third of another scale.
            let s = 10f64.powf(rng.range(-200.0, 200.0));
            let c = (rng.next() % 3) as usize;
            let mut m = r;
            for k in 0..3 {
                m[3 * k + c] *= s;
            }
            m
        }
        _ => {
            let mut m = r;
            let c = (rng.next() % 3) as usize;
            for k in 0..3 {
                m[3 * k + c] = -m[3 * k + c];
            }
            m
        }
    }
}

#[test]
fn check_rotation_accepts_no_non_rotation_against_a_double_double_oracle() {
    let mut rng = Rng::new(0x5DEE_CE66_D1CE_4E5B);
    let (mut accepted, mut refused, mut boundary) = (0, 0, 0);
    for _ in 0..200_000 {
        let m = hostile_matrix(&mut rng);
        let s = unsafe { cncrot_check_rotation(m.as_ptr()) };
        match verdict(&m) {
            Verdict::Rotation => {
                assert_eq!(s, 0, "a rotation refused: {m:?}");
                accepted += 1;
            }
            Verdict::NotARotation => {
                assert_eq!(s, NOT_A_ROTATION, "{m:?}");
                refused += 1;
            }
            Verdict::Boundary => boundary += 1,
        }
    }
    // The generator reaches both sides (a test that cannot fail is a defect).
    assert!(
        accepted > 10_000 && refused > 10_000,
        "{accepted} {refused} {boundary}"
    );
}

/// The issue's matrix: orthogonal columns of length 1.4e155, whose `MᵀM` overflows to
/// `∞ − ∞ = NaN`. Every function that takes a rotation refuses it as not a rotation.
#[test]
fn a_matrix_whose_gram_matrix_overflows_is_refused_everywhere() {
    let m = [1e155, -1e155, 0.0, 1e155, 1e155, 0.0, 0.0, 0.0, 1.0];
    let f = [
        1e155, -1e155, 0.0, 0.0, 1e155, 1e155, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    let idf = [
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    let v = [1.0, 2.0, 3.0];
    let sentinel = -12345.0;
    let mut out3 = [sentinel; 3];
    let mut out9 = [sentinel; 9];
    let mut out16 = [sentinel; 16];
    let nar = NOT_A_ROTATION;
    unsafe {
        assert_eq!(cncrot_check_rotation(m.as_ptr()), nar);
        assert_eq!(
            cncrot_angles_from_matrix(1, 57, m.as_ptr(), out3.as_mut_ptr()),
            nar
        );
        assert_eq!(
            cncrot_closest_angles(1, 57, m.as_ptr(), v.as_ptr(), out3.as_mut_ptr()),
            nar
        );
        assert_eq!(
            cncrot_rotate_vector(m.as_ptr(), v.as_ptr(), out3.as_mut_ptr()),
            nar
        );
        assert_eq!(
            cncrot_rotate_vector_inverse(m.as_ptr(), v.as_ptr(), out3.as_mut_ptr()),
            nar
        );
        assert_eq!(
            cncrot_add_rotation(1, 57, v.as_ptr(), m.as_ptr(), out9.as_mut_ptr()),
            nar
        );
        assert_eq!(cncrot_frame_inverse(f.as_ptr(), out16.as_mut_ptr()), nar);
        assert_eq!(
            cncrot_frame_compose(f.as_ptr(), idf.as_ptr(), out16.as_mut_ptr()),
            nar
        );
        assert_eq!(
            cncrot_frame_compose(idf.as_ptr(), f.as_ptr(), out16.as_mut_ptr()),
            nar
        );
        assert_eq!(
            cncrot_frame_transform_point(f.as_ptr(), v.as_ptr(), out3.as_mut_ptr()),
            nar
        );
    }
    assert!(out3
        .iter()
        .chain(&out9)
        .chain(&out16)
        .all(|&x| x == sentinel));
}

// ---- CYCLE600 states --------------------------------------------------------------------

/// One CYCLE600 call with the parameters a test varies; positions (1, 2, 3) before the
/// rotation, none after, output intrinsic Z, X', Y'' (39), `_ROT_INV` = `_RETR_Z` = 0.
fn cycle(
    gud: *mut cncrot_cycle600_gud,
    heads: *const cncrot_head_table,
    inexin: i32,
    name: &std::ffi::CStr,
    bin_in: i32,
    ang: [f64; 3],
    rot_ad: i32,
) -> i32 {
    unsafe {
        cncrot_cycle600(
            gud,
            heads,
            inexin,
            name.as_ptr(),
            1,
            bin_in,
            1.0,
            2.0,
            3.0,
            ang[0],
            ang[1],
            ang[2],
            0.0,
            0.0,
            0.0,
            1,
            39,
            rot_ad,
            0,
            0,
        )
    }
}

fn call(gud: *mut cncrot_cycle600_gud, heads: *const cncrot_head_table, rot_ad: i32) -> i32 {
    cycle(gud, heads, 0, c"UFK600", 57, [30.0, 45.0, 60.0], rot_ad)
}

fn bytes_of(g: &cncrot_cycle600_gud) -> Vec<u8> {
    let p = (g as *const cncrot_cycle600_gud).cast::<u8>();
    unsafe { std::slice::from_raw_parts(p, size_of::<cncrot_cycle600_gud>()) }.to_vec()
}

fn from_bytes(b: &[u8]) -> cncrot_cycle600_gud {
    assert_eq!(b.len(), size_of::<cncrot_cycle600_gud>());
    unsafe { std::ptr::read_unaligned(b.as_ptr().cast()) }
}

/// Re-seals a state as the library would: format and CRC-32 over the 212 bytes before the
/// checksum. The CRC here is written out bit by bit, independently of the library's table.
fn sealed(mut g: cncrot_cycle600_gud) -> cncrot_cycle600_gud {
    g.format = CNCROT_CYCLE600_GUD_FORMAT;
    let bytes = bytes_of(&g);
    let mut c = !0u32;
    for &b in &bytes[..212] {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 != 0 {
                (c >> 1) ^ 0xEDB8_8320
            } else {
                c >> 1
            };
        }
    }
    g.checksum = !c;
    g
}

fn valid_state() -> cncrot_cycle600_gud {
    let mut g: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
    assert_eq!(call(&mut g, null(), 0), 0);
    assert_eq!(call(&mut g, null(), 1), 0);
    g
}

/// The program state's documented layout (216 bytes; ABI 0.2).
#[test]
fn the_program_states_documented_layout() {
    use std::mem::offset_of;
    assert_eq!(size_of::<cncrot_program>(), 216);
    let offsets = [
        offset_of!(cncrot_program, rotation),
        offset_of!(cncrot_program, origin),
        offset_of!(cncrot_program, angles),
        offset_of!(cncrot_program, shift),
        offset_of!(cncrot_program, active),
        offset_of!(cncrot_program, dialect),
        offset_of!(cncrot_program, options),
        offset_of!(cncrot_program, choice),
        offset_of!(cncrot_program, reference_axis),
        offset_of!(cncrot_program, positioning),
        offset_of!(cncrot_program, direct_given),
        offset_of!(cncrot_program, retract),
        offset_of!(cncrot_program, retract_mm),
        offset_of!(cncrot_program, feed_mm_min),
        offset_of!(cncrot_program, feed),
        offset_of!(cncrot_program, plane),
        offset_of!(cncrot_program, table_rot),
        offset_of!(cncrot_program, relative),
        offset_of!(cncrot_program, spare),
        offset_of!(cncrot_program, reserved),
    ];
    assert_eq!(
        offsets,
        [
            0, 72, 96, 120, 144, 148, 152, 156, 160, 164, 168, 172, 176, 184, 192, 196, 200, 204,
            208, 212
        ]
    );
}

#[test]
fn the_documented_layout_and_checksum() {
    let g = valid_state();
    assert_eq!(size_of::<cncrot_cycle600_gud>(), 216);
    assert_eq!(cncrot_cycle600_gud_size(), 216);
    assert_eq!(std::mem::offset_of!(cncrot_cycle600_gud, frame), 64);
    assert_eq!(std::mem::offset_of!(cncrot_cycle600_gud, format), 208);
    assert_eq!(std::mem::offset_of!(cncrot_cycle600_gud, checksum), 212);
    // What the library wrote is what an independent CRC-32 gives.
    assert_eq!(bytes_of(&sealed(g)), bytes_of(&g));
    assert_eq!(g.active, 1);
}

#[test]
fn every_single_bit_flip_of_a_state_is_refused_and_leaves_it_untouched() {
    let zero: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
    for base in [valid_state(), zero] {
        let bytes = bytes_of(&base);
        for bit in 0..8 * bytes.len() {
            let mut b = bytes.clone();
            b[bit / 8] ^= 1 << (bit % 8);
            let mut g = from_bytes(&b);
            assert_eq!(call(&mut g, null(), 1), BAD_STATE, "bit {bit}");
            assert_eq!(bytes_of(&g), b, "bit {bit}: state changed");
        }
    }
}

#[test]
fn random_states_are_refused() {
    let mut rng = Rng::new(0xC0FF_EE00_1234_5678);
    for k in 0..100_000 {
        let b: Vec<u8> = (0..216).map(|_| rng.next() as u8).collect();
        let mut g = from_bytes(&b);
        if k % 2 == 0 {
            // With the right format and checksum but random fields: only a well-formed state
            // may pass, and a random one is not.
            g = sealed(g);
        }
        let before = bytes_of(&g);
        assert_eq!(call(&mut g, null(), 1), BAD_STATE);
        assert_eq!(bytes_of(&g), before);
    }
}

/// A correctly sealed state whose frame has the overflowing shape: refused, never turned
/// into NaN angles stored with status 0.
#[test]
fn a_sealed_state_with_an_overflowing_frame_is_refused() {
    let mut g = valid_state();
    g.frame[..3].copy_from_slice(&[1e155, -1e155, 0.0]);
    g.frame[4..7].copy_from_slice(&[1e155, 1e155, 0.0]);
    let mut g = sealed(g);
    let before = bytes_of(&g);
    assert_eq!(call(&mut g, null(), 1), BAD_STATE);
    assert_eq!(bytes_of(&g), before);
}

#[test]
fn an_inactive_flag_does_not_hide_a_stored_rotation() {
    let mut g = valid_state();
    g.active = 0;
    let mut g = sealed(g);
    assert_eq!(call(&mut g, null(), 1), BAD_STATE);
}

// ---- chains -----------------------------------------------------------------------------

const CHAIN: usize = 1_000_000;

#[test]
fn a_million_additive_rotations_stay_orthonormal() {
    let mut rng = Rng::new(0x1234_5678_9ABC_DEF1);
    let mut m = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let mut worst: f64 = 0.0;
    for k in 0..CHAIN {
        let a = [
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
        ];
        let s = unsafe {
            cncrot_add_rotation((k % 2) as i32, 57, a.as_ptr(), m.as_ptr(), m.as_mut_ptr())
        };
        assert_eq!(s, 0);
        if k % 1000 == 999 {
            worst = worst.max(oracle_error(&m).unwrap());
        }
    }
    assert!(worst <= 1e-15, "{worst:e}");
}

#[test]
fn a_million_additive_cycle600_calls_stay_orthonormal() {
    let mut rng = Rng::new(0x0F0F_1234_5678_9ABC);
    let mut g: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
    let mut worst: f64 = 0.0;
    for k in 0..CHAIN {
        let a = [
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
        ];
        let s = cycle(&mut g, null(), (k % 2) as i32, c"H", 57, a, 1);
        assert!(s >= 0);
        if k % 1000 == 999 {
            let r: [f64; 9] = core::array::from_fn(|i| g.frame[4 * (i / 3) + i % 3]);
            worst = worst.max(oracle_error(&r).unwrap());
        }
    }
    assert!(worst <= 1e-15, "{worst:e}");
}

/// Composing and inverting frames also re-orthonormalises: a chain of composed frames does
/// not drift either.
#[test]
fn composed_frames_stay_orthonormal() {
    let mut rng = Rng::new(0xABCD_EF01_2345_6789);
    let mut f = [
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    for _ in 0..100_000 {
        let a = [rng.range(-5.0, 5.0), rng.range(-5.0, 5.0), 0.0];
        let mut step = [0.0; 16];
        unsafe {
            assert_eq!(
                cncrot_frame_from_angles(
                    1,
                    57,
                    a.as_ptr(),
                    a.as_ptr(),
                    a.as_ptr(),
                    step.as_mut_ptr()
                ),
                0
            );
            assert_eq!(
                cncrot_frame_compose(f.as_ptr(), step.as_ptr(), f.as_mut_ptr()),
                0
            );
        }
    }
    let r: [f64; 9] = core::array::from_fn(|i| f[4 * (i / 3) + i % 3]);
    assert!(oracle_error(&r).unwrap() <= 1e-15);
}

/// A matrix accepted at the edge of the tolerance comes out of `add_rotation` as an
/// orthonormal one (the nearest rotation), not with its distortion carried along.
#[test]
#[allow(clippy::approx_constant)] // the paper's printed digits
fn additive_rotation_of_a_four_decimal_matrix_is_orthonormal() {
    // The paper's 4-decimal matrix (extrinsic X, Y, Z = 30, 45, 60).
    let m = [
        0.3536, -0.5732, 0.7392, 0.6124, 0.7392, 0.2803, -0.7071, 0.3536, 0.6124,
    ];
    assert!(oracle_error(&m).unwrap() > 1e-5);
    let mut out = [0.0; 9];
    let z = [0.0, 0.0, 0.0];
    assert_eq!(
        unsafe { cncrot_add_rotation(1, 57, z.as_ptr(), m.as_ptr(), out.as_mut_ptr()) },
        0
    );
    assert!(oracle_error(&out).unwrap() <= 1e-15);
    assert!(max_diff(&out, &m) < 1e-4);
}

// ---- huge angles ------------------------------------------------------------------------

/// Angles of every magnitude up to f64::MAX, with the values where rounding bites.
fn huge_angle(rng: &mut Rng) -> f64 {
    let special = [
        f64::MAX,
        2f64.powi(55),
        2f64.powi(55) + 8.0,
        2f64.powi(53) + 2.0,
        1e15,
        1e300,
        65_535.0,
        65_536.0,
        180.0,
        -180.0,
        0.0,
    ];
    match rng.next() % 4 {
        0 => rng.sign() * special[(rng.next() % special.len() as u64) as usize],
        _ => rng.sign() * 10f64.powf(rng.range(-3.0, 308.25)).min(f64::MAX),
    }
}

/// Rust's `%` is C's `fmod`: exact, and independent of the library's own reduction.
fn reduce(a: [f64; 3]) -> [f64; 3] {
    a.map(|x| x % 360.0)
}

const CODES: [i32; 12] = [57, 45, 54, 30, 39, 27, 25, 29, 38, 46, 55, 59];

#[test]
fn every_export_that_takes_angles_gives_the_reduced_rotation_or_refuses() {
    let mut rng = Rng::new(0x9E37_79B9_7F4A_7C15);
    let r0 = matrix(1, 57, [10.0, 20.0, 30.0]);
    for _ in 0..20_000 {
        let a = [
            huge_angle(&mut rng),
            huge_angle(&mut rng),
            huge_angle(&mut rng),
        ];
        let red = reduce(a);
        let intrinsic = (rng.next() % 2) as i32;
        let code = CODES[(rng.next() % 12) as usize];
        let mut out = [0.0; 3];
        let mut exp = [0.0; 3];
        unsafe {
            // Composition: bit for bit the matrix of the exactly reduced angles.
            assert_eq!(
                matrix(intrinsic, code, a),
                matrix(intrinsic, code, red),
                "{a:?}"
            );
            // Conversion: the same.
            let s = cncrot_convert(intrinsic, code, a.as_ptr(), 1, 39, out.as_mut_ptr());
            let t = cncrot_convert(intrinsic, code, red.as_ptr(), 1, 39, exp.as_mut_ptr());
            assert_eq!((s, out.map(f64::to_bits)), (t, exp.map(f64::to_bits)));
            // The second solution denotes the same rotation.
            assert_eq!(
                cncrot_second_solution(code, a.as_ptr(), out.as_mut_ptr()),
                0
            );
            let d = max_diff(&matrix(intrinsic, code, out), &matrix(intrinsic, code, red));
            assert!(d <= 4e-15, "second solution of {a:?}: {d:e}");
            // Closest angles to a huge reference: the rotation, or OUT_OF_RANGE.
            let m = matrix(intrinsic, code, red);
            let s =
                cncrot_closest_angles(intrinsic, code, m.as_ptr(), a.as_ptr(), out.as_mut_ptr());
            if a.iter().all(|x| x.abs() < 65_000.0) {
                assert!(s >= 0, "{a:?} refused");
            }
            if s >= 0 {
                let d = max_diff(&matrix(intrinsic, code, out), &m);
                assert!(d <= 2e-13, "closest to {a:?}: {out:?} off by {d:e}");
                for (o, r) in out.iter().zip(&a) {
                    assert!((o - r).abs() <= 360.0, "{o} far from {r}");
                }
            } else {
                assert_eq!(s, OUT_OF_RANGE);
            }
            // Additive rotation and frames: bit for bit those of the reduced angles.
            let (mut m1, mut m2) = ([0.0; 9], [0.0; 9]);
            cncrot_add_rotation(intrinsic, code, a.as_ptr(), r0.as_ptr(), m1.as_mut_ptr());
            cncrot_add_rotation(intrinsic, code, red.as_ptr(), r0.as_ptr(), m2.as_mut_ptr());
            assert_eq!(m1, m2);
            let p = [1.0, 2.0, 3.0];
            let (mut f1, mut f2) = ([0.0; 16], [0.0; 16]);
            cncrot_frame_from_angles(
                intrinsic,
                code,
                a.as_ptr(),
                p.as_ptr(),
                p.as_ptr(),
                f1.as_mut_ptr(),
            );
            cncrot_frame_from_angles(
                intrinsic,
                code,
                red.as_ptr(),
                p.as_ptr(),
                p.as_ptr(),
                f2.as_mut_ptr(),
            );
            assert_eq!(f1, f2);
            cncrot_frame_about_point(intrinsic, code, a.as_ptr(), p.as_ptr(), f1.as_mut_ptr());
            cncrot_frame_about_point(intrinsic, code, red.as_ptr(), p.as_ptr(), f2.as_mut_ptr());
            assert_eq!(f1, f2);
            // CYCLE600: the stored state of the reduced angles.
            let (mut g1, mut g2): (cncrot_cycle600_gud, cncrot_cycle600_gud) =
                (std::mem::zeroed(), std::mem::zeroed());
            cycle(&mut g1, null(), intrinsic, c"H", code, a, 0);
            cycle(&mut g2, null(), intrinsic, c"H", code, red, 0);
            assert_eq!(bytes_of(&g1), bytes_of(&g2));
        }
    }
}

/// The issue's cases, by hand.
#[test]
fn huge_references_and_second_solutions() {
    let m = matrix(1, 57, [10.0, 20.0, 30.0]);
    let mut out = [7.0; 3];
    unsafe {
        for r in [1e15, f64::MAX, -f64::MAX, 70_000.0] {
            let reference = [r, 0.0, 0.0];
            let s = cncrot_closest_angles(1, 57, m.as_ptr(), reference.as_ptr(), out.as_mut_ptr());
            assert_eq!(s, OUT_OF_RANGE, "{r:e}");
            assert_eq!(out, [7.0; 3]);
        }
        // 2^55 ≡ 2^55 mod 360 = 128 (2^k mod 360 has period 12 from k = 3: 2^7 = 128);
        // its second solution's first angle is 128 + 180 = 308 ≡ -52.
        let a = [2f64.powi(55), 0.0, 0.0];
        assert_eq!(cncrot_second_solution(57, a.as_ptr(), out.as_mut_ptr()), 0);
        assert_eq!(out, [-52.0, 180.0, 180.0]);
    }
}

// ---- small ones -------------------------------------------------------------------------

#[test]
fn frame_inverse_never_returns_negative_zero() {
    // A valid frame with -0 elements (Z by 90° written with -0 where 0 stands).
    let f = [
        -0.0, -1.0, -0.0, 0.0, 1.0, -0.0, -0.0, -0.0, -0.0, -0.0, 1.0, -0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    let mut out = [9.0; 16];
    assert_eq!(
        unsafe { cncrot_frame_inverse(f.as_ptr(), out.as_mut_ptr()) },
        0
    );
    assert!(
        out.iter().all(|x| x.to_bits() != (-0.0f64).to_bits()),
        "{out:?}"
    );
    assert_eq!(out[1], 1.0);
    assert_eq!(out[4], -1.0);
}

// ---- the head table ---------------------------------------------------------------------

fn full_table() -> cncrot_head_table {
    let mut text = String::new();
    for k in 0..16 {
        text.push_str(&format!("_HEAD_NAME=\"H{k}\" _DELTA_L1={k}\n"));
    }
    let mut t: cncrot_head_table = unsafe { std::mem::zeroed() };
    let s =
        unsafe { cncrot_head_table_parse(&mut t, text.as_ptr().cast(), text.len(), null_mut()) };
    assert_eq!(s, 0);
    t
}

fn call_head(t: *const cncrot_head_table, name: &std::ffi::CStr) -> i32 {
    let mut g: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
    cycle(&mut g, t, 0, name, 57, [1.0, 2.0, 3.0], 0)
}

#[test]
fn the_head_table_is_read_in_place_entry_by_entry() {
    let t = full_table();
    assert_eq!(call_head(&t, c"H15"), 0);
    assert_eq!(call_head(&t, c"H16"), UNKNOWN_HEAD);
    // Only the entry that matches is checked: a corrupt other entry does not matter, a
    // corrupt matching one is refused.
    let mut c = t;
    c.heads[3].delta[0] = f64::NAN;
    assert_eq!(call_head(&c, c"H15"), 0);
    assert_eq!(call_head(&c, c"H3"), NOT_FINITE);
    c.heads[3].allowed = 2;
    assert_eq!(call_head(&c, c"H3"), BAD_ARGUMENT);
    let mut c = t;
    c.count = 17;
    assert_eq!(call_head(&c, c"H0"), BAD_ARGUMENT);
    c.count = -1;
    assert_eq!(call_head(&c, c"H0"), BAD_ARGUMENT);
    // A name field without its NUL never matches (and is never read past its 32 bytes).
    let mut c = t;
    c.heads[0].name = [b'A' as std::ffi::c_char; 32];
    assert_eq!(call_head(&c, c"H0"), UNKNOWN_HEAD);
    // An empty name never matches, not even an entry whose name field is empty.
    let mut c = t;
    c.heads[2].name = [0; 32];
    assert_eq!(call_head(&c, c""), UNKNOWN_HEAD);
    // A misaligned table is refused, not read.
    let mut buf = vec![0u8; size_of::<cncrot_head_table>() + 8];
    let p = buf.as_mut_ptr();
    let off = p.align_offset(8) + 1;
    unsafe {
        std::ptr::copy_nonoverlapping(
            (&t as *const cncrot_head_table).cast(),
            p.add(off),
            size_of::<cncrot_head_table>(),
        )
    };
    let misaligned = unsafe { p.add(off) }.cast::<cncrot_head_table>();
    assert_eq!(call_head(misaligned, c"H15"), BAD_ARGUMENT);
}

#[test]
fn names_must_be_printable_ascii_without_spaces() {
    let mut g: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
    for bad in [c"MY HEAD", c"A\tB", c"A\r", c"\xC3\x84"] {
        let s = cycle(&mut g, null(), 0, bad, 57, [1.0, 2.0, 3.0], 0);
        assert_eq!(s, BAD_ARGUMENT, "{bad:?}");
    }
}

// ---- the machine description ------------------------------------------------------------

use std::ffi::c_char;

const BAD_FLAG: i32 = cncrot_status::BadFlag as i32;
const NAME_TOO_LONG: i32 = cncrot_status::NameTooLong as i32;

/// A fork head C/B (B within ±100°, pivot 150 mm up) built through the C interface, named.
fn c_machine() -> cncrot_machine {
    let mut m: cncrot_machine = unsafe { std::mem::zeroed() };
    let (z, y, o, p) = (
        [0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0],
        [0.0; 3],
        [0.0, 0.0, 150.0],
    );
    unsafe {
        assert_eq!(
            cncrot_machine_add_axis(&mut m, 0, z.as_ptr(), o.as_ptr(), 0.0, 0.0),
            0
        );
        assert_eq!(
            cncrot_machine_add_axis(&mut m, 0, y.as_ptr(), p.as_ptr(), -100.0, 100.0),
            0
        );
    }
    m.name[0] = b'M' as c_char;
    m
}

/// The statuses of every export that reads a description, on `m`: forward, inverse,
/// choose, follow-up, adding an axis, CYCLE600 positioning, the five-axis transformation,
/// sealing. On a refusal each must leave its outputs (and the description) untouched.
fn statuses_of(m: &cncrot_machine) -> [i32; 10] {
    let id = [
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    let n = usize::try_from(m.count).unwrap_or(0).min(3);
    let mut pos = [0.0; 3];
    pos[..n].fill(10.0);
    let x = [1.0, 0.0, 0.0];
    let gud = valid_state();
    let mut out = [[7.0f64; 16]; 9];
    let mut count = 99usize;
    let mut copy = *m;
    let mut sealed = *m;
    let six = [1.0, 2.0, 3.0, pos[0], pos[1], pos[2]];
    let s = unsafe {
        [
            cncrot_machine_forward(m, pos.as_ptr(), out[0].as_mut_ptr()),
            cncrot_machine_inverse(m, id.as_ptr(), out[1].as_mut_ptr(), 2, &mut count),
            cncrot_machine_choose(
                m,
                id.as_ptr(),
                pos.as_ptr(),
                CNCROT_CHOOSE_CLOSEST,
                0,
                out[2].as_mut_ptr(),
                out[3].as_mut_ptr(),
                out[4].as_mut_ptr(),
            ),
            cncrot_machine_follow(
                m,
                pos.as_ptr(),
                pos.as_ptr(),
                x.as_ptr(),
                100.0,
                out[5].as_mut_ptr(),
            ),
            cncrot_machine_add_axis(&mut copy, 1, x.as_ptr(), x.as_ptr(), 0.0, 0.0),
            cncrot_cycle600_position(
                &gud,
                m,
                pos.as_ptr(),
                out[2].as_mut_ptr(),
                out[3].as_mut_ptr(),
                out[4].as_mut_ptr(),
            ),
            cncrot_machine_tcp_forward(m, six.as_ptr(), 50.0, out[6].as_mut_ptr()),
            cncrot_machine_tcp_inverse(m, id.as_ptr(), 50.0, six.as_ptr(), out[7].as_mut_ptr()),
            cncrot_machine_tcp_inverse_rule(
                m,
                id.as_ptr(),
                50.0,
                six.as_ptr(),
                CNCROT_CHOOSE_CLOSEST,
                0,
                out[8].as_mut_ptr(),
            ),
            cncrot_machine_seal(&mut sealed),
        ]
    };
    if s.iter().all(|&x| x < 0) {
        assert!(out.iter().flatten().all(|&x| x == 7.0) && count == 99);
        assert_eq!(bytes_of_machine(&sealed), bytes_of_machine(m));
        assert_eq!(bytes_of_machine(&copy), bytes_of_machine(m));
    }
    s
}

fn bytes_of_machine(m: &cncrot_machine) -> Vec<u8> {
    let p = (m as *const cncrot_machine).cast::<u8>();
    unsafe { std::slice::from_raw_parts(p, size_of::<cncrot_machine>()) }.to_vec()
}

/// Issue 20, classes 1 and 4: a `cncrot_machine` filled by hand is checked field by field;
/// what is not a machine — garbage in an unused entry, parameters whose magnitude would
/// lose the degree or the millimetre, a Hirth step no grid has — is refused by every export
/// that reads it, with the same status, nothing written.
#[test]
fn a_hand_filled_machine_is_refused_unless_it_is_one() {
    type Edit = fn(&mut cncrot_machine);
    let refused: [(&str, Edit, i32); 26] = [
        (
            "garbage in an unused entry",
            |m| m.axes[2].point[0] = 1.0,
            BAD_ARGUMENT,
        ),
        (
            "NaN in an unused entry",
            |m| m.axes[2].direction[1] = f64::NAN,
            BAD_ARGUMENT,
        ),
        (
            "an unused entry's side",
            |m| m.axes[2].work_side = 1,
            BAD_ARGUMENT,
        ),
        ("a count over an empty entry", |m| m.count = 3, BAD_ARGUMENT),
        ("count -1", |m| m.count = -1, BAD_ARGUMENT),
        ("count 4", |m| m.count = 4, BAD_ARGUMENT),
        (
            "an axis' reserved",
            |m| m.axes[0].reserved = 1,
            BAD_ARGUMENT,
        ),
        ("side 2", |m| m.axes[1].work_side = 2, BAD_FLAG),
        ("side -1", |m| m.axes[1].work_side = -1, BAD_FLAG),
        (
            "zero direction",
            |m| m.axes[1].direction = [0.0; 3],
            BAD_ARGUMENT,
        ),
        (
            "parallel axes",
            |m| m.axes[1].direction = [0.0, 0.0, -3.0],
            BAD_ARGUMENT,
        ),
        (
            "infinite point",
            |m| m.axes[1].point[2] = f64::INFINITY,
            NOT_FINITE,
        ),
        ("NaN tool", |m| m.tool_direction[0] = f64::NAN, NOT_FINITE),
        ("min > max", |m| m.axes[1].min_deg = 101.0, BAD_ARGUMENT),
        ("NaN limit", |m| m.axes[1].max_deg = f64::NAN, NOT_FINITE),
        (
            "travel at 1e15",
            |m| {
                m.axes[1].min_deg = 1e15;
                m.axes[1].max_deg = 1e15 + 720.0;
            },
            OUT_OF_RANGE,
        ),
        (
            "a limit at -65 536",
            |m| m.axes[1].min_deg = -65_536.0,
            OUT_OF_RANGE,
        ),
        ("offset 1e12", |m| m.axes[0].offset_deg = 1e12, OUT_OF_RANGE),
        (
            "Hirth offset 1e17",
            |m| {
                m.axes[1].hirth_offset_deg = 1e17;
                m.axes[1].hirth_step_deg = 1.0;
            },
            OUT_OF_RANGE,
        ),
        ("point 1e12", |m| m.axes[1].point[0] = 1e12, OUT_OF_RANGE),
        (
            "point just beyond 1e6",
            |m| m.axes[0].point[1] = -1.000_000_1e6,
            OUT_OF_RANGE,
        ),
        (
            "Hirth step 1e-310",
            |m| m.axes[1].hirth_step_deg = 1e-310,
            BAD_ARGUMENT,
        ),
        (
            "Hirth step below 1e-6",
            |m| m.axes[1].hirth_step_deg = 0.999e-6,
            BAD_ARGUMENT,
        ),
        (
            "negative Hirth step",
            |m| m.axes[1].hirth_step_deg = -1.0,
            BAD_ARGUMENT,
        ),
        (
            "name without NUL",
            |m| m.name = [b'x' as c_char; 32],
            NAME_TOO_LONG,
        ),
        ("name not printable", |m| m.name[1] = 1, BAD_ARGUMENT),
    ];
    let good = c_machine();
    assert!(statuses_of(&good).iter().all(|&s| s >= 0));
    for (what, edit, want) in refused {
        let mut m = good;
        edit(&mut m);
        assert_eq!(statuses_of(&m), [want; 10], "{what}");
        // A seal that does not match (edited, or never written) is no way past the check.
        m.reserved = 1;
        assert_eq!(statuses_of(&m), [want; 10], "{what}, any seal");
    }
    let accepted: [(&str, Edit); 8] = [
        ("a seal that does not match", |m| m.reserved ^= 1),
        ("a direction of any length", |m| {
            m.axes[1].direction = [0.0, 5.0, 0.0]
        }),
        ("-0 in an unused entry", |m| m.axes[2].offset_deg = -0.0),
        ("a Hirth offset without a grid", |m| {
            m.axes[1].hirth_offset_deg = 1e300
        }),
        ("bytes after the name's NUL", |m| m.name[20] = -1),
        ("limits just within 65 536", |m| {
            m.axes[0].min_deg = -65_535.75;
            m.axes[0].max_deg = 65_535.75;
        }),
        ("points at 1e6", |m| m.axes[1].point = [1e6, -1e6, 1e6]),
        ("the finest Hirth step", |m| {
            m.axes[1].hirth_step_deg = 1e-6;
            m.axes[1].hirth_offset_deg = -65_535.75;
        }),
    ];
    for (what, edit) in accepted {
        let mut m = good;
        edit(&mut m);
        let s = statuses_of(&m);
        assert!(s.iter().all(|&s| s >= 0), "{what}: {s:?}");
    }
}

/// Random hostile descriptions: a valid machine with up to three fields set to values
/// that break it (NaN, ∞, huge, tiny, out-of-range integers, bytes of a name).
fn hostile_machine(rng: &mut Rng) -> cncrot_machine {
    let mut m = match rng.next() % 4 {
        0 => unsafe { std::mem::zeroed() },
        1 => c_machine(),
        2 => {
            let mut m = c_machine();
            m.axes[1].hirth_step_deg = 2.5;
            m.axes[1].hirth_offset_deg = 1.0;
            m.axes[0].min_deg = -30.0;
            m.axes[0].max_deg = 30.0;
            m
        }
        _ => {
            let mut m = c_machine();
            let (x, o) = ([1.0, 0.0, 0.0], [0.0, 0.0, 50.0]);
            unsafe { cncrot_machine_add_axis(&mut m, 1, x.as_ptr(), o.as_ptr(), -10.0, 10.0) };
            m
        }
    };
    let numbers = [
        f64::NAN,
        f64::INFINITY,
        -f64::INFINITY,
        0.0,
        -0.0,
        1e300,
        -1e15,
        65_536.0,
        2e6,
        1e-310,
        -1.0,
        0.5e-6,
        rng.range(-400.0, 400.0),
    ];
    for _ in 0..rng.next() % 4 {
        let v = numbers[(rng.next() % numbers.len() as u64) as usize];
        let i = [-1, 0, 1, 2, 3, 4][(rng.next() % 6) as usize];
        let a = (rng.next() % 3) as usize;
        let k = (rng.next() % 3) as usize;
        match rng.next() % 14 {
            0 => m.count = i,
            1 => m.reserved = i as u32,
            2 => m.tool_direction[k] = v,
            3 => m.axes[a].work_side = i,
            4 => m.axes[a].reserved = i,
            5 => m.axes[a].direction[k] = v,
            6 => m.axes[a].point[k] = v,
            7 => m.axes[a].offset_deg = v,
            8 => m.axes[a].min_deg = v,
            9 => m.axes[a].max_deg = v,
            10 => m.axes[a].hirth_offset_deg = v,
            11 => m.axes[a].hirth_step_deg = v,
            12 => m.name[(rng.next() % 32) as usize] = [0, 1, b'A' as c_char, -1][k],
            _ => m.name = [b'x' as c_char; 32],
        }
    }
    m
}

/// Issue 20, class 9: every status a kinematics export returns — driven with hostile
/// descriptions, frames, positions, rules, texts and tables — is named in the export's
/// doc comment in the header.
#[test]
fn every_status_of_a_kinematics_export_is_named_in_its_header_doc() {
    use std::collections::{BTreeMap, BTreeSet};
    let mut seen: BTreeMap<&str, BTreeSet<i32>> = BTreeMap::new();
    let mut note = |f: &'static str, s: i32| {
        seen.entry(f).or_default().insert(s);
    };
    let mut rng = Rng::new(2020);
    let gud = valid_state();
    let mut broken_gud = gud;
    broken_gud.cyc600_2 += 1.0;
    for round in 0..6000 {
        let m = hostile_machine(&mut rng);
        let n = usize::try_from(m.count).unwrap_or(0).min(3);
        // A frame the machine reaches, a rotation it may not, or no rotation at all.
        let mut pos = [0.0; 3];
        for p in pos.iter_mut().take(n) {
            *p = rng.range(-200.0, 200.0);
        }
        let mut frame = [0.0; 16];
        if unsafe { cncrot_machine_forward(&m, pos.as_ptr(), frame.as_mut_ptr()) } < 0 {
            let r = rng.rotation();
            for i in 0..3 {
                frame[4 * i..4 * i + 3].copy_from_slice(&r[i]);
            }
            frame[15] = 1.0;
        }
        match round % 7 {
            0 => frame[0] = f64::NAN,
            1 => frame[5] *= 1.1,
            _ => {}
        }
        let mut current = pos;
        match round % 5 {
            0 => current[0] = 70_000.0,
            1 => current[2] = 1.0,
            2 => current[1] = f64::INFINITY,
            3 => current[0] += 0.4,
            _ => {}
        }
        let (rule, reference) = ((rng.next() % 5) as i32, (rng.next() % 4) as i32 - 1);
        let (mut a, mut b, mut c, mut sol) = ([0.0; 3], [0.0; 3], [0.0; 16], [0.0; 6]);
        let mut count = 0usize;
        let lin = [rng.range(-1.0, 1.0) * [1.0, 1e308][round % 2], 0.0, 0.0];
        let mut copy = m;
        let dir = [[0.0, 1.0, 0.0], [0.0; 3], [1.0, 0.0, f64::NAN]][round % 3];
        let (lo, hi) = [(0.0, 0.0), (-1e15, 0.0), (5.0, -5.0), (-90.0, 90.0)][round % 4];
        unsafe {
            note(
                "cncrot_machine_forward",
                cncrot_machine_forward(&m, current.as_ptr(), c.as_mut_ptr()),
            );
            note(
                "cncrot_machine_inverse",
                cncrot_machine_inverse(&m, frame.as_ptr(), sol.as_mut_ptr(), round % 3, &mut count),
            );
            note(
                "cncrot_machine_choose",
                cncrot_machine_choose(
                    &m,
                    frame.as_ptr(),
                    current.as_ptr(),
                    rule,
                    reference,
                    a.as_mut_ptr(),
                    b.as_mut_ptr(),
                    c.as_mut_ptr(),
                ),
            );
            note(
                "cncrot_machine_follow",
                cncrot_machine_follow(
                    &m,
                    pos.as_ptr(),
                    current.as_ptr(),
                    lin.as_ptr(),
                    100.0,
                    a.as_mut_ptr(),
                ),
            );
            let six = [lin[0], 1.0, 2.0, current[0], current[1], current[2]];
            let length = [50.0, 1e7, f64::NAN, -20.0][round % 4];
            let mut six_out = [0.0; 6];
            note(
                "cncrot_machine_tcp_forward",
                cncrot_machine_tcp_forward(&m, six.as_ptr(), length, c.as_mut_ptr()),
            );
            note(
                "cncrot_machine_tcp_inverse",
                cncrot_machine_tcp_inverse(
                    &m,
                    frame.as_ptr(),
                    length,
                    six.as_ptr(),
                    six_out.as_mut_ptr(),
                ),
            );
            note(
                "cncrot_machine_tcp_inverse_rule",
                cncrot_machine_tcp_inverse_rule(
                    &m,
                    frame.as_ptr(),
                    length,
                    six.as_ptr(),
                    rule,
                    reference,
                    six_out.as_mut_ptr(),
                ),
            );
            let mut to_seal = m;
            note("cncrot_machine_seal", cncrot_machine_seal(&mut to_seal));
            // A five-axis program's point: the frame's direction, or rotary positions by
            // letter (some beyond what the machine has), on the hostile machine.
            let mut tp: cncrot_tool_path = std::mem::zeroed();
            tp.on = 1;
            tp.point = 1;
            tp.tip = [lin[0], 1.0, 2.0];
            if round % 2 == 0 {
                tp.orientation = CNCROT_ORIENTATION_DIRECTION;
                tp.direction = [frame[2], frame[6], frame[10]];
            } else {
                tp.orientation = CNCROT_ORIENTATION_AXES;
                tp.axes = current;
            }
            note(
                "cncrot_tool_path_axes",
                cncrot_tool_path_axes(
                    &tp,
                    &m,
                    length,
                    six.as_ptr(),
                    rule,
                    reference,
                    six_out.as_mut_ptr(),
                ),
            );
            note(
                "cncrot_machine_add_axis",
                cncrot_machine_add_axis(
                    &mut copy,
                    (round % 3) as i32,
                    dir.as_ptr(),
                    lin.as_ptr(),
                    lo,
                    hi,
                ),
            );
            let g = if round % 11 == 0 { &broken_gud } else { &gud };
            note(
                "cncrot_cycle600_position",
                cncrot_cycle600_position(
                    g,
                    &m,
                    current.as_ptr(),
                    a.as_mut_ptr(),
                    b.as_mut_ptr(),
                    c.as_mut_ptr(),
                ),
            );
        }
    }

    // Swivel data: each way a text can be wrong, on its own.
    let texts: [(&str, i32); 16] = [
        (
            "$TC_CARR7[1]=0 $TC_CARR9[1]=1 $TC_CARR11[1]=1 $TC_CARR32[1]=90 $TC_CARR34[1]=\"H\"",
            1,
        ),
        ("$TC_CARR8[1]=R1", 1),
        ("$TC_CARR8[1]=", 1),
        ("$TC_CARR52[1]=0", 1),
        ("$TC_CARR8[1]=1.2.3", 1),
        ("$TC_CARR34[1]=\"ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789\"", 1),
        ("$TC_CARR9[1]=1", 2),
        ("$TC_CARR9[1]=1", 0),
        ("$TC_CARR12[1]=1", 1),
        ("$TC_CARR9[1]=1 $TC_CARR23[1]=\"X\"", 1),
        ("$TC_CARR9[1]=1EX200", 1),
        ("$TC_CARR9[1]=1 $TC_CARR30[1]=-1EX15", 1),
        ("$TC_CARR9[1]=1 $TC_CARR24[1]=1EX12", 1),
        ("$TC_CARR9[1]=1 $TC_CARR28[1]=1EX-7", 1),
        ("$TC_CARR9[1]=1 $TC_CARR4[1]=1EX12", 1),
        ("$TC_CARR9[1]=1 $TC_CARR30[1]=5 $TC_CARR32[1]=-5", 1),
    ];
    for (text, set) in texts {
        let mut m: cncrot_machine = unsafe { std::mem::zeroed() };
        let mut line = 0;
        unsafe {
            note(
                "cncrot_machine_from_carr",
                cncrot_machine_from_carr(&mut m, text.as_ptr().cast(), text.len(), set),
            );
            note(
                "cncrot_machine_carr_error_line",
                cncrot_machine_carr_error_line(text.as_ptr().cast(), text.len(), set, &mut line),
            );
            note(
                "cncrot_machine_from_carr",
                cncrot_machine_from_carr(&mut m, text.as_ptr().cast(), usize::MAX, set),
            );
        }
    }

    // HEAD_DEF accessories: the table, the name and the directions each wrong in turn.
    let text = "_HEAD_NAME=\"H\" _DELTA_L1=540 _DELTA_L2=250 _DELTA_H1=200\n\
                _HEAD_NAME=\"J\" _DELTA_L1=1E12\n";
    let mut table: cncrot_head_table = unsafe { std::mem::zeroed() };
    let s = unsafe {
        cncrot_head_table_parse(&mut table, text.as_ptr().cast(), text.len(), null_mut())
    };
    assert_eq!(s, 0);
    let mut corrupt = [table; 6];
    corrupt[1].count = 17;
    corrupt[2].heads[0].allowed = 2;
    corrupt[3].heads[0].delta[0] = f64::NAN;
    corrupt[4].heads[0].delta = [f64::MAX; 3];
    corrupt[4].heads[0].offsets = [f64::MAX; 6];
    corrupt[5].heads[0].name[0] = 1;
    let (z, x, nan, zero) = ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [f64::NAN; 3], [0.0; 3]);
    let long = [b'N' as c_char; 40];
    for t in &corrupt {
        for name in [
            c"H".as_ptr(),
            c"J".as_ptr(),
            c"K".as_ptr(),
            c"\x01".as_ptr(),
            long.as_ptr(),
        ] {
            for (v1, v2) in [(z, x), (z, z), (nan, x), (zero, x)] {
                let mut m: cncrot_machine = unsafe { std::mem::zeroed() };
                note("cncrot_machine_from_head", unsafe {
                    cncrot_machine_from_head(&mut m, t, name, v1.as_ptr(), v2.as_ptr())
                });
            }
        }
    }

    // A NULL pointer, once each.
    let m = c_machine();
    let d = [0.0f64; 16];
    let mut o = [0.0f64; 16];
    let mut k = 0usize;
    let mut l = 0i32;
    let mut w = m;
    unsafe {
        note(
            "cncrot_machine_forward",
            cncrot_machine_forward(null(), d.as_ptr(), o.as_mut_ptr()),
        );
        note(
            "cncrot_machine_inverse",
            cncrot_machine_inverse(&m, null(), o.as_mut_ptr(), 2, &mut k),
        );
        note(
            "cncrot_machine_choose",
            cncrot_machine_choose(
                &m,
                d.as_ptr(),
                null(),
                0,
                0,
                o.as_mut_ptr(),
                o.as_mut_ptr(),
                o.as_mut_ptr(),
            ),
        );
        note(
            "cncrot_machine_follow",
            cncrot_machine_follow(&m, d.as_ptr(), d.as_ptr(), d.as_ptr(), 1.0, null_mut()),
        );
        note(
            "cncrot_machine_add_axis",
            cncrot_machine_add_axis(&mut w, 0, null(), d.as_ptr(), 0.0, 0.0),
        );
        note("cncrot_machine_seal", cncrot_machine_seal(null_mut()));
        note(
            "cncrot_cycle600_position",
            cncrot_cycle600_position(
                null(),
                &m,
                d.as_ptr(),
                o.as_mut_ptr(),
                o.as_mut_ptr(),
                o.as_mut_ptr(),
            ),
        );
        note(
            "cncrot_machine_tcp_forward",
            cncrot_machine_tcp_forward(&m, null(), 1.0, o.as_mut_ptr()),
        );
        note(
            "cncrot_machine_tcp_inverse",
            cncrot_machine_tcp_inverse(&m, d.as_ptr(), 1.0, null(), o.as_mut_ptr()),
        );
        note(
            "cncrot_machine_tcp_inverse_rule",
            cncrot_machine_tcp_inverse_rule(&m, null(), 1.0, d.as_ptr(), 0, 0, o.as_mut_ptr()),
        );
        note(
            "cncrot_machine_from_carr",
            cncrot_machine_from_carr(&mut w, null(), 0, 1),
        );
        note(
            "cncrot_machine_carr_error_line",
            cncrot_machine_carr_error_line(null(), 0, 1, &mut l),
        );
        note(
            "cncrot_machine_from_head",
            cncrot_machine_from_head(&mut w, null(), c"H".as_ptr(), d.as_ptr(), d.as_ptr()),
        );
    }

    let missing = common::undocumented(&seen);
    assert!(
        missing.is_empty(),
        "not in the header doc:\n{}",
        missing.join("\n")
    );
    // The hostile inputs reached what they were made for.
    let all: BTreeSet<i32> = seen.values().flatten().copied().collect();
    for s in [
        cncrot_status::BadFlag,
        cncrot_status::NameTooLong,
        cncrot_status::OutOfRange,
        cncrot_status::OutOfTravel,
        cncrot_status::Unreachable,
        cncrot_status::Snapped,
        cncrot_status::FreeAxis,
        cncrot_status::NoRoom,
        cncrot_status::TableFull,
        cncrot_status::BadState,
        cncrot_status::NotANumber,
        cncrot_status::MissingWord,
        cncrot_status::UnknownHead,
    ] {
        assert!(all.contains(&(s as i32)), "{s:?} never returned");
    }
}

/// `cncrot_probe_plane` of `pts`: the status and the frame (4x4, row-major).
fn probe_plane(pts: &[[f64; 3]]) -> (i32, [f64; 16]) {
    let (mut f, mut res) = ([0.0; 16], [0.0; 2]);
    let s = unsafe {
        cncrot_probe_plane(
            pts.as_ptr().cast(),
            pts.len(),
            f.as_mut_ptr(),
            res.as_mut_ptr(),
        )
    };
    (s, f)
}

/// Thin point sets got a wrong plane with success (the scatter matrix's closed-form
/// eigenvalues lost the two small ones): three points 1e-6 mm off a 100 mm line gave the
/// normal (0, 1, 0) while `PLANE POINTS` gives (0, 0, 1); four coplanar points on a strip
/// 101 mm × 9.6e-5 mm a plane 31° off. Expected: `PLANE POINTS`, and the exact normal
/// (2, 3, 6)/7 of points built from exact in-plane directions (3, −2, 0) and (12, 18, −13);
/// the tolerance ε·length/width is what rounding the points to doubles costs any fit.
#[test]
fn thin_point_sets_get_their_own_plane() {
    let three = [[0.0, 0.0, 0.0], [100.0, 0.0, 0.0], [50.0, 1e-6, 0.0]];
    let (s, f) = probe_plane(&three);
    assert_eq!(s, 0);
    let mut pp = [0.0; 16];
    let words: Vec<f64> = three.iter().flatten().copied().collect();
    let form = unsafe {
        cncrot_form_frame(
            CNCROT_FORM_PLANE_POINTS,
            0,
            words.as_ptr(),
            9,
            pp.as_mut_ptr(),
        )
    };
    assert_eq!(form, 0);
    assert!(max_diff(&f, &pp) <= 1e-15, "{f:?}");
    assert!(max_diff(&[f[2], f[6], f[10]], &[0.0, 0.0, 1.0]) <= 1e-15);

    let at = |a: f64, b: f64| -> [f64; 3] {
        std::array::from_fn(|k| {
            [5.0, -7.0, 120.0][k] + a * [3.0, -2.0, 0.0][k] + b * [12.0, 18.0, -13.0][k]
        })
    };
    let w = 2f64.powi(-18);
    let strip = [at(-14.0, 0.0), at(14.0, 0.0), at(14.0, w), at(-14.0, w)];
    let (s, f) = probe_plane(&strip);
    assert_eq!(s, 0);
    let tol = f64::EPSILON * 28.0 / (7.0 * w);
    let normal = [2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0];
    assert!(max_diff(&[f[2], f[6], f[10]], &normal) <= tol, "{f:?}");
}
