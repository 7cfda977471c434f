//! Every rotation and frame export with arguments made of arbitrary bytes: codes, flags,
//! NaN/Inf/subnormal/huge doubles, NULL pointers, outputs aliasing inputs. No crash, no hang,
//! no status outside the documented ones, outputs untouched on error and finite on success,
//! composed and repaired matrices orthonormal.
#![no_main]

#[path = "input.rs"]
mod input;

use cncrot::ffi::*;
use input::*;
use libfuzzer_sys::fuzz_target;

/// A matrix that is often a rotation (so that success paths are reached), sometimes a
/// rotation with one element replaced, sometimes nine arbitrary doubles.
fn matrix(inp: &mut Input) -> Box<[f64]> {
    let mut m = buffer(9, 0.0);
    let (kind, code, angles) = (inp.int(), inp.int(), inp.f64s::<3>());
    // SAFETY: valid buffers of 3 and 9 doubles.
    if unsafe { cncrot_matrix_from_angles(kind, code, angles.as_ptr(), m.as_mut_ptr()) } < 0 {
        m.copy_from_slice(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
    }
    match inp.u8() % 4 {
        0 => {
            let k = usize::from(inp.u8()) % 9;
            m[k] = inp.f64();
        }
        1 => m.iter_mut().for_each(|x| *x = inp.f64()),
        _ => {}
    }
    m
}

/// A frame that is often valid (built by cncrot), sometimes 16 arbitrary doubles.
fn frame(inp: &mut Input) -> Box<[f64]> {
    let mut f = buffer(16, 0.0);
    let (kind, code) = (inp.int(), inp.int());
    let (a, b, c) = (inp.f64s::<3>(), inp.f64s::<3>(), inp.f64s::<3>());
    // SAFETY: valid buffers.
    let s = unsafe {
        cncrot_frame_from_angles(
            kind,
            code,
            a.as_ptr(),
            b.as_ptr(),
            c.as_ptr(),
            f.as_mut_ptr(),
        )
    };
    if s < 0 || inp.u8().is_multiple_of(4) {
        f.iter_mut().for_each(|x| *x = inp.f64());
    }
    f
}

/// A form, a selector and a word count: mostly a valid form with a selector it has and its
/// own count, sometimes anything.
fn form_args(inp: &mut Input) -> (i32, i32, usize) {
    const SELECTORS: [i32; 20] = [
        0, 1, 2, 57, 27, 55, 3, 64, 185, 158, 167, 192, 123, 321, 213, 10157, 10159, 10400, 10300,
        1157,
    ];
    let form = match inp.u8() % 8 {
        0 => inp.int(),
        _ => i32::from(inp.u8() % 12) + 1,
    };
    let sel = match inp.u8() % 4 {
        0 => inp.int(),
        _ => SELECTORS[usize::from(inp.u8()) % SELECTORS.len()],
    };
    // The form's own count, from the library (for an unknown form, anything).
    let mut own = 0usize;
    // SAFETY: a valid pointer to a usize.
    let known = unsafe { cncrot_form_word_count(form, &mut own) } >= 0;
    let count = if known && !inp.u8().is_multiple_of(8) {
        own
    } else {
        usize::from(inp.u8() % 12)
    };
    (form, sel, count)
}

fn orthonormality(m: &[f64]) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            let dot: f64 = (0..3).map(|k| m[3 * k + i] * m[3 * k + j]).sum();
            worst = worst.max((dot - f64::from(u8::from(i == j))).abs());
        }
    }
    worst
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input(data);
    let op = inp.u8() % 24;
    let (n1, n2, n3, n4) = (inp.null(), inp.null(), inp.null(), inp.null());
    // SAFETY (every call below): each pointer is NULL or a heap buffer of the documented size.
    unsafe {
        match op {
            0 => {
                let s = inp.u64() as i32;
                assert!(!cncrot_status_str(s).is_null());
            }
            1 => {
                let (kind, code, a) = (inp.int(), inp.int(), buffer_from(&inp.f64s::<3>()));
                let mut m = buffer(9, SENTINEL);
                let s = cncrot_matrix_from_angles(kind, code, ptr(&a, n1), ptr_mut(&mut m, n2));
                check_outputs(s, &[&m]);
                if s >= 0 {
                    assert!(orthonormality(&m) <= 2e-15, "{:?}", &m[..]);
                }
            }
            2 => {
                let (kind, code, m) = (inp.int(), inp.int(), matrix(&mut inp));
                let mut a = buffer(3, SENTINEL);
                let s = cncrot_angles_from_matrix(kind, code, ptr(&m, n1), ptr_mut(&mut a, n2));
                check_outputs(s, &[&a]);
                if s >= 0 {
                    assert!(a.iter().all(|x| *x > -180.0 && *x <= 180.0), "{:?}", &a[..]);
                }
            }
            3 => {
                let (k1, c1, a) = (inp.int(), inp.int(), buffer_from(&inp.f64s::<3>()));
                let (k2, c2) = (inp.int(), inp.int());
                let mut out = buffer(3, SENTINEL);
                let s = cncrot_convert(k1, c1, ptr(&a, n1), k2, c2, ptr_mut(&mut out, n2));
                check_outputs(s, &[&out]);
            }
            4 => {
                let (code, a) = (inp.int(), inp.f64s::<3>());
                in_place_or_apart(n3, a, n1, n2, |i, o| cncrot_second_solution(code, i, o));
            }
            5 => {
                let (kind, code, m) = (inp.int(), inp.int(), matrix(&mut inp));
                let r = buffer_from(&inp.f64s::<3>());
                let mut out = buffer(3, SENTINEL);
                let s = cncrot_closest_angles(
                    kind,
                    code,
                    ptr(&m, n1),
                    ptr(&r, n2),
                    ptr_mut(&mut out, n3),
                );
                check_outputs(s, &[&out]);
            }
            6 => {
                let m = matrix(&mut inp);
                assert_known(cncrot_check_rotation(ptr(&m, n1)));
            }
            7 => {
                let m = matrix(&mut inp);
                let mut out = buffer(9, SENTINEL);
                let s = cncrot_nearest_rotation(ptr(&m, n1), ptr_mut(&mut out, n2));
                check_outputs(s, &[&out]);
                if s >= 0 {
                    assert!(orthonormality(&out) <= 2e-15, "{:?}", &out[..]);
                }
            }
            8 => {
                let (kind, code, a) = (inp.int(), inp.int(), buffer_from(&inp.f64s::<3>()));
                let old = matrix(&mut inp);
                let mut out = buffer(9, SENTINEL);
                let s = cncrot_add_rotation(
                    kind,
                    code,
                    ptr(&a, n1),
                    ptr(&old, n2),
                    ptr_mut(&mut out, n3),
                );
                check_outputs(s, &[&out]);
            }
            9 | 10 => {
                let f = if op == 9 {
                    cncrot_rotate_vector
                } else {
                    cncrot_rotate_vector_inverse
                };
                let (m, v) = (matrix(&mut inp), inp.f64s::<3>());
                in_place_or_apart(n4, v, n2, n3, |i, o| f(ptr(&m, n1), i, o));
            }
            11 => {
                let (kind, code) = (inp.int(), inp.int());
                let (a, b, c) = (inp.f64s::<3>(), inp.f64s::<3>(), inp.f64s::<3>());
                let (a, b, c) = (buffer_from(&a), buffer_from(&b), buffer_from(&c));
                let mut f = buffer(16, SENTINEL);
                let s = cncrot_frame_from_angles(
                    kind,
                    code,
                    ptr(&a, n1),
                    ptr(&b, n2),
                    ptr(&c, n3),
                    ptr_mut(&mut f, n4),
                );
                check_outputs(s, &[&f]);
            }
            12 => {
                let (kind, code) = (inp.int(), inp.int());
                let (a, p) = (buffer_from(&inp.f64s::<3>()), buffer_from(&inp.f64s::<3>()));
                let mut f = buffer(16, SENTINEL);
                let s = cncrot_frame_about_point(
                    kind,
                    code,
                    ptr(&a, n1),
                    ptr(&p, n2),
                    ptr_mut(&mut f, n3),
                );
                check_outputs(s, &[&f]);
            }
            13 => {
                let (a, b) = (frame(&mut inp), frame(&mut inp));
                let mut out = buffer(16, SENTINEL);
                let s = cncrot_frame_compose(ptr(&a, n1), ptr(&b, n2), ptr_mut(&mut out, n3));
                check_outputs(s, &[&out]);
            }
            14 => {
                let f = frame(&mut inp);
                let mut out = buffer(16, SENTINEL);
                let s = cncrot_frame_inverse(ptr(&f, n1), ptr_mut(&mut out, n2));
                check_outputs(s, &[&out]);
            }
            15 => {
                let (f, p) = (frame(&mut inp), buffer_from(&inp.f64s::<3>()));
                let mut out = buffer(3, SENTINEL);
                let s =
                    cncrot_frame_transform_point(ptr(&f, n1), ptr(&p, n2), ptr_mut(&mut out, n3));
                check_outputs(s, &[&out]);
            }
            16 => {
                let (form, sel, count) = form_args(&mut inp);
                let w: Vec<f64> = (0..count).map(|_| inp.f64()).collect();
                let w = buffer_from(&w);
                let mut f = buffer(16, SENTINEL);
                let s = cncrot_form_frame(form, sel, ptr(&w, n1), count, ptr_mut(&mut f, n2));
                check_outputs(s, &[&f]);
                if s >= 0 {
                    let r: Vec<f64> = (0..9).map(|k| f[4 * (k / 3) + k % 3]).collect();
                    assert!(orthonormality(&r) <= 2e-15, "{:?}", &f[..]);
                    assert_eq!(&f[12..], &[0.0, 0.0, 0.0, 1.0]);
                }
            }
            17 => {
                let (form, sel, count) = form_args(&mut inp);
                let f = frame(&mut inp);
                let mut w = buffer(count, SENTINEL);
                let s = cncrot_form_values(form, sel, ptr(&f, n1), ptr_mut(&mut w, n2), count);
                check_outputs(s, &[&w]);
                // Read back, the words give the frame again (projection angles are
                // ill-conditioned near a vertical first axis: not checked there).
                let projection = form == CNCROT_FORM_CYCLE800 && (sel >> 6) == 2;
                if s >= 0 && !projection {
                    let mut g = buffer(16, 0.0);
                    let t = cncrot_form_frame(form, sel, w.as_ptr(), count, g.as_mut_ptr());
                    assert!(
                        t >= 0,
                        "words {:?} of {:?} do not read back: {t}",
                        &w[..],
                        &f[..]
                    );
                    // A rotation rounded where it was written is written as its nearest
                    // rotation, which differs from it by about its distance from
                    // orthonormal.
                    let r: Vec<f64> = (0..9).map(|k| f[4 * (k / 3) + k % 3]).collect();
                    let off = orthonormality(&r);
                    for k in 0..12 {
                        let tol = if k % 4 == 3 {
                            1e-9 * (1.0 + f[k].abs())
                        } else {
                            1e-9 + 2.0 * off
                        };
                        assert!(
                            (g[k] - f[k]).abs() <= tol,
                            "{k}: {:?} vs {:?}",
                            &g[..],
                            &f[..]
                        );
                    }
                }
            }
            18 => {
                let form = inp.int();
                let mut n = usize::MAX;
                let np = if n1 {
                    std::ptr::null_mut()
                } else {
                    &mut n as *mut usize
                };
                let s = cncrot_form_word_count(form, np);
                assert_known(s);
                if s < 0 {
                    assert_eq!(n, usize::MAX, "count written on error");
                } else {
                    assert!((2..=CNCROT_FORM_MAX_WORDS).contains(&n));
                }
            }
            19 => {
                // Flange points: often on a tilted plane (so success is reached), or anything.
                let base = inp.f64s::<3>();
                let pts: [[f64; 3]; 4] = core::array::from_fn(|k| {
                    let d = inp.f64s::<3>();
                    if inp.u8() % 2 == 0 {
                        d
                    } else {
                        let along = [[0.0; 3], [100.0, 0.0, 0.0], [0.0; 3], [0.0, 100.0, 0.0]][k];
                        core::array::from_fn(|i| base[i] + along[i] + 0.01 * d[i].clamp(-1e3, 1e3))
                    }
                });
                let b: Vec<Box<[f64]>> = pts.iter().map(|p| buffer_from(p)).collect();
                let mut a = buffer(3, SENTINEL);
                let mut f = buffer(16, SENTINEL);
                let s = cncrot_probe_flange(
                    ptr(&b[0], n1),
                    ptr(&b[1], n2),
                    ptr(&b[2], n3),
                    ptr(&b[3], n4),
                    a.as_mut_ptr(),
                    f.as_mut_ptr(),
                );
                check_outputs(s, &[&a, &f]);
                if s >= 0 {
                    let r: Vec<f64> = (0..9).map(|k| f[4 * (k / 3) + k % 3]).collect();
                    assert!(orthonormality(&r) <= 2e-15, "{:?}", &f[..]);
                }
            }
            20 => {
                let n = usize::from(inp.u8() % 12);
                let w: Vec<f64> = (0..3 * n)
                    .map(|k| {
                        let x = inp.f64();
                        if k % 3 == 2 && inp.u8() % 2 == 0 {
                            5.0
                        } else {
                            x
                        }
                    })
                    .collect();
                let w = buffer_from(&w);
                let mut f = buffer(16, SENTINEL);
                let mut r = buffer(2, SENTINEL);
                let s =
                    cncrot_probe_plane(ptr(&w, n1), n, ptr_mut(&mut f, n2), ptr_mut(&mut r, n3));
                check_outputs(s, &[&f, &r]);
                if s >= 0 {
                    let m: Vec<f64> = (0..9).map(|k| f[4 * (k / 3) + k % 3]).collect();
                    assert!(orthonormality(&m) <= 2e-15, "{:?}", &f[..]);
                    assert!(r[0] >= 0.0 && r[1] >= 0.0, "{:?}", &r[..]);
                    // The tool's side: Z' never points down.
                    assert!(f[10] >= 0.0, "{:?}", &f[..]);
                }
                // Toward a side from the input (zero: the points' order): the same plane up
                // to the side of Z', the same flatness.
                let t = buffer_from(&inp.f64s::<3>());
                let mut g = buffer(16, SENTINEL);
                let mut q = buffer(2, SENTINEL);
                let s2 = cncrot_probe_plane_toward(
                    ptr(&w, n1),
                    n,
                    ptr(&t, n4),
                    ptr_mut(&mut g, n2),
                    ptr_mut(&mut q, n3),
                );
                check_outputs(s2, &[&g, &q]);
                if s >= 0 && s2 >= 0 {
                    assert_eq!(r[0].to_bits(), q[0].to_bits());
                    for k in [2, 6, 10] {
                        assert_eq!(f[k].abs().to_bits(), g[k].abs().to_bits(), "{k}");
                    }
                }
            }
            21 => {
                let f = frame(&mut inp);
                let (e1, e2) = (buffer_from(&inp.f64s::<3>()), buffer_from(&inp.f64s::<3>()));
                let mut a = buffer(1, SENTINEL);
                let mut out = buffer(16, SENTINEL);
                let s = cncrot_probe_edge(
                    ptr(&f, n1),
                    ptr(&e1, n2),
                    ptr(&e2, n3),
                    ptr_mut(&mut a, n4),
                    out.as_mut_ptr(),
                );
                check_outputs(s, &[&a, &out]);
            }
            22 => batch(&mut inp, n1, n2),
            _ => {
                assert_eq!(
                    cncrot_cycle600_gud_size(),
                    core::mem::size_of::<cncrot_cycle600_gud>()
                );
            }
        }
    }
});

/// Calls `f(input, output)` with one buffer for both (documented as allowed) or with two;
/// an error must leave the buffers as they were.
fn in_place_or_apart(
    in_place: bool,
    v: [f64; 3],
    null_in: bool,
    null_out: bool,
    f: impl Fn(*const f64, *mut f64) -> i32,
) {
    if in_place {
        let mut io = buffer_from(&v);
        let s = f(io.as_ptr(), io.as_mut_ptr());
        assert_known(s);
        if s < 0 {
            assert_eq!(bits(&io), bits(&v), "error changed the in-place buffer");
        }
    } else {
        let v = buffer_from(&v);
        let mut out = buffer(3, SENTINEL);
        let s = f(ptr(&v, null_in), ptr_mut(&mut out, null_out));
        check_outputs(s, &[&out]);
    }
}

fn buffer_from(v: &[f64]) -> Box<[f64]> {
    v.to_vec().into_boxed_slice()
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// A batch call with `n` rows in exactly sized buffers (or in place): a refusal before the
/// rows (NULL, a bad flag or code: what the single call gives on a valid row) writes
/// nothing; otherwise each row's status and output equal the single call's, failing rows
/// keep their contents, and the batch status is the first error's, else the first remark's.
///
/// # Safety
/// Calls the exports with buffers of the documented sizes.
unsafe fn batch(inp: &mut Input, null_in: bool, null_out: bool) {
    let n = usize::from(inp.u8() % 9);
    let which = inp.u8() % 4;
    let (k1, c1, k2, c2) = (inp.int(), inp.int(), inp.int(), inp.int());
    let with_statuses = inp.u8().is_multiple_of(2);
    let (width_in, width_out) = match which {
        0 => (3, 9),
        1 => (9, 3),
        _ => (3, 3),
    };
    let mut input = buffer(width_in * n, 0.0);
    for row in input.chunks_mut(width_in) {
        if width_in == 9 {
            row.copy_from_slice(&matrix(inp));
        } else {
            row.copy_from_slice(&inp.f64s::<3>());
        }
    }
    // The single call, on any row.
    let single = |row: *const f64, out: *mut f64| match which {
        0 => cncrot_matrix_from_angles(k1, c1, row, out),
        1 => cncrot_angles_from_matrix(k1, c1, row, out),
        _ => cncrot_convert(k1, c1, row, k2, c2, out),
    };
    const GOOD: [f64; 9] = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let mut scratch = [0.0; 9];
    let global = if null_in || null_out {
        Some(cncrot_status::NullPointer as i32)
    } else {
        let s = single(GOOD.as_ptr(), scratch.as_mut_ptr());
        (s < 0).then_some(s)
    };
    let in_place = which == 3;
    let before = input.clone();
    let mut out = if in_place {
        input.clone()
    } else {
        buffer(width_out * n, SENTINEL)
    };
    let mut st = vec![i32::MIN; n].into_boxed_slice();
    let st_ptr = if with_statuses {
        st.as_mut_ptr()
    } else {
        core::ptr::null_mut()
    };
    let (src, dst) = (ptr(&before, null_in), ptr_mut(&mut out, null_out));
    let r = match which {
        0 => cncrot_matrices_from_angles(k1, c1, src, n, dst, st_ptr),
        1 => cncrot_angles_from_matrices(k1, c1, src, n, dst, st_ptr),
        2 => cncrot_convert_many(k1, c1, src, n, k2, c2, dst, st_ptr),
        _ if null_in || null_out => cncrot_convert_many(k1, c1, src, n, k2, c2, dst, st_ptr),
        _ => {
            let p = out.as_mut_ptr();
            cncrot_convert_many(k1, c1, p, n, k2, c2, p, st_ptr)
        }
    };
    assert_known(r);
    let untouched = |out: &[f64]| {
        if in_place {
            out.iter()
                .zip(before.iter())
                .all(|(a, b)| a.to_bits() == b.to_bits())
        } else {
            out.iter().all(|x| x.to_bits() == SENTINEL.to_bits())
        }
    };
    if let Some(g) = global {
        assert_eq!(r, g, "refusal");
        assert!(
            untouched(&out) && st.iter().all(|&x| x == i32::MIN),
            "a refused batch wrote"
        );
        return;
    }
    let mut first_error = None;
    let mut first_remark = None;
    for i in 0..n {
        let row = &before[width_in * i..width_in * (i + 1)];
        let mut one = buffer(width_out, SENTINEL);
        let s = single(row.as_ptr(), one.as_mut_ptr());
        let got = &out[width_out * i..width_out * (i + 1)];
        let want: &[f64] = if s < 0 && in_place { row } else { &one };
        assert!(
            got.iter()
                .zip(want)
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            "row {i}"
        );
        if with_statuses {
            assert_eq!(st[i], s, "row {i}");
        }
        if s < 0 && first_error.is_none() {
            first_error = Some(s);
        } else if s > 0 && first_remark.is_none() {
            first_remark = Some(s);
        }
    }
    assert_eq!(r, first_error.or(first_remark).unwrap_or(0));
}
