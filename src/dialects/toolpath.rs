//! Programs of the five-axis transformation: motion blocks that state the tool tip and the
//! tool's orientation in workpiece coordinates while the control keeps the tip on the path
//! (SINUMERIK `TRAORI`, Heidenhain `M128` / `FUNCTION TCPM`, Fanuc and Syntec `G43.4` /
//! `G43.5`, Haas `G234`), read block by block into CL points: the tip, and the tool
//! direction or the rotary-axis positions the block states. What each dialect writes is in
//! its family file (`PathWords`); this module holds the modal state and the reading that is
//! the same for all.
//!
//! ```
//! use cncrot::dialects::program::Dialect;
//! use cncrot::dialects::toolpath::{Orientation, PathRemark, ToolPath};
//! let (p, _) = ToolPath::default().line(Dialect::Sinumerik, b"TRAORI").unwrap();
//! let (p, r) = p.line(Dialect::Sinumerik, b"N20 G1 X10 Y20 Z5 A3=0 B3=-1 C3=1").unwrap();
//! assert_eq!(r, PathRemark::Point);
//! assert_eq!(p.tip, [10.0, 20.0, 5.0]);
//! // The direction (0, −1, 1) made a unit vector.
//! let Orientation::Direction(d) = p.orientation else { panic!() };
//! assert!((d[1] + 0.5f64.sqrt()).abs() < 1e-15 && (d[2] - 0.5f64.sqrt()).abs() < 1e-15);
//! ```

use super::family::{Direct, DirectAxes, PathCommand, PathWords};
use super::program::{block_of, direct_positions};
use super::registry::Dialect;
use super::sinumerik::{orieuler_vector, orirpy_vector};
use crate::kinematics::{cl_pose, cl_pose_toward, Machine, Rule, Tcp, MAX_AXES, TRAVEL_TOLERANCE};
use crate::text::scan::{code_of, past_closing, LineError};
use crate::Frame;
use crate::{Error, Vector};

/// The tool's orientation a program last stated.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Orientation {
    /// None yet (the rotary axes stay where they are).
    #[default]
    Unstated,
    /// A tool direction (unit vector, workpiece coordinates): `A3 B3 C3`, `A2 B2 C2`,
    /// `TX TY TZ`, `I J K`.
    Direction(Vector),
    /// Rotary-axis positions by letter `A`, `B`, `C` (degrees; letters never stated 0):
    /// the machine gives the direction.
    Axes([f64; 3]),
}

/// The modal state of a five-axis program, as its blocks leave it. The default: the
/// transformation off, the tip at the origin, no orientation stated, absolute coordinates,
/// SINUMERIK's angles as Euler angles (`ORIEULER`, the usual machine data).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ToolPath {
    /// Whether the transformation is on (`TRAORI`, `M128`, `FUNCTION TCPM`, `G43.4`,
    /// `G43.5`, `G234`).
    pub on: bool,
    /// The programmed tip `X Y Z` (mm, workpiece coordinates).
    pub tip: Vector,
    /// The orientation last stated.
    pub orientation: Orientation,
    /// The rotary positions stated by letter so far (`A`, `B`, `C`), kept when a direction
    /// is stated in between.
    pub axes: [f64; 3],
    /// SINUMERIK `ORIRPY` (`A2 B2 C2` as roll, pitch, yaw) rather than `ORIEULER`.
    pub rpy: bool,
    /// ISO `G91`: `X Y Z` and the rotary positions add to the last ones.
    pub incremental: bool,
    /// Heidenhain `FUNCTION TCPM … AXIS SPAT`: the letters `A B C` are spatial angles (the
    /// tool direction `Rz(C)·Ry(B)·Rx(A)·e_z`, as `PLANE SPATIAL`), not axis positions.
    pub spatial: bool,
    /// An arc's mode (`G2`/`G3`; SINUMERIK also `CIP`, `CT`, the splines), in force until
    /// `G0`/`G1`: the motion blocks in it are arcs, not followed.
    pub circular: bool,
    /// An ISO canned cycle's mode (`G73`…`G89`), in force until `G80` or `G0`…`G3`: the
    /// positions in it are holes drilled, not followed.
    pub canned: bool,
    /// The tip is no longer known: a move was not followed (an arc, a reference-point
    /// return, a start-up move, a cycle or subprogram call), and the control's position is
    /// not `tip`: `known` is cleared, and until `X Y Z` are each stated absolutely again,
    /// motion blocks are not followed.
    pub lost: bool,
    /// `X`, `Y`, `Z` each stated absolutely since the program's start (or since the tip was
    /// lost): a motion block with the transformation on is a point only when all three are
    /// (the start position is not assumed to be the origin).
    pub known: [bool; 3],
    /// A tilt or frame the tilted-plane reader reads is active (`G68.2`, `PLANE`,
    /// `CYCLE800`, `ROT`, `TRANS`, `G158`, …, a SINUMERIK frame variable written): the
    /// coordinates are read in a frame this reader does not compose yet, so motion blocks
    /// are not followed until a cancel of it (`G69`, `PLANE RESET`, `CYCLE800()`, `TRANS`).
    pub framed: bool,
    /// A datum shift is active in `X`, `Y`, `Z` (`G52`, `CYCL DEF 7`, `TRANS DATUM`): as
    /// `framed`, until the shift is cancelled in each (`G52 X0 Y0 Z0`, `TRANS DATUM
    /// RESET`; `G52 X0 Y0` keeps a shift in Z).
    pub shifted: [bool; 3],
    /// Cutter radius compensation is on (`G41`/`G42` and their three-dimensional forms,
    /// Heidenhain `RL`/`RR`): the control offsets the tool from the programmed point by a
    /// radius this reader does not know; motion blocks are not followed until `G40` / `R0`.
    pub compensated: bool,
    /// A change of the coordinates or of the orientation's meaning this reader does not
    /// compute (ISO `G68`, `G51`, `G51.1`, `G92`; SINUMERIK `SCALE`, `MIRROR`, `ORIVIRT1/2`,
    /// `TRAORI` with a base orientation, Heidenhain's mirror, rotation and scaling cycles,
    /// `REFPNT` other than the tip): motion blocks are not followed until an ISO `G69`,
    /// `G50`, `G50.1` or `G92.1` \[choice: one mark for all of them\].
    pub altered: bool,
    /// Coordinates in inches (ISO `G20`, SINUMERIK `G70`/`G700`, Heidenhain `BEGIN PGM …
    /// INCH`): `X Y Z` are taken times 25.4, so `tip` stays in mm.
    pub inch: bool,
    /// The orientation is no longer known: a block not followed stated one (or turned the
    /// orientation axes, `ORIRESET`). Motion blocks are not followed until one states an
    /// orientation again.
    pub disoriented: bool,
}

/// What a block did, beside the state it leaves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathRemark {
    /// A motion block with the transformation on: the state's tip and orientation are a CL
    /// point.
    Point,
    /// A block that changes the state without a point (the transformation switched, an
    /// angle mode, a motion block with the transformation off).
    Applied,
    /// A block that concerns neither (the state is the one given, byte for byte).
    Passed,
    /// A move the reader does not follow (an arc, a block in an arc's or a canned cycle's
    /// mode, an expression or incremental function where a number belongs, a move while
    /// the tip is lost, the start-up move of `G43.4`/`G43.5`/`G234`, a frame command's
    /// origin words): the orientation is the one given, the modes the block sets are taken
    /// (the transformation on or off, absolute or incremental, the angle mode, an arc's or
    /// a canned cycle's mode); an ISO or SINUMERIK arc's end point becomes the tip (its
    /// path is not followed); any other move sets [`ToolPath::lost`], the tip as it was.
    NotFollowed,
}

/// One word of a block: its name (`X`, `A3`, `TX`, `TRAORI`, `G`), its value as written
/// (empty for a name alone) and the 1-based column of the name.
#[derive(Clone, Copy)]
struct Word<'a> {
    name: &'a [u8],
    value: &'a [u8],
    column: usize,
    /// SINUMERIK's `IC(…)` (`Some(true)`: the value adds to the last position) and `AC(…)`
    /// (`Some(false)`), whatever `G90`/`G91` say; `None`: as they say.
    incremental: Option<bool>,
}

/// The words of a block, comments, strings and parenthesised arguments skipped. Read
/// again for each question rather than kept in a table (stack bound).
#[derive(Clone)]
struct Words<'a> {
    text: &'a [u8],
    pos: usize,
    iso: bool,
    /// Heidenhain: words stand apart, and a `,` may stand for the point.
    spaced: bool,
    /// SINUMERIK's exponent `EX`.
    ex: bool,
}

impl<'a> Words<'a> {
    fn at(&self, k: usize) -> u8 {
        self.text.get(k).copied().unwrap_or(0)
    }
}

impl<'a> Iterator for Words<'a> {
    type Item = Word<'a>;

    fn next(&mut self) -> Option<Word<'a>> {
        loop {
            let b = self.at(self.pos);
            if self.pos >= self.text.len() || b == b';' {
                return None;
            }
            if b == b'(' || b == b'"' {
                self.pos = past_closing(self.text, self.pos);
                continue;
            }
            // An index (`FGREF[C]=100`, `$AA_IM[Z]`) names an axis, moves none.
            if b == b'[' {
                let rest = self.text.get(self.pos..).unwrap_or(&[]);
                self.pos += rest
                    .iter()
                    .position(|&c| c == b']')
                    .map_or(rest.len(), |k| k + 1);
                continue;
            }
            if !b.is_ascii_alphabetic() && b != b'_' {
                self.pos += 1;
                continue;
            }
            let start = self.pos;
            self.pos += 1;
            if !self.iso {
                while self.at(self.pos).is_ascii_alphabetic() || self.at(self.pos) == b'_' {
                    self.pos += 1;
                }
                // Digits belong to the name when `=` follows them (`A3=`, `C2=`).
                let mut k = self.pos;
                while self.at(k).is_ascii_digit() {
                    k += 1;
                }
                if k > self.pos && self.at(k) == b'=' {
                    self.pos = k;
                }
            }
            let name = self.text.get(start..self.pos).unwrap_or(&[]);
            let mut incremental = None;
            let mut close = false;
            if !self.iso && self.at(self.pos) == b'=' {
                self.pos += 1;
                // SINUMERIK's value functions: `IC(v)` incremental; `AC(v)`, and for rotary
                // axes `DC(v)`, `ACP(v)`, `ACN(v)` (which way the axis turns to it), absolute.
                for (f, inc) in [
                    (&b"IC("[..], true),
                    (b"AC(", false),
                    (b"DC(", false),
                    (b"ACP(", false),
                    (b"ACN(", false),
                ] {
                    let here = self.text.get(self.pos..self.pos + f.len());
                    if here.is_some_and(|h| h.eq_ignore_ascii_case(f)) {
                        self.pos += f.len();
                        incremental = Some(inc);
                        close = true;
                        break;
                    }
                }
            }
            let from = self.pos;
            let mut k = from;
            if matches!(self.at(k), b'+' | b'-') {
                k += 1;
            }
            let mut point = false;
            loop {
                let c = self.at(k);
                if c.is_ascii_digit() {
                    k += 1;
                } else if !point && (c == b'.' || (self.spaced && c == b',')) {
                    point = true;
                    k += 1;
                } else {
                    break;
                }
            }
            // SINUMERIK's exponent: `1.5EX3`, `-.1EX-3`.
            if self.ex
                && self.at(k).eq_ignore_ascii_case(&b'E')
                && self.at(k + 1).eq_ignore_ascii_case(&b'X')
            {
                let mut e = k + 2;
                if matches!(self.at(e), b'+' | b'-') {
                    e += 1;
                }
                let digits = e;
                while self.at(e).is_ascii_digit() {
                    e += 1;
                }
                if e > digits {
                    k = e;
                }
            }
            // A value that is not a plain number (`IC(5)`, `R1`, `Q3`) stays empty here
            // and reads as not followed where a number belongs.
            let has_digits = self
                .text
                .get(from..k)
                .is_some_and(|v| v.iter().any(u8::is_ascii_digit));
            // A function's argument must be the whole of it: `IC(5)`, not `IC(5+R1)`; and a
            // number must not go on as an expression (`X=10*R2`, `X10-R1`), nor as what this
            // reader does not read (a second point `1,5.2`, `1_000`, an exponent `1e7`, a
            // letter glued to it where words stand apart): never the digits before it.
            let c = self.at(k);
            let goes_on = matches!(c, b'.' | b',' | b'_')
                || c.is_ascii_digit()
                || (c.is_ascii_alphabetic()
                    && (self.spaced || (!self.iso && c.eq_ignore_ascii_case(&b'E'))));
            // SINUMERIK: a name with a numeric extension is followed by `=` (`A3=0.5`); `A3
            // =0.5` is no axis A at 3 but the control's alarm ("a numeric extension must
            // always be followed by one of the special characters =, (, [ …", its
            // programming manual).
            let mut after = k;
            while self.at(after) == b' ' || self.at(after) == b'\t' {
                after += 1;
            }
            let extension = self.ex && after > k && self.at(after) == b'=';
            let closed = if close {
                c == b')'
            } else {
                !matches!(c, b'*' | b'/' | b'+' | b'-') && !goes_on && !extension
            };
            let value = if has_digits && closed {
                self.pos = if close { k + 1 } else { k };
                self.text.get(from..k).unwrap_or(&[])
            } else {
                &[]
            };
            return Some(Word {
                name,
                value,
                column: start + 1,
                incremental,
            });
        }
    }
}

/// The number of a word's value (correctly rounded, by the program readers' own reader),
/// or `None` for a word without one or a value that is not a number (`1.2.3`).
fn number(w: &Word) -> Option<f64> {
    let (negative, digits) = match w.value {
        [b'-', rest @ ..] => (true, rest),
        [b'+', rest @ ..] => (false, rest),
        v => (false, v),
    };
    // SINUMERIK's `EX` (the tokenizer takes it only there, with its digits).
    let (digits, exp10) = match digits.iter().position(|b| b.eq_ignore_ascii_case(&b'E')) {
        Some(at) => {
            let e = digits.get(at + 2..)?;
            let (neg, e) = match e {
                [b'-', rest @ ..] => (true, rest),
                [b'+', rest @ ..] => (false, rest),
                e => (false, e),
            };
            let mut v: i32 = 0;
            for &d in e {
                v = v
                    .checked_mul(10)?
                    .checked_add(i32::from(d.wrapping_sub(b'0')))?;
            }
            (digits.get(..at)?, if neg { -v } else { v })
        }
        None => (digits, 0),
    };
    crate::text::number::parse(negative, digits, exp10).ok()
}

fn same(a: &[u8], b: &[u8]) -> bool {
    a.eq_ignore_ascii_case(b)
}

/// Whether word `w`, followed by the words of `rest`, is the command `c`.
fn is_command(w: &Word, rest: &Words, c: &PathCommand) -> bool {
    let plain = |w: &Word, name: &[u8]| same(w.name, name) && w.value.is_empty();
    match c {
        PathCommand::Code(letter, tenths) => {
            w.name.len() == 1
                && w.name.eq_ignore_ascii_case(&[*letter])
                && code_of(w.value) == Some(*tenths)
        }
        PathCommand::Name(name) => plain(w, name),
        PathCommand::Phrase(names) => {
            let mut after = rest.clone();
            names.split_first().is_some_and(|(first, others)| {
                plain(w, first)
                    && others
                        .iter()
                        .all(|n| after.next().is_some_and(|x| plain(&x, n)))
            })
        }
    }
}

/// Whether the tilted-plane reader of `dialect` reads `text` as a block that tilts or
/// shifts the frame (`CYCLE800`, `CROT`, `PLANE`, cycle 19, cycle 7's axis lines, `G68.2`,
/// `G52`: a tilt or datum shift active after it, read from no tilt; a SINUMERIK frame
/// variable written). A cancel is not one:
/// the reader's frame is the one without. A block the tilted-plane reader refuses or
/// does not follow is left to the lists of [`PathWords`] (a work-offset selection such as
/// `G54`, which states the frame the program's coordinates are in, is passed over). Not
/// inlined: its frame is gone when the block's words are read (stack bound).
#[inline(never)]
fn frame_block(dialect: Dialect, text: &[u8]) -> FrameBlock {
    use super::program::{Program, Remark};
    let both = Kinds {
        tilt: true,
        shift: [true; 3],
    };
    match Program::default().line(dialect, text) {
        Ok((next, Remark::Applied)) if next.is_active() => {
            let shift = next.shift.map(|x| x != 0.0);
            // A rotation, a direct mode, or an origin beyond the shift (a tilt's, or
            // SINUMERIK's `TRANS`, which is its one frame).
            let tilt = next.frame.rotation != crate::IDENTITY
                || next.direct.is_some()
                || next.frame.translation != next.shift;
            FrameBlock::Tilt(Kinds {
                tilt: tilt || shift == [false; 3],
                shift,
            })
        }
        // A cancel, or a frame command whose words leave nothing active (`G158 P10157` of
        // zeros, `G269 X0 Y0 Z0`): its coordinates are the command's, not a move.
        Ok((_, Remark::Applied)) => FrameBlock::Cancel,
        // A SINUMERIK frame variable written (`$P_PFRAME=CROT(Z,90)`, `$P_UIFR[1]=…`).
        Ok((_, Remark::NotFollowed)) if text.windows(3).any(|w| w.eq_ignore_ascii_case(b"$P_")) => {
            FrameBlock::Tilt(both)
        }
        // A frame command the tilted-plane reader refuses (`G268` without its `Q`): the
        // control's alarm, not a move.
        Err(e) if e.error != Error::LineTooLong => FrameBlock::Tilt(both),
        _ => FrameBlock::None,
    }
}

/// What a block that leaves nothing active cancels, as the tilted-plane reader reads it
/// after a tilt (`G69` ends a tilt, not a `G52` shift) and after the datum shift in the
/// axes `shifted` (`G52 X0 Y0 Z0` ends the shift, not the tilt; `G52 X0 Y0` its X and Y);
/// SINUMERIK's `TRANS`, `ROT` end its one frame. Not inlined: its two states are not on the
/// stack of the block's words (stack bound).
#[inline(never)]
fn cancels(dialect: Dialect, text: &[u8], shifted: [bool; 3]) -> Kinds {
    use super::program::Program;
    let tilted = Program {
        frame: Frame {
            rotation: crate::elementary(crate::Axis::X, 30.0),
            translation: [0.0; 3],
        },
        dialect: Some(dialect),
        ..Program::default()
    };
    let tilt = tilted.line(dialect, text).is_ok_and(|(n, _)| {
        n.frame.rotation == crate::IDENTITY && n.direct.is_none() && n.frame.translation == n.shift
    });
    let shifted = Program {
        // In the axes shifted: `G52 X0 Y0` ends the shift in X and Y, not in Z.
        frame: Frame {
            rotation: crate::IDENTITY,
            translation: shifted.map(f64::from),
        },
        shift: shifted.map(f64::from),
        dialect: Some(dialect),
        ..Program::default()
    };
    let shift = shifted
        .line(dialect, text)
        .map_or([false; 3], |(n, _)| n.shift.map(|x| x == 0.0));
    Kinds { tilt, shift }
}

/// Whether block `text` has a word of the tip or the orientation (`X`, `A3`, `I`, …).
fn coordinates(pw: &PathWords, dialect: Dialect, text: &[u8]) -> bool {
    let Ok(text) = block_of(dialect, text) else {
        return false;
    };
    let words = Words {
        text,
        pos: 0,
        iso: pw.iso,
        spaced: pw.spaced,
        ex: pw.ex,
    };
    words.into_iter().any(|w| {
        let name = match w.name {
            [b'I' | b'i', rest @ ..] if pw.i_prefix && rest.len() == 1 => rest,
            n => n,
        };
        let one =
            |set: &[u8]| name.len() == 1 && set.iter().any(|l| name.eq_ignore_ascii_case(&[*l]));
        one(b"XYZABC")
            || pw.vector.iter().any(|v| same(name, v))
            || pw.angles.is_some_and(|a| a.iter().any(|v| same(name, v)))
    })
}

/// Whether `text` switches the transformation on with a base orientation of the tool
/// (SINUMERIK `TRAORI(1, 0, 1, 0)`: more than the transformation's number) or a reference
/// point other than the tip (Heidenhain `REFPNT CENTER-CENTER`, `TIP-CENTER`): the
/// orientation or the point the reader would compute is another.
fn altering_text(text: &[u8]) -> bool {
    let find = |word: &[u8]| {
        text.windows(word.len())
            .position(|w| w.eq_ignore_ascii_case(word))
            .map(|at| text.get(at + word.len()..).unwrap_or(&[]))
    };
    let based = find(b"TRAORI(")
        .is_some_and(|rest| rest.iter().take_while(|&&c| c != b')').any(|&c| c == b','));
    let centre = find(b"REFPNT").is_some_and(|rest| {
        let rest = rest.trim_ascii_start();
        !rest
            .get(..7)
            .is_some_and(|w| w.eq_ignore_ascii_case(b"TIP-TIP"))
    });
    based || centre
}

/// What the tilted-plane reader makes of a block ([`frame_block`]).
#[derive(Clone, Copy, PartialEq, Eq)]
enum FrameBlock {
    /// A tilt or shift (which of them it makes active), or a frame command refused (both).
    Tilt(Kinds),
    /// A frame command that leaves nothing active (what it ends depends on what is
    /// active: [`cancels`]).
    Cancel,
    /// No frame command.
    None,
}

/// A tilt (a rotation, a tilt's origin, SINUMERIK's frame), a datum shift in `X`, `Y`,
/// `Z`.
#[derive(Clone, Copy, PartialEq, Eq)]
struct Kinds {
    tilt: bool,
    shift: [bool; 3],
}

impl ToolPath {
    /// The state after block `text` of a program in `dialect`, and what the block did. A
    /// refused block leaves the caller's state as it was: [`Error::NotAvailable`] for a
    /// dialect whose five-axis programs are not read (TwinCAT), [`Error::LineTooLong`],
    /// [`Error::BadArgument`] (a zero tool direction, a direction and rotary positions in
    /// one block), [`Error::OutOfRange`] (a position that overflows), with the column.
    pub fn line(&self, dialect: Dialect, text: &[u8]) -> Result<(ToolPath, PathRemark), LineError> {
        let Some(pw) = dialect.tool_path() else {
            return Err(LineError {
                error: Error::NotAvailable,
                column: 1,
                expected: None,
            });
        };
        if dialect == Dialect::Heidenhain {
            if let Some(read) = self.heidenhain_header(text) {
                return Ok(read);
            }
        }
        // A block that tilts or shifts the frame: the coordinates after it are read in a
        // frame this reader does not follow.
        match frame_block(dialect, text) {
            // The coordinates after it are another frame's: the tip in them is not known.
            FrameBlock::Tilt(k) => {
                let next = ToolPath {
                    framed: self.framed || k.tilt,
                    shifted: core::array::from_fn(|i| self.shifted[i] || k.shift[i]),
                    lost: true,
                    known: [false; 3],
                    ..*self
                };
                Ok((next, PathRemark::NotFollowed))
            }
            FrameBlock::Cancel => self.cancel(pw, dialect, text),
            FrameBlock::None => self.read(pw, dialect, text),
        }
    }

    /// Heidenhain's structure comments (`* - TOOL 1/4 INCH BALL`: no word of them is a
    /// command) and program heads (`BEGIN PGM C MM`: the unit, the program's name no
    /// word): what they do, or `None` for another block.
    #[inline(never)]
    fn heidenhain_header(&self, text: &[u8]) -> Option<(ToolPath, PathRemark)> {
        let t = text.trim_ascii_start();
        let t = t
            .get(t.iter().take_while(|c| c.is_ascii_digit()).count()..)
            .unwrap_or(&[])
            .trim_ascii_start();
        if t.first() == Some(&b'*') {
            return Some((*self, PathRemark::Passed));
        }
        let head = t
            .get(..9)
            .is_some_and(|h| h.eq_ignore_ascii_case(b"BEGIN PGM"));
        if !head {
            return None;
        }
        let last = t
            .trim_ascii_end()
            .rsplit(|c| *c == b' ')
            .next()
            .unwrap_or(&[]);
        let inch = last.eq_ignore_ascii_case(b"INCH");
        let next = ToolPath { inch, ..*self };
        let remark = if next == *self {
            PathRemark::Passed
        } else {
            PathRemark::Applied
        };
        Some((next, remark))
    }

    /// [`ToolPath::line`] for a frame command that leaves nothing active: its modes taken,
    /// its coordinates no move. Not inlined: its frame is not on top of the tilted-plane
    /// reader's (stack bound).
    #[inline(never)]
    fn cancel(
        &self,
        pw: &PathWords,
        dialect: Dialect,
        text: &[u8],
    ) -> Result<(ToolPath, PathRemark), LineError> {
        let ends = cancels(dialect, text, self.shifted);
        let (mut next, mut remark) = self.read(pw, dialect, text)?;
        let framed = self.framed && !ends.tilt;
        let shifted: [bool; 3] = core::array::from_fn(|i| self.shifted[i] && !ends.shift[i]);
        // The coordinates after an end of a frame are read without it: the tip in them
        // is not known.
        let ended = (framed, shifted) != (self.framed, self.shifted);
        if coordinates(pw, dialect, text) {
            next = ToolPath {
                tip: self.tip,
                orientation: self.orientation,
                axes: self.axes,
                lost: self.lost,
                known: self.known,
                ..next
            };
            remark = PathRemark::NotFollowed;
        }
        if ended {
            (next.lost, next.known) = (true, [false; 3]);
        }
        (next.framed, next.shifted) = (framed, shifted);
        // SINUMERIK's `TRANS`, `ROT` without values delete the whole programmable frame,
        // its scaling and mirroring (and `TOFRAME`'s rotation) with it.
        if ends.tilt && dialect == Dialect::Sinumerik && next.altered {
            (next.altered, next.lost, next.known) = (false, true, [false; 3]);
        }
        if ended && remark == PathRemark::Passed {
            remark = PathRemark::Applied;
        }
        Ok((next, remark))
    }

    /// [`ToolPath::line`] for a block that is no tilt or shift: its words. Not inlined:
    /// its frame and the tilted-plane reader's are on the stack one after the other, not
    /// one over the other (stack bound).
    #[inline(never)]
    fn read(
        &self,
        pw: &PathWords,
        dialect: Dialect,
        text: &[u8],
    ) -> Result<(ToolPath, PathRemark), LineError> {
        let text = block_of(dialect, text)?;
        let mut words = Words {
            text,
            pos: 0,
            iso: pw.iso,
            spaced: pw.spaced,
            ex: pw.ex,
        };
        // A leading block number `N10` (Heidenhain's bare digits are no word).
        let mut peek = words.clone();
        if peek
            .next()
            .is_some_and(|w| w.name.eq_ignore_ascii_case(b"N") && !w.value.is_empty())
        {
            words = peek;
        }
        let (mut next, mut remark) = self.apply(pw, words)?;
        if altering_text(text) && !next.altered {
            (next.altered, next.lost, next.known) = (true, true, [false; 3]);
            remark = PathRemark::NotFollowed;
        }
        Ok((next, remark))
    }

    /// The machine's axes for the state's CL point (the tip with the tool of length
    /// `tool_length`, mm, on `machine`), continuous with `previous` (`X, Y, Z`, then the
    /// rotary positions, as [`Machine::tcp_inverse`] takes them): for a tool direction the
    /// rotary solution `rule` picks; for rotary positions stated by letter, those positions
    /// (each machine axis takes the letter its direction is nearest: A for X, B for Y, C for
    /// Z \[choice\]); with no orientation stated, the rotary axes where they were. The
    /// linear axes put the tip on the point. Errors: those of [`Machine::tcp_inverse`],
    /// [`Error::BadArgument`] (a nonzero position for a letter the machine lacks).
    ///
    /// ```
    /// use cncrot::dialects::program::Dialect;
    /// use cncrot::dialects::toolpath::ToolPath;
    /// use cncrot::kinematics::{Machine, RotaryAxis, Rule, Side};
    /// // An AC table: A about X through (0, 0, 100), C on it.
    /// let m = Machine::new([0.0, 0.0, 1.0]).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0])).unwrap()
    ///     .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3])).unwrap();
    /// let (p, _) = ToolPath::default().line(Dialect::Fanuc, b"G43.4 H1").unwrap();
    /// let (p, _) = p.line(Dialect::Fanuc, b"G1 X10. Y0. Z0. A30. C90.").unwrap();
    /// let t = p.machine_axes(&m, 50.0, [0.0; 6], Rule::Closest).unwrap();
    /// // The worked example of docs/kinematics.md: Y = 50 + 5·√3, Z = 155 − 50·√3.
    /// let s3 = 3f64.sqrt();
    /// let want = [0.0, 50.0 + 5.0 * s3, 155.0 - 50.0 * s3, 30.0, 90.0, 0.0];
    /// assert!(t.axes.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-9));
    /// ```
    pub fn machine_axes(
        &self,
        machine: &Machine,
        tool_length: f64,
        previous: [f64; 6],
        rule: Rule,
    ) -> Result<Tcp, Error> {
        let (pose, previous, rule) = self.pose_on(machine, previous, rule)?;
        let mut t = machine.tcp_inverse_with(&pose, tool_length, previous, rule)?;
        if let Orientation::Axes(_) = self.orientation {
            // The stated positions themselves, not their round trip through the pose (a
            // `B10.` read back as 10.000000000000002, and drifting further where a caller
            // writes the positions back into the state's letters).
            for (x, &p) in t.axes.iter_mut().zip(&previous).skip(3) {
                if crate::math::abs(*x - p) < 1e-9 {
                    *x = p;
                }
            }
        }
        Ok(t)
    }

    /// The pose [`ToolPath::machine_axes`] inverts, with the start and the rule it inverts
    /// from. Not inlined: its temporaries are gone when the transformation runs (stack
    /// bound).
    #[inline(never)]
    fn pose_on(
        &self,
        machine: &Machine,
        previous: [f64; 6],
        rule: Rule,
    ) -> Result<(Frame, [f64; 6], Rule), Error> {
        let [_, _, _, r1, r2, r3] = previous;
        let (rotation, previous, rule) = match self.orientation {
            // Three rotary axes make the turn about the tool too: the one carried from
            // where the machine stands, so that a path does not jump where `cl_pose`
            // changes its X'.
            Orientation::Direction(d) if machine.axis_count() == MAX_AXES => {
                let before = machine.forward([r1, r2, r3])?.rotation;
                (
                    cl_pose_toward(self.tip, d, &before)?.rotation,
                    previous,
                    rule,
                )
            }
            Orientation::Direction(d) => (cl_pose(self.tip, d)?.rotation, previous, rule),
            Orientation::Axes(stated) => {
                let by = Direct {
                    by: DirectAxes::Letters,
                    given: 7,
                };
                let at = direct_positions(&by, stated, machine)?;
                // Positions stated beyond the travel are the control's alarm, not a cue to
                // take the other solution of the same orientation.
                for (a, &p) in machine.stored().iter().zip(&at) {
                    if let Some([lo, hi]) = a.limits() {
                        // Written so that NaN refuses.
                        if !(p >= lo - TRAVEL_TOLERANCE && p <= hi + TRAVEL_TOLERANCE) {
                            return Err(Error::OutOfTravel);
                        }
                    }
                }
                let [x, y, z, ..] = previous;
                let f = machine.forward(at)?;
                // From the stated positions themselves: the closest solution is they.
                (f.rotation, [x, y, z, at[0], at[1], at[2]], Rule::Closest)
            }
            Orientation::Unstated => (
                machine.forward([r1, r2, r3])?.rotation,
                previous,
                Rule::Closest,
            ),
        };
        let pose = Frame {
            rotation,
            translation: self.tip,
        };
        Ok((pose, previous, rule))
    }

    fn apply(&self, pw: &PathWords, words: Words) -> Result<(ToolPath, PathRemark), LineError> {
        let mut next = *self;
        let mut changed = false;
        // Commands first: the transformation, the angle mode, absolute or incremental.
        // The last of each kind counts (`G91 … G90`).
        // In the same pass: whether the block is an arc or another move not followed.
        let mut arc = false;
        let (mut still, mut off_after, mut loses) = (false, false, false);
        let mut it = words.clone();
        while let Some(w) = it.next() {
            let hit = |list: &[PathCommand]| list.iter().any(|c| is_command(&w, &it, c));
            arc |= hit(pw.arcs);
            still |= hit(pw.still);
            // A call: ISO `M98`, SINUMERIK's cycles (`CYCLE81(…)`; not `CYCLE832`, which
            // sets tolerances, nor the swivel cycles the tilted-plane reader reads) and
            // subprograms by number (`L123`).
            let cycle = |v: &[u8]| !v.is_empty() && ![&b"832"[..], b"800", b"600"].contains(&v);
            let call = (same(w.name, b"CYCLE") && cycle(w.value))
                || (!pw.iso
                    && same(w.name, b"L")
                    && w.value.first().is_some_and(u8::is_ascii_digit));
            loses |= call || hit(pw.loses);
            if hit(pw.compensation) {
                next.compensated = true;
            } else if hit(pw.compensation_off) {
                next.compensated = false;
            }
            // SINUMERIK's other angle definitions (`ORIVIRT1`, `ORIVIRT2`, `ORIRPY2`: the
            // name and a number, as the words split).
            let angles_defined = (same(w.name, b"ORIVIRT") && !w.value.is_empty())
                || (same(w.name, b"ORIRPY") && w.value == b"2");
            // Heidenhain's rotation and scaling cycles ended (`CYCL DEF 10.1 ROT+0`,
            // `CYCL DEF 11.1 SCL1`).
            let ended = pw.i_prefix
                && ((same(w.name, b"ROT") && number(&w) == Some(0.0))
                    || (same(w.name, b"SCL") && number(&w) == Some(1.0)));
            if hit(pw.altering) || angles_defined {
                // SINUMERIK's `SCALE` or `MIRROR` alone ends them (and the whole frame).
                let alone = it.clone().next().is_none()
                    && (same(w.name, b"SCALE") || same(w.name, b"MIRROR"));
                next.altered = !alone;
            } else if hit(pw.unaltering) || ended {
                next.altered = false;
            }
            // Another work offset: the coordinates after it are another frame's (the
            // block's own, stated, are known again).
            let g = same(w.name, b"G").then(|| code_of(w.value)).flatten();
            let offset = g.is_some_and(|c| {
                if pw.iso {
                    (540..=590).contains(&c) && c % 10 == 0 || c == 541
                } else {
                    (540..=570).contains(&c) && c % 10 == 0 || (5000..=5990).contains(&c)
                }
            }) || hit(pw.offsets);
            if offset {
                next.known = [false; 3];
            }
            if hit(pw.inch) {
                next.inch = true;
            } else if hit(pw.metric) {
                next.inch = false;
            }
            // The modes of motion, the last word of each group counting; a straight or
            // circular move ends a canned cycle (ISO group 01 over group 09).
            if hit(pw.circular) {
                (next.circular, next.canned) = (true, false);
            } else if hit(pw.linear) {
                (next.circular, next.canned) = (false, false);
            } else if hit(pw.canned) {
                next.canned = true;
            } else if hit(pw.canned_off) {
                next.canned = false;
            }
            if hit(pw.off_after) {
                off_after = true;
            } else if hit(pw.on) {
                (next.on, next.spatial) = (true, false);
            } else if hit(pw.off) {
                (next.on, next.spatial) = (false, false);
            } else if hit(pw.spatial) {
                next.spatial = true;
            } else if hit(pw.positions) {
                next.spatial = false;
            } else if hit(pw.rpy) {
                next.rpy = true;
            } else if hit(pw.euler) {
                next.rpy = false;
            } else if hit(pw.incremental) {
                next.incremental = true;
            } else if hit(pw.absolute) {
                next.incremental = false;
            } else {
                continue;
            }
            changed = true;
        }
        // Switched on or off: the coordinates are the workpiece's or the machine's; the
        // block's own, stated, are known again.
        if next.on != self.on {
            next.known = [false; 3];
        }
        // A block that is not a straight move: an arc, or a block whose first word the
        // dialect does not move with (Heidenhain's `L`/`LN`).
        let first = words.clone().next();
        let moves =
            pw.moves.is_empty() || first.is_some_and(|w| pw.moves.iter().any(|m| same(w.name, m)));
        // The motion words: tip, rotary positions (absolute, or Heidenhain's `I` prefix),
        // direction, angles.
        let mut tip = [None; 3];
        let mut tip_inc = [false; 3];
        let mut axes = [None; 3];
        let mut axes_inc = [false; 3];
        let mut vector = [None; 3];
        let mut angles = [None; 3];
        let mut first_column = 0;
        let (mut unreadable, mut unread) = (false, false);
        let lead = words.clone().next().map(|w| w.column);
        for w in words {
            let (name, prefixed) = match w.name {
                [b'I' | b'i', rest @ ..] if pw.i_prefix && rest.len() == 1 => (rest, true),
                _ => (w.name, false),
            };
            // An explicit `AC`/`IC` decides; else the `I` prefix or the modal G91.
            let inc = w.incremental.unwrap_or(prefixed || next.incremental);
            let letter = |set: &[u8; 3]| {
                set.iter()
                    .position(|l| name.len() == 1 && name.eq_ignore_ascii_case(&[*l]))
            };
            let named = |set: &[&[u8]; 3]| set.iter().position(|s| same(name, s));
            if pw.unread.iter().any(|u| same(name, u)) {
                // Lead and tilt angles, normals: an orientation not computed here.
                (unreadable, unread) = (true, true);
                if first_column == 0 {
                    first_column = w.column;
                }
                continue;
            }
            let slot = if let Some(k) = letter(b"XYZ") {
                if let Some(i) = tip_inc.get_mut(k) {
                    *i = inc;
                }
                tip.get_mut(k)
            } else if let Some(k) = letter(b"ABC").filter(|_| !pw.vector.contains(&name)) {
                if let Some(i) = axes_inc.get_mut(k) {
                    *i = inc;
                }
                axes.get_mut(k)
            } else if let Some(k) = named(&pw.vector).filter(|_| !prefixed) {
                vector.get_mut(k)
            } else if let Some(k) = pw.angles.and_then(|a| named(&a)).filter(|_| !prefixed) {
                angles.get_mut(k)
            } else {
                None
            };
            if let Some(slot) = slot {
                if first_column == 0 {
                    first_column = w.column;
                }
                // A word twice (`X1 X2`) is the control's alarm, not a value to pick.
                // Inches made millimetres (only the tip's words: a direction has no unit).
                let unit = if next.inch && letter(b"XYZ").is_some() {
                    25.4
                } else {
                    1.0
                };
                match number(&w) {
                    Some(v) if v.is_finite() && slot.is_none() => {
                        *slot = Some((v * unit, w.column));
                    }
                    // A rotary position or a direction not read (`C=R1`, `C#100`, `C+Q1`):
                    // the orientation after it is not known either (Heidenhain's circle
                    // `C X+5 Y+0`, whose first word is its command, is no axis C).
                    _ => {
                        let command = !pw.moves.is_empty() && Some(w.column) == lead;
                        unread |= letter(b"XYZ").is_none() && !command;
                        unreadable = true;
                    }
                }
            }
        }
        // Switched off at the end of the block: a move on it is still a point.
        let off = |mut p: ToolPath| {
            if off_after {
                (p.on, p.spatial) = (false, false);
            }
            p
        };
        changed |= (next.circular, next.canned) != (self.circular, self.canned)
            || (next.compensated, next.altered, next.inch, next.known)
                != (self.compensated, self.altered, self.inch, self.known);
        // An orientation stated (or turned, `ORIRESET`) by a block not followed is no
        // longer known.
        // (An ISO arc's or hole's `I J K` are its centre or shift, not the tool's.)
        let centre = pw.iso && (arc || next.circular || next.canned);
        let vectored = vector.iter().any(Option::is_some) && !centre;
        let lettered = axes.iter().any(Option::is_some);
        // Rotary positions by letter are where the axes go, followed or not; a direction or
        // angles (and Heidenhain's spatial letters) in a block not followed are lost.
        let oriented = unread
            || angles.iter().any(Option::is_some)
            || vectored
            || (lettered && next.spatial)
            || (loses && same(first.map_or(&[][..], |w| w.name), b"ORIRESET"));
        // Not followed: the modes taken (and the rotary positions stated), the tip lost
        // where the block moves.
        let mut moded = off(next);
        if lettered && !oriented {
            for ((a, v), inc) in moded.axes.iter_mut().zip(axes).zip(axes_inc) {
                if let Some((v, _)) = v {
                    *a = if inc { *a + v } else { v };
                }
            }
            if moded.axes.iter().all(|x| x.is_finite()) {
                moded.orientation = Orientation::Axes(moded.axes);
            } else {
                moded = off(next);
            }
        }
        let lost = ToolPath {
            lost: true,
            known: [false; 3],
            disoriented: next.disoriented || oriented,
            ..moded
        };
        // A call, or a change of the frame not computed: the coordinates after it are read
        // elsewhere (or the control is elsewhere).
        if loses || (next.altered && !self.altered) {
            return Ok((lost, PathRemark::NotFollowed));
        }
        let unchanged = if changed || (off_after && self.on) {
            (off(next), PathRemark::Applied)
        } else {
            (*self, PathRemark::Passed)
        };
        if arc {
            // Nothing of the block is taken but its modes: its end point, or the frame after
            // it, is not known here (with or without coordinates: `LP PR+10 PA+30`, `TRANS`).
            let moved = first_column != 0 && moves;
            return Ok((if moved { lost } else { moded }, PathRemark::NotFollowed));
        }
        if first_column == 0 || still {
            return Ok(unchanged);
        }
        // Coordinates in a frame, or with an offset, this reader does not compute: the
        // block is not followed, and the tip is not known after it.
        let geometry =
            next.framed || next.shifted.contains(&true) || next.compensated || next.altered;
        // The start-up block of an ISO transformation (`G43.4 H1 X… Y… Z…`): its move is made
        // with the tool length only, not under the transformation [doc: Fanuc's tool centre
        // point control, "movement to the position specified by the G43.4 block (startup)
        // does not constitute tool center point control"].
        let startup = pw.iso && next.on && !self.on;
        // Each coordinate known after the block: known before, or stated absolutely in it.
        // (From the modes' state: a work offset or the transformation switched forgets them.)
        let mut known = next.known;
        for ((k, t), inc) in known.iter_mut().zip(tip).zip(tip_inc) {
            *k |= t.is_some() && !inc;
        }
        // While the tip is lost, or with the transformation on, a block after which some
        // coordinate is still not known: the control's position is not the state's.
        let whole = known.iter().all(|&k| k);
        let stated = vector
            .iter()
            .chain(&angles)
            .chain(&axes)
            .any(Option::is_some);
        let blocked =
            unreadable || next.canned || startup || geometry || (self.disoriented && !stated);
        if (blocked || next.circular) && moves {
            if next.circular && !blocked {
                // An arc's end point is programmed (and a helix's Z): taken, its path not
                // followed; the tip known again where the block states it whole.
                let mut end = moded;
                for ((t, v), inc) in end.tip.iter_mut().zip(tip).zip(tip_inc) {
                    if let Some((v, _)) = v {
                        *t = if inc { *t + v } else { v };
                    }
                }
                (end.lost, end.known) = (self.lost && !whole, known);
                end.disoriented = self.disoriented || oriented;
                if !end.tip.iter().all(|x| x.is_finite()) {
                    return Err(LineError {
                        error: Error::OutOfRange,
                        column: first_column,
                        expected: None,
                    });
                }
                return Ok((end, PathRemark::NotFollowed));
            }
            // Nothing of the block is taken but its modes: its end point is not known here
            // (a hole's, a number not read, a start-up move, a move from a position not
            // known).
            return Ok((lost, PathRemark::NotFollowed));
        }
        if !moves {
            // Words of a block that does not move (Heidenhain's `TOOL CALL 1 Z`, `CC X Y`).
            return Ok(unchanged);
        }
        let given_vector = vector.iter().chain(&angles).find_map(|v| *v);
        let given_axes = axes.iter().find_map(|v| *v);
        if let (Some(_), Some((_, column))) = (given_vector, given_axes) {
            return Err(LineError {
                error: Error::BadArgument,
                column,
                expected: None,
            });
        }
        for k in 0..3 {
            if let (Some(t), Some(&(v, _))) =
                (next.tip.get_mut(k), tip.get(k).and_then(|v| v.as_ref()))
            {
                // An increment to a coordinate not known leaves it not known (and as it was).
                let inc = tip_inc.get(k).copied().unwrap_or(false);
                if !inc {
                    *t = v;
                } else if next.known.get(k).copied().unwrap_or(false) {
                    *t += v;
                }
            }
            if let (Some(a), Some(&(v, _))) =
                (next.axes.get_mut(k), axes.get(k).and_then(|v| v.as_ref()))
            {
                let inc = axes_inc.get(k).copied().unwrap_or(false);
                *a = if inc { *a + v } else { v };
            }
        }
        if given_axes.is_some() {
            next.orientation = if next.spatial {
                Orientation::Direction(orirpy_vector(next.axes))
            } else {
                Orientation::Axes(next.axes)
            };
        }
        if let Some((_, column)) = vector.iter().find_map(|v| *v) {
            // Components not written are 0 [choice].
            let v = vector.map(|c| c.map_or(0.0, |(x, _)| x));
            let d = crate::unit_vector(v).map_err(|_| LineError {
                error: Error::BadArgument,
                column,
                expected: None,
            })?;
            next.orientation = Orientation::Direction(d);
        } else if angles.iter().any(Option::is_some) {
            let [a, b, c] = angles.map(|x| x.map_or(0.0, |(v, _)| v));
            let d = if next.rpy {
                orirpy_vector([a, b, c])
            } else {
                orieuler_vector([a, b])
            };
            next.orientation = Orientation::Direction(d);
        }
        (next.lost, next.disoriented, next.known) = (self.lost && !whole, false, known);
        let all_finite = next.tip.iter().chain(&next.axes).all(|x| x.is_finite());
        if !all_finite {
            return Err(LineError {
                error: Error::OutOfRange,
                column: first_column,
                expected: None,
            });
        }
        // Words taken, but no point while a coordinate is not known (the tip lost, or not
        // yet stated since the start): the control's position is not the state's.
        let remark = if (self.lost || next.on) && !whole {
            PathRemark::NotFollowed
        } else if next.on {
            PathRemark::Point
        } else {
            PathRemark::Applied
        };
        Ok((off(next), remark))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn direction_near(o: Orientation, want: Vector) -> bool {
        matches!(o, Orientation::Direction(d) if d.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-15))
    }

    fn run(d: Dialect, lines: &[&str]) -> Vec<(ToolPath, PathRemark)> {
        let mut p = ToolPath::default();
        lines
            .iter()
            .map(|l| {
                let (n, r) = p.line(d, l.as_bytes()).unwrap();
                p = n;
                (n, r)
            })
            .collect()
    }

    #[test]
    fn sinumerik_vectors_angles_and_axes() {
        let s = 0.5f64.sqrt();
        let out = run(
            Dialect::Sinumerik,
            &[
                "N10 G1 X0 Y0 Z50",
                "N20 TRAORI(1)",
                // The transformation switched on: X, Y, Z stated again.
                "N30 X10 Y0 Z50 A3=0 B3=-1 C3=1",
                "N40 Y20",
                "N50 ORIRPY",
                // Roll 90° about X turns +Z onto −Y.
                "N60 A2=90 B2=0 C2=0",
                "N70 ORIEULER",
                // Euler: A2 about Z, then B2 about the new X: Rz(90)·Rx(90)·e_z = (1, 0, 0).
                "N80 A2=90 B2=90",
                "N90 A=30 C=-45.5",
                "N100 G2 X5 Y5 CR=5",
                "N110 X=IC(5+R1)",
                "N120 TRAFOOF",
                "; a comment",
            ],
        );
        let r: Vec<_> = out.iter().map(|o| o.1).collect();
        use PathRemark::*;
        assert_eq!(
            r,
            [
                Applied,
                Applied,
                Point,
                Point,
                Applied,
                Point,
                Applied,
                Point,
                Point,
                NotFollowed,
                NotFollowed,
                Applied,
                Passed
            ]
        );
        assert_eq!(out[2].0.tip, [10.0, 0.0, 50.0]);
        assert!(direction_near(out[2].0.orientation, [0.0, -s, s]));
        assert_eq!(out[3].0.tip, [10.0, 20.0, 50.0]);
        assert_eq!(out[3].0.orientation, out[2].0.orientation);
        let Orientation::Direction(d) = out[5].0.orientation else {
            panic!()
        };
        assert!(d[0].abs() < 1e-15 && (d[1] + 1.0).abs() < 1e-15 && d[2].abs() < 1e-15);
        let Orientation::Direction(d) = out[7].0.orientation else {
            panic!()
        };
        assert!((d[0] - 1.0).abs() < 1e-15 && d[1].abs() < 1e-15 && d[2].abs() < 1e-15);
        assert_eq!(out[8].0.orientation, Orientation::Axes([30.0, 0.0, -45.5]));
        // An arc is not followed: its mode and its end point taken (`G2 X5 Y5`), nothing
        // else; the tip is known.
        assert_eq!(
            out[9].0,
            ToolPath {
                circular: true,
                tip: [5.0, 5.0, 50.0],
                ..out[8].0
            }
        );
        // A value not read (`X=IC(5+R1)`): the tip lost.
        assert!(out[10].0.lost && out[10].0.tip == out[9].0.tip);
        assert!(!out[11].0.on);
    }

    /// Blocks that tilt or shift the frame the coordinates are read in are not followed,
    /// whatever their spelling (`CROT`, a `CYCLE800` swivel before `TRAORI` gave the
    /// points of the program without it); a cancel and a work-offset selection pass.
    #[test]
    fn frame_blocks_are_not_followed() {
        use PathRemark::*;
        for (d, block, want) in [
            (Dialect::Sinumerik, "N20 CROT Z90", NotFollowed),
            (Dialect::Sinumerik, "/N20 AROTS Z30", NotFollowed),
            (
                Dialect::Sinumerik,
                "CYCLE800(1,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)",
                NotFollowed,
            ),
            (
                Dialect::Sinumerik,
                "CYCLE600(0,\"HEAD\",1,57,0,0,0,30,0,0,0,0,0,0,57)",
                NotFollowed,
            ),
            (Dialect::Sinumerik, "$P_PFRAME=CROT(Z,90)", NotFollowed),
            (Dialect::Sinumerik, "TOFRAME", NotFollowed),
            (Dialect::Sinumerik, "CYCLE800()", Passed),
            (Dialect::Sinumerik, "G54", Passed),
            (Dialect::Heidenhain, "5 CYCL DEF 19.1 B+30", NotFollowed),
            (Dialect::Heidenhain, "5 CYCL DEF 7.1 X+10", NotFollowed),
            (
                Dialect::Heidenhain,
                "5 TCH PROBE 410 DATUM INSIDE RECTAN",
                NotFollowed,
            ),
            (Dialect::Heidenhain, "5 PLANE RESET STAY", NotFollowed),
            (Dialect::Fanuc, "G52 X10.", NotFollowed),
            (Dialect::Haas, "G268 X0 Y0 Z0 I0 J30. K0 Q123", NotFollowed),
            // Frame commands that leave nothing active: their coordinates are no move.
            (Dialect::Haas, "G268 X0 Y0 Z0 I0 J0 K0 Q123", NotFollowed),
            (Dialect::Haas, "G269 X0. Y0. Z0.", NotFollowed),
            (
                Dialect::Syntec,
                "G158 P10157 X0. Y0. Z0. A0. B0. C0.",
                NotFollowed,
            ),
            // One the tilted-plane reader refuses (no `Q`): the control's alarm, no move.
            (Dialect::Haas, "G268 X5. Y0. Z0. I0. J0. K0.", NotFollowed),
            (Dialect::Fanuc, "G69", Passed),
        ] {
            let on = if d == Dialect::Heidenhain {
                "M128"
            } else if d == Dialect::Sinumerik {
                "TRAORI"
            } else {
                "G43.4 H1"
            };
            let out = run(d, &[on, block]);
            assert_eq!(out[1].1, want, "{block}");
            // A tilt or shift left active marks the state (and the tip, in other
            // coordinates after it, lost); a cancel of nothing active leaves it as it was.
            let marks = ToolPath {
                framed: false,
                shifted: [false; 3],
                lost: false,
                altered: false,
                ..out[1].0
            };
            assert_eq!(marks, out[0].0, "{block}");
            let marked = out[1].0.framed || out[1].0.shifted.contains(&true) || out[1].0.altered;
            assert!(!marked || out[1].0.lost, "{block}");
        }
    }

    /// A block not followed still sets the modes it names (a retract `G91 G28 Z0.` leaves
    /// `G91`; `G49`, `M129`, `TRAFOOF` beside a reference move switch the transformation
    /// off), and its move loses the tip: until a block states X Y Z absolutely, the moves
    /// are not followed (an incremental `X10.` from an unknown position is no point). The
    /// start-up block of `G43.4` moves with the tool length only (Fanuc's manual): not a
    /// point.
    #[test]
    fn blocks_not_followed_keep_their_modes() {
        use PathRemark::*;
        let iso = run(
            Dialect::Fanuc,
            &[
                "G43.4 H1 X0. Y0. Z50. A0. C0.",
                "G1 X0. Y0. Z50. A0. C0.",
                "G91 G28 Z0.",
                "G1 X10.",
                "G90 G1 X1. Y2. Z3.",
                "G91 G28 Z0. G49",
            ],
        );
        let r: Vec<_> = iso.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                NotFollowed,
                Point,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed
            ]
        );
        assert!(iso[0].0.on && iso[0].0.lost && !iso[1].0.lost);
        assert!(iso[2].0.incremental && iso[2].0.lost && iso[2].0.tip == [0.0, 0.0, 50.0]);
        assert!(iso[3].0.lost && iso[3].0.tip == [0.0, 0.0, 50.0]);
        assert!(!iso[4].0.incremental && !iso[4].0.lost && iso[4].0.tip == [1.0, 2.0, 3.0]);
        assert!(!iso[5].0.on && iso[5].0.incremental);
        let h = run(
            Dialect::Heidenhain,
            &["M128", "L X+0 Y+0 Z+50 R0 FMAX", "L Z+500 R0 FMAX M91 M129"],
        );
        assert_eq!(h[2].1, NotFollowed);
        assert!(!h[2].0.on && h[2].0.lost);
        let s = run(
            Dialect::Sinumerik,
            &["TRAORI", "G1 X0 Y0 Z5", "TRAFOOF G74 Z1=0"],
        );
        assert_eq!(s[2].1, NotFollowed);
        assert!(!s[2].0.on);
        // `A3 =0.5`: a numeric extension before a blank and `=` is the control's alarm, not
        // the axis A at 3.
        let s = run(
            Dialect::Sinumerik,
            &["TRAORI", "G1 X0 Y0 Z5", "G1 A3 =0.5 C3 =0.8660254"],
        );
        assert_eq!(s[2].1, NotFollowed);
        assert_eq!(s[2].0.orientation, Orientation::Unstated);
    }

    /// Positions by letter on a machine with two axes nearest the same letter (a head C
    /// about Z carrying an axis tilted just past 45° toward Z, as a nutating head measured
    /// by a probing cycle is): C is the head's C, the tilted axis is B (its next nearest
    /// letter), so `C10.` turns C alone (it was given to both, then refused).
    #[test]
    fn a_letter_two_axes_are_nearest_goes_to_the_nearer() {
        use crate::kinematics::{RotaryAxis, Side};
        let m = Machine::new([0.0, 0.0, 1.0])
            .unwrap()
            .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]))
            .unwrap()
            .with_axis(RotaryAxis::new(
                Side::Tool,
                [0.0, 1.0, 1.0000001],
                [0.0, 0.0, 100.0],
            ))
            .unwrap();
        assert_eq!(super::super::program::axis_letters(&m), [2, 1, 0]);
        let out = run(
            Dialect::Fanuc,
            &["G43.4 H1", "G1 X0 Y0 Z0 C10.", "G1 X0 Y0 Z0 B20. C10."],
        );
        assert_eq!(out[1].1, PathRemark::Point);
        let t = out[1].0.machine_axes(&m, 50.0, [0.0; 6], Rule::Closest);
        assert_eq!(t.map(|t| [t.axes[3], t.axes[4]]), Ok([10.0, 0.0]));
        let t = out[2].0.machine_axes(&m, 50.0, [0.0; 6], Rule::Closest);
        assert_eq!(t.map(|t| [t.axes[3], t.axes[4]]), Ok([10.0, 20.0]));
    }

    /// `G2`/`G3` (group 01) stay in force until `G0`/`G1`, a canned cycle (group 09) until
    /// `G80` or a group 01 code: the blocks in either mode are arcs and holes, not straight
    /// moves to points. Under `G43.5` an arc's `I J K` are its centre, not the tool: read
    /// as a direction they would tilt the tool.
    #[test]
    fn arcs_and_canned_cycles_are_modal() {
        use PathRemark::*;
        let iso = run(
            Dialect::Fanuc,
            &[
                "G43.5 H1",
                "G1 X0. Y0. Z5. I0. J0. K1.",
                "G2 X10. Y0. I5. J0.",
                "X0. Y0. I-5. J0.",
                "G1 X1. Y1.",
                "G81 X5. Y5. Z-3. R1. F100.",
                "X6. Y6.",
                "G80",
                "X7. Y7.",
                "G3 X0. Y0. R5.",
                "G81 X1. Y1. Z-2. R1.",
                "G1 X2. Y2.",
            ],
        );
        let r: Vec<_> = iso.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Applied,
                Point,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed,
                NotFollowed,
                Applied,
                // After the holes the tip is not known (Z went back to the R or the initial
                // level): not followed until X Y Z are stated.
                NotFollowed,
                NotFollowed,
                NotFollowed,
                NotFollowed
            ]
        );
        // The arc's centre words did not become the tool direction.
        assert_eq!(iso[3].0.orientation, iso[1].0.orientation);
        assert_eq!(iso[3].0.tip, [0.0, 0.0, 5.0]);
        assert!(iso[2].0.circular && iso[3].0.circular && !iso[4].0.circular);
        assert!(iso[5].0.canned && iso[6].0.canned && !iso[7].0.canned);
        // `X7. Y7.` after the holes: X and Y known again, Z not; no point.
        assert!(iso[6].0.lost && iso[8].0.lost && iso[8].0.known == [true, true, false]);
        assert_eq!(iso[8].0.tip, [7.0, 7.0, iso[4].0.tip[2]]);
        assert_eq!(iso[4].0.tip, [1.0, 1.0, 5.0]);
        // A canned cycle in an arc's mode ends neither with the other; `G1` ends both.
        assert!(iso[10].0.circular && iso[10].0.canned);
        assert!(!iso[11].0.circular && !iso[11].0.canned);
        let sin = run(
            Dialect::Sinumerik,
            &[
                "TRAORI",
                "G1 X0 Y0 Z5",
                "CIP X10 Y10 I1=5 J1=5",
                "X0 Y0",
                "G0 X3",
            ],
        );
        let r: Vec<_> = sin.iter().map(|o| o.1).collect();
        assert_eq!(r, [Applied, Point, NotFollowed, NotFollowed, Point]);
        assert_eq!(sin[4].0.tip, [3.0, 0.0, 5.0]);
    }

    #[test]
    fn sinumerik_value_functions() {
        let out = run(
            Dialect::Sinumerik,
            &[
                "TRAORI",
                "G1 X=AC(10) Y20 Z5 A=30 C=ACP(90)",
                "X=IC(5) C=DC(-90)",
                "G91 X1 A=AC(0)",
                "X=IC(R1)",
                "X=10*R2",
                "Y20-R1",
            ],
        );
        use PathRemark::*;
        let r: Vec<_> = out.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Applied,
                Point,
                Point,
                Point,
                NotFollowed,
                NotFollowed,
                NotFollowed
            ]
        );
        assert_eq!(out[1].0.tip, [10.0, 20.0, 5.0]);
        assert_eq!(out[2].0.tip, [15.0, 20.0, 5.0]);
        assert_eq!(out[2].0.orientation, Orientation::Axes([30.0, 0.0, -90.0]));
        // G91 makes the words incremental, but AC(…) is absolute whatever G90/G91 say.
        assert_eq!(out[3].0.tip, [16.0, 20.0, 5.0]);
        assert_eq!(out[3].0.orientation, Orientation::Axes([0.0, 0.0, -90.0]));
    }

    #[test]
    fn heidenhain_l_and_ln_blocks() {
        let out = run(
            Dialect::Heidenhain,
            &[
                "0 BEGIN PGM P MM",
                "1 TOOL CALL 5 Z S8000",
                "2 L X+0 Y+0 Z+100 R0 FMAX",
                "3 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS",
                "4 L X+10 Y+5 Z+2 B+30 C-90 F1000",
                "5 L IX+5 IB+5",
                "6 LN X+1 Y+2 Z+3 NX+0 NY+0 NZ+1 TX+0 TY+0.6 TZ+0.8",
                "7 CC X+0 Y+0",
                "8 C X+5 Y+0 DR+",
                "9 FUNCTION RESET TCPM",
                "10 L X+5 Y+0 Z+100 M128",
                "11 L Z+50 M129",
                "12 L Z+500 R0 FMAX M91",
            ],
        );
        use PathRemark::*;
        let r: Vec<_> = out.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Passed,
                Passed,
                Applied,
                Applied,
                Point,
                Point,
                Point,
                Passed,
                NotFollowed,
                Applied,
                Point,
                // M129 at the end of its block: the move is still a point.
                Point,
                NotFollowed
            ]
        );
        assert_eq!(out[4].0.orientation, Orientation::Axes([0.0, 30.0, -90.0]));
        assert_eq!(out[5].0.tip, [15.0, 5.0, 2.0]);
        assert_eq!(out[5].0.orientation, Orientation::Axes([0.0, 35.0, -90.0]));
        assert!(direction_near(out[6].0.orientation, [0.0, 0.6, 0.8]));
        assert_eq!(out[6].0.tip, [1.0, 2.0, 3.0]);
        assert!(out[10].0.on && !out[11].0.on);
    }

    /// `FUNCTION TCPM … AXIS SPAT`: the `A B C` of `L` blocks are spatial angles (the tool
    /// direction `Rz(C)·Ry(B)·Rx(A)·e_z`, as `PLANE SPATIAL`); `AXIS POS`, `M128` and the
    /// cancel make them axis positions again (a helper's find: read as positions).
    #[test]
    fn heidenhain_axis_spat() {
        let out = run(
            Dialect::Heidenhain,
            &[
                "1 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS",
                "2 L X+10 Y+0 Z+0 A+0 B+30 C+0 F1000",
                "3 L C+90",
                "4 L A+90 B+0 C+0",
                "5 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS",
                "6 L B+30 C+0",
                "7 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS",
                "8 FUNCTION RESET TCPM",
                "9 L Z+100 M128",
            ],
        );
        assert!(out[0].0.spatial && out[0].0.on);
        // Ry(30°)·e_z; then Rz(90°)·Ry(30°)·e_z = (0, 0.5, 0.866); Rx(90°)·e_z = (0, -1, 0).
        let h = 3f64.sqrt() / 2.0;
        assert!(direction_near(out[1].0.orientation, [0.5, 0.0, h]));
        assert!(direction_near(out[2].0.orientation, [0.0, 0.5, h]));
        assert!(direction_near(out[3].0.orientation, [0.0, -1.0, 0.0]));
        assert!(!out[4].0.spatial);
        assert_eq!(out[5].0.orientation, Orientation::Axes([90.0, 30.0, 0.0]));
        assert!(out[6].0.spatial && !out[7].0.spatial && !out[8].0.spatial);
    }

    /// Numbers as each dialect writes them, and what is none (a helper's finds: the digits
    /// before an unread suffix were taken): SINUMERIK's `EX`, Heidenhain's decimal comma;
    /// `1e7`, `1_000`, `1,5.2`, a letter glued to a Heidenhain number, a word twice: not
    /// followed. Commands whose words are no points (frame commands, a dwell, machine
    /// coordinates, polar and approach moves) neither.
    #[test]
    fn numbers_and_commands_that_are_no_points() {
        let x = |d: Dialect, on: &str, block: &str| {
            let (p, _) = ToolPath::default().line(d, on.as_bytes()).unwrap();
            let (q, r) = p.line(d, block.as_bytes()).unwrap();
            (q.tip[0], r)
        };
        let s = Dialect::Sinumerik;
        assert_eq!(
            x(s, "TRAORI", "G1 X=1EX2 Y0 Z0"),
            (100.0, PathRemark::Point)
        );
        assert_eq!(
            x(s, "TRAORI", "G1 X=-.1EX-3 Y0 Z0"),
            (-1e-4, PathRemark::Point)
        );
        for bad in ["G1 X=1e7", "G1 X1_000", "G1 X1 X2", "G1 X=1.5.2"] {
            assert_eq!(x(s, "TRAORI", bad), (0.0, PathRemark::NotFollowed), "{bad}");
        }
        for frame in [
            "TRANS X100",
            "ROT Z90",
            "AROT X30",
            "ATRANS Y5",
            "MIRROR X0",
            "SCALE X2",
            "G1 G53 X5",
            "G0 G153 X8",
            "SUPA X7",
        ] {
            assert_eq!(
                x(s, "TRAORI", frame),
                (0.0, PathRemark::NotFollowed),
                "{frame}"
            );
        }
        let h = Dialect::Heidenhain;
        assert_eq!(x(h, "M128", "L X+25,5 Y+0 Z+0"), (25.5, PathRemark::Point));
        for bad in [
            "L X+1,5.2",
            "L X+1E3",
            "L X+1Y+2",
            "LP PR+10 PA+30",
            "APPR LT X+1 Y+1 LEN5 RL",
            "DEP LT LEN5",
            "TRANS DATUM AXIS X+10",
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
        ] {
            assert_eq!(x(h, "M128", bad), (0.0, PathRemark::NotFollowed), "{bad}");
        }
        let f = Dialect::Fanuc;
        assert_eq!(x(f, "G43.4 H1", "G1X10.Y0.Z0."), (10.0, PathRemark::Point));
        assert_eq!(x(f, "G43.4 H1", "G04 X1.5"), (0.0, PathRemark::Passed));
        for other in [
            "G10 L2 P1 X100.",
            "G92 X5.",
            "G65 P9000 X7.",
            "G68 X1. Y1. R30.",
            "G51.1 X0.",
            "G81 X10. Y0. Z-5. R1.",
            "G52 X10.",
        ] {
            assert_eq!(
                x(f, "G43.4 H1", other),
                (0.0, PathRemark::NotFollowed),
                "{other}"
            );
        }
    }

    /// What the reader does not compute is flagged, never guessed (a helper's hunt: each
    /// of these was a point in the old frame): while a tilt, a datum shift, a cutter
    /// compensation or a rotation in the plane is active, motion blocks are not followed,
    /// and after its cancel the tip must be stated again; `G43` ends the transformation;
    /// inches are taken as 25.4 mm; calls and program ends lose the tip; an orientation
    /// stated in a block not followed (or turned by `ORIRESET`) loses the orientation.
    #[test]
    fn frames_offsets_and_calls_are_flagged() {
        use PathRemark::*;
        let iso = run(
            Dialect::Fanuc,
            &[
                "G43.5 H1",
                "G1 X10. Y0. Z0. I0. J0. K1.",
                "G52 X100.",
                "X10. Y0. Z0.",
                "G52 X0. Y0. Z0.",
                "X10.",
                "X10. Y0. Z0.",
                "G68 X0. Y0. R90.",
                "X10. Y0. Z0.",
                "G69",
                "X10. Y0. Z0.",
                "G68.2 X0. Y0. Z0. I0. J30. K0.",
                "X10. Y0. Z0.",
                "G69",
                "G41.2 D1 X11. Y0. Z0.",
                "X12. Y0. Z0.",
                "G40 X13. Y0. Z0.",
                "M98 P2000",
                "X14. Y0. Z0.",
                "G20",
                "X1. Y0. Z0.",
                "G21 G43 H2",
                "X1. Y0. Z0.",
            ],
        );
        let r: Vec<_> = iso.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Applied,
                Point,
                NotFollowed,
                NotFollowed,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed,
                NotFollowed,
                Applied,
                Point,
                NotFollowed,
                NotFollowed,
                Applied,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed,
                Point,
                Applied,
                Point,
                Applied,
                Applied
            ]
        );
        assert!(iso[2].0.shifted == [true, false, false] && !iso[2].0.framed && iso[2].0.lost);
        assert!(iso[4].0.shifted == [false; 3] && iso[4].0.lost);
        // Fanuc's G68 is the tilted-plane reader's (a rotation in the plane: a tilt).
        assert!(iso[7].0.framed && !iso[9].0.framed);
        assert!(iso[11].0.framed && iso[11].0.shifted == [false; 3] && !iso[13].0.framed);
        assert!(iso[14].0.compensated && !iso[16].0.compensated);
        assert!(iso[17].0.lost);
        assert_eq!(iso[20].0.tip, [25.4, 0.0, 0.0]);
        assert!(iso[20].0.inch && !iso[21].0.inch && !iso[21].0.on);
        // G69 after G52 and G68.2 ends the tilt only; G52 X0 Y0 Z0 the shift only.
        let both = run(
            Dialect::Fanuc,
            &["G43.5 H1", "G52 X5.", "G68.2 X0 Y0 Z0 I0 J30. K0", "G69"],
        );
        assert!(both[2].0.framed && both[2].0.shifted[0]);
        assert!(!both[3].0.framed && both[3].0.shifted[0]);
        // G52 X0 Y0 ends the shift in X and Y: one in Z stays.
        let part = run(
            Dialect::Fanuc,
            &["G43.4 H1", "G52 X10. Y5. Z2.", "G52 X0 Y0", "G52 Z0"],
        );
        assert_eq!(part[1].0.shifted, [true; 3]);
        assert_eq!(part[2].0.shifted, [false, false, true]);
        assert_eq!(part[3].0.shifted, [false; 3]);

        let h = run(
            Dialect::Heidenhain,
            &[
                "M128",
                "L X+0 Y+0 Z+0 A+0 C+0 R0 F1000",
                "C X+0 Y+20 DR+",
                "L X+10",
                "L X+10 Y+20 Z+0",
                "CYCL DEF 7.0 DATUM SHIFT",
                "CYCL DEF 7.1 X+100",
                "L X+0 Y+0 Z+0",
                "CYCL DEF 7.1 X+0",
                "L X+20 Y+0 Z+0 RL",
                "L X+30 Y+0 Z+0 R0",
                "L X+30 Y+0 Z+0 A+30 M99",
                "L X+31 Y+0 Z+0",
                "L X+31 Y+0 Z+0 A+30",
            ],
        );
        let r: Vec<_> = h.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Applied,
                Point,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed,
                NotFollowed,
                NotFollowed,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed,
                Point,
                Point
            ]
        );
        assert!(h[6].0.shifted[0] && h[8].0.shifted == [false; 3] && h[9].0.compensated);
        // The cycle call's A+30 is where A goes: taken, the orientation known.
        assert!(!h[11].0.disoriented && h[11].0.axes[0] == 30.0);

        let s = run(
            Dialect::Sinumerik,
            &[
                "TRAORI",
                "G1 X0 Y0 Z0 A3=0 B3=0 C3=1",
                "TRANS X100",
                "G1 X0 Y0 Z0",
                "TRANS",
                "G1 X0 Y0 Z0",
                "X10 LEAD=20 TILT=0",
                "X11 Y0 Z0",
                "X11 Y0 Z0 A3=0 B3=0 C3=1",
                "ORIRESET(0,30)",
                "X12 Y0 Z0 A3=0 B3=0 C3=1",
                "CYCLE81(50,0,2,-10,)",
                "X13 Y0 Z0",
                "L123",
                "SCALE X2",
                "X14 Y0 Z0",
                "SCALE",
                "TRAORI(1,0,1,0)",
                "G70",
                "X1 Y0 Z0",
            ],
        );
        let r: Vec<_> = s.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Applied,
                Point,
                NotFollowed,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed,
                NotFollowed,
                Point,
                NotFollowed,
                Point,
                NotFollowed,
                Point,
                NotFollowed,
                NotFollowed,
                NotFollowed,
                Applied,
                NotFollowed,
                Applied,
                NotFollowed
            ]
        );
        assert!(s[2].0.framed && !s[4].0.framed);
        assert!(s[6].0.disoriented && s[9].0.disoriented && s[9].0.lost);
        assert!(s[14].0.altered && !s[16].0.altered && s[17].0.altered);
        assert!(s[18].0.inch);

        // The start is not assumed to be the origin: a point once X, Y and Z are known,
        // stated in one block or in several (moves with the transformation off count).
        let start = run(
            Dialect::Heidenhain,
            &["M128", "L X+10 Y+20 R0 FMAX", "L Z+5", "L X+11"],
        );
        let r: Vec<_> = start.iter().map(|o| o.1).collect();
        assert_eq!(r, [Applied, NotFollowed, Point, Point]);
        assert_eq!(start[3].0.tip, [11.0, 20.0, 5.0]);
        // Known with the transformation off; switched on, the coordinates are the
        // workpiece's: stated again.
        let off = run(
            Dialect::Fanuc,
            &["G0 X1. Y2.", "Z3.", "G43.4 H1", "G1 X4.", "X4. Y2. Z3."],
        );
        assert!(off[1].0.known == [true; 3] && off[2].0.known == [false; 3]);
        assert!(off[3].1 == NotFollowed && off[4].1 == Point);

        // A helper's false alarms and misses: Heidenhain's comments and program head are
        // no commands; a rotary position by a parameter loses the orientation; ORIVIRT1
        // marks; EXTCALL loses the tip; G55 forgets X Y Z; ROT+0 ends the rotation cycle;
        // FGREF[C] names an axis, moves none.
        let h = run(
            Dialect::Heidenhain,
            &[
                "0 BEGIN PGM C MM",
                "1 M128",
                "2 L X+1 Y+0 Z+50 A+0 C+0 R0 FMAX",
                "3 * - TOOL 1/4 INCH BALL, C CR PLANE",
                "4 L X+2",
                "5 CYCL DEF 10.0 ROTATION",
                "6 CYCL DEF 10.1 ROT+0",
                "7 L X+3",
                "8 L X+4 C+Q1",
                "9 L X+5 Y+0 Z+50",
            ],
        );
        let r: Vec<_> = h.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Passed,
                Applied,
                Point,
                Passed,
                Point,
                NotFollowed,
                Applied,
                // Its coordinates were the rotated system's: stated again.
                NotFollowed,
                NotFollowed,
                NotFollowed
            ]
        );
        assert!(h[5].0.altered && !h[6].0.altered && h[8].0.disoriented);
        let s = run(
            Dialect::Sinumerik,
            &[
                "TRAORI",
                "G1 X0 Y0 Z10 A3=0 B3=0 C3=1",
                "FGREF[C]=100",
                "X1",
                "G55",
                "X2",
                "X2 Y0 Z10",
                "EXTCALL \"FINISH.SPF\"",
                "X3 Y0 Z10",
                "ORIVIRT1",
            ],
        );
        let r: Vec<_> = s.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Applied,
                Point,
                Passed,
                Point,
                Applied,
                NotFollowed,
                Point,
                NotFollowed,
                Point,
                NotFollowed
            ]
        );
        assert!(s[9].0.altered);
    }

    #[test]
    fn fanuc_g43_4_and_g43_5() {
        let out = run(
            Dialect::Fanuc,
            &[
                "G90 G54 G0 X0 Y0",
                "G43.5 H1",
                "G1 X10. Y20. Z30. I0. J0. K1. F500",
                "G91 X1. I1. K0.",
                "G90 G43.4 H1",
                "X5.A10.C20.",
                "G2 X0 Y0 R5.",
                "G49",
                "(a comment) M30",
            ],
        );
        use PathRemark::*;
        let r: Vec<_> = out.iter().map(|o| o.1).collect();
        assert_eq!(
            r,
            [
                Applied,
                Applied,
                Point,
                Point,
                Applied,
                Point,
                NotFollowed,
                Applied,
                NotFollowed
            ]
        );
        assert_eq!(
            out[2].0.orientation,
            Orientation::Direction([0.0, 0.0, 1.0])
        );
        assert_eq!(out[3].0.tip, [11.0, 20.0, 30.0]);
        assert_eq!(
            out[3].0.orientation,
            Orientation::Direction([1.0, 0.0, 0.0])
        );
        assert_eq!(out[5].0.tip, [5.0, 20.0, 30.0]);
        assert_eq!(out[5].0.orientation, Orientation::Axes([10.0, 0.0, 20.0]));
    }

    #[test]
    fn refusals_leave_nothing() {
        let p = ToolPath::default();
        let e = p.line(Dialect::Fanuc, b"G1 X1 I0 J0 K0").unwrap_err();
        assert_eq!((e.error, e.column), (Error::BadArgument, 7));
        let e = p.line(Dialect::Fanuc, b"G1 X1 A5 I1").unwrap_err();
        assert_eq!(e.error, Error::BadArgument);
        let e = p.line(Dialect::Twincat, b"G1 X1").unwrap_err();
        assert_eq!(e.error, Error::NotAvailable);
        let long = vec![b'X'; 600];
        assert_eq!(
            p.line(Dialect::Fanuc, &long).unwrap_err().error,
            Error::LineTooLong
        );
    }
}
