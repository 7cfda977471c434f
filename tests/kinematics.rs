//! Swivel kinematics: the forward computation against an independent one (nalgebra's
//! axis-angle rotations and plain matrix products), hand geometry for the usual machines,
//! forward(inverse(F)) = F for thousands of random machines, and a dense numerical search
//! that finds no solution the closed form missed.

mod common;

use cncrot::kinematics::{Hirth, Machine, RotaryAxis, Rule, Side, MAX_SOLUTIONS};
use cncrot::{elementary, mul, Axis, Error, Matrix, Vector};
use common::Rng;
use nalgebra::{Matrix4, Rotation3, Translation3, Unit, Vector3};

const Z: Vector = [0.0, 0.0, 1.0];

fn axis(side: Side, v: Vector, p: Vector) -> RotaryAxis {
    RotaryAxis::new(side, v, p)
}

fn machine(axes: &[RotaryAxis]) -> Machine {
    axes.iter()
        .fold(Machine::new(Z).unwrap(), |m, a| m.with_axis(*a).unwrap())
}

/// The forward computation written independently: 4x4 products of nalgebra's axis-angle
/// rotations about lines, `W⁻¹·T`, tool base +Z.
fn reference_forward(axes: &[RotaryAxis], theta: [f64; 3]) -> Matrix4<f64> {
    let mut t = Matrix4::<f64>::identity();
    let mut w = Matrix4::<f64>::identity();
    for (a, th) in axes.iter().zip(theta) {
        let v = Unit::new_normalize(Vector3::from(a.direction));
        let r = Rotation3::from_axis_angle(&v, (th - a.offset).to_radians()).to_homogeneous();
        let p = Vector3::from(a.point);
        let h =
            Translation3::from(p).to_homogeneous() * r * Translation3::from(-p).to_homogeneous();
        match a.side {
            Side::Tool => t *= h,
            Side::Work => w *= h,
        }
    }
    w.try_inverse().unwrap() * t
}

fn random_direction(rng: &mut Rng) -> Vector {
    loop {
        let v = [rng.normal(), rng.normal(), rng.normal()];
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if n > 0.1 {
            return v.map(|x| x / n);
        }
    }
}

/// A random machine of `n` axes: random sides, directions (a third of them axis-aligned
/// or at 45°, like real heads), pivots within ±500 mm, offsets.
fn random_machine(rng: &mut Rng, n: usize) -> (Machine, Vec<RotaryAxis>) {
    loop {
        let mut axes = Vec::new();
        for _ in 0..n {
            let side = if rng.unit() < 0.5 {
                Side::Tool
            } else {
                Side::Work
            };
            let dir = match (rng.next_u64() % 6) as usize {
                0 => [0.0, 0.0, 1.0],
                1 => [1.0, 0.0, 0.0],
                2 => [0.0, (0.5f64).sqrt(), (0.5f64).sqrt()],
                _ => random_direction(rng),
            };
            let p = [0.0; 3].map(|_: f64| rng.range(-500.0, 500.0));
            let mut a = axis(side, dir, p);
            if rng.unit() < 0.3 {
                a.offset = rng.range(-90.0, 90.0);
            }
            axes.push(a);
        }
        let built = axes
            .iter()
            .try_fold(Machine::new(Z).unwrap(), |m, a| m.with_axis(*a));
        if let Ok(m) = built {
            let stored = m.axes().to_vec();
            return (m, stored);
        }
    }
}

fn angles(rng: &mut Rng, n: usize) -> [f64; 3] {
    let mut t = [0.0; 3];
    for x in t.iter_mut().take(n) {
        *x = rng.range(-180.0, 180.0);
    }
    t
}

/// The largest difference between the reached orientation and the target: the whole
/// rotation with three axes, the tool direction with fewer.
fn miss(m: &Machine, theta: [f64; 3], target: &Matrix) -> f64 {
    let r = m.forward(theta).unwrap().rotation;
    let n = m.axes().len();
    let mut worst: f64 = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            if n == 3 || j == 2 {
                worst = worst.max((r[i][j] - target[i][j]).abs());
            }
        }
    }
    worst
}

fn same_turn(a: f64, b: f64, tol: f64) -> bool {
    let d = (a - b).rem_euclid(360.0);
    d < tol || 360.0 - d < tol
}

#[test]
fn forward_matches_an_independent_computation() {
    let mut rng = Rng::new(10);
    for n in 1..=3 {
        for _ in 0..2000 {
            let (m, axes) = random_machine(&mut rng, n);
            let theta = angles(&mut rng, n);
            let f = m.forward(theta).unwrap().to_homogeneous();
            let r = reference_forward(&axes, theta);
            for i in 0..4 {
                for j in 0..4 {
                    let tol = if j == 3 { 1e-9 } else { 1e-13 };
                    assert!(
                        (f[i][j] - r[(i, j)]).abs() < tol,
                        "{n} {theta:?}\n{f:?}\n{r}"
                    );
                }
            }
        }
    }
}

#[test]
fn fork_head_and_table_by_hand() {
    // Head C (about Z) carrying B (about Y): tool direction (cos C sin B, sin C sin B, cos B).
    let head = machine(&[
        axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]),
        axis(Side::Tool, [0.0, 1.0, 0.0], [0.0, 0.0, 250.0]),
    ]);
    let (c, b) = (30f64, 40f64);
    let d = head.forward([c, b, 0.0]).unwrap().rotation;
    let want = [
        c.to_radians().cos() * b.to_radians().sin(),
        c.to_radians().sin() * b.to_radians().sin(),
        b.to_radians().cos(),
    ];
    for k in 0..3 {
        assert!((d[k][2] - want[k]).abs() < 1e-15);
    }
    // The tool tip of a 100 mm tool: the pivot 250 above the adapter; pivot-to-tip 350 mm
    // along the tilted tool.
    let tip = head.tool_tip([c, b, 0.0], [0.0; 3], 100.0).unwrap();
    for k in 0..3 {
        assert!(
            (tip[k] - ([0.0, 0.0, 250.0][k] - 350.0 * want[k])).abs() < 1e-12,
            "{tip:?}"
        );
    }

    // Table A (about X, turning the workpiece) carrying C (about Z): the tool, fixed along
    // +Z in the machine, seen from the workpiece: Rz(-C)·Rx(-A)·e_z.
    let table = machine(&[
        axis(Side::Work, [1.0, 0.0, 0.0], [0.0; 3]),
        axis(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]),
    ]);
    let (a, c) = (25f64, 70f64);
    let f = table.forward([a, c, 0.0]).unwrap().rotation;
    let r = mul(&elementary(Axis::Z, -c), &elementary(Axis::X, -a));
    assert!(common::max_diff(&f, &r) < 1e-15);
}

#[test]
fn nutating_head_tilt_by_hand() {
    // A 45° nutating head: B' about (0, √½, √½) on C. The tool tilt β for B' = θ satisfies
    // cos β = cos²45° + sin²45°·cos θ = (1 + cos θ)/2.
    let s = 0.5f64.sqrt();
    let m = machine(&[
        axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]),
        axis(Side::Tool, [0.0, s, s], [0.0, 0.0, 150.0]),
    ]);
    for beta in [0.0, 10.0, 45.0, 60.0, 89.0, 90.0] {
        let target = mul(&elementary(Axis::Z, 20.0), &elementary(Axis::X, -beta));
        let sol = m.inverse(&target).unwrap();
        let theta = (2.0 * beta.to_radians().cos() - 1.0).acos().to_degrees();
        for row in sol.as_slice() {
            assert!(miss(&m, *row, &target) < 1e-12, "{beta} {row:?}");
            assert!(
                (row[1].abs() - theta).abs() < 1e-6,
                "{beta} {row:?} {theta}"
            );
        }
        if beta == 0.0 {
            assert!(sol.free && sol.count == 1, "{sol:?}");
        } else if beta == 90.0 {
            // The edge of the reachable cone: the two solutions meet at θ = 180°.
            assert_eq!(sol.count, 1, "{sol:?}");
        } else {
            assert_eq!(sol.count, 2, "{beta}");
        }
    }
    // Beyond 90° the head cannot tilt.
    let target = elementary(Axis::X, -100.0);
    assert_eq!(m.inverse(&target), Err(Error::Unreachable));
}

/// forward(inverse(F)) = F for every returned solution, and the positions F was made
/// from are among them (a solution within one turn is never lost).
#[test]
fn inverse_reproduces_random_targets() {
    let mut rng = Rng::new(11);
    let mut checked = 0;
    for n in 1..=3 {
        for _ in 0..4000 {
            let (m, _) = random_machine(&mut rng, n);
            let theta = angles(&mut rng, n);
            let target = m.forward(theta).unwrap().rotation;
            let sol = m
                .inverse(&target)
                .unwrap_or_else(|e| panic!("{e:?} {m:?} {theta:?}"));
            assert!(sol.count >= 1 && sol.count <= MAX_SOLUTIONS);
            for row in sol.as_slice() {
                assert!(miss(&m, *row, &target) < 1e-12, "{m:?}\n{theta:?} {row:?}");
                assert!(row.iter().all(|x| *x > -180.0 && *x <= 180.0));
                assert!(row[n..].iter().all(|x| *x == 0.0));
            }
            if !sol.free {
                let found = sol
                    .as_slice()
                    .iter()
                    .any(|row| (0..n).all(|k| same_turn(row[k], theta[k], 1e-6)));
                assert!(found, "{m:?}\n{theta:?} {sol:?}");
            }
            checked += sol.count;
        }
    }
    assert!(checked > 12000);
}

/// Gauss–Newton from many starting points on a grid: every root it converges to is one of
/// the returned solutions (no solution missed), and the returned ones are roots.
#[test]
fn dense_search_finds_no_other_solution() {
    let mut rng = Rng::new(12);
    for n in 2..=3 {
        for _ in 0..40 {
            let (m, _) = random_machine(&mut rng, n);
            let theta = angles(&mut rng, n);
            let target = m.forward(theta).unwrap().rotation;
            let sol = m.inverse(&target).unwrap();
            if sol.free {
                continue;
            }
            let step = if n == 2 { 15.0 } else { 30.0 };
            let grid = (360.0 / step) as usize;
            let starts = grid.pow(n as u32);
            for s in 0..starts {
                let mut x = [0.0; 3];
                let mut rest = s;
                for xk in x.iter_mut().take(n) {
                    *xk = -180.0 + step * (rest % grid) as f64 + 0.5 * step;
                    rest /= grid;
                }
                if let Some(root) = newton(&m, &target, x, n) {
                    let known = sol
                        .as_slice()
                        .iter()
                        .any(|row| (0..n).all(|k| same_turn(row[k], root[k], 1e-5)));
                    assert!(known, "missed {root:?}; returned {sol:?}; {m:?}");
                }
            }
        }
    }
}

/// Gauss–Newton on the residual (direction or whole rotation) with a numerical Jacobian;
/// `Some` when it converged to a root.
fn newton(m: &Machine, target: &Matrix, mut x: [f64; 3], n: usize) -> Option<[f64; 3]> {
    let resid = |x: [f64; 3]| -> Vec<f64> {
        let r = m.forward(x).unwrap().rotation;
        let mut v = Vec::new();
        for i in 0..3 {
            for j in 0..3 {
                if n == 3 || j == 2 {
                    v.push(r[i][j] - target[i][j]);
                }
            }
        }
        v
    };
    for _ in 0..60 {
        let r0 = resid(x);
        let norm: f64 = r0.iter().map(|e| e * e).sum::<f64>().sqrt();
        if norm < 1e-13 {
            return Some(x);
        }
        let h = 1e-6;
        let mut jac = nalgebra::DMatrix::<f64>::zeros(r0.len(), n);
        for k in 0..n {
            let mut xp = x;
            xp[k] += h;
            let rp = resid(xp);
            for (i, (a, b)) in rp.iter().zip(&r0).enumerate() {
                jac[(i, k)] = (a - b) / h;
            }
        }
        let rv = nalgebra::DVector::from_vec(r0);
        let svd = jac.clone().svd(true, true);
        let dx = svd.solve(&(-rv), 1e-10).ok()?;
        for k in 0..n {
            x[k] += dx[k].clamp(-20.0, 20.0);
        }
    }
    let r: f64 = resid(x).iter().map(|e| e * e).sum::<f64>().sqrt();
    (r < 1e-10).then_some(x)
}

#[test]
fn unreachable_and_singular_targets() {
    // A single rotary table C with a vertical tool: any rotation about Z is reached with C
    // free (it stays where it is), a tilt is not reachable.
    let c = machine(&[axis(Side::Work, [0.0, 0.0, -1.0], [0.0; 3])]);
    let s = c.inverse(&elementary(Axis::Z, 30.0)).unwrap();
    assert!(s.free && s.count == 1 && s.angles[0] == [0.0; 3]);
    assert_eq!(
        c.inverse(&elementary(Axis::X, 1e-6)),
        Err(Error::Unreachable)
    );
    let ch = c
        .choose(&elementary(Axis::Z, 30.0), [123.0, 0.0, 0.0], Rule::Closest)
        .unwrap();
    assert!(ch.free && ch.axes[0] == 123.0);
    // The table about -Z at 123° has turned the workpiece by -123° about Z, so the tool
    // frame is Rz(123) and the remaining frame turns by 30 - 123 = -93° about Z.
    assert!(common::max_diff(&ch.remaining, &elementary(Axis::Z, -93.0)) < 1e-15);

    // A table A carrying C: a vertical target leaves C free at its current position.
    let ac = machine(&[
        axis(Side::Work, [1.0, 0.0, 0.0], [0.0; 3]),
        axis(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]),
    ]);
    let ch = ac
        .choose(&elementary(Axis::Z, 10.0), [0.0, 77.0, 0.0], Rule::Closest)
        .unwrap();
    assert!(ch.free && ch.axes == [0.0, 77.0, 0.0], "{ch:?}");
    // Upside down: A = 180 with C free.
    let ch = ac
        .choose(&elementary(Axis::X, 180.0), [0.0, 5.0, 0.0], Rule::Closest)
        .unwrap();
    assert!(
        ch.free && (ch.axes[0].abs() - 180.0).abs() < 1e-12 && ch.axes[1] == 5.0,
        "{ch:?}"
    );
}

#[test]
fn choice_rules_limits_and_hirth() {
    // Fork head C on B as in the CYCLE800 manuals, B limited to -100..100.
    let mut b = axis(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3]);
    b.limits = Some([-100.0, 100.0]);
    let m = machine(&[axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]), b]);
    let target = mul(&elementary(Axis::Z, 10.0), &elementary(Axis::Y, 30.0));
    // Solutions (10, 30) and (-170, -30).
    let near = m.choose(&target, [750.0, 0.0, 0.0], Rule::Closest).unwrap();
    assert!(
        (near.axes[0] - 730.0).abs() < 1e-9 && (near.axes[1] - 30.0).abs() < 1e-9,
        "{near:?}"
    );
    let minus = m.choose(&target, [0.0; 3], Rule::Minus(1)).unwrap();
    assert!((minus.axes[0] + 170.0).abs() < 1e-9 && (minus.axes[1] + 30.0).abs() < 1e-9);
    let plus = m.choose(&target, [0.0; 3], Rule::Plus(1)).unwrap();
    assert!((plus.axes[1] - 30.0).abs() < 1e-9);
    let inv = m.choose(&target, [0.0; 3], Rule::Inverse).unwrap();
    assert!((inv.axes[1] + 30.0).abs() < 1e-9, "{inv:?}");
    // The remaining frame: a fork head reaches the whole orientation Rz·Ry here.
    assert!(common::max_diff(&near.remaining, &cncrot::IDENTITY) < 1e-14);
    assert_eq!(
        m.choose(&target, [0.0; 3], Rule::Minus(2)),
        Err(Error::BadArgument)
    );

    // "Minus" and "plus" compare angles, not the turns placed toward the current position
    // (SEQ- is "the master axis at a negative angle"): on a B without limits, from
    // B = -170° the B = 30° solution unwinds to -330° (160° away, against 200° for 30°),
    // which is lower, yet the minus solution is B = -30° (140° away, placed at -30°).
    let free = machine(&[
        axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]),
        axis(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3]),
    ]);
    let minus = free
        .choose(&target, [0.0, -170.0, 0.0], Rule::Minus(1))
        .unwrap();
    assert!(
        (minus.axes[0] + 170.0).abs() < 1e-9 && (minus.axes[1] + 30.0).abs() < 1e-9,
        "{minus:?}"
    );
    // From B = 170°: B = -30° unwinds to 330°, higher, yet "plus" is B = 30°.
    let plus = free
        .choose(&target, [0.0, 170.0, 0.0], Rule::Plus(1))
        .unwrap();
    assert!(
        (plus.axes[0] - 10.0).abs() < 1e-9 && (plus.axes[1] - 30.0).abs() < 1e-9,
        "{plus:?}"
    );

    // Half a turn either way: the turn nearer 0. From B = 90° the B = -90° solution of a
    // 90° tilt is as far at -90° as at 270°: -90° (SEQ- after SEQ+; 270° drifted on to
    // 360° and 380° in the blocks after it), and from B = -90° the B = 90° one is 90°.
    let tilt90 = elementary(Axis::Y, 90.0);
    let minus = free
        .choose(&tilt90, [0.0, 90.0, 0.0], Rule::Minus(1))
        .unwrap();
    assert!((minus.axes[1] + 90.0).abs() < 1e-9, "{minus:?}");
    assert!((minus.axes[0].abs() - 180.0).abs() < 1e-9, "{minus:?}");
    let plus = free
        .choose(&tilt90, [0.0, -90.0, 0.0], Rule::Plus(1))
        .unwrap();
    assert!((plus.axes[1] - 90.0).abs() < 1e-9, "{plus:?}");
    // Not a tie: the nearest turn, however far from 0.
    let far = free
        .choose(&tilt90, [0.0, 200.0, 0.0], Rule::Minus(1))
        .unwrap();
    assert!((far.axes[1] - 270.0).abs() < 1e-9, "{far:?}");

    // With B limited to 0..100, "minus" cannot have B = -30 and takes the other.
    let mut b2 = b;
    b2.limits = Some([0.0, 100.0]);
    let m2 = machine(&[axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]), b2]);
    let minus = m2.choose(&target, [0.0; 3], Rule::Minus(1)).unwrap();
    assert!((minus.axes[1] - 30.0).abs() < 1e-9);
    // A tilt of 120° is beyond the travel on both branches.
    let far = elementary(Axis::Y, 120.0);
    assert_eq!(
        m.choose(&far, [0.0; 3], Rule::Closest),
        Err(Error::OutOfTravel)
    );

    // A limited modulo-like axis: C within 0..360 from current -10 goes to 350, not -10.
    let mut c = axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]);
    c.limits = Some([0.0, 360.0]);
    let m3 = machine(&[c, b]);
    let t = mul(&elementary(Axis::Z, -10.0), &elementary(Axis::Y, 30.0));
    let ch = m3.choose(&t, [-10.0, 0.0, 0.0], Rule::Plus(1)).unwrap();
    assert!((ch.axes[0] - 350.0).abs() < 1e-9, "{ch:?}");

    // Hirth: B on a 2.5° grid reaches 31.25° as 32.5 (or 30): the residual is reported
    // and the remaining frame turns the rest.
    let mut bh = b;
    bh.hirth = Some(Hirth {
        offset: 0.0,
        step: 2.5,
    });
    let m4 = machine(&[axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]), bh]);
    let t = elementary(Axis::Y, 31.0);
    let ch = m4.choose(&t, [0.0; 3], Rule::Plus(1)).unwrap();
    assert!(
        (ch.axes[1] - 30.0).abs() < 1e-12 && (ch.residual[1] + 1.0).abs() < 1e-12,
        "{ch:?}"
    );
    assert!(common::max_diff(&ch.remaining, &elementary(Axis::Y, 1.0)) < 1e-14);
}

#[test]
fn direction_of_travel_rules() {
    // Fork head C on B (C modulo, B limited to -100..100); Rz(10)·Ry(30) has the solutions
    // (C 10, B 30) and (C -170, B -30).
    let mut b = axis(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3]);
    b.limits = Some([-100.0, 100.0]);
    let m = machine(&[axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]), b]);
    let target = mul(&elementary(Axis::Z, 10.0), &elementary(Axis::Y, 30.0));
    let close = |got: [f64; 3], want: [f64; 2]| {
        (got[0] - want[0]).abs() < 1e-9 && (got[1] - want[1]).abs() < 1e-9
    };
    // From C 20: C turning up reaches -170 at 190 (a turn of 170°) and 10 at 370 (350°):
    // 190. Turning down: 10 (10°) before -170 (190°). The closest is 10 either way.
    let from = [20.0, 0.0, 0.0];
    let up = m.choose(&target, from, Rule::PositiveTurn(0)).unwrap();
    assert!(close(up.axes, [190.0, -30.0]), "{up:?}");
    let down = m.choose(&target, from, Rule::NegativeTurn(0)).unwrap();
    assert!(close(down.axes, [10.0, 30.0]), "{down:?}");
    // At the position already: no turn is the least turn, either way.
    let here = [10.0, 30.0, 0.0];
    for rule in [Rule::PositiveTurn(0), Rule::NegativeTurn(0)] {
        assert!(close(
            m.choose(&target, here, rule).unwrap().axes,
            [10.0, 30.0]
        ));
    }
    // A rounding below the current position is no turn (not a whole one): from C 10 + 1e-12.
    let ch = m
        .choose(&target, [10.0 + 1e-12, 30.0, 0.0], Rule::PositiveTurn(0))
        .unwrap();
    assert!(close(ch.axes, [10.0, 30.0]), "{ch:?}");
    // B limited: from B 40 turning up, neither 30 nor -30 lies ahead within the travel;
    // turning down, 30 comes first (10°), with C at its closest, 10.
    let from = [0.0, 40.0, 0.0];
    assert_eq!(
        m.choose(&target, from, Rule::PositiveTurn(1)),
        Err(Error::OutOfTravel)
    );
    let down = m.choose(&target, from, Rule::NegativeTurn(1)).unwrap();
    assert!(close(down.axes, [10.0, 30.0]), "{down:?}");
    // From B -50 turning up: -30 (20°) before 30 (80°).
    let up = m
        .choose(&target, [0.0, -50.0, 0.0], Rule::PositiveTurn(1))
        .unwrap();
    assert!(close(up.axes, [-170.0, -30.0]), "{up:?}");
    assert_eq!(
        m.choose(&target, [0.0; 3], Rule::NegativeTurn(2)),
        Err(Error::BadArgument)
    );
}

#[test]
fn follow_up_keeps_the_tip_on_the_workpiece() {
    let mut rng = Rng::new(13);
    for _ in 0..500 {
        let n = 1 + (rng.next_u64() % 3) as usize;
        let (m, _) = random_machine(&mut rng, n);
        let (from, to) = (angles(&mut rng, n), angles(&mut rng, n));
        let linear = [
            rng.range(-300.0, 300.0),
            rng.range(-300.0, 300.0),
            rng.range(-300.0, 300.0),
        ];
        let len = rng.range(0.0, 300.0);
        let next = m.follow_tool_tip(from, to, linear, len).unwrap();
        let a = m.tool_tip(from, linear, len).unwrap();
        let b = m.tool_tip(to, next, len).unwrap();
        for k in 0..3 {
            assert!((a[k] - b[k]).abs() < 1e-9, "{a:?} {b:?}");
        }
    }
}

/// Targets a hair away from the pole (the tool along the outer axis): still reproduced to
/// 1e-12, both branches, and exactly at the pole one free family.
#[test]
fn near_the_pole() {
    let s = 0.5f64.sqrt();
    let heads = [
        machine(&[
            axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]),
            axis(Side::Tool, [0.0, 1.0, 0.0], [0.0, 0.0, 200.0]),
        ]),
        machine(&[
            axis(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]),
            axis(Side::Tool, [0.0, s, s], [0.0, 0.0, 200.0]),
        ]),
        machine(&[
            axis(Side::Work, [1.0, 0.0, 0.0], [0.0; 3]),
            axis(Side::Work, [0.0, 0.0, -1.0], [10.0, 20.0, 0.0]),
        ]),
    ];
    for m in &heads {
        for tilt_rad in [1e-3, 1e-6, 1e-9, 1e-11, 1e-12, 1e-13, 1e-15, 0.0] {
            for azimuth in [0.0, 37.0, -120.0] {
                let target = mul(
                    &elementary(Axis::Z, azimuth),
                    &elementary(Axis::X, f64::to_degrees(tilt_rad)),
                );
                let sol = m.inverse(&target).unwrap();
                for row in sol.as_slice() {
                    assert!(
                        miss(m, *row, &target) < 1e-12,
                        "{tilt_rad} {row:?} {} {:?}",
                        miss(m, *row, &target),
                        m.axes()
                    );
                }
                if tilt_rad == 0.0 {
                    assert!(sol.free, "{sol:?}");
                }
            }
        }
    }
}

/// Machines whose axis `k` (A, about X) travels within `[0, 30]`, with the other axes
/// modulo: a head, a fork head C/A, a table A/C, a mixed machine, a table C with a head B/A.
fn a_limited_machines() -> Vec<(Machine, usize)> {
    let limited = |side, v: Vector, p: Vector| RotaryAxis {
        limits: Some([0.0, 30.0]),
        ..axis(side, v, p)
    };
    let (x, y) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    vec![
        (machine(&[limited(Side::Tool, x, [0.0, 0.0, 200.0])]), 0),
        (
            machine(&[
                axis(Side::Tool, Z, [0.0; 3]),
                limited(Side::Tool, x, [0.0, 0.0, 150.0]),
            ]),
            1,
        ),
        (
            machine(&[
                limited(Side::Work, x, [0.0, 0.0, -100.0]),
                axis(Side::Work, Z, [20.0, 10.0, -100.0]),
            ]),
            0,
        ),
        (
            machine(&[
                limited(Side::Tool, x, [0.0, 0.0, 250.0]),
                axis(Side::Work, Z, [300.0, 0.0, 0.0]),
            ]),
            0,
        ),
        (
            machine(&[
                axis(Side::Work, Z, [500.0, 300.0, 0.0]),
                axis(Side::Tool, y, [0.0, 0.0, 540.0]),
                limited(Side::Tool, x, [0.0, 0.0, 250.0]),
            ]),
            2,
        ),
    ]
}

/// Issue 20, class 3: a target built from positions exactly at an end of the travel, seen
/// from those positions, is reached there — not refused, not reached by a turn elsewhere —
/// and the position never lies outside the travel.
#[test]
fn a_target_at_a_travel_end_is_chosen_at_that_end() {
    // One B about Y within 0..10: B = 10 is the travel's end (the inverse may compute it
    // a few ulp beyond).
    let b = RotaryAxis {
        limits: Some([0.0, 10.0]),
        ..axis(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3])
    };
    let m = machine(&[b]);
    for end in [0.0, 10.0] {
        for target in [
            elementary(Axis::Y, end),
            m.forward([end, 0.0, 0.0]).unwrap().rotation,
        ] {
            let c = m.choose(&target, [end, 0.0, 0.0], Rule::Closest);
            let c = c.unwrap_or_else(|e| panic!("B = {end}: {e:?}"));
            assert!((c.axes[0] - end).abs() <= 1e-9 && (0.0..=10.0).contains(&c.axes[0]));
            assert_eq!(c.residual, [0.0; 3]);
        }
    }

    // Every combination of A at an end of 0..30 and the other axes on a 7.5° grid, on five
    // machines: chosen at that end, the other axes where they were.
    let mut targets = 0;
    for (m, k) in a_limited_machines() {
        let n = m.axes().len();
        let others: Vec<usize> = (0..n).filter(|&j| j != k).collect();
        let grid: Vec<f64> = (0..48).map(|i| -180.0 + 7.5 * f64::from(i)).collect();
        for end in [0.0, 30.0] {
            for (i, &g1) in grid.iter().enumerate() {
                // The third axis, if any, on a coarser grid of its own.
                for &g2 in grid.iter().skip(i % 6).step_by(6) {
                    let mut p = [0.0; 3];
                    p[k] = end;
                    if let Some(&j) = others.first() {
                        p[j] = g1;
                    }
                    if let Some(&j) = others.get(1) {
                        p[j] = g2;
                    }
                    let target = m.forward(p).unwrap().rotation;
                    let c = m
                        .choose(&target, p, Rule::Closest)
                        .unwrap_or_else(|e| panic!("{e:?} at {p:?} on {:?}", m.axes()));
                    assert!(
                        (c.axes[k] - end).abs() <= 1e-9 && (0.0..=30.0).contains(&c.axes[k]),
                        "{p:?} -> {:?}",
                        c.axes
                    );
                    for &j in &others {
                        assert!((c.axes[j] - p[j]).abs() <= 1e-9, "{p:?} -> {:?}", c.axes);
                    }
                    targets += 1;
                    if others.len() < 2 {
                        break;
                    }
                }
                if others.is_empty() {
                    break;
                }
            }
        }
    }
    assert!(targets > 500, "{targets}");

    // Near the pole of a fork head C/A, C's travel ending where the target has it: tilts
    // of A from 0.1° down to 1e-11°; C is still computed to rounding and kept at its end.
    for tilt in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11] {
        for k in 0..50 {
            let end = 37.3 + 6.7 * f64::from(k);
            let m = machine(&[
                RotaryAxis {
                    limits: Some([0.0, end]),
                    ..axis(Side::Tool, Z, [0.0; 3])
                },
                axis(Side::Tool, [1.0, 0.0, 0.0], [0.0, 0.0, 150.0]),
            ]);
            let p = [end, tilt, 0.0];
            let target = m.forward(p).unwrap().rotation;
            let c = m.choose(&target, p, Rule::Closest).unwrap();
            assert!(
                c.axes[0] <= end && end - c.axes[0] <= 1e-9,
                "{p:?} -> {c:?}"
            );
        }
    }

    // A table A (about X) carrying C (about Z), A within -120..30, standing at
    // (30, -162.5): that orientation is where it stands, not (-30, -342.5) half a turn of C
    // away.
    let table = machine(&[
        RotaryAxis {
            limits: Some([-120.0, 30.0]),
            ..axis(Side::Work, [1.0, 0.0, 0.0], [0.0; 3])
        },
        axis(Side::Work, Z, [0.0; 3]),
    ]);
    let here = [30.0, -162.5, 0.0];
    let target = table.forward(here).unwrap().rotation;
    let c = table.choose(&target, here, Rule::Closest).unwrap();
    assert!(
        c.axes[0] == 30.0 && (c.axes[1] + 162.5).abs() <= 1e-9,
        "{:?}",
        c.axes
    );
    // CYCLE600 positioning shares the choice.
    let state = cncrot::dialects::cycle600::State {
        frame: cncrot::Frame::from_rotation(target),
        ..Default::default()
    };
    let c = cncrot::dialects::cycle600::position(&state, &table, here).unwrap();
    assert!(c.axes[0] == 30.0 && (c.axes[1] + 162.5).abs() <= 1e-9);
}

/// Issue 20, class 4: limits, offsets, Hirth offsets and pivots whose magnitude would make
/// the degree (or length) arithmetic lose precision are refused, on both sides of each
/// bound; a Hirth step below the smallest one is refused.
#[test]
fn axis_parameters_beyond_their_bounds_are_refused() {
    let c = machine(&[axis(Side::Tool, Z, [0.0; 3])]);
    let b = axis(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3]);
    let hirth = |offset, step| Some(Hirth { offset, step });
    let refused = [
        // The cases: travel around 1e15°, a Hirth grid offset by 1e17°, an axis
        // offset of 1e12°, a pivot 1e12 mm away.
        (
            RotaryAxis {
                limits: Some([1e15, 1e15 + 720.0]),
                ..b
            },
            Error::OutOfRange,
        ),
        (
            RotaryAxis {
                hirth: hirth(1e17, 1.0),
                ..b
            },
            Error::OutOfRange,
        ),
        (RotaryAxis { offset: 1e12, ..b }, Error::OutOfRange),
        (
            RotaryAxis {
                point: [1e12, 0.0, 0.0],
                ..b
            },
            Error::OutOfRange,
        ),
        // Right at the bounds: 65 536° and 1e6 mm (a hair beyond).
        (
            RotaryAxis {
                limits: Some([-65_536.0, 0.0]),
                ..b
            },
            Error::OutOfRange,
        ),
        (
            RotaryAxis {
                limits: Some([0.0, 65_536.0]),
                ..b
            },
            Error::OutOfRange,
        ),
        (
            RotaryAxis {
                offset: -65_536.0,
                ..b
            },
            Error::OutOfRange,
        ),
        (
            RotaryAxis {
                offset: 65_536.0,
                ..b
            },
            Error::OutOfRange,
        ),
        (
            RotaryAxis {
                hirth: hirth(65_536.0, 1.0),
                ..b
            },
            Error::OutOfRange,
        ),
        (
            RotaryAxis {
                hirth: hirth(-65_536.0, 1.0),
                ..b
            },
            Error::OutOfRange,
        ),
        (
            RotaryAxis {
                point: [0.0, 0.0, -1.000_000_1e6],
                ..b
            },
            Error::OutOfRange,
        ),
        // Hirth steps below 1e-6°, down to the subnormal ones.
        (
            RotaryAxis {
                hirth: hirth(0.0, 0.999_999e-6),
                ..b
            },
            Error::BadArgument,
        ),
        (
            RotaryAxis {
                hirth: hirth(0.0, 1e-300),
                ..b
            },
            Error::BadArgument,
        ),
        (
            RotaryAxis {
                hirth: hirth(0.0, 5e-324),
                ..b
            },
            Error::BadArgument,
        ),
    ];
    for (a, e) in refused {
        assert_eq!(c.with_axis(a), Err(e), "{a:?}");
    }
    let accepted = [
        RotaryAxis {
            limits: Some([-65_535.75, 65_535.75]),
            ..b
        },
        RotaryAxis {
            offset: 65_535.75,
            ..b
        },
        RotaryAxis {
            offset: -65_535.75,
            ..b
        },
        RotaryAxis {
            hirth: hirth(-65_535.75, 1e-6),
            ..b
        },
        RotaryAxis {
            point: [1e6, -1e6, 1e6],
            ..b
        },
    ];
    for a in accepted {
        assert!(c.with_axis(a).is_ok(), "{a:?}");
    }

    // Within the bounds the arithmetic keeps its accuracy: a travel of 65 000..65 500 and
    // an offset of 65 000 turn B by 30° at 65 030 (65 030 − 65 000 = 30, exact), and a
    // target of Ry(30) seen from there is reached at 65 030 (≡ 30 + 180·360).
    let far = machine(&[RotaryAxis {
        limits: Some([65_000.0, 65_500.0]),
        offset: 65_000.0,
        ..b
    }]);
    let f = far.forward([65_030.0, 0.0, 0.0]).unwrap().rotation;
    assert!(common::max_diff(&f, &elementary(Axis::Y, 30.0)) < 1e-15);
    let ch = far
        .choose(
            &elementary(Axis::Y, 30.0),
            [65_100.0, 0.0, 0.0],
            Rule::Closest,
        )
        .unwrap();
    assert!((ch.axes[0] - 65_030.0).abs() < 1e-9, "{ch:?}");
    // Current positions obey the same bound, on both sides of it.
    let free = machine(&[b]);
    for current in [65_536.0, -65_536.0] {
        assert_eq!(
            free.choose(
                &elementary(Axis::Y, 16.0),
                [current, 0.0, 0.0],
                Rule::Closest
            ),
            Err(Error::OutOfRange)
        );
    }
    let ch = free
        .choose(
            &elementary(Axis::Y, 15.0),
            [65_535.75, 0.0, 0.0],
            Rule::Closest,
        )
        .unwrap();
    assert!((ch.axes[0] - 65_535.0).abs() < 1e-9, "{ch:?}");
}

/// The whole-turn placement within the travel, both directions and over several turns
/// (from `cargo mutants`: the upper wrap was never exercised).
#[test]
fn turns_are_placed_within_the_travel() {
    let b = |lo: f64, hi: f64| {
        machine(&[RotaryAxis {
            limits: Some([lo, hi]),
            ..axis(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3])
        }])
    };
    let target = elementary(Axis::Y, -10.0);
    // (travel, current, where −10° goes): the turn nearest the current position, else the
    // one nearest it within the travel.
    for (lo, hi, current, want) in [
        (-360.0, 0.0, 350.0, -10.0),
        (-720.0, -360.0, 0.0, -370.0),
        (-1080.0, -720.0, 0.0, -730.0),
        (360.0, 720.0, 0.0, 710.0),
        (0.0, 360.0, -10.0, 350.0),
        (-180.0, 180.0, 700.0, -10.0),
        // Exactly a whole turn beyond an end (from a current position outside the travel):
        // that end, not a second turn.
        (-370.0, -10.0, 350.0, -10.0),
        (-10.0, 350.0, -370.0, -10.0),
    ] {
        let c = b(lo, hi)
            .choose(&target, [current, 0.0, 0.0], Rule::Closest)
            .unwrap_or_else(|e| panic!("{lo}..{hi} from {current}: {e:?}"));
        assert!(
            (c.axes[0] - want).abs() < 1e-9,
            "{lo}..{hi} from {current}: {c:?}"
        );
    }
    assert_eq!(
        b(0.0, 300.0).choose(&target, [0.0; 3], Rule::Closest),
        Err(Error::OutOfTravel)
    );
}

/// Hirth grids with a non-zero offset, stepping back inside the travel at either end
/// (from `cargo mutants`: offsets were always 0, the step back never taken).
#[test]
fn hirth_grids_with_an_offset_step_back_into_the_travel() {
    let b = |lo: f64, hi: f64| {
        machine(&[RotaryAxis {
            limits: Some([lo, hi]),
            hirth: Some(Hirth {
                offset: 1.0,
                step: 5.0,
            }),
            ..axis(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3])
        }])
    };
    // Teeth at 1 + 5k: …, −34, −29, …, 31, 36, …
    for (lo, hi, angle, want) in [
        // 34 rounds to the tooth 36, beyond 35: one tooth back.
        (-100.0, 35.0, 34.0, 31.0),
        // Without the limit, 36.
        (-100.0, 100.0, 34.0, 36.0),
        // −32 rounds to −34, below −33: one tooth on.
        (-33.0, 100.0, -32.0, -29.0),
        (-100.0, 100.0, -32.0, -34.0),
        // 2.4 is nearest to the tooth 1 (the offset counts).
        (-100.0, 100.0, 2.4, 1.0),
    ] {
        let c = b(lo, hi)
            .choose(&elementary(Axis::Y, angle), [0.0; 3], Rule::Closest)
            .unwrap();
        assert!(
            (c.axes[0] - want).abs() < 1e-9 && (c.residual[0] - (want - angle)).abs() < 1e-9,
            "{lo}..{hi} {angle}: {c:?}"
        );
    }
    // No tooth within 32..35.
    assert_eq!(
        b(32.0, 35.0).choose(&elementary(Axis::Y, 34.0), [0.0; 3], Rule::Closest),
        Err(Error::OutOfTravel)
    );
}

/// A machine without rotary axes reaches its tool direction and nothing else (from `cargo
/// mutants`: the zero-axis branch of the inverse was never run).
#[test]
fn a_machine_without_axes_reaches_its_tool_direction_only() {
    for (tool, about) in [(Z, Axis::Z), ([1.0, 0.0, 0.0], Axis::X)] {
        let m = Machine::new(tool).unwrap();
        // The base turn B, then any turn about the tool: the direction is the tool's.
        let base = m.forward([0.0; 3]).unwrap().rotation;
        let target = mul(&elementary(about, 30.0), &base);
        let s = m.inverse(&target).unwrap();
        assert!(s.count == 1 && s.angles[0] == [0.0; 3] && !s.free, "{s:?}");
        let c = m.choose(&target, [0.0; 3], Rule::Closest).unwrap();
        assert!(
            c.axes == [0.0; 3]
                && common::max_diff(&c.remaining, &elementary(Axis::Z, 30.0)) < 1e-15
        );
        // A tilt of 1e-9° (1.7e-11 rad) is within the reach tolerance (1e-10 rad), 1e-8°
        // (1.7e-10 rad) is not.
        let tilt = |deg: f64| {
            mul(
                &elementary(if about == Axis::Z { Axis::X } else { Axis::Y }, deg),
                &base,
            )
        };
        assert!(m.inverse(&tilt(1e-9)).is_ok());
        assert_eq!(m.inverse(&tilt(1e-8)), Err(Error::Unreachable));
        assert_eq!(m.inverse(&tilt(90.0)), Err(Error::Unreachable));
    }
}

// ---------------------------------------------------------------------------------------
// The five-axis transformation (tool tip and direction <-> every machine axis).

/// The tool tip written independently: nalgebra's 4x4 products,
/// `W⁻¹·Trans(linear)·T·(−L·b)` with `b` the tool's base direction.
fn reference_tip(
    axes: &[RotaryAxis],
    theta: [f64; 3],
    linear: Vector,
    l: f64,
    b: Vector,
) -> Vector {
    let mut t = Matrix4::<f64>::identity();
    let mut w = Matrix4::<f64>::identity();
    for (a, th) in axes.iter().zip(theta) {
        let v = Unit::new_normalize(Vector3::from(a.direction));
        let r = Rotation3::from_axis_angle(&v, (th - a.offset).to_radians()).to_homogeneous();
        let p = Vector3::from(a.point);
        let h =
            Translation3::from(p).to_homogeneous() * r * Translation3::from(-p).to_homogeneous();
        match a.side {
            Side::Tool => t *= h,
            Side::Work => w *= h,
        }
    }
    let tip = w.try_inverse().unwrap()
        * Translation3::from(Vector3::from(linear)).to_homogeneous()
        * t
        * nalgebra::Vector4::new(-l * b[0], -l * b[1], -l * b[2], 1.0);
    [tip[0], tip[1], tip[2]]
}

fn six(linear: Vector, theta: [f64; 3]) -> [f64; 6] {
    [
        linear[0], linear[1], linear[2], theta[0], theta[1], theta[2],
    ]
}

#[test]
fn tcp_forward_matches_an_independent_computation() {
    let mut rng = Rng::new(23);
    for n in 0..=3 {
        for _ in 0..2000 {
            let (m, axes) = random_machine(&mut rng, n);
            let theta = angles(&mut rng, n);
            let linear = [0.0; 3].map(|_: f64| rng.range(-800.0, 800.0));
            let l = rng.range(0.0, 300.0);
            let pose = m.tcp_forward(six(linear, theta), l).unwrap();
            let r = reference_forward(&axes, theta);
            let tip = reference_tip(&axes, theta, linear, l, Z);
            for i in 0..3 {
                assert!(
                    (pose.translation[i] - tip[i]).abs() < 1e-9,
                    "{pose:?} {tip:?}"
                );
                for j in 0..3 {
                    assert!((pose.rotation[i][j] - r[(i, j)]).abs() < 1e-13);
                }
            }
        }
    }
}

/// A tool whose base direction is not +Z (a head mounted sideways): the tip lies `L` along
/// the turned base direction, the pose's third column is that direction.
#[test]
fn tcp_forward_with_a_sideways_tool() {
    let m = Machine::new([1.0, 0.0, 0.0])
        .unwrap()
        .with_axis(axis(Side::Tool, [0.0, 0.0, 1.0], [0.0, 0.0, 0.0]))
        .unwrap();
    // C = 90° turns the tool from +X to +Y: tip at the adapter minus 100 along +Y.
    let pose = m
        .tcp_forward([5.0, 6.0, 7.0, 90.0, 0.0, 0.0], 100.0)
        .unwrap();
    let want = [5.0, 6.0 - 100.0, 7.0];
    for (got, want) in pose.translation.iter().zip(want) {
        assert!((got - want).abs() < 1e-12, "{pose:?}");
    }
    assert!((pose.rotation[1][2] - 1.0).abs() < 1e-15, "{pose:?}");
}

/// tcp_forward(tcp_inverse(pose)) = pose: tip to 1e-9 mm, direction (the whole rotation
/// with three axes) to 1e-12, on random machines of every kind, from previous positions
/// near the true ones and far from them; near the true ones the true solution comes back.
#[test]
fn tcp_inverse_reproduces_random_poses() {
    let mut rng = Rng::new(24);
    let mut exact = 0;
    for n in 1..=3 {
        for round in 0..3000 {
            let (m, _) = random_machine(&mut rng, n);
            let theta = angles(&mut rng, n);
            let linear = [0.0; 3].map(|_: f64| rng.range(-800.0, 800.0));
            let l = rng.range(0.0, 300.0);
            let pose = m.tcp_forward(six(linear, theta), l).unwrap();
            let near = round % 2 == 0;
            let mut prev = theta;
            for p in prev.iter_mut().take(n) {
                *p += if near {
                    rng.range(-0.5, 0.5)
                } else {
                    rng.range(-400.0, 400.0)
                };
            }
            let t = m.tcp_inverse(&pose, l, six([0.0; 3], prev)).unwrap();
            let back = m.tcp_forward(t.axes, l).unwrap();
            for i in 0..3 {
                assert!(
                    (back.translation[i] - pose.translation[i]).abs() < 1e-9,
                    "{n} {theta:?} {t:?}"
                );
                for j in 0..3 {
                    if n == 3 || j == 2 {
                        assert!((back.rotation[i][j] - pose.rotation[i][j]).abs() < 1e-12);
                    }
                }
            }
            if near && !t.free {
                // The true solution, unless the two solutions lie within a degree of each
                // other (near the edge of a cone the tool direction can reach, where the
                // other branch can be nearer), or the axis is free (a single axis along the
                // tool: every position is a solution): count the exact returns.
                if (0..n).all(|k| (t.axes[3 + k] - theta[k]).abs() < 1e-7) {
                    for k in 0..3 {
                        assert!((t.axes[k] - linear[k]).abs() < 1e-8, "{t:?} {linear:?}");
                    }
                    exact += 1;
                }
            }
        }
    }
    // 3 992 of the 4 500 (250 single axes along the tool, 2 pairs within a degree).
    assert!(exact > 3900, "{exact}");
}

/// The worked example of docs/kinematics.md, by hand: an AC table (A about X through
/// (0, 0, 100), C about Z carried by it), tool 50 mm. Tip at the workpiece point (10, 0, 0),
/// direction (sin 30° sin 90°, sin 30° cos 90°, cos 30°) = (0.5, 0, √3/2): A = 30°, C = 90°,
/// and W·tip = Rx(30°)·(Rz(90°)·(10, 0, 0) − (0, 0, 100)) + (0, 0, 100)
/// = Rx(30°)·(0, 10, −100) + (0, 0, 100) = (0, 5√3 + 50, 5 − 50√3 + 100),
/// the adapter 50 mm above the tip: X = 0, Y = 50 + 5√3, Z = 155 − 50√3.
#[test]
fn tcp_inverse_ac_table_by_hand() {
    let m = worked_ac_table();
    let s3 = 3.0f64.sqrt();
    // Any rotation with that third column: the X' axis along -Y... chosen as Rz(-90)·Rx(-30)
    // of the workpiece, which the table gives (F = W⁻¹ = Rz(-C)·Rx(-A)).
    let rot = mul(&elementary(Axis::Z, -90.0), &elementary(Axis::X, -30.0));
    assert!((rot[0][2] - 0.5).abs() < 1e-16 && rot[1][2].abs() < 1e-16);
    let pose = cncrot::Frame {
        rotation: rot,
        translation: [10.0, 0.0, 0.0],
    };
    let t = m
        .tcp_inverse(&pose, 50.0, [0.0, 0.0, 0.0, 20.0, 80.0, 0.0])
        .unwrap();
    let want = [0.0, 50.0 + 5.0 * s3, 155.0 - 50.0 * s3, 30.0, 90.0, 0.0];
    for (got, want) in t.axes.iter().zip(want) {
        assert!((got - want).abs() < 1e-12, "{:?}", t.axes);
    }
    // The other solution (A = -30°, C = -90°) from previous positions near it.
    let t = m
        .tcp_inverse(&pose, 50.0, [0.0, 0.0, 0.0, -20.0, -80.0, 0.0])
        .unwrap();
    assert!((t.axes[3] + 30.0).abs() < 1e-12 && (t.axes[4] + 90.0).abs() < 1e-12);
    // Whole turns unwound toward the previous C: 90 + 720.
    let t = m
        .tcp_inverse(&pose, 50.0, [0.0, 0.0, 0.0, 20.0, 800.0, 0.0])
        .unwrap();
    assert!((t.axes[4] - 810.0).abs() < 1e-12, "{:?}", t.axes);
}

/// A pose rounded where it was written (√3/2 as 0.866025, as a printed matrix or a CAM
/// system's file holds it) passes the rotation check: it is solved for its nearest rotation,
/// not refused as unreachable (its rounding, 2.5e-7, missed every solution's verification).
/// The nearest rotation of this one turns the tool by under 1e-6 rad from (0.5, 0, √3/2):
/// A and C within 1e-4° of 30° and 90°; the inverse and choice alike.
#[test]
fn rounded_poses_are_solved_for_their_nearest_rotation() {
    let m = worked_ac_table();
    let rot = [
        [0.0, 0.866025, 0.5],
        [-1.0, 0.0, 0.0],
        [0.0, -0.5, 0.866025],
    ];
    let pose = cncrot::Frame {
        rotation: rot,
        translation: [10.0, 0.0, 0.0],
    };
    let t = m
        .tcp_inverse(&pose, 50.0, [0.0, 0.0, 0.0, 20.0, 80.0, 0.0])
        .unwrap();
    assert!(
        (t.axes[3] - 30.0).abs() < 1e-4 && (t.axes[4] - 90.0).abs() < 1e-4,
        "{:?}",
        t.axes
    );
    let c = m.choose(&rot, [20.0, 80.0, 0.0], Rule::Closest).unwrap();
    assert!((c.axes[0] - 30.0).abs() < 1e-4 && (c.axes[1] - 90.0).abs() < 1e-4);
    // Far from a rotation: still refused.
    let bent = [[0.0, 0.9, 0.5], [-1.0, 0.0, 0.0], [0.0, -0.5, 0.866025]];
    assert_eq!(
        m.choose(&bent, [0.0; 3], Rule::Closest).unwrap_err(),
        Error::NotARotation
    );
}

/// The AC table of docs/kinematics.md's worked example: A about X through (0, 0, 100), C
/// about Z through the origin.
fn worked_ac_table() -> Machine {
    machine(&[
        axis(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0]),
        axis(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]),
    ])
}

fn ac_table() -> Machine {
    machine(&[
        axis(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0]),
        axis(Side::Work, [0.0, 0.0, 1.0], [30.0, -20.0, 0.0]),
    ])
}

/// A path through the pole in the plane of the tilting axis (A from +10° to -10° at C =
/// 37°): A passes through 0 and C stays where it was, at the pole too (a free axis kept).
#[test]
fn tcp_path_through_the_pole_keeps_the_other_axis_still() {
    let m = ac_table();
    let mut prev = [5.0, 6.0, 7.0, 10.0, 37.0, 0.0];
    for i in 0..=2000 {
        let a = 10.0 - 0.01 * i as f64;
        let truth = [5.0, 6.0, 7.0, a, 37.0, 0.0];
        let pose = m.tcp_forward(truth, 80.0).unwrap();
        let t = m.tcp_inverse(&pose, 80.0, prev).unwrap();
        assert_eq!(t.free, a == 0.0, "{a}");
        for (got, want) in t.axes.iter().zip(truth) {
            assert!((got - want).abs() < 1e-9, "{a} {:?}", t.axes);
        }
        prev = t.axes;
    }
}

/// A path passing the pole at a small distance: C turns by 180° over the pass, as fast as
/// the direction's azimuth about C turns (computed here from the direction itself) and no
/// faster, with no jump anywhere.
#[test]
fn tcp_path_near_the_pole_turns_as_the_geometry_requires() {
    let m = ac_table();
    for miss_deg in [1.0, 1e-2, 1e-4] {
        let d0: f64 = f64::to_radians(miss_deg);
        let mut prev = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let mut first = true;
        let mut prev_azimuth = 0.0;
        let steps = 4000;
        for i in 0..=steps {
            // Tilt components: along x from -5° to +5°, along y held at the miss distance.
            let sx = f64::to_radians(-5.0 + 10.0 * i as f64 / steps as f64);
            let dir = [sx, d0, 1.0];
            let n = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
            let dir = dir.map(|x| x / n);
            // A frame with that third column.
            let x_axis = {
                let c = [dir[2], 0.0, -dir[0]];
                let n = (c[0] * c[0] + c[2] * c[2]).sqrt();
                c.map(|v| v / n)
            };
            let y_axis = [
                dir[1] * x_axis[2] - dir[2] * x_axis[1],
                dir[2] * x_axis[0] - dir[0] * x_axis[2],
                dir[0] * x_axis[1] - dir[1] * x_axis[0],
            ];
            let rot = [
                [x_axis[0], y_axis[0], dir[0]],
                [x_axis[1], y_axis[1], dir[1]],
                [x_axis[2], y_axis[2], dir[2]],
            ];
            let pose = cncrot::Frame {
                rotation: rot,
                translation: [1.0, 2.0, 3.0],
            };
            let t = m.tcp_inverse(&pose, 50.0, prev).unwrap();
            // d = (sin A sin C, sin A cos C, cos A): the azimuth atan2(dx, dy) is C (mod 180).
            let azimuth = f64::atan2(dir[0], dir[1]).to_degrees();
            if !first {
                let dc = t.axes[4] - prev[4];
                let mut da = azimuth - prev_azimuth;
                da -= 360.0 * (da / 360.0).round();
                assert!(
                    (dc - da).abs() < 1e-6,
                    "{miss_deg} {i}: C moved {dc}, azimuth {da}"
                );
            }
            first = false;
            prev_azimuth = azimuth;
            prev = t.axes;
        }
    }
}

/// Limits: a solution outside the travel gives way to the other; none inside is
/// OUT_OF_TRAVEL. Hirth: snapped, the tip still on the target.
#[test]
fn tcp_inverse_travel_and_hirth() {
    let limited = |lo, hi| {
        machine(&[
            RotaryAxis {
                limits: Some([lo, hi]),
                ..axis(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0])
            },
            axis(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]),
        ])
    };
    let free = ac_table();
    let pose = machine(&[
        axis(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0]),
        axis(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]),
    ])
    .tcp_forward([0.0, 0.0, 0.0, 30.0, 10.0, 0.0], 50.0)
    .unwrap();
    let _ = free;
    // From A = 29 the closest is A = 30; with A limited to [-90, 0] it is A = -30, C = -170.
    let t = limited(-90.0, 0.0)
        .tcp_inverse(&pose, 50.0, [0.0, 0.0, 0.0, 29.0, 0.0, 0.0])
        .unwrap();
    assert!(
        (t.axes[3] + 30.0).abs() < 1e-12 && (t.axes[4] + 170.0).abs() < 1e-9,
        "{t:?}"
    );
    assert_eq!(
        limited(-10.0, 10.0).tcp_inverse(&pose, 50.0, [0.0; 6]),
        Err(Error::OutOfTravel)
    );
    let hirth = machine(&[
        axis(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0]),
        RotaryAxis {
            hirth: Some(Hirth {
                offset: 0.0,
                step: 1.0,
            }),
            ..axis(Side::Work, [0.0, 0.0, 1.0], [0.0; 3])
        },
    ]);
    let pose = hirth
        .tcp_forward([0.0, 0.0, 0.0, 30.0, 10.4, 0.0], 50.0)
        .unwrap();
    let t = hirth
        .tcp_inverse(&pose, 50.0, [0.0, 0.0, 0.0, 29.0, 10.0, 0.0])
        .unwrap();
    assert!(
        (t.axes[4] - 10.0).abs() < 1e-12 && (t.residual[1] + 0.4).abs() < 1e-9,
        "{t:?}"
    );
    let back = hirth.tcp_forward(t.axes, 50.0).unwrap();
    for k in 0..3 {
        assert!((back.translation[k] - pose.translation[k]).abs() < 1e-9);
    }
}

/// The five-axis inverse takes the rotary positions `choose` takes with the closest rule,
/// bit for bit, on random machines with travel limits, from random previous positions
/// (the transformation solves the common case in a pass of its own).
#[test]
fn tcp_inverse_takes_the_rotary_positions_choose_takes() {
    let mut rng = Rng::new(25);
    let mut compared = 0;
    for n in 1..=3 {
        for round in 0..3000 {
            let (m, axes) = random_machine(&mut rng, n);
            let m = if round % 3 == 0 {
                let mut limited = Machine::new(Z).unwrap();
                for a in &axes {
                    let lo = rng.range(-200.0, 0.0);
                    limited = limited
                        .with_axis(RotaryAxis {
                            limits: Some([lo, lo + rng.range(30.0, 300.0)]),
                            ..*a
                        })
                        .unwrap();
                }
                limited
            } else {
                m
            };
            let theta = angles(&mut rng, n);
            let pose = m.tcp_forward(six([1.0, 2.0, 3.0], theta), 100.0).unwrap();
            let mut prev = [0.0; 3];
            for p in prev.iter_mut().take(n) {
                *p = rng.range(-720.0, 720.0);
            }
            let chosen = m.choose(&pose.rotation, prev, Rule::Closest);
            let t = m.tcp_inverse(&pose, 100.0, six([0.0; 3], prev));
            match (chosen, t) {
                (Ok(c), Ok(t)) => {
                    assert_eq!(
                        c.axes.map(f64::to_bits),
                        [t.axes[3], t.axes[4], t.axes[5]].map(f64::to_bits)
                    );
                    assert_eq!(c.free, t.free);
                    compared += 1;
                }
                (Err(a), Err(b)) => assert_eq!(a, b),
                (c, t) => panic!("{c:?} {t:?}"),
            }
        }
    }
    // 7 007 of the 9 000 reach their pose within the travel; the others fail alike.
    assert!(compared > 6500, "{compared}");
}

/// A tool 7.5e-9 rad from −Z (found by the fuzz target): the base rotation `B` turned +Z
/// onto a direction 6.5e-9 off the tool's through `1/(1 + c)`, and the five-axis inverse
/// then reached a direction that far from its target. The arc is computed stably now: `B`
/// takes +Z onto the tool direction to rounding, at and near −Z, for tools on every side.
#[test]
fn the_base_rotation_near_minus_z() {
    for b in [
        [-7.53866525610176e-9, 0.0, -1.0],
        [1e-12, -2e-12, -1.0],
        [0.0, 0.0, -1.0],
        [0.6, 0.0, -0.8],
        [0.0, 0.0, 1.0],
        [0.3, -0.4, 0.5],
    ] {
        let m = Machine::new(b)
            .unwrap()
            .with_axis(axis(Side::Tool, [0.0, -1.0, 0.0], [0.0; 3]))
            .unwrap();
        let unit = m.tool_direction();
        let f = m.forward([0.0; 3]).unwrap().rotation;
        for (i, u) in unit.iter().enumerate() {
            assert!((f[i][2] - u).abs() < 1e-15, "{b:?}: {f:?}");
        }
        // An orthonormal B.
        let ftf = mul(&cncrot::transpose(&f), &f);
        for (i, row) in ftf.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((x - want).abs() < 1e-15, "{b:?}: {ftf:?}");
            }
        }
        let pose = m
            .tcp_forward([0.0, 0.0, 0.0, 30.333, 0.0, 0.0], 10.0)
            .unwrap();
        let t = m
            .tcp_inverse(&pose, 10.0, [0.0, 0.0, 0.0, 537.984, 0.0, 0.0])
            .unwrap();
        let back = m.tcp_forward(t.axes, 10.0).unwrap();
        for i in 0..3 {
            assert!((back.rotation[i][2] - pose.rotation[i][2]).abs() < 1e-15);
            assert!((back.translation[i] - pose.translation[i]).abs() < 1e-12);
        }
    }
}

/// A machine without rotary axes (a three-axis mill): the tip is reached along the fixed
/// tool direction; any other direction is unreachable; tcp_forward puts the tip L below
/// the adapter.
#[test]
fn tcp_without_rotary_axes() {
    let m = Machine::new(Z).unwrap();
    let pose = m
        .tcp_forward([10.0, 20.0, 30.0, 0.0, 0.0, 0.0], 40.0)
        .unwrap();
    assert_eq!(pose.translation, [10.0, 20.0, -10.0]);
    let t = m.tcp_inverse(&pose, 40.0, [0.0; 6]).unwrap();
    assert_eq!(t.axes, [10.0, 20.0, 30.0, 0.0, 0.0, 0.0]);
    let tilted = cncrot::Frame {
        rotation: elementary(Axis::X, 1.0),
        translation: [0.0; 3],
    };
    assert_eq!(
        m.tcp_inverse(&tilted, 40.0, [0.0; 6]),
        Err(Error::Unreachable)
    );
    assert_eq!(
        m.tcp_forward([0.0, 0.0, 0.0, 1.0, 0.0, 0.0], 40.0),
        Err(Error::BadArgument)
    );
}

/// A head axis 2e-10 rad from the tool (found by the fuzz target): the target is 2e-10 off
/// its pole, so the solver's arguments for its angle are products of short vectors,
/// (1e-170, 0) and the like, whose squares vanish. The angle came out 90° and the sine and
/// cosine that turned the tool point those of 0°: the linear axes missed the tip by 264 mm.
/// So near its pole the axis' angle is rounding's (any angle nearly reaches the target);
/// what must hold is that the linear axes go with the angle chosen. By hand: C about −Z
/// through p = (170.562, 77.568, 272.577) carries the adapter's origin to p − Rz(−C)·p, so a
/// tip at the origin needs the linear axes at minus that (the axis' 2e-10 tilt moves it by
/// less than 1e-7 mm).
#[test]
fn tcp_inverse_near_a_pole_keeps_the_turn_it_chose() {
    let p = [170.562, 77.568, 272.577];
    let mut c = axis(
        Side::Tool,
        [2.0384681981891812e-10, -2.549311695463926e-303, -1.0],
        p,
    );
    c.limits = Some([16.705, 133.568]);
    let m = Machine::new(Z)
        .unwrap()
        .with_axis(c)
        .unwrap()
        .with_axis(axis(Side::Tool, [1.0, 0.0, 0.0], [0.0; 3]))
        .unwrap();
    let pose = cncrot::Frame {
        rotation: cncrot::IDENTITY,
        translation: [0.0; 3],
    };
    let t = m.tcp_inverse(&pose, 0.0, [0.0; 6]).unwrap();
    let angle = t.axes[3];
    assert!((16.705..=133.568).contains(&angle), "{:?}", t.axes);
    let (s, co) = angle.to_radians().sin_cos();
    // Rz(−C)·p = (x cos C + y sin C, −x sin C + y cos C, z).
    let turned = [p[0] * co + p[1] * s, -p[0] * s + p[1] * co, p[2]];
    for k in 0..3 {
        let want = -(p[k] - turned[k]);
        assert!((t.axes[k] - want).abs() < 1e-6, "{:?}", t.axes);
    }
    let back = m.tcp_forward(t.axes, 0.0).unwrap();
    assert!(back.translation.iter().all(|x| x.abs() < 1e-9), "{back:?}");
}

/// An axis without limits turns within ±`CLOSEST_MAX` (65 536°), the bound of the positions
/// a choice accepts as current: a path that winds a table up to it takes the next position
/// on the other side of a turn, or the other solution, never one beyond (a helper's find: C
/// 65 540 written, and every row after it refused as out of range).
#[test]
fn an_axis_without_limits_stays_within_the_bound() {
    use cncrot::CLOSEST_MAX;
    let m = ac_table();
    let a = m.forward([30.0, 20.0, 0.0]).unwrap().rotation;
    // From C = 65 530: 65 540 lies beyond; the choices left are C = 65 180 (A = 30) and
    // C = 65 360 (A = -30), the closer.
    let c = m.choose(&a, [30.0, 65_530.0, 0.0], Rule::Closest).unwrap();
    let want = [-30.0, 65_360.0, 0.0];
    assert!(
        c.axes.iter().zip(want).all(|(x, w)| (x - w).abs() < 1e-9),
        "{c:?}"
    );
    // Both sides of the bound, through the five-axis transformation too.
    for sign in [1.0, -1.0] {
        let mut prev = [0.0, 0.0, 0.0, 30.0, sign * (CLOSEST_MAX - 100.0), 0.0];
        for step in 0..2000 {
            let c = sign * (CLOSEST_MAX - 100.0) + sign * 0.5 * step as f64;
            let pose = m.tcp_forward([1.0, 2.0, 3.0, 30.0, c, 0.0], 50.0).unwrap();
            let t = m.tcp_inverse(&pose, 50.0, prev).unwrap();
            assert!(t.axes[4].abs() < CLOSEST_MAX, "{t:?}");
            let chosen = m.choose(&pose.rotation, [prev[3], prev[4], 0.0], Rule::Closest);
            assert_eq!(chosen.unwrap().axes, [t.axes[3], t.axes[4], t.axes[5]]);
            let back = m.tcp_forward(t.axes, 50.0).unwrap();
            let miss = (0..3)
                .map(|k| (back.translation[k] - pose.translation[k]).abs())
                .fold(0.0, f64::max);
            assert!(miss < 1e-9, "{miss}");
            prev = t.axes;
        }
    }
    // Turning only up from C = 65 530, the next C = 20 lies beyond: no position that way.
    let up = m.choose(&a, [30.0, 65_530.0, 0.0], Rule::PositiveTurn(1));
    assert_eq!(up, Err(Error::OutOfTravel));
}

/// A tool tip or a linear axis beyond ±`LENGTH_MAX` (1 km) is refused as the machine's other
/// lengths are: there a millimetre's digits are rounding (a helper's find: a tip at 1e20 mm
/// was accepted, its Z 8 192 mm apart from the next double).
#[test]
fn the_transformation_refuses_lengths_beyond_a_kilometre() {
    use cncrot::kinematics::LENGTH_MAX;
    let m = ac_table();
    let at = |x: f64| cncrot::Frame {
        rotation: cncrot::IDENTITY,
        translation: [x, 0.0, 0.0],
    };
    assert!(m.tcp_inverse(&at(LENGTH_MAX), 50.0, [0.0; 6]).is_ok());
    for x in [1e20, -2e6, 1e308] {
        assert_eq!(
            m.tcp_inverse(&at(x), 50.0, [0.0; 6]),
            Err(Error::OutOfRange)
        );
        assert_eq!(
            m.tcp_forward([0.0, x, 0.0, 0.0, 0.0, 0.0], 50.0),
            Err(Error::OutOfRange)
        );
    }
    assert!(m
        .tcp_forward([0.0, -LENGTH_MAX, 0.0, 0.0, 0.0, 0.0], 50.0)
        .is_ok());
}

/// `Rule::MasterFirst` by hand: the given axis' turn first, then the others', then the given
/// axis nearest 0°, then the others (Fanuc's order for `G53.1`).
#[test]
fn master_first_orders_turns_then_nearness_to_zero() {
    let m = ac_table();
    // Tilt 30° about X: (A 30, C 180) or (A -30, C 0).
    let f = m.forward([30.0, 180.0, 0.0]).unwrap().rotation;
    let near = |c: &cncrot::kinematics::Choice, a: f64, cc: f64| {
        (c.axes[0] - a).abs() < 1e-9 && (c.axes[1] - cc).abs() < 1e-9
    };
    // A from 5: 25° against 35°.
    let c = m.choose(&f, [5.0, 0.0, 0.0], Rule::MasterFirst(0)).unwrap();
    assert!(near(&c, 30.0, 180.0) || near(&c, 30.0, -180.0), "{c:?}");
    // C as the master, from C 10: 10° to 0 against 170° to 180.
    let c = m
        .choose(&f, [5.0, 10.0, 0.0], Rule::MasterFirst(1))
        .unwrap();
    assert!(near(&c, -30.0, 0.0), "{c:?}");
    // From (0, 90) both turn A by 30° and C by 90°, both A lie 30° from 0: C nearest 0.
    let c = m
        .choose(&f, [0.0, 90.0, 0.0], Rule::MasterFirst(0))
        .unwrap();
    assert!(near(&c, -30.0, 0.0), "{c:?}");
    // An axis the machine lacks.
    assert_eq!(
        m.choose(&f, [0.0; 3], Rule::MasterFirst(2)),
        Err(Error::BadArgument)
    );
}
