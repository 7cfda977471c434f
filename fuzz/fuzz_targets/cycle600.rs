//! CYCLE600 with arbitrary states (as if restored from corrupt storage), arbitrary head
//! tables, names that are oversized or unterminated within their 32 bytes, and the 18
//! parameters made of arbitrary bytes; several calls in a row so that `_ROT_AD` accumulates.
//! No crash, no hang, the state untouched on error and valid on success.
#![no_main]

#[path = "input.rs"]
mod input;

use cncrot::ffi::*;
use core::ffi::c_char;
use input::*;
use libfuzzer_sys::fuzz_target;
use std::mem::{size_of, zeroed};

/// A plain C struct made of arbitrary bytes (every bit pattern is a valid value of it).
fn from_bytes<T: Copy>(inp: &mut Input) -> T {
    // SAFETY: T is one of cncrot's plain C structs of integers, chars and doubles.
    unsafe {
        let mut v: T = zeroed();
        let p = (&mut v as *mut T).cast::<u8>();
        for k in 0..size_of::<T>() {
            p.add(k).write(inp.u8());
        }
        v
    }
}

/// The state with the format and checksum a state written by the library carries.
fn sealed(mut g: cncrot_cycle600_gud) -> cncrot_cycle600_gud {
    g.format = CNCROT_CYCLE600_GUD_FORMAT;
    g.checksum = cncrot::crc32(&as_bytes(&g)[..212]);
    g
}

fn as_bytes<T>(v: &T) -> Vec<u8> {
    // SAFETY: reads the object's own bytes.
    unsafe { std::slice::from_raw_parts((v as *const T).cast::<u8>(), size_of::<T>()).to_vec() }
}

/// The `_MIHEAD` argument: a NUL-terminated string of 0..80 bytes (over 31 is too long), or
/// exactly 32 bytes without a NUL (the function must stop reading there).
fn name(inp: &mut Input) -> Vec<u8> {
    let pick = [&b"UFK600"[..], b"IFVW207S", b"A", b""];
    match inp.u8() % 4 {
        0 => (0..32).map(|_| inp.u8().max(1)).collect(),
        1 => {
            let mut v: Vec<u8> = (0..inp.u8() % 81).map(|_| inp.u8().max(1)).collect();
            v.push(0);
            v
        }
        _ => {
            let mut v = pick[usize::from(inp.u8()) % pick.len()].to_vec();
            v.push(0);
            v
        }
    }
}

fn heads(inp: &mut Input) -> Option<Box<cncrot_head_table>> {
    match inp.u8() % 3 {
        0 => None,
        1 => Some(Box::new(from_bytes(inp))),
        _ => {
            // SAFETY: a zeroed table is valid; the text is a valid buffer of its length.
            let mut t: Box<cncrot_head_table> = Box::new(unsafe { zeroed() });
            let text = b"_HEAD_NAME=\"UFK600\" _HEAD_ALLOWED=1\n_HEAD_NAME=\"IFVW207S\" _DELTA_L1=540.735\n";
            let s = unsafe {
                cncrot_head_table_parse(
                    &mut *t,
                    text.as_ptr().cast(),
                    text.len(),
                    std::ptr::null_mut(),
                )
            };
            assert_eq!(s, 0);
            Some(t)
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input(data);
    let mut gud: Box<cncrot_cycle600_gud> = match inp.u8() % 4 {
        0 => Box::new(from_bytes(&mut inp)),
        // Arbitrary fields with the right format and checksum, so that the checks behind
        // the checksum are reached too.
        1 => Box::new(sealed(from_bytes(&mut inp))),
        // SAFETY: zeroed is the documented initial state.
        _ => Box::new(unsafe { zeroed() }),
    };
    let table = heads(&mut inp);
    let table_ptr = table.as_deref().map_or(std::ptr::null(), |t| t as *const _);
    for _ in 0..4 {
        if inp.is_empty() {
            break;
        }
        let mihead = name(&mut inp);
        let mihead_ptr: *const c_char = if inp.null() {
            std::ptr::null()
        } else {
            mihead.as_ptr().cast()
        };
        let gud_ptr: *mut cncrot_cycle600_gud = if inp.null() {
            std::ptr::null_mut()
        } else {
            &mut *gud
        };
        let before = as_bytes(&*gud);
        let ints: [i32; 8] = core::array::from_fn(|_| inp.int());
        let d: [f64; 9] = inp.f64s::<9>();
        // SAFETY: pointers are NULL or valid; mihead is NUL-terminated or 32 bytes long.
        let s = unsafe {
            cncrot_cycle600(
                gud_ptr, table_ptr, ints[0], mihead_ptr, ints[1], ints[2], d[0], d[1], d[2], d[3],
                d[4], d[5], d[6], d[7], d[8], ints[3], ints[4], ints[5], ints[6], ints[7],
            )
        };
        assert_known(s);
        if s < 0 {
            assert_eq!(as_bytes(&*gud), before, "status {s} changed the state");
        } else {
            let g = &*gud;
            assert_eq!(g.active, 1);
            assert_eq!(as_bytes(&sealed(*g)), as_bytes(g), "state not sealed");
            assert!(g.cyc600_1.contains(&0), "name not terminated");
            assert!([g.cyc600_2, g.cyc600_3, g.cyc600_4]
                .iter()
                .all(|x| x.is_finite()));
            assert!(g.frame.iter().all(|x| x.is_finite()));
            // The stored state is accepted again: a further recalculation with it must not
            // report a corrupt state.
            let again = unsafe {
                cncrot_cycle600(
                    &mut *gud,
                    table_ptr,
                    1,
                    mihead.as_ptr().cast(),
                    1,
                    57,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    1,
                    57,
                    1,
                    0,
                    0,
                )
            };
            assert!(
                again >= 0,
                "a state written by cncrot_cycle600 was refused: {again}"
            );
        }
    }
});
