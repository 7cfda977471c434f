//! The C boundary of the five-axis programs' reader (`dialects::toolpath`).

use core::ffi::c_char;

use super::{cncrot_status, guard, non_null};
use crate::dialects::program::Dialect;
use crate::dialects::toolpath::{Orientation, PathRemark, ToolPath};

/// `cncrot_tool_path.orientation`: no orientation stated yet.
pub const CNCROT_ORIENTATION_UNSTATED: i32 = 0;
/// `cncrot_tool_path.orientation`: a tool direction (`direction`).
pub const CNCROT_ORIENTATION_DIRECTION: i32 = 1;
/// `cncrot_tool_path.orientation`: rotary-axis positions by letter A, B, C (`axes`).
pub const CNCROT_ORIENTATION_AXES: i32 = 2;

/// The modal state of a five-axis program (SINUMERIK `TRAORI`, Heidenhain `M128` /
/// `FUNCTION TCPM`, Fanuc and Syntec `G43.4` / `G43.5`, Haas `G234`) as
/// `cncrot_tool_path_line` leaves it: a caller-owned plain struct, all zero bytes at the
/// start of a program (the transformation off, the tip at 0, no orientation, absolute
/// coordinates, SINUMERIK angles as `ORIEULER`). 88 bytes.
#[allow(non_camel_case_types)]
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct cncrot_tool_path {
    /// 1 while the transformation is on.
    pub on: i32,
    /// `CNCROT_ORIENTATION_*`: how the orientation was last stated.
    pub orientation: i32,
    /// 1 when the last block read with status 0 was a point: a move with the transformation
    /// on, `tip` and the orientation its CL point; 0 when it only changed the state.
    pub point: i32,
    /// Bit 0: SINUMERIK `ORIRPY` (else `ORIEULER`); bit 1: incremental (`G91`); bit 2:
    /// Heidenhain `AXIS SPAT` (`A B C` spatial angles, else axis positions); bit 3: an arc's
    /// mode (`G2`/`G3`, SINUMERIK `CIP`, `CT`, splines; until `G0`/`G1`); bit 4: an ISO
    /// canned cycle's mode (`G73`…`G89`; until `G80` or `G0`…`G3`); bit 5: the tip lost (a
    /// move not followed: until a block states `X Y Z` all three absolute, motion blocks are
    /// not followed); bits 6 to 11, while any is set motion blocks are not followed: 6 a tilt
    /// or frame active (`G68.2`, `PLANE`, `CYCLE800`, `ROT`, `TRANS`, a frame variable; until
    /// its cancel), 7, 8, 9 a datum shift active in X, Y, Z (`G52`, `CYCL DEF 7`, `TRANS
    /// DATUM`; until its cancel in that axis), 10 cutter radius compensation on (`G41`/`G42`
    /// and their 3-D forms, `RL`/`RR`; until `G40`/`R0`), 11 a change of the coordinates or
    /// of the angles' meaning not computed (ISO `G51`, `G51.1`, `G92`; SINUMERIK `SCALE`,
    /// `MIRROR`, `TOFRAME`, `ORIVIRT1/2`, `ORIRPY2`, `TRAORI` with a base orientation;
    /// Heidenhain's mirror, rotation and scaling cycles, `REFPNT` other than the tip; until
    /// ISO `G69`, `G50`, `G50.1`, `G92.1`, Heidenhain's `ROT+0`, `SCL1`); bit 12: inch
    /// coordinates (`G20`, `G70`, `G700`, `INCH`: `X Y Z` taken times 25.4, `tip` in mm); bit
    /// 13: the orientation lost (a block not followed stated a direction or angles, or
    /// `ORIRESET`: until a block states one, motion blocks are not followed); bits 14, 15,
    /// 16: `X`, `Y`, `Z` known (stated absolutely since the start, the tip lost, a work
    /// offset selected or the transformation switched: a zeroed state knows none, and a
    /// motion block with the transformation on is a point only when all three are).
    pub flags: i32,
    /// The programmed tool tip, mm, workpiece coordinates.
    pub tip: [f64; 3],
    /// The tool direction (a unit vector) when `orientation` is `CNCROT_ORIENTATION_DIRECTION`;
    /// otherwise 0.
    pub direction: [f64; 3],
    /// Rotary positions stated by letter A, B, C, degrees (0 for letters never stated): the
    /// orientation when `orientation` is `CNCROT_ORIENTATION_AXES`.
    pub axes: [f64; 3],
}

/// The Rust state of a C one, or `CNCROT_STATUS_BAD_STATE` for one the library does not
/// write (flags, codes, non-finite numbers, a direction that is not a unit vector).
fn load(c: &cncrot_tool_path) -> Result<ToolPath, cncrot_status> {
    let bad = cncrot_status::BadState;
    let finite = c
        .tip
        .iter()
        .chain(&c.direction)
        .chain(&c.axes)
        .all(|x| x.is_finite());
    if !(finite
        && (0..=1).contains(&c.on)
        && (0..=1).contains(&c.point)
        && (0..1 << 17).contains(&c.flags))
    {
        return Err(bad);
    }
    let orientation = match c.orientation {
        CNCROT_ORIENTATION_UNSTATED if c.direction == [0.0; 3] => Orientation::Unstated,
        CNCROT_ORIENTATION_DIRECTION => {
            let d = c.direction;
            let n = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            // NaN is refused above: a plain comparison decides.
            if (n - 1.0).abs() > 1e-12 {
                return Err(bad);
            }
            Orientation::Direction(d)
        }
        CNCROT_ORIENTATION_AXES if c.direction == [0.0; 3] => Orientation::Axes(c.axes),
        _ => return Err(bad),
    };
    Ok(ToolPath {
        on: c.on == 1,
        tip: c.tip,
        orientation,
        axes: c.axes,
        rpy: c.flags & 1 != 0,
        spatial: c.flags & 4 != 0,
        incremental: c.flags & 2 != 0,
        circular: c.flags & 8 != 0,
        canned: c.flags & 16 != 0,
        lost: c.flags & 32 != 0,
        framed: c.flags & 1 << 6 != 0,
        shifted: [
            c.flags & 1 << 7 != 0,
            c.flags & 1 << 8 != 0,
            c.flags & 1 << 9 != 0,
        ],
        compensated: c.flags & 1 << 10 != 0,
        altered: c.flags & 1 << 11 != 0,
        inch: c.flags & 1 << 12 != 0,
        disoriented: c.flags & 1 << 13 != 0,
        known: [
            c.flags & 1 << 14 != 0,
            c.flags & 1 << 15 != 0,
            c.flags & 1 << 16 != 0,
        ],
    })
}

fn store(p: &ToolPath, point: bool) -> cncrot_tool_path {
    let (orientation, direction) = match p.orientation {
        Orientation::Unstated => (CNCROT_ORIENTATION_UNSTATED, [0.0; 3]),
        Orientation::Direction(d) => (CNCROT_ORIENTATION_DIRECTION, d),
        Orientation::Axes(_) => (CNCROT_ORIENTATION_AXES, [0.0; 3]),
    };
    cncrot_tool_path {
        on: i32::from(p.on),
        orientation,
        point: i32::from(point),
        flags: i32::from(p.rpy)
            | (i32::from(p.incremental) << 1)
            | (i32::from(p.spatial) << 2)
            | (i32::from(p.circular) << 3)
            | (i32::from(p.canned) << 4)
            | (i32::from(p.lost) << 5)
            | (i32::from(p.framed) << 6)
            | (i32::from(p.shifted[0]) << 7)
            | (i32::from(p.shifted[1]) << 8)
            | (i32::from(p.shifted[2]) << 9)
            | (i32::from(p.compensated) << 10)
            | (i32::from(p.altered) << 11)
            | (i32::from(p.inch) << 12)
            | (i32::from(p.disoriented) << 13)
            | (i32::from(p.known[0]) << 14)
            | (i32::from(p.known[1]) << 15)
            | (i32::from(p.known[2]) << 16),
        tip: p.tip,
        direction,
        axes: p.axes,
    }
}

/// Reads one block of a five-axis program (`len` bytes, no NUL needed; a trailing line end
/// is ignored) in `dialect` (`CNCROT_DIALECT_*`) into `*path`: the transformation switched
/// on or off, SINUMERIK's angle mode, `G90`/`G91`, and a motion block's tip `X Y Z` and
/// orientation (the tool direction `A3 B3 C3`, `A2 B2 C2`, `TX TY TZ` or `I J K`, components
/// not written 0, made a unit vector; or rotary positions `A B C`, absolute or incremental),
/// as the control keeps them. With the transformation on, a motion block is a CL point:
/// status 0 and `path->point` 1; the machine's axes for it: `cncrot_machine_tcp_inverse`.
///
/// Returns 0 (`point` 1 for a CL point, 0 for a state change), `CNCROT_STATUS_PASSED` (a
/// block that concerns neither: `*path` byte-identical), `CNCROT_STATUS_NOT_FOLLOWED` (a
/// move the reader does not follow: an arc, a block in an arc's or a canned cycle's mode,
/// a reference or machine-coordinate move, a value that is not a number, the start-up move
/// of `G43.4`/`G43.5`/`G234`, a call, a move while the tip or the orientation is lost or in
/// a frame, shift, compensation or change marked by `flags` bits 6 to 11, a frame command —
/// tilt, shift or cancel — whose words are no move: `tip`, `orientation`, `direction` and
/// `axes` as they were (rotary positions stated by letter taken), the modes the block sets
/// taken — `on`, `flags` bits 0 to 4 and 6 to 12 — and `flags` bits 5 and 13 set where the
/// block moved the machine or stated a direction, bits 14 to 16 then cleared, `point` 0; a
/// motion block after which a
/// coordinate is still not known takes its words — absolute coordinates, the orientation —
/// without a point); or with
/// `*path` untouched: `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_STATE` (a state the
/// library does not write), `CNCROT_STATUS_NOT_AVAILABLE` (TwinCAT: its five-axis
/// programs are not read), `CNCROT_STATUS_LINE_TOO_LONG`, `CNCROT_STATUS_BAD_ARGUMENT` (a
/// dialect that is not one, a zero tool direction, a direction and rotary positions in one
/// block), `CNCROT_STATUS_OUT_OF_RANGE` (a position that overflows).
///
/// # Safety
/// `path` points to a writable `cncrot_tool_path`, `line` to `len` readable bytes.
///
/// ```c
/// cncrot_tool_path t;
/// memset(&t, 0, sizeof t);
/// cncrot_tool_path_line(&t, CNCROT_DIALECT_SINUMERIK, "TRAORI", 6);
/// const char *l = "G1 X10 Y20 Z5 A3=0 B3=-1 C3=1";
/// cncrot_tool_path_line(&t, CNCROT_DIALECT_SINUMERIK, l, strlen(l));
/// // t.point == 1, t.tip = (10, 20, 5), t.direction = (0, -0.7071, 0.7071)
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_tool_path_line(
    path: *mut cncrot_tool_path,
    dialect: i32,
    line: *const c_char,
    len: usize,
) -> i32 {
    guard(|| {
        non_null(&[path.is_null(), line.is_null()])?;
        let c = path.read_unaligned();
        let p = load(&c)?;
        let d = Dialect::from_code(dialect)?;
        // Beyond the longest block and its line end nothing is read.
        if len > d.max_line() + 2 {
            return Err(cncrot_status::LineTooLong);
        }
        let text = core::slice::from_raw_parts(line.cast::<u8>(), len);
        let (next, remark) = p.line(d, text).map_err(|e| cncrot_status::from(e.error))?;
        Ok(match remark {
            PathRemark::Point | PathRemark::Applied => {
                path.write_unaligned(store(&next, remark == PathRemark::Point));
                cncrot_status::Ok
            }
            PathRemark::Passed => cncrot_status::Passed,
            PathRemark::NotFollowed => {
                // The modes the block sets, and whether it lost the tip; nothing else of it.
                // `point` 0 in any case: the state no longer holds the last block's point.
                if next != p || c.point != 0 {
                    path.write_unaligned(store(&next, false));
                }
                cncrot_status::NotFollowed
            }
        })
    })
}

/// The machine's axes for the CL point `*path` holds (after a block read with status 0 and
/// `point` 1), as `cncrot_machine_tcp_inverse_rule` computes them (`axes`, `previous`,
/// `tool_length`, `rule` and `reference_axis` as there): for a tool direction the rotary
/// solution the rule picks; for rotary positions stated by letter, those positions (each
/// machine axis takes the letter its direction is nearest: A for X, B for Y, C for Z; of two
/// axes nearest one letter the one more nearly along it, the other its next nearest letter
/// \[choice: a description carries no axis names\]; `rule` is then not used); with no
/// orientation stated, the rotary axes where `previous` has them. The linear axes put the
/// tip on the point.
///
/// Returns 0, `CNCROT_STATUS_FREE_AXIS`, `CNCROT_STATUS_SNAPPED`, or with `axes` untouched:
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_STATE` (a state the library does not
/// write), `CNCROT_STATUS_BAD_ARGUMENT` (a rule or reference axis that is not one, an unused
/// previous rotary position not 0, a nonzero position for a letter the machine lacks),
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_UNREACHABLE`,
/// `CNCROT_STATUS_OUT_OF_TRAVEL`, `CNCROT_STATUS_OUT_OF_RANGE`, and the statuses of a
/// description that is not a machine (`CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NAME_TOO_LONG`:
/// see `cncrot_machine`).
///
/// # Safety
/// `path` points to a readable `cncrot_tool_path`, `machine` to a `cncrot_machine`,
/// `previous` and `axes` to 6 doubles (`axes` may be `previous`).
///
/// ```c
/// double prev[6] = {0}, ax[6];
/// if (cncrot_tool_path_line(&t, CNCROT_DIALECT_FANUC, l, n) == 0 && t.point)
///   cncrot_tool_path_axes(&t, &m, 50.0, prev, CNCROT_CHOOSE_CLOSEST, 0, ax);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_tool_path_axes(
    path: *const cncrot_tool_path,
    machine: *const super::cncrot_machine,
    tool_length: f64,
    previous: *const f64,
    rule: i32,
    reference_axis: i32,
    axes: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            path.is_null(),
            machine.is_null(),
            previous.is_null(),
            axes.is_null(),
        ])?;
        let p = load(&path.read_unaligned())?;
        let rule = super::machine::rule_of(rule, reference_axis)?;
        let prev = super::read_finite::<6>(previous)?;
        if !tool_length.is_finite() {
            return Err(cncrot_status::NotFinite);
        }
        super::machine::with_machine(machine, |m| {
            let t = p.machine_axes(m, tool_length, prev, rule)?;
            super::machine::write_tcp(axes, &t)
        })
    })
}
