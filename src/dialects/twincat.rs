//! Beckhoff TwinCAT NC I: `ROT`, `AROT`, their cancellation, and the vector functions
//! `CalcRot`, `CalcInvRot`, `RotVec`.
//!
//! Confidence as in [`crate::dialects::sinumerik`]. TwinCAT CNC (the ISG kernel, another
//! product) rotates negatively about Y in its YPR mode: this module is NC I only.

use crate::{
    angles_from_matrix, matrix_from_angles, rotate, rotate_inverse, Convention, Error, Kind,
    Matrix, Sequence, Vector,
};

/// The rotation TwinCAT NC I keeps: the angles `[x, y, z]` of the last `ROT` plus every
/// `AROT` since. The control keeps angles, not a matrix ("`CalcRot` rotates through the
/// current rotation angle; the rotation angles had been determined by `ROT` or `AROT`"
/// \[doc\]), so `AROT` adds to them \[derived\]. The default is no rotation.
///
/// ```
/// use cncrot::dialects::twincat::Rotation;
/// // The manual's example: ROT Z30, then AROT Z15, is a rotation of 45° about Z.
/// let r = Rotation::default().rot([0.0, 0.0, 30.0]).arot([0.0, 0.0, 15.0]);
/// assert_eq!(r.angles, [0.0, 0.0, 45.0]);
/// // After ROT Z45, CalcInvRot of (40, 10, 0) is (35.36, -21.21, 0).
/// let v = Rotation::default().rot([0.0, 0.0, 45.0]).calc_inv_rot([40.0, 10.0, 0.0]);
/// assert!((v[0] - 35.3553).abs() < 1e-4 && (v[1] + 21.2132).abs() < 1e-4);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Rotation {
    /// `x`, `y`, `z` in degrees, as programmed and added (not reduced).
    pub angles: [f64; 3],
}

impl Rotation {
    /// `ROT X Y Z`: replaces the rotation (omitted words are 0; `ROT` without words
    /// cancels).
    pub fn rot(self, xyz: [f64; 3]) -> Rotation {
        Rotation { angles: xyz }
    }

    /// `AROT X Y Z`: adds to the active angles \[derived\].
    pub fn arot(self, xyz: [f64; 3]) -> Rotation {
        Rotation {
            angles: core::array::from_fn(|k| self.angles[k] + xyz[k]),
        }
    }

    /// The rotation matrix: about the global axes Z, then Y, then X, whatever the order of
    /// the words \[doc\]: `F = Rx(x)·Ry(y)·Rz(z)`.
    pub fn matrix(&self) -> Matrix {
        matrix(self.angles)
    }

    /// `CalcRot`: the vector rotated by the active rotation, `F·v` \[doc\].
    pub fn calc_rot(&self, v: Vector) -> Vector {
        rotate(&self.matrix(), v)
    }

    /// `CalcInvRot`: turned back, `Fᵀ·v` ("the signs inverted, the order X, Y, Z") \[doc\].
    pub fn calc_inv_rot(&self, v: Vector) -> Vector {
        rotate_inverse(&self.matrix(), v)
    }
}

/// `F = Rx(x)·Ry(y)·Rz(z)` for `[x, y, z]` (extrinsic Z, Y, X).
pub fn matrix([x, y, z]: [f64; 3]) -> Matrix {
    matrix_from_angles(Kind::Extrinsic, Sequence::ZYX.into(), [z, y, x])
}

/// `RotVec[x; y; z; α; β; γ]`: the vector rotated by the given angles in the order of `ROT`,
/// without touching the active rotation \[doc\].
pub fn rot_vec(v: Vector, xyz: [f64; 3]) -> Vector {
    rotate(&matrix(xyz), v)
}

/// `[x, y, z]` for a `ROT` of a rotation: y in [-90, 90], x and z in (-180, 180]. At
/// y = ±90 only one combination of x and z is determined: the last rotation's angle, x, is
/// set to 0 and z carries it (`singular`), the library's rule in rotation order \[choice\].
pub fn rot_angles(m: &Matrix) -> Result<([f64; 3], bool), Error> {
    let d = angles_from_matrix(Convention::new(Kind::Extrinsic, Sequence::ZYX), m)?;
    let [z, y, x] = d.angles;
    Ok(([x, y, z], d.singular))
}

// Program lines.

use super::family::{
    no_selector, put, v3, Block, Family, Form, FormInfo, FormSpec, Modal, Motion, MAX_VALUES,
};
use crate::text::number::{write_word, Out, Style};
use crate::text::scan::{address_words, Comments, Cursor, LineError, Syntax, Tokens};
use crate::Frame;

const SYNTAX: Syntax = crate::text::scan::G_WORDS;

/// A TwinCAT block that does not start with `ROT`, `AROT`, `ROTEXON`, `ROTEXOFF`, `G58`: `ROT`
/// or `AROT` elsewhere on it is refused at its column (the command starts its block), the
/// zero offsets `G53` (all suppressed: modal in NC I), `G54`–`G57` (from the table),
/// `G58` not at the start, `G59` (the second programmable shift: the state holds one
/// \[choice\]), `G92` and mirroring `G351`, the coordinate systems `#CS`, `#ACS`, and the
/// contour rotation in the plane `G68 R X Y` and `#ROTATION ON`/`OFF` (TwinCAT CNC: its
/// centre the current position where not written) are not followed, anything else is passed
/// over (`G69`, which ends a contour rotation the state never held).
#[inline(never)]
fn other_block(text: &[u8]) -> Result<Block, LineError> {
    let comments = Comments {
        semicolon: true,
        parens: true,
    };
    let mut not_followed = false;
    for t in Tokens::new(text, comments, false) {
        if t.is(b"ROT") || t.is(b"AROT") {
            return Err(LineError {
                error: Error::UnknownWord,
                column: t.column,
                expected: None,
            });
        }
        let offset = matches!(
            t.g_code(),
            Some(530 | 540 | 550 | 560 | 570 | 580 | 590 | 680 | 920 | 3510)
        );
        if offset || t.is(b"#CS") || t.is(b"#ACS") || t.is(b"#ROTATION") {
            not_followed = true;
        }
    }
    Ok(if not_followed {
        Block::NotFollowed
    } else {
        Block::Passed
    })
}

/// `G58 X Y Z` after its code: the first programmable zero offset shift, set whole ("the
/// new translation value is given by the parameters X, Y, Z" \[doc\]), an omitted word 0
/// \[choice: the NC I manual's example `G58 X200 Y0` names no Z; the TwinCAT 3 manual calls
/// all three mandatory\]; at least one word. It adds to the adjustable shift `G54`–`G57`
/// selects (not followed: a table's), and the rotation turns about the whole shift ("the
/// total zero offset shift currently active describes the rotation centre" \[doc\]): the
/// state's datum shift, the rotation kept about it.
fn read_g58(m: &Modal, c: &mut Cursor) -> Result<Block, LineError> {
    let w = address_words(c, *b"XYZ", SYNTAX, true, (true, true))?;
    if !w.given.contains(&true) {
        return Err(c.missing("X, Y or Z"));
    }
    Ok(Block::Frame(m.with_shift(w.values)))
}

/// The TwinCAT NC I family: `ROT`, `AROT`, `G58`.
pub(crate) struct Twincat;

impl Family for Twincat {
    const MAX_LINE: usize = 256;
    const FORMS: &'static [FormInfo] = &[FormInfo {
        form: Form::TwincatRot,
        words: 3,
        origin: false,
        writable: true,
    }];

    /// One block of a TwinCAT NC I program: `ROT X Y Z` (no words: cancel), `AROT X Y Z`,
    /// `G58 X Y Z` (the programmable zero offset shift: the datum the rotation turns about),
    /// and `RotExOn`/`RotExOff` (no frame change), with a block number and `( … )` or `;`
    /// comments. "The rotation instructions must be programmed in their own block"
    /// \[doc\]: nothing else may stand on the line.
    #[inline(never)]
    fn read_line(m: &Modal, text: &[u8]) -> Result<Block, LineError> {
        let mut c = Cursor::new(text);
        c.block_number(b'N');
        let column = c.column();
        let additive = if c.keyword(b"ROT") {
            false
        } else if c.keyword(b"AROT") {
            true
        } else if c.keyword(b"ROTEXON") || c.keyword(b"ROTEXOFF") {
            c.end(true, true)?;
            return Ok(Block::Frame(*m));
        } else if c.code(b"G58") {
            return read_g58(m, &mut c);
        } else {
            return other_block(text);
        };
        // `=` before a value is allowed (`X=R1` is how NC I assigns a parameter).
        let w = address_words(&mut c, *b"XYZ", SYNTAX, true, (true, true))?;
        let xyz = w.values;
        let angles = if additive {
            if !w.given.contains(&true) {
                return Err(c.missing("X, Y or Z"));
            }
            Rotation { angles: m.angles }.arot(xyz).angles
        } else {
            xyz
        };
        if !angles.iter().all(|a| a.is_finite()) {
            return Err(LineError {
                error: Error::OutOfRange,
                column,
                expected: None,
            });
        }
        // About the datum the zero offsets shift to.
        Ok(Block::Frame(Modal {
            angles: angles.map(|a| a + 0.0),
            // Angles add: one axis' increment is a rotation composed with the frame (the
            // same each time a loop repeats it); two or more are not [derived].
            relative: additive && xyz.iter().filter(|a| **a != 0.0).count() == 1,
            ..m.with_frame(Frame::from_rotation(matrix(angles)))
        }))
    }

    const KEEPS_SHIFT: bool = true;

    /// TwinCAT keeps its programmed angles: the rotation must be theirs.
    fn consistent(m: &Modal) -> bool {
        matrix(m.angles) == m.frame.rotation
    }

    /// `ROT`.
    fn parse_form(text: &[u8]) -> Result<FormSpec, Error> {
        let mut c = Cursor::new(text);
        c.spaces();
        if !c.keyword(b"ROT") {
            return Err(Error::BadArgument);
        }
        c.spaces();
        if !c.at_end() {
            return Err(Error::BadArgument);
        }
        Ok(FormSpec {
            form: Form::TwincatRot,
            selector: 0,
        })
    }

    /// `G58 X… Y… Z…` (all three: the command sets the whole translation; zero is its
    /// reset).
    fn write_shift(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
        let style = Style {
            plus: false,
            point: false,
        };
        out.text(b"G58");
        for (name, &v) in [&b" X"[..], b" Y", b" Z"].iter().zip(&shift) {
            write_word(out, name, v, decimals, style)?;
        }
        Ok(())
    }

    /// None of its own: `ROT X0 Y0 Z0` is TwinCAT's rotation off.
    fn write_cancel(_: &FormSpec, _: Motion, _: i32, _: &mut Out) -> Result<bool, Error> {
        Ok(false)
    }

    /// `ROT X… Y… Z…`.
    #[inline(never)]
    fn write_line(
        spec: &FormSpec,
        words: &[f64],
        _: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        if spec.form != Form::TwincatRot {
            return Err(Error::BadArgument);
        }
        let style = Style {
            plus: false,
            point: false,
        };
        out.text(b"ROT");
        for (name, &v) in [&b" X"[..], b" Y", b" Z"].iter().zip(words) {
            write_word(out, name, v, decimals, style)?;
        }
        Ok(())
    }

    fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
        no_selector(selector)?;
        if form != Form::TwincatRot {
            return Err(Error::BadArgument);
        }
        Ok(Frame::from_rotation(matrix(v3(words, 0))))
    }

    fn form_values(
        form: Form,
        selector: i32,
        frame: &Frame,
        out: &mut [f64; MAX_VALUES],
    ) -> Result<bool, Error> {
        no_selector(selector)?;
        if form != Form::TwincatRot {
            return Err(Error::BadArgument);
        }
        let (xyz, singular) = rot_angles(&frame.rotation)?;
        put(out, 0, xyz);
        Ok(singular)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{elementary, mul, Axis};

    #[test]
    fn order_is_z_then_y_then_x_about_the_global_axes() {
        let f = matrix([10.0, 20.0, 30.0]);
        let expect = mul(
            &mul(&elementary(Axis::X, 10.0), &elementary(Axis::Y, 20.0)),
            &elementary(Axis::Z, 30.0),
        );
        let d = f
            .iter()
            .flatten()
            .zip(expect.iter().flatten())
            .map(|(a, b)| (a - b).abs());
        assert!(d.fold(0.0, f64::max) < 1e-15);
        // TwinCAT's frame example: transRotZ(45) twice maps (30, 0, 0) to
        // (0, 30, 0).
        let r = Rotation::default()
            .rot([0.0, 0.0, 45.0])
            .arot([0.0, 0.0, 45.0]);
        let p = r.calc_rot([30.0, 0.0, 0.0]);
        assert!(p[0].abs() < 1e-14 && (p[1] - 30.0).abs() < 1e-14);
        assert_eq!(
            r.calc_inv_rot(p).map(|x| (x * 1e9).round() / 1e9),
            [30.0, 0.0, 0.0]
        );
    }

    #[test]
    fn angles_round_trip_and_cancel() {
        for a in [[10.0, 20.0, 30.0], [-170.0, 80.0, 5.0], [0.0, 90.0, 40.0]] {
            let (b, _) = rot_angles(&matrix(a)).unwrap();
            let d = matrix(b)
                .iter()
                .flatten()
                .zip(matrix(a).iter().flatten())
                .map(|(x, y)| (x - y).abs())
                .fold(0.0, f64::max);
            assert!(d < 2e-15, "{a:?} {b:?}");
        }
        let r = Rotation::default().rot([1.0, 2.0, 3.0]).rot([0.0; 3]);
        assert_eq!(r.matrix(), crate::IDENTITY);
        assert_eq!(rot_vec([1.0, 0.0, 0.0], [0.0, 0.0, 90.0]), [0.0, 1.0, 0.0]);
    }
}
