//! ABI stability (docs/abi.md): every function, struct, enum value and constant of the last
//! released header (`abi/cncrot-X.Y.Z.h`) is in the current header unchanged, unless the
//! version's ABI part (`0.Y` before 1.0, `X` after) changed. Adding is fine.

use std::collections::BTreeMap;
use std::path::Path;

/// The declarations of a header: key (`fn cncrot_x`, `struct cncrot_y`, `enum value
/// CNCROT_Z`, `define CNCROT_W`, `typedef cncrot_v`) → its text with whitespace normalised.
fn declarations(header: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    // Comments out (block and line), then preprocessor lines: `#define` kept as items.
    let mut text = String::new();
    let mut rest = header;
    while let Some(start) = rest.find("/*") {
        text.push_str(&rest[..start]);
        rest = rest[start..]
            .find("*/")
            .map_or("", |end| &rest[start + end + 2..]);
    }
    text.push_str(rest);
    let mut code = String::new();
    for line in text.lines() {
        let line = line.split("//").next().unwrap_or("");
        let t = line.trim();
        if let Some(def) = t.strip_prefix("#define ") {
            let mut parts = def.splitn(2, char::is_whitespace);
            let name = parts.next().unwrap_or("").to_string();
            let value = normalise(parts.next().unwrap_or(""));
            out.insert(format!("define {name}"), value);
        } else if !t.starts_with('#') {
            code.push_str(line);
            code.push('\n');
        }
    }
    let code = code.replace("extern \"C\" {", "");
    // Statements at brace depth 0, ended by `;`.
    let mut depth = 0i32;
    let mut stmt = String::new();
    for c in code.chars() {
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => continue, // the close of `extern "C" {`
            '}' => depth -= 1,
            _ => {}
        }
        stmt.push(c);
        if c == ';' && depth == 0 {
            statement(&normalise(&stmt), &mut out);
            stmt.clear();
        }
    }
    out
}

fn normalise(s: &str) -> String {
    let mut out = s.split_whitespace().collect::<Vec<_>>().join(" ");
    for p in ["(", ")", ",", "*", ";", "{", "}", "[", "]", "="] {
        out = out
            .replace(&format!(" {p}"), p)
            .replace(&format!("{p} "), p);
    }
    out
}

fn statement(s: &str, out: &mut BTreeMap<String, String>) {
    let name_before = |s: &str, end: usize| {
        s[..end]
            .rsplit(|c: char| !(c.is_alphanumeric() || c == '_'))
            .next()
            .unwrap_or("")
            .to_string()
    };
    if let Some(body) = s.strip_prefix("enum ") {
        if let (Some(open), Some(close)) = (body.find('{'), body.rfind('}')) {
            for item in body[open + 1..close].split(',') {
                if let Some((name, value)) = item.split_once('=') {
                    out.insert(format!("enum value {name}"), value.to_string());
                }
            }
        }
    } else if s.starts_with("typedef struct") {
        let name = s
            .trim_end_matches(';')
            .rsplit('}')
            .next()
            .unwrap_or("")
            .to_string();
        out.insert(format!("struct {name}"), s.to_string());
    } else if s.starts_with("typedef") {
        let name = name_before(s, s.len() - 1);
        // `cncrot_status` is typedef'd per language; the enum values are its ABI.
        out.entry(format!("typedef {name}"))
            .or_insert_with(|| s.to_string());
    } else if let Some(open) = s.find('(') {
        out.insert(format!("fn {}", name_before(s, open)), s.to_string());
    }
}

/// The ABI part of a version: `0.Y` for 0.Y.Z, `X` for X.Y.Z.
fn abi(version: &str) -> String {
    let mut parts = version.split('.');
    let major = parts.next().unwrap_or("");
    let minor = parts.next().unwrap_or("");
    if major == "0" {
        format!("0.{minor}")
    } else {
        major.to_string()
    }
}

/// What `new` breaks of `old`.
fn breaks(old: &str, new: &str) -> Vec<String> {
    let new = declarations(new);
    declarations(old)
        .into_iter()
        .filter(|(k, _)| !k.starts_with("define CNCROT_VERSION"))
        .filter(|(k, v)| new.get(k) != Some(v))
        .map(|(k, v)| match new.get(&k) {
            Some(now) => format!("{k} changed: was `{v}`, is `{now}`"),
            None => format!("{k} removed (was `{v}`)"),
        })
        .collect()
}

/// The newest released header and its version.
fn last_release() -> (String, String) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("abi");
    let mut releases: Vec<(Vec<u64>, String, std::path::PathBuf)> = std::fs::read_dir(&dir)
        .expect("abi/ holds the released headers")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter_map(|p| {
            let name = p.file_name()?.to_str()?.to_string();
            let v = name
                .strip_prefix("cncrot-")?
                .strip_suffix(".h")?
                .to_string();
            let key = v.split('.').map(|x| x.parse().unwrap_or(0)).collect();
            Some((key, v, p))
        })
        .collect();
    releases.sort();
    let (_, version, path) = releases.pop().expect("at least one released header");
    (version, std::fs::read_to_string(path).expect("readable"))
}

fn current() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/cncrot.h"))
        .expect("the committed header")
}

#[test]
fn the_header_keeps_the_last_releases_abi() {
    let (version, released) = last_release();
    let now = env!("CARGO_PKG_VERSION");
    if abi(&version) != abi(now) {
        // A new ABI version may change anything; the soname changes with it.
        return;
    }
    let broken = breaks(&released, &current());
    assert!(
        broken.is_empty(),
        "version {now} breaks the ABI of {version} (docs/abi.md):\n{}",
        broken.join("\n")
    );
}

#[test]
fn the_check_reads_the_whole_header() {
    let d = declarations(&current());
    let count = |prefix: &str| d.keys().filter(|k| k.starts_with(prefix)).count();
    // Counted in include/cncrot.h by hand: 38 functions, 6 structs, 30 statuses.
    assert!(count("fn cncrot_") >= 38, "{d:#?}");
    assert!(count("struct cncrot_") >= 6, "{d:#?}");
    assert!(count("enum value CNCROT_STATUS_") >= 30, "{d:#?}");
    assert!(count("define CNCROT_") >= 10, "{d:#?}");
    assert_eq!(
        d.get("fn cncrot_convert").map(String::as_str),
        Some(
            "int32_t cncrot_convert(int32_t intrinsic_in,int32_t sequence_in,const double*angles_in_deg,\
             int32_t intrinsic_out,int32_t sequence_out,double*angles_out_deg);"
        )
    );
    assert_eq!(
        d.get("enum value CNCROT_STATUS_OK").map(String::as_str),
        Some("0")
    );
}

#[test]
fn the_check_fails_on_each_kind_of_break_and_allows_additions() {
    let base = current();
    assert!(breaks(&base, &base).is_empty());
    let added = format!("{base}\nint32_t cncrot_something_new(double *x);\n");
    assert!(
        breaks(&base, &added).is_empty(),
        "{:?}",
        breaks(&base, &added)
    );
    let cases = [
        (
            "int32_t cncrot_convert(",
            "int32_t cncrot_convert_renamed(",
            "fn cncrot_convert removed",
        ),
        (
            "int32_t cncrot_convert(int32_t intrinsic_in,",
            "int32_t cncrot_convert(int64_t intrinsic_in,",
            "fn cncrot_convert changed",
        ),
        (
            "} cncrot_machine;",
            "  double extra;\n} cncrot_machine;",
            "struct cncrot_machine changed",
        ),
        (
            "CNCROT_STATUS_OK = 0",
            "CNCROT_STATUS_OK = 5",
            "enum value CNCROT_STATUS_OK changed",
        ),
    ];
    for (from, to, why) in cases {
        assert!(base.contains(from), "{from}");
        let broken = breaks(&base, &base.replacen(from, to, 1));
        assert!(
            broken.iter().any(|b| b.starts_with(why)),
            "{why}: {broken:?}"
        );
    }
    // A constant's value.
    let define = base
        .lines()
        .find(|l| {
            l.starts_with("#define CNCROT_")
                && !l.contains("VERSION")
                && l.split_whitespace().count() == 3
        })
        .expect("a valued constant");
    let name = define.split_whitespace().nth(1).unwrap_or("");
    let broken = breaks(
        &base,
        &base.replacen(define, &format!("#define {name} 12345"), 1),
    );
    assert!(
        broken
            .iter()
            .any(|b| b.starts_with(&format!("define {name} changed"))),
        "{broken:?}"
    );
    // The version macros may change.
    let bumped = base.replacen(
        "#define CNCROT_VERSION_PATCH 0",
        "#define CNCROT_VERSION_PATCH 7",
        1,
    );
    assert!(breaks(&base, &bumped).is_empty());
    assert_eq!(
        (abi("0.1.7"), abi("0.2.0"), abi("1.4.2")),
        ("0.1".into(), "0.2".into(), "1".into())
    );
}
