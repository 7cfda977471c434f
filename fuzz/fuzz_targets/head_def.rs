//! HEAD_DEF text of arbitrary bytes, with a length that may stop short of the buffer. No
//! crash, no hang, no read past `len`, the table untouched on error with a plausible line
//! number, and on success a table whose every accessory CYCLE600 then finds.
#![no_main]

#[path = "input.rs"]
mod input;

use cncrot::ffi::*;
use libfuzzer_sys::fuzz_target;
use std::mem::size_of;

fn as_bytes<T>(v: &T) -> Vec<u8> {
    // SAFETY: reads the object's own bytes.
    unsafe { std::slice::from_raw_parts((v as *const T).cast::<u8>(), size_of::<T>()).to_vec() }
}

fuzz_target!(|data: &[u8]| {
    let Some((&mode, text)) = data.split_first() else {
        return;
    };
    // The text in a heap buffer of exactly its length: AddressSanitizer sees any over-read.
    let text: Box<[u8]> = text.to_vec().into_boxed_slice();
    let len = if mode & 1 == 1 {
        text.len() / 2
    } else {
        text.len()
    };
    // SAFETY: all-0x5A bytes form a valid (if odd) table; it must survive an error.
    let mut table: Box<cncrot_head_table> = Box::new(unsafe {
        std::mem::transmute::<[u8; size_of::<cncrot_head_table>()], cncrot_head_table>(
            [0x5Au8; size_of::<cncrot_head_table>()],
        )
    });
    let before = as_bytes(&*table);
    let mut line = -7;
    let line_ptr = if mode & 2 == 2 {
        std::ptr::null_mut()
    } else {
        &mut line as *mut i32
    };
    // SAFETY: text holds at least len bytes; table and line are valid or NULL.
    let s = unsafe { cncrot_head_table_parse(&mut *table, text.as_ptr().cast(), len, line_ptr) };
    input::assert_known(s);
    let lines = text[..len].iter().filter(|&&b| b == b'\n').count() + 1;
    if s < 0 {
        assert_eq!(as_bytes(&*table), before, "status {s} changed the table");
        if !line_ptr.is_null() {
            assert!(
                line >= 1 && line as usize <= lines,
                "line {line} of {lines}"
            );
        }
        return;
    }
    if !line_ptr.is_null() {
        assert_eq!(line, 0);
    }
    assert!((0..=16).contains(&table.count));
    // Deterministic: the same text gives the same table.
    let mut again: Box<cncrot_head_table> = Box::new(unsafe { std::mem::zeroed() });
    let s2 = unsafe {
        cncrot_head_table_parse(&mut *again, text.as_ptr().cast(), len, std::ptr::null_mut())
    };
    assert_eq!(s2, s);
    assert_eq!(as_bytes(&*again), as_bytes(&*table));
    // Every accessory read is found by CYCLE600.
    for h in &table.heads[..table.count as usize] {
        assert!(h.name.contains(&0));
        assert!(h.delta.iter().chain(&h.offsets).all(|x| x.is_finite()));
        let mut gud: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
        let r = unsafe {
            cncrot_cycle600(
                &mut gud,
                &*table,
                1,
                h.name.as_ptr(),
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
                57,
                0,
                0,
                0,
            )
        };
        assert_eq!(r, 0, "head {:?} not usable", &h.name[..]);
    }
});
