//! The batch exports against the single calls: every row's output and status bit for bit,
//! failing rows untouched, the batch status (first error, else first remark), refusals that
//! write nothing, in-place conversion.

mod common;

use cncrot::ffi::*;
use common::Rng;
use std::ptr::null_mut;

const SENTINEL: f64 = -12345.678;
const CODES: [i32; 14] = [57, 45, 54, 30, 39, 27, 25, 29, 38, 46, 55, 59, 7, 49];

/// Angle rows of every kind: random, right angles, huge, singular, non-finite.
fn angle_rows(rng: &mut Rng, n: usize) -> Vec<f64> {
    let mut v = Vec::with_capacity(3 * n);
    for i in 0..n {
        let row = match i % 7 {
            0 => [
                rng.range(-180.0, 180.0),
                rng.range(-90.0, 90.0),
                rng.range(-180.0, 180.0),
            ],
            1 => [90.0 * (i % 5) as f64, -90.0, 270.0],
            2 => [rng.range(-1e6, 1e6), rng.range(-1e300, 1e300), 0.0],
            3 => [rng.range(-180.0, 180.0), 90.0, rng.range(-180.0, 180.0)],
            4 => [f64::NAN, 1.0, 2.0],
            5 => [1.0, f64::INFINITY, 2.0],
            _ => [0.0, 0.0, rng.range(-180.0, 180.0)],
        };
        v.extend_from_slice(&row);
    }
    v
}

/// The batch status a sequence of row statuses gives.
fn expected(statuses: &[i32]) -> i32 {
    let error = statuses.iter().find(|&&s| s < 0);
    let remark = statuses.iter().find(|&&s| s > 0);
    *error.or(remark).unwrap_or(&0)
}

#[test]
fn matrices_from_angles_equals_single_calls() {
    let mut rng = Rng::new(11);
    for &code in &CODES {
        for kind in [0, 1] {
            let n = 50;
            let a = angle_rows(&mut rng, n);
            let mut m = vec![SENTINEL; 9 * n];
            let mut st = vec![99; n];
            let r = unsafe {
                cncrot_matrices_from_angles(
                    kind,
                    code,
                    a.as_ptr(),
                    n,
                    m.as_mut_ptr(),
                    st.as_mut_ptr(),
                )
            };
            for i in 0..n {
                let mut one = [SENTINEL; 9];
                let s = unsafe {
                    cncrot_matrix_from_angles(kind, code, a[3 * i..].as_ptr(), one.as_mut_ptr())
                };
                assert_eq!(st[i], s, "row {i}");
                let got: Vec<u64> = m[9 * i..9 * i + 9].iter().map(|x| x.to_bits()).collect();
                let want: Vec<u64> = one.iter().map(|x| x.to_bits()).collect();
                assert_eq!(got, want, "code {code} kind {kind} row {i}");
            }
            assert_eq!(r, expected(&st));
        }
    }
}

#[test]
fn angles_from_matrices_equals_single_calls() {
    let mut rng = Rng::new(12);
    for &code in &CODES[..12] {
        for kind in [0, 1] {
            let n = 40;
            let mut m = Vec::with_capacity(9 * n);
            for i in 0..n {
                let r = match i % 5 {
                    0 | 1 => rng.rotation(),
                    // Singular for every sequence's middle angle at some rows.
                    2 => cncrot::matrix_from_angles(
                        cncrot::Kind::from_flag(kind).unwrap(),
                        cncrot::AxisCode::new(code).unwrap(),
                        [
                            10.0,
                            if code == 25
                                || code == 29
                                || code == 38
                                || code == 46
                                || code == 55
                                || code == 59
                            {
                                0.0
                            } else {
                                90.0
                            },
                            20.0,
                        ],
                    ),
                    3 => [[2.0; 3]; 3],
                    _ => [[f64::NAN, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
                };
                m.extend(r.iter().flatten());
            }
            let mut a = vec![SENTINEL; 3 * n];
            let mut st = vec![99; n];
            let r = unsafe {
                cncrot_angles_from_matrices(
                    kind,
                    code,
                    m.as_ptr(),
                    n,
                    a.as_mut_ptr(),
                    st.as_mut_ptr(),
                )
            };
            assert!(st.contains(&1) && st.iter().any(|&s| s < 0), "{st:?}");
            for i in 0..n {
                let mut one = [SENTINEL; 3];
                let s = unsafe {
                    cncrot_angles_from_matrix(kind, code, m[9 * i..].as_ptr(), one.as_mut_ptr())
                };
                assert_eq!(st[i], s, "row {i}");
                let got: Vec<u64> = a[3 * i..3 * i + 3].iter().map(|x| x.to_bits()).collect();
                let want: Vec<u64> = one.iter().map(|x| x.to_bits()).collect();
                assert_eq!(got, want, "code {code} kind {kind} row {i}");
            }
            assert_eq!(r, expected(&st));
        }
    }
}

#[test]
fn convert_many_equals_single_calls_and_works_in_place() {
    let mut rng = Rng::new(13);
    for &from in &CODES {
        for &to in &CODES[..12] {
            let n = 21;
            let a = angle_rows(&mut rng, n);
            let mut out = vec![SENTINEL; 3 * n];
            let mut st = vec![99; n];
            let r = unsafe {
                cncrot_convert_many(
                    0,
                    from,
                    a.as_ptr(),
                    n,
                    1,
                    to,
                    out.as_mut_ptr(),
                    st.as_mut_ptr(),
                )
            };
            let mut inplace = a.clone();
            let p = inplace.as_mut_ptr();
            let r2 = unsafe { cncrot_convert_many(0, from, p, n, 1, to, p, null_mut()) };
            assert_eq!(r, r2);
            for i in 0..n {
                let mut one = [SENTINEL; 3];
                let s = unsafe {
                    cncrot_convert(0, from, a[3 * i..].as_ptr(), 1, to, one.as_mut_ptr())
                };
                assert_eq!(st[i], s);
                for k in 0..3 {
                    assert_eq!(out[3 * i + k].to_bits(), one[k].to_bits());
                    // In place: a failing row keeps its input.
                    let want = if s < 0 { a[3 * i + k] } else { one[k] };
                    assert_eq!(inplace[3 * i + k].to_bits(), want.to_bits());
                }
            }
            assert_eq!(r, expected(&st));
        }
    }
}

#[test]
fn refusals_write_nothing() {
    let a = [30.0, 45.0, 60.0];
    let mut m = [SENTINEL; 9];
    let mut st = [99];
    let bad = cncrot_status::BadArgument as i32;
    unsafe {
        assert_eq!(
            cncrot_matrices_from_angles(2, 57, a.as_ptr(), 1, m.as_mut_ptr(), st.as_mut_ptr()),
            cncrot_status::BadFlag as i32
        );
        assert_eq!(
            cncrot_matrices_from_angles(0, 64, a.as_ptr(), 1, m.as_mut_ptr(), st.as_mut_ptr()),
            cncrot_status::BadSequence as i32
        );
        assert_eq!(
            cncrot_matrices_from_angles(
                0,
                57,
                a.as_ptr(),
                usize::MAX / 8,
                m.as_mut_ptr(),
                st.as_mut_ptr()
            ),
            bad
        );
        assert_eq!(
            cncrot_angles_from_matrices(
                0,
                57,
                m.as_ptr(),
                usize::MAX / 72 + 1,
                m.as_mut_ptr(),
                st.as_mut_ptr()
            ),
            bad
        );
        assert_eq!(
            cncrot_convert_many(
                0,
                57,
                a.as_ptr(),
                usize::MAX / 24 + 1,
                1,
                39,
                m.as_mut_ptr(),
                st.as_mut_ptr()
            ),
            bad
        );
        assert_eq!(
            cncrot_convert_many(0, 57, a.as_ptr(), 1, 1, 7, m.as_mut_ptr(), st.as_mut_ptr()),
            cncrot_status::IncompleteSequence as i32
        );
        assert_eq!(
            cncrot_convert_many(
                0,
                57,
                std::ptr::null(),
                1,
                1,
                39,
                m.as_mut_ptr(),
                st.as_mut_ptr()
            ),
            cncrot_status::NullPointer as i32
        );
        assert_eq!(
            cncrot_angles_from_matrices(1, 57, a.as_ptr(), 1, null_mut(), st.as_mut_ptr()),
            cncrot_status::NullPointer as i32
        );
        // n = 0 with valid pointers: success, nothing written.
        assert_eq!(
            cncrot_convert_many(0, 57, a.as_ptr(), 0, 1, 39, m.as_mut_ptr(), st.as_mut_ptr()),
            0
        );
    }
    assert!(m.iter().all(|&x| x == SENTINEL));
    assert_eq!(st, [99]);
}
