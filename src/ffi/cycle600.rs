//! Exports of CYCLE600 and the HEAD_DEF table. The structs are plain data that C owns; each
//! is validated when read (a state restored from storage may be corrupt).

use super::{cncrot_status, guard, non_null};
use crate::dialects::cycle600::{self, Call, Results, State};
use crate::dialects::head_def::{Head, HeadTable, CAPACITY, NAME_MAX};
use crate::{Convention, Error, Frame};
use core::ffi::c_char;

/// Size of a name field, including its terminating NUL: names have at most 31 bytes.
pub const CNCROT_NAME_SIZE: usize = 32;
/// How many accessories a `cncrot_head_table` holds.
pub const CNCROT_HEAD_TABLE_CAPACITY: usize = 16;

/// CYCLE600's state, the controller's GUD block `MGUD_CYC600`: plain data, owned by the
/// caller, that can be stored as bytes and restored after a restart. A zeroed struct is the
/// valid initial state (no rotation yet). Its first six fields are the paper's results.
#[allow(non_camel_case_types)]
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct cncrot_cycle600_gud {
    /// `_CYC600_1`: the accessory's name (`_MIHEAD`), NUL-terminated.
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
}

/// One technological accessory of the HEAD_DEF cycle.
#[allow(non_camel_case_types)]
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct cncrot_head {
    /// `_HEAD_NAME`, NUL-terminated.
    pub name: [c_char; CNCROT_NAME_SIZE],
    /// `_HEAD_ALLOWED` (0 or 1).
    pub allowed: i32,
    /// Zero.
    pub reserved: i32,
    /// `_DELTA_L1`, `_DELTA_L2`, `_DELTA_H1`.
    pub delta: [f64; 3],
    /// `_OFFS_L1_X`, `_OFFS_L1_Y`, `_OFFS_L2_X`, `_OFFS_L2_Y`, `_OFFS_H1_X`, `_OFFS_H1_Z`.
    pub offsets: [f64; 6],
}

/// A caller-owned, fixed-capacity table of accessories, filled by
/// `cncrot_head_table_parse`. A zeroed table is empty.
#[allow(non_camel_case_types)]
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct cncrot_head_table {
    /// How many entries of `heads` are used (0..16).
    pub count: i32,
    /// Zero.
    pub reserved: i32,
    /// The accessories.
    pub heads: [cncrot_head; CNCROT_HEAD_TABLE_CAPACITY],
}

/// The bytes of a NUL-terminated name within its field, or `Err(fail)` without a NUL.
fn field_name(
    field: &[c_char; CNCROT_NAME_SIZE],
    fail: Error,
) -> Result<([u8; NAME_MAX], usize), Error> {
    let len = field.iter().position(|&c| c == 0).ok_or(fail)?;
    let mut name = [0u8; NAME_MAX];
    for (n, &c) in name.iter_mut().zip(&field[..len]) {
        *n = c as u8;
    }
    Ok((name, len))
}

fn to_field(name: &[u8]) -> [c_char; CNCROT_NAME_SIZE] {
    let mut field = [0 as c_char; CNCROT_NAME_SIZE];
    for (f, &b) in field.iter_mut().zip(name) {
        *f = b as c_char;
    }
    field
}

fn bit(v: i32) -> Result<bool, Error> {
    match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(Error::BadArgument),
    }
}

fn table_from_c(t: &cncrot_head_table) -> Result<HeadTable, Error> {
    let count = usize::try_from(t.count).map_err(|_| Error::BadArgument)?;
    if count > CAPACITY {
        return Err(Error::BadArgument);
    }
    let mut table = HeadTable {
        count,
        ..HeadTable::default()
    };
    for (h, c) in table.heads.iter_mut().zip(&t.heads).take(count) {
        let (name, len) = field_name(&c.name, Error::BadArgument)?;
        if !c.delta.iter().chain(&c.offsets).all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        *h = Head {
            name,
            len: len as u8,
            allowed: bit(c.allowed)?,
            delta: c.delta,
            offsets: c.offsets,
        };
    }
    Ok(table)
}

fn table_to_c(t: &HeadTable) -> cncrot_head_table {
    let empty = cncrot_head {
        name: [0; CNCROT_NAME_SIZE],
        allowed: 0,
        reserved: 0,
        delta: [0.0; 3],
        offsets: [0.0; 6],
    };
    let mut c = cncrot_head_table {
        count: t.count as i32,
        reserved: 0,
        heads: [empty; CNCROT_HEAD_TABLE_CAPACITY],
    };
    for (c, h) in c.heads.iter_mut().zip(&t.heads).take(t.count) {
        *c = cncrot_head {
            name: to_field(h.name()),
            allowed: h.allowed as i32,
            delta: h.delta,
            offsets: h.offsets,
            ..empty
        };
    }
    c
}

fn state_from_c(g: &cncrot_cycle600_gud) -> Result<State, Error> {
    let (name, len) = field_name(&g.cyc600_1, Error::BadArgument)?;
    let (results, frame) = if bit(g.active)? {
        let h: [[f64; 4]; 4] =
            core::array::from_fn(|i| core::array::from_fn(|j| g.frame[4 * i + j]));
        let frame = Frame::from_homogeneous(&h)?;
        let convention =
            Convention::from_c(g.cyc600_5, g.cyc600_6).map_err(|_| Error::BadArgument)?;
        let angles = [g.cyc600_2, g.cyc600_3, g.cyc600_4];
        if !angles.iter().all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        (
            Some(Results {
                angles,
                convention,
                singular: false,
            }),
            frame,
        )
    } else {
        (None, Frame::IDENTITY)
    };
    Ok(State {
        name,
        name_len: len as u8,
        results,
        frame,
        rot_inv: bit(g.rot_inv)?,
        retr_z: bit(g.retr_z)?,
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
    cncrot_cycle600_gud {
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
    }
}

/// `sizeof(cncrot_cycle600_gud)` as the library sees it: compare with the caller's
/// `sizeof` to detect a header/library mismatch before storing states.
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub extern "C" fn cncrot_cycle600_gud_size() -> usize {
    core::mem::size_of::<cncrot_cycle600_gud>()
}

/// Reads the text of a HEAD_DEF cycle into `table`: per line an optional block number
/// `N…`, then labels (`TZ7:`), `_HEAD_NAME="…"` (starts an accessory), `_HEAD_ALLOWED`,
/// `_DELTA_L1/_L2/_H1`, `_OFFS_L1_X/_L1_Y/_L2_X/_L2_Y/_H1_X/_H1_Z` assignments,
/// `GOTOF/GOTOB/GOTO …`, `RET`, `M17`, `M30`, comments after `;`. `text` holds `len` bytes
/// (no terminating NUL needed). Numbers are read exactly as `strtod` would, within up to 15
/// significant digits (precisely: digits forming an integer up to 2^53, times 10^-22..10^22);
/// others are refused with `CNCROT_STATUS_PARSE` rather than rounded twice.
///
/// Returns 0 and writes the table, with `*error_line` = 0; or a negative status
/// (`CNCROT_STATUS_PARSE` for an unknown or malformed line, `CNCROT_STATUS_NAME_TOO_LONG`,
/// `CNCROT_STATUS_TABLE_FULL`) with the table untouched and the 1-based number of the
/// offending line in `*error_line`. `error_line` may be NULL.
///
/// # Safety
/// `table` points to a writable `cncrot_head_table`, `text` to `len` readable bytes.
///
/// ```c
/// cncrot_head_table heads; int32_t line;
/// if (cncrot_head_table_parse(&heads, text, strlen(text), &line) < 0) printf("line %d\n", line);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_head_table_parse(
    table: *mut cncrot_head_table,
    text: *const c_char,
    len: usize,
    error_line: *mut i32,
) -> i32 {
    guard(|| {
        non_null(&[table.is_null(), text.is_null()])?;
        // No object is larger than isize::MAX bytes; a larger `len` is a caller's bug that
        // `from_raw_parts` must not see.
        if len > isize::MAX as usize {
            return Err(cncrot_status::BadArgument);
        }
        let bytes = core::slice::from_raw_parts(text.cast::<u8>(), len);
        let (status, line) = match HeadTable::parse(bytes) {
            Ok(t) => {
                table.write_unaligned(table_to_c(&t));
                (cncrot_status::Ok, 0)
            }
            Err(e) => (
                cncrot_status::from(e.error),
                i32::try_from(e.line).unwrap_or(i32::MAX),
            ),
        };
        if !error_line.is_null() {
            error_line.write_unaligned(line);
        }
        Ok(status)
    })
}

/// CYCLE600 with the paper's 18 parameters in its order, after the caller's state `gud` and
/// an optional head table `heads` (NULL: the name is only recorded; otherwise `_MIHEAD`
/// must name one of its accessories).
///
/// The input rotation (`_INEXIN`, `_BIN_IN`, `_ANG_1.._3`) with `_POS_*` before and
/// `_POS_*_R` after it forms a frame; `_ROT_AD = 1` adds it to the frame stored in `gud`
/// (intrinsic input on the right, extrinsic on the left). Its rotation is decomposed for
/// `_INEXOUT`/`_BIN_OUT` into `cyc600_2..4`. `_SW_REC = 1` recalculates only; `_SW_REC = 0`
/// (positioning the head) returns `CNCROT_STATUS_NOT_AVAILABLE`. `_ROT_INV` and `_RETR_Z`
/// (0/1) are kept in `gud`.
///
/// Returns 0 or `CNCROT_STATUS_SINGULAR` with `gud` updated; a negative status leaves
/// `gud` exactly as it was (also for a corrupt `gud` or `heads`).
///
/// # Safety
/// `gud` points to a writable state, `mihead` to a NUL-terminated string (at most 31 bytes
/// are used; at most 32 are read), `heads` to a table or is NULL.
///
/// ```c
/// cncrot_cycle600_gud gud = {0};   // paper, Example 3
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
            *n = mihead.add(k).read() as u8;
            if *n == 0 {
                len = Some(k);
                break;
            }
        }
        let len = len.ok_or(cncrot_status::NameTooLong)?;
        let table = if heads.is_null() {
            None
        } else {
            Some(table_from_c(&heads.read_unaligned())?)
        };
        let state = state_from_c(&gud.read_unaligned())?;
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
        let next = cycle600::cycle600(&state, table.as_ref(), &call)?;
        gud.write_unaligned(state_to_c(&next));
        let singular = next.results.is_some_and(|r| r.singular);
        Ok(super::status_of(singular))
    })
}
