//! Every function the header declares is called by a fuzz target: a new export that no
//! target calls fails here (the fuzz crate is built and run by `fuzz/run.sh`).

#[path = "common/exports.rs"]
mod exports;

#[test]
fn every_export_is_fuzzed() {
    let targets = [
        include_str!("../fuzz/fuzz_targets/rotation.rs"),
        include_str!("../fuzz/fuzz_targets/cycle600.rs"),
        include_str!("../fuzz/fuzz_targets/head_def.rs"),
        include_str!("../fuzz/fuzz_targets/program.rs"),
        include_str!("../fuzz/fuzz_targets/kinematics.rs"),
    ];
    // Used in code (called, or taken as a function value), not only named in a comment:
    // the whole identifier on a line that is not a comment.
    let whole_word = |line: &str, name: &str| {
        line.match_indices(name).any(|(at, _)| {
            let next = line[at + name.len()..].chars().next();
            !matches!(next, Some(c) if c.is_ascii_alphanumeric() || c == '_')
        })
    };
    let called = |name: &str| {
        targets.iter().any(|t| {
            t.lines()
                .filter(|l| !l.trim_start().starts_with("//"))
                .any(|l| whole_word(l, name))
        })
    };
    let missing: Vec<&str> = exports::declared_functions()
        .into_iter()
        .filter(|n| !called(n))
        .collect();
    assert!(
        missing.is_empty(),
        "not called by any fuzz target: {missing:?}"
    );
    // The check sees a missing function.
    assert!(!called("cncrot_not_an_export"));
}
