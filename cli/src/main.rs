//! `cncrot`: the library for people who do not program. Every subcommand reads one input
//! from its arguments, or one input per line with `--batch FILE` (`-`: standard input), and
//! writes one result per input; `--json` writes JSON Lines for programs. Bad input is a
//! message naming the input line and column, and the exit status is 1 when any input
//! failed (2 for a malformed command line).

mod commands;
mod input;
mod labels;
mod output;
mod params;
mod svg;

use clap::{Args, Parser, Subcommand};
use input::Failure;
use output::Json;
use std::ffi::OsString;
use std::io::Write;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "cncrot",
    version,
    about = "Coordinate rotations for CNC controllers: convert angles between conventions, \
             translate tilted-plane lines between controllers, turn probed points into a \
             plane, run the CYCLE600 cycle, position rotary axes.",
    after_help = "Angles are in degrees, lengths in millimetres. Conventions are written \
                  KIND:SEQUENCE: extrinsic (about the machine axes) or intrinsic (about the \
                  workpiece axes), then the axis letters in rotation order, e.g. \
                  extrinsic:XYZ, intrinsic:ZXY (or the codes 0:57, 1:39).\n\n\
                  Run 'cncrot help <COMMAND>' for each command's options and an example."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// What every subcommand shares: batch input, JSON output, decimals.
#[derive(Args, Clone)]
struct Common {
    /// One input per line from FILE ('-': standard input); one output line per input line
    /// (blank for a blank line, 'error: …' for a failed one).
    #[arg(long, value_name = "FILE")]
    batch: Option<String>,
    /// One JSON object per result (JSON Lines), numbers at full precision.
    #[arg(long)]
    json: bool,
    /// Decimals of the numbers written (0..17), or 'exact' for the shortest numbers that
    /// read back to the same double.
    #[arg(long, default_value = "4", value_parser = input::decimals)]
    decimals: i32,
}

/// A machine: SINUMERIK swivel data, or rotary axes one by one.
#[derive(Args, Clone)]
struct MachineOpts {
    /// SINUMERIK swivel data file ($TC_CARR1..65).
    #[arg(long, value_name = "FILE")]
    carr: Option<String>,
    /// Swivel data set number in the --carr file.
    #[arg(long, default_value_t = 1, value_parser = whole)]
    set: i32,
    /// A rotary axis (repeatable, at most 3, in chain order): SIDE:DX,DY,DZ[@PX,PY,PZ].
    #[arg(long, value_name = "SIDE:DIR[@POINT]")]
    axis: Vec<String>,
    /// Tool direction with every axis at 0.
    #[arg(long, value_name = "DX,DY,DZ", default_value = "0,0,1")]
    tool: String,
}

impl MachineOpts {
    fn args(&self) -> commands::MachineArgs<'_> {
        commands::MachineArgs {
            carr: self.carr.as_deref(),
            set: self.set,
            axis: &self.axis,
            tool: &self.tool,
        }
    }
}

#[derive(Subcommand)]
enum Command {
    /// Angles from one convention to another: both solutions, or the one nearest to given
    /// angles.
    #[command(
        after_help = "Example (the paper's probe angles about the machine axes X, Y, Z \
                            as CYCLE800's rotations about the workpiece axes Z, X', Y''):\n  \
                            cncrot convert --from extrinsic:XYZ --to intrinsic:ZXY 30 45 60\n\n\
                            Batch: each line holds three angles, e.g. '30 45 60' or '30,45,60'."
    )]
    Convert {
        /// Convention of the given angles, e.g. extrinsic:XYZ (a skipped rotation: 0 or a
        /// code with a 00 pair).
        #[arg(long, value_name = "KIND:SEQ")]
        from: String,
        /// Convention to convert to: one of the 12 sequences, e.g. intrinsic:ZXY.
        #[arg(long, value_name = "KIND:SEQ")]
        to: String,
        /// Write only the solution nearest to these angles (whole turns added as needed),
        /// e.g. the axis positions the machine is at.
        #[arg(long, value_name = "A,B,C")]
        near: Option<String>,
        /// The angles, in rotation order.
        angles: Vec<String>,
        #[command(flatten)]
        common: Common,
    },
    /// Read a controller's tilted-plane line and write the same plane in other dialects.
    #[command(
        after_help = "Dialects: sinumerik, heidenhain, fanuc, syntec, twincat, haas. \
                            A target is DIALECT or DIALECT:FORM, e.g. heidenhain:'PLANE EULER', \
                            sinumerik:'ROT EULER', syntec:'G158 P10157'; without --to every \
                            dialect is written in its usual form.\n\n\
                            Example:\n  \
                            cncrot line --from sinumerik --to heidenhain --to fanuc \\\n    \
                            'CYCLE800(0,\"TC1\",200000,57,0,0,0,30,45,60,0,0,0,-1,100,1)'\n\n\
                            Batch: the lines are one program; modal state (an active frame, \
                            AROT adding to ROT) carries from line to line, and each input line \
                            gives the frame then active, tab-separated per target."
    )]
    Line {
        /// Dialect of the input line(s).
        #[arg(long, value_name = "DIALECT")]
        from: String,
        /// What to write (repeatable): DIALECT or DIALECT:FORM.
        #[arg(long, value_name = "DIALECT[:FORM]")]
        to: Vec<String>,
        /// SINUMERIK: frame angles in Euler mode (machine data 10600 = 2), not RPY.
        #[arg(long)]
        euler: bool,
        /// Heidenhain: CYCL DEF 19's A B C are rotary-axis positions (a machine setting),
        /// not spatial angles.
        #[arg(long)]
        axis_angles: bool,
        /// The line to read.
        text: Option<String>,
        /// Draw the frame (after the last line) into FILE as an SVG picture.
        #[arg(long, value_name = "FILE")]
        svg: Option<String>,
        #[command(flatten)]
        common: Common,
    },
    /// A whole part program: what each block does to the frame, the frame after each tilt
    /// and, with a machine, the rotary positions it moves to; or the program translated.
    #[command(
        after_help = "One row per block that concerns the frame (line number, block, origin, \
                            tool direction; with --carr or --axis the rotary positions, chosen \
                            from where the last block that moved the axes left them, and any \
                            travel violation), then a \
                            summary of the blocks passed over. A block that changes the frame in \
                            a way cncrot does not follow (a work offset, preset, datum shift, \
                            mirroring) is flagged. A Heidenhain CALL LBL is followed through \
                            its label (the frame after it is the one the label's blocks leave), \
                            an M98 P, G65 P or M198 P (Haas also M97 P) through its subprogram in the same file. \
                            --to writes the whole program with its tilt \
                            and cancel blocks in the target's language and every other block as \
                            it is, and flags on standard error what it cannot carry across \
                            and a turn, tip kept in place or retraction the target has no word \
                            for (exit status 1). Parameters set once to a number (Q1, #1, R1) \
                            are read where a tilt uses them.\n\n\
                            Example:\n  cncrot program part.h --dialect heidenhain --carr head.carr \
                            --current 0,0\n  cncrot program part.h --dialect heidenhain --to fanuc"
    )]
    Program {
        /// The program file ('-': standard input).
        file: String,
        /// Its dialect.
        #[arg(long, value_name = "DIALECT")]
        dialect: String,
        /// SINUMERIK: frame angles in Euler mode (machine data 10600 = 2), not RPY.
        #[arg(long)]
        euler: bool,
        /// Heidenhain: CYCL DEF 19's A B C are rotary-axis positions (a machine setting),
        /// not spatial angles.
        #[arg(long)]
        axis_angles: bool,
        /// Write the program translated: DIALECT or DIALECT:FORM.
        #[arg(long, value_name = "DIALECT[:FORM]")]
        to: Option<String>,
        #[command(flatten)]
        machine: MachineOpts,
        /// Rotary positions before the program (the choice unwinds toward them).
        #[arg(long, value_name = "A,B,C")]
        current: Option<String>,
        /// One JSON object per block that concerns the frame, then the summary.
        #[arg(long)]
        json: bool,
        /// Draw the program's tilts (the first six) into FILE as an SVG picture.
        #[arg(long, value_name = "FILE")]
        svg: Option<String>,
        /// Decimals of the numbers written (0..17), or 'exact'.
        #[arg(long, default_value = "4", value_parser = input::decimals)]
        decimals: i32,
    },
    /// Probed points to the least-squares plane, its flatness, and the controllers' lines.
    #[command(
        after_help = "Points: 'X,Y,Z' arguments, or --points-file FILE with one point per \
                            line (numbers separated by commas, semicolons or spaces; lines \
                            starting with # and a first line that is not numbers are skipped).\n\n\
                            Example (four corners of a plane tilted 5.71 degrees about Y):\n  \
                            cncrot probe 0,0,0 100,0,-10 100,50,-10 0,50,0 --to heidenhain"
    )]
    Probe {
        /// The points, each as X,Y,Z.
        points: Vec<String>,
        /// Read the points from FILE ('-': standard input); `--points FILE` is the same.
        #[arg(long, visible_alias = "points", value_name = "FILE")]
        points_file: Option<String>,
        /// What to write (repeatable): DIALECT or DIALECT:FORM; default every dialect.
        #[arg(long, value_name = "DIALECT[:FORM]")]
        to: Vec<String>,
        /// The side the tool comes from: Z' gets a non-negative component along it (default
        /// the machine's +Z: the plane the right way up however the points were ordered).
        #[arg(long, value_name = "DX,DY,DZ", default_value = "0,0,1")]
        toward: String,
        /// Z' on the side the points' order gives, (P2-P1)x(P3-P1), as PLANE POINTS does.
        #[arg(long, conflicts_with = "toward")]
        order: bool,
        /// Draw the plane, its axes and the points (deviations enlarged) into FILE as an SVG
        /// picture.
        #[arg(long, value_name = "FILE")]
        svg: Option<String>,
        /// One JSON object.
        #[arg(long)]
        json: bool,
        /// Decimals of the numbers written (0..17), or 'exact'.
        #[arg(long, default_value = "4", value_parser = input::decimals)]
        decimals: i32,
    },
    /// The paper's cycle CYCLE600: a rotation about the machine or workpiece axes, with
    /// translations, into another convention; prints the results _CYC600_1.._6.
    #[command(
        after_help = "The call as written in a part program, or its parameters:\n  \
                            _INEXIN, _MIHEAD, _SW_REC, _BIN_IN, _POS_X, _POS_Y, _POS_Z, _ANG_1, \
                            _ANG_2, _ANG_3, _POS_X_R, _POS_Y_R, _POS_Z_R, _INEXOUT, _BIN_OUT, \
                            _ROT_AD, _ROT_INV, _RETR_Z (the last three may be left out: 0).\n\n\
                            Example (the paper's Example 3):\n  \
                            cncrot cycle600 'CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39,0,0,0)'\n\n\
                            Batch: one call per line; the state carries from call to call \
                            (_ROT_AD = 1 adds to the previous rotation)."
    )]
    Cycle600 {
        /// The call, e.g. 'CYCLE600(0,"UFK600",1,57,0,0,0,30,45,60,0,0,0,1,39)'.
        call: Vec<String>,
        /// HEAD_DEF file: _MIHEAD must name one of its accessories.
        #[arg(long, value_name = "FILE")]
        heads: Option<String>,
        /// SINUMERIK swivel data ($TC_CARR...) of the head, to position it (_SW_REC = 0).
        #[arg(long, value_name = "FILE")]
        carr: Option<String>,
        /// Swivel data set number in the --carr file.
        #[arg(long, default_value_t = 1, value_parser = whole)]
        set: i32,
        /// Current rotary-axis positions, for positioning.
        #[arg(long, value_name = "A,B,C")]
        current: Option<String>,
        #[command(flatten)]
        common: Common,
    },
    /// The five-axis transformation along a path: CL points (tool tip x y z and direction
    /// i j k) to the machine's linear and rotary axes, each row continuous with the one
    /// before.
    #[command(
        after_help = "FILE holds one CL point per line, 'x y z i j k' (spaces, commas or \
                      semicolons); '#' lines and a first line of column names are comments. \
                      The output has one line per input line: X Y Z (the tool adapter's \
                      reference point) and the rotary positions, blank for a comment, \
                      'error: ...' for a point the machine cannot reach (the path goes on from \
                      the last point reached). The machine as for 'axes'.\n\n\
                      Example (an AC table: A about X through z = 100, C on it; tool 50 mm):\n  \
                      cncrot path cl.txt --axis work:1,0,0@0,0,100 --axis work:0,0,1 \\\n    \
                      --tool-length 50 --current 20,80\n\n\
                      With --dialect, FILE is a five-axis part program (SINUMERIK TRAORI, \
                      Heidenhain M128 / FUNCTION TCPM, Fanuc or Syntec G43.4 / G43.5, Haas \
                      G234): each motion block with the transformation on is a point, its \
                      orientation a tool direction (A3 B3 C3, A2 B2 C2, TX TY TZ, I J K) or \
                      rotary positions (A B C, each machine axis taking the letter its \
                      direction is nearest); other blocks give blank lines."
    )]
    Path {
        /// The CL file ('-': standard input).
        file: String,
        #[command(flatten)]
        machine: MachineOpts,
        /// Tool length, mm: the tip lies this far from the tool adapter along the tool.
        #[arg(long, default_value_t = 0.0, value_parser = number)]
        tool_length: f64,
        /// Positions before the first point: the rotary axes (A,B,C) or X,Y,Z then them.
        #[arg(long, value_name = "[X,Y,Z,]A,B,C")]
        current: Option<String>,
        /// Which solution: closest (continuous with the row before), or a priority axis
        /// minus:K / plus:K (its lower / higher angle), up:K / down:K (it turns only
        /// up / only down, as G53.1 P1 / P2 ask), master:K (it turns the least, then the
        /// others: Fanuc's G53.1), or inverse (the first point the other solution, the
        /// points after it continuous with it).
        #[arg(long, default_value = "closest")]
        rule: String,
        /// FILE is a five-axis part program in this dialect, not CL points.
        #[arg(long)]
        dialect: Option<String>,
        /// One JSON object per line.
        #[arg(long)]
        json: bool,
        /// Decimals of the numbers written (0..17), or 'exact'.
        #[arg(long, default_value = "4", value_parser = input::decimals)]
        decimals: i32,
    },
    /// Rotary-axis positions of a described machine for an orientation (or, with
    /// --forward, the orientation of given positions).
    #[command(
        visible_alias = "kinematics",
        after_help = "The machine: SINUMERIK swivel data (--carr FILE, data set --set), or \
                      its axes in chain order, from the machine frame outwards (a head's C \
                      before the B it carries, a table's A before the C it carries), as \
                      --axis SIDE:DX,DY,DZ[@PX,PY,PZ] with SIDE tool (a swivel head) or work \
                      (a rotary table), direction and a point on the axis.\n\n\
                      Example (a head C about Z carrying B about Y; the plane tilted 30 \
                      degrees about Y, from C = 750):\n  \
                      cncrot axes --axis tool:0,0,1 --axis tool:0,1,0 --from extrinsic:XYZ \\\n    \
                      --current 750,0 0 30 0\n\n\
                      Batch: each line holds the three angles (or, with --forward, the \
                      positions)."
    )]
    Axes {
        #[command(flatten)]
        machine: MachineOpts,
        /// Convention of the given orientation angles.
        #[arg(long, value_name = "KIND:SEQ", default_value = "extrinsic:XYZ")]
        from: String,
        /// Current axis positions (the choice unwinds toward them).
        #[arg(long, value_name = "A,B,C")]
        current: Option<String>,
        /// Which solution: closest (to --current), minus:K or plus:K (the lower or higher
        /// position of axis K, 1-based), up:K or down:K (axis K turns only up or only down
        /// from --current, the least it must), master:K (axis K turns the least, then the
        /// others, then nearest 0: Fanuc's G53.1), inverse (the other one).
        #[arg(long, default_value = "closest")]
        rule: String,
        /// Every solution, not only the chosen one.
        #[arg(long)]
        all: bool,
        /// The numbers are axis positions: write the orientation they give (as angles of
        /// --from) and the tool direction.
        #[arg(long)]
        forward: bool,
        /// The orientation angles (or positions with --forward).
        values: Vec<String>,
        /// Draw the (last) orientation and its positions into FILE as an SVG picture.
        #[arg(long, value_name = "FILE")]
        svg: Option<String>,
        #[command(flatten)]
        common: Common,
    },
}

/// The result of one input: what a person reads (`full`), the one line batch mode writes
/// (`brief`), and the JSON.
pub(crate) struct Report {
    pub full: String,
    pub brief: String,
    pub json: Json,
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse_from(std::env::args_os().map(shield_negative)) {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    let result = match cli.command {
        Command::Convert {
            from,
            to,
            near,
            angles,
            common,
        } => commands::convert(&from, &to, near.as_deref(), &angles, &common),
        Command::Line {
            from,
            to,
            euler,
            axis_angles,
            text,
            svg,
            common,
        } => commands::line(
            &from,
            &to,
            (euler, axis_angles),
            text.as_deref(),
            &common,
            svg.as_deref(),
        ),
        Command::Program {
            file,
            dialect,
            euler,
            axis_angles,
            to,
            machine,
            current,
            json,
            svg,
            decimals,
        } => commands::program(
            &commands::ProgramArgs {
                file: &file,
                dialect: &dialect,
                euler,
                axis_angles,
                to: to.as_deref(),
                current: current.as_deref(),
                json,
                decimals,
                svg: svg.as_deref(),
            },
            &machine.args(),
        ),
        Command::Probe {
            points,
            points_file,
            to,
            toward,
            order,
            svg,
            json,
            decimals,
        } => commands::probe(
            &points,
            points_file.as_deref(),
            &to,
            (!order).then_some(toward.as_str()),
            json,
            decimals,
            svg.as_deref(),
        ),
        Command::Cycle600 {
            call,
            heads,
            carr,
            set,
            current,
            common,
        } => commands::cycle600(
            &call,
            heads.as_deref(),
            carr.as_deref(),
            set,
            current.as_deref(),
            &common,
        ),
        Command::Path {
            file,
            machine,
            tool_length,
            current,
            rule,
            dialect,
            json,
            decimals,
        } => commands::path(
            &commands::PathArgs {
                file: &file,
                tool_length,
                current: current.as_deref(),
                rule: &rule,
                dialect: dialect.as_deref(),
            },
            &machine.args(),
            &Common {
                batch: None,
                json,
                decimals,
            },
        ),
        Command::Axes {
            machine,
            from,
            current,
            rule,
            all,
            forward,
            values,
            svg,
            common,
        } => commands::axes(
            &machine.args(),
            &commands::AxesArgs {
                from: &from,
                current: current.as_deref(),
                rule: &rule,
                all,
                forward,
                svg: svg.as_deref(),
            },
            &values,
            &common,
        ),
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(f) => {
            eprintln!("cncrot: {}", f.message);
            ExitCode::from(2)
        }
    }
}

/// A number option's value (its shield of [`shield_negative`] skipped).
fn number(text: &str) -> Result<f64, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("'{}' is not a number", text.trim()))
}

/// A whole-number option's value (its shield of [`shield_negative`] skipped).
fn whole(text: &str) -> Result<i32, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("'{}' is not a whole number", text.trim()))
}

/// A negative number (`-30`, `-5,0,0`, `-.5`) would read as an option: it is given a
/// leading space, which every number reader here skips.
fn shield_negative(arg: OsString) -> OsString {
    match arg.to_str() {
        Some(s)
            if s.starts_with('-')
                && s[1..].starts_with(|c: char| c.is_ascii_digit() || c == '.') =>
        {
            OsString::from(format!(" {s}"))
        }
        _ => arg,
    }
}

/// Runs `each` on the one input of the arguments, or on every line of the batch, writes
/// the results and the failures; whether every input succeeded. A failure of the setup
/// (an unreadable file, a bad option) is an `Err`.
pub(crate) fn run(
    common: &Common,
    single: Option<String>,
    mut each: impl FnMut(&str) -> Result<Report, Failure>,
) -> Result<bool, Failure> {
    let inputs = match (&common.batch, single) {
        (Some(_), Some(_)) => {
            return Err(Failure::new(
                "give the input either as arguments or with --batch, not both",
            ))
        }
        (Some(source), None) => input::batch_lines(source)?,
        (None, Some(text)) => vec![(0, text)],
        (None, None) => return Err(Failure::new("no input: give it as arguments or --batch")),
    };
    let batch = common.batch.is_some();
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let mut ok = true;
    for (line, text) in inputs {
        // One output line per input line: a blank input gives a blank output (a line of
        // its own in JSON), a failed one a marked line.
        if batch && text.trim().is_empty() {
            let blank = if common.json {
                let j = Json::Obj(vec![
                    ("line", Json::Int(line as i64)),
                    ("blank", Json::Bool(true)),
                ]);
                writeln!(out, "{}", j.text())
            } else {
                writeln!(out)
            };
            if blank.is_err() {
                return Ok(ok);
            }
            continue;
        }
        let result = each(&text);
        let written = match (&result, common.json) {
            (Ok(r), true) => {
                let j = if batch {
                    r.json.clone().with("line", Json::Int(line as i64))
                } else {
                    r.json.clone()
                };
                writeln!(out, "{}", j.text())
            }
            (Ok(r), false) if batch => writeln!(out, "{}", r.brief),
            (Ok(r), false) => write!(out, "{}", r.full),
            (Err(f), json) => {
                ok = false;
                let place = match (batch, f.column) {
                    (true, Some(c)) => format!("line {line}, column {c}: "),
                    (true, None) => format!("line {line}: "),
                    (false, Some(c)) => format!("column {c}: "),
                    (false, None) => String::new(),
                };
                eprintln!("cncrot: {place}{}", f.message);
                if json {
                    let mut e = Json::Obj(vec![("error", Json::str(f.message.clone()))]);
                    if let Some(c) = f.column {
                        e = e.with("column", Json::Int(c as i64));
                    }
                    if batch {
                        e = e.with("line", Json::Int(line as i64));
                    }
                    writeln!(out, "{}", e.text())
                } else if batch {
                    writeln!(out, "error: {place}{}", f.message)
                } else {
                    Ok(())
                }
            }
        };
        if written.is_err() {
            // A closed pipe (`| head`): stop quietly, as command-line tools do.
            return Ok(ok);
        }
    }
    Ok(ok)
}
