//! Axis sequences and their codes (`_BIN_IN`, `_BIN_OUT`, CYCLE800 `_MODE` bits 5..0, G158).
//!
//! Two bits per rotation, X = 01, Y = 10, Z = 11, the first rotation in the lowest two bits:
//! `code = a1 + 4*a2 + 16*a3`. A pair `00` means "no rotation".

use crate::Error;

/// A coordinate axis.
///
/// ```
/// assert_eq!(cncrot::Axis::Z.bits(), 0b11);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The X axis (code bits `01`).
    X,
    /// The Y axis (code bits `10`).
    Y,
    /// The Z axis (code bits `11`).
    Z,
}

impl Axis {
    /// The two code bits of this axis.
    pub const fn bits(self) -> u8 {
        self.index() as u8 + 1
    }

    /// 0, 1, 2 for X, Y, Z: the row/column of this axis in a matrix.
    pub const fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
            Axis::Z => 2,
        }
    }

    const fn from_bits(bits: u8) -> Option<Axis> {
        match bits & 3 {
            1 => Some(Axis::X),
            2 => Some(Axis::Y),
            3 => Some(Axis::Z),
            _ => None,
        }
    }
}

/// About which axes the rotations turn.
///
/// ```
/// use cncrot::Kind;
/// assert_eq!(Kind::from_flag(1), Ok(Kind::Intrinsic)); // CYCLE600 `_INEXIN = 1`
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// About the fixed machine axes: `R = R_a3(θ3) · R_a2(θ2) · R_a1(θ1)`.
    Extrinsic,
    /// About the rotated workpiece axes: `R = R_a1(θ1) · R_a2(θ2) · R_a3(θ3)`.
    Intrinsic,
}

impl Kind {
    /// The paper's flag: 1 intrinsic, 0 extrinsic; anything else is [`Error::BadFlag`].
    pub const fn from_flag(flag: i32) -> Result<Kind, Error> {
        match flag {
            0 => Ok(Kind::Extrinsic),
            1 => Ok(Kind::Intrinsic),
            _ => Err(Error::BadFlag),
        }
    }

    /// 1 for intrinsic, 0 for extrinsic.
    pub const fn flag(self) -> i32 {
        match self {
            Kind::Extrinsic => 0,
            Kind::Intrinsic => 1,
        }
    }
}

/// A validated axis-sequence code, possibly with `00` pairs ("no rotation"): what can be
/// composed into a matrix.
///
/// ```
/// use cncrot::{Axis, AxisCode};
/// let c = AxisCode::new(57).unwrap();
/// assert_eq!(c.axes(), [Some(Axis::X), Some(Axis::Y), Some(Axis::Z)]);
/// assert!(AxisCode::new(0b11_00_11).is_err()); // Z, none, Z: the same axis twice in a row
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct AxisCode(u8);

impl AxisCode {
    /// Validates a code: 0..=63 and no axis equal to the previous one (`00` pairs skipped).
    pub const fn new(code: i32) -> Result<AxisCode, Error> {
        if code < 0 || code > 63 {
            return Err(Error::BadSequence);
        }
        let code = code as u8;
        let mut last = 0u8;
        let mut k = 0;
        while k < 3 {
            let bits = (code >> (2 * k)) & 3;
            if bits != 0 {
                if bits == last {
                    return Err(Error::BadSequence);
                }
                last = bits;
            }
            k += 1;
        }
        Ok(AxisCode(code))
    }

    /// The numeric code.
    pub const fn code(self) -> u8 {
        self.0
    }

    /// The axes of the three rotation slots, `None` for a `00` pair.
    pub const fn axes(self) -> [Option<Axis>; 3] {
        [
            Axis::from_bits(self.0),
            Axis::from_bits(self.0 >> 2),
            Axis::from_bits(self.0 >> 4),
        ]
    }
}

impl From<Sequence> for AxisCode {
    fn from(s: Sequence) -> AxisCode {
        AxisCode(s.code())
    }
}

/// One of the twelve sequences of three rotations, named by their axes in rotation order.
///
/// ```
/// use cncrot::Sequence;
/// assert_eq!(Sequence::XYZ.code(), 57);
/// assert_eq!(Sequence::from_code(39), Ok(Sequence::ZXY));
/// assert_eq!(Sequence::XYZ.reversed(), Sequence::ZYX);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sequence {
    /// X, Y, Z (code 57).
    XYZ,
    /// X, Z, Y (code 45).
    XZY,
    /// Y, X, Z (code 54).
    YXZ,
    /// Y, Z, X (code 30).
    YZX,
    /// Z, X, Y (code 39).
    ZXY,
    /// Z, Y, X (code 27).
    ZYX,
    /// X, Y, X (code 25).
    XYX,
    /// X, Z, X (code 29).
    XZX,
    /// Y, X, Y (code 38).
    YXY,
    /// Y, Z, Y (code 46).
    YZY,
    /// Z, X, Z (code 55).
    ZXZ,
    /// Z, Y, Z (code 59).
    ZYZ,
}

impl Sequence {
    /// All twelve, Tait-Bryan first.
    pub const ALL: [Sequence; 12] = [
        Sequence::XYZ,
        Sequence::XZY,
        Sequence::YXZ,
        Sequence::YZX,
        Sequence::ZXY,
        Sequence::ZYX,
        Sequence::XYX,
        Sequence::XZX,
        Sequence::YXY,
        Sequence::YZY,
        Sequence::ZXZ,
        Sequence::ZYZ,
    ];

    /// The axes in rotation order.
    pub const fn axes(self) -> [Axis; 3] {
        use Axis::{X, Y, Z};
        match self {
            Sequence::XYZ => [X, Y, Z],
            Sequence::XZY => [X, Z, Y],
            Sequence::YXZ => [Y, X, Z],
            Sequence::YZX => [Y, Z, X],
            Sequence::ZXY => [Z, X, Y],
            Sequence::ZYX => [Z, Y, X],
            Sequence::XYX => [X, Y, X],
            Sequence::XZX => [X, Z, X],
            Sequence::YXY => [Y, X, Y],
            Sequence::YZY => [Y, Z, Y],
            Sequence::ZXZ => [Z, X, Z],
            Sequence::ZYZ => [Z, Y, Z],
        }
    }

    /// The axis-sequence code.
    pub const fn code(self) -> u8 {
        let [a1, a2, a3] = self.axes();
        a1.bits() + 4 * a2.bits() + 16 * a3.bits()
    }

    /// The sequence of a code; codes with `00` pairs are [`Error::IncompleteSequence`],
    /// invalid codes [`Error::BadSequence`].
    pub const fn from_code(code: i32) -> Result<Sequence, Error> {
        // Every code's answer, computed once at compile time: this runs on every call of
        // the C boundary, where validating the three slots cost about 25 instructions.
        const BY_CODE: [Result<Sequence, Error>; 64] = {
            let mut table = [Err(Error::BadSequence); 64];
            let mut code = 0;
            while code < 64 {
                table[code] = match AxisCode::new(code as i32) {
                    Ok(c) => Sequence::from_axis_code(c),
                    Err(e) => Err(e),
                };
                code += 1;
            }
            table
        };
        if code < 0 || code > 63 {
            return Err(Error::BadSequence);
        }
        BY_CODE[code as usize]
    }

    /// The sequence of a validated code, if it has three rotations.
    pub const fn from_axis_code(code: AxisCode) -> Result<Sequence, Error> {
        // A table indexed by the code: on every call of the C boundary, where a search of
        // the twelve cost about 40 instructions.
        const BY_CODE: [Option<Sequence>; 64] = {
            let mut table = [None; 64];
            let mut k = 0;
            while k < Sequence::ALL.len() {
                table[Sequence::ALL[k].code() as usize] = Some(Sequence::ALL[k]);
                k += 1;
            }
            table
        };
        match BY_CODE[(code.code() & 63) as usize] {
            Some(s) => Ok(s),
            None => Err(Error::IncompleteSequence),
        }
    }

    /// First axis equal to the third (X,Y,X ...), as opposed to Tait-Bryan (all three axes).
    pub const fn is_proper_euler(self) -> bool {
        let [a1, _, a3] = self.axes();
        a1.index() == a3.index()
    }

    /// The same axes in reverse order: an extrinsic sequence equals the intrinsic reversed
    /// sequence with reversed angles (paper eq. 13).
    pub const fn reversed(self) -> Sequence {
        match self {
            Sequence::XYZ => Sequence::ZYX,
            Sequence::XZY => Sequence::YZX,
            Sequence::YXZ => Sequence::ZXY,
            Sequence::YZX => Sequence::XZY,
            Sequence::ZXY => Sequence::YXZ,
            Sequence::ZYX => Sequence::XYZ,
            proper => proper,
        }
    }
}

/// A complete convention: intrinsic or extrinsic, and one of the twelve sequences.
///
/// ```
/// use cncrot::{Convention, Kind, Sequence};
/// let c = Convention::new(Kind::Intrinsic, Sequence::ZXY);
/// assert_eq!(Convention::from_c(1, 39), Ok(c));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Convention {
    /// Intrinsic or extrinsic.
    pub kind: Kind,
    /// The axis order.
    pub sequence: Sequence,
}

impl Convention {
    /// A convention from its parts.
    pub const fn new(kind: Kind, sequence: Sequence) -> Convention {
        Convention { kind, sequence }
    }

    /// All 24 conventions.
    pub fn all() -> impl Iterator<Item = Convention> {
        [Kind::Intrinsic, Kind::Extrinsic]
            .into_iter()
            .flat_map(|k| {
                Sequence::ALL
                    .into_iter()
                    .map(move |s| Convention::new(k, s))
            })
    }

    /// From the paper's integers: `intrinsic` 0/1 and a sequence code.
    pub const fn from_c(intrinsic: i32, code: i32) -> Result<Convention, Error> {
        let kind = match Kind::from_flag(intrinsic) {
            Ok(k) => k,
            Err(e) => return Err(e),
        };
        match Sequence::from_code(code) {
            Ok(s) => Ok(Convention::new(kind, s)),
            Err(e) => Err(e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_code_table() {
        // The table of the 12 sequences in docs/conventions.md (the paper's and CYCLE800's codes).
        let table = [
            (Sequence::XYZ, 57),
            (Sequence::XZY, 45),
            (Sequence::YXZ, 54),
            (Sequence::YZX, 30),
            (Sequence::ZXY, 39),
            (Sequence::ZYX, 27),
            (Sequence::XYX, 25),
            (Sequence::XZX, 29),
            (Sequence::YXY, 38),
            (Sequence::YZY, 46),
            (Sequence::ZXZ, 55),
            (Sequence::ZYZ, 59),
        ];
        for (s, code) in table {
            assert_eq!(s.code(), code);
            assert_eq!(Sequence::from_code(code as i32), Ok(s));
            let r = s.reversed();
            let [a, b, c] = s.axes();
            assert_eq!(r.axes(), [c, b, a]);
        }
    }

    #[test]
    fn exactly_twelve_complete_codes() {
        let complete = (0..64).filter(|&c| Sequence::from_code(c).is_ok()).count();
        assert_eq!(complete, 12);
    }

    #[test]
    fn code_validation() {
        assert_eq!(AxisCode::new(-1), Err(Error::BadSequence));
        assert_eq!(AxisCode::new(64), Err(Error::BadSequence));
        assert_eq!(AxisCode::new(0b01_01_10), Err(Error::BadSequence)); // Y, X, X
        assert_eq!(AxisCode::new(0b01_00_01), Err(Error::BadSequence)); // X, -, X
        assert!(AxisCode::new(0).is_ok());
        assert!(AxisCode::new(0b00_11_00).is_ok());
        assert_eq!(
            Sequence::from_code(0b11_00_01),
            Err(Error::IncompleteSequence)
        );
        assert_eq!(Sequence::from_code(99), Err(Error::BadSequence));
        assert_eq!(Kind::from_flag(2), Err(Error::BadFlag));
    }
}
