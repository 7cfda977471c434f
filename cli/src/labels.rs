//! Labels, subprograms and their calls in a whole program. The library reads a program
//! block by block, and a call is a block like any other (passed over: it names no frame); the
//! command has the whole file, and follows the call: the frame after it is the one the
//! called blocks leave. CAM systems write a subprogram that resets the plane and the datum
//! (Heidenhain `CALL LBL 1 ; RESET WORKING PLANE`, the label after the program's end), and
//! people put a face's tilt in a subprogram (Fanuc `M98 P2000` … `O2000` … `G68.4 …` …
//! `M99`): read in the order of the file, the program would keep the frame it had before the
//! call, and a translation would turn the axes back to it, or write an increment from the
//! wrong plane.

use crate::params::{block_number_of, goto_number, Params};
use cncrot::dialects::program::{AxisChoice, Dialect, Program, Remark};

/// Nested calls followed at most this deep (a label that calls itself stops there).
pub const DEPTH: usize = 8;

/// Blocks read for one call at most (its repeats and nested calls included): `L9999` three
/// deep would be 10¹² blocks.
pub const BUDGET: usize = 1_000_000;

/// A block's words after its block number, up to a `;` comment, in capitals.
fn words(block: &str) -> Vec<String> {
    let text = block.split(';').next().unwrap_or("");
    let mut w: Vec<String> = text.split_whitespace().map(str::to_uppercase).collect();
    if w.first()
        .is_some_and(|n| n.bytes().all(|b| b.is_ascii_digit()))
    {
        w.remove(0);
    }
    w
}

/// The address words of an ISO-style block (Fanuc, Haas, Syntec), comments left out, with or
/// without blanks between them: `M98P2000L3` is `[('M', "98"), ('P', "2000"), ('L', "3")]`;
/// a program number `:2000` is `('O', "2000")`.
fn iso_words(block: &str) -> Vec<(char, String)> {
    let mut out: Vec<(char, String)> = Vec::new();
    let mut comment = false;
    for c in block.chars() {
        match c {
            '(' => comment = true,
            ')' => comment = false,
            ';' if !comment => break,
            _ if comment => {}
            c if c.is_ascii_alphabetic() || c == ':' => {
                let letter = if c == ':' {
                    'O'
                } else {
                    c.to_ascii_uppercase()
                };
                out.push((letter, String::new()));
            }
            c if c.is_ascii_digit() || matches!(c, '.' | '+' | '-') => {
                if let Some((_, v)) = out.last_mut() {
                    v.push(c);
                }
            }
            _ => {}
        }
    }
    out
}

/// The value of word `letter` of `w`.
fn iso_word(w: &[(char, String)], letter: char) -> Option<&str> {
    w.iter()
        .find(|(l, _)| *l == letter)
        .map(|(_, v)| v.as_str())
}

/// Whether `w` holds the M function `m`.
fn iso_has_m(w: &[(char, String)], m: u32) -> bool {
    w.iter()
        .any(|(l, v)| *l == 'M' && v.parse::<u32>().is_ok_and(|n| n == m))
}

/// The label a block defines (`LBL 1`, `LBL "NAME"`, not `LBL 0`, the end of one), or the
/// subprogram an ISO block starts (`O2000`, `:2000`: `O2000`; for Haas's `M97` also a block
/// number, `N1000`: `N1000`).
fn defined(dialect: Dialect, block: &str) -> Option<String> {
    if dialect != Dialect::Heidenhain {
        let w = iso_words(block);
        return match w.first() {
            Some(('O', v)) => v.parse::<u32>().ok().map(|n| format!("O{n}")),
            Some(('N', v)) if dialect == Dialect::Haas => {
                v.parse::<u32>().ok().map(|n| format!("N{n}"))
            }
            _ => None,
        };
    }
    match words(block).as_slice() {
        [lbl, name, ..] if lbl == "LBL" && name != "0" => Some(name.clone()),
        _ => None,
    }
}

/// Whether a block ends a subprogram: `LBL 0`, or an ISO `M99`.
fn ends(dialect: Dialect, block: &str) -> bool {
    if dialect != Dialect::Heidenhain {
        return iso_has_m(&iso_words(block), 99);
    }
    matches!(words(block).as_slice(), [lbl, zero, ..] if lbl == "LBL" && zero == "0")
}

/// The label a block calls and how often: `(name, repeats)`. Heidenhain's `CALL LBL 1 REP 2`
/// (the editor's `REP 2/2`): the repeats after the first run, 0 without `REP`. An ISO
/// subprogram call, `M98 P2000` with `L3` or `K3` (Fanuc, Syntec, Haas; the older
/// `M98 P32000`, a count in the first digits, is named `O32000` here and resolved by
/// [`Labels::target`]), Haas's `M97 P1000` (the local subprogram at `N1000`): the runs, at
/// least 1.
fn called(dialect: Dialect, block: &str) -> Option<(String, usize)> {
    if dialect != Dialect::Heidenhain {
        let w = iso_words(block);
        let local = dialect == Dialect::Haas && iso_has_m(&w, 97);
        // A macro call (`G65 P2000 L2 A15.`) runs its program as `M98` does (its arguments
        // are the program's `#` variables, not followed); `M198` one from external memory.
        let macro_call = w
            .iter()
            .any(|(l, v)| *l == 'G' && v.parse::<f64>().is_ok_and(|g| g == 65.0));
        if !(local || macro_call || iso_has_m(&w, 98) || iso_has_m(&w, 198)) {
            return None;
        }
        let p = iso_word(&w, 'P')?;
        let n: u32 = p.parse().ok()?;
        let times = iso_word(&w, 'L')
            .or_else(|| iso_word(&w, 'K'))
            .and_then(|t| t.parse::<usize>().ok());
        let name = if local {
            format!("N{n}")
        } else {
            format!("O{n}")
        };
        return Some((name, times.unwrap_or(1).max(1)));
    }
    match words(block).as_slice() {
        [call, lbl, name, rest @ ..] if call == "CALL" && lbl == "LBL" => {
            // `REP 2`, `REP2`, the editor's `REP 2/2`; a parameter (`REPQ106`): not known, none.
            let count = |n: &str| n.split('/').next().and_then(|c| c.parse().ok());
            let rep = match rest {
                [r, n, ..] if r == "REP" => count(n).unwrap_or(0),
                [r, ..] if r.starts_with("REP") => count(&r[3..]).unwrap_or(0),
                _ => 0,
            };
            Some((name.clone(), rep))
        }
        _ => None,
    }
}

/// SINUMERIK words that stand alone on a block (or with their arguments) and are no call of
/// a subprogram: transformations, orientation and compensation modes, control words. A block
/// of one other name is a call (`FACE_SIDE2`, `MYSUB(1, 2)`).
#[rustfmt::skip]
const SINUMERIK_WORDS: &[&str] = &[
    "TRAORI", "TRAFOOF", "TRANSMIT", "TRACYL", "TRAANG", "TRACON", "ORIWKS", "ORIMKS",
    "ORIAXES", "ORIVECT", "ORIPLANE", "ORICONCW", "ORICONCCW", "ORICONIO", "ORICONTO",
    "ORICURVE", "ORIPATH", "ORIPATHS", "ORIROTA", "ORIROTR", "ORIROTT", "ORIROTC", "ORIEULER",
    "ORIRPY", "ORIRPY2", "ORIVIRT1", "ORIVIRT2", "ORIAXPOS", "ORISON", "ORISOF", "UPATH",
    "SPATH", "CFTCP", "CFC", "CFIN", "CUT2D", "CUT2DF", "CUT3DC", "CUT3DF", "CUT3DFS",
    "CUT3DFF", "CUT3DCC", "CUT3DCCD", "CDON", "CDOF", "CDOF2", "SOFT", "BRISK", "DRIVE",
    "SOFTA", "BRISKA", "DRIVEA", "FFWON", "FFWOF", "COMPON", "COMPOF", "COMPCURV", "COMPCAD",
    "COMPSURF", "STOPRE", "RET", "SUPA", "TOFFON", "TOFFOF", "TCOABS", "TCOFR", "TCOFRX",
    "TCOFRY", "TCOFRZ", "TOROT", "TOROTOF", "TOROTX", "TOROTY", "TOROTZ", "TOFRAME", "TOFRAMEX",
    "TOFRAMEY", "TOFRAMEZ", "PAROT", "PAROTOF", "DIAMON", "DIAMOF", "DIAM90", "WAITM", "WAITMC",
    "WAITE", "SETM", "CLRM", "SETMS", "FGROUP", "FNORM", "FLIN", "FCUB", "FPRAON", "FPRAOF",
    "BSPLINE", "CSPLINE", "ASPLINE", "POLY", "POLYPATH", "PTP", "CP", "PTPG0", "STARTFIFO",
    "STOPFIFO", "FIFOCTRL", "RMB", "RME", "RMI", "RMN", "REPOSA", "REPOSL", "REPOSQ", "REPOSH",
    "NORM", "KONT", "KONTC", "KONTT", "ELSE", "ENDIF", "ENDWHILE", "LOOP", "ENDLOOP", "ENDFOR",
    "REPEAT", "UNTIL", "DISPLOF", "DISPLON", "SBLOF", "SBLON", "MSG", "WORKPIECE", "SETPIECE",
    "LIFTFAST", "SETAL", "TRANS", "ATRANS", "ROT", "AROT", "ROTS", "AROTS", "CROTS", "SCALE",
    "ASCALE", "MIRROR", "AMIRROR", "GOTOF", "GOTOB", "GOTO", "GOTOC",
    "GOTOS", "STOPREOF", "SAVE", "ACTBLOCNO", "CPRECON", "CPRECOF", "ORIC", "ORID", "OSOF",
    "OSC", "OSS", "OSSE", "OSD", "OST", "MOVT", "SPOF", "SPON", "SPIF1", "SPIF2", "DILF", "ALF",
    "LFON", "LFOF", "LFTXT", "LFWP", "LFPOS", "G500", "TRAILON", "TRAILOF", "CALCPOSI", "PROTA",
    "PROTS", "EXECUTE", "EXECSTRING", "CANCEL", "PUTFTOC", "PUTFTOCF", "SETINT", "DISABLE",
    "ENABLE", "CLRINT", "RESET", "WRTPR", "RELEASE", "GET", "GETD", "INIT", "START", "SYNFCT",
    "FTOC", "AXCTSWE", "AXCTSWED", "AXTOCHAN", "TANG", "TANGON", "TANGOF", "TLIFT", "CHKDNO",
    "GETSELT", "GETT", "NEWT", "DELT", "SETDNO", "SPI", "LOCK", "UNLOCK", "ACC", "OVRA",
    "VELOLIM", "JERKLIM", "G601", "G602", "G603",
];

/// A call to a program that stands in another file, not in this one: Heidenhain's
/// `CALL PGM name`, `CALL SELECTED PGM`; SINUMERIK's `L123`, `CALL`, `PCALL`, `EXTCALL`,
/// `MCALL name` (modal: after each motion block) and a block of a program's name alone
/// (`FACE_SIDE2`, `MYSUB(1, 2)`; the manufacturer's cycles, `CYCLE81` … and the
/// `POCKET`/`SLOT`/`HOLES` families, left out). The name, as the message gives it.
fn external(dialect: Dialect, block: &str) -> Option<String> {
    match dialect {
        Dialect::Heidenhain => match words(block).as_slice() {
            [call, pgm, name, ..] if call == "CALL" && pgm == "PGM" => Some(format!("PGM {name}")),
            [call, sel, pgm, ..] if call == "CALL" && sel == "SELECTED" && pgm == "PGM" => {
                Some("the selected program (SEL PGM)".into())
            }
            _ => None,
        },
        Dialect::Sinumerik => {
            let code = block.split(';').next().unwrap_or("").trim();
            let mut w: Vec<String> = code.split_whitespace().map(str::to_uppercase).collect();
            if w.first().is_some_and(|n| {
                n.strip_prefix('N')
                    .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
            }) {
                w.remove(0);
            }
            let first = w.first()?.clone();
            let cycle = |name: &str| {
                ["CYCLE", "POCKET", "SLOT", "HOLES", "LONGHOLE", "E_", "F_"]
                    .iter()
                    .any(|c| name.starts_with(c))
            };
            let name_of = |s: &str| {
                s.trim_matches('"')
                    .split('(')
                    .next()
                    .unwrap_or("")
                    .to_string()
            };
            match first.as_str() {
                "CALL" | "PCALL" | "EXTCALL" => w.get(1).map(|n| name_of(n)),
                "MCALL" => w
                    .get(1)
                    .map(|n| name_of(n))
                    .filter(|n| !cycle(n))
                    .map(|n| format!("{n} (after each motion block: MCALL)")),
                _ => {
                    let name = first.split('(').next().unwrap_or("");
                    let ident = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
                        && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
                    // `L123` (and `L123 P2`); otherwise a name alone on its block, not an
                    // address with its number (`G17`, `M30`) nor a word of the language.
                    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
                    let numbered = name.strip_prefix('L').is_some_and(digits);
                    let address = name.len() > 1
                        && name.as_bytes()[0].is_ascii_alphabetic()
                        && digits(&name[1..]);
                    let alone = w.len() == 1 || numbered && w.len() == 2 && w[1].starts_with('P');
                    (ident
                        && alone
                        && (numbered || !address)
                        && !cycle(name)
                        && !SINUMERIK_WORDS.contains(&name))
                    .then(|| name.to_string())
                }
            }
        }
        _ => None,
    }
}

/// A program's labels: where each is defined, and the states of the calls to a subprogram
/// that stands after them (one of them is the state its blocks are read from).
pub struct Labels {
    dialect: Dialect,
    lines: Vec<String>,
    defined: Vec<(String, usize)>,
    /// (the label's line, the call's line, the state at the call), in the order called.
    entered: Vec<(usize, usize, Program)>,
    /// The parameters the program sets once (a label's blocks are read with them too).
    params: Params,
    /// The lines each call runs and how often in all (a section above its call counts the
    /// pass in the file's order too): a block run more than once that adds to the frame adds
    /// each time.
    runs: Vec<(std::ops::Range<usize>, usize)>,
    /// The lines inside the program's loops (`WHILE … DO1` … `END1`, SINUMERIK `WHILE`,
    /// `FOR`, `LOOP`, `REPEAT … UNTIL`, `REPEAT LABEL P=n`, LinuxCNC's `o100 repeat`, TwinCAT
    /// `$WHILE`, Heidenhain's jump back to a label): run as often as their condition says.
    loops: Vec<std::ops::Range<usize>>,
    /// The frame each label or subprogram standing above its calls was read from, in the
    /// file's order.
    read_from: Vec<(usize, Program)>,
}

/// Whether a dialect's calls are followed (its subprograms stand in the same file).
fn follows(dialect: Dialect) -> bool {
    matches!(
        dialect,
        Dialect::Heidenhain | Dialect::Fanuc | Dialect::Haas | Dialect::Syntec
    )
}

/// What a call that the command cannot follow as the control does leaves to say.
pub enum Called {
    /// A subprogram not in the file (`M98 P9011`, `CALL LBL 7` without its label): its blocks
    /// are not followed.
    Elsewhere(String),
    /// A subprogram standing above its call (not a section the call repeats), read and
    /// translated in the file's order from the frame there (its line), which is not the
    /// call's.
    Above(usize),
    /// A call followed only in part: its passes keep changing the frame beyond [`BUDGET`]
    /// blocks (nested `L9999` around an increment of the tilt), or its calls nest deeper
    /// than [`DEPTH`] (a label that calls itself); the frame after it is not the one the
    /// control reaches.
    Cut(Cut),
}

/// Where a follow stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cut {
    /// At [`BUDGET`] blocks.
    Budget,
    /// At a call [`DEPTH`] calls deep.
    Depth,
}

/// The loops of a program's lines (see [`Labels::looped`]): each opener matched with the
/// nearest closer of its kind below it; a SINUMERIK `REPEAT LABEL P=n` from the line that
/// defines `LABEL:`; a SINUMERIK jump (`GOTOB`, `GOTO`, `GOTOC`) back to a label above it,
/// an ISO one (`IF [#1 LT 4] GOTO10`) back to a block number above it;
/// a Heidenhain conditional jump (`FN 12: IF … GOTO LBL 1`, `IF … GOTO
/// LBL`) back to a label above it.
fn loops(dialect: Dialect, lines: &[String]) -> Vec<std::ops::Range<usize>> {
    let upper: Vec<Vec<String>> = lines
        .iter()
        .map(|l| {
            let code = l.split([';', '(']).next().unwrap_or("");
            let mut w: Vec<String> = code.split_whitespace().map(str::to_uppercase).collect();
            // A block number (`N20`, Heidenhain's `12`) is no word of the loop.
            if w.first().is_some_and(|n| {
                let digits = n.strip_prefix('N').unwrap_or(n);
                !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit())
            }) {
                w.remove(0);
            }
            w
        })
        .collect();
    let first = |k: usize| {
        upper
            .get(k)
            .and_then(|w| w.first().cloned())
            .unwrap_or_default()
    };
    let mut out = Vec::new();
    let close = |open: usize, closer: &dyn Fn(usize) -> bool| {
        (open + 1..upper.len())
            .find(|&k| closer(k))
            .map(|end| open..end + 1)
    };
    for k in 0..upper.len() {
        let w = upper.get(k).cloned().unwrap_or_default();
        match dialect {
            Dialect::Fanuc | Dialect::Haas | Dialect::Syntec => {
                // `WHILE [#1 LT 4] DO1` … `END1` (with or without blanks: `WHILE[#1LT4]DO1`).
                let code = w.concat();
                // A jump back to a block number above (`IF [#1 LT 4] GOTO 10`, `GOTO10`).
                if let Some(want) = goto_number(&code) {
                    let number = |i: usize| lines.get(i).and_then(|l| block_number_of(l));
                    if let Some(start) = (0..=k).rev().find(|&i| number(i).as_ref() == Some(&want))
                    {
                        out.push(start..k + 1);
                    }
                }
                if code.starts_with("WHILE") {
                    let n = code
                        .rfind("DO")
                        .and_then(|at| code.get(at + 2..))
                        .unwrap_or("");
                    if !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()) {
                        let end = format!("END{n}");
                        out.extend(close(k, &|i| {
                            upper.get(i).is_some_and(|x| x.concat() == end)
                        }));
                    }
                }
                // LinuxCNC: `o100 repeat [3]` … `o100 endrepeat`, `o100 while` … `o100
                // endwhile`, `o100 do` … `o100 while`.
                // The keyword's letters alone (`REPEAT[100]`).
                let letters = |x: &String| -> String {
                    x.chars().take_while(|c| c.is_ascii_alphabetic()).collect()
                };
                if let [o, kind, ..] = w.as_slice() {
                    if o.starts_with('O') {
                        let end = match letters(kind).as_str() {
                            "REPEAT" => Some("ENDREPEAT"),
                            "WHILE" => Some("ENDWHILE"),
                            "DO" => Some("WHILE"),
                            _ => None,
                        };
                        if let Some(end) = end {
                            let o = o.clone();
                            out.extend(close(k, &|i| {
                                upper.get(i).is_some_and(|x| {
                                    x.first() == Some(&o)
                                        && x.get(1).is_some_and(|y| letters(y) == end)
                                })
                            }));
                        }
                    }
                }
            }
            Dialect::Sinumerik => {
                let pairs = [
                    ("WHILE", "ENDWHILE"),
                    ("FOR", "ENDFOR"),
                    ("LOOP", "ENDLOOP"),
                    ("REPEAT", "UNTIL"),
                ];
                for (open, end) in pairs {
                    // `REPEAT` with a label is the section repeat below.
                    if first(k) == open && !(open == "REPEAT" && w.len() > 1) {
                        out.extend(close(k, &|i| first(i) == end));
                    }
                }
                // A jump back to a label above (`IF R1<4 GOTOB MARK`, `GOTO MARK`,
                // `GOTOC MARK`; the label alone on its line or before the block's words).
                if let Some(g) = w
                    .iter()
                    .position(|x| matches!(x.as_str(), "GOTOB" | "GOTO" | "GOTOC"))
                {
                    if let Some(name) = w.get(g + 1) {
                        let name = format!("{name}:");
                        if let Some(at) = (0..k).rev().find(|&i| first(i) == name) {
                            out.push(at..k + 1);
                        }
                    }
                }
                if let (Some(x), Some(label)) = (w.first(), w.get(1)) {
                    if (x == "REPEAT" || x == "REPEATB") && w.iter().any(|y| y.starts_with("P=")) {
                        let name = format!("{label}:");
                        if let Some(at) = (0..k).rev().find(|&i| first(i) == name) {
                            out.push(at..k + 1);
                        }
                    }
                }
            }
            Dialect::Twincat => {
                for (open, end) in [
                    ("$WHILE", "$ENDWHILE"),
                    ("$FOR", "$ENDFOR"),
                    ("$REPEAT", "$UNTIL"),
                ] {
                    if first(k) == open {
                        out.extend(close(k, &|i| first(i) == end));
                    }
                }
            }
            Dialect::Heidenhain => {
                // A conditional jump back to a label above: `FN 12: IF +Q1 LT +4 GOTO LBL 1`.
                if let Some(g) = w.iter().position(|x| x == "GOTO") {
                    if w.get(g + 1).is_some_and(|x| x == "LBL") {
                        if let Some(name) = w.get(g + 2) {
                            let at = (0..k).rev().find(|&i| {
                                upper.get(i).is_some_and(|x| {
                                    x.first().is_some_and(|y| y == "LBL") && x.get(1) == Some(name)
                                })
                            });
                            if let Some(at) = at {
                                out.push(at..k + 1);
                            }
                        }
                    }
                }
            }
        }
    }
    out
}

impl Labels {
    /// The labels and subprograms of `text` (Heidenhain labels; ISO-style program numbers,
    /// and Haas's block numbers for `M97`; none in SINUMERIK and TwinCAT, whose subprograms
    /// are files of their own).
    pub fn new(dialect: Dialect, text: &str) -> Labels {
        let lines: Vec<String> = text
            .lines()
            .map(|l| l.trim_end_matches('\r').to_string())
            .collect();
        // SINUMERIK and TwinCAT subprograms are files of their own: nothing defined here.
        let defined = if follows(dialect) {
            lines
                .iter()
                .enumerate()
                .filter_map(|(k, l)| defined(dialect, l).map(|name| (name, k)))
                .collect()
        } else {
            Vec::new()
        };
        let mut labels = Labels {
            dialect,
            lines,
            defined,
            entered: Vec::new(),
            params: Params::scan(dialect, text),
            runs: Vec::new(),
            loops: Vec::new(),
            read_from: Vec::new(),
        };
        labels.loops = loops(dialect, &labels.lines);
        if follows(dialect) {
            // Each call's body and runs; a body's total is the sum over the calls to it of
            // their runs times the runs of the body each call stands in (nested calls
            // multiply), found by passes up to the nesting followed.
            let mut calls = Vec::new();
            for k in 0..labels.lines.len() {
                let call = labels.lines.get(k).and_then(|l| called(dialect, l));
                if let Some((at, rep)) = call.and_then(|c| labels.target(c, k)) {
                    calls.push((k, labels.body(k, at, rep)));
                }
            }
            for _ in 0..=DEPTH {
                let mut runs: Vec<(std::ops::Range<usize>, usize)> = Vec::new();
                for (k, (body, times, section)) in &calls {
                    let outer = labels.repeated(*k).unwrap_or(1);
                    let total = (times + usize::from(*section)).saturating_mul(outer);
                    match runs.iter_mut().find(|(b, _)| b == body) {
                        Some((_, n)) => *n = n.saturating_add(total),
                        None => runs.push((body.clone(), total)),
                    }
                }
                if runs == labels.runs {
                    break;
                }
                labels.runs = runs;
            }
        }
        labels
    }

    /// How often the program runs line `k` (0-based) through its calls, if more than once.
    pub fn repeated(&self, k: usize) -> Option<usize> {
        self.runs
            .iter()
            .filter(|(body, _)| body.contains(&k))
            .map(|(_, n)| *n)
            .max()
            .filter(|n| *n > 1)
    }

    /// The lines run more than once (by calls or a loop) that contain line `k` (0-based).
    pub fn repeated_lines(&self, k: usize) -> Vec<std::ops::Range<usize>> {
        let runs = self
            .runs
            .iter()
            .filter(|(b, n)| *n > 1 && b.contains(&k))
            .map(|(b, _)| b.clone());
        let loops = self.loops.iter().filter(|l| l.contains(&k)).cloned();
        runs.chain(loops).collect()
    }

    /// Whether line `k` (0-based) stands in one of the program's loops.
    pub fn looped(&self, k: usize) -> bool {
        self.loops.iter().any(|l| l.contains(&k))
    }

    /// The lines of the subprogram that starts at line `at` (0-based): what a call runs.
    pub fn body_of(&self, at: usize) -> std::ops::Range<usize> {
        self.body(0, at, 1).0
    }

    /// Whether the subprogram at line `at`, read from `p`, only sets the frame and ends
    /// untilted (hyperMILL's reset: cycle 7's zeros, `PLANE RESET`): its translation from one
    /// call's frame is then right from any, nothing moving in between.
    pub fn only_resets(&self, at: usize, p: &Program) -> bool {
        let mut q = *p;
        for i in self.body_of(at) {
            let Some(line) = self.lines.get(i) else {
                continue;
            };
            if line.trim().is_empty() {
                continue;
            }
            match q.line(self.dialect, line.as_bytes()) {
                Ok((next, Remark::Applied)) => q = next,
                _ => return false,
            }
        }
        q.frame.rotation == cncrot::IDENTITY && q.direct.is_none()
    }

    /// The parameters the program sets once to a number.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// Before line `k` (0-based) is read: a subprogram reached after a call to it is read
    /// from the state of a call, not from the blocks above it: the first call made with a
    /// tilt active, its way of moving and choice of solution cleared (the axes are where that
    /// call left them), else the first call \[choice: translated from a tilt, a shift in the
    /// subprogram is written after the target's cancel and the tilt again without a turn,
    /// which is right whatever the call's frame when the subprogram ends in a cancel, as a
    /// reset does; from no tilt, a Fanuc would meet its `G52` in `G68.2` mode\]. Returns the
    /// line (0-based) of that call and those of the calls made with another frame active, for
    /// which its translation may not fit; `None` where no subprogram starts.
    pub fn enter(&mut self, k: usize, p: &mut Program) -> Option<(usize, Vec<usize>)> {
        let calls: Vec<&(usize, usize, Program)> =
            self.entered.iter().filter(|(at, _, _)| *at == k).collect();
        // A label or subprogram reached in the file's order before any call to it: the frame
        // its blocks are read (and translated) from, for a call below it to compare.
        if calls.is_empty() && self.defined.iter().any(|d| d.1 == k) {
            self.read_from.push((k, *p));
            return None;
        }
        let tilted = |q: &Program| q.frame.rotation != cncrot::IDENTITY || q.direct.is_some();
        let &&(_, from, q) = calls.iter().find(|(_, _, q)| tilted(q)).or(calls.first())?;
        let entry = if tilted(&q) {
            Program {
                choice: AxisChoice::Closest,
                ..q.staying()
            }
        } else {
            q
        };
        *p = entry;
        let frame = |q: &Program| (q.frame, q.shift, q.direct, q.angles);
        let others = calls
            .iter()
            .filter(|(_, _, q)| frame(q) != frame(&entry))
            .map(|(_, line, _)| *line)
            .collect();
        Some((from, others))
    }

    /// After line `k` was read (and passed over): the state a call there leaves.
    pub fn after(&mut self, k: usize, p: &mut Program) -> Option<Called> {
        if let Some(name) = self.lines.get(k).and_then(|l| external(self.dialect, l)) {
            return Some(Called::Elsewhere(name));
        }
        if !follows(self.dialect) {
            return None;
        }
        let call = self.lines.get(k).and_then(|l| called(self.dialect, l))?;
        // Haas's `M97 P1000` jumps to the block numbered so: the first such after the call's
        // line or, failing that, any (block numbers repeat in programs).
        let name = if self.dialect == Dialect::Heidenhain {
            format!("LBL {}", call.0)
        } else {
            call.0.clone()
        };
        let Some((at, rep)) = self.target(call, k) else {
            return Some(Called::Elsewhere(name));
        };
        if at > k {
            self.entered.push((at, k, *p));
        }
        let (_, _, section) = self.body(k, at, rep);
        let frame = |q: &Program| (q.frame, q.shift, q.direct, q.angles);
        let above = (at < k && !section)
            .then(|| self.read_from.iter().find(|r| r.0 == at))
            .flatten()
            .filter(|r| frame(&r.1) != frame(p))
            .map(|r| Called::Above(r.0));
        let mut budget = BUDGET;
        let whole = self.run(k, at, rep, p, 0, &mut budget);
        above.or(whole.err().map(Called::Cut))
    }

    /// The line a call `(name, runs)` at line `k` goes to, and its runs: the label or
    /// subprogram of that name or, for an ISO `M98 P` of more than four digits whose program
    /// is not in the file, the older form: the last four digits the program, the first the
    /// count (`M98 P32000`: `O2000` three times \[doc: Fanuc's `M98 P68003`, `O8003` six
    /// times\]). Runs beyond 9 999 (the most `L` says) are 9 999.
    fn target(&self, (name, runs): (String, usize), k: usize) -> Option<(usize, usize)> {
        let runs = runs.min(9_999);
        if let Some(at) = self.find(&name, k) {
            return Some((at, runs));
        }
        let n: u32 = name.strip_prefix('O')?.parse().ok()?;
        let at = (n >= 10_000)
            .then(|| self.find(&format!("O{}", n % 10_000), k))
            .flatten()?;
        Some((at, (n / 10_000) as usize))
    }

    /// The line that defines `name`, for a call at line `k`: the first definition after the
    /// call, else the first.
    fn find(&self, name: &str, k: usize) -> Option<usize> {
        let mut at = self.defined.iter().filter(|(n, _)| n == name).map(|d| d.1);
        let first = at.next()?;
        Some(
            std::iter::once(first)
                .chain(at)
                .find(|&a| a > k)
                .unwrap_or(first),
        )
    }

    /// The lines the call at line `k` to the label at line `at` runs, how often, and whether
    /// they are a section above the call (read once in the file's order before it): see
    /// [`Labels::run`].
    fn body(&self, k: usize, at: usize, rep: usize) -> (std::ops::Range<usize>, usize, bool) {
        let end = |from: usize| {
            (from..self.lines.len())
                .find(|&i| self.lines.get(i).is_some_and(|l| ends(self.dialect, l)))
                .unwrap_or(self.lines.len())
        };
        if self.dialect != Dialect::Heidenhain {
            // An ISO subprogram runs from its first block (Haas's `N1000` is one) to its
            // `M99`, as often as the call says.
            let numbered = self
                .lines
                .get(at)
                .is_some_and(|l| iso_words(l).first().is_some_and(|w| w.0 == 'O'));
            let first = at + usize::from(numbered);
            return (first..end(first), rep, false);
        }
        if at < k && (rep > 0 || end(at + 1) > k) {
            (at + 1..k, rep, true)
        } else {
            (at + 1..end(at + 1), 1, false)
        }
    }

    /// Runs the label defined at line `at` as the call at line `k` does: a program section
    /// above the call, repeated (`REP`: the section again, `rep` times, whatever `LBL 0` stands
    /// in it — the TNC's dialog makes a call with `REP` a section repeat, one without a
    /// subprogram call) or without a `LBL 0` between, else a subprogram up to its `LBL 0`
    /// (once). A pass that leaves the frame as it found it ends the runs (every further pass
    /// would too). An error: where the follow stopped.
    fn run(
        &self,
        k: usize,
        at: usize,
        rep: usize,
        p: &mut Program,
        depth: usize,
        budget: &mut usize,
    ) -> Result<(), Cut> {
        let (body, times, _) = self.body(k, at, rep);
        for _ in 0..times {
            let before = *p;
            for i in body.clone() {
                // A bounded follow: calls that would read more blocks than that stop there.
                let Some(left) = budget.checked_sub(1) else {
                    return Err(Cut::Budget);
                };
                *budget = left;
                let Some(line) = self.lines.get(i) else {
                    continue;
                };
                // Run from the call at line k: what is assigned above the call.
                let resolved = self.params.resolve(line, p, k);
                let text = resolved.as_ref().map_or(line.as_str(), |(t, _)| t.as_str());
                if let Ok((next, Remark::Applied)) = p.line(self.dialect, text.as_bytes()) {
                    *p = next;
                }
                let inner = called(self.dialect, line).and_then(|c| self.target(c, i));
                if let Some((at, r)) = inner {
                    if depth + 1 >= DEPTH {
                        return Err(Cut::Depth);
                    }
                    self.run(i, at, r, p, depth + 1, budget)?;
                }
            }
            if *p == before {
                break;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_of_labels_and_calls() {
        let h = Dialect::Heidenhain;
        assert_eq!(
            defined(h, "79 LBL 1 ; RESET WORKING PLANE"),
            Some("1".into())
        );
        assert_eq!(defined(h, "LBL \"FACE\""), Some("\"FACE\"".into()));
        assert_eq!(defined(h, "85 LBL 0"), None);
        assert!(ends(h, "85 LBL 0"));
        assert_eq!(called(h, "65 CALL LBL 1 ; RESET"), Some(("1".into(), 0)));
        assert_eq!(called(h, "12 CALL LBL 2 REP 3/3"), Some(("2".into(), 3)));
        assert_eq!(called(h, "CALL LBL 1 REP6"), Some(("1".into(), 6)));
        assert_eq!(called(h, "CALL LBL 1 REPQ106 ;"), Some(("1".into(), 0)));
        assert_eq!(called(h, "12 CALL PGM TNC:\\X.H"), None);
        // ISO subprograms: `O2000` … `M99`, called by `M98 P2000` (`L`/`K` the runs);
        // Haas's `M97 P1000` to its block `N1000`.
        let (f, haas) = (Dialect::Fanuc, Dialect::Haas);
        assert_eq!(defined(f, "O2000 (FACE B)"), Some("O2000".into()));
        assert_eq!(defined(f, ":2000"), Some("O2000".into()));
        assert_eq!(defined(f, "N1000 G0 X0"), None);
        assert_eq!(defined(haas, "N1000 G0 X0"), Some("N1000".into()));
        assert!(ends(f, "N90 M99") && ends(f, "M99 (BACK)") && !ends(f, "M98 P2000"));
        assert_eq!(called(f, "N20 M98 P2000"), Some(("O2000".into(), 1)));
        assert_eq!(called(f, "M98P2000L3"), Some(("O2000".into(), 3)));
        assert_eq!(called(f, "M98 P2000 K2 (TWICE)"), Some(("O2000".into(), 2)));
        assert_eq!(called(haas, "M97 P1000"), Some(("N1000".into(), 1)));
        assert_eq!(called(f, "M97 P1000"), None);
        assert_eq!(called(f, "(M98 P2000)"), None);
    }

    #[test]
    fn loops_of_every_dialect() {
        let lines = |t: &str| t.lines().map(String::from).collect::<Vec<_>>();
        let f = lines("G68.2 J90.\nN40 WHILE[#1LT4]DO1\nG68.4 K90.\nN90 END1\nM30");
        assert_eq!(
            loops(Dialect::Fanuc, &f),
            vec![std::ops::Range { start: 1, end: 4 }]
        );
        let l = lines(
            "o100 REPEAT[100]\n g68.4 i35\no100 ENDREPEAT\no200 do\nG0 X0\no200 while [#1 lt 3]",
        );
        assert_eq!(loops(Dialect::Fanuc, &l), [0..3, 3..6]);
        let s = lines("SIDE:\nCYCLE800(0,\"\",1,57,0,0,0,90)\nENDSIDE:\nREPEAT SIDE ENDSIDE P=3\nWHILE R1<4\nAROT Z90\nENDWHILE");
        assert_eq!(loops(Dialect::Sinumerik, &s), [0..4, 4..7]);
        let t = lines("$FOR P1=0,3,1\nAROT Z90\n$ENDFOR");
        assert_eq!(
            loops(Dialect::Twincat, &t),
            vec![std::ops::Range { start: 0, end: 3 }]
        );
        let h = lines(
            "1 LBL 5\n2 PLANE RELATIV SPC+90 STAY\n3 FN 12: IF +Q1 LT +4 GOTO LBL 5\n4 LBL 0",
        );
        assert_eq!(
            loops(Dialect::Heidenhain, &h),
            vec![std::ops::Range { start: 0, end: 3 }]
        );
        // No loop: a `DO` without `WHILE`, an `END1` alone, a jump forward.
        let none = lines("G0 X0 (DO1)\nEND1\nIF [#1 GT 0] GOTO 100");
        assert!(loops(Dialect::Fanuc, &none).is_empty());
    }
}
