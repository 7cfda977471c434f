//! The subcommands: each reads its input with `input`, computes with the library, and
//! reports with `output`. No mathematics here beyond choosing what to print.

use crate::input::{self, Failure, Target};
use crate::output::{num, nums, Json};
use crate::{labels, svg};
use crate::{run, Common, Report};
use cncrot::dialects::cycle600::{self, Call, State};
use cncrot::dialects::head_def::HeadTable;
use cncrot::dialects::heidenhain::cycle_head;
use cncrot::dialects::program::{
    joins, rest, write_block, write_change, write_line, AxisChoice, Dialect, DirectAxes, Feed,
    Positioning, Program, Remark, Retract, MAX_CHANGE,
};
use cncrot::kinematics::{Machine, RotaryAxis, Rule, Side, MAX_AXES};
use cncrot::{
    angles_from_matrix, closest_of, decompose, matrix_from_angles, probe, second_solution,
    AxisCode, Convention, Error, Frame, Kind, Matrix, Sequence, Vector,
};

/// Prefixes an option's name to its failure.
fn option(name: &'static str) -> impl Fn(Failure) -> Failure {
    move |f| Failure::new(format!("{name}: {}", f.message))
}

/// The positional arguments as one input (they may be split by the shell).
fn joined(args: &[String]) -> Option<String> {
    let args: Vec<&str> = args.iter().map(|a| a.trim()).collect();
    (!args.is_empty()).then(|| args.join(" "))
}

fn kind_name(k: Kind) -> &'static str {
    match k {
        Kind::Intrinsic => "intrinsic",
        Kind::Extrinsic => "extrinsic",
    }
}

fn letters(code: AxisCode) -> String {
    code.axes()
        .iter()
        .map(|a| match a.map(|a| a.bits()) {
            Some(1) => 'X',
            Some(2) => 'Y',
            Some(3) => 'Z',
            _ => '0',
        })
        .collect()
}

fn convention_name(kind: Kind, code: AxisCode) -> String {
    format!("{} {} ({})", kind_name(kind), letters(code), code.code())
}

/// The angles of a rotation given in `code`: three numbers, or one per rotation the code
/// has (a skipped rotation's angle is 0).
fn angles_for(code: AxisCode, text: &str) -> Result<[f64; 3], Failure> {
    let given = input::numbers(text)?;
    if given.len() == 3 {
        return Ok([given[0], given[1], given[2]]);
    }
    let present = code.axes().iter().filter(|a| a.is_some()).count();
    if given.len() != present {
        return Err(Failure::at(
            text.len() + 1,
            format!("expected 3 angles, found {}", given.len()),
        ));
    }
    let mut out = [0.0; 3];
    let mut it = given.into_iter();
    for (slot, axis) in out.iter_mut().zip(code.axes()) {
        if axis.is_some() {
            *slot = it.next().unwrap_or(0.0);
        }
    }
    Ok(out)
}

pub fn convert(
    from: &str,
    to: &str,
    near: Option<&str>,
    angles: &[String],
    common: &Common,
) -> Result<bool, Failure> {
    let (kind, code) = input::convention(from, true).map_err(option("--from"))?;
    let conv = input::full_convention(to).map_err(option("--to"))?;
    let near = near
        .map(|t| input::exactly::<3>(t, "angles"))
        .transpose()
        .map_err(option("--near"))?;
    let d = common.decimals;
    run(common, joined(angles), |text| {
        let given = angles_for(code, text)?;
        let first = decompose(conv, &matrix_from_angles(kind, code, given));
        let second = second_solution(conv.sequence, first);
        let to_name = convention_name(conv.kind, conv.sequence.into());
        let mut full = format!("{}: {}\n", convention_name(kind, code), nums(&given, d));
        let mut json = Json::Obj(vec![
            ("intrinsic", Json::Int(conv.kind.flag().into())),
            ("code", Json::Int(conv.sequence.code().into())),
        ]);
        let brief = match near {
            Some(reference) => {
                let c = closest_of(conv.sequence, first, reference)?;
                full += &format!(
                    "{to_name}: {}  (nearest to {})\n",
                    nums(&c.angles, d),
                    nums(&reference, d)
                );
                json = json.with("angles", Json::nums(&c.angles));
                nums(&c.angles, d)
            }
            None => {
                full += &format!("{to_name}: {}\n", nums(&first.angles, d));
                json = json.with("angles", Json::nums(&first.angles));
                // At a singular pose there is no second solution, only other splits of the
                // determined sum or difference: printing one would contradict "the third is
                // set to 0".
                if !first.singular {
                    full += &format!("  second solution: {}\n", nums(&second.angles, d));
                    json = json.with("second", Json::nums(&second.angles));
                }
                nums(&first.angles, d)
            }
        };
        if first.singular {
            full += "  singular: the middle angle is at its singular value; only the first and \
                     third rotations together are determined, the third is set to 0\n";
        }
        Ok(Report {
            full,
            brief,
            json: json.with("singular", Json::Bool(first.singular)),
        })
    })
}

/// What writing one target gave: the line, whether its origin has to be set apart, or why
/// it could not be written.
struct Written {
    target: Target,
    result: Result<(String, bool), Error>,
}

/// The frame's lines for every target. A form without origin words writes the rotation
/// about the datum, which is the same frame once the datum is shifted to its origin.
fn write_targets(frame: &Frame, targets: &[Target], decimals: i32) -> Vec<Written> {
    let mut buf = [0u8; 1024];
    let mut write = |target: &Target, f: &Frame| {
        write_line(
            target.dialect,
            target.form.as_bytes(),
            f,
            decimals,
            &mut buf,
        )
        .map(|(n, _)| String::from_utf8_lossy(&buf[..n]).into_owned())
    };
    targets
        .iter()
        .map(|t| {
            let result = match write(t, frame) {
                Err(Error::HasOrigin) => {
                    write(t, &Frame::from_rotation(frame.rotation)).map(|s| (s, true))
                }
                other => other.map(|s| (s, false)),
            };
            Written {
                target: t.clone(),
                result,
            }
        })
        .collect()
}

/// A frame and its lines as a report; a target that could not be written fails the input.
fn frame_report(
    frame: &Frame,
    targets: &[Target],
    d: i32,
    mut full: String,
    json: Json,
) -> Result<Report, Failure> {
    let origin = nums(&frame.translation, d);
    full += &format!("origin: {origin}\nrotation:\n");
    for row in frame.rotation {
        full += &format!("  {}\n", nums(&row, d));
    }
    let written = write_targets(frame, targets, d);
    let mut brief = Vec::new();
    let mut lines = Vec::new();
    let mut failed = Vec::new();
    for w in &written {
        let name = input::dialect_name(w.target.dialect);
        match &w.result {
            Ok((text, apart)) => {
                let shown = frame.translation.iter().any(|&t| num(t, d) != num(0.0, d));
                let note = if *apart && shown {
                    format!("  [origin {origin}: shift the datum there first]")
                } else {
                    String::new()
                };
                full += &format!("{name:<10} {text}{note}\n");
                brief.push(format!("{text}{note}"));
                lines.push(Json::Obj(vec![
                    ("dialect", Json::str(name)),
                    ("form", Json::str(w.target.form.clone())),
                    ("text", Json::str(text.clone())),
                    // As the text: an origin that rounds to zero at the decimals asked for
                    // (2.6e-16 from a fit) is no datum to shift.
                    ("origin_apart", Json::Bool(*apart && shown)),
                ]));
            }
            Err(e) => failed.push(format!("{name} {}: {}", w.target.form, e.message())),
        }
    }
    if !failed.is_empty() {
        return Err(Failure::new(failed.join("; ")));
    }
    Ok(Report {
        full,
        brief: brief.join("\t"),
        json: json
            .with("origin", Json::nums(&frame.translation))
            .with("rotation", Json::matrix(&frame.rotation))
            .with("lines", Json::Arr(lines)),
    })
}

fn targets(to: &[String]) -> Result<Vec<Target>, Failure> {
    if to.is_empty() {
        return Ok(input::all_targets());
    }
    to.iter()
        .map(|t| input::target(t))
        .collect::<Result<_, _>>()
        .map_err(option("--to"))
}

/// The positions a direct mode states, as its block names them (`B=30 C=45`, or
/// `axis 1=45 axis 2=30`).
/// A program's choice of solution in words, for a message.
fn choice_name(c: AxisChoice) -> String {
    let axis = |k: u8| match k {
        0 => "the master axis".to_string(),
        k => format!("rotary axis {k}"),
    };
    match c {
        AxisChoice::Closest => "the closest".to_string(),
        AxisChoice::Minus(k) => format!("{} at its lower angle", axis(k)),
        AxisChoice::Plus(k) => format!("{} at its higher angle", axis(k)),
        AxisChoice::PositiveTurn(k) => format!("{} turning only up", axis(k)),
        AxisChoice::NegativeTurn(k) => format!("{} turning only down", axis(k)),
    }
}

fn direct_text(p: &Program, d: i32) -> String {
    let Some(direct) = p.direct else {
        return String::new();
    };
    let mut words = Vec::new();
    for (k, v) in p.angles.iter().enumerate() {
        if direct.given & (1 << k) == 0 {
            continue;
        }
        let v = nums(&[*v], d);
        words.push(match direct.by {
            DirectAxes::Letters => format!("{}={}", ["A", "B", "C"][k], v.trim()),
            DirectAxes::Numbered => format!("axis {}={}", k + 1, v.trim()),
        });
    }
    words.join(" ")
}

/// What `line` reports for a direct mode: its positions (the frame needs the machine) and
/// the block in each target that has a direct mode naming the axes the same way; a target
/// asked for by name that has none is a failure, one of the default list is left out.
fn direct_report(p: &Program, targets: &[Target], asked: bool, d: i32) -> Result<Report, Failure> {
    let axes = direct_text(p, d);
    let mut full = format!(
        "direct: {axes}\n(the frame follows from the machine: `cncrot program` with --carr or --axis)\n"
    );
    let (mut brief, mut lines, mut failed) = (vec![format!("direct: {axes}")], vec![], vec![]);
    for t in targets {
        let name = input::dialect_name(t.dialect);
        let mut buf = [0u8; MAX_CHANGE];
        match write_change(
            t.dialect,
            t.form.as_bytes(),
            &Program::default(),
            p,
            d,
            &mut buf,
        ) {
            Ok((n, _)) => {
                let text = String::from_utf8_lossy(&buf[..n]).replace('\n', "  ");
                full += &format!("{name:<10} {text}\n");
                brief.push(text.clone());
                lines.push(Json::Obj(vec![
                    ("dialect", Json::str(name)),
                    ("form", Json::str(t.form.clone())),
                    ("text", Json::str(text)),
                ]));
            }
            Err(e) if asked => failed.push(format!("{name} {}: {}", t.form, e.message())),
            Err(_) => {}
        }
    }
    if !failed.is_empty() {
        return Err(Failure::new(failed.join("; ")));
    }
    Ok(Report {
        full,
        brief: brief.join("\t"),
        json: Json::Obj(vec![
            ("direct", Json::nums(&p.angles)),
            ("by", Json::str(direct_by(p))),
            ("lines", Json::Arr(lines)),
        ]),
    })
}

fn direct_by(p: &Program) -> &'static str {
    match p.direct.map(|d| d.by) {
        Some(DirectAxes::Numbered) => "axis",
        _ => "letter",
    }
}

pub fn line(
    from: &str,
    to: &[String],
    (euler, axis_angles): (bool, bool),
    text: Option<&str>,
    common: &Common,
    svg: Option<&str>,
) -> Result<bool, Failure> {
    let dialect = input::dialect(from).map_err(option("--from"))?;
    let targets = targets(to)?;
    let mut program = Program {
        euler: euler && dialect == Dialect::Sinumerik,
        axis_angles: axis_angles && dialect == Dialect::Heidenhain,
        ..Program::default()
    };
    let d = common.decimals;
    let mut last = None;
    // The first line whose way of moving the machine `line` leaves out (it writes planes):
    // said once, after the results.
    let (mut read, mut moving) = (0usize, None);
    let ok = run(common, text.map(str::to_string), |line| {
        read += 1;
        let (next, remark) = program
            .line(dialect, line.as_bytes())
            .map_err(|e| Failure::at(e.column, input::block_message(line, &e)))?;
        program = next;
        if moving.is_none() && remark == Remark::Applied && has_way_of_moving(&program) {
            moving = Some(read);
        }
        let note = match remark {
            Remark::Applied => None,
            Remark::Passed => Some(("passed", "the block does not concern the frame")),
            Remark::NotFollowed => Some((
                "not followed",
                "the block changes the frame in a way cncrot does not follow \
                 (a work offset, preset, table or variable write, mirroring, scaling or a \
                 tilt through the machine's axes): cncrot's frame stays as it was and may no \
                 longer be the control's",
            )),
        };
        if let Some((brief, why)) = note {
            return Ok(Report {
                full: format!("{brief}: {why}\n"),
                brief: brief.to_string(),
                json: Json::Obj(vec![("remark", Json::str(brief.to_string()))]),
            });
        }
        if program.direct.is_some() {
            return direct_report(&program, &targets, !to.is_empty(), d);
        }
        last = Some(line.trim().to_string());
        frame_report(
            &program.frame,
            &targets,
            d,
            String::new(),
            Json::Obj(vec![]),
        )
    })?;
    if let Some(k) = moving {
        let at = if common.batch.is_some() {
            format!(" (first at line {k})")
        } else {
            String::new()
        };
        eprintln!(
            "cncrot: note: the way the line moves the machine (its turn, direction of solution, retraction or feed){at} is not written: `line` writes planes; `cncrot program FILE --dialect {} --to DIALECT` carries it",
            input::dialect_name(dialect)
        );
    }
    if let (Some(path), Some(block)) = (svg, last) {
        let title = match &common.batch {
            Some(_) => "the frame after the last tilt of the program".to_string(),
            None => block,
        };
        svg::write(
            path,
            &svg::Picture {
                title,
                planes: vec![svg::Plane {
                    frame: program.frame,
                    label: String::new(),
                }],
                size: 50.0,
                points: Vec::new(),
                notes: vec![format!(
                    "origin {}   tool direction (Z') {}",
                    nums(&program.frame.translation, d),
                    nums(&column(&program.frame.rotation, 2), d)
                )],
            },
        )?;
    }
    Ok(ok)
}

/// Whether the state holds a way of moving the machine to its tilt that a plane alone does
/// not say: a turn or a move, a solution the block chooses, a retraction, a feed, a
/// table turned to the plane.
fn has_way_of_moving(p: &Program) -> bool {
    use cncrot::dialects::program::{AxisChoice, Feed, Positioning, Retract};
    p.positioning != Positioning::Stay
        || p.choice != AxisChoice::Closest
        || p.retract != Retract::None
        || p.feed != Feed::Rapid
        || p.table_rot
}

/// A points file: one point per line; `#` lines, blank lines and a first line that is not
/// numbers (a header) are skipped.
fn points_of_file(source: &str) -> Result<Vec<Vector>, Vec<(usize, Failure)>> {
    let text = input::read_source(source).map_err(|f| vec![(0, f)])?;
    let mut points = Vec::new();
    let mut errors = Vec::new();
    let mut first = true;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        match input::exactly::<3>(line, "a point") {
            Ok(p) => points.push(p),
            // Column names hold no number ("x y z"): a first line with digits is a point or
            // an error (`P1 0 0 0`, a labelled point, was skipped as a header in silence).
            Err(_) if first && !t.bytes().any(|b| b.is_ascii_digit()) => {}
            Err(f) => errors.push((i + 1, f)),
        }
        first = false;
    }
    if errors.is_empty() {
        Ok(points)
    } else {
        Err(errors)
    }
}

pub fn probe(
    args: &[String],
    file: Option<&str>,
    to: &[String],
    toward: Option<&str>,
    json: bool,
    d: i32,
    svg: Option<&str>,
) -> Result<bool, Failure> {
    let targets = targets(to)?;
    // The tool's side, or (--order) none: the points' order decides.
    let toward = match toward {
        Some(t) => input::exactly::<3>(t, "direction").map_err(option("--toward"))?,
        None => [0.0; 3],
    };
    let points: Vec<Vector> = match (file, args.is_empty()) {
        (Some(_), false) => {
            return Err(Failure::new(
                "give the points as arguments or --points-file, not both",
            ))
        }
        (Some(source), true) => match points_of_file(source) {
            Ok(p) => p,
            // The file not read at all (missing, a directory, UTF-16): exit status 2, as
            // for every command.
            Err(mut errors) if errors.len() == 1 && errors[0].0 == 0 => {
                return Err(errors.remove(0).1);
            }
            Err(errors) => {
                for (line, f) in errors {
                    let column = f
                        .column
                        .map(|c| format!(", column {c}"))
                        .unwrap_or_default();
                    let place = if line > 0 {
                        format!("line {line}{column}: ")
                    } else {
                        String::new()
                    };
                    eprintln!("cncrot: {place}{}", f.message);
                }
                return Ok(false);
            }
        },
        (None, _) => {
            let mut v = Vec::new();
            for (k, a) in args.iter().enumerate() {
                match input::exactly::<3>(a, "a point") {
                    Ok(p) => v.push(p),
                    Err(f) => {
                        let column = f
                            .column
                            .map(|c| format!(", column {c}"))
                            .unwrap_or_default();
                        eprintln!("cncrot: point {}{column}: {}", k + 1, f.message);
                        return Ok(false);
                    }
                }
            }
            v
        }
    };
    let (plane, turned) = match probe::plane_toward(&points, toward) {
        Ok(p) => p,
        Err(cncrot::Error::Coincident) => {
            eprintln!(
                "cncrot: {} points: the first two points coincide, or lie closer than {} of the points' spread: X' runs from the first to the second; probe the second farther along the face's X",
                points.len(),
                probe::X_SPACING
            );
            return Ok(false);
        }
        Err(e) => {
            eprintln!("cncrot: {} points: {}", points.len(), e.message());
            return Ok(false);
        }
    };
    let angles = angles_from_matrix(
        Convention::new(Kind::Extrinsic, Sequence::XYZ),
        &plane.frame.rotation,
    )?;
    let mut full = format!(
        "points: {}\nflatness: {} mm\nrms: {} mm\nnormal (Z'): {}\n",
        points.len(),
        num(plane.flatness, d),
        num(plane.rms, d),
        nums(&column(&plane.frame.rotation, 2), d),
    );
    if turned {
        full += "  turned to the tool's side: the points' order, (P2-P1)x(P3-P1), gave the \
                 other side (--order keeps it)\n";
    }
    full += &format!(
        "as extrinsic XYZ (CYCLE600 _BIN_IN 57): {}\n",
        nums(&angles.angles, d)
    );
    let j = Json::Obj(vec![
        ("points", Json::Int(points.len() as i64)),
        ("flatness", Json::Num(plane.flatness)),
        ("rms", Json::Num(plane.rms)),
        ("normal", Json::nums(&column(&plane.frame.rotation, 2))),
        ("turned", Json::Bool(turned)),
        ("extrinsic_xyz", Json::nums(&angles.angles)),
    ]);
    if let Some(path) = svg {
        let o = plane.frame.translation;
        let z = column(&plane.frame.rotation, 2);
        let dev = |p: &Vector| (0..3).map(|k| (p[k] - o[k]) * z[k]).sum::<f64>();
        // The patch covers the points: half its side the farthest point's distance.
        let reach = points
            .iter()
            .map(|p| (0..3).map(|k| (p[k] - o[k]).powi(2)).sum::<f64>().sqrt())
            .fold(0.0f64, f64::max);
        let mut notes = vec![
            format!(
                "flatness {} mm   normal (Z') {}",
                num(plane.flatness, d),
                nums(&z, d)
            ),
            format!("as extrinsic XYZ: {}", nums(&angles.angles, d)),
        ];
        if turned {
            notes.push("turned to the tool's side (the points' order gave the other)".into());
        }
        svg::write(
            path,
            &svg::Picture {
                title: format!("probed plane of {} points", points.len()),
                planes: vec![svg::Plane {
                    frame: plane.frame,
                    label: String::new(),
                }],
                size: if reach > 0.0 { reach } else { 50.0 },
                points: points.iter().map(|p| (*p, dev(p))).collect(),
                notes,
            },
        )?;
    }
    match frame_report(&plane.frame, &targets, d, full, j) {
        Ok(r) if json => println!("{}", r.json.text()),
        Ok(r) => print!("{}", r.full),
        Err(f) => {
            eprintln!("cncrot: {}", f.message);
            return Ok(false);
        }
    }
    Ok(true)
}

fn column(m: &Matrix, k: usize) -> [f64; 3] {
    [m[0][k], m[1][k], m[2][k]]
}

/// The parameters of a CYCLE600 call with their columns: `CYCLE600(a, b, …)` (after an
/// optional block number, with an optional `;` comment after it), or the bare list.
/// The parameters of a bare list (`0 "UFK 600" 1 57 …` or with commas) with their
/// 1-based columns: separated by spaces, tabs, commas or semicolons, a quoted text one
/// parameter whatever it holds.
fn list_tokens(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut chars = text.char_indices().peekable();
    while let Some(&(i, c)) = chars.peek() {
        if c.is_whitespace() || c == ',' || c == ';' {
            chars.next();
            continue;
        }
        let mut end = i;
        let mut quoted = false;
        for (j, d) in chars.by_ref() {
            end = j + d.len_utf8();
            if d == '"' {
                quoted = !quoted;
            } else if !quoted && (d.is_whitespace() || d == ',' || d == ';') {
                end = j;
                break;
            }
        }
        out.push((i + 1, text[i..end].to_string()));
    }
    out
}

fn call_parameters(text: &str) -> Result<Vec<(usize, String)>, Failure> {
    let trimmed = text.trim_start();
    let lead = text.len() - trimmed.len();
    let Some(open) = text.find('(') else {
        return Ok(list_tokens(text));
    };
    let head = text[..open].trim();
    let head = match head.split_once(char::is_whitespace) {
        Some((n, rest)) if n.starts_with(['N', 'n']) => rest.trim(),
        _ => head,
    };
    if !head.eq_ignore_ascii_case("CYCLE600") {
        return Err(Failure::at(
            lead + 1,
            "expected CYCLE600(...) or the list of parameters",
        ));
    }
    let Some(close) = text.rfind(')').filter(|&c| c > open) else {
        return Err(Failure::at(text.len() + 1, "missing ')'"));
    };
    let rest = text[close + 1..].trim_start();
    if !(rest.is_empty() || rest.starts_with(';')) {
        return Err(Failure::at(
            text.len() - rest.len() + 1,
            "text after the call",
        ));
    }
    let mut out = Vec::new();
    let mut start = open + 1;
    for part in text[open + 1..close].split(',') {
        let t = part.trim();
        let column = start + (part.len() - part.trim_start().len()) + 1;
        out.push((column, t.to_string()));
        start += part.len() + 1;
    }
    Ok(out)
}

fn int_param(p: &(usize, String)) -> Result<i32, Failure> {
    if p.1.is_empty() {
        return Ok(0);
    }
    p.1.parse::<i32>()
        .map_err(|_| Failure::at(p.0, format!("'{}' is not a whole number", p.1)))
}

fn real_param(p: &(usize, String)) -> Result<f64, Failure> {
    if p.1.is_empty() {
        return Ok(0.0);
    }
    input::number(&p.1).map_err(|m| Failure::at(p.0, m))
}

/// A call as read: its parameters with their columns, the integer ones (`_INEXIN`,
/// `_SW_REC`, `_BIN_IN`, `_INEXOUT`, `_BIN_OUT`, `_ROT_AD`, `_ROT_INV`, `_RETR_Z`) and the
/// real ones (`_POS`, `_ANG`, `_POS_R`).
struct CallText {
    params: Vec<(usize, String)>,
    ints: [i32; 8],
    reals: [f64; 9],
}

fn read_call(text: &str) -> Result<CallText, Failure> {
    let params = call_parameters(text)?;
    if params.len() < 15 || params.len() > 18 {
        return Err(Failure::at(
            text.len() + 1,
            format!("CYCLE600 has 15 to 18 parameters, found {}", params.len()),
        ));
    }
    let mut ints = [0; 8];
    for (slot, k) in ints.iter_mut().zip([0, 2, 3, 13, 14, 15, 16, 17]) {
        if let Some(p) = params.get(k) {
            *slot = int_param(p)?;
        }
    }
    let mut reals = [0.0; 9];
    for (slot, p) in reals.iter_mut().zip(&params[4..13]) {
        *slot = real_param(p)?;
    }
    Ok(CallText {
        params,
        ints,
        reals,
    })
}

fn name_param(p: &(usize, String)) -> &str {
    let t = p.1.as_str();
    t.strip_prefix('"')
        .and_then(|s| s.strip_suffix('"'))
        .unwrap_or(t)
}

/// The machine of the options: swivel data, or axes given one by one.
pub struct MachineArgs<'a> {
    pub carr: Option<&'a str>,
    pub set: i32,
    pub axis: &'a [String],
    pub tool: &'a str,
}

fn carr_machine(source: &str, set: i32) -> Result<Machine, Failure> {
    let text = input::read_source(source)?;
    cncrot::dialects::carr::machine_from_carr(text.as_bytes(), set).map_err(|e| {
        let place = if e.line > 0 {
            format!(", line {}", e.line)
        } else {
            String::new()
        };
        Failure::new(format!("{source}{place}: {}", carr_message(&e, set)))
    })
}

/// What was wrong with swivel data, naming the parameter (`$TC_CARR23`) and what it may be.
fn carr_message(e: &cncrot::dialects::carr::CarrError, set: i32) -> String {
    let p = e.parameter;
    let name = format!("$TC_CARR{p}");
    let axis = |p: usize| if p >= 10 { 2 } else { 1 };
    match (e.error, p) {
        (Error::UnknownHead, _) => format!(
            "data set {set} is not in the file (no $TC_CARRn[{set}] is assigned; --set names \
             the data set)"
        ),
        (Error::BadArgument, 0) if set < 1 => {
            format!("data set {set}: --set counts from 1")
        }
        (Error::BadArgument, 23) | (Error::Parse, 23) => {
            format!(
                "{name}, the kinematics type, must be \"T\" (tool), \"P\" (part) or \"M\" (mixed)"
            )
        }
        (Error::BadArgument, 7..=12) => format!(
            "{name}: axis 2 ($TC_CARR10..12) needs axis 1 ($TC_CARR7..9) and must not be \
             parallel to it (axis {} at fault)",
            axis(p)
        ),
        (Error::BadArgument, 28 | 29) => {
            format!("{name}, a Hirth increment, must be 0 (no grid) or positive")
        }
        (Error::Parse, 34) => format!("{name}, the name, must be printable ASCII"),
        (Error::NameTooLong, _) => format!(
            "{name}, the name, is longer than {} characters",
            cncrot::kinematics::MACHINE_NAME_MAX
        ),
        (Error::UnknownWord, n) if n > 0 => {
            format!("$TC_CARR{n} is no swivel-data parameter (1..46, 55..60, 64, 65)")
        }
        (Error::UnknownWord, _) => {
            "not an assignment of swivel data ($TC_CARRn[set]=value)".to_string()
        }
        (Error::Parse, n) if n > 0 => format!(
            "{name}: malformed assignment ($TC_CARR{n}[set]=value with a number as \
             SINUMERIK writes it: 12.5, -3, 1.5EX3; a text in quotes)"
        ),
        (Error::NotANumber, n) if n > 0 => {
            format!("{name}: a variable or expression where a number must stand")
        }
        (Error::MissingWord, n) if n > 0 => format!("{name}: no number after '='"),
        (error, 7..=12) => format!(
            "axis {} ({name} and the axis' offset, limits, Hirth grid): {}",
            axis(p),
            error.message()
        ),
        (error, n) if n > 0 => format!("{name}: {}", error.message()),
        (error, _) => error.message().to_string(),
    }
}

fn machine(a: &MachineArgs) -> Result<Machine, Failure> {
    if let Some(source) = a.carr {
        if !a.axis.is_empty() {
            return Err(Failure::new(
                "describe the machine by --carr or by --axis, not both",
            ));
        }
        return carr_machine(source, a.set);
    }
    if a.axis.is_empty() {
        return Err(Failure::new(
            "describe the machine: --carr FILE (swivel data) or --axis SIDE:DX,DY,DZ[@PX,PY,PZ]",
        ));
    }
    let tool = input::exactly::<3>(a.tool, "direction").map_err(option("--tool"))?;
    let mut m = Machine::new(tool).map_err(|e| Failure::new(format!("--tool: {}", e.message())))?;
    for (k, spec) in a.axis.iter().enumerate() {
        let what = format!("--axis {}", k + 1);
        let (side, rest) = spec
            .split_once(':')
            .ok_or_else(|| Failure::new(format!("{what}: expected SIDE:DX,DY,DZ[@PX,PY,PZ]")))?;
        let side = match side.to_ascii_lowercase().as_str() {
            "tool" | "head" => Side::Tool,
            "work" | "table" => Side::Work,
            other => {
                return Err(Failure::new(format!(
                    "{what}: '{other}' is neither tool (a head) nor work (a table)"
                )))
            }
        };
        let (dir, point) = rest.split_once('@').unwrap_or((rest, "0,0,0"));
        let dir = input::exactly::<3>(dir, "direction").map_err(option("--axis"))?;
        let point = input::exactly::<3>(point, "point").map_err(option("--axis"))?;
        m.push_axis(RotaryAxis::new(side, dir, point))
            .map_err(|e| {
                let why = match e {
                    Error::BadArgument => {
                        "a zero direction, or parallel to its neighbour in the chain from the \
                         workpiece through the table's axes to the bed and through the head's \
                         axes to the tool (the outermost table and head axes are neighbours)"
                    }
                    Error::TableFull => "a machine has at most three rotary axes",
                    e => e.message(),
                };
                Failure::new(format!("{what}: {why}"))
            })?;
    }
    Ok(m)
}

/// Axis positions: 1 to 3 numbers, the unused ones 0.
fn positions(text: &str, n: usize, what: &str) -> Result<[f64; MAX_AXES], Failure> {
    let v = input::numbers(text)?;
    if v.is_empty()
        || v.len() > MAX_AXES.max(n)
        || (v.len() > n && v[n..].iter().any(|&x| x != 0.0))
    {
        return Err(Failure::at(
            text.len() + 1,
            format!(
                "{what}: the machine has {n} rotary axes, found {} positions",
                v.len()
            ),
        ));
    }
    let mut out = [0.0; MAX_AXES];
    out[..v.len().min(MAX_AXES)].copy_from_slice(&v[..v.len().min(MAX_AXES)]);
    Ok(out)
}

fn axes_text(axes: &[f64], d: i32) -> String {
    axes.iter()
        .enumerate()
        .map(|(k, &a)| format!("axis {} = {}", k + 1, num(a, d)))
        .collect::<Vec<_>>()
        .join(", ")
}

pub fn cycle600(
    call: &[String],
    heads: Option<&str>,
    carr: Option<&str>,
    set: i32,
    current: Option<&str>,
    common: &Common,
) -> Result<bool, Failure> {
    let table = heads
        .map(|source| {
            let text = input::read_source(source)?;
            HeadTable::parse(text.as_bytes()).map_err(|e| {
                // The line itself, so that the reader sees which assignment it is.
                let shown = text
                    .lines()
                    .nth(e.line.saturating_sub(1))
                    .filter(|_| e.line > 0)
                    .map(|l| {
                        let l = l.trim();
                        let cut: String = l.chars().take(60).collect();
                        let more = if l.chars().count() > 60 { "…" } else { "" };
                        format!(" ({cut}{more})")
                    })
                    .unwrap_or_default();
                let why = match e.error {
                    Error::Parse => "not a HEAD_DEF assignment (_NAME=value, the numbers as \
                                     SINUMERIK writes them, texts in quotes)"
                        .to_string(),
                    other => other.message().to_string(),
                };
                Failure::new(format!("{source}, line {}{shown}: {why}", e.line))
            })
        })
        .transpose()
        .map_err(option("--heads"))?;
    let head = carr
        .map(|c| carr_machine(c, set))
        .transpose()
        .map_err(option("--carr"))?;
    let n = head.as_ref().map_or(MAX_AXES, |m| m.axes().len());
    let current = current
        .map(|t| positions(t, n, "positions"))
        .transpose()
        .map_err(option("--current"))?
        .unwrap_or([0.0; MAX_AXES]);
    let d = common.decimals;
    let mut state = State::default();
    run(common, joined(call), |text| {
        let CallText {
            params,
            ints,
            reals,
        } = read_call(text)?;
        let name = name_param(&params[1]);
        let c = Call {
            inexin: ints[0],
            mihead: name.as_bytes(),
            sw_rec: ints[1],
            bin_in: ints[2],
            pos: [reals[0], reals[1], reals[2]],
            ang: [reals[3], reals[4], reals[5]],
            pos_r: [reals[6], reals[7], reals[8]],
            inexout: ints[3],
            bin_out: ints[4],
            rot_ad: ints[5],
            rot_inv: ints[6],
            retr_z: ints[7],
        };
        if let Some((k, error, allowed)) = cycle600::first_fault(&c) {
            let column = params.get(k).map_or(1, |p| p.0);
            return Err(Failure::at(
                column,
                format!("{}: {} ({allowed})", params[k].1, error.message()),
            ));
        }
        let next = cycle600::cycle600(&state, table.as_ref(), &c).map_err(|e| match e {
            Error::UnknownHead => Failure::at(
                params[1].0,
                format!(
                    "{}: _MIHEAD is not an accessory of the --heads table",
                    params[1].1
                ),
            ),
            e => Failure::from(e),
        })?;
        let Some(r) = next.results else {
            return Err(Failure::new("the cycle stored no results"));
        };
        let positioned = match (&head, c.sw_rec) {
            (Some(m), 0) => Some(cycle600::position(&next, m, current)?),
            _ => None,
        };
        state = next;
        let gud_name = String::from_utf8_lossy(next.name()).into_owned();
        let flag = r.convention.kind.flag();
        let code = r.convention.sequence.code();
        let mut full = format!("_CYC600_1 = \"{gud_name}\"\n");
        for (k, a) in r.angles.iter().enumerate() {
            full += &format!("_CYC600_{} = {}\n", k + 2, num(*a, d));
        }
        full += &format!("_CYC600_5 = {flag}\n_CYC600_6 = {code}\n");
        full += &format!("frame origin: {}\n", nums(&next.frame.translation, d));
        if r.singular {
            full += "singular: only the first and third rotations together are determined; \
                     the third is set to 0\n";
        }
        let mut brief = format!("\"{gud_name}\" {} {flag} {code}", nums(&r.angles, d));
        let mut json = Json::Obj(vec![
            ("name", Json::str(gud_name)),
            ("angles", Json::nums(&r.angles)),
            ("intrinsic", Json::Int(flag.into())),
            ("code", Json::Int(code.into())),
            ("singular", Json::Bool(r.singular)),
            ("origin", Json::nums(&next.frame.translation)),
        ]);
        match (positioned, c.sw_rec) {
            (Some(p), _) => {
                let used = &p.axes[..n];
                full += &format!("head positions: {}\n", axes_text(used, d));
                brief += &format!(" axes {}", nums(used, d));
                json = json.with("axes", Json::nums(used));
            }
            (None, 0) => {
                full += "_SW_REC = 0 positions the head: give its swivel data with --carr\n"
            }
            _ => {}
        }
        Ok(Report { full, brief, json })
    })
}

/// What to compute with a machine.
pub struct AxesArgs<'a> {
    pub from: &'a str,
    pub current: Option<&'a str>,
    pub rule: &'a str,
    pub all: bool,
    pub forward: bool,
    /// Draw the last orientation with its positions into this SVG file.
    pub svg: Option<&'a str>,
}

fn rule(text: &str, n: usize) -> Result<Rule, Failure> {
    let lower = text.to_ascii_lowercase();
    let axis = |k: &str| -> Result<usize, Failure> {
        match k.parse::<usize>() {
            Ok(k) if (1..=n).contains(&k) => Ok(k - 1),
            _ => Err(Failure::new(format!(
                "--rule: '{k}' is not an axis of the machine (1..{n})"
            ))),
        }
    };
    match lower.split_once(':') {
        None if lower == "closest" => Ok(Rule::Closest),
        None if lower == "inverse" => Ok(Rule::Inverse),
        Some(("minus", k)) => Ok(Rule::Minus(axis(k)?)),
        Some(("plus", k)) => Ok(Rule::Plus(axis(k)?)),
        Some(("up", k)) => Ok(Rule::PositiveTurn(axis(k)?)),
        Some(("down", k)) => Ok(Rule::NegativeTurn(axis(k)?)),
        Some(("master", k)) => Ok(Rule::MasterFirst(axis(k)?)),
        _ => Err(Failure::new(format!(
            "--rule: '{text}': closest, inverse, minus:K, plus:K, up:K, down:K or master:K"
        ))),
    }
}

pub fn axes(
    m: &MachineArgs,
    a: &AxesArgs,
    values: &[String],
    common: &Common,
) -> Result<bool, Failure> {
    let machine = machine(m)?;
    let n = machine.axes().len();
    let (kind, code) = input::convention(a.from, true).map_err(option("--from"))?;
    let current = a
        .current
        .map(|t| positions(t, n, "positions"))
        .transpose()
        .map_err(option("--current"))?
        .unwrap_or([0.0; MAX_AXES]);
    let rule = rule(a.rule, n)?;
    let d = common.decimals;
    // What the picture shows: the last orientation, and its positions.
    let mut last: Option<(Frame, Vec<String>)> = None;
    let ok = run(common, joined(values), |text| {
        if a.forward {
            let p = positions(text, n, "positions")?;
            let f = machine.forward(p)?;
            let tool = column(&f.rotation, 2);
            let mut full = format!(
                "tool direction: {}\norigin: {}\n",
                nums(&tool, d),
                nums(&f.translation, d)
            );
            let mut json = Json::Obj(vec![
                ("tool", Json::nums(&tool)),
                ("origin", Json::nums(&f.translation)),
                ("rotation", Json::matrix(&f.rotation)),
            ]);
            let mut brief = nums(&tool, d);
            if let Ok(conv) = Sequence::from_axis_code(code).map(|s| Convention::new(kind, s)) {
                let ang = angles_from_matrix(conv, &f.rotation)?;
                full += &format!(
                    "{}: {}\n",
                    convention_name(kind, code),
                    nums(&ang.angles, d)
                );
                brief = nums(&ang.angles, d);
                json = json.with("angles", Json::nums(&ang.angles));
            }
            last = Some((f, vec![format!("positions: {}", axes_text(&p[..n], d))]));
            return Ok(Report { full, brief, json });
        }
        let target = matrix_from_angles(kind, code, angles_for(code, text)?);
        if a.all {
            let s = machine.inverse(&target)?;
            let rows: Vec<&[f64]> = s.as_slice().iter().map(|r| &r[..n]).collect();
            let mut full = String::new();
            for (k, r) in rows.iter().enumerate() {
                full += &format!("solution {}: {}\n", k + 1, axes_text(r, d));
            }
            if s.free {
                full += "singular pose: one axis is free (shown at its position 0)\n";
            }
            let brief = rows
                .iter()
                .map(|r| nums(r, d))
                .collect::<Vec<_>>()
                .join("\t");
            let json = Json::Obj(vec![
                (
                    "solutions",
                    Json::Arr(rows.iter().map(|r| Json::nums(r)).collect()),
                ),
                ("free", Json::Bool(s.free)),
            ]);
            let notes = rows
                .iter()
                .enumerate()
                .map(|(k, r)| format!("solution {}: {}", k + 1, axes_text(r, d)))
                .collect();
            last = Some((Frame::from_rotation(target), notes));
            return Ok(Report { full, brief, json });
        }
        let c = machine.choose(&target, current, rule)?;
        let used = &c.axes[..n];
        let mut full = format!("{}\n", axes_text(used, d));
        if c.residual.iter().any(|&r| r != 0.0) {
            full += &format!("Hirth residual: {}\n", nums(&c.residual[..n], d));
        }
        if c.free {
            full += "singular pose: a free axis stays at its current position\n";
        }
        let identity = c
            .remaining
            .iter()
            .flatten()
            .zip(cncrot::IDENTITY.iter().flatten())
            .all(|(x, y)| (x - y).abs() <= 1e-12);
        let mut json = Json::Obj(vec![
            ("axes", Json::nums(used)),
            ("residual", Json::nums(&c.residual[..n])),
            ("free", Json::Bool(c.free)),
            ("remaining", Json::matrix(&c.remaining)),
        ]);
        if !identity {
            let conv = Convention::new(Kind::Extrinsic, Sequence::XYZ);
            let r = angles_from_matrix(conv, &c.remaining)?;
            full += &format!(
                "left to the frame (the axes cannot turn about the tool), as extrinsic XYZ: {}\n",
                nums(&r.angles, d)
            );
            json = json.with("remaining_extrinsic_xyz", Json::nums(&r.angles));
        }
        last = Some((
            Frame::from_rotation(target),
            vec![format!("positions: {}", axes_text(used, d))],
        ));
        Ok(Report {
            full,
            brief: nums(used, d),
            json,
        })
    })?;
    if let (Some(path), Some((frame, mut notes))) = (a.svg, last) {
        notes.push(format!(
            "tool direction (Z') {}",
            nums(&column(&frame.rotation, 2), d)
        ));
        let name = String::from_utf8_lossy(machine.name()).into_owned();
        svg::write(
            path,
            &svg::Picture {
                title: if name.is_empty() {
                    "the machine's orientation".to_string()
                } else {
                    format!("the orientation of {name}")
                },
                planes: vec![svg::Plane {
                    frame,
                    label: String::new(),
                }],
                size: 50.0,
                points: Vec::new(),
                notes,
            },
        )?;
    }
    Ok(ok)
}

/// The block skip mark `block` starts with, as the target writes it: `/` (ISO's levels
/// `/1`–`/9` kept between ISO-style dialects; Heidenhain has one mark, and its digits after
/// `/` are the block number), or "" for a block without one.
fn skip_mark(block: &str, from: Dialect, to: Dialect) -> String {
    let mut b = block.trim_start();
    if from == Dialect::Heidenhain {
        // After the line number too, where the TNC shows it (`12 /L X+0`).
        b = b
            .trim_start_matches(|c: char| c.is_ascii_digit())
            .trim_start();
    }
    let Some(rest) = b.strip_prefix('/') else {
        return String::new();
    };
    let iso = |d: Dialect| !matches!(d, Dialect::Heidenhain);
    let level: String = rest.chars().take_while(char::is_ascii_digit).collect();
    if iso(from) && iso(to) && !level.is_empty() {
        // `/2 CYCLE800(…)`, not `/2CYCLE800(…)`.
        format!("/{level} ")
    } else {
        "/".to_string()
    }
}

/// Whether a program's text (in capitals) selects a zero offset `G54` to `G57` (as a word:
/// not `G540`, `G54.1`).
fn selects_g54_to_g57(upper: &str) -> bool {
    ["G54", "G55", "G56", "G57"]
        .iter()
        .any(|g| iso_word(upper, g))
}

/// Whether the ISO word `word` (`G53`) stands in `upper` (a block's code in capitals): not
/// after a letter (`G0G53` has it), not followed by a digit or point (`G53.1`, `G530`).
fn iso_word(upper: &str, word: &str) -> bool {
    upper.match_indices(word).any(|(at, _)| {
        let before = upper[..at].chars().next_back();
        let after = upper[at + word.len()..].chars().next();
        !before.is_some_and(|c| c.is_ascii_alphabetic())
            && !after.is_some_and(|c| c.is_ascii_digit() || c == '.')
    })
}

/// The move `words` (`X5 Y6 Z7`, ISO-style) as a rapid in dialect `to`: `G0 X5 Y6 Z7`, or
/// Heidenhain's `L X+5 Y+6 Z+7 FMAX`.
fn rapid_move(words: &str, to: Dialect) -> String {
    if to != Dialect::Heidenhain {
        return format!("G0 {words}");
    }
    let signed: Vec<String> = words
        .split_whitespace()
        .map(|w| {
            let (letter, value) = w.split_at(w.chars().next().map_or(0, char::len_utf8));
            let value = value.trim_start_matches('=');
            if value.starts_with(['+', '-']) {
                format!("{letter}{value}")
            } else {
                format!("{letter}+{value}")
            }
        })
        .collect();
    format!("L {} FMAX", signed.join(" "))
}

/// Says on standard error that the block at `line` could not be written as `t`'s, and why.
fn not_carried(line: usize, t: &Target, e: Error, block: &str) {
    eprintln!(
        "cncrot: line {line}: not carried across as {} {}: {}: {block}",
        input::dialect_name(t.dialect),
        t.form,
        e.message()
    );
}

/// The block number (`N20`, SINUMERIK's main block `:20`) and SINUMERIK's label (`MARK:`)
/// an ISO-style block starts with (after its skip mark), as written: what a jump (`GOTO20`,
/// `GOTOB MARK`) or a restart by number looks for. `None` for Heidenhain, whose leading
/// numbers count lines and are no word of the block, and for a block with neither.
fn block_number(block: &str, from: Dialect) -> Option<String> {
    if from == Dialect::Heidenhain {
        return None;
    }
    let b = block.trim_start();
    let mut b = match b.strip_prefix('/') {
        Some(rest) => rest
            .trim_start_matches(|c: char| c.is_ascii_digit())
            .trim_start(),
        None => b,
    };
    let sinumerik = from == Dialect::Sinumerik;
    let mut parts = Vec::new();
    let number = b
        .strip_prefix(['N', 'n'])
        .or_else(|| b.strip_prefix(':').filter(|_| sinumerik));
    if let Some(rest) = number {
        let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
        let after = rest.get(digits.len()..).and_then(|r| r.chars().next());
        let ends = !after.is_some_and(|c| c.is_ascii_alphanumeric() || c == '.');
        if !digits.is_empty() && ends {
            parts.push(format!("{}{digits}", &b[..1]));
            b = rest[digits.len()..].trim_start();
        }
    }
    if sinumerik {
        // A label: two letters or underscores first, then letters, digits, underscores,
        // and the colon, before a blank or the end.
        let name: String = b
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect();
        let lead = name
            .chars()
            .take(2)
            .all(|c| c.is_ascii_alphabetic() || c == '_');
        let rest = &b[name.len()..];
        let colon = rest.strip_prefix(':').is_some_and(|r| {
            r.is_empty() || r.starts_with(char::is_whitespace) || r.starts_with(';')
        });
        if name.len() >= 2 && lead && colon {
            parts.push(format!("{name}:"));
        }
    }
    (!parts.is_empty()).then(|| parts.join(" "))
}

/// A block of a `from` program split into its code and its comments (`( … )` in the
/// ISO-style dialects and TwinCAT, `;` to the end of the line in all): the code as it
/// stands without them, and the comments' texts joined by a space (`None` without one).
/// SINUMERIK's strings (`"TC1"`) are no comment, whatever they hold.
/// Moves `current` where a block's rotary-axis words send the machine: the letters `A B C`
/// of a motion block (each the machine's axis whose direction is nearest X, Y, Z, as a
/// five-axis program names them), absolute or incremental from where the axes are. `path`
/// holds the reader's modal state (`G91`); its letters are set from `current` first, so an
/// increment adds to the positions the last turn left. Blocks the reader refuses or does
/// not follow (arcs, moves in machine coordinates) move nothing here.
fn moved_to(
    machine: &cncrot::kinematics::Machine,
    path: &mut cncrot::dialects::toolpath::ToolPath,
    dialect: Dialect,
    block: &str,
    current: &mut [f64; MAX_AXES],
) {
    let letters = cncrot::dialects::program::axis_letters(machine);
    let slots = &letters[..machine.axes().len()];
    // Only the rotary letters count here: where the tip is, in which frame and with which
    // offset (which make the reader leave a point unfollowed) moves no rotary axis.
    let mut from = cncrot::dialects::toolpath::ToolPath {
        lost: false,
        framed: false,
        shifted: [false; 3],
        compensated: false,
        altered: false,
        disoriented: false,
        ..*path
    };
    for (k, &slot) in slots.iter().enumerate() {
        from.axes[slot] = current[k];
    }
    let Ok((next, _)) = from.line(dialect, block.as_bytes()) else {
        return;
    };
    if next.axes != from.axes {
        for (k, &slot) in slots.iter().enumerate() {
            current[k] = next.axes[slot];
        }
    }
    *path = next;
}

/// The plane a direct mode's positions (`PLANE AXIAL`, `G158` mode 2, `CYCLE800` direct)
/// give on machine `m`, as a program that states that plane, its choice the side of the
/// master axis the positions take (`SEQ±`, `_DIR ±1`: the master axis' higher or lower angle
/// of the pair), so that a target that turns to a plane turns the machine to those
/// positions; a program without a direct mode as it is. `None`: not on this machine.
fn plane_of_direct(q: &Program, m: &cncrot::kinematics::Machine) -> Option<Program> {
    if q.direct.is_none() {
        return Some(*q);
    }
    let f = q.frame_on(m).ok()?;
    let stated = q.axes(m, [0.0; MAX_AXES]).ok()?.axes;
    // The master axis, as the library takes it for choice words.
    let k = cncrot::dialects::program::master_axis(m);
    let wrap = |x: f64| {
        let r = x.rem_euclid(360.0);
        if r > 180.0 {
            r - 360.0
        } else {
            r
        }
    };
    let mine = wrap(stated.get(k).copied().unwrap_or(0.0));
    let other = m.inverse(&f.rotation).ok().and_then(|s| {
        s.as_slice()
            .iter()
            .filter_map(|x| x.get(k).copied().map(wrap))
            .find(|&x| (x - mine).abs() > 1e-6)
    });
    let choice = match other {
        Some(o) if mine > o => AxisChoice::Plus(0),
        Some(_) => AxisChoice::Minus(0),
        None => q.choice,
    };
    Some(Program {
        frame: f,
        direct: None,
        angles: [0.0; 3],
        dialect: None,
        table_rot: false,
        choice,
        ..*q
    })
}

/// Where a SINUMERIK program's `CYCLE800` and its frame commands meet: the configuration of
/// the control decides what the program does there (one programmable frame that each
/// replaces, as cncrot reads it, or the swivel in system frames that `TRANS`, `ROT` and
/// `CYCLE800()` leave apart).
#[derive(Default)]
struct SinumerikFrames {
    /// A swivel of `CYCLE800` is active.
    swivel: bool,
    /// A frame command left a frame that is not the identity beside the swivel (`TRANS`
    /// before it, `ATRANS` after it).
    programmable: bool,
    /// A `CYCLE800()` that reset the swivel while such a frame was active (its line and
    /// block): the same either way if the next block sets the frame anew (`TRANS X=…`, as
    /// the writers write it), else said at that block.
    reset: Option<(usize, String)>,
}

impl SinumerikFrames {
    /// After block `block` at `line` (its code without comments, the states around it, and
    /// whether it applied): the blocks whose meaning depends on the configuration, with
    /// what depends.
    fn step(
        &mut self,
        line: usize,
        block: &str,
        code: &str,
        (before, after): (&Program, &Program),
        applied: bool,
    ) -> Vec<(usize, String, &'static str)> {
        let upper = code.trim().to_uppercase();
        // The command after what may stand before it: a skip mark (`/`, `/2`), a block
        // number (`N20`, `:20`), a label (`MARK:`), each spelled apart or not.
        let mut rest = upper.as_str();
        loop {
            rest = rest.trim_start();
            let digits =
                |r: &str| r.len() - r.trim_start_matches(|c: char| c.is_ascii_digit()).len();
            if let Some(r) = rest.strip_prefix('/') {
                rest = &r[digits(r)..];
            } else if let Some(r) = rest.strip_prefix(['N', ':']).filter(|r| digits(r) > 0) {
                rest = &r[digits(r)..];
            } else if let Some(at) = rest.find(':').filter(|&at| {
                at >= 2
                    && rest[..at]
                        .bytes()
                        .all(|b| b.is_ascii_alphanumeric() || b == b'_')
            }) {
                rest = &rest[at + 1..];
            } else {
                break;
            }
        }
        let Some(first) = rest.split_whitespace().next() else {
            return Vec::new();
        };
        let command = first.split(['=', '(']).next().unwrap_or("");
        // `CROT` and `CROTS` are read as `ROT` and `ROTS`: they replace too.
        let replaces = matches!(
            command,
            "TRANS" | "ROT" | "CROT" | "ROTS" | "CROTS" | "SCALE" | "MIRROR"
        );
        let mut said = Vec::new();
        const RESET: &str =
            "CYCLE800() after TRANS, ROT or ATRANS, and the blocks after it: the control may keep their frame";
        if let Some((at, b)) = self.reset.take() {
            let end = ["M30", "M2", "M02", "M17", "RET"].contains(&first);
            if !(end || applied && replaces) {
                said.push((at, b, RESET));
            }
        }
        if !applied {
            return said;
        }
        let changed = before.frame != after.frame || before.direct != after.direct;
        let untilted = after.frame == cncrot::Frame::IDENTITY && after.direct.is_none();
        if command == "CYCLE800" {
            let args = cycle800_args(code).map(|a| a.0).unwrap_or_default();
            let reset =
                args.iter().all(|a| a.is_empty()) || args.get(1).is_some_and(|tc| tc == "\"0\"");
            if self.programmable {
                if reset {
                    self.reset = Some((line, block.to_string()));
                } else {
                    said.push((
                        line,
                        block.to_string(),
                        "CYCLE800 after TRANS, ROT or ATRANS: the control may keep their frame apart, after the swivel",
                    ));
                }
                self.programmable = false;
            }
            self.swivel = !reset && !untilted;
        } else if replaces {
            if self.swivel {
                said.push((
                    line,
                    block.to_string(),
                    "TRANS, ROT, ROTS, SCALE or MIRROR while a CYCLE800 swivel is active: the control may keep the swivel",
                ));
                self.swivel = false;
            }
            self.programmable = !untilted;
        } else if changed && matches!(command, "ATRANS" | "AROT" | "AROTS" | "ASCALE" | "AMIRROR") {
            self.programmable = true;
        }
        if untilted && self.reset.is_none() {
            (self.swivel, self.programmable) = (false, false);
        }
        said
    }
}

/// The arguments of the first `CYCLE800(…)` of a SINUMERIK block's code (commas inside
/// quotes kept), and the byte range of the text between its parentheses; `None` without one.
fn cycle800_args(code: &str) -> Option<(Vec<String>, std::ops::Range<usize>)> {
    let at = code.to_uppercase().find("CYCLE800")?;
    let open = at + code.get(at..)?.find('(')?;
    let mut quoted = false;
    let close = code
        .char_indices()
        .skip_while(|&(i, _)| i <= open)
        .find(|&(_, c)| {
            if c == '"' {
                quoted = !quoted;
            }
            c == ')' && !quoted
        })?
        .0;
    let inner = code.get(open + 1..close)?;
    let mut args = vec![String::new()];
    let mut quoted = false;
    for c in inner.chars() {
        match c {
            '"' => {
                quoted = !quoted;
                args.last_mut()?.push(c);
            }
            ',' if !quoted => args.push(String::new()),
            c => args.last_mut()?.push(c),
        }
    }
    Some((
        args.iter().map(|a| a.trim().to_string()).collect(),
        open + 1..close,
    ))
}

/// A `CYCLE800` written for a SINUMERIK source's `CYCLE800`, with the source's own words
/// that name no plane kept: the swivel data set `_TC`, the digits of `_ST` above the units
/// (their coding is not public; the units digit, new or additive, is the writer's) and
/// `_DMODE`. A translation into SINUMERIK from SINUMERIK keeps the data set the program
/// swivels (a machine with a head and a table has two).
fn keep_cycle800_words(source: &str, written: &str) -> String {
    let Some((from, _)) = cycle800_args(source) else {
        return written.to_string();
    };
    let int = |a: &str| a.parse::<i64>().ok();
    written
        .lines()
        .map(|l| {
            let Some((mut args, range)) = cycle800_args(l) else {
                return l.to_string();
            };
            if args.len() < 3 {
                return l.to_string();
            }
            if let Some(tc) = from.get(1).filter(|t| !t.is_empty()) {
                args[1] = tc.clone();
            }
            if let (Some(src), Some(w)) = (from.get(2).and_then(|a| int(a)), int(&args[2])) {
                args[2] = (src / 10 * 10 + w % 10).to_string();
            }
            if let (Some(dm), Some(slot)) =
                (from.get(15).filter(|a| !a.is_empty()), args.get_mut(15))
            {
                *slot = dm.clone();
            }
            format!("{}{}{}", &l[..range.start], args.join(","), &l[range.end..])
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn split_comments(block: &str, from: Dialect) -> (String, Option<String>) {
    let parens = !matches!(from, Dialect::Sinumerik | Dialect::Heidenhain);
    let (mut code, mut found) = (String::new(), Vec::new());
    let mut chars = block.char_indices();
    let mut quoted = false;
    while let Some((at, c)) = chars.next() {
        match c {
            '"' if from == Dialect::Sinumerik => {
                quoted = !quoted;
                code.push(c);
            }
            _ if quoted => code.push(c),
            ';' => {
                found.push(block[at + 1..].to_string());
                break;
            }
            '(' if parens => {
                let text: String = chars
                    .by_ref()
                    .map(|(_, c)| c)
                    .take_while(|&c| c != ')')
                    .collect();
                found.push(text);
                code.push(' ');
            }
            _ => code.push(c),
        }
    }
    let text = found
        .iter()
        .flat_map(|t| t.split_whitespace())
        .collect::<Vec<_>>()
        .join(" ");
    (code, (!text.is_empty()).then_some(text))
}

/// The comments of a block (see [`split_comments`]).
fn comments(block: &str, from: Dialect) -> Option<String> {
    split_comments(block, from).1
}

/// What a translation keeps of a block (its rest), written with the target's comments: a
/// parenthesis is no comment in SINUMERIK or Heidenhain, a `;` ends an ISO block. `None`
/// where nothing is left.
fn kept_in(kept: &str, from: Dialect, to: Dialect) -> Option<String> {
    let parens = |d: Dialect| !matches!(d, Dialect::Sinumerik | Dialect::Heidenhain);
    if parens(from) == parens(to) {
        return Some(kept.to_string());
    }
    let (code, note) = split_comments(kept, from);
    let code = code.split_whitespace().collect::<Vec<_>>().join(" ");
    match (code.is_empty(), note.map(|n| comment_in(&n, to))) {
        (true, note) => note,
        (false, Some(n)) => Some(format!("{code} {n}")),
        (false, None) => Some(code),
    }
}

/// `text` as a comment of `to`'s, to stand at the end of a block: `(TEXT)` where a comment
/// is a parenthesis (the parentheses inside it left out: a Fanuc comment does not nest),
/// `; TEXT` in SINUMERIK and Heidenhain.
fn comment_in(text: &str, to: Dialect) -> String {
    match to {
        Dialect::Sinumerik | Dialect::Heidenhain => format!("; {text}"),
        _ => {
            let text = text.replace(['(', ')'], " ");
            format!(
                "({})",
                text.split_whitespace().collect::<Vec<_>>().join(" ")
            )
        }
    }
}

/// What `program` is asked: the file, its dialect, a translation, the positions before.
pub struct ProgramArgs<'a> {
    pub file: &'a str,
    pub dialect: &'a str,
    pub euler: bool,
    pub axis_angles: bool,
    pub to: Option<&'a str>,
    pub current: Option<&'a str>,
    pub json: bool,
    pub decimals: i32,
    /// Draw every tilt the program applies into this SVG file.
    pub svg: Option<&'a str>,
}

/// The tilt's cancel on a block the library does not follow as a whole (`G69 G54`: a work
/// offset beside it; SINUMERIK's `SCALE X2`, `MIRROR X0`, which replace the programmable
/// frame, its rotation with it), read alone on `p`: a control cancels the plane whatever
/// else the block holds, and the state after it is untilted, whatever the offset, scale or
/// mirror does. The ISO dialects (`G69`, Haas's `G269`) and SINUMERIK (read as `TRANS`,
/// which replaces the frame as they do); `None` where the block holds none.
fn cancel_beside(dialect: Dialect, block: &str, p: &Program) -> Option<(Program, &'static str)> {
    let (words, code): (&[&str], &'static str) = match dialect {
        Dialect::Fanuc | Dialect::Syntec => (&["G69"], "G69"),
        Dialect::Haas => (&["G269"], "G269"),
        // Not `ASCALE`, `AMIRROR` (they add to the frame) nor the frame functions `CSCALE`,
        // `CMIRROR` of a frame variable's value.
        Dialect::Sinumerik => (&["SCALE", "MIRROR"], "TRANS"),
        _ => return None,
    };
    let text = block.split(['(', ';']).next().unwrap_or("").to_uppercase();
    let bytes = text.as_bytes();
    let name = |b: &u8| b.is_ascii_alphanumeric() || *b == b'_';
    let found = words.iter().any(|word| {
        text.match_indices(word).any(|(at, _)| {
            let before = at.checked_sub(1).and_then(|k| bytes.get(k));
            let after = bytes.get(at + word.len());
            !before.is_some_and(|b| name(b) || *b == b'.' || *b == b'$')
                && !after.is_some_and(|b| name(b) || *b == b'.')
        })
    });
    if !found {
        return None;
    }
    match p.line(dialect, code.as_bytes()) {
        Ok((c, Remark::Applied)) => Some((c, code)),
        _ => None,
    }
}

/// The work offsets a block selects (`G54`–`G59`, not `G54.1`), when they are all that is
/// not followed in it (the block read without them is passed over, or a cancel): their
/// numbers. `None` for any other block.
fn work_offsets(dialect: Dialect, block: &str, p: &Program) -> Option<Vec<u32>> {
    if dialect == Dialect::Heidenhain {
        return None;
    }
    let code = block.split(['(', ';']).next().unwrap_or("");
    let comment = &block[code.len()..];
    // Byte by byte (ASCII upper case only: other bytes, in any code page, stay as they are).
    let bytes = code.to_ascii_uppercase().into_bytes();
    let mut found = Vec::new();
    let mut kept: Vec<u8> = Vec::new();
    let mut k = 0;
    while let Some(&b) = bytes.get(k) {
        let starts = b == b'G'
            && !k
                .checked_sub(1)
                .and_then(|j| bytes.get(j))
                .is_some_and(|b| b.is_ascii_alphanumeric() || *b == b'_' || *b == b'$');
        let digits: Vec<u8> = bytes
            .get(k + 1..)
            .unwrap_or(&[])
            .iter()
            .copied()
            .take_while(|c| c.is_ascii_digit() || *c == b'.')
            .collect();
        let number = std::str::from_utf8(&digits)
            .ok()
            .and_then(|d| d.parse::<u32>().ok());
        if let (true, Some(n)) = (starts, number) {
            if (54..=59).contains(&n) {
                found.push(n);
                kept.push(b' ');
                k += 1 + digits.len();
                continue;
            }
        }
        kept.push(b);
        k += 1;
    }
    if found.is_empty() {
        return None;
    }
    let mut kept = String::from_utf8_lossy(&kept).into_owned();
    kept.push_str(comment);
    // Beside nothing else of the frame's, or beside a cancel (`G69 G55`, which the command
    // applies); beside a tilt (`G54 G68.2 …`) the block is more than an offset.
    match p.line(dialect, kept.trim().as_bytes()) {
        Ok((_, Remark::Passed)) => Some(found),
        Ok((_, Remark::Applied)) if cancel_beside(dialect, block, p).is_some() => Some(found),
        _ => None,
    }
}

/// Whether the work offsets `offsets` (`G54`–`G59`) of a `from` program select the same in
/// `to`: `G54`–`G59` among the ISO-style dialects (Fanuc, Haas, Syntec), `G54`–`G57` also in
/// SINUMERIK (settable frames) and TwinCAT (zero offsets from the table), whose `G58`/`G59`
/// are other commands; Heidenhain has none.
fn offsets_same(from: Dialect, to: Dialect, offsets: &[u32]) -> bool {
    let iso = |d: Dialect| matches!(d, Dialect::Fanuc | Dialect::Haas | Dialect::Syntec);
    let table = |d: Dialect| iso(d) || matches!(d, Dialect::Sinumerik | Dialect::Twincat);
    if !(table(from) && table(to)) {
        return false;
    }
    offsets.iter().all(|&n| n <= 57 || (iso(from) && iso(to)))
}

/// A whole part program, block by block (see the command's help). Exit status 1 when a
/// block was refused or (with `--to`) could not be carried across, or was written without a
/// turn, a tip kept in place or a retraction it states.
pub fn program(a: &ProgramArgs, m: &MachineArgs) -> Result<bool, Failure> {
    use std::io::Write;
    let dialect = input::dialect(a.dialect).map_err(option("--dialect"))?;
    let target =
        a.to.map(input::target)
            .transpose()
            .map_err(option("--to"))?;
    let machine = if m.carr.is_some() || !m.axis.is_empty() {
        Some(machine(m)?)
    } else {
        None
    };
    let n = machine.as_ref().map_or(MAX_AXES, |m| m.axes().len());
    let mut current = a
        .current
        .map(|t| positions(t, n, "positions"))
        .transpose()
        .map_err(option("--current"))?
        .unwrap_or([0.0; MAX_AXES]);
    if a.current.is_some() && machine.is_none() {
        return Err(Failure::new(
            "--current needs a machine: --carr FILE or --axis ...",
        ));
    }
    let (text, latin1, bom) = input::read_source_as(a.file)?;
    let d = a.decimals;
    let mut p = Program {
        euler: a.euler && dialect == Dialect::Sinumerik,
        axis_angles: a.axis_angles && dialect == Dialect::Heidenhain,
        ..Program::default()
    };
    let (mut applied, mut passed, mut unfollowed, mut refused) = (0, 0, 0, 0);
    // Blocks read but not written in the target (its form has no words for the change).
    let mut uncarried = 0;
    // The rotary positions the program's motion blocks state (their letters `A B C`, absolute
    // or incremental), read as the five-axis reader reads a motion block.
    let mut rotary = cncrot::dialects::toolpath::ToolPath::default();
    let mut frames = SinumerikFrames::default();
    // The swivel data sets (`_TC`) named so far that the target has no word for.
    let mut data_sets: Vec<String> = Vec::new();
    // Blocks written without a turn, a tip kept in place or a retraction the source has.
    let mut moved_otherwise = 0;
    // A block refused or not followed since the last one that set the frame: the control's tilt is not the
    // state's, and a block that only turns the axes to it (`G53.1`) cannot be carried across.
    let mut lost = false;
    // The lines of a subprogram also called with another frame active, and the call its
    // translation is made from: a block whose text depends on the frame there is not
    // carried across.
    let mut varied: (std::ops::Range<usize>, usize) = (0..0, 0);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let mut ok = true;
    // A translation is a program again: written in the bytes and line ends it came in (a
    // comment in Latin-1 or GBK stays those bytes, CRLF stays CRLF); the report is text.
    let crlf = text.split('\n').next().is_some_and(|l| l.ends_with('\r'));
    let translating = target.is_some();
    let mut mark = bom;
    let mut put = |s: String| {
        if !translating {
            return writeln!(out, "{s}").is_ok();
        }
        if std::mem::take(&mut mark) && out.write_all(b"\xEF\xBB\xBF").is_err() {
            return false;
        }
        let s = if crlf { s.replace('\n', "\r\n") } else { s };
        let bytes: Vec<u8> = if latin1 {
            // Read byte for byte: every char below 256 (what the writers add is ASCII).
            s.chars().map(|c| u8::try_from(c).unwrap_or(b'?')).collect()
        } else {
            s.into_bytes()
        };
        let end: &[u8] = if crlf { b"\r\n" } else { b"\n" };
        out.write_all(&bytes).is_ok() && out.write_all(end).is_ok()
    };
    // The tilts the picture shows: the first few, more would hide each other.
    const MAX_DRAWN: usize = 6;
    let (mut drawn, mut tilts) = (Vec::new(), 0);
    // A cycle's first line (`CYCL DEF 19.0`) in a translation into its own dialect: held
    // until the next block shows whether the cycle is rewritten (the writer writes its own
    // first line) or kept as it stands.
    let mut held: Option<String> = None;
    // Each block's state read ahead, so that a translation sees the next block: blocks
    // that are one command spread over lines (cycle 7's axis lines, a tilt and its turn)
    // are written as one change at the last of them; `run` holds the state before the
    // first.
    let ahead: Vec<Option<Program>> = if target.is_some() {
        let mut q = p;
        let mut calls = labels::Labels::new(dialect, &text);
        text.lines()
            .enumerate()
            .map(|(k, raw)| {
                calls.enter(k, &mut q);
                let raw = raw.trim_end_matches('\r');
                let resolved = calls.params().resolve(raw, &q, k);
                let source = resolved.as_ref().map_or(raw, |(t, _)| t.as_str());
                match q.line(dialect, source.as_bytes()) {
                    Ok((next, Remark::Applied)) => {
                        q = next;
                        Some(next)
                    }
                    Ok((_, Remark::Passed)) => {
                        calls.after(k, &mut q);
                        None
                    }
                    Ok((_, Remark::NotFollowed)) => {
                        if let Some((c, _)) = cancel_beside(dialect, source, &q) {
                            q = c;
                        }
                        None
                    }
                    _ => None,
                }
            })
            .collect()
    } else {
        Vec::new()
    };
    // Heidenhain's `CALL LBL`: followed through the label (the state after the call is the
    // one its blocks leave), and a subprogram standing after its calls read from the state
    // of one of them (`Labels::enter`).
    let mut calls = labels::Labels::new(dialect, &text);
    let mut run: Option<Program> = None;
    // The blocks of that run as written so far (their block number or other words, or
    // nothing) and as they stand: held until the run is written, so that a run the target
    // cannot write keeps all its blocks as they stand, not only its last.
    let mut pending: Vec<(Option<String>, String)> = Vec::new();
    // The first block of the run that adds to the datum shift (`CYCL DEF 7.1 IX+10`,
    // `ATRANS`): its line and text.
    let mut adds: Option<(usize, String)> = None;
    // The last block inside a loop that adds to the frame, since the frame was last set
    // whole.
    let mut looped_adds: Option<usize> = None;
    let lines: Vec<&str> = text.lines().map(|l| l.trim_end_matches('\r')).collect();
    let text_upper = text.to_uppercase();
    let mut g58_said = false;
    // The line of an optional block (`/G52 X10.`) that set the datum shift still in force: a
    // target that writes the shift into its tilt blocks (cycle 7 with a `PLANE`'s origin,
    // `CYCLE800`'s origin words, TwinCAT's `G58` with `ROT`'s) would write it into blocks
    // that are not optional.
    let mut optional_shift: Option<usize> = None;
    // A TwinCAT program's `G58` shifts only under a zero offset `G54`–`G57`; with none
    // selected in the program, the default `G53` leaves it without effect (Beckhoff: "since
    // zero-offset-shifts are still disabled (default G53), the PCS and MCS match"). cncrot
    // reads the shift (a control may have kept a zero offset from before): said once, on its
    // line (check on the control).
    if dialect == Dialect::Twincat && !selects_g54_to_g57(&text_upper) {
        let g58 = lines
            .iter()
            .position(|l| iso_word(&split_comments(l, dialect).0.to_uppercase(), "G58"));
        if let Some(k) = g58 {
            eprintln!(
                "cncrot: line {}: G58 shifts only while a zero offset G54 to G57 is active, and the program selects none (G53, the default, deactivates them): cncrot reads the shift; check on the control: {}",
                k + 1,
                lines[k]
            );
        }
    }
    for (k, raw) in text.lines().enumerate() {
        let mut rewritten = false;
        let line = k + 1;
        let block = raw.trim_end_matches('\r');
        let entered = calls.enter(k, &mut p);
        if let (Some(t), Some((from, others))) = (&target, &entered) {
            if !others.is_empty() && !calls.only_resets(k, &p) {
                varied = (calls.body_of(k), *from);
            }
            if !others.is_empty() {
                let lines: Vec<String> = others.iter().map(|l| (l + 1).to_string()).collect();
                eprintln!(
                    "cncrot: line {line}: the subprogram is also called with another frame active ({} {}): its blocks are translated into {} once, from the frame of the call at line {}{}: {block}",
                    if lines.len() == 1 { "line" } else { "lines" },
                    lines.join(", "),
                    input::dialect_name(t.dialect),
                    from + 1,
                    if p.frame.rotation != cncrot::IDENTITY || p.direct.is_some() {
                        " without its turn"
                    } else {
                        ""
                    }
                );
            }
        }
        // A block that uses parameters the program sets once: read with their values
        // (written so in a translation), said on standard error.
        let resolved = calls.params().resolve(block, &p, k);
        if let Some((_, used)) = &resolved {
            eprintln!("cncrot: line {line}: read with {used}: {block}");
        }
        let source = resolved.as_ref().map_or(block, |(t, _)| t.as_str());
        // A block that moves the rotary axes (`G0 A30. C180.`, `L A+30 C+180 FMAX`): the
        // next turn is chosen from where it left them.
        if let Some(m) = &machine {
            moved_to(m, &mut rotary, dialect, source, &mut current);
        }
        let (next, remark) = match p.line(dialect, source.as_bytes()) {
            Ok(r) => r,
            Err(e) => {
                refused += 1;
                lost = true;
                ok = false;
                let message = input::block_message(block, &e);
                let why = format!("line {line}, column {}: {message}", e.column);
                eprintln!("cncrot: {why}");
                let row = match (&target, a.json) {
                    (Some(_), _) => block.to_string(),
                    (None, true) => Json::Obj(vec![
                        ("line", Json::Int(line as i64)),
                        ("error", Json::str(message)),
                        ("column", Json::Int(e.column as i64)),
                    ])
                    .text(),
                    (None, false) => format!("line {line}: error: column {}: {message}", e.column),
                };
                if held.take().is_some_and(|h| !put(h)) || !put(row) {
                    return Ok(ok);
                }
                continue;
            }
        };
        let before = p;
        p = next;
        let mut remark = remark;
        if dialect == Dialect::Sinumerik {
            let code = split_comments(block, dialect).0;
            let applied = remark == Remark::Applied;
            for (at, b, what) in frames.step(line, block, &code, (&before, &p), applied) {
                eprintln!(
                    "cncrot: line {at}: {what}: where CYCLE800 keeps its swivel in system frames ($P_WPFRAME, $P_TOOLFRAME: machine data 28082 bits 3 and 4, which SINUMERIK Operate's swivelling asks for) and TRANS, ROT, ATRANS write the programmable frame, each keeps the other; cncrot reads one frame that each replaces [choice]{}: {b}",
                    if target.is_some() { ": not carried across" } else { ": check on the control" }
                );
                if target.is_some() {
                    (ok, uncarried) = (false, uncarried + 1);
                }
            }
        }
        // A block that changes the frame each time it runs (`AROT Z90`, `G68.4`, `PLANE
        // RELATIV`, `ATRANS`: applied again, it is not where it was) inside a loop: the
        // control runs it as often as the loop's condition says, cncrot once. The frame
        // after it is followed for one pass: said once per loop; in a translation a later
        // block that adds to that frame is not carried across.
        if remark == Remark::Applied {
            let again = p.line(dialect, source.as_bytes()).map(|r| r.0);
            let adds_each_time = again.is_ok_and(|q| q != p);
            if adds_each_time && calls.looped(k) {
                if looped_adds.is_none() {
                    eprintln!(
                        "cncrot: line {line}: the block adds to the frame and stands in a loop, which the control runs as often as its condition says: cncrot follows one pass, so the frame after it is not the control's{}: {block}",
                        if target.is_some() { " (a block after it that adds to the frame: not carried across)" } else { ": check on the control" }
                    );
                }
                looped_adds = Some(line);
            } else if !adds_each_time {
                // A frame set whole (`ROT`, `G68.2`, a cancel): the control's again.
                looped_adds = None;
            } else if let (Some(_), Some(at)) = (&target, looped_adds) {
                // Written as an increment it would be right, as the frame it reaches (a
                // datum shift, a target without the increment) not: not told apart here.
                eprintln!(
                    "cncrot: line {line}: the block adds to a frame that a loop above (line {at}) changed as often as it ran, which cncrot followed for one pass: not carried across: {block}"
                );
                (ok, uncarried) = (false, uncarried + 1);
            }
        }
        if remark == Remark::Passed {
            match calls.after(k, &mut p) {
                Some(labels::Called::Elsewhere(name)) => eprintln!(
                    "cncrot: line {line}: calls {name}, which is not in this file: its blocks are not followed (the frame after the call is the one before it): {block}"
                ),
                Some(labels::Called::Above(at)) => {
                    eprintln!(
                        "cncrot: line {line}: calls the subprogram at line {}, which stands above and was read{} from the frame there, not this call's{}: {block}",
                        at + 1,
                        if target.is_some() { " and translated" } else { "" },
                        if target.is_some() { ": not carried across" } else { "" }
                    );
                    if target.is_some() {
                        (ok, uncarried) = (false, uncarried + 1);
                    }
                }
                Some(labels::Called::Cut(cut)) => {
                    let why = match cut {
                        labels::Cut::Budget => format!(
                            "change the frame in every pass for more than {} blocks",
                            labels::BUDGET
                        ),
                        labels::Cut::Depth => {
                            format!("nest more than {} calls deep", labels::DEPTH)
                        }
                    };
                    eprintln!(
                        "cncrot: line {line}: the calls from here {why}: followed that far, so the frame after them is not the control's{}: {block}",
                        if target.is_some() { ": not carried across" } else { "" }
                    );
                    if target.is_some() {
                        (ok, uncarried) = (false, uncarried + 1);
                    }
                }
                None => {}
            }
            // A call that changes the frame (`CALL LBL 1 ; RESET WORKING PLANE`) has its row
            // in the report, as the blocks that change it have: the state after the call.
            // (A translation copies the call: the label's blocks are translated where they
            // stand.)
            if target.is_none() && p != before {
                remark = Remark::Applied;
            }
        }
        // Whether this block is written with the next one, and whether the run it ends could
        // not be written.
        let (mut deferred, mut run_failed) = (false, false);
        let row = match remark {
            Remark::Passed => {
                passed += 1;
                // An ISO `G53` moves in machine coordinates for its block only; TwinCAT's
                // `G53` switches every zero offset off until one is selected again ("G53 …
                // deactivate any zero offset shift translation", Beckhoff's manual): copied
                // as it stands it would move the rest of the program.
                if let Some(t) = target.as_ref().filter(|t| {
                    t.dialect == Dialect::Twincat
                        && dialect != Dialect::Twincat
                        && iso_word(&split_comments(block, dialect).0.to_uppercase(), "G53")
                }) {
                    (ok, uncarried) = (false, uncarried + 1);
                    eprintln!(
                        "cncrot: line {line}: not carried across as {} {}: the machine-coordinate move G53 holds for its block only here, but in TwinCAT G53 switches the zero offsets off until G54 to G59 selects one again: write the move and the offset selection after it for the control: {block}",
                        input::dialect_name(t.dialect),
                        t.form
                    );
                }
                target.as_ref().map(|_| block.to_string())
            }
            Remark::NotFollowed => {
                unfollowed += 1;
                // A cancel beside what is not followed (`G69 G54`) still cancels.
                let cancel = cancel_beside(dialect, source, &before);
                let why = if cancel.is_some() {
                    "changes the frame in a way cncrot does not follow; its cancel is applied"
                } else {
                    "changes the frame in a way cncrot does not follow; cncrot's frame stays as it was"
                };
                let why = format!("it {why}");
                // A work offset alone (`G54`): the tilt stays the control's; copied into a
                // target where it selects the same, it is carried across.
                let offsets = work_offsets(dialect, source, &before);
                let same = match (&offsets, &target) {
                    (Some(o), Some(t)) => offsets_same(dialect, t.dialect, o),
                    _ => false,
                };
                // The control's tilt is no longer the state's, unless the cancel beside sets
                // it again: a turn to the plane after it (`G53.1` after `G68.2 P3`) is not
                // carried across.
                lost = cancel.is_none() && offsets.is_none();
                if let Some((c, _)) = cancel {
                    p = c;
                    run = None;
                }
                if let (Some(t), Some((c, code))) = (&target, cancel) {
                    ok &= same;
                    let mut buf = [0u8; MAX_CHANGE];
                    let written = write_block(
                        t.dialect,
                        t.form.as_bytes(),
                        &before,
                        &c,
                        code.as_bytes(),
                        d,
                        &mut buf,
                    );
                    let mut rest_buf = [0u8; MAX_CHANGE];
                    // (SINUMERIK's rest is empty: its frame commands stand alone; the block
                    // beside the cancel, `SCALE X2`, is all there is to keep.)
                    let kept = match rest(dialect, source.as_bytes(), &mut rest_buf) {
                        Ok(_) if dialect == Dialect::Sinumerik => {
                            kept_in(block, dialect, t.dialect).unwrap_or_default()
                        }
                        Ok(n) => {
                            kept_in(&String::from_utf8_lossy(&rest_buf[..n]), dialect, t.dialect)
                                .unwrap_or_default()
                        }
                        Err(_) => block.to_string(),
                    };
                    match written {
                        Ok((len, _)) => {
                            let (what, why) = if same {
                                ("a work offset", "it selects the same there")
                            } else {
                                ("not followed", why.as_str())
                            };
                            eprintln!(
                                "cncrot: line {line}: {what} beside its cancel: the rest copied as it stands, the cancel written as {} {}'s ({why}): {block}",
                                input::dialect_name(t.dialect),
                                t.form
                            );
                            let mark = skip_mark(block, dialect, t.dialect);
                            let text = String::from_utf8_lossy(&buf[..len]);
                            Some(
                                std::iter::once(kept)
                                    .filter(|k| !k.is_empty())
                                    .chain(text.lines().map(|l| format!("{mark}{l}")))
                                    .collect::<Vec<_>>()
                                    .join("\n"),
                            )
                        }
                        Err(e) => {
                            uncarried += 1;
                            not_carried(line, t, e, block);
                            Some(block.to_string())
                        }
                    }
                } else if let (Some(t), true) = (&target, same) {
                    eprintln!(
                        "cncrot: line {line}: a work offset, copied as it stands: it selects the same in {}: {block}",
                        input::dialect_name(t.dialect)
                    );
                    Some(block.to_string())
                } else if target.is_some() {
                    eprintln!(
                        "cncrot: line {line}: not followed, copied as it stands ({why}): {block}"
                    );
                    ok = false;
                    Some(block.to_string())
                } else if a.json {
                    Some(
                        Json::Obj(vec![
                            ("line", Json::Int(line as i64)),
                            ("block", Json::str(block)),
                            ("remark", Json::str("not followed")),
                        ])
                        .text(),
                    )
                } else {
                    Some(format!("line {line}: not followed: {block}\n  ({why})"))
                }
            }
            Remark::Applied => {
                applied += 1;
                // A direct mode's frame needs the machine.
                let on_machine = match (p.direct, &machine) {
                    (None, _) => Some(Ok(p.frame)),
                    (Some(_), Some(m)) => Some(p.frame_on(m)),
                    (Some(_), None) => None,
                };
                let f = match on_machine {
                    Some(Ok(f)) => f,
                    _ => Frame::IDENTITY,
                };
                if f != Frame::IDENTITY {
                    tilts += 1;
                    if drawn.len() < MAX_DRAWN {
                        drawn.push(svg::Plane {
                            frame: f,
                            label: format!("line {line}"),
                        });
                    }
                }
                let next = ahead.get(k + 1).copied().flatten();
                // Blocks joined into one command share one skip mark: a block skipped
                // alone (`/N20 G68.2 …` before `N30 G53.1`) is written alone.
                let same_mark = lines.get(k + 1).is_some_and(|n| {
                    skip_mark(n, dialect, dialect) == skip_mark(block, dialect, dialect)
                });
                // A turn to the plane and nothing else (a cancel, which moves nothing, sets the
                // frame again: the state is the control's once more).
                let turns_only = p.positioning != Positioning::Stay
                    && p != before
                    && (p.frame, p.shift, p.direct) == (before.frame, before.shift, before.direct);
                lost &= turns_only;
                if let (Some(t), true) = (&target, lost) {
                    // Written as a turn it would turn the axes to the state's plane, not to
                    // the refused one the control has: the block as it stands, flagged.
                    uncarried += 1;
                    ok = false;
                    eprintln!(
                        "cncrot: line {line}: not carried across as {} {}: it moves the machine to a tilt refused or not followed above: {block}",
                        input::dialect_name(t.dialect),
                        t.form
                    );
                    Some(block.to_string())
                } else if let Some(t) = &target {
                    let mut buf = [0u8; MAX_CHANGE];
                    // What the block holds besides the frame's words, kept as it stands.
                    let kept = {
                        let mut rest_buf = [0u8; MAX_CHANGE];
                        match rest(dialect, source.as_bytes(), &mut rest_buf) {
                            Ok(n) if n > 0 => kept_in(
                                &String::from_utf8_lossy(&rest_buf[..n]),
                                dialect,
                                t.dialect,
                            ),
                            _ => None,
                        }
                    };
                    let number = match (&kept, t.dialect) {
                        (None, to) if to != Dialect::Heidenhain => block_number(block, dialect),
                        _ => None,
                    };
                    // The block's comment (`(TILT FRONT)`, `; ORIENT TOOL`), which the
                    // rest leaves out, in the target's own form on the block written for it.
                    // (Kept already where the rest holds it: `N50 G90 (TILT)`.)
                    let note = comments(block, dialect)
                        .filter(|_| {
                            kept.as_ref()
                                .map_or(true, |k| comments(k, dialect).is_none())
                        })
                        .map(|c| comment_in(&c, t.dialect));
                    // A block that moves the datum and turns nothing, and read again moves it
                    // again: it adds to the datum shift.
                    let origin = |q: &Program| (q.shift, q.frame.translation);
                    let adds_here = (origin(&p) != origin(&before)
                        && p.frame.rotation == before.frame.rotation
                        && matches!(p.line(dialect, source.as_bytes()),
                            Ok((q, Remark::Applied)) if origin(&q) != origin(&p)))
                    .then(|| (line, block.to_string()));
                    // Into another dialect also what the block restates (a cancel, a
                    // datum shift, with nothing active: the control may have something
                    // active); in its own, such a block stays as it stands.
                    let written = if t.dialect == dialect
                        && (p.frame.rotation, p.direct) == (before.frame.rotation, before.direct)
                    {
                        // In its own dialect a block that leaves the tilt as it is (a datum
                        // shift, cycle 7's lines, a turn to the plane `L B+Q121 C+Q122 R0 FMAX
                        // M126`, `G53.1`) stays as it stands, with all its words.
                        Ok((0, false))
                    } else if t.dialect == dialect {
                        // What changes is written as `write_block` writes it (a datum shift
                        // under a tilt does not turn the axes again).
                        let form = t.form.as_bytes();
                        match write_change(t.dialect, form, &before, &p, d, &mut buf) {
                            Ok((0, s)) => Ok((0, s)),
                            _ => write_block(
                                t.dialect,
                                form,
                                &before,
                                &p,
                                source.as_bytes(),
                                d,
                                &mut buf,
                            ),
                        }
                    } else if next.is_some_and(|n| joins(&before, &p, &n)) && !same_mark {
                        // Written alone: the next block's command, written as one, then says
                        // this block's part again whether it was skipped or not.
                        eprintln!(
                            "cncrot: line {line}: the target writes this block and the next as one command, and only one of them is optional (/): written apart, the second says the first's part again: not carried across: {block}"
                        );
                        (ok, uncarried) = (false, uncarried + 1);
                        let from = run.take().unwrap_or(before);
                        write_block(
                            t.dialect,
                            t.form.as_bytes(),
                            &from,
                            &p,
                            source.as_bytes(),
                            d,
                            &mut buf,
                        )
                    } else if next.is_some_and(|n| joins(&before, &p, &n)) {
                        // Written with the next block.
                        deferred = true;
                        run = run.or(Some(before));
                        adds = adds.take().or(adds_here);
                        Ok((0, false))
                    } else {
                        let from = run.take().unwrap_or(before);
                        let adds = adds.take().or(adds_here);
                        let text = source.as_bytes();
                        let form = t.form.as_bytes();
                        let w = write_block(t.dialect, form, &from, &p, text, d, &mut buf);
                        // A direct mode (rotary positions: `G158 P10200`, `CYCLE800` direct,
                        // `PLANE AXIAL`) into a target without one: with the machine given,
                        // the plane its positions give there.
                        let direct = from.direct.is_some() || p.direct.is_some();
                        let planes = machine.as_ref().filter(|_| direct).and_then(|m| {
                            Some((plane_of_direct(&from, m)?, plane_of_direct(&p, m)?))
                        });
                        let w = match (w, planes) {
                            (Err(Error::NotAvailable), Some((a, b))) => {
                                let r = write_block(t.dialect, form, &a, &b, text, d, &mut buf);
                                if r.is_ok() && p.direct.is_some() {
                                    eprintln!(
                                        "cncrot: line {line}: the rotary positions written as the plane they give on the machine described (--carr, --axis), with the side of its master axis they take: {block}"
                                    );
                                }
                                r
                            }
                            (w, _) => w,
                        };
                        // What the target cannot say of the block is judged on what was
                        // written: for rotary positions, the plane they give.
                        let (from, p) = match planes {
                            Some(both) if w.is_ok() => both,
                            _ => (from, p),
                        };
                        // A choice the target has no word for: the same text with the
                        // opposite choice.
                        let opposite = match p.choice {
                            AxisChoice::Minus(k) => Some(AxisChoice::Plus(k)),
                            AxisChoice::Plus(k) => Some(AxisChoice::Minus(k)),
                            AxisChoice::PositiveTurn(k) => Some(AxisChoice::NegativeTurn(k)),
                            AxisChoice::NegativeTurn(k) => Some(AxisChoice::PositiveTurn(k)),
                            AxisChoice::Closest => None,
                        };
                        // Whether the target writes the same text for `q` as for the
                        // block's state: what differs between them has no word there.
                        let unsaid = |q: &Program| {
                            let mut other = [0u8; MAX_CHANGE];
                            w.is_ok_and(|(len, _)| {
                                write_block(t.dialect, form, &from, q, text, d, &mut other)
                                    .is_ok_and(|(n, _)| other.get(..n) == buf.get(..len))
                            })
                        };
                        // Whether the target's tilt, written from no tilt, is the same text
                        // for `q` as for the block's state: a way of moving it has no word for
                        // (compared so, not after this block's state before, where the writer
                        // may write the turn alone for one and the plane again for the other).
                        let same_from_untilted = |one: &Program, two: &Program| {
                            let (mut a, mut b) = ([0u8; MAX_CHANGE], [0u8; MAX_CHANGE]);
                            let untilted = Program::default();
                            let one = write_change(t.dialect, form, &untilted, one, d, &mut a);
                            let two = write_change(t.dialect, form, &untilted, two, d, &mut b);
                            match (one, two) {
                                (Ok((n, _)), Ok((m, _))) => a.get(..n) == b.get(..m),
                                _ => false,
                            }
                        };
                        let unsaid_moving = |q: &Program| same_from_untilted(&p, q);
                        let written = w.is_ok_and(|(len, _)| len > 0);
                        // What the target has no word for, and what follows from it.
                        let target_name = format!("{} {}", input::dialect_name(t.dialect), t.form);
                        let say = |what: &str, then: &str| {
                            eprintln!(
                                "cncrot: line {line}: {what} has no word in {target_name}: {then}: {block}"
                            );
                        };
                        // Whether the rotary axes turn at this block: a way of moving stated,
                        // or another tilt under the one kept (a datum shift under a tilt
                        // turns nothing).
                        let staying = from.staying();
                        let turns = from.positioning != p.positioning
                            || (from.frame.rotation, from.direct) != (p.frame.rotation, p.direct)
                            // The same swivel again (a tool change's): it turns again.
                            || matches!(staying.line(dialect, text),
                                Ok((q, Remark::Applied)) if q.positioning != Positioning::Stay);
                        if let Some(choice) = opposite {
                            if written && turns && unsaid_moving(&Program { choice, ..p }) {
                                say(
                                    &format!("the choice of solution ({})", choice_name(p.choice)),
                                    "the control chooses by its own rule",
                                );
                            }
                        }
                        // `TABLE ROT` (a rotary table parallel to the tool makes the turn about
                        // it) the target has no word for: its control turns the coordinates. A
                        // choice of positions for the same plane, as `SEQ`: named, not counted.
                        let coord = Program {
                            table_rot: false,
                            ..p
                        };
                        let table_lost = p.table_rot && turns && unsaid_moving(&coord);
                        if table_lost {
                            say(
                                "TABLE ROT (the rotary table making the turn about the tool)",
                                "not written: the control turns the coordinates instead (COORD ROT), the table staying",
                            );
                        }
                        // A turn of the rotary axes to the plane the target has no word for
                        // (`ROT`, `G158`): the same text as staying where they are.
                        let still = p.staying();
                        // A turn home (the untilted plane, `PLANE RESET TURN`): written from no
                        // tilt it is no tilt either way; lost where the target says no turn
                        // at all (the same text for a tilt that turns and one that stays).
                        let home = p.frame.rotation == cncrot::IDENTITY && p.direct.is_none();
                        let says_no_turn = || {
                            let f = Dialect::Fanuc;
                            let probe = Program::default()
                                .line(f, b"G68.2 X0 Y0 Z0 I0 J30 K0")
                                .and_then(|(q, _)| q.line(f, b"G53.1"));
                            probe.is_ok_and(|(q, _)| same_from_untilted(&q, &q.staying()))
                        };
                        let turn_lost = p.positioning != Positioning::Stay
                            && turns
                            && (unsaid_moving(&still) || (home && says_no_turn()));
                        if turn_lost {
                            say(
                                "the turn of the rotary axes to the plane",
                                "not written: the rotary axes stay where they are until the program moves them",
                            );
                        }
                        // A turn that keeps the tool tip in place (`MOVE`, `G53.6`) the target
                        // says only as a turn about the pivot (`G253`): the linear axes stay.
                        let pivot = Program {
                            positioning: Positioning::Turn,
                            ..p
                        };
                        let tip_lost = !turn_lost
                            && p.positioning == Positioning::Move
                            && turns
                            && unsaid_moving(&pivot);
                        if tip_lost {
                            say(
                                "the turn that keeps the tool tip in place (the linear axes following)",
                                "written as a turn about the pivot, the linear axes staying",
                            );
                        }
                        // The feed of the turn (`F2000`, `_FR`'s feed) the target has no word
                        // for: the control turns at its own rate.
                        let rapid = Program {
                            feed: Feed::Rapid,
                            feed_mm_min: 0.0,
                            ..p
                        };
                        if !turn_lost && p.feed != Feed::Rapid && turns && unsaid_moving(&rapid) {
                            let how = match p.feed {
                                Feed::Rate => format!("F{}", p.feed_mm_min),
                                _ => "the feed programmed before".to_string(),
                            };
                            say(
                                &format!("the feed of the turn ({how})"),
                                "not written: the control turns at its own rate",
                            );
                        }
                        // A retraction before the axes turn the target has no word for
                        // (`MB`, `_FR` into `G53.1`, `G253`): the same text without it.
                        let dry = Program {
                            retract: Retract::None,
                            retract_mm: 0.0,
                            ..p
                        };
                        let retract_lost =
                            p.retract != Retract::None && turns && unsaid_moving(&dry);
                        // Heidenhain's `DIST n` (`ABST n`): `MOVE` turns about a point n mm
                        // from the tool tip, which no other control's words say (`G53.6`
                        // keeps the tip itself): read, not kept, named here and counted (the
                        // tip moves otherwise).
                        let dist = (dialect == Dialect::Heidenhain
                            && t.dialect != Dialect::Heidenhain
                            && p.positioning == Positioning::Move)
                            .then(|| {
                                let code = block.split(';').next().unwrap_or("").to_uppercase();
                                let words: Vec<&str> = code.split_whitespace().collect();
                                words.iter().enumerate().find_map(|(k, w)| {
                                    let v = ["DIST", "ABST"]
                                        .iter()
                                        .find_map(|d| w.strip_prefix(d))
                                        .map(|v| match v {
                                            "" => words.get(k + 1).copied().unwrap_or(""),
                                            v => v,
                                        })?;
                                    v.trim_start_matches('+').parse::<f64>().ok()
                                })
                            })
                            .flatten()
                            .filter(|d| *d != 0.0);
                        let dist_lost = dist.is_some() && written && turns;
                        if let (Some(d), true) = (dist, dist_lost) {
                            // What is written instead: the tip kept (`G53.6`), or where the
                            // target has no such turn either, the turn about the pivot.
                            let then = if tip_lost || turn_lost {
                                "not written: the target's turn keeps no point of the tool in place"
                            } else {
                                "written as the turn that keeps the tool tip itself in place"
                            };
                            say(
                                &format!("the turn about a point {d} mm from the tool tip (DIST)"),
                                then,
                            );
                        }
                        // A retraction along the machine's Z (`_FR` 1, 2) the target writes as
                        // one along the tool (Heidenhain's `MB MAX`): from a tilted tool along
                        // another line (and `_FR` 2's X and Y left out): named and counted.
                        let along_tool = Program {
                            retract: Retract::ToolMax,
                            retract_mm: 0.0,
                            ..p
                        };
                        let machine_z =
                            matches!(p.retract, Retract::MachineZ | Retract::MachineZThenXy);
                        let retract_line =
                            machine_z && !retract_lost && turns && unsaid_moving(&along_tool);
                        if retract_line {
                            let what = if p.retract == Retract::MachineZ {
                                "the retraction along the machine's Z before the rotary axes turn"
                            } else {
                                "the retraction along the machine's Z, then X and Y, before the rotary axes turn"
                            };
                            say(
                                what,
                                "written as one along the tool axis, as far as the travel allows: the same line only while the tool is vertical",
                            );
                        }
                        // What moves the machine otherwise than the source: counted, and the
                        // exit status 1 (a batch run sees it).
                        if turn_lost || tip_lost || retract_lost || dist_lost || retract_line {
                            moved_otherwise += 1;
                            ok = false;
                        }
                        if retract_lost {
                            let how = match p.retract {
                                Retract::ToolMax => {
                                    "along the tool, as far as the travel allows".to_string()
                                }
                                Retract::Tool => format!("{} mm along the tool", p.retract_mm),
                                Retract::MachineZ => "along the machine's Z".to_string(),
                                _ => "along the machine's Z, then X and Y".to_string(),
                            };
                            say(
                                &format!("the retraction before the rotary axes turn ({how})"),
                                "not written: retract the tool before this block",
                            );
                        }
                        // Heidenhain's way for the rotary axes from now on, beside a turn
                        // to the plane (`L A+Q120 C+Q122 R0 FMAX M126`): a machine parameter
                        // elsewhere, no word of the block written for it.
                        let rotary_m = (dialect == Dialect::Heidenhain)
                            .then(|| {
                                let code = block.split(';').next().unwrap_or("").to_uppercase();
                                let words = code.split_whitespace().collect::<Vec<_>>();
                                ["M126", "M127"].into_iter().find(|m| words.contains(m))
                            })
                            .flatten();
                        if let (Some(m), true) = (rotary_m, written) {
                            let how = if m == "M126" {
                                "take"
                            } else {
                                "no longer take"
                            };
                            say(
                                &format!(
                                    "{m} (the rotary axes {how} the shortest way from now on)"
                                ),
                                "not written",
                            );
                        }
                        // An increment the target cannot say: the same text as the plane
                        // it reaches (a block that moves the datum alone under such a tilt
                        // adds nothing to it).
                        let whole = Program {
                            relative: false,
                            ..p
                        };
                        // The target wrote the block's increment (`G68.4 X20.` for `ATRANS
                        // X20` under a `CYCLE800`): it adds as often as the source.
                        let incremental = p.relative && !unsaid(&whole);
                        // Every target's datum shift is the shift reached (`G52`, `TRANS`,
                        // `CYCL DEF 7` with absolute axes).
                        // Run more than once through the program's calls (a section
                        // repeated, a subprogram called again): the target's runs after the
                        // first do not add, and the program is not carried across.
                        let repeated = |line: usize| {
                            let k = line.saturating_sub(1);
                            match (calls.repeated(k), calls.looped(k)) {
                                (Some(n), _) => {
                                    format!(" (the program runs it {n} times: not carried across)")
                                }
                                (None, true) => {
                                    " (the program repeats it in a loop: not carried across)"
                                        .to_string()
                                }
                                (None, false) => String::new(),
                            }
                        };
                        if let (Some((line, block)), true, false) = (adds, written, incremental) {
                            let again = repeated(line);
                            if !again.is_empty() {
                                (ok, uncarried) = (false, uncarried + 1);
                            }
                            eprintln!(
                                "cncrot: line {line}: the block adds to the active datum shift and is written as the shift it reaches in {} {}, so a loop that repeats the block does not add{again}: {block}",
                                input::dialect_name(t.dialect),
                                t.form
                            );
                        }
                        // In a subprogram also called with another frame active: a block
                        // written for the frame of one call (a datum shift under its tilt,
                        // written with the tilt again; an increment written as the plane it
                        // reaches) is wrong for the others.
                        let tilted_before =
                            from.frame.rotation != cncrot::IDENTITY || from.direct.is_some();
                        let shift_under_tilt = tilted_before
                            && (p.frame.rotation, p.direct) == (from.frame.rotation, from.direct)
                            && p.shift != from.shift;
                        let absolute = p.relative && !incremental;
                        // A shift under the tilt in lines the program runs again after an
                        // increment among them (a side per pass): written with the first
                        // pass's tilt, wrong for the others.
                        let passes_turn = calls.repeated_lines(line - 1).iter().any(|r| {
                            r.clone().any(|i| {
                                ahead.get(i).copied().flatten().is_some_and(|q| q.relative)
                            })
                        });
                        if shift_under_tilt && written && passes_turn {
                            (ok, uncarried) = (false, uncarried + 1);
                            eprintln!(
                                "cncrot: line {line}: not carried across as {} {}: the program runs it again after an increment of the tilt, and it is written with the tilt of its first pass: {block}",
                                input::dialect_name(t.dialect),
                                t.form
                            );
                        }
                        if varied.0.contains(&(line - 1))
                            && written
                            && (shift_under_tilt || absolute)
                        {
                            (ok, uncarried) = (false, uncarried + 1);
                            eprintln!(
                                "cncrot: line {line}: not carried across as {} {}: written for the frame of the call at line {}, the subprogram is also called with another frame active: {block}",
                                input::dialect_name(t.dialect),
                                t.form,
                                varied.1 + 1
                            );
                        }
                        let turned = p.frame.rotation != from.frame.rotation;
                        if p.relative && turned && written && unsaid(&whole) {
                            let again = repeated(line);
                            if !again.is_empty() {
                                (ok, uncarried) = (false, uncarried + 1);
                            }
                            eprintln!(
                                "cncrot: line {line}: the block adds to the active tilt and {} {} cannot say this increment: written as the plane it reaches, so a loop that repeats the block does not add{again}: {block}",
                                input::dialect_name(t.dialect),
                                t.form
                            );
                        }
                        w
                    };
                    match written {
                        Ok((0, _))
                            if t.dialect == dialect
                                && dialect == Dialect::Heidenhain
                                && cycle_head(block.as_bytes()) =>
                        {
                            held = Some(block.to_string());
                            None
                        }
                        // A cycle's first line (`CYCL DEF 19.0`, `7.0`), written with its
                        // other lines: held with them, kept as it stands if they cannot be
                        // written.
                        Ok((0, _))
                            if t.dialect != dialect
                                && dialect == Dialect::Heidenhain
                                && cycle_head(block.as_bytes())
                                && kept.is_none()
                                && note.is_none() =>
                        {
                            deferred = true;
                            None
                        }
                        // The same dialect, or a plane selected (`G18`, perhaps with a
                        // move): the block as it stands (no writer says a plane).
                        Ok((0, _)) if t.dialect == dialect || before.plane != p.plane => {
                            Some(block.to_string())
                        }
                        // Nothing changes in the target (cycle 7's first line, a
                        // command repeated, a block written with the next): nothing to
                        // write but the block's other words.
                        // A block number with no other word left (`N20 G68.2 …`) stays,
                        // alone where nothing is written, on the first line written
                        // otherwise: a jump (`GOTO20`, `M99 P20`) or a restart by number
                        // still finds it (not into Heidenhain, which numbers lines itself).
                        // Its comment beside it, or on a line of its own.
                        Ok((0, _)) => match (kept.clone().or(number.clone()), &note) {
                            (Some(l), Some(n)) => Some(format!("{l} {n}")),
                            (l, n) => l.or(n.clone()),
                        },
                        Ok((len, _)) => {
                            rewritten = true;
                            let text = String::from_utf8_lossy(&buf[..len]);
                            let folds = matches!(
                                t.dialect,
                                Dialect::Heidenhain | Dialect::Sinumerik | Dialect::Twincat
                            );
                            if let (Some(at), true, true) = (
                                optional_shift,
                                folds,
                                skip_mark(block, dialect, dialect).is_empty(),
                            ) {
                                (ok, uncarried) = (false, uncarried + 1);
                                eprintln!(
                                    "cncrot: line {line}: not carried across as {} {}: written with the datum shift of the optional block at line {at} (/), which {} writes into this block, not optional: wrong while the skip switch is on: {block}",
                                    input::dialect_name(t.dialect),
                                    t.form,
                                    input::dialect_name(t.dialect)
                                );
                            }
                            // TwinCAT's G58 shifts only under a zero offset G54–G57 ("G53
                            // (default setting) … deactivate any zero offset shift
                            // translation"): said once where the program selects none.
                            if t.dialect == Dialect::Twincat
                                && !g58_said
                                && text.split_whitespace().any(|w| w == "G58")
                                && !selects_g54_to_g57(&text_upper)
                            {
                                g58_said = true;
                                eprintln!(
                                    "cncrot: line {line}: the datum shift is written as TwinCAT's G58, which shifts only while a zero offset G54 to G57 is active (G53, the default, deactivates it): the program selects none, so select one before it: {block}"
                                );
                            }
                            let code = split_comments(block, dialect).0;
                            let text = if dialect == Dialect::Sinumerik
                                && t.dialect == Dialect::Sinumerik
                            {
                                keep_cycle800_words(&code, &text)
                            } else {
                                text.into_owned()
                            };
                            // The data set a SINUMERIK program swivels with: a machine's
                            // configuration elsewhere (said once per name).
                            let set = (dialect == Dialect::Sinumerik
                                && t.dialect != Dialect::Sinumerik)
                                .then(|| cycle800_args(&code))
                                .flatten()
                                .and_then(|(a, _)| a.get(1).cloned())
                                .filter(|tc| !matches!(tc.as_str(), "" | "\"\"" | "\"0\"" | "0"));
                            if let Some(tc) = set.filter(|tc| !data_sets.contains(tc)) {
                                eprintln!(
                                    "cncrot: line {line}: the swivel data set {tc} (_TC) has no word in {}: the kinematics the control uses is the machine's own (check it is the one this data set describes): {block}",
                                    input::dialect_name(t.dialect)
                                );
                                data_sets.push(tc);
                            }
                            // An optional block stays optional: its skip mark on each line.
                            let mark = skip_mark(block, dialect, t.dialect);
                            // The block's other words (a retract beside a cancel, the
                            // motion mode and feed beside a tilt) first, as they stand; after
                            // it where they are the move of LinuxCNC's `G53.3 X Y Z` (to a
                            // point in the plane, with the turn).
                            let written = text.lines().enumerate().map(|(k, l)| {
                                let n = number.as_ref().filter(|_| k == 0);
                                let c = note.as_ref().filter(|_| k == 0);
                                match (n, c) {
                                    (Some(n), Some(c)) => format!("{mark}{n} {l} {c}"),
                                    (Some(n), None) => format!("{mark}{n} {l}"),
                                    (None, Some(c)) => format!("{mark}{l} {c}"),
                                    (None, None) => format!("{mark}{l}"),
                                }
                            });
                            let moves_after = split_comments(block, dialect)
                                .0
                                .to_uppercase()
                                .split_whitespace()
                                .any(|w| w == "G53.3");
                            let lines: Vec<String> = if moves_after {
                                // LinuxCNC runs it as `G0 X Y Z` with the turn: a rapid in
                                // the target too, whatever motion mode is modal there.
                                let rapid = kept.as_deref().map(|k| rapid_move(k, t.dialect));
                                written.chain(rapid).collect()
                            } else {
                                kept.iter().cloned().chain(written).collect()
                            };
                            Some(lines.join("\n"))
                        }
                        Err(e) => {
                            uncarried += 1;
                            not_carried(line, t, e, block);
                            ok = false;
                            run_failed = true;
                            Some(block.to_string())
                        }
                    }
                } else {
                    let tool = column(&f.rotation, 2);
                    let axes = machine.as_ref().map(|m| p.axes(m, current));
                    let mut json = Json::Obj(vec![
                        ("line", Json::Int(line as i64)),
                        ("block", Json::str(block)),
                        ("origin", Json::nums(&f.translation)),
                        ("tool", Json::nums(&tool)),
                    ]);
                    let mut row = format!(
                        "line {line}: {block}\n  origin: {}  tool direction: {}",
                        nums(&f.translation, d),
                        nums(&tool, d)
                    );
                    match on_machine {
                        Some(Ok(_)) => {}
                        Some(Err(e)) => {
                            ok = false;
                            let why = match e {
                                Error::BadArgument => {
                                    "the machine has no axis for a position the block states"
                                }
                                e => e.message(),
                            };
                            row = format!(
                                "line {line}: {block}\n  direct: {}  frame: {why}",
                                direct_text(&p, d),
                            );
                            json = Json::Obj(vec![
                                ("line", Json::Int(line as i64)),
                                ("block", Json::str(block)),
                                ("direct", Json::nums(&p.angles)),
                                ("frame_error", Json::str(why)),
                            ]);
                        }
                        None => {
                            row = format!(
                                "line {line}: {block}\n  direct: {} (the frame follows from the machine: --carr or --axis)",
                                direct_text(&p, d)
                            );
                            json = Json::Obj(vec![
                                ("line", Json::Int(line as i64)),
                                ("block", Json::str(block)),
                                ("direct", Json::nums(&p.angles)),
                                ("by", Json::str(direct_by(&p))),
                            ]);
                        }
                    }
                    match axes {
                        Some(Ok(c)) => {
                            // The axes are where the last block that moved them left them: a
                            // block that stays (`STAY`, a `G68.2` before its `G53.1`, a
                            // cancel, a datum shift) shows where its plane needs them.
                            if p.positioning != Positioning::Stay {
                                current = c.axes;
                            }
                            let shown = c.axes.get(..n).unwrap_or(&c.axes);
                            row += &format!("  axes: {}", nums(shown, d));
                            if c.free {
                                row += " (a free axis kept where it was)";
                            }
                            json = json.with("axes", Json::nums(shown));
                        }
                        Some(Err(e)) => {
                            ok = false;
                            let why = match e {
                                Error::BadArgument if p.direct.is_some() => {
                                    "the machine has no axis for a position the block states"
                                }
                                e => e.message(),
                            };
                            row += &format!("  axes: {why}");
                            json = json.with("axes_error", Json::str(why));
                        }
                        None => {}
                    }
                    Some(if a.json { json.text() } else { row })
                }
            }
        };
        if remark == Remark::Applied && p.shift != before.shift {
            optional_shift = (!skip_mark(block, dialect, dialect).is_empty()).then_some(line);
        }
        if deferred {
            pending.push((row, block.to_string()));
            continue;
        }
        // The run before this block: as written, or as it stands where its last block could
        // not be written.
        for (written, stands) in pending.drain(..) {
            let text = if run_failed { Some(stands) } else { written };
            if text.is_some_and(|t| !put(t)) {
                return Ok(ok);
            }
        }
        if let Some(row) = row {
            let head = held.take().filter(|_| !rewritten);
            if head.is_some_and(|h| !put(h)) || !put(row) {
                return Ok(ok);
            }
        }
    }
    for (written, _) in pending.drain(..) {
        if written.is_some_and(|t| !put(t)) {
            return Ok(ok);
        }
    }
    if held.take().is_some_and(|h| !put(h)) {
        return Ok(ok);
    }
    let total = applied + passed + unfollowed + refused;
    let mut summary = format!(
        "{total} blocks: {applied} concerning the frame, {passed} passed over, {unfollowed} not followed, {refused} refused"
    );
    if target.is_some() {
        summary += &format!(
            ", {uncarried} not carried across, {moved_otherwise} with a way of moving left out"
        );
    }
    match (&target, a.json) {
        (Some(_), _) => eprintln!("cncrot: {summary}"),
        (None, true) => {
            let j = Json::Obj(vec![
                ("blocks", Json::Int(total as i64)),
                ("applied", Json::Int(applied as i64)),
                ("passed", Json::Int(passed as i64)),
                ("not_followed", Json::Int(unfollowed as i64)),
                ("refused", Json::Int(refused as i64)),
            ]);
            put(j.text());
        }
        (None, false) => {
            put(summary.clone());
        }
    }
    if let Some(path) = a.svg {
        let mut notes = vec![summary];
        if tilts > drawn.len() {
            notes.push(format!(
                "the first {} of {tilts} tilts are drawn",
                drawn.len()
            ));
        }
        svg::write(
            path,
            &svg::Picture {
                title: format!("the tilts of {}", a.file),
                planes: drawn,
                size: 50.0,
                points: Vec::new(),
                notes,
            },
        )?;
    }
    Ok(ok)
}

/// What `path` takes besides the machine.
/// One row of `path`: the machine's axes, the free-axis or Hirth remark, and as JSON.
fn path_row(t: &cncrot::kinematics::Tcp, n: usize, d: i32) -> Report {
    let shown = &t.axes[..3 + n];
    let mut brief = nums(shown, d);
    if t.free {
        brief += "  (free axis kept)";
    } else if t.residual.iter().any(|&r| r != 0.0) {
        brief += &format!("  (Hirth: snapped by {})", nums(&t.residual[..n], d));
    }
    let json = Json::Obj(vec![
        ("linear", Json::nums(&t.axes[..3])),
        ("rotary", Json::nums(&t.axes[3..3 + n])),
        ("free", Json::Bool(t.free)),
        ("residual", Json::nums(&t.residual[..n])),
    ]);
    Report {
        full: brief.clone() + "\n",
        brief,
        json,
    }
}

pub struct PathArgs<'a> {
    pub file: &'a str,
    pub tool_length: f64,
    pub current: Option<&'a str>,
    pub rule: &'a str,
    pub dialect: Option<&'a str>,
}

/// The five-axis transformation along a path of CL points (tool tip and direction): the
/// machine's linear and rotary axes for each, continuous with the row before.
pub fn path(a: &PathArgs, m: &MachineArgs, common: &Common) -> Result<bool, Failure> {
    let machine = machine(m)?;
    let n = machine.axes().len();
    if !a.tool_length.is_finite() {
        return Err(Failure::new("--tool-length: not a finite number"));
    }
    let mut rule = rule(a.rule, n)?;
    // The start: the rotary positions, or X,Y,Z and the rotary positions.
    let mut previous = [0.0; 6];
    if let Some(text) = a.current {
        let v = input::numbers(text).map_err(option("--current"))?;
        let rotary: &[f64] = if v.len() > MAX_AXES {
            &v[3.min(v.len())..]
        } else {
            &v
        };
        if v.len() > MAX_AXES {
            previous[..3].copy_from_slice(&v[..3]);
        }
        let p = positions(&nums(rotary, 17), n, "positions").map_err(option("--current"))?;
        previous[3..].copy_from_slice(&p);
    }
    let d = common.decimals;
    let common = Common {
        batch: Some(a.file.to_string()),
        json: common.json,
        decimals: common.decimals,
    };
    let mut first = true;
    let program = a.dialect.map(input::dialect).transpose()?;
    let mut state = cncrot::dialects::toolpath::ToolPath::default();
    // Rotary positions by letter (`A B C` of `G1 X1 C20`) name the machine's axes; a letter
    // a block leaves out is where that axis stands (from `--current` on, then each point's),
    // not 0. Under Heidenhain's `AXIS SPAT` the letters are spatial angles, which the axes'
    // positions are not: left as the program states them.
    let stand = |state: &mut cncrot::dialects::toolpath::ToolPath, at: &[f64; 6]| {
        if state.spatial {
            return;
        }
        let letters = cncrot::dialects::program::axis_letters(&machine);
        for k in 0..machine.axes().len() {
            state.axes[letters[k]] = at[3 + k];
        }
    };
    stand(&mut state, &previous);
    run(&common, None, |text| {
        if let Some(dialect) = program {
            use cncrot::dialects::toolpath::PathRemark;
            let (next, remark) = state.line(dialect, text.as_bytes()).map_err(|e| {
                if e.error == cncrot::Error::BadArgument {
                    // The reader's one refusal of a block's words: say which.
                    Failure::at(
                        e.column,
                        "the tool direction is zero, or the block states both a tool direction and rotary positions"
                            .to_string(),
                    )
                } else {
                    Failure::at(e.column, input::block_message(text, &e))
                }
            })?;
            // A point the machine does not reach leaves the state as it was: the path goes
            // on from the last point reached, without the refused block's words.
            let reached = state;
            state = next;
            if remark != PathRemark::Point {
                let note = if remark == PathRemark::NotFollowed {
                    "(not followed: the point is not known here)"
                } else {
                    ""
                };
                let mut json = Json::Obj(vec![("point", Json::Bool(false))]);
                if remark == PathRemark::NotFollowed {
                    json = json.with("remark", Json::str("not followed".to_string()));
                }
                return Ok(Report {
                    full: note.to_string(),
                    brief: note.to_string(),
                    json,
                });
            }
            let t = match state.machine_axes(&machine, a.tool_length, previous, rule) {
                Ok(t) => t,
                Err(e) => {
                    let stated = matches!(
                        state.orientation,
                        cncrot::dialects::toolpath::Orientation::Axes(_)
                    );
                    state = reached;
                    return Err(if e == cncrot::Error::BadArgument && stated {
                        Failure::new(
                            "the block gives a position to a rotary axis the machine does not have (A, B, C go to the machine's axis whose direction is nearest X, Y, Z)",
                        )
                    } else {
                        e.into()
                    });
                }
            };
            previous = t.axes;
            // Every rule picks the first point's solution; the points after it continue
            // from it (a side or a direction of travel taken again at each point would swap
            // branches where that axis passes 0, the other solution every point).
            rule = Rule::Closest;
            // The letters a later block leaves out (`G1 X1 C20` after a direction) are where
            // the machine's axes now stand, not the last ones a block stated.
            stand(&mut state, &previous);
            return Ok(path_row(&t, n, d));
        }
        let trimmed = text.trim_start();
        // Column names hold no number ("x y z i j k", "X;Y;Z;I;J;K"): a first line with
        // digits is a point, read as one (`X10 Y0 …`, `GOTO/…` are then errors, not
        // headers skipped in silence).
        let header =
            first && !trimmed.starts_with('#') && !trimmed.bytes().any(|b| b.is_ascii_digit());
        first = first && trimmed.starts_with('#');
        if trimmed.starts_with('#') || header {
            // A comment or a column header: a blank line keeps the rows aligned.
            return Ok(Report {
                full: String::new(),
                brief: String::new(),
                json: Json::Obj(vec![("comment", Json::Bool(true))]),
            });
        }
        let v = input::exactly::<6>(text, "a CL point x y z i j k")?;
        let k = [v[3], v[4], v[5]];
        // Any length but zero, as `cncrot_cl_pose` takes it (and MATLAB through it).
        if k == [0.0; 3] {
            return Err(Failure::new("the tool direction i j k is zero"));
        }
        let tip = [v[0], v[1], v[2]];
        // With three rotary axes the turn about the tool is carried from where the machine
        // stands (as the program reader carries it): no jump where `cl_pose`'s X' changes.
        let pose = if machine.axis_count() == cncrot::kinematics::MAX_AXES {
            let before = machine.forward([previous[3], previous[4], previous[5]])?;
            cncrot::kinematics::cl_pose_toward(tip, k, &before.rotation)?
        } else {
            cncrot::kinematics::cl_pose(tip, k)?
        };
        let t = machine.tcp_inverse_with(&pose, a.tool_length, previous, rule)?;
        previous = t.axes;
        // As for a program's points: the rule picks the first row's solution.
        rule = Rule::Closest;
        Ok(path_row(&t, n, d))
    })
}
