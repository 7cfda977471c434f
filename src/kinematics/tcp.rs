//! The five-axis transformation (tool centre point): the tool tip and direction in
//! workpiece coordinates from every machine axis, linear and rotary, and back, as a
//! controller computes it in each interpolation cycle (SINUMERIK `TRAORI`, Heidenhain
//! `M128` / `FUNCTION TCPM`, Fanuc `G43.4` / `G43.5`) and a post-processor for each CL
//! point.
//!
//! The linear axes `X, Y, Z` are the machine coordinates of the tool adapter's reference
//! point: the origin of the axis points `p_k` when every rotary axis is at its initial
//! position (so that `X = Y = Z = 0` with every turn 0 puts the adapter at the machine
//! origin). For positions `θ` and a tool of length `L` along the base direction `b`:
//!
//! - the tool tip in machine coordinates is `(X, Y, Z) + T·(−L·b)` (the head's turns carry
//!   the tip around their pivots; the linear axes carry the head);
//! - in workpiece coordinates it is `W⁻¹·((X, Y, Z) + T·(−L·b))` (the table's turns carry
//!   the workpiece);
//! - the tool direction is the third column of `F = W⁻¹·T·B`, which is also the rotation of
//!   the pose.
//!
//! The inverse takes the rotary solution that [`Machine::choose`] takes from the previous
//! positions (the last cycle's), then the linear axes that put the tip on the target:
//! `(X, Y, Z) = W·tip − T·(−L·b)`.

use super::choose::place;
use super::solve::{along, third_angles, turn_onto, two_isolated, Phis, VERIFY};
use super::{
    about_axis_sc, Choice, Machine, Rule, LENGTH_MAX, MAX_AXES, MAX_SOLUTIONS, REACH_TOLERANCE,
};
use crate::math::{abs, sin_cos_deg4, wrap_deg};
use crate::vector::dot;
use crate::{
    check_rotation, mul, rotate, transpose, Error, Frame, Matrix, Vector, CLOSEST_MAX, IDENTITY,
};

/// Machine axes of the transformation: linear `X, Y, Z` (the tool adapter's reference
/// point), then the rotary axes in the order they were added (unused ones 0).
pub const TCP_AXES: usize = 6;

/// What [`Machine::tcp_inverse`] returns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tcp {
    /// `X, Y, Z` (mm) then the rotary positions (degrees; unused ones 0).
    pub axes: [f64; TCP_AXES],
    /// Hirth snapping: the rotary position moved to minus the exact one (0 without a grid).
    /// The linear axes keep the tip on the target; the direction is off by the residual.
    pub residual: [f64; MAX_AXES],
    /// A singular pose: a free rotary axis stayed at its previous position.
    pub free: bool,
}

/// The pose of a CL point (a tool tip and a tool direction in workpiece coordinates, as
/// CAM systems write them and [`Machine::tcp_inverse`] takes them): the translation `tip`,
/// the third column `direction` made a unit vector, X' the workpiece's X made
/// perpendicular to it, or Y for a direction with an X component of 0.9 or more
/// \[choice: only the direction counts for a machine of fewer than three rotary axes; with
/// three, the turn about the tool is this frame's\], Y' = Z' × X'. A zero or non-finite
/// direction: [`Error::Degenerate`].
///
/// ```
/// let p = cncrot::kinematics::cl_pose([10.0, 0.0, 0.0], [0.0, 0.0, 2.0]).unwrap();
/// assert_eq!(p.rotation, cncrot::IDENTITY);
/// assert_eq!(p.translation, [10.0, 0.0, 0.0]);
/// ```
pub fn cl_pose(tip: Vector, direction: Vector) -> Result<Frame, Error> {
    let d = crate::unit_vector(direction)?;
    let hint = if abs(d[0]) < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    Ok(Frame {
        // From `direction` as given: `rotation_from_z_x` makes it a unit vector itself.
        rotation: crate::rotation_from_z_x(direction, hint)?,
        translation: tip,
    })
}

/// The isolated solutions' positions, one row per solution.
type Positions = [[f64; MAX_AXES]; MAX_SOLUTIONS];

impl Machine {
    /// The tool's pose in workpiece coordinates at machine axes `axes` (`X, Y, Z` in mm,
    /// then the rotary positions in degrees, unused ones 0) with a tool of length
    /// `tool_length` (mm): the rotation `F` of [`Machine::forward`], its third column the
    /// tool direction, and as translation the tool tip.
    ///
    /// Errors: [`Error::NotFinite`], [`Error::BadArgument`] (an unused rotary position not
    /// 0), [`Error::OutOfRange`] (a tool length beyond ±[`LENGTH_MAX`], a result that
    /// overflows).
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// // A table tilting about X through (0, 0, 100) (A), carrying a rotary table about Z (C).
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3])).unwrap();
    /// // A = 90°: the workpiece tilts up about the line y = 0, z = 100; the tool, 50 mm long,
    /// // with its adapter at (0, 0, 150), has its tip at the machine point (0, 0, 100),
    /// // which is on the tilt axis: it stays the workpiece point (0, 0, 100).
    /// let pose = m.tcp_forward([0.0, 0.0, 150.0, 90.0, 0.0, 0.0], 50.0).unwrap();
    /// assert!(pose.translation[1].abs() < 1e-12 && (pose.translation[2] - 100.0).abs() < 1e-12);
    /// // The tool, along the machine's +Z, is along +Y of the workpiece tilted by 90°:
    /// // Rx(-90°)·e_z = (0, 1, 0).
    /// assert!((pose.rotation[1][2] - 1.0).abs() < 1e-15);
    /// ```
    pub fn tcp_forward(&self, axes: [f64; TCP_AXES], tool_length: f64) -> Result<Frame, Error> {
        if !(axes.iter().all(|x| x.is_finite()) && tool_length.is_finite()) {
            return Err(Error::NotFinite);
        }
        let theta = self.positions([axes[3], axes[4], axes[5]])?;
        length_in_range(tool_length)?;
        let r = self.turns(theta);
        let at = self.tool_point(&r, self.tip_in_tool(tool_length));
        let machine: Vector = core::array::from_fn(|k| axes[k] + at[k]);
        let pose = Frame {
            rotation: self.rotation_of(&r),
            translation: self.work_point_inverse(&r, machine),
        };
        finite_frame(pose)
    }

    /// The machine axes that put the tool tip of a tool of length `tool_length` (mm) at
    /// the translation of `pose` with the tool direction of its third column: the rotary
    /// solution continuous with `previous` (the last cycle's axes, as `tcp_forward` takes
    /// them; its linear part is only checked), then the linear axes.
    ///
    /// The rotary positions are those [`Machine::choose`] takes with [`Rule::Closest`]
    /// from the previous rotary positions: whole turns unwound toward them, within the
    /// travel limits and Hirth grids. With three rotary axes the whole rotation of `pose`
    /// is matched; with fewer, the tool direction, and the turn about the tool is left to
    /// the frame. At a pole (the direction along a rotary axis, within
    /// [`super::POLE_SINE`]) the free axis stays at its previous position
    /// ([`Tcp::free`]); near one, the exact solution, so that an axis turns as fast as
    /// the path requires and no faster.
    ///
    /// Errors: [`Error::Unreachable`], [`Error::OutOfTravel`], [`Error::NotARotation`],
    /// [`Error::NotFinite`], [`Error::BadArgument`] (an unused previous rotary position
    /// not 0), [`Error::OutOfRange`] (a previous rotary position of magnitude
    /// [`crate::CLOSEST_MAX`] or more, a tool length beyond ±[`LENGTH_MAX`], a result
    /// that overflows).
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// use cncrot::Frame;
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3])).unwrap();
    /// let pose = m.tcp_forward([10.0, 20.0, 150.0, 30.0, 40.0, 0.0], 50.0).unwrap();
    /// let t = m.tcp_inverse(&pose, 50.0, [0.0, 0.0, 0.0, 25.0, 45.0, 0.0]).unwrap();
    /// let want = [10.0, 20.0, 150.0, 30.0, 40.0, 0.0];
    /// assert!(t.axes.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-9));
    /// ```
    pub fn tcp_inverse(
        &self,
        pose: &Frame,
        tool_length: f64,
        previous: [f64; TCP_AXES],
    ) -> Result<Tcp, Error> {
        self.tcp_inverse_with(pose, tool_length, previous, Rule::Closest)
    }

    /// [`Machine::tcp_inverse`] with the rotary solution picked by `rule`: a priority axis
    /// and its side ([`Rule::Minus`] / [`Rule::Plus`]: the solution with that axis' lower
    /// or higher position, as `SEQ-`/`SEQ+` ask) or its direction of travel
    /// ([`Rule::PositiveTurn`] / [`Rule::NegativeTurn`], as `G53.1 P1`/`P2` ask), or the
    /// other solution of the pair ([`Rule::Inverse`]). Whole turns are unwound toward
    /// `previous` in every case.
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Rule, Side};
    /// // An AC table: A about X through (0, 0, 100), C on it.
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3])).unwrap();
    /// let pose = m.tcp_forward([0.0, 0.0, 150.0, 30.0, 90.0, 0.0], 50.0).unwrap();
    /// // A is the priority axis, its lower position: A = -30°, C = -90°, the same tip.
    /// let t = m.tcp_inverse_with(&pose, 50.0, [0.0; 6], Rule::Minus(0)).unwrap();
    /// assert!((t.axes[3] + 30.0).abs() < 1e-12 && (t.axes[4] + 90.0).abs() < 1e-12);
    /// let back = m.tcp_forward(t.axes, 50.0).unwrap();
    /// assert!((back.translation[2] - pose.translation[2]).abs() < 1e-12);
    /// ```
    pub fn tcp_inverse_with(
        &self,
        pose: &Frame,
        tool_length: f64,
        previous: [f64; TCP_AXES],
        rule: Rule,
    ) -> Result<Tcp, Error> {
        let tip = pose.translation;
        if !(tip.iter().all(|x| x.is_finite())
            && tool_length.is_finite()
            && previous.iter().all(|x| x.is_finite()))
        {
            return Err(Error::NotFinite);
        }
        length_in_range(tool_length)?;
        let current = [previous[3], previous[4], previous[5]];
        if rule == Rule::Closest {
            if let Some(t) = self.tcp_closest(pose, tool_length, current)? {
                return Ok(t);
            }
        }
        self.tcp_general(pose, tool_length, current, rule)
    }

    /// The common case of [`Machine::tcp_inverse`]: the checks of `settle`, in its order,
    /// then one or two axes away from a pole in one pass. `None`: the general way decides.
    /// Not inlined, like the general way: each path's frames stack alone (stack bound).
    #[inline(never)]
    fn tcp_closest(
        &self,
        pose: &Frame,
        tool_length: f64,
        current: [f64; MAX_AXES],
    ) -> Result<Option<Tcp>, Error> {
        check_rotation(&pose.rotation)?;
        let cur = self.positions(current)?;
        if !cur.iter().all(|x| abs(*x) < CLOSEST_MAX) {
            return Err(Error::OutOfRange);
        }
        match self.closest_isolated(&pose.rotation, cur) {
            Some(c) => self.tcp_linear(&c?, pose, tool_length, true),
            None => Ok(None),
        }
    }

    /// The general way (a pole, a rule other than the closest, a choice that
    /// missed its verification or was snapped to a Hirth grid): the choice among verified
    /// solutions, as `choose` makes it.
    #[inline(never)]
    fn tcp_general(
        &self,
        pose: &Frame,
        tool_length: f64,
        current: [f64; MAX_AXES],
        rule: Rule,
    ) -> Result<Tcp, Error> {
        // Verified solutions at once: the first-unverified round of the common case would
        // keep a second choice in this frame, on the deepest path (stack bound).
        let c = self.settle(&pose.rotation, current, rule, true)?;
        self.tcp_linear(&c, pose, tool_length, false)?
            .ok_or(Error::Unreachable)
    }

    /// The rotary positions [`Machine::settle`] takes for [`Rule::Closest`] (unverified),
    /// away from the poles, solved and placed in one pass over fixed arrays: the same
    /// solutions in the same order, the same placement, the distances summed in the same
    /// order, so the same choice. `None`: another case (no axis, a pole), which the general
    /// path decides. Not inlined (stack bound).
    #[inline(never)]
    fn closest_isolated(
        &self,
        target: &Matrix,
        current: [f64; MAX_AXES],
    ) -> Option<Result<Choice, Error>> {
        let (thetas, count) = match self.isolated(target)? {
            Ok(p) => p,
            Err(e) => return Some(Err(e)),
        };
        let axes = self.stored();
        let mut best: Option<([f64; MAX_AXES], [f64; MAX_AXES], f64)> = None;
        'solutions: for theta in thetas.iter().take(count) {
            // Placed as `settle` places them, the distance summed in axis order.
            let (mut placed, mut residual, mut distance) = ([0.0; MAX_AXES], [0.0; MAX_AXES], 0.0);
            for (k, a) in axes.iter().enumerate() {
                let (Some(&angle), Some(&cur)) = (theta.get(k), current.get(k)) else {
                    continue;
                };
                let Some((x, r)) = place(a, angle, cur) else {
                    continue 'solutions;
                };
                if let (Some(ax), Some(re)) = (placed.get_mut(k), residual.get_mut(k)) {
                    *ax = x;
                    *re = r;
                }
                distance += (x - cur) * (x - cur);
            }
            if best.map_or(true, |q| distance < q.2) {
                best = Some((placed, residual, distance));
            }
        }
        Some(match best {
            Some((axes, residual, _)) => Ok(Choice {
                axes,
                residual,
                remaining: IDENTITY,
                free: false,
            }),
            None => Err(Error::OutOfTravel),
        })
    }

    /// The isolated solutions of `target` as [`Machine::solve`] computes and writes them
    /// (positions within (-180°, 180°], in axis order), and their count; `None` at a pole
    /// or without axes. Not inlined: its matrices are gone from the stack when the
    /// solutions are placed (stack bound).
    #[inline(never)]
    fn isolated(&self, target: &Matrix) -> Option<Result<(Positions, usize), Error>> {
        let n = self.axis_count();
        if n == 0 {
            return None;
        }
        let (chain, _) = self.chain();
        let [l1, l2, l3] = chain;
        let b = self.tool_direction();
        let d = [target[0][2], target[1][2], target[2][2]];
        let mut third = [0.0; MAX_SOLUTIONS];
        let phis = if n == MAX_AXES {
            // As `solve` does it: the first two axes bring the third's direction where the
            // target has it, the third turns about it for the rest.
            let m = mul(target, &transpose(&self.base()));
            let u3 = l3.axis;
            let t3 = rotate(&m, u3);
            if along(l2.axis, u3) || along(l1.axis, t3) {
                return None;
            }
            let phis = match two_isolated(l1.axis, l2.axis, u3, t3) {
                Ok(p) => p,
                Err(e) => return Some(Err(e)),
            };
            third = third_angles(l1.axis, l2.axis, u3, &m, &phis);
            phis
        } else if n == 1 {
            // Subproblem 1, as `one` solves it; a pole goes the general way.
            let u = l1.axis;
            if abs(dot(u, b) - dot(u, d)) > REACH_TOLERANCE {
                return Some(Err(Error::Unreachable));
            }
            let phi = turn_onto(u, b, d)?;
            Phis {
                phi: [[phi, 0.0], [0.0; 2]],
                count: 1,
                free: false,
            }
        } else {
            if along(l2.axis, b) || along(l1.axis, d) {
                return None;
            }
            match two_isolated(l1.axis, l2.axis, b, d) {
                Ok(p) => p,
                Err(e) => return Some(Err(e)),
            }
        };
        let mut thetas = [[0.0; MAX_AXES]; MAX_SOLUTIONS];
        let axes = self.stored();
        for ((p, t3), theta) in phis.phi.iter().zip(third).zip(&mut thetas) {
            // The positions as `solve` writes them.
            for (link, ph) in chain.iter().zip([p[0], p[1], t3]).take(n) {
                let offset = axes.get(link.index).map_or(0.0, |a| a.offset);
                if let Some(t) = theta.get_mut(link.index) {
                    *t = wrap_deg(offset + link.sign * ph);
                }
            }
        }
        Some(Ok((thetas, phis.count.min(MAX_SOLUTIONS))))
    }

    /// The linear axes for the rotary choice `c`: `None` when `verify` is set and the
    /// choice misses the pose's rotation or was snapped to a Hirth grid. Not inlined: its
    /// turns would otherwise sit in the caller's frame under the solver (stack bound).
    #[inline(never)]
    fn tcp_linear(
        &self,
        c: &Choice,
        pose: &Frame,
        tool_length: f64,
        verify: bool,
    ) -> Result<Option<Tcp>, Error> {
        let r = self.turns(c.axes);
        if verify {
            let snapped = c.residual.iter().any(|&x| x != 0.0);
            // Written so that NaN retries.
            let reached = self.rotation_misses(&r, &pose.rotation) <= VERIFY;
            if snapped || !reached {
                return Ok(None);
            }
        }
        let at = self.tool_point(&r, self.tip_in_tool(tool_length));
        let on = self.work_point(&r, pose.translation);
        let [x, y, z] = core::array::from_fn(|k| on[k] - at[k] + 0.0);
        let [a, b, cc] = c.axes;
        let axes = [x, y, z, a, b, cc];
        if !axes.iter().all(|v| v.is_finite()) {
            return Err(Error::OutOfRange);
        }
        Ok(Some(Tcp {
            axes,
            residual: c.residual,
            free: c.free,
        }))
    }

    /// How far the rotation at the turns `r` is from `target`: the largest element
    /// difference of the whole rotation with three axes, of the tool direction with fewer.
    fn rotation_misses(&self, r: &[Matrix; MAX_AXES], target: &Matrix) -> f64 {
        let whole = self.axis_count() == MAX_AXES;
        if !whole {
            // The direction alone: the chain applied to `b`, vector by vector.
            let (chain, n) = self.chain();
            let mut v = self.tool_direction();
            for link in chain.iter().take(n).rev() {
                if let Some(rk) = r.get(link.index) {
                    v = if link.sign < 0.0 {
                        rotate(&transpose(rk), v)
                    } else {
                        rotate(rk, v)
                    };
                }
            }
            let e = [0, 1, 2].map(|i| abs(v[i] - target[i][2]));
            // NaN would make the miss NaN, which the caller refuses.
            return e[0].max(e[1]).max(e[2]) + (e[0] + e[1] + e[2]) * 0.0;
        }
        let reached = self.rotation_of(r);
        let mut worst = 0.0f64;
        for (row_r, row_t) in reached.iter().zip(target) {
            for (j, (a, b)) in row_r.iter().zip(row_t).enumerate() {
                if whole || j == 2 {
                    // NaN would make the miss infinite.
                    let e = abs(a - b);
                    worst = if e <= worst { worst } else { e };
                }
            }
        }
        worst
    }

    /// The tool tip in the tool adapter's system: `−L·b`.
    fn tip_in_tool(&self, length: f64) -> Vector {
        self.tool_direction().map(|x| -length * x + 0.0)
    }

    /// The turn of each axis at positions `theta` as a rotation, in the order the axes
    /// were added (the identity for unused ones): every sine and cosine in one four-lane
    /// call.
    pub(crate) fn turns(&self, theta: [f64; MAX_AXES]) -> [Matrix; MAX_AXES] {
        let t = [
            self.turn(0, theta),
            self.turn(1, theta),
            self.turn(2, theta),
            0.0,
        ];
        let (s, c) = sin_cos_deg4(t);
        core::array::from_fn(|k| match (self.stored().get(k), s.get(k), c.get(k)) {
            (Some(a), Some(&sk), Some(&ck)) => about_axis_sc(a.direction, sk, ck),
            _ => IDENTITY,
        })
    }

    /// `T·q`: a point of the tool adapter's system in machine coordinates (the head's
    /// axes, innermost first).
    pub(crate) fn tool_point(&self, r: &[Matrix; MAX_AXES], q: Vector) -> Vector {
        self.stored()
            .iter()
            .zip(r)
            .rev()
            .filter(|(a, _)| a.work_side == 0)
            .fold(q, |q, (a, rk)| about_point(rk, a.point, q))
    }

    /// `W·q`: a workpiece point in machine coordinates (the table's axes, innermost
    /// first).
    pub(crate) fn work_point(&self, r: &[Matrix; MAX_AXES], q: Vector) -> Vector {
        self.stored()
            .iter()
            .zip(r)
            .rev()
            .filter(|(a, _)| a.work_side != 0)
            .fold(q, |q, (a, rk)| about_point(rk, a.point, q))
    }

    /// `W⁻¹·q`: a machine point in workpiece coordinates (the table's axes undone,
    /// outermost first).
    pub(crate) fn work_point_inverse(&self, r: &[Matrix; MAX_AXES], q: Vector) -> Vector {
        self.stored()
            .iter()
            .zip(r)
            .filter(|(a, _)| a.work_side != 0)
            .fold(q, |q, (a, rk)| about_point(&transpose(rk), a.point, q))
    }

    /// The rotation of `F = W⁻¹·T·B` from the turns: the chain's product, the identity
    /// factors left out.
    pub(crate) fn rotation_of(&self, r: &[Matrix; MAX_AXES]) -> Matrix {
        let (chain, n) = self.chain();
        let mut out: Option<Matrix> = None;
        for link in chain.iter().take(n) {
            let Some(rk) = r.get(link.index) else {
                continue;
            };
            let h = if link.sign < 0.0 { transpose(rk) } else { *rk };
            out = Some(match out {
                None => h,
                Some(o) => mul(&o, &h),
            });
        }
        let out = out.unwrap_or(IDENTITY);
        if self.base_is_identity() {
            out
        } else {
            mul(&out, &self.base())
        }
    }
}

/// `R·(q − p) + p`: the turn `R` about the line through `p`.
#[inline(always)]
fn about_point(r: &Matrix, p: Vector, q: Vector) -> Vector {
    let d: Vector = core::array::from_fn(|k| q[k] - p[k]);
    let t = rotate(r, d);
    core::array::from_fn(|k| t[k] + p[k] + 0.0)
}

fn length_in_range(length: f64) -> Result<(), Error> {
    if abs(length) <= LENGTH_MAX {
        Ok(())
    } else {
        Err(Error::OutOfRange)
    }
}

fn finite_frame(f: Frame) -> Result<Frame, Error> {
    let ok = f.rotation.iter().flatten().all(|x| x.is_finite())
        && f.translation.iter().all(|x| x.is_finite());
    if ok {
        Ok(f)
    } else {
        Err(Error::OutOfRange)
    }
}
