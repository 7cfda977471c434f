//! Program lines: what a block of a part program does to the active frame, in each
//! controller's own syntax, and the line that programs a given frame.
//!
//! A [`Program`] is the modal state a controller keeps between blocks (the active frame,
//! TwinCAT's programmed angles, SINUMERIK's angle mode); [`Program::line`] applies one block
//! and returns the next state, so a refused block leaves the caller's state as it was.
//! [`write_line`] is the inverse: the block that the same dialect's reader turns into a frame.
//! The syntax each dialect accepts is in that dialect's module (`read_line`, `write_line`);
//! this module holds what they share: the state, the scanner and the errors with columns.

use super::form::{self, Form, MAX_VALUES};
use super::{fanuc, haas, heidenhain, sinumerik, syntec, twincat};
use crate::text::number::Out;
use crate::text::scan::Cursor;
pub use crate::text::scan::LineError;
use crate::{Error, Frame};

/// A controller family whose program lines the library reads and writes.
///
/// ```
/// use cncrot::dialects::program::Dialect;
/// assert_eq!(Dialect::from_code(2), Ok(Dialect::Heidenhain));
/// assert_eq!(Dialect::Heidenhain.max_line(), 254);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dialect {
    /// Siemens SINUMERIK (`CYCLE800`, `CYCLE600`, `ROT`/`AROT`/`CROT`, `ROTS`, `TRANS`).
    Sinumerik = 1,
    /// Heidenhain TNC plain language (`PLANE …`).
    Heidenhain = 2,
    /// Fanuc and the controls that read its `G68.2`/`G68.4`/`G69`.
    Fanuc = 3,
    /// Syntec (`G158`, and its Fanuc-style `G68.2` mode).
    Syntec = 4,
    /// Beckhoff TwinCAT NC I (`ROT`, `AROT`).
    Twincat = 5,
    /// Haas (`G268`, `G269`).
    Haas = 6,
}

impl Dialect {
    /// Every dialect, in code order.
    pub const ALL: [Dialect; 6] = [
        Dialect::Sinumerik,
        Dialect::Heidenhain,
        Dialect::Fanuc,
        Dialect::Syntec,
        Dialect::Twincat,
        Dialect::Haas,
    ];

    /// The dialect of a code (1..=6), else [`Error::BadArgument`].
    pub fn from_code(code: i32) -> Result<Dialect, Error> {
        usize::try_from(code)
            .ok()
            .and_then(|c| c.checked_sub(1))
            .and_then(|i| Dialect::ALL.get(i).copied())
            .ok_or(Error::BadArgument)
    }

    /// The longest block the dialect's reader accepts, in bytes without the line end:
    /// SINUMERIK 512 (its manual's limit for a block), Heidenhain 254 \[choice\], the others
    /// 256 \[choice\].
    pub fn max_line(self) -> usize {
        match self {
            Dialect::Sinumerik => 512,
            Dialect::Heidenhain => 254,
            _ => 256,
        }
    }
}

/// The modal state of a program: what the blocks read so far have left active. The
/// default is nothing active.
///
/// ```
/// use cncrot::dialects::program::{Dialect, Program};
/// // The TwinCAT manual's example: ROT Z30, then AROT Z15, is a rotation of 45° about Z.
/// let p = Program::default()
///     .line(Dialect::Twincat, b"N65 ROT Z30").unwrap()
///     .line(Dialect::Twincat, b"N90 AROT Z15").unwrap();
/// assert_eq!(p.angles, [0.0, 0.0, 45.0]);
/// // A line that cannot be executed is refused with the column of its first bad character.
/// let e = p.line(Dialect::Twincat, b"ROT Z=R1").unwrap_err();
/// assert_eq!((e.error, e.column), (cncrot::Error::NotANumber, 7));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Program {
    /// The active frame (identity: nothing active).
    pub frame: Frame,
    /// TwinCAT's programmed angles `X Y Z` (its `AROT` adds angles, not matrices).
    pub angles: [f64; 3],
    /// The dialect of the lines read so far: a program speaks one.
    pub dialect: Option<Dialect>,
    /// SINUMERIK's frame angles in Euler mode (machine data 10600 = 2) instead of RPY: a
    /// setting of the machine that no block changes.
    pub euler: bool,
}

impl Program {
    /// Applies one block in `dialect`; returns the next state. Refused (with the column):
    /// another dialect than the program's ([`Error::BadArgument`]), a line longer than
    /// [`Dialect::max_line`] ([`Error::LineTooLong`]), an unknown, repeated or misplaced word
    /// ([`Error::UnknownWord`]), a variable or expression where a number must stand
    /// ([`Error::NotANumber`]), a missing word ([`Error::MissingWord`]), a malformed number
    /// ([`Error::Parse`]), and whatever the command's mathematics refuses.
    pub fn line(&self, dialect: Dialect, text: &[u8]) -> Result<Program, LineError> {
        if self.dialect.is_some_and(|d| d != dialect) {
            return Err(LineError {
                error: Error::BadArgument,
                column: 1,
            });
        }
        // The line end is not part of the block.
        let text = match text {
            [rest @ .., b'\r', b'\n'] | [rest @ .., b'\n'] | [rest @ .., b'\r'] => rest,
            _ => text,
        };
        if text.len() > dialect.max_line() {
            return Err(LineError {
                error: Error::LineTooLong,
                column: dialect.max_line() + 1,
            });
        }
        let mut next = match dialect {
            Dialect::Sinumerik => sinumerik::read_line(self, text)?,
            Dialect::Heidenhain => heidenhain::read_line(self, text)?,
            Dialect::Fanuc => fanuc::read_line(self, text)?,
            Dialect::Syntec => syntec::read_line(self, text)?,
            Dialect::Twincat => twincat::read_line(self, text)?,
            Dialect::Haas => haas::read_line(self, text)?,
        };
        let h = next.frame.to_homogeneous();
        if !h.iter().flatten().all(|x| x.is_finite()) {
            return Err(LineError {
                error: Error::OutOfRange,
                column: 1,
            });
        }
        next.dialect = Some(dialect);
        Ok(next)
    }

    /// Whether this state is one that reading lines can leave: finite, its frame a rotation,
    /// TwinCAT's rotation the one of its angles and no angles in the other dialects (a state
    /// restored from elsewhere is checked before use).
    ///
    /// ```
    /// use cncrot::dialects::program::{Dialect, Program};
    /// let p = Program::default().line(Dialect::Twincat, b"ROT Z30").unwrap();
    /// assert!(p.check().is_ok());
    /// assert!(Program { angles: [0.0, 0.0, 31.0], ..p }.check().is_err());
    /// ```
    pub fn check(&self) -> Result<(), Error> {
        let numbers = self.frame.translation.iter().chain(&self.angles);
        if !numbers.into_iter().all(|x| x.is_finite()) {
            return Err(Error::NotFinite);
        }
        crate::check_rotation(&self.frame.rotation)?;
        let consistent = if self.dialect == Some(Dialect::Twincat) {
            twincat::matrix(self.angles) == self.frame.rotation
        } else {
            self.angles == [0.0; 3]
        };
        if consistent {
            Ok(())
        } else {
            Err(Error::BadArgument)
        }
    }

    /// This state with `frame` active (TwinCAT's angles cleared: they belong to `ROT`).
    pub(crate) fn with_frame(&self, frame: Frame) -> Program {
        Program {
            frame,
            angles: [0.0; 3],
            ..*self
        }
    }
}

/// Writes the block that programs `frame` in `dialect` with the command `form` into `out`
/// and returns its length and whether the decomposition was singular (the free angle then
/// sits where the dialect's rule puts it). `decimals < 0` writes the shortest numbers that
/// read back exactly; otherwise every number is rounded to that many decimals (at most
/// 17).
///
/// The forms, as written (upper or lower case, single spaces):
///
/// | dialect | forms |
/// |---|---|
/// | SINUMERIK | `CYCLE800` (`_MODE` 57), `CYCLE800 <_MODE>`, `ROT` (RPY), `ROT EULER` |
/// | Heidenhain | `PLANE SPATIAL`, `PLANE EULER`, `PLANE VECTOR`, `PLANE POINTS`, `PLANE PROJECTED` |
/// | Fanuc | `G68.2` |
/// | Syntec | `G158` (`P10157`), `G158 P<p>`, `G68.2` |
/// | TwinCAT | `ROT` |
/// | Haas | `G268` (`Q123`), `G268 Q<q>` |
///
/// Refused: an unknown form ([`Error::BadArgument`]), a frame with an origin for a form
/// without origin words ([`Error::BadArgument`]), a frame the form cannot express
/// ([`Error::OutOfRange`]), numbers outside what can be written, or a line longer than the
/// dialect reads ([`Error::OutOfRange`], whatever the buffer), a buffer shorter than the
/// line that [`Dialect::max_line`] would hold ([`Error::NoRoom`]).
///
/// ```
/// use cncrot::dialects::program::{write_line, Dialect};
/// use cncrot::{Frame, elementary, Axis};
/// let f = Frame::from_rotation(elementary(Axis::X, 30.0));
/// let mut buf = [0u8; 128];
/// let (n, _) = write_line(Dialect::Heidenhain, b"PLANE SPATIAL", &f, 6, &mut buf).unwrap();
/// assert_eq!(&buf[..n], b"PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY");
/// // The shortest exact numbers show the decomposition's last bit.
/// let (n, _) = write_line(Dialect::Heidenhain, b"PLANE SPATIAL", &f, -1, &mut buf).unwrap();
/// assert_eq!(&buf[..n], b"PLANE SPATIAL SPA+30.000000000000004 SPB+0 SPC+0 STAY");
/// ```
pub fn write_line(
    dialect: Dialect,
    form_text: &[u8],
    frame: &Frame,
    decimals: i32,
    buf: &mut [u8],
) -> Result<(usize, bool), Error> {
    let spec = parse_form(dialect, form_text)?;
    let n = spec.form.count();
    let mut words = [0.0; MAX_VALUES];
    let singular = form::form_values(
        spec.form,
        spec.selector,
        frame,
        words.get_mut(..n).ok_or(Error::BadArgument)?,
    )?;
    // A buffer that holds the dialect's longest line and still overflowed holds a line the
    // dialect cannot read: no buffer would help.
    let room = buf.len();
    let mut out = Out::new(buf);
    match dialect {
        Dialect::Sinumerik => sinumerik::write_line(&spec, &words, decimals, &mut out)?,
        Dialect::Heidenhain => heidenhain::write_line(&spec, &words, decimals, &mut out)?,
        Dialect::Fanuc | Dialect::Syntec | Dialect::Haas => {
            fanuc::write_line(&spec, &words, decimals, &mut out)?
        }
        Dialect::Twincat => twincat::write_line(&words, decimals, &mut out)?,
    }
    let len = match out.finish() {
        Some(len) => len,
        None if room >= dialect.max_line() => return Err(Error::OutOfRange),
        None => return Err(Error::NoRoom),
    };
    if len > dialect.max_line() {
        return Err(Error::OutOfRange);
    }
    Ok((len, singular))
}

/// A form as named for [`write_line`].
pub(crate) struct FormSpec {
    pub form: Form,
    pub selector: i32,
}

fn parse_form(dialect: Dialect, text: &[u8]) -> Result<FormSpec, Error> {
    let mut c = Cursor::new(text);
    c.spaces();
    let spec = |form, selector| FormSpec { form, selector };
    let found = match dialect {
        Dialect::Sinumerik => {
            if c.keyword(b"CYCLE800") {
                c.spaces();
                let mode = if c.at_end() { 57 } else { c.integer() };
                spec(Form::Cycle800, mode)
            } else if c.keyword(b"ROT") {
                c.spaces();
                spec(Form::SinumerikRot, i32::from(c.keyword(b"EULER")))
            } else {
                return Err(Error::BadArgument);
            }
        }
        Dialect::Heidenhain => {
            if !c.keyword(b"PLANE") {
                return Err(Error::BadArgument);
            }
            c.spaces();
            let forms = [
                (&b"SPATIAL"[..], Form::PlaneSpatial),
                (b"EULER", Form::PlaneEuler),
                (b"VECTOR", Form::PlaneVector),
                (b"POINTS", Form::PlanePoints),
                (b"PROJECTED", Form::PlaneProjected),
            ];
            match forms.iter().find(|(name, _)| c.keyword(name)) {
                Some(&(_, form)) => spec(form, 0),
                None => return Err(Error::BadArgument),
            }
        }
        _ if c.keyword(b"G68.2") && dialect != Dialect::Haas => spec(Form::G68_2, 0),
        Dialect::Syntec if c.keyword(b"G158") => {
            c.spaces();
            let p = if c.at_end() {
                10157
            } else if c.letter(b'P') {
                c.integer()
            } else {
                -1
            };
            spec(Form::G158, p)
        }
        Dialect::Twincat if c.keyword(b"ROT") => spec(Form::TwincatRot, 0),
        Dialect::Haas if c.keyword(b"G268") => {
            c.spaces();
            let q = if c.at_end() {
                123
            } else if c.letter(b'Q') {
                c.integer()
            } else {
                -1
            };
            spec(Form::G268, q)
        }
        _ => return Err(Error::BadArgument),
    };
    c.spaces();
    if !c.at_end() || found.selector < 0 {
        return Err(Error::BadArgument);
    }
    Ok(found)
}

/// The form's frame for a line, refusal mapped to the command's column.
pub(crate) fn frame_at(
    column: usize,
    form: Form,
    selector: i32,
    words: &[f64],
) -> Result<Frame, LineError> {
    form::form_frame(form, selector, words).map_err(|error| LineError { error, column })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A line longer than the dialect reads is `OutOfRange` whatever the buffer; `NoRoom`
    /// only when a buffer that cannot hold the dialect's longest line is the reason.
    #[test]
    fn no_room_only_for_the_buffer() {
        let a = 1e-97;
        let m = crate::matrix_from_angles(
            crate::Kind::Intrinsic,
            crate::AxisCode::new(57).unwrap(),
            [a, a, a],
        );
        let f = Frame::with_translations([1e99; 3], m, [0.0; 3]);
        // Nine numbers of about 100 digits: more than any buffer of 512 bytes holds.
        for room in [256, 512, 4096] {
            let mut buf = vec![0x5Au8; room];
            assert_eq!(
                write_line(Dialect::Syntec, b"G158", &f, -1, &mut buf),
                Err(Error::OutOfRange),
                "{room}"
            );
        }
        let mut small = [0u8; 40];
        let g = Frame::from_rotation(m);
        assert_eq!(
            write_line(Dialect::Syntec, b"G158", &g, 4, &mut small),
            Err(Error::NoRoom)
        );
        let mut enough = [0u8; 256];
        assert!(write_line(Dialect::Syntec, b"G158", &g, 4, &mut enough).is_ok());
    }

    #[test]
    fn a_program_speaks_one_dialect() {
        let p = Program::default()
            .line(Dialect::Fanuc, b"G68.2 J30")
            .unwrap();
        assert_eq!(
            p.line(Dialect::Haas, b"G269").unwrap_err().error,
            Error::BadArgument
        );
        let long = [b' '; 257];
        assert_eq!(
            p.line(Dialect::Fanuc, &long).unwrap_err(),
            LineError {
                error: Error::LineTooLong,
                column: 257
            }
        );
    }
}
