//! One table with a call of every exported C function, on its success path, a remark path
//! where there is one (singular) and error paths (NULL, NaN, bad codes, non-rotation). Each
//! entry records the statuses and the output bytes in a fixed-size `Trace` (no allocation),
//! so that `no_alloc.rs` can count allocations and `concurrency.rs` can compare results
//! across threads with the same table. `declared_functions` lists the header's functions:
//! a new export without an entry here fails both tests.
#![allow(dead_code)]

use cncrot::ffi::*;
use std::ptr::{null, null_mut};

/// Statuses and output bits, in call order; fixed capacity so recording never allocates.
#[derive(Clone, PartialEq, Eq)]
pub struct Trace {
    words: [u64; 1024],
    len: usize,
}

impl Trace {
    pub fn new() -> Trace {
        Trace {
            words: [0; 1024],
            len: 0,
        }
    }
    pub fn word(&mut self, w: u64) {
        assert!(self.len < self.words.len(), "Trace is full");
        self.words[self.len] = w;
        self.len += 1;
    }
    pub fn status(&mut self, s: i32) {
        self.word(s as u64);
    }
    pub fn f64s(&mut self, v: &[f64]) {
        for x in v {
            self.word(x.to_bits());
        }
    }
    /// The bytes of a plain C struct (no padding in cncrot's structs), 8 to a word.
    pub fn bytes<T>(&mut self, v: &T) {
        let p = (v as *const T).cast::<u8>();
        // SAFETY: reads the object's own bytes.
        let bytes = unsafe { std::slice::from_raw_parts(p, std::mem::size_of::<T>()) };
        for chunk in bytes.chunks(8) {
            let mut w = [0u8; 8];
            w[..chunk.len()].copy_from_slice(chunk);
            self.word(u64::from_le_bytes(w));
        }
    }
    pub fn len(&self) -> usize {
        self.len
    }
}

impl std::fmt::Debug for Trace {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:x?}", &self.words[..self.len])
    }
}

const ID: [f64; 9] = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
const IDF: [f64; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];
const A: [f64; 3] = [30.0, 90.0, 60.0]; // singular for Tait-Bryan: exercises that branch too
const BAD: [f64; 3] = [f64::NAN, 0.0, 0.0];

pub type Call = (&'static str, fn(&mut Trace));

/// A head from swivel data: C about Z carrying B about Y, pivot 150 mm above the adapter.
const CARR: &[u8] = b"$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1
$TC_CARR10[1]=0 $TC_CARR11[1]=1 $TC_CARR12[1]=0
$TC_CARR4[1]=0 $TC_CARR5[1]=0 $TC_CARR6[1]=-150 $TC_CARR23[1]=\"T\"
$TC_CARR31[1]=-100 $TC_CARR33[1]=100 $TC_CARR34[1]=\"BC\"
";

/// The CARR head as a machine.
fn head() -> cncrot_machine {
    let mut m: cncrot_machine = unsafe { std::mem::zeroed() };
    let s = unsafe { cncrot_machine_from_carr(&mut m, CARR.as_ptr().cast(), CARR.len(), 1) };
    assert_eq!(s, 0);
    m
}

/// Each entry calls its function on a success path, a singular or remark path where there
/// is one, and error paths (NULL, NaN, bad codes, non-rotation).
pub fn table() -> Vec<Call> {
    [
        rotations(),
        batches(),
        rotation_tools(),
        frames(),
        forms(),
        probing(),
        programs(),
        machines(),
        cycle600(),
    ]
    .concat()
}

/// Composition, decomposition and conversion, one call at a time.
fn rotations() -> Vec<Call> {
    vec![
        ("cncrot_status_str", |t| {
            for s in [-100, -13, -1, 0, 1, 7] {
                t.word(cncrot_status_str(s) as u64);
            }
        }),
        ("cncrot_matrix_from_angles", |t| unsafe {
            let mut m = [0.0; 9];
            t.status(cncrot_matrix_from_angles(1, 57, A.as_ptr(), m.as_mut_ptr()));
            t.status(cncrot_matrix_from_angles(
                1,
                57,
                BAD.as_ptr(),
                m.as_mut_ptr(),
            ));
            t.status(cncrot_matrix_from_angles(3, 57, A.as_ptr(), m.as_mut_ptr()));
            t.status(cncrot_matrix_from_angles(1, 57, null(), m.as_mut_ptr()));
            t.f64s(&m);
        }),
        ("cncrot_angles_from_matrix", |t| unsafe {
            let mut a = [0.0; 3];
            let mut m = [0.0; 9];
            t.status(cncrot_matrix_from_angles(1, 57, A.as_ptr(), m.as_mut_ptr()));
            t.status(cncrot_angles_from_matrix(1, 57, m.as_ptr(), a.as_mut_ptr()));
            t.status(cncrot_angles_from_matrix(
                0,
                25,
                ID.as_ptr(),
                a.as_mut_ptr(),
            ));
            t.status(cncrot_angles_from_matrix(1, 3, ID.as_ptr(), a.as_mut_ptr()));
            t.status(cncrot_angles_from_matrix(
                1,
                57,
                [2.0; 9].as_ptr(),
                a.as_mut_ptr(),
            ));
            t.status(cncrot_angles_from_matrix(1, 57, ID.as_ptr(), null_mut()));
            t.f64s(&a);
            t.f64s(&m);
        }),
        ("cncrot_convert", |t| unsafe {
            let mut a = [0.0; 3];
            t.status(cncrot_convert(0, 57, A.as_ptr(), 1, 39, a.as_mut_ptr()));
            t.status(cncrot_convert(0, 57, BAD.as_ptr(), 1, 39, a.as_mut_ptr()));
            t.status(cncrot_convert(0, 57, A.as_ptr(), 1, 64, a.as_mut_ptr()));
            t.f64s(&a);
        }),
    ]
}

/// The batch functions: rows of angles, matrices, conversions.
fn batches() -> Vec<Call> {
    vec![
        ("cncrot_matrices_from_angles", |t| unsafe {
            // Rows: good, NaN (fails, its matrix untouched), good; then a bad code.
            let a = [30.0, 45.0, 60.0, f64::NAN, 0.0, 0.0, 0.0, 90.0, 0.0];
            let mut m = [0.0; 27];
            let mut st = [7i32; 3];
            t.status(cncrot_matrices_from_angles(
                0,
                57,
                a.as_ptr(),
                3,
                m.as_mut_ptr(),
                st.as_mut_ptr(),
            ));
            t.status(cncrot_matrices_from_angles(
                0,
                57,
                a.as_ptr(),
                3,
                m.as_mut_ptr(),
                null_mut(),
            ));
            t.status(cncrot_matrices_from_angles(
                0,
                64,
                a.as_ptr(),
                3,
                m.as_mut_ptr(),
                null_mut(),
            ));
            t.status(cncrot_matrices_from_angles(
                0,
                57,
                a.as_ptr(),
                usize::MAX,
                m.as_mut_ptr(),
                null_mut(),
            ));
            t.f64s(&m);
            st.iter().for_each(|&s| t.status(s));
        }),
        ("cncrot_angles_from_matrices", |t| unsafe {
            let mut m = [0.0; 27];
            m[..9].copy_from_slice(&ID);
            m[9..18].copy_from_slice(&[2.0; 9]);
            m[18..].copy_from_slice(&ID);
            let mut a = [0.0; 9];
            let mut st = [7i32; 3];
            t.status(cncrot_angles_from_matrices(
                1,
                57,
                m.as_ptr(),
                3,
                a.as_mut_ptr(),
                st.as_mut_ptr(),
            ));
            t.status(cncrot_angles_from_matrices(
                1,
                25,
                m.as_ptr(),
                3,
                a.as_mut_ptr(),
                null_mut(),
            ));
            t.status(cncrot_angles_from_matrices(
                1,
                57,
                null(),
                3,
                a.as_mut_ptr(),
                null_mut(),
            ));
            t.f64s(&a);
            st.iter().for_each(|&s| t.status(s));
        }),
        ("cncrot_convert_many", |t| unsafe {
            let mut a = [30.0, 45.0, 60.0, 30.0, 90.0, 60.0, f64::NAN, 0.0, 0.0];
            let mut st = [7i32; 3];
            let p = a.as_mut_ptr();
            t.status(cncrot_convert_many(0, 57, p, 3, 1, 39, p, st.as_mut_ptr()));
            t.status(cncrot_convert_many(0, 57, p, 3, 1, 64, p, null_mut()));
            t.status(cncrot_convert_many(0, 57, p, 0, 1, 39, p, null_mut()));
            t.f64s(&a);
            st.iter().for_each(|&s| t.status(s));
        }),
    ]
}

/// Second solutions, closest angles, checks, nearest and additive rotations, vectors.
fn rotation_tools() -> Vec<Call> {
    vec![
        ("cncrot_second_solution", |t| unsafe {
            let mut a = [0.0; 3];
            t.status(cncrot_second_solution(57, A.as_ptr(), a.as_mut_ptr()));
            t.status(cncrot_second_solution(3, A.as_ptr(), a.as_mut_ptr()));
            t.f64s(&a);
        }),
        ("cncrot_closest_angles", |t| unsafe {
            let mut a = [0.0; 3];
            t.status(cncrot_closest_angles(
                1,
                55,
                ID.as_ptr(),
                A.as_ptr(),
                a.as_mut_ptr(),
            ));
            t.status(cncrot_closest_angles(
                1,
                57,
                ID.as_ptr(),
                BAD.as_ptr(),
                a.as_mut_ptr(),
            ));
            t.f64s(&a);
        }),
        ("cncrot_check_rotation", |t| unsafe {
            t.status(cncrot_check_rotation(ID.as_ptr()));
            t.status(cncrot_check_rotation([0.0; 9].as_ptr()));
            t.status(cncrot_check_rotation(null()));
        }),
        ("cncrot_nearest_rotation", |t| unsafe {
            let mut m = [0.0; 9];
            let measured = [1.0, 0.001, 0.0, -0.001, 1.0, 0.0, 0.0, 0.0, 1.0002];
            t.status(cncrot_nearest_rotation(measured.as_ptr(), m.as_mut_ptr()));
            t.status(cncrot_nearest_rotation([0.0; 9].as_ptr(), m.as_mut_ptr()));
            t.f64s(&m);
        }),
        ("cncrot_add_rotation", |t| unsafe {
            let mut m = ID;
            t.status(cncrot_add_rotation(
                1,
                57,
                A.as_ptr(),
                ID.as_ptr(),
                m.as_mut_ptr(),
            ));
            t.status(cncrot_add_rotation(
                0,
                57,
                A.as_ptr(),
                [3.0; 9].as_ptr(),
                m.as_mut_ptr(),
            ));
            t.f64s(&m);
        }),
        ("cncrot_rotate_vector", |t| unsafe {
            let mut v = [0.0; 3];
            t.status(cncrot_rotate_vector(
                ID.as_ptr(),
                A.as_ptr(),
                v.as_mut_ptr(),
            ));
            t.status(cncrot_rotate_vector(
                ID.as_ptr(),
                BAD.as_ptr(),
                v.as_mut_ptr(),
            ));
            t.f64s(&v);
        }),
        ("cncrot_rotate_vector_inverse", |t| unsafe {
            let mut v = [0.0; 3];
            t.status(cncrot_rotate_vector_inverse(
                ID.as_ptr(),
                A.as_ptr(),
                v.as_mut_ptr(),
            ));
            t.status(cncrot_rotate_vector_inverse(
                null(),
                A.as_ptr(),
                v.as_mut_ptr(),
            ));
            t.f64s(&v);
        }),
    ]
}

/// Frames: from angles, about a point, composed, inverted, applied.
fn frames() -> Vec<Call> {
    vec![
        ("cncrot_frame_from_angles", |t| unsafe {
            let mut f = [0.0; 16];
            t.status(cncrot_frame_from_angles(
                1,
                57,
                A.as_ptr(),
                A.as_ptr(),
                A.as_ptr(),
                f.as_mut_ptr(),
            ));
            t.status(cncrot_frame_from_angles(
                1,
                57,
                A.as_ptr(),
                BAD.as_ptr(),
                A.as_ptr(),
                f.as_mut_ptr(),
            ));
            t.f64s(&f);
        }),
        ("cncrot_frame_about_point", |t| unsafe {
            let mut f = [0.0; 16];
            t.status(cncrot_frame_about_point(
                1,
                57,
                A.as_ptr(),
                A.as_ptr(),
                f.as_mut_ptr(),
            ));
            t.status(cncrot_frame_about_point(
                2,
                57,
                A.as_ptr(),
                A.as_ptr(),
                f.as_mut_ptr(),
            ));
            t.f64s(&f);
        }),
        ("cncrot_frame_compose", |t| unsafe {
            let mut f = [0.0; 16];
            t.status(cncrot_frame_compose(
                IDF.as_ptr(),
                IDF.as_ptr(),
                f.as_mut_ptr(),
            ));
            t.status(cncrot_frame_compose(
                IDF.as_ptr(),
                [0.0; 16].as_ptr(),
                f.as_mut_ptr(),
            ));
            t.f64s(&f);
        }),
        ("cncrot_frame_inverse", |t| unsafe {
            let mut f = [0.0; 16];
            t.status(cncrot_frame_inverse(IDF.as_ptr(), f.as_mut_ptr()));
            t.status(cncrot_frame_inverse(null(), f.as_mut_ptr()));
            t.f64s(&f);
        }),
        ("cncrot_frame_transform_point", |t| unsafe {
            let mut p = [0.0; 3];
            t.status(cncrot_frame_transform_point(
                IDF.as_ptr(),
                A.as_ptr(),
                p.as_mut_ptr(),
            ));
            t.status(cncrot_frame_transform_point(
                IDF.as_ptr(),
                BAD.as_ptr(),
                p.as_mut_ptr(),
            ));
            t.f64s(&p);
        }),
    ]
}

/// Forms: every controller command as numbers.
fn forms() -> Vec<Call> {
    vec![
        ("cncrot_form_word_count", |t| unsafe {
            let mut n = 0usize;
            for form in [0, 1, 3, 8, 11, 12, -1] {
                t.status(cncrot_form_word_count(form, &mut n));
                t.word(n as u64);
            }
            t.status(cncrot_form_word_count(1, std::ptr::null_mut()));
        }),
        ("cncrot_form_frame", |t| unsafe {
            let mut f = [0.0; 16];
            let g68 = [10.0, 0.0, 0.0, 0.0, 30.0, 0.0];
            t.status(cncrot_form_frame(8, 0, g68.as_ptr(), 6, f.as_mut_ptr()));
            t.f64s(&f);
            let c800 = [0.0, 0.0, 0.0, 30.0, 20.0, 10.0, 0.0, 0.0, 0.0];
            t.status(cncrot_form_frame(
                1,
                128 + 57,
                c800.as_ptr(),
                9,
                f.as_mut_ptr(),
            ));
            t.f64s(&f);
            t.status(cncrot_form_frame(1, 192, c800.as_ptr(), 9, f.as_mut_ptr()));
            t.status(cncrot_form_frame(8, 0, g68.as_ptr(), 5, f.as_mut_ptr()));
            t.status(cncrot_form_frame(12, 0, g68.as_ptr(), 6, f.as_mut_ptr()));
            t.status(cncrot_form_frame(8, 0, BAD.as_ptr(), 3, f.as_mut_ptr()));
            t.status(cncrot_form_frame(
                7,
                0,
                [0.0; 9].as_ptr(),
                9,
                f.as_mut_ptr(),
            ));
            t.status(cncrot_form_frame(8, 0, null(), 6, f.as_mut_ptr()));
            t.f64s(&f);
        }),
        ("cncrot_form_values", |t| unsafe {
            let mut w = [0.0; 9];
            let mut f = [0.0; 16];
            let a = [0.0, 0.0, 0.0, 30.0, 90.0, 60.0];
            t.status(cncrot_form_frame(8, 0, a.as_ptr(), 6, f.as_mut_ptr()));
            for (form, sel, n) in [
                (8, 0, 6),
                (1, 57, 9),
                (4, 0, 3),
                (11, 123, 6),
                (9, 10157, 9),
            ] {
                t.status(cncrot_form_values(form, sel, f.as_ptr(), w.as_mut_ptr(), n));
                t.f64s(&w);
            }
            t.status(cncrot_form_values(4, 0, IDF.as_ptr(), w.as_mut_ptr(), 3));
            t.status(cncrot_form_values(3, 0, IDF.as_ptr(), w.as_mut_ptr(), 2));
            t.status(cncrot_form_values(1, 192, IDF.as_ptr(), w.as_mut_ptr(), 9));
            t.status(cncrot_form_values(
                8,
                0,
                [0.0; 16].as_ptr(),
                w.as_mut_ptr(),
                6,
            ));
            t.status(cncrot_form_values(8, 0, IDF.as_ptr(), null_mut(), 6));
            t.f64s(&w);
        }),
    ]
}

/// Probing: flange, plane, edge.
fn probing() -> Vec<Call> {
    vec![
        ("cncrot_probe_flange", |t| unsafe {
            let (mut a, mut f) = ([0.0; 3], [0.0; 16]);
            let o = [0.0; 3];
            let (x, y) = ([100.0, 0.0, 10.0], [0.0, 100.0, -5.0]);
            t.status(cncrot_probe_flange(
                o.as_ptr(),
                x.as_ptr(),
                o.as_ptr(),
                y.as_ptr(),
                a.as_mut_ptr(),
                f.as_mut_ptr(),
            ));
            t.f64s(&a);
            t.f64s(&f);
            t.status(cncrot_probe_flange(
                o.as_ptr(),
                o.as_ptr(),
                o.as_ptr(),
                y.as_ptr(),
                a.as_mut_ptr(),
                f.as_mut_ptr(),
            ));
            t.status(cncrot_probe_flange(
                o.as_ptr(),
                x.as_ptr(),
                o.as_ptr(),
                x.as_ptr(),
                a.as_mut_ptr(),
                f.as_mut_ptr(),
            ));
            t.status(cncrot_probe_flange(
                o.as_ptr(),
                BAD.as_ptr(),
                o.as_ptr(),
                y.as_ptr(),
                a.as_mut_ptr(),
                f.as_mut_ptr(),
            ));
            t.status(cncrot_probe_flange(
                null(),
                x.as_ptr(),
                o.as_ptr(),
                y.as_ptr(),
                a.as_mut_ptr(),
                f.as_mut_ptr(),
            ));
            t.f64s(&a);
        }),
        ("cncrot_probe_plane_toward", |t| unsafe {
            let (mut f, mut r) = ([0.0; 16], [0.0; 2]);
            // Clockwise from above: the order gives Z' down.
            let pts = [
                0.0, 0.0, 0.0, 0.0, 50.0, 0.0, 100.0, 50.0, -10.0, 100.0, 0.0, -10.0,
            ];
            for toward in [
                [0.0, 0.0, 1.0],
                [0.0; 3],
                [0.0, 0.0, -1.0],
                [f64::NAN, 0.0, 0.0],
            ] {
                t.status(cncrot_probe_plane_toward(
                    pts.as_ptr(),
                    4,
                    toward.as_ptr(),
                    f.as_mut_ptr(),
                    r.as_mut_ptr(),
                ));
                t.f64s(&f);
            }
            t.status(cncrot_probe_plane_toward(
                pts.as_ptr(),
                4,
                null(),
                f.as_mut_ptr(),
                r.as_mut_ptr(),
            ));
            t.f64s(&r);
        }),
        ("cncrot_probe_plane", |t| unsafe {
            let (mut f, mut r) = ([0.0; 16], [0.0; 2]);
            let pts = [
                0.0, 0.0, 5.0, 100.0, 0.0, 5.0, 0.0, 100.0, 5.0, 100.0, 100.0, 5.02,
            ];
            t.status(cncrot_probe_plane(
                pts.as_ptr(),
                4,
                f.as_mut_ptr(),
                r.as_mut_ptr(),
            ));
            t.f64s(&f);
            t.f64s(&r);
            t.status(cncrot_probe_plane(
                pts.as_ptr(),
                2,
                f.as_mut_ptr(),
                r.as_mut_ptr(),
            ));
            t.status(cncrot_probe_plane(
                [1.0; 12].as_ptr(),
                4,
                f.as_mut_ptr(),
                r.as_mut_ptr(),
            ));
            t.status(cncrot_probe_plane(
                [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0].as_ptr(),
                3,
                f.as_mut_ptr(),
                r.as_mut_ptr(),
            ));
            t.status(cncrot_probe_plane(
                pts.as_ptr(),
                4,
                f.as_mut_ptr(),
                null_mut(),
            ));
            t.f64s(&r);
        }),
        ("cncrot_probe_edge", |t| unsafe {
            let (mut a, mut f) = (0.0, [0.0; 16]);
            let (e1, e2) = ([0.0; 3], [100.0, 100.0, 0.0]);
            t.status(cncrot_probe_edge(
                IDF.as_ptr(),
                e1.as_ptr(),
                e2.as_ptr(),
                &mut a,
                f.as_mut_ptr(),
            ));
            t.f64s(&[a]);
            t.f64s(&f);
            t.status(cncrot_probe_edge(
                IDF.as_ptr(),
                e1.as_ptr(),
                e1.as_ptr(),
                &mut a,
                f.as_mut_ptr(),
            ));
            t.status(cncrot_probe_edge(
                IDF.as_ptr(),
                e1.as_ptr(),
                [0.0, 0.0, 1.0].as_ptr(),
                &mut a,
                f.as_mut_ptr(),
            ));
            t.status(cncrot_probe_edge(
                [0.0; 16].as_ptr(),
                e1.as_ptr(),
                e2.as_ptr(),
                &mut a,
                f.as_mut_ptr(),
            ));
            t.status(cncrot_probe_edge(
                IDF.as_ptr(),
                e1.as_ptr(),
                e2.as_ptr(),
                null_mut(),
                f.as_mut_ptr(),
            ));
            t.f64s(&[a]);
        }),
    ]
}

/// Program lines: read, column, frame, init, write.
fn programs() -> Vec<Call> {
    vec![
        ("cncrot_tool_path_line", |t| unsafe {
            // A five-axis program of each kind, a refusal (a zero direction) and a state the
            // library does not write.
            let lines: [(i32, &[u8]); 9] = [
                (CNCROT_DIALECT_SINUMERIK, b"TRAORI"),
                (
                    CNCROT_DIALECT_SINUMERIK,
                    b"N30 G1 X10 Y0 Z5 A3=0 B3=-1 C3=1",
                ),
                (CNCROT_DIALECT_SINUMERIK, b"N40 G2 X0 Y10 CR=10"),
                (
                    CNCROT_DIALECT_HEIDENHAIN,
                    b"3 L X+1 Y+2 Z+3 B+30 C-90 FMAX M128",
                ),
                (CNCROT_DIALECT_HEIDENHAIN, b"4 LN X+1 TX+0 TY+0.6 TZ+0.8"),
                (CNCROT_DIALECT_FANUC, b"G43.5 H1 X1. I1. J0. K1."),
                (CNCROT_DIALECT_FANUC, b"G1 X1. I0 J0 K0"),
                (CNCROT_DIALECT_TWINCAT, b"G1 X1"),
                (CNCROT_DIALECT_FANUC, b"M30"),
            ];
            let mut p: cncrot_tool_path = std::mem::zeroed();
            for (d, l) in lines {
                t.status(cncrot_tool_path_line(&mut p, d, l.as_ptr().cast(), l.len()));
                t.bytes(&p);
            }
            let mut bad = p;
            bad.orientation = 7;
            t.status(cncrot_tool_path_line(
                &mut bad,
                CNCROT_DIALECT_FANUC,
                c"X1".as_ptr(),
                2,
            ));
            t.bytes(&bad);
        }),
        ("cncrot_tool_path_axes", |t| unsafe {
            // The AC table of the five-axis worked example, from a direction, from rotary
            // positions, and refused (a rule that is not one).
            let mut m: cncrot_machine = std::mem::zeroed();
            let (x, z, pa, pc) = (
                [1.0, 0.0, 0.0],
                [0.0, 0.0, 1.0],
                [0.0, 0.0, 100.0],
                [0.0; 3],
            );
            cncrot_machine_add_axis(&mut m, 1, x.as_ptr(), pa.as_ptr(), 0.0, 0.0);
            cncrot_machine_add_axis(&mut m, 1, z.as_ptr(), pc.as_ptr(), 0.0, 0.0);
            let prev = [0.0, 0.0, 0.0, 20.0, 80.0, 0.0];
            let mut out = [0.0; 6];
            let mut p: cncrot_tool_path = std::mem::zeroed();
            for l in [
                &b"G43.5 H1"[..],
                b"G1 X10. I0.5 J0 K0.8660254037844386",
                b"G43.4 A30. C90.",
            ] {
                cncrot_tool_path_line(&mut p, CNCROT_DIALECT_FANUC, l.as_ptr().cast(), l.len());
                t.status(cncrot_tool_path_axes(
                    &p,
                    &m,
                    50.0,
                    prev.as_ptr(),
                    0,
                    0,
                    out.as_mut_ptr(),
                ));
                t.f64s(&out);
            }
            t.status(cncrot_tool_path_axes(
                &p,
                &m,
                50.0,
                prev.as_ptr(),
                9,
                0,
                out.as_mut_ptr(),
            ));
            t.f64s(&out);
        }),
        ("cncrot_program_line", |t| unsafe {
            let mut p = cncrot_program::default();
            let lines: [(i32, &[u8]); 8] = [
                (
                    CNCROT_DIALECT_SINUMERIK,
                    b"N10 CYCLE800(1,\"TC1\",0,57,10,0,0,30,45,60,0,0,0,-1,100,1)",
                ),
                (
                    CNCROT_DIALECT_SINUMERIK,
                    b"N20 AROT Z=15 ; on the tilted plane",
                ),
                (
                    CNCROT_DIALECT_SINUMERIK,
                    b"N30 CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39,1,0,0)",
                ),
                (CNCROT_DIALECT_SINUMERIK, b"ROT X=R1"),
                (CNCROT_DIALECT_HEIDENHAIN, b"PLANE RESET STAY"),
                (CNCROT_DIALECT_SINUMERIK, b"ROTS X30 Y20 Z10"),
                (
                    CNCROT_DIALECT_SINUMERIK,
                    b"CYCLE800(0,\"TC1\",0,192,0,0,0,0,0,0,0,0,0,1)",
                ),
                (0, b""),
            ];
            for (d, l) in lines {
                t.status(cncrot_program_line(&mut p, d, l.as_ptr().cast(), l.len()));
                t.bytes(&p);
            }
            let l = b"G68.2 X10 I30 J45 K60";
            let mut q = cncrot_program::default();
            t.status(cncrot_program_line(
                &mut q,
                CNCROT_DIALECT_FANUC,
                l.as_ptr().cast(),
                usize::MAX,
            ));
            t.status(cncrot_program_line(&mut q, CNCROT_DIALECT_FANUC, null(), 0));
            t.status(cncrot_program_line(
                null_mut(),
                CNCROT_DIALECT_FANUC,
                l.as_ptr().cast(),
                l.len(),
            ));
            let mut bad = q;
            bad.reserved = 1;
            t.status(cncrot_program_line(
                &mut bad,
                CNCROT_DIALECT_FANUC,
                l.as_ptr().cast(),
                l.len(),
            ));
            for d in [1, 2, 3, 4, 5, 6, 7] {
                let mut q = cncrot_program::default();
                t.status(cncrot_program_line(&mut q, d, l.as_ptr().cast(), l.len()));
                t.bytes(&q);
            }
        }),
        ("cncrot_program_column", |t| unsafe {
            let p = cncrot_program::default();
            let mut col = 99;
            for l in [
                &b"ROT X=R1"[..],
                b"ROT X10 X20",
                b"CYCLE800(0,\"A\",0",
                b"ROT Z30",
            ] {
                t.status(cncrot_program_column(
                    &p,
                    CNCROT_DIALECT_SINUMERIK,
                    l.as_ptr().cast(),
                    l.len(),
                    &mut col,
                ));
                t.word(col as u64);
            }
            t.status(cncrot_program_column(
                &p,
                9,
                b"G69".as_ptr().cast(),
                3,
                &mut col,
            ));
            t.word(col as u64);
            t.status(cncrot_program_column(
                &p,
                3,
                b"G69".as_ptr().cast(),
                3,
                null_mut(),
            ));
        }),
        ("cncrot_program_expected", |t| unsafe {
            let p = cncrot_program::default();
            let mut what = [0x5Au8; CNCROT_PROGRAM_EXPECTED_SIZE];
            for l in [
                &b"PLANE SPATIAL SPA+10 SPB+0"[..],
                b"PLANE SPATIAL SPX+10",
                b"PLANE SPATIAL SPA+10 SPB+0 SPC+0 SEQ",
                b"PLANE RESET STAY",
            ] {
                t.status(cncrot_program_expected(
                    &p,
                    CNCROT_DIALECT_HEIDENHAIN,
                    l.as_ptr().cast(),
                    l.len(),
                    what.as_mut_ptr().cast(),
                    what.len(),
                ));
                t.bytes(&what);
            }
            t.status(cncrot_program_expected(
                &p,
                CNCROT_DIALECT_HEIDENHAIN,
                b"PLANE".as_ptr().cast(),
                5,
                what.as_mut_ptr().cast(),
                what.len() - 1,
            ));
            t.status(cncrot_program_expected(
                &p,
                3,
                b"G69".as_ptr().cast(),
                3,
                null_mut(),
                what.len(),
            ));
        }),
        ("cncrot_program_axes", |t| unsafe {
            let m = head();
            let mut p = cncrot_program::default();
            let mut ax = [0.0; 3];
            // Nothing active, a tilt, a current position to unwind toward, refusals.
            t.status(cncrot_program_axes(
                &p,
                &m,
                [0.0; 3].as_ptr(),
                ax.as_mut_ptr(),
            ));
            t.f64s(&ax);
            let l = b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY";
            t.status(cncrot_program_line(
                &mut p,
                CNCROT_DIALECT_HEIDENHAIN,
                l.as_ptr().cast(),
                l.len(),
            ));
            t.status(cncrot_program_axes(
                &p,
                &m,
                [730.0, 0.0, 0.0].as_ptr(),
                ax.as_mut_ptr(),
            ));
            t.f64s(&ax);
            t.status(cncrot_program_axes(
                &p,
                &m,
                [f64::NAN, 0.0, 0.0].as_ptr(),
                ax.as_mut_ptr(),
            ));
            t.status(cncrot_program_axes(
                &p,
                null(),
                [0.0; 3].as_ptr(),
                ax.as_mut_ptr(),
            ));
            let mut bad = p;
            bad.origin[0] += 1.0;
            t.status(cncrot_program_axes(
                &bad,
                &m,
                [0.0; 3].as_ptr(),
                ax.as_mut_ptr(),
            ));
            t.f64s(&ax);
        }),
        ("cncrot_program_frame", |t| unsafe {
            let mut p = cncrot_program::default();
            let mut f = [0.0; 16];
            t.status(cncrot_program_frame(&p, f.as_mut_ptr()));
            t.f64s(&f);
            let l = b"G158 L1 P10157 X2. Y0. Z10. A20 B20 C-30 U0 V10 W0";
            t.status(cncrot_program_line(
                &mut p,
                CNCROT_DIALECT_SYNTEC,
                l.as_ptr().cast(),
                l.len(),
            ));
            t.status(cncrot_program_frame(&p, f.as_mut_ptr()));
            t.f64s(&f);
            p.origin[0] = f64::NAN;
            t.status(cncrot_program_frame(&p, f.as_mut_ptr()));
            t.status(cncrot_program_frame(null(), f.as_mut_ptr()));
            t.f64s(&f);
        }),
        ("cncrot_program_frame_on", |t| unsafe {
            let m = head();
            let mut p = cncrot_program::default();
            let mut f = [0.0; 16];
            // Nothing active, a frame, a direct mode (which cncrot_program_frame refuses),
            // refusals.
            t.status(cncrot_program_frame_on(&p, &m, f.as_mut_ptr()));
            t.f64s(&f);
            for l in [
                &b"PLANE SPATIAL SPA+0 SPB+30 SPC+0"[..],
                b"PLANE AXIAL B+30 C+45",
            ] {
                t.status(cncrot_program_line(
                    &mut p,
                    CNCROT_DIALECT_HEIDENHAIN,
                    l.as_ptr().cast(),
                    l.len(),
                ));
                t.status(cncrot_program_frame_on(&p, &m, f.as_mut_ptr()));
                t.f64s(&f);
                t.status(cncrot_program_frame(&p, f.as_mut_ptr()));
            }
            t.status(cncrot_program_frame_on(&p, null(), f.as_mut_ptr()));
            t.status(cncrot_program_frame_on(&p, &m, null_mut()));
            let mut bad = p;
            bad.angles[1] += 1.0;
            t.status(cncrot_program_frame_on(&bad, &m, f.as_mut_ptr()));
            t.f64s(&f);
        }),
        ("cncrot_program_init", |t| unsafe {
            let mut p = cncrot_program::default();
            for options in [0, CNCROT_PROGRAM_SINUMERIK_EULER, 2, u32::MAX] {
                t.status(cncrot_program_init(&mut p, options));
                t.bytes(&p);
            }
            let l = b"ROT X10 Y20";
            t.status(cncrot_program_line(
                &mut p,
                CNCROT_DIALECT_SINUMERIK,
                l.as_ptr().cast(),
                l.len(),
            ));
            t.bytes(&p);
            t.status(cncrot_program_init(null_mut(), 0));
        }),
        ("cncrot_program_write", |t| unsafe {
            let mut f = [0.0; 16];
            let a = [5.0, -2.0, 1.0, 30.0, 90.0, 60.0];
            t.status(cncrot_form_frame(8, 0, a.as_ptr(), 6, f.as_mut_ptr()));
            let mut out = [0u8; 520];
            for (d, form, dec) in [
                (CNCROT_DIALECT_SINUMERIK, c"CYCLE800", -1),
                (CNCROT_DIALECT_SINUMERIK, c"CYCLE800 27", 4),
                (CNCROT_DIALECT_HEIDENHAIN, c"PLANE POINTS", 3),
                (CNCROT_DIALECT_FANUC, c"G68.2", -1),
                (CNCROT_DIALECT_SYNTEC, c"G158 P10139", 6),
                (CNCROT_DIALECT_HAAS, c"G268", -1),
                (CNCROT_DIALECT_HEIDENHAIN, c"PLANE SPATIAL", -1),
                (CNCROT_DIALECT_TWINCAT, c"ROTS", -1),
                (CNCROT_DIALECT_FANUC, c"G68.2", 18),
            ] {
                t.status(cncrot_program_write(
                    d,
                    form.as_ptr(),
                    f.as_ptr(),
                    dec,
                    out.as_mut_ptr().cast(),
                    out.len(),
                ));
                t.bytes(&out);
            }
            t.status(cncrot_program_write(
                CNCROT_DIALECT_HEIDENHAIN,
                c"PLANE SPATIAL".as_ptr(),
                IDF.as_ptr(),
                3,
                out.as_mut_ptr().cast(),
                out.len(),
            ));
            t.status(cncrot_program_write(
                3,
                c"G68.2".as_ptr(),
                f.as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                8,
            ));
            t.status(cncrot_program_write(
                3,
                c"G68.2".as_ptr(),
                [0.0; 16].as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                8,
            ));
            t.status(cncrot_program_write(
                0,
                c"G68.2".as_ptr(),
                f.as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                8,
            ));
            t.status(cncrot_program_write(
                3,
                null(),
                f.as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                8,
            ));
            let long = [b'G'; 100];
            t.status(cncrot_program_write(
                3,
                long.as_ptr().cast(),
                f.as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                8,
            ));
            t.bytes(&out);
        }),
        ("cncrot_program_write_change", |t| unsafe {
            let states = heidenhain_states(
                t,
                &[
                    b"CYCL DEF 7.1 X+10",
                    b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN SEQ-",
                ],
            );
            let mut out = [0u8; CNCROT_PROGRAM_CHANGE_MAX + 1];
            for (a, b, d, form, dec) in [
                (0, 2, CNCROT_DIALECT_FANUC, c"G68.2", -1),
                (1, 2, CNCROT_DIALECT_SINUMERIK, c"CYCLE800", 4),
                (2, 0, CNCROT_DIALECT_HEIDENHAIN, c"PLANE EULER", 3),
                (0, 2, CNCROT_DIALECT_SINUMERIK, c"ROT", 3),
                (0, 1, CNCROT_DIALECT_TWINCAT, c"ROT", 3),
                (0, 2, 7, c"G68.2", 3),
            ] {
                t.status(cncrot_program_write_change(
                    &states[a],
                    &states[b],
                    d,
                    form.as_ptr(),
                    dec,
                    out.as_mut_ptr().cast(),
                    out.len(),
                ));
            }
            t.bytes(&out);
            let bad = cncrot_program {
                reserved: 1,
                ..states[1]
            };
            t.status(cncrot_program_write_change(
                &bad,
                &states[2],
                CNCROT_DIALECT_FANUC,
                c"G68.2".as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                out.len(),
            ));
            t.status(cncrot_program_write_change(
                &states[0],
                &states[2],
                CNCROT_DIALECT_HEIDENHAIN,
                c"PLANE SPATIAL".as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                20,
            ));
            t.status(cncrot_program_write_change(
                &states[0],
                null(),
                CNCROT_DIALECT_FANUC,
                c"G68.2".as_ptr(),
                -1,
                out.as_mut_ptr().cast(),
                out.len(),
            ));
            t.bytes(&out);
        }),
        ("cncrot_program_joins", |t| unsafe {
            // Cycle 7 line by line, then a tilt and its turn: each pair of blocks judged.
            let states = heidenhain_states(
                t,
                &[
                    b"CYCL DEF 7.1 X+10",
                    b"CYCL DEF 7.2 Y+20",
                    b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
                    b"L A+Q120 B+Q121 C+Q122 R0 FMAX",
                    b"PLANE RESET STAY",
                ],
            );
            for w in states[..6].windows(3) {
                let mut join = -1;
                t.status(cncrot_program_joins(&w[0], &w[1], &w[2], &mut join));
                t.status(join);
            }
            let mut join = 7;
            t.status(cncrot_program_joins(
                &states[0],
                null(),
                &states[1],
                &mut join,
            ));
            let mut bad = states[1];
            bad.shift[0] = 11.0;
            t.status(cncrot_program_joins(
                &states[0], &bad, &states[2], &mut join,
            ));
            t.status(join);
        }),
        ("cncrot_program_rest", |t| unsafe {
            // A cancel among a retract's words, a tilt with its motion mode and feed, a
            // cancel alone, a SINUMERIK block; then the errors, `out` untouched by each.
            for (d, l) in [
                (CNCROT_DIALECT_FANUC, &b"G91 G28 Z0. G69"[..]),
                (
                    CNCROT_DIALECT_SYNTEC,
                    b"N40 G1 G68.2 X0 Y0 Z0 I0 J30 K0 F300.",
                ),
                (CNCROT_DIALECT_HAAS, b"G269 (CANCEL)"),
                (CNCROT_DIALECT_SINUMERIK, b"CYCLE800()"),
            ] {
                let mut out = [0xAAu8; 64];
                t.status(cncrot_program_rest(
                    d,
                    l.as_ptr().cast(),
                    l.len(),
                    out.as_mut_ptr().cast(),
                    out.len(),
                ));
                t.bytes(&out);
            }
            let l = b"G0 G69 G90";
            let mut out = [0xAAu8; 8];
            for (d, text, n, cap) in [
                (CNCROT_DIALECT_FANUC, null(), 0, 8),
                (0, l.as_ptr(), l.len(), 8),
                (CNCROT_DIALECT_FANUC, l.as_ptr(), 300, 8),
                (CNCROT_DIALECT_FANUC, l.as_ptr(), l.len(), 6),
            ] {
                t.status(cncrot_program_rest(
                    d,
                    text.cast(),
                    n,
                    out.as_mut_ptr().cast(),
                    cap,
                ));
            }
            t.status(cncrot_program_rest(
                CNCROT_DIALECT_FANUC,
                l.as_ptr().cast(),
                l.len(),
                null_mut(),
                8,
            ));
            t.bytes(&out);
        }),
        ("cncrot_program_write_block", |t| unsafe {
            // A safety cancel and a zero shift with nothing active, a cycle's first line, a
            // tilt: each block read, then what a translator writes for it.
            let mut out = [0u8; CNCROT_PROGRAM_CHANGE_MAX + 1];
            let mut p = cncrot_program::default();
            for (l, d, form) in [
                (&b"PLANE RESET STAY"[..], CNCROT_DIALECT_FANUC, c"G68.2"),
                (
                    b"CYCL DEF 7.0 DATUM SHIFT",
                    CNCROT_DIALECT_SINUMERIK,
                    c"CYCLE800",
                ),
                (b"CYCL DEF 7.1 X+0", CNCROT_DIALECT_FANUC, c"G68.2"),
                (
                    b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN",
                    CNCROT_DIALECT_HAAS,
                    c"G268",
                ),
                (b"PLANE RESET STAY", CNCROT_DIALECT_TWINCAT, c"ROT"),
            ] {
                let before = p;
                t.status(cncrot_program_line(
                    &mut p,
                    CNCROT_DIALECT_HEIDENHAIN,
                    l.as_ptr().cast(),
                    l.len(),
                ));
                t.status(cncrot_program_write_block(
                    &before,
                    &p,
                    l.as_ptr().cast(),
                    l.len(),
                    d,
                    form.as_ptr(),
                    -1,
                    out.as_mut_ptr().cast(),
                    out.len(),
                ));
                // The start of each text: the trace has room for the whole buffer once.
                let head: &[u8; 96] = out.first_chunk().unwrap_or(&[0; 96]);
                t.bytes(head);
            }
            // A length beyond the dialect's line, a NULL line, no room.
            let l = b"PLANE RESET STAY";
            for (line, len, cap) in [
                (l.as_ptr(), 300, out.len()),
                (null(), 0, out.len()),
                (l.as_ptr(), l.len(), 2),
            ] {
                t.status(cncrot_program_write_block(
                    &p,
                    &p,
                    line.cast(),
                    len,
                    CNCROT_DIALECT_FANUC,
                    c"G68.2".as_ptr(),
                    -1,
                    out.as_mut_ptr().cast(),
                    cap,
                ));
            }
            t.bytes(&out);
        }),
    ]
}

/// Machines: from swivel data and heads, axes added, forward, inverse, choice, following.
/// The states of a Heidenhain program after each of its `lines` (at most 7; the empty state
/// first, the last repeated after them), each read's status traced. An array: the tables
/// run under the allocation counter.
unsafe fn heidenhain_states(t: &mut Trace, lines: &[&[u8]]) -> [cncrot_program; 8] {
    let mut states = [cncrot_program::default(); 8];
    for (k, l) in lines.iter().enumerate().take(7) {
        let mut p = states[k];
        t.status(cncrot_program_line(
            &mut p,
            CNCROT_DIALECT_HEIDENHAIN,
            l.as_ptr().cast(),
            l.len(),
        ));
        states[k + 1..].fill(p);
    }
    states
}

fn machines() -> Vec<Call> {
    vec![
        ("cncrot_machine_from_carr", |t| unsafe {
            let mut m: cncrot_machine = std::mem::zeroed();
            t.status(cncrot_machine_from_carr(
                &mut m,
                CARR.as_ptr().cast(),
                CARR.len(),
                1,
            ));
            t.bytes(&m);
            t.status(cncrot_machine_from_carr(
                &mut m,
                CARR.as_ptr().cast(),
                CARR.len(),
                2,
            ));
            let bad = b"$TC_CARR50[1]=1\n";
            t.status(cncrot_machine_from_carr(
                &mut m,
                bad.as_ptr().cast(),
                bad.len(),
                1,
            ));
            t.status(cncrot_machine_from_carr(&mut m, null(), 0, 1));
            t.bytes(&m);
        }),
        ("cncrot_machine_carr_error_line", |t| unsafe {
            let mut line = -1;
            let bad = b"$TC_CARR7[1]=1\n$TC_CARR8[1]=x\n";
            t.status(cncrot_machine_carr_error_line(
                bad.as_ptr().cast(),
                bad.len(),
                1,
                &mut line,
            ));
            t.word(line as u64);
            t.status(cncrot_machine_carr_error_line(
                CARR.as_ptr().cast(),
                CARR.len(),
                1,
                &mut line,
            ));
            t.word(line as u64);
            t.status(cncrot_machine_carr_error_line(
                bad.as_ptr().cast(),
                bad.len(),
                1,
                null_mut(),
            ));
        }),
        ("cncrot_machine_from_head", |t| unsafe {
            let mut table: cncrot_head_table = std::mem::zeroed();
            let text = b"_HEAD_NAME=\"H\"\n_DELTA_L1=500 _DELTA_L2=250\n";
            t.status(cncrot_head_table_parse(
                &mut table,
                text.as_ptr().cast(),
                text.len(),
                null_mut(),
            ));
            let mut m: cncrot_machine = std::mem::zeroed();
            let (z, x) = ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
            t.status(cncrot_machine_from_head(
                &mut m,
                &table,
                c"H".as_ptr(),
                z.as_ptr(),
                x.as_ptr(),
            ));
            t.bytes(&m);
            t.status(cncrot_machine_from_head(
                &mut m,
                &table,
                c"X".as_ptr(),
                z.as_ptr(),
                x.as_ptr(),
            ));
            t.status(cncrot_machine_from_head(
                &mut m,
                &table,
                c"H".as_ptr(),
                z.as_ptr(),
                z.as_ptr(),
            ));
            t.status(cncrot_machine_from_head(
                &mut m,
                &table,
                c"H".as_ptr(),
                BAD.as_ptr(),
                x.as_ptr(),
            ));
            t.bytes(&m);
        }),
        ("cncrot_machine_add_axis", |t| unsafe {
            let mut m: cncrot_machine = std::mem::zeroed();
            let (z, y, o) = ([0.0, 0.0, 1.0], [0.0, 2.0, 0.0], [0.0, 0.0, 150.0]);
            t.status(cncrot_machine_add_axis(
                &mut m,
                0,
                z.as_ptr(),
                o.as_ptr(),
                0.0,
                0.0,
            ));
            t.status(cncrot_machine_add_axis(
                &mut m,
                0,
                y.as_ptr(),
                o.as_ptr(),
                -100.0,
                100.0,
            ));
            t.status(cncrot_machine_add_axis(
                &mut m,
                2,
                z.as_ptr(),
                o.as_ptr(),
                0.0,
                0.0,
            ));
            t.status(cncrot_machine_add_axis(
                &mut m,
                1,
                [0.0; 3].as_ptr(),
                o.as_ptr(),
                0.0,
                0.0,
            ));
            t.status(cncrot_machine_add_axis(
                &mut m,
                1,
                z.as_ptr(),
                BAD.as_ptr(),
                0.0,
                0.0,
            ));
            t.status(cncrot_machine_add_axis(
                &mut m,
                1,
                z.as_ptr(),
                o.as_ptr(),
                5.0,
                1.0,
            ));
            t.status(cncrot_machine_add_axis(
                &mut m,
                1,
                z.as_ptr(),
                o.as_ptr(),
                0.0,
                0.0,
            ));
            t.status(cncrot_machine_add_axis(
                &mut m,
                1,
                y.as_ptr(),
                o.as_ptr(),
                0.0,
                0.0,
            ));
            t.bytes(&m);
        }),
        ("cncrot_machine_seal", |t| unsafe {
            // Edited by hand (unsealed), sealed again; a description that is not a machine
            // refused with it untouched.
            let mut m = head();
            m.axes[1].min_deg = -90.0;
            m.axes[0].direction = [0.0, 0.0, 2.0];
            t.status(cncrot_machine_seal(&mut m));
            t.bytes(&m);
            let mut broken = m;
            broken.axes[0].direction = [0.0; 3];
            t.status(cncrot_machine_seal(&mut broken));
            t.bytes(&broken);
        }),
        ("cncrot_machine_forward", |t| unsafe {
            let m = head();
            let mut f = [0.0; 16];
            t.status(cncrot_machine_forward(
                &m,
                [30.0, 40.0, 0.0].as_ptr(),
                f.as_mut_ptr(),
            ));
            t.f64s(&f);
            t.status(cncrot_machine_forward(
                &m,
                [30.0, 40.0, 1.0].as_ptr(),
                f.as_mut_ptr(),
            ));
            t.status(cncrot_machine_forward(&m, BAD.as_ptr(), f.as_mut_ptr()));
            let mut broken = m;
            broken.count = 4;
            t.status(cncrot_machine_forward(&broken, A.as_ptr(), f.as_mut_ptr()));
            t.f64s(&f);
        }),
        ("cncrot_machine_inverse", |t| unsafe {
            let m = head();
            let mut f = [0.0; 16];
            t.status(cncrot_machine_forward(
                &m,
                [30.0, 40.0, 0.0].as_ptr(),
                f.as_mut_ptr(),
            ));
            let (mut sol, mut n) = ([0.0; 6], 0usize);
            t.status(cncrot_machine_inverse(
                &m,
                f.as_ptr(),
                sol.as_mut_ptr(),
                2,
                &mut n,
            ));
            t.f64s(&sol);
            t.word(n as u64);
            t.status(cncrot_machine_inverse(
                &m,
                IDF.as_ptr(),
                sol.as_mut_ptr(),
                2,
                &mut n,
            ));
            t.status(cncrot_machine_inverse(
                &m,
                f.as_ptr(),
                sol.as_mut_ptr(),
                1,
                &mut n,
            ));
            t.status(cncrot_machine_inverse(
                &m,
                [2.0; 16].as_ptr(),
                sol.as_mut_ptr(),
                2,
                &mut n,
            ));
            let tilt = [
                1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
            ];
            let mut one: cncrot_machine = std::mem::zeroed();
            t.status(cncrot_machine_add_axis(
                &mut one,
                1,
                [0.0, 0.0, 1.0].as_ptr(),
                [0.0; 3].as_ptr(),
                0.0,
                0.0,
            ));
            t.status(cncrot_machine_inverse(
                &one,
                tilt.as_ptr(),
                sol.as_mut_ptr(),
                2,
                &mut n,
            ));
            t.f64s(&sol);
            t.word(n as u64);
        }),
        ("cncrot_machine_choose", |t| unsafe {
            let m = head();
            let mut f = [0.0; 16];
            t.status(cncrot_machine_forward(
                &m,
                [30.0, 40.0, 0.0].as_ptr(),
                f.as_mut_ptr(),
            ));
            let (mut ax, mut res, mut rem) = ([0.0; 3], [0.0; 3], [0.0; 16]);
            let cur = [750.0, 0.0, 0.0];
            for (rule, axis) in [(0, 0), (1, 2), (2, 2), (3, 0), (1, 0), (4, 0), (0, 1)] {
                t.status(cncrot_machine_choose(
                    &m,
                    f.as_ptr(),
                    cur.as_ptr(),
                    rule,
                    axis,
                    ax.as_mut_ptr(),
                    res.as_mut_ptr(),
                    rem.as_mut_ptr(),
                ));
                t.f64s(&ax);
            }
            t.status(cncrot_machine_choose(
                &m,
                IDF.as_ptr(),
                cur.as_ptr(),
                0,
                0,
                ax.as_mut_ptr(),
                res.as_mut_ptr(),
                rem.as_mut_ptr(),
            ));
            t.status(cncrot_machine_choose(
                &m,
                f.as_ptr(),
                [1e9, 0.0, 0.0].as_ptr(),
                0,
                0,
                ax.as_mut_ptr(),
                res.as_mut_ptr(),
                rem.as_mut_ptr(),
            ));
            let mut hirth = m;
            hirth.axes[1].hirth_step_deg = 7.0;
            hirth.axes[1].min_deg = -50.0;
            hirth.axes[1].max_deg = 50.0;
            t.status(cncrot_machine_choose(
                &hirth,
                f.as_ptr(),
                cur.as_ptr(),
                0,
                0,
                ax.as_mut_ptr(),
                res.as_mut_ptr(),
                rem.as_mut_ptr(),
            ));
            t.f64s(&res);
            t.f64s(&rem);
            hirth.axes[1].max_deg = -45.0;
            t.status(cncrot_machine_choose(
                &hirth,
                f.as_ptr(),
                cur.as_ptr(),
                0,
                0,
                ax.as_mut_ptr(),
                res.as_mut_ptr(),
                rem.as_mut_ptr(),
            ));
            t.f64s(&ax);
        }),
        ("cncrot_machine_follow", |t| unsafe {
            let m = head();
            let mut next = [0.0; 3];
            let (from, to) = ([0.0; 3], [0.0, 90.0, 0.0]);
            t.status(cncrot_machine_follow(
                &m,
                from.as_ptr(),
                to.as_ptr(),
                [1.0, 2.0, 3.0].as_ptr(),
                100.0,
                next.as_mut_ptr(),
            ));
            t.f64s(&next);
            t.status(cncrot_machine_follow(
                &m,
                from.as_ptr(),
                to.as_ptr(),
                [1.0, 2.0, 3.0].as_ptr(),
                f64::NAN,
                next.as_mut_ptr(),
            ));
            t.status(cncrot_machine_follow(
                &m,
                from.as_ptr(),
                BAD.as_ptr(),
                [1.0, 2.0, 3.0].as_ptr(),
                1.0,
                next.as_mut_ptr(),
            ));
            t.f64s(&next);
        }),
        ("cncrot_machine_tcp_forward", |t| unsafe {
            let m = head();
            let mut pose = [0.0; 16];
            let ax = [10.0, 20.0, 30.0, 40.0, 50.0, 0.0];
            t.status(cncrot_machine_tcp_forward(
                &m,
                ax.as_ptr(),
                100.0,
                pose.as_mut_ptr(),
            ));
            t.f64s(&pose);
            // Pole: B = 0 puts the tool along C.
            let pole = [1.0, 2.0, 3.0, 70.0, 0.0, 0.0];
            t.status(cncrot_machine_tcp_forward(
                &m,
                pole.as_ptr(),
                0.0,
                pose.as_mut_ptr(),
            ));
            t.f64s(&pose);
            let bad = [0.0, 0.0, f64::NAN, 0.0, 0.0, 0.0];
            t.status(cncrot_machine_tcp_forward(
                &m,
                bad.as_ptr(),
                1.0,
                pose.as_mut_ptr(),
            ));
            let unused = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0];
            t.status(cncrot_machine_tcp_forward(
                &m,
                unused.as_ptr(),
                1.0,
                pose.as_mut_ptr(),
            ));
            t.status(cncrot_machine_tcp_forward(
                &m,
                ax.as_ptr(),
                1e7,
                pose.as_mut_ptr(),
            ));
            t.status(cncrot_machine_tcp_forward(
                &m,
                null(),
                1.0,
                pose.as_mut_ptr(),
            ));
            t.f64s(&pose);
        }),
        ("cncrot_cl_pose", |t| unsafe {
            let mut pose = [0.0; 16];
            for dir in [
                [0.0, 0.0, 2.0],
                [1.0, 1.0, 1.0],
                [0.95, 0.1, 0.3],
                [-1.0, 0.0, 0.0],
            ] {
                t.status(cncrot_cl_pose(
                    [10.0, 20.0, 5.0].as_ptr(),
                    dir.as_ptr(),
                    pose.as_mut_ptr(),
                ));
                t.f64s(&pose);
            }
            t.status(cncrot_cl_pose(
                [0.0; 3].as_ptr(),
                [0.0; 3].as_ptr(),
                pose.as_mut_ptr(),
            ));
            t.status(cncrot_cl_pose(
                [f64::NAN, 0.0, 0.0].as_ptr(),
                [0.0, 0.0, 1.0].as_ptr(),
                pose.as_mut_ptr(),
            ));
            t.status(cncrot_cl_pose(
                null(),
                [0.0, 0.0, 1.0].as_ptr(),
                pose.as_mut_ptr(),
            ));
            t.f64s(&pose);
        }),
        ("cncrot_cl_pose_toward", |t| unsafe {
            let mut pose = [0.0; 16];
            cncrot_cl_pose(
                [0.0; 3].as_ptr(),
                [0.3, 0.1, 0.9].as_ptr(),
                pose.as_mut_ptr(),
            );
            // Along a path (the previous pose is the last one written, in place), across
            // the x component 0.9, and back against the previous direction.
            for dir in [
                [0.8, 0.1, 0.5],
                [0.95, 0.1, 0.3],
                [1.0, 0.0, 0.0],
                [-1.0, 0.0, 0.0],
            ] {
                t.status(cncrot_cl_pose_toward(
                    [10.0, 20.0, 5.0].as_ptr(),
                    dir.as_ptr(),
                    pose.as_ptr(),
                    pose.as_mut_ptr(),
                ));
                t.f64s(&pose);
            }
            let mut bad = pose;
            bad[0] = 2.0;
            t.status(cncrot_cl_pose_toward(
                [0.0; 3].as_ptr(),
                [0.0, 0.0, 1.0].as_ptr(),
                bad.as_ptr(),
                pose.as_mut_ptr(),
            ));
            bad[15] = f64::NAN;
            t.status(cncrot_cl_pose_toward(
                [0.0; 3].as_ptr(),
                [0.0, 0.0, 1.0].as_ptr(),
                bad.as_ptr(),
                pose.as_mut_ptr(),
            ));
            t.status(cncrot_cl_pose_toward(
                [0.0; 3].as_ptr(),
                [0.0; 3].as_ptr(),
                IDF.as_ptr(),
                pose.as_mut_ptr(),
            ));
            t.status(cncrot_cl_pose_toward(
                [0.0; 3].as_ptr(),
                [0.0, 0.0, 1.0].as_ptr(),
                null(),
                pose.as_mut_ptr(),
            ));
            t.f64s(&pose);
        }),
        ("cncrot_machine_tcp_inverse", |t| unsafe {
            let m = head();
            let mut pose = [0.0; 16];
            let ax = [10.0, 20.0, 30.0, 40.0, 50.0, 0.0];
            cncrot_machine_tcp_forward(&m, ax.as_ptr(), 100.0, pose.as_mut_ptr());
            let prev = [0.0, 0.0, 0.0, 400.0, 45.0, 0.0];
            let mut out = [0.0; 6];
            t.status(cncrot_machine_tcp_inverse(
                &m,
                pose.as_ptr(),
                100.0,
                prev.as_ptr(),
                out.as_mut_ptr(),
            ));
            t.f64s(&out);
            // At the pole C is free: it stays at 400.
            t.status(cncrot_machine_tcp_inverse(
                &m,
                IDF.as_ptr(),
                100.0,
                prev.as_ptr(),
                out.as_mut_ptr(),
            ));
            t.f64s(&out);
            // B beyond its travel of ±100°: a tilt of 120° cannot be reached.
            let far = [0.0, 0.0, 0.0, 0.0, 100.0, 0.0];
            let mut tilt = [0.0; 16];
            let m0 = {
                let mut z = m;
                z.axes[1].min_deg = 0.0;
                z.axes[1].max_deg = 0.0;
                z
            };
            cncrot_machine_tcp_forward(
                &m0,
                [0.0, 0.0, 0.0, 0.0, 120.0, 0.0].as_ptr(),
                0.0,
                tilt.as_mut_ptr(),
            );
            t.status(cncrot_machine_tcp_inverse(
                &m,
                tilt.as_ptr(),
                0.0,
                far.as_ptr(),
                out.as_mut_ptr(),
            ));
            let mut skew = IDF;
            skew[0] = 2.0;
            t.status(cncrot_machine_tcp_inverse(
                &m,
                skew.as_ptr(),
                0.0,
                prev.as_ptr(),
                out.as_mut_ptr(),
            ));
            let nan = [f64::NAN, 0.0, 0.0, 0.0, 0.0, 0.0];
            t.status(cncrot_machine_tcp_inverse(
                &m,
                pose.as_ptr(),
                0.0,
                nan.as_ptr(),
                out.as_mut_ptr(),
            ));
            t.status(cncrot_machine_tcp_inverse(
                &m,
                pose.as_ptr(),
                f64::INFINITY,
                prev.as_ptr(),
                out.as_mut_ptr(),
            ));
            t.status(cncrot_machine_tcp_inverse(
                &m,
                pose.as_ptr(),
                0.0,
                prev.as_ptr(),
                null_mut(),
            ));
            t.f64s(&out);
        }),
        ("cncrot_machine_tcp_inverse_rule", |t| unsafe {
            let m = head();
            let mut pose = [0.0; 16];
            let ax = [10.0, 20.0, 30.0, 40.0, 50.0, 0.0];
            cncrot_machine_tcp_forward(&m, ax.as_ptr(), 100.0, pose.as_mut_ptr());
            let prev = [0.0, 0.0, 0.0, 40.0, 50.0, 0.0];
            let mut out = [0.0; 6];
            for (rule, reference) in [(0, 0), (1, 2), (2, 2), (3, 0), (1, 0), (7, 0), (0, 1)] {
                t.status(cncrot_machine_tcp_inverse_rule(
                    &m,
                    pose.as_ptr(),
                    100.0,
                    prev.as_ptr(),
                    rule,
                    reference,
                    out.as_mut_ptr(),
                ));
                t.f64s(&out);
            }
        }),
    ]
}

/// CYCLE600, its state and the HEAD_DEF table.
fn cycle600() -> Vec<Call> {
    vec![
        ("cncrot_cycle600_position", |t| unsafe {
            let m = head();
            let mut gud: cncrot_cycle600_gud = std::mem::zeroed();
            let (mut ax, mut res, mut rem) = ([0.0; 3], [0.0; 3], [0.0; 16]);
            t.status(cncrot_cycle600(
                &mut gud,
                null(),
                1,
                c"H".as_ptr(),
                0,
                7,
                0.0,
                0.0,
                0.0,
                30.0,
                40.0,
                0.0,
                0.0,
                0.0,
                0.0,
                1,
                39,
                0,
                0,
                0,
            ));
            t.status(cncrot_cycle600_position(
                &gud,
                &m,
                [0.0; 3].as_ptr(),
                ax.as_mut_ptr(),
                res.as_mut_ptr(),
                rem.as_mut_ptr(),
            ));
            t.f64s(&ax);
            t.status(cncrot_cycle600(
                &mut gud,
                null(),
                1,
                c"H".as_ptr(),
                0,
                7,
                0.0,
                0.0,
                0.0,
                30.0,
                40.0,
                0.0,
                0.0,
                0.0,
                0.0,
                1,
                39,
                0,
                1,
                0,
            ));
            t.status(cncrot_cycle600_position(
                &gud,
                &m,
                [0.0; 3].as_ptr(),
                ax.as_mut_ptr(),
                res.as_mut_ptr(),
                rem.as_mut_ptr(),
            ));
            t.f64s(&ax);
            gud.cyc600_2 += 1.0;
            t.status(cncrot_cycle600_position(
                &gud,
                &m,
                [0.0; 3].as_ptr(),
                ax.as_mut_ptr(),
                res.as_mut_ptr(),
                rem.as_mut_ptr(),
            ));
        }),
        ("cncrot_cycle600_gud_size", |t| {
            t.word(cncrot_cycle600_gud_size() as u64);
        }),
        ("cncrot_head_table_parse", |t| unsafe {
            let mut table: cncrot_head_table = std::mem::zeroed();
            let mut line = 0;
            let text = b"N1 _HEAD_NAME=\"IFVW207S\"\nN2 _DELTA_L1=540.735 _OFFS_H1_Z=0.247\n";
            t.status(cncrot_head_table_parse(
                &mut table,
                text.as_ptr().cast(),
                text.len(),
                &mut line,
            ));
            let bad = b"_HEAD_NAME=\"A\"\nDELTA_L2=1\n";
            t.status(cncrot_head_table_parse(
                &mut table,
                bad.as_ptr().cast(),
                bad.len(),
                &mut line,
            ));
            t.bytes(&table);
            t.word(line as u64);
        }),
        ("cncrot_cycle600", |t| unsafe {
            let mut gud: cncrot_cycle600_gud = std::mem::zeroed();
            let mut table: cncrot_head_table = std::mem::zeroed();
            let text = b"_HEAD_NAME=\"UFK600\"\n";
            t.status(cncrot_head_table_parse(
                &mut table,
                text.as_ptr().cast(),
                text.len(),
                null_mut(),
            ));
            let name = c"UFK600".as_ptr();
            t.status(cncrot_cycle600(
                &mut gud, &table, 0, name, 1, 57, 0.0, 0.0, 0.0, 30.0, 45.0, 60.0, 0.0, 0.0, 0.0,
                1, 39, 0, 0, 0,
            ));
            t.status(cncrot_cycle600(
                &mut gud, &table, 0, name, 1, 3, 1.0, 2.0, 3.0, 15.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0,
                27, 1, 0, 0,
            ));
            t.status(cncrot_cycle600(
                &mut gud,
                &table,
                0,
                c"NOPE".as_ptr(),
                1,
                57,
                0.0,
                0.0,
                0.0,
                1.0,
                2.0,
                3.0,
                0.0,
                0.0,
                0.0,
                1,
                39,
                0,
                0,
                0,
            ));
            t.status(cncrot_cycle600(
                &mut gud,
                null(),
                0,
                name,
                0,
                57,
                0.0,
                0.0,
                0.0,
                1.0,
                2.0,
                3.0,
                0.0,
                0.0,
                0.0,
                1,
                39,
                0,
                0,
                0,
            ));
            t.bytes(&gud);
            t.bytes(&table);
        }),
    ]
}

/// The functions `include/cncrot.h` declares.
pub fn declared_functions() -> Vec<&'static str> {
    functions_of(include_str!("../../include/cncrot.h"))
}

/// The functions a header declares: names `cncrot_…` followed by `(` outside comments,
/// sorted, once each.
pub fn functions_of(header: &str) -> Vec<&str> {
    let mut declared: Vec<&str> = header
        .lines()
        .filter(|l| !l.trim_start().starts_with('*') && !l.trim_start().starts_with("/*"))
        .filter_map(|l| {
            let start = l.find("cncrot_")?;
            let rest = &l[start..];
            let end = rest.find('(')?;
            let name = &rest[..end];
            name.chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_')
                .then_some(name)
        })
        .collect();
    declared.sort_unstable();
    declared.dedup();
    declared
}

/// The names in `table()`, sorted.
pub fn covered_functions() -> Vec<&'static str> {
    let mut covered: Vec<&str> = table().iter().map(|(n, _)| *n).collect();
    covered.sort_unstable();
    covered
}
