//! Writing results: numbers with a chosen count of decimals (or the shortest exact ones),
//! and JSON for machines.

use std::fmt::Write;

/// `x` with `decimals` decimals (`-1`: the shortest text that reads back to `x`); never
/// `-0`.
pub fn num(x: f64, decimals: i32) -> String {
    let s = match usize::try_from(decimals) {
        Ok(d) => format!("{x:.d$}"),
        Err(_) => format!("{x}"),
    };
    match s.strip_prefix('-') {
        Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
        _ => s,
    }
}

/// Numbers separated by spaces.
pub fn nums(v: &[f64], decimals: i32) -> String {
    v.iter()
        .map(|&x| num(x, decimals))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A JSON value. Numbers are written as the shortest text that reads back exactly.
#[derive(Clone, Debug)]
pub enum Json {
    Num(f64),
    Int(i64),
    Bool(bool),
    Str(String),
    Arr(Vec<Json>),
    Obj(Vec<(&'static str, Json)>),
}

impl Json {
    pub fn nums(v: &[f64]) -> Json {
        Json::Arr(v.iter().map(|&x| Json::Num(x)).collect())
    }

    pub fn matrix(m: &[[f64; 3]; 3]) -> Json {
        Json::Arr(m.iter().map(|r| Json::nums(r)).collect())
    }

    pub fn str(s: impl Into<String>) -> Json {
        Json::Str(s.into())
    }

    /// Adds a field to an object (no effect on other values).
    pub fn with(mut self, key: &'static str, value: Json) -> Json {
        if let Json::Obj(fields) = &mut self {
            fields.push((key, value));
        }
        self
    }

    pub fn write(&self, out: &mut String) {
        match self {
            // The library never returns a non-finite number as a result; null if it did.
            Json::Num(x) if x.is_finite() => {
                let _ = write!(out, "{}", if *x == 0.0 { 0.0 } else { *x });
            }
            Json::Num(_) => out.push_str("null"),
            Json::Int(i) => {
                let _ = write!(out, "{i}");
            }
            Json::Bool(b) => {
                let _ = write!(out, "{b}");
            }
            Json::Str(s) => {
                out.push('"');
                for c in s.chars() {
                    match c {
                        '"' => out.push_str("\\\""),
                        '\\' => out.push_str("\\\\"),
                        '\n' => out.push_str("\\n"),
                        '\r' => out.push_str("\\r"),
                        '\t' => out.push_str("\\t"),
                        c if (c as u32) < 0x20 => {
                            let _ = write!(out, "\\u{:04x}", c as u32);
                        }
                        c => out.push(c),
                    }
                }
                out.push('"');
            }
            Json::Arr(v) => {
                out.push('[');
                for (i, x) in v.iter().enumerate() {
                    if i > 0 {
                        out.push(',');
                    }
                    x.write(out);
                }
                out.push(']');
            }
            Json::Obj(fields) => {
                out.push('{');
                for (i, (k, v)) in fields.iter().enumerate() {
                    if i > 0 {
                        out.push(',');
                    }
                    Json::Str((*k).to_string()).write(out);
                    out.push(':');
                    v.write(out);
                }
                out.push('}');
            }
        }
    }

    pub fn text(&self) -> String {
        let mut s = String::new();
        self.write(&mut s);
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_as_written() {
        assert_eq!(num(37.79231, 4), "37.7923");
        assert_eq!(num(-0.00001, 4), "0.0000");
        assert_eq!(num(-0.0, -1), "0");
        assert_eq!(num(0.1 + 0.2, -1), "0.30000000000000004");
    }

    #[test]
    fn json_escapes_and_numbers() {
        let j = Json::Obj(vec![
            ("a", Json::str("q\"\\\n\u{1}")),
            ("b", Json::nums(&[-0.0, 1.5, f64::NAN])),
        ]);
        assert_eq!(j.text(), r#"{"a":"q\"\\\n\u0001","b":[0,1.5,null]}"#);
    }
}
