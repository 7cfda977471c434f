//! What CYCLE600 and the machines share at the C boundary: names, the HEAD_DEF table and
//! its parser.

use super::{byte, cncrot_status, guard};
use crate::dialects::cycle600::HeadLookup;
use crate::dialects::head_def::{HeadTable, CAPACITY, NAME_MAX};
use crate::Error;
use core::ffi::c_char;

/// Size of a name field, including its terminating NUL: names have at most 31 bytes.
pub const CNCROT_NAME_SIZE: usize = 32;
/// How many accessories a `cncrot_head_table` holds.
pub const CNCROT_HEAD_TABLE_CAPACITY: usize = 16;

// The C capacities are the Rust ones: a change on one side fails to compile.
const _: () = assert!(CNCROT_NAME_SIZE == NAME_MAX + 1);
const _: () = assert!(CNCROT_NAME_SIZE == crate::kinematics::MACHINE_NAME_MAX + 1);
const _: () = assert!(CNCROT_HEAD_TABLE_CAPACITY == CAPACITY);

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
pub(super) fn field_name(
    field: &[c_char; CNCROT_NAME_SIZE],
    fail: Error,
) -> Result<([u8; NAME_MAX], usize), Error> {
    let len = field.iter().position(|&c| c == 0).ok_or(fail)?;
    let mut name = [0u8; NAME_MAX];
    for (n, &c) in name.iter_mut().zip(&field[..len]) {
        *n = byte(c);
    }
    Ok((name, len))
}

pub(super) fn to_field(name: &[u8]) -> [c_char; CNCROT_NAME_SIZE] {
    let mut field = [0 as c_char; CNCROT_NAME_SIZE];
    for (f, &b) in field.iter_mut().zip(name) {
        *f = b as c_char;
    }
    field
}

pub(super) fn bit(v: i32) -> Result<bool, Error> {
    match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(Error::BadArgument),
    }
}

/// The caller's head table, read in place: a lookup checks the count and the entry it
/// finds, nothing else, so a call costs the same whatever the table holds.
pub(super) struct CHeads<'a>(pub(super) &'a cncrot_head_table);

impl CHeads<'_> {
    /// The entry named `name`, checked; `None` when there is none.
    pub(super) fn find(&self, name: &[u8]) -> Result<Option<&cncrot_head>, Error> {
        let t = self.0;
        let count = usize::try_from(t.count)
            .ok()
            .filter(|&c| c <= CAPACITY)
            .ok_or(Error::BadArgument)?;
        if t.reserved != 0 {
            return Err(Error::BadArgument);
        }
        for h in t.heads.iter().take(count) {
            // A match is the name's bytes followed by the NUL; an entry without a NUL in
            // its field never matches.
            let matches = h.name.get(name.len()) == Some(&0)
                && h.name.iter().zip(name).all(|(&c, &n)| byte(c) == n);
            if matches {
                bit(h.allowed)?;
                if h.reserved != 0 {
                    return Err(Error::BadArgument);
                }
                if !h.delta.iter().chain(&h.offsets).all(|x| x.is_finite()) {
                    return Err(Error::NotFinite);
                }
                return Ok(Some(h));
            }
        }
        Ok(None)
    }
}

impl HeadLookup for CHeads<'_> {
    fn contains(&self, name: &[u8]) -> Result<bool, Error> {
        Ok(self.find(name)?.is_some())
    }
}

/// Parses into one table on the stack (1.8 KiB, filled in place), then writes it into the
/// caller's only on success. Not inlined, so that no second table is laid out in the
/// export's frame (stack bound of `cncrot_head_table_parse`).
///
/// # Safety
/// `out` is non-NULL and points to a writable `cncrot_head_table`.
#[inline(never)]
unsafe fn parse_into(
    out: *mut cncrot_head_table,
    text: &[u8],
) -> Result<(), crate::dialects::head_def::ParseError> {
    let mut t = HeadTable::EMPTY;
    t.read(text)?;
    write_table(out, &t);
    Ok(())
}

/// Writes the parsed table into the caller's, entry by entry (no second full copy on the
/// stack).
///
/// # Safety
/// `out` is non-NULL and points to a writable `cncrot_head_table`.
#[inline(never)]
unsafe fn write_table(out: *mut cncrot_head_table, t: &HeadTable) {
    let empty = cncrot_head {
        name: [0; CNCROT_NAME_SIZE],
        allowed: 0,
        reserved: 0,
        delta: [0.0; 3],
        offsets: [0.0; 6],
    };
    let count = t.count.min(CAPACITY);
    core::ptr::addr_of_mut!((*out).count).write_unaligned(count as i32);
    core::ptr::addr_of_mut!((*out).reserved).write_unaligned(0);
    let heads = core::ptr::addr_of_mut!((*out).heads).cast::<cncrot_head>();
    for k in 0..CNCROT_HEAD_TABLE_CAPACITY {
        let entry = match t.heads.get(k) {
            Some(h) if k < count => cncrot_head {
                name: to_field(h.name()),
                allowed: h.allowed as i32,
                delta: h.delta,
                offsets: h.offsets,
                ..empty
            },
            _ => empty,
        };
        heads.add(k).write_unaligned(entry);
    }
}

/// Reads the text of a HEAD_DEF cycle into `table`: per line an optional block number
/// `N…`, then labels (`TZ7:`), `_HEAD_NAME="…"` (starts an accessory), `_HEAD_ALLOWED`,
/// `_DELTA_L1/_L2/_H1`, `_OFFS_L1_X/_L1_Y/_L2_X/_L2_Y/_H1_X/_H1_Z` assignments,
/// `GOTOF/GOTOB/GOTO …`, comments after `;`, read as a SINUMERIK control reads them:
/// keywords in any case, a UTF-8 byte-order mark skipped, block-skip marks (`/`, `/0`..`/9`)
/// read as executed, reading ended by the block with `M30`, `M17`, `M2`, `M02` or `RET`.
/// Names are 1 to 31 printable ASCII characters without spaces or quotes. `text` holds
/// `len` bytes (no terminating NUL needed). Numbers (`[+-]digits[.digits][(e|E)[+-]digits]`)
/// are correctly rounded, as `strtod` reads them, by the reader of every program line;
/// magnitudes beyond 10^±100 are `CNCROT_STATUS_PARSE`.
///
/// Returns 0 and writes the table, with `*error_line` = 0; or a negative status with the
/// table untouched: `CNCROT_STATUS_PARSE` for an unknown or malformed line,
/// `CNCROT_STATUS_NAME_TOO_LONG`, `CNCROT_STATUS_TABLE_FULL` (with the 1-based number of the
/// offending line in `*error_line`), `CNCROT_STATUS_NULL_POINTER` for `table` or `text`,
/// `CNCROT_STATUS_BAD_ARGUMENT` for `len` beyond the largest object (`PTRDIFF_MAX`) (with
/// `*error_line` = 0). `error_line` may be NULL.
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
        // No object is larger than isize::MAX bytes; a larger `len` is a caller's bug that
        // `from_raw_parts` must not see.
        let early = if table.is_null() || text.is_null() {
            Some(cncrot_status::NullPointer)
        } else if len > isize::MAX as usize {
            Some(cncrot_status::BadArgument)
        } else {
            None
        };
        let (status, line) = match early {
            Some(status) => (status, 0),
            None => match parse_into(table, core::slice::from_raw_parts(text.cast::<u8>(), len)) {
                Ok(()) => (cncrot_status::Ok, 0),
                Err(e) => (
                    cncrot_status::from(e.error),
                    i32::try_from(e.line).unwrap_or(i32::MAX),
                ),
            },
        };
        if !error_line.is_null() {
            error_line.write_unaligned(line);
        }
        Ok(status)
    })
}
