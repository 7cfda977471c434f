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

use crate::Error;

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

impl HeadTable {
    /// Looks an accessory up by its exact name.
    pub fn find(&self, name: &[u8]) -> Option<&Head> {
        self.heads[..self.count.min(CAPACITY)]
            .iter()
            .find(|h| h.name() == name)
    }

    /// Reads HEAD_DEF text. Every accessory starts with `_HEAD_NAME="…"`; the variables
    /// after it belong to it. Errors name the 1-based line.
    pub fn parse(text: &[u8]) -> Result<HeadTable, ParseError> {
        let mut table = HeadTable::default();
        for (index, raw) in text.split(|&b| b == b'\n').enumerate() {
            let fail = |error| ParseError {
                error,
                line: index + 1,
            };
            let line = match raw.iter().position(|&b| b == b';') {
                Some(p) => &raw[..p],
                None => raw,
            };
            let mut tokens = Tokens { rest: line };
            let mut first = true;
            while let Some(token) = tokens.next().map_err(|_| fail(Error::Parse))? {
                let is_block_number = first
                    && token.len() > 1
                    && token[0] == b'N'
                    && token[1..].iter().all(u8::is_ascii_digit);
                first = false;
                if is_block_number {
                    continue;
                }
                if matches!(token, b"GOTOF" | b"GOTOB" | b"GOTO") {
                    // The jump target is the rest of the line.
                    tokens.rest = &[];
                    continue;
                }
                if matches!(token, b"RET" | b"M17" | b"M30") || is_label(token) {
                    continue;
                }
                table.assign(token).map_err(fail)?;
            }
        }
        Ok(table)
    }

    fn assign(&mut self, token: &[u8]) -> Result<(), Error> {
        let eq = token.iter().position(|&b| b == b'=').ok_or(Error::Parse)?;
        let (key, value) = (&token[..eq], &token[eq + 1..]);
        let k = KEYS
            .iter()
            .position(|&known| known == key)
            .ok_or(Error::Parse)?;
        if key == b"_HEAD_NAME" {
            let name = value
                .strip_prefix(b"\"")
                .and_then(|v| v.strip_suffix(b"\""))
                .ok_or(Error::Parse)?;
            if name.is_empty() || name.contains(&b'"') || name.contains(&0) {
                return Err(Error::Parse);
            }
            if name.len() > NAME_MAX {
                return Err(Error::NameTooLong);
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
            self.heads[self.count] = head;
            self.count += 1;
            return Ok(());
        }
        // A variable before the first _HEAD_NAME belongs to no accessory.
        let head = self.count.checked_sub(1).ok_or(Error::Parse)?;
        let head = &mut self.heads[head];
        let v = number(value)?;
        match k {
            0 => {
                head.allowed = match v {
                    0.0 => false,
                    1.0 => true,
                    _ => return Err(Error::Parse),
                }
            }
            1..=3 => head.delta[k - 1] = v,
            _ => head.offsets[k - 4] = v,
        }
        Ok(())
    }
}

fn is_label(token: &[u8]) -> bool {
    match token.split_last() {
        Some((b':', name)) => {
            !name.is_empty() && name.iter().all(|&b| b.is_ascii_alphanumeric() || b == b'_')
        }
        _ => false,
    }
}

/// A finite decimal number; no `inf`/`nan`, which `str::parse` would accept.
fn number(value: &[u8]) -> Result<f64, Error> {
    let ok = !value.is_empty()
        && value
            .iter()
            .all(|&b| b.is_ascii_digit() || matches!(b, b'.' | b'-' | b'+' | b'e' | b'E'));
    let s = core::str::from_utf8(value).map_err(|_| Error::Parse)?;
    match s.parse::<f64>() {
        Ok(v) if ok && v.is_finite() => Ok(v),
        _ => Err(Error::Parse),
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
        self.rest = &s[end..];
        Ok(Some(&s[..end]))
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
}
