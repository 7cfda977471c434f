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

use super::choose::unwound;
use super::solve::{along, lanes_atan2, sin_cos_of, third_args, turn_pair, two_args, Args, VERIFY};
use super::{
    about_axis_sc, turn_vector, Link, Machine, Rule, Solutions, LENGTH_MAX, MAX_AXES,
    MAX_SOLUTIONS, REACH_TOLERANCE, TRAVEL_TOLERANCE,
};
use crate::math::{abs, sin_cos_deg4, wrap_deg};
use crate::vector::{cross, dot};
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
/// perpendicular to it, or Y for a unit direction whose X component is 0.9 or more in
/// magnitude (either way along X) \[choice: only the direction counts for a machine of fewer than three rotary axes; with
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

/// The pose of a CL point continuous with a previous pose: as [`cl_pose`], but X' is the
/// previous pose's X' carried along by the smallest turn that takes the previous tool
/// direction (the third column of `previous`) to `direction` — no turn about the tool
/// between two points. What a machine of three rotary axes needs on CL data, which does
/// not state the turn about the tool: [`cl_pose`]'s X' switches from the workpiece's X to
/// its Y where the direction's x component passes 0.9, and every axis would jump there.
/// A direction 120° or more from the previous one (no step of a path; a first point far
/// from where the machine stands) has no such turn worth keeping: [`cl_pose`]'s frame
/// \[choice\].
///
/// Errors: [`Error::NotARotation`] / [`Error::NotFinite`] (`previous`, as
/// [`crate::check_rotation`]), [`Error::Degenerate`] (a zero or non-finite `direction`).
///
/// ```
/// use cncrot::kinematics::{cl_pose, cl_pose_toward};
/// // Along X the plain pose takes Y as X'; carried from the pose along Z tilted 60° about Y,
/// // X' stays in the XZ plane: (0, 0, -1) for the direction (1, 0, 0).
/// let s = 60f64.to_radians().sin_cos();
/// let before = cl_pose([0.0; 3], [s.0, 0.0, s.1]).unwrap();
/// let p = cl_pose_toward([1.0, 2.0, 3.0], [1.0, 0.0, 0.0], &before.rotation).unwrap();
/// assert!((p.rotation[2][0] + 1.0).abs() < 1e-15 && p.rotation[1][0].abs() < 1e-15);
/// assert_eq!(p.translation, [1.0, 2.0, 3.0]);
/// assert_eq!(cl_pose([0.0; 3], [1.0, 0.0, 0.0]).unwrap().rotation[1][0], 1.0);
/// ```
pub fn cl_pose_toward(tip: Vector, direction: Vector, previous: &Matrix) -> Result<Frame, Error> {
    check_rotation(previous)?;
    let d = crate::unit_vector(direction)?;
    let z = [previous[0][2], previous[1][2], previous[2][2]];
    let x = [previous[0][0], previous[1][0], previous[2][0]];
    let c = dot(z, d);
    // Both are finite unit vectors: `c` is a number.
    if c <= -0.5 {
        return cl_pose(tip, direction);
    }
    // Rodrigues' formula for the turn about k = z × d by the angle between them:
    // R·x = x + k × x + k × (k × x) / (1 + z·d).
    let k = cross(z, d);
    let kx = cross(k, x);
    let kkx = cross(k, kx);
    let carried: Vector = core::array::from_fn(|i| x[i] + kx[i] + kkx[i] / (1.0 + c));
    Ok(Frame {
        rotation: crate::rotation_from_z_x(direction, carried)?,
        translation: tip,
    })
}

/// The common case's choice: the rotary positions and each chain link's sine and cosine.
struct Turned {
    rotary: [f64; MAX_AXES],
    sc: [(f64, f64); MAX_AXES],
}

impl Machine {
    /// The tool's pose in workpiece coordinates at machine axes `axes` (`X, Y, Z` in mm,
    /// then the rotary positions in degrees, unused ones 0) with a tool of length
    /// `tool_length` (mm): the rotation `F` of [`Machine::forward`], its third column the
    /// tool direction, and as translation the tool tip.
    ///
    /// Errors: [`Error::NotFinite`], [`Error::BadArgument`] (an unused rotary position not
    /// 0), [`Error::OutOfRange`] (a tool length or a linear axis beyond ±[`LENGTH_MAX`], a
    /// result that overflows).
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
        // Beyond a kilometre a millimetre's digits are rounding (and the library's lengths
        // are bounded alike).
        axes[..3].iter().try_for_each(|&x| length_in_range(x))?;
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
    /// [`crate::CLOSEST_MAX`] or more, a tool length or a coordinate of the tip beyond
    /// ±[`LENGTH_MAX`], a result that overflows).
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
    #[inline(always)]
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
    /// or higher angle in (−180°, 180°], as `SEQ-`/`SEQ+` ask) or its direction of travel
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
    #[inline(always)]
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
        tip.iter().try_for_each(|&x| length_in_range(x))?;
        let current = [previous[3], previous[4], previous[5]];
        // Written in place by the way that computes it: no copy of it in each frame between
        // (stack bound).
        let mut t = Tcp {
            axes: [0.0; TCP_AXES],
            residual: [0.0; MAX_AXES],
            free: false,
        };
        if rule == Rule::Closest {
            if !self.tcp_closest(pose, tool_length, current, &mut t)? {
                self.closest_general(pose, tool_length, current, &mut t)?;
            }
        } else {
            self.tcp_general(pose, tool_length, current, rule, &mut t)?;
        }
        Ok(t)
    }

    /// The common case of [`Machine::tcp_inverse`]: the checks of `settle`, in its order,
    /// then one to three axes away from a pole, without a Hirth grid, in three passes over
    /// fixed arrays ([`Machine::closest_args`], [`Machine::closest_turns`],
    /// [`Machine::tcp_turned`]), written to `out`. `false`: another case (no axis, a pole,
    /// a grid, a position taken onto an end of the travel, a choice that missed its
    /// verification), which the general way decides. Not inlined, like the general way:
    /// each path's frames stack alone (stack bound).
    #[inline(never)]
    fn tcp_closest(
        &self,
        pose: &Frame,
        tool_length: f64,
        current: [f64; MAX_AXES],
        out: &mut Tcp,
    ) -> Result<bool, Error> {
        check_rotation(&pose.rotation)?;
        let cur = self.positions(current)?;
        if !cur.iter().all(|x| abs(*x) < CLOSEST_MAX) {
            return Err(Error::OutOfRange);
        }
        // A grid leaves part of the turn to the frame: the general way says how much.
        if self.stored().iter().any(|a| a.hirth().is_some()) {
            return Ok(false);
        }
        let mut args = Args::NONE;
        let mut third = args;
        // Built once for the three passes.
        let (chain, n) = self.chain();
        if !self.closest_args(&chain, n, &pose.rotation, &mut args, &mut third)? {
            return Ok(false);
        }
        let mut t = Turned {
            rotary: [0.0; MAX_AXES],
            sc: [(0.0, 1.0); MAX_AXES],
        };
        if !self.closest_turns(&chain, n, &args, &third, &cur, &mut t)? {
            return Ok(false);
        }
        self.tcp_turned(&chain, n, &t, pose, tool_length, out)
    }

    /// The `atan2` arguments of the common case's solutions, as [`Machine::solve`] finds
    /// them in its order: solution k's first two links in lanes 2k and 2k + 1 of `args`,
    /// its third link in lane k of `third`. `false`: a pole or no axis. Not inlined: its
    /// vectors are gone when the solutions are placed (stack bound).
    #[inline(never)]
    fn closest_args(
        &self,
        chain: &[Link; MAX_AXES],
        n: usize,
        target: &Matrix,
        args: &mut Args,
        third: &mut Args,
    ) -> Result<bool, Error> {
        let [l1, l2, _] = chain;
        let b = self.tool_direction();
        let d = [target[0][2], target[1][2], target[2][2]];
        match n {
            1 => {
                // Subproblem 1, as `one` solves it; a pole goes the general way.
                let u = l1.axis;
                if abs(dot(u, b) - dot(u, d)) > REACH_TOLERANCE {
                    return Err(Error::Unreachable);
                }
                let Some([y, x]) = turn_pair(u, b, d) else {
                    return Ok(false);
                };
                (args.y[0], args.x[0], args.count) = (y, x, 1);
                Ok(true)
            }
            2 => {
                if along(l2.axis, b) || along(l1.axis, d) {
                    return Ok(false);
                }
                two_args(&l1.axis, &l2.axis, &b, &d, args)?;
                Ok(true)
            }
            3 => self.three_args(chain, target, args, third),
            _ => Ok(false),
        }
    }

    /// The common case's rotary positions and each link's sine and cosine, written to
    /// `out`, from the solutions' `atan2` arguments ([`Machine::closest_args`]): placed as
    /// `place` places them, the distances summed in the same order, the same choice as
    /// [`Machine::settle`] with [`Rule::Closest`], bit for bit; the sines and cosines from
    /// the arguments (none computed again). `false`: a position taken onto an end of the
    /// travel. Not inlined (stack bound).
    #[inline(never)]
    fn closest_turns(
        &self,
        chain: &[Link; MAX_AXES],
        n: usize,
        args: &Args,
        third: &Args,
        cur: &[f64; MAX_AXES],
        out: &mut Turned,
    ) -> Result<bool, Error> {
        // The same bits as `atan2_deg` one by one (lane by lane the same operations).
        let phi = lanes_atan2(&args.y, &args.x);
        let phi3 = if n == MAX_AXES {
            lanes_atan2(&third.y, &third.x)
        } else {
            [0.0; 4]
        };
        // Placed as `settle` places them (solution by solution, axis by axis).
        let mut best: Option<(usize, [f64; MAX_AXES], f64)> = None;
        for k in 0..args.count.min(MAX_SOLUTIONS) {
            let p = [lane(&phi, 2 * k), lane(&phi, 2 * k + 1), lane(&phi3, k)];
            let (placed, distance) = match self.placed(chain, n, &p, cur) {
                Ok(Some(p)) => p,
                Ok(None) => continue,
                Err(()) => return Ok(false),
            };
            if best.map_or(true, |q| distance < q.2) {
                best = Some((k, placed, distance));
            }
        }
        let Some((k, rotary, _)) = best else {
            return Err(Error::OutOfTravel);
        };
        let ys = [
            lane(&args.y, 2 * k),
            lane(&args.y, 2 * k + 1),
            lane(&third.y, k),
        ];
        let xs = [
            lane(&args.x, 2 * k),
            lane(&args.x, 2 * k + 1),
            lane(&third.x, k),
        ];
        *out = Turned {
            rotary,
            sc: core::array::from_fn(|j| sin_cos_of(ys[j], xs[j])),
        };
        Ok(true)
    }

    /// Three axes, as `solve` does it: the first two axes bring the third's direction
    /// where the target has it (their `atan2` arguments in `args`), the third turns about
    /// it for the rest (solution k's in lane k of `third`). `false` at a pole. Not
    /// inlined (stack bound).
    #[inline(never)]
    fn three_args(
        &self,
        chain: &[Link; MAX_AXES],
        target: &Matrix,
        args: &mut Args,
        third: &mut Args,
    ) -> Result<bool, Error> {
        let [l1, l2, l3] = chain;
        let m = self.without_base(target);
        let u3 = l3.axis;
        let t3 = rotate(&m, u3);
        if along(l2.axis, u3) || along(l1.axis, t3) {
            return Ok(false);
        }
        two_args(&l1.axis, &l2.axis, &u3, &t3, args)?;
        *third = *args;
        third_args(&[l1.axis, l2.axis, u3], &m, third);
        Ok(true)
    }

    /// One solution's chain angles `phi` placed as [`place`](super::choose::place) places
    /// them, and the squared distance from `cur` summed in axis order, as `settle` sums it.
    /// `Ok(None)`: the solution does not fit the travel; `Err(())`: a position was taken
    /// onto an end of the travel (the turn is no longer the solver's: the general way).
    /// Not inlined: unrolled over both solutions, its registers would spill into the
    /// caller's frame (stack bound).
    #[inline(never)]
    fn placed(
        &self,
        chain: &[Link; MAX_AXES],
        n: usize,
        phi: &[f64; MAX_AXES],
        cur: &[f64; MAX_AXES],
    ) -> Result<Option<([f64; MAX_AXES], f64)>, ()> {
        let stored = self.stored();
        let mut placed = [0.0; MAX_AXES];
        for (link, &ph) in chain.iter().zip(phi).take(n) {
            let k = link.index;
            let (Some(a), Some(&c), Some(slot)) = (stored.get(k), cur.get(k), placed.get_mut(k))
            else {
                continue;
            };
            let angle = wrap_deg(a.offset + link.sign * ph);
            let limits = a.limits();
            let x = unwound(limits, angle, c);
            if let Some([lo, hi]) = limits {
                // Written so that NaN skips the solution.
                if !(x >= lo - TRAVEL_TOLERANCE && x <= hi + TRAVEL_TOLERANCE) {
                    return Ok(None);
                }
                if !(x >= lo && x <= hi) {
                    return Err(());
                }
            }
            *slot = x;
        }
        let mut distance = 0.0;
        for (x, c) in placed.iter().zip(cur).take(n) {
            distance += (x - c) * (x - c);
        }
        Ok(Some((placed, distance)))
    }

    /// The common case's linear axes for the turns `t`, verified as `solve` verifies (the
    /// direction, or the whole rotation with three axes); the turns move vectors, not
    /// matrices. `false`: missed. Not inlined (stack bound).
    #[inline(never)]
    fn tcp_turned(
        &self,
        chain: &[Link; MAX_AXES],
        n: usize,
        t: &Turned,
        pose: &Frame,
        tool_length: f64,
        out: &mut Tcp,
    ) -> Result<bool, Error> {
        let sc = &t.sc;
        let target = &pose.rotation;
        let worst = if n == MAX_AXES {
            // The whole rotation `F = H1·H2·H3·B`.
            let [l0, l1, l2] = chain;
            let [(s0, c0), (s1, c1), (s2, c2)] = *sc;
            let h = mul(
                &about_axis_sc(l0.axis, s0, c0),
                &mul(
                    &about_axis_sc(l1.axis, s1, c1),
                    &about_axis_sc(l2.axis, s2, c2),
                ),
            );
            let f = if self.base_is_identity() {
                h
            } else {
                mul(&h, &self.base())
            };
            let mut worst = 0.0f64;
            for (row_f, row_t) in f.iter().zip(target) {
                let e = miss(*row_f, *row_t);
                worst = if e <= worst { worst } else { e };
            }
            worst
        } else {
            let got = chain_turn(chain, sc, n, self.tool_direction());
            miss(got, [target[0][2], target[1][2], target[2][2]])
        };
        // Written so that NaN retries.
        let reached = worst <= VERIFY;
        if !reached {
            return Ok(false);
        }
        // The machine axes' turns: link j turns its axis by sign·φ.
        let mut turn = [(0.0, 1.0); MAX_AXES];
        for (l, &(s, c)) in chain.iter().zip(sc).take(n) {
            if let Some(t) = turn.get_mut(l.index) {
                *t = (l.sign * s, c);
            }
        }
        // `T·(−L·b)` and `W·tip`, innermost axis first (by value: a reference to either
        // would keep both in memory).
        let (mut at, mut on) = (self.tip_in_tool(tool_length), pose.translation);
        let stored = self.stored();
        for k in (0..MAX_AXES).rev() {
            let (Some(a), Some(&(s, c))) = (stored.get(k), turn.get(k)) else {
                continue;
            };
            let tool = a.work_side == 0;
            let q = if tool { at } else { on };
            let d: Vector = core::array::from_fn(|k| q[k] - a.point[k]);
            let t = turn_vector(a.direction, s, c, d);
            let q: Vector = core::array::from_fn(|k| t[k] + a.point[k] + 0.0);
            if tool {
                at = q;
            } else {
                on = q;
            }
        }
        let [x, y, z] = core::array::from_fn(|k| on[k] - at[k] + 0.0);
        let [a, b, c] = t.rotary;
        let axes = [x, y, z, a, b, c];
        if !axes.iter().all(|v| v.is_finite()) {
            return Err(Error::OutOfRange);
        }
        *out = Tcp {
            axes,
            residual: [0.0; MAX_AXES],
            free: false,
        };
        Ok(true)
    }

    /// The general way of [`Rule::Closest`] (a pole, a Hirth grid, a position taken onto
    /// an end of the travel, a solution that missed its verification): what
    /// [`Machine::settle`] chooses with that rule (the verified solutions placed alike,
    /// the first closest), without its frame for the other rules (stack bound). Taken
    /// only after [`Machine::tcp_closest`], which made `settle`'s checks of the pose's
    /// rotation and of `cur`.
    #[inline(never)]
    fn closest_general(
        &self,
        pose: &Frame,
        tool_length: f64,
        cur: [f64; MAX_AXES],
        out: &mut Tcp,
    ) -> Result<(), Error> {
        let mut s = Solutions::NONE;
        self.solve_into(&pose.rotation, &cur, true, &mut s)?;
        let mut best = ([0.0; MAX_AXES], [0.0; MAX_AXES], 0.0);
        if !self.closest_placed(&s, &cur, &mut best) {
            return Err(Error::OutOfTravel);
        }
        self.tcp_linear(best.0, best.1, s.free, pose, tool_length, out)
    }

    /// The solution of `s` placed closest to `cur` (the first of equals), as `settle`
    /// picks it with [`Rule::Closest`], written to `best`; `false` when none fits the
    /// travel. Not inlined: its second placement is not on the solver's stack.
    #[inline(never)]
    fn closest_placed(
        &self,
        s: &Solutions,
        cur: &[f64; MAX_AXES],
        best: &mut ([f64; MAX_AXES], [f64; MAX_AXES], f64),
    ) -> bool {
        let mut found = false;
        let mut placed = *best;
        for theta in s.as_slice() {
            if self.place_solution(theta, cur, None, &mut placed) && (!found || placed.2 < best.2) {
                *best = placed;
                found = true;
            }
        }
        found
    }

    /// The way of the rules other than the closest: the choice among verified solutions,
    /// as `choose` makes it.
    #[inline(never)]
    fn tcp_general(
        &self,
        pose: &Frame,
        tool_length: f64,
        current: [f64; MAX_AXES],
        rule: Rule,
        out: &mut Tcp,
    ) -> Result<(), Error> {
        let c = self.settle(&pose.rotation, current, rule, true)?;
        self.tcp_linear(c.axes, c.residual, c.free, pose, tool_length, out)
    }

    /// The linear axes for the rotary positions `rotary` (with their Hirth `residual` and
    /// whether an axis was `free`), written to `out`. Not inlined: its turns would
    /// otherwise sit in the caller's frame under the solver (stack bound).
    #[inline(never)]
    fn tcp_linear(
        &self,
        rotary: [f64; MAX_AXES],
        residual: [f64; MAX_AXES],
        free: bool,
        pose: &Frame,
        tool_length: f64,
        out: &mut Tcp,
    ) -> Result<(), Error> {
        let r = self.turns(rotary);
        let at = self.tool_point(&r, self.tip_in_tool(tool_length));
        let on = self.work_point(&r, pose.translation);
        let [x, y, z] = core::array::from_fn(|k| on[k] - at[k] + 0.0);
        let [a, b, cc] = rotary;
        let axes = [x, y, z, a, b, cc];
        if !axes.iter().all(|v| v.is_finite()) {
            return Err(Error::OutOfRange);
        }
        *out = Tcp {
            axes,
            residual,
            free,
        };
        Ok(())
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

/// The chain's first `n` links turned by their sines and cosines `sc`, applied to `v`
/// (innermost first).
#[inline(always)]
fn chain_turn(
    chain: &[Link; MAX_AXES],
    sc: &[(f64, f64); MAX_AXES],
    n: usize,
    v: Vector,
) -> Vector {
    let [l0, l1, l2] = chain;
    let [(s0, c0), (s1, c1), (s2, c2)] = *sc;
    match n {
        1 => turn_vector(l0.axis, s0, c0, v),
        2 => turn_vector(l0.axis, s0, c0, turn_vector(l1.axis, s1, c1, v)),
        _ => turn_vector(
            l0.axis,
            s0,
            c0,
            turn_vector(l1.axis, s1, c1, turn_vector(l2.axis, s2, c2, v)),
        ),
    }
}

/// The largest element difference of `a` and `b`: NaN when one is NaN (`max` would drop
/// it).
#[inline(always)]
fn miss(a: Vector, b: Vector) -> f64 {
    let e = [0, 1, 2].map(|i| abs(a[i] - b[i]));
    e[0].max(e[1]).max(e[2]) + (e[0] + e[1] + e[2]) * 0.0
}

/// Lane `k` of `v`, 0 beyond it.
#[inline(always)]
fn lane(v: &[f64; 4], k: usize) -> f64 {
    v.get(k).copied().unwrap_or(0.0)
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
