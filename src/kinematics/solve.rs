//! The inverse: every set of axis positions that gives an orientation, in closed form
//! (Paden–Kahan subproblems: a rotation about one axis that takes one direction onto
//! another, and two rotations about two axes that do).

use super::{about_axis, turn_vector, Link, Machine, MAX_AXES, MAX_SOLUTIONS, REACH_TOLERANCE};
use crate::math::{abs, atan2_deg, atan2_deg4, sin_cos_deg4, sqrt, wrap_deg};
use crate::vector::{cross, dot};
use crate::{check_rotation, rotate, Error, Matrix, Vector};

/// The isolated solutions of [`Machine::inverse`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solutions {
    /// Axis positions in degrees, `count` rows used; unused axes 0.
    pub angles: [[f64; MAX_AXES]; MAX_SOLUTIONS],
    /// How many rows are used (1 or 2).
    pub count: usize,
    /// A singular pose: one axis is free (its family is represented once, with the free
    /// axis at the given position).
    pub free: bool,
}

impl Solutions {
    /// None yet: where a solver writes them.
    pub(crate) const NONE: Solutions = Solutions {
        angles: [[0.0; MAX_AXES]; MAX_SOLUTIONS],
        count: 0,
        free: false,
    };

    /// The used rows.
    pub fn as_slice(&self) -> &[[f64; MAX_AXES]] {
        self.angles.get(..self.count).unwrap_or(&[])
    }
}

/// Up to two solutions in chain angles `φ`.
#[derive(Clone, Copy)]
pub(crate) struct Phis {
    pub(crate) phi: [[f64; 2]; 2],
    pub(crate) count: usize,
    pub(crate) free: bool,
}

/// A direction within this sine of an axis is along it: the axis is free \[choice\]. Below
/// the verification bound 1e-12 by a margin (the pose is treated as exactly singular, which
/// moves the result by at most this), above the rounding of a computed target (1e-16).
pub const POLE_SINE: f64 = 1e-14;

/// Beyond this a solution whose forward computation misses the target is dropped as not
/// a solution (a safety net: the construction reaches it to rounding).
pub(crate) const VERIFY: f64 = 1e-9;

/// The angle (degrees) of the turn about the unit vector `u` that takes `x` onto `y`
/// (both made perpendicular to `u` first; their lengths do not matter). `None` when `x` is
/// along `u`: every angle does.
pub(crate) fn turn_onto(u: Vector, x: Vector, y: Vector) -> Option<f64> {
    turn_pair(u, x, y).map(|[s, c]| atan2_deg(s, c))
}

/// The arguments `[sine, cosine]` (scaled alike) of the `atan2` that [`turn_onto`] takes:
/// so that a solver can take several angles in one four-lane call, with the same bits.
pub(crate) fn turn_pair(u: Vector, x: Vector, y: Vector) -> Option<[f64; 2]> {
    let ux = dot(u, x);
    let uy = dot(u, y);
    let xp: Vector = core::array::from_fn(|k| x[k] - ux * u[k]);
    let yp: Vector = core::array::from_fn(|k| y[k] - uy * u[k]);
    if dot(xp, xp) <= POLE_SINE * POLE_SINE {
        return None;
    }
    Some([dot(u, cross(xp, yp)), dot(xp, yp)])
}

/// Subproblem 1: `Rot(u, φ)·x = y`. The free angle `free` when `x` is along `u`.
#[inline(never)]
fn one(u: &Vector, x: &Vector, y: &Vector, free: f64) -> Result<(f64, bool), Error> {
    let (u, x, y) = (*u, *x, *y);
    if abs(dot(u, x) - dot(u, y)) > REACH_TOLERANCE {
        return Err(Error::Unreachable);
    }
    match turn_onto(u, x, y) {
        Some(phi) => Ok((phi, false)),
        // x along u: y must be x itself (the dot products agree, so y is ±u with x's sign).
        None => Ok((free, true)),
    }
}

/// Subproblem 2: `Rot(u1, φ1)·Rot(u2, φ2)·b = d` for unit vectors, `u1` not parallel to
/// `u2`. The intermediate direction `c = Rot(u2, φ2)·b = Rot(u1, −φ1)·d` lies on both
/// cones: `u1·c = u1·d`, `u2·c = u2·b`, `|c| = 1`; it is `α·u1 + β·u2 ± γ·(u1 × u2)`.
/// Written to `out`; the vectors by reference and not inlined (stack bound).
#[inline(never)]
fn two(
    u: [&Vector; 2],
    b: &Vector,
    d: &Vector,
    free: [f64; 2],
    out: &mut Phis,
) -> Result<(), Error> {
    let [u1, u2] = u;
    *out = Phis {
        phi: [[0.0; 2]; 2],
        count: 1,
        free: true,
    };
    if along(*u2, *b) {
        // The inner axis turns the tool about itself: φ2 is free.
        let (phi1, _) = one(u1, b, d, free[0])?;
        out.phi[0] = [phi1, free[1]];
        return Ok(());
    }
    if along(*u1, *d) {
        // The target along the outer axis: φ1 is free, φ2 brings b onto d.
        let d1 = rotate(&about_axis(*u1, -free[0]), *d);
        let (phi2, _) = one(u2, b, &d1, free[1])?;
        out.phi[0] = [free[0], phi2];
        return Ok(());
    }
    let mut a = Args::NONE;
    two_args(u1, u2, b, d, &mut a)?;
    *out = a.phis();
    Ok(())
}

/// Whether the unit vectors `u` and `v` are parallel within [`POLE_SINE`]: a free axis.
pub(crate) fn along(u: Vector, v: Vector) -> bool {
    let c = cross(u, v);
    dot(c, c) <= POLE_SINE * POLE_SINE
}

/// The `atan2` arguments of subproblem 2's isolated solutions: solution `k`'s two chain
/// angles in lanes `2k` (the outer axis) and `2k + 1`, its `[sine, cosine]` scaled alike;
/// unused lanes `(0, 1)`.
#[derive(Clone, Copy)]
pub(crate) struct Args {
    pub(crate) y: [f64; 4],
    pub(crate) x: [f64; 4],
    pub(crate) count: usize,
}

impl Args {
    /// No solution yet: every lane the angle 0.
    pub(crate) const NONE: Args = Args {
        y: [0.0; 4],
        x: [1.0; 4],
        count: 0,
    };

    /// The chain angles (degrees) of the solutions, in one four-lane `atan2` (the same
    /// bits as one by one).
    pub(crate) fn phis(&self) -> Phis {
        let a = atan2_deg4(self.y, self.x);
        Phis {
            phi: [[a[0], a[1]], [a[2], a[3]]],
            count: self.count,
            free: false,
        }
    }

    /// The sine and cosine of lane `j`'s angle, from its arguments (no turn computed
    /// twice): `(0, 1)` for arguments of no direction.
    fn sin_cos(&self, j: usize) -> (f64, f64) {
        sin_cos_of(
            self.y.get(j).copied().unwrap_or(0.0),
            self.x.get(j).copied().unwrap_or(1.0),
        )
    }
}

/// The sine and cosine of `atan2(y, x)` without the angle: `(y, x)` made a unit vector,
/// `(0, 1)` (the angle 0, as `atan2` gives it) for `(0, 0)`. Arguments so small (or large)
/// that their squares leave the range of doubles are scaled first: near a pole they are
/// products of short vectors (the fuzz target found `(1e-170, 0)`, whose square vanished:
/// the angle 90° with the sine and cosine of 0°).
#[inline(always)]
pub(crate) fn sin_cos_of(y: f64, x: f64) -> (f64, f64) {
    let r = sqrt(y * y + x * x);
    // Written so that NaN takes the scaled way. Inline, not a call: a call in the solver's
    // loops would make every vector register live across it spill (stack bound).
    if r > 1e-150 && r < 1e150 {
        return (y / r, x / r);
    }
    let m = if abs(y) >= abs(x) { abs(y) } else { abs(x) };
    // Written so that NaN (of both) gives the angle 0, as `atan2` gives it.
    let some = m > 0.0;
    if !some {
        return (0.0, 1.0);
    }
    let (y, x) = (y / m, x / m);
    let r = sqrt(y * y + x * x);
    (y / r, x / r)
}

/// Subproblem 2 away from its poles (`b` not along `u2`, `d` not along `u1`): the isolated
/// solutions, one or two, as `atan2` arguments, written to `out`. The vectors by
/// reference, the result in place and not inlined: a caller keeps no copies for the call
/// (stack bound).
#[inline(never)]
pub(crate) fn two_args(
    u1: &Vector,
    u2: &Vector,
    b: &Vector,
    d: &Vector,
    out: &mut Args,
) -> Result<(), Error> {
    let (u1, u2, b, d) = (*u1, *u2, *b, *d);
    // In the orthonormal frame u1, e2 (u2 made perpendicular to u1), n = u1 × u2 / |…|:
    // c = a1·u1 + p2·e2 ± g·n. The height g² = r² − q² is formed from a cone radius r
    // computed as a cross product (|u × v|, exact to rounding even when tiny) instead of
    // 1 − |p|², which loses half the digits near the pole.
    let k = dot(u1, u2);
    let w = cross(u1, u2);
    let wn = sqrt(dot(w, w));
    let n: Vector = w.map(|x| x / wn);
    let e2: Vector = core::array::from_fn(|i| (u2[i] - k * u1[i]) / wn);
    let (a1, a2) = (dot(u1, d), dot(u2, b));
    let p2 = (a2 - k * a1) / wn;
    let q1 = (a1 - k * a2) / wn;
    let (c1, c2) = (cross(u1, d), cross(u2, b));
    let (r1, r2) = (sqrt(dot(c1, c1)), sqrt(dot(c2, c2)));
    let h = if r1 <= r2 {
        (r1 - abs(p2)) * (r1 + abs(p2))
    } else {
        (r2 - abs(q1)) * (r2 + abs(q1))
    };
    // NaN refuses too.
    if h.is_nan() || h < -2.0 * REACH_TOLERANCE {
        return Err(Error::Unreachable);
    }
    let gamma = sqrt(h.max(0.0));
    let p: Vector = core::array::from_fn(|i| a1 * u1[i] + p2 * e2[i]);
    // The turns as `turn_pair` takes them (about u2 from b to c, about u1 from c to d),
    // with what both solutions share formed once: b and d made perpendicular to the axis
    // they turn about, and with them c's sines and cosines in two dot products each
    // (u·(x⊥ × c⊥) = c·(u × x⊥), x⊥·c⊥ = x⊥·c, as x⊥ and u × x⊥ are perpendicular to u).
    let b2: Vector = core::array::from_fn(|i| b[i] - a2 * u2[i]);
    let d1: Vector = core::array::from_fn(|i| d[i] - a1 * u1[i]);
    let (s2, s1) = (cross(u2, b2), cross(d1, u1));
    *out = Args::NONE;
    // A turn of no direction (b along u2, d along u1: a pole, which the callers leave out
    // before) has no isolated solution.
    if dot(b2, b2) <= POLE_SINE * POLE_SINE || dot(d1, d1) <= POLE_SINE * POLE_SINE {
        return Err(Error::Unreachable);
    }
    let signs: &[f64] = if gamma > 0.0 { &[1.0, -1.0] } else { &[1.0] };
    for &sign in signs {
        let c: Vector = core::array::from_fn(|i| p[i] + sign * gamma * n[i]);
        let k = 2 * out.count;
        if let (Some(y), Some(x)) = (out.y.get_mut(k..k + 2), out.x.get_mut(k..k + 2)) {
            y.copy_from_slice(&[dot(c, s1), dot(c, s2)]);
            x.copy_from_slice(&[dot(c, d1), dot(c, b2)]);
            out.count += 1;
        }
    }
    if out.count == 0 {
        return Err(Error::Unreachable);
    }
    Ok(())
}

impl Machine {
    /// Every isolated set of axis positions within (-180°, 180°] per axis whose tool frame
    /// has the orientation `target` (a rotation, checked as [`check_rotation`]), limits
    /// ignored (see [`Machine::choose`]).
    ///
    /// With three axes the whole orientation is matched; with fewer, only the tool
    /// direction (the target's third column): the rotation about the tool that the axes
    /// cannot make is what [`Machine::choose`] returns as the remaining frame.
    ///
    /// At a singular pose (the target direction along an axis, which is then free) the
    /// family is returned once, the free axis at 0, and [`Solutions::free`] is set.
    /// [`Error::Unreachable`]: no positions give that orientation (farther than
    /// [`super::REACH_TOLERANCE`]).
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// use cncrot::{elementary, mul, Axis};
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3])).unwrap();
    /// // Tilt 30° about Y: C = 0, B = 30, or C = 180, B = -30.
    /// let s = m.inverse(&elementary(Axis::Y, 30.0)).unwrap();
    /// assert_eq!(s.count, 2);
    /// let mut rows = s.as_slice().to_vec();
    /// rows.sort_by(|a, b| a[0].total_cmp(&b[0]));
    /// assert!(rows[0][0].abs() < 1e-12 && (rows[0][1] - 30.0).abs() < 1e-12);
    /// assert!((rows[1][0] - 180.0).abs() < 1e-12 && (rows[1][1] + 30.0).abs() < 1e-12);
    /// ```
    pub fn inverse(&self, target: &Matrix) -> Result<Solutions, Error> {
        check_rotation(target)?;
        self.solve(target, [0.0; MAX_AXES], true)
    }

    /// [`Machine::inverse`] with a free axis placed at its position in `free` (unwrapped),
    /// for a `target` already checked as a rotation. `verify`: drop a solution whose
    /// forward computation misses the target (a safety net; the five-axis transformation
    /// checks the one it takes instead, at a third of the cost).
    pub(crate) fn solve(
        &self,
        target: &Matrix,
        free: [f64; MAX_AXES],
        verify: bool,
    ) -> Result<Solutions, Error> {
        let mut out = Solutions::NONE;
        self.solve_into(target, &free, verify, &mut out)?;
        Ok(out)
    }

    /// [`Machine::solve`] written to `out` (which a caller keeps in its own frame: no
    /// copy on the way, stack bound). Not inlined.
    #[inline(never)]
    pub(crate) fn solve_into(
        &self,
        target: &Matrix,
        free: &[f64; MAX_AXES],
        verify: bool,
        out: &mut Solutions,
    ) -> Result<(), Error> {
        let free = *free;
        if !free.iter().all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        // A target rounded where it was written (a pose printed to 4 or 6 decimals, a float
        // one) passes `check_rotation` but would miss every solution's verification by its
        // rounding: solved for the rotation nearest to it. An exact one (every rotation the
        // library computes) is taken bit for bit as it is.
        let rounded;
        let target = if crate::rotation::is_exact(target) {
            target
        } else {
            rounded = crate::rotation::reorthonormalize(target);
            &rounded
        };
        let (chain, n) = self.chain();
        let mut phis = Phis {
            phi: [[0.0; 2]; 2],
            count: 1,
            free: false,
        };
        let mut third = [0.0f64; MAX_SOLUTIONS];
        self.chain_angles(&chain, n, target, &free, &mut phis, &mut third)?;
        *out = Solutions {
            free: phis.free,
            ..Solutions::NONE
        };
        for (p, t3) in phis.phi.iter().zip(third).take(phis.count) {
            self.keep_solution(&chain, n, &[p[0], p[1], t3], target, verify, out);
        }
        if out.count == 0 {
            return Err(Error::Unreachable);
        }
        Ok(())
    }

    /// One solution of [`Machine::solve_into`] from its chain angles `phi`: the positions
    /// (each within (-180°, 180°]) added to `out` unless `verify` finds them missing
    /// `target`. Not inlined (stack bound).
    #[inline(never)]
    fn keep_solution(
        &self,
        chain: &[Link; MAX_AXES],
        n: usize,
        phi: &[f64; MAX_AXES],
        target: &Matrix,
        verify: bool,
        out: &mut Solutions,
    ) {
        let mut theta = [0.0; MAX_AXES];
        for (l, &ph) in chain.iter().zip(phi).take(n) {
            let offset = self.stored().get(l.index).map_or(0.0, |a| a.offset);
            if let Some(t) = theta.get_mut(l.index) {
                *t = wrap_deg(offset + l.sign * ph);
            }
        }
        if !verify || self.misses(&theta, target, n) <= VERIFY {
            if let Some(slot) = out.angles.get_mut(out.count) {
                *slot = theta;
                out.count += 1;
            }
        }
    }

    /// The chain angles of [`Machine::solve_into`]'s solutions (degrees), the third
    /// link's apart; a free axis kept at its position in `free`.
    #[inline(always)]
    fn chain_angles(
        &self,
        chain: &[Link; MAX_AXES],
        n: usize,
        target: &Matrix,
        free: &[f64; MAX_AXES],
        phis: &mut Phis,
        third: &mut [f64; MAX_SOLUTIONS],
    ) -> Result<(), Error> {
        let link = |j: usize| chain.get(j).copied();
        // A free axis kept at `free`, as its chain angle.
        let free_phi = |j: usize| match link(j) {
            Some(l) => l.sign * self.turn(l.index, *free),
            None => 0.0,
        };
        let b = self.tool_direction();
        let d = [target[0][2], target[1][2], target[2][2]];
        let [l1, l2, l3] = chain;
        match n {
            0 => {
                let e: Vector = core::array::from_fn(|k| d[k] - b[k]);
                let e2 = dot(e, e);
                if e2.is_nan() || e2 > REACH_TOLERANCE * REACH_TOLERANCE {
                    return Err(Error::Unreachable);
                }
            }
            1 => {
                let (phi, free1) = one(&l1.axis, &b, &d, free_phi(0))?;
                phis.phi[0] = [phi, 0.0];
                phis.free = free1;
            }
            2 => {
                let free = [free_phi(0), free_phi(1)];
                two([&l1.axis, &l2.axis], &b, &d, free, phis)?;
            }
            3 => {
                let u = [l1.axis, l2.axis, l3.axis];
                let free = [free_phi(0), free_phi(1)];
                self.three(target, &u, free, phis, third)?;
            }
            _ => return Err(Error::BadArgument),
        }
        Ok(())
    }

    /// Three axes: the third axis keeps its own direction, the first two bring it where
    /// the target has it, the third turns about it for the rest; a free axis at `free`.
    /// Not inlined: its matrices are not on the stack when one or two axes are solved
    /// (stack bound).
    #[inline(never)]
    fn three(
        &self,
        target: &Matrix,
        u: &[Vector; 3],
        free: [f64; 2],
        phis: &mut Phis,
        third: &mut [f64; MAX_SOLUTIONS],
    ) -> Result<(), Error> {
        let [u1, u2, u3] = u;
        let m = self.without_base(target);
        let target_u3 = rotate(&m, *u3);
        if along(*u2, *u3) || along(*u1, target_u3) {
            two([u1, u2], u3, &target_u3, free, phis)?;
            *third = third_angles(u, &m, phis);
        } else {
            // Isolated: as the five-axis transformation solves it, bit for bit.
            let mut args = Args::NONE;
            two_args(u1, u2, u3, &target_u3, &mut args)?;
            *phis = args.phis();
            *third = third_from_args(u, &m, &args);
        }
        Ok(())
    }

    /// How far the orientation at `theta` is from `target`: the largest element difference
    /// of the whole rotation with three axes, of the tool direction with fewer.
    #[inline(never)]
    pub(crate) fn misses(&self, theta: &[f64; MAX_AXES], target: &Matrix, n: usize) -> f64 {
        let r = self.rotation_at(*theta);
        let mut worst = 0.0f64;
        for (row_r, row_t) in r.iter().zip(target) {
            for (j, (a, b)) in row_r.iter().zip(row_t).enumerate() {
                if n == 3 || j == 2 {
                    // NaN would make the miss infinite.
                    let e = abs(a - b);
                    worst = if e <= worst { worst } else { e };
                }
            }
        }
        worst
    }
}

/// The third angles of a three-axis machine's solutions: the turn about `u3` left once
/// the first two axes of each solution have turned (`m` the target without the tool
/// base): the sines and cosines of both solutions' first two angles in one four-lane
/// call, then [`third_args`] as for isolated solutions. Not inlined: its lanes would
/// otherwise sit in the frame of `solve` under every subproblem (stack bound).
#[inline(never)]
pub(crate) fn third_angles(u: &[Vector; 3], m: &Matrix, phis: &Phis) -> [f64; MAX_SOLUTIONS] {
    // The first two angles' sines and cosines stand for their `atan2` arguments.
    let [p, q] = phis.phi;
    let (s, c) = lanes_sin_cos([p[0], p[1], q[0], q[1]]);
    let mut third = Args {
        y: s,
        x: c,
        count: phis.count.min(MAX_SOLUTIONS),
    };
    third_args(u, m, &mut third);
    let t = lanes_atan2(&third.y, &third.x);
    [t[0], t[1]]
}

/// The third angles of a three-axis machine's isolated solutions, as [`third_angles`]
/// takes them, from the first two angles' `atan2` arguments (their sines and cosines
/// without a turn computed twice) and with the vector turned rather than the matrix:
/// `x` turned back by the first two turns from the target `m`, against `x` itself.
#[inline(never)]
pub(crate) fn third_from_args(u: &[Vector; 3], m: &Matrix, args: &Args) -> [f64; MAX_SOLUTIONS] {
    let mut third = *args;
    third_args(u, m, &mut third);
    let t = atan2_deg4(third.y, third.x);
    [t[0], t[1]]
}

/// The `atan2` arguments of [`third_from_args`], in place of the first two angles' in
/// `args`: solution `k`'s in lane `k`, unused lanes `(0, 1)`. Not inlined, its inputs by
/// reference (stack bound).
#[inline(never)]
pub(crate) fn third_args(u: &[Vector; 3], m: &Matrix, args: &mut Args) {
    // The four lanes' sines and cosines first, in place: the vector work below then has
    // no branch of their rare scaled way among its values (stack bound).
    for j in 0..4 {
        let (s, c) = args.sin_cos(j);
        if let (Some(y), Some(x)) = (args.y.get_mut(j), args.x.get_mut(j)) {
            (*y, *x) = (s, c);
        }
    }
    let [u1, u2, u3] = *u;
    let x = perpendicular_to(u3);
    let v = rotate(m, x);
    let (mut ys, mut xs) = ([0.0; 4], [1.0; 4]);
    for k in 0..args.count.min(MAX_SOLUTIONS) {
        let at = |j: usize| {
            (
                args.y.get(j).copied().unwrap_or(0.0),
                args.x.get(j).copied().unwrap_or(1.0),
            )
        };
        let ((s1, c1), (s2, c2)) = (at(2 * k), at(2 * k + 1));
        // Rot(u2, −φ2)·Rot(u1, −φ1)·v.
        let back = turn_vector(u2, -s2, c2, turn_vector(u1, -s1, c1, v));
        // A lane left at (0, 1) gives 0 (never: x is perpendicular to u3).
        if let (Some([y, xx]), Some(ty), Some(tx)) =
            (turn_pair(u3, x, back), ys.get_mut(k), xs.get_mut(k))
        {
            (*ty, *tx) = (y, xx);
        }
    }
    (args.y, args.x) = (ys, xs);
}

/// [`sin_cos_deg4`] in a frame of its own: its lanes are not on the stack while
/// [`third_angles`] works out its `atan2` arguments (stack bound).
#[inline(never)]
fn lanes_sin_cos(deg: [f64; 4]) -> ([f64; 4], [f64; 4]) {
    sin_cos_deg4(deg)
}

/// [`atan2_deg4`] in a frame of its own (see [`lanes_sin_cos`]).
#[inline(never)]
pub(crate) fn lanes_atan2(y: &[f64; 4], x: &[f64; 4]) -> [f64; 4] {
    atan2_deg4(*y, *x)
}

/// A unit vector perpendicular to the unit vector `u`.
fn perpendicular_to(u: Vector) -> Vector {
    // Crossed with the coordinate axis least aligned with u, so the result is never short.
    let e = if abs(u[0]) <= abs(u[1]) && abs(u[0]) <= abs(u[2]) {
        [1.0, 0.0, 0.0]
    } else if abs(u[1]) <= abs(u[2]) {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let c = cross(u, e);
    let len = sqrt(dot(c, c));
    c.map(|x| x / len)
}
