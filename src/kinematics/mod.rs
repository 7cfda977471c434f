//! Swivel kinematics: rotary-axis positions of a real machine (swivel head, rotary table,
//! both, up to three rotary axes) to the frame they give, and back.
//!
//! A rotary axis is a unit direction `v` and a point `p` on it, both in machine coordinates
//! with every rotary axis at its initial position. Positive rotation is the right-hand rule
//! about `v`, applied to the part the axis moves: the tool (tool side) or the workpiece (work
//! side). Axes are given outermost first: an axis added after another on the same side is
//! carried by it. With `H_k(a)` the turn by `a` about the line through `p_k` along `v_k`,
//!
//! - the tool adapter sits at `T = H_1·H_2…` over the tool-side axes,
//! - the workpiece at `W = H_1·H_2…` over the work-side axes,
//! - and the tool frame relative to the workpiece is `F = W⁻¹·T·B`, where `B` turns +Z onto
//!   the tool's base direction (the identity for the usual +Z). Its third column is the tool
//!   direction in workpiece coordinates; the tool tip for a length `L` is `F·(0, 0, −L)`.
//!
//! An axis at position `θ` turns by `θ − offset` (SINUMERIK `$TC_CARR24/25`: the position
//! the axis reads in the described initial state).
//!
//! ```
//! use cncrot::kinematics::{Machine, RotaryAxis, Side};
//! // A fork head: C about Z, then A about X carried by it, both through the origin.
//! let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
//!     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3])).unwrap()
//!     .with_axis(RotaryAxis::new(Side::Tool, [1.0, 0.0, 0.0], [0.0; 3])).unwrap();
//! let f = m.forward([90.0, 30.0, 0.0]).unwrap();
//! // The tool direction Rz(90)·Rx(30)·e_z = (0.5, 0, 0.866).
//! assert!((f.rotation[0][2] - 0.5).abs() < 1e-15 && f.rotation[1][2].abs() < 1e-15);
//! ```

mod choose;
mod solve;
mod tcp;

pub use choose::{Choice, Rule};
pub(crate) use solve::VERIFY;
pub use solve::{Solutions, POLE_SINE};
pub use tcp::{cl_pose, cl_pose_toward, Tcp, TCP_AXES};

use crate::math::{abs, sin_cos_deg4};
pub(crate) use crate::rotation::{about_axis, about_axis_sc, turn_vector};
use crate::vector::{cross, dot};
use crate::{mul, transpose, unit_vector, Error, Frame, Matrix, Vector, CLOSEST_MAX, IDENTITY};

/// The most rotary axes a machine has here (a table with a two-axis head).
pub const MAX_AXES: usize = 3;
/// The most isolated solutions an orientation has within one turn of every axis.
pub const MAX_SOLUTIONS: usize = 2;
/// Longest machine name in bytes (SINUMERIK `$TC_CARR34` holds 32 characters).
pub const MACHINE_NAME_MAX: usize = 31;
/// Below this sine two consecutive axes of the chain count as parallel: such a machine
/// loses a degree of freedom everywhere and is refused \[choice\].
pub const PARALLEL_SINE: f64 = 1e-6;
/// A target closer than this (in radians of direction) to the reachable orientations is
/// reached at the nearest reachable one; farther is [`Error::Unreachable`] \[choice\]. Well
/// below any measurable angle (2e-8°), well above the rounding of a target computed in
/// doubles (1e-15).
pub const REACH_TOLERANCE: f64 = 1e-10;
/// A computed position at most this far beyond an end of its axis' travel, degrees, is
/// taken at that end (and the position moved to is exactly the end) \[choice\]. The
/// inverse computes a position the target put exactly at an end a few ulp beyond it
/// (1e-14° at 10°, 1.5e-11° at 65 536°); moving by this much turns the tool by 1.7e-11
/// rad, within [`REACH_TOLERANCE`], so the end still reaches the target.
pub const TRAVEL_TOLERANCE: f64 = 1e-9;
/// The largest magnitude of a coordinate of an axis' point, millimetres \[choice\]: a
/// kilometre, far beyond any machine tool. Translations `p − R·p` of such a point
/// are exact to 1e-9 mm; a point 1e12 mm away would leave 1e-4 mm of rounding.
pub const LENGTH_MAX: f64 = 1e6;
/// The finest Hirth grid, degrees \[choice\]: finer than any rotary axis resolves. The
/// teeth `offset + k·step` of positions within the angle bound ([`crate::CLOSEST_MAX`])
/// are computed to 5e-11°, a twenty-thousandth of this step; much finer steps would make
/// the grid rounding, and below 1e-303° `k` overflows.
pub const HIRTH_STEP_MIN: f64 = 1e-6;

/// Which part a rotary axis turns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The axis turns the tool (a swivel head).
    Tool,
    /// The axis turns the workpiece (a rotary or tilting table).
    Work,
}

/// A Hirth tooth system: the axis stops only at `offset + k·step` degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hirth {
    /// Position of one tooth, degrees (`$TC_CARR26/27`); below [`crate::CLOSEST_MAX`] in
    /// magnitude.
    pub offset: f64,
    /// Tooth spacing, degrees, at least [`HIRTH_STEP_MIN`] (`$TC_CARR28/29`).
    pub step: f64,
}

/// One rotary axis of a machine.
///
/// ```
/// use cncrot::kinematics::{RotaryAxis, Side};
/// let c = RotaryAxis::new(Side::Work, [0.0, 0.0, -1.0], [100.0, 50.0, 0.0]);
/// assert_eq!(c.limits, None); // modulo until limits are set
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RotaryAxis {
    /// Tool or work side.
    pub side: Side,
    /// Direction `v` (any length when given; the machine keeps it as a unit vector).
    pub direction: Vector,
    /// A point `p` on the axis, millimetres; each coordinate within ±[`LENGTH_MAX`].
    pub point: Vector,
    /// The position the axis reads in the described initial state, degrees; below
    /// [`crate::CLOSEST_MAX`] in magnitude.
    pub offset: f64,
    /// Travel limits `[min, max]`, degrees, below [`crate::CLOSEST_MAX`] in magnitude;
    /// `None`: a modulo axis without limits. A position computed within
    /// [`TRAVEL_TOLERANCE`] beyond an end is taken at that end.
    pub limits: Option<[f64; 2]>,
    /// The Hirth grid, if the axis has one.
    pub hirth: Option<Hirth>,
}

impl RotaryAxis {
    /// An axis without offset, limits or Hirth grid.
    pub const fn new(side: Side, direction: Vector, point: Vector) -> RotaryAxis {
        RotaryAxis {
            side,
            direction,
            point,
            offset: 0.0,
            limits: None,
            hirth: None,
        }
    }

    /// The axis made canonical (unit direction) and checked: finite numbers
    /// ([`Error::NotFinite`]); a nonzero direction, `min <= max`, a Hirth step of at least
    /// [`HIRTH_STEP_MIN`] ([`Error::BadArgument`]); offset, limits and Hirth offset below
    /// [`crate::CLOSEST_MAX`] in magnitude, point coordinates at most [`LENGTH_MAX`]
    /// ([`Error::OutOfRange`]).
    pub(crate) fn checked(&self) -> Result<RotaryAxis, Error> {
        let [lo, hi] = self.limits.unwrap_or([0.0; 2]);
        let (tooth, step) = self
            .hirth
            .map_or((0.0, HIRTH_STEP_MIN), |h| (h.offset, h.step));
        // Scalar tests, no arrays of the values: this runs inside every export's frame.
        let finite = |v: &Vector| v[0].is_finite() && v[1].is_finite() && v[2].is_finite();
        if !(finite(&self.direction)
            && finite(&self.point)
            && self.offset.is_finite()
            && lo.is_finite()
            && hi.is_finite()
            && tooth.is_finite()
            && step.is_finite())
        {
            return Err(Error::NotFinite);
        }
        // Written so that NaN would refuse.
        if !(lo <= hi && step >= HIRTH_STEP_MIN) {
            return Err(Error::BadArgument);
        }
        // The bound of current positions: beyond it doubles are too coarse for a degree, and
        // `θ − offset`, a limit or a tooth would be off by more than the tolerances.
        let angle = |x: f64| abs(x) < CLOSEST_MAX;
        let length = |v: &Vector| v.iter().all(|x| abs(*x) <= LENGTH_MAX);
        if !(angle(self.offset) && angle(lo) && angle(hi) && angle(tooth) && length(&self.point)) {
            return Err(Error::OutOfRange);
        }
        let direction = direction_of(self.direction)?;
        Ok(RotaryAxis { direction, ..*self })
    }
}

/// One axis as a [`Machine`] stores it: the layout of the C description's axis
/// (`cncrot_machine_axis`), plain numbers only, so that a sealed description is read in
/// place. Limits `[0, 0]` stand for none and a Hirth step of 0 for no grid, as in C.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Stored {
    /// 0: the tool side; anything else the work side (a machine holds 0 or 1).
    pub(crate) work_side: i32,
    pub(crate) reserved: i32,
    pub(crate) direction: Vector,
    pub(crate) point: Vector,
    pub(crate) offset: f64,
    pub(crate) min: f64,
    pub(crate) max: f64,
    pub(crate) tooth: f64,
    pub(crate) step: f64,
}

impl Stored {
    const EMPTY: Stored = Stored {
        work_side: 0,
        reserved: 0,
        direction: [0.0; 3],
        point: [0.0; 3],
        offset: 0.0,
        min: 0.0,
        max: 0.0,
        tooth: 0.0,
        step: 0.0,
    };

    fn of(a: &RotaryAxis) -> Stored {
        let [min, max] = a.limits.unwrap_or([0.0; 2]);
        let (tooth, step) = a.hirth.map_or((0.0, 0.0), |h| (h.offset, h.step));
        Stored {
            work_side: i32::from(a.side == Side::Work),
            reserved: 0,
            direction: a.direction,
            point: a.point,
            offset: a.offset,
            min,
            max,
            tooth,
            step,
        }
    }

    pub(crate) fn side(&self) -> Side {
        if self.work_side == 0 {
            Side::Tool
        } else {
            Side::Work
        }
    }

    pub(crate) fn limits(&self) -> Option<[f64; 2]> {
        (self.min != 0.0 || self.max != 0.0).then_some([self.min, self.max])
    }

    pub(crate) fn hirth(&self) -> Option<Hirth> {
        // Written so that NaN (not in a machine) would mean no grid.
        (self.step > 0.0).then_some(Hirth {
            offset: self.tooth,
            step: self.step,
        })
    }

    fn axis(&self) -> RotaryAxis {
        RotaryAxis {
            offset: self.offset,
            limits: self.limits(),
            hirth: self.hirth(),
            ..RotaryAxis::new(self.side(), self.direction, self.point)
        }
    }
}

/// A machine: up to three rotary axes, the tool's base direction and a name. Built by
/// [`Machine::new`] and [`Machine::with_axis`], which check every part, so a `Machine` is
/// always usable.
///
/// Its layout is the C description's (`cncrot_machine`), plain numbers only, with a seal
/// over the rest (0 in a machine built here; the C boundary writes it into the
/// descriptions it hands out): a description the library wrote is read in place, its seal
/// checked instead of every field (the five-axis transformation runs in the interpolation
/// cycle).
///
/// ```
/// use cncrot::kinematics::{Machine, RotaryAxis, Side};
/// // Two parallel axes in a row cannot tilt the tool in two directions: refused.
/// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3])).unwrap();
/// assert!(m.with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 2.0], [0.0; 3])).is_err());
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Machine {
    count: i32,
    seal: u32,
    tool_direction: Vector,
    axes: [Stored; MAX_AXES],
    /// NUL-terminated (so at most [`MACHINE_NAME_MAX`] bytes), zeros after the NUL.
    name: [u8; MACHINE_NAME_MAX + 1],
}

/// The size of a machine's image in bytes: eight-byte words without padding, which the seal
/// covers (all but the seal's own four bytes).
pub(crate) const IMAGE_SIZE: usize = 352;
const _: () = assert!(core::mem::size_of::<Stored>() == 96);
const _: () = assert!(core::mem::size_of::<Machine>() == IMAGE_SIZE);
const _: () = assert!(core::mem::align_of::<Machine>() == 8);
// No padding: the fields' sizes add up to the whole, so every byte is initialised.
const _: () = assert!(4 + 4 + 24 + 3 * 96 + MACHINE_NAME_MAX + 1 == IMAGE_SIZE);

/// Offsets of a machine's fields (count, seal, tool direction, axes, name) and of an axis'
/// (side, reserved, direction, point, offset, min, max, Hirth tooth, Hirth step): the C
/// boundary asserts that its description has the same.
pub(crate) const MACHINE_LAYOUT: [usize; 5] = [
    core::mem::offset_of!(Machine, count),
    core::mem::offset_of!(Machine, seal),
    core::mem::offset_of!(Machine, tool_direction),
    core::mem::offset_of!(Machine, axes),
    core::mem::offset_of!(Machine, name),
];
/// See [`MACHINE_LAYOUT`].
pub(crate) const AXIS_LAYOUT: [usize; 9] = [
    core::mem::offset_of!(Stored, work_side),
    core::mem::offset_of!(Stored, reserved),
    core::mem::offset_of!(Stored, direction),
    core::mem::offset_of!(Stored, point),
    core::mem::offset_of!(Stored, offset),
    core::mem::offset_of!(Stored, min),
    core::mem::offset_of!(Stored, max),
    core::mem::offset_of!(Stored, tooth),
    core::mem::offset_of!(Stored, step),
];

/// The axes of a machine, as [`Machine::axes`] returns them: a slice of
/// [`RotaryAxis`] (through `Deref`), copied out of the machine's storage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axes {
    items: [RotaryAxis; MAX_AXES],
    len: usize,
}

impl core::ops::Deref for Axes {
    type Target = [RotaryAxis];
    fn deref(&self) -> &[RotaryAxis] {
        self.items.get(..self.len).unwrap_or(&[])
    }
}

impl<'a> IntoIterator for &'a Axes {
    type Item = &'a RotaryAxis;
    type IntoIter = core::slice::Iter<'a, RotaryAxis>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

/// One link of the rotation chain `W⁻¹·T`: work-side axes innermost first with negated
/// angles, then tool-side axes outermost first.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Link {
    pub(crate) axis: Vector,
    /// +1 on the tool side, -1 on the work side.
    pub(crate) sign: f64,
    /// Index of the machine axis (the order of addition).
    pub(crate) index: usize,
}

impl Machine {
    /// A machine without rotary axes whose tool points along +Z: where a machine is built
    /// in place ([`Machine::reset`]). Not sealed: only a start.
    pub(crate) const EMPTY: Machine = Machine {
        count: 0,
        seal: 0,
        tool_direction: [0.0, 0.0, 1.0],
        axes: [Stored::EMPTY; MAX_AXES],
        name: [0; MACHINE_NAME_MAX + 1],
    };

    /// Makes `self`, a [`Machine::EMPTY`], [`Machine::new`]`(tool_direction)` in place
    /// (unchanged on an error):
    /// the C boundary builds its machine in the caller's frame instead of returning it
    /// through two `Result`s (stack bound of the hot path).
    pub(crate) fn reset(&mut self, tool_direction: Vector) -> Result<(), Error> {
        if !tool_direction.iter().all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        let b = direction_of(tool_direction)?;
        *self = Machine::EMPTY;
        self.tool_direction = b;
        Ok(())
    }

    /// A machine without rotary axes whose tool points along `tool_direction` (any length)
    /// when every axis is in its initial position; +Z on most machines.
    pub fn new(tool_direction: Vector) -> Result<Machine, Error> {
        let mut m = Machine::EMPTY;
        m.reset(tool_direction)?;
        Ok(m)
    }

    /// The machine with one more axis, carried by the axes already on its side.
    /// Refused: a fourth axis ([`Error::TableFull`]), a non-finite number
    /// ([`Error::NotFinite`]), a zero direction, `min > max`, a Hirth step below
    /// [`HIRTH_STEP_MIN`], or two consecutive axes of the chain parallel within
    /// [`PARALLEL_SINE`] ([`Error::BadArgument`]), an offset, limit or Hirth offset of
    /// magnitude [`crate::CLOSEST_MAX`] (65 536°) or more, or a point coordinate beyond
    /// ±[`LENGTH_MAX`] ([`Error::OutOfRange`]). Limits `Some([0.0, 0.0])` mean no limits,
    /// as in the C description.
    pub fn with_axis(&self, axis: RotaryAxis) -> Result<Machine, Error> {
        let mut next = *self;
        next.push_axis(axis)?;
        Ok(next)
    }

    /// [`Machine::with_axis`] in place (the machine is unchanged on an error): what the C
    /// boundary uses, so that no copies of the machine pile up on the stack. Not inlined:
    /// one frame serves every axis added (stack bound of the C exports).
    #[inline(never)]
    pub fn push_axis(&mut self, axis: RotaryAxis) -> Result<(), Error> {
        let n = self.stored().len();
        if n >= MAX_AXES {
            return Err(Error::TableFull);
        }
        let checked = axis.checked()?;
        // The new axis joins the chain `W⁻¹·T` at one end (a table axis first, a head axis
        // last), next to one axis: the newest on its side, else the oldest on the other.
        // That pair is the only new one: checking it checks every pair once.
        let before = self.stored();
        let neighbour = before
            .iter()
            .rev()
            .find(|a| a.side() == checked.side)
            .or_else(|| before.iter().find(|a| a.side() != checked.side));
        if let Some(a) = neighbour {
            let c = cross(a.direction, checked.direction);
            if dot(c, c) < PARALLEL_SINE * PARALLEL_SINE {
                return Err(Error::BadArgument);
            }
        }
        if let Some(slot) = self.axes.get_mut(n) {
            *slot = Stored::of(&checked);
            self.count = n as i32 + 1;
        }
        Ok(())
    }

    /// The machine with a name (printable ASCII, at most [`MACHINE_NAME_MAX`] bytes).
    pub fn with_name(&self, name: &[u8]) -> Result<Machine, Error> {
        let mut next = *self;
        next.set_name(name)?;
        Ok(next)
    }

    /// [`Machine::with_name`] in place (unchanged on an error).
    pub fn set_name(&mut self, name: &[u8]) -> Result<(), Error> {
        if name.len() > MACHINE_NAME_MAX {
            return Err(Error::NameTooLong);
        }
        if !name.iter().all(|b| (0x20..0x7f).contains(b)) {
            return Err(Error::BadArgument);
        }
        self.name = [0; MACHINE_NAME_MAX + 1];
        if let Some(dst) = self.name.get_mut(..name.len()) {
            dst.copy_from_slice(name);
        }
        Ok(())
    }

    /// The axes, in the order they were added (copies).
    pub fn axes(&self) -> Axes {
        let stored = self.stored();
        let mut items = [RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]); MAX_AXES];
        for (dst, a) in items.iter_mut().zip(stored) {
            *dst = a.axis();
        }
        Axes {
            items,
            len: stored.len(),
        }
    }

    /// The axes as stored: what the computations read (no copies).
    pub(crate) fn stored(&self) -> &[Stored] {
        let n = usize::try_from(self.count).map_or(0, |n| n.min(MAX_AXES));
        self.axes.get(..n).unwrap_or(&[])
    }

    /// The number of rotary axes.
    pub fn axis_count(&self) -> usize {
        self.stored().len()
    }

    /// The tool's base direction (a unit vector).
    pub fn tool_direction(&self) -> Vector {
        self.tool_direction
    }

    /// The name.
    pub fn name(&self) -> &[u8] {
        let len = self.name.iter().position(|&b| b == 0).unwrap_or(0);
        self.name.get(..len).unwrap_or(&[])
    }

    /// The image's eight-byte words.
    fn words(&self) -> &[u64; IMAGE_SIZE / 8] {
        // SAFETY: `Machine` is `repr(C)`, 352 bytes aligned to 8 without padding (asserted
        // above), every byte an initialised number: it reads as 44 words.
        unsafe { &*(self as *const Machine).cast::<[u64; IMAGE_SIZE / 8]>() }
    }

    /// The seal of the image as it is: a hash of every byte but the seal's own, never 0
    /// (the seal of a description the library did not write). Four independent lanes of
    /// multiply-xor steps, each a bijection of its state, so a change of any one word
    /// changes its lane and the result (up to the final fold to 32 bits); about 20 ns.
    pub(crate) fn seal_of(&self) -> u32 {
        const K: u64 = 0x9E37_79B9_7F4A_7C15;
        // The format of the image: a library that lays it out otherwise starts elsewhere.
        let mut lane = [0x636E_6372_6F74_0001u64, 1, 2, 3];
        let mut step = |c: [u64; 4]| {
            for (l, x) in lane.iter_mut().zip(c) {
                *l = (*l ^ x).wrapping_mul(K);
            }
        };
        let w = self.words();
        // The first word holds the count and the seal: only the count is covered.
        step([u64::from(self.count as u32), w[1], w[2], w[3]]);
        for c in w[4..].chunks_exact(4) {
            if let [a, b, c, d] = *c {
                step([a, b, c, d]);
            }
        }
        let mut h =
            lane[0] ^ lane[1].rotate_left(16) ^ lane[2].rotate_left(32) ^ lane[3].rotate_left(48);
        // Murmur3's finaliser: every bit of `h` reaches the low 32.
        h ^= h >> 33;
        h = h.wrapping_mul(0xFF51_AFD7_ED55_8CCD);
        h ^= h >> 33;
        h = h.wrapping_mul(0xC4CE_B9FE_1A85_EC53);
        h ^= h >> 33;
        (h as u32).max(1)
    }

    /// The machine with its seal written: its image as the C boundary hands it out (the
    /// Rust builders leave the seal 0; only an image in the caller's memory needs one).
    pub(crate) fn sealed(&self) -> Machine {
        Machine {
            seal: self.seal_of(),
            ..*self
        }
    }

    /// Whether the image carries its seal: written by the library and not changed since.
    pub(crate) fn is_sealed(&self) -> bool {
        self.seal == self.seal_of()
    }

    /// The rotation chain of `W⁻¹·T` and its length.
    pub(crate) fn chain(&self) -> ([Link; MAX_AXES], usize) {
        let mut chain = [Link {
            axis: [0.0; 3],
            sign: 1.0,
            index: 0,
        }; MAX_AXES];
        let mut n = 0;
        let axes = self.stored();
        // Plain loops over the three slots: the iterator adapters cost a tenth of a
        // five-axis transformation, which builds the chain more than once.
        let mut put = |index: usize, a: &Stored, sign: f64| {
            if let Some(link) = chain.get_mut(n) {
                *link = Link {
                    axis: a.direction,
                    sign,
                    index,
                };
                n += 1;
            }
        };
        for index in (0..axes.len()).rev() {
            if let Some(a) = axes.get(index).filter(|a| a.work_side != 0) {
                put(index, a, -1.0);
            }
        }
        for index in 0..axes.len() {
            if let Some(a) = axes.get(index).filter(|a| a.work_side == 0) {
                put(index, a, 1.0);
            }
        }
        (chain, n)
    }

    /// `B`: the rotation that turns +Z onto the tool's base direction along the shortest
    /// arc (a half turn about X for −Z) \[choice\].
    pub(crate) fn base(&self) -> Matrix {
        let b = self.tool_direction;
        // sin² of the arc, from the components (exact to rounding however small).
        let s2 = b[0] * b[0] + b[1] * b[1];
        if b[2] < 0.0 && s2 <= 1e-200 {
            // −Z (within 1e-100 rad): the arc has no direction of its own.
            return [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]];
        }
        // I + [k]× + f·[k]×² with k = e_z × b, c = b_z and f = 1/(1 + c) = (1 − c)/s²: exact
        // for axis directions. The second form below the equator, where 1 + c cancels: a
        // tool 7.5e-9 rad from −Z had its direction off by 6.5e-9 through 1/(1 + c) (found
        // by the fuzz target), and exactly at c = −1 a tool slightly off −Z was turned
        // onto −Z itself.
        let k = [-b[1], b[0], 0.0];
        let s = if b[2] >= 0.0 {
            1.0 / (1.0 + b[2])
        } else {
            (1.0 - b[2]) / s2
        };
        let kx = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]];
        let kk = mul(&kx, &kx);
        core::array::from_fn(|i| {
            core::array::from_fn(|j| IDENTITY[i][j] + kx[i][j] + kk[i][j] * s + 0.0)
        })
    }

    /// `target·Bᵀ`: the target without the tool's base rotation, the target itself for a
    /// tool along +Z (no product computed for nothing).
    pub(crate) fn without_base(&self, target: &Matrix) -> Matrix {
        if self.base_is_identity() {
            *target
        } else {
            mul(target, &transpose(&self.base()))
        }
    }

    /// Checks the positions: finite; unused axes must be 0.
    fn positions(&self, axes: [f64; MAX_AXES]) -> Result<[f64; MAX_AXES], Error> {
        if !axes.iter().all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        if axes.iter().skip(self.axis_count()).any(|&x| x != 0.0) {
            return Err(Error::BadArgument);
        }
        Ok(axes)
    }

    /// The rotation part of `F` for positions `θ` (degrees): `R_W⁻¹·R_T·B`.
    ///
    /// The sines and cosines of every link in one four-lane call, the identity factors left
    /// out: the same bits as the product written link by link from the identity (a product
    /// with the identity is exact for the finite elements of a rotation, and every element
    /// here has had `+ 0.0`), at about half the cost.
    pub(crate) fn rotation_at(&self, theta: [f64; MAX_AXES]) -> Matrix {
        let (chain, n) = self.chain();
        let mut angles = [0.0; 4];
        for (a, link) in angles.iter_mut().zip(chain.iter().take(n)) {
            *a = link.sign * self.turn(link.index, theta);
        }
        let (s, c) = sin_cos_deg4(angles);
        let mut r: Option<Matrix> = None;
        for (k, link) in chain.iter().take(n).enumerate() {
            let (sk, ck) = (
                s.get(k).copied().unwrap_or(0.0),
                c.get(k).copied().unwrap_or(1.0),
            );
            let h = about_axis_sc(link.axis, sk, ck);
            r = Some(match r {
                None => h,
                Some(r) => mul(&r, &h),
            });
        }
        let r = r.unwrap_or(IDENTITY);
        if self.base_is_identity() {
            r
        } else {
            mul(&r, &self.base())
        }
    }

    /// Whether the tool's base direction is +Z, so that `B` is the identity.
    pub(crate) fn base_is_identity(&self) -> bool {
        self.tool_direction == [0.0, 0.0, 1.0]
    }

    /// How far axis `k` turns at position `theta[k]`: `θ − offset`.
    pub(crate) fn turn(&self, k: usize, theta: [f64; MAX_AXES]) -> f64 {
        let offset = self.stored().get(k).map_or(0.0, |a| a.offset);
        theta.get(k).copied().unwrap_or(0.0) - offset
    }

    /// The tool frame relative to the workpiece, `F = W⁻¹·T·B`, at axis positions
    /// `axes` (degrees; unused ones 0). [`Error::OutOfRange`] when the result overflows.
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// // A rotary table C (turning the workpiece about +Z) with its centre at x = 100.
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [100.0, 0.0, 0.0])).unwrap();
    /// let f = m.forward([90.0, 0.0, 0.0]).unwrap();
    /// // The tool (at the machine origin) seen from the workpiece turned by 90°: the point
    /// // (0, 0) of the machine is at (100, 100) of the workpiece.
    /// assert!((f.translation[0] - 100.0).abs() < 1e-12 && (f.translation[1] - 100.0).abs() < 1e-12);
    /// ```
    pub fn forward(&self, axes: [f64; MAX_AXES]) -> Result<Frame, Error> {
        let theta = self.positions(axes)?;
        let r = self.turns(theta);
        let f = Frame {
            rotation: self.rotation_of(&r),
            translation: self.work_point_inverse(&r, self.tool_point(&r, [0.0; 3])),
        };
        let h = f.to_homogeneous();
        if !h.iter().flatten().all(|x| x.is_finite()) {
            return Err(Error::OutOfRange);
        }
        Ok(f)
    }

    /// The tool tip in workpiece coordinates for a tool of length `length` (mm) at axis
    /// positions `axes`, with the linear axes at `linear` (machine coordinates of the tool
    /// adapter's reference point; the origin of `p_k`): `W⁻¹·(linear + T·(−L·b))`.
    pub fn tool_tip(
        &self,
        axes: [f64; MAX_AXES],
        linear: Vector,
        length: f64,
    ) -> Result<Vector, Error> {
        let theta = self.positions(axes)?;
        if !(linear.iter().all(|x| x.is_finite()) && length.is_finite()) {
            return Err(Error::NotFinite);
        }
        let r = self.turns(theta);
        let tip_in_tool = self.tool_direction.map(|x| -length * x);
        let at = self.tool_point(&r, tip_in_tool);
        let machine: Vector = core::array::from_fn(|k| linear[k] + at[k]);
        finite(self.work_point_inverse(&r, machine))
    }

    /// Tool-tip follow-up: the linear-axis positions that keep the tool tip of a tool of
    /// length `length` on the same workpiece point when the rotary axes move from `from`
    /// to `to` with the linear axes at `linear` before.
    ///
    /// ```
    /// use cncrot::kinematics::{Machine, RotaryAxis, Side};
    /// // A head tilting about X through the point 200 mm above the tool adapter.
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Tool, [1.0, 0.0, 0.0], [0.0, 0.0, 200.0])).unwrap();
    /// let p = m.follow_tool_tip([0.0; 3], [90.0, 0.0, 0.0], [0.0; 3], 100.0).unwrap();
    /// // Pivot-to-tip is 300 mm: tilted 90° the tip would move 300 mm along +Y and up
    /// // 300 mm (Rx(90)·(0, 0, -300) = (0, 300, 0)); the linear axes take it back.
    /// assert!((p[1] + 300.0).abs() < 1e-9 && (p[2] + 300.0).abs() < 1e-9);
    /// ```
    pub fn follow_tool_tip(
        &self,
        from: [f64; MAX_AXES],
        to: [f64; MAX_AXES],
        linear: Vector,
        length: f64,
    ) -> Result<Vector, Error> {
        let q = self.tool_tip(from, linear, length)?;
        let theta = self.positions(to)?;
        let r = self.turns(theta);
        let tip_in_tool = self.tool_direction.map(|x| -length * x);
        let on_work = self.work_point(&r, q);
        let at = self.tool_point(&r, tip_in_tool);
        finite(core::array::from_fn(|k| on_work[k] - at[k] + 0.0))
    }
}

/// A direction as a machine keeps it: `v` itself when it is a unit vector to within eight
/// units in the last place, else `v` made one ([`Error::BadArgument`] for a zero vector).
/// Idempotent: the unit vectors the library computes are within that of length 1, so a
/// description it wrote, checked again, keeps the same bits, and a sealed description
/// computes exactly as its unsealed copy.
fn direction_of(v: Vector) -> Result<Vector, Error> {
    // Written so that NaN (refused before) would normalise and fail.
    if abs(dot(v, v) - 1.0) <= 8.0 * f64::EPSILON {
        return Ok(v.map(|x| x + 0.0));
    }
    unit_vector(v).map_err(|_| Error::BadArgument)
}

fn finite(v: Vector) -> Result<Vector, Error> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(v)
    } else {
        Err(Error::OutOfRange)
    }
}
