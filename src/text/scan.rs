//! Scanning a line of program text: the cursor every reader walks with (program lines,
//! `$TC_CARR` assignments, `HEAD_DEF` tokens), what a number looks like in each dialect
//! ([`Syntax`]), address words, and errors with their column.

use super::number;
use crate::Error;

/// A refused line: why, and the 1-based column (byte) of the first offending character
/// (one past the end when something is missing at the end).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineError {
    /// Why the line was refused.
    pub error: Error,
    /// 1-based byte column.
    pub column: usize,
    /// What the reader expected at `column`, in the dialect's own words: for
    /// [`Error::MissingWord`] the word that is missing (`SPC`, `Q`, `ROT`, `a number`,
    /// `'+' or '-'`); for a value a cycle refuses, the values its parameter takes
    /// (`_MIHEAD: empty, or …`); `None` where the reader names none. A message can then
    /// say which word is missing or what may stand there, not only that something is wrong.
    pub expected: Option<&'static str>,
}

impl LineError {
    /// A value the command does not take ([`Error::BadArgument`]) at `column`, with what
    /// may stand there.
    pub(crate) fn bad_value(column: usize, expected: &'static str) -> LineError {
        LineError {
            error: Error::BadArgument,
            column,
            expected: Some(expected),
        }
    }

    /// `result`, its error reported at `column`.
    pub fn at<T>(column: usize, result: Result<T, Error>) -> Result<T, LineError> {
        result.map_err(|error| LineError {
            error,
            column,
            expected: None,
        })
    }
}

/// How an exponent is written in a dialect's numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exponent {
    /// None (the address-word dialects: `E` is a word of its own there).
    None,
    /// SINUMERIK's `EX`: `1.5EX3`.
    Ex,
    /// C's `e`/`E`: `1.5e3` (tool and head tables written by programs).
    E,
}

/// What a number is in one dialect: the one rule its reader hands to [`Cursor::number`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Syntax {
    /// How the exponent is written, if at all.
    pub exponent: Exponent,
    /// Characters that end a number besides spaces and the end (`,` `)` in calls, `;` `(`).
    pub ends: &'static [u8],
    /// A `,` may stand for the decimal point (`A-8,182`, `X+25,`): Heidenhain programs
    /// written by posts for a decimal comma.
    pub comma: bool,
    /// ISO words (Fanuc and its kin): blanks between an address and its value (`X 10.`)
    /// and a constant in brackets (`X[0.]`, `X [ -5. ]`: macro B's expression of one
    /// number) are its number.
    pub iso: bool,
}

/// Numbers of the address-word dialects (Fanuc, Syntec, Haas, TwinCAT): no exponent, ended
/// by a comment.
pub const G_WORDS: Syntax = Syntax {
    exponent: Exponent::None,
    ends: b"(;",
    comma: false,
    iso: false,
};

/// Numbers of the ISO dialects whose words may stand without spaces (Fanuc, Syntec, Haas:
/// `X0.Y0.J45.`): no exponent, ended by a comment or the next word's letter.
pub const ISO_WORDS: Syntax = Syntax {
    exponent: Exponent::None,
    ends: b"(;ABCDEFGHIJKLMNOPQRSTUVWXYZ",
    comma: false,
    iso: true,
};

/// A position in a line, with the scanning the dialects share. Columns are 1-based bytes.
#[derive(Clone)]
pub struct Cursor<'a> {
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

    /// A missing word at the current position: `what` (the word, or what kind of text)
    /// was expected there.
    pub fn missing(&self, what: &'static str) -> LineError {
        LineError {
            error: Error::MissingWord,
            column: self.column(),
            expected: Some(what),
        }
    }

    /// An error at the current position.
    pub fn error(&self, error: Error) -> LineError {
        LineError {
            error,
            column: self.column(),
            expected: None,
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
        self.pos += self
            .rest()
            .iter()
            .take_while(|&&b| b == b' ' || b == b'\t')
            .count();
    }

    /// The text from here on.
    fn rest(&self) -> &'a [u8] {
        self.text.get(self.pos..).unwrap_or(&[])
    }

    /// Consumes `kw` (case-insensitive) when it stands here and the character after it (if
    /// any) is not one that would continue it.
    fn take(&mut self, kw: &[u8], continues: impl Fn(u8) -> bool) -> bool {
        let n = kw.len();
        let matches = self
            .text
            .get(self.pos..self.pos + n)
            .is_some_and(|h| h.eq_ignore_ascii_case(kw));
        let whole = !self.text.get(self.pos + n).is_some_and(|&b| continues(b));
        if matches && whole {
            self.pos += n;
        }
        matches && whole
    }

    /// Consumes `kw` (case-insensitive) when it stands here as a whole name: "ROT" does not
    /// match "ROTS", "G68.2" not "G68.25".
    pub fn keyword(&mut self, kw: &[u8]) -> bool {
        self.take(kw, |b| is_name(b) || b == b'.')
    }

    /// Consumes the code `kw` (case-insensitive; a G-code such as `G68.2`) when no digit or
    /// point follows it. ISO programs may write their words without spaces (`G68.2X0.J45.`):
    /// a letter after a code starts the next word; and blanks between the letter and the
    /// number carry no meaning there (`G 68.2` is `G68.2`) [doc: Fanuc, "spaces are
    /// ignored"]; within the number they end it, as the block's words read (`G6 8.2` is no
    /// `G68.2`: a block's rest joins its pieces with a blank) [choice].
    pub fn code(&mut self, kw: &[u8]) -> bool {
        let blank = |k: usize| matches!(self.text.get(k), Some(b' ' | b'\t'));
        let mut k = self.pos;
        for (i, c) in kw.iter().enumerate() {
            while i == 1 && blank(k) {
                k += 1;
            }
            if !self.text.get(k).is_some_and(|b| b.eq_ignore_ascii_case(c)) {
                return false;
            }
            k += 1;
        }
        if self
            .text
            .get(k)
            .is_some_and(|&b| b.is_ascii_digit() || b == b'.')
        {
            return false;
        }
        self.pos = k;
        true
    }

    /// Consumes the address letter `l` (case-insensitive) when the next character is not a
    /// letter (so `X` in `X30` and `X=30`, not in `XA`).
    pub fn letter(&mut self, l: u8) -> bool {
        self.peek() == Some(l) && self.letter_here()
    }

    /// Consumes the letter here when the next character is not a letter (`X` in `X30`, not
    /// in `XA`).
    fn letter_here(&mut self) -> bool {
        let next_is_letter = self
            .text
            .get(self.pos + 1)
            .is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_');
        if next_is_letter {
            false
        } else {
            self.bump();
            true
        }
    }

    /// Consumes the word name `w` (case-insensitive) when no letter follows it (`SPA` in
    /// `SPA+27` and `SPA27`, not in `SPAN`).
    pub fn word(&mut self, w: &[u8]) -> bool {
        self.take(w, |b| b.is_ascii_alphabetic() || b == b'_')
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
    /// `1.5EX3`, C's `1.5e3`, Heidenhain's `-8,182`, ISO's `[0.]`). A variable or expression
    /// here is [`Error::NotANumber`] at its column (a bracket's at the bracket), a malformed
    /// number [`Error::Parse`].
    pub fn number(&mut self, syntax: Syntax) -> Result<f64, LineError> {
        if !(syntax.iso && self.peek() == Some(b'[')) {
            return self.plain_number(syntax);
        }
        // `[ 0. ]`: the number inside, or the expression it is.
        let start = self.pos;
        self.bump();
        self.spaces();
        let inner = Syntax {
            ends: b"]",
            ..syntax
        };
        let v = self.plain_number(inner);
        self.spaces();
        let (Ok(v), Some(b']')) = (v, self.peek()) else {
            self.pos = start;
            return Err(self.error(Error::NotANumber));
        };
        self.bump();
        self.number_ends(syntax)?;
        Ok(v)
    }

    /// What follows a number must end it: an operator or a letter makes an expression.
    fn number_ends(&self, syntax: Syntax) -> Result<(), LineError> {
        match self.peek() {
            None | Some(b' ' | b'\t') => Ok(()),
            Some(b) if syntax.ends.contains(&b) => Ok(()),
            Some(b'+' | b'-' | b'*' | b'/' | b'^' | b'[' | b'(' | b'#' | b'$') => {
                Err(self.error(Error::NotANumber))
            }
            Some(_) => Err(self.error(Error::Parse)),
        }
    }

    /// [`Cursor::number`] without brackets.
    fn plain_number(&mut self, syntax: Syntax) -> Result<f64, LineError> {
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
        // A second point ends the digits, so that it is reported where it stands.
        let rest = self.rest();
        let scanned = number::scan_digits(rest, syntax.comma);
        let digits = rest.get(..scanned.len).unwrap_or(&[]);
        self.pos += scanned.len;
        if digits.is_empty() {
            // `R1`, `Q120`, `#100`, `$P_…`, `_name`, `(`, `[`: not a number the block can
            // be executed with here.
            return Err(match self.peek() {
                Some(b) if b.is_ascii_alphabetic() || b"#$_[(".contains(&b) => {
                    self.error(Error::NotANumber)
                }
                _ => self.missing("a number"),
            });
        }
        let mut exp = 0i32;
        let marker = match syntax.exponent {
            Exponent::Ex if self.peek() == Some(b'E') && self.peek_at(1) == Some(b'X') => 2,
            Exponent::E if self.peek() == Some(b'E') => 1,
            _ => 0,
        };
        if marker > 0 {
            for _ in 0..marker {
                self.bump();
            }
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
                    expected: None,
                });
            }
            exp = exp.saturating_mul(sign);
        }
        self.number_ends(syntax)?;
        number::parse_scanned(negative, digits, &scanned, exp).map_err(|error| LineError {
            error,
            column: start + 1,
            expected: None,
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
pub struct Words<const N: usize> {
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
pub fn address_words<const N: usize>(
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
        if comments.1
            && c.peek() == Some(b'(')
            && c.text.get(c.pos..).is_some_and(|t| !t.contains(&b')'))
        {
            return Err(c.error(Error::Parse));
        }
        // Only the end, `;` or `(` can start the rest of the line as a comment.
        let may_end = matches!(c.peek(), None | Some(b';' | b'('));
        if may_end && c.rest_is_comment(comments.0, comments.1) {
            c.end(comments.0, comments.1)?;
            return Ok(w);
        }
        let column = c.column();
        // The letter here, looked up once (not one `letter` test per address: a line's
        // words were a third of its reading time).
        let hit = c
            .peek()
            .and_then(|b| letters.iter().position(|&l| l == b))
            .filter(|_| c.letter_here());
        let Some(k) = hit else {
            return Err(c.error(Error::UnknownWord));
        };
        if w.given.get(k).copied().unwrap_or(true) {
            return Err(LineError {
                error: Error::UnknownWord,
                column,
                expected: None,
            });
        }
        if equals && c.peek() == Some(b'=') {
            c.bump();
        }
        if syntax.iso {
            // Blanks inside a word, where a value follows them (`X 10.`); before another
            // word the value is missing where the blanks start.
            let here = c.pos;
            c.spaces();
            if !matches!(c.peek(), Some(b'0'..=b'9' | b'+' | b'-' | b'.' | b'[')) {
                c.pos = here;
            }
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

/// Which comments a dialect has: `;` to the end of the line, `( … )`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Comments {
    /// `;` starts a comment to the end of the line.
    pub semicolon: bool,
    /// `(` starts a comment to the next `)`.
    pub parens: bool,
}

/// A number as written as a G- or M-code in tenths (`54.1` → 541, `69` → 690, `068.2` →
/// 682), if it is a plain number with at most one decimal.
pub fn code_of(value: &[u8]) -> Option<u32> {
    // Blanks between an ISO word's letter and its number (`G 68.2`): left out.
    let (mut int, mut frac, mut point, mut v) = (0usize, 0usize, false, 0u32);
    for &b in value {
        match b {
            b' ' | b'\t' => continue,
            b'.' if !point => point = true,
            b'0'..=b'9' if point => frac += 1,
            b'0'..=b'9' => int += 1,
            _ => return None,
        }
        if b != b'.' {
            v = v.checked_mul(10)?.checked_add(u32::from(b - b'0'))?;
        }
    }
    if int == 0 || int > 6 || frac > 1 {
        return None;
    }
    Some(if frac == 0 { v * 10 } else { v })
}

/// Where the text after the `( … )` or `" … "` that opens at `pos` goes on: one past its
/// closing character, or one past the end when it is not closed.
pub fn past_closing(text: &[u8], pos: usize) -> usize {
    let close = if text.get(pos) == Some(&b'(') {
        b')'
    } else {
        b'"'
    };
    let rest = text.get(pos + 1..).unwrap_or(&[]);
    pos + 2 + rest.iter().position(|&c| c == close).unwrap_or(rest.len())
}

/// One token of a block, for telling what a block does without reading it: an address
/// word (`G54.1`, `X-10.`, `#5221`: `letter` upper-cased, `#` for a variable, `value` the
/// number as written) or a name (`MIRROR`, `$P_UIFR`, `CYCL`, `7.0`: `letter` 0, `value`
/// the whole name).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token<'a> {
    /// The address letter (upper case), `#`, or 0 for a name.
    pub letter: u8,
    /// The number after the letter, or the name.
    pub value: &'a [u8],
    /// 1-based column of the token.
    pub column: usize,
    /// Whether `=` follows (after an index in brackets): an assignment.
    pub assigned: bool,
}

impl Token<'_> {
    /// The value of an address word as a G- or M-code in tenths (`54.1` → 541, `69` → 690,
    /// `068.2` → 682), if it is a plain number with at most one decimal.
    pub fn code(&self) -> Option<u32> {
        code_of(self.value)
    }

    /// A name `G<code>` (`G505`, `g54.1`) as its code in tenths, as [`Token::code`]: the
    /// G-codes of the dialects read as names (SINUMERIK, TwinCAT).
    pub fn g_code(&self) -> Option<u32> {
        let (first, rest) = self.value.split_first()?;
        if !first.eq_ignore_ascii_case(&b'G') {
            return None;
        }
        Token {
            value: rest,
            ..*self
        }
        .code()
    }

    /// Whether this is the name `name` (case-insensitive).
    pub fn is(&self, name: &[u8]) -> bool {
        self.letter == 0 && self.value.eq_ignore_ascii_case(name)
    }
}

/// The tokens of a block, comments and strings skipped. `words`: address words, split
/// where no space separates them (`G0G90G54X0` is four words: ISO dialects); otherwise
/// names, runs of letters, digits, `_`, `$`, `#` and `.` (SINUMERIK, Heidenhain).
pub struct Tokens<'a> {
    text: &'a [u8],
    pos: usize,
    comments: Comments,
    words: bool,
}

impl<'a> Tokens<'a> {
    /// The tokens of `text`.
    pub fn new(text: &'a [u8], comments: Comments, words: bool) -> Tokens<'a> {
        Tokens {
            text,
            pos: 0,
            comments,
            words,
        }
    }

    fn at(&self, k: usize) -> u8 {
        self.text.get(k).copied().unwrap_or(0)
    }

    /// Whether `=` (not `==`) follows from `k` on, after spaces and one `[…]` index.
    fn assigned_from(&self, mut k: usize) -> bool {
        while self.at(k) == b' ' || self.at(k) == b'\t' {
            k += 1;
        }
        if self.at(k) == b'[' {
            while k < self.text.len() && self.at(k) != b']' {
                k += 1;
            }
            k += 1;
            while self.at(k) == b' ' || self.at(k) == b'\t' {
                k += 1;
            }
        }
        self.at(k) == b'=' && self.at(k + 1) != b'='
    }
}

impl<'a> Iterator for Tokens<'a> {
    type Item = Token<'a>;

    fn next(&mut self) -> Option<Token<'a>> {
        let name = |b: u8| b.is_ascii_alphanumeric() || b"_$#.".contains(&b);
        while self.pos < self.text.len() {
            let b = self.at(self.pos);
            let start = self.pos;
            if self.comments.semicolon && b == b';' {
                self.pos = self.text.len();
                return None;
            }
            if (self.comments.parens && b == b'(') || b == b'"' {
                self.pos = past_closing(self.text, self.pos);
                continue;
            }
            if self.words && (b.is_ascii_alphabetic() || b == b'#') {
                self.pos += 1;
                let mut k = self.pos;
                // Blanks between an ISO word's letter and its number carry no meaning (`G
                // 68.2`): the value holds them (`code_of` leaves them out). Not within the
                // number: a block's rest joins its pieces with a blank, and a `G6` before a
                // word taken out and a `9` after it would become `G69`.
                let blanks = |t: &Self, mut j: usize| {
                    while t.at(j) == b' ' || t.at(j) == b'\t' {
                        j += 1;
                    }
                    j
                };
                let digit = |c: u8| c.is_ascii_digit() || c == b'.';
                if b != b'#' && digit(self.at(blanks(self, k))) {
                    k = blanks(self, k);
                }
                if matches!(self.at(k), b'+' | b'-') {
                    k += 1;
                }
                while digit(self.at(k)) {
                    k += 1;
                }
                self.pos = k;
                return Some(Token {
                    letter: b.to_ascii_uppercase(),
                    value: self.text.get(start + 1..k).unwrap_or(&[]),
                    column: start + 1,
                    assigned: self.assigned_from(k),
                });
            }
            if !self.words && name(b) {
                while self.pos < self.text.len() && name(self.at(self.pos)) {
                    self.pos += 1;
                }
                return Some(Token {
                    letter: 0,
                    value: self.text.get(start..self.pos).unwrap_or(&[]),
                    column: start + 1,
                    assigned: self.assigned_from(self.pos),
                });
            }
            self.pos += 1;
        }
        None
    }
}

/// An integer-valued word (`_MODE`, `P`, `Q`, `_ST`): the value must be a whole number of at
/// most nine digits, else [`Error::BadArgument`] at `column`.
pub fn whole(v: f64, column: usize) -> Result<i32, LineError> {
    if crate::math::abs(v) < 1e9 && f64::from(v as i32) == v {
        Ok(v as i32)
    } else {
        Err(LineError {
            error: Error::BadArgument,
            column,
            expected: None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_in_lines() {
        let s = Syntax {
            exponent: Exponent::Ex,
            ends: b",);",
            comma: false,
            iso: false,
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
                column: 3,
                expected: None,
            }
        );
        assert_eq!(read(b"3.0.1").unwrap_err().error, Error::Parse);
        assert_eq!(read(b"30x").unwrap_err().error, Error::Parse);
        assert_eq!(read(b"").unwrap_err().error, Error::MissingWord);
        // `E` alone is SINUMERIK's end of a number, not an exponent; C's rule reads it.
        assert_eq!(read(b"1.5E3").unwrap_err().error, Error::Parse);
        let c = Syntax {
            exponent: Exponent::E,
            ends: b"",
            comma: false,
            iso: false,
        };
        let read_c = |t: &[u8]| Cursor::new(t).number(c);
        assert_eq!(read_c(b"1.5e3"), Ok(1500.0));
        assert_eq!(read_c(b"1.5E-3"), Ok(0.0015));
        assert_eq!(read_c(b"1e").unwrap_err().error, Error::Parse);
        let none = |t: &[u8]| Cursor::new(t).number(G_WORDS);
        assert_eq!(none(b"1.5E3").unwrap_err().error, Error::Parse);
        assert_eq!(none(b"1.5(c)"), Ok(1.5));
        // A decimal comma where the dialect has one; a second mark ends the digits.
        let comma = Syntax {
            exponent: Exponent::None,
            ends: b";",
            comma: true,
            iso: false,
        };
        let read_comma = |t: &[u8]| Cursor::new(t).number(comma);
        assert_eq!(read_comma(b"-8,182"), Ok(-8.182));
        assert_eq!(read_comma(b"+25, "), Ok(25.0));
        assert_eq!(read_comma(b"0,"), Ok(0.0));
        assert_eq!(read_comma(b",5"), Ok(0.5));
        assert_eq!(read_comma(b"1,5.2").unwrap_err().error, Error::Parse);
        assert_eq!(read_comma(b"1.5,2").unwrap_err().error, Error::Parse);
        // 25 significant digits: the general reader, which takes the comma alike.
        assert_eq!(
            read_comma(b"0,1000000000000000000000001"),
            read(b"0.1000000000000000000000001")
        );
        // Without it, a comma ends the number where the call syntax lists its arguments.
        assert_eq!(read(b"-20,5"), Ok(-20.0));
    }
}
