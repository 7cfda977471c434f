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
    /// A stored state (CYCLE600's, a program's) that this library did not write as it is:
    /// corrupted in storage, edited, or from a version with another layout.
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
    /// A frame with an origin for a form that has no words for one (`PLANE SPATIAL`,
    /// `ROT`, `PLANE POINTS`): write the datum shift in that dialect's own command first,
    /// then the rotation alone.
    HasOrigin,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.message())
    }
}

/// The one table of statuses: for each, its C value, its C name and its text. `Error`'s
/// messages, `cncrot_status_str` and the tests that tie both to the C enum come from it, so
/// that the Rust and the C text of one status cannot differ. The first part lists the
/// statuses that are `Error` variants, the second those only the C boundary has.
macro_rules! statuses {
    (
        errors { $($variant:ident = $code:literal, $name:literal, $text:literal;)* }
        others { $($ocode:literal, $oname:literal, $otext:literal;)* }
    ) => {
        impl Error {
            /// Every error, in the order of their C values (-2 down to -26).
            pub const ALL: &'static [Error] = &[$(Error::$variant,)*];

            /// A short English description: the text `cncrot_status_str` gives after the
            /// status's name.
            ///
            /// ```
            /// assert_eq!(cncrot::Error::TooFew.message(), "too few points (a plane needs three)");
            /// ```
            pub const fn message(self) -> &'static str {
                match self {
                    $(Error::$variant => $text,)*
                }
            }

            /// The value of this error's `cncrot_status` in C (negative).
            ///
            /// ```
            /// assert_eq!(cncrot::Error::NotFinite.code(), -2);
            /// ```
            pub const fn code(self) -> i32 {
                match self {
                    $(Error::$variant => $code,)*
                }
            }
        }

        /// The name and text of a C status value, NUL-terminated (what `cncrot_status_str`
        /// returns); `None` for a value that is no status.
        pub(crate) const fn status_text(code: i32) -> Option<&'static core::ffi::CStr> {
            match code {
                $($code => Some(cstr(concat!($name, ": ", $text, "\0"))),)*
                $($ocode => Some(cstr(concat!($oname, ": ", $otext, "\0"))),)*
                _ => None,
            }
        }

        /// Every status of the table: value, name and text (for the tests that tie the
        /// table to the C enum and the header).
        pub const STATUSES: &[(i32, &str, &str)] = &[
            $(($code, $name, $text),)*
            $(($ocode, $oname, $otext),)*
        ];
    };
}

/// A string literal with its NUL as a C string; the table's literals are checked when the
/// crate compiles (each call is evaluated in a constant).
const fn cstr(s: &'static str) -> &'static core::ffi::CStr {
    match core::ffi::CStr::from_bytes_with_nul(s.as_bytes()) {
        Ok(c) => c,
        Err(_) => c"CNCROT_STATUS_INTERNAL: a status text with a NUL inside",
    }
}

statuses! {
    errors {
        NotFinite = -2, "CNCROT_STATUS_NOT_FINITE", "a number is NaN or infinite";
        BadFlag = -3, "CNCROT_STATUS_BAD_FLAG", "a flag is neither 0 nor 1";
        BadSequence = -4, "CNCROT_STATUS_BAD_SEQUENCE",
            "axis-sequence code outside 0..63 or with a repeated axis";
        IncompleteSequence = -5, "CNCROT_STATUS_INCOMPLETE_SEQUENCE",
            "decomposition needs a sequence of three rotations";
        NotARotation = -6, "CNCROT_STATUS_NOT_A_ROTATION",
            "matrix is not a rotation (not orthonormal within 1e-3, a reflection, or a frame whose last row is not 0 0 0 1)";
        Degenerate = -7, "CNCROT_STATUS_DEGENERATE",
            "matrix is singular or nearest to a reflection, or a direction is zero or along another";
        BadArgument = -8, "CNCROT_STATUS_BAD_ARGUMENT", "parameter outside its allowed values";
        NotAvailable = -9, "CNCROT_STATUS_NOT_AVAILABLE",
            "not available: needs a machine description (rotary axes)";
        UnknownHead = -10, "CNCROT_STATUS_UNKNOWN_HEAD",
            "accessory or data set not found (head table, swivel data)";
        NameTooLong = -11, "CNCROT_STATUS_NAME_TOO_LONG", "name longer than its field";
        Parse = -12, "CNCROT_STATUS_PARSE", "text could not be read (a malformed number or line)";
        TableFull = -13, "CNCROT_STATUS_TABLE_FULL", "head table is full";
        OutOfRange = -14, "CNCROT_STATUS_OUT_OF_RANGE",
            "a number or result is beyond what can be represented or written to the library's accuracy";
        BadState = -15, "CNCROT_STATUS_BAD_STATE",
            "stored state (CYCLE600 or program) is corrupt, edited or from another version (format or checksum)";
        Coincident = -16, "CNCROT_STATUS_COINCIDENT", "points that must differ coincide";
        Collinear = -17, "CNCROT_STATUS_COLLINEAR",
            "points or directions that must span a plane lie on one line";
        TooFew = -18, "CNCROT_STATUS_TOO_FEW", "too few points (a plane needs three)";
        UnknownWord = -19, "CNCROT_STATUS_UNKNOWN_WORD",
            "unknown, repeated or misplaced word in the line";
        NotANumber = -20, "CNCROT_STATUS_NOT_A_NUMBER",
            "a variable or expression where a number must stand";
        MissingWord = -21, "CNCROT_STATUS_MISSING_WORD", "a word the command requires is missing";
        LineTooLong = -22, "CNCROT_STATUS_LINE_TOO_LONG", "line longer than the controller accepts";
        NoRoom = -23, "CNCROT_STATUS_NO_ROOM", "the text does not fit the buffer";
        Unreachable = -24, "CNCROT_STATUS_UNREACHABLE",
            "no rotary-axis positions of the machine give that orientation";
        OutOfTravel = -25, "CNCROT_STATUS_OUT_OF_TRAVEL",
            "the orientation is reachable only outside the travel limits";
        HasOrigin = -26, "CNCROT_STATUS_HAS_ORIGIN",
            "the frame has an origin and the form has no words for one: shift the datum first, then write the rotation alone";
    }
    others {
        0, "CNCROT_STATUS_OK", "success";
        1, "CNCROT_STATUS_SINGULAR",
            "success; singular decomposition, only the sum or difference of the first and third angles is determined, the third was set to 0";
        2, "CNCROT_STATUS_FREE_AXIS",
            "success at a singular pose; a rotary axis is free and was kept at its current position";
        3, "CNCROT_STATUS_SNAPPED",
            "success; a Hirth axis was snapped to its grid, the residual is in the remaining frame";
        6, "CNCROT_STATUS_TURNED",
            "success; the plane's Z' was turned to the tool's side: the order of the points gave the other side";
        4, "CNCROT_STATUS_PASSED",
            "success; the block does not concern the frame (motion, tool, M/S words, program structure, comment, blank): the state is unchanged";
        5, "CNCROT_STATUS_NOT_FOLLOWED",
            "success; the block changes the frame in a way the library does not follow (a work-offset or preset selection, a table or system-variable write, mirroring, scaling, a tilt that needs the machine): the state is unchanged and may differ from the control's";
        -1, "CNCROT_STATUS_NULL_POINTER", "a pointer argument is NULL";
        -100, "CNCROT_STATUS_INTERNAL", "internal failure (caught panic), please report";
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Error {}
