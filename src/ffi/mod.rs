//! The C boundary. No mathematics here: every export validates its arguments, calls the
//! Rust API and writes the results.
//!
//! The rules every export follows:
//! - all pointers are checked for NULL first, then flags and codes, then every input float
//!   for finiteness; the first failure is returned;
//! - outputs are written only on success (status >= 0), and only after all computation, so
//!   an output may alias an input; a result that is not finite (finite inputs near
//!   `DBL_MAX` can overflow) is not written but reported as `CNCROT_STATUS_OUT_OF_RANGE`;
//! - nothing panics: `c_tests/no_panic.sh` proves that no export contains a reachable panic
//!   (each carries `#[no_panic]` under the feature `no-panic-proof`); with `std` each body
//!   also runs under `catch_unwind`, and a panic would become `CNCROT_STATUS_INTERNAL`;
//! - integers from C are validated, never transmuted into Rust enums.

mod batch;
mod cycle600;
mod dialects;
mod frame;
mod heads;
mod machine;
mod probe;
mod program;
mod rotation;
mod toolpath;

pub use batch::*;
pub use cycle600::*;
pub use dialects::*;
pub use frame::*;
pub use heads::*;
pub use machine::*;
pub use probe::*;
pub use program::*;
pub use rotation::*;
pub use toolpath::*;

use crate::{Convention, Error, Kind};
use core::ffi::c_char;

/// Status of every `cncrot_` function: 0 success, positive success with a remark, negative
/// an error (outputs untouched).
#[allow(non_camel_case_types)]
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum cncrot_status {
    /// Success.
    Ok = 0,
    /// Success; the decomposition is singular (only θ1 ± θ3 determined, θ3 set to 0).
    Singular = 1,
    /// Success at a singular pose of the machine: a rotary axis is free (the target
    /// direction lies along it) and was kept at its current position (at 0 in
    /// `cncrot_machine_inverse`, which returns the family once).
    FreeAxis = 2,
    /// Success; a Hirth axis was snapped to its grid: the residual is in the remaining
    /// frame.
    Snapped = 3,
    /// Success; the program block does not concern the frame (motion, tool, M and S words,
    /// program structure, a comment, a blank line): the state is unchanged.
    Passed = 4,
    /// Success; the program block changes the frame in a way the library does not follow
    /// (a work-offset or preset selection, a table or system-variable write, mirroring,
    /// scaling, a tilt that needs the machine): the state is unchanged and may differ from
    /// the control's.
    NotFollowed = 5,
    /// Success; the probed plane's Z' was turned to the side asked for (the tool's): the
    /// order of the points gave the other side.
    Turned = 6,
    /// A pointer argument is NULL.
    NullPointer = -1,
    /// A floating-point argument is NaN or infinite.
    NotFinite = -2,
    /// A 0/1 flag has another value.
    BadFlag = -3,
    /// An axis-sequence code is outside 0..63 or repeats an axis.
    BadSequence = -4,
    /// A decomposition target has fewer than three rotations.
    IncompleteSequence = -5,
    /// A matrix is not a rotation (see `CNCROT_ROTATION_TOLERANCE`) or a frame's last row is
    /// not 0 0 0 1.
    NotARotation = -6,
    /// `cncrot_nearest_rotation`: singular matrix, or nearest to a reflection.
    Degenerate = -7,
    /// A parameter outside its allowed values.
    BadArgument = -8,
    /// Not available without a machine description (rotary-axis positions need one).
    NotAvailable = -9,
    /// The accessory name is not in the head table, or the data set not in the swivel data.
    UnknownHead = -10,
    /// A name is longer than its field.
    NameTooLong = -11,
    /// Text could not be read: a HEAD_DEF line, or a malformed number in a program line.
    Parse = -12,
    /// The head table is full.
    TableFull = -13,
    /// A result would overflow (finite inputs too large, e.g. translations near `DBL_MAX`).
    OutOfRange = -14,
    /// A restored `cncrot_cycle600_gud` or `cncrot_program` is not one this library wrote:
    /// its format or checksum is wrong (storage corruption, an edited field, another
    /// version), or it is neither all zero bytes nor well-formed.
    BadState = -15,
    /// Points that must differ coincide (probing, `PLANE POINTS`).
    Coincident = -16,
    /// Points or directions that must span a plane lie on one line.
    Collinear = -17,
    /// Too few points (a plane needs three).
    TooFew = -18,
    /// A program line has a word the dialect does not have there, or one twice.
    UnknownWord = -19,
    /// A program line has a variable or expression (`R1`, `Q120`, `#100`) where a number must
    /// stand.
    NotANumber = -20,
    /// A program line lacks a word its command requires.
    MissingWord = -21,
    /// A program line is longer than the controller accepts.
    LineTooLong = -22,
    /// The caller's text buffer is too small.
    NoRoom = -23,
    /// No positions of the machine's rotary axes give the orientation.
    Unreachable = -24,
    /// The orientation is reachable only outside the rotary axes' travel limits.
    OutOfTravel = -25,
    /// A frame with an origin for a form without origin words: shift the datum first,
    /// then write the rotation alone.
    HasOrigin = -26,
    /// Internal failure (a caught panic): a bug in cncrot, please report it.
    Internal = -100,
}

/// The tolerance of the rotation check: the largest element of `MᵀM − I` accepted.
/// Matrices printed to four decimals stay below 2e-4; more distorted ones (raw probe data)
/// must go through `cncrot_nearest_rotation` deliberately.
pub const CNCROT_ROTATION_TOLERANCE: f64 = 1e-3;

impl From<Error> for cncrot_status {
    fn from(e: Error) -> cncrot_status {
        match e {
            Error::NotFinite => cncrot_status::NotFinite,
            Error::BadFlag => cncrot_status::BadFlag,
            Error::BadSequence => cncrot_status::BadSequence,
            Error::IncompleteSequence => cncrot_status::IncompleteSequence,
            Error::NotARotation => cncrot_status::NotARotation,
            Error::Degenerate => cncrot_status::Degenerate,
            Error::BadArgument => cncrot_status::BadArgument,
            Error::NotAvailable => cncrot_status::NotAvailable,
            Error::UnknownHead => cncrot_status::UnknownHead,
            Error::NameTooLong => cncrot_status::NameTooLong,
            Error::Parse => cncrot_status::Parse,
            Error::TableFull => cncrot_status::TableFull,
            Error::OutOfRange => cncrot_status::OutOfRange,
            Error::BadState => cncrot_status::BadState,
            Error::Coincident => cncrot_status::Coincident,
            Error::Collinear => cncrot_status::Collinear,
            Error::TooFew => cncrot_status::TooFew,
            Error::UnknownWord => cncrot_status::UnknownWord,
            Error::NotANumber => cncrot_status::NotANumber,
            Error::MissingWord => cncrot_status::MissingWord,
            Error::LineTooLong => cncrot_status::LineTooLong,
            Error::NoRoom => cncrot_status::NoRoom,
            Error::Unreachable => cncrot_status::Unreachable,
            Error::OutOfTravel => cncrot_status::OutOfTravel,
            Error::HasOrigin => cncrot_status::HasOrigin,
        }
    }
}

/// The name and meaning of a status, as a static NUL-terminated string (never NULL;
/// unknown values give "CNCROT_STATUS_UNKNOWN: not a cncrot status"): its name, a colon and
/// what it means.
///
/// ```c
/// int32_t s = cncrot_matrix_from_angles(1, 57, angles, m);
/// if (s < 0) fprintf(stderr, "cncrot: %s\n", cncrot_status_str(s));
/// ```
#[cfg_attr(feature = "no-panic-proof", no_panic::no_panic)]
#[no_mangle]
pub extern "C" fn cncrot_status_str(status: i32) -> *const c_char {
    // The texts are the crate's one status table (`Error::message` says the same).
    let s =
        crate::error::status_text(status).unwrap_or(c"CNCROT_STATUS_UNKNOWN: not a cncrot status");
    s.as_ptr()
}

type Outcome = Result<cncrot_status, cncrot_status>;

/// Runs an export's body; with `std`, a panic becomes `Internal` instead of unwinding into C.
/// The no-panic proof (feature `no-panic-proof`) leaves out the boundary, so that a panic
/// path inside the body reaches the `#[no_panic]` guard of the export and fails the link.
#[inline(always)]
fn guard(body: impl FnOnce() -> Outcome) -> i32 {
    #[cfg(all(feature = "std", not(feature = "no-panic-proof")))]
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(body))
        .unwrap_or(Err(cncrot_status::Internal));
    #[cfg(any(not(feature = "std"), feature = "no-panic-proof"))]
    let outcome = body();
    match outcome {
        Ok(s) | Err(s) => s as i32,
    }
}

fn status_of(singular: bool) -> cncrot_status {
    if singular {
        cncrot_status::Singular
    } else {
        cncrot_status::Ok
    }
}

/// A C `char` as a byte: `char` is signed on x86-64 and unsigned on AArch64, where the cast
/// is the identity (hence the allowance).
#[allow(clippy::unnecessary_cast)]
#[inline(always)]
fn byte(c: core::ffi::c_char) -> u8 {
    c as u8
}

/// Fails with `NullPointer` when any pointer is NULL.
fn non_null(ptrs: &[bool]) -> Result<(), cncrot_status> {
    if ptrs.iter().any(|&is_null| is_null) {
        Err(cncrot_status::NullPointer)
    } else {
        Ok(())
    }
}

/// Whether every element is finite, without a branch per element (the checks of a matrix
/// are a tenth of a decomposition's instructions when each returns early).
#[inline(always)]
fn all_finite<const N: usize>(v: &[f64; N]) -> bool {
    v.iter().fold(true, |ok, x| ok & x.is_finite())
}

/// Reads `N` doubles and checks each for finiteness.
///
/// # Safety
/// `p` is non-NULL and points to `N` readable doubles.
unsafe fn read_finite<const N: usize>(p: *const f64) -> Result<[f64; N], cncrot_status> {
    let v: [f64; N] = core::array::from_fn(|k| p.add(k).read_unaligned());
    if all_finite(&v) {
        Ok(v)
    } else {
        Err(cncrot_status::NotFinite)
    }
}

/// Writes `N` results, or none when one of them is not finite (finite inputs can overflow:
/// translations near `f64::MAX`), so that an output is either valid or untouched.
///
/// # Safety
/// `p` is non-NULL and points to `N` writable doubles.
unsafe fn write<const N: usize>(p: *mut f64, v: [f64; N]) -> Result<(), cncrot_status> {
    if !all_finite(&v) {
        return Err(cncrot_status::OutOfRange);
    }
    for (k, x) in v.into_iter().enumerate() {
        p.add(k).write_unaligned(x);
    }
    Ok(())
}

/// # Safety
/// `p` is non-NULL and points to 9 readable doubles.
unsafe fn read_matrix(p: *const f64) -> Result<crate::Matrix, cncrot_status> {
    let v: [f64; 9] = read_finite(p)?;
    Ok([[v[0], v[1], v[2]], [v[3], v[4], v[5]], [v[6], v[7], v[8]]])
}

/// Runs `f` on the caller's 9 doubles as a matrix, unchecked: only for `f` that pass it to
/// `check_rotation`, which refuses non-finite elements with the same status.
///
/// An aligned array (every `double` array C or MATLAB allocates) is read where it is. A
/// copy on the stack, read back at once by the decomposition's 16-byte loads across the
/// copy's stores, defeated store-to-load forwarding and cost a third of the call. Misaligned
/// pointers still work, through a copy.
///
/// # Safety
/// `p` is non-NULL and points to 9 readable doubles, not written while `f` runs.
#[inline(always)]
unsafe fn with_matrix<R>(p: *const f64, f: impl FnOnce(&crate::Matrix) -> R) -> R {
    let p = p.cast::<crate::Matrix>();
    if p.is_aligned() {
        f(&*p)
    } else {
        f(&p.read_unaligned())
    }
}

/// # Safety
/// `p` is non-NULL and points to 9 writable doubles.
unsafe fn write_matrix(p: *mut f64, m: &crate::Matrix) -> Result<(), cncrot_status> {
    write::<9>(p, core::array::from_fn(|k| m[k / 3][k % 3]))
}

fn kind(intrinsic: i32) -> Result<Kind, cncrot_status> {
    Ok(Kind::from_flag(intrinsic)?)
}

fn convention(intrinsic: i32, sequence: i32) -> Result<Convention, cncrot_status> {
    Ok(Convention::from_c(intrinsic, sequence)?)
}

/// Only in builds with the feature `no-panic-canary`: an export with a reachable panic (an
/// index from C), on which `c_tests/no_panic.sh` shows that the proof fails.
#[cfg(feature = "no-panic-canary")]
#[no_panic::no_panic]
#[no_mangle]
pub extern "C" fn cncrot_no_panic_canary(index: usize) -> i32 {
    [1, 2, 3][index]
}

#[cfg(all(test, feature = "std"))]
mod tests {
    #[test]
    fn tolerance_constant_matches_the_rust_api() {
        assert_eq!(super::CNCROT_ROTATION_TOLERANCE, crate::ROTATION_TOLERANCE);
    }

    #[test]
    fn every_status_has_a_name() {
        use super::cncrot_status as S;
        let all = [
            S::Ok,
            S::Singular,
            S::FreeAxis,
            S::Snapped,
            S::Passed,
            S::NotFollowed,
            S::Turned,
            S::NullPointer,
            S::NotFinite,
            S::BadFlag,
            S::BadSequence,
            S::IncompleteSequence,
            S::NotARotation,
            S::Degenerate,
            S::BadArgument,
            S::NotAvailable,
            S::UnknownHead,
            S::NameTooLong,
            S::Parse,
            S::TableFull,
            S::OutOfRange,
            S::BadState,
            S::Coincident,
            S::Collinear,
            S::TooFew,
            S::UnknownWord,
            S::NotANumber,
            S::MissingWord,
            S::LineTooLong,
            S::NoRoom,
            S::Unreachable,
            S::OutOfTravel,
            S::HasOrigin,
            S::Internal,
        ];
        for s in all {
            let text = unsafe { core::ffi::CStr::from_ptr(super::cncrot_status_str(s as i32)) };
            let text = text.to_str().unwrap();
            // The C name is derived independently from the Rust variant name.
            let name: String = format!("{s:?}")
                .chars()
                .flat_map(|c| {
                    let sep = c.is_uppercase().then_some('_');
                    sep.into_iter().chain(c.to_uppercase())
                })
                .collect();
            assert!(text.starts_with(&format!("CNCROT_STATUS{name}:")), "{text}");
        }
        let unknown = unsafe { core::ffi::CStr::from_ptr(super::cncrot_status_str(42)) };
        assert!(unknown
            .to_str()
            .unwrap()
            .starts_with("CNCROT_STATUS_UNKNOWN"));
    }
}
