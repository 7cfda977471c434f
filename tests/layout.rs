//! The source tree's architecture, checked: no module of `src/` imports another that
//! imports it back (directly or through others), and the controller families build on the
//! contract only — never on the registry or the modules that dispatch to them.
//!
//! Imports are read from the text: `use` trees and `crate::`/`super::`/`self::` paths
//! outside test modules and comments, each resolved to the longest file module it names.
//! A module's own children and parents are not counted (`mod.rs` declares its children).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

type Module = Vec<String>;

/// Every `.rs` file under `dir` as its module path (`src/dialects/mod.rs` is `dialects`).
fn modules(root: &Path, dir: &Path, out: &mut BTreeMap<Module, String>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            modules(root, &path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let rel = path.strip_prefix(root).unwrap().with_extension("");
            let mut m: Module = rel
                .iter()
                .map(|c| c.to_string_lossy().into_owned())
                .collect();
            if m.last().is_some_and(|l| l == "mod") {
                m.pop();
            }
            if m == ["lib"] {
                m.clear();
            }
            out.insert(m, std::fs::read_to_string(&path).unwrap());
        }
    }
}

/// The text without `#[cfg(test)] mod … { … }` blocks and `//` comments.
fn strip(src: &str) -> String {
    let mut out = String::new();
    let mut rest = src;
    while let Some(k) = rest.find("#[cfg(test)]") {
        let after = &rest[k + 12..];
        let trimmed = after.trim_start();
        let is_mod = trimmed.starts_with("mod ") || trimmed.starts_with("pub mod ");
        let brace = trimmed.find('{');
        let semi = trimmed.find(';');
        out.push_str(&rest[..k]);
        if is_mod && brace.is_some_and(|b| semi.map_or(true, |s| b < s)) {
            let start = after.len() - trimmed.len() + brace.unwrap() + 1;
            let mut depth = 1;
            let mut end = start;
            for (i, c) in after[start..].char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    _ => {}
                }
                if depth == 0 {
                    end = start + i + 1;
                    break;
                }
            }
            rest = &after[end..];
        } else {
            rest = after;
        }
    }
    out.push_str(rest);
    out.lines()
        .map(|l| l.find("//").map_or(l, |k| &l[..k]))
        .collect::<Vec<_>>()
        .join("\n")
}

fn is_path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == ':'
}

/// The paths of a `use` tree (`a::{b, c::{d, e}}` → `a::b`, `a::c::d`, `a::c::e`).
fn expand(tree: &str) -> Vec<String> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let Some(open) = tree.find("::{") else {
        return vec![tree.split(" as ").next().unwrap().to_string()];
    };
    let head = &tree[..open];
    let body = &tree[open + 3..tree.len() - 1];
    let mut items = Vec::new();
    let (mut depth, mut cur) = (0, String::new());
    for c in body.chars() {
        match c {
            ',' if depth == 0 => items.push(std::mem::take(&mut cur)),
            '{' => {
                depth += 1;
                cur.push(c)
            }
            '}' => {
                depth -= 1;
                cur.push(c)
            }
            _ => cur.push(c),
        }
    }
    items.push(cur);
    items
        .into_iter()
        .filter(|i| !i.is_empty())
        .flat_map(|i| {
            if i == "self" {
                vec![head.to_string()]
            } else {
                expand(&format!("{head}::{i}"))
            }
        })
        .collect()
}

/// The file modules `module`'s text refers to.
fn imports(module: &Module, src: &str, files: &BTreeMap<Module, String>) -> BTreeSet<Module> {
    let src = strip(src);
    let mut refs = Vec::new();
    let mut rest = src.as_str();
    while let Some(k) = rest.find("use ") {
        let before = rest[..k].chars().last();
        rest = &rest[k + 4..];
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        if let Some(end) = rest.find(';') {
            refs.extend(expand(&rest[..end]));
        }
    }
    for start in ["crate::", "super::", "self::"] {
        for (k, _) in src.match_indices(start) {
            let before = src[..k].chars().last();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let end = src[k..]
                .find(|c| !is_path_char(c))
                .map_or(src.len(), |e| k + e);
            refs.push(src[k..end].trim_end_matches(':').to_string());
        }
    }
    let mut out = BTreeSet::new();
    for r in refs {
        let parts: Vec<&str> = r.split("::").collect();
        let (mut base, mut parts) = match parts.first() {
            Some(&"crate") => (Vec::new(), &parts[1..]),
            Some(&("super" | "self")) => (module.clone(), &parts[..]),
            _ => continue,
        };
        while let Some(&p) = parts.first() {
            match p {
                "super" => {
                    base.pop();
                }
                "self" => {}
                _ => break,
            }
            parts = &parts[1..];
        }
        let full: Module = base
            .into_iter()
            .chain(parts.iter().map(|s| s.to_string()))
            .collect();
        if let Some(k) = (0..=full.len())
            .rev()
            .find(|&k| files.contains_key(&full[..k]))
        {
            let target = full[..k].to_vec();
            let related = target.starts_with(module) || module.starts_with(&target);
            if !target.is_empty() && !related {
                out.insert(target);
            }
        }
    }
    out
}

fn graph() -> BTreeMap<Module, BTreeSet<Module>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = BTreeMap::new();
    modules(&root, &root, &mut files);
    files
        .iter()
        .filter(|(m, _)| !m.is_empty())
        .map(|(m, src)| (m.clone(), imports(m, src, &files)))
        .collect()
}

/// The strongly connected components of more than one module (Tarjan).
fn circles(g: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<Vec<Module>> {
    struct State<'a> {
        g: &'a BTreeMap<Module, BTreeSet<Module>>,
        index: BTreeMap<&'a Module, usize>,
        low: BTreeMap<&'a Module, usize>,
        stack: Vec<&'a Module>,
        on: BTreeSet<&'a Module>,
        found: Vec<Vec<Module>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a Module) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        s.on.insert(v);
        for w in s.g.get(v).into_iter().flatten() {
            let Some((w, _)) = s.g.get_key_value(w) else {
                continue;
            };
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if s.on.contains(w) {
                let iw = s.index[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if s.low[v] == s.index[v] {
            let mut c = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on.remove(w);
                c.push(w.clone());
                if w == v {
                    break;
                }
            }
            if c.len() > 1 {
                s.found.push(c);
            }
        }
    }
    let mut s = State {
        g,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        found: Vec::new(),
    };
    for v in g.keys() {
        if !s.index.contains_key(v) {
            visit(&mut s, v);
        }
    }
    s.found
}

fn name(m: &Module) -> String {
    m.join("::")
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let g = graph();
    let found: Vec<String> = circles(&g)
        .iter()
        .map(|c| c.iter().map(name).collect::<Vec<_>>().join(", "))
        .collect();
    assert!(found.is_empty(), "import circles: {found:#?}");
}

/// The detector finds what it must: a made-up pair that imports each other, and a circle
/// of three.
#[test]
fn the_detector_sees_circles() {
    let m = |s: &str| -> Module { s.split("::").map(String::from).collect() };
    let mut files = BTreeMap::new();
    for k in ["a", "b", "c", "d", "d::e"] {
        files.insert(m(k), String::new());
    }
    let src = "use crate::b::X;\n// use crate::d;\n#[cfg(test)]\nmod tests { use crate::c; }\n";
    assert_eq!(imports(&m("a"), src, &files), BTreeSet::from([m("b")]));
    let brace = "use super::{b, c::{self, Y}};\nfn f() { super::d::e::g(); }";
    assert_eq!(
        imports(&m("a"), brace, &files),
        BTreeSet::from([m("b"), m("c"), m("d::e")])
    );
    // A child's use of its parent is not an import.
    assert!(imports(&m("d::e"), "use super::Z;", &files).is_empty());
    let g = BTreeMap::from([
        (m("a"), BTreeSet::from([m("b")])),
        (m("b"), BTreeSet::from([m("c")])),
        (m("c"), BTreeSet::from([m("a")])),
        (m("d"), BTreeSet::from([m("a")])),
    ]);
    let c = circles(&g);
    assert_eq!(c.len(), 1);
    assert_eq!(c[0].len(), 3);
}

/// A controller family builds on the contract, the text room and the mathematics (and on
/// another family whose commands it reads), never on what dispatches to the families.
#[test]
fn families_do_not_reach_above_the_contract() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let g = graph();
    let above = [
        vec!["dialects".to_string(), "registry".to_string()],
        vec!["dialects".to_string(), "program".to_string()],
        vec!["dialects".to_string(), "form".to_string()],
    ];
    let mut families = 0;
    for (m, deps) in &g {
        let file = m.iter().fold(root.clone(), |p, c| p.join(c));
        let src = std::fs::read_to_string(file.with_extension("rs"))
            .or_else(|_| std::fs::read_to_string(file.join("mod.rs")))
            .unwrap();
        if !src.contains("impl Family for") {
            continue;
        }
        families += 1;
        for a in &above {
            assert!(!deps.contains(a), "{} imports {}", name(m), name(a));
        }
        assert!(
            !deps.iter().any(|d| d.first().is_some_and(|f| f == "ffi")),
            "{} imports the C boundary",
            name(m)
        );
    }
    assert_eq!(
        families, 6,
        "every registered family implements the contract"
    );
}
