//! Program lines of arbitrary text in any dialect, one block after another on one state:
//! no crash, no hang, no read past `len`; a refused block leaves the state byte-identical and
//! `cncrot_program_column` reports the same status with a column inside the line (or one
//! past it), `cncrot_program_expected` the same status with a NUL-terminated text that
//! fits (what a missing word should be: never empty for one); an accepted one leaves a finite frame whose every writable form writes a line
//! that its dialect reads back as the same frame, and a sealed state of which single-bit
//! flips are refused; the program translated block by block into every dialect and form
//! (`cncrot_program_write_block`, with what each block restates) reads back as the same frames,
//! and a block that adds to the tilt, written as the target's increment, read twice there
//! gives the block read twice. Frames close to the forms' singularities (tilts of
//! 90° − 10^-k) go through every writer too: a refusal must be one the documentation names for that frame.
#![no_main]

#[path = "input.rs"]
mod input;

use cncrot::ffi::*;
use libfuzzer_sys::fuzz_target;
use std::ffi::CStr;
use std::mem::size_of;

fn as_bytes<T>(v: &T) -> Vec<u8> {
    // SAFETY: reads the object's own bytes.
    unsafe { std::slice::from_raw_parts((v as *const T).cast::<u8>(), size_of::<T>()).to_vec() }
}

/// The forms each dialect writes (what `cncrot_program_write` documents), with the form
/// code and selector of `cncrot_form_values` that give the same words, and whether the form
/// has origin words.
fn forms(dialect: i32) -> &'static [(&'static CStr, i32, i32, bool)] {
    match dialect {
        1 => &[
            (c"CYCLE800", CNCROT_FORM_CYCLE800, 57, true),
            (c"CYCLE800 185", CNCROT_FORM_CYCLE800, 185, true),
            (c"ROT", CNCROT_FORM_SINUMERIK_ROT, 0, false),
            (c"ROT EULER", CNCROT_FORM_SINUMERIK_ROT, 1, false),
        ],
        2 => &[
            (c"PLANE SPATIAL", CNCROT_FORM_PLANE_SPATIAL, 0, false),
            (c"PLANE EULER", CNCROT_FORM_PLANE_EULER, 0, false),
            (c"PLANE VECTOR", CNCROT_FORM_PLANE_VECTOR, 0, false),
            (c"PLANE POINTS", CNCROT_FORM_PLANE_POINTS, 0, false),
            (c"PLANE PROJECTED", CNCROT_FORM_PLANE_PROJECTED, 0, false),
        ],
        3 => &[(c"G68.2", CNCROT_FORM_G68_2, 0, true)],
        4 => &[
            (c"G158", CNCROT_FORM_G158, 10157, true),
            (c"G158 P10159", CNCROT_FORM_G158, 10159, true),
            (c"G68.2", CNCROT_FORM_G68_2, 0, true),
        ],
        5 => &[(c"ROT", CNCROT_FORM_TWINCAT_ROT, 0, false)],
        _ => &[
            (c"G268", CNCROT_FORM_G268, 123, true),
            (c"G268 Q213", CNCROT_FORM_G268, 213, true),
        ],
    }
}

fn mul(a: &[f64; 9], b: &[f64; 9]) -> [f64; 9] {
    std::array::from_fn(|k| (0..3).map(|j| a[3 * (k / 3) + j] * b[3 * j + k % 3]).sum())
}

/// A rotation about a machine axis (0 X, 1 Y, 2 Z), exact at whole right angles.
fn about(axis: usize, deg: f64) -> [f64; 9] {
    let (s, c) = deg.to_radians().sin_cos();
    let mut m = [0.0; 9];
    let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
    m[4 * axis] = 1.0;
    m[4 * i] = c;
    m[4 * j] = c;
    m[3 * j + i] = s;
    m[3 * i + j] = -s;
    m
}

fn frame(p: &cncrot_program) -> [f64; 16] {
    let mut f = [0.0; 16];
    // SAFETY: valid pointers.
    let s = unsafe { cncrot_program_frame(p, f.as_mut_ptr()) };
    assert_eq!(s, 0);
    f
}

fuzz_target!(|data: &[u8]| {
    let Some((&head, text)) = data.split_first() else {
        return;
    };
    let dialect = i32::from(head % 8);
    let mut p = cncrot_program::default();
    // Bits 6 and 7: the options (SINUMERIK Euler mode, Heidenhain axis angles).
    if head >> 6 != 0 {
        // SAFETY: p is valid.
        assert_eq!(
            unsafe { cncrot_program_init(&mut p, u32::from(head >> 6)) },
            0
        );
    }
    if (1..=6).contains(&dialect) {
        near_singular(dialect, text);
    }
    let mut translations: Vec<(i32, &CStr, bool, cncrot_program)> = (1..=6)
        .flat_map(|d| forms(d).iter().map(move |f| (d, f.0, f.3)))
        .map(|(d, form, has_origin)| {
            let mut q = cncrot_program::default();
            // SAFETY: q is valid.
            let init = unsafe { cncrot_program_init(&mut q, u32::from(form == c"ROT EULER")) };
            assert_eq!(init, 0);
            (d, form, has_origin, q)
        })
        .collect();
    let mut path: cncrot_tool_path = unsafe { std::mem::zeroed() };
    // The state before the last block, when that block was applied (0): whether it joins
    // the next one.
    let mut applied: Option<cncrot_program> = None;
    for line in text.split(|&b| b == b'\n') {
        // Each block in a heap buffer of exactly its length: AddressSanitizer sees any
        // over-read.
        let line: Box<[u8]> = line.to_vec().into_boxed_slice();
        tool_path(&mut path, dialect, &line);
        let again = p;
        let before = as_bytes(&p);
        // SAFETY: the line holds len bytes; p is valid.
        let s = unsafe { cncrot_program_line(&mut p, dialect, line.as_ptr().cast(), line.len()) };
        input::assert_known(s);
        // Only the block just before counts: whatever this one is, it ends the pair.
        let first = applied.take();
        let mut column = usize::MAX;
        // SAFETY: as above.
        let c = unsafe {
            cncrot_program_column(
                &again,
                dialect,
                line.as_ptr().cast(),
                line.len(),
                &mut column,
            )
        };
        assert_eq!(c, s, "the column function disagrees");
        let mut what = [0x5Au8; CNCROT_PROGRAM_EXPECTED_SIZE + 1];
        // SAFETY: as above; `what` holds more than the room given.
        let e = unsafe {
            cncrot_program_expected(
                &again,
                dialect,
                line.as_ptr().cast(),
                line.len(),
                what.as_mut_ptr().cast(),
                CNCROT_PROGRAM_EXPECTED_SIZE,
            )
        };
        assert_eq!(e, s, "the expected-word function disagrees");
        let nul = what.iter().position(|&b| b == 0).expect("NUL-terminated");
        assert!(nul < CNCROT_PROGRAM_EXPECTED_SIZE && what[CNCROT_PROGRAM_EXPECTED_SIZE] == 0x5A);
        assert!(what[..nul].iter().all(|b| (0x20..0x7f).contains(b)));
        if s == -21 {
            assert!(nul > 0, "a missing word that is not named");
        }
        if s >= 0 {
            assert_eq!(nul, 0);
        }
        if s < 0 {
            assert_eq!(as_bytes(&p), before, "status {s} changed the program");
            assert!(
                column <= line.len() + 1,
                "column {column} of {}",
                line.len()
            );
            if s == -19 || s == -20 || s == -21 {
                assert!(column >= 1);
            }
            continue;
        }
        assert_eq!(column, 0);
        // A block passed over or not followed leaves the state byte-identical.
        if s == 4 || s == 5 {
            assert_eq!(as_bytes(&p), before, "status {s} changed the program");
        }
        if p.active >= 2 {
            // A direct mode: the frame needs the machine.
            direct_on_machine(&p, &line);
        } else {
            let f = frame(&p);
            assert!(f.iter().all(|x| x.is_finite()));
            round_trips(dialect, &f);
            axes_of(&p, &line);
        }
        translated(&again, &p, &line, &mut translations);
        flips_are_refused(&p, line.len());
        kept(dialect, &again, &line);
        if s == 0 {
            joined(first.as_ref(), &again, &p);
            applied = Some(again);
        }
    }
});

/// What a translator keeps of a block read on `before`, `cncrot_program_rest`: no
/// longer than the block, its own rest, and read on `before` it changes no frame, shift or
/// tilt's increment (only a plane selection it may hold); `out` untouched when refused.
fn kept(dialect: i32, before: &cncrot_program, line: &[u8]) {
    let mut out = [0x5Au8; 520];
    let mut small = [0x5Au8; 4];
    // SAFETY: `line` holds its length in bytes, `out` and `small` theirs.
    let (s, t) = unsafe {
        (
            cncrot_program_rest(
                dialect,
                line.as_ptr().cast(),
                line.len(),
                out.as_mut_ptr().cast(),
                out.len(),
            ),
            cncrot_program_rest(
                dialect,
                line.as_ptr().cast(),
                line.len(),
                small.as_mut_ptr().cast(),
                small.len(),
            ),
        )
    };
    if s != 0 {
        assert!(s < 0 && out == [0x5Au8; 520], "rest {s}");
        return;
    }
    let n = out.iter().position(|&b| b == 0).expect("NUL-terminated");
    assert!(n <= line.len(), "a rest longer than its block");
    assert!(
        t == 0 || (t == -23 && small == [0x5Au8; 4]),
        "rest into 4 bytes: {t}"
    );
    if n == 0 {
        return;
    }
    let rest = out[..n].to_vec().into_boxed_slice();
    let mut again = [0x5Au8; 520];
    // SAFETY: as above.
    let r = unsafe {
        cncrot_program_rest(
            dialect,
            rest.as_ptr().cast(),
            n,
            again.as_mut_ptr().cast(),
            again.len(),
        )
    };
    assert_eq!(r, 0);
    assert_eq!(&again[..=n], &out[..=n], "the rest of a rest is itself");
    let mut q = *before;
    // SAFETY: as above; q is valid.
    let k = unsafe { cncrot_program_line(&mut q, dialect, rest.as_ptr().cast(), n) };
    if k >= 0 {
        assert!(
            q.rotation == before.rotation && q.origin == before.origin && q.shift == before.shift,
            "the rest of {:?} changed the frame: {:?}",
            String::from_utf8_lossy(line),
            String::from_utf8_lossy(&rest)
        );
    }
}

/// Two applied blocks in a row (`first` → `after` → `next`): `cncrot_program_joins` answers,
/// and a join is of blocks that leave the tilt's rotation alone in the second (a shift's
/// next axis, a turn to the plane), with the first one changing something or a tilt active.
fn joined(first: Option<&cncrot_program>, after: &cncrot_program, next: &cncrot_program) {
    let Some(first) = first else {
        return;
    };
    let mut join = -1;
    // SAFETY: valid states and a writable answer.
    let s = unsafe { cncrot_program_joins(first, after, next, &mut join) };
    assert_eq!(s, 0);
    assert!(join == 0 || join == 1);
    if join == 1 {
        // A direct mode's frame needs the machine: its positions stay instead.
        assert_eq!(
            (after.active >= 2, after.angles),
            (next.active >= 2, next.angles)
        );
        if after.active < 2 {
            let (f, g) = (frame(after), frame(next));
            for k in [0, 1, 2, 4, 5, 6, 8, 9, 10] {
                assert_eq!(f[k], g[k], "the second block turned the frame");
            }
        }
        assert!(as_bytes(first) != as_bytes(after) || after.active != 0);
    }
}

/// The fork head of the checks: C about Z carrying B about Y, B within ±100°, the pivot
/// 150 mm above the tool adapter.
fn fork_head() -> cncrot_machine {
    const CARR: &[u8] = b"$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1
$TC_CARR10[1]=0 $TC_CARR11[1]=1 $TC_CARR12[1]=0 $TC_CARR6[1]=-150 $TC_CARR23[1]=\"T\"
$TC_CARR31[1]=-100 $TC_CARR33[1]=100
";
    // SAFETY: every bit pattern of zeros is a valid description to fill.
    let mut m: cncrot_machine = unsafe { std::mem::zeroed() };
    // SAFETY: valid pointers and lengths.
    let s = unsafe { cncrot_machine_from_carr(&mut m, CARR.as_ptr().cast(), CARR.len(), 1) };
    assert_eq!(s, 0);
    m
}

/// A direct mode's state: `cncrot_program_frame` refuses it with the output untouched;
/// on the fork head, `cncrot_program_frame_on` gives the rotation `cncrot_machine_forward`
/// gives at the stated positions (by letter: C is axis 1, B axis 2, an A other than 0
/// refused; by place: axes 1 and 2), about the state's origin, and `cncrot_program_axes`
/// positions that give the same rotation.
/// The same block read as a five-axis program's: refusals and passed blocks leave the
/// state byte for byte, not followed ones all but the modes they set (and an arc's end
/// point); a state written holds finite numbers and a unit
/// direction; a CL point's axes on the fork head are finite or refused with them untouched,
/// and put the tip back on the point.
fn tool_path(path: &mut cncrot_tool_path, dialect: i32, line: &[u8]) {
    let before = *path;
    // SAFETY: valid pointers; the line holds len bytes.
    let s = unsafe { cncrot_tool_path_line(path, dialect, line.as_ptr().cast(), line.len()) };
    input::assert_known(s);
    if s == cncrot_status::NotFollowed as i32 && as_bytes(path) != as_bytes(&before) {
        // Only the modes the block sets (`on`, flags), whether it lost the tip (bit 5), and
        // an arc's end point (in an arc's mode, bit 3), the rotary positions it states; a
        // block after which a coordinate is still not known (bits 14 to 16) takes its words,
        // without a point.
        let mut moded = before;
        (moded.on, moded.flags, moded.point) = (path.on, path.flags, 0);
        if path.flags & 8 != 0 {
            moded.tip = path.tip;
        }
        if path.orientation == CNCROT_ORIENTATION_AXES {
            moded.orientation = path.orientation;
            moded.direction = path.direction;
            moded.axes = path.axes;
        }
        if path.flags & (7 << 14) == 7 << 14 {
            assert_eq!(as_bytes(path), as_bytes(&moded), "a block not followed");
        }
        assert_eq!(path.point, 0);
        assert!((0..1 << 17).contains(&path.flags) && (0..=1).contains(&path.on));
        assert!(path.tip.iter().all(|x| x.is_finite()));
        return;
    }
    if s != 0 {
        assert_eq!(
            as_bytes(path),
            as_bytes(&before),
            "status {s} changed the state"
        );
        return;
    }
    assert!(path.tip.iter().chain(&path.axes).all(|x| x.is_finite()));
    // A point is one whose tip, orientation and frame the reader knows: not while the tip
    // or the orientation is lost (bits 5, 11), nor in a frame, a shift, a compensation or
    // another change it does not compute (bits 6 to 9).
    if path.point == 1 {
        assert_eq!(
            path.flags & (32 | 64 | 128 | 256 | 512 | 2048),
            0,
            "{path:?}"
        );
    }
    if path.orientation == CNCROT_ORIENTATION_DIRECTION {
        let d = path.direction;
        assert!((d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - 1.0).abs() < 1e-12);
    }
    if path.point != 1 {
        return;
    }
    let m = fork_head();
    let prev = [0.0; 6];
    let mut axes = [input::SENTINEL; 6];
    // SAFETY: valid pointers.
    let r =
        unsafe { cncrot_tool_path_axes(path, &m, 50.0, prev.as_ptr(), 0, 0, axes.as_mut_ptr()) };
    input::check_outputs(r, &[&axes]);
    if r < 0 {
        return;
    }
    let mut pose = [0.0; 16];
    // SAFETY: valid pointers.
    let f = unsafe { cncrot_machine_tcp_forward(&m, axes.as_ptr(), 50.0, pose.as_mut_ptr()) };
    assert!(f >= 0);
    let scale = 1.0
        + path
            .tip
            .iter()
            .chain(&axes[..3])
            .fold(0.0f64, |a, x| a.max(x.abs()));
    for i in 0..3 {
        let e = (pose[4 * i + 3] - path.tip[i]).abs();
        assert!(e <= 1e-9 * scale, "tip {i}: {e}");
    }
}

fn direct_on_machine(p: &cncrot_program, line: &[u8]) {
    let mut f = [input::SENTINEL; 16];
    // SAFETY: valid pointers.
    let s = unsafe { cncrot_program_frame(p, f.as_mut_ptr()) };
    assert_eq!(s, cncrot_status::NotAvailable as i32);
    assert!(f.iter().all(|x| x.to_bits() == input::SENTINEL.to_bits()));
    let m = fork_head();
    let a = p.angles;
    let (positions, lacking) = if p.active == 2 {
        ([a[2], a[1], 0.0], a[0] != 0.0)
    } else {
        (a, a[2] != 0.0)
    };
    // SAFETY: valid pointers.
    let s = unsafe { cncrot_program_frame_on(p, &m, f.as_mut_ptr()) };
    input::check_outputs(s, &[&f]);
    let mut want = [0.0; 16];
    // SAFETY: valid pointers.
    let w = unsafe { cncrot_machine_forward(&m, positions.as_ptr(), want.as_mut_ptr()) };
    if lacking {
        assert_eq!(s, cncrot_status::BadArgument as i32);
    } else {
        assert_eq!(s, w);
    }
    if s == 0 {
        for (i, row) in [0usize, 4, 8].into_iter().enumerate() {
            assert_eq!(f[row..row + 3], want[row..row + 3]);
            assert_eq!(f[row + 3].to_bits(), (p.origin[i] + 0.0).to_bits());
        }
    }
    let current = [
        line.first().map_or(0.0, |&b| f64::from(b as i8) * 10.0),
        0.0,
        0.0,
    ];
    let mut ax = [input::SENTINEL; 3];
    // SAFETY: valid pointers.
    let s = unsafe { cncrot_program_axes(p, &m, current.as_ptr(), ax.as_mut_ptr()) };
    input::check_outputs(s, &[&ax]);
    if s >= 0 {
        let mut at = [0.0; 16];
        // SAFETY: valid pointers.
        assert_eq!(
            unsafe { cncrot_machine_forward(&m, ax.as_ptr(), at.as_mut_ptr()) },
            0
        );
        let scale = positions
            .iter()
            .chain(&ax)
            .fold(1.0f64, |a, x| a.max(x.abs()));
        for k in [0, 1, 2, 4, 5, 6, 8, 9, 10] {
            assert!(
                (at[k] - want[k]).abs() <= 1e-12 * scale,
                "{:?} {:?}",
                ax,
                positions
            );
        }
    }
}

/// The positions the state's tilt moves a fork head to (C about Z carrying B about Y, B
/// within ±100°), from a current position made of the line's bytes: the outputs written
/// only on success and then finite, the same as the machine's own choice under the rule the
/// state's choice words name (the closest without them; `TABLE ROT` has no table to turn on
/// a head).
fn axes_of(p: &cncrot_program, line: &[u8]) {
    let m = fork_head();
    let c = line.first().map_or(0.0, |&b| f64::from(b as i8) * 10.0);
    let current = [c, 0.0, 0.0];
    let (mut ax, mut want) = ([input::SENTINEL; 3], [0.0; 3]);
    // SAFETY: valid pointers.
    let s = unsafe { cncrot_program_axes(p, &m, current.as_ptr(), ax.as_mut_ptr()) };
    input::check_outputs(s, &[&ax]);
    let f = frame(p);
    let (mut res, mut rem) = ([0.0; 3], [0.0; 16]);
    // The state's own choice words; the default axis of a side (SEQ±, _DIR) on this head
    // is its master axis, B (axis 2, the one nearest the tool), of a direction of travel
    // (G53.1 P1/P2) the primary axis, C (axis 1, which carries B). Without words a Fanuc
    // tilt takes Fanuc's rule, on C too.
    let (rule, reference) = match (p.choice, p.reference_axis) {
        (CNCROT_CHOOSE_CLOSEST, _) if p.dialect == CNCROT_DIALECT_FANUC => {
            (CNCROT_CHOOSE_MASTER_FIRST, 1)
        }
        (CNCROT_CHOOSE_CLOSEST, _) => (CNCROT_CHOOSE_CLOSEST, 0),
        (c @ (CNCROT_CHOOSE_POSITIVE_TURN | CNCROT_CHOOSE_NEGATIVE_TURN), 0) => (c, 1),
        (c, 0) => (c, 2),
        (c, k) => (c, k),
    };
    // SAFETY: valid pointers.
    let s2 = unsafe {
        cncrot_machine_choose(
            &m,
            f.as_ptr(),
            current.as_ptr(),
            rule,
            reference,
            want.as_mut_ptr(),
            res.as_mut_ptr(),
            rem.as_mut_ptr(),
        )
    };
    // Heidenhain's SEQ: the angles themselves, not wound toward the current ones, and the
    // control's error where the side it names lies beyond the travel (where the choice
    // falls back to the other side).
    let seq = p.dialect == CNCROT_DIALECT_HEIDENHAIN
        && matches!(rule, CNCROT_CHOOSE_MINUS | CNCROT_CHOOSE_PLUS);
    if seq && s == cncrot_status::OutOfTravel as i32 && s2 >= 0 {
        return;
    }
    assert_eq!(
        s, s2,
        "program_axes and machine_choose disagree on the status"
    );
    if s >= 0 && seq {
        let turn = |x: f64| (x / 360.0).round() * 360.0;
        for (a, w) in ax.iter().zip(&want) {
            let d = (a - w) - turn(a - w);
            assert!(d.abs() < 1e-9, "{ax:?} {want:?}");
        }
    } else if s >= 0 {
        assert_eq!(ax.map(f64::to_bits), want.map(f64::to_bits));
    }
}

/// Some single-bit flips of an accepted state, spread over all its bytes: each refused.
fn flips_are_refused(p: &cncrot_program, salt: usize) {
    let bits = 8 * size_of::<cncrot_program>();
    for k in 0..8 {
        let bit = (salt * 31 + k * 137 + 7) % bits;
        let mut bytes = as_bytes(p);
        bytes[bit / 8] ^= 1 << (bit % 8);
        // SAFETY: every bit pattern is a valid cncrot_program (integers and doubles).
        let q: cncrot_program = unsafe { std::ptr::read_unaligned(bytes.as_ptr().cast()) };
        let mut f = [0.0; 16];
        // SAFETY: valid pointers.
        let s = unsafe { cncrot_program_frame(&q, f.as_mut_ptr()) };
        assert_eq!(
            s,
            cncrot_status::BadState as i32,
            "bit {bit} of an accepted state"
        );
    }
}

/// A frame `Rb(θ)·Ra(base ± (90° − 10^-k))·Rb(φ)` with an origin, from the input's bytes:
/// each form's singularities are at such tilts.
fn near_singular(dialect: i32, data: &[u8]) {
    let mut input = input::Input(data);
    let (a, b) = (usize::from(input.u8() % 3), usize::from(input.u8() % 3));
    let eps = 10f64.powi(-i32::from(input.u8() % 17));
    let base = f64::from(input.u8() % 4) * 90.0;
    let sign = if input.u8() & 1 == 0 { 1.0 } else { -1.0 };
    let (theta, phi) = (f64::from(input.u8() as i8), f64::from(input.u8() as i8));
    let r = mul(
        &mul(&about(b, theta), &about(a, base + sign * (90.0 - eps))),
        &about(b, phi),
    );
    let t = [
        f64::from(input.u8() as i8),
        0.0,
        f64::from(input.u8() as i8),
    ];
    let mut f = [0.0; 16];
    for i in 0..3 {
        f[4 * i..4 * i + 3].copy_from_slice(&r[3 * i..3 * i + 3]);
        f[4 * i + 3] = t[i];
    }
    f[15] = 1.0;
    round_trips(dialect, &f);
}

/// The program translated block by block into every dialect and form: the text
/// `cncrot_program_write_block` writes for the block and the state before and after it (with
/// what the block restates: a cancel or a datum shift with nothing changed), read in the
/// target dialect on its own translated state, gives the source's frame (and its way of
/// moving to a rotated plane where the target says it). A refusal is one the
/// documentation names (an origin for a form without origin words in a dialect that keeps no
/// shift apart, numbers the writer cannot write, a frame a form cannot express), leaves `out`
/// untouched and ends that translation.
fn translated(
    before: &cncrot_program,
    after: &cncrot_program,
    line: &[u8],
    translations: &mut Vec<(i32, &CStr, bool, cncrot_program)>,
) {
    if after.active >= 2 {
        translations.retain_mut(|(dialect, form, _, state)| {
            direct_translated(before, after, *dialect, form, state)
        });
        return;
    }
    let f = frame(after);
    let scale = f
        .iter()
        .chain(&after.shift)
        .fold(1.0f64, |a, x| a.max(x.abs()));
    translations.retain_mut(|(dialect, form, has_origin, state)| {
        let text = match write_and_read(before, after, Some(line), *dialect, form, state) {
            Ok(text) => text,
            Err(s) => {
                let origin = f[3] != 0.0 || f[7] != 0.0 || f[11] != 0.0;
                // (SINUMERIK's `ROT` writes an origin as `TRANS` and `AROT`.)
                let ok = (s == cncrot_status::HasOrigin as i32
                    && !*has_origin
                    && origin
                    && *dialect == 5)
                    || s == cncrot_status::OutOfRange as i32;
                assert!(ok, "{form:?} in dialect {dialect}: {s}");
                return false;
            }
        };
        let g = frame(state);
        // Where the target says how to move (Heidenhain's PLANE, G68.2's G53.1 and G53.6),
        // the way of moving to a rotated plane reads back. A tilt so small that the form's
        // angles round it to none (1e-22° about X is `EULNU+0`: cos of it is 1 in a double)
        // reads back unrotated (no tilt active), whose way of moving is Stay by definition.
        let says = *dialect == 2 || (*form == c"G68.2" && (*dialect == 3 || *dialect == 4));
        let rotated = |p: &cncrot_program| {
            p.active == 1
                && (0..3)
                    .any(|i| (0..3).any(|j| p.rotation[3 * i + j] != f64::from(u8::from(i == j))))
        };
        // A block that keeps the tilt and changes no way of moving (a datum shift under a
        // plane that turned the axes) moves nothing: written as staying, it may read back so.
        let motion = |p: &cncrot_program| {
            (
                p.positioning,
                p.retract,
                p.retract_mm.to_bits(),
                p.feed,
                p.feed_mm_min.to_bits(),
            )
        };
        let still = (before.rotation, before.active) == (after.rotation, after.active)
            && motion(before) == motion(after)
            && motion(state) == (0, CNCROT_RETRACT_NONE, 0, CNCROT_FEED_RAPID, 0);
        if says && rotated(after) && rotated(state) && !still {
            assert_eq!(
                state.positioning, after.positioning,
                "{form:?} in dialect {dialect}: {text}"
            );
        }
        // The choice words read back where the target has them: Heidenhain's SEQ for a
        // side of the master axis, G68.2's G53.1 P for its direction of travel.
        let sided = [CNCROT_CHOOSE_MINUS, CNCROT_CHOOSE_PLUS].contains(&after.choice);
        let turning =
            [CNCROT_CHOOSE_POSITIVE_TURN, CNCROT_CHOOSE_NEGATIVE_TURN].contains(&after.choice);
        let worded = (*dialect == 2 && sided)
            || (says && *dialect != 2 && turning && after.positioning != 0);
        if worded && after.reference_axis == 0 && rotated(after) && rotated(state) && !still {
            assert_eq!(
                (state.choice, state.reference_axis),
                (after.choice, 0),
                "{form:?} in dialect {dialect}: {text}"
            );
        }
        // The retraction reads back where the tilt block has words for it (PLANE's MB,
        // CYCLE800's _FR and _FR_I; a retraction along machine Z is MB MAX in a PLANE), the
        // feed in a PLANE.
        let cycle800 = form.to_bytes().starts_with(b"CYCLE800");
        if (*dialect == 2 || cycle800) && rotated(after) && rotated(state) && !still {
            let machine_z = [CNCROT_RETRACT_MACHINE_Z, CNCROT_RETRACT_MACHINE_Z_XY];
            let want = if *dialect == 2 && machine_z.contains(&after.retract) {
                CNCROT_RETRACT_TOOL_MAX
            } else {
                after.retract
            };
            assert_eq!(
                (state.retract, state.retract_mm.to_bits()),
                (want, after.retract_mm.to_bits()),
                "{form:?} in dialect {dialect}: {text}"
            );
            if *dialect == 2 {
                assert_eq!(
                    (state.feed, state.feed_mm_min.to_bits()),
                    (after.feed, after.feed_mm_min.to_bits()),
                    "{form:?} in dialect {dialect}: {text}"
                );
            }
        }
        let d = g
            .iter()
            .zip(&f)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            d <= 1e-11 * scale,
            "{form:?} in dialect {dialect}: {text}: {d:e}"
        );
        // A block that adds to the tilt, written as the target's increment, adds as often:
        // the text read again gives the block read again (a loop's second pass).
        // (`ROT`'s whole frame with an origin is `TRANS`, which replaces it, then `AROT`.)
        let increment = ["PLANE RELATIV", "G68.4", "AROT", " P01", ",\"\",1,"]
            .iter()
            .any(|w| text.contains(w))
            && !text.contains("TRANS");
        if after.relative == 1 && increment {
            let mut again = *after;
            // SAFETY: the line holds its length in bytes; the state is valid.
            let s = unsafe {
                cncrot_program_line(&mut again, after.dialect, line.as_ptr().cast(), line.len())
            };
            if s == 0 && again.active == 1 {
                let mut twice = *state;
                for block in text.split('\n') {
                    // SAFETY: as above.
                    let r = unsafe {
                        cncrot_program_line(
                            &mut twice,
                            *dialect,
                            block.as_ptr().cast(),
                            block.len(),
                        )
                    };
                    assert!(r >= 0, "{form:?}: {block}: {r}");
                }
                let (a, b) = (frame(&again), frame(&twice));
                let scale = a.iter().chain(&b).fold(1.0f64, |m, x| m.max(x.abs()));
                let d = a
                    .iter()
                    .zip(&b)
                    .map(|(x, y)| (x - y).abs())
                    .fold(0.0, f64::max);
                assert!(
                    d <= 1e-9 * scale,
                    "{form:?} in dialect {dialect}, twice: {text}: {d:e}"
                );
            }
        }
        true
    });
}

/// A direct mode translated: written in the target's direct mode where it names the axes
/// the same way (else `CNCROT_STATUS_NOT_AVAILABLE`, or numbers it cannot write:
/// `OUT_OF_RANGE`, with `out` untouched), it reads back as the same positions, exactly
/// (the shortest numbers), about the same origin.
fn direct_translated(
    before: &cncrot_program,
    after: &cncrot_program,
    dialect: i32,
    form: &CStr,
    state: &mut cncrot_program,
) -> bool {
    let text = match write_and_read(before, after, None, dialect, form, state) {
        Ok(text) => text,
        Err(s) => {
            assert!(
                s == cncrot_status::NotAvailable as i32 || s == cncrot_status::OutOfRange as i32,
                "{form:?} in dialect {dialect}: {s}"
            );
            return false;
        }
    };
    assert_eq!(state.active, after.active, "{form:?}: {text}");
    assert_eq!(
        state.angles.map(f64::to_bits),
        after.angles.map(f64::to_bits),
        "{form:?}: {text}"
    );
    let scale = after.origin.iter().fold(1.0f64, |a, x| a.max(x.abs()));
    for k in 0..3 {
        assert!(
            (state.origin[k] - after.origin[k]).abs() <= 1e-11 * scale,
            "{form:?}: {text}"
        );
    }
    true
}

/// The blocks `cncrot_program_write_block` (for a `block`) or `cncrot_program_write_change`
/// writes for `before` → `after` in `dialect` and `form`, each read into `state` (every one
/// accepted); a known refusal, with `out` untouched, as `Err`. The text never passes the room
/// given.
fn write_and_read(
    before: &cncrot_program,
    after: &cncrot_program,
    block: Option<&[u8]>,
    dialect: i32,
    form: &CStr,
    state: &mut cncrot_program,
) -> Result<String, i32> {
    let mut out = [0x5Au8; CNCROT_PROGRAM_CHANGE_MAX + 2];
    let (o, cap) = (out.as_mut_ptr().cast(), CNCROT_PROGRAM_CHANGE_MAX + 1);
    // SAFETY: valid pointers, out holds more than cap bytes.
    let s = unsafe {
        match block {
            Some(b) => cncrot_program_write_block(
                before,
                after,
                b.as_ptr().cast(),
                b.len(),
                dialect,
                form.as_ptr(),
                -1,
                o,
                cap,
            ),
            None => cncrot_program_write_change(before, after, dialect, form.as_ptr(), -1, o, cap),
        }
    };
    input::assert_known(s);
    assert_eq!(out[CNCROT_PROGRAM_CHANGE_MAX + 1], 0x5A);
    if s < 0 {
        assert!(out.iter().all(|&b| b == 0x5A), "{form:?}: {s} wrote");
        return Err(s);
    }
    let n = out.iter().position(|&b| b == 0).expect("NUL");
    if n > 0 {
        for block in out[..n].split(|&b| b == b'\n') {
            let text = String::from_utf8_lossy(block);
            // SAFETY: the block holds its length in bytes; state is valid.
            let r =
                unsafe { cncrot_program_line(state, dialect, block.as_ptr().cast(), block.len()) };
            assert!(r >= 0, "{form:?}: {text}: {r}");
        }
    }
    Ok(String::from_utf8_lossy(&out[..n]).into_owned())
}

fn round_trips(dialect: i32, f: &[f64; 16]) {
    let scale = f.iter().fold(1.0f64, |a, x| a.max(x.abs()));
    let mut rot_only = *f;
    for k in [3, 7, 11] {
        rot_only[k] = 0.0;
    }
    for &(form, code, selector, has_origin) in forms(dialect) {
        for g in [f, &rot_only] {
            let mut out = [0x5Au8; CNCROT_PROGRAM_LINE_MAX + 1];
            // SAFETY: valid pointers, out holds cap bytes.
            let s = unsafe {
                cncrot_program_write(
                    dialect,
                    form.as_ptr(),
                    g.as_ptr(),
                    -1,
                    out.as_mut_ptr().cast(),
                    out.len(),
                )
            };
            input::assert_known(s);
            if s < 0 {
                assert!(out.iter().all(|&b| b == 0x5A));
                refused_as_documented(form, code, selector, has_origin, g, s);
                continue;
            }
            let n = out.iter().position(|&b| b == 0).expect("NUL");
            let mut q = cncrot_program::default();
            // SAFETY: q is valid.
            let init = unsafe { cncrot_program_init(&mut q, u32::from(form == c"ROT EULER")) };
            assert_eq!(init, 0);
            // SAFETY: the line holds n bytes.
            let r = unsafe { cncrot_program_line(&mut q, dialect, out.as_ptr().cast(), n) };
            let line = String::from_utf8_lossy(&out[..n]);
            assert_eq!(r, 0, "{line}");
            let h = frame(&q);
            let d = h
                .iter()
                .zip(g)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            // Rotations to 1e-12; origins relative to their size.
            assert!(d <= 1e-11 * scale, "{line}: {d:e}");
        }
    }
}

/// A writer's refusal must be one its documentation names for this frame: an origin for a
/// form without origin words (`HAS_ORIGIN`); a frame the form cannot express, near a
/// projection's singularity (`OUT_OF_RANGE` from the form's own words too); numbers of 1e100
/// or more, or below 1e-100, or so long that the line exceeds the dialect's (`OUT_OF_RANGE`).
/// A frame of ordinary numbers that a form can express must be written.
fn refused_as_documented(
    form: &CStr,
    code: i32,
    selector: i32,
    has_origin: bool,
    g: &[f64; 16],
    s: i32,
) {
    let origin = g[3] != 0.0 || g[7] != 0.0 || g[11] != 0.0;
    if s == cncrot_status::HasOrigin as i32 {
        assert!(!has_origin && origin, "{form:?} refused a frame it writes");
        return;
    }
    assert_eq!(s, cncrot_status::OutOfRange as i32, "{form:?}: {s}");
    let mut n = 0usize;
    // SAFETY: valid pointers.
    assert_eq!(unsafe { cncrot_form_word_count(code, &mut n) }, 0);
    let mut w = [0.0; 9];
    // SAFETY: valid pointers, w holds n doubles.
    let v = unsafe { cncrot_form_values(code, selector, g.as_ptr(), w.as_mut_ptr(), n) };
    if v == cncrot_status::OutOfRange as i32 {
        return; // the form cannot express this frame: the same answer either way
    }
    assert!(v >= 0, "{form:?}: form_values {v}");
    // Numbers that take many digits: beyond 1e15 or below 1e-15 (or beyond the writable
    // range): the line may outgrow the dialect's.
    let long = w[..n]
        .iter()
        .any(|&x| x != 0.0 && !(1e-15..=1e15).contains(&x.abs()));
    assert!(long, "{form:?} refused ordinary words {:?}", &w[..n]);
}
