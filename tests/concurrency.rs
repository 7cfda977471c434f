//! Many threads calling every exported function on shared read-only inputs, each with its own
//! outputs, get bit for bit what one thread gets: there is no hidden shared state.

mod common;
#[path = "common/exports.rs"]
mod exports;

use cncrot::ffi::cncrot_angles_from_matrix;
use common::{all_conventions, Rng};
use exports::{covered_functions, declared_functions, table, Trace};

const THREADS: usize = 8;

#[test]
fn every_export_gives_the_same_results_in_every_thread() {
    assert_eq!(declared_functions(), covered_functions());
    let calls = table();
    let reference: Vec<Trace> = calls
        .iter()
        .map(|(_, call)| {
            let mut t = Trace::new();
            call(&mut t);
            t
        })
        .collect();
    std::thread::scope(|s| {
        for thread in 0..THREADS {
            let (calls, reference) = (&calls, &reference);
            s.spawn(move || {
                for round in 0..200 {
                    // Each thread walks the table from another starting point, so that
                    // different functions run at the same time.
                    for k in 0..calls.len() {
                        let i = (k + thread + round) % calls.len();
                        let (name, call) = &calls[i];
                        let mut t = Trace::new();
                        call(&mut t);
                        assert_eq!(t, reference[i], "{name} in thread {thread}");
                    }
                }
            });
        }
    });
}

#[test]
fn decompositions_in_parallel_equal_the_sequential_ones() {
    let mut rng = Rng::new(0xC0C0);
    let mut inputs: Vec<[f64; 9]> = Vec::new();
    for k in 0..500 {
        let conv = all_conventions()[k % 24];
        let m = if k % 2 == 0 {
            rng.rotation()
        } else {
            rng.near_singular(conv, 1e-9)
        };
        inputs.push(core::array::from_fn(|i| m[i / 3][i % 3]));
    }
    let run = |inputs: &[[f64; 9]]| -> Vec<u64> {
        let mut out = Vec::with_capacity(inputs.len() * 24 * 4);
        for m in inputs {
            for c in all_conventions() {
                let mut a = [0.0; 3];
                // SAFETY: valid arrays of 9 and 3 doubles.
                let s = unsafe {
                    cncrot_angles_from_matrix(
                        c.kind.flag(),
                        i32::from(c.sequence.code()),
                        m.as_ptr(),
                        a.as_mut_ptr(),
                    )
                };
                out.push(s as u64);
                out.extend(a.map(f64::to_bits));
            }
        }
        out
    };
    let reference = run(&inputs);
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..THREADS).map(|_| s.spawn(|| run(&inputs))).collect();
        for h in handles {
            assert!(h.join().unwrap() == reference);
        }
    });
}
