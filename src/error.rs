//! Errors of the Rust API. The C boundary maps each to one negative `cncrot_status`.

use core::fmt;

/// Why a computation was refused. Inputs are never modified when an error is returned.
///
/// ```
/// use cncrot::{AxisCode, Error};
/// assert_eq!(AxisCode::new(0b01_01_11), Err(Error::BadSequence)); // Z, X, X: X repeated
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Error {
    /// A number was NaN or infinite.
    NotFinite,
    /// A 0/1 flag had another value.
    BadFlag,
    /// An axis-sequence code outside 0..=63, or with an axis equal to the one before it.
    BadSequence,
    /// A decomposition target with fewer than three rotations.
    IncompleteSequence,
    /// A matrix that is not a rotation: not orthonormal within [`crate::ROTATION_TOLERANCE`],
    /// a reflection, or a frame whose last row is not `0 0 0 1`.
    NotARotation,
    /// [`crate::nearest_rotation`]: the matrix is singular or nearest to a reflection.
    Degenerate,
    /// A parameter outside its documented domain (a value other than the allowed ones).
    BadArgument,
    /// The requested capability needs something the call did not provide (a machine
    /// description for positions of rotary axes).
    NotAvailable,
    /// CYCLE600: the accessory name is not in the head table.
    UnknownHead,
    /// A name longer than its fixed-size field.
    NameTooLong,
    /// Text that could not be read: a HEAD_DEF line (its number is reported separately) or a
    /// malformed number in a program line.
    Parse,
    /// A fixed-capacity table is full.
    TableFull,
    /// A result is too large to represent (finite inputs whose result overflows, such as
    /// translations near `f64::MAX`), or an angle too large to denote the rotation to the
    /// library's accuracy.
    OutOfRange,
    /// A stored CYCLE600 state that this library did not write as it is: corrupted in
    /// storage, edited, or from a version with another layout.
    BadState,
    /// Points that should be different coincide (probing: A1 = A2; all plane points
    /// equal; PLANE POINTS with P1 = P2).
    Coincident,
    /// Points or directions that should span a plane lie on one line (within a sine of
    /// [`crate::MIN_SINE`]).
    Collinear,
    /// Fewer points than the computation needs (a plane needs three).
    TooFew,
    /// A program line: a word the dialect does not have there, or one given twice.
    UnknownWord,
    /// A program line: a variable or an expression (`R1`, `Q120`, `#100`, `30+5`) where the
    /// library needs a number.
    NotANumber,
    /// A program line: a word the command requires is missing.
    MissingWord,
    /// A program line longer than the controller accepts.
    LineTooLong,
    /// The caller's text buffer is too small for the line.
    NoRoom,
    /// No positions of the machine's rotary axes give that orientation.
    Unreachable,
    /// The orientation is reachable, but only outside the rotary axes' travel limits.
    OutOfTravel,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.message())
    }
}

impl Error {
    /// A short English description, the same text `cncrot_status_str` returns.
    pub const fn message(self) -> &'static str {
        match self {
            Error::NotFinite => "a number is NaN or infinite",
            Error::BadFlag => "a flag is neither 0 nor 1",
            Error::BadSequence => "axis-sequence code outside 0..63 or with a repeated axis",
            Error::IncompleteSequence => "decomposition needs a sequence of three rotations",
            Error::NotARotation => "matrix is not a rotation (not orthonormal, or a reflection)",
            Error::Degenerate => "matrix is singular or nearest to a reflection",
            Error::BadArgument => "parameter outside its allowed values",
            Error::NotAvailable => "not available: needs a machine description (rotary axes)",
            Error::UnknownHead => "accessory name not found in the head table",
            Error::NameTooLong => "name longer than its field",
            Error::Parse => "text could not be read (a malformed number or line)",
            Error::TableFull => "head table is full",
            Error::OutOfRange => "a result is too large to represent",
            Error::Coincident => "points that must differ coincide",
            Error::Collinear => "points or directions that must span a plane lie on one line",
            Error::TooFew => "too few points (a plane needs three)",
            Error::UnknownWord => "unknown, repeated or misplaced word in the line",
            Error::NotANumber => "a variable or expression where a number must stand",
            Error::MissingWord => "a word the command requires is missing",
            Error::LineTooLong => "line longer than the controller accepts",
            Error::NoRoom => "the text does not fit the buffer",
            Error::Unreachable => "no rotary-axis positions of the machine give that orientation",
            Error::OutOfTravel => "the orientation is reachable only outside the travel limits",
            Error::BadState => {
                "stored CYCLE600 state is corrupt, edited or from another version (format or checksum)"
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Error {}
