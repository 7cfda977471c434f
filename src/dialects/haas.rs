//! Haas `G268`/`G269`: the tilted working plane with a sequence of fixed-axis rotations.
//!
//! Confidence as in [`crate::dialects::sinumerik`].

use super::fanuc;
use crate::{angles_from_matrix, Convention, Decomposition, Error, Frame, Kind, Sequence, Vector};

/// The rotation order of a `Q` word: its three digits name the fixed axes in the order the
/// rotations are made (1 = X with angle `I`, 2 = Y with `J`, 3 = Z with `K`), e.g. `Q123`:
/// about X by I, then about the fixed Y by J, then about the fixed Z by K:
/// `F = Rz(K)·Ry(J)·Rx(I)` [3rd: the main CAM post writes it so]. Only the six orders of the
/// three axes are accepted ([`Error::BadSequence`]); Haas's default for a missing `Q` is not
/// public, so `Q` is required here \[choice\]. The same reading as Fanuc's roll-pitch-yaw
/// form ([`fanuc::fixed_order`]).
///
/// ```
/// use cncrot::dialects::haas::q_order;
/// assert_eq!(q_order(123).unwrap().code(), 57); // X, Y, Z
/// assert!(q_order(313).is_err());
/// ```
pub fn q_order(q: i32) -> Result<Sequence, Error> {
    fanuc::fixed_order(q)
}

/// `G268 X Y Z I J K Q`: origin `X Y Z`, then the fixed-axis rotations of `Q` with each
/// axis's own angle (I about X, J about Y, K about Z): the frame of Fanuc's
/// `G68.2 P1 Q X Y Z I J K` ([`fanuc::g68_2_rpy`]).
///
/// ```
/// use cncrot::dialects::haas::g268;
/// let f = g268([0.0; 3], [0.0, 0.0, 90.0], 123).unwrap();
/// assert_eq!(f.rotation, cncrot::elementary(cncrot::Axis::Z, 90.0));
/// ```
pub fn g268(origin: Vector, ijk: [f64; 3], q: i32) -> Result<Frame, Error> {
    fanuc::g68_2_rpy(origin, q, ijk)
}

/// `I, J, K` of a rotation for a `Q` order (the middle rotation's angle in [-90, 90]; at
/// ±90 the last rotation's angle is 0, `singular`).
pub fn g268_angles(m: &crate::Matrix, q: i32) -> Result<([f64; 3], bool), Error> {
    let s = q_order(q)?;
    let d: Decomposition = angles_from_matrix(Convention::new(Kind::Extrinsic, s), m)?;
    let mut ijk = [0.0; 3];
    for (a, v) in s.axes().iter().zip(d.angles) {
        ijk[a.index()] = v;
    }
    Ok((ijk, d.singular))
}

/// `G269`: no tilted plane.
pub const G269: Frame = Frame::IDENTITY;

// Program lines.

use super::family::{
    put, v3, Block, Family, Form, FormInfo, FormSpec, Modal, Motion, Positioning, MAX_VALUES,
};
use crate::text::number::{write_integer, write_word, Out, Style};
use crate::text::scan::{address_words, whole, Cursor, LineError, Syntax};

const SYNTAX: Syntax = crate::text::scan::ISO_WORDS;

/// The Haas family: `G268`, `G269`.
pub(crate) struct Haas;

/// Haas's five-axis programs: `G234` (tool centre point control, rotary positions `A B C`)
/// on, `G49` off \[doc\]; no direction words.
pub(crate) const HAAS_PATH: super::family::PathWords = super::family::iso_path(
    &[super::family::PathCommand::Code(b'G', 2340)],
    [b"", b"", b""],
);

impl Family for Haas {
    const TOOL_PATH: Option<&'static super::family::PathWords> = Some(&HAAS_PATH);
    const MAX_LINE: usize = 256;
    const KEEPS_SHIFT: bool = true;
    const FORMS: &'static [FormInfo] = &[FormInfo {
        form: Form::G268,
        words: 6,
        origin: true,
        writable: true,
    }];

    /// `G268`, `G269`, `G253`, `G52` and their words left out.
    fn rest(text: &[u8], out: &mut Out) -> bool {
        const WORDS: &[(u32, &[u8])] =
            &[(2680, b"XYZIJKQ"), (2690, b""), (2530, b""), (520, b"XYZ")];
        fanuc::iso_rest(text, &[WORDS], out)
    }

    /// One block of a Haas program: `G268 X Y Z I J K Q` (omitted `X … K` are 0; `Q` is
    /// required [choice: Haas's default is not public]), `G269` (cancel), `G253` (orients
    /// the spindle: no frame change), with a block number and `( … )` comments. A `G268`
    /// while one is active replaces it \[choice\].
    #[inline(never)]
    fn read_line(m: &Modal, text: &[u8]) -> Result<Block, LineError> {
        let mut c = Cursor::new(text);
        c.block_number(b'N');
        if let Some(block) = read_g268(m, &mut c)? {
            return Ok(block);
        }
        if c.code(b"G52") {
            return fanuc::read_g52(m, &mut c);
        }
        if c.code(b"G253") {
            // Turns the tool to the plane (with none active, to the untilted one): no frame
            // change.
            return c.end(true, true).map(|()| {
                Block::Frame(Modal {
                    positioning: Positioning::Turn,
                    ..*m
                })
            });
        }
        // Haas adds `G154` (work offsets P1–P99), `G100`/`G101` (mirroring), `G254`/`G255`
        // (dynamic work offsets) to the ISO codes the library does not follow, and Fanuc's
        // tilts `G68.2`, `G68.3`, `G68.4`, which are not a Haas's (it writes `G268`): a
        // program read in the wrong dialect is flagged, not passed over in silence.
        // After the modal words a post writes before it (`G0 G90 G268 …`), as Fanuc's reader
        // takes them before `G68.2`.
        if fanuc::skip_leading(&mut c) {
            if let Some(block) = read_g268(m, &mut c)? {
                return fanuc::in_block_plane(m, text, Ok(block));
            }
        }
        fanuc::iso_block(
            m,
            text,
            &[2680, 2530],
            &[2690],
            &[1540, 1000, 1010, 2540, 2550, 682, 683, 684],
        )
    }

    /// `G268` (`Q123`), `G268 Q<q>`.
    fn parse_form(text: &[u8]) -> Result<FormSpec, Error> {
        let mut c = Cursor::new(text);
        c.spaces();
        if !c.keyword(b"G268") {
            return Err(Error::BadArgument);
        }
        c.spaces();
        let selector = if c.at_end() {
            123
        } else if c.letter(b'Q') {
            c.integer()
        } else {
            -1
        };
        c.spaces();
        if !c.at_end() || selector < 0 {
            return Err(Error::BadArgument);
        }
        Ok(FormSpec {
            form: Form::G268,
            selector,
        })
    }

    /// `G269`; none while the axes turn to the untilted plane (`G268` of zeros, then `G253`).
    fn write_cancel(_: &FormSpec, how: Motion, _: i32, out: &mut Out) -> Result<bool, Error> {
        if how.positioning != Positioning::Stay {
            return Ok(false);
        }
        out.text(b"G269");
        Ok(true)
    }

    /// `G268 X Y Z I J K Q`, numbers always with a point.
    #[inline(never)]
    fn write_line(
        spec: &FormSpec,
        words: &[f64],
        _: Motion,
        decimals: i32,
        out: &mut Out,
    ) -> Result<(), Error> {
        if spec.form != Form::G268 {
            return Err(Error::BadArgument);
        }
        let style = Style {
            plus: false,
            point: true,
        };
        out.text(b"G268");
        for (name, &v) in [b" X", b" Y", b" Z", b" I", b" J", b" K"].iter().zip(words) {
            write_word(out, *name, v, decimals, style)?;
        }
        out.text(b" Q");
        write_integer(out, spec.selector);
        Ok(())
    }

    /// `G52 X Y Z`, as Fanuc writes it.
    fn write_shift(shift: Vector, decimals: i32, out: &mut Out) -> Result<(), Error> {
        fanuc::write_g52(shift, decimals, out)
    }

    /// `G253` (the spindle turned normal to the plane) for either way of turning: Haas has no
    /// code that keeps the tool tip \[choice\].
    fn positioning_block(_: &FormSpec, how: Motion) -> Option<&'static [u8]> {
        match how.positioning {
            Positioning::Stay => None,
            Positioning::Turn | Positioning::Move => Some(b"G253"),
        }
    }

    fn form_frame(form: Form, selector: i32, words: &[f64]) -> Result<Frame, Error> {
        if form != Form::G268 {
            return Err(Error::BadArgument);
        }
        g268(v3(words, 0), v3(words, 3), selector)
    }

    fn form_values(
        form: Form,
        selector: i32,
        frame: &Frame,
        out: &mut [f64; MAX_VALUES],
    ) -> Result<bool, Error> {
        if form != Form::G268 {
            return Err(Error::BadArgument);
        }
        let (ijk, singular) = g268_angles(&frame.rotation, selector)?;
        put(out, 0, frame.translation);
        put(out, 3, ijk);
        Ok(singular)
    }
}

/// `G268 X Y Z I J K Q` or `G269` where the cursor stands; `None` for neither.
fn read_g268(m: &Modal, c: &mut Cursor) -> Result<Option<Block>, LineError> {
    let column = c.column();
    if c.code(b"G268") {
        let w = address_words(c, *b"XYZIJKQ", SYNTAX, false, (true, true))?;
        let [x, y, z, i, j, k, q] = w.values;
        if !w.given[6] {
            return Err(c.missing("Q"));
        }
        // A bad Q is reported at its value, not at the command.
        let q = whole(q, w.column(6))?;
        LineError::at(w.column(6), q_order(q))?;
        let frame = LineError::at(column, g268([x, y, z], [i, j, k], q))?;
        return Ok(Some(Block::Frame(m.with_frame(frame))));
    }
    if c.code(b"G269") {
        // With other words on the block, the cancel is found among them (`iso_block`); an
        // unclosed comment is malformed text.
        match c.end(true, true) {
            Ok(()) => return Ok(Some(Block::Frame(m.with_frame(Frame::IDENTITY)))),
            Err(e) if e.error == Error::Parse => return Err(e),
            Err(_) => {}
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{elementary, mul, Axis};

    #[test]
    fn q123_is_fixed_x_then_y_then_z() {
        let f = g268([1.0, 2.0, 3.0], [10.0, 20.0, 30.0], 123).unwrap();
        let expect = mul(
            &mul(&elementary(Axis::Z, 30.0), &elementary(Axis::Y, 20.0)),
            &elementary(Axis::X, 10.0),
        );
        let d = f.rotation.iter().flatten().zip(expect.iter().flatten());
        assert!(d.map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) < 1e-15);
        assert_eq!(f.translation, [1.0, 2.0, 3.0]);
        // Q321: fixed Z by K first, then Y by J, then X by I.
        let g = g268([0.0; 3], [10.0, 20.0, 30.0], 321).unwrap();
        let expect = mul(
            &mul(&elementary(Axis::X, 10.0), &elementary(Axis::Y, 20.0)),
            &elementary(Axis::Z, 30.0),
        );
        let d = g.rotation.iter().flatten().zip(expect.iter().flatten());
        assert!(d.map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) < 1e-15);
    }

    #[test]
    fn every_order_round_trips_and_bad_orders_are_refused() {
        for q in [123, 132, 213, 231, 312, 321] {
            let f = g268([0.0; 3], [15.0, -40.0, 100.0], q).unwrap();
            let (ijk, _) = g268_angles(&f.rotation, q).unwrap();
            let back = g268([0.0; 3], ijk, q).unwrap();
            let d = back
                .rotation
                .iter()
                .flatten()
                .zip(f.rotation.iter().flatten());
            assert!(
                d.map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) < 2e-15,
                "Q{q}"
            );
        }
        for q in [0, 12, 113, 121, 124, 333, 1234, -123] {
            assert_eq!(q_order(q), Err(Error::BadSequence), "Q{q}");
        }
    }
}
