//! CYCLE600, the paper's cycle: recalculates a rotation given about the machine or the
//! workpiece axes, with translations before and after it, optionally added to the previous
//! one, into the angles of another convention (for CYCLE800).
//!
//! The cycle works on a state that the caller owns and stores (the controller's GUD block):
//! [`cycle600`] reads it and returns the next one, so on any error the caller's state is
//! untouched.

use super::head_def::{valid_name, HeadTable, NAME_MAX};
use crate::kinematics::{Choice, Machine, Rule, MAX_AXES};
use crate::{angles_from_matrix, matrix_from_angles, AxisCode, Convention, Error, Frame, Kind};

/// The paper's 18 documented parameters, in its order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Call<'a> {
    /// `_INEXIN`: 1 intrinsic, 0 extrinsic input rotation.
    pub inexin: i32,
    /// `_MIHEAD`: the accessory's name (at most 31 bytes).
    pub mihead: &'a [u8],
    /// `_SW_REC`: 1 recalculation only; 0 also positions the head ([`position`]).
    pub sw_rec: i32,
    /// `_BIN_IN`: axis-sequence code of the input rotation (`00` pairs allowed).
    pub bin_in: i32,
    /// `_POS_X`, `_POS_Y`, `_POS_Z`: translation before the rotation.
    pub pos: [f64; 3],
    /// `_ANG_1`, `_ANG_2`, `_ANG_3` in degrees.
    pub ang: [f64; 3],
    /// `_POS_X_R`, `_POS_Y_R`, `_POS_Z_R`: translation after the rotation.
    pub pos_r: [f64; 3],
    /// `_INEXOUT`: 1 intrinsic, 0 extrinsic output angles.
    pub inexout: i32,
    /// `_BIN_OUT`: one of the 12 three-rotation codes.
    pub bin_out: i32,
    /// `_ROT_AD`: 1 adds the rotation to the one stored by the previous call.
    pub rot_ad: i32,
    /// `_ROT_INV`: 1 use the inverse head position (the other solution, see [`position`]).
    pub rot_inv: i32,
    /// `_RETR_Z`: 1 retract before rotating (kept for the calling cycle).
    pub retr_z: i32,
}

/// The results of a call: the paper's `_CYC600_2.._6`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Results {
    /// `_CYC600_2.._4`: the output angles in rotation order.
    pub angles: [f64; 3],
    /// `_CYC600_5` (`_INEXOUT`) and `_CYC600_6` (`_BIN_OUT`).
    pub convention: Convention,
    /// The decomposition was singular (θ3 = 0 by rule).
    pub singular: bool,
}

/// What CYCLE600 remembers between calls (and across a restart).
///
/// ```
/// use cncrot::dialects::cycle600::{cycle600, Call, State};
/// // Paper, Example 3, first call.
/// let call = Call { inexin: 0, mihead: b"UFK600", sw_rec: 1, bin_in: 57, pos: [0.0; 3],
///     ang: [30.0, 45.0, 60.0], pos_r: [0.0; 3], inexout: 1, bin_out: 39, rot_ad: 0,
///     rot_inv: 0, retr_z: 0 };
/// let s = cycle600(&State::default(), None, &call).unwrap();
/// let r = s.results.unwrap();
/// assert!((r.angles[0] - 37.7923).abs() < 1e-4 && (r.angles[2] - 49.1066).abs() < 1e-4);
/// assert_eq!(s.name(), b"UFK600");
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct State {
    /// `_CYC600_1`: the accessory's name, `name_len` bytes.
    pub name: [u8; NAME_MAX],
    /// Length of the name.
    pub name_len: u8,
    /// The results of the last call, `None` before the first.
    pub results: Option<Results>,
    /// The active frame (identity before the first call).
    pub frame: Frame,
    /// `_ROT_INV` of the last call.
    pub rot_inv: bool,
    /// `_RETR_Z` of the last call.
    pub retr_z: bool,
}

impl State {
    /// The accessory's name.
    pub fn name(&self) -> &[u8] {
        &self.name[..usize::from(self.name_len).min(NAME_MAX)]
    }
}

/// Where CYCLE600 looks `_MIHEAD` up: a [`HeadTable`], or a table in another layout (the C
/// boundary reads the caller's table in place, so that a call costs the same whatever the
/// table holds).
pub trait HeadLookup {
    /// Whether an accessory of that name is defined; an error when its entry is corrupt.
    fn contains(&self, name: &[u8]) -> Result<bool, Error>;
}

impl HeadLookup for HeadTable {
    fn contains(&self, name: &[u8]) -> Result<bool, Error> {
        Ok(self.find(name).is_some())
    }
}

fn flag(v: i32) -> Result<bool, Error> {
    Ok(Kind::from_flag(v)? == Kind::Intrinsic)
}

/// One call of CYCLE600 on `state`; returns the next state.
///
/// The input frame is `Trans(pos)·R_in·Trans(pos_r)`. With `rot_ad = 1` it is added to the
/// stored frame: on the right for an intrinsic input, on the left for an extrinsic one. Its
/// rotation is decomposed for `inexout`/`bin_out`. With a head table, `mihead` must name one
/// of its accessories ([`Error::UnknownHead`]); without one the name is only recorded.
/// `sw_rec = 0` (positioning the head) recalculates the same way; the axis positions then
/// come from [`position`] with the accessory's machine. A frame that overflows (positions near `f64::MAX`) returns [`Error::OutOfRange`]. The name
/// must be printable ASCII without spaces or quotes ([`valid_name`]; empty is allowed
/// without a table), else [`Error::BadArgument`].
pub fn cycle600(state: &State, heads: Option<&HeadTable>, call: &Call) -> Result<State, Error> {
    cycle600_in(state, heads.map(|t| t as &dyn HeadLookup), call)
}

/// Whether `_MIHEAD` can name an accessory: empty, or at most [`NAME_MAX`] bytes
/// ([`Error::NameTooLong`]) of printable ASCII without spaces or quotes
/// ([`Error::BadArgument`]).
pub(crate) fn check_name(mihead: &[u8]) -> Result<(), Error> {
    if mihead.len() > NAME_MAX {
        return Err(Error::NameTooLong);
    }
    if mihead.is_empty() || valid_name(mihead) {
        Ok(())
    } else {
        Err(Error::BadArgument)
    }
}

/// The first parameter of `call` that the cycle refuses on its own, whatever the others
/// (a flag other than 0 or 1, a `_MIHEAD` that names nothing, a code that is no sequence):
/// its index in the call (0 `_INEXIN` … 17 `_RETR_Z`, as the paper numbers them from 1),
/// the error, and what the parameter may be, so that a message can name it. `None` when
/// each is well-formed (the call can still be refused as a whole: an unknown accessory).
///
/// ```
/// use cncrot::dialects::cycle600::{first_fault, Call};
/// let call = Call { inexin: 0, mihead: b"UFK 600", sw_rec: 1, bin_in: 57, pos: [0.0; 3],
///     ang: [30.0, 45.0, 60.0], pos_r: [0.0; 3], inexout: 1, bin_out: 39, rot_ad: 0,
///     rot_inv: 0, retr_z: 0 };
/// let (k, e, _) = first_fault(&call).unwrap();
/// assert_eq!((k, e), (1, cncrot::Error::BadArgument)); // _MIHEAD with a space
/// ```
pub fn first_fault(call: &Call) -> Option<(usize, Error, &'static str)> {
    let flag = |f: i32| Kind::from_flag(f).map(drop);
    let checks: [(usize, Result<(), Error>, &'static str); 9] = [
        (
            0,
            flag(call.inexin),
            "_INEXIN: 0 (extrinsic) or 1 (intrinsic)",
        ),
        (
            1,
            check_name(call.mihead),
            "_MIHEAD: empty, or at most 31 printable characters without spaces or quotes",
        ),
        (2, flag(call.sw_rec), "_SW_REC: 0 or 1"),
        (
            3,
            AxisCode::new(call.bin_in).map(drop),
            "_BIN_IN: an axis-sequence code (57: X, Y, Z)",
        ),
        (
            13,
            flag(call.inexout),
            "_INEXOUT: 0 (extrinsic) or 1 (intrinsic)",
        ),
        (
            14,
            Convention::from_c(call.inexout, call.bin_out).map(drop),
            "_BIN_OUT: a code of three rotations (57: X, Y, Z)",
        ),
        (15, flag(call.rot_ad), "_ROT_AD: 0 or 1"),
        (16, flag(call.rot_inv), "_ROT_INV: 0 or 1"),
        (17, flag(call.retr_z), "_RETR_Z: 0 or 1"),
    ];
    checks
        .into_iter()
        .find_map(|(k, check, allowed)| check.err().map(|e| (k, e, allowed)))
}

/// [`cycle600`] with the accessories looked up through any [`HeadLookup`].
pub fn cycle600_in(
    state: &State,
    heads: Option<&dyn HeadLookup>,
    call: &Call,
) -> Result<State, Error> {
    let kind_in = Kind::from_flag(call.inexin)?;
    let recalc_only = flag(call.sw_rec)?;
    let code_in = AxisCode::new(call.bin_in)?;
    let out = Convention::from_c(call.inexout, call.bin_out)?;
    let additive = flag(call.rot_ad)?;
    let rot_inv = flag(call.rot_inv)?;
    let retr_z = flag(call.retr_z)?;
    let numbers = call.pos.iter().chain(&call.ang).chain(&call.pos_r);
    if !numbers.into_iter().all(|x| x.is_finite()) {
        return Err(Error::NotFinite);
    }
    check_name(call.mihead)?;
    if let Some(table) = heads {
        // An empty name names no accessory (a corrupt entry with an empty name field must
        // not match it).
        if call.mihead.is_empty() || !table.contains(call.mihead)? {
            return Err(Error::UnknownHead);
        }
    }
    // `_SW_REC = 0` recalculates the same way; positioning is [`position`]'s, with the
    // machine the accessory stands for.
    let _ = recalc_only;

    let rotation = matrix_from_angles(kind_in, code_in, call.ang);
    let input = Frame::with_translations(call.pos, rotation, call.pos_r);
    let frame = match (additive, kind_in) {
        (false, _) => input,
        (true, Kind::Intrinsic) => state.frame.compose(&input),
        (true, Kind::Extrinsic) => input.compose(&state.frame),
    };
    // Finite inputs can still overflow (positions near f64::MAX): such a frame is refused
    // rather than stored.
    let h = frame.to_homogeneous();
    if !h.iter().flatten().all(|x| x.is_finite()) {
        return Err(Error::OutOfRange);
    }
    let d = angles_from_matrix(out, &frame.rotation)?;
    // Nothing non-finite is ever stored (a decomposition of a checked rotation is finite;
    // this keeps it so whatever changes above).
    if !d.angles.iter().all(|x| x.is_finite()) {
        return Err(Error::OutOfRange);
    }
    let mut next = State {
        name: [0; NAME_MAX],
        name_len: call.mihead.len() as u8,
        results: Some(Results {
            angles: d.angles,
            convention: out,
            singular: d.singular,
        }),
        frame,
        rot_inv,
        retr_z,
    };
    next.name[..call.mihead.len()].copy_from_slice(call.mihead);
    Ok(next)
}

/// `_SW_REC = 0`: the positions of the accessory's rotary axes for the frame a call left in
/// `state`, seen from the current positions: the solution closest to them, or with
/// `_ROT_INV = 1` the other one of the pair (the same orientation "by an inverse rotation of
/// 180° in both axes" — exactly that only for perpendicular axes, so the other solution is
/// computed, not derived by that rule). Errors as [`Machine::choose`].
///
/// ```
/// use cncrot::dialects::cycle600::{cycle600, position, Call, State};
/// use cncrot::kinematics::{Machine, RotaryAxis, Side};
/// let head = Machine::new([0.0, 0.0, 1.0]).unwrap()
///     .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3])).unwrap()
///     .with_axis(RotaryAxis::new(Side::Tool, [1.0, 0.0, 0.0], [0.0; 3])).unwrap();
/// // Intrinsic Z, X' = 30°, 40°, swivelled with the head.
/// let call = Call { inexin: 1, mihead: b"H", sw_rec: 0, bin_in: 7, pos: [0.0; 3],
///     ang: [30.0, 40.0, 0.0], pos_r: [0.0; 3], inexout: 1, bin_out: 39, rot_ad: 0,
///     rot_inv: 0, retr_z: 0 };
/// let s = cycle600(&State::default(), None, &call).unwrap();
/// let c = position(&s, &head, [0.0; 3]).unwrap();
/// assert!((c.axes[0] - 30.0).abs() < 1e-9 && (c.axes[1] - 40.0).abs() < 1e-9);
/// let inv = position(&State { rot_inv: true, ..s }, &head, [0.0; 3]).unwrap();
/// assert!((inv.axes[0] + 150.0).abs() < 1e-9 && (inv.axes[1] + 40.0).abs() < 1e-9);
/// ```
pub fn position(
    state: &State,
    machine: &Machine,
    current: [f64; MAX_AXES],
) -> Result<Choice, Error> {
    let rule = if state.rot_inv {
        Rule::Inverse
    } else {
        Rule::Closest
    };
    machine.choose(&state.frame.rotation, current, rule)
}
