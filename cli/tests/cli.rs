//! The command-line tool as its users run it: the paper's and the manuals' numbers, every
//! subcommand, batch mode, JSON, bad input (a message with line and column, a non-zero
//! exit, never a panic trace).

use std::io::Write;
use std::process::{Command, Stdio};

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn cncrot(args: &[&str], stdin: &str) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cncrot"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    child
        .stdin
        .take()
        .expect("piped")
        .write_all(stdin.as_bytes())
        .expect("stdin written");
    let out = child.wait_with_output().expect("the binary ends");
    let run = Run {
        code: out.status.code().expect("exited, not killed"),
        stdout: String::from_utf8(out.stdout).expect("UTF-8"),
        stderr: String::from_utf8(out.stderr).expect("UTF-8"),
    };
    assert!(
        !run.stderr.contains("panicked") && !run.stderr.contains("RUST_BACKTRACE"),
        "{args:?}: {}",
        run.stderr
    );
    run
}

fn ok(args: &[&str]) -> String {
    let r = cncrot(args, "");
    assert_eq!(r.code, 0, "{args:?}: {}", r.stderr);
    r.stdout
}

/// The numbers of a text (tokens that read as numbers; quotes and words skipped).
fn numbers(text: &str) -> Vec<f64> {
    text.split(|c: char| c.is_whitespace() || c == ',')
        .filter_map(|t| t.parse::<f64>().ok())
        .collect()
}

fn close(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() <= tol, "{got:?} vs {want:?}");
    }
}

// The paper, Examples 2 and 3: probe angles (30, 45, 60) about the machine axes X, Y, Z.
const PROBE: [&str; 3] = ["30", "45", "60"];
// As printed in the paper (4 decimals): intrinsic Z, X', Y'' and extrinsic Z, X, Y.
const I39: [f64; 3] = [37.7923, 20.7048, 49.1066];
const E39: [f64; 3] = [39.6392, -16.2799, 50.3607];

#[test]
fn convert_gives_the_papers_numbers() {
    let mut args = vec![
        "convert",
        "--from",
        "extrinsic:XYZ",
        "--to",
        "intrinsic:ZXY",
    ];
    args.extend(PROBE);
    let out = ok(&args);
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[1].starts_with("intrinsic ZXY (39): "), "{out}");
    close(&numbers(lines[1]), &I39, 1e-4);
    // Codes and letters (with primes) are the same conventions.
    let mut args = vec![
        "convert", "--from", "0:57", "--to", "e:ZX'Y''", "--batch", "-",
    ];
    args.push("--decimals");
    args.push("exact");
    let r = cncrot(&args, "30 45 60\n30,45,60\n");
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0], lines[1]);
    close(&numbers(lines[0]), &E39, 1e-4);
}

#[test]
fn convert_second_solution_nearest_and_singular() {
    // The second decomposition of a Tait-Bryan rotation is (θ1+180, 180-θ2, θ3+180).
    let out = ok(&[
        "convert", "--from", "e:XYZ", "--to", "e:XYZ", "10", "20", "30",
    ]);
    let second = out.lines().find(|l| l.contains("second")).expect("second");
    close(&numbers(second), &[-170.0, 160.0, -150.0], 1e-9);
    // Nearest to angles one turn on: the second solution, unwound.
    let out = ok(&[
        "convert",
        "--from",
        "e:XYZ",
        "--to",
        "e:XYZ",
        "--near",
        "190,160,210",
        "10",
        "20",
        "30",
    ]);
    close(
        &numbers(out.lines().nth(1).expect("result"))[..3],
        &[190.0, 160.0, 210.0],
        1e-9,
    );
    // Negative numbers are numbers, not options.
    let out = ok(&[
        "convert", "--from", "e:XYZ", "--to", "e:XYZ", "-10", "-20", "-30",
    ]);
    close(
        &numbers(out.lines().nth(1).expect("result")),
        &[-10.0, -20.0, -30.0],
        1e-9,
    );
    // Intrinsic Z, Y', X'' with Y' = 90: singular, θ3 = 0, θ1 carries θ1 - θ3.
    let out = ok(&[
        "convert", "--from", "i:ZYX", "--to", "i:ZYX", "40", "90", "10",
    ]);
    assert!(out.contains("singular"), "{out}");
    close(
        &numbers(out.lines().nth(1).expect("result")),
        &[30.0, 90.0, 0.0],
        1e-9,
    );
    // A skipped rotation: X then Z (code 1 + 3·16 = 49) given with two angles.
    let a = ok(&["convert", "--from", "e:X0Z", "--to", "e:XYZ", "30", "60"]);
    let b = ok(&[
        "convert", "--from", "e:XYZ", "--to", "e:XYZ", "30", "0", "60",
    ]);
    assert_eq!(a.lines().nth(1), b.lines().nth(1));
}

#[test]
fn convert_json() {
    let out = ok(&[
        "convert", "--from", "e:XYZ", "--to", "i:ZXY", "--json", "30", "45", "60",
    ]);
    assert!(
        out.starts_with("{\"intrinsic\":1,\"code\":39,\"angles\":[37.792"),
        "{out}"
    );
    assert!(out.trim_end().ends_with("\"singular\":false}"), "{out}");
    assert_eq!(out.lines().count(), 1);
}

#[test]
fn bad_input_is_a_message_with_its_place() {
    // A malformed command line: exit 2.
    let r = cncrot(
        &["convert", "--from", "XYZ", "--to", "i:ZXY", "1", "2", "3"],
        "",
    );
    assert_eq!(r.code, 2);
    assert!(
        r.stderr.contains("--from") && r.stderr.contains("KIND:SEQUENCE"),
        "{}",
        r.stderr
    );
    let r = cncrot(
        &["convert", "--from", "e:XYZ", "--to", "i:ZX", "1", "2", "3"],
        "",
    );
    assert_eq!(r.code, 2, "{}", r.stderr);
    let r = cncrot(&["frobnicate"], "");
    assert_eq!(r.code, 2);
    // A bad input: exit 1, with its column.
    let r = cncrot(
        &[
            "convert", "--from", "e:XYZ", "--to", "i:ZXY", "30", "4x5", "60",
        ],
        "",
    );
    assert_eq!(r.code, 1);
    assert!(
        r.stderr.contains("column 4") && r.stderr.contains("'4x5'"),
        "{}",
        r.stderr
    );
    for bad in ["nan", "inf", "1e999"] {
        let r = cncrot(
            &["convert", "--from", "e:XYZ", "--to", "i:ZXY", "1", bad, "3"],
            "",
        );
        assert_eq!(r.code, 1, "{bad}");
        assert!(r.stdout.is_empty());
    }
    let r = cncrot(
        &["convert", "--from", "e:XYZ", "--to", "i:ZXY", "1", "2"],
        "",
    );
    assert_eq!(r.code, 1);
    assert!(r.stderr.contains("expected 3 angles"), "{}", r.stderr);
    // Both an argument and a batch: refused before anything is read.
    let r = cncrot(
        &[
            "convert", "--from", "e:XYZ", "--to", "i:ZXY", "--batch", "-", "1 2 3",
        ],
        "",
    );
    assert_eq!(r.code, 2);
    let r = cncrot(
        &[
            "convert",
            "--from",
            "e:XYZ",
            "--to",
            "i:ZXY",
            "--batch",
            "/nonexistent",
        ],
        "",
    );
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("/nonexistent"), "{}", r.stderr);
    let r = cncrot(
        &[
            "convert",
            "--from",
            "e:XYZ",
            "--to",
            "i:ZXY",
            "--decimals",
            "99",
            "1 2 3",
        ],
        "",
    );
    assert_eq!(r.code, 2);
}

#[test]
fn batch_reports_each_line_and_fails_if_any_failed() {
    let input = "30 45 60\n\n1 2 x\r\n0,90,10\n";
    let args = [
        "convert", "--from", "e:XYZ", "--to", "i:ZYX", "--batch", "-",
    ];
    let r = cncrot(&args, input);
    assert_eq!(r.code, 1);
    // One output line per input line, so that they align: line 2 is blank and stays blank,
    // line 3 fails at its 5th column and leaves a marked line.
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines.len(), 4, "{}", r.stdout);
    assert_eq!(lines[1], "");
    assert_eq!(lines[2], "error: line 3, column 5: 'x' is not a number");
    assert_eq!(
        r.stderr.trim(),
        "cncrot: line 3, column 5: 'x' is not a number"
    );
    // Extrinsic X, Y, Z = (0, 90, 10) is intrinsic Z, Y', X'' = (10, 90, 0).
    close(
        &numbers(r.stdout.lines().nth(3).expect("line 4")),
        &[10.0, 90.0, 0.0],
        1e-9,
    );
    // JSON: one object per input line, errors in place.
    let mut json = args.to_vec();
    json.push("--json");
    let r = cncrot(&json, input);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines.len(), 4);
    assert!(lines[0].ends_with("\"line\":1}"));
    assert_eq!(lines[1], "{\"line\":2,\"blank\":true}");
    assert_eq!(
        lines[2],
        "{\"error\":\"'x' is not a number\",\"column\":5,\"line\":3}"
    );
    // All good: exit 0.
    let r = cncrot(&args, "1 2 3\n4 5 6\n");
    assert_eq!((r.code, r.stdout.lines().count()), (0, 2));
}

#[test]
fn line_translates_between_dialects() {
    // TwinCAT's ROT X30 is a rotation of 30° about X: PLANE SPATIAL SPA+30.
    let out = ok(&["line", "--from", "twincat", "--to", "heidenhain", "ROT X30"]);
    assert!(
        out.contains("heidenhain PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY"),
        "{out}"
    );
    // Without --to: every dialect.
    let out = ok(&[
        "line",
        "--from",
        "heidenhain",
        "PLANE SPATIAL SPA+0 SPB+0 SPC+30 STAY",
    ]);
    for name in [
        "sinumerik",
        "heidenhain",
        "fanuc",
        "syntec",
        "twincat",
        "haas",
    ] {
        assert!(out.lines().any(|l| l.starts_with(name)), "{name}: {out}");
    }
    assert!(out.contains("twincat    ROT X0 Y0 Z30"), "{out}");
    // `line` writes planes: a way of moving the machine (TURN, SEQ-, MB) is said to be left
    // out, once, with the command that carries it; a STAY line has none.
    let r = cncrot(
        &[
            "line",
            "--from",
            "heidenhain",
            "--to",
            "fanuc",
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 FMAX SEQ-",
        ],
        "",
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.contains("is not written: `line` writes planes; `cncrot program FILE --dialect heidenhain --to DIALECT` carries it"), "{}", r.stderr);
    let r = cncrot(
        &[
            "line",
            "--from",
            "fanuc",
            "--to",
            "heidenhain",
            "--batch",
            "-",
        ],
        "G68.2 X0 Y0 Z0 I0 J30 K0\nG53.1\nG69\nG68.2 X0 Y0 Z0 I0 J20 K0\nG53.1\n",
    );
    assert_eq!(
        r.stderr.matches("(first at line 2)").count(),
        1,
        "{}",
        r.stderr
    );
    let r = cncrot(
        &[
            "line",
            "--from",
            "heidenhain",
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
        ],
        "",
    );
    assert!(r.stderr.is_empty(), "{}", r.stderr);
    // The TwinCAT manual: ROT Z30, then AROT Z15, is 45° about Z. A program's lines carry
    // their modal state in batch mode; a bad line is refused at its column and the next
    // line still sees the state before it.
    let r = cncrot(
        &[
            "line", "--from", "twincat", "--to", "twincat", "--to", "fanuc", "--batch", "-",
        ],
        "N65 ROT Z30\nN70 ROT Z=R1\nN90 AROT Z15\n",
    );
    assert_eq!(r.code, 1);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines.len(), 3, "{}", r.stdout);
    assert!(
        lines[1].starts_with("error: line 2, column 11: "),
        "{}",
        lines[1]
    );
    assert!(
        lines[2].starts_with("ROT X0 Y0 Z45\tG68.2 "),
        "{}",
        lines[2]
    );
    assert!(r.stderr.contains("line 2, column 11:"), "{}", r.stderr);
    // A named form, and the origin kept where the form has no origin words.
    let out = ok(&[
        "line",
        "--from",
        "fanuc",
        "--to",
        "heidenhain:PLANE EULER",
        "--to",
        "syntec",
        "G68.2 X10 Y0 Z0 I0 J30 K0",
    ]);
    assert!(
        out.contains("PLANE EULER EULPR+0 EULNU+30 EULROT+0"),
        "{out}"
    );
    assert!(
        out.contains("[origin 10.0000 0.0000 0.0000: shift the datum there first]"),
        "{out}"
    );
    assert!(out.contains("G158 P10157 X10. "), "{out}");
    // Unknown dialect or form.
    let r = cncrot(&["line", "--from", "mazak", "G68.2 I0 J0 K0"], "");
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("'mazak' is not a dialect"));
    let r = cncrot(
        &[
            "line",
            "--from",
            "fanuc",
            "--to",
            "heidenhain:PLANE FLAT",
            "G68.2 X0 Y0 Z0 I0 J0 K0",
        ],
        "",
    );
    assert_eq!(r.code, 1);
    assert!(r.stderr.contains("PLANE FLAT"), "{}", r.stderr);
}

#[test]
fn probe_plane_flatness_and_lines() {
    // Two opposite corners 0.01 mm above z = 5, the other two 0.01 below: by symmetry the
    // plane is z = 5, the flatness 0.02 and the RMS 0.01; X' runs from the first point to
    // the second, here +X, so the plane is not rotated, only shifted to z = 5.
    let out = ok(&[
        "probe",
        "0,0,5.01",
        "100,0,4.99",
        "100,100,5.01",
        "0,100,4.99",
        "--to",
        "heidenhain",
    ]);
    assert!(out.contains("[origin 0.0000 0.0000 5.0000: shift"), "{out}");
    assert!(
        out.contains("flatness: 0.0200 mm") && out.contains("rms: 0.0100 mm"),
        "{out}"
    );
    // An untilted plane is written as no tilt: the cancel.
    assert!(out.contains("PLANE RESET STAY"), "{out}");
    // A plane rising 10 mm over 100 mm along X: tilted atan(0.1) = 5.7106° about -Y.
    let file = std::env::temp_dir().join(format!("cncrot_probe_{}.csv", std::process::id()));
    std::fs::write(
        &file,
        "x;y;z\n# probed\n0;0;0\n100;0;10\n100;50;10\n0;50;0\n",
    )
    .expect("written");
    let path = file.to_str().expect("UTF-8 path");
    let out = ok(&["probe", "--points-file", path, "--to", "twincat", "--json"]);
    assert!(out.contains("\"points\":4"), "{out}");
    assert!(
        out.contains("\"extrinsic_xyz\":[0,-5.71059313749964"),
        "{out}"
    );
    // A bad point names its line and column.
    std::fs::write(&file, "0 0 0\n100 0 10\n100 5O 10\n").expect("written");
    let r = cncrot(&["probe", "--points-file", path], "");
    assert_eq!(r.code, 1);
    assert!(
        r.stderr.contains("line 3, column 5: '5O' is not a number"),
        "{}",
        r.stderr
    );
    std::fs::remove_file(&file).ok();
    // Too few, or collinear: the library's reasons.
    let r = cncrot(&["probe", "0,0,0", "1,0,0"], "");
    assert_eq!(r.code, 1);
    assert!(r.stderr.contains("too few points"), "{}", r.stderr);
    let r = cncrot(&["probe", "0,0,0", "1,0,0", "2,0,0"], "");
    assert!(r.code == 1 && r.stderr.contains("one line"), "{}", r.stderr);
    // Points from standard input, negative coordinates.
    let r = cncrot(
        &["probe", "--points-file", "-", "--to", "fanuc"],
        "-1 -1 0\n1 -1 0\n1 1 0\n",
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    // The help names the option as it is spelt; `--points FILE`, which it once showed, works.
    let help = ok(&["help", "probe"]);
    assert!(help.contains("--points-file FILE"), "{help}");
    assert!(!help.contains("or --points FILE"), "{help}");
    let r = cncrot(
        &["probe", "--points", "-", "--to", "fanuc"],
        "0 0 0\n1 0 0\n0 1 0\n",
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
}

#[test]
fn cycle600_the_papers_example_3() {
    let call = "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39,0,0,0)";
    let out = ok(&["cycle600", call]);
    assert!(out.starts_with("_CYC600_1 = \"UFK600\"\n"), "{out}");
    let values: Vec<f64> = out
        .lines()
        .filter(|l| l.starts_with("_CYC600_") && !l.starts_with("_CYC600_1"))
        .flat_map(numbers)
        .collect();
    close(&values, &[I39[0], I39[1], I39[2], 1.0, 39.0], 1e-4);
    // The second call (_INEXOUT = 0) as a bare list of parameters, in batch with the first.
    let r = cncrot(
        &["cycle600", "--batch", "-"],
        &format!("N120 {call} ; intrinsic\n0 UFK600 1 57 0 0 0 30 45 60 0 0 0 0 39\n"),
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines.len(), 2);
    close(
        &numbers(lines[1]),
        &[E39[0], E39[1], E39[2], 0.0, 39.0],
        1e-4,
    );
    // _ROT_AD = 1: Z 30 then Z 15 added (intrinsic, code 3 = Z alone) is Z 45, and the
    // state carries from line to line.
    let r = cncrot(
        &["cycle600", "--batch", "-"],
        "CYCLE600(1,\"\",1,3,,,,30,,,,,,1,39)\nCYCLE600(1,\"\",1,3,,,,15,,,,,,1,39,1)\n",
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    close(
        &numbers(r.stdout.lines().nth(1).expect("2nd")),
        &[45.0, 0.0, 0.0, 1.0, 39.0],
        1e-12,
    );
}

#[test]
fn cycle600_refusals() {
    // An unknown accessory with a HEAD_DEF table, a bad flag, a bad number, too few.
    let heads = std::env::temp_dir().join(format!("cncrot_heads_{}.spf", std::process::id()));
    std::fs::write(&heads, "_HEAD_NAME=\"UFK600\"\nM17\n").expect("written");
    let h = heads.to_str().expect("UTF-8 path");
    let good = "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39)";
    assert_eq!(cncrot(&["cycle600", "--heads", h, good], "").code, 0);
    let r = cncrot(
        &["cycle600", "--heads", h, &good.replace("UFK600", "UFK700")],
        "",
    );
    assert!(
        r.code == 1
            && r.stderr.contains(
                "column 12: \"UFK700\": _MIHEAD is not an accessory of the --heads table"
            ),
        "{}",
        r.stderr
    );
    std::fs::remove_file(&heads).ok();
    let r = cncrot(&["cycle600", &good.replace("(0,", "(2,")], "");
    assert!(r.code == 1 && r.stderr.contains("flag"), "{}", r.stderr);
    let r = cncrot(&["cycle600", &good.replace("30,45", "30,4.5.")], "");
    assert!(
        r.code == 1 && r.stderr.contains("column 35"),
        "{}",
        r.stderr
    );
    let r = cncrot(&["cycle600", "CYCLE600(0,\"A\",1,57)"], "");
    assert!(
        r.code == 1 && r.stderr.contains("15 to 18 parameters"),
        "{}",
        r.stderr
    );
    let r = cncrot(&["cycle600", "CYCLE800(0,\"A\",1,57)"], "");
    assert!(r.code == 1 && r.stderr.contains("column 1"), "{}", r.stderr);
}

/// A head C about Z carrying B about Y (the library's documented example).
const HEAD: [&str; 4] = ["--axis", "tool:0,0,1", "--axis", "tool:0,1,0"];

#[test]
fn axes_of_a_swivel_head() {
    // The plane tilted 30° about Y, from C = 750°: C = 720° (whole turns toward the
    // current position), B = 30°.
    let mut args = vec!["axes"];
    args.extend(HEAD);
    args.extend(["--current", "750,0", "0", "30", "0"]);
    let out = ok(&args);
    assert_eq!(out.trim(), "axis 1 = 720.0000, axis 2 = 30.0000");
    // "Minus" on B: B = -30° (C = 180°).
    let mut args = vec!["axes"];
    args.extend(HEAD);
    args.extend(["--rule", "minus:2", "--batch", "-"]);
    let r = cncrot(&args, "0 30 0\n");
    let got = numbers(&r.stdout);
    // C = ±180° are one position, equally far from 0.
    assert!(
        (got[0].abs() - 180.0).abs() < 1e-9 && (got[1] + 30.0).abs() < 1e-9,
        "{got:?}"
    );
    // C turning only up from 20: C 0 lies 340° ahead, C 180 160°: C 180, B -30 (the half
    // turn about the tool left to the frame). Down: C 0 (20° away), B 30.
    for (rule, want) in [
        ("up:1", [1.0, 180.0, 2.0, -30.0]),
        ("down:1", [1.0, 0.0, 2.0, 30.0]),
    ] {
        let mut args = vec!["axes"];
        args.extend(HEAD);
        args.extend(["--rule", rule, "--current", "20,0", "0", "30", "0"]);
        let out = ok(&args);
        close(&numbers(out.lines().next().unwrap_or("")), &want, 1e-9);
    }
    // Every solution.
    let mut args = vec!["axes"];
    args.extend(HEAD);
    args.extend(["--all", "0", "30", "0"]);
    let out = ok(&args);
    assert_eq!(out.lines().count(), 2, "{out}");
    // Forward: B = 30° tilts the tool +Z toward +X: (sin 30°, 0, cos 30°).
    let mut args = vec!["axes"];
    args.extend(HEAD);
    args.extend(["--forward", "--decimals", "exact", "0", "30"]);
    let out = ok(&args);
    let tool = out.lines().next().expect("tool line");
    close(&numbers(tool), &[0.5, 0.0, 3f64.sqrt() / 2.0], 1e-15);
    // A head with a C axis alone cannot tilt: unreachable, exit 1.
    let r = cncrot(&["axes", "--axis", "tool:0,0,1", "30", "0", "0"], "");
    assert!(
        r.code == 1 && r.stderr.contains("no rotary-axis positions"),
        "{}",
        r.stderr
    );
    // ...but turns about the tool are left to the frame.
    let out = ok(&["axes", "--axis", "tool:1,0,0", "0", "0", "30"]);
    assert!(out.contains("left to the frame"), "{out}");
}

#[test]
fn axes_from_swivel_data_and_refusals() {
    // Swivel data of a head C (about Z) carrying B (about Y), as the library's example.
    let carr = std::env::temp_dir().join(format!("cncrot_carr_{}.mpf", std::process::id()));
    std::fs::write(
        &carr,
        "$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0\n$TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=1\n\
         $TC_CARR23[1]=\"T\"\n$TC_CARR34[1]=\"HEAD_BC\"\n",
    )
    .expect("written");
    let c = carr.to_str().expect("UTF-8 path");
    let out = ok(&["axes", "--carr", c, "--all", "0", "30", "0"]);
    assert_eq!(out.lines().count(), 2, "{out}");
    // CYCLE600 positioning the same head (_SW_REC = 0).
    let out = ok(&[
        "cycle600",
        "--carr",
        c,
        "CYCLE600(0,\"H\",0,57,0,0,0,0,30,0,0,0,0,1,39)",
    ]);
    assert!(out.contains("head positions: "), "{out}");
    let r = cncrot(&["axes", "--carr", c, "--set", "2", "0", "30", "0"], "");
    assert_eq!(r.code, 2, "{}", r.stderr);
    std::fs::write(&carr, "$TC_CARR7[1]=0\n$TC_CARR50[1]=1\n").expect("written");
    let r = cncrot(&["axes", "--carr", c, "0", "30", "0"], "");
    assert!(r.code == 2 && r.stderr.contains("line 2"), "{}", r.stderr);
    std::fs::remove_file(&carr).ok();
    // Machines that cannot be.
    for (axes, why) in [
        (&["--axis", "tool:0,0,0"][..], "zero direction"),
        (
            &["--axis", "tool:0,0,1", "--axis", "tool:0,0,2"][..],
            "parallel",
        ),
        (&["--axis", "arm:0,0,1"][..], "neither tool"),
        (&["--axis", "tool:0,0"][..], "expected 3 numbers"),
        (&[][..], "describe the machine"),
    ] {
        let mut args = vec!["axes"];
        args.extend(axes);
        args.extend(["0", "0", "0"]);
        let r = cncrot(&args, "");
        assert!(
            r.code == 2 && r.stderr.contains(why),
            "{axes:?}: {}",
            r.stderr
        );
    }
    let mut args = vec!["axes"];
    args.extend(HEAD);
    args.extend(["--rule", "minus:3", "0", "0", "0"]);
    assert_eq!(cncrot(&args, "").code, 2);
}

#[test]
fn every_subcommand_has_help_with_an_example() {
    for sub in ["convert", "line", "probe", "cycle600", "axes", "kinematics"] {
        let out = ok(&[sub, "--help"]);
        assert!(out.contains("Example"), "{sub}: {out}");
    }
    let out = ok(&["--help"]);
    for sub in ["convert", "line", "probe", "cycle600", "axes"] {
        assert!(out.contains(sub), "{out}");
    }
}

#[test]
fn hostile_input_never_panics() {
    let huge = "1e308";
    let cases: Vec<Vec<&str>> = vec![
        vec![
            "convert", "--from", "e:XYZ", "--to", "i:ZXY", huge, huge, huge,
        ],
        vec![
            "convert",
            "--from",
            "e:XYZ",
            "--to",
            "i:ZXY",
            "--near",
            "1e308,0,0",
            "1",
            "2",
            "3",
        ],
        vec!["convert", "--from", "e:", "--to", "i:ZXY", "1", "2", "3"],
        vec![
            "convert",
            "--from",
            "e:99999999999999999999",
            "--to",
            "i:ZXY",
            "1",
            "2",
            "3",
        ],
        vec!["line", "--from", "sinumerik", ""],
        vec!["line", "--from", "sinumerik", "TRANS X1e308 Y1e308"],
        vec![
            "line",
            "--from",
            "heidenhain",
            "PLANE SPATIAL SPA+1e400 SPB+0 SPC+0 STAY",
        ],
        vec!["line", "--from", "fanuc", "\u{1F600}"],
        vec![
            "probe",
            "1e308,1e308,1e308",
            "-1e308,-1e308,-1e308",
            "1e308,-1e308,0",
        ],
        vec!["probe"],
        vec!["cycle600", "CYCLE600("],
        vec!["cycle600", ")CYCLE600("],
        vec![
            "cycle600",
            "CYCLE600(0,\"\u{e9}\",1,57,0,0,0,1,2,3,0,0,0,1,39)",
        ],
        vec![
            "cycle600",
            "CYCLE600(0,\"A\",1,57,1e308,0,0,1,2,3,1e308,0,0,1,39)",
        ],
        vec!["axes", "--axis", "tool:1e308,1e308,0", "1", "2", "3"],
        vec![
            "axes",
            "--axis",
            "tool:0,0,1",
            "--current",
            "1e300",
            "1",
            "2",
            "3",
        ],
        vec!["axes", "--axis", "tool:0,0,1", "--forward", "1e308"],
    ];
    for args in cases {
        let r = cncrot(&args, "");
        assert!(r.code == 0 || r.code == 1 || r.code == 2, "{args:?}");
        if r.code != 0 {
            assert!(
                r.stderr.starts_with("cncrot: ") || r.stderr.starts_with("error: "),
                "{args:?}: {}",
                r.stderr
            );
        }
    }
    // Bytes that are not UTF-8 in a batch file: read as Latin-1, so only their line fails
    // (the file was refused whole).
    let file = std::env::temp_dir().join(format!("cncrot_bytes_{}.txt", std::process::id()));
    std::fs::write(&file, b"1 2 3\n\xff\xfe 2 3\n4 5 6\n").expect("written");
    let path = file.to_str().expect("UTF-8 path");
    let r = cncrot(
        &[
            "convert", "--from", "e:XYZ", "--to", "i:ZXY", "--batch", path,
        ],
        "",
    );
    assert!(
        r.code == 1
            && r.stderr
                .contains("line 2, column 1: '\u{ff}\u{fe}' is not a number"),
        "{}",
        r.stderr
    );
    assert_eq!(r.stdout.lines().count(), 3, "{}", r.stdout);
    std::fs::remove_file(&file).ok();
    // A Heidenhain program with a Latin-1 comment (as hyperMILL writes them) is read whole.
    let file = std::env::temp_dir().join(format!("cncrot_latin1_{}.h", std::process::id()));
    std::fs::write(
        &file,
        b"0 BEGIN PGM T MM\n1 ; JOB: M12 - let\xf6r\xe9s\n2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n3 END PGM T MM\n",
    )
    .expect("written");
    let path = file.to_str().expect("UTF-8 path");
    let r = cncrot(&["program", path, "--dialect", "heidenhain"], "");
    assert!(
        r.code == 0
            && r.stdout
                .contains("4 blocks: 1 concerning the frame, 3 passed over"),
        "{}{}",
        r.stdout,
        r.stderr
    );
    std::fs::remove_file(&file).ok();
}

/// A whole Heidenhain program through `line --batch`: one output line per block, the
/// blocks that do not concern the frame marked as passed, the datum shift as not followed,
/// and the exit status 0 (nothing was refused).
#[test]
fn line_reads_a_whole_program() {
    let program = "0 BEGIN PGM TILT MM\n1 TOOL CALL 1 Z S5000\n2 CYCL DEF 7.0 DATUM SHIFT\n\
                   3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-\n\
                   4 L X+10 Y+0 FMAX\n5 PLANE RESET STAY\n6 END PGM TILT MM\n";
    let r = cncrot(
        &[
            "line",
            "--from",
            "heidenhain",
            "--to",
            "fanuc",
            "--batch",
            "-",
        ],
        program,
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines.len(), 7, "{}", r.stdout);
    for k in [0, 1, 4, 6] {
        assert_eq!(lines[k], "passed", "{k}");
    }
    // Cycle 7's first line belongs to the datum shift and leaves nothing active: the line of
    // that frame is the cancel.
    assert_eq!(lines[2], "G69");
    // A tilt about Y by 30° is Rz(90)·Rx(30)·Rz(-90) in G68.2's Euler angles.
    assert!(
        lines[3].starts_with("G68.2 X0. Y0. Z0. I90. J30. K-90."),
        "{}",
        lines[3]
    );
    // The cancel is written as the cancel.
    assert_eq!(lines[5], "G69");
    let r = cncrot(
        &["line", "--from", "heidenhain", "--json", "--batch", "-"],
        program,
    );
    assert!(r
        .stdout
        .lines()
        .nth(1)
        .unwrap()
        .contains("\"remark\":\"passed\""));
}

/// `program`: a whole Heidenhain program on a fork head (C about Z carrying B about Y): one
/// row per block that concerns the frame with the tool direction and the positions chosen
/// closest to the ones before; the datum shift flagged; the summary. With `--to`, the whole
/// program translated, other blocks as they are, what is not carried across on standard
/// error and the exit status 1.
#[test]
fn program_reads_a_whole_program_on_a_machine() {
    let dir = std::env::temp_dir();
    let id = std::process::id();
    let prog = dir.join(format!("cncrot_prog_{id}.h"));
    let carr = dir.join(format!("cncrot_prog_{id}.carr"));
    std::fs::write(
        &prog,
        "0 BEGIN PGM TILT MM\n1 TOOL CALL 1 Z S5000\n2 CYCL DEF 7.0 DATUM SHIFT\n\
         3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-\n4 L X+10 Y+0 FMAX\n\
         5 PLANE SPATIAL SPA+0 SPB-20 SPC+90 TURN FMAX\n6 PLANE RESET STAY\n7 END PGM TILT MM\n",
    )
    .unwrap();
    std::fs::write(
        &carr,
        "$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1 $TC_CARR10[1]=0 $TC_CARR11[1]=1\n\
         $TC_CARR12[1]=0 $TC_CARR6[1]=-150 $TC_CARR23[1]=\"T\" $TC_CARR31[1]=-100 $TC_CARR33[1]=100\n",
    )
    .unwrap();
    let (p, c) = (prog.to_str().unwrap(), carr.to_str().unwrap());
    let out = ok(&[
        "program",
        p,
        "--dialect",
        "heidenhain",
        "--carr",
        c,
        "--current",
        "0,0",
    ]);
    // SPB+30 tilts the tool to (sin 30°, 0, cos 30°): C 0, B 30 or C 180, B -30; SEQ-
    // asks for the master axis (B, the axis nearest the tool) at a negative angle: C 180,
    // B -30 (the angles themselves, as the TNC gives them under SEQ). SPB-20 SPC+90 to
    // (0, -sin 20°, cos 20°), without SEQ: the pair closest to C 180, B -30 — C 90, B -20
    // (C -90 wound to 270, B 20 is farther).
    assert!(out.contains("line 4: 3 PLANE SPATIAL"), "{out}");
    assert!(
        out.contains("tool direction: 0.5000 0.0000 0.8660  axes: 180.0000 -30.0000"),
        "{out}"
    );
    assert!(
        out.contains("tool direction: 0.0000 -0.3420 0.9397  axes: 90.0000 -20.0000"),
        "{out}"
    );
    assert!(
        out.contains("8 blocks: 4 concerning the frame, 4 passed over, 0 not followed, 0 refused"),
        "{out}"
    );
    let r = cncrot(
        &["program", p, "--dialect", "heidenhain", "--to", "fanuc"],
        "",
    );
    // A retraction or turn the target has no word for: exit status 1.
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains(", 1 with a way of moving left out"),
        "{}",
        r.stderr
    );
    let lines: Vec<&str> = r.stdout.lines().collect();
    // Cycle 7's first line changes nothing in a Fanuc program: it is left out; TURN is
    // G53.1 after the G68.2; the next plane cancels this one first.
    assert_eq!(lines.len(), 10, "{}", r.stdout);
    assert_eq!(lines[1], "1 TOOL CALL 1 Z S5000");
    assert_eq!(lines[2], "G68.2 X0. Y0. Z0. I90. J30. K-90.");
    assert_eq!(lines[3], "G53.1");
    assert_eq!(lines[5], "G69");
    assert_eq!(lines[8], "G69");
    // A plane selection is carried across as it stands (no writer says a plane): the
    // rotation in the G18 plane that follows is written as the target's tilt.
    let r = cncrot(
        &[
            "program",
            "-",
            "--dialect",
            "fanuc",
            "--to",
            "sinumerik:CYCLE800",
        ],
        "G18 G1 X10.\nG68 Z0 X0 R30.\nG69\n",
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines[0], "G18 G1 X10.", "{}", r.stdout);
    assert!(
        lines[1].starts_with("CYCLE800(0,\"\",0,57,0,0,0,0,30,0,"),
        "{}",
        r.stdout
    );
    assert_eq!(lines[2], "CYCLE800()", "{}", r.stdout);
    let r = cncrot(
        &["program", p, "--dialect", "heidenhain", "--current", "0,0"],
        "",
    );
    assert_eq!(r.code, 2);
    assert!(
        r.stderr.contains("--current needs a machine"),
        "{}",
        r.stderr
    );
    std::fs::remove_file(prog).ok();
    std::fs::remove_file(carr).ok();
}

/// At gimbal lock `convert` says the third angle is set to 0 and writes no second solution
/// (any split of the sum would be one): the outputs agree with each other.
#[test]
fn convert_at_gimbal_lock_writes_one_solution() {
    // A turn of 30° about Z alone is Z,X',Z'' = (30, 0, 0): the middle angle singular.
    let out = ok(&[
        "convert", "--from", "e:XYZ", "--to", "i:ZXZ", "0", "0", "30",
    ]);
    assert!(
        out.contains("intrinsic ZXZ (55): 30.0000 0.0000 0.0000"),
        "{out}"
    );
    assert!(
        out.contains("the third is set to 0") && !out.contains("second solution"),
        "{out}"
    );
    let json = ok(&[
        "convert", "--from", "e:XYZ", "--to", "i:ZXZ", "--json", "0", "0", "30",
    ]);
    assert!(
        json.contains("\"singular\":true") && !json.contains("\"second\""),
        "{json}"
    );
    // Away from it both solutions are written.
    let out = ok(&[
        "convert", "--from", "e:XYZ", "--to", "i:ZXZ", "0", "10", "30",
    ]);
    assert!(out.contains("second solution"), "{out}");
}

/// `probe` (a helper's finds): the first point probed twice, 2 µm apart, gave an X' of the
/// probe's noise (SPC -180): refused as coinciding; a labelled first point in a file
/// (`P1 0 0 0`) is an error, not a header skipped in silence.
#[test]
fn probe_refuses_an_undefined_x_and_labelled_points() {
    let r = cncrot(
        &[
            "probe",
            "0,0,0",
            "0,0,0.002",
            "100,0,-10",
            "0,100,0",
            "100,100,-10",
        ],
        "",
    );
    assert_eq!(r.code, 1, "{}", r.stdout);
    assert!(
        r.stderr.contains("first two points coincide"),
        "{}",
        r.stderr
    );
    let r = cncrot(&["probe", "0,0,0", "1,0,-0.1", "100,0,-10", "0,100,0"], "");
    assert_eq!(r.code, 0, "{}", r.stderr);
    let r = cncrot(
        &["probe", "--points", "-"],
        "P1 0 0 0\n100 0 -10\n100 50 -10\n0 50 0\n",
    );
    assert_eq!(r.code, 1, "{}", r.stdout);
    assert!(r.stderr.contains("line 1"), "{}", r.stderr);
    let r = cncrot(
        &["probe", "--points", "-"],
        "x y z\n0 0 0\n100 0 -10\n100 50 -10\n0 50 0\n",
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stdout.contains("points: 4"), "{}", r.stdout);
    // A file not read at all: exit status 2, as for every command.
    let r = cncrot(&["probe", "--points", "/nonexistent/points.csv"], "");
    assert_eq!(r.code, 2, "{}", r.stderr);
}

/// `probe`: the same corners probed clockwise give the plane the right way up (Z' toward
/// the machine's +Z) and say it was turned; `--order` keeps the points' order (PLANE
/// POINTS's rule: upside down here); `--toward` takes another side. The JSON agrees with
/// the text: an origin of a few 1e-16 from the fit is no datum to shift.
#[test]
fn probe_defaults_to_the_tools_side() {
    // Falling 10 mm over 100 mm along X, corners in clockwise order seen from above.
    let pts = ["0,0,0", "0,50,0", "100,50,-10", "100,0,-10"];
    let mut args = vec!["probe"];
    args.extend(pts);
    args.extend(["--to", "heidenhain"]);
    let out = ok(&args);
    assert!(out.contains("normal (Z'): 0.0995 0.0000 0.9950"), "{out}");
    assert!(out.contains("turned to the tool's side"), "{out}");
    assert!(
        out.contains("PLANE SPATIAL SPA+5.7106 SPB+0 SPC+90 STAY"),
        "{out}"
    );
    let mut order = args.clone();
    order.push("--order");
    let out = ok(&order);
    assert!(out.contains("normal (Z'): -0.0995 0.0000 -0.9950"), "{out}");
    assert!(!out.contains("turned"), "{out}");
    let mut down = args.clone();
    down.extend(["--toward", "0,0,-1"]);
    let out = ok(&down);
    assert!(
        out.contains("normal (Z'): -0.0995 0.0000 -0.9950") && !out.contains("turned"),
        "{out}"
    );
    let mut json = args.clone();
    json.push("--json");
    let out = ok(&json);
    assert!(
        out.contains("\"turned\":true") && out.contains("\"origin_apart\":false"),
        "{out}"
    );
}

/// The AC table of docs/kinematics.md: A about X through z = 100, C on it, tool 50 mm.
const AC: [&str; 6] = [
    "--axis",
    "work:1,0,0@0,0,100",
    "--axis",
    "work:0,0,1",
    "--tool-length",
    "50",
];

/// `path`: the worked example by hand (X 0, Y 50 + 5√3, Z 155 − 50√3, A 30, C 90), a
/// header and a comment as blank lines, a zero direction as an error line in place, the
/// pole keeping C, and the rows after an error going on.
#[test]
fn path_worked_example_alignment_and_the_pole() {
    let cl = "x,y,z,i,j,k\n10 0 0 0.5 0 0.8660254037844386\n# a comment\n10 0 0 0 0 0\n\
              10 0 0 0 0 1\n10 0 0 -0.5 0 0.8660254037844386\n";
    let mut args = vec!["path", "-", "--current", "20,80", "--decimals", "exact"];
    args.extend(AC);
    let r = cncrot(&args, cl);
    assert_eq!(r.code, 1, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines.len(), 6, "{}", r.stdout);
    assert_eq!(lines[0], "");
    let s3 = 3f64.sqrt();
    close(
        &numbers(lines[1]),
        &[0.0, 50.0 + 5.0 * s3, 155.0 - 50.0 * s3, 30.0, 90.0],
        1e-12,
    );
    assert_eq!(lines[2], "");
    assert!(
        lines[3].starts_with("error: line 4") && lines[3].contains("zero"),
        "{}",
        lines[3]
    );
    // The pole: A = 0, C stays at 90 (free), the tip 50 below the adapter.
    assert!(lines[4].contains("free axis kept"), "{}", lines[4]);
    close(&numbers(lines[4]), &[0.0, 10.0, 50.0, 0.0, 90.0], 1e-12);
    // Past the pole in the plane of A: A changes sign, C stays still. Rx(-30°)·(0, 10, -100)
    // + (0, 0, 100) = (0, 5√3 - 50, -5 - 50√3 + 100), the adapter 50 above.
    close(
        &numbers(lines[5]),
        &[0.0, 5.0 * s3 - 50.0, 145.0 - 50.0 * s3, -30.0, 90.0],
        1e-12,
    );
}

/// `path --rule up:1` (a helper's find): the rule picks the first point's solution, the
/// rows after it continue from it. Taken at every row, C only turning up swung half a turn
/// (and B changed sign) for a step of 0.1° backwards. And a position stated by letter is
/// that position, not its round trip through the pose (`B30.` read back exactly).
#[test]
fn path_rules_pick_the_first_point_only() {
    let (s, c) = 30f64.to_radians().sin_cos();
    let cl: String = [10.0f64, 9.9, 9.8, 10.0]
        .iter()
        .map(|az| {
            let (sa, ca) = az.to_radians().sin_cos();
            format!("0 0 0 {} {} {}\n", s * ca, s * sa, c)
        })
        .collect();
    let head = [
        "--axis",
        "tool:0,0,1",
        "--axis",
        "tool:0,1,0@0,0,150",
        "--tool-length",
        "50",
    ];
    let mut args = vec!["path", "-", "--rule", "up:1", "--decimals", "exact"];
    args.extend(head);
    let r = cncrot(&args, &cl);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let rows: Vec<Vec<f64>> = r.stdout.lines().map(numbers).collect();
    for (row, want) in rows.iter().zip([10.0, 9.9, 9.8, 10.0]) {
        assert!(
            (row[3] - want).abs() < 1e-9 && (row[4] - 30.0).abs() < 1e-9,
            "{row:?}"
        );
    }
    let mut args = vec!["path", "-", "--dialect", "fanuc", "--decimals", "exact"];
    args.extend(head);
    let r = cncrot(&args, "G43.4 H1\nG1 X1. Y0. Z0. B30. C10.\nX2.\n");
    let rows: Vec<Vec<f64>> = r.stdout.lines().skip(1).map(numbers).collect();
    assert!(
        rows.iter().all(|r| r[3] == 10.0 && r[4] == 30.0),
        "{}",
        r.stdout
    );
}

/// `path` on three rotary axes (a C table, a B and an A head): CL rows whose `i` passes 0.9
/// (where a frame built from X alone switches to Y) turn the axes by what the direction
/// turned, 0.25°, not by tens of degrees; every row reaches its direction (the forward
/// model's third column, Ry(B)·Rx(A)·e_z turned back by C).
#[test]
fn path_three_rotary_axes_is_continuous_across_x_09() {
    let cl = "0 0 0 0.899 0.1 0.4264\n0 0 0 0.901 0.1 0.4222\n0 0 0 0.95 0.1 0.3\n";
    let args = [
        "path",
        "-",
        "--axis",
        "work:0,0,1",
        "--axis",
        "tool:0,1,0@0,0,150",
        "--axis",
        "tool:1,0,0@0,0,100",
        "--tool-length",
        "30",
        "--decimals",
        "exact",
    ];
    let r = cncrot(&args, cl);
    assert_eq!(r.code, 0, "{}", r.stderr);
    let rows: Vec<Vec<f64>> = r.stdout.lines().map(numbers).collect();
    assert_eq!(rows.len(), 3, "{}", r.stdout);
    for (row, line) in rows.iter().zip(cl.lines()) {
        let (c, b, a) = (
            row[3].to_radians(),
            row[4].to_radians(),
            row[5].to_radians(),
        );
        // Head: Ry(b)·Rx(a)·e_z; the table turns the workpiece by c: Rz(-c) of it.
        let h = [b.sin() * a.cos(), -a.sin(), b.cos() * a.cos()];
        let d = [
            c.cos() * h[0] + c.sin() * h[1],
            -c.sin() * h[0] + c.cos() * h[1],
            h[2],
        ];
        let want = numbers(line);
        let n = (want[3].powi(2) + want[4].powi(2) + want[5].powi(2)).sqrt();
        for k in 0..3 {
            assert!((d[k] - want[3 + k] / n).abs() < 1e-12, "{row:?} {line}");
        }
    }
    for w in rows.windows(2) {
        let jump = (3..6)
            .map(|k| (w[1][k] - w[0][k]).abs())
            .fold(0.0, f64::max);
        assert!(jump < 12.0, "{:?} -> {:?}", w[0], w[1]);
    }
    assert!(
        (3..6).all(|k| (rows[1][k] - rows[0][k]).abs() < 1.0),
        "{rows:?}"
    );
}
/// `path` as a user's files and options come (a helper's finds): `--rule inverse` takes the
/// other solution at the first point and stays on that branch (it swapped branches every
/// row); a byte-order mark before the first point is no header; a first line with numbers
/// is a point or an error, never a header skipped in silence; a negative `--tool-length`;
/// a program block the machine refuses leaves no words behind for the blocks after it.
#[test]
fn path_rules_marks_headers_and_refused_blocks() {
    let row = "10 0 0 0.5 0 0.8660254037844386\n";
    let mut args = vec!["path", "-", "--current", "20,80", "--rule", "inverse"];
    args.extend(AC);
    let r = cncrot(&args, &row.repeat(3));
    assert_eq!(r.code, 0, "{}", r.stderr);
    let rows: Vec<Vec<f64>> = r.stdout.lines().map(numbers).collect();
    assert_eq!(rows.len(), 3);
    close(&rows[0][3..], &[-30.0, -90.0], 1e-12);
    assert!(rows.iter().all(|r| r == &rows[0]), "{}", r.stdout);
    let mut args = vec!["path", "-", "--tool-length", "-20"];
    args.extend(&AC[..4]);
    let r = cncrot(&args, &format!("\u{feff}{row}"));
    assert_eq!(r.code, 0, "{}", r.stderr);
    // The worked example's W·tip = (0, 50 + 5√3, 105 − 50√3), the adapter L·b = −20 along
    // Z from the tip: Z = 85 − 50√3.
    let s3 = 3f64.sqrt();
    close(
        &numbers(&r.stdout)[..3],
        &[0.0, 50.0 + 5.0 * s3, 85.0 - 50.0 * s3],
        1e-4,
    );
    for first in ["l0 0 0 0 0 1", "X10 Y0 Z0 I0 J0 K1", "GOTO/10,0,0,0,0,1"] {
        let r = cncrot(&args, &format!("{first}\n{row}"));
        assert_eq!(r.code, 1, "{first}: {}", r.stdout);
        assert!(r.stdout.starts_with("error: line 1"), "{}", r.stdout);
    }
    let prog = "G43.4 H1\nG1 X10. Y0. Z0. B30. C90.\nG1 B-20.\nG1 X10. Y0. Z0. A30. C90.\n\
                G1 B-20.\nG49\n";
    let r = cncrot(
        &[
            "path",
            "-",
            "--dialect",
            "fanuc",
            "--axis",
            "work:0,1,0@10,0,50",
            "--axis",
            "work:0,0,1@5,-3,0",
            "--tool-length",
            "50",
        ],
        prog,
    );
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(
        lines[3].contains("a rotary axis the machine does not have"),
        "{}",
        r.stdout
    );
    assert_eq!(lines[4], lines[2], "{}", r.stdout);
    // After a direction, a block that names one rotary axis leaves the other where the
    // machine stands (A 30), not at the letter's last stated value (a helper's find: A 0).
    let prog = "TRAORI\nG1 X0 Y0 Z0 A3=0 B3=0.5 C3=0.8660254037844386\nG1 X1 C20\nG91 C10\n";
    let mut args = vec!["path", "-", "--dialect", "sinumerik"];
    args.extend(AC);
    let r = cncrot(&args, prog);
    let rows: Vec<Vec<f64>> = r.stdout.lines().skip(1).map(numbers).collect();
    close(&rows[0][3..], &[30.0, 0.0], 1e-9);
    close(&rows[1][3..], &[30.0, 20.0], 1e-9);
    close(&rows[2][3..], &[30.0, 30.0], 1e-9);
}

/// `path --dialect … --json`: a block not followed says so, as the text does.
#[test]
fn path_json_says_not_followed() {
    let mut args = vec!["path", "-", "--dialect", "fanuc", "--json"];
    args.extend(AC);
    let r = cncrot(&args, "G43.4 H1\nG2 X10. Y0. R5.\nG04 X1.5\n");
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(
        lines[1].contains("\"remark\":\"not followed\""),
        "{}",
        r.stdout
    );
    assert!(!lines[2].contains("remark"), "{}", r.stdout);
}

/// `path --json`: one object per input line, numbers at full precision.
#[test]
fn path_json() {
    let mut args = vec!["path", "-", "--json", "--current", "0,0,0,20,80"];
    args.extend(AC);
    let r = cncrot(&args, "10 0 0 0.5 0 0.8660254037844386\n");
    assert_eq!(r.code, 0, "{}", r.stderr);
    // Full precision: every digit a double needs (16 or 17 significant ones here), the
    // values 50 + 5√3 and 155 − 50√3 to a few ulp.
    let linear = r
        .stdout
        .strip_prefix("{\"linear\":[0,")
        .and_then(|s| s.split(']').next())
        .unwrap_or_else(|| panic!("{}", r.stdout));
    let s3 = 3f64.sqrt();
    for (text, want) in linear.split(',').zip([50.0 + 5.0 * s3, 155.0 - 50.0 * s3]) {
        let digits = text.chars().filter(char::is_ascii_digit).count();
        assert!(digits >= 15, "{text}");
        assert!(
            (text.parse::<f64>().unwrap() - want).abs() < 1e-12,
            "{text}"
        );
    }
    assert!(r.stdout.contains("\"rotary\":[30"), "{}", r.stdout);
}

/// `path --dialect`: five-axis programs of three dialects give the worked example's axes
/// on their point blocks, blank lines elsewhere, a not-followed arc marked in place.
#[test]
fn path_reads_five_axis_programs() {
    let s3 = 3f64.sqrt();
    let want = [0.0, 50.0 + 5.0 * s3, 155.0 - 50.0 * s3, 30.0, 90.0];
    let programs = [
        (
            "sinumerik",
            "N10 G0 X0 Y0 Z100\nN20 TRAORI\nN30 G1 X10 Y0 Z0 A3=0.5 B3=0 C3=0.8660254037844386\n\
             N40 G2 X0 Y10 CR=10\nN50 TRAFOOF\n",
            2,
        ),
        (
            "heidenhain",
            "0 BEGIN PGM P MM\n1 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n\
             2 L X+10 Y+0 Z+0 A+30 C+90 R0 FMAX\n3 C X+0 Y+10 DR+\n4 FUNCTION RESET TCPM\n",
            2,
        ),
        (
            "fanuc",
            "G90 G54\nG43.4 H1\nG1 X10. Y0. Z0. A30. C90.\nG2 X0 Y10. R10.\nG49\n",
            2,
        ),
    ];
    for (dialect, text, point) in programs {
        let mut args = vec![
            "path",
            "-",
            "--dialect",
            dialect,
            "--current",
            "20,80",
            "--decimals",
            "exact",
        ];
        args.extend(AC);
        let r = cncrot(&args, text);
        assert_eq!(r.code, 0, "{dialect}: {}", r.stderr);
        let lines: Vec<&str> = r.stdout.lines().collect();
        assert_eq!(lines.len(), 5, "{dialect}: {}", r.stdout);
        for (k, line) in lines.iter().enumerate() {
            if k == point {
                close(&numbers(line), &want, 1e-9);
            } else if k == point + 1 {
                assert!(line.contains("not followed"), "{dialect}: {line}");
            } else {
                assert_eq!(*line, "", "{dialect}, line {k}");
            }
        }
    }
    // A block that is not a five-axis program's: an error line in place, the exit status 1.
    let mut args = vec!["path", "-", "--dialect", "fanuc"];
    args.extend(AC);
    let r = cncrot(
        &args,
        "G43.5 H1\nG1 X1. I0 J0 K0\nG1 X1. Y0. Z0. I0 J0 K1.\n",
    );
    assert_eq!(r.code, 1);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(lines[1].starts_with("error: line 2"), "{}", r.stdout);
    assert!(lines[1].contains("tool direction"), "{}", r.stdout);
    assert_eq!(numbers(lines[2]).len(), 5, "{}", r.stdout);
}

/// An SVG picture as written: its XML root checked, its projection read off the root.
struct Picture {
    text: String,
    scale: f64,
    u0: f64,
    v0: f64,
}

impl Picture {
    fn read(path: &std::path::Path) -> Picture {
        let text = std::fs::read_to_string(path).expect("the picture is written");
        let p = {
            let doc = roxmltree::Document::parse(&text).expect("well-formed XML");
            let root = doc.root_element();
            assert_eq!(root.tag_name().name(), "svg");
            assert_eq!(
                root.tag_name().namespace(),
                Some("http://www.w3.org/2000/svg")
            );
            assert_eq!(root.attribute("data-projection"), Some("isometric"));
            let f = |a: &str| root.attribute(a).unwrap().parse::<f64>().unwrap();
            (f("data-scale"), f("data-u0"), f("data-v0"))
        };
        Picture {
            scale: p.0,
            u0: p.1,
            v0: p.2,
            text,
        }
    }

    /// Where the documented projection puts a model point (mm) on the page.
    fn at(&self, p: [f64; 3]) -> (f64, f64) {
        let c = 3f64.sqrt() / 2.0;
        let u = (p[0] + p[1]) * c;
        let w = p[2] + (p[1] - p[0]) * 0.5;
        (self.u0 + self.scale * u, self.v0 - self.scale * w)
    }

    /// An attribute of the element with this id.
    fn attr(&self, id: &str, name: &str) -> Option<String> {
        let doc = roxmltree::Document::parse(&self.text).unwrap();
        let node = doc.descendants().find(|n| n.attribute("id") == Some(id))?;
        node.attribute(name).map(str::to_string)
    }

    fn num(&self, id: &str, name: &str) -> f64 {
        self.attr(id, name)
            .unwrap_or_else(|| panic!("{id} has {name}"))
            .parse()
            .unwrap()
    }

    /// A line's two ends on the page.
    fn line(&self, id: &str) -> [(f64, f64); 2] {
        [
            (self.num(id, "x1"), self.num(id, "y1")),
            (self.num(id, "x2"), self.num(id, "y2")),
        ]
    }

    fn texts(&self) -> Vec<String> {
        let doc = roxmltree::Document::parse(&self.text).unwrap();
        doc.descendants()
            .filter(|n| n.has_tag_name("text"))
            .map(|n| n.text().unwrap_or("").to_string())
            .collect()
    }
}

fn near(a: (f64, f64), b: (f64, f64)) {
    assert!(
        (a.0 - b.0).abs() < 1e-5 && (a.1 - b.1).abs() < 1e-5,
        "{a:?} vs {b:?}"
    );
}

fn mm(o: [f64; 3], d: [f64; 3], k: f64) -> [f64; 3] {
    [o[0] + k * d[0], o[1] + k * d[1], o[2] + k * d[2]]
}

/// The pictures show the numbers: every drawn coordinate is the documented projection of
/// the frame the text reports, a plane upside down says so, the points carry their
/// deviations.
#[test]
fn svg_pictures_show_the_numbers() {
    let dir = std::env::temp_dir().join(format!("cncrot-svg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = |name: &str| dir.join(name);

    // PLANE SPATIAL SPA+30: Z' = (0, -sin 30°, cos 30°), X' = X, at the datum.
    let l = file("line.svg");
    ok(&[
        "line",
        "--from",
        "heidenhain",
        "--to",
        "fanuc",
        "--svg",
        l.to_str().unwrap(),
        "PLANE SPATIAL SPA+30 SPB+0 SPC+0",
    ]);
    let p = Picture::read(&l);
    let z = [0.0, -0.5, 3f64.sqrt() / 2.0];
    let size = p.num("plane", "data-size");
    let [a, b] = p.line("z-prime");
    near(a, p.at([0.0; 3]));
    near(b, p.at(mm([0.0; 3], z, 0.8 * size)));
    let [_, b] = p.line("x-prime");
    near(b, p.at([0.8 * size, 0.0, 0.0]));
    let [a, b] = p.line("machine-Z");
    near(a, p.at([0.0; 3]));
    assert!(
        (a.0 - b.0).abs() < 1e-9 && b.1 < a.1,
        "Z is drawn straight up"
    );
    // The patch's corners: ±size along X' and Y'.
    let y = [0.0, 3f64.sqrt() / 2.0, 0.5];
    let corners: Vec<f64> = p
        .attr("plane", "points")
        .unwrap()
        .split([' ', ','])
        .map(|t| t.parse().unwrap())
        .collect();
    for (k, (sx, sy)) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
        .into_iter()
        .enumerate()
    {
        let c = mm(mm([0.0; 3], [1.0, 0.0, 0.0], sx * size), y, sy * size);
        near((corners[2 * k], corners[2 * k + 1]), p.at(c));
    }
    assert_eq!(p.attr("plane", "class").as_deref(), Some("upper-face"));
    assert!(!p.texts().iter().any(|t| t.contains("upside down")));

    // Four corners probed clockwise, the order kept: Z' points down, said in red, the
    // underside seen. The plane z = -x/10 through the centroid (50, 25, -5); one corner
    // 0.02 mm low.
    let s = file("probe.svg");
    let pts = ["0,0,0", "0,50,0", "100,50,-10.02", "100,0,-10"];
    let mut args = vec!["probe", "--order", "--svg", s.to_str().unwrap(), "--json"];
    args.extend(pts);
    let json = ok(&args);
    let p = Picture::read(&s);
    assert_eq!(p.attr("plane", "class").as_deref(), Some("underside"));
    assert!(p.texts().iter().any(|t| t.contains("upside down")));
    let field = |name: &str| {
        let at = json.find(&format!("\"{name}\":")).unwrap();
        let rest = &json[at + name.len() + 3..];
        numbers(&rest[..rest.find(']').unwrap()].replace('[', " "))
    };
    let n = field("normal");
    let o = field("origin");
    assert!(n[2] < -0.99, "{n:?}");
    let size = p.num("plane", "data-size");
    let [a, b] = p.line("z-prime");
    let (o, n) = ([o[0], o[1], o[2]], [n[0], n[1], n[2]]);
    near(a, p.at(o));
    near(b, p.at(mm(o, n, 0.8 * size)));
    let [_, t] = p.line("tool");
    near(t, p.at(mm(o, n, 1.6 * size)));
    for (k, q) in pts.iter().enumerate() {
        let q: Vec<f64> = numbers(q);
        let id = format!("P{}", k + 1);
        let want: f64 = (0..3).map(|i| (q[i] - o[i]) * n[i]).sum();
        let dev = p.num(&id, "data-deviation");
        assert!((dev - want).abs() < 1e-6, "{id}: {dev} vs {want}");
        // The corners' deviations are a quarter of the 0.02 mm, along the normal.
        assert!((dev.abs() - 0.005 * n[2].abs()).abs() < 1e-5, "{id}: {dev}");
        assert!(size >= (0..3).map(|i| (q[i] - o[i]).powi(2)).sum::<f64>().sqrt());
        // Drawn enlarged along the normal from its foot on the plane.
        let foot = mm([q[0], q[1], q[2]], n, -dev);
        let (fx, fy) = p.at(foot);
        let (dx, dy) = (p.num(&id, "cx") - fx, p.num(&id, "cy") - fy);
        let (nx, ny) = {
            let (a, b) = (p.at(mm(foot, n, 1.0)), p.at(foot));
            (a.0 - b.0, a.1 - b.1)
        };
        assert!((dx * ny - dy * nx).abs() < 1e-6, "{id} off the normal");
        assert!((dx * nx + dy * ny) * dev > 0.0, "{id} on its side");
    }

    // The machine's positions, and a program's tilts each drawn and labelled.
    let a = file("axes.svg");
    ok(&[
        "axes",
        "--axis",
        "work:1,0,0",
        "--axis",
        "work:0,0,1",
        "--svg",
        a.to_str().unwrap(),
        "0",
        "30",
        "0",
    ]);
    let p = Picture::read(&a);
    assert!(p
        .texts()
        .iter()
        .any(|t| t.contains("axis 1 = 30.0000, axis 2 = 90.0000")));
    let [_, b] = p.line("z-prime");
    let size = p.num("plane", "data-size");
    near(
        b,
        p.at([0.8 * size * 0.5, 0.0, 0.8 * size * 3f64.sqrt() / 2.0]),
    );
    let prog = file("part.h");
    std::fs::write(
        &prog,
        "BEGIN PGM P MM\nPLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY\nL X0 Y0\n\
         PLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY\nPLANE RESET STAY\nEND PGM P MM\n",
    )
    .unwrap();
    let g = file("program.svg");
    ok(&[
        "program",
        prog.to_str().unwrap(),
        "--dialect",
        "heidenhain",
        "--svg",
        g.to_str().unwrap(),
    ]);
    let p = Picture::read(&g);
    assert!(p.attr("plane", "points").is_some() && p.attr("plane-1", "points").is_some());
    assert!(
        p.attr("plane-2", "points").is_none(),
        "the cancel draws no plane"
    );
    let texts = p.texts();
    assert!(texts.contains(&"line 2".to_string()) && texts.contains(&"line 4".to_string()));
    let [_, b] = p.line("z-prime-1");
    let size = p.num("plane-1", "data-size");
    let h = 0.8 * size / 2f64.sqrt();
    near(b, p.at([h, 0.0, h]));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Every refusal names what was wrong: the word that is missing or not understood, the
/// parameter and what it may be, the line of a file, the data set asked for.
#[test]
fn refusals_name_what_was_wrong() {
    let dir = std::env::temp_dir().join(format!("cncrot-msg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let carr = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let kind_x = carr("x.carr", "$TC_CARR7[1]=1\n$TC_CARR23[1]=\"X\"\n");
    let parallel = carr(
        "par.carr",
        "$TC_CARR8[1]=1\n$TC_CARR10[1]=0 $TC_CARR11[1]=2 $TC_CARR12[1]=0\n",
    );
    let no_first = carr("nofirst.carr", "$TC_CARR23[1]=\"P\"\n$TC_CARR12[1]=1\n");
    let hirth = carr("hirth.carr", "$TC_CARR7[1]=1\n$TC_CARR28[1]=-1\n");
    let unknown = carr("p50.carr", "$TC_CARR7[1]=1\n$TC_CARR50[1]=1\n");
    let variable = carr("r1.carr", "$TC_CARR7[1]=R1\n");
    let exponent = carr("e.carr", "$TC_CARR7[1]=1\n$TC_CARR24[1]=1e6\n");
    let missing_svg = dir.join("no-such-dir").join("p.svg");
    let heads = carr("heads.spf", "_HEAD_NAME=\"UFK600\"\n_DELTA_L1=1.2.3\n");
    let cases: Vec<(Vec<&str>, &str)> =
        vec![
        (
            vec!["line", "--from", "heidenhain", "PLANE SPATIAL SPA+10 SPB+0"],
            "column 27: missing: SPC",
        ),
        (
            vec!["line", "--from", "heidenhain", "PLANE SPATIAL SPA+10 SPB+0 SPC+0 SEQ"],
            "missing: '+' or '-'",
        ),
        (
            vec!["line", "--from", "haas", "G268 X0 I0 J30 K0"],
            "missing: Q",
        ),
        (
            vec!["line", "--from", "heidenhain", "PLANE SPATIAL SPX+10 SPB+0 SPC+0"],
            "column 15: 'SPX+10': unknown, repeated or misplaced word",
        ),
        (
            vec!["line", "--from", "twincat", "ROT Z=R1"],
            "column 7: 'R1': a variable or an expression where a number must stand",
        ),
        (
            vec!["line", "--from", "fanuc", "G68.2 X1 (note"],
            "'(note': a comment that is not closed",
        ),
        (
            vec![
                "line",
                "--from",
                "sinumerik",
                "CYCLE600(0,\"UFK 600\",1,57,0,0,0,30,45,60,0,0,0,1,39)",
            ],
            "column 12: \"UFK 600\": parameter outside its allowed values (_MIHEAD: empty, or \
             at most 31 printable characters without spaces or quotes)",
        ),
        (
            vec!["cycle600", "0,\"UFK 600\",1,57,0,0,0,30,45,60,0,0,0,1,39"],
            "column 3: \"UFK 600\": parameter outside its allowed values (_MIHEAD:",
        ),
        (
            vec!["cycle600", "0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,3,39"],
            "3: a flag is neither 0 nor 1 (_INEXOUT: 0 (extrinsic) or 1 (intrinsic))",
        ),
        (
            vec!["axes", "--carr", &kind_x, "0", "0", "0"],
            "x.carr, line 2: $TC_CARR23, the kinematics type, must be \"T\" (tool), \"P\" \
             (part) or \"M\" (mixed)",
        ),
        (
            vec!["axes", "--carr", &kind_x, "--set", "2", "0", "0", "0"],
            "x.carr: data set 2 is not in the file",
        ),
        (
            vec!["axes", "--carr", &parallel, "0", "0", "0"],
            "par.carr, line 2: $TC_CARR10: axis 2 ($TC_CARR10..12) needs axis 1",
        ),
        (
            vec!["axes", "--carr", &no_first, "0", "0", "0"],
            "nofirst.carr, line 2: $TC_CARR12: axis 2",
        ),
        (
            vec!["axes", "--carr", &hirth, "0", "0", "0"],
            "hirth.carr, line 2: $TC_CARR28, a Hirth increment, must be 0 (no grid) or positive",
        ),
        (
            vec!["axes", "--carr", &unknown, "0", "0", "0"],
            "p50.carr, line 2: $TC_CARR50 is no swivel-data parameter",
        ),
        (
            vec!["axes", "--carr", &variable, "0", "0", "0"],
            "r1.carr, line 1: $TC_CARR7: a variable or expression where a number must stand",
        ),
        (
            vec!["axes", "--carr", &exponent, "0", "0", "0"],
            "e.carr, line 2: $TC_CARR24: malformed assignment",
        ),
        (
            vec![
                "cycle600",
                "--heads",
                &heads,
                "0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39",
            ],
            "heads.spf, line 2 (_DELTA_L1=1.2.3): not a HEAD_DEF assignment",
        ),
        (
            vec![
                "probe",
                "0,0,0",
                "1,0,0",
                "0,1,0",
                "--svg",
                missing_svg.to_str().unwrap(),
            ],
            "--svg ",
        ),
    ];
    for (args, want) in cases {
        let r = cncrot(&args, "");
        assert!(r.code != 0, "{args:?} succeeded");
        assert!(
            r.stderr.contains(want),
            "{args:?}:\n{}\nwanted: {want}",
            r.stderr
        );
    }
    // The option the help names is the option that works.
    let help = ok(&["help", "probe"]);
    assert!(help.contains("--points-file <FILE>"), "{help}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `program --to` on a program as CAM writes it for a TNC (cycle 7 before the plane): the
/// datum shift in the target's own command, the tilt about the shifted datum (Fanuc) or with
/// the whole origin (SINUMERIK's CYCLE800, which replaces the frame), the reset keeping the
/// shift, cycle 7's first line left out, TURN as G53.1 (the text of docs/cli.md). By hand:
/// SPB+30 is Ry(30) = Rz(90)·Rx(30)·Rz(−90) (I90 J30 K−90); SPB−20 SPC+90 is
/// Rz(90)·Ry(−20) = Rx(20)·Rz(90) (I0 J20 K90; CYCLE800 57: A20 B0 C90).
#[test]
fn program_to_writes_datum_shifts() {
    let prog = "0 BEGIN PGM TILT MM\n1 TOOL CALL 1 Z S5000\n2 CYCL DEF 7.0 DATUM SHIFT\n\
                3 CYCL DEF 7.1 X+10\n4 CYCL DEF 7.2 Y+20\n\
                5 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-\n6 L X+10 Y+0 FMAX\n\
                7 PLANE SPATIAL SPA+0 SPB-20 SPC+90 TURN FMAX\n8 PLANE RESET STAY\n9 END PGM TILT MM\n";
    let r = cncrot(
        &["program", "-", "--dialect", "heidenhain", "--to", "fanuc"],
        prog,
    );
    // A retraction or turn the target has no word for: exit status 1.
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains(", 1 with a way of moving left out"),
        "{}",
        r.stderr
    );
    let want = [
        "0 BEGIN PGM TILT MM",
        "1 TOOL CALL 1 Z S5000",
        // Cycle 7's axis lines: one shift.
        "G52 X10. Y20. Z0.",
        "G68.2 X0. Y0. Z0. I90. J30. K-90.",
        "G53.1",
        "6 L X+10 Y+0 FMAX",
        // A new plane over an active one: cancelled first.
        "G69",
        "G68.2 X0. Y0. Z0. I0. J20. K90.",
        "G53.1",
        "G69",
        "9 END PGM TILT MM",
    ];
    assert_eq!(r.stdout.lines().collect::<Vec<_>>(), want);
    let r = cncrot(
        &[
            "program",
            "-",
            "--dialect",
            "heidenhain",
            "--to",
            "sinumerik",
        ],
        prog,
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    // The shift alone reset before the cycle carries the whole origin, the tilt cancelled
    // before the shift is set alone again.
    assert_eq!(
        lines[2..5],
        [
            "TRANS X=10 Y=20 Z=0",
            "TRANS",
            "CYCLE800(4,\"\",0,57,10,20,0,0,30,0,0,0,0,-1,0,0)"
        ]
    );
    assert_eq!(lines[7..9], ["CYCLE800()", "TRANS X=10 Y=20 Z=0"]);
    // Into SINUMERIK's ROT, which has no origin words: the origin is `TRANS` (which replaces
    // the one frame), the rotation `AROT` about it; the cancel `ROT` takes the shift too, so
    // the shift follows it again. SPB+30 is RPY Y=30; SPB−20 SPC+90, Rz(90)·Ry(−20), is RPY
    // Y=-20 Z=90. `ROT` has no word for TURN: exit status 1.
    let r = cncrot(
        &[
            "program",
            "-",
            "--dialect",
            "heidenhain",
            "--to",
            "sinumerik:ROT",
        ],
        prog,
    );
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert_eq!(
        r.stdout.lines().collect::<Vec<_>>()[2..10],
        [
            "TRANS X=10 Y=20 Z=0",
            "TRANS X=10 Y=20 Z=0",
            "AROT X=0 Y=30 Z=0",
            "6 L X+10 Y+0 FMAX",
            "TRANS X=10 Y=20 Z=0",
            "AROT X=0 Y=-20 Z=90",
            "ROT",
            "TRANS X=10 Y=20 Z=0",
        ]
    );
    // The summary counts what was left out.
    assert!(
        r.stderr
            .contains("0 refused, 0 not carried across, 2 with a way of moving left out"),
        "{}",
        r.stderr
    );
}

/// Blocks the target writes as one command (cycle 19's lines, a `G68.2` and its `G53.1`):
/// when the command cannot be written (rotary-axis positions without a machine), every one of
/// them keeps its line as it stands, not only the last.
#[test]
fn program_to_keeps_a_whole_run_it_cannot_write() {
    let prog = "1 CYCL DEF 19.0 WORKING PLANE\n2 CYCL DEF 19.1 A+0 B+45 C+90\n3 L Z+50 FMAX\n";
    let args = [
        "program",
        "-",
        "--dialect",
        "heidenhain",
        "--axis-angles",
        "--to",
        "fanuc",
    ];
    let r = cncrot(&args, prog);
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert_eq!(r.stdout, prog);
    assert!(r.stderr.contains("1 not carried across"), "{}", r.stderr);
    // Written, cycle 19's first line goes with the others.
    let prog = "1 CYCL DEF 19.0 WORKING PLANE\n2 CYCL DEF 19.1 B+30\n3 L Z+50 FMAX\n";
    let r = cncrot(
        &["program", "-", "--dialect", "heidenhain", "--to", "fanuc"],
        prog,
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_eq!(
        r.stdout.lines().collect::<Vec<_>>(),
        ["G68.2 X0. Y0. Z0. I90. J30. K-90.", "3 L Z+50 FMAX"]
    );
}

/// Each block's positions are chosen from where the axes are: the last block that moved
/// them (`TURN`, `G53.1`), not a block that stays (`STAY`, a cancel, a datum shift, a
/// `G68.2` before its `G53.1`), whose row shows where its plane needs them (a helper's
/// checks on a fork head C on B). From C 87, B -20 the plane (0.5, 0, 0.866) is C 0, B 30
/// (87² + 50² = 10069 away) or C 180, B -30 (93² + 10² = 8749): the latter, also after a
/// datum shift or a `STAY`; and `G53.1 P1` turns the master axis up from where it is.
#[test]
fn program_positions_follow_the_blocks_that_move_the_axes() {
    let axes = |prog: &str, dialect: &str, machine: &[&str], current: &str| -> Vec<String> {
        let mut args = vec!["program", "-", "--dialect", dialect, "--current", current];
        args.extend_from_slice(machine);
        let r = cncrot(&args, prog);
        assert_eq!(r.code, 0, "{}", r.stderr);
        r.stdout
            .lines()
            .filter_map(|l| l.split("axes: ").nth(1))
            .map(String::from)
            .collect()
    };
    let fork = ["--axis", "tool:0,0,1", "--axis", "tool:0,1,0"];
    let shifted = "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\n\
                   PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n";
    let got = axes(shifted, "heidenhain", &fork, "87,-20");
    assert_eq!(
        got.last().map(String::as_str),
        Some("180.0000 -30.0000"),
        "{got:?}"
    );
    let stayed = "PLANE SPATIAL SPA+0 SPB-60 SPC+0 STAY\n\
                  PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n";
    let got = axes(stayed, "heidenhain", &fork, "87,-20");
    assert_eq!(
        got.last().map(String::as_str),
        Some("180.0000 -30.0000"),
        "{got:?}"
    );
    // An AC table from A 0, C 0: the G68.2 row (not moved to) shows the closest, A -30; then
    // G53.1 P1 turns A (the master axis) up: A 30 (C 180) rather than A -30 330° up.
    let ac = ["--axis", "work:1,0,0", "--axis", "work:0,0,1"];
    let got = axes("G68.2 X0 Y0 Z0 I0 J30 K0\nG53.1 P1\n", "fanuc", &ac, "0,0");
    assert_eq!(got, ["-30.0000 0.0000", "30.0000 -180.0000"]);
}

/// A turn to a tilt not followed above (Fanuc's two vectors, `G68.2 P3`, whose words no text
/// found defines; then `G53.1`) is not written as a turn to the plane the state has: it was
/// `PLANE RESET TURN FMAX`, which turns the axes home where the control turns them to the
/// `P3` plane (a helper's find). Kept as it stands and flagged; a tilt after it is written.
#[test]
fn program_to_keeps_a_turn_to_a_tilt_not_followed() {
    let prog = "G68.2 P3 Q1 X10. Y0. Z0. I1. J0. K0.\nG68.2 P3 Q2 I0. J-0.5 K0.866\nG0 X0\nG53.1\nG69\nG68.2 X0 Y0 Z0 I0 J30 K0\nG53.1\n";
    let r = translate(prog, "fanuc", "heidenhain");
    assert_eq!(r.code, 1);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(
        lines,
        [
            "G68.2 P3 Q1 X10. Y0. Z0. I1. J0. K0.",
            "G68.2 P3 Q2 I0. J-0.5 K0.866",
            "G0 X0",
            "G53.1",
            "PLANE RESET STAY",
            "PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX"
        ]
    );
    assert!(
        r.stderr.contains("line 4: not carried across as heidenhain PLANE SPATIAL: it moves the machine to a tilt refused or not followed above"),
        "{}",
        r.stderr
    );
    // A work offset beside a cancel sets the frame again: the turn after it is written.
    let prog = "G69 G54\nG68.2 X0 Y0 Z0 I0 J30 K0\nG53.1\n";
    let r = translate(prog, "fanuc", "heidenhain");
    assert!(!r.stderr.contains("not carried across as"), "{}", r.stderr);
}

/// A turn to a tilt refused above (Hurco's `G68.2 … U V W`, then `G53.1`) is not written as
/// a turn to the plane the state has (the untilted one: `PLANE RESET TURN` would move the
/// machine where the source does not): kept as it stands and flagged; a cancel after it sets
/// the frame again and is written.
#[test]
fn program_to_keeps_a_turn_to_a_refused_tilt() {
    let prog = "G69\nG68.2 X10. Y0. Z-5. I0.866025 J0. K-0.5 U0. V1. W0.\nG53.1\nG0 X0 Y0\nG69\n";
    let r = translate(prog, "fanuc", "heidenhain");
    assert_eq!(r.code, 1);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(
        lines,
        [
            "PLANE RESET STAY",
            "G68.2 X10. Y0. Z-5. I0.866025 J0. K-0.5 U0. V1. W0.",
            "G53.1",
            "G0 X0 Y0",
            "PLANE RESET STAY"
        ]
    );
    assert!(
        r.stderr.contains("line 3: not carried across as heidenhain PLANE SPATIAL: it moves the machine to a tilt refused or not followed above")
            && r.stderr.contains("1 refused, 1 not carried across"),
        "{}",
        r.stderr
    );
}

/// `cncrot program - --dialect FROM --to TO` on `prog`.
fn translate(prog: &str, from: &str, to: &str) -> Run {
    cncrot(&["program", "-", "--dialect", from, "--to", to], prog)
}

/// A program in `from` translated by `cncrot program - --to TO`, which must succeed: its
/// output lines.
fn program_to(prog: &str, from: &str, to: &str) -> Vec<String> {
    let r = translate(prog, from, to);
    assert_eq!(r.code, 0, "{}", r.stderr);
    r.stdout.lines().map(String::from).collect()
}

/// A block number stays where a tilt or cancel block is translated: on the first line
/// written for it, or alone where the block writes nothing (the first of a `G68.2` and its
/// `G53.1`), so that `GOTO20` still finds its block (a helper's find: the control's alarm
/// "sequence number not found"); into Heidenhain none (it numbers its lines itself).
#[test]
fn program_to_keeps_block_numbers() {
    let prog = "#1=0\nN20 G68.2 X0 Y0 Z0 I0 J30 K0\nN25 G53.1\nN30 G69\n#1=#1+1\n\
                IF [#1 LT 3] GOTO20\n/N40 G69\nM30\n";
    assert_eq!(
        program_to(prog, "fanuc", "haas"),
        [
            "#1=0",
            "N20",
            "N25 G268 X0. Y0. Z0. I30. J0. K0. Q123",
            "G253",
            "N30 G269",
            "#1=#1+1",
            "IF [#1 LT 3] GOTO20",
            "/N40 G269",
            "M30"
        ]
    );
    assert!(!program_to(prog, "fanuc", "heidenhain")
        .iter()
        .any(|l| l.starts_with("N2") || l.starts_with("N3")));
}

/// A comment on a translated block is carried in the target's form, at the end of the first
/// line written for the block, or alone where the block writes nothing: CAM posts name each
/// plane (`(TILT FRONT)`, `; SIDE (B)`), and the translation dropped every such name.
#[test]
fn program_to_keeps_comments() {
    let prog = "N20 G68.2 X0. Y0. Z0. I0. J45. K0. (TILT FRONT)\nN30 G53.1 (ORIENT)\n\
                N40 G0 X0 Y0\nN50 G69 (CANCEL TILT)\n";
    assert_eq!(
        program_to(prog, "fanuc", "haas"),
        [
            "N20 (TILT FRONT)",
            "N30 G268 X0. Y0. Z0. I45. J0. K0. Q123 (ORIENT)",
            "G253",
            "N40 G0 X0 Y0",
            "N50 G269 (CANCEL TILT)"
        ]
    );
    assert_eq!(
        program_to(prog, "fanuc", "heidenhain"),
        [
            "; TILT FRONT",
            "PLANE SPATIAL SPA+45 SPB+0 SPC+0 TURN FMAX ; ORIENT",
            "N40 G0 X0 Y0",
            "PLANE RESET STAY ; CANCEL TILT"
        ]
    );
    // A comment's parentheses, which a Fanuc comment cannot hold; a SINUMERIK string is no
    // comment, whatever it holds.
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY ; SIDE (B)\n";
    assert_eq!(
        program_to(prog, "heidenhain", "fanuc"),
        ["G68.2 X0. Y0. Z0. I90. J30. K-90. (SIDE B)"]
    );
    let prog = "CYCLE800(0,\"T;C\",0,57,0,0,0,0,30,0,0,0,0,0,0,0)\nCYCLE800() ; RESET\n";
    assert_eq!(
        program_to(prog, "sinumerik", "fanuc"),
        ["G68.2 X0. Y0. Z0. I90. J30. K-90.", "G69 (RESET)"]
    );
    // The words kept beside a tilt hold their comment in the target's form: a parenthesis
    // is no comment in SINUMERIK (it was copied so).
    assert_eq!(
        program_to(
            "N50 G90 G68.2 X0 Y0 Z0 I0 J30 K0 (TILT)\n",
            "fanuc",
            "sinumerik"
        ),
        [
            "N50 G90 ; TILT",
            "CYCLE800(0,\"\",0,57,0,0,0,30,0,0,0,0,0,0,0,0)"
        ]
    );
}

/// A spindle or coolant M function on Heidenhain's turn to the plane (`L B+Q121 C+Q122 R0
/// FMAX M3`) leaves the block the turn it is: it was passed over as a move, so the target got
/// no `G53.1` (the axes never turned) and the TNC's `Q121`/`Q122` copied as they stood. The
/// M function is kept on a line before the turn (the TNC switches it at the block's start).
#[test]
fn program_to_keeps_the_m_functions_of_a_turn() {
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY SEQ+\nL B+Q121 C+Q122 R0 FMAX M3\n\
                L X+0 Y+0 R0 FMAX\n";
    assert_eq!(
        program_to(prog, "heidenhain", "fanuc"),
        [
            "M3",
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "G53.1",
            "L X+0 Y+0 R0 FMAX"
        ]
    );
}

/// A cancel beside a work offset (`G69 G55`) still cancels: the block is not followed as a
/// whole (the offset is a table's), but the control cancels the plane whatever else the
/// block holds. Before, the block was copied as it stood and the target stayed tilted: the
/// plunge after it ran at 45° (a helper's find). The offset, copied, selects the same on a
/// Haas (exit status 0); into Heidenhain, which has no `G55`, it is not carried (status 1).
#[test]
fn program_to_cancels_beside_a_work_offset() {
    let prog = "G68.2 X0 Y0 Z0 I0 J45 K0\nG53.1\nG69 G55\nG1 Z-5 F100\n";
    let r = translate(prog, "fanuc", "heidenhain");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 3: not followed beside its cancel"),
        "{}",
        r.stderr
    );
    let r = translate(prog, "fanuc", "haas");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_eq!(
        r.stdout.lines().collect::<Vec<_>>(),
        [
            "G268 X0. Y0. Z0. I45. J0. K0. Q123",
            "G253",
            "G55",
            "G269",
            "G1 Z-5 F100"
        ]
    );
    assert!(
        r.stderr.contains("line 3: a work offset beside its cancel"),
        "{}",
        r.stderr
    );
    // SINUMERIK's SCALE and MIRROR replace the programmable frame, its rotation with it
    // (substituting commands, as TRANS and ROT): the tilt is cancelled, the block kept
    // (a helper's find: the Heidenhain translation stayed tilted to the program's end).
    // `ROT Y30` is Ry(30°), SPB+30.
    let r = translate(
        "ROT Y30\nSCALE X2\nG0 X10\nASCALE X2\n",
        "sinumerik",
        "heidenhain",
    );
    assert_eq!(
        r.stdout.lines().collect::<Vec<_>>(),
        [
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
            "SCALE X2",
            "PLANE RESET STAY",
            "G0 X10",
            "ASCALE X2"
        ]
    );
    // The report: the frame after it is untilted.
    let r = cncrot(
        &["program", "-", "--dialect", "fanuc"],
        "G68.2 X0 Y0 Z0 I0 J45 K0\nG69 G55\nG68.4 I0 J0 K0\n",
    );
    assert!(
        r.stdout.contains("line 3: G68.4 I0 J0 K0\n  origin: 0.0000 0.0000 0.0000  tool direction: 0.0000 0.0000 1.0000"),
        "{}",
        r.stdout
    );
}

/// `TABLE ROT` (the rotary table makes the turn about the tool) has no word in Fanuc's
/// `G68.2`: named on standard error like a choice of solution (a helper's find: it was left
/// out without a word), the same plane written.
#[test]
fn program_to_names_a_table_rot_left_out() {
    let prog = "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX TABLE ROT\nPLANE RESET STAY\n";
    let r = translate(prog, "heidenhain", "fanuc");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 1: TABLE ROT (the rotary table making the turn about the tool) has no word in fanuc G68.2"),
        "{}",
        r.stderr
    );
    let r = translate(
        &prog.replace("TABLE ROT", "COORD ROT"),
        "heidenhain",
        "fanuc",
    );
    assert!(!r.stderr.contains("TABLE ROT"), "{}", r.stderr);
}

/// SINUMERIK's retraction along the machine's Z (`_FR` 1) is Heidenhain's `MB MAX` along the
/// tool: from a tilted tool another line, so named and counted (two helpers' find: changed
/// without a word).
#[test]
fn program_to_names_a_retraction_along_another_line() {
    let prog = "CYCLE800(1,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1)\nCYCLE800()\n";
    let r = translate(prog, "sinumerik", "heidenhain");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert_eq!(
        r.stdout.lines().next(),
        Some("PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-")
    );
    assert!(
        r.stderr.contains("line 1: the retraction along the machine's Z before the rotary axes turn has no word in heidenhain PLANE SPATIAL"),
        "{}",
        r.stderr
    );
}

/// Heidenhain's `MOVE` about a point `DIST`/`ABST` mm from the tool tip is written as the turn
/// that keeps the tip itself (`G53.6`): named and counted (a helper's find: dropped without a
/// word); `DIST+0` is the tip.
#[test]
fn program_to_names_a_pivot_distance_left_out() {
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE ABST50 FMAX\nPLANE RESET STAY\n";
    let r = translate(prog, "heidenhain", "fanuc");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 1: the turn about a point 50 mm from the tool tip (DIST) has no word in fanuc G68.2")
            && r.stderr.contains("1 with a way of moving left out"),
        "{}",
        r.stderr
    );
    let r = translate(&prog.replace("ABST50", "DIST+0"), "heidenhain", "fanuc");
    assert_eq!(r.code, 0, "{}", r.stderr);
    // Into a target whose turn keeps no point in place (CYCLE800) the two notes agree: a
    // turn about the pivot, the distance not written (a helper's find: the second note said
    // the tip was kept).
    let r = translate(prog, "heidenhain", "sinumerik");
    assert!(
        r.stderr
            .contains("(DIST) has no word in sinumerik CYCLE800: not written")
            && !r.stderr.contains("keeps the tool tip itself in place"),
        "{}",
        r.stderr
    );
}

/// A Fanuc subprogram in the same file (`M98 P2000` … `O2000` … `M99`) is followed: its
/// `G68.4` adds to the plane of the call (a helper's find: read from no tilt, `G68.4 I90` was
/// written as Haas's `G268 … I0 J0 K90`, the tool swung from horizontal back to vertical). By
/// hand: `G68.2 J90` is Rx(90°), the tool along −Y; `G68.4 I90` adds Rz(90°) on it, about
/// the tool: Rx(90°)·Rz(90°) takes X to +Z, which Haas's `Q123` writes as `I90 J-90 K0`
/// (Ry(−90°)·Rx(90°) takes X to +Z and Z to −Y). `L2` runs it twice: Rz(180°) on Rx(90°).
#[test]
fn program_follows_an_iso_subprogram() {
    let prog = "N10 G68.2 X0 Y0 Z0 I0 J90. K0\nN20 G53.1\nN30 M98 P2000\nN40 G69\nN50 M30\n\
                O2000\nN100 G68.4 X0 Y0 Z0 I90. J0 K0\nN110 G53.1\nN120 M99\n";
    let r = translate(prog, "fanuc", "haas");
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(
        lines.contains(&"G268 X0. Y0. Z0. I90. J-90. K0. Q123"),
        "{lines:?}"
    );
    // `L2` runs it twice: the plane after the call is the one the same blocks written twice
    // in place reach (an increment after it is written from there).
    let after = |p: &str| {
        let r = translate(p, "fanuc", "haas");
        let lines: Vec<String> = r.stdout.lines().map(String::from).collect();
        let k = lines.iter().position(|l| l.starts_with("N40")).unwrap_or(0);
        lines[k..k + 3].join("\n")
    };
    let called = "N10 G68.2 X0 Y0 Z0 I0 J90. K0\nN20 G53.1\nN30 M98 P2000 L2\n\
                  N40 G68.4 X0 Y0 Z0 I0 J30. K0\nN50 M30\n\
                  O2000\nN100 G68.4 X0 Y0 Z0 I90. J0 K0\nN120 M99\n";
    let inline = "N10 G68.2 X0 Y0 Z0 I0 J90. K0\nN20 G53.1\nN31 G68.4 X0 Y0 Z0 I90. J0 K0\n\
                  N32 G68.4 X0 Y0 Z0 I90. J0 K0\nN40 G68.4 X0 Y0 Z0 I0 J30. K0\nN50 M30\n";
    assert_eq!(after(called), after(inline));
    assert_ne!(after(called), after(&called.replace(" L2", "")));
    // Haas's local subprogram, `M97 P1000` to `N1000`.
    let haas = "G268 X0 Y0 Z0 I90. J0 K0 Q123\nG253\nM97 P1000\nG269\nM30\n\
                N1000 G269\nM99\n";
    let r = cncrot(&["program", "-", "--dialect", "haas"], haas);
    assert!(
        r.stdout.contains("line 3: M97 P1000\n  origin: 0.0000 0.0000 0.0000  tool direction: 0.0000 0.0000 1.0000"),
        "{}",
        r.stdout
    );
}

/// An increment the target cannot say (Haas's `G268`), in a section the program repeats
/// (`CALL LBL 1 REP 2`: three runs) or a subprogram called twice (`M98 P2000 L2`): not
/// carried across, exit status 1 (a helper's find: exit 0 with a note, every pass after the
/// first machining the same face). Run once, the note alone.
#[test]
fn program_to_counts_an_increment_the_program_repeats() {
    let section = "0 BEGIN PGM R MM\n1 PLANE SPATIAL SPA+0 SPB+90 SPC+0 STAY\n2 LBL 1\n\
                   3 L Z+50 R0 FMAX\n4 PLANE RELATIV SPA+90 STAY\n5 CALL LBL 1 REP 2\n\
                   6 PLANE RESET STAY\n7 END PGM R MM\n";
    let r = translate(section, "heidenhain", "haas");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr
            .contains("does not add (the program runs it 3 times: not carried across)")
            && r.stderr.contains("1 not carried across"),
        "{}",
        r.stderr
    );
    let sub = "G68.2 X0 Y0 Z0 I0 J90. K0\nG53.1\nM98 P2000 L2\nM30\nO2000\n\
               G68.4 X0 Y0 Z0 I90. J0 K0\nM99\n";
    let r = translate(sub, "fanuc", "haas");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("(the program runs it 2 times"),
        "{}",
        r.stderr
    );
    let r = translate(&sub.replace(" L2", ""), "fanuc", "haas");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.contains("does not add: G68.4"), "{}", r.stderr);
}

/// Calls as programs write them (a helper's finds): Fanuc's older `M98 P32000` runs `O2000`
/// three times; a call inside a subprogram run three times runs its own three times too
/// (counted: "runs it 3 times"); runs of `L` beyond reason are bounded (three `L9999` deep
/// returned only after minutes) and the bound named.
#[test]
fn program_follows_calls_as_programs_write_them() {
    let old = "G68.2 X0 Y0 Z0 I90. J0 K0\nM98 P32000\nG68.4 X0 Y0 Z0 I0 J0 K0\nM30\n\
               O2000\nG68.4 X0 Y0 Z0 I10. J0 K0\nM99\n";
    let r = translate(old, "fanuc", "haas");
    assert!(
        r.stderr.contains("(the program runs it 3 times"),
        "{}",
        r.stderr
    );
    let nested = "G68.2 X0 Y0 Z0 I0 J90. K0\nM98 P2000 L3\nM30\nO2000\nM98 P3000\nM99\n\
                  O3000\nG68.4 X0 Y0 Z0 I0 J0 K30.\nM99\n";
    let r = translate(nested, "fanuc", "haas");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("(the program runs it 3 times"),
        "{}",
        r.stderr
    );
    let loops = "G68.2 X0 Y0 Z0 I0 J30. K0\nM98 P2000 L9999\nM30\nO2000\nM98 P3000 L9999\nM99\n\
                 O3000\nM98 P4000 L9999\nM99\nO4000\nG0 X0\nM99\n";
    // Passes that leave the frame as they found it end the runs: nothing is cut.
    let r = cncrot(&["program", "-", "--dialect", "fanuc"], loops);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(!r.stderr.contains("followed that far"), "{}", r.stderr);
    // Passes that turn the plane each time (10⁸ of them) are followed to the bound, and
    // the cut is said: the frame after the call is not the control's.
    let turning = "G68.2 X0 Y0 Z0 I0 J30. K0\nM98 P2000 L9999\nM30\nO2000\nM98 P3000 L9999\nM99\n\
                   O3000\nG68.4 X0 Y0 Z0 I0 J0 K1.\nM99\n";
    let r = cncrot(&["program", "-", "--dialect", "fanuc"], turning);
    assert!(
        r.stderr
            .contains("line 2: the calls from here change the frame in every pass"),
        "{}",
        r.stderr
    );
    let r = translate(turning, "fanuc", "haas");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(r.stderr.contains("followed that far"), "{}", r.stderr);
    // A subprogram that calls itself (a control stops it with an alarm) is followed 8 calls
    // deep, and the cut said.
    let own = "G68.2 X0 Y0 Z0 I0 J30. K0\nM98 P2000\nM30\nO2000\nG68.4 X0 Y0 Z0 I0 J0 K1.\n\
               M98 P2000\nM99\n";
    let r = cncrot(&["program", "-", "--dialect", "fanuc"], own);
    assert!(
        r.stderr
            .contains("line 2: the calls from here nest more than 8 calls deep"),
        "{}",
        r.stderr
    );
}

/// A turn home (`PLANE RESET TURN`) into a target that says no turn (Syntec's `G158`,
/// TwinCAT's `ROT`) is a turn left out: named and counted (a helper's find: written from no
/// tilt it compared as no tilt either way, and went unsaid).
#[test]
fn program_to_counts_a_turn_home_left_out() {
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\nPLANE RESET TURN FMAX\n";
    for to in ["syntec", "twincat"] {
        let r = translate(prog, "heidenhain", to);
        assert_eq!(r.code, 1, "{to}: {}", r.stderr);
        assert!(
            r.stderr
                .contains("line 2: the turn of the rotary axes to the plane has no word"),
            "{to}: {}",
            r.stderr
        );
    }
    assert_eq!(translate(prog, "heidenhain", "fanuc").code, 0);
}

/// A subprogram called from two planes that shifts the datum under them and moves (a face's
/// pattern): its translation, made once from the first call's frame, writes that call's
/// tilt again around each shift, wrong for the other call: not carried across, exit status
/// 1 (a helper's find: exit 0 with a note). hyperMILL's reset label (frame blocks only,
/// ending untilted) stays right from any call (`program_to_follows_calls_to_labels`).
#[test]
fn program_to_flags_a_subprogram_written_for_one_frame() {
    let prog = "0 BEGIN PGM T MM\n1 PLANE SPATIAL SPA+0 SPB+90 SPC+0 TURN FMAX\n2 CALL LBL 10\n\
                3 PLANE SPATIAL SPA+90 SPB+90 SPC+0 TURN FMAX\n4 CALL LBL 10\n\
                5 PLANE RESET TURN FMAX\n6 M30\n7 LBL 10\n8 CYCL DEF 7.0 DATUM SHIFT\n\
                9 CYCL DEF 7.1 X+20\n10 L X+0 Y+0 R0 FMAX\n11 CYCL DEF 7.0 DATUM SHIFT\n\
                12 CYCL DEF 7.1 X+0\n13 LBL 0\n14 END PGM T MM\n";
    for to in ["fanuc", "sinumerik"] {
        let r = translate(prog, "heidenhain", to);
        assert_eq!(r.code, 1, "{to}: {}", r.stderr);
        assert!(
            r.stderr.contains("line 10: not carried across as")
                && r.stderr.contains("written for the frame of the call at line 3, the subprogram is also called with another frame active: 9 CYCL DEF 7.1 X+20"),
            "{to}: {}",
            r.stderr
        );
    }
}

/// An increment the target cannot say inside a loop of the program (Fanuc's `WHILE … DO1` …
/// `END1`, SINUMERIK's `REPEAT SIDE ENDSIDE P=3`): not carried across, exit status 1 (a
/// helper's find: exit 0 with a note).
#[test]
fn program_to_counts_an_increment_in_a_loop() {
    let fanuc = "G68.2 X0 Y0 Z0 I0 J90. K0\nG53.1\n#1=0\nWHILE[#1LT4]DO1\n\
                 G68.4 X0 Y0 Z0 I0 J0 K90.\n#1=#1+1\nEND1\nG69\n";
    let r = translate(fanuc, "fanuc", "haas");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr
            .contains("(the program repeats it in a loop: not carried across)"),
        "{}",
        r.stderr
    );
    let sinumerik = "CYCLE800(0,\"TC1\",0,57,0,0,0,0,90,0,0,0,0,0,,1)\nSIDE:\n\
                     CYCLE800(0,\"TC1\",1,57,0,0,0,90,0,0,0,0,0,0,,1)\nENDSIDE:\n\
                     REPEAT SIDE ENDSIDE P=3\nCYCLE800()\n";
    let r = translate(sinumerik, "sinumerik", "haas");
    assert_eq!(r.code, 1, "{}", r.stderr);
    // Outside a loop, the note alone.
    let once = fanuc.replace("WHILE[#1LT4]DO1\n", "").replace("END1\n", "");
    assert_eq!(translate(&once, "fanuc", "haas").code, 0);
}

/// A subprogram standing above its call (Fanuc's `O2000` before the main `O9000`) is read,
/// and translated, in the file's order from the frame there: wrong for a call under a tilt,
/// so that call is not carried across (exit status 1); a call to a program not in the file
/// is named (its blocks are not followed). Both were silent (a helper's finds).
#[test]
fn program_names_calls_it_cannot_follow_in_place() {
    let prog = "O2000\nG68.4 X0 Y0 Z0 I0 J10. K0\nM99\nO9000\nG68.2 X0 Y0 Z0 I0 J90. K0\n\
                G53.1\nM98 P2000\nG69\nM30\n";
    let r = translate(prog, "fanuc", "heidenhain");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 7: calls the subprogram at line 1, which stands above and was read and translated from the frame there, not this call's: not carried across"),
        "{}",
        r.stderr
    );
    let r = cncrot(
        &["program", "-", "--dialect", "fanuc"],
        "G68.2 X0 Y0 Z0 I0 J30. K0\nM98 P9011\n",
    );
    assert!(
        r.stderr.contains(
            "line 2: calls O9011, which is not in this file: its blocks are not followed"
        ),
        "{}",
        r.stderr
    );
    // SINUMERIK's subprograms stand in files of their own: every way of calling one is named
    // (`L…`, a name alone, `CALL`, `PCALL`, `MCALL` of a program), not the manufacturer's
    // cycles nor the words of the language (a helper's find: passed over in silence).
    let sin = "N10 CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,1)\nN20 L9011\nN25 FACE_SIDE2\n\
               N26 CALL \"SIDE3\"\nN27 PCALL SIDE4\nN28 MCALL SIDE5\nN29 MCALL CYCLE81(10,0,2,-5)\n\
               N30 TRAORI\nN31 ORIWKS\nN32 G17\nN33 CYCLE832(0.01,3,1)\nN34 MCALL\nN35 L10 P2\n\
               N36 MYSUB(1,2)\nN37 TRAFOOF\nN38 M30\n";
    let r = cncrot(&["program", "-", "--dialect", "sinumerik"], sin);
    let named: Vec<&str> = r
        .stderr
        .lines()
        .filter(|l| l.contains("which is not in this file"))
        .filter_map(|l| l.split("calls ").nth(1)?.split(", which").next())
        .collect();
    assert_eq!(
        named,
        [
            "L9011",
            "FACE_SIDE2",
            "SIDE3",
            "SIDE4",
            "SIDE5 (after each motion block: MCALL)",
            "L10",
            "MYSUB"
        ],
        "{}",
        r.stderr
    );
    // Heidenhain's programs called by name.
    let r = cncrot(
        &["program", "-", "--dialect", "heidenhain"],
        "1 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n2 CALL PGM TNC:\\SIDE2.H\n",
    );
    assert!(
        r.stderr
            .contains("line 2: calls PGM TNC:\\SIDE2.H, which is not in this file"),
        "{}",
        r.stderr
    );
}

/// Where a SINUMERIK program's `CYCLE800` and its `TRANS`/`ROT` meet, the control's
/// configuration decides (system frames keep the swivel apart; cncrot reads one frame that
/// each replaces): said, and with `--to` not carried across (a helper's find: `TRANS X10`
/// after a swivel was read, and translated, as the swivel cancelled, exit 0). A reset set
/// anew by the next block (`CYCLE800()` then `TRANS X=10`, as the writers write it) means
/// the same either way.
#[test]
fn program_says_where_sinumerik_frames_depend_on_the_control() {
    let prog = "N10 CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,1)\nN20 TRANS X10\n\
                N30 ROT Z45\nN40 CYCLE800()\nN50 M30\n";
    let r = cncrot(&["program", "-", "--dialect", "sinumerik"], prog);
    assert!(
        r.stderr.contains("line 2: TRANS, ROT, ROTS, SCALE or MIRROR while a CYCLE800 swivel is active: the control may keep the swivel"),
        "{}",
        r.stderr
    );
    assert!(
        r.stderr.contains(": check on the control: N20 TRANS X10"),
        "{}",
        r.stderr
    );
    let r = translate(prog, "sinumerik", "heidenhain");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr
            .contains("[choice]: not carried across: N20 TRANS X10"),
        "{}",
        r.stderr
    );
    // A shift before the swivel, an ATRANS after it and the reset that follows.
    let prog = "N10 TRANS X10\nN20 CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,1)\n\
                N30 ATRANS X1\nN40 CYCLE800()\nN50 G0 X0\nN60 M30\n";
    let r = cncrot(&["program", "-", "--dialect", "sinumerik"], prog);
    let lines: Vec<&str> = r
        .stderr
        .lines()
        .filter_map(|l| l.strip_prefix("cncrot: line "))
        .map(|l| l.split(':').next().unwrap_or(""))
        .collect();
    assert_eq!(lines, ["2", "4"], "{}", r.stderr);
    // What the writers write: the reset and the shift set anew, a reset shift before the
    // swivel that carries the origin.
    let prog = "N10 CYCLE800(0,\"\",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)\nN20 ATRANS X5\nCYCLE800()\n\
                TRANS X=10 Y=0 Z=0\nN30 G0 X0\nTRANS\nCYCLE800(0,\"\",0,57,10,0,0,0,20,0,0,0,0,-1,0,0)\n";
    let r = cncrot(&["program", "-", "--dialect", "sinumerik"], prog);
    assert!(!r.stderr.contains("the control may keep"), "{}", r.stderr);
}

/// A block that moves the rotary axes (`G0 A30. C180.` before the tilt, as posts
/// pre-position them; Heidenhain's `L A+30 C+180`, an increment `L IC+90`) moves the
/// positions the next turn starts from (a helper's find: chosen from `--current`, the axes
/// swung to the other solution).
#[test]
fn program_follows_the_rotary_axes_blocks_move() {
    let ac = [
        "--axis",
        "work:1,0,0@0,0,100",
        "--axis",
        "work:0,0,1",
        "--current",
        "0,0",
    ];
    let axes = |dialect: &str, prog: &str| -> Vec<Vec<f64>> {
        let mut args = vec!["program", "-", "--dialect", dialect];
        args.extend(ac);
        let r = cncrot(&args, prog);
        assert_eq!(r.code, 0, "{}", r.stderr);
        r.stdout
            .lines()
            .filter_map(|l| l.split("axes: ").nth(1))
            .map(numbers)
            .collect()
    };
    let fanuc = axes(
        "fanuc",
        "G0 A30. C180.\nG68.2 X0. Y0. Z0. I0. J30. K0.\nG53.1\n",
    );
    close(&fanuc[1], &[30.0, 180.0], 1e-9);
    // From C = 180 + 90 = 270, the other solution (A -30, C 360) is as far as (30, 180)
    // no longer: C 360 is 90 away, A 60.
    let heidenhain = axes(
        "heidenhain",
        "1 L A+30 C+180 R0 FMAX\n2 PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX\n\
         3 L IA-60 IC+180 FMAX\n4 PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX\n",
    );
    close(&heidenhain[0], &[30.0, 180.0], 1e-9);
    close(&heidenhain[1], &[-30.0, 360.0], 1e-9);
}

/// `PLANE AXIAL` (rotary positions) translated on a machine: the plane they give, with the
/// side of the master axis they take (`_DIR +1` for B+30 on a B head), and the retraction
/// the target has no word for named (a helper's finds: `_DIR -1` swung the head to the
/// other side; `MB 50` dropped into Fanuc without a word).
#[test]
fn program_to_keeps_the_side_of_stated_positions() {
    let prog = "1 PLANE AXIAL B+30 C+45 TURN MB 50 F1000 SEQ+\n";
    let head = ["--axis", "tool:0,1,0", "--axis", "work:0,0,1"];
    let mut args = vec![
        "program",
        "-",
        "--dialect",
        "heidenhain",
        "--to",
        "sinumerik",
    ];
    args.extend(head);
    let r = cncrot(&args, prog);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stdout.contains(",0,0,0,1,50,0)"), "{}", r.stdout);
    // Read back on the machine: B 30, C 45.
    let mut back = vec!["program", "-", "--dialect", "sinumerik"];
    back.extend(head);
    let b = cncrot(&back, &r.stdout);
    let axes = numbers(
        b.stdout
            .split("axes: ")
            .nth(1)
            .and_then(|l| l.lines().next())
            .unwrap_or(""),
    );
    close(&axes, &[30.0, 45.0], 1e-3);
    let mut args = vec!["program", "-", "--dialect", "heidenhain", "--to", "fanuc"];
    args.extend(head);
    let r = cncrot(&args, prog);
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(r.stderr.contains("the retraction before the rotary axes turn (50 mm along the tool) has no word in fanuc"), "{}", r.stderr);
}

/// Fanuc into Fanuc: a `G53.1 P1` (the choice a word of the turn's own block) stays as it
/// stands, not the tilt written again before it in `G68.2` mode (a helper's find).
#[test]
fn program_keeps_a_turn_with_its_choice() {
    let prog = "N10 G68.2 X10. Y0. Z0. I0. J30. K0.\nN20 G53.1 P1\nN30 G53.1\nN40 G69\n";
    let r = translate(prog, "fanuc", "fanuc");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_eq!(r.stdout, prog);
}

/// SINUMERIK into SINUMERIK keeps the swivel data set a `CYCLE800` names (`_TC`), `_ST`'s
/// digits above the units and `_DMODE`: a machine with a head and a table has a data set for
/// each (a helper's find: written `""`, exit 0). Into another dialect the data set is named
/// once.
#[test]
fn program_keeps_the_swivel_data_set() {
    let prog = "N10 CYCLE800(1,\"TABLE\",200000,27,0,0,0,30,20,10,0,0,0,1,100,1)\nN20 G0 X0\n\
                N30 CYCLE800(2,\"HEAD\",0,57,0,0,0,0,20,0,0,0,0,-1,0,1)\n\
                N35 CYCLE800(2,\"HEAD\",1,57,0,0,0,0,5,0,0,0,0,-1,0,1)\nN40 CYCLE800()\n";
    let r = translate(prog, "sinumerik", "sinumerik");
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(
        lines[0].starts_with("N10 CYCLE800(1,\"TABLE\",200000,57,"),
        "{}",
        r.stdout
    );
    assert!(lines[0].ends_with(",1,0,1)"), "{}", r.stdout);
    assert_eq!(
        lines[2], "N30 CYCLE800(2,\"HEAD\",0,57,0,0,0,0,20,0,0,0,0,-1,0,1)",
        "{}",
        r.stdout
    );
    // Additive stays additive.
    assert!(
        lines[3].starts_with("N35 CYCLE800(2,\"HEAD\",1,57,"),
        "{}",
        r.stdout
    );
    assert_eq!(lines[4], "N40 CYCLE800()", "{}", r.stdout);
    let r = translate(prog, "sinumerik", "heidenhain");
    assert_eq!(
        r.stderr
            .matches("the swivel data set \"HEAD\" (_TC) has no word in heidenhain")
            .count(),
        1,
        "{}",
        r.stderr
    );
    assert!(
        r.stderr.contains("line 1: the swivel data set \"TABLE\""),
        "{}",
        r.stderr
    );
}

/// A datum shift under the tilt in a section the program repeats after an increment of the
/// tilt in it (a side per pass: `PLANE RELATIV SPA+90` then `CALL LBL 1 REP 3`): written with
/// the first pass's tilt around it, wrong for the next sides: not carried across (a
/// helper's find: exit 0). Repeated without an increment, the same tilt each pass: written.
#[test]
fn program_to_flags_a_shift_in_passes_that_turn() {
    let prog = "0 BEGIN PGM F MM\n1 PLANE SPATIAL SPA+0 SPB+90 SPC+0 TURN FMAX\n2 LBL 1\n\
                3 CYCL DEF 7.0 DATUM SHIFT\n4 CYCL DEF 7.1 X+10\n5 L Z-5 R0 F200\n\
                6 CYCL DEF 7.0 DATUM SHIFT\n7 CYCL DEF 7.1 X+0\n8 PLANE RELATIV SPA+90 TURN FMAX\n\
                9 CALL LBL 1 REP 3\n10 PLANE RESET TURN FMAX\n11 END PGM F MM\n";
    let r = translate(prog, "heidenhain", "fanuc");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 5: not carried across as fanuc G68.2: the program runs it again after an increment of the tilt"),
        "{}",
        r.stderr
    );
    let same = prog.replace("8 PLANE RELATIV SPA+90 TURN FMAX\n", "");
    let r = translate(&same, "heidenhain", "fanuc");
    assert!(
        !r.stderr.contains("runs it again after an increment"),
        "{}",
        r.stderr
    );
}

/// A work offset (`G54`–`G59`) copied into a target where it selects the same (Fanuc to
/// Haas, SINUMERIK, TwinCAT for `G54`–`G57`) is carried across: exit status 0, a note; into
/// Heidenhain, or `G59` into SINUMERIK (an axial offset there), or `G54.1 P3`, it is not (a
/// helper's find: every program that selects `G54` exited 1, so a batch run could not tell).
#[test]
fn program_to_carries_a_work_offset_that_means_the_same() {
    let prog = "N1 G90 G54 G00 X0 Y0 Z200.\nG68.2 X0 Y0 Z0 I0 J30 K0\nG53.1\nG69\nM30\n";
    for (to, code) in [("haas", 0), ("sinumerik", 0), ("heidenhain", 1)] {
        let r = translate(prog, "fanuc", to);
        assert_eq!(r.code, code, "{to}: {}", r.stderr);
        assert_eq!(r.stdout.lines().next(), Some("N1 G90 G54 G00 X0 Y0 Z200."));
    }
    let r = translate(prog, "fanuc", "haas");
    assert!(
        r.stderr
            .contains("line 1: a work offset, copied as it stands: it selects the same in haas"),
        "{}",
        r.stderr
    );
    assert_eq!(translate("G59\n", "fanuc", "haas").code, 0);
    assert_eq!(translate("G57\n", "fanuc", "twincat").code, 0);
    assert_eq!(translate("G59\n", "fanuc", "sinumerik").code, 1);
    assert_eq!(translate("G54.1 P3\n", "fanuc", "haas").code, 1);
    // A character of more than one byte after the offset (the first version sliced the
    // upper-cased text by byte and panicked there).
    let r = translate("G54 X1 \u{fc}\nG55 (\u{e9})\n", "fanuc", "haas");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_eq!(r.stdout.lines().next(), Some("G54 X1 \u{fc}"));
    // The report still says the library does not follow it.
    let r = cncrot(&["program", "-", "--dialect", "fanuc"], "G54\n");
    assert!(
        r.stdout.contains("line 1: not followed: G54"),
        "{}",
        r.stdout
    );
}

/// A program section repeated by `CALL LBL 1 REP 2` adds its increment twice more: after the
/// call the plane is SPB+30 (three times 10°), whose tool direction is (sin 30°, 0, cos 30°).
#[test]
fn program_repeats_a_section_called_again() {
    let prog = "0 BEGIN PGM R MM\n1 LBL 1\n2 PLANE RELATIV SPB+10 STAY\n3 CALL LBL 1 REP2\n\
                4 PLANE RELATIV SPB+0 STAY\n5 END PGM R MM\n";
    let r = cncrot(&["program", "-", "--dialect", "heidenhain"], prog);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stdout
            .contains("line 5: 4 PLANE RELATIV SPB+0 STAY\n  origin: 0.0000 0.0000 0.0000  tool direction: 0.5000 0.0000 0.8660"),
        "{}",
        r.stdout
    );
    // A call with REP repeats the section whatever `LBL 0` stands in it (the TNC's dialog:
    // with REP a section repeat, without a subprogram call): three passes of SPB+10 again.
    let prog = "1 LBL 1\n2 PLANE RELATIV SPB+10 STAY\n3 LBL 0\n4 CALL LBL 1 REP2\n\
                5 PLANE RELATIV SPB+0 STAY\n";
    let r = cncrot(&["program", "-", "--dialect", "heidenhain"], prog);
    assert!(
        r.stdout.contains("line 5: 5 PLANE RELATIV SPB+0 STAY\n  origin: 0.0000 0.0000 0.0000  tool direction: 0.5000 0.0000 0.8660"),
        "{}",
        r.stdout
    );
}

/// A call that changes the frame (hyperMILL's `CALL LBL 1 ; RESET WORKING PLANE`, the label
/// after `M30`) has its row in the report, with the frame after the call: untilted. Before,
/// the report showed no row there, and the reset only at the label's own line after `M30`,
/// so the moves after the call read as still under the tilt (a helper's find).
#[test]
fn program_lists_a_call_that_changes_the_frame() {
    let prog = "0 BEGIN PGM M3 MM\n1 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n\
                2 CALL LBL 1 ; RESET WORKING PLANE\n3 L Z+100 R0 FMAX M91\n4 M30\n\
                5 LBL 1 ; RESET WORKING PLANE\n6 PLANE RESET STAY\n7 LBL 0\n8 END PGM M3 MM\n";
    let r = cncrot(&["program", "-", "--dialect", "heidenhain"], prog);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stdout.contains("line 3: 2 CALL LBL 1 ; RESET WORKING PLANE\n  origin: 0.0000 0.0000 0.0000  tool direction: 0.0000 0.0000 1.0000"),
        "{}",
        r.stdout
    );
    // A call that changes nothing has none.
    let r = cncrot(
        &["program", "-", "--dialect", "heidenhain"],
        "1 CALL LBL 1\n2 M30\n3 LBL 1\n4 L X+0 R0 FMAX\n5 LBL 0\n",
    );
    assert!(!r.stdout.contains("CALL"), "{}", r.stdout);
}

/// A turn of the rotary axes to the plane (`G53.1`) into a form without a word for it
/// (Syntec's `G158`, TwinCAT's `ROT`) is not written, and standard error says so, as for a
/// choice of solution; into `G268` it is `G253`, said nothing. The machine then moves
/// otherwise than the source says: counted in the summary, exit status 1 (it was 0). So is a
/// turn that keeps the tool tip in place (`MOVE`) written as `G253`, a turn about the pivot.
#[test]
fn program_to_says_a_turn_it_cannot_write() {
    let prog = "G68.2 X0 Y0 Z0 I0 J30 K0\nG53.1\nG69\n";
    let r = translate(prog, "fanuc", "syntec");
    // A retraction or turn the target has no word for: exit status 1.
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains(", 1 with a way of moving left out"),
        "{}",
        r.stderr
    );
    assert_eq!(
        r.stdout.lines().collect::<Vec<_>>(),
        ["G158 P10157 X0. Y0. Z0. A30. B0. C0. U0. V0. W0.", "G158"]
    );
    assert!(
        r.stderr.contains("line 2: the turn of the rotary axes to the plane has no word in syntec G158: not written"),
        "{}",
        r.stderr
    );
    let r = translate(prog, "fanuc", "haas");
    assert!(!r.stderr.contains("no word"), "{}", r.stderr);
    // The retraction before the turn (MB 50) has no word in G68.2's G53.1: said too.
    let r = translate(
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 FMAX\n",
        "heidenhain",
        "fanuc",
    );
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 1: the retraction before the rotary axes turn (50 mm along the tool) has no word in fanuc G68.2: not written"),
        "{}",
        r.stderr
    );
    let r = translate(
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 FMAX\n",
        "heidenhain",
        "sinumerik",
    );
    assert!(!r.stderr.contains("retraction"), "{}", r.stderr);
    let r = translate(
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE DIST50 F2000\n",
        "heidenhain",
        "haas",
    );
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 1: the turn that keeps the tool tip in place (the linear axes following) has no word in haas G268"),
        "{}",
        r.stderr
    );
    assert!(
        r.stderr
            .contains("line 1: the feed of the turn (F2000) has no word in haas G268"),
        "{}",
        r.stderr
    );
    // Fanuc's G53.6 keeps the tip: nothing to say of that (its `DIST` is another matter:
    // `program_to_names_a_pivot_distance_left_out`).
    let r = translate(
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE DIST50 FMAX\n",
        "heidenhain",
        "fanuc",
    );
    assert!(
        !r.stderr
            .contains("the turn that keeps the tool tip in place"),
        "{}",
        r.stderr
    );
}

/// Heidenhain `CALL LBL` is followed through its label: hyperMILL resets the plane and the
/// datum in a subprogram after the program's end (`CALL LBL 1 ; RESET WORKING PLANE`).
/// Before, the second job's cycle 7 was written under the first job's tilt, which the
/// program still held: `G69`, the `G52`, then the first plane again with its `G53.1` (the
/// axes back to it) before the second. The subprogram's own blocks are read from the state
/// of its first call with a tilt active (its turn cleared), and the other calls are named on
/// standard error.
#[test]
fn program_to_follows_calls_to_labels() {
    let prog = "0 BEGIN PGM HM MM\n1 CALL LBL 1 ; RESET WORKING PLANE\n\
                2 CYCL DEF 7.0 DATUM SHIFT\n3 CYCL DEF 7.1 X+10\n\
                4 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n5 CALL LBL 1\n\
                6 CYCL DEF 7.0 DATUM SHIFT\n7 CYCL DEF 7.1 X+20\n\
                8 PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX\n9 CALL LBL 1\n10 M30\n\
                11 LBL 1\n12 CYCL DEF 7.0 DATUM SHIFT\n13 CYCL DEF 7.1 X+0\n\
                13 CYCL DEF 7.2 Y+0\n13 CYCL DEF 7.3 Z+0\n\
                14 PLANE RESET STAY\n15 LBL 0\n16 END PGM HM MM\n";
    let r = translate(prog, "heidenhain", "fanuc");
    assert_eq!(r.code, 0, "{}", r.stderr);
    let out: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(
        out,
        [
            "0 BEGIN PGM HM MM",
            "1 CALL LBL 1 ; RESET WORKING PLANE",
            "G52 X10. Y0. Z0.",
            // SPB+30, Ry(30°), as Euler Z-X-Z: Rz(90°)·Rx(30°)·Rz(-90°).
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "G53.1",
            "5 CALL LBL 1",
            "G52 X20. Y0. Z0.",
            "G68.2 X0. Y0. Z0. I90. J45. K-90.",
            "G53.1",
            "9 CALL LBL 1",
            "10 M30",
            "11 LBL 1",
            // Read from the first call with a tilt (line 6), its turn cleared: the shift
            // after the cancel, the tilt again without G53.1, then the cancel: the same
            // whatever frame a call finds.
            "G69",
            "G52 X0. Y0. Z0.",
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "G69",
            "15 LBL 0",
            "16 END PGM HM MM"
        ]
    );
    assert!(
        r.stderr.contains(
            "line 12: the subprogram is also called with another frame active (lines 2, 10): its blocks are translated into fanuc once, from the frame of the call at line 6 without its turn"
        ),
        "{}",
        r.stderr
    );
}

/// `PLANE RESET TURN` into Fanuc: the tilt cancelled, a zero `G68.2` and its `G53.1` turn the
/// axes, then `G69` again, so that the `G52` of the cycle 7 that follows is not written in
/// `G68.2` mode (which Fanuc refuses) and the next tilt over none (a helper's find).
#[test]
fn program_to_cancels_after_a_zero_tilt_that_turns() {
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\nPLANE RESET TURN FMAX\n\
                CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\n\
                PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX\nPLANE RESET STAY\n";
    assert_eq!(
        program_to(prog, "heidenhain", "fanuc"),
        [
            // SPB+30, Ry(30°), as Euler Z-X-Z: Rz(90°)·Rx(30°)·Rz(-90°).
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "G53.1",
            "G69",
            "G68.2 X0. Y0. Z0. I0. J0. K0.",
            "G53.1",
            "G69",
            "G52 X10. Y0. Z0.",
            "G68.2 X0. Y0. Z0. I90. J45. K-90.",
            "G53.1",
            "G69"
        ]
    );
}

/// The other words of a tilt or cancel block stay (a helper's shop programs: a TECH STAR
/// header, a generator's `G1 G68.2 … F300.`): the retract `G91 G28 Z0.` beside `G69` and the
/// motion mode and feed beside `G68.2` on a line of their own before the translation, the
/// block's own line when only the cancel was there; a joined tilt keeps its first line's.
#[test]
fn program_to_keeps_a_blocks_other_words() {
    let prog = "G0 G90 G49 G69 G80 G40 G17\nG91 G28 Z0. G69\n\
                N40 G1 G68.2 X0. Y0. Z0. I0. J30. K0. F300.\nN50 G53.1\nN70 X10. Y10.\nG69\n";
    assert_eq!(
        program_to(prog, "fanuc", "haas"),
        [
            "G0 G90 G49 G80 G40 G17",
            "G269",
            "G91 G28 Z0.",
            "G269",
            "N40 G1 F300.",
            // Euler Z-X-Z (0, 30, 0) is Rx(30°): roll 30 about X.
            "N50 G268 X0. Y0. Z0. I30. J0. K0. Q123",
            "G253",
            "N70 X10. Y10.",
            "G269"
        ]
    );
}

/// TwinCAT NC I's programmable zero offset shift `G58` is the datum `ROT` turns about (its
/// manual's example): carried across as the target's datum shift, and back. By hand: `ROT
/// Y30` is `Ry(30°)` = G68.2 `I90. J30. K-90.`; the shift moved under the rotation is
/// written untilted (the rotation off, the shift, the rotation again).
#[test]
fn program_to_carries_twincats_zero_offset_shift() {
    let prog = "N20 G58 X10 Y20 Z5\nN30 ROT Y30\nN40 G58 X0 Y200\nN50 ROT\nM30\n";
    assert_eq!(
        program_to(prog, "twincat", "fanuc"),
        [
            "N20 G52 X10. Y20. Z5.",
            "N30 G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "N40 G69",
            "G52 X0. Y200. Z0.",
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "N50 G69",
            "M30"
        ]
    );
    let back = "G52 X10. Y20. Z5.\nG68.2 X0. Y0. Z0. I90. J30. K-90.\nG69\nG52 X0. Y0. Z0.\n";
    assert_eq!(
        program_to(back, "fanuc", "twincat"),
        [
            "G58 X10 Y20 Z5",
            "ROT X0 Y30 Z0",
            "ROT X0 Y0 Z0",
            "G58 X0 Y0 Z0"
        ]
    );
}

/// A command spread over lines is written as one in the target: cycle 7's axis lines as one
/// `G52`, a `PLANE … STAY` and the block that turns to it as one `G68.2` with its `G53.1`;
/// under the tilt, the shift reset once (not once per axis), the tilt again without a turn. By hand: `SPB+30` is `Ry(30°)`
/// = `Rz(90°)·Rx(30°)·Rz(−90°)`, Fanuc's `I90. J30. K-90.`. `SEQ-` has no word in `G68.2`:
/// said on standard error.
#[test]
fn program_to_joins_commands_spread_over_lines() {
    let prog = "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\nCYCL DEF 7.2 Y+20\n\
                CYCL DEF 7.3 Z-5\nPLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY SEQ-\n\
                L B+Q121 C+Q122 R0 FMAX\nL X+0 Y+0 R0 FMAX\nCYCL DEF 7.0 DATUM SHIFT\n\
                CYCL DEF 7.1 X+0\nCYCL DEF 7.2 Y+0\nCYCL DEF 7.3 Z+0\nPLANE RESET STAY\n";
    let tilt = "G68.2 X0. Y0. Z0. I90. J30. K-90.";
    assert_eq!(
        program_to(prog, "heidenhain", "fanuc"),
        [
            "G52 X10. Y20. Z-5.",
            tilt,
            "G53.1",
            "L X+0 Y+0 R0 FMAX",
            "G69",
            "G52 X0. Y0. Z0.",
            // The tilt again around the shift: the axes are there already (no `G53.1`).
            tilt,
            "G69"
        ]
    );
    let r = translate(prog, "heidenhain", "fanuc");
    assert!(
        r.stderr.contains("line 6: the choice of solution (the master axis at its lower angle) has no word in fanuc"),
        "{}",
        r.stderr
    );
    // CYCLE800 has the word (`_DIR` -1): nothing to say.
    let r = translate(prog, "heidenhain", "sinumerik");
    assert!(!r.stderr.contains("choice"), "{}", r.stderr);
    // Into Heidenhain: G68.2 and its G53.1 are one PLANE … TURN.
    assert_eq!(
        program_to(
            "G68.2 X0 Y0 Z0 I90. J30. K-90.\nG53.1\nG69\n",
            "fanuc",
            "heidenhain"
        ),
        [
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX",
            "PLANE RESET STAY"
        ]
    );
}

/// A program's opening cancel and zero datum shift, which change nothing in a state where
/// nothing is active, are still written into another dialect (the control may have a tilt or
/// a shift left active); in the program's own dialect they stay as they stand.
#[test]
fn program_to_keeps_safety_cancels() {
    let prog = "0 BEGIN PGM T MM\n1 PLANE RESET STAY\n2 CYCL DEF 7.0 DATUM SHIFT\n\
                3 CYCL DEF 7.1 X+0\n4 END PGM T MM\n";
    let to = |d: &str| program_to(prog, "heidenhain", d);
    assert_eq!(
        to("fanuc"),
        [
            "0 BEGIN PGM T MM",
            "G69",
            "G52 X0. Y0. Z0.",
            "4 END PGM T MM"
        ]
    );
    assert_eq!(to("heidenhain"), prog.lines().collect::<Vec<_>>());
}

/// A translation is the program again, in its own bytes: a comment in a one-byte code page
/// (here GBK's two bytes for a Chinese word, not UTF-8) stays those bytes, CRLF line ends
/// stay CRLF, also on the lines the writer adds.
#[test]
fn program_to_keeps_bytes_and_line_ends() {
    let dir = std::env::temp_dir().join(format!("cncrot-bytes-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("gbk.h");
    let mut prog = b"0 BEGIN PGM T MM\r\n1 ; T1 - \xb5\xb6\r\n".to_vec();
    prog.extend_from_slice(b"2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\r\n3 END PGM T MM\r\n");
    std::fs::write(&file, &prog).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_cncrot"))
        .args([
            "program",
            file.to_str().unwrap(),
            "--dialect",
            "heidenhain",
            "--to",
            "fanuc",
        ])
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(out.status.code(), Some(0));
    let mut want = b"0 BEGIN PGM T MM\r\n1 ; T1 - \xb5\xb6\r\n".to_vec();
    want.extend_from_slice(b"G68.2 X0. Y0. Z0. I90. J30. K-90.\r\nG53.1\r\n3 END PGM T MM\r\n");
    assert_eq!(out.stdout, want, "{}", String::from_utf8_lossy(&out.stdout));
}

/// An optional block stays optional in a translation: the skip mark on every line written
/// for it, ISO's level kept between ISO-style dialects (Heidenhain's `/81` is the mark and
/// block 81).
#[test]
fn program_to_keeps_skip_marks() {
    let prog = "/7 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n/81 M30\n";
    assert_eq!(
        program_to(prog, "heidenhain", "fanuc"),
        ["/G68.2 X0. Y0. Z0. I90. J30. K-90.", "/81 M30"]
    );
    assert_eq!(
        program_to("/2 G68.2 X10. I0. J30. K0.\n/2G69\n", "fanuc", "sinumerik"),
        [
            // No G53.1: the frame without swivelling, `_DIR` 0.
            "/2 CYCLE800(0,\"\",0,57,10,0,0,30,0,0,0,0,0,0,0,0)",
            "/2 CYCLE800()"
        ]
    );
}

/// Cycle 19 as older posts write it, with spatial angles (the default): `B+30 C+90` is
/// Rz(90)·Ry(30) = Rz(180)·Rx(30)·Rz(−90) by hand (Ry(30) = Rz(90)·Rx(30)·Rz(−90)), so
/// `G68.2 I180 J30 K-90`; the zero angles cancel (`G69`), and so does the cycle without
/// angles, though nothing is active any more (the cancel is kept). Into Heidenhain itself the cycle
/// is rewritten as `PLANE SPATIAL`, and its first line goes with it; a cycle that changes
/// nothing (the second reset line) stays as it stands, both lines. With `--axis-angles`
/// the angles are the positions of B and C.
#[test]
fn program_reads_cycle_19() {
    let prog = "0 BEGIN PGM C19 MM\n1 CYCL DEF 19.0 WORKING PLANE\n2 CYCL DEF 19.1 B+30 C+90\n\
                3 L X+0 Y+0 R0 FMAX\n4 CYCL DEF 19.0 WORKING PLANE\n5 CYCL DEF 19.1 A+0 B+0 C+0\n\
                6 CYCL DEF 19.0 WORKING PLANE\n7 CYCL DEF 19.1\n8 END PGM C19 MM\n";
    let translated = |to: &str| program_to(prog, "heidenhain", to);
    let want = [
        "0 BEGIN PGM C19 MM",
        "G68.2 X0. Y0. Z0. I180. J30. K-90.",
        "3 L X+0 Y+0 R0 FMAX",
        "G69",
        "G69",
        "8 END PGM C19 MM",
    ];
    assert_eq!(translated("fanuc"), want);
    let want = [
        "0 BEGIN PGM C19 MM",
        "PLANE SPATIAL SPA+0 SPB+30 SPC+90 STAY",
        "3 L X+0 Y+0 R0 FMAX",
        "PLANE RESET STAY",
        "6 CYCL DEF 19.0 WORKING PLANE",
        "7 CYCL DEF 19.1",
        "8 END PGM C19 MM",
    ];
    assert_eq!(translated("heidenhain"), want);
    let r = cncrot(
        &[
            "program",
            "-",
            "--dialect",
            "heidenhain",
            "--axis-angles",
            "--axis",
            "work:0,1,0",
            "--axis",
            "work:0,0,1",
        ],
        prog,
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stdout.contains("axes: 30.0000 90.0000"), "{}", r.stdout);
}

/// A direct mode (`PLANE AXIAL`) states the rotary-axis positions: without a machine its
/// frame is not known and the row says so; on a head C about Z carrying B about Y the tool
/// direction is Rz(45)·Ry(30)·e_z = (0.5·cos 45°, 0.5·sin 45°, cos 30°) by hand, the
/// modulo C the turn nearest 730 (765), B as stated; an A on that head is refused with
/// the reason. `line` writes it in the direct mode of the dialects that name axes by
/// letter.
#[test]
fn program_reads_direct_modes_through_the_machine() {
    let prog = "PLANE AXIAL B+30 C+45 TURN FMAX\nPLANE AXIAL A+10\n";
    let r = cncrot(&["program", "-", "--dialect", "heidenhain"], prog);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stdout
            .contains("direct: B=30.0000 C=45.0000 (the frame follows from the machine"),
        "{}",
        r.stdout
    );
    let head = [
        "--axis",
        "tool:0,0,1",
        "--axis",
        "tool:0,1,0@0,0,150",
        "--current",
        "730,0",
    ];
    let mut args = vec!["program", "-", "--dialect", "heidenhain"];
    args.extend(head);
    let r = cncrot(&args, prog);
    assert_eq!(r.code, 1, "{}", r.stdout);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(
        lines[1],
        "  origin: 0.0000 0.0000 0.0000  tool direction: 0.3536 0.3536 0.8660  axes: 765.0000 30.0000"
    );
    assert!(
        lines[3].contains("the machine has no axis for a position the block states"),
        "{}",
        lines[3]
    );
    let out = ok(&[
        "line",
        "--from",
        "heidenhain",
        "--to",
        "syntec:G158",
        "PLANE AXIAL B+30 C+45",
    ]);
    assert!(
        out.contains("G158 P10200 X0. Y0. Z0. A0. B30. C45. U0. V0. W0."),
        "{out}"
    );
    let r = cncrot(
        &[
            "line",
            "--from",
            "heidenhain",
            "--to",
            "fanuc",
            "PLANE AXIAL B+30",
        ],
        "",
    );
    assert_eq!(r.code, 1, "{}", r.stderr);
}

/// A parameter the program sets once, to a number, is read where a tilt uses it (the
/// library reads numbers only, and refused these blocks): `SPB+Q1` with `FN 0: Q1 = +30`
/// is SPB+30, tool direction (sin 30°, 0, cos 30°); `J-#1` with `#1=30.` is J-30; `_C` of
/// `-ROT1` with `DEF REAL ROT1` and `ROT1=15` is -15. A parameter set twice (`#3`), by an
/// expression (`R5=R5+1`) or overwritten by a function (`CalcInvRot[R1; …]`) is not known:
/// the block stays refused.
#[test]
fn program_reads_parameters_set_once() {
    let r = cncrot(
        &["program", "-", "--dialect", "heidenhain"],
        "FN 0: Q1 = +30\nPLANE SPATIAL SPA+0 SPB+Q1 SPC+0 TURN FMAX\n",
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stdout.contains("tool direction: 0.5000 0.0000 0.8660"),
        "{}",
        r.stdout
    );
    assert!(
        r.stderr.contains("line 2: read with Q1 = +30 (line 1)"),
        "{}",
        r.stderr
    );
    assert_eq!(
        program_to(
            "#1=30.\nG68.2 X0 Y0 Z0 I0 J-#1 K0 (#1 IS THE TILT)\n",
            "fanuc",
            "heidenhain"
        ),
        [
            "#1=30.",
            "PLANE SPATIAL SPA-30 SPB+0 SPC+0 STAY ; #1 IS THE TILT"
        ]
    );
    assert_eq!(
        program_to(
            "DEF REAL ROT1\nROT1=15\nCYCLE800(0,\"\",0,57,0,0,0,0,0,-ROT1,0,0,0,0,0,0)\n",
            "sinumerik",
            "fanuc"
        )[2],
        // `_C` -15: Rz(-15°), Euler Z-X-Z (-15°, 0, 0).
        "G68.2 X0. Y0. Z0. I-15. J0. K0."
    );
    for (prog, dialect) in [
        ("#3=1\n#3=2\nG68.2 I#3\n", "fanuc"),
        (
            "R5=1\nR5=R5+1\nCYCLE800(0,\"\",0,57,0,0,0,0,R5,0,0,0,0,0,0,0)\n",
            "sinumerik",
        ),
        (
            "N10 R1=30\nN30 CalcInvRot[R1; R2; R3]\nN40 ROT Z=R1\n",
            "twincat",
        ),
    ] {
        let r = cncrot(&["program", "-", "--dialect", dialect], prog);
        assert_eq!(r.code, 1, "{prog}: {}", r.stdout);
        assert!(r.stdout.contains("error"), "{prog}: {}", r.stdout);
    }
}

/// A datum shift under a plane that turned the axes moves nothing on the control: its
/// translation writes the plane again without a turn (no `G53.1`), and says nothing of a turn,
/// retraction or choice the shift does not make (a helper's find: `G53.1` again and "retract the
/// tool before this block" at `CYCL DEF 7.1 X+10`).
#[test]
fn program_to_turns_nothing_at_a_shift_under_a_tilt() {
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ+\nL Z+2 R0 FMAX\n\
                CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\nPLANE RESET STAY\n";
    let r = translate(prog, "heidenhain", "fanuc");
    // A retraction or turn the target has no word for: exit status 1.
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains(", 1 with a way of moving left out"),
        "{}",
        r.stderr
    );
    assert_eq!(
        r.stdout.lines().collect::<Vec<_>>(),
        [
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "G53.1",
            "L Z+2 R0 FMAX",
            "G69",
            "G52 X8.6603 Y0. Z-5.",
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "G69"
        ]
    );
    assert!(!r.stderr.contains("line 4"), "{}", r.stderr);
    assert!(r.stderr.contains("line 1: the retraction"), "{}", r.stderr);
}

/// A post's tool change on the same plane (`G68.2` and `G53.1` again, no `G69` between, the
/// program having moved the axes) swivels again: its translation writes the plane again with
/// its turn (it was dropped: the head stayed where the tool change left it).
#[test]
fn program_to_swivels_again_at_a_tool_change() {
    let prog = "N20 G68.2 X0 Y0 Z0 I90. J45. K-90.\nN25 G53.1\nN40 G100 T02 Z15. G43 H02 M03\n\
                N45 G68.2 X0 Y0 Z0 I90. J45. K-90.\nN50 G53.1\nN65 G69\n";
    assert_eq!(
        program_to(prog, "fanuc", "heidenhain"),
        [
            "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX",
            "N40 G100 T02 Z15. G43 H02 M03",
            "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX",
            "PLANE RESET STAY"
        ]
    );
}

/// A direct mode (rotary positions: Syntec's `G158 P10200`) into a target without one is
/// written as the plane the positions give on the machine described, when one is: a C head
/// (about Z) carrying a B head (about Y) at C45 B30 points the tool along
/// Rz(45°)·Ry(30°)·e_z = (sin 30° cos 45°, sin 30° sin 45°, cos 30°) = (0.3536, 0.3536,
/// 0.8660), G68.2's Euler Z-X-Z (135°, 30°, −90°) by hand. Without the machine it is not
/// carried across (exit status 1), as before.
#[test]
fn program_to_writes_a_direct_mode_on_the_machine_given() {
    let prog = "G158 P10200 X10. Y0 Z0 A0 B30. C45.\nG0 X0 Y0\n";
    let r = cncrot(
        &[
            "program",
            "-",
            "--dialect",
            "syntec",
            "--axis",
            "tool:0,0,1",
            "--axis",
            "tool:0,1,0",
            "--to",
            "fanuc",
        ],
        prog,
    );
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_eq!(
        r.stdout.lines().collect::<Vec<_>>(),
        ["G68.2 X10. Y0. Z0. I135. J30. K-90.", "G53.1", "G0 X0 Y0"]
    );
    assert!(
        r.stderr
            .contains("line 1: the rotary positions written as the plane they give on the machine"),
        "{}",
        r.stderr
    );
    let r = translate(prog, "syntec", "fanuc");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(r.stderr.contains("not carried across"), "{}", r.stderr);
}

/// LinuxCNC's `G53.3 X Y Z` turns the axes to the plane and moves to the point: the turn,
/// then the move (it was passed over: the axes never turned), a rapid as LinuxCNC runs it
/// (`G0 X Y Z`; a bare `X10 Y20 Z30` took the modal motion, a feed or an arc).
#[test]
fn program_to_turns_and_moves_at_g53_3() {
    let prog = "G1 X0 F100\nG68.2 X0 Y0 Z0 I0 J30 K0\nG53.3 X10 Y20 Z-30\nG69\n";
    assert_eq!(
        program_to(prog, "fanuc", "haas"),
        [
            "G1 X0 F100",
            "G268 X0. Y0. Z0. I30. J0. K0. Q123",
            "G253",
            "G0 X10 Y20 Z-30",
            "G269"
        ]
    );
    let h = program_to(prog, "fanuc", "heidenhain");
    assert!(h.contains(&"L X+10 Y+20 Z-30 FMAX".to_string()), "{h:?}");
}

/// Heidenhain's `M126` beside the turn to the plane (the rotary axes take the shortest way
/// from now on) has no word in a `G53.1` or a `CYCLE800`: standard error says so (it was
/// dropped silently); within Heidenhain the block stays as it stands.
#[test]
fn program_to_names_the_rotary_axes_way() {
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\nL A+Q120 C+Q122 R0 FMAX M126\n";
    let r = translate(prog, "heidenhain", "fanuc");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 2: M126 (the rotary axes take the shortest way from now on) has no word in fanuc G68.2"),
        "{}",
        r.stderr
    );
    let r = translate(prog, "heidenhain", "heidenhain");
    assert!(!r.stderr.contains("M126"), "{}", r.stderr);
}

/// A block that adds to the datum shift (`CYCL DEF 7.1 IX+10`, `ATRANS`) is written as the
/// shift it reaches (every target's datum shift block is absolute): standard error says so,
/// since a loop that repeats it no longer adds (it was silent); here the program repeats it
/// (`CALL LBL 1 REP 2`), so it is not carried across (exit status 1). An absolute shift, and
/// a datum shift under a tilt set by `AROT` (which adds nothing to the tilt), say nothing.
#[test]
fn program_to_names_shift_increments() {
    let prog = "LBL 1\nCYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 IX+10\nL X+0 Y+0 R0 FMAX\n\
                CALL LBL 1 REP 2\nCYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\n";
    let r = translate(prog, "heidenhain", "fanuc");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 3: the block adds to the active datum shift and is written as the shift it reaches in fanuc G68.2"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("line 7"), "{}", r.stderr);
    let r = translate("ATRANS X10\nG0 X0\nTRANS X5\n", "sinumerik", "heidenhain");
    assert!(
        r.stderr
            .contains("line 1: the block adds to the active datum shift"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("line 3"), "{}", r.stderr);
    let r = translate("ROT Z30\nAROT Z10\nG58 X20 Y0 Z0\n", "twincat", "sinumerik");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(!r.stderr.contains("adds"), "{}", r.stderr);
}

/// A block that adds to the tilt, in a loop, is written as the target's increment, so that
/// each pass adds: `PLANE RELATIV SPC+15` is `Rz(15°)`, G68.2's `I15. J0. K0.` as a `G68.4`;
/// `SPB+30` is `I90. J30. K-90.`. Haas has no incremental `G268`: said on standard error.
#[test]
fn program_to_keeps_increments() {
    let prog = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\nLBL 1\nPLANE RELATIV SPC+15 TURN FMAX\n\
                L Z+100 R0 FMAX\nCALL LBL 1 REP 3\nPLANE RESET STAY\n";
    assert_eq!(
        program_to(prog, "heidenhain", "fanuc"),
        [
            "G68.2 X0. Y0. Z0. I90. J30. K-90.",
            "LBL 1",
            "G68.4 X0. Y0. Z0. I15. J0. K0.",
            "G53.1",
            "L Z+100 R0 FMAX",
            "CALL LBL 1 REP 3",
            "G69"
        ]
    );
    let r = translate(prog, "heidenhain", "fanuc");
    assert!(!r.stderr.contains("does not add"), "{}", r.stderr);
    let r = translate(prog, "heidenhain", "haas");
    assert!(
        r.stderr.contains(
            "line 3: the block adds to the active tilt and haas G268 cannot say this increment"
        ),
        "{}",
        r.stderr
    );
}

/// A block that adds to the frame inside a loop (here a jump back, `GOTOB MARK`) runs as
/// often as the loop's condition says, cncrot's reading once: the report says so, and a
/// translation does not carry across a later block that adds to that frame (it was exit 0,
/// the frame after the loop one pass's: Rz(90) where the control has Rz(360)). The label and
/// SINUMERIK's main block number stay on their translated blocks, so the jump finds them
/// (both were dropped).
#[test]
fn program_names_a_frame_added_to_in_a_loop() {
    let prog = "N5 R1=0\nMARK: AROT Z90\nN20 G1 X10\nN25 R1=R1+1\nN30 IF R1<4 GOTOB MARK\n\
                N35 ATRANS X5\n:40 ROT Z30\nN50 BACK: ROT\nN60 M30\n";
    let r = cncrot(&["program", "-", "--dialect", "sinumerik"], prog);
    assert!(
        r.stderr
            .contains("line 2: the block adds to the frame and stands in a loop")
            && r.stderr.contains("check on the control"),
        "{}",
        r.stderr
    );
    let r = translate(prog, "sinumerik", "sinumerik");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr
            .contains("line 6: the block adds to a frame that a loop above (line 2)"),
        "{}",
        r.stderr
    );
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(lines[1].starts_with("MARK: CYCLE800("), "{}", r.stdout);
    assert!(lines[6].starts_with(":40 CYCLE800("), "{}", r.stdout);
    assert_eq!(lines[7], "N50 BACK: CYCLE800()");
    // A frame set whole after the loop is the control's again: nothing after it flagged.
    let set = prog.replace("N35 ATRANS X5\n", "");
    let r = translate(&set, "sinumerik", "fanuc");
    assert_eq!(r.code, 0, "{}", r.stderr);
}

/// A parameter used above its only assignment holds what the control held before, which
/// the program does not state: the block stays refused (it was read with the value assigned
/// below, exit 0, a tilt of 30° invented).
#[test]
fn program_reads_no_parameter_before_it_is_set() {
    let prog = "0 BEGIN PGM QP MM\n1 PLANE SPATIAL SPA+0 SPB+Q1 SPC+0 STAY\n\
                2 FN 0: Q1 = +30\n3 PLANE SPATIAL SPA+0 SPB+Q1 SPC+0 STAY\n4 END PGM QP MM\n";
    let r = translate(prog, "heidenhain", "fanuc");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(r.stderr.contains("line 2, column"), "{}", r.stderr);
    assert!(
        r.stderr.contains("line 4: read with Q1 = +30 (line 3)"),
        "{}",
        r.stderr
    );
    assert!(!r.stderr.contains("line 2: read with"), "{}", r.stderr);
}

/// A macro call (`G65 P2000 A15.`) runs its program as `M98` does: followed through it (the
/// increment there was read from the frame before the call, `I15.` where the control is at
/// 45°); `M198` and a `G65` to a program not in the file are named.
#[test]
fn program_follows_a_macro_call() {
    let prog = "%\nO1000\nN20 G68.2 X0 Y0 Z0 I0 J30. K0\nN30 G53.1\nN40 G65 P2000 A15.\n\
                N50 G1 X10.\nN60 G69\nN70 M30\nO2000\nN100 G68.4 X0 Y0 Z0 I0 J15. K0\n\
                N110 G53.1\nN120 M99\n%\n";
    let r = translate(prog, "fanuc", "haas");
    assert!(
        r.stdout.contains("G268 X0. Y0. Z0. I45. J0. K0. Q123"),
        "{}",
        r.stdout
    );
    let r = cncrot(
        &["program", "-", "--dialect", "fanuc"],
        "G65 P9100 A1.\nM198 P1000\n",
    );
    assert!(
        r.stderr
            .contains("line 1: calls O9100, which is not in this file")
            && r.stderr
                .contains("line 2: calls O1000, which is not in this file"),
        "{}",
        r.stderr
    );
}

/// Blocks the target writes as one command (a `G68.2` and its `G53.1`, cycle 7's axis
/// lines) with a skip mark on only one of them: either way the translation would be wrong
/// with the switch on or off (the tilt came out unskippable): not carried across.
#[test]
fn program_to_names_a_join_of_optional_and_plain_blocks() {
    let prog = "N10 G0 X0 Y0\n/N20 G68.2 X0 Y0 Z0 I0 J30 K0\nN30 G53.1\nN40 G1 X1.\nN60 M30\n";
    let r = translate(prog, "fanuc", "heidenhain");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 2: the target writes this block and the next as one command, and only one of them is optional"),
        "{}",
        r.stderr
    );
    let cycle = "CYCL DEF 7.0 DATUM SHIFT\n/CYCL DEF 7.1 X+10\nCYCL DEF 7.2 Y+20\nL X+0 FMAX\n";
    assert_eq!(translate(cycle, "heidenhain", "fanuc").code, 1);
    // Both optional, or neither: one command, with the mark where there is one.
    let both = prog.replace("N30 G53.1", "/N30 G53.1");
    let r = translate(&both, "fanuc", "heidenhain");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(
        r.stdout
            .contains("/PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX"),
        "{}",
        r.stdout
    );
}

/// SINUMERIK's frames and CYCLE800's swivel: the check reads the command whatever stands
/// before it (a skip mark, `:20`, a label) and `CROT`/`CROTS` as the `ROT`/`ROTS` they are
/// read as (each was translated silently, exit 0).
#[test]
fn program_to_names_frames_beside_a_swivel_however_spelled() {
    for second in [
        "/N20 ROT Z30",
        ":20 ROT Z30",
        "N20 CROT Z30",
        "N20 CROTS X10 Y10",
        "MARK: ROT Z30",
    ] {
        let prog = format!(
            "N10 CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)\n{second}\nN30 G1 X10\nN40 M30\n"
        );
        let r = translate(&prog, "sinumerik", "fanuc");
        assert_eq!(r.code, 1, "{second}: {}", r.stderr);
        assert!(
            r.stderr.contains("while a CYCLE800 swivel is active"),
            "{second}: {}",
            r.stderr
        );
    }
    let r = translate(
        "N10 TRANS X10\nMARK: CYCLE800()\nN25 G1 X0\nN30 M30\n",
        "sinumerik",
        "fanuc",
    );
    assert_eq!(r.code, 1, "{}", r.stderr);
}

/// Into its own dialect a block that leaves the tilt as it is stays as it stands: the turn
/// to the plane with its `M126` (dropped: the way of the rotary axes from then on), cycle 7's
/// lines (each was written as a whole cycle, the last one then alone).
#[test]
fn program_to_its_own_dialect_keeps_what_leaves_the_tilt() {
    let turn =
        "1 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n2 L B+Q121 C+Q122 R0 FMAX M126\n3 L C+350 FMAX\n";
    let out = program_to(turn, "heidenhain", "heidenhain");
    assert_eq!(out[1], "2 L B+Q121 C+Q122 R0 FMAX M126", "{out:?}");
    let cycle = "1 CYCL DEF 7.0 DATUM SHIFT\n2 CYCL DEF 7.1 X+50\n3 CYCL DEF 7.2 Y+20\n\
                 4 CYCL DEF 7.3 Z+0\n5 L X+0 FMAX\n";
    assert_eq!(
        program_to(cycle, "heidenhain", "heidenhain"),
        cycle.lines().collect::<Vec<_>>()
    );
}

/// TwinCAT's `G58` shifts only under a zero offset `G54`–`G57` (the default `G53`
/// deactivates it): a translation that writes one for a program that selects none says so.
#[test]
fn program_to_twincat_names_g58_without_a_zero_offset() {
    let prog = "0 BEGIN PGM T MM\n1 CYCL DEF 7.0 DATUM SHIFT\n2 CYCL DEF 7.1 X+50\n\
                3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n4 END PGM T MM\n";
    let r = translate(prog, "heidenhain", "twincat");
    assert!(r.stdout.contains("G58 X50 Y0 Z0"), "{}", r.stdout);
    assert!(
        r.stderr
            .contains("which shifts only while a zero offset G54 to G57 is active"),
        "{}",
        r.stderr
    );
    let fanuc = "G54\nG52 X50.\nG68.2 X0 Y0 Z0 I0 J30. K0\nG69\n";
    let r = translate(fanuc, "fanuc", "twincat");
    assert!(!r.stderr.contains("zero offset G54 to G57"), "{}", r.stderr);
}

/// An ISO jump back to a block number (`IF [#1 LT 3] GOTO10`) is a loop as `WHILE` is: the
/// increment in it is named (it was read once, silently).
#[test]
fn program_names_an_increment_in_a_goto_loop() {
    let prog = "G68.2 X0 Y0 Z0 I0 J0 K0\n#1=0\nN10 G68.4 I0 J10 K0\n#1=#1+1\nIF[#1LT3]GOTO10\nG53.1\nG69\n";
    let r = cncrot(&["program", "-", "--dialect", "fanuc"], prog);
    assert!(
        r.stderr
            .contains("line 3: the block adds to the frame and stands in a loop"),
        "{}",
        r.stderr
    );
    let straight = prog.replace("IF[#1LT3]GOTO10\n", "");
    let r = cncrot(&["program", "-", "--dialect", "fanuc"], &straight);
    assert!(!r.stderr.contains("in a loop"), "{}", r.stderr);
}

/// An assignment a forward jump passes over, or inside `IF … ENDIF`, runs only on a
/// condition: the tilt that uses it stays refused (it was read with the value, exit 0).
#[test]
fn program_reads_no_parameter_a_jump_may_skip() {
    let fanuc = "IF[#5EQ1]GOTO10\n#2=30.\nN10 G68.2 X0 Y0 Z0 I0 J#2 K0\nG69\n";
    let r = translate(fanuc, "fanuc", "heidenhain");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(!r.stderr.contains("read with #2"), "{}", r.stderr);
    let sinumerik = "IF R5==1 GOTOF SKIP\nR2=30\nSKIP:\n\
                     CYCLE800(0,\"TC1\",0,57,0,0,0,0,R2,0,0,0,0,-1,0,0)\n";
    assert_eq!(translate(sinumerik, "sinumerik", "fanuc").code, 1);
    let inside = "IF R5==1\nR2=30\nENDIF\nCYCLE800(0,\"TC1\",0,57,0,0,0,0,R2,0,0,0,0,-1,0,0)\n";
    assert_eq!(translate(inside, "sinumerik", "fanuc").code, 1);
    let heidenhain = "0 BEGIN PGM Q MM\n1 FN 9: IF +Q5 EQU +1 GOTO LBL 5\n2 FN 0: Q1 = +30\n\
                      3 LBL 5\n4 PLANE SPATIAL SPA+0 SPB+Q1 SPC+0 STAY\n5 END PGM Q MM\n";
    assert_eq!(translate(heidenhain, "heidenhain", "fanuc").code, 1);
    // Without the jump: read with the value.
    let plain = fanuc.replace("IF[#5EQ1]GOTO10\n", "");
    assert_eq!(translate(&plain, "fanuc", "heidenhain").code, 0);
    // A skip-marked assignment (the switch may leave it out), one inside a loop that may run
    // no time, a macro's local variable set by the main program (`G65 … A30.` sets the
    // macro's #1 to 30, not to the main program's 10): not read with a value.
    let skipped = "/#2=30.\nG68.2 X0 Y0 Z0 I0 J#2 K0\nG69\n";
    assert_eq!(translate(skipped, "fanuc", "heidenhain").code, 1);
    let looped =
        "#1=0\nWHILE [#1 LT #5] DO1\n#2=30.\n#1=#1+1\nEND1\nG68.2 X0 Y0 Z0 I0 J#2 K0\nG69\n";
    assert_eq!(translate(looped, "fanuc", "heidenhain").code, 1);
    let sinumerik_loop = "WHILE R5>0\nR2=30\nR5=R5-1\nENDWHILE\n\
                          CYCLE800(0,\"TC1\",0,57,0,0,0,0,R2,0,0,0,0,-1,0,0)\n";
    assert_eq!(translate(sinumerik_loop, "sinumerik", "fanuc").code, 1);
    let local = "O1000\n#1=10.\nG65 P3000 A30.\nM30\nO3000\nG68.2 X0 Y0 Z0 I0 J#1 K0\nG69\nM99\n";
    let r = translate(local, "fanuc", "heidenhain");
    assert_eq!(r.code, 1, "{}", r.stdout);
    assert!(
        !r.stdout.contains("SPB+10") && !r.stdout.contains("SPA+10"),
        "{}",
        r.stdout
    );
}

/// TwinCAT's `G53` and `G58` are modal zero-offset commands (Beckhoff's manual: `G53`
/// "deactivate[s] any zero offset shift translation"; `G58` shifts only under `G54`–`G57`):
/// an ISO one-shot `G53 G0 Z0.` copied into TwinCAT would leave the rest of the program in
/// machine coordinates, and a TwinCAT program's `G58` with no `G54`–`G57` selected shifts
/// nothing. Both named (the move not carried across, exit status 1; the `G58` read, to be
/// checked on the control, which may have kept a zero offset from before); with `G54`
/// selected the `G58` is read in silence.
#[test]
fn twincat_zero_offsets_are_named() {
    let fanuc = "G68.2 X0 Y0 Z0 I0 J30 K0\nN50 G0G53Z0.\nG69\n";
    let r = translate(fanuc, "fanuc", "twincat");
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stderr.contains("line 2: not carried across"),
        "{}",
        r.stderr
    );
    assert!(r.stdout.contains("N50 G0G53Z0."), "{}", r.stdout);
    // G53.1 is no G53.
    let r = translate("G68.2 X0 Y0 Z0 I0 J30 K0\nG53.1\nG69\n", "fanuc", "twincat");
    assert!(
        !r.stderr.contains("machine-coordinate move"),
        "{}",
        r.stderr
    );
    let twincat = "G58 X100 Y0 Z0\nROT X30\nROT\n";
    let r = cncrot(&["program", "-", "--dialect", "twincat"], twincat);
    assert!(r.stderr.contains("line 1: G58 shifts only"), "{}", r.stderr);
    let r = cncrot(
        &["program", "-", "--dialect", "twincat"],
        &format!("G54\n{twincat}"),
    );
    assert!(!r.stderr.contains("G58 shifts only"), "{}", r.stderr);
}

/// A UTF-16 file (a NUL beside every ASCII letter) read byte for byte had every block passed
/// over, exit 0: refused with what to do, as a text holding NUL bytes.
#[test]
fn program_refuses_utf16_and_nul_bytes() {
    let dir = std::env::temp_dir().join(format!("cncrot-utf16-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("u16.nc");
    let mut bytes = vec![0xFF, 0xFE];
    for c in "G68.2 X0 Y0 Z0 I0 J30 K0\r\n".encode_utf16() {
        bytes.extend_from_slice(&c.to_le_bytes());
    }
    std::fs::write(&file, bytes).unwrap();
    let r = cncrot(
        &["program", file.to_str().unwrap(), "--dialect", "fanuc"],
        "",
    );
    assert_eq!(r.code, 2, "{}", r.stdout);
    assert!(r.stderr.contains("UTF-16"), "{}", r.stderr);
    let r = cncrot(
        &["program", "-", "--dialect", "fanuc"],
        "G1\nG6\u{0}8.2 J30.\n",
    );
    assert_eq!(r.code, 2, "{}", r.stdout);
    assert!(r.stderr.contains("line 2 holds a NUL byte"), "{}", r.stderr);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A datum shift on an optional block (`/G52 X10.`): Fanuc and Haas keep it in a block of its
/// own, which stays optional; Heidenhain, SINUMERIK and TwinCAT write it into the tilt blocks
/// after it (cycle 7 with the `G68.2`'s origin, `X+15`; `CYCLE800`'s origin words; `G58`),
/// which are not: those blocks are named, exit status 1.
#[test]
fn program_to_names_an_optional_shift_written_into_other_blocks() {
    let prog = "/G52 X10.\nG68.2 X5. Y0 Z0 I0 J45. K0\nG53.1\nG69\n";
    for to in ["heidenhain", "sinumerik", "twincat"] {
        let r = translate(prog, "fanuc", to);
        assert_eq!(r.code, 1, "{to}: {}", r.stderr);
        assert!(
            r.stderr
                .contains("datum shift of the optional block at line 1"),
            "{to}: {}",
            r.stderr
        );
    }
    let haas = program_to(prog, "fanuc", "haas");
    assert_eq!(haas[0], "/G52 X10. Y0. Z0.");
    // Without the skip mark nothing is said.
    let plain = translate(&prog[1..], "fanuc", "heidenhain");
    assert_eq!(plain.code, 0, "{}", plain.stderr);
}
