//! Every exported function, on success and on error paths, allocates nothing.
//!
//! A counting global allocator counts the allocations made by this thread while
//! `COUNTING` is set. The table in `common/exports.rs` must name every function the header
//! declares: a new export without an entry there fails `table_covers_the_header`.

#[path = "common/exports.rs"]
mod exports;

use exports::{covered_functions, declared_functions, table, Trace};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static COUNT: Cell<usize> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = COUNTING.try_with(|c| {
            if c.get() {
                COUNT.with(|n| n.set(n.get() + 1));
            }
        });
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations(f: &mut dyn FnMut()) -> usize {
    COUNT.with(|n| n.set(0));
    COUNTING.with(|c| c.set(true));
    f();
    COUNTING.with(|c| c.set(false));
    COUNT.with(|n| n.get())
}

#[test]
fn no_exported_function_allocates() {
    for (name, call) in table() {
        // Once outside the count: lazily initialised runtime state (none expected) is not
        // charged to the function.
        call(&mut Trace::new());
        let mut trace = Trace::new();
        let n = allocations(&mut || call(&mut trace));
        assert_eq!(n, 0, "{name} allocated {n} times");
        assert!(trace.len() > 0, "{name} recorded nothing");
    }
}

#[test]
fn the_counter_counts() {
    // A test that cannot fail is a defect: make sure an allocation is seen.
    let n = allocations(&mut || {
        let v: Vec<u8> = Vec::with_capacity(16);
        std::hint::black_box(v);
    });
    assert_eq!(n, 1);
}

#[test]
fn table_covers_the_header() {
    assert_eq!(declared_functions(), covered_functions());
}
