//! Measures the worst reconstruction error of the decomposition (angles → matrix, max
//! element difference) over random rotations and over rotations whose middle angle lies
//! 1e-15..1e-3 rad from its singular value, for all 24 conventions.
//!
//! `cargo run --release --example accuracy [rotations]` (default 1 000 000 per class).

#[path = "../tests/common/mod.rs"]
mod common;

use common::{all_conventions, reconstruction_error, Rng};

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let convs = all_conventions();
    let mut rng = Rng::new(0x5EED);
    let (mut worst_random, mut worst_near, mut worst_at) = (0.0f64, 0.0f64, 0.0f64);
    let mut at_flagged = 0usize;
    let mut singular_flagged = 0usize;
    for i in 0..n {
        let conv = convs[i % convs.len()];
        let m = rng.rotation();
        worst_random = worst_random.max(reconstruction_error(conv, &m));
        let delta = 10f64.powf(rng.range(-15.0, -3.0));
        let m = rng.near_singular(conv, delta);
        worst_near = worst_near.max(reconstruction_error(conv, &m));
        singular_flagged += cncrot::decompose(conv, &m).singular as usize;
        // At the singularity and within 1e-15 rad of it (a quarter of the draws exact).
        let delta = if i % 4 == 0 {
            0.0
        } else {
            10f64.powf(rng.range(-20.0, -15.0))
        };
        let m = rng.near_singular(conv, delta);
        worst_at = worst_at.max(reconstruction_error(conv, &m));
        at_flagged += cncrot::decompose(conv, &m).singular as usize;
    }
    println!("rotations per class: {n} (spread over the 24 conventions)");
    println!("worst reconstruction error, random rotations:       {worst_random:.3e}");
    println!("worst reconstruction error, middle angle 1e-15..1e-3 rad from singular:   {worst_near:.3e}");
    println!("near-singular inputs flagged singular: {singular_flagged}");
    println!(
        "worst reconstruction error, middle angle 0..1e-15 rad from singular:    {worst_at:.3e}"
    );
    println!("of those flagged singular: {at_flagged} of {n}");
}
