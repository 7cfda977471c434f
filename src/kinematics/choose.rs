//! The choice among the solutions: travel limits, whole-turn unwinding, Hirth grids, and
//! the controllers' rules (CYCLE800 minus/plus, Heidenhain `SEQ±`, CYCLE600 `_ROT_INV`).

use super::{Machine, Solutions, Stored, MAX_AXES, MAX_SOLUTIONS, TRAVEL_TOLERANCE};
use crate::math::{abs, ceil, round, turns_toward, wrap_deg};
use crate::{check_rotation, mul, transpose, Error, Matrix, CLOSEST_MAX, IDENTITY};

/// Which solution [`Machine::choose`] takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// The one closest to the current positions (sum of squared differences): what
    /// SINUMERIK does for a frame ("the pair closest to the current positions").
    Closest,
    /// The solution whose position of the given axis (0-based), as an angle in
    /// (−180°, 180°], is the lower, then placed like every solution (whole turns toward
    /// the current position): CYCLE800 "minus" on the direction-reference axis;
    /// Heidenhain `SEQ-` on the master axis ("a negative angle"). The same solution
    /// whatever the current positions.
    Minus(usize),
    /// The higher angle of the given axis, as [`Rule::Minus`]: CYCLE800 "plus",
    /// Heidenhain `SEQ+`.
    Plus(usize),
    /// The other one of the pair: the paper's `_ROT_INV = 1` (the same orientation with the
    /// axes in the inverse position). The closest when there is no other.
    Inverse,
    /// The given axis turns in its positive direction only, the least it must (a
    /// direction-of-travel rule: LinuxCNC's `G53.1 P1`, "positive rotation only" of the
    /// priority axis); the other axes take the turn nearest their current positions. Of
    /// the solutions so reached, the one with the smallest turn of that axis (then the
    /// closest). On an axis with travel limits only positions from the current one up to
    /// the upper end qualify.
    PositiveTurn(usize),
    /// The given axis turns in its negative direction only (`G53.1 P2`), as
    /// [`Rule::PositiveTurn`].
    NegativeTurn(usize),
    /// The solution whose given axis (the master) turns the least from its current
    /// position; of equal turns (within [`super::TRAVEL_TOLERANCE`]) the one whose other
    /// axes, in their order, turn the least; then the one whose given axis, then each other,
    /// lies nearest 0° (a multiple of 360°): Fanuc's "output judgement conditions" for
    /// `G53.1` \[doc: Fanuc Series 16i/18i-MB operator's manual, tool axis direction
    /// control: the master (first rotation) axis for tool and table rotation machines, the
    /// table (second rotation) axis for mixed ones\].
    MasterFirst(usize),
}

/// The positions [`Machine::choose`] chose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choice {
    /// Axis positions to move to, degrees, unwound to the current positions and on the
    /// Hirth grids; unused axes 0.
    pub axes: [f64; MAX_AXES],
    /// Hirth snapping: the position moved to minus the exact one, per axis (0 without a
    /// grid).
    pub residual: [f64; MAX_AXES],
    /// The rotation the axes leave to the frame: `Fᵀ·target` with `F` the tool frame at
    /// `axes` — a rotation about the tool axis for machines with fewer than three axes,
    /// plus the Hirth residual.
    pub remaining: Matrix,
    /// A singular pose: a free axis was kept at its current position.
    pub free: bool,
}

/// Where an axis goes: the turn of `angle` nearest to `current` within the travel, snapped
/// to the Hirth grid. `None` when no turn (or no tooth) lies within the travel. A position
/// within [`TRAVEL_TOLERANCE`] beyond an end is that end: the inverse computes an end a few
/// ulp off, and a turn elsewhere (or a refusal) for rounding would move the machine for
/// nothing. Every comparison is written so that NaN refuses. Not inlined: its temporaries
/// would otherwise stay in the frame of `choose` through the inverse (stack bound).
#[inline(never)]
pub(crate) fn place(axis: &Stored, angle: f64, current: f64) -> Option<(f64, f64)> {
    let limits = axis.limits();
    let mut x = unwound(limits, angle, current);
    if let Some([lo, hi]) = limits {
        x = onto_travel(x, lo, hi);
    }
    let exact = x;
    if let Some(h) = axis.hirth() {
        x = h.offset + round((x - h.offset) / h.step) * h.step + 0.0;
        if let Some([lo, hi]) = limits {
            if x > hi + TRAVEL_TOLERANCE {
                x -= h.step;
            } else if x < lo - TRAVEL_TOLERANCE {
                x += h.step;
            }
            x = onto_travel(x, lo, hi);
        } else if abs(x) >= CLOSEST_MAX {
            // A tooth beyond the bound of an axis without limits: the one before it.
            x = if x > 0.0 { x - h.step } else { x + h.step };
        }
    }
    let fits = limits.map_or(true, |[lo, hi]| x >= lo && x <= hi);
    fits.then_some((x, x - exact + 0.0))
}

/// The turn of `angle` that [`place`] starts from: the one nearest `current` (of two half a
/// turn away, within [`TRAVEL_TOLERANCE`], the one nearer 0), on an axis with travel
/// `limits` the one nearest it within them (or within [`TRAVEL_TOLERANCE`] beyond an end,
/// not yet taken onto it).
#[inline(always)]
pub(crate) fn unwound(limits: Option<[f64; 2]>, angle: f64, current: f64) -> f64 {
    let mut x = angle + turns_toward(angle, current) + 0.0;
    // Half a turn either way (up to rounding): the turn nearer 0, whichever side `current`
    // lies on, so that SEQ- after SEQ+ on a tilt of 90° puts A at -90°, not at 270° (and the
    // next plane at 380°) [choice].
    let other = if x > current { x - 360.0 } else { x + 360.0 };
    if abs(abs(x - current) - 180.0) <= TRAVEL_TOLERANCE && abs(other) < abs(x) {
        x = other;
    }
    if let Some([lo, hi]) = limits {
        if x > hi + TRAVEL_TOLERANCE {
            x -= 360.0 * ceil((x - hi - TRAVEL_TOLERANCE) / 360.0);
        } else if x < lo - TRAVEL_TOLERANCE {
            x += 360.0 * ceil((lo - TRAVEL_TOLERANCE - x) / 360.0);
        }
    } else if abs(x) >= CLOSEST_MAX {
        // An axis without limits turns within ±CLOSEST_MAX, where a position still denotes
        // its angle to the library's accuracy (and is one the next choice accepts as
        // current): a turn that would cross it is taken a whole turn back [choice].
        x = if x > 0.0 { x - 360.0 } else { x + 360.0 };
    }
    x
}

/// Where an axis goes when it may turn only in the direction `sign` (+1 or −1) from
/// `current`: the first turn of `angle` met that way (a turn within [`TRAVEL_TOLERANCE`]
/// of the current position is no turn, so a rounding never costs a whole turn), within
/// the travel, then snapped to the Hirth grid as [`place`] snaps (the nearest tooth: a
/// snap may stop a tooth short of the exact position, never turns back past `current`
/// by more than half a tooth). `None` when that turn lies beyond the travel. Not inlined,
/// like [`place`] (stack bound).
#[inline(never)]
pub(crate) fn place_turning(
    axis: &Stored,
    angle: f64,
    current: f64,
    sign: f64,
) -> Option<(f64, f64)> {
    // The whole turns that bring `angle` to the current position or past it, the way
    // the axis turns.
    let n = ceil((sign * (current - angle) - TRAVEL_TOLERANCE) / 360.0);
    let x = angle + sign * 360.0 * n + 0.0;
    // Written so that NaN refuses: a position beyond the travel the way the axis turns is
    // never reached (the next turn lies further out); without limits the travel is
    // ±CLOSEST_MAX (see `unwound`).
    let [lo, hi] = axis.limits().unwrap_or([-CLOSEST_MAX, CLOSEST_MAX]);
    if !(x >= lo - TRAVEL_TOLERANCE && x <= hi + TRAVEL_TOLERANCE) || abs(x) >= CLOSEST_MAX {
        return None;
    }
    // On the travel now: `place` only snaps it (the nearest turn of `x` is `x`).
    place(axis, x, x)
}

/// `x`, or the end of `[lo, hi]` it lies within [`TRAVEL_TOLERANCE`] beyond: so that the
/// position moved to never lies outside the travel.
fn onto_travel(x: f64, lo: f64, hi: f64) -> f64 {
    if x > hi && x <= hi + TRAVEL_TOLERANCE {
        hi
    } else if x < lo && x >= lo - TRAVEL_TOLERANCE {
        lo
    } else {
        x
    }
}

impl Machine {
    /// The axis positions to move to for the orientation `target`, seen from `current`
    /// positions (degrees; unused axes 0).
    ///
    /// Every solution of [`Machine::inverse`] is brought to the whole turn nearest to the
    /// current position (computed 10°, current 750° → 730°; of two half a turn away, the
    /// one nearer 0: −90° from 90°, not 270°), or, on an axis with travel
    /// limits, to the turn nearest to it within them (without limits, within
    /// ±[`CLOSEST_MAX`]: a turn that would cross it is taken a whole turn back), and snapped
    /// to the axis' Hirth grid;
    /// a solution that does not fit the travel is skipped and the other taken. A position
    /// within [`super::TRAVEL_TOLERANCE`] beyond an end of the travel is taken exactly at
    /// that end, so a target made at an end is reached there. Of those left, `rule` picks
    /// one; [`Rule::Inverse`] takes the only one left when the other does not fit the
    /// travel (or the orientation has one solution). A free axis (singular pose) stays at
    /// its current position.
    ///
    /// Errors: [`Error::Unreachable`] (no positions give the orientation),
    /// [`Error::OutOfTravel`] (only outside the travel limits), [`Error::BadArgument`] (a
    /// rule's axis that the machine does not have, a nonzero unused position),
    /// [`Error::OutOfRange`] (a current position of magnitude [`CLOSEST_MAX`] = 65 536° or
    /// more), [`Error::NotFinite`], [`Error::NotARotation`].
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Rule, Side};
    /// use cncrot::{elementary, Axis};
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3])).unwrap();
    /// let target = elementary(Axis::Y, 30.0);
    /// // From C = 750°: C = 720°, B = 30° (the other pair would need C = 900° or 540°).
    /// let c = m.choose(&target, [750.0, 0.0, 0.0], Rule::Closest).unwrap();
    /// assert!((c.axes[0] - 720.0).abs() < 1e-9 && (c.axes[1] - 30.0).abs() < 1e-9);
    /// // "Minus" on B takes B = -30°.
    /// let c = m.choose(&target, [0.0; 3], Rule::Minus(1)).unwrap();
    /// assert!((c.axes[1] + 30.0).abs() < 1e-9);
    /// ```
    pub fn choose(
        &self,
        target: &Matrix,
        current: [f64; MAX_AXES],
        rule: Rule,
    ) -> Result<Choice, Error> {
        let c = self.settle(target, current, rule, true)?;
        let reached = self.rotation_at(c.axes);
        Ok(Choice {
            remaining: mul(&transpose(&reached), target),
            ..c
        })
    }

    /// The positions a direct command moves the axes to (`PLANE AXIAL`, a `CYCLE800`
    /// direct, `G158` mode 2: the positions themselves, not a plane): an axis with travel
    /// limits to the position as stated ([`Error::OutOfTravel`] beyond them), a modulo axis
    /// (no limits) to the turn of it nearest `current`, on its Hirth grid. The remaining
    /// rotation is what the grid leaves: `Fᵀ·F_stated`. Errors: [`Error::NotFinite`],
    /// [`Error::BadArgument`] (a nonzero position of an axis the machine lacks),
    /// [`Error::OutOfRange`] (a position of magnitude [`CLOSEST_MAX`] or more),
    /// [`Error::OutOfTravel`].
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// let mut c = RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]);
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap().with_axis(c).unwrap();
    /// // A modulo C: 370° from 0° is 10°, the same plane.
    /// assert_eq!(m.commanded([370.0, 0.0, 0.0], [0.0; 3]).unwrap().axes[0], 10.0);
    /// c.limits = Some([-360.0, 360.0]);
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap().with_axis(c).unwrap();
    /// assert!(m.commanded([370.0, 0.0, 0.0], [0.0; 3]).is_err());
    /// ```
    pub fn commanded(
        &self,
        positions: [f64; MAX_AXES],
        current: [f64; MAX_AXES],
    ) -> Result<Choice, Error> {
        let stated = self.positions(positions)?;
        let current = self.positions(current)?;
        if !stated.iter().chain(&current).all(|x| abs(*x) < CLOSEST_MAX) {
            return Err(Error::OutOfRange);
        }
        let mut axes = [0.0; MAX_AXES];
        let mut residual = [0.0; MAX_AXES];
        for (k, axis) in self.stored().iter().enumerate() {
            let (x, cur) = (stated.get(k).copied(), current.get(k).copied());
            let (Some(x), Some(cur)) = (x, cur) else {
                continue;
            };
            let from = match axis.limits() {
                Some([lo, hi]) if !(x >= lo - TRAVEL_TOLERANCE && x <= hi + TRAVEL_TOLERANCE) => {
                    return Err(Error::OutOfTravel);
                }
                Some(_) => x,
                None => cur,
            };
            let (at, r) = place(axis, x, from).ok_or(Error::OutOfTravel)?;
            if let (Some(a), Some(slot)) = (axes.get_mut(k), residual.get_mut(k)) {
                *a = at;
                *slot = r;
            }
        }
        let reached = self.rotation_at(axes);
        let target = self.rotation_at(stated);
        Ok(Choice {
            axes,
            residual,
            remaining: mul(&transpose(&reached), &target),
            free: false,
        })
    }

    /// One solution `theta` placed axis by axis (the axis of `turning` one way only),
    /// written to `out` with the squared distance from `current` summed in axis order;
    /// `false` when an axis does not fit its travel. Not inlined (stack bound).
    #[inline(never)]
    pub(crate) fn place_solution(
        &self,
        theta: &[f64; MAX_AXES],
        current: &[f64; MAX_AXES],
        turning: Option<(usize, f64)>,
        out: &mut ([f64; MAX_AXES], [f64; MAX_AXES], f64),
    ) -> bool {
        let (axes, residual, distance) = out;
        (*axes, *residual, *distance) = ([0.0; MAX_AXES], [0.0; MAX_AXES], 0.0);
        for (k, a) in self.stored().iter().enumerate() {
            let (Some(&angle), Some(&cur)) = (theta.get(k), current.get(k)) else {
                continue;
            };
            let at = match turning {
                Some((j, sign)) if j == k => place_turning(a, angle, cur, sign),
                _ => place(a, angle, cur),
            };
            let Some((x, r)) = at else {
                return false;
            };
            if let (Some(ax), Some(re)) = (axes.get_mut(k), residual.get_mut(k)) {
                *ax = x;
                *re = r;
            }
            *distance += (x - cur) * (x - cur);
        }
        true
    }

    /// [`Machine::choose`] without the remaining rotation (left the identity): what the
    /// five-axis transformation needs, which computes the reached pose itself. `verify`:
    /// as in [`Machine::solve`].
    pub(crate) fn settle(
        &self,
        target: &Matrix,
        current: [f64; MAX_AXES],
        rule: Rule,
        verify: bool,
    ) -> Result<Choice, Error> {
        check_rotation(target)?;
        let current = self.positions(current)?;
        // Written so that NaN refuses.
        if !current.iter().all(|x| crate::math::abs(*x) < CLOSEST_MAX) {
            return Err(Error::OutOfRange);
        }
        let n = self.axis_count();
        let turning = match rule {
            Rule::Minus(k) | Rule::Plus(k) if k >= n => return Err(Error::BadArgument),
            Rule::PositiveTurn(k) | Rule::NegativeTurn(k) | Rule::MasterFirst(k) if k >= n => {
                return Err(Error::BadArgument)
            }
            Rule::PositiveTurn(k) => Some((k, 1.0)),
            Rule::NegativeTurn(k) => Some((k, -1.0)),
            _ => None,
        };
        let mut solutions = Solutions::NONE;
        self.solve_into(target, &current, verify, &mut solutions)?;
        let mut placed = [([0.0; MAX_AXES], [0.0; MAX_AXES], 0.0f64); MAX_SOLUTIONS];
        let mut count = 0;
        for s in solutions.as_slice() {
            let Some(slot) = placed.get_mut(count) else {
                break;
            };
            if self.place_solution(s, &current, turning, slot) {
                count += 1;
            }
        }
        let placed = placed.get(..count).unwrap_or(&[]);
        let closest = |skip: Option<usize>| {
            let mut best: Option<usize> = None;
            for (i, p) in placed.iter().enumerate() {
                if Some(i) == skip {
                    continue;
                }
                if best.map_or(true, |b| placed.get(b).map_or(true, |q| p.2 < q.2)) {
                    best = Some(i);
                }
            }
            best
        };
        let by_axis = |k: usize, higher: bool| {
            let mut best: Option<usize> = None;
            for (i, p) in placed.iter().enumerate() {
                let better = match best.and_then(|b| placed.get(b)) {
                    None => true,
                    Some(q) => {
                        // Compared as angles in (-180°, 180°], not as the turns placed
                        // toward `current`: `SEQ-` asks for the master axis at a negative
                        // angle, and from A = -90° the other solution's A = 90° is placed
                        // at -270° (a tie), which is lower but the `SEQ+` solution.
                        let at = |s: &([f64; MAX_AXES], [f64; MAX_AXES], f64)| {
                            s.0.get(k).map(|&x| wrap_deg(x))
                        };
                        let (x, y) = (at(p), at(q));
                        // Equal angles: the closer one.
                        if x == y {
                            p.2 < q.2
                        } else {
                            (x > y) == higher
                        }
                    }
                };
                if better {
                    best = Some(i);
                }
            }
            best
        };
        // The least turn of the axis that may turn one way only, then the closest.
        let least_turn = |k: usize| {
            let mut best: Option<usize> = None;
            for (i, p) in placed.iter().enumerate() {
                let turn = |q: &([f64; MAX_AXES], [f64; MAX_AXES], f64)| {
                    let (x, c) = (q.0.get(k).copied(), current.get(k).copied());
                    abs(x.unwrap_or(0.0) - c.unwrap_or(0.0))
                };
                let better = match best.and_then(|b| placed.get(b)) {
                    None => true,
                    Some(q) if turn(p) == turn(q) => p.2 < q.2,
                    Some(q) => turn(p) < turn(q),
                };
                if better {
                    best = Some(i);
                }
            }
            best
        };
        // The least turn of axis `k`, then of the others in order, then `k` nearest 0°, then
        // the others: each compared to the travel tolerance, the first that differs decides.
        let master_first = |k: usize| {
            let key = |q: &([f64; MAX_AXES], [f64; MAX_AXES], f64)| {
                let mut key = [0.0; 2 * MAX_AXES];
                let order = core::iter::once(k).chain((0..n).filter(|&j| j != k));
                for (slot, j) in order.enumerate() {
                    let (x, c) = (q.0.get(j).copied(), current.get(j).copied());
                    let x = x.unwrap_or(0.0);
                    if let Some(t) = key.get_mut(slot) {
                        *t = abs(x - c.unwrap_or(0.0));
                    }
                    if let Some(z) = key.get_mut(MAX_AXES + slot) {
                        *z = abs(wrap_deg(x));
                    }
                }
                key
            };
            let mut best: Option<usize> = None;
            for (i, p) in placed.iter().enumerate() {
                let better = match best.and_then(|b| placed.get(b)) {
                    None => true,
                    Some(q) => {
                        let (a, b) = (key(p), key(q));
                        a.iter()
                            .zip(&b)
                            .find(|(x, y)| abs(*x - *y) > TRAVEL_TOLERANCE)
                            .is_some_and(|(x, y)| x < y)
                    }
                };
                if better {
                    best = Some(i);
                }
            }
            best
        };
        let pick = match rule {
            Rule::Closest => closest(None),
            Rule::MasterFirst(k) => master_first(k),
            Rule::Minus(k) => by_axis(k, false),
            Rule::Plus(k) => by_axis(k, true),
            Rule::Inverse => closest(closest(None)).or(closest(None)),
            Rule::PositiveTurn(k) | Rule::NegativeTurn(k) => least_turn(k),
        };
        let Some(&(axes, residual, _)) = pick.and_then(|i| placed.get(i)) else {
            return Err(Error::OutOfTravel);
        };
        Ok(Choice {
            axes,
            residual,
            remaining: IDENTITY,
            free: solutions.free,
        })
    }
}
