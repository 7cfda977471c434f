//! Heidenhain labels and their calls in a whole program. The library reads a program block
//! by block, and a `CALL LBL` is a block like any other (passed over: it names no frame);
//! the command has the whole file, and follows the call: the frame after it is the one the
//! label's blocks leave. CAM systems write a subprogram that resets the plane and the datum
//! (`CALL LBL 1 ; RESET WORKING PLANE`, the label after the program's end): read in the
//! order of the file, the program would keep the tilt it had before the call, and a
//! translation would turn the axes back to it before the next tilt.

use crate::params::Params;
use cncrot::dialects::program::{AxisChoice, Dialect, Program, Remark};

/// Nested calls followed at most this deep (a label that calls itself stops there).
const DEPTH: usize = 8;

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

/// The label a block defines (`LBL 1`, `LBL "NAME"`), not `LBL 0` (the end of one).
fn defined(block: &str) -> Option<String> {
    match words(block).as_slice() {
        [lbl, name, ..] if lbl == "LBL" && name != "0" => Some(name.clone()),
        _ => None,
    }
}

fn ends(block: &str) -> bool {
    matches!(words(block).as_slice(), [lbl, zero, ..] if lbl == "LBL" && zero == "0")
}

/// The label a block calls and how often it repeats it (`CALL LBL 1 REP 2`, the editor's
/// `REP 2/2`): `(name, repeats)`, 0 without `REP`.
fn called(block: &str) -> Option<(String, usize)> {
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
}

impl Labels {
    /// The labels of `text` (a Heidenhain program; none in the other dialects).
    pub fn new(dialect: Dialect, text: &str) -> Labels {
        let lines: Vec<String> = text
            .lines()
            .map(|l| l.trim_end_matches('\r').to_string())
            .collect();
        let defined = if dialect == Dialect::Heidenhain {
            lines
                .iter()
                .enumerate()
                .filter_map(|(k, l)| defined(l).map(|name| (name, k)))
                .collect()
        } else {
            Vec::new()
        };
        Labels {
            dialect,
            lines,
            defined,
            entered: Vec::new(),
            params: Params::scan(dialect, text),
        }
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
    pub fn enter(&self, k: usize, p: &mut Program) -> Option<(usize, Vec<usize>)> {
        let calls: Vec<&(usize, usize, Program)> =
            self.entered.iter().filter(|(at, _, _)| *at == k).collect();
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
    pub fn after(&mut self, k: usize, p: &mut Program) {
        let Some((name, rep)) = self.lines.get(k).and_then(|l| called(l)) else {
            return;
        };
        let Some(&(_, at)) = self.defined.iter().find(|(n, _)| *n == name) else {
            return;
        };
        if at > k {
            self.entered.push((at, k, *p));
        }
        self.run(k, at, rep, p, 0);
    }

    /// Runs the label defined at line `at` as the call at line `k` does: a program section
    /// above the call, repeated (`REP`: the section again, `rep` times, whatever `LBL 0` stands
    /// in it — the TNC's dialog makes a call with `REP` a section repeat, one without a
    /// subprogram call) or without a `LBL 0` between, else a subprogram up to its `LBL 0`
    /// (once).
    fn run(&self, k: usize, at: usize, rep: usize, p: &mut Program, depth: usize) {
        let end = |from: usize| {
            (from..self.lines.len())
                .find(|&i| self.lines.get(i).is_some_and(|l| ends(l)))
                .unwrap_or(self.lines.len())
        };
        let section = at < k && (rep > 0 || end(at + 1) > k);
        let (body, times) = if section {
            (at + 1..k, rep)
        } else {
            (at + 1..end(at + 1), 1)
        };
        for _ in 0..times {
            for i in body.clone() {
                let Some(line) = self.lines.get(i) else {
                    continue;
                };
                let resolved = self.params.resolve(line, p);
                let text = resolved.as_ref().map_or(line.as_str(), |(t, _)| t.as_str());
                if let Ok((next, Remark::Applied)) = p.line(self.dialect, text.as_bytes()) {
                    *p = next;
                }
                if depth < DEPTH {
                    let inner = called(line).and_then(|(n, r)| {
                        self.defined.iter().find(|(m, _)| *m == n).map(|d| (d.1, r))
                    });
                    if let Some((at, r)) = inner {
                        self.run(i, at, r, p, depth + 1);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_of_labels_and_calls() {
        assert_eq!(defined("79 LBL 1 ; RESET WORKING PLANE"), Some("1".into()));
        assert_eq!(defined("LBL \"FACE\""), Some("\"FACE\"".into()));
        assert_eq!(defined("85 LBL 0"), None);
        assert!(ends("85 LBL 0"));
        assert_eq!(called("65 CALL LBL 1 ; RESET"), Some(("1".into(), 0)));
        assert_eq!(called("12 CALL LBL 2 REP 3/3"), Some(("2".into(), 3)));
        assert_eq!(called("CALL LBL 1 REP6"), Some(("1".into(), 6)));
        assert_eq!(called("CALL LBL 1 REPQ106 ;"), Some(("1".into(), 0)));
        assert_eq!(called("12 CALL PGM TNC:\\X.H"), None);
    }
}
