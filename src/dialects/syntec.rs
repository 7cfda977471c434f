//! Syntec `G158`: rotation modes 0 to 4 with the order code, `X Y Z` before and `U V W`
//! after the rotation, and the `P` word that carries mode and order.
//!
//! Confidence as in [`crate::dialects::sinumerik`].

use crate::{matrix_from_angles, AxisCode, Error, Frame, Kind, Matrix, Sequence, Vector};

/// How `G158` reads `A B C`: the rotation mode \[doc\].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// 0: no rotation.
    None,
    /// 1: three rotations in the order code, each about the axes already turned ("the
    /// rotation in the latter order is based on the last rotation") \[doc\]: intrinsic.
    Order(AxisCode),
    /// 2: the rotary-axis positions themselves: the frame follows from the machine's
    /// kinematics (a program keeps the positions, [`crate::dialects::program::Direct`];
    /// [`rotation`] and [`frame`], which have no machine, refuse it with
    /// [`Error::NotAvailable`]).
    Direct,
    /// 3: `A B C` is the tool direction, the new Z axis \[doc\].
    Normal,
    /// 4: projection angles [doc wording; signs are our reading, see [`rotation`]].
    Projection,
}

/// What a `P` word says: the mode and order code, and whether it applies incrementally.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PWord {
    /// The rotation mode with its order code.
    pub mode: Mode,
    /// Applied on the active plane (`P01…`) rather than replacing it (`P10…`).
    pub incremental: bool,
}

impl PWord {
    /// Decodes `P`: the last two digits are the order code, the digit before them the mode
    /// [derived from the manual's four examples: `P10157` mode 1 order 57, `P10200`, `P10400`,
    /// `P01159` mode 1 order 59 "increment and then turn"]; the leading digits `10` mean
    /// absolute and `01` incremental (our reading of the same examples \[choice\]); other
    /// leading digits are refused ([`Error::BadArgument`]). Mode 1 needs a three-rotation
    /// or shorter valid order code ([`Error::BadSequence`]); the other modes ignore it.
    ///
    /// ```
    /// use cncrot::dialects::syntec::{Mode, PWord};
    /// let p = PWord::decode(10157).unwrap();
    /// assert!(matches!(p.mode, Mode::Order(c) if c.code() == 57) && !p.incremental);
    /// assert!(PWord::decode(1159).unwrap().incremental); // P01159
    /// ```
    pub fn decode(p: i32) -> Result<PWord, Error> {
        if !(0..=99_999).contains(&p) {
            return Err(Error::BadArgument);
        }
        let (lead, mode, order) = (p / 1000, (p / 100) % 10, p % 100);
        let incremental = match lead {
            10 => false,
            1 => true,
            _ => return Err(Error::BadArgument),
        };
        let mode = match mode {
            0 => Mode::None,
            1 => Mode::Order(AxisCode::new(order)?),
            2 => Mode::Direct,
            3 => Mode::Normal,
            4 => Mode::Projection,
            _ => return Err(Error::BadArgument),
        };
        Ok(PWord { mode, incremental })
    }
}

/// The rotation of `A B C` in a mode.
///
/// - mode 3: the new Z is `(A, B, C)` normalised; the new X lies in the old XZ plane, as in
///   mode 4: `X = (Y × Z)/|Y × Z|`, or the old X when Z is along Y [choice: the manual
///   leaves the plane's turn about the tool open and says to turn it with another block];
/// - mode 4: the new X lies in the old XZ plane at the angle A above the old XY plane, and
///   the new XY plane makes the angle B with the old Y axis; C turns in the new XY plane
///   \[doc\]: `F = Ry(−A)·Rx(B)·Rz(C)` [choice of signs: positive A lifts the new X towards +Z,
///   positive B lifts the new Y towards +Z; unverified on a control].
///
/// ```
/// use cncrot::dialects::syntec::{rotation, Mode};
/// let f = rotation(Mode::Projection, [20.0, 0.0, 0.0]).unwrap();
/// assert!((f[2][0] - 20f64.to_radians().sin()).abs() < 1e-15 && f[1][0] == 0.0);
/// ```
pub fn rotation(mode: Mode, abc: [f64; 3]) -> Result<Matrix, Error> {
    match mode {
        Mode::None => Ok(crate::IDENTITY),
        Mode::Order(code) => Ok(matrix_from_angles(Kind::Intrinsic, code, abc)),
        Mode::Direct => Err(Error::NotAvailable),
        Mode::Normal => normal(abc),
        Mode::Projection => Ok(matrix_from_angles(
            Kind::Intrinsic,
            Sequence::YXZ.into(),
            [-abc[0], abc[1], abc[2]],
        )),
    }
}

/// The frame of a `G158` block: `Trans(X, Y, Z)·Rot·Trans(U, V, W)`, `U V W` in the rotated
/// system \[doc\]; omitted words are 0. An incremental `P` applies it on the active plane,
/// in its system (`active · call`) \[derived\].
///
/// ```
/// use cncrot::dialects::syntec::{frame, PWord};
/// // The manual's example: G158 L1 P10157 X2. Y0. Z10. A20 B20 C-30 U0 V10 W0.
/// let f = frame(&cncrot::Frame::IDENTITY, PWord::decode(10157).unwrap(),
///               [2.0, 0.0, 10.0], [20.0, 20.0, -30.0], [0.0, 10.0, 0.0]).unwrap();
/// let r = cncrot::matrix_from_angles(cncrot::Kind::Intrinsic, cncrot::AxisCode::new(57).unwrap(),
///                                    [20.0, 20.0, -30.0]);
/// assert!((f.translation[0] - (2.0 + 10.0 * r[0][1])).abs() < 1e-12);
/// ```
pub fn frame(
    active: &Frame,
    p: PWord,
    xyz: Vector,
    abc: [f64; 3],
    uvw: Vector,
) -> Result<Frame, Error> {
    let call = Frame::with_translations(xyz, rotation(p.mode, abc)?, uvw);
    Ok(if p.incremental {
        active.compose(&call)
    } else {
        call
    })
}

fn normal(n: Vector) -> Result<Matrix, Error> {
    let z = crate::unit_vector(n)?;
    // Y × Z = (z_z, 0, −z_x) lies in the old XZ plane; along Y, the old X instead.
    let h = [z[2], 0.0, -z[0]];
    let hint = if h[0] * h[0] + h[2] * h[2] > crate::MIN_SINE * crate::MIN_SINE {
        h
    } else {
        [1.0, 0.0, 0.0]
    };
    crate::rotation_from_z_x(z, hint)
}

// Program lines.

use super::family::{
    put, v3, Block, Direct, DirectAxes, Family, Form, FormInfo, FormSpec, Modal, Motion,
    Positioning, MAX_VALUES,
};
use super::fanuc;
use crate::text::number::{write_integer, write_word, Out};
use crate::text::scan::{address_words, whole, Cursor, LineError, Syntax};

const SYNTAX: Syntax = crate::text::scan::ISO_WORDS;

/// The Syntec family: `G158`, and the Fanuc-style `G68.2` of its G68.2 mode.
pub(crate) struct Syntec;

/// Syntec's five-axis programs: `G43.4` and `G43.5` as Fanuc's \[doc\].
pub(crate) const SYNTEC_PATH: super::family::PathWords = super::family::iso_path(
    &[
        super::family::PathCommand::Code(b'G', 434),
        super::family::PathCommand::Code(b'G', 435),
    ],
    [b"I", b"J", b"K"],
);

impl Family for Syntec {
    const TOOL_PATH: Option<&'static super::family::PathWords> = Some(&SYNTEC_PATH);
    const MAX_LINE: usize = 256;
    const KEEPS_SHIFT: bool = true;
    const FORMS: &'static [FormInfo] = &[FormInfo {
        form: Form::G158,
        words: 9,
        origin: true,
        writable: true,
    }];

    /// `G158` and the commands of its `G68.2` mode left out.
    fn rest(text: &[u8], out: &mut Out) -> bool {
        const G158: &[(u32, &[u8])] = &[(1580, b"LPXYZABCUVW")];
        fanuc::iso_rest(text, &[G158, fanuc::FANUC_FRAME_WORDS], out)
    }

    /// One block of a Syntec program: `G158 L P X Y Z A B C U V W` (omitted words are 0,
    /// `L` accepted and ignored [choice: not documented]; `G158` without words cancels
    /// \[choice\]), and the Fanuc-style `G68.2`, `G68.4`, `G69`, `G53.1` of its G68.2 mode,
    /// with a block number, `( … )` and `;` comments.
    #[inline(never)]
    fn read_line(m: &Modal, text: &[u8]) -> Result<Block, LineError> {
        let mut c = Cursor::new(text);
        c.block_number(b'N');
        if let Some(block) = read_g158(m, &mut c)? {
            return Ok(block);
        }
        if let Some(result) = fanuc::read_g68(m, &mut c) {
            return result;
        }
        let rest = text.get(c.column() - 1..).unwrap_or(&[]);
        if let Some(result) = fanuc::read_rotation(m, &mut c, rest, text, false) {
            return result;
        }
        if fanuc::skip_leading(&mut c) {
            // `G90 G158 …`, as Fanuc's reader takes `G90 G68.2 …`.
            if let Some(block) = read_g158(m, &mut c)? {
                return fanuc::in_block_plane(m, text, Ok(block));
            }
            if let Some(result) = fanuc::read_g68(m, &mut c) {
                return fanuc::in_block_plane(m, text, result);
            }
            let rest = text.get(c.column() - 1..).unwrap_or(&[]);
            if let Some(result) = fanuc::read_rotation(m, &mut c, rest, text, false) {
                return fanuc::in_block_plane(m, text, result);
            }
        }
        fanuc::iso_block(m, text, &[1580, 682, 683, 684, 531, 533, 536], &[690], &[])
    }

    /// `G158` (`P10157`), `G158 P<p>`, `G68.2`.
    fn parse_form(text: &[u8]) -> Result<FormSpec, Error> {
        let mut c = Cursor::new(text);
        c.spaces();
        let spec = if c.keyword(b"G68.2") {
            FormSpec {
                form: Form::G68_2,
                selector: 0,
            }
        } else if c.keyword(b"G158") {
            c.spaces();
            let selector = if c.at_end() {
                10157
            } else if c.letter(b'P') {
                c.integer()
            } else {
                -1
            };
            FormSpec {
                form: Form::G158,
                selector,
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

    /// `G158` without words for its own form (it says nothing of the axes), `G69` in its
    /// G68.2 mode; none while the axes turn to the untilted plane there (`G68.2` of zeros,
    /// then `G53.1`).
    fn write_cancel(spec: &FormSpec, how: Motion, _: i32, out: &mut Out) -> Result<bool, Error> {
        if spec.form == Form::G158 {
            out.text(b"G158");
        } else if how.positioning == Positioning::Stay {
            out.text(b"G69");
        } else {
            return Ok(false);
        }
        Ok(true)
    }

    /// `G158 P X Y Z A B C U V W` or `G68.2 X Y Z I J K`, numbers always with a point.
    #[inline(never)]
    fn write_line(
        spec: &FormSpec,
        words: &[f64],
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        match spec.form {
            Form::G68_2 => super::fanuc::write_g68_2(words, how.relative, decimals, out),
            Form::G158 => {
                // Incremental: the leading digits `01` instead of `10` (`P01157`).
                if how.relative {
                    out.text(b"G158 P0");
                    write_integer(out, spec.selector - 9000);
                } else {
                    out.text(b"G158 P");
                    write_integer(out, spec.selector);
                }
                let names: [&[u8]; 9] = [
                    b" X", b" Y", b" Z", b" A", b" B", b" C", b" U", b" V", b" W",
                ];
                for (name, &v) in names.iter().zip(words) {
                    write_word(out, name, v, decimals, super::fanuc::STYLE)?;
                }
                Ok(())
            }
            _ => Err(Error::BadArgument),
        }
    }

    /// `G158 P10200 X Y Z A B C U0. V0. W0.`: mode 2, the axes named by letter.
    const DIRECT_HAS_ORIGIN: bool = true;

    fn write_direct(
        _: &FormSpec,
        origin: Vector,
        (direct, positions): (Direct, [f64; 3]),
        how: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        if direct.by != DirectAxes::Letters {
            return Err(Error::NotAvailable);
        }
        // The `G158` block of mode 2: its words as any mode's.
        let [a, b, c] = positions;
        let words = [origin[0], origin[1], origin[2], a, b, c, 0.0, 0.0, 0.0];
        let spec = FormSpec {
            form: Form::G158,
            selector: 10200,
        };
        Self::write_line(&spec, &words, how, decimals, out)
    }

    /// `G52 X Y Z`, as Fanuc writes it.
    fn write_shift(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
        fanuc::write_g52(shift, decimals, out)
    }

    /// `G53.1`/`G53.6` in the `G68.2` mode; `G158` has none in any public text.
    fn positioning_block(spec: &FormSpec, how: Motion) -> Option<&'static [u8]> {
        match spec.form {
            Form::G68_2 => fanuc::g53(how),
            _ => None,
        }
    }

    /// `G68.4` in the `G68.2` mode; `G158 P01…` for an absolute `G158 P10…` of a mode that
    /// rotates (mode 2 states positions, which do not add).
    fn relative_form(spec: &FormSpec) -> Option<FormSpec> {
        let absolute =
            PWord::decode(spec.selector).is_ok_and(|p| !p.incremental && p.mode != Mode::Direct);
        match spec.form {
            Form::G68_2 => Some(*spec),
            Form::G158 if absolute => Some(*spec),
            _ => None,
        }
    }

    fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
        if form != Form::G158 {
            return Err(Error::BadArgument);
        }
        let p = PWord::decode(selector)?;
        // Incremental P words apply on an active plane: as a lone block, on none.
        frame(
            &Frame::IDENTITY,
            p,
            v3(words, 0),
            v3(words, 3),
            v3(words, 6),
        )
    }

    fn form_values(
        form: Form,
        selector: i32,
        frame: &Frame,
        out: &mut [f64; MAX_VALUES],
    ) -> Result<bool, Error> {
        if form != Form::G158 {
            return Err(Error::BadArgument);
        }
        let p = PWord::decode(selector)?;
        if p.incremental {
            return Err(Error::BadArgument);
        }
        let d = match p.mode {
            Mode::Order(code) => {
                let seq = Sequence::from_axis_code(code)?;
                crate::angles_from_matrix(
                    crate::Convention::new(Kind::Intrinsic, seq),
                    &frame.rotation,
                )?
            }
            Mode::Direct => return Err(Error::NotAvailable),
            _ => return Err(Error::BadArgument),
        };
        put(out, 0, frame.translation);
        put(out, 3, d.angles);
        Ok(d.singular)
    }
}

/// `G158 …` where the cursor stands; `None` for another command.
fn read_g158(m: &Modal, c: &mut Cursor) -> Result<Option<Block>, LineError> {
    let column = c.column();
    if !c.code(b"G158") {
        return Ok(None);
    }
    if c.rest_is_comment(true, true) {
        c.end(true, true)?;
        return Ok(Some(Block::Frame(m.with_frame(Frame::IDENTITY))));
    }
    let w = address_words(c, *b"LPXYZABCUVW", SYNTAX, false, (true, true))?;
    let [_, pw, x, y, z, a, b, cc, u, v, ww] = w.values;
    if !w.given[1] {
        return Err(c.missing("P"));
    }
    // A bad P is reported at its value, not at the command.
    let at = w.column(1);
    let pword = LineError::at(at, PWord::decode(whole(pw, at)?))?;
    // Incremental on the active tilt, about its datum (the shift is added once).
    let base = if pword.incremental {
        LineError::at(column, m.tilt_base())?
    } else {
        Frame::IDENTITY
    };
    if pword.mode == Mode::Direct {
        // The positions of the axes A, B, C (omitted: 0); the axes turn there [doc:
        // "the rotary axis will be selected to be actuated"]. On an active plane, or
        // with `U V W` after a rotation only the machine knows: not followed here.
        if pword.incremental || [u, v, ww] != [0.0; 3] {
            return LineError::at(column, Err(Error::NotAvailable));
        }
        let direct = Direct {
            by: DirectAxes::Letters,
            given: 0b111,
        };
        return Ok(Some(Block::Frame(Modal {
            positioning: Positioning::Turn,
            ..m.with_direct([x, y, z], direct, [a, b, cc])
        })));
    }
    let f = frame(&base, pword, [x, y, z], [a, b, cc], [u, v, ww]);
    let f = LineError::at(column, f)?;
    Ok(Some(Block::Frame(m.with_tilt(f, pword.incremental))))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn p_words_of_the_manual() {
        assert_eq!(
            PWord::decode(10200),
            Ok(PWord {
                mode: Mode::Direct,
                incremental: false
            })
        );
        assert_eq!(PWord::decode(10400).map(|p| p.mode), Ok(Mode::Projection));
        let p = PWord::decode(1159).unwrap();
        assert!(p.incremental && matches!(p.mode, Mode::Order(c) if c.code() == 59));
        assert_eq!(PWord::decode(10122), Err(Error::BadSequence));
        for bad in [157, 20157, 10557, -1, 100_000] {
            assert_eq!(PWord::decode(bad), Err(Error::BadArgument), "P{bad}");
        }
        assert_eq!(
            rotation(Mode::Direct, [0.0, 20.0, 45.0]),
            Err(Error::NotAvailable)
        );
    }

    #[test]
    fn mode_4_geometry() {
        // The new X in the old XZ plane at A above XY; the old Y at B from the new XY plane.
        for (a, b, c) in [(20.0, 30.0, 0.0), (20.0, 30.0, 15.0), (-40.0, 10.0, 0.0)] {
            let f = rotation(Mode::Projection, [a, b, c]).unwrap();
            if c == 0.0 {
                let x = [f[0][0], f[1][0], f[2][0]];
                assert!(x[1].abs() < 1e-15);
                assert!((x[2] - f64::to_radians(a).sin()).abs() < 1e-15);
                // sin(angle between e_y and the new XY plane) = |Z'·e_y|.
                assert!((f[1][2].abs() - f64::to_radians(b).sin()).abs() < 1e-15);
            }
            assert!(crate::orthonormality_error(&f) < 1e-15);
        }
    }

    #[test]
    fn mode_3_normal() {
        let f = rotation(Mode::Normal, [0.0, 0.0, 5.0]).unwrap();
        assert_eq!(f, crate::IDENTITY);
        for n in [[1.0, 2.0, 3.0], [0.0, 1.0, 0.0], [-1.0, 0.0, -1.0]] {
            let f = rotation(Mode::Normal, n).unwrap();
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((0..3).all(|i| (f[i][2] - n[i] / len).abs() < 1e-15));
            assert!(f[1][0].abs() < 1e-15, "X' in the old XZ plane");
            assert!(crate::orthonormality_error(&f) < 1e-15 && crate::determinant(&f) > 0.0);
        }
        assert_eq!(rotation(Mode::Normal, [0.0; 3]), Err(Error::Degenerate));
    }

    #[test]
    fn incremental_applies_on_the_active_plane() {
        let a = frame(
            &Frame::IDENTITY,
            PWord::decode(10157).unwrap(),
            [0.0; 3],
            [0.0, 20.0, 0.0],
            [0.0; 3],
        )
        .unwrap();
        let b = frame(
            &a,
            PWord::decode(1159).unwrap(),
            [0.0; 3],
            [10.0, 0.0, 0.0],
            [0.0; 3],
        )
        .unwrap();
        let expect = crate::mul(&a.rotation, &crate::elementary(crate::Axis::Z, 10.0));
        let d = b.rotation.iter().flatten().zip(expect.iter().flatten());
        assert!(d.map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) < 1e-15);
    }
}
