//! SINUMERIK swivel data (`$TC_CARR1[n]` … `$TC_CARR65[n]`, the orientable tool holder of
//! CYCLE800) read into a [`Machine`].
//!
//! What each parameter means (the SINUMERIK function manual "Tool offset", tool holders
//! with orientation capability):
//!
//! | parameters | meaning |
//! |---|---|
//! | 1-3, 4-6, 15-17, 18-20 | offset vectors l1, l2, l3, l4 (mm) |
//! | 7-9, 10-12 | rotary-axis vectors v1, v2 (any length; zero: no such axis) |
//! | 13, 14 | angles α1, α2 when no axis is assigned (not a property of the machine: read and ignored) |
//! | 21, 22 | axis identifiers (read and ignored) |
//! | 23 | kinematics type `"T"` (tool), `"P"` (part), `"M"` (mixed) |
//! | 24, 25 | rotary-axis offsets: the positions the axes read in the described state |
//! | 26-29 | Hirth tooth offset (26, 27) and increment (28, 29; 0: no Hirth grid) |
//! | 30-33 | travel limits: minimum (30, 31), maximum (32, 33); both 0: no limits |
//! | 34 | the tool holder's name |
//! | 35-40 | for the user (read and ignored) |
//! | 41-46, 55-60, 64, 65 | fine offsets, added to parameter − 40 [choice: as with the fine correction enabled] |
//!
//! 47-54 and 61-63 do not exist (the control raises an alarm): refused.
//!
//! Pivots [spec of this library, from the kinematics types]: type T (both axes turn the
//! tool): `p1 = −l1`, `p2 = −l1 − l2` (l3 leads from the tool adapter to pivot 2, l2 from
//! pivot 2 to pivot 1, l1 closes the chain); type P (both turn the workpiece): `p1 = l2`,
//! `p2 = l2 + l3` (l4 closes the chain); type M: axis 1 turns the tool about `p1 = l2`,
//! axis 2 the workpiece about `p2 = l3`. The axis vectors are taken as they stand: for an
//! axis that turns the workpiece the commissioning enters the vector whose right-hand turn
//! is the axis' positive direction (a C table turning clockwise seen from above for C+ is
//! entered as `0, 0, −1`).

use crate::kinematics::{Hirth, Machine, RotaryAxis, Side, MACHINE_NAME_MAX};
use crate::text::scan::{Cursor, Exponent, Syntax};
use crate::{Error, Vector};

const NUMBER: Syntax = Syntax {
    exponent: Exponent::Ex,
    ends: b";",
    comma: false,
    iso: false,
};

/// Why and where swivel data could not be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CarrError {
    /// Why (the errors of [`machine_from_carr`]).
    pub error: Error,
    /// 1-based line: where the text could not be read, or for a data set that does not
    /// make a machine, the line that last assigned the parameter at fault; 0 when no line
    /// is (no parameter of the data set, a data set number below 1).
    pub line: usize,
    /// The `$TC_CARR` parameter at fault: the one a line could not read; 23 for a
    /// kinematics type other than T, P, M; one of the axis' vector (7..9, 10..12, the last
    /// assigned) for a second axis without a first or parallel to it, and for an axis whose
    /// offset, limits or Hirth grid are out of bounds; 28 or 29 for a negative Hirth
    /// increment; 0 when none is.
    pub parameter: usize,
}

/// The parameters of one data set as read.
struct Data {
    values: [f64; 66],
    /// The line of each parameter's last assignment (0: none; u32 to keep the reader's
    /// frame within the setup stack bound).
    lines: [u32; 66],
    kind: u8,
    name: [u8; MACHINE_NAME_MAX],
    name_len: usize,
    found: bool,
}

/// Reads the swivel data set `data_set` (1-based) from `$TC_CARR…` assignments and builds
/// its machine; assignments to other data sets and other tool data (`$TC_DP…`, `$TC_TP…`,
/// the rest of a TOA archive) are skipped, as are `CHANDATA(…)` and comments; `M17`, `M30`,
/// `M2` end the text. Errors name the 1-based line and the parameter ([`CarrError`]):
/// [`Error::Parse`] (malformed),
/// [`Error::UnknownWord`] (a parameter that does not exist, the chain-based
/// `$TC_CARR_KIN_…`, anything else), [`Error::NameTooLong`], [`Error::UnknownHead`] (line 0:
/// no parameter of that data set), [`Error::BadArgument`] (at the parameter's line: a
/// kinematics type other than T, P, M; v2 without v1; two parallel axes; limits or Hirth
/// increments that do not make sense).
///
/// ```
/// use cncrot::dialects::carr::machine_from_carr;
/// let text = b"$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0 ; B about Y
/// $TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=1 ; C about Z
/// $TC_CARR23[1]=\"T\"
/// $TC_CARR4[1]=0 $TC_CARR5[1]=0 $TC_CARR6[1]=-150
/// $TC_CARR34[1]=\"HEAD_BC\"";
/// let m = machine_from_carr(text, 1).unwrap();
/// assert_eq!(m.axes().len(), 2);
/// assert_eq!(m.axes()[1].point, [0.0, 0.0, 150.0]); // p2 = -l1 - l2
/// assert_eq!(m.name(), b"HEAD_BC");
/// assert_eq!(machine_from_carr(b"$TC_CARR50[1]=0", 1).unwrap_err().line, 1);
/// // A type that is not T, P or M: its parameter and line.
/// let e = machine_from_carr(b"$TC_CARR7[1]=1\n$TC_CARR23[1]=\"X\"", 1).unwrap_err();
/// assert_eq!((e.error, e.line, e.parameter), (cncrot::Error::BadArgument, 2, 23));
/// ```
pub fn machine_from_carr(text: &[u8], data_set: i32) -> Result<Machine, CarrError> {
    let at = |line: usize, parameter: usize| {
        move |error: Error| CarrError {
            error,
            line,
            parameter,
        }
    };
    if data_set < 1 {
        return Err(at(0, 0)(Error::BadArgument));
    }
    let mut data = Data {
        values: [0.0; 66],
        lines: [0; 66],
        kind: b'T',
        name: [0; MACHINE_NAME_MAX],
        name_len: 0,
        found: false,
    };
    let text = text.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(text);
    for (index, raw) in text.split(|&b| b == b'\n').enumerate() {
        let line = raw.strip_suffix(b"\r").unwrap_or(raw);
        match read_line(line, index + 1, data_set, &mut data) {
            Ok(true) => {}
            Ok(false) => break,
            Err((e, parameter)) => return Err(at(index + 1, parameter)(e)),
        }
    }
    if !data.found {
        return Err(at(0, 0)(Error::UnknownHead));
    }
    build(&data).map_err(|(error, parameter)| CarrError {
        error,
        line: data.lines.get(parameter).map_or(0, |&l| l as usize),
        parameter,
    })
}

/// One line (number `at`); `Ok(false)` at the end of the program. An error comes with the
/// parameter it concerns (0: none).
fn read_line(
    line: &[u8],
    at: usize,
    data_set: i32,
    data: &mut Data,
) -> Result<bool, (Error, usize)> {
    let plain = |e: Error| (e, 0);
    let mut c = Cursor::new(line);
    c.block_number(b'N');
    c.label();
    loop {
        c.spaces();
        match c.peek() {
            None | Some(b';') => return Ok(true),
            Some(b'$') => {
                c.bump();
                let name = c.name();
                let number = name
                    .get(..7)
                    .filter(|p| p.eq_ignore_ascii_case(b"TC_CARR"))
                    .and_then(|_| name.get(7..));
                let Some(digits) = number else {
                    if name
                        .get(..3)
                        .is_some_and(|p| p.eq_ignore_ascii_case(b"TC_"))
                    {
                        // Other tool data of the same archive (tool edges, magazines).
                        return Ok(true);
                    }
                    return Err(plain(Error::UnknownWord));
                };
                if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) {
                    return Err(plain(Error::UnknownWord));
                }
                let n = small(digits).ok_or(plain(Error::UnknownWord))?;
                let mine = assign(&mut c, n, data_set, data).map_err(|e| (e, n))?;
                if let (true, Some(l)) = (mine, data.lines.get_mut(n)) {
                    *l = u32::try_from(at).unwrap_or(u32::MAX);
                }
            }
            Some(_) => {
                let word = c.name();
                if word.eq_ignore_ascii_case(b"CHANDATA") {
                    c.until(b')').ok_or(plain(Error::Parse))?;
                } else if [&b"M17"[..], b"M30", b"M2", b"M02", b"RET"]
                    .iter()
                    .any(|w| w.eq_ignore_ascii_case(word))
                {
                    return Ok(false);
                } else {
                    return Err(plain(Error::UnknownWord));
                }
            }
        }
    }
}

/// A decimal number of 1 to 9 digits (none is no number: `$TC_CARR10[]` names no data set).
fn small(digits: &[u8]) -> Option<usize> {
    if digits.is_empty() || digits.len() > 9 {
        return None;
    }
    Some(
        digits
            .iter()
            .fold(0usize, |v, &d| v * 10 + usize::from(d - b'0')),
    )
}

/// `[index]=value` of parameter `n`; whether it was the data set's own.
fn assign(c: &mut Cursor, n: usize, data_set: i32, data: &mut Data) -> Result<bool, Error> {
    let exists = matches!(n, 1..=46 | 55..=60 | 64 | 65);
    if !exists {
        return Err(Error::UnknownWord);
    }
    if c.peek() != Some(b'[') {
        return Err(Error::Parse);
    }
    c.bump();
    let index = c.until(b']').ok_or(Error::Parse)?;
    let index = small(trim(index)).filter(|_| trim(index).iter().all(u8::is_ascii_digit));
    let index = index.ok_or(Error::Parse)?;
    c.spaces();
    if c.peek() != Some(b'=') {
        return Err(Error::Parse);
    }
    c.bump();
    c.spaces();
    let mine = usize::try_from(data_set).is_ok_and(|d| d == index);
    match n {
        23 | 34 | 35 | 36 => {
            let text = string(c)?;
            if !mine {
                return Ok(false);
            }
            if n == 23 {
                data.kind = match text {
                    [k] => k.to_ascii_uppercase(),
                    _ => return Err(Error::Parse),
                };
            } else if n == 34 {
                if text.len() > MACHINE_NAME_MAX {
                    return Err(Error::NameTooLong);
                }
                if !text.iter().all(|b| (0x20..0x7f).contains(b)) {
                    return Err(Error::Parse);
                }
                data.name = [0; MACHINE_NAME_MAX];
                if let Some(dst) = data.name.get_mut(..text.len()) {
                    dst.copy_from_slice(text);
                }
                data.name_len = text.len();
            }
        }
        21 | 22 => {
            // An axis identifier (`B1`, `"C"`, 0): only its syntax is checked.
            if c.peek() == Some(b'"') {
                string(c)?;
            } else if c.name().is_empty() {
                return Err(Error::Parse);
            }
        }
        _ => {
            let v = c.number(NUMBER).map_err(|e| e.error)?;
            if mine {
                if let Some(slot) = data.values.get_mut(n) {
                    *slot = v;
                }
            }
        }
    }
    if mine {
        data.found = true;
    }
    // The next assignment, a comment or the end must follow.
    match c.peek() {
        None | Some(b' ' | b'\t' | b';') => Ok(mine),
        Some(_) => Err(Error::Parse),
    }
}

fn trim(s: &[u8]) -> &[u8] {
    let start = s.iter().position(|b| *b != b' ').unwrap_or(s.len());
    let end = s.iter().rposition(|b| *b != b' ').map_or(start, |e| e + 1);
    s.get(start..end).unwrap_or(&[])
}

/// A quoted string here, without its quotes.
fn string<'a>(c: &mut Cursor<'a>) -> Result<&'a [u8], Error> {
    if c.peek() != Some(b'"') {
        return Err(Error::Parse);
    }
    c.bump();
    c.until(b'"').ok_or(Error::Parse)
}

/// The parameter of an axis' vector (`first` = 7 or 10) that was assigned last, so that an
/// error about the axis points to a line that gives it.
fn vector_parameter(d: &Data, first: usize) -> usize {
    (first..first + 3)
        .max_by_key(|&k| (d.lines.get(k).copied().unwrap_or(0), usize::MAX - k))
        .unwrap_or(first)
}

/// Of two parameters, the one assigned last (the first of equals): where a pair is at
/// fault together (limits the wrong way round, an offset and its fine offset).
fn later(d: &Data, a: usize, b: usize) -> usize {
    let line = |k: usize| d.lines.get(k).copied().unwrap_or(0);
    if line(b) > line(a) {
        b
    } else {
        a
    }
}

/// The parameter at fault when axis `k` (0 or 1) of a data set is refused: its limits
/// (`$TC_CARR30`–`33`), its Hirth grid (`26`–`29`), its offset (`24`, `25`, fine `64`,
/// `65`) where the axis is accepted without them, else its direction (`7`–`12`; also for
/// an axis parallel to the other). Not inlined: on the error path only.
#[inline(never)]
fn culprit(d: &Data, axis: &RotaryAxis, k: usize) -> usize {
    let ok = |a: RotaryAxis| a.checked().is_ok();
    if ok(*axis) {
        vector_parameter(d, 7 + 3 * k)
    } else if ok(RotaryAxis {
        limits: None,
        ..*axis
    }) {
        later(d, 30 + k, 32 + k)
    } else if ok(RotaryAxis {
        hirth: None,
        ..*axis
    }) {
        later(d, 26 + k, 28 + k)
    } else if ok(RotaryAxis {
        offset: 0.0,
        ..*axis
    }) {
        later(d, 24 + k, 64 + k)
    } else {
        vector_parameter(d, 7 + 3 * k)
    }
}

/// The machine of a data set; an error comes with the parameter at fault.
fn build(d: &Data) -> Result<Machine, (Error, usize)> {
    let v = |k: usize| d.values.get(k).copied().unwrap_or(0.0);
    // A basic parameter plus its fine offset (parameter + 40).
    let with_fine = |k: usize| v(k) + v(k + 40);
    let vec3 = |k: usize| -> Vector { [with_fine(k), with_fine(k + 1), with_fine(k + 2)] };
    let (l1, l2, l3) = (vec3(1), vec3(4), vec3(15));
    let v1 = [v(7), v(8), v(9)];
    let v2 = [v(10), v(11), v(12)];
    let neg = |a: Vector| a.map(|x| -x + 0.0);
    let add = |a: Vector, b: Vector| -> Vector { core::array::from_fn(|k| a[k] + b[k] + 0.0) };
    let (sides, p1, p2) = match d.kind {
        b'T' => ([Side::Tool, Side::Tool], neg(l1), neg(add(l1, l2))),
        b'P' => ([Side::Work, Side::Work], l2, add(l2, l3)),
        b'M' => ([Side::Tool, Side::Work], l2, l3),
        _ => return Err((Error::BadArgument, 23)),
    };
    let present = |a: Vector| a.iter().any(|&x| x != 0.0);
    if present(v2) && !present(v1) {
        return Err((Error::BadArgument, vector_parameter(d, 10)));
    }
    let mut m = Machine::new([0.0, 0.0, 1.0]).map_err(|e| (e, 0))?;
    for (k, (dir, p)) in [(v1, p1), (v2, p2)].into_iter().enumerate() {
        if !present(dir) {
            continue;
        }
        let side = sides.get(k).copied().unwrap_or(Side::Tool);
        let (lo, hi) = (v(30 + k), v(32 + k));
        let step = v(28 + k);
        if step < 0.0 {
            return Err((Error::BadArgument, 28 + k));
        }
        let axis = RotaryAxis {
            offset: with_fine(24 + k),
            limits: (lo != 0.0 || hi != 0.0).then_some([lo, hi]),
            hirth: (step > 0.0).then_some(Hirth {
                offset: v(26 + k),
                step,
            }),
            ..RotaryAxis::new(side, dir, p)
        };
        m.push_axis(axis).map_err(|e| (e, culprit(d, &axis, k)))?;
    }
    m.set_name(d.name.get(..d.name_len).unwrap_or(&[]))
        .map_err(|e| (e, 34))?;
    Ok(m)
}
