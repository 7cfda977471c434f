//! Accuracy and identities of the Rust API over all 24 conventions. The full 10^6-rotation
//! measurement is `cargo run --release --example accuracy`; this runs a smaller sample with
//! the same bound so that a regression fails the test suite.

mod common;

use cncrot::*;
use common::{all_conventions, max_diff, reconstruction_error, Rng};

const N: usize = 100_000;

#[test]
fn reconstruction_within_1e15_random_and_near_singular() {
    let mut rng = Rng::new(7);
    let convs = all_conventions();
    for i in 0..N {
        let conv = convs[i % 24];
        let m = rng.rotation();
        let e = reconstruction_error(conv, &m);
        assert!(e <= 1e-15, "{conv:?} random: {e:e}");
        let delta = 10f64.powf(rng.range(-15.0, -3.0));
        let m = rng.near_singular(conv, delta);
        let e = reconstruction_error(conv, &m);
        assert!(e <= 1e-15, "{conv:?} near singular {delta:e}: {e:e}");
        let m = rng.near_singular(conv, if i % 2 == 0 { 0.0 } else { 1e-17 });
        let e = reconstruction_error(conv, &m);
        assert!(e <= 1e-15, "{conv:?} at singular: {e:e}");
    }
}

#[test]
fn canonical_ranges_and_no_negative_zero() {
    let mut rng = Rng::new(11);
    for conv in all_conventions() {
        for i in 0..2000 {
            let m = if i % 3 == 0 {
                rng.near_singular(conv, 0.0)
            } else {
                rng.rotation()
            };
            let d = angles_from_matrix(conv, &m).unwrap();
            let [a, b, c] = d.angles;
            assert!(
                a > -180.0 && a <= 180.0 && c > -180.0 && c <= 180.0,
                "{conv:?} {a} {c}"
            );
            if conv.sequence.is_proper_euler() {
                assert!((0.0..=180.0).contains(&b), "{conv:?} {b}");
            } else {
                assert!((-90.0..=90.0).contains(&b), "{conv:?} {b}");
            }
            for x in d.angles {
                assert!(!(x == 0.0 && x.is_sign_negative()), "-0 in {conv:?}");
            }
            if d.singular {
                assert_eq!(c, 0.0);
            }
        }
    }
}

#[test]
fn second_solution_and_closest_are_the_same_rotation() {
    let mut rng = Rng::new(13);
    for conv in all_conventions() {
        for _ in 0..500 {
            let m = rng.rotation();
            let d = angles_from_matrix(conv, &m).unwrap();
            let s = second_solution(conv.sequence, d);
            let ms = matrix_from_angles(conv.kind, conv.sequence.into(), s.angles);
            assert!(max_diff(&ms, &m) < 2e-15);
            assert_ne!(s.angles, d.angles);
            let reference = [
                rng.range(-1000.0, 1000.0),
                rng.range(-400.0, 400.0),
                rng.range(-1000.0, 1000.0),
            ];
            let c = closest_angles(conv, &m, reference).unwrap();
            let mc = matrix_from_angles(conv.kind, conv.sequence.into(), c.angles);
            assert!(max_diff(&mc, &m) < 1e-13);
            // No single whole turn brings any angle nearer to its reference.
            for (a, r) in c.angles.iter().zip(reference) {
                assert!((a - r).abs() <= 180.0 + 1e-9);
            }
        }
    }
}

#[test]
fn extrinsic_equals_reversed_intrinsic() {
    // Paper eq. 13: R_xyz (extrinsic) = R_z'y'x'' (intrinsic) with the same angles reversed.
    let mut rng = Rng::new(17);
    for s in Sequence::ALL {
        let a = [
            rng.range(-180.0, 180.0),
            rng.range(-90.0, 90.0),
            rng.range(-180.0, 180.0),
        ];
        let ext = matrix_from_angles(Kind::Extrinsic, s.into(), a);
        let int = matrix_from_angles(Kind::Intrinsic, s.reversed().into(), [a[2], a[1], a[0]]);
        assert!(max_diff(&ext, &int) < 1e-15);
    }
}

#[test]
fn composed_matrices_are_orthonormal() {
    let mut rng = Rng::new(19);
    for conv in all_conventions() {
        for _ in 0..1000 {
            let a = [
                rng.range(-1e6, 1e6),
                rng.range(-720.0, 720.0),
                rng.range(-400.0, 400.0),
            ];
            let m = matrix_from_angles(conv.kind, conv.sequence.into(), a);
            assert!(orthonormality_error(&m) <= 1e-15, "{conv:?} {a:?}");
            assert!((determinant(&m) - 1.0).abs() <= 1e-15);
        }
    }
}

#[test]
fn nearest_rotation_recovers_a_perturbed_rotation() {
    let mut rng = Rng::new(23);
    for _ in 0..1000 {
        let r = rng.rotation();
        let noisy = r.map(|row| row.map(|x| x + rng.range(-1e-4, 1e-4)));
        let n = nearest_rotation(&noisy).unwrap();
        assert!(orthonormality_error(&n) <= 1e-15);
        assert!(max_diff(&n, &r) < 3e-4);
        assert_eq!(check_rotation(&n), Ok(()));
        let scaled = r.map(|row| row.map(|x| 1000.0 * x));
        assert!(max_diff(&nearest_rotation(&scaled).unwrap(), &r) < 1e-14);
    }
    let mirror = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]];
    assert_eq!(nearest_rotation(&mirror), Err(Error::Degenerate));
    assert_eq!(nearest_rotation(&[[0.0; 3]; 3]), Err(Error::Degenerate));
    assert_eq!(nearest_rotation(&[[f64::NAN; 3]; 3]), Err(Error::NotFinite));
}

#[test]
fn frames_compose_and_invert() {
    let mut rng = Rng::new(29);
    for _ in 0..1000 {
        let f = Frame::with_translations(
            [
                rng.range(-1e3, 1e3),
                rng.range(-1e3, 1e3),
                rng.range(-1e3, 1e3),
            ],
            rng.rotation(),
            [
                rng.range(-1e3, 1e3),
                rng.range(-1e3, 1e3),
                rng.range(-1e3, 1e3),
            ],
        );
        let g = Frame::about_point(rng.rotation(), [rng.range(-1e3, 1e3), 0.0, 5.0]);
        let p = [
            rng.range(-1e3, 1e3),
            rng.range(-1e3, 1e3),
            rng.range(-1e3, 1e3),
        ];
        let direct = f.transform_point(g.transform_point(p));
        let composed = f.compose(&g).transform_point(p);
        assert!(direct
            .iter()
            .zip(composed)
            .all(|(a, b)| (a - b).abs() < 1e-9));
        let back = f.inverse().transform_point(f.transform_point(p));
        assert!(back.iter().zip(p).all(|(a, b)| (a - b).abs() < 1e-9));
    }
}

#[cfg(feature = "nalgebra")]
#[test]
fn nalgebra_interop_round_trips() {
    let mut rng = Rng::new(31);
    let m = rng.rotation();
    assert_eq!(from_nalgebra(&to_nalgebra(&m)), m);
    assert_eq!(to_nalgebra(&m)[(0, 2)], m[0][2]);
}
