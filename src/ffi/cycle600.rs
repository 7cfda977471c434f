//! Exports of CYCLE600 and the HEAD_DEF table. The structs are plain data that C owns; each
//! is validated when read (a state restored from storage may be corrupt).

use super::heads::{bit, cncrot_head_table, field_name, to_field, CHeads, CNCROT_NAME_SIZE};
use super::{byte, cncrot_status, guard, non_null};
use crate::dialects::cycle600::{self, Call, HeadLookup, Results, State};
use crate::dialects::head_def::valid_name;
use crate::{crc32, Convention, Error, Frame};
use core::ffi::c_char;

/// The value of `cncrot_cycle600_gud::format` in every state this version writes.
pub const CNCROT_CYCLE600_GUD_FORMAT: u32 = 0x4336_3031;

/// CYCLE600's state, the controller's GUD block `MGUD_CYC600`: plain data, owned by the
/// caller, that can be stored as bytes and restored after a restart. A zeroed struct is the
/// valid initial state (no rotation yet). Its first six fields are the paper's results.
///
/// Layout (216 bytes, no padding, native byte order): `cyc600_1` at 0, `cyc600_2..4` at
/// 32/40/48, `cyc600_5`/`cyc600_6` at 56/60, `frame` at 64, `active` 192, `rot_inv` 196,
/// `retr_z` 200, `reserved` 204, `format` 208, `checksum` 212. A state is accepted on entry
/// only if it is all zero bytes (the initial state) or has `format` =
/// `CNCROT_CYCLE600_GUD_FORMAT`, `checksum` = the CRC-32 (IEEE, as zlib's `crc32`) of bytes
/// 0..212, and well-formed fields; anything else is `CNCROT_STATUS_BAD_STATE`. So every
/// single-bit flip, random bytes and an edited field are refused, and a state is never
/// half-used. Treat it as opaque: to change it, call `cncrot_cycle600`.
#[allow(non_camel_case_types)]
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct cncrot_cycle600_gud {
    /// `_CYC600_1`: the accessory's name (`_MIHEAD`), NUL-terminated, zero-filled after.
    pub cyc600_1: [c_char; CNCROT_NAME_SIZE],
    /// `_CYC600_2`: first output angle, degrees.
    pub cyc600_2: f64,
    /// `_CYC600_3`: second output angle, degrees.
    pub cyc600_3: f64,
    /// `_CYC600_4`: third output angle, degrees.
    pub cyc600_4: f64,
    /// `_CYC600_5`: `_INEXOUT` of the last call (1 intrinsic, 0 extrinsic).
    pub cyc600_5: i32,
    /// `_CYC600_6`: `_BIN_OUT` of the last call.
    pub cyc600_6: i32,
    /// The active frame, 4x4 row-major, translations included (`_ROT_AD` adds to it).
    pub frame: [f64; 16],
    /// 1 once a call has stored a result, 0 in the initial state (frame = identity).
    pub active: i32,
    /// `_ROT_INV` of the last call, for the calling cycle.
    pub rot_inv: i32,
    /// `_RETR_Z` of the last call, for the calling cycle.
    pub retr_z: i32,
    /// Zero.
    pub reserved: i32,
    /// `CNCROT_CYCLE600_GUD_FORMAT` once a call has stored a result; 0 in the initial state.
    pub format: u32,
    /// CRC-32 of the 212 bytes before it; 0 in the initial state.
    pub checksum: u32,
}

/// The bytes the checksum covers: everything before it.
const CHECKED: usize = core::mem::offset_of!(cncrot_cycle600_gud, checksum);
const GUD_SIZE: usize = core::mem::size_of::<cncrot_cycle600_gud>();
// No padding anywhere (every byte is a field's, so every byte is covered), and the layout
// the documentation states.
const _: () = assert!(CHECKED == 212 && GUD_SIZE == 216);

/// The state's bytes.
fn gud_bytes(g: &cncrot_cycle600_gud) -> &[u8; GUD_SIZE] {
    // SAFETY: a plain repr(C) struct of integers and doubles without padding (asserted
    // above): all of its bytes are initialised, and u8 has no alignment requirement.
    unsafe { &*(g as *const cncrot_cycle600_gud).cast::<[u8; GUD_SIZE]>() }
}

/// Reads the caller's state. Not inlined: the copy of the stored bytes lives in this frame
/// only, which is gone before the cycle computes (stack bound of `cncrot_cycle600`).
///
/// # Safety
/// `gud` is non-NULL and points to a readable `cncrot_cycle600_gud`.
#[inline(never)]
unsafe fn load(gud: *const cncrot_cycle600_gud) -> Result<State, Error> {
    state_from_c(&gud.read_unaligned())
}

/// Writes the next state; not inlined for the same reason as [`load`].
///
/// # Safety
/// `gud` is non-NULL and points to a writable `cncrot_cycle600_gud`.
#[inline(never)]
unsafe fn store(gud: *mut cncrot_cycle600_gud, s: &State) {
    gud.write_unaligned(state_to_c(s));
}

/// The state in a stored `cncrot_cycle600_gud`, or `BadState` unless it is the initial
/// state (all zero bytes) or one this library wrote (format, checksum, and well-formed).
fn state_from_c(g: &cncrot_cycle600_gud) -> Result<State, Error> {
    let bytes = gud_bytes(g);
    if g.format == 0 {
        return if bytes.iter().all(|&b| b == 0) {
            Ok(State::default())
        } else {
            Err(Error::BadState)
        };
    }
    if g.format != CNCROT_CYCLE600_GUD_FORMAT || g.checksum != crc32(&bytes[..CHECKED]) {
        return Err(Error::BadState);
    }
    // A state with a right checksum was written by this library; reading it strictly all
    // the same refuses the one random state in 2^32 whose checksum matches by chance.
    decode(g).ok_or(Error::BadState)
}

fn decode(g: &cncrot_cycle600_gud) -> Option<State> {
    let (name, len) = field_name(&g.cyc600_1, Error::BadState).ok()?;
    let zero_filled = g.cyc600_1.iter().skip(len).all(|&c| c == 0);
    let name_ok = len == 0 || valid_name(name.get(..len)?);
    if !zero_filled || !name_ok || g.active != 1 || g.reserved != 0 {
        return None;
    }
    let h: [[f64; 4]; 4] = core::array::from_fn(|i| core::array::from_fn(|j| g.frame[4 * i + j]));
    let frame = Frame::from_homogeneous(&h).ok()?;
    let convention = Convention::from_c(g.cyc600_5, g.cyc600_6).ok()?;
    let angles = [g.cyc600_2, g.cyc600_3, g.cyc600_4];
    if !angles.iter().all(|x| x.is_finite()) {
        return None;
    }
    Some(State {
        name,
        name_len: len as u8,
        results: Some(Results {
            angles,
            convention,
            singular: false,
        }),
        frame,
        rot_inv: bit(g.rot_inv).ok()?,
        retr_z: bit(g.retr_z).ok()?,
    })
}

fn state_to_c(s: &State) -> cncrot_cycle600_gud {
    let h = s.frame.to_homogeneous();
    let (angles, conv) = match s.results {
        Some(r) => (
            r.angles,
            (
                r.convention.kind.flag(),
                r.convention.sequence.code() as i32,
            ),
        ),
        None => ([0.0; 3], (0, 0)),
    };
    let mut g = cncrot_cycle600_gud {
        cyc600_1: to_field(s.name()),
        cyc600_2: angles[0],
        cyc600_3: angles[1],
        cyc600_4: angles[2],
        cyc600_5: conv.0,
        cyc600_6: conv.1,
        frame: core::array::from_fn(|k| h[k / 4][k % 4]),
        active: s.results.is_some() as i32,
        rot_inv: s.rot_inv as i32,
        retr_z: s.retr_z as i32,
        reserved: 0,
        format: CNCROT_CYCLE600_GUD_FORMAT,
        checksum: 0,
    };
    g.checksum = crc32(&gud_bytes(&g)[..CHECKED]);
    g
}

/// `sizeof(cncrot_cycle600_gud)` as the library sees it: compare with the caller's
/// `sizeof` to detect a header/library mismatch before storing states.
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub extern "C" fn cncrot_cycle600_gud_size() -> usize {
    core::mem::size_of::<cncrot_cycle600_gud>()
}

/// CYCLE600 with the paper's 18 parameters in its order, after the caller's state `gud` and
/// an optional head table `heads` (NULL: the name is only recorded; otherwise `_MIHEAD`
/// must name one of its accessories).
///
/// The input rotation (`_INEXIN`, `_BIN_IN`, `_ANG_1.._3`) with `_POS_*` before and
/// `_POS_*_R` after it forms a frame; `_ROT_AD = 1` adds it to the frame stored in `gud`
/// (intrinsic input on the right, extrinsic on the left). Its rotation is decomposed for
/// `_INEXOUT`/`_BIN_OUT` into `cyc600_2..4`. `_SW_REC = 1` recalculates only; `_SW_REC = 0`
/// (positioning the head) recalculates the same way, and `cncrot_cycle600_position` then
/// gives the axis positions for the accessory's machine. `_ROT_INV` and `_RETR_Z`
/// (0/1) are kept in `gud`. The stored rotation is kept orthonormal however many additive
/// calls follow. `_MIHEAD` is printable ASCII without spaces or quotes, or empty without a
/// table (`CNCROT_STATUS_BAD_ARGUMENT` otherwise). The table is read in place: only its
/// count and the entry that matches are checked.
///
/// Returns 0 or `CNCROT_STATUS_SINGULAR` with `gud` updated (and sealed with its format and
/// checksum); a negative status leaves `gud` exactly as it was: `CNCROT_STATUS_BAD_STATE`
/// for a `gud` that is neither zeroed nor one this library wrote (see
/// `cncrot_cycle600_gud`), `CNCROT_STATUS_BAD_ARGUMENT` for a corrupt or misaligned table
/// or a `_MIHEAD` that is no name (a space, a quote, a control character),
/// `CNCROT_STATUS_NULL_POINTER` (`gud` or `mihead`), `CNCROT_STATUS_BAD_FLAG` (`_INEXIN`,
/// `_SW_REC`, `_INEXOUT`, `_ROT_AD`, `_ROT_INV`, `_RETR_Z` other than 0 or 1),
/// `CNCROT_STATUS_BAD_SEQUENCE` (`_BIN_IN`, `_BIN_OUT`), `CNCROT_STATUS_INCOMPLETE_SEQUENCE`
/// (a `_BIN_OUT` of fewer than three rotations), `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_NAME_TOO_LONG` (`_MIHEAD` of more than 31 bytes),
/// `CNCROT_STATUS_UNKNOWN_HEAD` (with a table: `_MIHEAD` not in it),
/// `CNCROT_STATUS_OUT_OF_RANGE` (positions whose frame overflows).
///
/// # Safety
/// `gud` points to a writable state, `mihead` to a NUL-terminated string (at most 31 bytes
/// are used; at most 32 are read), `heads` to a table (aligned as `cncrot_head_table`) or is
/// NULL.
///
/// ```c
/// cncrot_cycle600_gud gud;   // paper, Example 3
/// memset(&gud, 0, sizeof gud);
/// cncrot_cycle600(&gud, NULL, 0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0);
/// // gud.cyc600_2..4 = 37.7923, 20.7048, 49.1066; gud.cyc600_5 = 1; gud.cyc600_6 = 39
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_cycle600(
    gud: *mut cncrot_cycle600_gud,
    heads: *const cncrot_head_table,
    inexin: i32,
    mihead: *const c_char,
    sw_rec: i32,
    bin_in: i32,
    pos_x: f64,
    pos_y: f64,
    pos_z: f64,
    ang_1: f64,
    ang_2: f64,
    ang_3: f64,
    pos_x_r: f64,
    pos_y_r: f64,
    pos_z_r: f64,
    inexout: i32,
    bin_out: i32,
    rot_ad: i32,
    rot_inv: i32,
    retr_z: i32,
) -> i32 {
    guard(|| {
        non_null(&[gud.is_null(), mihead.is_null()])?;
        // Bounded read: stop at the NUL, never past CNCROT_NAME_SIZE bytes.
        let mut name = [0u8; CNCROT_NAME_SIZE];
        let mut len = None;
        for (k, n) in name.iter_mut().enumerate() {
            *n = byte(mihead.add(k).read());
            if *n == 0 {
                len = Some(k);
                break;
            }
        }
        let len = len.ok_or(cncrot_status::NameTooLong)?;
        // The table is read in place (only the entry that matches), so it must be aligned
        // like the C type; a misaligned pointer is refused rather than read.
        if heads.align_offset(core::mem::align_of::<cncrot_head_table>()) != 0 {
            return Err(cncrot_status::BadArgument);
        }
        // SAFETY: NULL gives None; otherwise aligned (checked) and, as the caller
        // guarantees, pointing to a table, whose integer and double fields are valid for
        // every bit pattern.
        let lookup = heads.as_ref().map(CHeads);
        let state = load(gud)?;
        let call = Call {
            inexin,
            mihead: &name[..len],
            sw_rec,
            bin_in,
            pos: [pos_x, pos_y, pos_z],
            ang: [ang_1, ang_2, ang_3],
            pos_r: [pos_x_r, pos_y_r, pos_z_r],
            inexout,
            bin_out,
            rot_ad,
            rot_inv,
            retr_z,
        };
        let heads = lookup.as_ref().map(|l| l as &dyn HeadLookup);
        let next = cycle600::cycle600_in(&state, heads, &call)?;
        store(gud, &next);
        let singular = next.results.is_some_and(|r| r.singular);
        Ok(super::status_of(singular))
    })
}

/// `_SW_REC = 0`: the rotary-axis positions of `machine` for the frame the last
/// `cncrot_cycle600` call left in `gud`, seen from the current positions `current_deg`:
/// the solution closest to them, or with `_ROT_INV = 1` stored in `gud` the other one of
/// the pair — or, when the other lies outside the travel or there is none, the closest,
/// with status 0 (compare `axes_deg` with `current_deg` to tell). Outputs as
/// `cncrot_machine_choose` with rule `CNCROT_CHOOSE_CLOSEST` / `CNCROT_CHOOSE_INVERSE`,
/// positions within `CNCROT_MACHINE_TRAVEL_TOLERANCE_DEG` beyond a travel end taken at
/// that end. `_RETR_Z` (in `gud`) is the calling cycle's: retract before moving the axes.
///
/// Returns 0, `CNCROT_STATUS_FREE_AXIS`, `CNCROT_STATUS_SNAPPED`, or with nothing written:
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_STATE` (a `gud` this library did not
/// write), `CNCROT_STATUS_UNREACHABLE`, `CNCROT_STATUS_OUT_OF_TRAVEL`,
/// `CNCROT_STATUS_BAD_ARGUMENT` (an unused current position not 0),
/// `CNCROT_STATUS_OUT_OF_RANGE` (a current position of magnitude
/// `CNCROT_MACHINE_ANGLE_MAX_DEG` or more), `CNCROT_STATUS_NOT_FINITE` (a current
/// position), and for a description that is not a machine (see `cncrot_machine`)
/// `CNCROT_STATUS_BAD_ARGUMENT`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE`, `CNCROT_STATUS_NAME_TOO_LONG`.
///
/// # Safety
/// `gud` points to a state, `machine` to a `cncrot_machine`, `current_deg`, `axes_deg`,
/// `residual_deg` to 3 and `remaining` to 16 doubles.
///
/// ```c
/// double cur[3] = {0, 0, 0}, ax[3], res[3], rem[16];
/// cncrot_cycle600(&gud, &heads, 1, "H", 0, 7, 0, 0, 0, 30, 40, 0, 0, 0, 0, 1, 39, 0, 0, 0);
/// cncrot_cycle600_position(&gud, &m, cur, ax, res, rem);   // ax = {30, 40, 0}
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_cycle600_position(
    gud: *const cncrot_cycle600_gud,
    machine: *const super::cncrot_machine,
    current_deg: *const f64,
    axes_deg: *mut f64,
    residual_deg: *mut f64,
    remaining: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            gud.is_null(),
            machine.is_null(),
            current_deg.is_null(),
            axes_deg.is_null(),
            residual_deg.is_null(),
            remaining.is_null(),
        ])?;
        let state = load(gud)?;
        let mut m = crate::kinematics::Machine::EMPTY;
        super::machine::load_into(machine, &mut m)?;
        let current = super::read_finite::<3>(current_deg)?;
        let c = cycle600::position(&state, &m, current)?;
        super::machine::write_choice(&c, axes_deg, residual_deg, remaining)
    })
}
