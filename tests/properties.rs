//! Property tests over all 24 conventions, frames and the CYCLE600 dialect: round trips,
//! orthonormality of every returned matrix (largest element of RᵀR − I at most 1e-15),
//! canonical ranges, and determinism (the same input gives the same bits on every call;
//! across threads see `concurrency.rs`).

mod common;

use cncrot::dialects::cycle600::{cycle600, Call, State};
use cncrot::dialects::head_def::HeadTable;
use cncrot::{
    add_rotation, angles_from_matrix, closest_angles, convert, decompose, determinant,
    matrix_from_angles, nearest_rotation, orthonormality_error, rotate, rotate_inverse,
    second_solution, AxisCode, Convention, Frame, Kind, Matrix, Sequence,
};
use common::max_diff;
use proptest::prelude::*;

const ORTHO: f64 = 1e-15;

fn convention() -> impl Strategy<Value = Convention> {
    (0usize..24).prop_map(|k| Convention::all().nth(k).unwrap())
}

/// Angles that hit the interesting places: arbitrary values, exact multiples of 90° (the
/// singular middle angles and exact table values), tiny values and huge ones (1e6°).
fn angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -360.0..360.0f64,
        2 => (-8i32..=8).prop_map(|k| f64::from(k) * 90.0),
        1 => (-8i32..=8, -1e-9..1e-9f64).prop_map(|(k, e)| f64::from(k) * 90.0 + e),
        1 => -1e6..1e6f64,
    ]
}

fn angles() -> impl Strategy<Value = [f64; 3]> {
    [angle(), angle(), angle()]
}

fn vector() -> impl Strategy<Value = [f64; 3]> {
    [-1e3..1e3f64, -1e3..1e3f64, -1e3..1e3f64]
}

fn code(c: Convention) -> AxisCode {
    AxisCode::from(c.sequence)
}

fn assert_rotation(m: &Matrix) -> Result<(), TestCaseError> {
    let e = orthonormality_error(m);
    prop_assert!(e <= ORTHO, "RᵀR − I = {e:e}");
    prop_assert!(determinant(m) > 0.0);
    Ok(())
}

fn assert_canonical(seq: Sequence, a: [f64; 3]) -> Result<(), TestCaseError> {
    let in_turn = |x: f64| x > -180.0 && x <= 180.0;
    prop_assert!(in_turn(a[0]) && in_turn(a[2]), "{a:?}");
    if seq.is_proper_euler() {
        prop_assert!((0.0..=180.0).contains(&a[1]), "{a:?}");
    } else {
        prop_assert!((-90.0..=90.0).contains(&a[1]), "{a:?}");
    }
    prop_assert!(
        a.iter().all(|x| x.to_bits() != (-0.0f64).to_bits()),
        "-0 in {a:?}"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10_000, ..ProptestConfig::default() })]

    #[test]
    fn composed_matrices_are_rotations(c in convention(), a in angles()) {
        assert_rotation(&matrix_from_angles(c.kind, code(c), a))?;
    }

    #[test]
    fn decomposition_reconstructs_the_matrix(c in convention(), a in angles()) {
        let m = matrix_from_angles(c.kind, code(c), a);
        let d = angles_from_matrix(c, &m).unwrap();
        assert_canonical(c.sequence, d.angles)?;
        let back = matrix_from_angles(c.kind, code(c), d.angles);
        prop_assert!(max_diff(&m, &back) <= 1e-15, "{:e}", max_diff(&m, &back));
        // The second solution is the same rotation, its angles in (-180°, 180°] (its middle
        // angle lies outside the first solution's range by construction).
        let s = second_solution(c.sequence, d);
        prop_assert!(s.angles.iter().all(|&x| x > -180.0 && x <= 180.0 && x.to_bits() != (-0.0f64).to_bits()), "{:?}", s.angles);
        // Its θ1 + 180° and θ3 + 180° are rounded to ulp(180°) = 2.8e-14° = 5e-16 rad each.
        let back2 = matrix_from_angles(c.kind, code(c), s.angles);
        prop_assert!(max_diff(&m, &back2) <= 2e-15, "{:e}", max_diff(&m, &back2));
    }

    #[test]
    fn conversion_keeps_the_rotation(from in convention(), to in convention(), a in angles()) {
        let m = matrix_from_angles(from.kind, code(from), a);
        let d = convert(from.kind, code(from), a, to);
        let back = matrix_from_angles(to.kind, code(to), d.angles);
        prop_assert!(max_diff(&m, &back) <= 1e-15, "{:e}", max_diff(&m, &back));
        // Intrinsic and extrinsic are the same rotation with the axis order reversed.
        let mirrored = Convention::new(
            match to.kind { Kind::Intrinsic => Kind::Extrinsic, Kind::Extrinsic => Kind::Intrinsic },
            to.sequence.reversed(),
        );
        let r = convert(from.kind, code(from), a, mirrored);
        let back_r = matrix_from_angles(mirrored.kind, code(mirrored), r.angles);
        prop_assert!(max_diff(&m, &back_r) <= 1e-15);
    }

    #[test]
    fn closest_angles_stay_near_the_reference(c in convention(), a in angles(), turns in [-3i32..=3, -3i32..=3, -3i32..=3]) {
        let m = matrix_from_angles(c.kind, code(c), a);
        let d = decompose(c, &m);
        let reference: [f64; 3] = core::array::from_fn(|k| d.angles[k] + 360.0 * f64::from(turns[k]));
        let near = closest_angles(c, &m, reference).unwrap();
        let back = matrix_from_angles(c.kind, code(c), near.angles);
        // Angles of several turns carry the rounding of their size: ulp(1080°) is 2.3e-13°.
        let size = near.angles.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let tol = 1e-15 + 2.0 * f64::EPSILON * size.to_radians();
        prop_assert!(max_diff(&m, &back) <= tol, "{:e} > {tol:e}", max_diff(&m, &back));
        for k in 0..3 {
            prop_assert!((near.angles[k] - reference[k]).abs() <= 180.0 + 1e-9, "{:?} {:?}", near.angles, reference);
        }
    }

    #[test]
    fn additive_rotations_compose_in_the_documented_order(c in convention(), a in angles(), b in angles()) {
        let old = matrix_from_angles(c.kind, code(c), a);
        let add = matrix_from_angles(c.kind, code(c), b);
        let r = add_rotation(c.kind, &old, &add);
        assert_rotation(&r)?;
        // Adding the inverse rotation takes us back.
        let inv: Matrix = core::array::from_fn(|i| core::array::from_fn(|j| add[j][i]));
        let back = add_rotation(c.kind, &r, &inv);
        prop_assert!(max_diff(&back, &old) <= 2e-15, "{:e}", max_diff(&back, &old));
    }

    #[test]
    fn vectors_rotate_and_back(c in convention(), a in angles(), v in vector()) {
        let m = matrix_from_angles(c.kind, code(c), a);
        let w = rotate_inverse(&m, rotate(&m, v));
        for k in 0..3 {
            prop_assert!((w[k] - v[k]).abs() <= 1e-12 * (1.0 + v[k].abs()));
        }
    }

    #[test]
    fn nearest_rotation_returns_a_rotation(c in convention(), a in angles(), noise in proptest::array::uniform9(-1e-3..1e-3f64)) {
        let m = matrix_from_angles(c.kind, code(c), a);
        let measured: Matrix = core::array::from_fn(|i| core::array::from_fn(|j| m[i][j] + noise[3 * i + j]));
        let r = nearest_rotation(&measured).unwrap();
        assert_rotation(&r)?;
        prop_assert!(max_diff(&r, &m) <= 3e-3);
        // A rotation is its own nearest rotation.
        let same = nearest_rotation(&m).unwrap();
        prop_assert!(max_diff(&same, &m) <= 1e-15, "{:e}", max_diff(&same, &m));
    }

    #[test]
    fn nearest_rotation_recovers_the_polar_factor(c in convention(), a in angles(), k in 0usize..3, squash in -6.0..0.0f64) {
        // M = R·diag(…, s, …) with s in [1e-6, 1]: its orthogonal polar factor is R itself,
        // and well determined (sensitivity 2/(σi + σj) <= 2), however small s is.
        let r = matrix_from_angles(c.kind, code(c), a);
        let s = 10f64.powf(squash);
        let m: Matrix = core::array::from_fn(|i| core::array::from_fn(|j| if j == k { r[i][j] * s } else { r[i][j] }));
        let p = nearest_rotation(&m).unwrap();
        assert_rotation(&p)?;
        prop_assert!(max_diff(&p, &r) <= 4e-15, "{:e}", max_diff(&p, &r));
    }

    #[test]
    fn frames_invert_and_compose(c in convention(), a in angles(), b in angles(), t1 in vector(), t2 in vector(), p in vector()) {
        let f = Frame::with_translations(t1, matrix_from_angles(c.kind, code(c), a), t2);
        let g = Frame::about_point(matrix_from_angles(c.kind, code(c), b), t2);
        for h in [f, g, f.compose(&g), f.inverse(), g.compose(&f.inverse())] {
            assert_rotation(&h.rotation)?;
        }
        let id = f.compose(&f.inverse());
        prop_assert!(max_diff(&id.rotation, &cncrot::IDENTITY) <= 2e-15);
        // The translation cancels to the rounding of its own size (ulp(2000) = 2.3e-13).
        let size = f.translation.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        prop_assert!(id.translation.iter().all(|x| x.abs() <= 16.0 * f64::EPSILON * size), "{:?}", id.translation);
        // Composition is application one after the other.
        let q = f.compose(&g).transform_point(p);
        let r = f.transform_point(g.transform_point(p));
        for k in 0..3 {
            prop_assert!((q[k] - r[k]).abs() <= 1e-11, "{q:?} {r:?}");
        }
    }

    #[test]
    fn cycle600_results_describe_its_frame(
        inexin in 0i32..=1, c_in in convention(), c_out in convention(),
        a in angles(), b in angles(), pos in vector(), pos_r in vector(),
    ) {
        let call = |ang: [f64; 3], rot_ad: i32| Call {
            inexin, mihead: b"UFK600", sw_rec: 1, bin_in: i32::from(c_in.sequence.code()), pos,
            ang, pos_r, inexout: c_out.kind.flag(), bin_out: i32::from(c_out.sequence.code()),
            rot_ad, rot_inv: 0, retr_z: 0,
        };
        let first = cycle600(&State::default(), None, &call(a, 0)).unwrap();
        let second = cycle600(&first, None, &call(b, 1)).unwrap();
        for s in [first, second] {
            assert_rotation(&s.frame.rotation)?;
            let r = s.results.unwrap();
            assert_canonical(c_out.sequence, r.angles)?;
            let m = matrix_from_angles(c_out.kind, code(c_out), r.angles);
            prop_assert!(max_diff(&m, &s.frame.rotation) <= 2e-15, "{:e}", max_diff(&m, &s.frame.rotation));
        }
        // Determinism: the same call on the same state gives the same bits.
        let again = cycle600(&first, None, &call(b, 1)).unwrap();
        prop_assert_eq!(format!("{again:?}"), format!("{second:?}"));
    }

    #[test]
    fn results_are_deterministic(c in convention(), a in angles()) {
        let m1 = matrix_from_angles(c.kind, code(c), a);
        let m2 = matrix_from_angles(c.kind, code(c), a);
        prop_assert_eq!(m1.map(|r| r.map(f64::to_bits)), m2.map(|r| r.map(f64::to_bits)));
        let d1 = decompose(c, &m1);
        let d2 = decompose(c, &m2);
        prop_assert_eq!(d1.angles.map(f64::to_bits), d2.angles.map(f64::to_bits));
        prop_assert_eq!(d1.singular, d2.singular);
    }

    #[test]
    fn head_def_text_reads_back_what_was_written(
        heads in proptest::collection::vec(
            (
                proptest::collection::vec(proptest::sample::select(b"ABCXYZ019_".to_vec()), 1..=31),
                0i32..=1,
                proptest::array::uniform9(-1_000_000_000i64..1_000_000_000),
            ),
            0..=16,
        ),
    ) {
        // Lengths and offsets in micrometres, written in millimetres as a setup sheet would.
        let keys = ["_DELTA_L1", "_DELTA_L2", "_DELTA_H1", "_OFFS_L1_X", "_OFFS_L1_Y",
                    "_OFFS_L2_X", "_OFFS_L2_Y", "_OFFS_H1_X", "_OFFS_H1_Z"];
        // Names are unique in a table: keep the first of each.
        let mut unique: Vec<&(Vec<u8>, i32, [i64; 9])> = Vec::new();
        for h in &heads {
            if !unique.iter().any(|u| u.0 == h.0) {
                unique.push(h);
            }
        }
        let mut text = String::from("N10 TZ7:\n");
        for (n, (name, allowed, values)) in unique.iter().enumerate() {
            let name = String::from_utf8_lossy(name);
            text += &format!("N{} _HEAD_NAME=\"{name}\" _HEAD_ALLOWED={allowed} ; head {n}\n", 20 + n);
            for (key, v) in keys.iter().zip(values) {
                text += &format!("{key}={}\n", *v as f64 / 1000.0);
            }
        }
        text += "GOTOF END\nEND:\nM17\n";
        let table = HeadTable::parse(text.as_bytes()).unwrap();
        prop_assert_eq!(table.count, unique.len());
        for (name, allowed, values) in unique {
            let h = table.find(name).unwrap();
            prop_assert_eq!(h.allowed, *allowed == 1);
            let read: Vec<f64> = h.delta.iter().chain(&h.offsets).copied().collect();
            let expect: Vec<f64> = values.iter().map(|v| *v as f64 / 1000.0).collect();
            prop_assert_eq!(read, expect);
        }
    }
}
