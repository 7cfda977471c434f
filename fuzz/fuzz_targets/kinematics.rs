//! Machines and targets from arbitrary bytes: swivel-data text, a HEAD_DEF accessory, axes
//! added one by one with any numbers, and raw `cncrot_machine` bytes (any field, any
//! count). No crash, no hang, no read past `len`; outputs untouched on every error; every
//! solution the inverse returns reproduces the target to 1e-9 through the forward
//! computation; a choice lies within the travel and on the Hirth grid; a target made with
//! an axis exactly at an end of its travel is chosen at that end; the follow-up keeps the
//! tool tip where it was; the five-axis transformation brings a pose it made back (tip and
//! direction) from any previous positions.
#![no_main]

#[path = "input.rs"]
mod input;

use cncrot::ffi::*;
use libfuzzer_sys::fuzz_target;
use std::mem::size_of;

fn f64_at(data: &[u8], k: usize) -> f64 {
    let mut b = [0u8; 8];
    for (i, x) in b.iter_mut().enumerate() {
        *x = data.get(8 * k + i).copied().unwrap_or(0);
    }
    let v = f64::from_le_bytes(b);
    // Half the numbers small and meaningful, half raw bit patterns (NaN, ∞, 1e300, -0).
    if b[7] & 0x80 == 0 {
        (i64::from_le_bytes(b) % 720_000) as f64 / 1000.0
    } else {
        v
    }
}

fn as_bytes<T>(v: &T) -> Vec<u8> {
    // SAFETY: reads the object's own bytes.
    unsafe { std::slice::from_raw_parts((v as *const T).cast::<u8>(), size_of::<T>()).to_vec() }
}

/// How far the orientation at `ax` is from the target; 0 when the forward computation
/// overflows (pivots near `f64::MAX`: the translation, which the inverse does not use).
fn miss(m: &cncrot_machine, ax: &[f64], target: &[f64; 16], whole: bool) -> f64 {
    let mut f = [0.0; 16];
    match unsafe { cncrot_machine_forward(m, ax.as_ptr(), f.as_mut_ptr()) } {
        0 => {}
        s if s == cncrot_status::OutOfRange as i32 => return 0.0,
        _ => return f64::INFINITY,
    }
    let mut worst: f64 = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            if whole || j == 2 {
                worst = worst.max((f[4 * i + j] - target[4 * i + j]).abs());
            }
        }
    }
    worst
}

/// The five-axis transformation on the machine: a pose made by the forward computation at
/// `pos` comes back to a tip within 1e-9 (relative to the sizes involved) and a direction
/// within 1e-9 from any previous positions; a refusal leaves the output untouched.
fn tcp(m: &cncrot_machine, n: usize, pos: &[f64; 3], current: &[f64; 3], t: &[u8]) {
    let length = f64_at(t, 8);
    let six = [
        f64_at(t, 9),
        f64_at(t, 10),
        f64_at(t, 11),
        pos[0],
        pos[1],
        pos[2],
    ];
    let mut pose = [9.0; 16];
    let s = unsafe { cncrot_machine_tcp_forward(m, six.as_ptr(), length, pose.as_mut_ptr()) };
    if s < 0 {
        assert_eq!(pose, [9.0; 16]);
        return;
    }
    assert!(pose.iter().all(|x| x.is_finite()));
    // The CL point of that pose (its tip, its direction scaled by the bytes): the same tip
    // and direction, an orthonormal frame; the bytes' direction as given, untouched on
    // refusal, finite otherwise.
    let tip = [pose[3], pose[7], pose[11]];
    let scale = f64_at(t, 12);
    let dir = [pose[2] * scale, pose[6] * scale, pose[10] * scale];
    let mut cl = [8.0; 16];
    let c = unsafe { cncrot_cl_pose(tip.as_ptr(), dir.as_ptr(), cl.as_mut_ptr()) };
    if c < 0 {
        assert_eq!(cl, [8.0; 16]);
    } else {
        assert!(cl.iter().all(|x| x.is_finite()));
        assert_eq!([cl[3], cl[7], cl[11]], tip);
        let s = scale.signum();
        for (k, i) in [2, 6, 10].into_iter().enumerate() {
            // A scale that leaves the components their precision (no underflow).
            if (1e-100..1e100).contains(&scale.abs()) {
                assert!(
                    (cl[i] - s * pose[i]).abs() < 1e-12,
                    "{cl:?} {pose:?} {scale}"
                );
            }
            let row = [cl[4 * k], cl[4 * k + 1], cl[4 * k + 2]];
            let n = row.iter().map(|x| x * x).sum::<f64>();
            assert!((n - 1.0).abs() < 1e-12, "{cl:?}");
        }
    }
    let mut junk = [8.0; 16];
    let free = [f64_at(t, 13), f64_at(t, 14), f64_at(t, 15)];
    let c = unsafe { cncrot_cl_pose(tip.as_ptr(), free.as_ptr(), junk.as_mut_ptr()) };
    if c < 0 {
        assert_eq!(junk, [8.0; 16]);
    } else {
        assert!(junk.iter().all(|x| x.is_finite()));
    }
    // Carried from the machine's pose to the bytes' direction: the same direction as
    // `cncrot_cl_pose` gives, an orthonormal frame; to the pose's own direction, the pose's
    // own rotation (no turn, no turn about the tool).
    let mut carried = [7.0; 16];
    let c = unsafe {
        cncrot_cl_pose_toward(
            tip.as_ptr(),
            free.as_ptr(),
            pose.as_ptr(),
            carried.as_mut_ptr(),
        )
    };
    if c < 0 {
        assert_eq!(carried, [7.0; 16]);
    } else {
        assert_eq!(
            [carried[2], carried[6], carried[10]],
            [junk[2], junk[6], junk[10]]
        );
        for k in 0..3 {
            let row = [carried[4 * k], carried[4 * k + 1], carried[4 * k + 2]];
            let n = row.iter().map(|x| x * x).sum::<f64>();
            assert!((n - 1.0).abs() < 1e-12, "{carried:?}");
        }
    }
    let own = [pose[2], pose[6], pose[10]];
    let c = unsafe {
        cncrot_cl_pose_toward(
            tip.as_ptr(),
            own.as_ptr(),
            pose.as_ptr(),
            carried.as_mut_ptr(),
        )
    };
    // (A forged seal's pose need not be a rotation: then refused, as any such previous.)
    let r: [f64; 9] = core::array::from_fn(|k| pose[4 * (k / 3) + k % 3]);
    if unsafe { cncrot_check_rotation(r.as_ptr()) } == 0 {
        assert_eq!(c, 0, "{pose:?}");
        for (a, b) in carried.iter().zip(&pose) {
            assert!((a - b).abs() < 1e-12, "{carried:?} {pose:?}");
        }
    } else {
        assert!(c < 0, "{pose:?}");
    }
    let prev = [0.0, 0.0, 0.0, current[0], current[1], current[2]];
    let mut out = [4.0; 6];
    let s = unsafe {
        cncrot_machine_tcp_inverse(m, pose.as_ptr(), length, prev.as_ptr(), out.as_mut_ptr())
    };
    // Every rule and reference axis the bytes give: untouched on refusal, finite otherwise.
    let (rule, reference) = (
        i32::from(t.first().copied().unwrap_or(0) % 7),
        i32::from(t.get(1).copied().unwrap_or(0) % 4),
    );
    let mut ruled = [6.0; 6];
    let r = unsafe {
        cncrot_machine_tcp_inverse_rule(
            m,
            pose.as_ptr(),
            length,
            prev.as_ptr(),
            rule,
            reference,
            ruled.as_mut_ptr(),
        )
    };
    if r < 0 {
        assert_eq!(ruled, [6.0; 6]);
    } else {
        assert!(ruled.iter().all(|x| x.is_finite()));
    }
    // A description read unchecked because its seal matches contents that are not a
    // machine's as the check leaves it (raw bytes whose hash the fuzzer's comparison tracing
    // computed: a forged seal) only has to stay finite, checked above: the same description
    // with no seal (checked whole) computes otherwise or is refused, and sealing, which
    // checks whole, either refuses it untouched or makes it what the check makes it.
    // Both ways are compared: an inverse refused alike (out of travel, say) would hide a
    // forward that computes otherwise (the fuzz target found such a forged seal).
    let mut whole = *m;
    whole.reserved = 0;
    let mut w = [4.0; 6];
    let ws = unsafe {
        cncrot_machine_tcp_inverse(&whole, pose.as_ptr(), length, prev.as_ptr(), w.as_mut_ptr())
    };
    let mut wp = [9.0; 16];
    let wf = unsafe { cncrot_machine_tcp_forward(&whole, six.as_ptr(), length, wp.as_mut_ptr()) };
    if (ws, as_bytes(&w)) != (s, as_bytes(&out)) || (wf, as_bytes(&wp)) != (0, as_bytes(&pose)) {
        let mut sealed = *m;
        if unsafe { cncrot_machine_seal(&mut sealed) } != 0 {
            assert_eq!(as_bytes(&sealed), as_bytes(m));
        }
        return;
    }
    // The description sealed and the same without a seal compute exactly alike (a machine
    // tcp_forward accepted and the whole check agrees with is one, so sealing it succeeds).
    let mut sealed = *m;
    assert_eq!(unsafe { cncrot_machine_seal(&mut sealed) }, 0);
    let mut unsealed = sealed;
    unsealed.reserved ^= 0x5a5a;
    for d in [&sealed, &unsealed] {
        let mut again = [4.0; 6];
        let s2 = unsafe {
            cncrot_machine_tcp_inverse(d, pose.as_ptr(), length, prev.as_ptr(), again.as_mut_ptr())
        };
        assert_eq!((s2, as_bytes(&again)), (s, as_bytes(&out)));
        let mut p2 = [9.0; 16];
        let f2 = unsafe { cncrot_machine_tcp_forward(d, six.as_ptr(), length, p2.as_mut_ptr()) };
        assert_eq!((f2, as_bytes(&p2)), (0, as_bytes(&pose)));
    }
    if s < 0 {
        assert_eq!(out, [4.0; 6]);
        return;
    }
    assert!(out.iter().all(|x| x.is_finite()));
    // A Hirth axis snaps (the status may name a free axis instead, which ranks first): the
    // tip stays on the target, the direction is off by the residual.
    let hirth = m.axes.iter().take(n).any(|a| a.hirth_step_deg > 0.0);
    let mut back = [0.0; 16];
    let s = unsafe { cncrot_machine_tcp_forward(m, out.as_ptr(), length, back.as_mut_ptr()) };
    if s != 0 {
        return;
    }
    // The sizes the tip is made of: rounding is relative to them.
    let scale = 1.0
        + six.iter().take(3).fold(0.0f64, |a, x| a.max(x.abs()))
        + out.iter().take(3).fold(0.0f64, |a, x| a.max(x.abs()))
        + length.abs()
        + m.axes
            .iter()
            .take(n)
            .flat_map(|a| a.point)
            .fold(0.0f64, |a, x| a.max(x.abs()));
    for i in 0..3 {
        let d = (back[4 * i + 3] - pose[4 * i + 3]).abs();
        assert!(
            d <= 1e-9 * scale,
            "tip {i}: {d} {pose:?} {back:?} {out:?} {length} {m:?}"
        );
        let e = (back[4 * i + 2] - pose[4 * i + 2]).abs();
        assert!(hirth || e <= 1e-9, "direction {i}: {e}");
    }
}

/// Whether `a` and `b` are the same angle to within `tol`, whole turns apart.
fn same_turn(a: f64, b: f64, tol: f64) -> bool {
    let d = (a - b).rem_euclid(360.0);
    d <= tol || 360.0 - d <= tol
}

/// A target made with a limited axis exactly at an end of its travel (the other limited
/// axes within theirs), seen from those positions, is reached at that end, never refused.
/// Checked whenever the inverse computes those positions to within the travel tolerance
/// (the contract; near a pole an axis is ill-determined and computed farther off) and no
/// axis has a Hirth grid (an end need not be a tooth).
fn end_of_travel(m: &cncrot_machine, n: usize, t: &[u8]) {
    let axes = &m.axes[..n];
    let limited: Vec<usize> = (0..n)
        .filter(|&j| axes[j].min_deg != 0.0 || axes[j].max_deg != 0.0)
        .collect();
    if limited.is_empty() || axes.iter().any(|a| a.hirth_step_deg != 0.0) {
        return;
    }
    let byte = |i: usize| t.get(i).copied().unwrap_or(0);
    let k = limited[usize::from(byte(0)) % limited.len()];
    let mut pos = [0.0; 3];
    for (j, p) in pos.iter_mut().enumerate().take(n) {
        let a = &axes[j];
        *p = if limited.contains(&j) {
            a.min_deg + f64::from(byte(j + 1)) / 255.0 * (a.max_deg - a.min_deg)
        } else {
            let x = f64_at(t, j);
            if x.is_finite() && x.abs() < 720.0 {
                x
            } else {
                0.0
            }
        };
    }
    let end = if byte(4) & 1 == 0 {
        axes[k].min_deg
    } else {
        axes[k].max_deg
    };
    pos[k] = end;
    let mut f = [0.0; 16];
    if unsafe { cncrot_machine_forward(m, pos.as_ptr(), f.as_mut_ptr()) } != 0 {
        return;
    }
    let mut sol = [0.0; 6];
    let mut count = 0usize;
    let s = unsafe { cncrot_machine_inverse(m, f.as_ptr(), sol.as_mut_ptr(), 2, &mut count) };
    let tolerance = 0.9 * CNCROT_MACHINE_TRAVEL_TOLERANCE_DEG;
    let computed = s == 0
        && sol
            .chunks(3)
            .take(count)
            .any(|row| (0..n).all(|j| same_turn(row[j], pos[j], tolerance)));
    if !computed {
        return;
    }
    let (mut out, mut res, mut rem) = ([0.0; 3], [0.0; 3], [0.0; 16]);
    let s = unsafe {
        cncrot_machine_choose(
            m,
            f.as_ptr(),
            pos.as_ptr(),
            CNCROT_CHOOSE_CLOSEST,
            0,
            out.as_mut_ptr(),
            res.as_mut_ptr(),
            rem.as_mut_ptr(),
        )
    };
    assert!(
        s >= 0,
        "status {s} at the end {end} of axis {k}: {pos:?} {m:?}"
    );
    let a = &axes[k];
    assert!(
        out[k] >= a.min_deg && out[k] <= a.max_deg && (out[k] - end).abs() <= 1e-8,
        "{out:?} for {pos:?} (axis {k} at {end}) {m:?}"
    );
}

fuzz_target!(|data: &[u8]| {
    let Some((&mode, rest)) = data.split_first() else {
        return;
    };
    let mut m: Box<cncrot_machine> = Box::new(unsafe { std::mem::zeroed() });
    match mode % 4 {
        0 => {
            // Swivel-data text in a heap buffer of exactly its length.
            let text: Box<[u8]> = rest.to_vec().into_boxed_slice();
            let before = as_bytes(&*m);
            let s = unsafe {
                cncrot_machine_from_carr(
                    &mut *m,
                    text.as_ptr().cast(),
                    text.len(),
                    1 + i32::from(mode >> 6),
                )
            };
            let mut line = -1;
            let s2 = unsafe {
                cncrot_machine_carr_error_line(
                    text.as_ptr().cast(),
                    text.len(),
                    1 + i32::from(mode >> 6),
                    &mut line,
                )
            };
            assert_eq!(s, s2);
            if s < 0 {
                assert_eq!(before, as_bytes(&*m));
                let lines = text.iter().filter(|&&b| b == b'\n').count() + 1;
                assert!(line >= 0 && line as usize <= lines);
                return;
            }
            assert_eq!(line, 0);
        }
        1 => {
            // Axes added one by one.
            for k in 0..4 {
                let base = 9 * k;
                let dir = [
                    f64_at(rest, base),
                    f64_at(rest, base + 1),
                    f64_at(rest, base + 2),
                ];
                let p = [
                    f64_at(rest, base + 3),
                    f64_at(rest, base + 4),
                    f64_at(rest, base + 5),
                ];
                let (lo, hi) = (f64_at(rest, base + 6), f64_at(rest, base + 7));
                let side = (f64_at(rest, base + 8).abs() as i32) % 3;
                let before = as_bytes(&*m);
                let s = unsafe {
                    cncrot_machine_add_axis(&mut *m, side, dir.as_ptr(), p.as_ptr(), lo, hi)
                };
                if s < 0 {
                    assert_eq!(before, as_bytes(&*m));
                }
            }
        }
        2 => {
            // Raw bytes as a description: every call must check it.
            let mut raw = [0u8; size_of::<cncrot_machine>()];
            for (d, s) in raw.iter_mut().zip(rest) {
                *d = *s;
            }
            // SAFETY: integers and doubles accept every bit pattern; the name is c_char.
            *m = unsafe {
                std::mem::transmute::<[u8; size_of::<cncrot_machine>()], cncrot_machine>(raw)
            };
        }
        _ => {
            // A HEAD_DEF accessory with given directions.
            let text = b"_HEAD_NAME=\"H\"\n_DELTA_L1=540.735 _DELTA_L2=250.049 _DELTA_H1=200.007\n";
            let mut table: Box<cncrot_head_table> = Box::new(unsafe { std::mem::zeroed() });
            unsafe {
                cncrot_head_table_parse(
                    &mut *table,
                    text.as_ptr().cast(),
                    text.len(),
                    std::ptr::null_mut(),
                )
            };
            let v1 = [f64_at(rest, 0), f64_at(rest, 1), f64_at(rest, 2)];
            let v2 = [f64_at(rest, 3), f64_at(rest, 4), f64_at(rest, 5)];
            let before = as_bytes(&*m);
            if unsafe {
                cncrot_machine_from_head(&mut *m, &*table, c"H".as_ptr(), v1.as_ptr(), v2.as_ptr())
            } < 0
            {
                assert_eq!(before, as_bytes(&*m));
            }
        }
    }
    // Positions and a target from the tail of the input.
    let tail = rest.len().saturating_sub(64);
    let t = &rest[tail..];
    let ax = [f64_at(t, 0), f64_at(t, 1), f64_at(t, 2)];
    let n = usize::try_from(m.count).unwrap_or(0).min(3);
    let mut pos = [0.0; 3];
    pos[..n].copy_from_slice(&ax[..n]);
    let mut f = [0.0; 16];
    let s = unsafe { cncrot_machine_forward(&*m, pos.as_ptr(), f.as_mut_ptr()) };
    if s < 0 {
        return;
    }
    assert!(f.iter().all(|x| x.is_finite()));
    let mut sol = [7.0; 6];
    let mut count = 99usize;
    let s = unsafe { cncrot_machine_inverse(&*m, f.as_ptr(), sol.as_mut_ptr(), 2, &mut count) };
    if s >= 0 {
        for row in sol.chunks(3).take(count) {
            assert!(miss(&m, row, &f, n == 3) < 1e-9, "{row:?} {m:?}");
        }
    } else {
        assert!(sol == [7.0; 6] && count == 99);
    }
    let cur = [f64_at(t, 3), f64_at(t, 4), f64_at(t, 5)];
    let mut current = [0.0; 3];
    current[..n].copy_from_slice(&cur[..n]);
    let rule = (f64_at(t, 6).abs() as i32) % 8;
    let refax = (f64_at(t, 7).abs() as i32) % 4;
    let (mut out, mut res, mut rem) = ([5.0; 3], [5.0; 3], [5.0; 16]);
    let s = unsafe {
        cncrot_machine_choose(
            &*m,
            f.as_ptr(),
            current.as_ptr(),
            rule,
            refax,
            out.as_mut_ptr(),
            res.as_mut_ptr(),
            rem.as_mut_ptr(),
        )
    };
    if s >= 0 {
        for (k, a) in m.axes.iter().enumerate().take(n) {
            if a.min_deg != 0.0 || a.max_deg != 0.0 {
                assert!(out[k] >= a.min_deg && out[k] <= a.max_deg, "{out:?} {a:?}");
            }
        }
        assert!(out.iter().chain(&res).chain(&rem).all(|x| x.is_finite()));
        // A direction of travel: the axis moved that way, or stayed (a rounding of the
        // tolerance the other way; a Hirth snap may stop half a tooth short).
        let k = (refax as usize).wrapping_sub(1);
        if let (CNCROT_CHOOSE_POSITIVE_TURN | CNCROT_CHOOSE_NEGATIVE_TURN, Some(&x), Some(&r)) =
            (rule, out.get(k), res.get(k))
        {
            let sign = if rule == CNCROT_CHOOSE_POSITIVE_TURN {
                1.0
            } else {
                -1.0
            };
            let moved = sign * (x - r - current[k]);
            assert!(
                (-1e-9..360.0 + 1e-9).contains(&moved),
                "{rule} {out:?} {current:?}"
            );
        }
    } else {
        assert!(out == [5.0; 3] && res == [5.0; 3] && rem == [5.0; 16]);
    }
    end_of_travel(&m, n, t);
    let lin = [f64_at(t, 6), f64_at(t, 7), 0.0];
    let mut next = [3.0; 3];
    let s = unsafe {
        cncrot_machine_follow(
            &*m,
            pos.as_ptr(),
            current.as_ptr(),
            lin.as_ptr(),
            100.0,
            next.as_mut_ptr(),
        )
    };
    if s < 0 {
        assert_eq!(next, [3.0; 3]);
    }
    tcp(&m, n, &pos, &current, t);
    let mut gud: Box<cncrot_cycle600_gud> = Box::new(unsafe { std::mem::zeroed() });
    unsafe {
        cncrot_cycle600(
            &mut *gud,
            std::ptr::null(),
            1,
            c"".as_ptr(),
            0,
            57,
            0.0,
            0.0,
            0.0,
            ax[0],
            ax[1],
            ax[2],
            0.0,
            0.0,
            0.0,
            1,
            39,
            0,
            i32::from(mode & 1),
            0,
        );
        cncrot_cycle600_position(
            &*gud,
            &*m,
            current.as_ptr(),
            out.as_mut_ptr(),
            res.as_mut_ptr(),
            rem.as_mut_ptr(),
        );
    }
});
