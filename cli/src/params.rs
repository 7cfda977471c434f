//! Parameters a program sets once to a number and uses in a tilt block (`FN 0: Q1 = +30`
//! then `PLANE SPATIAL SPA+0 SPB+Q1 SPC+0 TURN FMAX`; `#1=30.` then `G68.2 … J#1 …`;
//! `R1=30` then `CYCLE800(…,R1,…)`). The library reads numbers only: such a block is
//! refused where a variable stands. The command has the whole file: a parameter that the
//! file assigns exactly once, to a constant, has that value wherever the block stands (no
//! branch or loop can give it another), and the block is read with it. A parameter assigned
//! more than once, by an expression, or not at all (a probing cycle's result, a value set
//! at the control) is not known, and the block stays refused.

use cncrot::dialects::program::{Dialect, Program};
use cncrot::Error;
use std::collections::HashMap;

/// What a file assigns to one parameter.
enum Assigned {
    /// One constant, on this line (0-based).
    Once(f64, usize),
    /// Twice or more, or by something other than a constant.
    Unknown,
}

/// The parameters of a whole program, as its lines assign them.
pub struct Params {
    dialect: Dialect,
    values: HashMap<String, Assigned>,
    /// SINUMERIK's user variables (`DEF REAL ANGLE`).
    declared: Vec<String>,
}

/// Each block's code: after its block number (Heidenhain's line number, ISO's `N…`) and
/// before its comment, in capitals.
fn code(block: &str, dialect: Dialect) -> String {
    let mut text = block.trim_start();
    if let Some(rest) = text.strip_prefix('/') {
        text = rest.trim_start_matches(|c: char| c.is_ascii_digit());
    }
    let text = match dialect {
        Dialect::Heidenhain => text.trim_start_matches(|c: char| c.is_ascii_digit()),
        _ => match text.strip_prefix(['N', 'n']) {
            Some(r) if r.starts_with(|c: char| c.is_ascii_digit()) => {
                r.trim_start_matches(|c: char| c.is_ascii_digit())
            }
            _ => text,
        },
    };
    let end = match dialect {
        Dialect::Sinumerik | Dialect::Heidenhain => text.find(';'),
        _ => text.find(['(', ';']),
    };
    text[..end.unwrap_or(text.len())]
        .trim()
        .to_ascii_uppercase()
}

/// A number as programs write it: a sign, digits with a point (or Heidenhain's comma).
fn constant(text: &str) -> Option<f64> {
    let t = text.trim().replace(',', ".");
    let digits = t.trim_start_matches(['+', '-']);
    let ok = !digits.is_empty()
        && t.len() - digits.len() <= 1
        && digits.bytes().all(|b| b.is_ascii_digit() || b == b'.')
        && digits.bytes().filter(|&b| b == b'.').count() <= 1
        && digits.bytes().any(|b| b.is_ascii_digit());
    ok.then(|| t.parse().ok()).flatten()
}

/// The parameter name at the start of `s` in `dialect` (`Q1`, `QL2`, `QR3`; `#1`; `R1` or a
/// declared name), with its length.
fn name_at(s: &str, dialect: Dialect, declared: &[String]) -> Option<(String, usize)> {
    let digits = |r: &str| r.bytes().take_while(u8::is_ascii_digit).count();
    match dialect {
        Dialect::Heidenhain => {
            let r = s.strip_prefix('Q')?;
            let prefix = usize::from(r.starts_with(['L', 'R']));
            let n = digits(&r[prefix..]);
            (n > 0).then(|| (s[..1 + prefix + n].to_string(), 1 + prefix + n))
        }
        Dialect::Fanuc | Dialect::Syntec | Dialect::Haas => {
            let n = digits(s.strip_prefix('#')?);
            (n > 0).then(|| (s[..1 + n].to_string(), 1 + n))
        }
        Dialect::Sinumerik | Dialect::Twincat => {
            let len = s
                .bytes()
                .take_while(|b| b.is_ascii_alphanumeric() || *b == b'_')
                .count();
            let word = &s[..len];
            let r_param = word.len() > 1
                && word.starts_with('R')
                && word[1..].bytes().all(|b| b.is_ascii_digit());
            (r_param || declared.iter().any(|d| d == word)).then(|| (word.to_string(), len))
        }
    }
}

/// Whether `s` has a name character at byte `at` (a name there runs on).
fn name_char(s: &str, at: usize) -> bool {
    s.as_bytes()
        .get(at)
        .is_some_and(|b| b.is_ascii_alphanumeric() || *b == b'_')
}

impl Params {
    /// The assignments of a whole program text.
    pub fn scan(dialect: Dialect, text: &str) -> Params {
        let lines: Vec<String> = text.lines().map(|l| code(l, dialect)).collect();
        // SINUMERIK's user variables (`DEF REAL ANGLE=30`, `DEF REAL A, B`).
        let mut declared = Vec::new();
        if dialect == Dialect::Sinumerik {
            for l in &lines {
                if let Some(rest) = l.strip_prefix("DEF REAL ") {
                    for d in rest.split(',') {
                        let name = d.split('=').next().unwrap_or("").trim();
                        if !name.is_empty() {
                            declared.push(name.to_string());
                        }
                    }
                }
            }
        }
        let mut values: HashMap<String, Assigned> = HashMap::new();
        let mut assign = |name: String, value: Option<f64>, k: usize| {
            let entry = match (values.get(&name), value) {
                (None, Some(v)) => Assigned::Once(v, k),
                _ => Assigned::Unknown,
            };
            values.insert(name, entry);
        };
        for (k, l) in lines.iter().enumerate() {
            let body = match dialect {
                Dialect::Heidenhain => l
                    .strip_prefix("FN")
                    .and_then(|r| r.trim_start().strip_prefix('0'))
                    .and_then(|r| r.trim_start().strip_prefix(':'))
                    .map_or(l.as_str(), str::trim_start),
                Dialect::Sinumerik => l.strip_prefix("DEF REAL ").unwrap_or(l),
                _ => l,
            };
            // A whole block of `name = constant` (SINUMERIK and TwinCAT: several, `R1=30 R2=5`,
            // or declared with commas).
            let pieces: Vec<String> = match dialect {
                Dialect::Sinumerik | Dialect::Twincat => {
                    let mut t = body.to_string();
                    while t.contains(" =") || t.contains("= ") {
                        t = t.replace(" =", "=").replace("= ", "=");
                    }
                    t.split([' ', ','])
                        .filter(|p| !p.is_empty())
                        .map(String::from)
                        .collect()
                }
                _ => vec![body.to_string()],
            };
            let mut all_constant = !pieces.is_empty();
            let mut found = Vec::new();
            for piece in &pieces {
                let parsed = name_at(piece, dialect, &declared).and_then(|(name, len)| {
                    let rest = piece[len..].trim_start().strip_prefix('=')?;
                    Some((name, constant(rest)))
                });
                match parsed {
                    Some((name, Some(v))) => found.push((name, v)),
                    _ => all_constant = false,
                }
            }
            if all_constant {
                for (name, v) in found {
                    assign(name, Some(v), k);
                }
                continue;
            }
            // TwinCAT's rotation functions write their results into the parameters they name
            // (`CalcInvRot[R1; R2; R3]`): none of them is known after.
            let writes_all = dialect == Dialect::Twincat
                && ["CALCROT", "CALCINVROT", "ROTVEC"]
                    .iter()
                    .any(|f| l.contains(f));
            // Any other assignment makes its parameter not known: `name =` anywhere, not
            // `==` (a comparison), not `<=`, `>=`, `<>` (`FN 1: Q1 = +Q1 + +5`, `#1=#1+90`,
            // `R1=R1+15`, a system read).
            let mut at = 0;
            while at < l.len() {
                let starts = at == 0 || !name_char(l, at - 1) || l[at..].starts_with('#');
                if let Some((name, len)) = starts
                    .then(|| name_at(&l[at..], dialect, &declared))
                    .flatten()
                {
                    let after = l[at + len..].trim_start();
                    let assigned = after.starts_with('=') && !after.starts_with("==");
                    if !name_char(l, at + len) && (assigned || writes_all) {
                        assign(name, None, k);
                    }
                    at += len;
                } else {
                    at += l[at..].chars().next().map_or(1, char::len_utf8);
                }
            }
        }
        // An assignment a jump may pass over, or that only a condition runs, holds no value
        // the block below can count on (`IF [#5 EQ 1] GOTO10` before `#2=30.`).
        let raw: Vec<String> = text.lines().map(|l| l.trim().to_uppercase()).collect();
        for range in conditional(dialect, &lines, &raw) {
            for v in values.values_mut() {
                if matches!(v, Assigned::Once(_, at) if range.contains(at)) {
                    *v = Assigned::Unknown;
                }
            }
        }
        // A macro called with arguments (`G65 P3000 A30.`, `G66`) runs on a level of local
        // variables of its own, `#1`–`#33` set from its arguments ("each time a macro is
        // called (with G65 or G66), the local variable level is incremented", Fanuc's
        // operator's manual): an assignment the main program makes to them is not the
        // macro's [choice: none of them is read with a value in such a program].
        let iso = matches!(dialect, Dialect::Fanuc | Dialect::Haas | Dialect::Syntec);
        let macro_calls = lines.iter().any(|l| {
            let joined: String = l.split_whitespace().collect();
            ["G65", "G66"].iter().any(|g| {
                joined.match_indices(g).any(|(i, _)| {
                    !joined[i + g.len()..].starts_with(|c: char| c.is_ascii_digit() || c == '.')
                })
            })
        });
        if iso && macro_calls {
            for (name, v) in values.iter_mut() {
                let local = name[1..]
                    .parse::<u32>()
                    .is_ok_and(|n| (1..=33).contains(&n));
                if local {
                    *v = Assigned::Unknown;
                }
            }
        }
        Params {
            dialect,
            values,
            declared,
        }
    }

    /// `block` with every parameter it uses replaced by its value, and what was replaced
    /// (`Q1 = 30 (line 4)`), when the library refuses the block where a variable stands, every
    /// parameter it uses is known and assigned on a line above `runs_at` (0-based: the
    /// block's own line, or the call that runs it; a use before its assignment reads the
    /// value the control held before, which the program does not state), and the replaced
    /// block is read on `p`; `None` otherwise.
    pub fn resolve(&self, block: &str, p: &Program, runs_at: usize) -> Option<(String, String)> {
        if self.values.is_empty() {
            return None;
        }
        match p.line(self.dialect, block.as_bytes()) {
            Err(e) if e.error == Error::NotANumber => {}
            _ => return None,
        }
        let declared = &self.declared;
        let mut out = String::new();
        let mut used: Vec<String> = Vec::new();
        let mut at = 0;
        // ASCII capitals: the same byte positions as `block`.
        let upper = block.to_ascii_uppercase();
        // Up to the comment: a parameter named in a comment is no use of it.
        let end = code_end(&upper, self.dialect);
        while at < block.len() {
            // (`#` starts a name after an address letter: `J#1`.)
            let starts = at == 0 || !name_char(&upper, at - 1) || upper[at..].starts_with('#');
            let found = (starts && at < end)
                .then(|| name_at(&upper[at..], self.dialect, declared))
                .flatten()
                .filter(|(_, len)| !name_char(&upper, at + len));
            let Some((name, len)) = found else {
                let c = block[at..].chars().next().unwrap_or(' ');
                out.push(c);
                at += c.len_utf8();
                continue;
            };
            let Some(&Assigned::Once(value, line)) = self.values.get(&name) else {
                return None;
            };
            if line >= runs_at {
                return None;
            }
            // A sign before the parameter applies to its value (`SPB-Q1`, `J-#1`).
            let negated = out.ends_with('-');
            let signed = negated || out.ends_with('+');
            if signed {
                out.pop();
            }
            let v = if negated { -value } else { value };
            out.push_str(&self.number(v, signed));
            let note = format!("{name} = {} (line {})", self.number(value, false), line + 1);
            if !used.contains(&note) {
                used.push(note);
            }
            at += len;
        }
        match p.line(self.dialect, out.as_bytes()) {
            Ok(_) => Some((out, used.join(", "))),
            Err(_) => None,
        }
    }

    /// `v` as the dialect writes a number: Heidenhain with its sign where one stood, the ISO
    /// dialects with a point (a number without one may be read in thousandths).
    fn number(&self, v: f64, signed: bool) -> String {
        let v = v + 0.0;
        let mut s = format!("{v}");
        if matches!(
            self.dialect,
            Dialect::Fanuc | Dialect::Syntec | Dialect::Haas
        ) && !s.contains('.')
        {
            s.push('.');
        }
        if (signed || self.dialect == Dialect::Heidenhain) && v >= 0.0 {
            s.insert(0, '+');
        }
        s
    }
}

/// The lines a program runs only on a condition: those a forward jump passes over (ISO
/// `GOTO10` to `N10` below, SINUMERIK `GOTOF`/`GOTO`/`GOTOC` to a label below, Heidenhain
/// `GOTO LBL` to a label below, TwinCAT `$GOTO`), the bodies of `IF … ENDIF` (SINUMERIK,
/// TwinCAT's `$IF … $ENDIF`), and an ISO `IF […] THEN` line. `codes` are the blocks'
/// codes, `raw` the lines in capitals (with their block numbers).
fn conditional(dialect: Dialect, codes: &[String], raw: &[String]) -> Vec<std::ops::Range<usize>> {
    let mut out = Vec::new();
    let number = |i: usize| raw.get(i).and_then(|l| block_number_of(l));
    let label_at = |i: usize, name: &str| {
        codes.get(i).is_some_and(|c| {
            let first = c.split_whitespace().next().unwrap_or("");
            first == format!("{name}:")
                || (c.starts_with("LBL") && c[3..].trim().trim_matches('"') == name)
        })
    };
    for (k, code) in codes.iter().enumerate() {
        let words: Vec<&str> = code.split_whitespace().collect();
        let below = |found: &dyn Fn(usize) -> bool| (k + 1..codes.len()).find(|&i| found(i));
        // A block the skip switch may leave out (`/#100=30.`, Heidenhain's `12 /…`).
        let line = raw.get(k).map_or("", String::as_str);
        let line = match dialect {
            Dialect::Heidenhain => line.trim_start_matches(|c: char| c.is_ascii_digit()),
            _ => line,
        };
        if line.trim_start().starts_with('/') {
            out.push(k..k + 1);
        }
        // A loop's body, which runs no time when the condition fails at once (`WHILE [#1
        // LT 3] DO1` … `END1`; SINUMERIK `WHILE` … `ENDWHILE`, TwinCAT `$WHILE` …
        // `$ENDWHILE`).
        let first = words.first().copied().unwrap_or("");
        if first.starts_with("WHILE") || first == "$WHILE" {
            let end = match dialect {
                Dialect::Fanuc | Dialect::Haas | Dialect::Syntec => {
                    let joined = words.concat();
                    joined
                        .rfind("DO")
                        .map(|i| format!("END{}", &joined[i + 2..]))
                        .unwrap_or_default()
                }
                Dialect::Twincat => "$ENDWHILE".to_string(),
                _ => "ENDWHILE".to_string(),
            };
            let ends = |i: usize| {
                codes
                    .get(i)
                    .is_some_and(|c| c.split_whitespace().collect::<String>() == end)
            };
            if let Some(j) = below(&ends) {
                out.push(k + 1..j);
            }
        }
        match dialect {
            Dialect::Fanuc | Dialect::Haas | Dialect::Syntec => {
                let joined = words.concat();
                if joined.starts_with("IF") && joined.contains("THEN") {
                    out.push(k..k + 1);
                }
                if let Some(want) = goto_number(&joined) {
                    if let Some(j) = below(&|i| number(i).as_ref() == Some(&want)) {
                        out.push(k + 1..j);
                    }
                }
            }
            Dialect::Sinumerik | Dialect::Twincat => {
                let jump = words
                    .iter()
                    .position(|w| matches!(*w, "GOTOF" | "GOTO" | "GOTOC" | "$GOTO"));
                if let Some(name) = jump.and_then(|g| words.get(g + 1)) {
                    if let Some(j) = below(&|i| label_at(i, name)) {
                        out.push(k + 1..j);
                    }
                } else if matches!(words.first(), Some(&("IF" | "$IF"))) {
                    let end = if dialect == Dialect::Twincat {
                        "$ENDIF"
                    } else {
                        "ENDIF"
                    };
                    let ends = |i: usize| {
                        codes.get(i).and_then(|c| c.split_whitespace().next()) == Some(end)
                    };
                    if let Some(j) = below(&ends) {
                        out.push(k + 1..j);
                    }
                }
            }
            Dialect::Heidenhain => {
                if let Some(g) = words.iter().position(|w| *w == "GOTO") {
                    if let (Some(&"LBL"), Some(name)) = (words.get(g + 1), words.get(g + 2)) {
                        let name = name.trim_matches('"');
                        if let Some(j) = below(&|i| label_at(i, name)) {
                            out.push(k + 1..j);
                        }
                    }
                }
            }
        }
    }
    out
}

/// The number of the ISO block `line` starts with (`N10`, `n010`, after a skip mark `/`
/// or `/2`), leading zeros dropped: what a jump to it names.
pub(crate) fn block_number_of(line: &str) -> Option<String> {
    let l = line.trim_start().trim_start_matches('/');
    let l = l
        .trim_start_matches(|c: char| c.is_ascii_digit())
        .trim_start();
    let digits: String = l
        .strip_prefix(['N', 'n'])?
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    Some(digits.trim_start_matches('0').to_string())
}

/// The block number an ISO jump goes to (`GOTO10`, `IF[#1LT4]GOTO010`: the block's code in
/// capitals, its words joined), leading zeros dropped; `None` without one (`GOTO#1`).
pub(crate) fn goto_number(joined: &str) -> Option<String> {
    let at = joined.find("GOTO")?;
    let n: String = joined[at + 4..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    (!n.is_empty()).then(|| n.trim_start_matches('0').to_string())
}

/// Where a block's comment begins (its length without one).
fn code_end(block: &str, dialect: Dialect) -> usize {
    let end = match dialect {
        Dialect::Sinumerik | Dialect::Heidenhain => block.find(';'),
        _ => block.find(['(', ';']),
    };
    end.unwrap_or(block.len())
}
