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
use crate::decimal::{self, Out, Style};
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

/// A refused line: why, and the 1-based column (byte) of the first offending character
/// (one past the end when something is missing at the end).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineError {
    /// Why the line was refused.
    pub error: Error,
    /// 1-based byte column.
    pub column: usize,
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

/// Writes `<name><number>` (the name carries its leading space and any `=`).
pub(crate) fn write_word(
    out: &mut Out,
    name: &[u8],
    value: f64,
    decimals: i32,
    style: Style,
) -> Result<(), Error> {
    out.text(name);
    decimal::write(out, value, decimals, style)
}

/// Writes an integer (selectors: `_MODE`, `P`, `Q`).
pub(crate) fn write_integer(out: &mut Out, v: i32) {
    let mut digits = [0u8; 11];
    let mut n = 0;
    let mut x = v.unsigned_abs();
    loop {
        if let Some(d) = digits.get_mut(n) {
            *d = b'0' + (x % 10) as u8;
        }
        n += 1;
        x /= 10;
        if x == 0 || n >= digits.len() {
            break;
        }
    }
    if v < 0 {
        out.byte(b'-');
    }
    for i in (0..n).rev() {
        out.byte(digits.get(i).copied().unwrap_or(b'0'));
    }
}

/// How numbers are spelt in a dialect's lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Syntax {
    /// SINUMERIK's exponent `EX`: `1.5EX3`.
    pub ex: bool,
    /// Characters that end a number besides spaces and the end (`,` `)` in calls, `;` `(`).
    pub ends: &'static [u8],
}

/// Numbers of the address-word dialects (Fanuc, Syntec, Haas, TwinCAT): no exponent, ended
/// by a comment.
pub(crate) const G_WORDS: Syntax = Syntax {
    ex: false,
    ends: b"(;",
};

/// A position in a line, with the scanning the dialects share. Columns are 1-based bytes.
pub(crate) struct Cursor<'a> {
    text: &'a [u8],
    pos: usize,
}

/// Characters of a name (address letters and keywords).
fn is_name(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

impl<'a> Cursor<'a> {
    pub fn new(text: &'a [u8]) -> Cursor<'a> {
        Cursor { text, pos: 0 }
    }

    /// The 1-based column of the current position.
    pub fn column(&self) -> usize {
        self.pos + 1
    }

    /// An error at the current position.
    pub fn error(&self, error: Error) -> LineError {
        LineError {
            error,
            column: self.column(),
        }
    }

    pub fn peek(&self) -> Option<u8> {
        self.text.get(self.pos).map(u8::to_ascii_uppercase)
    }

    pub fn peek_at(&self, k: usize) -> Option<u8> {
        self.text.get(self.pos + k).map(u8::to_ascii_uppercase)
    }

    pub fn bump(&mut self) {
        self.pos = (self.pos + 1).min(self.text.len());
    }

    pub fn at_end(&self) -> bool {
        self.pos >= self.text.len()
    }

    pub fn spaces(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t')) {
            self.bump();
        }
    }

    /// Consumes `kw` (case-insensitive) when it stands here as a whole name.
    pub fn keyword(&mut self, kw: &[u8]) -> bool {
        let n = kw.len();
        let here = self.text.get(self.pos..self.pos + n);
        let matches = here.is_some_and(|h| h.eq_ignore_ascii_case(kw));
        // "ROT" must not match "ROTS"; "G68.2" must not match "G68.25".
        let whole = !self
            .text
            .get(self.pos + n)
            .is_some_and(|&b| is_name(b) || b == b'.');
        if matches && whole {
            self.pos += n;
        }
        matches && whole
    }

    /// Consumes the address letter `l` (case-insensitive) when the next character is not a
    /// letter (so `X` in `X30` and `X=30`, not in `XA`).
    pub fn letter(&mut self, l: u8) -> bool {
        let next_is_letter = self
            .text
            .get(self.pos + 1)
            .is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_');
        if self.peek() == Some(l) && !next_is_letter {
            self.bump();
            true
        } else {
            false
        }
    }

    /// Consumes the word name `w` (case-insensitive) when no letter follows it (`SPA` in
    /// `SPA+27` and `SPA27`, not in `SPAN`).
    pub fn word(&mut self, w: &[u8]) -> bool {
        let n = w.len();
        let matches = self
            .text
            .get(self.pos..self.pos + n)
            .is_some_and(|h| h.eq_ignore_ascii_case(w));
        let letter = self
            .text
            .get(self.pos + n)
            .is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_');
        if matches && !letter {
            self.pos += n;
        }
        matches && !letter
    }

    /// The text up to the next `close` (consumed), or `None` when there is none.
    pub fn until(&mut self, close: u8) -> Option<&'a [u8]> {
        let rest = self.text.get(self.pos..)?;
        let k = rest.iter().position(|&b| b == close)?;
        self.pos += k + 1;
        rest.get(..k)
    }

    /// A label (`NAME:`) here: consumed with the spaces after it.
    pub fn label(&mut self) {
        let start = self.pos;
        let name = self.name();
        if !name.is_empty() && self.peek() == Some(b':') {
            self.bump();
            self.spaces();
        } else {
            self.pos = start;
        }
    }

    /// A name (letters, digits, `_`) starting here.
    pub fn name(&mut self) -> &'a [u8] {
        let start = self.pos;
        while self.peek().is_some_and(is_name) {
            self.bump();
        }
        self.text.get(start..self.pos).unwrap_or(&[])
    }

    /// An unsigned integer (selectors in form names); -1 if none.
    pub fn integer(&mut self) -> i32 {
        let mut v: i32 = -1;
        while let Some(d @ b'0'..=b'9') = self.peek() {
            v = v
                .max(0)
                .saturating_mul(10)
                .saturating_add(i32::from(d - b'0'));
            self.bump();
        }
        v
    }

    /// A block number (`N10`, `n10`) or a skip mark (`/`) at the start: consumed.
    pub fn block_number(&mut self, letter: u8) {
        self.spaces();
        if self.peek() == Some(b'/') {
            self.bump();
            while self.peek().is_some_and(|b| b.is_ascii_digit()) {
                self.bump();
            }
            self.spaces();
        }
        if self.peek() == Some(letter) && self.peek_at(1).is_some_and(|b| b.is_ascii_digit()) {
            self.bump();
            while self.peek().is_some_and(|b| b.is_ascii_digit()) {
                self.bump();
            }
        }
        self.spaces();
    }

    /// A number in `syntax` starting here (`30`, `-20.5`, `+27`, `30.`, `.5`, SINUMERIK's
    /// `1.5EX3`). A variable or expression here is [`Error::NotANumber`] at its column, a
    /// malformed number [`Error::Parse`].
    pub fn number(&mut self, syntax: Syntax) -> Result<f64, LineError> {
        let start = self.pos;
        let negative = match self.peek() {
            Some(b'-') => {
                self.bump();
                true
            }
            Some(b'+') => {
                self.bump();
                false
            }
            _ => false,
        };
        let digits_start = self.pos;
        let mut point = false;
        // A second point ends the digits, so that it is reported where it stands.
        while let Some(b @ (b'0'..=b'9' | b'.')) = self.peek() {
            if b == b'.' && core::mem::replace(&mut point, true) {
                break;
            }
            self.bump();
        }
        let digits = self.text.get(digits_start..self.pos).unwrap_or(&[]);
        if digits.is_empty() {
            // `R1`, `Q120`, `#100`, `$P_…`, `_name`, `(`, `[`: not a number the block can
            // be executed with here.
            return Err(match self.peek() {
                Some(b) if b.is_ascii_alphabetic() || b"#$_[(".contains(&b) => {
                    self.error(Error::NotANumber)
                }
                _ => self.error(Error::MissingWord),
            });
        }
        let mut exp = 0i32;
        if syntax.ex && self.peek() == Some(b'E') && self.peek_at(1) == Some(b'X') {
            self.bump();
            self.bump();
            let exp_start = self.pos;
            let sign = match self.peek() {
                Some(b'-') => {
                    self.bump();
                    -1
                }
                Some(b'+') => {
                    self.bump();
                    1
                }
                _ => 1,
            };
            let mut any = false;
            while let Some(d @ b'0'..=b'9') = self.peek() {
                exp = exp.saturating_mul(10).saturating_add(i32::from(d - b'0'));
                any = true;
                self.bump();
            }
            if !any {
                return Err(LineError {
                    error: Error::Parse,
                    column: exp_start + 1,
                });
            }
            exp = exp.saturating_mul(sign);
        }
        // What follows must end the number: an operator or a letter makes an expression.
        match self.peek() {
            None | Some(b' ' | b'\t') => {}
            Some(b) if syntax.ends.contains(&b) => {}
            Some(b'+' | b'-' | b'*' | b'/' | b'^' | b'[' | b'(' | b'#' | b'$') => {
                return Err(self.error(Error::NotANumber))
            }
            Some(_) => return Err(self.error(Error::Parse)),
        }
        decimal::parse(negative, digits, exp).map_err(|error| LineError {
            error,
            column: start + 1,
        })
    }

    /// The rest of the line is a comment starting with one of `marks` (`;`, or `(` to the
    /// matching `)` followed by only spaces and more comments), or nothing.
    pub fn end(&mut self, semicolon: bool, parens: bool) -> Result<(), LineError> {
        loop {
            self.spaces();
            match self.peek() {
                None => return Ok(()),
                Some(b';') if semicolon => return Ok(()),
                Some(b'(') if parens => {
                    let close = self
                        .text
                        .get(self.pos..)
                        .and_then(|t| t.iter().position(|&b| b == b')'));
                    match close {
                        Some(k) => self.pos += k + 1,
                        None => return Err(self.error(Error::Parse)),
                    }
                }
                Some(_) => return Err(self.error(Error::UnknownWord)),
            }
        }
    }

    /// Whether only spaces and comments remain.
    pub fn rest_is_comment(&self, semicolon: bool, parens: bool) -> bool {
        let mut c = Cursor {
            text: self.text,
            pos: self.pos,
        };
        c.end(semicolon, parens).is_ok()
    }
}

/// What [`address_words`] read: the values in the order of the letters (0 for omitted
/// ones), which were given, and the 1-based column of each value (0 for omitted ones), so
/// that a value refused later is reported where it stands.
pub(crate) struct Words<const N: usize> {
    pub values: [f64; N],
    pub given: [bool; N],
    pub columns: [usize; N],
}

impl<const N: usize> Words<N> {
    /// The column of word `k`'s value.
    pub fn column(&self, k: usize) -> usize {
        self.columns.get(k).copied().unwrap_or(0)
    }
}

/// Address words such as `X30 I-20.5 K0.`: each letter of `letters` at most once, in any
/// order, until the end of the line or a comment.
pub(crate) fn address_words<const N: usize>(
    c: &mut Cursor,
    letters: [u8; N],
    syntax: Syntax,
    equals: bool,
    comments: (bool, bool),
) -> Result<Words<N>, LineError> {
    let mut w = Words {
        values: [0.0; N],
        given: [false; N],
        columns: [0; N],
    };
    loop {
        c.spaces();
        // An unclosed `(` comment is malformed text, not an unknown word.
        let unclosed = c.text.get(c.pos..).is_some_and(|t| !t.contains(&b')'));
        if comments.1 && c.peek() == Some(b'(') && unclosed {
            return Err(c.error(Error::Parse));
        }
        if c.rest_is_comment(comments.0, comments.1) {
            c.end(comments.0, comments.1)?;
            return Ok(w);
        }
        let column = c.column();
        let hit = letters.iter().position(|&l| c.letter(l));
        let Some(k) = hit else {
            return Err(c.error(Error::UnknownWord));
        };
        if w.given.get(k).copied().unwrap_or(true) {
            return Err(LineError {
                error: Error::UnknownWord,
                column,
            });
        }
        if equals && c.peek() == Some(b'=') {
            c.bump();
        }
        let at = c.column();
        let v = c.number(syntax)?;
        if let (Some(slot), Some(g), Some(col)) = (
            w.values.get_mut(k),
            w.given.get_mut(k),
            w.columns.get_mut(k),
        ) {
            *slot = v;
            *g = true;
            *col = at;
        }
    }
}

/// An integer-valued word (`_MODE`, `P`, `Q`, `_ST`): the value must be a whole number of at
/// most nine digits, else [`Error::BadArgument`] at `column`.
pub(crate) fn whole(v: f64, column: usize) -> Result<i32, LineError> {
    if crate::math::abs(v) < 1e9 && f64::from(v as i32) == v {
        Ok(v as i32)
    } else {
        Err(LineError {
            error: Error::BadArgument,
            column,
        })
    }
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

    #[test]
    fn numbers_in_lines() {
        let s = Syntax {
            ex: true,
            ends: b",);",
        };
        let read = |t: &[u8]| Cursor::new(t).number(s);
        assert_eq!(read(b"30"), Ok(30.0));
        assert_eq!(read(b"30.").unwrap(), 30.0);
        assert_eq!(read(b"-20.5,"), Ok(-20.5));
        assert_eq!(read(b"+27 "), Ok(27.0));
        assert_eq!(read(b"1.5EX3"), Ok(1500.0));
        assert_eq!(read(b"1.5ex-1"), Ok(0.15));
        assert_eq!(read(b"R1").unwrap_err().error, Error::NotANumber);
        assert_eq!(read(b"#100").unwrap_err().error, Error::NotANumber);
        assert_eq!(
            read(b"30+5").unwrap_err(),
            LineError {
                error: Error::NotANumber,
                column: 3
            }
        );
        assert_eq!(read(b"3.0.1").unwrap_err().error, Error::Parse);
        assert_eq!(read(b"30x").unwrap_err().error, Error::Parse);
        assert_eq!(read(b"").unwrap_err().error, Error::MissingWord);
    }

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
