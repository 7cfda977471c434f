//! Program lines of arbitrary text in any dialect, one block after another on one state:
//! no crash, no hang, no read past `len`; a refused block leaves the state byte-identical and
//! `cncrot_program_column` reports the same status with a column inside the line (or one
//! past it); an accepted one leaves a finite frame whose every writable form writes a line
//! that its dialect reads back as the same frame.
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

/// The forms each dialect writes (what `cncrot_program_write` documents).
fn forms(dialect: i32) -> &'static [&'static CStr] {
    match dialect {
        1 => &[c"CYCLE800", c"CYCLE800 185", c"ROT", c"ROT EULER"],
        2 => &[
            c"PLANE SPATIAL",
            c"PLANE EULER",
            c"PLANE VECTOR",
            c"PLANE POINTS",
            c"PLANE PROJECTED",
        ],
        3 => &[c"G68.2"],
        4 => &[c"G158", c"G158 P10159", c"G68.2"],
        5 => &[c"ROT"],
        _ => &[c"G268", c"G268 Q213"],
    }
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
    let mut p = cncrot_program {
        options: u32::from(head >> 7),
        ..Default::default()
    };
    for line in text.split(|&b| b == b'\n') {
        // Each block in a heap buffer of exactly its length: AddressSanitizer sees any
        // over-read.
        let line: Box<[u8]> = line.to_vec().into_boxed_slice();
        let again = p;
        let before = as_bytes(&p);
        // SAFETY: the line holds len bytes; p is valid.
        let s = unsafe { cncrot_program_line(&mut p, dialect, line.as_ptr().cast(), line.len()) };
        input::assert_known(s);
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
        let f = frame(&p);
        assert!(f.iter().all(|x| x.is_finite()));
        round_trips(dialect, &f);
    }
});

fn round_trips(dialect: i32, f: &[f64; 16]) {
    let scale = f.iter().fold(1.0f64, |a, x| a.max(x.abs()));
    let mut rot_only = *f;
    for k in [3, 7, 11] {
        rot_only[k] = 0.0;
    }
    for form in forms(dialect) {
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
                // Forms without origin words, projections that cannot express the frame,
                // numbers beyond 1e100: refused, the buffer untouched.
                assert!([-8, -14].contains(&s), "{form:?}: {s}");
                assert!(out.iter().all(|&b| b == 0x5A));
                continue;
            }
            let n = out.iter().position(|&b| b == 0).expect("NUL");
            let mut q = cncrot_program {
                options: u32::from(*form == c"ROT EULER"),
                ..Default::default()
            };
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
