//! Exports of program lines: read a block into a caller-owned program state, read the active
//! frame, write the block for a frame.

use super::frame::{read_frame, write_frame};
use super::machine::{
    cncrot_machine, CNCROT_CHOOSE_CLOSEST, CNCROT_CHOOSE_MINUS, CNCROT_CHOOSE_NEGATIVE_TURN,
    CNCROT_CHOOSE_PLUS, CNCROT_CHOOSE_POSITIVE_TURN,
};
use super::{cncrot_status, guard, non_null, read_finite, write};
use crate::dialects::program::{
    self, AxisChoice, Dialect, Direct, DirectAxes, Feed, FormSpec, Plane, Positioning, Program,
    Remark, Retract,
};
use crate::{crc32, Error, Frame};
use core::ffi::c_char;

/// Siemens SINUMERIK: `CYCLE800(…)`, `CYCLE600(…)`, `ROT`/`AROT`/`CROT`, `ROTS`/`AROTS`/`CROTS`,
/// `TRANS`/`ATRANS`; blocks of at most 512 bytes.
pub const CNCROT_DIALECT_SINUMERIK: i32 = 1;
/// Heidenhain plain language: `PLANE SPATIAL|PROJECTED|EULER|VECTOR|POINTS|RELATIV|RESET`;
/// blocks of at most 254 bytes.
pub const CNCROT_DIALECT_HEIDENHAIN: i32 = 2;
/// Fanuc-style: `G68.2`, `G68.4`, `G69`, `G53.1`, the 3-D coordinate conversion
/// `G68 X Y Z I J K R` and the rotation in the plane `G68 X Y R`; blocks of at most 256
/// bytes.
pub const CNCROT_DIALECT_FANUC: i32 = 3;
/// Syntec: `G158` and its Fanuc-style `G68.2` mode; blocks of at most 256 bytes.
pub const CNCROT_DIALECT_SYNTEC: i32 = 4;
/// Beckhoff TwinCAT NC I: `ROT`, `AROT`, the zero offset shift `G58`; blocks of at most 256
/// bytes.
pub const CNCROT_DIALECT_TWINCAT: i32 = 5;
/// Haas: `G268`, `G269`, `G253`; blocks of at most 256 bytes.
pub const CNCROT_DIALECT_HAAS: i32 = 6;
// Each C code is the Rust dialect's, and every dialect has one: a family registered
// without its C code fails to compile here.
const _: () = {
    assert!(CNCROT_DIALECT_SINUMERIK == Dialect::Sinumerik as i32);
    assert!(CNCROT_DIALECT_HEIDENHAIN == Dialect::Heidenhain as i32);
    assert!(CNCROT_DIALECT_FANUC == Dialect::Fanuc as i32);
    assert!(CNCROT_DIALECT_SYNTEC == Dialect::Syntec as i32);
    assert!(CNCROT_DIALECT_TWINCAT == Dialect::Twincat as i32);
    assert!(CNCROT_DIALECT_HAAS == Dialect::Haas as i32);
    assert!(Dialect::ALL.len() == 6);
};
// The longest line written is the longest any dialect reads.
const _: () = {
    let mut k = 0;
    while k < Dialect::ALL.len() {
        assert!(Dialect::ALL[k].max_line() <= CNCROT_PROGRAM_LINE_MAX);
        k += 1;
    }
};

/// An option of `cncrot_program_init`: SINUMERIK frame angles in Euler mode (machine data
/// 10600 = 2) instead of RPY.
pub const CNCROT_PROGRAM_SINUMERIK_EULER: u32 = 1;
/// An option of `cncrot_program_init`: Heidenhain's `CYCL DEF 19.1 A B C` are the positions
/// of the rotary axes named A, B, C (a direct mode, as `PLANE AXIAL`: iTNC 530 machine
/// parameter 7500 bit 1 = 0) instead of spatial angles (as `PLANE SPATIAL`).
pub const CNCROT_PROGRAM_HEIDENHAIN_AXIS_ANGLES: u32 = 2;
/// Every option bit this version knows.
const OPTIONS: u32 = CNCROT_PROGRAM_SINUMERIK_EULER | CNCROT_PROGRAM_HEIDENHAIN_AXIS_ANGLES;
/// The longest line `cncrot_program_write` writes, without its NUL (SINUMERIK's block limit).
pub const CNCROT_PROGRAM_LINE_MAX: usize = 512;
/// The longest form name `cncrot_program_write` reads, without its NUL.
const FORM_MAX: usize = 64;

/// The modal state of a part program, owned by the caller: the active frame and what the
/// controller keeps between blocks. Start from all zero bytes (nothing active, no options,
/// ready for the first block) or from `cncrot_program_init` (to set `options`). Treat it as
/// opaque: the library seals every state it writes (`reserved` holds a checksum of the
/// bytes before it), and a state it did not write as it is — a field set or edited by
/// hand, a bit flipped in storage, a state of another version — is refused with
/// `CNCROT_STATUS_BAD_STATE`.
///
/// Layout (216 bytes, no padding, native byte order): `rotation` at 0, `origin` 72,
/// `angles` 96, `shift` 120, `active` 144, `dialect` 148, `options` 152, `choice` 156,
/// `reference_axis` 160, `positioning` 164, `direct_given` 168, `retract` 172,
/// `retract_mm` 176, `feed_mm_min` 184, `feed` 192, `plane` 196, `table_rot` 200,
/// `relative` 204, `spare` 208, `reserved` 212. Accepted on entry: all zero bytes, or
/// `reserved` = the CRC-32 (IEEE, as zlib's `crc32`) of bytes 0..212 exclusive-or
/// `CNCROT_PROGRAM_FORMAT`, with well-formed fields.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct cncrot_program {
    /// The active rotation, row-major (all zero while `active` is 0).
    pub rotation: [f64; 9],
    /// The active origin: the datum shift and the tilt's origin together (all zero while
    /// `active` is 0).
    pub origin: [f64; 3],
    /// TwinCAT's programmed angles `X Y Z` (its `AROT` adds angles); a direct mode's
    /// rotary-axis positions (degrees); zero otherwise.
    pub angles: [f64; 3],
    /// The datum shift the program made active (Heidenhain `CYCL DEF 7`, `TRANS DATUM`;
    /// Fanuc-style `G52`; TwinCAT `G58`), in the workpiece axes before the tilt: part of
    /// `origin`, kept when the tilt is cancelled.
    pub shift: [f64; 3],
    /// 1 while a frame is active, 0 when none is (the identity); 2 or 3 while a direct mode
    /// is (`PLANE AXIAL`, `G158` mode 2: 2, the positions of the axes named A, B, C;
    /// `CYCLE800` direct: 3, the positions of the machine's rotary axes 1, 2, 3): then
    /// `angles` holds the positions, `origin` the origin, `rotation` is all zero (the
    /// machine's kinematics gives it: `cncrot_program_frame_on`).
    pub active: i32,
    /// The dialect of the blocks read so far (`CNCROT_DIALECT_*`), 0 before the first.
    pub dialect: i32,
    /// `CNCROT_PROGRAM_*` settings of the machine, given to `cncrot_program_init`.
    pub options: u32,
    /// The solution the active tilt's own words choose for the rotary axes
    /// (`CNCROT_CHOOSE_CLOSEST` when they choose none, `CNCROT_CHOOSE_MINUS` for `SEQ-`,
    /// `_DIR = -1`, `CNCROT_CHOOSE_PLUS` for `SEQ+`, `_DIR = +1`,
    /// `CNCROT_CHOOSE_POSITIVE_TURN` / `_NEGATIVE_TURN` for `G53.1 P1` / `P2`);
    /// `cncrot_program_axes` follows it.
    pub choice: i32,
    /// The axis the choice refers to: 1..3 in chain order, or 0 for the machine's master
    /// axis (for a head the axis nearest the tool, else the one nearest the machine base);
    /// 0 with `CNCROT_CHOOSE_CLOSEST`.
    pub reference_axis: i32,
    /// How the program moves the machine to the active tilt: `CNCROT_POSITIONING_STAY`
    /// (`STAY`, a `G68.2` alone, a `CYCLE800` with `_DIR` 0, frames, a cancel),
    /// `CNCROT_POSITIONING_TURN` (`TURN`, `G53.1`, `G253`, a `CYCLE800` with `_DIR` ±1),
    /// `CNCROT_POSITIONING_MOVE` (`MOVE`, `G53.6`: the tool
    /// tip kept in place). With no tilt active, turn or move means the axes turn to the
    /// untilted plane (`PLANE RESET TURN`, a zero tilt with `TURN`, a `CYCLE800` of zero
    /// angles, a `G53.1` after a `G68.2` of zeros).
    pub positioning: i32,
    /// Which rotary-axis positions an active direct mode gave: bit k for `angles[k]`
    /// (1..7 while `active` is 2 or 3; 0 otherwise).
    pub direct_given: u32,
    /// How the tool retracts before the rotary axes turn, as the tilt block says
    /// (`CNCROT_RETRACT_*`: Heidenhain `MB`, CYCLE800 `_FR`); `CNCROT_RETRACT_NONE` while
    /// `positioning` is stay.
    pub retract: i32,
    /// The retraction along the tool axis in mm for `CNCROT_RETRACT_TOOL` (`MB n`,
    /// `_FR_I`), positive; 0 otherwise.
    pub retract_mm: f64,
    /// The feed rate in mm/min for `CNCROT_FEED_RATE` (`F n`), positive; 0 otherwise.
    pub feed_mm_min: f64,
    /// How fast the rotary axes turn (`CNCROT_FEED_*`: Heidenhain `FMAX`, `F n`,
    /// `F AUTO`); `CNCROT_FEED_RAPID` while `positioning` is stay and in every dialect
    /// without a feed word in its tilt.
    pub feed: i32,
    /// The working plane the program selected (`CNCROT_PLANE_*`: `G17`, `G18`, `G19`;
    /// `CNCROT_PLANE_XY` until one is): the plane of the rotations that name no axis
    /// (`ROT RPL=`, `G68 X Y R`).
    pub plane: i32,
    /// 1 while the active tilt turns a free rotary table to the plane (Heidenhain `TABLE
    /// ROT`: `cncrot_program_axes` turns the first table from the workpiece where it is
    /// parallel to the tool so that the machine makes the whole rotation), 0 otherwise
    /// (`COORD ROT` or no word: the coordinate system turns, the table stays; always 0
    /// while no tilt or a direct mode is active).
    pub table_rot: u32,
    /// 1 while the active tilt was set by a block that adds to the tilt before it (`PLANE
    /// RELATIV`, `G68.4`, a `CYCLE800` with `_ST` 1, `AROT`, `ATRANS`, `G158 P01…`,
    /// `CYCLE600` with `_ROT_AD` 1, TwinCAT's `AROT` of one axis): `cncrot_program_write_change`
    /// then writes the target's incremental form (`PLANE RELATIV`, `G68.4`, `_ST` 1, `AROT`,
    /// `G158 P01…`), so that a loop repeating the block adds as often; 0 otherwise (always
    /// while no tilt or a direct mode is active).
    pub relative: u32,
    /// 0: room for a field of a later version (a state with anything else is refused).
    pub spare: u32,
    /// The seal: 0 in the all-zero initial state, else the checksum described above (the
    /// field keeps the name it had when it was reserved, so that the layout is unchanged).
    pub reserved: u32,
}

/// Mixed into the seal of every `cncrot_program` this version writes: a state of a version
/// with another meaning of the same bytes gets another constant, and is refused.
pub const CNCROT_PROGRAM_FORMAT: u32 = 0x5052_4736;

/// `cncrot_program.positioning`: the tilt command moves no axis (`STAY`, `G68.2` alone).
pub const CNCROT_POSITIONING_STAY: i32 = 0;
/// `cncrot_program.positioning`: the rotary axes turn to the plane (`TURN`, `G53.1`,
/// `G253`, `CYCLE800`).
pub const CNCROT_POSITIONING_TURN: i32 = 1;
/// `cncrot_program.positioning`: the rotary axes turn, the tool tip kept in place (`MOVE`,
/// `G53.6`).
pub const CNCROT_POSITIONING_MOVE: i32 = 2;

/// `cncrot_program.retract`: no retraction (no `MB`; `_FR` 0).
pub const CNCROT_RETRACT_NONE: i32 = 0;
/// `cncrot_program.retract`: as far as the travel allows along the tool axis (`MB MAX`;
/// `_FR` 4).
pub const CNCROT_RETRACT_TOOL_MAX: i32 = 1;
/// `cncrot_program.retract`: `retract_mm` along the tool axis (`MB n`; `_FR` 5 with
/// `_FR_I`).
pub const CNCROT_RETRACT_TOOL: i32 = 2;
/// `cncrot_program.retract`: along the machine's Z axis (`_FR` 1).
pub const CNCROT_RETRACT_MACHINE_Z: i32 = 3;
/// `cncrot_program.retract`: along the machine's Z axis, then in X and Y (`_FR` 2).
pub const CNCROT_RETRACT_MACHINE_Z_XY: i32 = 4;

/// `cncrot_program.feed`: the rotary axes turn at rapid (`FMAX`).
pub const CNCROT_FEED_RAPID: i32 = 0;
/// `cncrot_program.feed`: at `feed_mm_min` (`F n`).
pub const CNCROT_FEED_RATE: i32 = 1;
/// `cncrot_program.feed`: at the feed rate programmed before (`F AUTO`).
pub const CNCROT_FEED_AUTO: i32 = 2;

/// `cncrot_program.plane`: `G17`, X and Y (rotations in the plane about Z); the default.
pub const CNCROT_PLANE_XY: i32 = 0;
/// `cncrot_program.plane`: `G18`, Z and X (about Y).
pub const CNCROT_PLANE_ZX: i32 = 1;
/// `cncrot_program.plane`: `G19`, Y and Z (about X).
pub const CNCROT_PLANE_YZ: i32 = 2;

const PROGRAM_SIZE: usize = core::mem::size_of::<cncrot_program>();
/// The bytes the seal covers: everything before it.
const SEALED: usize = core::mem::offset_of!(cncrot_program, reserved);
// No padding (every byte is a field's, so every byte is covered), and the documented layout.
const _: () = assert!(SEALED == 212 && PROGRAM_SIZE == 216);

fn program_bytes(c: &cncrot_program) -> &[u8; PROGRAM_SIZE] {
    // SAFETY: a plain repr(C) struct of integers and doubles without padding (asserted
    // above): all of its bytes are initialised, and u8 has no alignment requirement.
    unsafe { &*(c as *const cncrot_program).cast::<[u8; PROGRAM_SIZE]>() }
}

fn seal_of(c: &cncrot_program) -> u32 {
    crc32(program_bytes(c).get(..SEALED).unwrap_or(&[])) ^ CNCROT_PROGRAM_FORMAT
}

#[inline(always)]
fn load(c: &cncrot_program) -> Result<Program, Error> {
    // A sealed state almost never has a zero seal: the byte scan only when it has.
    let initial = c.reserved == 0 && program_bytes(c).iter().all(|&b| b == 0);
    if !initial && c.reserved != seal_of(c) {
        return Err(Error::BadState);
    }
    // A sealed state was written by this library; reading it strictly all the same refuses
    // the one random state in 2^32 whose seal matches by chance.
    let dialect = match c.dialect {
        0 => None,
        d => Some(Dialect::from_code(d).map_err(|_| Error::BadState)?),
    };
    if c.options & !OPTIONS != 0 {
        return Err(Error::BadState);
    }
    let frame = match c.active {
        0 if c.rotation == [0.0; 9] && c.origin == [0.0; 3] && c.shift == [0.0; 3] => {
            Frame::IDENTITY
        }
        1 => {
            let r = core::array::from_fn(|i| core::array::from_fn(|j| c.rotation[3 * i + j]));
            Frame::with_translations(c.origin, r, [0.0; 3])
        }
        2 | 3 if c.rotation == [0.0; 9] => {
            Frame::with_translations(c.origin, crate::IDENTITY, [0.0; 3])
        }
        _ => return Err(Error::BadState),
    };
    let direct = match (c.active, u8::try_from(c.direct_given)) {
        (0 | 1, Ok(0)) => None,
        (2, Ok(given)) => Some((DirectAxes::Letters, given)),
        (3, Ok(given)) => Some((DirectAxes::Numbered, given)),
        _ => return Err(Error::BadState),
    };
    let direct = direct.map(|(by, given)| Direct { by, given });
    let axis = u8::try_from(c.reference_axis)
        .ok()
        .filter(|&k| usize::from(k) <= crate::kinematics::MAX_AXES)
        .ok_or(Error::BadState)?;
    let choice = match c.choice {
        CNCROT_CHOOSE_CLOSEST if axis == 0 => AxisChoice::Closest,
        CNCROT_CHOOSE_MINUS => AxisChoice::Minus(axis),
        CNCROT_CHOOSE_PLUS => AxisChoice::Plus(axis),
        CNCROT_CHOOSE_POSITIVE_TURN => AxisChoice::PositiveTurn(axis),
        CNCROT_CHOOSE_NEGATIVE_TURN => AxisChoice::NegativeTurn(axis),
        _ => return Err(Error::BadState),
    };
    let positioning = match c.positioning {
        CNCROT_POSITIONING_STAY => Positioning::Stay,
        // Also with nothing active: the axes turn to the untilted plane.
        CNCROT_POSITIONING_TURN => Positioning::Turn,
        CNCROT_POSITIONING_MOVE => Positioning::Move,
        _ => return Err(Error::BadState),
    };
    // The lengths are checked with the rest (`Program::check`).
    let retract = match c.retract {
        CNCROT_RETRACT_NONE => Retract::None,
        CNCROT_RETRACT_TOOL_MAX => Retract::ToolMax,
        CNCROT_RETRACT_TOOL => Retract::Tool,
        CNCROT_RETRACT_MACHINE_Z => Retract::MachineZ,
        CNCROT_RETRACT_MACHINE_Z_XY => Retract::MachineZThenXy,
        _ => return Err(Error::BadState),
    };
    let feed = match c.feed {
        CNCROT_FEED_RAPID => Feed::Rapid,
        CNCROT_FEED_RATE => Feed::Rate,
        CNCROT_FEED_AUTO => Feed::Auto,
        _ => return Err(Error::BadState),
    };
    let plane = match c.plane {
        CNCROT_PLANE_XY => Plane::Xy,
        CNCROT_PLANE_ZX => Plane::Zx,
        CNCROT_PLANE_YZ => Plane::Yz,
        _ => return Err(Error::BadState),
    };
    // Only with a tilt (`Program::check`).
    let table_rot = match c.table_rot {
        0 => false,
        1 => true,
        _ => return Err(Error::BadState),
    };
    // Only with a tilt (`Program::check`); the spare field empty.
    let relative = match (c.relative, c.spare) {
        (0, 0) => false,
        (1, 0) => true,
        _ => return Err(Error::BadState),
    };
    let p = Program {
        relative,
        retract,
        retract_mm: c.retract_mm,
        feed,
        feed_mm_min: c.feed_mm_min,
        frame,
        angles: c.angles,
        direct,
        dialect,
        euler: c.options & CNCROT_PROGRAM_SINUMERIK_EULER != 0,
        axis_angles: c.options & CNCROT_PROGRAM_HEIDENHAIN_AXIS_ANGLES != 0,
        shift: c.shift,
        choice,
        positioning,
        plane,
        table_rot,
    };
    p.check().map_err(|_| Error::BadState)?;
    Ok(p)
}

/// [`load`] of a caller's state, its copy in a frame of its own (not inlined: a function
/// that loads two states keeps only the results).
///
/// # Safety
/// `c` points to a readable `cncrot_program` (any alignment).
#[inline(never)]
unsafe fn load_at(c: *const cncrot_program) -> Result<Program, Error> {
    load(&c.read_unaligned())
}

#[inline(always)]
fn store(p: &Program, options: u32) -> cncrot_program {
    let active = match p.direct {
        None => i32::from(p.frame != Frame::IDENTITY),
        Some(Direct {
            by: DirectAxes::Letters,
            ..
        }) => 2,
        Some(_) => 3,
    };
    let (rotation, origin) = if active > 1 {
        ([0.0; 9], p.frame.translation.map(|x| x + 0.0))
    } else if active == 1 {
        let r = p.frame.rotation;
        (
            core::array::from_fn(|k| r[k / 3][k % 3] + 0.0),
            p.frame.translation.map(|x| x + 0.0),
        )
    } else {
        ([0.0; 9], [0.0; 3])
    };
    let (choice, reference_axis) = match p.choice {
        AxisChoice::Closest => (CNCROT_CHOOSE_CLOSEST, 0),
        AxisChoice::Minus(k) => (CNCROT_CHOOSE_MINUS, i32::from(k)),
        AxisChoice::Plus(k) => (CNCROT_CHOOSE_PLUS, i32::from(k)),
        AxisChoice::PositiveTurn(k) => (CNCROT_CHOOSE_POSITIVE_TURN, i32::from(k)),
        AxisChoice::NegativeTurn(k) => (CNCROT_CHOOSE_NEGATIVE_TURN, i32::from(k)),
    };
    let positioning = match p.positioning {
        Positioning::Stay => CNCROT_POSITIONING_STAY,
        Positioning::Turn => CNCROT_POSITIONING_TURN,
        Positioning::Move => CNCROT_POSITIONING_MOVE,
    };
    let retract = match p.retract {
        Retract::None => CNCROT_RETRACT_NONE,
        Retract::ToolMax => CNCROT_RETRACT_TOOL_MAX,
        Retract::Tool => CNCROT_RETRACT_TOOL,
        Retract::MachineZ => CNCROT_RETRACT_MACHINE_Z,
        Retract::MachineZThenXy => CNCROT_RETRACT_MACHINE_Z_XY,
    };
    let feed = match p.feed {
        Feed::Rapid => CNCROT_FEED_RAPID,
        Feed::Rate => CNCROT_FEED_RATE,
        Feed::Auto => CNCROT_FEED_AUTO,
    };
    let mut c = cncrot_program {
        rotation,
        origin,
        angles: p.angles.map(|x| x + 0.0),
        shift: p.shift.map(|x| x + 0.0),
        active,
        dialect: p.dialect.map_or(0, |d| d as i32),
        options,
        choice,
        reference_axis,
        positioning,
        direct_given: p.direct.map_or(0, |d| u32::from(d.given)),
        retract,
        retract_mm: p.retract_mm + 0.0,
        feed_mm_min: p.feed_mm_min + 0.0,
        feed,
        plane: match p.plane {
            Plane::Xy => CNCROT_PLANE_XY,
            Plane::Zx => CNCROT_PLANE_ZX,
            Plane::Yz => CNCROT_PLANE_YZ,
        },
        table_rot: u32::from(p.table_rot),
        relative: u32::from(p.relative),
        spare: 0,
        reserved: 0,
    };
    c.reserved = seal_of(&c);
    c
}

/// Writes the initial state of a program read on a machine with `options`
/// (`CNCROT_PROGRAM_*`, or 0: then it equals the all-zero state in meaning): nothing
/// active, sealed.
///
/// Returns 0, or with `*program` untouched `CNCROT_STATUS_NULL_POINTER` or
/// `CNCROT_STATUS_BAD_ARGUMENT` (an option bit this version does not know).
///
/// # Safety
/// `program` points to a writable `cncrot_program` (or NULL: error).
///
/// ```c
/// cncrot_program p;
/// cncrot_program_init(&p, CNCROT_PROGRAM_SINUMERIK_EULER);   // machine data 10600 = 2
/// cncrot_program_init(&p, CNCROT_PROGRAM_HEIDENHAIN_AXIS_ANGLES);   // MP7500 bit 1 = 0
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_init(program: *mut cncrot_program, options: u32) -> i32 {
    guard(|| {
        non_null(&[program.is_null()])?;
        if options & !OPTIONS != 0 {
            return Err(cncrot_status::BadArgument);
        }
        program.write_unaligned(store(&Program::default(), options));
        Ok(cncrot_status::Ok)
    })
}

/// Reads one block; on success the next state, else the error and its 1-based column.
///
/// # Safety
/// `program` readable, `line` (non-NULL) `len` readable bytes.
// Inlined, as `load` and `store`: the state (168 bytes) then goes from the caller's struct
// to the caller's struct without intermediate copies (they were a fifth of a short line).
#[inline(always)]
unsafe fn read(
    program: *mut cncrot_program,
    dialect: i32,
    line: *const c_char,
    len: usize,
    write: bool,
) -> Result<cncrot_status, (cncrot_status, usize, Option<&'static str>)> {
    // The caller's struct is read in place when aligned (as C aligns it), copied if not.
    let copy;
    let c = if program.is_aligned() {
        &*program
    } else {
        copy = program.read_unaligned();
        &copy
    };
    let p = load(c).map_err(|e| (e.into(), 0, None))?;
    let d = Dialect::from_code(dialect).map_err(|e| (e.into(), 0, None))?;
    // Beyond the longest block and its line end nothing is read.
    if len > d.max_line() + 2 {
        return Err((cncrot_status::LineTooLong, d.max_line() + 1, None));
    }
    let text = core::slice::from_raw_parts(line.cast::<u8>(), len);
    let (next, remark) = p
        .line(d, text)
        .map_err(|e| (e.error.into(), e.column, e.expected))?;
    Ok(match remark {
        Remark::Applied => {
            // Written here, once: a state carried out in the result took stack.
            if write {
                write_state(program, &next, c.options);
            }
            cncrot_status::Ok
        }
        // The state is not written at all: byte-identical.
        Remark::Passed => cncrot_status::Passed,
        Remark::NotFollowed => cncrot_status::NotFollowed,
    })
}

/// Writes `p` sealed to `program`. Not inlined: the 200-byte state it builds is not in the
/// reader's frame, under the block's reader (stack bound).
///
/// # Safety
/// `program` points to a writable `cncrot_program` (any alignment).
#[inline(never)]
unsafe fn write_state(program: *mut cncrot_program, p: &Program, options: u32) {
    program.write_unaligned(store(p, options));
}

/// Applies one block of a part program (`len` bytes, no NUL needed; a trailing line end is
/// ignored) in `dialect` (`CNCROT_DIALECT_*`) to `*program`, as that controller does: a tilt
/// replaces or adds to the active frame, a cancel (`ROT`, `CROT`, `CYCLE800()`,
/// `PLANE RESET`, `G69`, `G269`, `G158`) restores none. Any other block of a program in
/// that dialect is success with a remark and `*program` byte-identical:
/// `CNCROT_STATUS_PASSED` when it does not concern the frame (motion, tool call, M and S
/// words, program begin and end, labels and calls, parameter assignments, comments, blank
/// and block-number-only lines), `CNCROT_STATUS_NOT_FOLLOWED` when it changes the frame in
/// a way the library does not follow (work-offset or preset selections such as `G54`,
/// `G54.1 P`, `G154 P`, `G505`, `CYCL DEF 247`, `PRESET SELECT`; `G92`; writes to offset
/// tables and frame variables such as `G10 L2`, `#5221=`, `$P_UIFR[1]=`, `FN 17`; datum
/// shifts from tables such as `CYCL DEF 7.1 #5`, `TRANS DATUM TABLE`; mirroring, scaling
/// and rotations that need more than the state keeps such as `MIRROR`, `G51.1`,
/// `CYCL DEF 10`, Haas's `G68`; a tilt through the machine's axes such as `TOROT`, Fanuc's
/// `G68.3`).
/// Heidenhain's `CYCL DEF 19` (WORKING PLANE) is read with spatial angles, as `PLANE
/// SPATIAL`, or as the rotary axes' positions when the state was initialised with
/// `CNCROT_PROGRAM_HEIDENHAIN_AXIS_ANGLES`. A block that selects another working plane
/// (`G17`–`G19`, for `ROT RPL=` and `G68 X Y R`) is applied with the frame unchanged. A
/// program speaks one dialect.
///
/// Returns 0, `CNCROT_STATUS_PASSED`, `CNCROT_STATUS_NOT_FOLLOWED`, or a negative status
/// with `*program` byte-identical:
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_UNKNOWN_WORD` (a word the dialect does not
/// have there, or twice), `CNCROT_STATUS_NOT_A_NUMBER` (`R1`, `Q120`, `#100`, `30+5` where a
/// number must stand), `CNCROT_STATUS_MISSING_WORD`, `CNCROT_STATUS_PARSE` (a malformed
/// number, an unclosed comment or string, text where a number must stand),
/// `CNCROT_STATUS_LINE_TOO_LONG`, `CNCROT_STATUS_BAD_ARGUMENT` (unknown dialect, a dialect
/// other than the program's, a value outside its set such as `_ST`, a `P` or `Q` that is no
/// whole number, an invalid `_MIHEAD`), `CNCROT_STATUS_BAD_STATE` (a state this library did
/// not write), `CNCROT_STATUS_NOT_AVAILABLE` (a direct mode that is
/// additive, incremental or turns after its rotation: it needs the machine's kinematics;
/// an incremental command such as `PLANE RELATIV`, `G68.4`, `AROT` on an active direct
/// mode is `CNCROT_STATUS_NOT_FOLLOWED`), `CNCROT_STATUS_OUT_OF_RANGE` (a number of magnitude 1e100 or
/// more, or non-zero below 1e-100; a frame that overflows), and the statuses of the
/// command's mathematics: `CNCROT_STATUS_BAD_FLAG` (a CYCLE600 flag),
/// `CNCROT_STATUS_BAD_SEQUENCE` (an axis order in `_MODE`, `_BIN_IN`/`_BIN_OUT`, `P`, `Q`),
/// `CNCROT_STATUS_INCOMPLETE_SEQUENCE` (a CYCLE600 `_BIN_OUT` of fewer than three
/// rotations), `CNCROT_STATUS_NAME_TOO_LONG` (`_MIHEAD`), `CNCROT_STATUS_DEGENERATE`
/// (`PLANE VECTOR`, `G158` mode 3), `CNCROT_STATUS_COINCIDENT` and
/// `CNCROT_STATUS_COLLINEAR` (`PLANE POINTS`). `cncrot_program_column` names the column of
/// the offending character: the bad value itself where a value is refused.
///
/// # Safety
/// `program` points to a readable and writable `cncrot_program`, `line` to `len` readable
/// bytes (or NULL: error).
///
/// ```c
/// cncrot_program p;
/// memset(&p, 0, sizeof p);
/// const char *l = "N10 PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY";
/// int s = cncrot_program_line(&p, CNCROT_DIALECT_HEIDENHAIN, l, strlen(l));
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_line(
    program: *mut cncrot_program,
    dialect: i32,
    line: *const c_char,
    len: usize,
) -> i32 {
    guard(|| {
        non_null(&[program.is_null(), line.is_null()])?;
        read(program, dialect, line, len, true).map_err(|(s, _, _)| s)
    })
}

/// What `cncrot_program_line` would return for this block (the same statuses, listed there),
/// without changing anything, and in `*column` the 1-based byte column of the first
/// offending character (one past the end when a word is missing at the end; 0 on success and
/// for errors that are not in the text: a bad dialect or state). `*column` is written for
/// every status but `CNCROT_STATUS_NULL_POINTER`.
///
/// # Safety
/// `program` points to a readable `cncrot_program`, `line` to `len` readable bytes,
/// `column` to a writable `size_t` (or NULL: error; `*column` is written for every other
/// status).
///
/// ```c
/// size_t col;
/// cncrot_program_column(&p, CNCROT_DIALECT_SINUMERIK, "ROT X=R1", 8, &col);   // -20, col 7
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_column(
    program: *const cncrot_program,
    dialect: i32,
    line: *const c_char,
    len: usize,
    column: *mut usize,
) -> i32 {
    guard(|| {
        non_null(&[program.is_null(), line.is_null(), column.is_null()])?;
        // Never written: `program` is only read (`write` false).
        match read(program.cast_mut(), dialect, line, len, false) {
            Ok(status) => {
                column.write_unaligned(0);
                Ok(status)
            }
            Err((s, c, _)) => {
                column.write_unaligned(c);
                Err(s)
            }
        }
    })
}

/// The room `cncrot_program_expected` needs: the longest text it writes and its NUL.
pub const CNCROT_PROGRAM_EXPECTED_SIZE: usize = 96;

/// What `cncrot_program_line` would return for this block (the same statuses, listed there),
/// without changing anything, and in `expected` what the reader expected where it refused
/// the block, NUL-terminated: for `CNCROT_STATUS_MISSING_WORD` the word that is missing
/// (`SPC`, `Q`, `ROT`, `a number`, `'+' or '-'`), for a cycle parameter it refuses the
/// values that parameter takes (`_MIHEAD: empty, or …`); the empty text on success and
/// where the reader names nothing (the word not understood is the one at the column of
/// `cncrot_program_column`). `expected` is written for every status but those below.
///
/// Refused with nothing written: `CNCROT_STATUS_NULL_POINTER`; `CNCROT_STATUS_NO_ROOM` when
/// `size` is below `CNCROT_PROGRAM_EXPECTED_SIZE`.
///
/// # Safety
/// `program` points to a readable `cncrot_program`, `line` to `len` readable bytes,
/// `expected` to `size` writable bytes.
///
/// ```c
/// char what[CNCROT_PROGRAM_EXPECTED_SIZE];
/// cncrot_program_expected(&p, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL SPA+10 SPB+0", 26,
///                         what, sizeof what);   // -21, "SPC"
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_expected(
    program: *const cncrot_program,
    dialect: i32,
    line: *const c_char,
    len: usize,
    expected: *mut c_char,
    size: usize,
) -> i32 {
    guard(|| {
        non_null(&[program.is_null(), line.is_null(), expected.is_null()])?;
        if size < CNCROT_PROGRAM_EXPECTED_SIZE {
            return Err(cncrot_status::NoRoom);
        }
        // Never written: `program` is only read (`write` false).
        let (status, text) = match read(program.cast_mut(), dialect, line, len, false) {
            Ok(status) => (Ok(status), ""),
            Err((s, _, what)) => (Err(s), what.unwrap_or("")),
        };
        // Every text the readers name is shorter than the room (a test holds them to it);
        // cut, never overrun, if one were not.
        let n = text.len().min(CNCROT_PROGRAM_EXPECTED_SIZE - 1);
        let out = expected.cast::<u8>();
        for (k, &b) in text.as_bytes().iter().take(n).enumerate() {
            out.add(k).write(b);
        }
        out.add(n).write(0);
        status
    })
}

/// The rotary-axis positions the active tilt of `program` moves `machine` to, seen from the
/// current positions `current` (degrees): what `cncrot_machine_choose` gives under the
/// rule of the tilt's own choice words, kept in `program->choice` — `SEQ-` / `_DIR = -1`
/// `CNCROT_CHOOSE_MINUS`, `SEQ+` / `_DIR = +1` `CNCROT_CHOOSE_PLUS`, on the master axis (a
/// head's axis nearest the tool, else the axis nearest the machine base) — and without
/// them for a Fanuc tilt (`G53.1`, `G53.1 P0`) Fanuc's own rule, `CNCROT_CHOOSE_MASTER_FIRST`
/// on its first rotation axis (a mixed machine's table axis), else `CNCROT_CHOOSE_CLOSEST`,
/// the choice SINUMERIK makes for a frame and Heidenhain without `SEQ`: whole turns unwound
/// toward `current`, within the travel limits and on the Hirth grids. Heidenhain's `SEQ±`
/// gives the angles themselves in (-180, 180] (within the travel), not wound toward
/// `current`, and `CNCROT_STATUS_OUT_OF_TRAVEL` where the side it names lies beyond the
/// travel, as the TNC's "Entered angle not permitted". No tilt active: the positions of the identity frame. A direct mode
/// (`active` 2 or 3): the positions it states, mapped onto the machine's axes (by place, or
/// by letter: each axis takes the position of the letter its direction is nearest (of two
/// nearest one, the one more nearly along it; the other its next nearest), A for X,
/// B for Y, C for Z), as stated on an axis with travel limits, the turn nearest `current`
/// on a modulo axis. Axes the machine lacks are 0 in `axes` (and must be 0 in `current`).
///
/// Returns 0, `CNCROT_STATUS_FREE_AXIS` (a free axis kept at its current position),
/// `CNCROT_STATUS_SNAPPED` (a Hirth axis snapped to its grid), or with `axes` untouched:
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_STATE` (a program state this library did
/// not write), `CNCROT_STATUS_UNREACHABLE`, `CNCROT_STATUS_OUT_OF_TRAVEL`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_OUT_OF_RANGE` (a current position, a direct
/// position of magnitude `CNCROT_MACHINE_ANGLE_MAX_DEG` or more), `CNCROT_STATUS_BAD_ARGUMENT`
/// (a direct position for an axis the machine lacks), and the statuses of a description
/// that is not a machine (see `cncrot_machine`).
///
/// # Safety
/// `program` points to a readable `cncrot_program`, `machine` to a `cncrot_machine`,
/// `current` to 3 readable and `axes` to 3 writable doubles (or NULL: error).
///
/// ```c
/// double cur[3] = {0, 0, 0}, ax[3];
/// cncrot_program_axes(&p, &m, cur, ax);   // after PLANE SPATIAL SPA+0 SPB+30 SPC+0
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_axes(
    program: *const cncrot_program,
    machine: *const cncrot_machine,
    current: *const f64,
    axes: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            program.is_null(),
            machine.is_null(),
            current.is_null(),
            axes.is_null(),
        ])?;
        let p = load(&program.read_unaligned())?;
        let mut m = crate::kinematics::Machine::EMPTY;
        super::machine::load_into(machine, &mut m)?;
        let current = read_finite::<3>(current)?;
        let c = p.axes(&m, current)?;
        write::<3>(axes, c.axes)?;
        Ok(super::machine::choice_status(&c))
    })
}

/// The active frame of a program (4x4, row-major; the identity when none is active).
///
/// Returns 0, or with `frame` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_STATE` (a state this library did not write) or
/// `CNCROT_STATUS_NOT_AVAILABLE` (a direct mode is active, whose rotation follows from the
/// machine: `cncrot_program_frame_on`).
///
/// # Safety
/// `program` points to a readable `cncrot_program`, `frame` to 16 writable doubles (or NULL:
/// error).
///
/// ```c
/// double f[16];
/// cncrot_program_frame(&p, f);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_frame(
    program: *const cncrot_program,
    frame: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[program.is_null(), frame.is_null()])?;
        let p = load(&program.read_unaligned())?;
        if p.direct.is_some() {
            return Err(cncrot_status::NotAvailable);
        }
        write_frame(frame, &p.frame)?;
        Ok(cncrot_status::Ok)
    })
}

/// The active frame of a program on `machine` (4x4, row-major): the state's frame, or for a
/// direct mode (`PLANE AXIAL`, `CYCLE800` direct, `G158` mode 2) the rotation the machine's
/// kinematics gives with its rotary axes at the stated positions (the rotation of
/// `cncrot_machine_forward`; the axes mapped as in `cncrot_program_axes`) about the
/// block's origin.
///
/// Returns 0, or with `frame` untouched `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_STATE` (a state this library did not write),
/// `CNCROT_STATUS_BAD_ARGUMENT` (a direct position for an axis the machine lacks),
/// `CNCROT_STATUS_OUT_OF_RANGE` (a result that overflows), and the statuses of a
/// description that is not a machine (see `cncrot_machine`).
///
/// # Safety
/// `program` points to a readable `cncrot_program`, `machine` to a `cncrot_machine`,
/// `frame` to 16 writable doubles (or NULL: error).
///
/// ```c
/// double f[16];
/// cncrot_program_frame_on(&p, &m, f);   // after PLANE AXIAL B+30 C+45
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_frame_on(
    program: *const cncrot_program,
    machine: *const cncrot_machine,
    frame: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[program.is_null(), machine.is_null(), frame.is_null()])?;
        let p = load(&program.read_unaligned())?;
        let mut m = crate::kinematics::Machine::EMPTY;
        super::machine::load_into(machine, &mut m)?;
        write_frame(frame, &p.frame_on(&m)?)?;
        Ok(cncrot_status::Ok)
    })
}

/// Writes the block that programs `frame` (4x4, row-major) in `dialect` with the command
/// `form` (a NUL-terminated name, upper or lower case):
///
/// | dialect | forms |
/// |---|---|
/// | SINUMERIK | `"CYCLE800"` (`_MODE` 57), `"CYCLE800 <_MODE>"`, `"ROT"`, `"ROT EULER"` |
/// | Heidenhain | `"PLANE SPATIAL"`, `"PLANE EULER"`, `"PLANE VECTOR"`, `"PLANE POINTS"`, `"PLANE PROJECTED"` |
/// | Fanuc | `"G68.2"` |
/// | Syntec | `"G158"` (`P10157`), `"G158 P<p>"`, `"G68.2"` |
/// | TwinCAT | `"ROT"` |
/// | Haas | `"G268"` (`Q123`), `"G268 Q<q>"` |
///
/// The same dialect's `cncrot_program_line` reads the line back as the same frame (`"ROT
/// EULER"`: on a state in Euler mode, `cncrot_program_init` with
/// `CNCROT_PROGRAM_SINUMERIK_EULER`, as the control with machine data 10600 = 2). The
/// identity frame (nothing active) is written as the form's cancel: `CYCLE800()`, `ROT`,
/// `PLANE RESET STAY`, `G69`, `G158`, `G269` (TwinCAT, which has none of its own, writes
/// `ROT X0 Y0 Z0`). With
/// `decimals` < 0 the numbers are the shortest that read back exactly; with 0..17 they are
/// rounded to that many decimals (ties to even; `PLANE VECTOR`'s and `PLANE POINTS`' words
/// to at least 7), trailing zeros dropped. Angles are in each
/// dialect's read-back ranges; `CNCROT_STATUS_SINGULAR` says the middle angle was singular and
/// the free angle sits where that dialect's rule puts it. A rotation rounded where it was
/// written (within the rotation tolerance but more than 1e-12 from orthonormal: a matrix
/// printed to 4 decimals) is written as its nearest rotation. `out` receives the line and a
/// NUL (at most `CNCROT_PROGRAM_LINE_MAX` + 1 bytes).
///
/// Returns 0 or `CNCROT_STATUS_SINGULAR`, or a negative status with `out` untouched:
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_HAS_ORIGIN` (a
/// frame with an origin for a form without origin words — every `PLANE` form, `ROT` —: the
/// datum goes in the dialect's own command), `CNCROT_STATUS_BAD_ARGUMENT` (unknown dialect
/// or form, a form name of 64 bytes or more, `decimals` > 17, an incremental or mode-0
/// `G158 P`), `CNCROT_STATUS_BAD_SEQUENCE` (an axis order in `CYCLE800 <_MODE>`,
/// `G158 P<p>`, `G268 Q<q>` that is none, `"G268 Q0"`), `CNCROT_STATUS_INCOMPLETE_SEQUENCE`
/// (an axis-by-axis order of fewer than three rotations, `"CYCLE800 7"`: it cannot express
/// every frame), `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_NOT_AVAILABLE` (direct
/// modes), `CNCROT_STATUS_OUT_OF_RANGE` (a frame the form cannot express, such as a
/// projection at or near its singularity whose words would not read back within
/// `CNCROT_READ_BACK_TOLERANCE`; numbers of magnitude 1e100 or more, or non-zero below
/// 1e-100 with `decimals` < 0; a line longer than the dialect reads, whatever `cap`),
/// `CNCROT_STATUS_NO_ROOM` (`cap` too small for a line the dialect reads).
///
/// # Safety
/// `form` is a NUL-terminated string (at most 64 bytes are read: a name of 64 bytes or more is refused), `frame` points to 16
/// readable doubles, `out` to `cap` writable bytes (or NULL: error).
///
/// ```c
/// char line[CNCROT_PROGRAM_LINE_MAX + 1];
/// cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", f, 4, line, sizeof line);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_write(
    dialect: i32,
    form: *const c_char,
    frame: *const f64,
    decimals: i32,
    out: *mut c_char,
    cap: usize,
) -> i32 {
    guard(|| {
        non_null(&[form.is_null(), frame.is_null(), out.is_null()])?;
        let d = Dialect::from_code(dialect)?;
        let mut name = [0u8; FORM_MAX];
        let name = read_form(form, &mut name)?;
        let mut f = read_frame(frame)?;
        // A rotation rounded where it was written (4 decimals): its words are those of the
        // nearest rotation (its own would not read back to it).
        f.rotation = crate::rotation::exact_or_nearest(&f.rotation);
        let mut buf = [0u8; CNCROT_PROGRAM_LINE_MAX];
        let (len, singular) = program::write_line(d, name, &f, decimals, &mut buf)?;
        put_text(buf.get(..len).ok_or(cncrot_status::Internal)?, out, cap)?;
        Ok(super::status_of(singular))
    })
}

/// A NUL-terminated form name into `name` (at most `FORM_MAX` bytes are read).
///
/// # Safety
/// `form` is NUL-terminated or has at least `FORM_MAX` readable bytes.
#[inline(always)]
unsafe fn read_form(
    form: *const c_char,
    name: &mut [u8; FORM_MAX],
) -> Result<&[u8], cncrot_status> {
    let mut n = 0;
    loop {
        let slot = name.get_mut(n).ok_or(cncrot_status::BadArgument)?;
        let b = form.add(n).cast::<u8>().read();
        if b == 0 {
            break;
        }
        *slot = b;
        n += 1;
    }
    name.get(..n).ok_or(cncrot_status::BadArgument)
}

/// The caller's NUL-terminated form name in place (at most `FORM_MAX` bytes are read): for
/// a call that reads it whole before it writes anything.
///
/// # Safety
/// `form` is NUL-terminated or has at least `FORM_MAX` readable bytes, and nothing writes
/// to them while the result is used.
unsafe fn form_of<'a>(form: *const c_char) -> Result<&'a [u8], cncrot_status> {
    let mut n = 0;
    while form.add(n).cast::<u8>().read() != 0 {
        n += 1;
        if n == FORM_MAX {
            return Err(cncrot_status::BadArgument);
        }
    }
    Ok(core::slice::from_raw_parts(form.cast::<u8>(), n))
}

/// `text` and a NUL into `out`, or `NO_ROOM` with `out` untouched.
///
/// # Safety
/// `out` points to `cap` writable bytes.
#[inline(always)]
unsafe fn put_text(text: &[u8], out: *mut c_char, cap: usize) -> Result<(), cncrot_status> {
    let len = text.len();
    if cap <= len {
        return Err(cncrot_status::NoRoom);
    }
    let dst = core::slice::from_raw_parts_mut(out.cast::<u8>(), len + 1);
    let (body, nul) = dst.split_at_mut(len);
    body.copy_from_slice(text);
    if let Some(z) = nul.first_mut() {
        *z = 0;
    }
    Ok(())
}

/// The longest text `cncrot_program_write_change` writes, without its NUL.
pub const CNCROT_PROGRAM_CHANGE_MAX: usize = 2048;
const _: () = assert!(CNCROT_PROGRAM_CHANGE_MAX == program::MAX_CHANGE);

/// Writes the blocks that take a program in `dialect` from the state `before` to the state
/// `after` (states `cncrot_program_line` wrote, read in any dialect: a translator passes
/// the state before and after each source block), with the tilt command `form` (the names
/// of `cncrot_program_write`), one block per line separated by `\n`, and a NUL; an empty
/// text when nothing changes in the target dialect. No writer says a working plane: a
/// block that only selects one (`G18`, perhaps with a move) writes nothing, and a
/// translator keeps it as it stands.
///
/// - A changed datum shift is written with the dialect's own command: Heidenhain's cycle 7
///   (`CYCL DEF 7.0 DATUM SHIFT`, `CYCL DEF 7.1 X…`, `7.2 Y…`, `7.3 Z…`), Fanuc, Haas and
///   Syntec `G52 X… Y… Z…` (an active tilt cancelled first: a shift is programmed untilted),
///   TwinCAT `G58 X… Y… Z…` (its programmable zero offset shift), SINUMERIK `TRANS X=… Y=…
///   Z=…` (`TRANS` for none) when no rotation is active.
/// - A form without origin words (every `PLANE`, `ROT`) tilts about the datum: Heidenhain
///   and TwinCAT write the tilt's origin as the datum shift; SINUMERIK `ROT`, whose one frame
///   holds both, as `TRANS X=… Y=… Z=…` (which replaces the frame) and the rotation added
///   about it, `AROT`.
/// - A changed tilt, or the same tilt with other choice words, is written as
///   `cncrot_program_write` writes it, with the choice words the block has: Heidenhain
///   `SEQ-`/`SEQ+`, CYCLE800 `_DIR` -1/+1 where it swivels (-1 also for no choice: a swivel
///   always names one); Fanuc, Syntec, Haas and TwinCAT blocks have none. Nothing active
///   is written as the form's cancel; nothing active with the axes turning to the untilted plane
///   (`positioning` turn or move) as the dialect says that turn (`PLANE RESET TURN FMAX`, a
///   `G68.2` of zeros and `G53.1`, a `CYCLE800` of zero angles), or its cancel where it
///   cannot.
/// - How the machine moves to the plane (`positioning`) goes where the dialect says it:
///   Heidenhain `STAY`, `TURN FMAX`, `MOVE FMAX` in the `PLANE`; Fanuc-style `G53.1` /
///   `G53.6` and Haas `G253` as a block after the tilt, or alone when only the way of moving
///   changed; CYCLE800's `_DIR` 0 where the axes stay (the frame alone), ±1 where they
///   turn. `ROT`, TwinCAT and `G158` say nothing.
/// - A tilt added to the one before (`relative` 1 in `after`: `PLANE RELATIV`, `G68.4`, …)
///   is written as the target's increment on it (`before⁻¹·after`): `PLANE RELATIV`, one
///   angle per block, `G68.4`, `CYCLE800` with `_ST` 1, `AROT`, `G158 P01…`, so that a loop
///   repeating the source block adds as often. Written whole where the target has no such
///   form (Haas, TwinCAT), for an increment with an origin the form has no words for, or
///   with the datum shift changed.
///
/// Returns 0 or `CNCROT_STATUS_SINGULAR` (as `cncrot_program_write`), or a negative status
/// with `out` untouched: `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_STATE` (a state
/// this library did not write), `CNCROT_STATUS_BAD_ARGUMENT` (unknown dialect or form, a
/// form name longer than 64 bytes, `decimals` > 17, an incremental or mode-0 `G158 P`),
/// `CNCROT_STATUS_BAD_SEQUENCE` and `CNCROT_STATUS_INCOMPLETE_SEQUENCE` (a form's axis order,
/// as `cncrot_program_write`),
/// `CNCROT_STATUS_NOT_AVAILABLE` (a direct mode; a choice of an axis other than the master
/// axis, which no block names), `CNCROT_STATUS_OUT_OF_RANGE` (a frame the form cannot
/// express, numbers the writer cannot write, a block longer than the dialect reads),
/// `CNCROT_STATUS_NO_ROOM` (`cap` too small for the text).
///
/// # Safety
/// `before` and `after` point to readable `cncrot_program`s, `form` is a NUL-terminated
/// string (at most 64 bytes are read), `out` points to `cap` writable bytes (or NULL: error).
///
/// ```c
/// char text[CNCROT_PROGRAM_CHANGE_MAX + 1];
/// cncrot_program_write_change(&before, &after, CNCROT_DIALECT_HEIDENHAIN, "PLANE SPATIAL",
///                             4, text, sizeof text);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_write_change(
    before: *const cncrot_program,
    after: *const cncrot_program,
    dialect: i32,
    form: *const c_char,
    decimals: i32,
    out: *mut c_char,
    cap: usize,
) -> i32 {
    guard(|| {
        non_null(&[
            before.is_null(),
            after.is_null(),
            form.is_null(),
            out.is_null(),
        ])?;
        let p0 = load_at(before)?;
        let p1 = load_at(after)?;
        let d = Dialect::from_code(dialect)?;
        // The form is read whole before `out` is touched (they may be the same memory).
        let spec = d.parse_form(form_of(form)?)?;
        write_change_into(d, &spec, &p0, &p1, None, decimals, out, cap)
    })
}

/// The change from `from` to `to` measured, then written straight into `out` (no text
/// buffer on the stack): a refusal leaves it untouched.
///
/// # Safety
/// `out` points to `cap` writable bytes.
// Inlined: a frame of its own took 32 bytes more stack from `cncrot_program_write_change`.
#[inline(always)]
#[allow(clippy::too_many_arguments)] // The C function's, and the block's increment.
unsafe fn write_change_into(
    d: Dialect,
    spec: &FormSpec,
    from: &Program,
    to: &Program,
    step: Option<&Frame>,
    decimals: i32,
    out: *mut c_char,
    cap: usize,
) -> Result<cncrot_status, cncrot_status> {
    let c = program::Change {
        before: from,
        after: to,
        step,
    };
    let (len, singular) = program::change_length_with(d, spec, &c, decimals)?;
    if cap <= len {
        return Err(cncrot_status::NoRoom);
    }
    let dst = core::slice::from_raw_parts_mut(out.cast::<u8>(), len + 1);
    let (body, nul) = dst.split_at_mut(len);
    let (written, again) = program::write_change_with(d, spec, &c, decimals, body)?;
    if (written, again) != (len, singular) {
        return Err(cncrot_status::Internal);
    }
    if let Some(z) = nul.first_mut() {
        *z = 0;
    }
    Ok(super::status_of(singular))
}

/// What a translator writes for one block `line` (`len` bytes) of the source program, which
/// `cncrot_program_line` read from `before` to `after` with status 0: the text of
/// `cncrot_program_write_change` from `before` to `after`, and also what the block restates
/// although the state does not change (the control may have something active that the
/// state does not know of): a cancel while no tilt is active (the `PLANE RESET STAY`,
/// `G69` or `CYCLE800()` a program opens with) is written as the target's cancel, a datum
/// shift set to the value it already has (`G52 X0 Y0`, `TRANS DATUM RESET`, cycle 7 with
/// zeros) as the target's datum shift. Found by reading the block again on a state with
/// another tilt or shift. A block that only names a cycle (`CYCL DEF 7.0`) or a tilt
/// repeated unchanged that stays restates nothing (an empty text); one that turns the axes
/// (the same `CYCLE800` or `G53.1` again, a tool change's swivel) is written as that turn
/// again, wherever the program moved the axes since. A block that adds to the tilt is
/// written as the target's increment with the block's own numbers (read again on a state
/// with nothing active: `PLANE RELATIV SPC+15` is `G68.4 … I15. J0. K0.` in the shortest
/// exact numbers, where the two states alone give `I14.999999999999996`). A block that
/// keeps the tilt and states no way of moving (a datum shift under a plane that turned the
/// axes) is written as moving nothing: the tilt written again around the shift stays
/// (`G68.2` without `G53.1`, `CYCLE800` with `_FR` 0 and `_DIR` 0).
///
/// Returns as `cncrot_program_write_change`, and `CNCROT_STATUS_NULL_POINTER` for a NULL
/// `line`, `CNCROT_STATUS_LINE_TOO_LONG` for a `len` longer than the dialect of `after`
/// reads (with its line end).
///
/// # Safety
/// As `cncrot_program_write_change`; `line` points to `len` readable bytes.
///
/// ```c
/// struct cncrot_program before = p;
/// if (cncrot_program_line(&p, CNCROT_DIALECT_HEIDENHAIN, l, strlen(l)) == 0)
///     cncrot_program_write_block(&before, &p, l, strlen(l), CNCROT_DIALECT_FANUC, "G68.2", 4,
///                                text, sizeof text);   // "G69" for "PLANE RESET STAY"
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_write_block(
    before: *const cncrot_program,
    after: *const cncrot_program,
    line: *const c_char,
    len: usize,
    dialect: i32,
    form: *const c_char,
    decimals: i32,
    out: *mut c_char,
    cap: usize,
) -> i32 {
    guard(|| {
        non_null(&[
            before.is_null(),
            after.is_null(),
            line.is_null(),
            form.is_null(),
            out.is_null(),
        ])?;
        let mut p0 = load_at(before)?;
        let mut p1 = load_at(after)?;
        let d = Dialect::from_code(dialect)?;
        if p1.dialect.is_some_and(|source| len > source.max_line() + 2) {
            return Err(cncrot_status::LineTooLong);
        }
        // The block without its line end, no longer than its dialect reads (as
        // `cncrot_program_line` measures it).
        let text = match p1.dialect {
            Some(source) => {
                let raw = core::slice::from_raw_parts(line.cast::<u8>(), len);
                crate::dialects::program::block_of(source, raw)
                    .map_err(|e| cncrot_status::from(e.error))?
            }
            None => &[],
        };
        // The form is read whole before `out` is touched (they may be the same memory).
        let spec = d.parse_form(form_of(form)?)?;
        let step = program::block_states(&mut p0, &mut p1, text);
        write_change_into(d, &spec, &p0, &p1, step.as_ref(), decimals, out, cap)
    })
}

/// The words of block `line` (`len` bytes) of a `dialect` program that are not the
/// frame's, as they stand: what a translator keeps beside the text of
/// `cncrot_program_write_block` for the block (the motion, feed, compensation and mode
/// words an ISO-style post writes on the block of a tilt or a cancel, and the block
/// number). Without them a translation drops a retract (`G91 G28 Z0.` of
/// `G91 G28 Z0. G69`) or a feed (`N40 G1 F300.` of `N40 G1 G68.2 … F300.`). Also for the
/// first block of two that `cncrot_program_joins` writes as one. An empty text where
/// nothing but the block number and comments is left, and for SINUMERIK and TwinCAT, whose
/// readers refuse other words beside a frame command; a block without a frame command is
/// left whole (up to a NUL byte, which ends it). Heidenhain's rest is the M functions of the
/// turn to the plane (`M3` of `L B+Q121 C+Q122 R0 FMAX M3`; not `M126`/`M127`, the rotary
/// axes' way, a machine parameter elsewhere) or of a block of M functions alone, else empty.
/// `out` receives the text NUL-terminated.
///
/// No allocation, no panic, time linear in `len`.
///
/// Returns 0, or with `out` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_BAD_ARGUMENT` (an unknown `dialect`), `CNCROT_STATUS_LINE_TOO_LONG` (a
/// `len` longer than the dialect reads, with its line end), `CNCROT_STATUS_NO_ROOM` (`cap`
/// not above the text's length; `len + 1` always suffices).
///
/// # Safety
/// `line` points to `len` readable bytes, `out` to `cap` writable ones (they may overlap).
///
/// ```c
/// char keep[260];
/// cncrot_program_rest(CNCROT_DIALECT_FANUC, "G91 G28 Z0. G69", 15, keep, sizeof keep);
/// // keep: "G91 G28 Z0.", then the target's cancel
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_rest(
    dialect: i32,
    line: *const c_char,
    len: usize,
    out: *mut c_char,
    cap: usize,
) -> i32 {
    guard(|| {
        non_null(&[line.is_null(), out.is_null()])?;
        let d = Dialect::from_code(dialect)?;
        // `program::rest` refuses a line longer than the dialect reads.
        let text = core::slice::from_raw_parts(line.cast::<u8>(), len);
        // Into a buffer of its own: `out` is written whole or not at all, and may be `line`.
        let mut buf = [0u8; REST_MAX];
        let n = program::rest(d, text, &mut buf)?;
        let Some(body) = buf.get(..n) else {
            return Err(cncrot_status::Internal);
        };
        if cap <= n {
            return Err(cncrot_status::NoRoom);
        }
        let dst = core::slice::from_raw_parts_mut(out.cast::<u8>(), n + 1);
        let (head, nul) = dst.split_at_mut(n);
        head.copy_from_slice(body);
        if let Some(z) = nul.first_mut() {
            *z = 0;
        }
        Ok(cncrot_status::Ok)
    })
}

/// The longest block any dialect reads, with its line end: what a block's rest can hold.
const REST_MAX: usize = 514;
const _: () = {
    let mut k = 0;
    while k < Dialect::ALL.len() {
        assert!(Dialect::ALL[k].max_line() + 2 <= REST_MAX);
        k += 1;
    }
};

/// Whether a translator writes two blocks read one after the other — the first from
/// `before` to `after`, the next from `after` to `next`, each read by `cncrot_program_line`
/// with status 0 — as one change: `cncrot_program_write_block` from `before` to `next` with
/// the second block's text, nothing for the first. They are one command spread over lines:
/// the lines of one datum shift (Heidenhain's `CYCL DEF 7.1 X…`, `7.2 Y…`, `7.3 Z…`, each
/// changing the shift alone or nothing; a first line that changes nothing joins only while a
/// tilt is active, since with none it may be a cancel the program restates), or a tilt and the block
/// that turns the axes to it (`G68.2` then `G53.1`, `PLANE … STAY` then `L A+Q120 … FMAX`,
/// `G268` then `G253`: the second changes only how the machine moves, the first changed
/// something without turning). Within one dialect a translator keeps the blocks as they
/// stand and needs no join.
///
/// Writes 1 (join) or 0 to `*joins` and returns 0; or a negative status with `*joins`
/// untouched: `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_STATE` (a state this library
/// did not write).
///
/// # Safety
/// `before`, `after` and `next` point to readable `cncrot_program`s, `joins` to a writable
/// `int32_t`.
///
/// ```c
/// int32_t join = 0;
/// cncrot_program_joins(&before, &after, &next, &join);  // CYCL DEF 7.1 X+10, 7.2 Y+20: 1
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_program_joins(
    before: *const cncrot_program,
    after: *const cncrot_program,
    next: *const cncrot_program,
    joins: *mut i32,
) -> i32 {
    guard(|| {
        non_null(&[
            before.is_null(),
            after.is_null(),
            next.is_null(),
            joins.is_null(),
        ])?;
        let p0 = load_at(before)?;
        let p1 = load_at(after)?;
        let p2 = load_at(next)?;
        *joins = i32::from(program::joins(&p0, &p1, &p2));
        Ok(cncrot_status::Ok)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dialect_constants_name_the_dialects() {
        let c = [
            (CNCROT_DIALECT_SINUMERIK, Dialect::Sinumerik),
            (CNCROT_DIALECT_HEIDENHAIN, Dialect::Heidenhain),
            (CNCROT_DIALECT_FANUC, Dialect::Fanuc),
            (CNCROT_DIALECT_SYNTEC, Dialect::Syntec),
            (CNCROT_DIALECT_TWINCAT, Dialect::Twincat),
            (CNCROT_DIALECT_HAAS, Dialect::Haas),
        ];
        assert_eq!(c.len(), Dialect::ALL.len());
        for (code, d) in c {
            assert_eq!(Dialect::from_code(code), Ok(d));
        }
        let longest = Dialect::ALL.iter().map(|d| d.max_line()).max();
        assert_eq!(longest, Some(CNCROT_PROGRAM_LINE_MAX));
    }

    /// `table_rot` read strictly even under a matching seal: 0 or 1, and 1 only with a
    /// Heidenhain tilt (the word is Heidenhain's, and only a tilt has a table to turn).
    #[test]
    fn table_rot_is_read_strictly() {
        let tilt = Program::default()
            .line(
                Dialect::Heidenhain,
                b"PLANE SPATIAL SPA+0 SPB+0 SPC+90 STAY TABLE ROT",
            )
            .unwrap()
            .0;
        let c = store(&tilt, 0);
        assert_eq!((c.table_rot, load(&c)), (1, Ok(tilt)));
        let resealed = |mut c: cncrot_program| {
            c.reserved = seal_of(&c);
            load(&c)
        };
        assert_eq!(
            resealed(cncrot_program { table_rot: 2, ..c }),
            Err(Error::BadState)
        );
        let fanuc = Program::default()
            .line(Dialect::Fanuc, b"G68.2 I0 J0 K90")
            .unwrap()
            .0;
        let f = store(&fanuc, 0);
        assert_eq!(
            resealed(cncrot_program { table_rot: 1, ..f }),
            Err(Error::BadState)
        );
        let off = tilt
            .line(Dialect::Heidenhain, b"PLANE RESET STAY")
            .unwrap()
            .0;
        let o = store(&off, 0);
        assert_eq!(o.table_rot, 0);
        assert_eq!(
            resealed(cncrot_program { table_rot: 1, ..o }),
            Err(Error::BadState)
        );
    }

    /// `relative` read strictly even under a matching seal: 0 or 1, and 1 only with a tilt
    /// (a direct mode's positions or the untilted plane are not added to); `spare` 0.
    #[test]
    fn relative_is_read_strictly() {
        let read = |lines: &[&str]| {
            lines.iter().fold(Program::default(), |p, l| {
                p.line(Dialect::Heidenhain, l.as_bytes()).unwrap().0
            })
        };
        let added = read(&[
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
            "PLANE RELATIV SPA+5 STAY",
        ]);
        let c = store(&added, 0);
        assert_eq!((c.relative, c.spare, load(&c)), (1, 0, Ok(added)));
        let resealed = |mut c: cncrot_program| {
            c.reserved = seal_of(&c);
            load(&c)
        };
        for bad in [
            cncrot_program { relative: 2, ..c },
            cncrot_program { spare: 1, ..c },
        ] {
            assert_eq!(resealed(bad), Err(Error::BadState));
        }
        // Back to the untilted plane by increments: nothing active is added to.
        let back = read(&["PLANE RELATIV SPB+90 STAY", "PLANE RELATIV SPB-90 STAY"]);
        assert_eq!((back.frame, back.relative), (Frame::IDENTITY, false));
        let o = store(&back, 0);
        assert_eq!(
            resealed(cncrot_program { relative: 1, ..o }),
            Err(Error::BadState)
        );
        let axial = read(&["PLANE AXIAL B+30 STAY"]);
        let a = store(&axial, 0);
        assert_eq!(
            resealed(cncrot_program { relative: 1, ..a }),
            Err(Error::BadState)
        );
    }

    /// Every state the library stores loads back as itself; zero is nothing active.
    #[test]
    fn states_round_trip_and_strangers_are_refused() {
        assert_eq!(load(&cncrot_program::default()), Ok(Program::default()));
        let p = Program::default()
            .line(Dialect::Twincat, b"ROT Z30")
            .unwrap()
            .0
            .line(Dialect::Twincat, b"AROT X10")
            .unwrap()
            .0;
        let c = store(&p, 0);
        assert_eq!(load(&c), Ok(p));
        let mut bad = c;
        bad.angles[0] = 11.0;
        assert_eq!(load(&bad), Err(Error::BadState));
        let mut bad = c;
        bad.rotation[0] = 2.0;
        assert_eq!(load(&bad), Err(Error::BadState));
        let mut bad = c;
        bad.dialect = 7;
        assert_eq!(load(&bad), Err(Error::BadState));
        let mut bad = cncrot_program::default();
        bad.origin[1] = 1.0;
        assert_eq!(load(&bad), Err(Error::BadState));
        let bad = cncrot_program {
            options: 2,
            ..Default::default()
        };
        assert_eq!(load(&bad), Err(Error::BadState));
        let mut bad = c;
        bad.origin[2] = f64::NAN;
        assert_eq!(load(&bad), Err(Error::BadState));
        // A cancelled program is all zero again but for its dialect and seal.
        let off = p.line(Dialect::Twincat, b"ROT").unwrap().0;
        let c = store(&off, 0);
        assert_eq!(
            c,
            cncrot_program {
                dialect: CNCROT_DIALECT_TWINCAT,
                reserved: c.reserved,
                ..Default::default()
            }
        );
        // Options set by hand on the zero state: not a state the library wrote.
        let hand = cncrot_program {
            options: CNCROT_PROGRAM_SINUMERIK_EULER,
            ..Default::default()
        };
        assert_eq!(load(&hand), Err(Error::BadState));
    }

    /// The seal is what the header documents: the CRC-32 of bytes 0..212 exclusive-or
    /// `CNCROT_PROGRAM_FORMAT`; a state sealed without the format (another version's) is
    /// refused.
    #[test]
    fn the_seal_is_the_documented_one() {
        let p = Program::default()
            .line(Dialect::Fanuc, b"G68.2 X10 I0 J30 K0")
            .unwrap()
            .0;
        let c = store(&p, 0);
        let bytes = program_bytes(&c);
        assert_eq!(c.reserved, crc32(&bytes[..212]) ^ 0x5052_4736);
        let mut other = c;
        other.reserved = crc32(&bytes[..212]);
        assert_eq!(load(&other), Err(Error::BadState));
    }

    /// Every single-bit flip of the zero state and of states the library wrote is refused
    /// (the issue's case: `origin[0]` of `G68.2 X10 I0 J30 K0` turned from 10 into 14).
    #[test]
    fn every_single_bit_flip_is_refused() {
        let fanuc = Program::default()
            .line(Dialect::Fanuc, b"G68.2 X10 I0 J30 K0")
            .unwrap()
            .0;
        let twincat = Program::default()
            .line(Dialect::Twincat, b"ROT X10 Y-20 Z30")
            .unwrap()
            .0;
        let off = fanuc.line(Dialect::Fanuc, b"G69").unwrap().0;
        let states = [
            cncrot_program::default(),
            store(&Program::default(), 0),
            store(&Program::default(), CNCROT_PROGRAM_SINUMERIK_EULER),
            store(&fanuc, 0),
            store(&twincat, 0),
            store(&off, 0),
        ];
        for c in states {
            assert!(load(&c).is_ok());
            for bit in 0..8 * PROGRAM_SIZE {
                let mut bytes = *program_bytes(&c);
                bytes[bit / 8] ^= 1 << (bit % 8);
                // SAFETY: every bit pattern is a valid cncrot_program (integers, doubles).
                let flipped: cncrot_program = unsafe { core::mem::transmute(bytes) };
                assert_eq!(load(&flipped), Err(Error::BadState), "bit {bit} of {c:?}");
            }
        }
        let mut edited = store(&fanuc, 0);
        edited.origin[0] = 14.0;
        assert_eq!(load(&edited), Err(Error::BadState));
    }
}
