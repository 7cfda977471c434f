//! Reading what people type: numbers, conventions, dialects, points, and one input per line
//! for batch mode. Every refusal names the column of the first character it could not use.

use cncrot::dialects::program::Dialect;
use cncrot::{AxisCode, Convention, Kind, Sequence};

/// A refused input: why, and the 1-based column (byte) where reading stopped, if the
/// input is text that has columns.
#[derive(Debug)]
pub struct Failure {
    pub message: String,
    pub column: Option<usize>,
}

impl Failure {
    pub fn new(message: impl Into<String>) -> Failure {
        Failure {
            message: message.into(),
            column: None,
        }
    }

    pub fn at(column: usize, message: impl Into<String>) -> Failure {
        Failure {
            message: message.into(),
            column: Some(column),
        }
    }
}

impl From<cncrot::Error> for Failure {
    fn from(e: cncrot::Error) -> Failure {
        Failure::new(e.message())
    }
}

/// The word that starts at a 1-based column of a block: up to the next space, at most 24
/// characters (then `…`).
fn word_at(text: &str, column: usize) -> Option<String> {
    let rest = text.get(column.checked_sub(1)?..)?;
    // A quoted text is one word, spaces and all.
    let word: String = match rest.strip_prefix('"') {
        Some(inner) => match inner.find('"') {
            Some(end) => format!("\"{}\"", &inner[..end]),
            None => rest.to_string(),
        },
        None => rest.chars().take_while(|c| !c.is_whitespace()).collect(),
    };
    if word.is_empty() {
        return None;
    }
    Some(if word.chars().count() > 24 {
        word.chars().take(24).collect::<String>() + "…"
    } else {
        word
    })
}

/// Why a block was refused, naming what was wrong: the word the reader expected
/// (`missing: SPC`), the word it could not use (`'SPX+10': unknown, repeated or misplaced
/// word`), the variable where a number must stand, the malformed number, the controller's
/// longest line; other refusals (a frame the mathematics refuses) with the word they were
/// found at.
pub fn block_message(text: &str, e: &cncrot::dialects::program::LineError) -> String {
    use cncrot::Error;
    // A quoted text shows its own quotes; another word is put in single quotes.
    let word = word_at(text, e.column).map(|w| {
        if w.starts_with('"') {
            w
        } else {
            format!("'{w}'")
        }
    });
    match (e.error, e.expected, word) {
        (Error::MissingWord, Some(what), _) => format!("missing: {what}"),
        (Error::MissingWord, None, _) => e.error.message().to_string(),
        (Error::UnknownWord, _, Some(w)) => {
            format!("{w}: unknown, repeated or misplaced word (not one this command takes here)")
        }
        (Error::NotANumber, _, Some(w)) => format!(
            "{w}: a variable or an expression where a number must stand (cncrot reads \
             numbers only)"
        ),
        (Error::Parse, _, Some(w)) if w.starts_with("'(") => {
            format!("{w}: a comment that is not closed")
        }
        (Error::Parse, _, Some(w)) => {
            format!("{w}: malformed (not a number as the control writes it)")
        }
        (Error::LineTooLong, _, _) => format!(
            "the line is longer than the controller reads ({} characters at most)",
            e.column.saturating_sub(1)
        ),
        // Not a machine's lack: a word the reader does not follow here, and what may stand.
        (Error::NotAvailable, Some(allowed), Some(w)) => {
            format!("{w}: not followed by cncrot (it takes {allowed})")
        }
        (other, Some(allowed), Some(w)) => {
            format!("{w}: {} ({allowed})", other.message())
        }
        (other, _, Some(w)) if e.column > 1 => format!("{w}: {}", other.message()),
        (other, _, _) => other.message().to_string(),
    }
}

/// The numbers of a text, separated by spaces, tabs, commas or semicolons, each with the
/// column it starts at. A token that is not a finite number is refused at its column.
pub fn numbers(text: &str) -> Result<Vec<f64>, Failure> {
    let mut out = Vec::new();
    for (column, token) in tokens(text) {
        out.push(number(token).map_err(|m| Failure::at(column, m))?);
    }
    Ok(out)
}

/// Exactly `n` numbers.
pub fn exactly<const N: usize>(text: &str, what: &str) -> Result<[f64; N], Failure> {
    let v = numbers(text)?;
    <[f64; N]>::try_from(v.as_slice()).map_err(|_| {
        Failure::at(
            text.len() + 1,
            format!("{what}: expected {N} numbers, found {}", v.len()),
        )
    })
}

/// The tokens of a text with their 1-based columns.
pub fn tokens(text: &str) -> Vec<(usize, &str)> {
    let sep = |c: char| c.is_whitespace() || c == ',' || c == ';';
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.char_indices() {
        match (sep(c), start) {
            (true, Some(s)) => {
                out.push((s + 1, &text[s..i]));
                start = None;
            }
            (false, None) => start = Some(i),
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s + 1, &text[s..]));
    }
    out
}

/// One finite number in the usual decimal notation (`1`, `-2.5`, `1e3`).
pub fn number(token: &str) -> Result<f64, String> {
    let plain = token
        .bytes()
        .all(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.' | b'e' | b'E'));
    match token.parse::<f64>() {
        Ok(x) if plain && x.is_finite() => Ok(x),
        Ok(_) if plain => Err(format!("'{token}' is too large")),
        _ => Err(format!("'{token}' is not a number")),
    }
}

/// A convention as `KIND:SEQUENCE`: kind `intrinsic`/`i`/`1` (about the workpiece axes) or
/// `extrinsic`/`e`/`0` (about the machine axes); the sequence as letters (`ZXY`, primes
/// allowed: `ZX'Y''`) or as the code (`39`). `partial` allows skipped rotations (`0` for
/// a letter, or a code with `00` pairs), which only a rotation to compose may have.
pub fn convention(text: &str, partial: bool) -> Result<(Kind, AxisCode), Failure> {
    let Some((kind, seq)) = text.split_once(':') else {
        return Err(Failure::at(
            1,
            format!("'{text}': expected KIND:SEQUENCE, e.g. extrinsic:XYZ or intrinsic:ZXY"),
        ));
    };
    let kind = match kind.to_ascii_lowercase().as_str() {
        "intrinsic" | "i" | "1" => Kind::Intrinsic,
        "extrinsic" | "e" | "0" => Kind::Extrinsic,
        other => {
            return Err(Failure::at(
                1,
                format!("'{other}' is neither intrinsic (i, 1) nor extrinsic (e, 0)"),
            ))
        }
    };
    let column = kind_len(text) + 2;
    let code = if seq.bytes().all(|b| b.is_ascii_digit()) && !seq.is_empty() {
        seq.parse::<i32>().unwrap_or(-1)
    } else {
        let mut code = 0;
        let mut k = 0;
        for (i, c) in seq.char_indices() {
            let bits = match c.to_ascii_uppercase() {
                'X' => 1,
                'Y' => 2,
                'Z' => 3,
                '0' | '-' => 0,
                '\'' | '"' => continue,
                _ => {
                    return Err(Failure::at(
                        column + i,
                        format!("'{c}' is not an axis letter (X, Y, Z)"),
                    ))
                }
            };
            if k == 3 {
                return Err(Failure::at(column + i, "more than three rotations"));
            }
            code += bits << (2 * k);
            k += 1;
        }
        code
    };
    let axis_code = AxisCode::new(code)
        .map_err(|e| Failure::at(column, format!("'{seq}': {}", e.message())))?;
    if !partial && Sequence::from_axis_code(axis_code).is_err() {
        return Err(Failure::at(
            column,
            format!("'{seq}': the result needs three rotations (one of the 12 sequences)"),
        ));
    }
    Ok((kind, axis_code))
}

fn kind_len(text: &str) -> usize {
    text.find(':').unwrap_or(0)
}

/// A target convention: one of the 12 sequences.
pub fn full_convention(text: &str) -> Result<Convention, Failure> {
    let (kind, code) = convention(text, false)?;
    let sequence = Sequence::from_axis_code(code)?;
    Ok(Convention::new(kind, sequence))
}

/// A controller family by name.
pub fn dialect(name: &str) -> Result<Dialect, Failure> {
    match name.trim().to_ascii_lowercase().as_str() {
        "sinumerik" | "siemens" => Ok(Dialect::Sinumerik),
        "heidenhain" | "tnc" => Ok(Dialect::Heidenhain),
        "fanuc" => Ok(Dialect::Fanuc),
        "syntec" => Ok(Dialect::Syntec),
        "twincat" | "beckhoff" => Ok(Dialect::Twincat),
        "haas" => Ok(Dialect::Haas),
        other => Err(Failure::new(format!(
            "'{other}' is not a dialect: sinumerik, heidenhain, fanuc, syntec, twincat, haas"
        ))),
    }
}

/// The name a dialect is given on the command line.
pub fn dialect_name(d: Dialect) -> &'static str {
    match d {
        Dialect::Sinumerik => "sinumerik",
        Dialect::Heidenhain => "heidenhain",
        Dialect::Fanuc => "fanuc",
        Dialect::Syntec => "syntec",
        Dialect::Twincat => "twincat",
        Dialect::Haas => "haas",
    }
}

/// The command each dialect writes when no form is named.
pub fn default_form(d: Dialect) -> &'static str {
    match d {
        Dialect::Sinumerik => "CYCLE800",
        Dialect::Heidenhain => "PLANE SPATIAL",
        Dialect::Fanuc => "G68.2",
        Dialect::Syntec => "G158",
        Dialect::Twincat => "ROT",
        Dialect::Haas => "G268",
    }
}

/// A line to write: `DIALECT` or `DIALECT:FORM` (`heidenhain:PLANE EULER`).
#[derive(Clone, Debug)]
pub struct Target {
    pub dialect: Dialect,
    pub form: String,
}

pub fn target(text: &str) -> Result<Target, Failure> {
    let (name, form) = match text.split_once(':') {
        Some((n, f)) => (n, f.trim().to_string()),
        None => (text, String::new()),
    };
    let dialect = dialect(name)?;
    let form = if form.is_empty() {
        default_form(dialect).to_string()
    } else {
        form
    };
    Ok(Target { dialect, form })
}

/// Every dialect in its default form.
pub fn all_targets() -> Vec<Target> {
    Dialect::ALL
        .iter()
        .map(|&dialect| Target {
            dialect,
            form: default_form(dialect).to_string(),
        })
        .collect()
}

/// The inputs of a batch: every line of a file (`-`: standard input), each with its 1-based
/// number, so that the outputs align with them; a `\r` before the line end is dropped.
pub fn batch_lines(source: &str) -> Result<Vec<(usize, String)>, Failure> {
    let text = read_source(source)?;
    Ok(text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.to_string()))
        .collect())
}

/// The whole text of a file, or of standard input for `-`: UTF-8, or else Latin-1.
pub fn read_source(source: &str) -> Result<String, Failure> {
    read_source_as(source).map(|(text, _, _)| text)
}

/// [`read_source`], whether the file was read as Latin-1 and whether it began with a
/// byte-order mark (a translation writes it back in the bytes it came in). The mark (what
/// Windows editors and spreadsheets' "CSV UTF-8" put first) is not part of the text.
pub fn read_source_as(source: &str) -> Result<(String, bool, bool), Failure> {
    let bytes = if source == "-" {
        let mut v = Vec::new();
        std::io::Read::read_to_end(&mut std::io::stdin(), &mut v)
            .map_err(|e| Failure::new(format!("standard input: {e}")))?;
        v
    } else {
        std::fs::read(source).map_err(|e| Failure::new(format!("{source}: {e}")))?
    };
    // Controls and their editors write comments in Latin-1 (ISO 8859-1: a hyperMILL
    // program for a Heidenhain control has "letörés" in one byte per letter): such a file
    // is read byte for byte as Latin-1, so that every block is read (the commands are
    // ASCII either way) instead of the whole file refused.
    // A UTF-16 file (what an editor's "Unicode" saves) has a NUL beside every ASCII
    // letter: read byte for byte, no block would be read and every one passed over. Refused,
    // as a file holding NUL bytes otherwise (no control program does).
    let name = if source == "-" {
        "standard input"
    } else {
        source
    };
    if bytes.starts_with(b"\xFF\xFE") || bytes.starts_with(b"\xFE\xFF") {
        return Err(Failure::new(format!(
            "{name}: a UTF-16 text (its first bytes say so): save it as UTF-8 or Latin-1 (ANSI)"
        )));
    }
    if let Some(at) = bytes.iter().position(|&b| b == 0) {
        let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
        return Err(Failure::new(format!(
            "{name}: line {line} holds a NUL byte, which no program text has (a UTF-16 file? save it as UTF-8 or Latin-1)"
        )));
    }
    const BOM: &[u8] = b"\xEF\xBB\xBF";
    let bom = bytes.starts_with(BOM);
    let bytes = if bom {
        bytes.get(BOM.len()..).unwrap_or_default().to_vec()
    } else {
        bytes
    };
    Ok(match String::from_utf8(bytes) {
        Ok(text) => (text, false, bom),
        Err(e) => (
            e.into_bytes().into_iter().map(char::from).collect(),
            true,
            bom,
        ),
    })
}

/// The decimals option: a count from 0 to 17, or `exact` (the shortest numbers that read
/// back to the same double).
pub fn decimals(text: &str) -> Result<i32, String> {
    let text = text.trim();
    if text.eq_ignore_ascii_case("exact") {
        return Ok(-1);
    }
    match text.parse::<i32>() {
        Ok(d) if (0..=17).contains(&d) => Ok(d),
        _ => Err(format!("'{text}': a count of decimals 0..17, or 'exact'")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conventions_in_letters_and_codes() {
        // Codes from the definition a1 + 4·a2 + 16·a3 with X = 1, Y = 2, Z = 3.
        let (k, c) = convention("extrinsic:XYZ", false).unwrap();
        assert_eq!((k, c.code()), (Kind::Extrinsic, 57));
        let (k, c) = convention("i:ZX'Y''", false).unwrap();
        assert_eq!((k, c.code()), (Kind::Intrinsic, 39));
        assert_eq!(convention("1:39", false).unwrap().1.code(), 39);
        assert_eq!(convention("e:Z0X", true).unwrap().1.code(), 3 + 16);
        assert!(convention("e:ZX", false).is_err());
        assert_eq!(convention("e:XXZ", true).unwrap_err().column, Some(3));
        assert_eq!(convention("e:XQZ", true).unwrap_err().column, Some(4));
        assert!(convention("XYZ", false).is_err());
    }

    #[test]
    fn numbers_with_columns() {
        assert_eq!(numbers("30, 45;60").unwrap(), vec![30.0, 45.0, 60.0]);
        assert_eq!(numbers("30 4x5").unwrap_err().column, Some(4));
        assert!(numbers("nan").is_err() && numbers("inf").is_err() && numbers("1e999").is_err());
    }
}
