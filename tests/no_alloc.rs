//! Every exported function, on success and on error paths, allocates nothing.
//!
//! A counting global allocator counts the allocations made by this thread while
//! `COUNTING` is set. The table below must name every function the header declares: a
//! new export without an entry here fails `table_covers_the_header`.

use cncrot::ffi::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::ptr::{null, null_mut};

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

fn allocations(f: &dyn Fn()) -> usize {
    COUNT.with(|n| n.set(0));
    COUNTING.with(|c| c.set(true));
    f();
    COUNTING.with(|c| c.set(false));
    COUNT.with(|n| n.get())
}

const ID: [f64; 9] = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
const IDF: [f64; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];
const A: [f64; 3] = [30.0, 90.0, 60.0]; // singular for Tait-Bryan: exercises that branch too
const BAD: [f64; 3] = [f64::NAN, 0.0, 0.0];

type Call = (&'static str, fn());

/// Each entry calls its function on a success path, a singular or remark path where there
/// is one, and error paths (NULL, NaN, bad codes, non-rotation).
fn table() -> Vec<Call> {
    vec![
        ("cncrot_status_str", || {
            for s in [-100, -13, -1, 0, 1, 7] {
                let _ = cncrot_status_str(s);
            }
        }),
        ("cncrot_matrix_from_angles", || unsafe {
            let mut m = [0.0; 9];
            cncrot_matrix_from_angles(1, 57, A.as_ptr(), m.as_mut_ptr());
            cncrot_matrix_from_angles(1, 57, BAD.as_ptr(), m.as_mut_ptr());
            cncrot_matrix_from_angles(3, 57, A.as_ptr(), m.as_mut_ptr());
            cncrot_matrix_from_angles(1, 57, null(), m.as_mut_ptr());
        }),
        ("cncrot_angles_from_matrix", || unsafe {
            let mut a = [0.0; 3];
            let mut m = [0.0; 9];
            cncrot_matrix_from_angles(1, 57, A.as_ptr(), m.as_mut_ptr());
            cncrot_angles_from_matrix(1, 57, m.as_ptr(), a.as_mut_ptr());
            cncrot_angles_from_matrix(0, 25, ID.as_ptr(), a.as_mut_ptr());
            cncrot_angles_from_matrix(1, 3, ID.as_ptr(), a.as_mut_ptr());
            cncrot_angles_from_matrix(1, 57, [2.0; 9].as_ptr(), a.as_mut_ptr());
            cncrot_angles_from_matrix(1, 57, ID.as_ptr(), null_mut());
        }),
        ("cncrot_convert", || unsafe {
            let mut a = [0.0; 3];
            cncrot_convert(0, 57, A.as_ptr(), 1, 39, a.as_mut_ptr());
            cncrot_convert(0, 57, BAD.as_ptr(), 1, 39, a.as_mut_ptr());
            cncrot_convert(0, 57, A.as_ptr(), 1, 64, a.as_mut_ptr());
        }),
        ("cncrot_second_solution", || unsafe {
            let mut a = [0.0; 3];
            cncrot_second_solution(57, A.as_ptr(), a.as_mut_ptr());
            cncrot_second_solution(3, A.as_ptr(), a.as_mut_ptr());
        }),
        ("cncrot_closest_angles", || unsafe {
            let mut a = [0.0; 3];
            cncrot_closest_angles(1, 55, ID.as_ptr(), A.as_ptr(), a.as_mut_ptr());
            cncrot_closest_angles(1, 57, ID.as_ptr(), BAD.as_ptr(), a.as_mut_ptr());
        }),
        ("cncrot_check_rotation", || unsafe {
            cncrot_check_rotation(ID.as_ptr());
            cncrot_check_rotation([0.0; 9].as_ptr());
            cncrot_check_rotation(null());
        }),
        ("cncrot_nearest_rotation", || unsafe {
            let mut m = [0.0; 9];
            let measured = [1.0, 0.001, 0.0, -0.001, 1.0, 0.0, 0.0, 0.0, 1.0002];
            cncrot_nearest_rotation(measured.as_ptr(), m.as_mut_ptr());
            cncrot_nearest_rotation([0.0; 9].as_ptr(), m.as_mut_ptr());
        }),
        ("cncrot_add_rotation", || unsafe {
            let mut m = ID;
            cncrot_add_rotation(1, 57, A.as_ptr(), ID.as_ptr(), m.as_mut_ptr());
            cncrot_add_rotation(0, 57, A.as_ptr(), [3.0; 9].as_ptr(), m.as_mut_ptr());
        }),
        ("cncrot_rotate_vector", || unsafe {
            let mut v = [0.0; 3];
            cncrot_rotate_vector(ID.as_ptr(), A.as_ptr(), v.as_mut_ptr());
            cncrot_rotate_vector(ID.as_ptr(), BAD.as_ptr(), v.as_mut_ptr());
        }),
        ("cncrot_rotate_vector_inverse", || unsafe {
            let mut v = [0.0; 3];
            cncrot_rotate_vector_inverse(ID.as_ptr(), A.as_ptr(), v.as_mut_ptr());
            cncrot_rotate_vector_inverse(null(), A.as_ptr(), v.as_mut_ptr());
        }),
        ("cncrot_frame_from_angles", || unsafe {
            let mut f = [0.0; 16];
            cncrot_frame_from_angles(1, 57, A.as_ptr(), A.as_ptr(), A.as_ptr(), f.as_mut_ptr());
            cncrot_frame_from_angles(1, 57, A.as_ptr(), BAD.as_ptr(), A.as_ptr(), f.as_mut_ptr());
        }),
        ("cncrot_frame_about_point", || unsafe {
            let mut f = [0.0; 16];
            cncrot_frame_about_point(1, 57, A.as_ptr(), A.as_ptr(), f.as_mut_ptr());
            cncrot_frame_about_point(2, 57, A.as_ptr(), A.as_ptr(), f.as_mut_ptr());
        }),
        ("cncrot_frame_compose", || unsafe {
            let mut f = [0.0; 16];
            cncrot_frame_compose(IDF.as_ptr(), IDF.as_ptr(), f.as_mut_ptr());
            cncrot_frame_compose(IDF.as_ptr(), [0.0; 16].as_ptr(), f.as_mut_ptr());
        }),
        ("cncrot_frame_inverse", || unsafe {
            let mut f = [0.0; 16];
            cncrot_frame_inverse(IDF.as_ptr(), f.as_mut_ptr());
            cncrot_frame_inverse(null(), f.as_mut_ptr());
        }),
        ("cncrot_frame_transform_point", || unsafe {
            let mut p = [0.0; 3];
            cncrot_frame_transform_point(IDF.as_ptr(), A.as_ptr(), p.as_mut_ptr());
            cncrot_frame_transform_point(IDF.as_ptr(), BAD.as_ptr(), p.as_mut_ptr());
        }),
        ("cncrot_cycle600_gud_size", || {
            let _ = cncrot_cycle600_gud_size();
        }),
        ("cncrot_head_table_parse", || unsafe {
            let mut t: cncrot_head_table = std::mem::zeroed();
            let mut line = 0;
            let text = b"N1 _HEAD_NAME=\"IFVW207S\"\nN2 _DELTA_L1=540.735 _OFFS_H1_Z=0.247\n";
            cncrot_head_table_parse(&mut t, text.as_ptr().cast(), text.len(), &mut line);
            let bad = b"_HEAD_NAME=\"A\"\nDELTA_L2=1\n";
            cncrot_head_table_parse(&mut t, bad.as_ptr().cast(), bad.len(), &mut line);
        }),
        ("cncrot_cycle600", || unsafe {
            let mut gud: cncrot_cycle600_gud = std::mem::zeroed();
            let mut t: cncrot_head_table = std::mem::zeroed();
            let text = b"_HEAD_NAME=\"UFK600\"\n";
            cncrot_head_table_parse(&mut t, text.as_ptr().cast(), text.len(), null_mut());
            let name = c"UFK600".as_ptr();
            cncrot_cycle600(
                &mut gud, &t, 0, name, 1, 57, 0.0, 0.0, 0.0, 30.0, 45.0, 60.0, 0.0, 0.0, 0.0, 1,
                39, 0, 0, 0,
            );
            cncrot_cycle600(
                &mut gud, &t, 0, name, 1, 3, 1.0, 2.0, 3.0, 15.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, 27,
                1, 0, 0,
            );
            cncrot_cycle600(
                &mut gud,
                &t,
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
            );
            cncrot_cycle600(
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
            );
        }),
    ]
}

#[test]
fn no_exported_function_allocates() {
    for (name, call) in table() {
        // Once outside the count: lazily initialised runtime state (none expected) is not
        // charged to the function.
        call();
        let n = allocations(&call);
        assert_eq!(n, 0, "{name} allocated {n} times");
    }
}

#[test]
fn the_counter_counts() {
    // A test that cannot fail is a defect: make sure an allocation is seen.
    let n = allocations(&|| {
        let v: Vec<u8> = Vec::with_capacity(16);
        std::hint::black_box(v);
    });
    assert_eq!(n, 1);
}

#[test]
fn table_covers_the_header() {
    let header = include_str!("../include/cncrot.h");
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
    let mut covered: Vec<&str> = table().iter().map(|(n, _)| *n).collect();
    covered.sort_unstable();
    assert_eq!(declared, covered);
}
