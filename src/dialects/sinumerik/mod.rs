//! SINUMERIK (Siemens): the swivel cycle CYCLE800 in its modes, the frame commands
//! `ROT`/`AROT`/`CROT` in RPY and Euler mode with the control's read-back, `ROTS`
//! (projection angles), and the tool orientation of `ORIRPY`/`ORIEULER`/`A3 B3 C3`; beside
//! it the paper's cycle CYCLE600 ([`cycle600`]), the `HEAD_DEF` table of accessories
//! ([`head_def`]) and the swivel data `$TC_CARR` ([`carr`]).
//!
//! Confidence of each behaviour, as the project's documentation lists it: **\[doc\]** stated by
//! the vendor's manual, **\[3rd\]** how widely used post-processors treat it, **\[derived\]**
//! follows from the manual's wording by geometry, **\[choice\]** ours where nothing public
//! decides. A frame's rotation `F` has the new axes as its columns (`p_old = t + F·p_new`).

pub mod carr;
pub mod cycle600;
pub mod head_def;

use crate::math::{atan2_deg, sin_cos_deg, sqrt};
use crate::{
    angles_from_matrix, matrix_from_angles, AxisCode, Convention, Decomposition, Error, Frame,
    Kind, Matrix, Sequence, Vector,
};

/// How CYCLE800 reads `_A`, `_B`, `_C`: the swivel mode of `_MODE` (bits 7..6) with the axis
/// sequence of bits 5..0.
///
/// ```
/// use cncrot::dialects::sinumerik::SwivelMode;
/// use cncrot::{AxisCode, Sequence};
/// assert_eq!(SwivelMode::from_mode(57), Ok(SwivelMode::AxisByAxis(AxisCode::new(57).unwrap())));
/// assert_eq!(SwivelMode::from_mode(128 + 57), Ok(SwivelMode::Projection(Sequence::XYZ)));
/// assert_eq!(SwivelMode::from_mode(192), Ok(SwivelMode::Direct));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SwivelMode {
    /// Bits 00: rotations about the axes in the coded order, each about the axis already
    /// turned by the ones before (intrinsic), angles `_A, _B, _C` in rotation order [3rd,
    /// strong: independent post-processors agree, and the paper feeds CYCLE600's intrinsic
    /// output to it]. A `00` pair skips a rotation.
    AxisByAxis(AxisCode),
    /// Bits 01: solid angle: `_A` turns about Z, `_B` tilts about the new Y, so the tool axis
    /// is `(cos A sin B, sin A sin B, cos B)` \[derived\]; `_C` turns about the new Z
    /// \[choice\]: `F = Rz(A)·Ry(B)·Rz(C)`. Bits 5..0 are not used \[choice\].
    SolidAngle,
    /// Bits 10: projection angles, as `ROTS` defines them \[derived\]: for `Sequence::XYZ`, `_A`
    /// and `_B` are the projected angles about X and Y and `_C` turns about the new Z
    /// (`F = Ry(B)·Rx(γ)·Rz(C)`, `tan γ = tan A · cos B`); `Sequence::YZX` and
    /// `Sequence::ZXY` are the same with the axes exchanged cyclically \[derived\]. Which bits
    /// code the three positions is not public: these three codes are our \[choice\].
    Projection(Sequence),
    /// Bits 11: the rotary-axis positions themselves; the frame needs the machine's
    /// kinematics ([`Error::NotAvailable`] until the library has them). Bits 5..0 are not
    /// used \[choice\].
    Direct,
}

impl SwivelMode {
    /// Decodes `_MODE` (0..=255). Refused: other values ([`Error::BadArgument`]), an
    /// axis-by-axis code with a repeated axis and a projection code other than 57, 30, 39
    /// ([`Error::BadSequence`]).
    pub fn from_mode(mode: i32) -> Result<SwivelMode, Error> {
        if !(0..=255).contains(&mode) {
            return Err(Error::BadArgument);
        }
        let low = mode & 0x3f;
        match mode >> 6 {
            0 => Ok(SwivelMode::AxisByAxis(AxisCode::new(low)?)),
            1 => Ok(SwivelMode::SolidAngle),
            2 => match Sequence::from_code(low)? {
                s @ (Sequence::XYZ | Sequence::YZX | Sequence::ZXY) => {
                    Ok(SwivelMode::Projection(s))
                }
                _ => Err(Error::BadSequence),
            },
            _ => Ok(SwivelMode::Direct),
        }
    }

    /// The `_MODE` value of this swivel mode (what a writer puts in a CYCLE800 call).
    pub fn mode(self) -> i32 {
        match self {
            SwivelMode::AxisByAxis(code) => i32::from(code.code()),
            SwivelMode::SolidAngle => 64,
            SwivelMode::Projection(s) => 128 + i32::from(s.code()),
            SwivelMode::Direct => 192,
        }
    }
}

/// The rotation of a CYCLE800 call: `_A`, `_B`, `_C` read in the swivel mode.
///
/// ```
/// use cncrot::dialects::sinumerik::{cycle800_rotation, SwivelMode};
/// // Solid angle: the tool axis is (cos A sin B, sin A sin B, cos B).
/// let f = cycle800_rotation(SwivelMode::SolidAngle, [30.0, 40.0, 0.0]).unwrap();
/// let (a, b) = (30f64.to_radians(), 40f64.to_radians());
/// assert!((f[0][2] - a.cos() * b.sin()).abs() < 1e-15 && (f[2][2] - b.cos()).abs() < 1e-15);
/// ```
pub fn cycle800_rotation(mode: SwivelMode, abc: [f64; 3]) -> Result<Matrix, Error> {
    match mode {
        SwivelMode::AxisByAxis(code) => Ok(matrix_from_angles(Kind::Intrinsic, code, abc)),
        SwivelMode::SolidAngle => Ok(matrix_from_angles(
            Kind::Intrinsic,
            Sequence::ZYZ.into(),
            abc,
        )),
        SwivelMode::Projection(s) => Ok(projection(s, abc)),
        SwivelMode::Direct => Err(Error::NotAvailable),
    }
}

/// The frame of a CYCLE800 call: `Trans(_X0, _Y0, _Z0)·Rot·Trans(_X1, _Y1, _Z1)` \[derived\].
pub fn cycle800_frame(
    mode: SwivelMode,
    abc: [f64; 3],
    before: Vector,
    after: Vector,
) -> Result<Frame, Error> {
    Ok(Frame::with_translations(
        before,
        cycle800_rotation(mode, abc)?,
        after,
    ))
}

/// `_ST`'s swivel: a new plane replaces the active frame; an additive one (`_ST` units
/// digit 1 [choice: the digit coding of `_ST` is not public]) applies in the already swivelled
/// system, on the right, as `AROT` does \[derived\].
pub fn cycle800_apply(active: &Frame, additive: bool, call: &Frame) -> Frame {
    if additive {
        active.compose(call)
    } else {
        *call
    }
}

/// `_A`, `_B`, `_C` for a rotation in a swivel mode: the inverse of [`cycle800_rotation`]
/// (canonical ranges; at the singular middle angle `_C` = 0). Refused: a mode without three
/// rotations ([`Error::IncompleteSequence`]), direct mode ([`Error::NotAvailable`]), a
/// rotation that is not one, and, in projection mode, a frame whose first projected axis
/// has turned onto the third axis while the plane is turned about it (projection angles
/// cannot express it: [`Error::OutOfRange`]).
///
/// ```
/// use cncrot::dialects::sinumerik::{cycle800_angles, cycle800_rotation, SwivelMode};
/// use cncrot::Sequence;
/// let mode = SwivelMode::Projection(Sequence::XYZ);
/// let f = cycle800_rotation(mode, [30.0, 20.0, 10.0]).unwrap();
/// let d = cycle800_angles(mode, &f).unwrap();
/// assert!((d.angles[0] - 30.0).abs() < 1e-12 && (d.angles[2] - 10.0).abs() < 1e-12);
/// ```
pub fn cycle800_angles(mode: SwivelMode, rotation: &Matrix) -> Result<Decomposition, Error> {
    match mode {
        SwivelMode::AxisByAxis(code) => {
            let seq = Sequence::from_axis_code(code)?;
            angles_from_matrix(Convention::new(Kind::Intrinsic, seq), rotation)
        }
        SwivelMode::SolidAngle => {
            angles_from_matrix(Convention::new(Kind::Intrinsic, Sequence::ZYZ), rotation)
        }
        SwivelMode::Projection(s) => projection_angles(s, rotation),
        SwivelMode::Direct => Err(Error::NotAvailable),
    }
}

/// The sequence in which the projection's rotations are composed: for projected axes
/// `(p, q)` and the third axis `r`, `F = R_q(β)·R_p(γ)·R_r(C)`.
fn projection_order(s: Sequence) -> Sequence {
    match s {
        Sequence::YZX => Sequence::ZYX,
        Sequence::ZXY => Sequence::XZY,
        _ => Sequence::YXZ,
    }
}

/// Projection angles `[α, β, C]` about the axes `p, q` of `s` (then `r` for `C`): the new
/// `p` axis is `R_q(β)·e_p` and the new `pq` plane contains `R_p(α)·e_q`, so
/// `F = R_q(β)·R_p(γ)·R_r(C)` with `γ = atan2(sin α cos β, cos α)` (`tan γ = tan α cos β`,
/// on the branch that keeps the new `q` axis on the side of `R_p(α)·e_q`).
pub(crate) fn projection(s: Sequence, [alpha, beta, c]: [f64; 3]) -> Matrix {
    let (sa, ca) = sin_cos_deg(alpha);
    let (_, cb) = sin_cos_deg(beta);
    let gamma = atan2_deg(sa * cb, ca);
    matrix_from_angles(
        Kind::Intrinsic,
        projection_order(s).into(),
        [beta, gamma, c],
    )
}

pub(crate) fn projection_angles(s: Sequence, m: &Matrix) -> Result<Decomposition, Error> {
    let d = angles_from_matrix(Convention::new(Kind::Intrinsic, projection_order(s)), m)?;
    let [beta, gamma, c] = d.angles;
    let (sg, cg) = sin_cos_deg(gamma);
    let (_, cb) = sin_cos_deg(beta);
    if cb == 0.0 && sg != 0.0 {
        // The new p axis lies on the r axis: every α gives a plane through r, turned by
        // 0° or 180° only.
        return Err(Error::OutOfRange);
    }
    // tan α = tan γ / cos β, on the branch of `projection`: the pair (sin γ·cos β,
    // cos γ·cos² β) divided by |cos β| > 0, which keeps the quadrant.
    let sign = if cb < 0.0 { -1.0 } else { 1.0 };
    let alpha = atan2_deg(sg * sign, cg * crate::math::abs(cb));
    Ok(Decomposition {
        angles: [alpha, beta, c],
        singular: d.singular,
    })
}

/// The angle mode of the frame commands: RPY (the default) or Euler (machine data
/// `$MN_FRAME_ANGLE_CHOICE`/MD10600 = 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AngleMode {
    /// `F = Rz(z)·Ry(y)·Rx(x)`: intrinsic Z, Y', X'' with the letters z, y, x \[doc\].
    Rpy,
    /// Intrinsic Z, X', Z'' with x the nutation \[doc\]; which of y and z is the first Z
    /// rotation is not public: `F = Rz(z)·Rx(x)·Rz(y)` \[choice\].
    Euler,
}

impl AngleMode {
    fn convention(self) -> Convention {
        match self {
            AngleMode::Rpy => Convention::new(Kind::Intrinsic, Sequence::ZYX),
            AngleMode::Euler => Convention::new(Kind::Intrinsic, Sequence::ZXZ),
        }
    }
}

/// The rotation of `ROT X=x Y=y Z=z` (omitted words are 0), also `CROT` \[derived\] and each
/// step of `AROT` (which applies on the right of the active frame \[doc\]).
///
/// ```
/// use cncrot::dialects::sinumerik::{rot, AngleMode};
/// use cncrot::{elementary, Axis};
/// assert_eq!(rot(AngleMode::Rpy, [0.0, 0.0, 90.0]), elementary(Axis::Z, 90.0));
/// ```
pub fn rot(mode: AngleMode, [x, y, z]: [f64; 3]) -> Matrix {
    let c = mode.convention();
    let angles = match mode {
        AngleMode::Rpy => [z, y, x],
        AngleMode::Euler => [z, x, y],
    };
    matrix_from_angles(c.kind, c.sequence.into(), angles)
}

/// The angles the control reads back for a rotation, `[x, y, z]`: RPY with x and z in
/// (-180, 180] and y in [-90, 90]; at y = ±90 only z − x (or z + x) is determined and x = 0
/// [doc: `CROT(x,10,y,90,z,40)` reads back `x 0, y 90, z 30`]. Euler with x in [0, 180].
///
/// ```
/// use cncrot::dialects::sinumerik::{readback, rot, AngleMode};
/// let (a, singular) = readback(AngleMode::Rpy, &rot(AngleMode::Rpy, [10.0, 90.0, 40.0])).unwrap();
/// assert!(singular && a[0] == 0.0 && a[1] == 90.0 && (a[2] - 30.0).abs() < 1e-12);
/// ```
pub fn readback(mode: AngleMode, m: &Matrix) -> Result<([f64; 3], bool), Error> {
    let d = angles_from_matrix(mode.convention(), m)?;
    let [a1, a2, a3] = d.angles;
    let xyz = match mode {
        AngleMode::Rpy => [a3, a2, a1],
        AngleMode::Euler => [a2, a3, a1],
    };
    Ok((xyz, d.singular))
}

/// The projected axes of `ROTS`/`AROTS`/`CROTS`: `X Y`, `Y Z` or `Z X` \[doc\].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RotsPlane {
    /// `ROTS X=α Y=β`.
    XY,
    /// `ROTS Y=α Z=β`.
    YZ,
    /// `ROTS Z=α X=β`.
    ZX,
}

/// The rotation of `ROTS` with the first letter's angle `alpha` and the second's `beta`
/// ("Y gives the angle by which the X axis must rotate around the Y axis to bring it to the
/// line of intersection" \[doc\]; the closed form \[derived\]).
///
/// ```
/// use cncrot::dialects::sinumerik::{rots, RotsPlane};
/// // ROTS X30 Y20: γ = 28.481238°, F row 1 = (0.939693, 0.163099, 0.300627).
/// let f = rots(RotsPlane::XY, 30.0, 20.0);
/// assert!((f[0][1] - 0.163099).abs() < 1e-6 && (f[1][1] - 0.878973).abs() < 1e-6);
/// ```
pub fn rots(plane: RotsPlane, alpha: f64, beta: f64) -> Matrix {
    let s = match plane {
        RotsPlane::XY => Sequence::XYZ,
        RotsPlane::YZ => Sequence::YZX,
        RotsPlane::ZX => Sequence::ZXY,
    };
    projection(s, [alpha, beta, 0.0])
}

/// The tool direction of `ORIRPY` angles `A2 B2 C2`: "first with C2 around Z, then with B2
/// around the new Y, finally with A2 around the new X" applied to +Z \[doc\]:
/// `Rz(C2)·Ry(B2)·Rx(A2)·e_z`.
///
/// ```
/// use cncrot::dialects::sinumerik::orirpy_vector;
/// assert_eq!(orirpy_vector([0.0, 90.0, 0.0]), [1.0, 0.0, 0.0]);
/// ```
pub fn orirpy_vector([a2, b2, c2]: [f64; 3]) -> Vector {
    let m = matrix_from_angles(Kind::Intrinsic, Sequence::ZYX.into(), [c2, b2, a2]);
    [m[0][2], m[1][2], m[2][2]]
}

/// The tool direction of `ORIEULER` angles `A2 B2 (C2)`: "A2 around Z, then B2 around the new
/// X, lastly C2 around the new Z" \[doc\]; C2 does not move a tool on +Z:
/// `Rz(A2)·Rx(B2)·e_z`.
///
/// ```
/// use cncrot::dialects::sinumerik::orieuler_vector;
/// assert_eq!(orieuler_vector([90.0, 90.0]), [1.0, 0.0, 0.0]);
/// ```
pub fn orieuler_vector([a2, b2]: [f64; 2]) -> Vector {
    let m = matrix_from_angles(Kind::Intrinsic, Sequence::ZXZ.into(), [a2, b2, 0.0]);
    [m[0][2], m[1][2], m[2][2]]
}

/// A direction vector `A3 B3 C3` as a unit vector: its length is irrelevant \[doc\]; a zero
/// (or non-finite, or overflowing) vector is refused ([`Error::Degenerate`]).
///
/// ```
/// use cncrot::dialects::sinumerik::unit_direction;
/// assert_eq!(unit_direction([0.0, 0.0, 7.0]), Ok([0.0, 0.0, 1.0]));
/// assert!(unit_direction([0.0; 3]).is_err());
/// ```
pub fn unit_direction(v: Vector) -> Result<Vector, Error> {
    crate::unit_vector(v)
}

/// `ORIEULER` angles `[A2, B2]` of a tool direction (any length): B2 in [0, 180], A2 in
/// (-180, 180]; along ±Z only B2 is determined and A2 = 0 (`singular`).
///
/// ```
/// use cncrot::dialects::sinumerik::{orieuler_angles, orieuler_vector};
/// let (a, _) = orieuler_angles(orieuler_vector([30.0, 40.0])).unwrap();
/// assert!((a[0] - 30.0).abs() < 1e-12 && (a[1] - 40.0).abs() < 1e-12);
/// ```
pub fn orieuler_angles(v: Vector) -> Result<([f64; 2], bool), Error> {
    let [x, y, z] = unit_direction(v)?;
    let h = sqrt(x * x + y * y);
    let b2 = atan2_deg(h, z);
    if h == 0.0 {
        return Ok(([0.0, b2], true));
    }
    // t = (sin A sin B, −cos A sin B, cos B).
    Ok(([atan2_deg(x, -y), b2], false))
}

/// `ORIRPY` angles `[A2, B2, C2]` of a tool direction, with C2 = 0 [choice: two angles fix a
/// direction]: `t = (cos A sin B, −sin A, cos A cos B)`, A2 in [-90, 90], B2 in (-180, 180];
/// along ±Y only A2 is determined and B2 = 0 (`singular`).
///
/// ```
/// use cncrot::dialects::sinumerik::{orirpy_angles, orirpy_vector};
/// let (a, _) = orirpy_angles(orirpy_vector([20.0, -35.0, 0.0])).unwrap();
/// assert!((a[0] - 20.0).abs() < 1e-12 && (a[1] + 35.0).abs() < 1e-12 && a[2] == 0.0);
/// ```
pub fn orirpy_angles(v: Vector) -> Result<([f64; 3], bool), Error> {
    let [x, y, z] = unit_direction(v)?;
    let h = sqrt(x * x + z * z);
    let a2 = atan2_deg(-y, h);
    if h == 0.0 {
        return Ok(([a2, 0.0, 0.0], true));
    }
    Ok(([a2, atan2_deg(x, z), 0.0], false))
}

// Program lines.

use super::family::{
    put, v3, AxisChoice, Block, Direct, DirectAxes, Family, Form, FormInfo, FormSpec, Modal,
    Motion, Plane, Positioning, Retract, MAX_VALUES,
};
use crate::text::number::{write, write_integer, write_word, Out, Style};
use crate::text::scan::{
    address_words, whole, Comments, Cursor, Exponent, LineError, Syntax, Tokens,
};

const WORDS: Syntax = Syntax {
    exponent: Exponent::Ex,
    ends: b";",
    comma: false,
    iso: false,
};
const ARGS: Syntax = Syntax {
    exponent: Exponent::Ex,
    ends: b",);",
    comma: false,
    iso: false,
};

/// The arguments of a cycle call, compact (a line is parsed on a small stack): each a
/// number, empty or text, with its column; the text of argument `TEXT` is kept, the
/// others' only checked.
struct Args<'a, const N: usize> {
    value: [f64; N],
    text: [bool; N],
    column: [u16; N],
    name: &'a [u8],
    n: usize,
}

impl<'a, const N: usize> Args<'a, N> {
    /// The arguments of `NAME(a, "b", , d)` at the cursor (after the name): at most `N`.
    fn read(c: &mut Cursor<'a>, text_at: usize) -> Result<Self, LineError> {
        let mut a = Args {
            value: [0.0; N],
            text: [false; N],
            column: [0; N],
            name: &[],
            n: 0,
        };
        c.spaces();
        if c.peek() != Some(b'(') {
            return Err(c.missing("'('"));
        }
        c.bump();
        c.spaces();
        if c.peek() == Some(b')') {
            c.bump();
            return Ok(a);
        }
        loop {
            c.spaces();
            let column = c.column();
            let k = a.n;
            let (Some(v), Some(t), Some(col)) =
                (a.value.get_mut(k), a.text.get_mut(k), a.column.get_mut(k))
            else {
                return Err(c.error(Error::UnknownWord));
            };
            // Lines are at most 512 bytes: the column fits.
            *col = column as u16;
            match c.peek() {
                Some(b',' | b')') => {}
                Some(b'"') => {
                    c.bump();
                    let s = c.until(b'"').ok_or(LineError {
                        error: Error::Parse,
                        column,
                        expected: None,
                    })?;
                    *t = true;
                    if k == text_at {
                        a.name = s;
                    }
                }
                _ => *v = c.number(ARGS)?,
            }
            a.n += 1;
            c.spaces();
            match c.peek() {
                Some(b',') => c.bump(),
                Some(b')') => {
                    c.bump();
                    return Ok(a);
                }
                None => return Err(c.missing("',' or ')'")),
                Some(_) => return Err(c.error(Error::UnknownWord)),
            }
        }
    }

    fn column(&self, k: usize) -> usize {
        usize::from(self.column.get(k).copied().unwrap_or(0))
    }

    /// A numeric argument (empty or omitted: 0); text is refused.
    fn real(&self, k: usize) -> Result<f64, LineError> {
        if self.text.get(k).copied().unwrap_or(false) {
            return Err(at(self.column(k))(Error::Parse));
        }
        Ok(self.value.get(k).copied().unwrap_or(0.0))
    }

    /// An integer argument (empty or omitted: 0).
    fn int(&self, k: usize) -> Result<i32, LineError> {
        whole(self.real(k)?, self.column(k))
    }

    /// The text argument (empty: no text); a number there is refused.
    fn name(&self, k: usize) -> Result<&'a [u8], LineError> {
        if k < self.n
            && !self.text.get(k).copied().unwrap_or(false)
            && self.value.get(k) != Some(&0.0)
        {
            return Err(at(self.column(k))(Error::Parse));
        }
        Ok(self.name)
    }
}

fn at(column: usize) -> impl Fn(Error) -> LineError {
    move |error| LineError {
        error,
        column,
        expected: None,
    }
}

/// `_FR` and `_FR_I` for a retraction (see `cycle800_retract`).
fn retract_words(how: &Motion) -> (i32, f64) {
    match how.retract {
        Retract::None => (0, 0.0),
        Retract::MachineZ => (1, 0.0),
        Retract::MachineZThenXy => (2, 0.0),
        Retract::ToolMax => (4, 0.0),
        Retract::Tool => (5, how.retract_mm),
    }
}

/// A frame command's words after its name (`ROT`, `AROT`, `ROTS`, `TRANS`, …: `kind` R, S or
/// T), the frame it leaves. Not inlined: a `CYCLE800`, the deepest block, does not carry
/// this command's temporaries in the reader's frame (stack bound).
#[inline(never)]
fn frame_command(
    m: &Modal,
    c: &mut Cursor,
    column: usize,
    additive: bool,
    kind: u8,
) -> Result<Block, LineError> {
    let words = match address_words(c, *b"XYZ", WORDS, true, (true, false)) {
        Ok(w) => w,
        // An offset of a special axis (`TRANS C90`, `ATRANS X10 A5`: "the programmable
        // offsets for all geometry axes and special axes are specified with TRANS"):
        // the geometry is not all the block changes.
        Err(e) if kind == b'T' && e.error == Error::UnknownWord => return Ok(Block::NotFollowed),
        Err(e) => return Err(e),
    };
    let (xyz, given) = (words.values, words.given);
    let count = given.iter().filter(|&&g| g).count();
    if count == 0 {
        return if additive {
            Err(c.missing("X, Y or Z"))
        } else {
            Ok(Block::Frame(m.with_frame(Frame::IDENTITY)))
        };
    }
    let step = match kind {
        b'R' => {
            let mode = if m.euler {
                AngleMode::Euler
            } else {
                AngleMode::Rpy
            };
            Frame::from_rotation(rot(mode, xyz))
        }
        b'S' => {
            let [x, y, z] = xyz;
            let (plane, a, b) = match given {
                [true, true, true] => return Err(at(column)(Error::UnknownWord)),
                [_, true, true] => (RotsPlane::YZ, y, z),
                // `ROTS Z30` alone: Z with X 0 (the same rotation as Y 0 with Z).
                [_, false, true] => (RotsPlane::ZX, z, x),
                _ => (RotsPlane::XY, x, y),
            };
            Frame::from_rotation(rots(plane, a, b))
        }
        _ => Frame::with_translations(xyz, crate::IDENTITY, [0.0; 3]),
    };
    let tilt = if additive {
        m.tilt_base().map_err(at(column))?.compose(&step)
    } else {
        step
    };
    Ok(Block::Frame(m.with_tilt(tilt, additive)))
}

/// Whether the words of a `ROT`/`AROT`/`CROT` name `RPL`: a rotation in the working plane.
fn plane_rotation(words: &[u8]) -> bool {
    let comments = Comments {
        semicolon: true,
        parens: false,
    };
    Tokens::new(words, comments, false).any(|t| t.is(b"RPL"))
}

/// `ROT RPL=a`, `AROT RPL=a` (`CROT` as `ROT`) after the command: the rotation by `a` in
/// the working plane, about its normal (`G17` Z, `G18` Y, `G19` X) \[doc: "RPL: rotation in
/// the plane: the angle by which the coordinate system is rotated (plane set with G17 to
/// G19)"; the positive sense as `ROT Z=`, `Y=`, `X=`\]; `ROT` replaces the programmable
/// frame, `AROT` adds to it. `RPL` with `X Y Z` angles on the block, in no manual's
/// syntax, is not followed \[choice\].
fn rpl_command(
    m: &Modal,
    c: &mut Cursor,
    column: usize,
    additive: bool,
) -> Result<Block, LineError> {
    c.spaces();
    if !c.word(b"RPL") {
        return Ok(Block::NotFollowed);
    }
    c.spaces();
    if c.peek() != Some(b'=') {
        return Err(c.missing("="));
    }
    c.bump();
    c.spaces();
    let angle = c.number(WORDS)?;
    match c.end(true, false) {
        Ok(()) => {}
        Err(e) if e.error == Error::Parse => return Err(e),
        Err(_) => return Ok(Block::NotFollowed),
    }
    let step = Frame::from_rotation(crate::elementary(m.plane.normal(), angle));
    let tilt = if additive {
        m.tilt_base().map_err(at(column))?.compose(&step)
    } else {
        step
    };
    Ok(Block::Frame(m.with_tilt(tilt, additive)))
}

/// A refused value at `column`, with what the parameter may be.
fn refused(column: usize, allowed: &'static str) -> impl Fn(Error) -> LineError {
    move |error| LineError {
        error,
        column,
        expected: Some(allowed),
    }
}

/// `CYCLE800(_FR, _TC, _ST, _MODE, _X0, _Y0, _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR, _FR_I,
/// _DMODE)`: at least the four up to `_MODE` (omitted and empty arguments are 0);
/// `CYCLE800()` and `_TC = "0"` deselect the swivel \[doc\], and so does `CYCLE800` without
/// parentheses \[choice: a call without parameters may leave them out; DMG and Hermle
/// programs cancel so\]; `_ST` units digit 0 new plane,
/// 1 additive \[choice\], the higher digits (tool alignment, …) do not change the plane;
/// `_DIR`, `_FR`, `_FR_I`, `_DMODE` choose motion and solution, not the plane.
// Its own frame: the reader's frame holds only the deepest command's (CYCLE600) locals.
#[inline(never)]
fn cycle800_line(m: &Modal, c: &mut Cursor) -> Result<Modal, LineError> {
    let args = Args::<16>::read(c, 1)?;
    c.end(true, false)?;
    if args.n == 0 {
        return Ok(m.with_frame(Frame::IDENTITY));
    }
    // `_TC` "0" deselects whatever follows it, or does not (`CYCLE800(0,"0")`).
    if args.n >= 2 && args.name(1)? == b"0" {
        return Ok(m.with_frame(Frame::IDENTITY));
    }
    if args.n < 4 {
        return Err(c.missing("CYCLE800's parameters up to _MODE (4)"));
    }
    let (retract, retract_mm) = cycle800_retract(&args)?;
    let tc = args.name(1)?;
    let st = args.int(2)?;
    let mode = args.int(3)?;
    // `_DIR`: the solution, by the direction of the direction-reference axis [doc]; 0 the
    // frame alone, calculated without swivelling [3rd: posts write 0 where the axes must not
    // turn and ±1 where they do; the cycle's dialog offers "do not swivel (calculate only)"].
    let (choice, swivels) = match args.int(13)? {
        -1 => (AxisChoice::Minus(0), true),
        1 => (AxisChoice::Plus(0), true),
        0 => (AxisChoice::Closest, false),
        _ => {
            let allowed = "_DIR: -1 (minus), +1 (plus) or 0 (no swivel: calculate only)";
            return Err(refused(args.column(13), allowed)(Error::BadArgument));
        }
    };
    for k in 14..16 {
        args.real(k)?;
    }
    let mut w = [0.0; 9];
    for (k, slot) in w.iter_mut().enumerate() {
        *slot = args.real(4 + k)?;
    }
    if tc == b"0" {
        return Ok(m.with_frame(Frame::IDENTITY));
    }
    if st < 0 || st % 10 > 1 {
        let allowed = "_ST: units digit 0 (a new plane) or 1 (additive)";
        return Err(refused(args.column(2), allowed)(Error::BadArgument));
    }
    let allowed = "_MODE: a swivel mode (57: axis by axis X, Y, Z; 27: Z, Y, X; ...)";
    if SwivelMode::from_mode(mode) == Ok(SwivelMode::Direct) {
        return cycle800_direct(m, &args, st % 10 == 1, &w);
    }
    let call = cycle800_words(mode, &w).map_err(refused(args.column(3), allowed))?;
    let base = if st % 10 == 1 {
        m.tilt_base().map_err(at(args.column(2)))?
    } else {
        m.frame
    };
    // Without a swivel nothing moves: no retraction either. Decided before the state is
    // built, not by a return of its own (stack bound).
    let (positioning, retract, retract_mm) = if swivels {
        (Positioning::Turn, retract, retract_mm)
    } else {
        (Positioning::Stay, Retract::None, 0.0)
    };
    Ok(Modal {
        choice,
        positioning,
        retract,
        retract_mm,
        ..m.with_tilt(cycle800_apply(&base, st % 10 == 1, &call), st % 10 == 1)
    })
}

/// `CYCLE800`'s retraction before it swivels, `_FR` (with `_FR_I`): 0 none, 1 along the
/// machine's Z, 2 along Z then X, Y \[3rd: CAM posts name these three\]; 4 as far as the
/// travel allows in the tool direction, 5 by `_FR_I` mm in the tool direction \[choice: the
/// cycle's dialog has these two modes after the first three, their numbers are in no public
/// text; `_FR_I` is read only for 5, where posts that write `_DMODE` in its place leave
/// it\]. Another `_FR` (3, 6, …) is read as no retraction \[choice: the plane is read, the
/// retraction is not guessed\]; a negative one or `_FR_I`, refused.
fn cycle800_retract(args: &Args<16>) -> Result<(Retract, f64), LineError> {
    let fr = args.int(0)?;
    let allowed = "_FR: 0 (none), 1 (Z), 2 (Z, then X Y), 4 (maximum), 5 (by _FR_I)";
    Ok(match fr {
        1 => (Retract::MachineZ, 0.0),
        2 => (Retract::MachineZThenXy, 0.0),
        4 => (Retract::ToolMax, 0.0),
        5 => match args.real(14)? {
            0.0 => (Retract::None, 0.0),
            d if d > 0.0 => (Retract::Tool, d),
            _ => {
                let allowed = "_FR_I: a length >= 0";
                return Err(refused(args.column(14), allowed)(Error::BadArgument));
            }
        },
        f if f < 0 => return Err(refused(args.column(0), allowed)(Error::BadArgument)),
        _ => (Retract::None, 0.0),
    })
}

/// A `CYCLE800` in direct mode (`_MODE` bits 7..6 = 11): `_A` and `_B` are the positions
/// of the swivel data set's rotary axes 1 and 2 \[doc\], about the origin `_X0 _Y0 _Z0`; the
/// frame follows from the kinematics, so the program keeps the positions (a
/// [`Direct`] mode). Additive (`_ST` units digit 1), a `_C` (a data set has two axes) or a
/// translation `_X1 _Y1 _Z1` after a rotation only the machine knows: not read here
/// ([`Error::NotAvailable`] at that parameter). Not inlined (stack bound).
#[inline(never)]
fn cycle800_direct(
    m: &Modal,
    args: &Args<16>,
    additive: bool,
    w: &[f64; 9],
) -> Result<Modal, LineError> {
    // What may stand there instead, said with the refusal (`cncrot_program_expected`).
    const ADDITIVE: &str = "_ST units digit 0: a direct mode is not added to";
    const THIRD: &str = "0: a direct mode turns rotary axes 1 and 2 (_A, _B) only";
    const AFTER: &str = "0: a translation after a direct mode's turn needs the machine";
    let unread = [(additive, 2, ADDITIVE), (w[5] != 0.0, 9, THIRD)]
        .into_iter()
        .chain((6..9).map(|k| (w[k] != 0.0, 4 + k, AFTER)));
    for (unread, k, allowed) in unread {
        if unread {
            return Err(refused(args.column(k), allowed)(Error::NotAvailable));
        }
    }
    let direct = Direct {
        by: DirectAxes::Numbered,
        given: 0b011,
    };
    let (retract, retract_mm) = cycle800_retract(args)?;
    Ok(Modal {
        positioning: Positioning::Turn,
        retract,
        retract_mm,
        ..m.with_direct(v3(w, 0), direct, [w[3], w[4], 0.0])
    })
}

/// `CYCLE600(_INEXIN, _MIHEAD, _SW_REC, _BIN_IN, _POS_X, _POS_Y, _POS_Z, _ANG_1, _ANG_2,
/// _ANG_3, _POS_X_R, _POS_Y_R, _POS_Z_R, _INEXOUT, _BIN_OUT, _ROT_AD, _ROT_INV, _RETR_Z)`:
/// at least up to `_BIN_OUT`. The frame the cycle computes becomes the active one, as when
/// its results are passed on to CYCLE800 \[choice\]; `_ROT_AD = 1` adds to the active frame.
fn cycle600_line(m: &Modal, c: &mut Cursor, column: usize) -> Result<Modal, LineError> {
    let args = Args::<18>::read(c, 1)?;
    c.end(true, false)?;
    if args.n < 15 {
        return Err(c.missing("CYCLE600's parameters up to _BIN_OUT (15)"));
    }
    let v3 = |k: usize| -> Result<[f64; 3], LineError> {
        Ok([args.real(k)?, args.real(k + 1)?, args.real(k + 2)?])
    };
    let call = cycle600::Call {
        inexin: args.int(0)?,
        mihead: args.name(1)?,
        sw_rec: args.int(2)?,
        bin_in: args.int(3)?,
        pos: v3(4)?,
        ang: v3(7)?,
        pos_r: v3(10)?,
        inexout: args.int(13)?,
        bin_out: args.int(14)?,
        rot_ad: args.int(15)?,
        rot_inv: args.int(16)?,
        retr_z: args.int(17)?,
    };
    // The cycle checks its arguments as a whole; here each is checked first where it
    // stands, so that a bad one is reported at its own column.
    if let Some((k, error, allowed)) = cycle600::first_fault(&call) {
        return Err(refused(args.column(k).max(column), allowed)(error));
    }
    // `_ROT_AD = 1` adds to the active frame: not to a direct mode's, which only the
    // machine knows.
    if call.rot_ad == 1 && m.direct.is_some() {
        return Err(at(args.column(15).max(column))(Error::NotAvailable));
    }
    let state = cycle600::State {
        frame: m.frame,
        ..Default::default()
    };
    let next = cycle600::cycle600_in(&state, None, &call).map_err(at(column))?;
    // It swivels as the CYCLE800 it calls does.
    Ok(Modal {
        positioning: Positioning::Turn,
        ..m.with_tilt(next.frame, call.rot_ad == 1)
    })
}

/// The frame of `CYCLE800`'s words `_X0 _Y0 _Z0 _A _B _C _X1 _Y1 _Z1` in `_MODE`.
fn cycle800_words(mode: i32, w: &[f64]) -> Result<Frame, Error> {
    cycle800_frame(SwivelMode::from_mode(mode)?, v3(w, 3), v3(w, 0), v3(w, 6))
}

/// The angle mode of a form's selector: 0 RPY, 1 Euler.
fn angle_mode(selector: i32) -> Result<AngleMode, Error> {
    match selector {
        0 => Ok(AngleMode::Rpy),
        1 => Ok(AngleMode::Euler),
        _ => Err(Error::BadArgument),
    }
}

/// A SINUMERIK block that does not start with a command the library reads (`rest`, which
/// starts at byte `offset` of the line). A frame command elsewhere on it is refused at its
/// column ("frame instructions are programmed in their own block" \[doc\]); its name before
/// `(` is a frame function in an expression (`CROT(Z,30)`), not refused. Not followed:
/// the settable frames `G54`–`G57`, `G505`–`G599` and `G500`, the axial offsets `G58`/`G59`,
/// mirroring and scaling (`MIRROR`, `AMIRROR`, `SCALE`, `ASCALE`), frames from the tool
/// orientation (`TOROT`, `TOROTX`/`Y`/`Z`, `TOFRAME`, `TOFRAMEX`/`Y`/`Z`, `TOROTOF`) and from
/// the workpiece (`PAROT`, `PAROTOF`), setting actual values (`PRESETON`, `PRESETONS`),
/// and assignments to frame variables (`$P_…FRAME`,
/// `$P_UIFR[…]`, `$P_UBFR`, `$P_UGFR`). Another working plane (`G17`–`G19`) is kept, the
/// frame unchanged. Anything else is passed over (motion, `T`/`D`/`M`, `R` parameters,
/// `DEF`, control structures, calls, `TRAORI`, `G53`/`G153`/`SUPA`, which suppress frames
/// for their own block only).
#[inline(never)]
fn other_block(m: &Modal, rest: &[u8], offset: usize) -> Result<Block, LineError> {
    let comments = Comments {
        semicolon: true,
        parens: false,
    };
    // `SCALE` or `MIRROR` without values, alone on the block: like `TRANS` and `ROT`
    // without values they replace the programmable frame with none ("SCALE ; without
    // values: clears the old instructions for offset, rotation, scaling factor,
    // mirroring") [doc].
    let mut words = Tokens::new(rest, comments, false);
    if let (Some(t), None) = (words.next(), words.next()) {
        if t.is(b"SCALE") || t.is(b"MIRROR") {
            return Ok(Block::Frame(m.with_frame(Frame::IDENTITY)));
        }
    }
    const COMMANDS: [&[u8]; 10] = [
        b"ROT",
        b"CROT",
        b"AROT",
        b"ROTS",
        b"CROTS",
        b"AROTS",
        b"TRANS",
        b"ATRANS",
        b"CYCLE800",
        b"CYCLE600",
    ];
    const NOT_FOLLOWED: [&[u8]; 24] = [
        b"PRESETON",
        b"PRESETONS",
        b"G54",
        b"G55",
        b"G56",
        b"G57",
        b"G500",
        b"G58",
        b"G59",
        b"MIRROR",
        b"AMIRROR",
        b"SCALE",
        b"ASCALE",
        b"TOROT",
        b"TOROTX",
        b"TOROTY",
        b"TOROTZ",
        b"TOFRAME",
        b"TOFRAMEX",
        b"TOFRAMEY",
        b"TOFRAMEZ",
        b"TOROTOF",
        b"PAROT",
        b"PAROTOF",
    ];
    let mut not_followed = false;
    let mut plane = m.plane;
    for t in Tokens::new(rest, comments, false) {
        if let Some(p) = t.g_code().and_then(Plane::of_code) {
            plane = p;
        }
        // A frame command's name before `(` is the frame function of an expression
        // (`$P_UIFR[1]=CTRANS(X,10):CROT(Z,30)`, `$P_BFRAME=CROTS(X,10,Y,5)`), no command.
        let after = (t.column + t.value.len()).saturating_sub(1);
        let function =
            rest.get(after) == Some(&b'(') && COMMANDS.iter().take(8).any(|name| t.is(name));
        if COMMANDS.iter().any(|name| t.is(name)) && !function {
            return Err(LineError {
                error: Error::UnknownWord,
                column: offset + t.column,
                expected: None,
            });
        }
        let v = t.value;
        let starts = |p: &[u8]| v.get(..p.len()).is_some_and(|h| h.eq_ignore_ascii_case(p));
        let settable = t
            .g_code()
            .is_some_and(|c| c % 10 == 0 && (5050..=5990).contains(&c));
        let frame_variable = t.assigned
            && starts(b"$P_")
            && (v.windows(5).any(|w| w.eq_ignore_ascii_case(b"FRAME"))
                || starts(b"$P_UIFR")
                || starts(b"$P_UBFR")
                || starts(b"$P_UGFR"));
        if NOT_FOLLOWED.iter().any(|name| t.is(name)) || settable || frame_variable {
            not_followed = true;
        }
    }
    Ok(if not_followed {
        Block::NotFollowed
    } else if plane != m.plane {
        // A plane selection: the frame stays, `RPL` turns otherwise.
        Block::Frame(Modal { plane, ..*m })
    } else {
        Block::Passed
    })
}

/// The SINUMERIK family: `CYCLE800`, `CYCLE600`, the frame commands.
pub(crate) struct Sinumerik;

/// SINUMERIK's five-axis programs: `TRAORI` on, `TRAFOOF` off; the tool direction `A3 B3
/// C3`, orientation angles `A2 B2 C2` after `ORIEULER` (the default machine data) or
/// `ORIRPY`, rotary positions by axis name \[doc\]; `G90`/`G91`; arcs (`G2`, `G3`, `CIP`,
/// `CT`, modal until `G0`/`G1`, and the splines) and reference moves (`G74`) not followed.
pub(crate) const SINUMERIK_PATH: super::family::PathWords = {
    use super::family::PathCommand::{Code, Name};
    super::family::PathWords {
        iso: false,
        spaced: false,
        ex: true,
        on: &[Name(b"TRAORI")],
        off: &[Name(b"TRAFOOF")],
        vector: [b"A3", b"B3", b"C3"],
        angles: Some([b"A2", b"B2", b"C2"]),
        rpy: &[Name(b"ORIRPY")],
        euler: &[Name(b"ORIEULER")],
        incremental: &[Code(b'G', 910)],
        absolute: &[Code(b'G', 900)],
        spatial: &[],
        positions: &[],
        i_prefix: false,
        moves: &[],
        arcs: &[
            Code(b'G', 740),
            Code(b'G', 750),
            // Moves in machine coordinates (the frames suppressed for the block).
            Code(b'G', 530),
            Code(b'G', 1530),
            Name(b"SUPA"),
            // Frame commands: the coordinates after them are read in another frame.
            Name(b"TRANS"),
            Name(b"ATRANS"),
            Name(b"ROT"),
            Name(b"AROT"),
            Name(b"CROT"),
            Name(b"ROTS"),
            Name(b"AROTS"),
            Name(b"CROTS"),
            Name(b"PRESETON"),
        ],
        // G group 1: circles and splines stay in force until `G0`/`G1`.
        circular: &[
            Code(b'G', 20),
            Code(b'G', 30),
            Name(b"CIP"),
            Name(b"CT"),
            Name(b"ASPLINE"),
            Name(b"BSPLINE"),
            Name(b"CSPLINE"),
            Name(b"POLY"),
        ],
        linear: &[Code(b'G', 0), Code(b'G', 10)],
        canned: &[],
        canned_off: &[],
        // A dwell (`G4 F2`).
        still: &[Code(b'G', 40)],
        off_after: &[],
        // Program ends and returns, cycle calls (`MCALL`; each `CYCLE…` word, see
        // `toolpath`), the orientation axes moved to a position (`ORIRESET`).
        loses: &[
            Code(b'M', 20),
            Code(b'M', 300),
            Code(b'M', 170),
            Name(b"RET"),
            Name(b"MCALL"),
            Name(b"CALL"),
            Name(b"PCALL"),
            Name(b"EXTCALL"),
            Name(b"ORIRESET"),
        ],
        // The orientation relative to the path (`ORIPATH`'s lead and tilt angles), the
        // surface normals, the second curve of `ORICURVE`, the rotation about the tool.
        unread: &[
            b"LEAD", b"TILT", b"THETA", b"A4", b"B4", b"C4", b"A5", b"B5", b"C5", b"A6", b"B6",
            b"C6", b"A7", b"B7", b"C7", b"A8", b"B8", b"C8", b"XH", b"YH", b"ZH", b"PO", b"PSI",
        ],
        compensation: &[Code(b'G', 410), Code(b'G', 420)],
        compensation_off: &[Code(b'G', 400)],
        // Scaling and mirroring (a frame the tilted-plane reader does not compose), other
        // orientation angles (`ORIVIRT1/2`: machine data).
        altering: &[
            // Frames to the tool's orientation or the table's: a rotation of the frame.
            Name(b"TOFRAME"),
            Name(b"TOROT"),
            Name(b"PAROT"),
            Name(b"SCALE"),
            Name(b"ASCALE"),
            Name(b"MIRROR"),
            Name(b"AMIRROR"),
            Name(b"ORIVIRT1"),
            Name(b"ORIVIRT2"),
        ],
        unaltering: &[],
        offsets: &[],
        inch: &[Code(b'G', 700), Code(b'G', 7000)],
        metric: &[Code(b'G', 710), Code(b'G', 7100)],
    }
};

impl Family for Sinumerik {
    const TOOL_PATH: Option<&'static super::family::PathWords> = Some(&SINUMERIK_PATH);
    /// Its manual's limit for a block.
    const MAX_LINE: usize = 512;
    /// `CYCLE800`'s `_DIR` says whether the axes swivel (0: the frame alone); `ROT` says
    /// nothing, and is the same block again.
    const POSITIONING_IN_BLOCK: bool = true;
    const FORMS: &'static [FormInfo] = &[
        FormInfo {
            form: Form::Cycle800,
            words: 9,
            origin: true,
            writable: true,
        },
        FormInfo {
            form: Form::SinumerikRot,
            words: 3,
            origin: false,
            writable: true,
        },
        FormInfo {
            form: Form::SinumerikRots,
            words: 2,
            origin: false,
            writable: false,
        },
    ];

    /// One block of a SINUMERIK program: `ROT`, `AROT`, `CROT` (`X Y Z`, with or without `=`,
    /// in the program's angle mode; `ROT`/`CROT` without words cancel, and replace the whole
    /// programmable frame as the control's substituting commands do \[doc\]; `CROT` reads like
    /// `ROT` \[choice\]; or `RPL=` in the working plane), `ROTS`/`AROTS`/`CROTS` (two of
    /// `X Y Z`), `TRANS`/`ATRANS`, `CYCLE800(…)` and `CYCLE600(…)`, after a block number
    /// (`N10`, `:10`), a skip mark or a label, with `;` comments. "Frame instructions are
    /// programmed in their own block" \[doc\]: nothing else may stand on the line. `G17`,
    /// `G18`, `G19` on any other block select the working plane.
    #[inline(never)]
    fn read_line(m: &Modal, text: &[u8]) -> Result<Block, LineError> {
        let mut c = Cursor::new(text);
        c.block_number(b'N');
        if c.peek() == Some(b':') {
            c.bump();
            while c.peek().is_some_and(|b| b.is_ascii_digit()) {
                c.bump();
            }
            c.spaces();
        }
        c.label();
        if c.at_end() || c.rest_is_comment(true, false) {
            return Ok(Block::Passed);
        }
        let column = c.column();
        if c.keyword(b"CYCLE800") {
            if c.rest_is_comment(true, false) {
                // Without parentheses: the cancel, as `CYCLE800()`.
                return Ok(Block::Frame(m.with_frame(Frame::IDENTITY)));
            }
            return cycle800_line(m, &mut c).map(Block::Frame);
        }
        if c.keyword(b"CYCLE600") {
            return cycle600_line(m, &mut c, column).map(Block::Frame);
        }
        // Frame commands: (substituting, additive) × (rotation, projection, translation).
        let commands: [(&[u8], bool, u8); 8] = [
            (b"ROT", false, b'R'),
            (b"CROT", false, b'R'),
            (b"AROT", true, b'R'),
            (b"ROTS", false, b'S'),
            (b"CROTS", false, b'S'),
            (b"AROTS", true, b'S'),
            (b"TRANS", false, b'T'),
            (b"ATRANS", true, b'T'),
        ];
        let Some(&(_, additive, kind)) = commands.iter().find(|(name, _, _)| c.keyword(name))
        else {
            return other_block(m, text.get(column - 1..).unwrap_or(&[]), column - 1);
        };
        if kind == b'R' && plane_rotation(text.get(c.column() - 1..).unwrap_or(&[])) {
            return rpl_command(m, &mut c, column, additive);
        }
        frame_command(m, &mut c, column, additive, kind)
    }

    /// `CYCLE800` (`_MODE` 57), `CYCLE800 <_MODE>`, `ROT` (RPY), `ROT EULER`.
    fn parse_form(text: &[u8]) -> Result<FormSpec, Error> {
        let mut c = Cursor::new(text);
        c.spaces();
        let spec = if c.keyword(b"CYCLE800") {
            c.spaces();
            let mode = if c.at_end() { 57 } else { c.integer() };
            FormSpec {
                form: Form::Cycle800,
                selector: mode,
            }
        } else if c.keyword(b"ROT") {
            c.spaces();
            FormSpec {
                form: Form::SinumerikRot,
                selector: i32::from(c.keyword(b"EULER")),
            }
        } else {
            return Err(Error::BadArgument);
        };
        c.spaces();
        if !c.at_end() || spec.selector < 0 {
            return Err(Error::BadArgument);
        }
        Ok(spec)
    }

    /// `CYCLE800()` (deselects the swivel data set), `ROT` (no rotation); none while the
    /// axes turn to the untilted plane (a `CYCLE800` of zero angles swivels them;
    /// `CYCLE800()` turns nothing).
    fn write_cancel(spec: &FormSpec, how: Motion, _: i32, out: &mut Out) -> Result<bool, Error> {
        if spec.form != Form::Cycle800 {
            out.text(b"ROT");
        } else if how.positioning == Positioning::Stay {
            out.text(b"CYCLE800()");
        } else {
            return Ok(false);
        }
        Ok(true)
    }

    /// `CYCLE800(0,"",0,_MODE,_X0,_Y0,_Z0,_A,_B,_C,_X1,_Y1,_Z1,_DIR,0,0)` (`_DIR` 0 where
    /// the axes stay, else +1 for a plus choice, −1 otherwise, "minus" \[choice\]) or
    /// `ROT X=… Y=… Z=…`.
    #[inline(never)]
    fn write_line(
        spec: &FormSpec,
        words: &[f64],
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        let style = Style {
            plus: false,
            point: false,
        };
        match spec.form {
            Form::Cycle800 => {
                let (fr, fr_i) = retract_words(&how);
                out.text(b"CYCLE800(");
                write_integer(out, fr);
                // `_ST` 1: additive, on the swivelled plane.
                out.text(if how.relative {
                    b",\"\",1,"
                } else {
                    b",\"\",0,"
                });
                write_integer(out, spec.selector);
                for &v in words {
                    out.byte(b',');
                    write(out, v, decimals, style)?;
                }
                // `_DIR`: 0 where the axes stay (the frame alone); where they turn "minus"
                // unless the plus direction is asked for [choice: a swivel always names a
                // direction]; the direction-reference axis is machine data.
                out.text(match how.choice {
                    _ if how.positioning == Positioning::Stay => b",0,",
                    // A direction of travel has no parameter: as no choice [choice].
                    AxisChoice::Closest
                    | AxisChoice::Minus(0)
                    | AxisChoice::PositiveTurn(0)
                    | AxisChoice::NegativeTurn(0) => b",-1,",
                    AxisChoice::Plus(0) => b",1,",
                    _ => return Err(Error::NotAvailable),
                });
                write(out, fr_i, decimals, style)?;
                out.text(b",0)");
            }
            Form::SinumerikRot => {
                out.text(if how.relative { b"AROT" } else { b"ROT" });
                for (name, &v) in [&b" X="[..], b" Y=", b" Z="].iter().zip(words) {
                    write_word(out, name, v, decimals, style)?;
                }
            }
            _ => return Err(Error::BadArgument),
        }
        Ok(())
    }

    /// A `CYCLE800` in direct mode (`_MODE` 192): `_X0 _Y0 _Z0` the origin, `_A _B` the
    /// positions of rotary axes 1 and 2; the axes named by place.
    const DIRECT_HAS_ORIGIN: bool = true;

    fn write_direct(
        _: &FormSpec,
        origin: Vector,
        (direct, positions): (Direct, [f64; 3]),
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        if direct.by != DirectAxes::Numbered || positions[2] != 0.0 {
            return Err(Error::NotAvailable);
        }
        let style = Style {
            plus: false,
            point: false,
        };
        let (fr, fr_i) = retract_words(&how);
        out.text(b"CYCLE800(");
        write_integer(out, fr);
        out.text(b",\"\",0,192");
        let [a, b, _] = positions;
        for v in [origin[0], origin[1], origin[2], a, b, 0.0, 0.0, 0.0, 0.0] {
            out.byte(b',');
            write(out, v, decimals, style)?;
        }
        // `_DIR` names no choice: the positions are the solution.
        out.text(b",0,");
        write(out, fr_i, decimals, style)?;
        out.text(b",0)");
        Ok(())
    }

    /// `CYCLE800` with `_ST` 1 (additive), `AROT` for `ROT`.
    fn relative_form(spec: &FormSpec) -> Option<FormSpec> {
        matches!(spec.form, Form::Cycle800 | Form::SinumerikRot).then_some(*spec)
    }

    /// `TRANS X=… Y=… Z=…`, or `TRANS` for no shift. SINUMERIK keeps one programmable
    /// frame, which `TRANS` replaces (its rotation too).
    fn write_shift(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
        let style = Style {
            plus: false,
            point: false,
        };
        out.text(b"TRANS");
        if shift != [0.0; 3] {
            for (name, &v) in [&b" X="[..], b" Y=", b" Z="].iter().zip(&shift) {
                write_word(out, name, v, decimals, style)?;
            }
        }
        Ok(())
    }

    fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
        match form {
            Form::Cycle800 => cycle800_words(selector, words),
            Form::SinumerikRot => Ok(Frame::from_rotation(rot(
                angle_mode(selector)?,
                v3(words, 0),
            ))),
            Form::SinumerikRots => {
                let plane = match selector {
                    0 => RotsPlane::XY,
                    1 => RotsPlane::YZ,
                    2 => RotsPlane::ZX,
                    _ => return Err(Error::BadArgument),
                };
                let [a, b] = [0, 1].map(|k| words.get(k).copied().unwrap_or(0.0));
                Ok(Frame::from_rotation(rots(plane, a, b)))
            }
            _ => Err(Error::BadArgument),
        }
    }

    fn form_values(
        form: Form,
        selector: i32,
        frame: &Frame,
        out: &mut [f64; MAX_VALUES],
    ) -> Result<bool, Error> {
        let m = &frame.rotation;
        match form {
            Form::Cycle800 => {
                let mode = SwivelMode::from_mode(selector)?;
                let d = cycle800_angles(mode, m)?;
                put(out, 0, frame.translation);
                put(out, 3, d.angles);
                Ok(d.singular)
            }
            Form::SinumerikRot => {
                let (xyz, singular) = readback(angle_mode(selector)?, m)?;
                put(out, 0, xyz);
                Ok(singular)
            }
            // Not every frame is a projection.
            _ => Err(Error::BadArgument),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialects::close;
    use crate::{elementary, mul, Axis};

    #[test]
    fn mode_decoding() {
        assert_eq!(
            SwivelMode::from_mode(57),
            Ok(SwivelMode::AxisByAxis(AxisCode::new(57).unwrap()))
        );
        assert_eq!(
            SwivelMode::from_mode(3),
            Ok(SwivelMode::AxisByAxis(AxisCode::new(3).unwrap()))
        );
        assert_eq!(SwivelMode::from_mode(64), Ok(SwivelMode::SolidAngle));
        assert_eq!(
            SwivelMode::from_mode(128 + 30),
            Ok(SwivelMode::Projection(Sequence::YZX))
        );
        assert_eq!(SwivelMode::from_mode(192 + 57), Ok(SwivelMode::Direct));
        assert_eq!(SwivelMode::from_mode(22), Err(Error::BadSequence));
        assert_eq!(SwivelMode::from_mode(128 + 27), Err(Error::BadSequence));
        assert_eq!(SwivelMode::from_mode(128), Err(Error::IncompleteSequence));
        assert_eq!(SwivelMode::from_mode(256), Err(Error::BadArgument));
        assert_eq!(SwivelMode::from_mode(-1), Err(Error::BadArgument));
        for m in [57, 27, 39, 3, 64, 128 + 57, 128 + 30, 128 + 39, 192] {
            assert_eq!(SwivelMode::from_mode(m).unwrap().mode(), m);
        }
    }

    /// The worked number of docs/dialects.md: ROTS X30 Y20, γ = 28.481238°.
    #[test]
    fn rots_x30_y20() {
        let expect = [
            [0.939693, 0.163099, 0.300627],
            [0.0, 0.878973, -0.476871],
            [-0.342020, 0.448112, 0.825965],
        ];
        let f = rots(RotsPlane::XY, 30.0, 20.0);
        assert!(close(&f, &expect, 5e-7), "{f:?}");
        let gamma = (30f64.to_radians().tan() * 20f64.to_radians().cos())
            .atan()
            .to_degrees();
        assert!((gamma - 28.481238).abs() < 1e-6);
    }

    /// One solid angle alone is the rotation about its own axis (the other 0): `ROTS Z30`
    /// is Rz(30°), as `ROTS Z30 X0` and `ROTS Y0 Z30` (it was read as no rotation).
    #[test]
    fn rots_with_one_angle() {
        for (block, axis) in [
            ("ROTS Z30", Axis::Z),
            ("AROTS Z30", Axis::Z),
            ("CROTS Z30", Axis::Z),
            ("ROTS X30", Axis::X),
            ("ROTS Y30", Axis::Y),
            ("ROTS Z30 X0", Axis::Z),
            ("ROTS Y0 Z30", Axis::Z),
        ] {
            let (p, _) = crate::dialects::program::Program::default()
                .line(
                    crate::dialects::program::Dialect::Sinumerik,
                    block.as_bytes(),
                )
                .unwrap();
            let f = p.frame;
            assert!(
                close(&f.rotation, &crate::elementary(axis, 30.0), 1e-15),
                "{block}: {f:?}"
            );
        }
    }

    /// The defining geometry, for every projection position and angles in all quadrants:
    /// the new p axis is R_q(β)·e_p, and the new pq plane contains R_p(α)·e_q on the side
    /// of the new q axis.
    #[test]
    fn projection_geometry() {
        for (s, p, q) in [
            (Sequence::XYZ, Axis::X, Axis::Y),
            (Sequence::YZX, Axis::Y, Axis::Z),
            (Sequence::ZXY, Axis::Z, Axis::X),
        ] {
            for alpha in [-170.0, -95.0, -30.0, 0.0, 25.0, 89.0, 120.0] {
                for beta in [-150.0, -60.0, 0.0, 20.0, 75.0, 160.0] {
                    let f = projection(s, [alpha, beta, 0.0]);
                    let col = |k: usize| [f[0][k], f[1][k], f[2][k]];
                    let (ip, iq) = (p.index(), q.index());
                    let e = |i: usize| core::array::from_fn::<f64, 3, _>(|k| (k == i) as u8 as f64);
                    let xp = crate::rotate(&elementary(q, beta), e(ip));
                    assert!(col(ip).iter().zip(&xp).all(|(a, b)| (a - b).abs() < 1e-15));
                    let u = crate::rotate(&elementary(p, alpha), e(iq));
                    let normal = col(3 - ip - iq);
                    let dot: f64 = normal.iter().zip(&u).map(|(a, b)| a * b).sum();
                    assert!(dot.abs() < 1e-15, "{s:?} {alpha} {beta}");
                    let side: f64 = col(iq).iter().zip(&u).map(|(a, b)| a * b).sum();
                    assert!(side >= -1e-15, "{s:?} {alpha} {beta}");
                }
            }
        }
    }

    #[test]
    fn every_mode_round_trips() {
        let modes = [
            SwivelMode::from_mode(57).unwrap(),
            SwivelMode::from_mode(27).unwrap(),
            SwivelMode::from_mode(55).unwrap(),
            SwivelMode::SolidAngle,
            SwivelMode::Projection(Sequence::XYZ),
            SwivelMode::Projection(Sequence::YZX),
            SwivelMode::Projection(Sequence::ZXY),
        ];
        for mode in modes {
            for abc in [
                [30.0, 45.0, 60.0],
                [-120.0, 10.0, 170.0],
                [5.0, -80.0, -45.0],
                [0.0, 0.0, 0.0],
            ] {
                let f = cycle800_rotation(mode, abc).unwrap();
                let d = cycle800_angles(mode, &f).unwrap();
                let back = cycle800_rotation(mode, d.angles).unwrap();
                assert!(
                    close(&f, &back, 2e-15),
                    "{mode:?} {abc:?} -> {:?}",
                    d.angles
                );
            }
        }
        assert_eq!(
            cycle800_rotation(SwivelMode::Direct, [0.0; 3]),
            Err(Error::NotAvailable)
        );
        let two = SwivelMode::from_mode(3 + 4).unwrap();
        assert_eq!(
            cycle800_angles(two, &crate::IDENTITY),
            Err(Error::IncompleteSequence)
        );
    }

    #[test]
    fn projection_cannot_express_a_vertical_first_axis_with_a_turned_plane() {
        // X' = Ry(90)·e_x = −Z; a plane through it turned by 30° about it.
        let f = mul(&elementary(Axis::Y, 90.0), &elementary(Axis::X, 30.0));
        let mode = SwivelMode::Projection(Sequence::XYZ);
        assert_eq!(cycle800_angles(mode, &f), Err(Error::OutOfRange));
        // Untwisted, it is expressible (γ = 0).
        let g = elementary(Axis::Y, 90.0);
        let d = cycle800_angles(mode, &g).unwrap();
        assert!(close(
            &cycle800_rotation(mode, d.angles).unwrap(),
            &g,
            1e-15
        ));
    }

    /// The manual's read-back examples.
    #[test]
    fn control_read_back() {
        let (a, singular) =
            readback(AngleMode::Rpy, &rot(AngleMode::Rpy, [10.0, 90.0, 40.0])).unwrap();
        assert!(singular);
        assert_eq!([a[0], a[1]], [0.0, 90.0]);
        assert!((a[2] - 30.0).abs() < 1e-12);
        let (a, singular) =
            readback(AngleMode::Rpy, &rot(AngleMode::Rpy, [190.0, 0.0, -200.0])).unwrap();
        assert!(!singular);
        assert!((a[0] + 170.0).abs() < 1e-12 && a[1] == 0.0 && (a[2] - 160.0).abs() < 1e-12);
        // Euler: F = Rz(z)·Rx(x)·Rz(y), x the nutation in [0, 180].
        let f = rot(AngleMode::Euler, [30.0, 20.0, 10.0]);
        let expect = mul(
            &mul(&elementary(Axis::Z, 10.0), &elementary(Axis::X, 30.0)),
            &elementary(Axis::Z, 20.0),
        );
        assert!(close(&f, &expect, 1e-15));
        let (a, _) = readback(AngleMode::Euler, &f).unwrap();
        assert!(
            (a[0] - 30.0).abs() < 1e-12
                && (a[1] - 20.0).abs() < 1e-12
                && (a[2] - 10.0).abs() < 1e-12
        );
    }

    #[test]
    fn tool_orientation() {
        // Hand geometry: ORIRPY A2 = 90 turns +Z about X onto −Y; B2 = 90 about Y onto +X.
        assert_eq!(orirpy_vector([90.0, 0.0, 0.0]), [0.0, -1.0, 0.0]);
        assert_eq!(orirpy_vector([0.0, 90.0, 0.0]), [1.0, 0.0, 0.0]);
        assert_eq!(orirpy_vector([0.0, 90.0, 90.0]), [0.0, 1.0, 0.0]);
        // ORIEULER: B2 tilts about X, A2 turns about Z; C2 does not move the tool.
        assert_eq!(orieuler_vector([0.0, 90.0]), [0.0, -1.0, 0.0]);
        for v in [
            [1.0, 2.0, 3.0],
            [-0.5, 0.0, -2.0],
            [0.0, 3.0, 0.0],
            [1e-300, 0.0, 1e-300],
        ] {
            let u = unit_direction(v).unwrap();
            let (e, _) = orieuler_angles(v).unwrap();
            let back = orieuler_vector(e);
            assert!(
                u.iter().zip(&back).all(|(a, b)| (a - b).abs() < 1e-15),
                "{v:?}"
            );
            let (r, _) = orirpy_angles(v).unwrap();
            let back = orirpy_vector(r);
            assert!(
                u.iter().zip(&back).all(|(a, b)| (a - b).abs() < 1e-15),
                "{v:?}"
            );
        }
        assert_eq!(unit_direction([0.0; 3]), Err(Error::Degenerate));
        assert_eq!(unit_direction([f64::NAN, 0.0, 1.0]), Err(Error::Degenerate));
        assert_eq!(
            unit_direction([f64::MAX, f64::MAX, 0.0]).map(|v| v[2]),
            Ok(0.0)
        );
        assert_eq!(orieuler_angles([0.0, 0.0, -2.0]), Ok(([0.0, 180.0], true)));
    }
}
