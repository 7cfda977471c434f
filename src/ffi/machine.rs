//! Exports of the swivel kinematics: a caller-owned machine description, its forward and
//! inverse computation, the choice of positions and the tool-tip follow-up.

use super::frame::{read_frame, read_frame_unchecked, write_frame};
use super::heads::{cncrot_head_table, CHeads, CNCROT_NAME_SIZE};
use super::{byte, cncrot_status, guard, non_null, read_finite, write};
use crate::dialects::carr::machine_from_carr;
use crate::dialects::head_def::Head;
use crate::kinematics::{Choice, Hirth, Machine, RotaryAxis, Rule, Side, MAX_AXES};
use crate::Frame;
use core::ffi::c_char;

/// Capacity of `cncrot_machine.axes`.
pub const CNCROT_MACHINE_AXES: usize = 3;
/// Machine axes of the five-axis transformation (`cncrot_machine_tcp_forward` /
/// `_tcp_inverse`): linear `X, Y, Z`, then the rotary axes 1..3.
pub const CNCROT_MACHINE_TCP_AXES: usize = 6;
/// The most solutions `cncrot_machine_inverse` returns.
pub const CNCROT_MACHINE_SOLUTIONS_MAX: usize = 2;
/// `cncrot_machine_choose`: the solution closest to the current positions.
pub const CNCROT_CHOOSE_CLOSEST: i32 = 0;
/// `cncrot_machine_choose`: the solution with the lower angle of the reference axis, as an
/// angle in (-180, 180] before whole turns are unwound (CYCLE800 "minus", Heidenhain `SEQ-`
/// on the master axis: "a negative angle").
pub const CNCROT_CHOOSE_MINUS: i32 = 1;
/// `cncrot_machine_choose`: the solution with the higher angle of the reference axis, as
/// `CNCROT_CHOOSE_MINUS` (CYCLE800 "plus", Heidenhain `SEQ+`).
pub const CNCROT_CHOOSE_PLUS: i32 = 2;
/// `cncrot_machine_choose`: the other solution of the pair (CYCLE600 `_ROT_INV = 1`); the
/// only one left when the other lies outside the travel or there is no other.
pub const CNCROT_CHOOSE_INVERSE: i32 = 3;
/// `cncrot_machine_choose`: the reference axis turns in its positive direction only, the
/// least it must (LinuxCNC's `G53.1 P1`, "positive rotation only" of the priority axis);
/// the other axes take the turn nearest their current positions. On an axis with travel
/// limits only positions from the current one up to the upper end qualify.
pub const CNCROT_CHOOSE_POSITIVE_TURN: i32 = 4;
/// `cncrot_machine_choose`: the reference axis turns in its negative direction only
/// (`G53.1 P2`), as `CNCROT_CHOOSE_POSITIVE_TURN`.
pub const CNCROT_CHOOSE_NEGATIVE_TURN: i32 = 5;
/// `cncrot_machine_choose`: the solution whose reference axis (the master) turns the least,
/// then the other axes in their order, then the reference axis nearest 0° (a multiple of
/// 360°), then the others: Fanuc's rule for `G53.1` ("output judgement conditions"; the
/// first rotation axis as the master, on a mixed machine the table's axis), which
/// `cncrot_program_axes` applies to a Fanuc tilt without choice words.
pub const CNCROT_CHOOSE_MASTER_FIRST: i32 = 6;
/// A computed position at most this far (degrees) beyond an end of its axis' travel is
/// taken exactly at that end \[choice\]: the inverse computes a position at an end a few
/// ulp off; moving by this much turns the tool by 1.7e-11 rad, within the 1e-10 rad to
/// which a target counts as reached.
pub const CNCROT_MACHINE_TRAVEL_TOLERANCE_DEG: f64 = 1e-9;
/// Angles of a machine — axis offsets, travel limits, Hirth offsets, and the current
/// positions given to `cncrot_machine_choose` — must be below this in magnitude (degrees);
/// otherwise `CNCROT_STATUS_OUT_OF_RANGE`. There doubles are 7.3e-12° apart at most; from
/// it on a turn of the axis would be computed to 1.5e-11° or worse (at 1e15°, 0.125°).
pub const CNCROT_MACHINE_ANGLE_MAX_DEG: f64 = 65536.0;
/// The coordinates of an axis' point must lie within ± this (millimetres; a kilometre)
/// \[choice\]; otherwise `CNCROT_STATUS_OUT_OF_RANGE`. The translations made from such a
/// point are exact to 1e-9 mm.
pub const CNCROT_MACHINE_LENGTH_MAX_MM: f64 = 1e6;
/// The finest Hirth grid (degrees) \[choice\]: `hirth_step_deg` is 0 (no grid) or at least
/// this; a step between is `CNCROT_STATUS_BAD_ARGUMENT`.
pub const CNCROT_MACHINE_HIRTH_STEP_MIN_DEG: f64 = 1e-6;

// The C capacities and limits are the Rust ones: a change on one side fails to compile.
const _: () = assert!(CNCROT_MACHINE_AXES == MAX_AXES);
const _: () = assert!(CNCROT_MACHINE_TCP_AXES == crate::kinematics::TCP_AXES);
const _: () = assert!(CNCROT_MACHINE_SOLUTIONS_MAX == crate::kinematics::MAX_SOLUTIONS);
const _: () = assert!(CNCROT_MACHINE_TRAVEL_TOLERANCE_DEG == crate::kinematics::TRAVEL_TOLERANCE);
const _: () = assert!(CNCROT_MACHINE_LENGTH_MAX_MM == crate::kinematics::LENGTH_MAX);
const _: () = assert!(CNCROT_MACHINE_HIRTH_STEP_MIN_DEG == crate::kinematics::HIRTH_STEP_MIN);

/// One rotary axis of a `cncrot_machine`: a direction and a point on it (machine
/// coordinates, every axis at its initial position).
#[allow(non_camel_case_types)]
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct cncrot_machine_axis {
    /// 0: the axis turns the tool; 1: it turns the workpiece.
    pub work_side: i32,
    /// Zero.
    pub reserved: i32,
    /// Direction; positive rotation is the right-hand turn about it (any length, not 0).
    pub direction: [f64; 3],
    /// A point on the axis, mm, each coordinate within ±`CNCROT_MACHINE_LENGTH_MAX_MM`.
    pub point: [f64; 3],
    /// The position the axis reads in the described initial state, degrees
    /// (`$TC_CARR24/25`), below `CNCROT_MACHINE_ANGLE_MAX_DEG` in magnitude.
    pub offset_deg: f64,
    /// Travel limits, degrees, `min_deg <= max_deg`, below `CNCROT_MACHINE_ANGLE_MAX_DEG` in
    /// magnitude; both 0: a modulo axis without limits.
    pub min_deg: f64,
    /// See `min_deg`.
    pub max_deg: f64,
    /// Hirth grid: a tooth position, degrees, below `CNCROT_MACHINE_ANGLE_MAX_DEG` in
    /// magnitude; without a grid (`hirth_step_deg` 0) not used, not checked but for being
    /// finite, and written as 0 by `cncrot_machine_seal` and the builders.
    pub hirth_offset_deg: f64,
    /// Hirth grid: tooth spacing, degrees, at least `CNCROT_MACHINE_HIRTH_STEP_MIN_DEG`; 0:
    /// no grid.
    pub hirth_step_deg: f64,
}

/// A machine: up to three rotary axes, outermost first (an axis added after another on the
/// same side is carried by it), the tool's base direction and a name. A caller-owned plain
/// struct; zeroed, it is a machine without rotary axes whose tool points along +Z.
///
/// Every function that writes one (`cncrot_machine_from_carr`, `_from_head`, `_add_axis`,
/// `_seal`) seals it: `reserved` holds a hash of the rest, and a call that reads a sealed
/// description uses it in place, checking the seal (about 20 ns) instead of every field:
/// what the five-axis transformation needs in the interpolation cycle.
///
/// The caller may fill it by hand, wholly or in part (offsets, Hirth grids and limits after
/// `cncrot_machine_add_axis`, say): the seal no longer matches, and every call that reads
/// it checks all of it (as `cncrot_machine_seal` does, which seals it again) and refuses
/// what is not a machine, with nothing written. `CNCROT_STATUS_BAD_ARGUMENT`: a pointer
/// not aligned for the struct, `count` outside 0..3, an axis' `reserved` field not 0, an
/// unused entry of `axes` not all zero, a zero direction, `min_deg > max_deg`, a Hirth step
/// between 0 and `CNCROT_MACHINE_HIRTH_STEP_MIN_DEG` or negative, two consecutive axes of
/// the rotation chain parallel (within a sine of 1e-6), a name with bytes other than
/// printable ASCII; `CNCROT_STATUS_BAD_FLAG`: `work_side` other than 0 or 1;
/// `CNCROT_STATUS_NOT_FINITE`: a NaN or infinity in `tool_direction` or in any field of a
/// used axis;
/// `CNCROT_STATUS_OUT_OF_RANGE`: an angle (offset, limit, Hirth offset) of magnitude
/// `CNCROT_MACHINE_ANGLE_MAX_DEG` or more, a point coordinate beyond
/// ±`CNCROT_MACHINE_LENGTH_MAX_MM`; `CNCROT_STATUS_NAME_TOO_LONG`: no NUL in `name`.
/// Directions need not be unit vectors (the library stores unit vectors, and a direction
/// within 8 units in the last place of length 1 as it is); bytes after the name's NUL are
/// not read. A description and its sealed form compute exactly alike.
#[allow(non_camel_case_types)]
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct cncrot_machine {
    /// How many entries of `axes` are used (0..3).
    pub count: i32,
    /// The seal the library writes (any value: a description whose seal does not match is
    /// checked whole).
    pub reserved: u32,
    /// The tool's direction with every axis at its initial position; all 0: +Z.
    pub tool_direction: [f64; 3],
    /// The axes, outermost first.
    pub axes: [cncrot_machine_axis; CNCROT_MACHINE_AXES],
    /// A name, NUL-terminated, printable ASCII (`$TC_CARR34`).
    pub name: [c_char; CNCROT_NAME_SIZE],
}

const EMPTY_AXIS: cncrot_machine_axis = cncrot_machine_axis {
    work_side: 0,
    reserved: 0,
    direction: [0.0; 3],
    point: [0.0; 3],
    offset_deg: 0.0,
    min_deg: 0.0,
    max_deg: 0.0,
    hirth_offset_deg: 0.0,
    hirth_step_deg: 0.0,
};

/// The Rust machine a C description stands for, checked, built in `out` (which is left
/// in an unspecified state on an error). Not inlined: its temporaries would otherwise stay
/// in every export's frame (stack bound).
#[inline(never)]
fn machine_of(m: &cncrot_machine, out: &mut Machine) -> Result<(), cncrot_status> {
    let count = usize::try_from(m.count)
        .ok()
        .filter(|&c| c <= MAX_AXES)
        .ok_or(cncrot_status::BadArgument)?;
    // An unused entry that is not empty is a description the caller did not mean (a count
    // lowered by hand, a struct never zeroed): refused rather than silently ignored.
    if !unused_empty(m, count) {
        return Err(cncrot_status::BadArgument);
    }
    let b = if m.tool_direction == [0.0; 3] {
        [0.0, 0.0, 1.0]
    } else {
        m.tool_direction
    };
    out.reset(b)?;
    for a in m.axes.iter().take(count) {
        out.push_axis(axis_of(a)?)?;
    }
    // SAFETY: `c_char` is `i8` or `u8`: the same size and alignment as `u8`, every bit
    // pattern valid. Read in place: a copy of the name cost a loop of its own.
    let name: &[u8; CNCROT_NAME_SIZE] = unsafe { &*m.name.as_ptr().cast() };
    let len = name
        .iter()
        .position(|&c| c == 0)
        .ok_or(cncrot_status::NameTooLong)?;
    out.set_name(name.get(..len).unwrap_or(&[]))?;
    Ok(())
}

/// Whether the entries of `axes` from `count` on have every field 0 (−0 included; NaN is
/// not). Not inlined, and field by field rather than `== EMPTY_AXIS`: either kept a copy
/// in the frame of `machine_of`, which lies under every axis it adds (stack bound).
#[inline(never)]
fn unused_empty(m: &cncrot_machine, count: usize) -> bool {
    let zero = |v: &[f64; 3]| v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
    m.axes.iter().skip(count).all(|a| {
        a.work_side == 0
            && a.reserved == 0
            && zero(&a.direction)
            && zero(&a.point)
            && zero(&[a.offset_deg, a.min_deg, a.max_deg])
            && a.hirth_offset_deg == 0.0
            && a.hirth_step_deg == 0.0
    })
}

fn axis_of(a: &cncrot_machine_axis) -> Result<RotaryAxis, cncrot_status> {
    let side = match a.work_side {
        0 => Side::Tool,
        1 => Side::Work,
        _ => return Err(cncrot_status::BadFlag),
    };
    if a.reserved != 0 {
        return Err(cncrot_status::BadArgument);
    }
    let numbers = [
        a.offset_deg,
        a.min_deg,
        a.max_deg,
        a.hirth_offset_deg,
        a.hirth_step_deg,
    ];
    if !numbers
        .iter()
        .chain(&a.direction)
        .chain(&a.point)
        .all(|x| x.is_finite())
    {
        return Err(cncrot_status::NotFinite);
    }
    // Finite (checked above), so a plain comparison decides.
    if a.hirth_step_deg < 0.0 {
        return Err(cncrot_status::BadArgument);
    }
    Ok(RotaryAxis {
        offset: a.offset_deg,
        limits: (a.min_deg != 0.0 || a.max_deg != 0.0).then_some([a.min_deg, a.max_deg]),
        hirth: (a.hirth_step_deg > 0.0).then_some(Hirth {
            offset: a.hirth_offset_deg,
            step: a.hirth_step_deg,
        }),
        ..RotaryAxis::new(side, a.direction, a.point)
    })
}

// The description is the Rust machine's image: the same fields at the same places.
const _: () = {
    use crate::kinematics::{AXIS_LAYOUT, IMAGE_SIZE, MACHINE_LAYOUT};
    use core::mem::{align_of, offset_of, size_of};
    assert!(size_of::<cncrot_machine>() == IMAGE_SIZE);
    assert!(align_of::<cncrot_machine>() == align_of::<Machine>());
    assert!(size_of::<cncrot_machine>() == size_of::<Machine>());
    let m = [
        offset_of!(cncrot_machine, count),
        offset_of!(cncrot_machine, reserved),
        offset_of!(cncrot_machine, tool_direction),
        offset_of!(cncrot_machine, axes),
        offset_of!(cncrot_machine, name),
    ];
    let a = [
        offset_of!(cncrot_machine_axis, work_side),
        offset_of!(cncrot_machine_axis, reserved),
        offset_of!(cncrot_machine_axis, direction),
        offset_of!(cncrot_machine_axis, point),
        offset_of!(cncrot_machine_axis, offset_deg),
        offset_of!(cncrot_machine_axis, min_deg),
        offset_of!(cncrot_machine_axis, max_deg),
        offset_of!(cncrot_machine_axis, hirth_offset_deg),
        offset_of!(cncrot_machine_axis, hirth_step_deg),
    ];
    let mut k = 0;
    while k < 5 {
        assert!(m[k] == MACHINE_LAYOUT[k]);
        k += 1;
    }
    let mut k = 0;
    while k < 9 {
        assert!(a[k] == AXIS_LAYOUT[k]);
        k += 1;
    }
    assert!(size_of::<cncrot_machine_axis>() * CNCROT_MACHINE_AXES == IMAGE_SIZE - 64);
};

/// The C description of a machine: its image, sealed.
fn c_of(m: &Machine) -> cncrot_machine {
    let sealed = m.sealed();
    // SAFETY: the same size, alignment and fields (asserted above), every bit pattern of
    // both valid (integers, doubles, `c_char`s).
    unsafe { core::ptr::read((&sealed as *const Machine).cast::<cncrot_machine>()) }
}

/// Runs `f` on the machine at `p`: in place when the description carries its seal (the
/// hot path: no check but the seal's, no copy), else checked and built in a frame of its
/// own. A pointer not aligned like the C type is refused (`CNCROT_STATUS_BAD_ARGUMENT`).
///
/// # Safety
/// `p` is NULL or points to a readable `cncrot_machine`.
pub(super) unsafe fn with_machine<R>(
    p: *const cncrot_machine,
    f: impl FnOnce(&Machine) -> Result<R, cncrot_status>,
) -> Result<R, cncrot_status> {
    if p.align_offset(core::mem::align_of::<cncrot_machine>()) != 0 {
        return Err(cncrot_status::BadArgument);
    }
    // SAFETY: aligned (checked), readable (the caller's promise); the description has the
    // machine's layout (asserted above) and every bit pattern of it is a valid `Machine`.
    match p.cast::<Machine>().as_ref() {
        Some(m) if m.is_sealed() => f(m),
        Some(_) => built(p, f),
        None => Err(cncrot_status::NullPointer),
    }
}

/// The slow way of [`with_machine`]: the whole description checked, the machine built in
/// this frame (which the hot path does not have on its stack).
#[inline(never)]
unsafe fn built<R>(
    p: *const cncrot_machine,
    f: impl FnOnce(&Machine) -> Result<R, cncrot_status>,
) -> Result<R, cncrot_status> {
    let mut m = Machine::EMPTY;
    // SAFETY: non-NULL and aligned (checked by the caller), readable.
    match p.as_ref() {
        Some(d) => machine_of(d, &mut m)?,
        None => return Err(cncrot_status::NullPointer),
    }
    f(&m)
}

/// The machine at `p`, checked and built in `out` in place: the exports keep one machine
/// in their frame, not the copies a returned `Result<Machine, _>` leaves (stack bound). A
/// pointer not aligned like the C type is refused (`CNCROT_STATUS_BAD_ARGUMENT`) rather
/// than copied (a copy would cost 352 bytes of stack). A sealed description is copied as
/// it is.
///
/// # Safety
/// `p` is non-NULL and points to a readable `cncrot_machine`.
pub(super) unsafe fn load_into(
    p: *const cncrot_machine,
    out: &mut Machine,
) -> Result<(), cncrot_status> {
    if p.align_offset(core::mem::align_of::<cncrot_machine>()) != 0 {
        return Err(cncrot_status::BadArgument);
    }
    // SAFETY: non-NULL and aligned (checked); every bit pattern of its integer and double
    // fields is valid, and it has the machine's layout.
    match p.cast::<Machine>().as_ref() {
        Some(m) if m.is_sealed() => {
            *out = *m;
            Ok(())
        }
        Some(_) => match p.as_ref() {
            Some(m) => machine_of(m, out),
            None => Err(cncrot_status::NullPointer),
        },
        None => Err(cncrot_status::NullPointer),
    }
}

/// # Safety
/// `text` is non-NULL and points to `len` readable bytes.
unsafe fn bytes<'a>(text: *const c_char, len: usize) -> Result<&'a [u8], cncrot_status> {
    // No object is larger than isize::MAX bytes.
    if len > isize::MAX as usize {
        return Err(cncrot_status::BadArgument);
    }
    Ok(core::slice::from_raw_parts(text.cast::<u8>(), len))
}

/// Reads SINUMERIK swivel data set `data_set` (1-based) from `$TC_CARR…` assignments
/// (`len` bytes of `text`, no NUL needed) into `machine`: type T (both axes turn the tool,
/// pivots `−l1` and `−l1 − l2`), P (both turn the workpiece, `l2` and `l2 + l3`), M (axis
/// 1 turns the tool about `l2`, axis 2 the workpiece about `l3`); vectors v1, v2 (7-12),
/// offsets (24, 25), Hirth grids (26-29), limits (30-33), name (34), fine offsets (41-65,
/// added). Other data sets, other tool data, `CHANDATA(…)` and comments are skipped.
///
/// Returns 0 with `machine` written, or with it untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_PARSE` (a malformed line or number), `CNCROT_STATUS_UNKNOWN_WORD` (a
/// parameter that does not exist, anything that is not an assignment),
/// `CNCROT_STATUS_NOT_A_NUMBER` (a variable or expression where a number must stand:
/// `R1`), `CNCROT_STATUS_MISSING_WORD` (no number after `=`),
/// `CNCROT_STATUS_NAME_TOO_LONG`, `CNCROT_STATUS_UNKNOWN_HEAD` (no parameter of that data
/// set), `CNCROT_STATUS_BAD_ARGUMENT` (`data_set` < 1, `len` beyond the largest object, a
/// type other than T/P/M, v2 without v1, parallel axes, min > max, a Hirth increment
/// negative or below `CNCROT_MACHINE_HIRTH_STEP_MIN_DEG`), `CNCROT_STATUS_OUT_OF_RANGE` (a
/// nonzero number outside 1e-100..1e100 in magnitude; an offset, limit, Hirth offset or
/// point beyond the bounds of `cncrot_machine`). The line of an error:
/// `cncrot_machine_carr_error_line`.
///
/// # Safety
/// `machine` points to a writable `cncrot_machine`, `text` to `len` readable bytes.
///
/// ```c
/// const char *t = "$TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=-1\n"
///                 "$TC_CARR7[1]=1 $TC_CARR8[1]=0 $TC_CARR9[1]=0\n$TC_CARR23[1]=\"P\"\n";
/// cncrot_machine m;
/// cncrot_machine_from_carr(&m, t, strlen(t), 1);   // table A carrying C
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_from_carr(
    machine: *mut cncrot_machine,
    text: *const c_char,
    len: usize,
    data_set: i32,
) -> i32 {
    guard(|| {
        non_null(&[machine.is_null(), text.is_null()])?;
        let m = machine_from_carr(bytes(text, len)?, data_set).map_err(|e| e.error)?;
        machine.write_unaligned(c_of(&m));
        Ok(cncrot_status::Ok)
    })
}

/// The line at which `cncrot_machine_from_carr` refuses the same text: its status, and the
/// 1-based line in `*line`: the line that could not be read, or for a data set that does
/// not make a machine (a type other than T/P/M, parallel axes, a negative Hirth increment)
/// the line that last assigned the parameter at fault; 0 when the text was read, for
/// `CNCROT_STATUS_UNKNOWN_HEAD` (no parameter of the data set) and for `data_set` < 1.
///
/// Returns the status `cncrot_machine_from_carr` returns for the text (with `*line`
/// written): 0, `CNCROT_STATUS_PARSE`, `CNCROT_STATUS_UNKNOWN_WORD`,
/// `CNCROT_STATUS_NOT_A_NUMBER`, `CNCROT_STATUS_MISSING_WORD`,
/// `CNCROT_STATUS_NAME_TOO_LONG`, `CNCROT_STATUS_UNKNOWN_HEAD`,
/// `CNCROT_STATUS_BAD_ARGUMENT`, `CNCROT_STATUS_OUT_OF_RANGE`; or, with nothing written,
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_ARGUMENT` (`len` beyond the largest
/// object).
///
/// # Safety
/// `text` points to `len` readable bytes, `line` to a writable `int32_t`.
///
/// ```c
/// int32_t line;
/// if (cncrot_machine_carr_error_line(t, strlen(t), 1, &line) < 0) printf("line %d\n", line);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_carr_error_line(
    text: *const c_char,
    len: usize,
    data_set: i32,
    line: *mut i32,
) -> i32 {
    guard(|| {
        non_null(&[text.is_null(), line.is_null()])?;
        let (status, at) = match machine_from_carr(bytes(text, len)?, data_set) {
            Ok(_) => (cncrot_status::Ok, 0),
            Err(e) => (e.error.into(), i32::try_from(e.line).unwrap_or(i32::MAX)),
        };
        line.write_unaligned(at);
        Ok(status)
    })
}

/// The accessory `name` (NUL-terminated) of a HEAD_DEF table as a two-axis swivel head
/// with axis directions `v1` (outer) and `v2` (inner): HEAD_DEF gives the lengths, the
/// directions come from the caller. Pivots \[derived\]: the tool adapter at the origin,
/// `p2 = (OFFS_L2_X, OFFS_L2_Y, DELTA_L2)`,
/// `p1 = p2 + (OFFS_L1_X, OFFS_L1_Y, DELTA_L1) + (OFFS_H1_X, DELTA_H1, OFFS_H1_Z)`.
///
/// Returns 0 with `machine` written, or with it untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_UNKNOWN_HEAD`, `CNCROT_STATUS_NAME_TOO_LONG` (no NUL within 32 bytes of
/// `name`), `CNCROT_STATUS_BAD_ARGUMENT` (a zero or parallel direction, a corrupt or
/// misaligned table, an entry's name not printable ASCII), `CNCROT_STATUS_NOT_FINITE` (a
/// direction, the entry's lengths, or a pivot that overflows), `CNCROT_STATUS_OUT_OF_RANGE`
/// (a pivot coordinate beyond ±`CNCROT_MACHINE_LENGTH_MAX_MM`).
///
/// # Safety
/// `machine` points to a writable `cncrot_machine`, `heads` to a table (aligned as
/// `cncrot_head_table`), `name` to a NUL-terminated string, `v1`, `v2` to 3 doubles.
///
/// ```c
/// double z[3] = {0, 0, 1}, x[3] = {1, 0, 0};
/// cncrot_machine_from_head(&m, &heads, "IFVW207S", z, x);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_from_head(
    machine: *mut cncrot_machine,
    heads: *const cncrot_head_table,
    name: *const c_char,
    v1: *const f64,
    v2: *const f64,
) -> i32 {
    guard(|| {
        non_null(&[
            machine.is_null(),
            heads.is_null(),
            name.is_null(),
            v1.is_null(),
            v2.is_null(),
        ])?;
        let mut field = [0u8; CNCROT_NAME_SIZE];
        let mut len = None;
        for (k, n) in field.iter_mut().enumerate() {
            *n = byte(name.add(k).read());
            if *n == 0 {
                len = Some(k);
                break;
            }
        }
        let len = len.ok_or(cncrot_status::NameTooLong)?;
        let (v1, v2) = (read_finite::<3>(v1)?, read_finite::<3>(v2)?);
        if heads.align_offset(core::mem::align_of::<cncrot_head_table>()) != 0 {
            return Err(cncrot_status::BadArgument);
        }
        let Some(table) = heads.as_ref() else {
            return Err(cncrot_status::NullPointer);
        };
        let wanted = field.get(..len).unwrap_or(&[]);
        let lookup = CHeads(table);
        let entry = lookup.find(wanted)?;
        let c = entry.ok_or(cncrot_status::UnknownHead)?;
        let mut head = Head {
            len: len as u8,
            allowed: c.allowed == 1,
            delta: c.delta,
            offsets: c.offsets,
            ..Head::default()
        };
        for (d, &s) in head.name.iter_mut().zip(wanted) {
            *d = s;
        }
        let m = head.machine(v1, v2)?;
        machine.write_unaligned(c_of(&m));
        Ok(cncrot_status::Ok)
    })
}

/// Checks `machine` whole and seals it: directions stored as unit vectors, the seal
/// written. What a caller does once after filling or editing a description by hand (the
/// functions that write one seal it themselves), so that the calls that read it (the
/// five-axis transformation in every interpolation cycle) check the seal instead of every
/// field. A sealed description computes exactly as it did unsealed.
///
/// Returns 0, or with `machine` untouched: `CNCROT_STATUS_NULL_POINTER`, and the statuses
/// of a description that is not a machine (`CNCROT_STATUS_BAD_ARGUMENT`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_OUT_OF_RANGE`,
/// `CNCROT_STATUS_NAME_TOO_LONG`: see `cncrot_machine`).
///
/// # Safety
/// `machine` points to a writable `cncrot_machine`.
///
/// ```c
/// m.axes[0].min_deg = -30;       // edited by hand: the seal no longer matches
/// cncrot_machine_seal(&m);       // checked once, sealed again
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_seal(machine: *mut cncrot_machine) -> i32 {
    guard(|| {
        non_null(&[machine.is_null()])?;
        if machine.align_offset(core::mem::align_of::<cncrot_machine>()) != 0 {
            return Err(cncrot_status::BadArgument);
        }
        // Checked whole whatever its seal says: a seal that matches contents it should not
        // (forged, or matched by chance) is not passed on.
        let mut m = Machine::EMPTY;
        match machine.as_ref() {
            Some(d) => machine_of(d, &mut m)?,
            None => return Err(cncrot_status::NullPointer),
        }
        machine.write(c_of(&m));
        Ok(cncrot_status::Ok)
    })
}

/// Adds a rotary axis to `machine`: it turns the tool (`work_side` 0) or the workpiece (1)
/// about the line through `point` along `direction` (machine coordinates, every axis at its
/// initial position), and is carried by the axes already on its side. `min_deg`,
/// `max_deg`: travel limits, both 0 for a modulo axis without limits. The direction is
/// stored as a unit vector; offset and Hirth grid may be set in the struct afterwards.
///
/// Returns 0, or with `machine` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_TABLE_FULL` (three axes already), `CNCROT_STATUS_BAD_FLAG` (`work_side`),
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_BAD_ARGUMENT` (a zero direction,
/// `min > max`, an axis parallel to its neighbour in the chain), `CNCROT_STATUS_OUT_OF_RANGE`
/// (a limit of magnitude `CNCROT_MACHINE_ANGLE_MAX_DEG` or more, a point coordinate beyond
/// ±`CNCROT_MACHINE_LENGTH_MAX_MM`); and for a description already in `machine` that is not
/// a machine, `CNCROT_STATUS_BAD_ARGUMENT`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE`, `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a
/// machine: see `cncrot_machine`).
///
/// # Safety
/// `machine` points to a writable `cncrot_machine`, `direction` and `point` to 3 doubles.
///
/// ```c
/// cncrot_machine m;
/// memset(&m, 0, sizeof m);
/// double z[3] = {0, 0, 1}, y[3] = {0, 1, 0}, o[3] = {0, 0, 0}, p[3] = {0, 0, 150};
/// cncrot_machine_add_axis(&m, 0, z, o, 0, 0);        // C, modulo
/// cncrot_machine_add_axis(&m, 0, y, p, -100, 100);   // B on C, pivot 150 above the adapter
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_add_axis(
    machine: *mut cncrot_machine,
    work_side: i32,
    direction: *const f64,
    point: *const f64,
    min_deg: f64,
    max_deg: f64,
) -> i32 {
    guard(|| {
        non_null(&[machine.is_null(), direction.is_null(), point.is_null()])?;
        let mut m = Machine::EMPTY;
        load_into(machine, &mut m)?;
        let new = cncrot_machine_axis {
            work_side,
            direction: read_finite::<3>(direction)?,
            point: read_finite::<3>(point)?,
            min_deg,
            max_deg,
            ..EMPTY_AXIS
        };
        m.push_axis(axis_of(&new)?)?;
        machine.write_unaligned(c_of(&m));
        Ok(cncrot_status::Ok)
    })
}

/// The tool frame relative to the workpiece, `F = W⁻¹·T` (with the tool's base direction
/// turned onto +Z), at axis positions `axes_deg` (degrees, in the order the axes were
/// added; unused ones 0): its third column is the tool direction in workpiece coordinates,
/// `F·(0, 0, −L, 1)` the tool tip of a tool of length L.
///
/// Returns 0, or with `frame` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE` (a position), `CNCROT_STATUS_BAD_ARGUMENT` (an unused
/// position not 0), `CNCROT_STATUS_BAD_ARGUMENT`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE`, `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a
/// machine: see `cncrot_machine`).
///
/// # Safety
/// `machine` points to a `cncrot_machine`, `axes_deg` to 3 and `frame` to 16 doubles.
///
/// ```c
/// double ax[3] = {90, 30, 0}, f[16];
/// cncrot_machine_forward(&m, ax, f);   // tool direction (f[2], f[6], f[10])
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_forward(
    machine: *const cncrot_machine,
    axes_deg: *const f64,
    frame: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[machine.is_null(), axes_deg.is_null(), frame.is_null()])?;
        with_machine(machine, |m| {
            let f = m.forward(read_finite::<3>(axes_deg)?)?;
            write_frame(frame, &f)?;
            Ok(cncrot_status::Ok)
        })
    })
}

/// Every isolated set of axis positions, each within (-180, 180], whose tool frame has the
/// orientation of `frame` (its translation is not used): the whole rotation with three
/// axes, the tool direction (third column) with fewer. Travel limits are ignored (see
/// `cncrot_machine_choose`). `solutions_deg` receives `*count` rows of 3 (unused axes 0).
///
/// Returns 0; `CNCROT_STATUS_FREE_AXIS` at a singular pose (the target direction along an
/// axis, which is free: the family once, the free axis at 0); or with nothing written:
/// `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_UNREACHABLE`, `CNCROT_STATUS_NO_ROOM`
/// (`capacity` below the count; 2 always suffice), `CNCROT_STATUS_NOT_A_ROTATION`,
/// `CNCROT_STATUS_NOT_FINITE` (the frame), `CNCROT_STATUS_BAD_ARGUMENT`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE`, `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a
/// machine: see `cncrot_machine`).
///
/// # Safety
/// `machine` points to a `cncrot_machine`, `frame` to 16 doubles, `solutions_deg` to
/// `3·capacity` writable doubles, `count` to a writable `size_t`.
///
/// ```c
/// double sol[2 * 3]; size_t n;
/// cncrot_machine_inverse(&m, f, sol, 2, &n);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_inverse(
    machine: *const cncrot_machine,
    frame: *const f64,
    solutions_deg: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> i32 {
    guard(|| {
        non_null(&[
            machine.is_null(),
            frame.is_null(),
            solutions_deg.is_null(),
            count.is_null(),
        ])?;
        with_machine(machine, |m| {
            let target = read_frame(frame)?;
            let s = m.inverse(&target.rotation)?;
            let rows = s.as_slice();
            if rows.len() > capacity {
                return Err(cncrot_status::NoRoom);
            }
            if !rows.iter().flatten().all(|x| x.is_finite()) {
                return Err(cncrot_status::OutOfRange);
            }
            for (k, row) in rows.iter().enumerate() {
                write::<3>(solutions_deg.add(3 * k), *row)?;
            }
            count.write_unaligned(rows.len());
            Ok(if s.free {
                cncrot_status::FreeAxis
            } else {
                cncrot_status::Ok
            })
        })
    })
}

/// The axis positions to move to for the orientation of `frame`, seen from the current
/// positions `current_deg`: every solution brought to the whole turn nearest to the
/// current position (computed 10°, current 750° → 730°; of two half a turn away, the one
/// nearer 0: -90° from 90°, not 270°), or within the travel limits (without limits within
/// ±`CNCROT_MACHINE_ANGLE_MAX_DEG`: a turn that would cross it is taken a whole turn back),
/// and snapped to Hirth grids; solutions outside the travel are skipped. A position computed
/// within `CNCROT_MACHINE_TRAVEL_TOLERANCE_DEG` beyond an end of the travel is taken exactly
/// at that end (a target made at an end is reached there; `axes_deg` never lies outside
/// the travel). `rule`: `CNCROT_CHOOSE_CLOSEST` (`reference_axis` 0), `CNCROT_CHOOSE_MINUS`
/// / `_PLUS` (the lower / higher angle in (-180, 180] of axis `reference_axis`, 1-based,
/// whatever the current positions: CYCLE800's
/// direction reference, Heidenhain `SEQ-` / `SEQ+` on the master axis; the other solution
/// when one lies outside the travel), `CNCROT_CHOOSE_INVERSE` (`reference_axis` 0; the
/// other solution of the pair: CYCLE600 `_ROT_INV`), `CNCROT_CHOOSE_POSITIVE_TURN` /
/// `_NEGATIVE_TURN` (axis `reference_axis` turns only up / only down from its current
/// position, the least it must: `G53.1 P1` / `P2`; `CNCROT_STATUS_OUT_OF_TRAVEL` when the
/// travel ends before either solution), `CNCROT_CHOOSE_MASTER_FIRST` (axis `reference_axis`
/// turning the least, then the others, then nearest 0°: Fanuc's `G53.1`).
/// `CNCROT_CHOOSE_INVERSE` returns the
/// closest solution, with status 0, when the other one lies outside the travel or the
/// orientation has only one (a free axis, the edge of a nutating head's cone): compare
/// `axes_deg` with the current positions to tell. A free axis (singular pose) stays at its
/// current position.
///
/// Outputs: `axes_deg` (unused 0), `residual_deg` (Hirth: position minus exact value),
/// `remaining` (the rotation the axes leave to the frame, `Fᵀ·target`: about the tool axis
/// with fewer than three axes, plus the Hirth residual; no translation).
///
/// Returns 0, `CNCROT_STATUS_FREE_AXIS`, `CNCROT_STATUS_SNAPPED` (a Hirth axis left a
/// residual), or with nothing written: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_UNREACHABLE`, `CNCROT_STATUS_OUT_OF_TRAVEL`, `CNCROT_STATUS_BAD_ARGUMENT`
/// (rule, reference axis, an unused current position not 0), `CNCROT_STATUS_OUT_OF_RANGE`
/// (a current position of magnitude `CNCROT_MACHINE_ANGLE_MAX_DEG` or more),
/// `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_NOT_FINITE` (the frame, a current
/// position), `CNCROT_STATUS_BAD_ARGUMENT`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE`, `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a
/// machine: see `cncrot_machine`).
///
/// # Safety
/// `machine` points to a `cncrot_machine`, `frame` and `remaining` to 16 doubles,
/// `current_deg`, `axes_deg`, `residual_deg` to 3.
///
/// ```c
/// double cur[3] = {750, 0, 0}, ax[3], res[3], rem[16];
/// cncrot_machine_choose(&m, f, cur, CNCROT_CHOOSE_CLOSEST, 0, ax, res, rem);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_choose(
    machine: *const cncrot_machine,
    frame: *const f64,
    current_deg: *const f64,
    rule: i32,
    reference_axis: i32,
    axes_deg: *mut f64,
    residual_deg: *mut f64,
    remaining: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            machine.is_null(),
            frame.is_null(),
            current_deg.is_null(),
            axes_deg.is_null(),
            residual_deg.is_null(),
            remaining.is_null(),
        ])?;
        let rule = rule_of(rule, reference_axis)?;
        with_machine(machine, |m| {
            let target = read_frame(frame)?;
            let current = read_finite::<3>(current_deg)?;
            let c = m.choose(&target.rotation, current, rule)?;
            write_choice(&c, axes_deg, residual_deg, remaining)
        })
    })
}

/// The Rust rule for the C `rule` and 1-based `reference_axis`.
pub(super) fn rule_of(rule: i32, reference_axis: i32) -> Result<Rule, cncrot_status> {
    let axis = usize::try_from(reference_axis)
        .ok()
        .and_then(|k| k.checked_sub(1));
    match (rule, axis) {
        (CNCROT_CHOOSE_CLOSEST, None) if reference_axis == 0 => Ok(Rule::Closest),
        (CNCROT_CHOOSE_INVERSE, None) if reference_axis == 0 => Ok(Rule::Inverse),
        (CNCROT_CHOOSE_MINUS, Some(k)) => Ok(Rule::Minus(k)),
        (CNCROT_CHOOSE_PLUS, Some(k)) => Ok(Rule::Plus(k)),
        (CNCROT_CHOOSE_POSITIVE_TURN, Some(k)) => Ok(Rule::PositiveTurn(k)),
        (CNCROT_CHOOSE_NEGATIVE_TURN, Some(k)) => Ok(Rule::NegativeTurn(k)),
        (CNCROT_CHOOSE_MASTER_FIRST, Some(k)) => Ok(Rule::MasterFirst(k)),
        _ => Err(cncrot_status::BadArgument),
    }
}

/// Writes a choice (all outputs checked first) and returns its status.
///
/// # Safety
/// The pointers are non-NULL: `axes`, `residual` to 3, `remaining` to 16 writable doubles.
pub(super) unsafe fn write_choice(
    c: &Choice,
    axes: *mut f64,
    residual: *mut f64,
    remaining: *mut f64,
) -> Result<cncrot_status, cncrot_status> {
    let rem = Frame::from_rotation(c.remaining);
    let h = rem.to_homogeneous();
    let all = c.axes.iter().chain(&c.residual).chain(h.iter().flatten());
    if !all.into_iter().all(|x| x.is_finite()) {
        return Err(cncrot_status::OutOfRange);
    }
    write::<3>(axes, c.axes)?;
    write::<3>(residual, c.residual)?;
    write_frame(remaining, &rem)?;
    Ok(choice_status(c))
}

/// The remark of a choice: a free axis kept, a Hirth axis snapped, or none.
pub(super) fn choice_status(c: &Choice) -> cncrot_status {
    if c.free {
        cncrot_status::FreeAxis
    } else if c.residual.iter().any(|&r| r != 0.0) {
        cncrot_status::Snapped
    } else {
        cncrot_status::Ok
    }
}

/// Tool-tip follow-up: the linear-axis positions `linear_to` that keep the tip of a tool
/// of length `tool_length` (mm) on the same workpiece point when the rotary axes move from
/// `from_deg` to `to_deg`, the linear axes being at `linear_from` before (machine
/// coordinates of the tool adapter's reference point, the origin of the axis points).
///
/// Returns 0, or with `linear_to` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE` (a position, `tool_length`), `CNCROT_STATUS_BAD_ARGUMENT` (an
/// unused position not 0), `CNCROT_STATUS_OUT_OF_RANGE` (a result that overflows),
/// `CNCROT_STATUS_BAD_ARGUMENT`, `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`,
/// `CNCROT_STATUS_OUT_OF_RANGE`, `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a
/// machine: see `cncrot_machine`).
///
/// # Safety
/// `machine` points to a `cncrot_machine`, the arrays to 3 doubles each.
///
/// ```c
/// double from[3] = {0, 0, 0}, to[3] = {0, 90, 0}, lin[3] = {0, 0, 0}, next[3];
/// cncrot_machine_follow(&m, from, to, lin, 100.0, next);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_follow(
    machine: *const cncrot_machine,
    from_deg: *const f64,
    to_deg: *const f64,
    linear_from: *const f64,
    tool_length: f64,
    linear_to: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            machine.is_null(),
            from_deg.is_null(),
            to_deg.is_null(),
            linear_from.is_null(),
            linear_to.is_null(),
        ])?;
        if !tool_length.is_finite() {
            return Err(cncrot_status::NotFinite);
        }
        with_machine(machine, |m| {
            let from = read_finite::<3>(from_deg)?;
            let to = read_finite::<3>(to_deg)?;
            let lin = read_finite::<3>(linear_from)?;
            let next = m.follow_tool_tip(from, to, lin, tool_length)?;
            write::<3>(linear_to, next)?;
            Ok(cncrot_status::Ok)
        })
    })
}

/// The five-axis transformation, forward: the tool's pose in workpiece coordinates at
/// machine axes `axes` — `X, Y, Z` (mm, the machine coordinates of the tool adapter's
/// reference point, as `cncrot_machine_follow` takes them) then the rotary positions 1..3
/// (degrees, in the order the axes were added; unused ones 0) — with a tool of length
/// `tool_length` (mm) along the tool's base direction. `pose` is a 4x4 frame, row-major, in
/// the workpiece coordinates of `cncrot_machine_forward`: its rotation is that function's,
/// its third column the tool direction, its translation the tool tip
/// `W⁻¹·((X, Y, Z) + T·(−L·b))`.
///
/// Real-time: no allocation, no panic, a bounded number of operations (no loop depends on
/// the values), stack within the hot-path bound.
///
/// Returns 0, or with `pose` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE` (an axis, `tool_length`), `CNCROT_STATUS_BAD_ARGUMENT` (an
/// unused rotary position not 0), `CNCROT_STATUS_OUT_OF_RANGE` (`tool_length` or a linear
/// axis beyond ±`CNCROT_MACHINE_LENGTH_MAX_MM`, a result that overflows),
/// `CNCROT_STATUS_BAD_ARGUMENT`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_OUT_OF_RANGE`,
/// `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a machine: see
/// `cncrot_machine`).
///
/// # Safety
/// `machine` points to a `cncrot_machine`, `axes` to 6 and `pose` to 16 doubles.
///
/// ```c
/// double ax[6] = {10, 20, 150, 30, 40, 0}, pose[16];
/// cncrot_machine_tcp_forward(&m, ax, 50.0, pose);   // tip (pose[3], pose[7], pose[11])
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_tcp_forward(
    machine: *const cncrot_machine,
    axes: *const f64,
    tool_length: f64,
    pose: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[machine.is_null(), axes.is_null(), pose.is_null()])?;
        let ax = read_finite::<6>(axes)?;
        if !tool_length.is_finite() {
            return Err(cncrot_status::NotFinite);
        }
        with_machine(machine, |m| {
            let f = m.tcp_forward(ax, tool_length)?;
            write_frame(pose, &f)?;
            Ok(cncrot_status::Ok)
        })
    })
}

/// The five-axis transformation, inverse: the machine axes (`X, Y, Z`, rotary 1..3, as
/// `cncrot_machine_tcp_forward` takes them) that put the tip of a tool of length
/// `tool_length` at the translation of `pose` (a 4x4 frame, row-major, in workpiece
/// coordinates) with the tool direction of its third column; with three rotary axes the
/// whole rotation of `pose`, with fewer the direction only (the turn about the tool is
/// left to the frame, as in `cncrot_machine_inverse`).
///
/// The rotary solution is the one continuous with `previous` (the last cycle's output):
/// each solution's whole turns unwound toward the previous positions, within the travel
/// limits and Hirth grids, the closest taken (as `cncrot_machine_choose` with
/// `CNCROT_CHOOSE_CLOSEST`); then the linear axes `W·tip − T·(−L·b)`. At a pole (the
/// direction along a rotary axis) the free axis stays at its previous position
/// (`CNCROT_STATUS_FREE_AXIS`); near one the exact solution is taken, so the axis turns as
/// fast as the path requires and no faster. `previous`'s linear part is only checked for
/// finiteness. On a Hirth axis the position is snapped (`CNCROT_STATUS_SNAPPED`): the
/// linear axes still put the tip on the target; the direction is off by the residual.
///
/// No allocation, no panic, a bounded number of operations (no loop depends on the
/// values). Stack and time are measured in `docs/kinematics.md`: on a sealed description
/// within the interpolation cycle's 2 048 bytes (about 1.9 KiB), on its common and its
/// general way.
///
/// Returns 0, `CNCROT_STATUS_FREE_AXIS`, `CNCROT_STATUS_SNAPPED`, or with `axes`
/// untouched: `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_NOT_FINITE` (the pose,
/// `tool_length`, `previous`), `CNCROT_STATUS_NOT_A_ROTATION`,
/// `CNCROT_STATUS_UNREACHABLE` (no rotary positions give the direction),
/// `CNCROT_STATUS_OUT_OF_TRAVEL` (only outside the travel limits),
/// `CNCROT_STATUS_BAD_ARGUMENT` (an unused previous rotary position not 0),
/// `CNCROT_STATUS_OUT_OF_RANGE` (a previous rotary position of magnitude
/// `CNCROT_MACHINE_ANGLE_MAX_DEG` or more, `tool_length` or a coordinate of the tip beyond
/// ±`CNCROT_MACHINE_LENGTH_MAX_MM`, a result that overflows), `CNCROT_STATUS_BAD_ARGUMENT`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_OUT_OF_RANGE`,
/// `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a machine: see
/// `cncrot_machine`).
///
/// # Safety
/// `machine` points to a `cncrot_machine`, `pose` to 16, `previous` and `axes` to 6
/// doubles (`axes` may be `previous`).
///
/// ```c
/// double prev[6] = {0}, ax[6];
/// for (int i = 0; i < n; i++) {          // one CL point per interpolation cycle
///   if (cncrot_machine_tcp_inverse(&m, poses[i], 50.0, prev, ax) < 0) break;
///   memcpy(prev, ax, sizeof ax);
/// }
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_tcp_inverse(
    machine: *const cncrot_machine,
    pose: *const f64,
    tool_length: f64,
    previous: *const f64,
    axes: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            machine.is_null(),
            pose.is_null(),
            previous.is_null(),
            axes.is_null(),
        ])?;
        // The rotation is checked by `tcp_inverse` (once: this runs every cycle).
        let target = read_frame_unchecked(pose)?;
        let prev = read_finite::<6>(previous)?;
        if !tool_length.is_finite() {
            return Err(cncrot_status::NotFinite);
        }
        with_machine(machine, |m| {
            let t = m.tcp_inverse(&target, tool_length, prev)?;
            write_tcp(axes, &t)
        })
    })
}

/// `cncrot_machine_tcp_inverse` with the rotary solution picked by `rule` and
/// `reference_axis` as in `cncrot_machine_choose`: `CNCROT_CHOOSE_CLOSEST` (`reference_axis`
/// 0; the same as `cncrot_machine_tcp_inverse`), `CNCROT_CHOOSE_MINUS` / `_PLUS` (a priority
/// axis, 1-based: the solution with its lower / higher angle in (-180, 180], as `SEQ-`/`SEQ+` or
/// CYCLE800's `_DIR` ask; the other one when that lies outside the travel),
/// `CNCROT_CHOOSE_POSITIVE_TURN` / `_NEGATIVE_TURN` (a priority axis and its direction of
/// travel: it turns only up / only down, the least it must, as `G53.1 P1` / `P2` ask),
/// `CNCROT_CHOOSE_MASTER_FIRST` (a priority axis turning the least, then the others, as
/// Fanuc's `G53.1` chooses), `CNCROT_CHOOSE_INVERSE` (`reference_axis` 0; the other solution
/// of the pair). Whole turns
/// are unwound toward `previous` in every case (the turning axis: the first turn met its
/// way).
///
/// Returns 0, `CNCROT_STATUS_FREE_AXIS`, `CNCROT_STATUS_SNAPPED`, or with `axes`
/// untouched: `CNCROT_STATUS_NULL_POINTER`, `CNCROT_STATUS_BAD_ARGUMENT` (a rule or
/// reference axis that is not one, an unused previous rotary position not 0),
/// `CNCROT_STATUS_NOT_FINITE` (the pose, `tool_length`, `previous`),
/// `CNCROT_STATUS_NOT_A_ROTATION`, `CNCROT_STATUS_UNREACHABLE`,
/// `CNCROT_STATUS_OUT_OF_TRAVEL`, `CNCROT_STATUS_OUT_OF_RANGE` (a previous rotary position
/// of magnitude `CNCROT_MACHINE_ANGLE_MAX_DEG` or more, `tool_length` or a coordinate of
/// the tip beyond ±`CNCROT_MACHINE_LENGTH_MAX_MM`, a result that overflows),
/// `CNCROT_STATUS_BAD_ARGUMENT`,
/// `CNCROT_STATUS_BAD_FLAG`, `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_OUT_OF_RANGE`,
/// `CNCROT_STATUS_NAME_TOO_LONG` (a description that is not a machine: see
/// `cncrot_machine`).
///
/// # Safety
/// As `cncrot_machine_tcp_inverse`.
///
/// ```c
/// // B is the priority axis: its lower position.
/// cncrot_machine_tcp_inverse_rule(&m, pose, 50.0, prev, CNCROT_CHOOSE_MINUS, 2, ax);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_machine_tcp_inverse_rule(
    machine: *const cncrot_machine,
    pose: *const f64,
    tool_length: f64,
    previous: *const f64,
    rule: i32,
    reference_axis: i32,
    axes: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            machine.is_null(),
            pose.is_null(),
            previous.is_null(),
            axes.is_null(),
        ])?;
        let rule = rule_of(rule, reference_axis)?;
        let target = read_frame_unchecked(pose)?;
        let prev = read_finite::<6>(previous)?;
        if !tool_length.is_finite() {
            return Err(cncrot_status::NotFinite);
        }
        with_machine(machine, |m| {
            let t = m.tcp_inverse_with(&target, tool_length, prev, rule)?;
            write_tcp(axes, &t)
        })
    })
}

/// The pose of a CL point, as the five-axis transformation takes it: a 4x4 frame,
/// row-major, whose translation is the tool tip `tip` and whose third column is `direction`
/// made a unit vector (any length but zero), X' the component of the workpiece X axis
/// perpendicular to it (of Y when the direction's x component is 0.9 or more in magnitude),
/// Y' = Z' x X'. With fewer than three rotary axes a machine matches the direction only, so
/// this X' does not matter; with three it chooses the turn about the tool, and `cncrot
/// path`, the five-axis program reader and MATLAB's CL rows carry X' from where the machine
/// stands instead (`cncrot_cl_pose_toward`): this X' switches at 0.9.
///
/// Returns 0, or with `pose` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_DEGENERATE` (a zero direction).
///
/// # Safety
/// `tip` and `direction` point to 3 doubles, `pose` to 16 writable doubles.
///
/// ```c
/// double tip[3] = {10, 20, 5}, dir[3] = {0, 0, 2}, pose[16];
/// cncrot_cl_pose(tip, dir, pose);   // the identity rotation, translation (10, 20, 5)
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_cl_pose(
    tip: *const f64,
    direction: *const f64,
    pose: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[tip.is_null(), direction.is_null(), pose.is_null()])?;
        let t = read_finite::<3>(tip)?;
        let d = read_finite::<3>(direction)?;
        let f = crate::kinematics::cl_pose(t, d)?;
        write_frame(pose, &f)?;
        Ok(cncrot_status::Ok)
    })
}

/// The pose of a CL point continuous with `previous` (a 4x4 frame, row-major, whose
/// rotation is the last point's: the last pose, or `cncrot_machine_tcp_forward` of the
/// axes the machine stands at): as `cncrot_cl_pose`, but X' is the previous X' carried
/// along by the smallest turn that takes the previous tool direction to `direction`, so
/// that the tool does not turn about itself between two points. For machines of three
/// rotary axes, where X' chooses the turn about the tool: `cncrot_cl_pose`'s X' switches
/// from X to Y where the direction's x component passes 0.9, and every axis would jump.
/// A direction 120 degrees or more from the previous one gets `cncrot_cl_pose`'s frame.
/// Only the rotation of `previous` is read (its translation must be finite).
///
/// Returns 0, or with `pose` untouched: `CNCROT_STATUS_NULL_POINTER`,
/// `CNCROT_STATUS_NOT_FINITE`, `CNCROT_STATUS_DEGENERATE` (a zero direction),
/// `CNCROT_STATUS_NOT_A_ROTATION` (`previous`, also its last row other than 0 0 0 1).
///
/// # Safety
/// `tip` and `direction` point to 3 doubles, `previous` to 16, `pose` to 16 writable
/// doubles (it may be `previous` itself).
///
/// ```c
/// double tip[3] = {10, 20, 5}, x[3] = {1, 0, 0}, pose[16];
/// // From the tool along Z tilted 60 degrees about Y (pose) to the tool along X:
/// // X' stays in the XZ plane, (0, 0, -1), where cncrot_cl_pose would take Y.
/// cncrot_cl_pose_toward(tip, x, pose, pose);
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub unsafe extern "C" fn cncrot_cl_pose_toward(
    tip: *const f64,
    direction: *const f64,
    previous: *const f64,
    pose: *mut f64,
) -> i32 {
    guard(|| {
        non_null(&[
            tip.is_null(),
            direction.is_null(),
            previous.is_null(),
            pose.is_null(),
        ])?;
        let t = read_finite::<3>(tip)?;
        let d = read_finite::<3>(direction)?;
        // Its rotation is checked by `cl_pose_toward` (once).
        let before = read_frame_unchecked(previous)?;
        let f = crate::kinematics::cl_pose_toward(t, d, &before.rotation)?;
        write_frame(pose, &f)?;
        Ok(cncrot_status::Ok)
    })
}

/// Writes the axes of a five-axis solution and returns its status.
///
/// # Safety
/// `axes` is non-NULL and points to 6 writable doubles.
pub(super) unsafe fn write_tcp(
    axes: *mut f64,
    t: &crate::kinematics::Tcp,
) -> Result<cncrot_status, cncrot_status> {
    write::<6>(axes, t.axes)?;
    Ok(if t.free {
        cncrot_status::FreeAxis
    } else if t.residual.iter().any(|&r| r != 0.0) {
        cncrot_status::Snapped
    } else {
        cncrot_status::Ok
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The header's bounds are the ones the Rust API applies.
    #[test]
    fn the_c_constants_are_the_rust_bounds() {
        use crate::kinematics::{HIRTH_STEP_MIN, LENGTH_MAX, TRAVEL_TOLERANCE};
        assert_eq!(CNCROT_MACHINE_TRAVEL_TOLERANCE_DEG, TRAVEL_TOLERANCE);
        assert_eq!(CNCROT_MACHINE_ANGLE_MAX_DEG, crate::CLOSEST_MAX);
        assert_eq!(CNCROT_MACHINE_LENGTH_MAX_MM, LENGTH_MAX);
        assert_eq!(CNCROT_MACHINE_HIRTH_STEP_MIN_DEG, HIRTH_STEP_MIN);
    }
}
