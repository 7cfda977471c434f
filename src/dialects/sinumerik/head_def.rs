//! The HEAD_DEF cycle: definitions of technological accessories (milling heads, rotary
//! tables) read by CYCLE600, as in the paper:
//!
//! ```text
//! N830 TZ7:
//! N840 _HEAD_NAME="IFVW207S"
//! N850 _HEAD_ALLOWED=1
//! N860 _DELTA_L1=540.735 _DELTA_L2=250.049
//! ```
//!
//! Read line by line: an optional block number `N…`, then labels (`TZ7:`), assignments of the
//! known `_KEY=value` variables, `GOTOF`/`GOTOB`/`GOTO` jumps, `RET`/`M17`/`M30`, comments
//! after `;`. Anything else is an error that names its line: nothing is skipped silently.

use crate::kinematics::{Machine, RotaryAxis, Side};
use crate::text::scan::{Cursor, Exponent, Syntax};
use crate::{Error, Vector};

/// Longest accessory name in bytes (the field holds one more, the terminating NUL).
pub const NAME_MAX: usize = 31;
/// How many accessories a table holds.
pub const CAPACITY: usize = 16;

/// One accessory of the HEAD_DEF cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Head {
    /// `_HEAD_NAME`, `len` bytes of `name` are used.
    pub name: [u8; NAME_MAX],
    /// Length of the name.
    pub len: u8,
    /// `_HEAD_ALLOWED`.
    pub allowed: bool,
    /// `_DELTA_L1`, `_DELTA_L2`, `_DELTA_H1`.
    pub delta: [f64; 3],
    /// `_OFFS_L1_X`, `_OFFS_L1_Y`, `_OFFS_L2_X`, `_OFFS_L2_Y`, `_OFFS_H1_X`, `_OFFS_H1_Z`.
    pub offsets: [f64; 6],
}

impl Head {
    /// The name as bytes.
    pub fn name(&self) -> &[u8] {
        &self.name[..usize::from(self.len).min(NAME_MAX)]
    }

    /// The accessory as a two-axis swivel head whose axes have the directions `v1` (outer)
    /// and `v2` (inner, carried by the first); HEAD_DEF gives lengths, not directions.
    ///
    /// The lengths become pivots [derived; the paper names the variables but does not
    /// draw their geometry, so this is the reading the library documents]: the tool adapter
    /// is the origin, the tool points along +Z; `_DELTA_L2` is the height of the inner
    /// axis above the tool adapter and `_DELTA_L1` that of the outer axis above the inner
    /// one, `_DELTA_H1` the horizontal (Y) distance of the outer axis from the spindle; the
    /// `_OFFS_*` are the small errors across each length:
    /// `p2 = (OFFS_L2_X, OFFS_L2_Y, DELTA_L2)`,
    /// `p1 = p2 + (OFFS_L1_X, OFFS_L1_Y, DELTA_L1) + (OFFS_H1_X, DELTA_H1, OFFS_H1_Z)`.
    ///
    /// ```
    /// use cncrot::dialects::head_def::HeadTable;
    /// let t = HeadTable::parse(b"_HEAD_NAME=\"H\"\n_DELTA_L1=500 _DELTA_L2=250 _DELTA_H1=20\n").unwrap();
    /// let m = t.find(b"H").unwrap().machine([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();
    /// assert_eq!(m.axes()[1].point, [0.0, 0.0, 250.0]);
    /// assert_eq!(m.axes()[0].point, [0.0, 20.0, 750.0]);
    /// ```
    pub fn machine(&self, v1: Vector, v2: Vector) -> Result<Machine, Error> {
        let [l1, l2, h1] = self.delta;
        let [l1x, l1y, l2x, l2y, h1x, h1z] = self.offsets;
        let p2 = [l2x, l2y, l2];
        let p1 = [l2x + l1x + h1x, l2y + l1y + h1, l2 + l1 + h1z];
        let mut m = Machine::new([0.0, 0.0, 1.0])?;
        m.push_axis(RotaryAxis::new(Side::Tool, v1, p1))?;
        m.push_axis(RotaryAxis::new(Side::Tool, v2, p2))?;
        m.set_name(self.name())?;
        Ok(m)
    }
}

/// A fixed-capacity table of accessories (no allocation).
///
/// ```
/// use cncrot::dialects::head_def::HeadTable;
/// let t = HeadTable::parse(b"N840 _HEAD_NAME=\"IFVW207S\"\nN850 _HEAD_ALLOWED=1\n").unwrap();
/// assert!(t.find(b"IFVW207S").is_some());
/// assert_eq!(HeadTable::parse(b"_HEAD_NAME=\"A\"\nFOO=1\n").unwrap_err().line, 2);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HeadTable {
    /// The accessories, `count` of them used.
    pub heads: [Head; CAPACITY],
    /// How many are used.
    pub count: usize,
}

/// Why and where HEAD_DEF text could not be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// [`Error::Parse`], [`Error::NameTooLong`] or [`Error::TableFull`].
    pub error: Error,
    /// 1-based line number.
    pub line: usize,
}

const KEYS: [&[u8]; 11] = [
    b"_HEAD_ALLOWED",
    b"_DELTA_L1",
    b"_DELTA_L2",
    b"_DELTA_H1",
    b"_OFFS_L1_X",
    b"_OFFS_L1_Y",
    b"_OFFS_L2_X",
    b"_OFFS_L2_Y",
    b"_OFFS_H1_X",
    b"_OFFS_H1_Z",
    b"_HEAD_NAME",
];
/// The index of `_HEAD_NAME` in `KEYS`.
const NAME_KEY: usize = 10;

impl HeadTable {
    /// The empty table (the same as `HeadTable::default()`, usable in constants).
    pub const EMPTY: HeadTable = HeadTable {
        heads: [Head {
            name: [0; NAME_MAX],
            len: 0,
            allowed: false,
            delta: [0.0; 3],
            offsets: [0.0; 6],
        }; CAPACITY],
        count: 0,
    };

    /// Looks an accessory up by its exact name.
    pub fn find(&self, name: &[u8]) -> Option<&Head> {
        self.heads[..self.count.min(CAPACITY)]
            .iter()
            .find(|h| h.name() == name)
    }

    /// Reads HEAD_DEF text. Every accessory starts with `_HEAD_NAME="…"`; the variables
    /// after it belong to it. Errors name the 1-based line.
    ///
    /// Read as a SINUMERIK control reads a part program: keywords, addresses and variable
    /// names in any case (`_head_name`, `n10`, `gotof`; the name inside the quotes is
    /// compared exactly); a UTF-8 byte-order mark before the first line is skipped; a block
    /// marked for skipping (`/`, `/0` … `/9` before the block) is read as executed, as with
    /// the skip levels off, the control's default; reading ends with the block that ends
    /// the program (`M30`, `M17`, `M2`, `M02`, `RET`), as execution does: what follows is
    /// not read. Jumps (`GOTOF`, `GOTOB`, `GOTO`) are not followed: the text is a list of
    /// definitions.
    ///
    /// ```
    /// use cncrot::dialects::head_def::HeadTable;
    /// let t = HeadTable::parse(b"n10 _head_name=\"A\"\n/N20 M30\n_HEAD_NAME=\"B\"\n").unwrap();
    /// assert!(t.find(b"A").is_some() && t.find(b"B").is_none());
    /// ```
    pub fn parse(text: &[u8]) -> Result<HeadTable, ParseError> {
        let mut table = HeadTable::default();
        table.read(text)?;
        Ok(table)
    }

    /// [`HeadTable::parse`] into `self`, which must be empty; on an error it holds what was
    /// read before the failing line. The C boundary fills one table in place this way
    /// rather than moving a 1.8 KiB result around on the stack.
    pub(crate) fn read(&mut self, text: &[u8]) -> Result<(), ParseError> {
        let table = self;
        let text = text.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(text);
        for (index, raw) in text.split(|&b| b == b'\n').enumerate() {
            let fail = |error| ParseError {
                error,
                line: index + 1,
            };
            let line = match raw.iter().position(|&b| b == b';') {
                Some(p) => &raw[..p],
                None => raw,
            };
            let mut tokens = Tokens {
                rest: skip_mark(line),
            };
            let mut first = true;
            let mut end = false;
            while let Some(token) = tokens.next().map_err(|_| fail(Error::Parse))? {
                let is_block_number = first
                    && token.len() > 1
                    && token[0].eq_ignore_ascii_case(&b'N')
                    && token[1..].iter().all(u8::is_ascii_digit);
                first = false;
                if is_block_number {
                    continue;
                }
                if is_one_of(token, &[b"GOTOF", b"GOTOB", b"GOTO"]) {
                    // The jump target is the rest of the line.
                    tokens.rest = &[];
                    continue;
                }
                if is_one_of(token, &[b"RET", b"M17", b"M30", b"M2", b"M02"]) {
                    end = true;
                    continue;
                }
                if is_label(token) {
                    continue;
                }
                table.assign(token).map_err(fail)?;
            }
            if end {
                break;
            }
        }
        Ok(())
    }

    fn assign(&mut self, token: &[u8]) -> Result<(), Error> {
        let eq = token.iter().position(|&b| b == b'=').ok_or(Error::Parse)?;
        let (key, value) = (&token[..eq], &token[eq + 1..]);
        let k = KEYS
            .iter()
            .position(|&known| known.eq_ignore_ascii_case(key))
            .ok_or(Error::Parse)?;
        if k == NAME_KEY {
            let name = value
                .strip_prefix(b"\"")
                .and_then(|v| v.strip_suffix(b"\""))
                .ok_or(Error::Parse)?;
            if name.len() > NAME_MAX {
                return Err(Error::NameTooLong);
            }
            if !valid_name(name) {
                return Err(Error::Parse);
            }
            if self.find(name).is_some() {
                return Err(Error::Parse);
            }
            if self.count >= CAPACITY {
                return Err(Error::TableFull);
            }
            let mut head = Head {
                len: name.len() as u8,
                ..Head::default()
            };
            head.name[..name.len()].copy_from_slice(name);
            *self.heads.get_mut(self.count).ok_or(Error::TableFull)? = head;
            self.count += 1;
            return Ok(());
        }
        // A variable before the first _HEAD_NAME belongs to no accessory.
        // `get_mut` rather than indexing: the index is sound by construction, and this keeps
        // the parser provably free of panics (c_tests/no_panic.sh).
        let head = self.count.checked_sub(1).ok_or(Error::Parse)?;
        let head = self.heads.get_mut(head).ok_or(Error::Parse)?;
        let v = number(value)?;
        let slot = match k {
            0 => {
                head.allowed = match v {
                    0.0 => false,
                    1.0 => true,
                    _ => return Err(Error::Parse),
                };
                return Ok(());
            }
            1..=3 => head.delta.get_mut(k - 1),
            _ => head.offsets.get_mut(k - 4),
        };
        *slot.ok_or(Error::Parse)? = v;
        Ok(())
    }
}

/// Whether `name` can name an accessory: 1 to 31 printable ASCII characters other than the
/// space and the quote. A control character (a tab, the CR of a CRLF file inside the
/// quotes), a space (invisible when `_MIHEAD` is typed) or a byte outside ASCII (the
/// control's character set is not UTF-8) would make a name that a CYCLE600 call cannot
/// reliably match, so such names are refused rather than stored.
///
/// ```
/// use cncrot::dialects::head_def::valid_name;
/// assert!(valid_name(b"IFVW207S") && valid_name(b"UFK_600-A"));
/// assert!(!valid_name(b"") && !valid_name(b"MY HEAD") && !valid_name(b"A\r"));
/// ```
pub fn valid_name(name: &[u8]) -> bool {
    (1..=NAME_MAX).contains(&name.len()) && name.iter().all(|&b| b.is_ascii_graphic() && b != b'"')
}

/// The line without a block-skip mark (`/` or `/0` … `/9` before the block).
fn skip_mark(line: &[u8]) -> &[u8] {
    let start = line
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(line.len());
    match line.get(start..) {
        Some([b'/', d, rest @ ..]) if d.is_ascii_digit() => rest,
        Some([b'/', rest @ ..]) => rest,
        _ => line,
    }
}

fn is_one_of(token: &[u8], words: &[&[u8]]) -> bool {
    words.iter().any(|w| w.eq_ignore_ascii_case(token))
}

fn is_label(token: &[u8]) -> bool {
    match token.split_last() {
        Some((b':', name)) => {
            !name.is_empty() && name.iter().all(|&b| b.is_ascii_alphanumeric() || b == b'_')
        }
        _ => false,
    }
}

/// What a number is in a `HEAD_DEF` table: C's `[+-]digits[.digits][(e|E)[+-]digits]`, a
/// whole token (tokens are separated by white space).
const NUMBER: Syntax = Syntax {
    exponent: Exponent::E,
    ends: b"",
    comma: false,
    iso: false,
};

/// A token that is one number, correctly rounded (the reader every program text goes
/// through); anything else, a magnitude beyond `1e±100` too, is [`Error::Parse`] (a table
/// reports the line, not the kind of damage).
pub(crate) fn number(token: &[u8]) -> Result<f64, Error> {
    let mut c = Cursor::new(token);
    let v = c.number(NUMBER).map_err(|_| Error::Parse)?;
    if c.at_end() {
        Ok(v)
    } else {
        Err(Error::Parse)
    }
}

/// Whitespace-separated tokens; a quoted string is one token with its quotes.
struct Tokens<'a> {
    rest: &'a [u8],
}

impl<'a> Tokens<'a> {
    fn next(&mut self) -> Result<Option<&'a [u8]>, Error> {
        let start = self.rest.iter().position(|b| !b.is_ascii_whitespace());
        let Some(start) = start else {
            self.rest = &[];
            return Ok(None);
        };
        let s = &self.rest[start..];
        let mut in_quotes = false;
        let mut end = s.len();
        for (i, &b) in s.iter().enumerate() {
            if b == b'"' {
                in_quotes = !in_quotes;
            } else if b.is_ascii_whitespace() && !in_quotes {
                end = i;
                break;
            }
        }
        if in_quotes {
            return Err(Error::Parse);
        }
        // `end <= s.len()` always; the checked form keeps the reader provably panic-free.
        let (token, rest) = s.split_at_checked(end).unwrap_or((s, &[]));
        self.rest = rest;
        Ok(Some(token))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The paper's HEAD_DEF listing with its OCR damage mended (`DELTA_L2` without its
    /// underscore, `_OFFS_H1 _X`, `OFFS_H1_7`, a doubled N880, `END.`).
    const PAPER: &[u8] = b"N830 TZ7:
N840 _HEAD_NAME=\"IFVW207S\"
N850 _HEAD_ALLOWED=1
N860 _DELTA_L1=540.735 _DELTA_L2=250.049
N870 _DELTA_H1=200.007
N880 _OFFS_L1_X=0.024 _OFFS_L1_Y=0.032
N890 _OFFS_L2_X=0.011 _OFFS_L2_Y=-0.041
N900 _OFFS_H1_X=0.335 _OFFS_H1_Z=0.247 ; tool side
N910 GOTOF END
END:
";

    #[test]
    fn reads_the_papers_head() {
        let t = HeadTable::parse(PAPER).unwrap();
        assert_eq!(t.count, 1);
        let h = t.find(b"IFVW207S").unwrap();
        assert!(h.allowed);
        assert_eq!(h.delta, [540.735, 250.049, 200.007]);
        assert_eq!(h.offsets, [0.024, 0.032, 0.011, -0.041, 0.335, 0.247]);
        assert!(t.find(b"UFK600").is_none());
    }

    #[test]
    fn the_papers_ocr_text_is_refused_at_its_first_damaged_line() {
        let ocr = b"N830 TZ7:\nN840 _HEAD_NAME=\"IFVW207S\"\nN850 _HEAD_ALLOWED=1\nN860 _DELTA_L1=540.735 DELTA_L2=250.049\n";
        assert_eq!(
            HeadTable::parse(ocr),
            Err(ParseError {
                error: Error::Parse,
                line: 4
            })
        );
    }

    #[test]
    fn errors_name_their_line() {
        let cases: [(&[u8], Error, usize); 9] = [
            (b"_DELTA_L1=1\n", Error::Parse, 1),
            (b"_HEAD_NAME=\"A\"\n\n_DELTA_L1=abc\n", Error::Parse, 3),
            (b"_HEAD_NAME=\"A\"\n_DELTA_L1=inf\n", Error::Parse, 2),
            (b"_HEAD_NAME=\"A\"\n_DELTA_L1=1e999\n", Error::Parse, 2),
            (b"_HEAD_NAME=\"A\"\n_HEAD_NAME=\"A\"\n", Error::Parse, 2),
            (b"_HEAD_NAME=\"unterminated\n", Error::Parse, 1),
            (
                b"_HEAD_NAME=\"0123456789012345678901234567890123\"\n",
                Error::NameTooLong,
                1,
            ),
            (b"_HEAD_NAME=\"A\"\n_HEAD_ALLOWED=2\n", Error::Parse, 2),
            (b"N10 G0 X1\n", Error::Parse, 1),
        ];
        for (text, error, line) in cases {
            assert_eq!(
                HeadTable::parse(text),
                Err(ParseError { error, line }),
                "{:?}",
                core::str::from_utf8(text)
            );
        }
    }

    /// The choices "as the control reads a part program", one by one.
    #[test]
    fn read_as_the_control_reads_it() {
        // A UTF-8 byte-order mark (an editor on Windows) is skipped.
        let t = HeadTable::parse(b"\xEF\xBB\xBFN10 _HEAD_NAME=\"A\"\n").unwrap();
        assert!(t.find(b"A").is_some());
        // Keywords in any case; the name itself is compared exactly.
        let t =
            HeadTable::parse(b"n10 tz7:\n_head_name=\"Ab\" _Delta_L1=2\ngotof end\nm17\n").unwrap();
        assert_eq!(t.find(b"Ab").unwrap().delta[0], 2.0);
        assert!(t.find(b"AB").is_none());
        // A block marked for skipping is read as executed (skip levels off).
        let t = HeadTable::parse(b"/N10 _HEAD_NAME=\"A\"\n/3 N20 _DELTA_L2=5\n / _DELTA_H1=6\n")
            .unwrap();
        assert_eq!(t.find(b"A").unwrap().delta, [0.0, 5.0, 6.0]);
        // Reading ends with the block that ends the program; that block itself is read.
        for end in ["M30", "RET", "M17", "M2", "M02", "m30"] {
            let text =
                format!("_HEAD_NAME=\"A\"\nN90 _DELTA_L1=1 {end}\n_HEAD_NAME=\"B\"\nGARBAGE\n");
            let t = HeadTable::parse(text.as_bytes()).unwrap();
            assert_eq!((t.count, t.find(b"A").unwrap().delta[0]), (1, 1.0), "{end}");
        }
        // Names: printable ASCII, no spaces, no control characters, nothing outside ASCII.
        for bad in [
            &b"\"MY HEAD\""[..],
            b"\"A\tB\"",
            b"\"A\rB\"",
            b"\"\xC3\x84\"",
            b"\"\xFF\"",
        ] {
            let mut text = b"_HEAD_NAME=".to_vec();
            text.extend_from_slice(bad);
            assert_eq!(
                HeadTable::parse(&text).map(|t| t.count),
                Err(ParseError {
                    error: Error::Parse,
                    line: 1
                }),
                "{bad:?}"
            );
        }
        // A CRLF file: the CR ends the line, not the name.
        let t = HeadTable::parse(b"_HEAD_NAME=\"A\"\r\n_DELTA_L1=3\r\n").unwrap();
        assert_eq!(t.find(b"A").unwrap().delta[0], 3.0);
    }

    #[test]
    fn a_full_table_is_reported() {
        let mut text = Vec::new();
        for k in 0..=CAPACITY {
            text.extend_from_slice(format!("_HEAD_NAME=\"H{k}\"\n").as_bytes());
        }
        let e = HeadTable::parse(&text).unwrap_err();
        assert_eq!(
            e,
            ParseError {
                error: Error::TableFull,
                line: CAPACITY + 1
            }
        );
    }

    #[test]
    fn numbers_read_correctly_rounded() {
        let exact: [(&[u8], f64); 14] = [
            (b"540.735", 540.735),
            (b"-0.041", -0.041),
            (b"+7", 7.0),
            (b"1e3", 1000.0),
            (b"1.5E-3", 0.0015),
            (b"0.0000001", 1e-7),
            (b"123456789012345", 123456789012345.0),
            (b"9007199254740992", 9007199254740992.0),
            (b"1.5000000000000000000000000", 1.5),
            (b"1e22", 1e22),
            (b"1e23", 1e23),
            (b"000.5", 0.5),
            (b"5.", 5.0),
            (b".5", 0.5),
        ];
        for (text, v) in exact {
            assert_eq!(number(text).map(f64::to_bits), Ok(v.to_bits()), "{text:?}");
        }
        // No -0: the library never returns it.
        assert_eq!(number(b"-0").map(f64::to_bits), Ok(0));
        assert_eq!(number(b"-0.000e5").map(f64::to_bits), Ok(0));
        let refused: [&[u8]; 14] = [
            b"", b".", b"-", b"1e", b"e5", b"1.2.3", b"+-1", b"inf", b"nan", b"1,5", b"0x10",
            b" 1", b"1 ", b"1e400",
        ];
        for text in refused {
            assert_eq!(number(text), Err(Error::Parse), "{text:?}");
        }
        // Beyond Clinger's exact case, correctly rounded as the program lines are: 2^53 + 1
        // is a tie that goes to the even 2^53; 1e-23 is the double nearest to it.
        assert_eq!(number(b"9007199254740993"), Ok(9007199254740992.0));
        assert_eq!(number(b"1e-23").map(f64::to_bits), Ok(1e-23f64.to_bits()));
    }

    /// The reader gives the bits `str::parse` (correctly rounded) gives.
    #[test]
    fn numbers_match_the_standard_parser() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        };
        for _ in 0..200_000 {
            let digits = 1 + next(25) as usize;
            let mut text = String::new();
            if next(2) == 0 {
                text.push('-');
            }
            let point = next(digits as u64 + 1) as usize;
            for k in 0..digits {
                if k == point {
                    text.push('.');
                }
                text.push(char::from(b'0' + next(10) as u8));
            }
            if next(2) == 0 {
                text.push_str(&format!("e{}", next(61) as i64 - 30));
            }
            let ours = number(text.as_bytes()).expect(&text);
            let theirs: f64 = text.parse().unwrap();
            let theirs = if theirs == 0.0 { 0.0 } else { theirs };
            assert_eq!(ours.to_bits(), theirs.to_bits(), "{text}");
        }
    }
}
