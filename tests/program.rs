//! Program lines: each dialect's reader against vendor examples, the worked numbers of
//! docs/dialects.md and hand geometry; refusals with their columns and the state untouched;
//! every writer read back by its own dialect; every pair of dialects and forms converted
//! through text, with random and with singular frames.

mod common;

use cncrot::dialects::program::{
    write_block, write_change, write_line, AxisChoice, Dialect, Direct, DirectAxes, Feed,
    LineError, Positioning, Program, Remark, Retract, MAX_CHANGE,
};
use cncrot::{elementary, mul, Axis, Error, Frame, Matrix};
use common::Rng;

fn read(d: Dialect, lines: &[&str]) -> Program {
    let mut p = Program::default();
    for l in lines {
        p = p
            .line(d, l.as_bytes())
            .unwrap_or_else(|e| panic!("{d:?} {l:?}: {e:?}"))
            .0;
    }
    p
}

fn rot(d: Dialect, lines: &[&str]) -> Matrix {
    read(d, lines).frame.rotation
}

fn dist(a: &Matrix, b: &Matrix) -> f64 {
    a.iter()
        .flatten()
        .zip(b.iter().flatten())
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn frame_dist(a: &Frame, b: &Frame) -> f64 {
    a.to_homogeneous()
        .iter()
        .flatten()
        .zip(b.to_homogeneous().iter().flatten())
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn r(axis: Axis, deg: f64) -> Matrix {
    elementary(axis, deg)
}

/// The worked numbers of docs/dialects.md (printed to six decimals).
#[allow(clippy::approx_constant)]
const SPATIAL_27_0_45: Matrix = [
    [0.707107, -0.630037, 0.321020],
    [0.707107, 0.630037, -0.321020],
    [0.0, 0.453990, 0.891007],
];
const ROTS_X30_Y20: Matrix = [
    [0.939693, 0.163099, 0.300627],
    [0.0, 0.878973, -0.476871],
    [-0.342020, 0.448112, 0.825965],
];
const EULER_45_20_22: Matrix = [
    [0.406706, -0.880966, 0.241845],
    [0.904530, 0.351193, -0.241845],
    [0.128123, 0.317116, 0.939693],
];

#[test]
fn heidenhain_reads_the_worked_numbers_with_real_line_words() {
    let d = Dialect::Heidenhain;
    let f = rot(
        d,
        &["5 PLANE SPATIAL SPA+27 SPB+0 SPC+45 TURN MB MAX FMAX SEQ-"],
    );
    assert!(dist(&f, &SPATIAL_27_0_45) < 1e-6);
    let f = rot(
        d,
        &["12 plane spatial spc+45 spa+27 spb+0 stay ; words in any order"],
    );
    assert!(dist(&f, &SPATIAL_27_0_45) < 1e-6);
    let f = rot(
        d,
        &["PLANE EULER EULPR45 EULNU20 EULROT22 MOVE DIST50 F1000 SYM+ COORD ROT"],
    );
    assert!(dist(&f, &EULER_45_20_22) < 1e-6);
    // ABST: the same word in the German dialog (it was refused as unknown).
    let p = read(
        d,
        &["PLANE EULER EULPR45 EULNU20 EULROT22 MOVE ABST50 F1000 SYM+ COORD ROT"],
    );
    assert!(dist(&p.frame.rotation, &EULER_45_20_22) < 1e-6);
    assert_eq!((p.positioning, p.feed_mm_min), (Positioning::Move, 1000.0));
    // PROJECTED: PROPR in ZX, PROMIN in YZ, as ROTS Y=PROPR X=PROMIN.
    let f = rot(
        d,
        &["PLANE PROJECTED PROPR+20 PROMIN+30 ROT+0 TABLE ROT STAY"],
    );
    assert!(dist(&f, &ROTS_X30_Y20) < 1e-6);
    // The TNC's own word for the turn is PROROT (its manual's example block, as EULROT is
    // PLANE EULER's): the same plane; both words at once refused.
    let f = rot(
        d,
        &["PLANE PROJECTED PROPR+20 PROMIN+30 PROROT+0 MOVE ABST10 F500"],
    );
    assert!(dist(&f, &ROTS_X30_Y20) < 1e-6);
    let f = rot(d, &["PLANE PROJECTED PROMIN+0 PROPR+0 PROROT+30 STAY"]);
    assert!(dist(&f, &r(Axis::Z, 30.0)) < 1e-15);
    let e = Program::default()
        .line(d, b"PLANE PROJECTED PROPR+20 PROMIN+30 PROROT+0 ROT+0 STAY")
        .unwrap_err();
    assert_eq!(e.error, Error::UnknownWord);
    // RELATIV turns about the tilted axis: SPB30, then about the new X by 20.
    let f = rot(
        d,
        &[
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
            "PLANE RELATIV SPA+20 STAY",
        ],
    );
    assert!(dist(&f, &mul(&r(Axis::Y, 30.0), &r(Axis::X, 20.0))) < 1e-15);
    // POINTS: X' from P1 to P2, Z' to P3's side; the datum is not moved (P1 is a point of
    // the plane, not its origin).
    let p = read(
        d,
        &["PLANE POINTS P1X+10 P1Y+0 P1Z+0 P2X+10 P2Y+5 P2Z+0 P3X+0 P3Y+0 P3Z+0 STAY"],
    );
    // Z' = (0, 5, 0) × (−10, 0, 0) / 50 = +Z, Y' = Z' × X' = −X.
    assert_eq!(
        p.frame.rotation,
        [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    );
    assert_eq!(p.frame.translation, [0.0; 3]);
    // VECTOR: N is Z', B (made perpendicular) X'.
    let f = rot(d, &["PLANE VECTOR BX+0 BY+1 BZ+0 NX+0 NY+0 NZ+2 STAY"]);
    assert_eq!(f, r(Axis::Z, 90.0));
    let p = read(
        d,
        &[
            "BEGIN PGM TILT MM",
            "; comment",
            "* - structure",
            "7 PLANE SPATIAL SPA+10 SPB+0 SPC+0 STAY",
            "8 PLANE RESET STAY",
            "END PGM TILT MM",
        ],
    );
    assert_eq!(p.frame, Frame::IDENTITY);
}

#[test]
fn sinumerik_frames_cycles_and_readback() {
    let d = Dialect::Sinumerik;
    assert!(dist(&rot(d, &["N10 ROTS X30 Y20"]), &ROTS_X30_Y20) < 1e-6);
    assert!(dist(&rot(d, &["N10 CROTS Y=20 X=30 ; any order"]), &ROTS_X30_Y20) < 1e-6);
    // The manual's projection check: CYCLE800 in projection mode (_MODE 128 + 57) equals ROTS.
    let f = rot(
        d,
        &["N20 CYCLE800(1,\"TC1\",0,185,0,0,0,30,20,0,0,0,0,-1,100,1)"],
    );
    assert!(dist(&f, &ROTS_X30_Y20) < 1e-6);
    // RPY: F = Rz(z)·Ry(y)·Rx(x), whatever the word order; AROT on the right.
    let f = rot(d, &["ROT Z=30 X=10 Y=-20", "AROT Z15"]);
    let want = mul(
        &mul(
            &mul(&r(Axis::Z, 30.0), &r(Axis::Y, -20.0)),
            &r(Axis::X, 10.0),
        ),
        &r(Axis::Z, 15.0),
    );
    assert!(dist(&f, &want) < 1e-15);
    // TRANS then AROT rotates about the translated origin.
    let p = read(d, &["TRANS X10", "AROT Z90"]);
    assert_eq!(p.frame.translation, [10.0, 0.0, 0.0]);
    assert_eq!(p.frame.rotation, r(Axis::Z, 90.0));
    // ROT replaces the whole programmable frame; ROT and CROT without words cancel.
    assert_eq!(
        read(d, &["TRANS X10", "ROT Z90"]).frame.translation,
        [0.0; 3]
    );
    assert_eq!(read(d, &["ROT Z90", "ROT"]).frame, Frame::IDENTITY);
    assert_eq!(read(d, &["ROT Z90", "CROT"]).frame, Frame::IDENTITY);
    // CYCLE800: two additive calls about Y by 10 equal one by 20 (_ST units digit 1).
    let two = rot(
        d,
        &[
            "CYCLE800(0,\"\",0,57,0,0,0,0,10,0,0,0,0,-1)",
            "CYCLE800(0,\"\",1,57,0,0,0,0,10,0,0,0,0,-1)",
        ],
    );
    assert!(dist(&two, &r(Axis::Y, 20.0)) < 1e-15);
    // Empty arguments count as 0; _TC="0" and CYCLE800() deselect.
    let p = read(d, &["CYCLE800(,,,27,10,,,,90,,,,,-1,,)"]);
    assert_eq!(p.frame.translation, [10.0, 0.0, 0.0]);
    assert_eq!(p.frame.rotation, r(Axis::Y, 90.0));
    assert_eq!(
        read(d, &["CYCLE800(,,,27,10,,,,90,,,,,-1,,)", "CYCLE800()"]).frame,
        Frame::IDENTITY
    );
    assert_eq!(
        read(
            d,
            &[
                "CYCLE800(,,,27,10,,,,90,,,,,-1,,)",
                "CYCLE800(0,\"0\",0,57,0,0,0,0,0,0,0,0,0,1)"
            ]
        )
        .frame,
        Frame::IDENTITY
    );
    // The paper's Example 3: CYCLE600 turns the probe angles (extrinsic X, Y, Z = 30, 45,
    // 60) into intrinsic Z, X', Y'' = 37.7923, 20.7048, 49.1066 for CYCLE800; both lines,
    // and PLANE SPATIAL with the same probe angles, are the same plane.
    let a = rot(
        d,
        &["N120 CYCLE600(0, \"UFK600\", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)"],
    );
    let b = rot(
        d,
        &["N130 CYCLE800(0,\"\",0,39,0,0,0,37.7923,20.7048,49.1066,0,0,0,-1)"],
    );
    let c = rot(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA+30 SPB+45 SPC+60 STAY"],
    );
    assert!(dist(&a, &b) < 1e-5 && dist(&a, &c) < 1e-15);
    // Labels, main block numbers, skip marks, lower case, EX exponents.
    let f = rot(d, &["/N10 TILT: rot z=3ex1"]);
    assert!(dist(&f, &r(Axis::Z, 30.0)) < 1e-15);
    assert_eq!(
        read(d, &[":100 ; main block", "", "N5"]).frame,
        Frame::IDENTITY
    );
}

#[test]
fn sinumerik_reads_back_as_the_control_does() {
    // The manual: CROT(x,10,y,90,z,40) reads back x 0, y 90, z 30;
    // CROT(x,190,y,0,z,-200) reads back x -170, y 0, z 160.
    let d = Dialect::Sinumerik;
    let mut buf = [0u8; 128];
    for (line, want) in [
        ("ROT X10 Y90 Z40", "ROT X=0 Y=90 Z=30"),
        ("ROT X190 Y0 Z-200", "ROT X=-170 Y=0 Z=160"),
    ] {
        let f = read(d, &[line]).frame;
        let (n, _) = write_line(d, b"ROT", &f, 6, &mut buf).unwrap();
        assert_eq!(std::str::from_utf8(&buf[..n]).unwrap(), want);
    }
}

/// A datum shift programmed under a tilt shifts the tilted coordinate system (TNC 620:
/// cycle 7 before tilting is the workpiece system's, "the result … depends on the
/// programming sequence"; TNC7: `TRANS DATUM` among the transformations "after having
/// tilted the working plane"). By hand: SPB+30 is Ry(30°), whose X' is (cos 30°, 0, −sin 30°):
/// X+10 along it puts the datum at (8.6603, 0, −5). The axes the block does not name keep
/// their place along the tilted axes; the shift stays where it was put when the tilt is
/// cancelled [choice].
#[test]
fn heidenhain_shift_under_a_tilt_is_along_the_tilted_axes() {
    let d = Dialect::Heidenhain;
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    for shift in [
        &["CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X+10"][..],
        &["TRANS DATUM AXIS X+10"],
    ] {
        let mut lines = vec!["PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY"];
        lines.extend_from_slice(shift);
        let p = read(d, &lines);
        let t = p.frame.translation;
        assert!(
            (t[0] - 10.0 * c).abs() < 1e-12
                && t[1].abs() < 1e-12
                && (t[2] + 10.0 * s).abs() < 1e-12,
            "{shift:?}: {t:?}"
        );
        assert!(dist(&p.frame.rotation, &r(Axis::Y, 30.0)) < 1e-15);
        let q = p.line(d, b"PLANE RESET STAY").unwrap().0;
        assert_eq!(q.frame.translation, t);
    }
    // Y+5 under the tilt after X+10 before it: X+10 keeps its place, Y is Y' here.
    let p = read(
        d,
        &[
            "CYCL DEF 7.1 X+10",
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
            "CYCL DEF 7.2 Y+5",
        ],
    );
    let t = p.frame.translation;
    assert!(
        (t[0] - 10.0).abs() < 1e-12 && (t[1] - 5.0).abs() < 1e-12 && t[2].abs() < 1e-12,
        "{t:?}"
    );
    // Untilted as before.
    assert_eq!(
        read(d, &["CYCL DEF 7.1 X+10"]).frame.translation,
        [10.0, 0.0, 0.0]
    );
}

#[test]
fn twincat_the_manuals_examples() {
    let d = Dialect::Twincat;
    let p = read(d, &["N65 ROT Z30", "N90 AROT Z15"]);
    assert_eq!(p.angles, [0.0, 0.0, 45.0]);
    assert!(dist(&p.frame.rotation, &r(Axis::Z, 45.0)) < 1e-15);
    // After ROT Z45, CalcInvRot of (40, 10, 0) is (35.36, -21.21, 0): Fᵀ·v.
    let f = rot(d, &["N30 ROT Z45 (rotate)"]);
    let v = [40.0, 10.0, 0.0];
    let back: Vec<f64> = (0..3)
        .map(|k| (0..3).map(|i| f[i][k] * v[i]).sum())
        .collect();
    assert!((back[0] - 35.3553).abs() < 1e-4 && (back[1] + 21.2132).abs() < 1e-4);
    // Z, then Y, then X about the global axes, whatever the word order: F = Rx·Ry·Rz.
    let f = rot(d, &["ROT Z30 X10 Y20"]);
    let want = mul(
        &mul(&r(Axis::X, 10.0), &r(Axis::Y, 20.0)),
        &r(Axis::Z, 30.0),
    );
    assert!(dist(&f, &want) < 1e-15);
    assert_eq!(read(d, &["N110 ROT X90", "ROT"]).frame, Frame::IDENTITY);
    assert_eq!(
        read(d, &["N10 RotExOn", "N1000 RotExOff"]).frame,
        Frame::IDENTITY
    );
    // The manual's example of a zero offset shift and rotation: "the total zero offset shift
    // currently active describes the rotation centre". G58 sets its translation whole (Y0
    // named, Z omitted: 0); the rotation stays about the datum as the shift moves.
    let p = read(d, &["N20 G55", "N30 G58 X200 Y0"]);
    assert_eq!(
        p.frame,
        Frame::with_translations([200.0, 0.0, 0.0], cncrot::IDENTITY, [0.0; 3])
    );
    let p = read(d, &["N30 G58 X200 Y0", "N60 G58 X200 Y200", "N65 ROT Z30"]);
    assert_eq!(p.frame.translation, [200.0, 200.0, 0.0]);
    assert!(dist(&p.frame.rotation, &r(Axis::Z, 30.0)) < 1e-15);
    let q = read(
        d,
        &[
            "N60 G58 X200 Y200",
            "N65 ROT Z30",
            "N80 G58 X0 Y200",
            "N90 AROT Z15",
        ],
    );
    assert_eq!(
        (q.shift, q.frame.translation),
        ([0.0, 200.0, 0.0], [0.0, 200.0, 0.0])
    );
    assert!(dist(&q.frame.rotation, &r(Axis::Z, 45.0)) < 1e-15);
    // ROT alone ends the rotation, not the shift; G58 X0 Y0 Z0 ends the shift.
    let u = read(d, &["G58 X1 Y2 Z3", "ROT Y30", "ROT"]);
    assert_eq!(
        u.frame,
        Frame::with_translations([1.0, 2.0, 3.0], cncrot::IDENTITY, [0.0; 3])
    );
    assert_eq!(
        read(d, &["G58 X1 Y2 Z3", "G58 X0 Y0 Z0"]).frame,
        Frame::IDENTITY
    );
    let e = Program::default().line(d, b"N10 G58").unwrap_err();
    assert_eq!((e.error, e.column), (Error::MissingWord, 8));
    let e = Program::default().line(d, b"G58 X1 A2").unwrap_err();
    assert_eq!((e.error, e.column), (Error::UnknownWord, 8));
}

#[test]
fn syntec_the_manuals_examples() {
    let d = Dialect::Syntec;
    // "translated first X2 Y0 Z10, then 20° about X, 20° about Y, -30° about Z, then
    // U V W in the rotated system".
    let p = read(d, &["G158 L1 P10157 X2. Y0. Z10. A20 B20 C-30 U0 V10 W0"]);
    let m = mul(
        &mul(&r(Axis::X, 20.0), &r(Axis::Y, 20.0)),
        &r(Axis::Z, -30.0),
    );
    let want = Frame::with_translations([2.0, 0.0, 10.0], m, [0.0, 10.0, 0.0]);
    assert!(frame_dist(&p.frame, &want) < 1e-14);
    // "Increment and then turn the XY plane to 10 degrees": twice is 20.
    let f = rot(
        d,
        &[
            "G158 L3 P01159 X0 Y0 Z0 A0 B0 C10 U0 V0 W0",
            "G158 L3 P01159 X0 Y0 Z0 A0 B0 C10 U0 V0 W0 ;Increment",
        ],
    );
    assert!(dist(&f, &r(Axis::Z, 20.0)) < 1e-15);
    // Mode 4: F = Ry(-A)·Rx(B)·Rz(C).
    let f = rot(d, &["G158 P10400 X0 Y0 Z0 A20. B30. C15. U0 V0 W0"]);
    let want = mul(
        &mul(&r(Axis::Y, -20.0), &r(Axis::X, 30.0)),
        &r(Axis::Z, 15.0),
    );
    assert!(dist(&f, &want) < 1e-15);
    // Mode 2: the positions of the axes A, B, C, which the machine turns to, about the
    // origin X Y Z; the frame needs the machine.
    let (p, _) = Program::default()
        .line(d, b"G158 L3 P10200 X0 Y0 Z10 A0 B20 C45 U0 V0 W0")
        .unwrap();
    let direct = Direct {
        by: DirectAxes::Letters,
        given: 0b111,
    };
    assert_eq!((p.direct, p.angles), (Some(direct), [0.0, 20.0, 45.0]));
    assert_eq!(
        p.frame,
        Frame::with_translations([0.0, 0.0, 10.0], cncrot::IDENTITY, [0.0; 3])
    );
    assert_eq!(p.positioning, Positioning::Turn);
    // Incremental, or with U V W after a rotation only the machine knows: not read.
    for line in ["G158 P01200 A0 B20 C45", "G158 P10200 A0 B20 C45 U0 V5 W0"] {
        let e = Program::default().line(d, line.as_bytes()).unwrap_err();
        assert_eq!((e.error, e.column), (Error::NotAvailable, 1), "{line}");
    }
    // Syntec's G68.2 mode reads Fanuc's words; G158 alone and G69 cancel.
    assert!(dist(&rot(d, &["G68.2 X0 Y0 Z0 I0 J30 K0"]), &r(Axis::X, 30.0)) < 1e-15);
    assert_eq!(read(d, &["G68.2 J30", "G69"]).frame, Frame::IDENTITY);
    assert_eq!(read(d, &["G158 P10157 A30", "G158"]).frame, Frame::IDENTITY);
}

/// Fanuc's three-dimensional coordinate conversion, against hand derivation: `R` about
/// `I J K` through `X Y Z`, right-handed, a second one in the converted system.
#[test]
fn fanuc_coordinate_conversion() {
    let d = Dialect::Fanuc;
    // Ry(45°) about (10, 0, 0): the origin moves to c − Ry(45°)·c = (10 − 5√2, 0, 5√2).
    let p = read(d, &["N10 G90 G68 X10. Y0 Z0 I0. J1. K0. R45."]);
    assert!(dist(&p.frame.rotation, &r(Axis::Y, 45.0)) < 1e-15);
    let h = 5.0 * 2f64.sqrt();
    let want = [10.0 - h, 0.0, h];
    assert!((0..3).all(|k| (p.frame.translation[k] - want[k]).abs() < 1e-13));
    // Right-handed about +Z (X turns onto Y), whatever the length of I J K; the second
    // conversion about the converted X: Rz(90°)·Rx(30°).
    let f = rot(
        d,
        &["G68 X0 Y0 Z0 I0 J0 K5 R90.", "G68 X0 Y0 Z0 I1. J0 K0 R30."],
    );
    assert!(dist(&f, &mul(&r(Axis::Z, 90.0), &r(Axis::X, 30.0))) < 1e-15);
    assert_eq!(
        read(d, &["G68 X0 Y0 Z0 I0 J0 K1 R90.", "G69"]).frame,
        Frame::IDENTITY
    );
    // After a local shift: about the shifted datum.
    let p = read(d, &["G52 X10.", "G68 X0 Y0 Z0 I0 J0 K1 R90."]);
    assert_eq!(p.frame.translation, [10.0, 0.0, 0.0]);
    assert!(dist(&p.frame.rotation, &r(Axis::Z, 90.0)) < 1e-15);
    // The control's alarms: I J K all 0, no R.
    let e = Program::default()
        .line(d, b"G68 X0 Y0 Z0 I0 J0 K0 R3.")
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::BadArgument, 15)); // at the value of I
    let e = Program::default()
        .line(d, b"G68 X0 Y0 Z0 I0 J1 K0")
        .unwrap_err();
    assert_eq!(e.error, Error::MissingWord);
    // What the state cannot know: the tool's position as the centre. Haas and Syntec have
    // no such conversion.
    for (d, line) in [
        (Dialect::Fanuc, "G68 I0 J1. K0 R30."),
        (Dialect::Fanuc, "G68 X0 Y0 I0 J1. K0 R30."),
        (Dialect::Haas, "G68 X0 Y0 Z0 I0 J0 K1 R90."),
        (Dialect::Syntec, "G68 X0 Y0 Z0 I0 J0 K1 R90."),
        // TwinCAT CNC's contour rotation in the plane (Beckhoff's TF5200 manual, "Rotate
        // the coordinate system in the plane"): not the state's, flagged.
        (Dialect::Twincat, "G68 R30 X0 Y0"),
        (Dialect::Twincat, "#ROTATION ON [ANGLE=30]"),
    ] {
        let (_, remark) = Program::default().line(d, line.as_bytes()).unwrap();
        assert_eq!(remark, Remark::NotFollowed, "{line}");
    }
}

/// Rotations in the working plane, against hand derivation: about Z, Y, X for G17, G18,
/// G19, the plane kept by the state.
#[test]
fn rotations_in_the_plane() {
    use cncrot::dialects::program::Plane;
    let d = Dialect::Sinumerik;
    // ROT replaces, AROT adds: 30 + 10 about Z.
    let p = read(d, &["ROT RPL=30", "AROT RPL=10"]);
    assert!(dist(&p.frame.rotation, &r(Axis::Z, 40.0)) < 1e-15);
    // G18 (a plane selection: applied, the frame unchanged), then about Y.
    let (q, remark) = p.line(d, b"N20 G18 G0 X0").unwrap();
    assert_eq!(
        (remark, q.plane, q.frame),
        (Remark::Applied, Plane::Zx, p.frame)
    );
    let q = q.line(d, b"AROT RPL = -45.5 ; in the plane").unwrap().0;
    let want = mul(&r(Axis::Z, 40.0), &r(Axis::Y, -45.5));
    assert!(dist(&q.frame.rotation, &want) < 1e-15);
    // G19: ROT RPL=90 alone, Rx(90°): the tool (0, -1, 0).
    let q = read(d, &["G19", "ROT RPL=90"]);
    assert_eq!(q.frame.rotation, r(Axis::X, 90.0));
    // The plane a passed block leaves: a selection of the same plane is passed over.
    assert_eq!(q.line(d, b"G19 G1 Y10").unwrap().1, Remark::Passed);

    // Fanuc-style G68 X Y R: about the plane's normal through the centre its words give.
    let d = Dialect::Fanuc;
    // Rz(90°) about (10, 0): the origin c − Rz·c = (10, −10, 0).
    let p = read(d, &["G68 X10. Y0 R90."]);
    assert_eq!(p.frame.translation, [10.0, -10.0, 0.0]);
    assert_eq!(p.frame.rotation, r(Axis::Z, 90.0));
    // A G68 again changes centre and angle; G69 cancels.
    let p = read(d, &["G68 X10. Y0 R90.", "G68 X0 Y0 R30."]);
    assert_eq!(p.frame.translation, [0.0; 3]);
    assert!(dist(&p.frame.rotation, &r(Axis::Z, 30.0)) < 1e-15);
    assert_eq!(read(d, &["G68 X0 Y0 R30.", "G69"]).frame, Frame::IDENTITY);
    // G18 G68 Z X R on one block: Ry(30°) about (10, 0, 0): c − Ry·c = (10 − 5√3, 0, 5).
    let p = read(d, &["N10 G18 G68 Z0 X10. R30."]);
    assert_eq!(p.plane, Plane::Zx);
    assert!(dist(&p.frame.rotation, &r(Axis::Y, 30.0)) < 1e-15);
    let want = [10.0 - 5.0 * 3f64.sqrt(), 0.0, 5.0];
    assert!((0..3).all(|k| (p.frame.translation[k] - want[k]).abs() < 1e-13));
    // Syntec writes the same form.
    let s = read(Dialect::Syntec, &["G68 X10. Y0 R90."]);
    assert_eq!(s.frame, read(d, &["G68 X10. Y0 R90."]).frame);
    // Not followed: a centre word missing, no R, the third axis, G91, a tilt not in the
    // plane; Haas (its G69 cancels only G68, which the state cannot tell from a G268).
    for (d, lines) in [
        (d, &["G68 X0 R30."][..]),
        (d, &["G68 X0 Y0"]),
        (d, &["G68 X0 Y0 Z0 R30."]),
        (d, &["G91 G68 X0 Y0 R30."]),
        (d, &["G68.2 X0 Y0 Z0 I0 J30. K0", "G68 X0 Y0 R30."]),
        (Dialect::Haas, &["G68 X0 Y0 R30."]),
    ] {
        let (last, before) = lines.split_last().unwrap();
        let p = read(d, before);
        let (q, remark) = p.line(d, last.as_bytes()).unwrap();
        assert_eq!((remark, q), (Remark::NotFollowed, p), "{lines:?}");
    }
}

#[test]
fn fanuc_and_haas() {
    let d = Dialect::Fanuc;
    let p = read(d, &["%", "N10 G68.2 X10. Y0 Z0 I0 J30. K0 (TILT)"]);
    assert_eq!(p.frame.translation, [10.0, 0.0, 0.0]);
    assert!(dist(&p.frame.rotation, &r(Axis::X, 30.0)) < 1e-15);
    // I J K: Z, X', Z''.
    let f = rot(d, &["g68.2 i30 j45 k60", "G53.1"]);
    let want = mul(
        &mul(&r(Axis::Z, 30.0), &r(Axis::X, 45.0)),
        &r(Axis::Z, 60.0),
    );
    assert!(dist(&f, &want) < 1e-15);
    // Two G68.4 by 15 are one G68.2 by 30.
    let f = rot(d, &["G68.4 I0 J15 K0", "G68.4 I0 J15 K0"]);
    assert!(dist(&f, &r(Axis::X, 30.0)) < 1e-15);
    assert_eq!(read(d, &["G68.2 J30", "G69"]).frame, Frame::IDENTITY);
    // G53.1 and G53.6 turn the tool onto the plane (G53.6 keeping the tool tip): the frame
    // stays, the state says how the machine moves; words after them are not theirs.
    let tilted = read(d, &["G68.2 X5 J30"]);
    assert_eq!(tilted.positioning, Positioning::Stay);
    let moved = Program {
        positioning: Positioning::Move,
        ..tilted
    };
    assert_eq!(read(d, &["G68.2 X5 J30", "G53.6"]), moved);
    let turned = Program {
        positioning: Positioning::Turn,
        ..tilted
    };
    assert_eq!(read(d, &["G68.2 X5 J30", "N20 G53.1 (turn)"]), turned);
    // Without a tilt the axes turn to the untilted plane (after a G68.2 of zeros; without
    // one the control raises an alarm); a new tilt states its own way.
    assert_eq!(read(d, &["G53.1"]).positioning, Positioning::Turn);
    assert_eq!(
        read(d, &["G68.2 J30", "G53.1", "G68.2 J40"]).positioning,
        Positioning::Stay
    );
    let e = tilted.line(d, b"G53.6 X1").unwrap_err();
    assert_eq!((e.error, e.column), (Error::UnknownWord, 7));
    // `G53.6 H<n>`: the tool offset whose tip stays (a generator writes it); no frame word,
    // and the same state as without it. `G53.1` turns about the pivot: no `H`.
    assert_eq!(read(d, &["G68.2 X5 J30", "G53.6 H12 (ORIENT TOOL)"]), moved);
    assert_eq!(read(d, &["G68.2 X5 J30", "G53.6 P0 H0"]), moved);
    let e = tilted.line(d, b"G53.6 H-1").unwrap_err();
    assert_eq!((e.error, e.column), (Error::BadArgument, 8));
    let e = tilted.line(d, b"G53.6 H1.5").unwrap_err();
    assert_eq!((e.error, e.column), (Error::BadArgument, 8));
    let e = tilted.line(d, b"G53.1 H1").unwrap_err();
    assert_eq!((e.error, e.column), (Error::UnknownWord, 7));
    // A tilt beside a work offset (`G54 G68.2 …`): the frame is one the library does not
    // follow, as with a cancel beside one; a tilt after another word stays misplaced.
    let block = b"N10 G0 G90 G54 G68.2 X0. Y0. Z0. I0. J90. K0.";
    assert_eq!(
        Program::default().line(d, block).unwrap(),
        (Program::default(), Remark::NotFollowed)
    );
    let e = Program::default()
        .line(d, b"N10 G0 X10. G68.2 X0. J90.")
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::UnknownWord, 13));
    // `G68.3`: the plane of the tool direction where the machine stands, which the program
    // does not state: not followed, the state unchanged; its words checked.
    let (p, remark) = tilted.line(d, b"G68.3 X10 Y0 Z0 R30").unwrap();
    assert_eq!((p, remark), (tilted, Remark::NotFollowed));
    let e = Program::default().line(d, b"G68.3 R0 A1").unwrap_err();
    assert_eq!((e.error, e.column), (Error::UnknownWord, 10));

    let d = Dialect::Haas;
    // Fanuc's tilts are no Haas commands (a Haas writes `G268`): a Fanuc program read as a
    // Haas one is flagged, not passed over.
    for fanuc in ["G68.2 X0 Y0 Z0 I0 J45 K0", "G68.4 J10", "G68.3 R0"] {
        let (q, remark) = Program::default().line(d, fanuc.as_bytes()).unwrap();
        assert_eq!(
            (q, remark),
            (Program::default(), Remark::NotFollowed),
            "{fanuc}"
        );
    }
    let f = rot(d, &["G268 X0 Y0 Z0 I0 J30 K0 Q123"]);
    assert!(dist(&f, &r(Axis::Y, 30.0)) < 1e-15);
    // Q321 and Q123 agree on a turn about Z alone.
    assert_eq!(rot(d, &["G268 K40 Q321"]), rot(d, &["G268 K40 Q123"]));
    // About the fixed axes: F = Rz(K)·Ry(J)·Rx(I) with Q123.
    let f = rot(d, &["G268 I10 J20 K30 Q123"]);
    let want = mul(
        &mul(&r(Axis::Z, 30.0), &r(Axis::Y, 20.0)),
        &r(Axis::X, 10.0),
    );
    assert!(dist(&f, &want) < 1e-15);
    assert_eq!(
        read(d, &["G268 J30 Q123", "G253", "G269"]).frame,
        Frame::IDENTITY
    );
}

/// Every refusal leaves the state as it was and names the column of the first bad
/// character (1-based; one past the end for something missing at the end).
#[test]
fn refusals_name_their_column() {
    let active = read(Dialect::Sinumerik, &["ROT Z30"]);
    let cases: [(Dialect, &str, Error, &str); 37] = [
        (Dialect::Sinumerik, "ROT X=R1", Error::NotANumber, "R1"),
        (Dialect::Sinumerik, "ROT X10 A5", Error::UnknownWord, "A5"),
        (Dialect::Sinumerik, "ROT X10 X20", Error::UnknownWord, "X20"),
        (Dialect::Sinumerik, "ROT X=10+5", Error::NotANumber, "+5"),
        (Dialect::Sinumerik, "ROT X1.2.3", Error::Parse, ".3"),
        // A frame command stands at the start of its block.
        (
            Dialect::Sinumerik,
            "G1 X10 ROT Z30",
            Error::UnknownWord,
            "ROT",
        ),
        (Dialect::Sinumerik, "AROT", Error::MissingWord, ""),
        // Direct mode with a `_C` (a swivel data set has two axes) or a `_X1`.
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0,192,0,0,0,0,30,5,0,0,0,-1)",
            Error::NotAvailable,
            "5,",
        ),
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0,192,0,0,0,0,30,0,7,0,0,-1)",
            Error::NotAvailable,
            "7,",
        ),
        (Dialect::Heidenhain, "PLANE AXIAL", Error::MissingWord, ""),
        (
            Dialect::Heidenhain,
            "PLANE AXIAL B+30 B+40",
            Error::UnknownWord,
            "B+40",
        ),
        (
            Dialect::Heidenhain,
            "PLANE AXIAL B+30 X+40",
            Error::UnknownWord,
            "X+40",
        ),
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0,300,0,0,0,0,30,0,0,0,0,-1)",
            Error::BadArgument,
            "300",
        ),
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0,57,0,0,0,_A,30,0,0,0,0,-1)",
            Error::NotANumber,
            "_A",
        ),
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0)",
            Error::MissingWord,
            "",
        ),
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0,57",
            Error::MissingWord,
            "",
        ),
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL SPA+Q120 SPB+0 SPC+0",
            Error::NotANumber,
            "Q120",
        ),
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL SPA+0 SPB+0",
            Error::MissingWord,
            "",
        ),
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL SPA+0 SPB+0 SPC+0 WARP",
            Error::UnknownWord,
            "WARP",
        ),
        (
            Dialect::Heidenhain,
            "PLANE WARPED SPA+0",
            Error::UnknownWord,
            "WARPED",
        ),
        // A word the command does not have is unknown, not a missing one.
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL SPX+10 SPB+0 SPC+0 STAY",
            Error::UnknownWord,
            "SPX",
        ),
        (
            Dialect::Heidenhain,
            "PLANE VECTOR BX+1 BY+0 BZ+0 NX+1 NY+0 NZ+0",
            Error::Degenerate,
            "VECTOR",
        ),
        (
            Dialect::Fanuc,
            "G68.2 X0 Y0 Z0 I0 J#100 K0",
            Error::NotANumber,
            "#100",
        ),
        (
            Dialect::Fanuc,
            "G68.2 X0 P7 Q123",
            Error::BadArgument,
            "7 Q",
        ),
        (Dialect::Fanuc, "G68.2 X0 P1.5", Error::BadArgument, "1.5"),
        (Dialect::Fanuc, "G53.1 P1 X1", Error::UnknownWord, "X1"),
        (Dialect::Haas, "G268 X0 I0 J30 K0", Error::MissingWord, ""),
        (Dialect::Twincat, "ROT Z30 G1", Error::UnknownWord, "G1"),
        // A bad value is reported where it stands, not at its command.
        (Dialect::Haas, "G268 Q123.5", Error::BadArgument, "123.5"),
        (Dialect::Haas, "G268 X1 Q0", Error::BadSequence, "0"),
        (Dialect::Syntec, "G158 X0 P157", Error::BadArgument, "157"),
        (
            Dialect::Sinumerik,
            "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,2,39)",
            Error::BadFlag,
            "2,39",
        ),
        (
            Dialect::Sinumerik,
            "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39,0,5)",
            Error::BadFlag,
            "5)",
        ),
        // An unclosed comment is malformed text, not an unknown word.
        (
            Dialect::Fanuc,
            "G68.2 X1 (comment",
            Error::Parse,
            "(comment",
        ),
        (Dialect::Haas, "G269 (comment", Error::Parse, "(comment"),
        (
            Dialect::Twincat,
            "ROT Z30 (comment",
            Error::Parse,
            "(comment",
        ),
        // A closed comment with words after it: the words are not the comment's.
        (
            Dialect::Fanuc,
            "G68.2 X1 (c) Y2",
            Error::UnknownWord,
            "(c) Y2",
        ),
    ];
    for (d, line, error, at) in cases {
        let p = Program {
            dialect: Some(d),
            ..active
        };
        let before = p;
        let e = p.line(d, line.as_bytes()).expect_err(line);
        let column = if at.is_empty() {
            line.len() + 1
        } else {
            line.find(at).unwrap() + 1
        };
        assert_eq!((e.error, e.column), (error, column), "{line}");
        assert_eq!(p, before);
    }
    // Too long for the controller: SINUMERIK's 512 bytes, the others' 256 (Heidenhain 254).
    let long = format!("ROT Z30 ;{}", "x".repeat(503));
    assert_eq!(long.len(), 512);
    assert!(Program::default()
        .line(Dialect::Sinumerik, long.as_bytes())
        .is_ok());
    let longer = format!("{long}x");
    assert_eq!(
        Program::default().line(Dialect::Sinumerik, longer.as_bytes()),
        Err(LineError {
            error: Error::LineTooLong,
            column: 513,
            expected: None,
        })
    );
    // Non-ASCII and control bytes are words no dialect has.
    let e = Program::default()
        .line(Dialect::Fanuc, "G68.2 J30 \u{b0}".as_bytes())
        .unwrap_err();
    assert_eq!(
        e,
        LineError {
            error: Error::UnknownWord,
            column: 11,
            expected: None,
        }
    );
}

/// The forms each dialect writes.
const FORMS: [(Dialect, &str); 14] = [
    (Dialect::Sinumerik, "CYCLE800"),
    (Dialect::Sinumerik, "CYCLE800 27"),
    (Dialect::Sinumerik, "CYCLE800 64"),
    (Dialect::Sinumerik, "ROT"),
    (Dialect::Heidenhain, "PLANE SPATIAL"),
    (Dialect::Heidenhain, "PLANE EULER"),
    (Dialect::Heidenhain, "PLANE VECTOR"),
    (Dialect::Heidenhain, "PLANE POINTS"),
    (Dialect::Fanuc, "G68.2"),
    (Dialect::Syntec, "G158"),
    (Dialect::Syntec, "G158 P10139"),
    (Dialect::Syntec, "G68.2"),
    (Dialect::Twincat, "ROT"),
    (Dialect::Haas, "G268 Q321"),
];

/// Whether a form carries an origin.
fn has_origin(form: &str) -> bool {
    !matches!(
        form,
        "ROT" | "PLANE SPATIAL" | "PLANE EULER" | "PLANE VECTOR" | "PLANE POINTS"
    )
}

/// Random frames, and the singular ones: middle angles of ±90 and 0/180 in each
/// dialect's convention, from the rotations that put a new axis on an old one.
fn frames() -> Vec<Frame> {
    let mut rng = Rng::new(0x1234_5678_9ABC_DEF1);
    let mut out = Vec::new();
    for _ in 0..60 {
        let a = [0; 3].map(|_| rng.range(-180.0, 180.0));
        let m = mul(
            &mul(&r(Axis::Z, a[0]), &r(Axis::Y, a[1] / 2.0)),
            &r(Axis::X, a[2]),
        );
        let t = [0; 3].map(|_| rng.range(-200.0, 200.0));
        out.push(Frame::with_translations(t, m, [0.0; 3]));
    }
    for (axis, deg) in [
        (Axis::Y, 90.0),
        (Axis::Y, -90.0),
        (Axis::X, 90.0),
        (Axis::X, 0.0),
        (Axis::X, 180.0),
    ] {
        for twist in [0.0, 25.0, -130.0] {
            let m = mul(
                &mul(&r(Axis::Z, twist), &r(axis, deg)),
                &r(Axis::Z, 40.0 - twist),
            );
            out.push(Frame::with_translations([5.0, -2.0, 1.0], m, [0.0; 3]));
        }
    }
    out
}

fn write(d: Dialect, form: &str, f: &Frame, decimals: i32) -> Result<String, Error> {
    let mut buf = [0u8; 512];
    let (n, _) = write_line(d, form.as_bytes(), f, decimals, &mut buf)?;
    Ok(String::from_utf8(buf[..n].to_vec()).unwrap())
}

/// Every writer's line reads back, in the same dialect, as the same frame: shortest numbers
/// to rounding (1e-12), rounded ones to their decimals.
/// What `write_block` writes into `to` (form `form`, 4 decimals) for `text`, read from
/// `before` to `after`.
fn block_in(to: Dialect, form: &str, before: &Program, after: &Program, text: &[u8]) -> String {
    let mut buf = [0u8; 1024];
    let (n, _) = write_block(to, form.as_bytes(), before, after, text, 4, &mut buf).unwrap();
    String::from_utf8_lossy(&buf[..n]).into_owned()
}

#[test]
fn every_writer_reads_back() {
    for f in frames() {
        for (d, form) in FORMS {
            let f = if has_origin(form) {
                f
            } else {
                Frame::from_rotation(f.rotation)
            };
            let line = match write(d, form, &f, -1) {
                Ok(l) => l,
                // Projection-like forms cannot express every frame; no others fail.
                Err(e) => panic!("{d:?} {form}: {e:?}"),
            };
            let g = read(d, &[&line]).frame;
            assert!(
                frame_dist(&f, &g) < 1e-12,
                "{line}: {:e}",
                frame_dist(&f, &g)
            );
            let line = write(d, form, &f, 6).unwrap();
            let g = read(d, &[&line]).frame;
            // Six decimals: angles within 5e-7°, vector components within 5e-7.
            assert!(frame_dist(&f, &g) < 1e-3, "{line}");
            assert!(dist(&f.rotation, &g.rotation) < 3e-6, "{line}");
        }
    }
}

/// PLANE PROJECTED and CYCLE800's projection mode written from their own definition
/// (`F = Ry(PROPR)·Rx(γ)·Rz(ROT)`, `tan γ = tan PROMIN · cos PROPR`): the words come back.
#[test]
fn projection_writers_give_their_words_back() {
    for (propr, promin, rot_) in [(20.0, 30.0, 10.0), (-35.0, 12.5, -70.0), (0.0, 45.0, 0.0)] {
        let (p, q) = (f64::to_radians(propr), f64::to_radians(promin));
        let gamma = (q.tan() * p.cos()).atan().to_degrees();
        let m = mul(
            &mul(&r(Axis::Y, propr), &r(Axis::X, gamma)),
            &r(Axis::Z, rot_),
        );
        let line = write(
            Dialect::Heidenhain,
            "PLANE PROJECTED",
            &Frame::from_rotation(m),
            6,
        )
        .unwrap();
        let want = format!("PLANE PROJECTED PROPR{propr:+} PROMIN{promin:+} PROROT{rot_:+} STAY");
        assert_eq!(line, want);
        let g = read(Dialect::Heidenhain, &[&line]).frame;
        assert!(dist(&g.rotation, &m) < 1e-6, "{line}");
    }
}

/// Read in one dialect, write in another, read again: the frame survives every pair.
#[test]
fn every_pair_of_dialects_converts() {
    let mut pairs = 0;
    for f in frames() {
        for (da, fa) in FORMS {
            for (db, fb) in FORMS {
                let both = has_origin(fa) && has_origin(fb);
                let f = if both {
                    f
                } else {
                    Frame::from_rotation(f.rotation)
                };
                let a = write(da, fa, &f, -1).unwrap();
                let ga = read(da, &[&a]).frame;
                let b = write(db, fb, &ga, -1).unwrap();
                let gb = read(db, &[&b]).frame;
                assert!(frame_dist(&f, &gb) < 1e-12, "{a} → {b}");
                pairs += 1;
            }
        }
    }
    assert_eq!(pairs, frames().len() * FORMS.len() * FORMS.len());
}

#[test]
fn writers_say_where_the_free_angle_went() {
    let mut buf = [0u8; 128];
    // PLANE SPATIAL at SPB = 90 puts the free angle in SPA (SPC = 0 by its rule)...
    let f = Frame::from_rotation(mul(&r(Axis::Y, 90.0), &r(Axis::X, 30.0)));
    let (n, singular) = write_line(Dialect::Heidenhain, b"PLANE SPATIAL", &f, 6, &mut buf).unwrap();
    assert!(singular);
    assert_eq!(&buf[..n], b"PLANE SPATIAL SPA+30 SPB+90 SPC+0 STAY");
    // ...SINUMERIK's read-back the other way round (x = 0).
    let (n, singular) = write_line(Dialect::Sinumerik, b"ROT", &f, 6, &mut buf).unwrap();
    assert!(singular);
    assert_eq!(&buf[..n], b"ROT X=0 Y=90 Z=-30");
    // Fanuc numbers always carry a point; Haas names its Q.
    let f = Frame::with_translations([10.0, 0.0, 0.0], r(Axis::X, 30.0), [0.0; 3]);
    let (n, _) = write_line(Dialect::Fanuc, b"G68.2", &f, 3, &mut buf).unwrap();
    assert_eq!(&buf[..n], b"G68.2 X10. Y0. Z0. I0. J30. K0.");
    let (n, _) = write_line(Dialect::Haas, b"g268", &f, 3, &mut buf).unwrap();
    assert_eq!(&buf[..n], b"G268 X10. Y0. Z0. I30. J0. K0. Q123");
    let (n, _) = write_line(Dialect::Sinumerik, b"CYCLE800", &f, 3, &mut buf).unwrap();
    assert_eq!(
        &buf[..n],
        b"CYCLE800(0,\"\",0,57,10,0,0,30,0,0,0,0,0,-1,0,0)"
    );
}

#[test]
fn writers_refuse() {
    let mut buf = [0u8; 128];
    let moved = Frame::with_translations([1.0, 0.0, 0.0], cncrot::IDENTITY, [0.0; 3]);
    let id = Frame::IDENTITY;
    let w =
        |d, form: &str, f: &Frame, dec, buf: &mut [u8]| write_line(d, form.as_bytes(), f, dec, buf);
    assert_eq!(
        w(Dialect::Heidenhain, "PLANE SPATIAL", &moved, -1, &mut buf),
        Err(Error::HasOrigin)
    );
    assert_eq!(
        w(Dialect::Heidenhain, "G68.2", &id, -1, &mut buf),
        Err(Error::BadArgument)
    );
    assert_eq!(
        w(Dialect::Haas, "G68.2", &id, -1, &mut buf),
        Err(Error::BadArgument)
    );
    assert_eq!(
        w(Dialect::Sinumerik, "ROTS", &id, -1, &mut buf),
        Err(Error::BadArgument)
    );
    assert_eq!(
        w(Dialect::Sinumerik, "CYCLE800 192", &id, -1, &mut buf),
        Err(Error::NotAvailable)
    );
    assert_eq!(
        w(Dialect::Sinumerik, "CYCLE800 x", &id, -1, &mut buf),
        Err(Error::BadArgument)
    );
    assert_eq!(
        w(Dialect::Syntec, "G158 P10200", &id, -1, &mut buf),
        Err(Error::NotAvailable)
    );
    assert_eq!(
        w(Dialect::Fanuc, "G68.2", &id, 18, &mut buf),
        Err(Error::BadArgument)
    );
    let tilted = Frame::from_rotation(r(Axis::X, 30.0));
    assert_eq!(
        w(Dialect::Fanuc, "G68.2", &tilted, -1, &mut buf[..10]),
        Err(Error::NoRoom)
    );
    let far = Frame::with_translations([1e120, 0.0, 0.0], cncrot::IDENTITY, [0.0; 3]);
    assert_eq!(
        w(Dialect::Fanuc, "G68.2", &far, -1, &mut buf),
        Err(Error::OutOfRange)
    );
}

/// `_SW_REC = 0` (swivel with the accessory) reads as the recalculation `_SW_REC = 1`: the
/// positions come from the machine (`cycle600::position`), not from the line.
#[test]
fn cycle600_sw_rec_0_recalculates() {
    let a = read(
        Dialect::Sinumerik,
        &["CYCLE600(0,\"UFK600\",0,57,0,0,0,30,45,60,0,0,0,1,39,0,0,0)"],
    );
    let b = read(
        Dialect::Sinumerik,
        &["CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39,0,0,0)"],
    );
    assert_eq!(a.frame, b.frame);
}

/// Swivel data: an empty index names no data set (`$TC_CARR11[]` was skipped silently, so
/// that v2 was lost); refused at its line as a malformed one is.
#[test]
fn an_empty_swivel_data_index_is_refused_at_its_line() {
    use cncrot::dialects::carr::machine_from_carr;
    let text = b"$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0\n$TC_CARR10[]=0 $TC_CARR11[]=1 $TC_CARR12[]=0\n";
    let e = machine_from_carr(text, 1).unwrap_err();
    assert_eq!((e.error, e.line), (Error::Parse, 2));
    let e = machine_from_carr(b"$TC_CARR7[ ]=1", 1).unwrap_err();
    assert_eq!((e.error, e.line), (Error::Parse, 1));
    // With the index written, the same data set has both axes.
    let good = b"$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0\n$TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=1\n";
    assert_eq!(machine_from_carr(good, 1).unwrap().axes().len(), 2);
}

/// The length limits of names and numbers, at the limit and one past it: a CYCLE600
/// `_MIHEAD` of 31 bytes is a name, of 32 too long; a swivel-data index of 9 digits is a
/// number, of 10 not.
#[test]
fn names_and_indices_at_their_limits() {
    let call = |name: &str| format!("CYCLE600(0,\"{name}\",1,57,0,0,0,30,45,60,0,0,0,1,39)");
    let n31 = "A".repeat(31);
    assert!(Program::default()
        .line(Dialect::Sinumerik, call(&n31).as_bytes())
        .is_ok());
    let e = Program::default()
        .line(Dialect::Sinumerik, call(&"A".repeat(32)).as_bytes())
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::NameTooLong, 12));
    use cncrot::dialects::carr::machine_from_carr;
    let axis = b"$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0\n";
    let mut text = axis.to_vec();
    text.extend_from_slice(b"$TC_CARR7[123456789]=1\n");
    assert_eq!(machine_from_carr(&text, 1).unwrap().axes().len(), 1);
    let mut text = axis.to_vec();
    text.extend_from_slice(b"$TC_CARR7[1234567890]=1\n");
    let e = machine_from_carr(&text, 1).unwrap_err();
    assert_eq!((e.error, e.line), (Error::Parse, 2));
}

/// Swivel data's axis parameters reach the machine: offsets (24, 25), Hirth offsets and
/// increments (26..29), travel minimum (30, 31) and maximum (32, 33), per axis as the
/// parameter table of the function manual lists them.
#[test]
fn swivel_data_axis_parameters_reach_the_machine() {
    use cncrot::dialects::carr::machine_from_carr;
    let text = b"$TC_CARR7[1]=0 $TC_CARR8[1]=1 $TC_CARR9[1]=0 $TC_CARR10[1]=0 $TC_CARR11[1]=0
$TC_CARR12[1]=1 $TC_CARR24[1]=1.5 $TC_CARR25[1]=-2 $TC_CARR26[1]=0.5 $TC_CARR28[1]=2.5
$TC_CARR27[1]=0 $TC_CARR29[1]=0 $TC_CARR30[1]=-100 $TC_CARR31[1]=-360 $TC_CARR32[1]=30
$TC_CARR33[1]=360
";
    let m = machine_from_carr(text, 1).unwrap();
    let [a, c] = [m.axes()[0], m.axes()[1]];
    assert_eq!((a.offset, c.offset), (1.5, -2.0));
    assert_eq!(a.limits, Some([-100.0, 30.0]));
    assert_eq!(c.limits, Some([-360.0, 360.0]));
    let h = a.hirth.expect("a Hirth grid on axis 1");
    assert_eq!((h.offset, h.step), (0.5, 2.5));
    assert!(c.hirth.is_none());
}

/// Each line of `program` with the remark it must give; the state after a passed or
/// unfollowed block is the state before it, to the bit.
fn remarks(d: Dialect, program: &[(&str, Remark)]) -> Program {
    let mut p = Program::default();
    for &(line, want) in program {
        let (next, remark) = p
            .line(d, line.as_bytes())
            .unwrap_or_else(|e| panic!("{d:?} {line:?}: {e:?}"));
        assert_eq!(remark, want, "{d:?} {line:?}");
        if remark != Remark::Applied {
            assert_eq!(format!("{next:?}"), format!("{p:?}"), "{line:?}");
        }
        p = next;
    }
    p
}

/// Every block of a program, as CAM systems and people write them: a block the library
/// reads is applied, a block that does not concern the frame passed over, a block that
/// changes the frame in a way the library does not follow (work offsets, presets, datum
/// tables, variable writes, mirroring, scaling, tilts through the machine) says so; none is
/// refused. The datum shifts CAM output writes before each plane are applied.
#[test]
fn every_block_of_a_program() {
    use Remark::{Applied as A, NotFollowed as N, Passed as P};
    let p = remarks(
        Dialect::Heidenhain,
        &[
            ("0 BEGIN PGM 1234 MM", P),
            ("1 BLK FORM 0.1 Z X-50 Y-50 Z-40", P),
            ("2 BLK FORM 0.2 X+50 Y+50 Z+0", P),
            ("3 TOOL CALL 5 Z S8000 F2000", P),
            ("4 CYCL DEF 7.0 DATUM SHIFT", A),
            ("5 CYCL DEF 7.1 X+10", A),
            ("6 CYCL DEF 7.2 Y+20", A),
            ("7 CYCL DEF 7.3 Z+0", A),
            (
                "8 PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN MB MAX FMAX SEQ-",
                A,
            ),
            ("9 L X+0 Y+0 R0 FMAX M3", P),
            ("10 CYCL DEF 200 DRILLING ~", P),
            ("   Q200=+2 ;SET-UP CLEARANCE ~", P),
            ("   Q201=-20 ;DEPTH", P),
            ("11 CYCL CALL", P),
            ("12 L Z+100 R0 FMAX", P),
            ("13 TRANS DATUM AXIS X+5 Y+0 Z+0", A),
            ("14 TRANS DATUM RESET", A),
            ("15 CYCL DEF 19.0 WORKING PLANE", A),
            ("16 CYCL DEF 19.1 A+0 B+30 C+0", A),
            ("17 CYCL DEF 10.0 ROTATION", N),
            ("18 CYCL DEF 247 DATUM SETTING ~", N),
            ("19 PRESET SELECT #2", N),
            ("20 FN 17: SYSWRITE ID 990 NR4 IDX0 =1", N),
            ("21 FN 0: Q1 = +5", P),
            ("22 * - roughing", P),
            ("23 ; a comment", P),
            ("24 LBL 1", P),
            ("25 CALL LBL 1", P),
            ("26 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS", P),
            ("27 M30", P),
            ("28 END PGM 1234 MM", P),
        ],
    );
    // Cycle 19 (spatial angles) replaced the PLANE.
    assert!(dist(&p.frame.rotation, &r(Axis::Y, 30.0)) < 1e-15);

    let p = remarks(
        Dialect::Fanuc,
        &[
            ("%", P),
            ("O1000 (TILT TEST)", P),
            ("N10 G90 G17 G40 G49 G80", P),
            ("N20 G54", N),
            ("N30 T1 M6", P),
            ("N40 G0 G90 X0 Y0 S5000 M3", P),
            ("N50 G68.2 X10. Y20. Z0. I0. J45. K0.", A),
            ("N60 G53.1", A),
            ("N70 G43.4 H1 Z50.", P),
            ("N80 G1 X10. F500", P),
            ("N90 G52 X10. Y5.", A),
            ("N100 G54.1 P3", N),
            ("N110 G10 L2 P1 X0 Y0", N),
            ("N120 #5221=100.", N),
            // A computed variable number may be a work offset: #[5220+1] is #5221.
            ("#[5220+1]=-100.", N),
            ("N130 #100=5.", P),
            ("N140 G92 X0 Y0", N),
            ("N150 G51.1 X0", N),
            ("N160 G68 X0 Y0 R30.", N),
            ("N170 G0G90G55X0Y0", N),
            ("N180 G90 G68.2 X0 Y0 Z0 I0 J30 K0", A),
            // Fanuc's G68.2 forms without a public definition and LinuxCNC's R: not followed,
            // not guessed.
            ("N182 G68.2 P1 Q123 X0 Y0 Z0 I10 J20 K30", A),
            ("N183 G68.2 P2 X0 Y0 Z0 I1 J0 K0", N),
            ("N184 G68.2 X0 Y0 Z0 I0 J30 K0 R10", N),
            ("N185 G53.1 P1", A),
            ("N186 G68.2 P0 X0 Y0 Z0 I0 J30 K0", A),
            // The local coordinate system cancelled as the manuals write it.
            ("N187 G52 X0 Y0", A),
            ("N190 M30", P),
        ],
    );
    assert_eq!(p.frame.translation, [0.0; 3]);
    let (off, remark) = p.line(Dialect::Fanuc, b"N200 G49 G69").unwrap();
    assert_eq!((off.frame, remark), (Frame::IDENTITY, A));
    // A cancel on a block that also changes the work offset: not followed, state kept.
    assert_eq!(p.line(Dialect::Fanuc, b"G69 G54").unwrap(), (p, N));
    // A tilt the library reads, written where it does not read it, is never passed over.
    for line in ["G0 X10 G68.2 X0 I0 J30 K0", "M3 G68.4 J10"] {
        let e = p.line(Dialect::Fanuc, line.as_bytes()).unwrap_err();
        assert_eq!(e.error, Error::UnknownWord, "{line}");
    }
    // ISO programs may leave out the spaces: the next word's letter ends a number, and a
    // letter may follow a code. The same frames as with spaces (hand-derived: J30 is Rx(30),
    // G52 X5. a shift of 5 along X).
    let spaced = read(
        Dialect::Fanuc,
        &[
            "N10 G90 G17",
            "N20 G52 X5. Y0.",
            "N30 G68.2 X1. Y2. Z3. I0. J30. K0.",
            "N40 G53.1",
        ],
    );
    let packed = read(
        Dialect::Fanuc,
        &[
            "N10G90G17",
            "N20G52X5.Y0.",
            "N30G68.2X1.Y2.Z3.I0.J30.K0.",
            "N40G53.1",
        ],
    );
    assert_eq!(packed, spaced);
    // Blanks inside a word and a constant in brackets (macro B's expression of one number,
    // `G52 X [ 0. ]` as a post wrote it) are the number: the same frame again.
    let bracketed = read(
        Dialect::Fanuc,
        &[
            "N10 G90 G17",
            "N20 G52 X [ 5. ] Y[0]",
            "N30 G68.2 X 1. Y[+2.]Z [3.] I0. J 30. K[ -0 ]",
            "N40 G53.1",
        ],
    );
    assert_eq!(bracketed, spaced);
    // What is not one number stays refused, at the bracket; a word without its value is
    // missing it where its blanks start.
    for (line, error, column) in [
        ("G52 X[#1]", Error::NotANumber, 6),
        ("G52 X[1+2]", Error::NotANumber, 6),
        ("G52 X[1]+2", Error::NotANumber, 9),
        ("G52 X[1", Error::NotANumber, 6),
        ("G52 X Y0", Error::MissingWord, 6),
    ] {
        let e = p.line(Dialect::Fanuc, line.as_bytes()).unwrap_err();
        assert_eq!((e.error, e.column), (error, column), "{line}");
    }
    assert_eq!(packed.frame.translation, [6.0, 2.0, 3.0]);
    assert!(dist(&packed.frame.rotation, &r(Axis::X, 30.0)) < 1e-15);
    assert_eq!(packed.positioning, Positioning::Turn);
    assert_eq!(
        read(Dialect::Haas, &["G268X0.Y0.Z0.I0.J45.K0.Q123", "G253"]),
        read(
            Dialect::Haas,
            &["G268 X0. Y0. Z0. I0. J45. K0. Q123", "G253"]
        )
    );
    assert_eq!(
        read(Dialect::Syntec, &["G158P10157X1.A20.B20.C-30."]),
        read(Dialect::Syntec, &["G158 P10157 X1. A20. B20. C-30."])
    );
    // A code that goes on is another code (G69.1: not followed; G68.25: none the library
    // knows, passed over); an expression stays refused.
    assert_eq!(p.line(Dialect::Fanuc, b"G69.1X0").unwrap().1, N);
    assert_eq!(p.line(Dialect::Fanuc, b"G68.25X0").unwrap().1, P);
    assert_eq!(
        p.line(Dialect::Fanuc, b"G68.2X10+5J30").unwrap_err().error,
        Error::NotANumber
    );

    let p = remarks(
        Dialect::Sinumerik,
        &[
            ("; program header", P),
            ("N10 G17 G90 G54", N),
            ("N20 T=\"MILL10\" D1 M6", P),
            (
                "N30 CYCLE800(1,\"TC1\",0,57,0,0,0,0,45,0,0,0,0,-1,100,1)",
                A,
            ),
            ("N40 TRAORI", P),
            ("N50 G1 X10 Y10 F1000", P),
            ("N60 MIRROR X0", N),
            ("N70 $P_UIFR[1]=CTRANS(X,10)", N),
            // Frame functions in the value (`CROT(`, `CROTS(`) are no frame commands.
            ("N71 $P_UIFR[1]=CTRANS(X,10,Y,20):CROT(Z,30)", N),
            ("N72 $P_BFRAME=CROTS(X,10,Y,5)", N),
            ("N80 R1=5 ; ROT in a comment", P),
            ("N90 MSG(\"TRANS and ROT in a string\")", P),
            ("N100 TOROT", N),
            ("N110 G505", N),
            ("N120 G500", N),
            ("N130 SCALE X2", N),
            // Setting actual values moves the workpiece coordinates by an amount the
            // program does not state.
            ("N131 PRESETON(X,0,Y,0)", N),
            // RPL with an axis' angle: in no manual's syntax.
            ("N132 AROT X10 RPL=30", N),
            ("N140 G153 G0 Z0", P),
            ("N150 M30", P),
        ],
    );
    let want = r(Axis::Y, 45.0);
    assert!(dist(&p.frame.rotation, &want) < 1e-12);
    // RPL is no word of ROTS: still refused there.
    let e = p.line(Dialect::Sinumerik, b"ROTS RPL=3").unwrap_err();
    assert_eq!((e.error, e.column), (Error::UnknownWord, 6));
    assert_eq!(
        p.line(Dialect::Sinumerik, b"CYCLE800()").unwrap().0.frame,
        Frame::IDENTITY
    );

    remarks(
        Dialect::Twincat,
        &[
            ("N10 G54", N),
            ("N20 G01 X10 F1000", P),
            ("N30 ROT Z30", A),
            ("N32 G58 X10 Y0 Z0", A),
            ("N34 G59 X10 Y0 Z0", N),
            ("N36 G53", N),
            ("N38 G1 G58 X10 Y0 Z0", N),
            ("N40 #CS ON [0,0,0,0,0,30]", N),
            ("N50 (a comment)", P),
            ("N60 M30", P),
        ],
    );
    remarks(
        Dialect::Haas,
        &[
            ("O00001 (HAAS)", P),
            ("N10 G154 P1", N),
            ("N20 G268 X0 Y0 Z0 I0 J45 K0 Q123", A),
            ("N30 G253", A),
            ("N40 G101 X0", N),
            ("N50 G0 G269", A),
            ("N60 M30", P),
        ],
    );
    remarks(
        Dialect::Syntec,
        &[
            ("N10 G54.1 P1", N),
            ("N20 G158 P10157 X0 Y0 Z0 A0 B30 C0 U0 V0 W0", A),
            ("N30 G1 X10 F100", P),
            ("N40 G69", A),
            ("N50 G90 G68.2 X0 Y0 Z0 I0 J30 K0", A),
            ("N60 M30", P),
        ],
    );
}

/// Nothing active is written as each form's cancel, which its own reader reads back as the
/// cancel; TwinCAT, which has none of its own, writes zero angles.
#[test]
fn cancels_are_written_as_cancels() {
    let cases: [(Dialect, &str, &str); 11] = [
        (Dialect::Sinumerik, "CYCLE800", "CYCLE800()"),
        (Dialect::Sinumerik, "CYCLE800 27", "CYCLE800()"),
        (Dialect::Sinumerik, "ROT", "ROT"),
        (Dialect::Heidenhain, "PLANE SPATIAL", "PLANE RESET STAY"),
        (Dialect::Heidenhain, "PLANE VECTOR", "PLANE RESET STAY"),
        (Dialect::Fanuc, "G68.2", "G69"),
        (Dialect::Syntec, "G158", "G158"),
        (Dialect::Syntec, "G68.2", "G69"),
        (Dialect::Haas, "G268", "G269"),
        (Dialect::Haas, "G268 Q321", "G269"),
        (Dialect::Twincat, "ROT", "ROT X0 Y0 Z0"),
    ];
    let tilted = read(Dialect::Fanuc, &["G68.2 J30"]);
    for (d, form, want) in cases {
        let mut buf = [0u8; 64];
        let (n, _) = write_line(d, form.as_bytes(), &Frame::IDENTITY, 4, &mut buf).unwrap();
        assert_eq!(
            std::str::from_utf8(&buf[..n]).unwrap(),
            want,
            "{d:?} {form}"
        );
        let p = Program {
            dialect: Some(d),
            ..tilted
        };
        let (off, remark) = p.line(d, &buf[..n]).unwrap();
        assert_eq!(
            (off.frame, remark),
            (Frame::IDENTITY, Remark::Applied),
            "{want}"
        );
    }
    // Anything but the exact identity is written with its words, however small the tilt.
    let mut buf = [0u8; 64];
    let nearly = Frame::from_rotation(r(Axis::X, 1e-9));
    let (n, _) = write_line(Dialect::Fanuc, b"G68.2", &nearly, -1, &mut buf).unwrap();
    assert!(buf[..n].starts_with(b"G68.2 "));
}

/// A block that restates what the state already holds is written again by `write_block`:
/// each dialect's cancel, read with nothing active, becomes each target form's cancel (the
/// texts of `cancels_are_written_as_cancels`), a zero shift with none active the target's
/// shift; blocks that restate nothing write nothing; a block that changes the state writes
/// what `write_change` writes.
#[test]
fn restated_blocks_are_written() {
    let sources: [(Dialect, &str); 8] = [
        (Dialect::Heidenhain, "PLANE RESET STAY"),
        (Dialect::Heidenhain, "20 PLANE RESET"),
        (Dialect::Sinumerik, "CYCLE800()"),
        (Dialect::Sinumerik, "N10 CYCLE800"),
        (Dialect::Fanuc, "G69"),
        (Dialect::Haas, "G269"),
        (Dialect::Syntec, "G158"),
        (Dialect::Twincat, "ROT X0 Y0 Z0"),
    ];
    let targets: [(Dialect, &str, &str); 6] = [
        (Dialect::Sinumerik, "CYCLE800", "CYCLE800()"),
        (Dialect::Heidenhain, "PLANE SPATIAL", "PLANE RESET STAY"),
        (Dialect::Fanuc, "G68.2", "G69"),
        (Dialect::Syntec, "G158", "G158"),
        (Dialect::Haas, "G268", "G269"),
        (Dialect::Twincat, "ROT", "ROT X0 Y0 Z0"),
    ];
    let mut buf = [0u8; MAX_CHANGE];
    let mut text = |to: Dialect, form: &str, a: &Program, b: &Program, block: &str| {
        let (n, _) = write_block(to, form.as_bytes(), a, b, block.as_bytes(), 4, &mut buf)
            .unwrap_or_else(|e| panic!("{block} into {form}: {e:?}"));
        String::from_utf8(buf[..n].to_vec()).unwrap()
    };
    let p0 = Program::default();
    for (d, block) in sources {
        let (p1, remark) = p0.line(d, block.as_bytes()).unwrap();
        assert_eq!(
            (remark, p1.frame),
            (Remark::Applied, Frame::IDENTITY),
            "{block}"
        );
        for (to, form, want) in targets {
            assert_eq!(text(to, form, &p0, &p1, block), want, "{block} into {form}");
        }
    }
    // A zero shift with none active: the target's shift command with zeros.
    let (p1, _) = p0.line(Dialect::Fanuc, b"G52 X0 Y0").unwrap();
    assert_eq!(
        text(Dialect::Heidenhain, "PLANE SPATIAL", &p0, &p1, "G52 X0 Y0"),
        "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\nCYCL DEF 7.2 Y+0\nCYCL DEF 7.3 Z+0"
    );
    let (p1, _) = p0.line(Dialect::Heidenhain, b"TRANS DATUM RESET").unwrap();
    assert_eq!(
        text(Dialect::Fanuc, "G68.2", &p0, &p1, "TRANS DATUM RESET"),
        "G52 X0. Y0. Z0."
    );
    // Nothing restated: a cycle's first line, an incremental shift of nothing, a tilt
    // repeated.
    for (d, block) in [
        (Dialect::Heidenhain, "CYCL DEF 7.0 DATUM SHIFT"),
        (Dialect::Heidenhain, "CYCL DEF 7.1 IX+0"),
    ] {
        let (p1, _) = p0.line(d, block.as_bytes()).unwrap();
        assert_eq!(
            text(Dialect::Fanuc, "G68.2", &p0, &p1, block),
            "",
            "{block}"
        );
    }
    let tilt = "G68.2 X1 I0 J30 K0";
    let (p1, _) = p0.line(Dialect::Fanuc, tilt.as_bytes()).unwrap();
    assert_eq!(
        text(Dialect::Heidenhain, "PLANE SPATIAL", &p1, &p1, tilt),
        ""
    );
    // A change: write_change's text.
    let mut change = [0u8; MAX_CHANGE];
    let (n, _) = write_change(
        Dialect::Heidenhain,
        b"PLANE SPATIAL",
        &p0,
        &p1,
        4,
        &mut change,
    )
    .unwrap();
    assert_eq!(
        text(Dialect::Heidenhain, "PLANE SPATIAL", &p0, &p1, tilt).as_bytes(),
        &change[..n]
    );
}

/// A tilt of zero that turns the axes (they go back to the untilted plane) is written so in
/// every target that can say it — a reset with `TURN`, a zero `G68.2`/`G268` and its
/// `G53.1`/`G253` then the cancel (the target untilted, as the state: a Fanuc refuses `G52`
/// in `G68.2` mode), a `CYCLE800` of zero angles — and reads back as that turn; a target that
/// says nothing of the axes writes its cancel; the cancel after it is the cancel in each
/// (none where the turn's text ended with it).
#[test]
fn zero_tilts_that_turn_are_written_so() {
    let targets: [(Dialect, &str, &str, bool); 6] = [
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL",
            "PLANE RESET TURN FMAX",
            true,
        ),
        (
            Dialect::Fanuc,
            "G68.2",
            "G68.2 X0. Y0. Z0. I0. J0. K0.\nG53.1\nG69",
            true,
        ),
        (
            Dialect::Haas,
            "G268",
            "G268 X0. Y0. Z0. I0. J0. K0. Q123\nG253\nG269",
            true,
        ),
        (
            Dialect::Sinumerik,
            "CYCLE800",
            "CYCLE800(0,\"\",0,57,0,0,0,0,0,0,0,0,0,-1,0,0)",
            true,
        ),
        (Dialect::Syntec, "G158", "G158", false),
        (Dialect::Twincat, "ROT", "ROT X0 Y0 Z0", false),
    ];
    let cancel = [
        "PLANE RESET STAY",
        "G69",
        "G269",
        "CYCLE800()",
        "G158",
        "ROT X0 Y0 Z0",
    ];
    let p0 = Program::default();
    for source in [
        "PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN FMAX",
        "PLANE RESET TURN FMAX",
    ] {
        let (p1, _) = p0.line(Dialect::Heidenhain, source.as_bytes()).unwrap();
        assert_eq!(
            (p1.frame, p1.positioning),
            (Frame::IDENTITY, Positioning::Turn)
        );
        let (p2, _) = p1.line(Dialect::Heidenhain, b"PLANE RESET STAY").unwrap();
        for ((to, form, want, says), cancel) in targets.into_iter().zip(cancel) {
            let mut buf = [0u8; MAX_CHANGE];
            let (n, _) = write_change(to, form.as_bytes(), &p0, &p1, 4, &mut buf).unwrap();
            let text = std::str::from_utf8(&buf[..n]).unwrap();
            assert_eq!(text, want, "{source} into {form}");
            let mut back = Program::default();
            let mut turned = false;
            for l in text.lines() {
                back = back.line(to, l.as_bytes()).unwrap().0;
                turned |= back.frame == Frame::IDENTITY && back.positioning == Positioning::Turn;
            }
            assert_eq!((back.frame, turned), (Frame::IDENTITY, says), "{want}");
            let (n, _) = write_change(to, form.as_bytes(), &p1, &p2, 4, &mut buf).unwrap();
            // Where the turn ended with the cancel, nothing is left to cancel.
            let after = if says && want.ends_with(cancel) {
                ""
            } else {
                cancel
            };
            assert_eq!(&buf[..n], after.as_bytes(), "{form}: the cancel after it");
        }
    }
}

/// Every text a reader names as expected fits the room C gives it
/// (`CNCROT_PROGRAM_EXPECTED_SIZE` with its NUL): the literals of the readers' sources.
#[test]
fn expected_texts_fit_their_room() {
    let sources = [
        include_str!("../src/dialects/heidenhain.rs"),
        include_str!("../src/dialects/haas.rs"),
        include_str!("../src/dialects/syntec.rs"),
        include_str!("../src/dialects/twincat.rs"),
        include_str!("../src/dialects/fanuc.rs"),
        include_str!("../src/dialects/sinumerik/mod.rs"),
        include_str!("../src/dialects/sinumerik/cycle600.rs"),
        include_str!("../src/text/scan.rs"),
    ];
    let mut seen = 0;
    let mut check = |text: &str| {
        assert!(
            text.len() < cncrot::ffi::CNCROT_PROGRAM_EXPECTED_SIZE,
            "{text}"
        );
        // C and MATLAB show it as it is: printable ASCII.
        assert!(text.bytes().all(|b| (0x20..0x7f).contains(&b)), "{text}");
        seen += 1;
    };
    for src in sources {
        for (k, _) in src.match_indices(".missing(\"") {
            let rest = &src[k + 10..];
            check(&rest[..rest.find("\")").unwrap()]);
        }
        // A parameter's allowed values: "_NAME: …".
        for (k, _) in src.match_indices("\"_") {
            let rest = &src[k + 1..];
            let name = rest[1..].find(|c: char| !c.is_ascii_uppercase() && c != '_');
            if name.is_some_and(|n| n > 0 && rest[1 + n..].starts_with(": ")) {
                check(&rest[..rest.find('"').unwrap()]);
            }
        }
    }
    // Heidenhain's three, Haas, Syntec, TwinCAT, SINUMERIK's five, the number; CYCLE600's
    // nine parameters, CYCLE800's _ST and _MODE.
    assert!(seen >= 23, "{seen}");
}

/// A missing word is named: the first word of the command that is not there, or what
/// kind of text should stand at the column.
#[test]
fn missing_words_are_named() {
    let cases = [
        (Dialect::Heidenhain, "PLANE SPATIAL SPA+10 SPB+0", "SPC"),
        (Dialect::Heidenhain, "PLANE SPATIAL SPB+0 SPC+0 STAY", "SPA"),
        (
            Dialect::Heidenhain,
            "PLANE EULER EULPR+10 EULROT+0",
            "EULNU",
        ),
        (
            Dialect::Heidenhain,
            "PLANE VECTOR BX1 BY0 BZ0 NX0 NY0",
            "NZ",
        ),
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL SPA+10 SPB+0 SPC+0 TABLE",
            "ROT",
        ),
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL SPA+10 SPB+0 SPC+0 SEQ",
            "'+' or '-'",
        ),
        (Dialect::Heidenhain, "PLANE RELATIV +10", "SPA, SPB or SPC"),
        (
            Dialect::Heidenhain,
            "PLANE SPATIAL SPA+10 SPB+0 SPC",
            "a number",
        ),
        (Dialect::Haas, "G268 X0 I0 J30 K0", "Q"),
        (Dialect::Syntec, "G158 X0 A30", "P"),
        (Dialect::Twincat, "AROT", "X, Y or Z"),
        (Dialect::Sinumerik, "AROT", "X, Y or Z"),
        (Dialect::Sinumerik, "CYCLE800 _TC", "'('"),
        (Dialect::Sinumerik, "CYCLE800(0,\"TC1\",0", "',' or ')'"),
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0)",
            "CYCLE800's parameters up to _MODE (4)",
        ),
        (
            Dialect::Sinumerik,
            "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60)",
            "CYCLE600's parameters up to _BIN_OUT (15)",
        ),
        (Dialect::Fanuc, "G68.2 X", "a number"),
    ];
    for (d, line, want) in cases {
        let e = Program::default().line(d, line.as_bytes()).expect_err(line);
        assert_eq!(
            (e.error, e.expected),
            (Error::MissingWord, Some(want)),
            "{line}"
        );
    }
    // Other refusals name no expected word: the word at the column is the one to show.
    let e = Program::default()
        .line(Dialect::Heidenhain, b"PLANE SPATIAL SPX+10 SPB+0 SPC+0")
        .unwrap_err();
    assert_eq!(
        (e.error, e.column, e.expected),
        (Error::UnknownWord, 15, None)
    );
}

/// The datum shifts CAM output writes before a plane: cycle 7's lines set the axes they
/// name, `IX` adds, a `PLANE` tilts about the shifted datum, `PLANE RESET` keeps the shift
/// and `TRANS DATUM RESET` clears it; the tilt of a Fanuc-style program is its own.
#[test]
fn datum_shifts_compose_with_the_tilt() {
    let lines = [
        "1 CYCL DEF 7.0 DATUM SHIFT",
        "2 CYCL DEF 7.1 X+10",
        "3 CYCL DEF 7.2 Y+20",
        "4 CYCL DEF 7.3 Z-5",
        "5 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX",
    ];
    let mut p = Program::default();
    for l in lines {
        p = p.line(Dialect::Heidenhain, l.as_bytes()).unwrap().0;
    }
    // The frame: the shift, then the tilt about the shifted datum.
    assert_eq!(p.shift, [10.0, 20.0, -5.0]);
    assert_eq!(p.frame.translation, [10.0, 20.0, -5.0]);
    assert!(dist(&p.frame.rotation, &r(Axis::Y, 30.0)) < 1e-15);
    let q = p
        .line(Dialect::Heidenhain, b"6 PLANE RESET STAY")
        .unwrap()
        .0;
    assert_eq!(
        (q.frame.translation, q.shift),
        ([10.0, 20.0, -5.0], [10.0, 20.0, -5.0])
    );
    assert_eq!(q.frame.rotation, cncrot::IDENTITY);
    let q = q
        .line(Dialect::Heidenhain, b"7 CYCL DEF 7.1 IX-4")
        .unwrap()
        .0;
    assert_eq!(q.shift, [6.0, 20.0, -5.0]);
    let q = q
        .line(Dialect::Heidenhain, b"8 TRANS DATUM RESET")
        .unwrap()
        .0;
    assert_eq!((q.frame, q.shift), (Frame::IDENTITY, [0.0; 3]));
    let q = q
        .line(Dialect::Heidenhain, b"9 TRANS DATUM AXIS X+1 Y+2 Z+3")
        .unwrap()
        .0;
    assert_eq!(q.frame.translation, [1.0, 2.0, 3.0]);
    // A new plane on a shifted datum keeps the shift; the datum table is not followed.
    let q = q
        .line(
            Dialect::Heidenhain,
            b"10 PLANE SPATIAL SPA+90 SPB+0 SPC+0 STAY",
        )
        .unwrap()
        .0;
    assert_eq!(q.frame.translation, [1.0, 2.0, 3.0]);
    let (_, remark) = q.line(Dialect::Heidenhain, b"11 CYCL DEF 7.1 #5").unwrap();
    assert_eq!(remark, Remark::NotFollowed);
    let e = q
        .line(Dialect::Heidenhain, b"12 TRANS DATUM AXIS")
        .unwrap_err();
    assert_eq!(
        (e.error, e.expected),
        (Error::MissingWord, Some("X, Y or Z"))
    );
}

/// The choice words of a tilt are kept in the state and followed on the machine: `SEQ-`
/// takes the master axis (a head's axis nearest the tool) at a negative angle, `_DIR = +1`
/// the higher position; a new tilt without words takes the closest again.
#[test]
fn choice_words_are_kept_and_followed() {
    use cncrot::kinematics::{Machine, RotaryAxis, Rule, Side};
    // A head C about Z carrying B about Y: the tool at (sin 30°, 0, cos 30°) is C 0, B 30 or
    // C ±180, B -30.
    let head = Machine::new([0.0, 0.0, 1.0])
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]))
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3]))
        .unwrap();
    let plane = |words: &str| {
        let l = format!("PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN {words}");
        Program::default()
            .line(Dialect::Heidenhain, l.as_bytes())
            .unwrap()
            .0
    };
    let b = |p: &Program| p.axes(&head, [0.0; 3]).unwrap().axes[1];
    assert_eq!(plane("SEQ-").choice, AxisChoice::Minus(0));
    assert!((b(&plane("SEQ-")) + 30.0).abs() < 1e-9);
    assert!((b(&plane("SEQ+")) - 30.0).abs() < 1e-9);
    assert!((b(&plane("")) - 30.0).abs() < 1e-9);
    // From B = -25 the closest is B -30; SEQ+ still takes B 30.
    let from = [180.0, -25.0, 0.0];
    assert!((plane("").axes(&head, from).unwrap().axes[1] + 30.0).abs() < 1e-9);
    assert!((plane("SEQ+").axes(&head, from).unwrap().axes[1] - 30.0).abs() < 1e-9);
    // The same solution wherever the axes stand (a program's blocks each start where the
    // one before left them): an AC table, the tool along the workpiece's X (hyperMILL's
    // "A-90 C270" comment beside this block: the same position on a C shown 0..360). SEQ-
    // is A -90 with C -90, the angles themselves, not wound toward the current position (the
    // iTNC 530 manual's table of SEQ results: SEQ+ from C-105 and from C-135 both C+90);
    // from A -90 the A +90 solution unwinds to -270, which was taken as the lower.
    let table = Machine::new([0.0, 0.0, 1.0])
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Work, [1.0, 0.0, 0.0], [0.0; 3]))
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]))
        .unwrap();
    let seq = read(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA90 SPB0 SPC90 STAY SEQ- TABLE ROT"],
    );
    for (from, want) in [
        ([0.0, 0.0, 0.0], [-90.0, -90.0]),
        ([-90.0, -90.0, 0.0], [-90.0, -90.0]),
        ([-90.0, 270.0, 0.0], [-90.0, -90.0]),
        ([80.0, 100.0, 0.0], [-90.0, -90.0]),
    ] {
        let got = seq.axes(&table, from).unwrap().axes;
        assert!(
            (got[0] - want[0]).abs() < 1e-9 && (got[1] - want[1]).abs() < 1e-9,
            "from {from:?}: {got:?}"
        );
    }
    // CYCLE800 _DIR (the 14th parameter): -1 minus, +1 plus (each swivels), 0 the frame
    // calculated without swivelling (no retraction either), others refused.
    let c800 = |dir: &str| {
        let l = format!("CYCLE800(1,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,{dir})");
        Program::default().line(Dialect::Sinumerik, l.as_bytes())
    };
    let (minus, plus) = (c800("-1").unwrap().0, c800("1").unwrap().0);
    assert_eq!(
        (minus.choice, minus.positioning),
        (AxisChoice::Minus(0), Positioning::Turn)
    );
    assert_eq!(
        (plus.choice, plus.positioning),
        (AxisChoice::Plus(0), Positioning::Turn)
    );
    assert_eq!(plus.retract, Retract::MachineZ);
    let stay = c800("0").unwrap().0;
    assert_eq!(
        (stay.choice, stay.positioning, stay.retract),
        (AxisChoice::Closest, Positioning::Stay, Retract::None)
    );
    assert_eq!(stay.frame, plus.frame);
    let e = c800("2").unwrap_err();
    // Reported at `_DIR` itself, the last parameter.
    let at = "CYCLE800(1,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,".len() + 1;
    assert_eq!((e.error, e.column), (Error::BadArgument, at));
    assert_eq!(
        e.expected,
        Some("_DIR: -1 (minus), +1 (plus) or 0 (no swivel: calculate only)")
    );
    assert!((b(&c800("-1").unwrap().0) + 30.0).abs() < 1e-9);
    // A tilt without words clears them.
    let p = plane("SEQ-")
        .line(
            Dialect::Heidenhain,
            b"PLANE SPATIAL SPA+0 SPB+20 SPC+0 STAY",
        )
        .unwrap()
        .0;
    assert_eq!(p.choice, AxisChoice::Closest);

    // G53.1 P (LinuxCNC's remap): P0 the control's rule, P1 the primary axis (C here: it
    // carries B, "the secondary [is] the one closest to the tool") turning up only, P2
    // down only, the other the shortest way. The solutions: (C 0, B 30), (C 180, B -30).
    // From C 20: up reaches 180 after 160°, 0 only after 340°; down reaches 0 after 20°.
    let g53 = |p: &str| read(Dialect::Fanuc, &["G68.2 X0 Y0 Z0 I90 J30 K-90", p]);
    let from = [20.0, -25.0, 0.0];
    let at = |p: &Program| p.axes(&head, from).unwrap().axes;
    assert_eq!(g53("G53.1 P1").choice, AxisChoice::PositiveTurn(0));
    assert_eq!(g53("G53.6 P2").choice, AxisChoice::NegativeTurn(0));
    assert_eq!(g53("G53.1 P0").choice, AxisChoice::Closest);
    assert_eq!(g53("G53.1").choice, AxisChoice::Closest);
    // LinuxCNC's G53.3: the turn with a move to X Y Z in the plane (the move no frame word,
    // the rest of the block).
    let moved = g53("G53.3 P1 X10 Y20 Z30");
    assert_eq!(
        (moved.positioning, moved.choice, moved.frame),
        (
            Positioning::Turn,
            AxisChoice::PositiveTurn(0),
            g53("G53.1").frame
        )
    );
    let mut buf = [0u8; 64];
    let n =
        cncrot::dialects::program::rest(Dialect::Fanuc, b"G53.3 P1 X10 Y20 Z30", &mut buf).unwrap();
    assert_eq!(&buf[..n], b"X10 Y20 Z30");
    let up = at(&g53("G53.1 P1"));
    assert!(
        (up[0] - 180.0).abs() < 1e-9 && (up[1] + 30.0).abs() < 1e-9,
        "{up:?}"
    );
    let down = at(&g53("G53.1 P2"));
    assert!(
        (down[0] - 0.0).abs() < 1e-9 && (down[1] - 30.0).abs() < 1e-9,
        "{down:?}"
    );
    // The same as the machine's own choice under that rule, C (axis 0) the reference.
    let f = g53("G53.1 P2").frame.rotation;
    let want = head.choose(&f, from, Rule::NegativeTurn(0)).unwrap().axes;
    assert_eq!(down, want);
    let want = head.choose(&f, from, Rule::PositiveTurn(0)).unwrap().axes;
    assert_eq!(up, want);
    let e = Program::default()
        .line(Dialect::Fanuc, b"G53.1 P3")
        .unwrap_err();
    // Reported at the value.
    assert_eq!((e.error, e.column), (Error::BadArgument, 8));
    // After Syntec's direct mode the positions are stated: P is checked, not kept, and the
    // state stays one the library reads back (the fuzz target found it kept, a state then
    // refused as BAD_STATE).
    let direct = read(
        Dialect::Syntec,
        &["G158 P10200 X0 Y0 Z10 A0 B20 C45", "G53.1 P1"],
    );
    assert_eq!(direct.choice, AxisChoice::Closest);
    assert_eq!(direct.positioning, Positioning::Turn);
    assert_eq!(direct.check(), Ok(()));
    let e = read(Dialect::Syntec, &["G158 P10200 B20"])
        .line(Dialect::Syntec, b"G53.1 P7")
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::BadArgument, 8));
    // Written back as Fanuc and Syntec write it: the choice is a word of the turn's own
    // block, which alone is written again (a helper's find: the tilt was written again
    // before it, a second G68.2 in G68.2 mode); Heidenhain's SEQ is a side, not a way to
    // turn: TURN alone.
    let src = ["G68.2 J30", "G53.1 P2", "G68.2 J30", "G53.6 P1"];
    assert_eq!(
        translate(Dialect::Fanuc, &src, Dialect::Syntec, "G68.2"),
        [
            "G68.2 X0. Y0. Z0. I0. J30. K0.",
            "G53.1 P2",
            "G68.2 X0. Y0. Z0. I0. J30. K0.",
            "G53.6 P1"
        ]
    );
    assert_eq!(
        translate(
            Dialect::Fanuc,
            &src[..2],
            Dialect::Heidenhain,
            "PLANE SPATIAL"
        )[1],
        "PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX"
    );
}

#[test]
fn retraction_and_feed_words_are_kept_and_written() {
    let plane = |words: &str| {
        let l = format!("PLANE SPATIAL SPA+0 SPB+30 SPC+0 {words}");
        Program::default().line(Dialect::Heidenhain, l.as_bytes())
    };
    let kept = |words: &str| {
        let p = plane(words).unwrap().0;
        (p.retract, p.retract_mm, p.feed, p.feed_mm_min)
    };
    assert_eq!(
        kept("TURN MB50 FMAX SEQ-"),
        (Retract::Tool, 50.0, Feed::Rapid, 0.0)
    );
    assert_eq!(
        kept("MOVE DIST20 MB MAX F2000"),
        (Retract::ToolMax, 0.0, Feed::Rate, 2000.0)
    );
    assert_eq!(kept("TURN F AUTO"), (Retract::None, 0.0, Feed::Auto, 0.0));
    assert_eq!(
        kept("TURN MB0 FMAX"),
        (Retract::None, 0.0, Feed::Rapid, 0.0)
    );
    // STAY moves nothing: no retraction, no feed.
    assert_eq!(
        kept("STAY MB MAX F500"),
        (Retract::None, 0.0, Feed::Rapid, 0.0)
    );
    // Refused where the value stands.
    let head = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN ".len();
    for (words, at) in [("TURN MB-5", head + 3), ("TURN F0", head + 2)] {
        let e = plane(words).unwrap_err();
        assert_eq!((e.error, e.column), (Error::BadArgument, at), "{words}");
    }
    // CYCLE800's _FR (first) and _FR_I (15th).
    let c800 = |fr: &str, fr_i: &str| {
        let l = format!("CYCLE800({fr},\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,{fr_i},0)");
        Program::default().line(Dialect::Sinumerik, l.as_bytes())
    };
    let r = |fr: &str, fr_i: &str| {
        let p = c800(fr, fr_i).unwrap().0;
        (p.retract, p.retract_mm)
    };
    assert_eq!(r("0", "7"), (Retract::None, 0.0));
    assert_eq!(r("1", "1"), (Retract::MachineZ, 0.0));
    assert_eq!(r("2", "0"), (Retract::MachineZThenXy, 0.0));
    assert_eq!(r("4", "0"), (Retract::ToolMax, 0.0));
    assert_eq!(r("5", "50"), (Retract::Tool, 50.0));
    assert_eq!(r("3", "0"), (Retract::None, 0.0));
    assert_eq!(c800("-1", "0").unwrap_err().column, "CYCLE800(".len() + 1);
    let e = c800("5", "-2").unwrap_err();
    let at = "CYCLE800(5,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,".len() + 1;
    assert_eq!((e.error, e.column), (Error::BadArgument, at));
    // Written in each dialect's terms: MB n <-> _FR 5 with _FR_I, MB MAX <-> _FR 4; the
    // machine-Z retractions as MB MAX; the G-code dialects retract in blocks of their own.
    let mb50 = "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB50 FMAX SEQ-";
    let fr1 = "CYCLE800(1,\"TC1\",200000,57,0,0,0,0,30,0,0,0,0,1,1)";
    // A new retraction for the same plane is the tilt block again.
    let again = [
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX",
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB20 F1000",
    ];
    let (h, s, f) = (Dialect::Heidenhain, Dialect::Sinumerik, Dialect::Fanuc);
    // Source dialect and blocks, target dialect and form, what is written.
    type Case<'a> = (Dialect, &'a [&'a str], Dialect, &'a str, &'a [&'a str]);
    let cases: [Case; 6] = [
        (h, &[mb50], h, "PLANE SPATIAL", &[mb50]),
        (
            h,
            &[mb50],
            s,
            "CYCLE800",
            &["CYCLE800(5,\"\",0,57,0,0,0,0,30,0,0,0,0,-1,50,0)"],
        ),
        (
            h,
            &[mb50],
            f,
            "G68.2",
            &["G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1"],
        ),
        (
            s,
            &[fr1],
            h,
            "PLANE SPATIAL",
            &["PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ+"],
        ),
        (
            s,
            &[fr1],
            s,
            "CYCLE800",
            &["CYCLE800(1,\"\",0,57,0,0,0,0,30,0,0,0,0,1,0,0)"],
        ),
        (h, &again, h, "PLANE SPATIAL", &again),
    ];
    for (from, src, to, form, want) in cases {
        assert_eq!(translate(from, src, to, form), want, "{src:?} into {form}");
    }
}

/// A program translated block by block: what `write_change` writes for the state before and
/// after each source block.
fn translate(from: Dialect, lines: &[&str], to: Dialect, form: &str) -> Vec<String> {
    let mut p = Program::default();
    let mut out = Vec::new();
    for l in lines {
        let (q, _) = p.line(from, l.as_bytes()).unwrap();
        let mut buf = [0u8; MAX_CHANGE];
        let (n, _) = write_change(to, form.as_bytes(), &p, &q, 4, &mut buf).unwrap();
        out.push(String::from_utf8(buf[..n].to_vec()).unwrap());
        p = q;
    }
    out
}

/// A new tilt over an active one: where a block of its own turns the axes (`G68.2` with
/// `G53.1`, `G268` with `G253`) the old one is cancelled first, which every control
/// accepts; a `PLANE`, a `CYCLE800`, a `G158` replace it. Hand-derived: SPA+30 is `Rx(30)`,
/// G68.2 `I0 J30 K0`, G268 `I30 J0 K0`.
#[test]
fn a_new_tilt_over_an_active_one() {
    let prog = [
        "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY",
        "PLANE SPATIAL SPA+0 SPB+0 SPC+0 STAY",
        "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY",
        "PLANE SPATIAL SPA-30 SPB+0 SPC+0 STAY",
    ];
    let fanuc = translate(Dialect::Heidenhain, &prog, Dialect::Fanuc, "G68.2");
    assert_eq!(
        fanuc,
        [
            "G68.2 X0. Y0. Z0. I0. J30. K0.",
            "G69",
            "G68.2 X0. Y0. Z0. I0. J30. K0.",
            // Rx(-30) = Rz(180)·Rx(30)·Rz(180): J stays in [0, 180].
            "G69\nG68.2 X0. Y0. Z0. I180. J30. K180."
        ]
    );
    let haas = translate(Dialect::Heidenhain, &prog, Dialect::Haas, "G268");
    assert_eq!(haas[3], "G269\nG268 X0. Y0. Z0. I-30. J0. K0. Q123");
    for (to, form) in [
        (Dialect::Heidenhain, "PLANE SPATIAL"),
        (Dialect::Sinumerik, "CYCLE800"),
        (Dialect::Syntec, "G158"),
    ] {
        let t = translate(Dialect::Heidenhain, &prog, to, form);
        assert!(!t[3].contains('\n'), "{form}: {}", t[3]);
    }
}

/// Datum shifts are written with the target's own command, the tilt about the shifted
/// datum, a tilt's origin into the datum shift where the form has no origin words, a shift
/// under an active tilt after its cancel, and cancels as cancels. The expected lines are
/// hand-derived: SPB+30 is a rotation about Y by 30°, Rz(90)·Rx(30)·Rz(−90) in G68.2's
/// Z, X', Z'' angles; SPA+30 is Rx(30), G68.2 I0 J30 K0.
#[test]
fn changes_are_written_with_the_targets_own_blocks() {
    let hyper = [
        "1 BEGIN PGM P1 MM",
        "2 CYCL DEF 7.0 DATUM SHIFT",
        "3 CYCL DEF 7.1 X+10",
        "4 CYCL DEF 7.2 Y+20",
        "5 CYCL DEF 7.3 Z-5",
        "6 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-",
        "7 L Z+100 R0 FMAX",
        "8 PLANE RESET STAY",
        "9 END PGM P1 MM",
    ];
    assert_eq!(
        translate(Dialect::Heidenhain, &hyper, Dialect::Fanuc, "G68.2"),
        [
            "",
            "",
            "G52 X10. Y0. Z0.",
            "G52 X10. Y20. Z0.",
            "G52 X10. Y20. Z-5.",
            // TURN: the axes turn to the plane, as G53.1 says.
            "G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1",
            "",
            "G69",
            "",
        ]
    );
    let cycle800 = translate(Dialect::Heidenhain, &hyper, Dialect::Sinumerik, "CYCLE800");
    assert_eq!(cycle800[4], "TRANS X=10 Y=20 Z=-5");
    // MB MAX: the maximum retraction in the tool direction, _FR 4. The shift alone reset
    // first and the cycle carrying the whole origin, the tilt cancelled before the shift is
    // set alone again: the same whether the control keeps CYCLE800's frame apart from
    // TRANS or not.
    assert_eq!(
        cycle800[5],
        "TRANS\nCYCLE800(4,\"\",0,57,10,20,-5,0,30,0,0,0,0,-1,0,0)"
    );
    assert_eq!(cycle800[7], "CYCLE800()\nTRANS X=10 Y=20 Z=-5");
    // The plus direction in SINUMERIK is SEQ+ in Heidenhain, and back.
    let plus = translate(
        Dialect::Sinumerik,
        &["CYCLE800(0,\"T\",0,57,0,0,0,30,0,0,0,0,0,1,0,0)"],
        Dialect::Heidenhain,
        "PLANE SPATIAL",
    );
    // The cycle swivels: TURN.
    assert_eq!(plus, ["PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX SEQ+"]);
    let back = translate(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY SEQ+"],
        Dialect::Sinumerik,
        "CYCLE800",
    );
    // `STAY` computes the plane without swivelling: `_DIR` 0 (the choice waits for the block
    // that turns); with `TURN`, the plus direction.
    assert_eq!(back, ["CYCLE800(0,\"\",0,57,0,0,0,30,0,0,0,0,0,0,0,0)"]);
    let back = translate(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN SEQ+"],
        Dialect::Sinumerik,
        "CYCLE800",
    );
    assert_eq!(back, ["CYCLE800(0,\"\",0,57,0,0,0,30,0,0,0,0,0,1,0,0)"]);
    // A G68.2 origin becomes the datum shift of a PLANE; its cancel resets the shift after
    // cancelling the plane.
    let fanuc = [
        "G68.2 X10 Y20 Z0 I0 J30 K0",
        "G53.1",
        "G69",
        "G52 X1 Y2 Z3",
        "G68.2 I0 J30 K0",
        "G52 X4 Y2 Z3",
    ];
    assert_eq!(
        translate(Dialect::Fanuc, &fanuc, Dialect::Heidenhain, "PLANE SPATIAL"),
        [
            "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+10\nCYCL DEF 7.2 Y+20\nCYCL DEF 7.3 Z+0\nPLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY",
            // G53.1 turns the axes: the plane again, with TURN.
            "PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX",
            "PLANE RESET STAY\nCYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\nCYCL DEF 7.2 Y+0\nCYCL DEF 7.3 Z+0",
            "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+1\nCYCL DEF 7.2 Y+2\nCYCL DEF 7.3 Z+3",
            "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY",
            "PLANE RESET STAY\nCYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+4\nCYCL DEF 7.2 Y+2\nCYCL DEF 7.3 Z+3\nPLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY",
        ]
    );
    // Into G68.2 the tilt keeps its own origin beside the G52.
    assert_eq!(
        translate(Dialect::Fanuc, &fanuc, Dialect::Haas, "G268")[..2],
        ["G268 X10. Y20. Z0. I30. J0. K0. Q123", "G253"]
    );
    // SINUMERIK's ROT has no origin words and its one frame no shift kept apart: the origin
    // is `TRANS`, which replaces the frame, and the rotation `AROT` about it. `G68.2 X10 J30`
    // is Rx(30°) about (10, 0, 0): RPY X=30.
    let mut buf = [0u8; MAX_CHANGE];
    let p0 = Program::default();
    let (p1, _) = p0.line(Dialect::Fanuc, b"G68.2 X10 J30").unwrap();
    let (n, _) = write_change(Dialect::Sinumerik, b"ROT", &p0, &p1, 4, &mut buf).unwrap();
    assert_eq!(&buf[..n], b"TRANS X=10 Y=0 Z=0\nAROT X=30 Y=0 Z=0");
    // From a shift alone, no reset first (the `TRANS` of the tilt replaces it); read back, the
    // same frame.
    let (s1, _) = p0.line(Dialect::Fanuc, b"G52 X5").unwrap();
    let (s2, _) = s1.line(Dialect::Fanuc, b"G68.2 X10 J30").unwrap();
    let (n, _) = write_change(Dialect::Sinumerik, b"ROT", &s1, &s2, 4, &mut buf).unwrap();
    assert_eq!(&buf[..n], b"TRANS X=15 Y=0 Z=0\nAROT X=30 Y=0 Z=0");
    let back = std::str::from_utf8(&buf[..n])
        .unwrap()
        .lines()
        .fold(p0, |q, l| {
            q.line(Dialect::Sinumerik, l.as_bytes()).unwrap().0
        });
    let want = cncrot::Frame::with_translations(
        [15.0, 0.0, 0.0],
        cncrot::elementary(cncrot::Axis::X, 30.0),
        [0.0; 3],
    );
    assert!(back.frame.translation == want.translation);
    let err = back
        .frame
        .rotation
        .iter()
        .zip(&want.rotation)
        .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs()))
        .fold(0.0, f64::max);
    assert!(err < 1e-15, "{err}");
    // A choice of another axis than the master axis is not a word of any block.
    let p2 = Program {
        choice: AxisChoice::Minus(2),
        ..p1
    };
    assert_eq!(
        write_change(Dialect::Heidenhain, b"PLANE SPATIAL", &p0, &p2, 4, &mut buf),
        Err(Error::NotAvailable)
    );
    // A buffer shorter than the longest change, too short for this one: NoRoom.
    assert_eq!(
        write_change(
            Dialect::Heidenhain,
            b"PLANE SPATIAL",
            &p0,
            &p1,
            4,
            &mut buf[..20]
        ),
        Err(Error::NoRoom)
    );
}

/// Every translated program reads back, in the target dialect, as the source program's
/// frames, block by block, for every pair of dialects and forms that can carry the frames.
#[test]
fn translated_programs_read_back_as_the_source() {
    let sources: [(Dialect, &[&str]); 4] = [
        (
            Dialect::Heidenhain,
            &[
                "CYCL DEF 7.1 X+10",
                "CYCL DEF 7.3 Z-5",
                "PLANE SPATIAL SPA+10 SPB+30 SPC-20 STAY SEQ-",
                "PLANE RESET STAY",
                "TRANS DATUM RESET",
                "PLANE EULER EULPR+15 EULNU+40 EULROT+5 TURN",
                "TRANS DATUM AXIS X+3",
            ],
        ),
        (
            Dialect::Fanuc,
            &[
                "G52 X1 Y2",
                "G68.2 X10 Y20 Z-3 I30 J40 K50",
                "G69",
                "G68.2 I0 J90 K0",
                "G52",
            ],
        ),
        (
            Dialect::Sinumerik,
            &[
                "TRANS X10 Y5",
                "CYCLE800(0,\"T\",0,57,1,2,3,10,20,30,0,0,0,1,0,0)",
                "CYCLE800()",
                "TRANS",
            ],
        ),
        (
            Dialect::Twincat,
            &[
                "N30 G58 X200 Y0",
                "N65 ROT Z30 X10",
                "N80 G58 X0 Y200 Z-5",
                "N90 AROT Y15",
                "ROT",
                "G58 X0 Y0 Z0",
            ],
        ),
    ];
    let targets = [
        (Dialect::Twincat, "ROT"),
        (Dialect::Heidenhain, "PLANE SPATIAL"),
        (Dialect::Heidenhain, "PLANE VECTOR"),
        (Dialect::Fanuc, "G68.2"),
        (Dialect::Haas, "G268"),
        (Dialect::Syntec, "G158"),
        (Dialect::Syntec, "G68.2"),
        (Dialect::Sinumerik, "CYCLE800"),
    ];
    for (from, lines) in sources {
        for (to, form) in targets {
            let (mut p, mut q) = (Program::default(), Program::default());
            for l in lines {
                let (next, _) = p.line(from, l.as_bytes()).unwrap();
                let mut buf = [0u8; MAX_CHANGE];
                let (n, _) = write_change(to, form.as_bytes(), &p, &next, -1, &mut buf)
                    .unwrap_or_else(|e| panic!("{from:?} {l} -> {to:?} {form}: {e:?}"));
                for block in buf[..n].split(|&b| b == b'\n').filter(|b| !b.is_empty()) {
                    q = q.line(to, block).unwrap().0;
                }
                assert!(
                    frame_dist(&q.frame, &next.frame) < 1e-12,
                    "{from:?} {l} -> {to:?} {form}: {:?} {:?}",
                    q.frame,
                    next.frame
                );
                p = next;
            }
        }
    }
}

/// LinuxCNC's `Q` on `G68.2`'s Euler form: the proper Euler order of `I J K` (digits 1 X,
/// 2 Y, 3 Z), each about the axis as turned by the ones before; the default 313. Expected
/// frames by hand: a single rotation is the elementary one about its axis; `G68.4` (as the
/// remap's demo `g68.4 x50 q232 i45`) composes in the active plane, its origin taken there.
#[test]
fn linuxcnc_euler_orders() {
    let f = |l: &str| read(Dialect::Fanuc, &[l]).frame;
    assert!(dist(&f("G68.2 Q323 I90 J0 K0").rotation, &r(Axis::Z, 90.0)) < 1e-15);
    assert!(dist(&f("G68.2 Q121 I0 J90 K0").rotation, &r(Axis::Y, 90.0)) < 1e-15);
    assert!(dist(&f("G68.2 Q232 I0 J90 K0").rotation, &r(Axis::Z, 90.0)) < 1e-15);
    assert!(dist(&f("G68.2 Q131 I0 J0 K-30").rotation, &r(Axis::X, -30.0)) < 1e-15);
    assert_eq!(
        f("G68.2 P0 Q313 X1 Y2 Z3 I10 J20 K30"),
        f("G68.2 X1 Y2 Z3 I10 J20 K30")
    );
    // Q232 with all three: Ry(I)·Rz(J)·Ry(K).
    let want = mul(
        &mul(&r(Axis::Y, 10.0), &r(Axis::Z, 20.0)),
        &r(Axis::Y, 30.0),
    );
    assert!(dist(&f("G68.2 Q232 I10 J20 K30").rotation, &want) < 1e-15);
    let p = read(
        Dialect::Fanuc,
        &["G68.2 X10 I0 J30 K0", "G68.4 X50 Q232 I45 J0 K0"],
    );
    let want = mul(&r(Axis::X, 30.0), &r(Axis::Y, 45.0));
    assert!(dist(&p.frame.rotation, &want) < 1e-15);
    assert!(
        frame_dist(
            &Frame::with_translations(p.frame.translation, cncrot::IDENTITY, [0.0; 3]),
            &Frame::with_translations([60.0, 0.0, 0.0], cncrot::IDENTITY, [0.0; 3])
        ) < 1e-13
    );
    // Orders that are not proper Euler orders, and a fraction, are refused at the Q.
    let e = Program::default()
        .line(Dialect::Fanuc, b"G68.2 Q123 I0 J30 K0")
        .unwrap_err();
    assert_eq!(
        (e.error, e.column, e.expected),
        (
            Error::BadSequence,
            8,
            Some("Q: 121, 131, 212, 232, 313 or 323")
        )
    );
    let e = Program::default()
        .line(Dialect::Fanuc, b"G68.2 Q313.5 J30")
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::BadArgument, 8));
    // LinuxCNC's R stays not followed: the sources disagree about the axis it turns about.
    let (_, remark) = Program::default()
        .line(Dialect::Fanuc, b"G68.2 I0 J30 K0 R15")
        .unwrap();
    assert_eq!(remark, Remark::NotFollowed);
}

/// Fanuc's roll-pitch-yaw form `G68.2 P1 Q X Y Z I J K`: each letter's angle about its own
/// axis (I about X, J about Y, K about Z), the rotations about the fixed axes in the order of
/// `Q`. Expected by hand: `Q123 I30 J20` is `Ry(20)·Rx(30)`, tool axis
/// (sin 20°·cos 30°, −sin 30°, cos 20°·cos 30°) = (0.2962, −0.5, 0.8138); `Q321` with the same
/// angles is `Rx(30)·Ry(20)`, tool axis (sin 20°, −sin 30°·cos 20°, cos 30°·cos 20°) =
/// (0.3420, −0.4698, 0.8138) — the block that tells fixed axes from moving ones (moving axes
/// by place would give the first for `Q321` and the second for `Q123`).
#[test]
fn fanuc_roll_pitch_yaw() {
    let f = |l: &str| read(Dialect::Fanuc, &[l]).frame;
    let z = |f: Frame| [f.rotation[0][2], f.rotation[1][2], f.rotation[2][2]];
    let (s20, c20) = (20f64.to_radians().sin(), 20f64.to_radians().cos());
    let (s30, c30) = (0.5, 3f64.sqrt() / 2.0);
    let close = |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-15);
    assert!(close(
        z(f("G68.2 P1 Q123 I30 J20 K0")),
        [s20 * c30, -s30, c20 * c30]
    ));
    assert!(close(
        z(f("G68.2 P1 Q321 I30 J20 K0")),
        [s20, -s30 * c20, c30 * c20]
    ));
    // A letter keeps its axis whatever its place in Q.
    assert!(dist(&f("G68.2 P1 Q321 I10 J0 K0").rotation, &r(Axis::X, 10.0)) < 1e-15);
    assert!(dist(&f("G68.2 P1 Q231 I0 J0 K-40").rotation, &r(Axis::Z, -40.0)) < 1e-15);
    // Q213: Y by J, then the fixed X by I, then the fixed Z by K.
    let want = mul(
        &mul(&r(Axis::Z, 30.0), &r(Axis::X, 10.0)),
        &r(Axis::Y, 20.0),
    );
    assert!(dist(&f("G68.2 P1 Q213 I10 J20 K30").rotation, &want) < 1e-15);
    // Without Q: X, Y, Z [choice]; the origin as in the Euler form.
    let g = f("G68.2 P1 X10. Y-5. Z2. I10 J20 K30");
    assert_eq!(g, f("G68.2 P1 Q123 X10 Y-5 Z2 I10 J20 K30"));
    assert_eq!(g.translation, [10.0, -5.0, 2.0]);
    // Haas's G268 writes the same frame with the same words.
    assert_eq!(
        g,
        read(Dialect::Haas, &["G268 X10. Y-5. Z2. I10. J20. K30. Q123"]).frame
    );
    // G68.4 P1 composes in the active plane: two turns of 15° about X make 30°.
    let p = read(Dialect::Fanuc, &["G68.2 P1 Q123 I15", "G68.4 P1 Q123 I15"]);
    assert!(dist(&p.frame.rotation, &r(Axis::X, 30.0)) < 1e-15);
    // An Euler order, or a repeated axis, is refused at the value of Q.
    for (l, col) in [("G68.2 P1 Q313 J30", 11), ("G68.2 P1 Q112 J30", 11)] {
        let e = Program::default()
            .line(Dialect::Fanuc, l.as_bytes())
            .unwrap_err();
        assert_eq!(
            (e.error, e.column, e.expected),
            (
                Error::BadSequence,
                col,
                Some("Q: 123, 132, 213, 231, 312 or 321")
            ),
            "{l}"
        );
    }
}

/// Programs as CAM posts write them (a Fusion-style Heidenhain program with cycle 7 in
/// German, TCPM, labels, Q parameters, arcs and approach blocks; an NX-style SINUMERIK program
/// with TRAORI and orientation vectors; a Fanuc program with G52, G53.1 and G43.4): every
/// block read, only the work-offset selections not followed, the frames where the tilts are
/// (hand-derived: SPB+45 is Ry(45), G68.2 J45 is Rx(45)), and each program translated into
/// every other dialect reads back as the same frames, block by block.
#[test]
fn cam_programs_read_end_to_end() {
    let heidenhain = [
        "0 BEGIN PGM 1001 MM",
        "1 BLK FORM 0.1 Z X-50 Y-50 Z-50",
        "2 BLK FORM 0.2 X+50 Y+50 Z+0",
        "3 ; T1 D=10 CR=0 - ZMIN=-5 - flat end mill",
        "4 TOOL CALL 1 Z S5000",
        "5 L M3",
        "6 PLANE RESET STAY",
        "7 CYCL DEF 7.0 NULLPUNKT",
        "8 CYCL DEF 7.1 X+0",
        "9 CYCL DEF 7.2 Y+0",
        "10 CYCL DEF 7.3 Z+0",
        "11 PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN MB MAX FMAX SEQ+ TABLE ROT",
        "12 L X+10 Y+20 FMAX",
        "13 M129",
        "14 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS",
        "15 L X+1 Y+2 Z+3 B+45 C+0 F1000",
        "16 FUNCTION RESET TCPM",
        "17 CYCL DEF 32.0 TOLERANCE",
        "18 CYCL DEF 32.1 T0.01",
        "19 L Z+100 R0 FMAX M91",
        "20 * - second op",
        "21 PLANE RESET STAY",
        "22 TRANS DATUM AXIS X+5 Y+5",
        "23 PLANE SPATIAL SPA-30 SPB+0 SPC+0 MOVE DIST50 F1000 SEQ- COORD ROT",
        "24 LBL 1",
        "25 CALL LBL 1 REP2",
        "26 Q1 = 5",
        "27 FN 0: Q2 = +7",
        "28 CC X+0 Y+0",
        "29 C X+10 Y+0 DR+",
        "30 APPR LCT X+10 Y+0 R5 RL F200",
        "31 DEP LCT X+20 Y+0 R5",
        "32 PLANE RESET MOVE FMAX",
        "33 TRANS DATUM RESET",
        "34 M30",
        "35 END PGM 1001 MM",
    ];
    let sinumerik = [
        "N10 G40 G17 G710 G94 G90 G60 G601 FNORM",
        "N20 CYCLE800(1,\"TC1\",200000,57,0,0,0,0,45,0,0,0,0,-1,100,1)",
        "N30 TRAORI",
        "N50 ORIWKS",
        "N60 CYCLE832(0.01,_ORI_ROUGH,0.1)",
        "N70 G0 X10 Y20 A3=0 B3=0 C3=1",
        "N80 CYCLE800()",
        "N90 TRAFOOF",
        "N95 TRANS X10 Y5",
        "N96 AROT Z30",
        "N97 ROT",
        "N100 M30",
    ];
    let fanuc = [
        "%",
        "O1001 (TEST)",
        "N10 G90 G94 G17 G49 G40 G80",
        "N25 G52 X5. Y0. Z0.",
        "N30 G68.2 X0. Y0. Z0. I0. J45. K0.",
        "N40 G53.1",
        "N50 G43 Z50. H1",
        "N60 G0 X10. Y20.",
        "N70 G69",
        "N75 G52 X0 Y0 Z0",
        "N80 G43.4 H1",
        "N90 G1 X1. Y2. Z3. A45. C0. F1000.",
        "N100 G49",
        "N110 M30",
        "%",
    ];
    let programs: [(Dialect, &[&str], usize, Frame); 3] = [
        (
            Dialect::Heidenhain,
            &heidenhain,
            11,
            Frame::from_rotation(r(Axis::Y, 45.0)),
        ),
        (
            Dialect::Sinumerik,
            &sinumerik,
            1,
            Frame::from_rotation(r(Axis::Y, 45.0)),
        ),
        (
            Dialect::Fanuc,
            &fanuc,
            4,
            Frame::with_translations([5.0, 0.0, 0.0], r(Axis::X, 45.0), [0.0; 3]),
        ),
    ];
    for (d, lines, tilted_at, tilt) in programs {
        let mut p = Program::default();
        for (k, l) in lines.iter().enumerate() {
            let (q, remark) = p
                .line(d, l.as_bytes())
                .unwrap_or_else(|e| panic!("{d:?} {l}: {e:?}"));
            assert_ne!(remark, Remark::NotFollowed, "{l}");
            if k == tilted_at {
                assert!(frame_dist(&q.frame, &tilt) < 1e-14, "{l}: {:?}", q.frame);
            }
            p = q;
        }
        assert_eq!(p.frame, Frame::IDENTITY, "{d:?}");
        for (to, form) in [
            (Dialect::Heidenhain, "PLANE SPATIAL"),
            (Dialect::Fanuc, "G68.2"),
            (Dialect::Sinumerik, "CYCLE800"),
            (Dialect::Haas, "G268"),
            (Dialect::Syntec, "G158"),
        ] {
            let (mut p, mut q) = (Program::default(), Program::default());
            for l in lines {
                let (next, _) = p.line(d, l.as_bytes()).unwrap();
                let mut buf = [0u8; MAX_CHANGE];
                let (n, _) = write_change(to, form.as_bytes(), &p, &next, 4, &mut buf).unwrap();
                for block in buf[..n].split(|&b| b == b'\n').filter(|b| !b.is_empty()) {
                    q = q.line(to, block).unwrap().0;
                }
                assert!(frame_dist(&q.frame, &next.frame) < 1e-4, "{l} -> {form}");
                p = next;
            }
        }
    }
}

/// How the machine moves to the plane is kept and written in each dialect's own words:
/// Heidenhain `STAY`/`TURN`/`MOVE` ↔ Fanuc-style `G53.1` (turn) and `G53.6` (turn, tool tip
/// kept) after the `G68.2` ↔ Haas `G253`; a `CYCLE800` swivels (turn); a reset or a zero
/// tilt with `TURN` turns the axes to the untilted plane (turn, kept), and so does a
/// `G53.1` or `G253` with no tilt active (after a `G68.2` of zeros; without one the control
/// raises an alarm).
#[test]
fn positioning_words_are_kept_and_written() {
    use Positioning::{Move, Stay, Turn};
    let h = |l: &str| read(Dialect::Heidenhain, &[l]).positioning;
    assert_eq!(h("PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY"), Stay);
    assert_eq!(
        h("PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ-"),
        Turn
    );
    assert_eq!(
        h("PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE DIST50 F1000"),
        Move
    );
    assert_eq!(h("PLANE SPATIAL SPA+0 SPB+30 SPC+0"), Stay);
    assert_eq!(h("PLANE RESET TURN FMAX"), Turn);
    assert_eq!(h("PLANE RESET STAY"), Stay);
    assert_eq!(h("PLANE SPATIAL SPA+0 SPB+0 SPC+0 MOVE FMAX"), Move);
    assert_eq!(
        read(Dialect::Fanuc, &["G68.2 I0 J0 K0", "G53.1"]).positioning,
        Turn
    );
    assert_eq!(read(Dialect::Haas, &["G253"]).positioning, Turn);
    assert_eq!(read(Dialect::Fanuc, &["G53.1", "G69"]).positioning, Stay);
    assert_eq!(
        read(Dialect::Haas, &["G268 J30 Q123", "G253"]).positioning,
        Turn
    );
    assert_eq!(
        read(
            Dialect::Sinumerik,
            &["CYCLE800(1,\"TC1\",200000,57,0,0,0,0,45,0,0,0,0,-1,100,1)"]
        )
        .positioning,
        Turn
    );
    let cases: [(&str, &[&str], &[&str]); 3] = [
        (
            "MOVE",
            &["G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.6"],
            &["PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE FMAX"],
        ),
        (
            "TURN",
            &["G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1"],
            &["PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX"],
        ),
        (
            "STAY",
            &["G68.2 X0. Y0. Z0. I90. J30. K-90."],
            &["PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY"],
        ),
    ];
    for (word, fanuc, heidenhain) in cases {
        let line = format!("PLANE SPATIAL SPA+0 SPB+30 SPC+0 {word}");
        let src = [line.as_str()];
        assert_eq!(
            translate(Dialect::Heidenhain, &src, Dialect::Fanuc, "G68.2"),
            fanuc
        );
        assert_eq!(
            translate(
                Dialect::Heidenhain,
                &src,
                Dialect::Heidenhain,
                "PLANE SPATIAL"
            ),
            heidenhain
        );
    }
    // Fanuc's two blocks become one PLANE, then the same PLANE with the way to move.
    assert_eq!(
        translate(
            Dialect::Fanuc,
            &["G68.2 I90 J30 K-90", "G53.6", "G69"],
            Dialect::Heidenhain,
            "PLANE SPATIAL"
        ),
        [
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 MOVE FMAX",
            "PLANE RESET STAY"
        ]
    );
    // Haas has one code for turning; Syntec's G68.2 mode has Fanuc's two.
    assert_eq!(
        translate(
            Dialect::Fanuc,
            &["G68.2 J30", "G53.6"],
            Dialect::Haas,
            "G268"
        ),
        ["G268 X0. Y0. Z0. I30. J0. K0. Q123", "G253"]
    );
    assert_eq!(
        translate(
            Dialect::Fanuc,
            &["G68.2 J30", "G53.6"],
            Dialect::Syntec,
            "G68.2"
        ),
        ["G68.2 X0. Y0. Z0. I0. J30. K0.", "G53.6"]
    );
    // The same tilt commanded again after a G53.1 stays where it is: no block takes a
    // G53.1 or G253 back, so the tilt block is written again without it.
    assert_eq!(
        translate(
            Dialect::Fanuc,
            &["G68.2 J30", "G53.1", "G68.2 J30"],
            Dialect::Haas,
            "G268"
        ),
        [
            "G268 X0. Y0. Z0. I30. J0. K0. Q123",
            "G253",
            "G268 X0. Y0. Z0. I30. J0. K0. Q123"
        ]
    );
    assert_eq!(
        translate(
            Dialect::Fanuc,
            &["G68.2 J30", "G53.1", "G68.2 J30"],
            Dialect::Heidenhain,
            "PLANE SPATIAL"
        ),
        [
            "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY",
            "PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX",
            "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY"
        ]
    );
    // Every translation reads back with the same way of moving where the target says it.
    for (to, form) in [
        (Dialect::Heidenhain, "PLANE EULER"),
        (Dialect::Fanuc, "G68.2"),
        (Dialect::Syntec, "G68.2"),
    ] {
        for src in [
            &["G68.2 J30", "G53.1", "G68.2 J40", "G53.6", "G69"][..],
            &["G52 X5", "G68.2 J30", "G53.6", "G52 X6", "G69"],
            &[
                "G68.2 J30",
                "G53.1",
                "G68.2 J30",
                "G53.6",
                "G68.2 J30",
                "G69",
            ],
        ] {
            let (mut p, mut q) = (Program::default(), Program::default());
            for l in src {
                let (next, _) = p.line(Dialect::Fanuc, l.as_bytes()).unwrap();
                let mut buf = [0u8; MAX_CHANGE];
                let (n, _) = write_change(to, form.as_bytes(), &p, &next, -1, &mut buf).unwrap();
                for block in buf[..n].split(|&b| b == b'\n').filter(|b| !b.is_empty()) {
                    q = q.line(to, block).unwrap().0;
                }
                assert_eq!(q.positioning, next.positioning, "{l} -> {form}");
                assert!(frame_dist(&q.frame, &next.frame) < 1e-12, "{l} -> {form}");
                p = next;
            }
        }
    }
}

/// What real programs write around their tilts (found running public programs through the
/// reader): Heidenhain's block skip mark before the block number (`/7 PLANE …`, read as
/// the ISO dialects read `/G68.2`: the block runs while block skip is off), SINUMERIK's
/// `CYCLE800` without parentheses (the cancel), and a Fanuc `G68.2` after the motion mode
/// with a feed on the block (a shop's `G1 G68.2 … F300.`, whose own table says tool along
/// +X: by hand Rz(90)·Rx(90)·Rz(−90)·e_z = Rz(90)·(0, −1, 0) = (1, 0, 0)).
#[test]
fn what_real_programs_write_around_their_tilts() {
    let p = read(
        Dialect::Heidenhain,
        &["/7 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY", "/8 L X+0 FMAX"],
    );
    assert!(dist(&p.frame.rotation, &r(Axis::Y, 30.0)) < 1e-15);
    let (_, remark) = p.line(Dialect::Heidenhain, b"/81 M30").unwrap();
    assert_eq!(remark, Remark::Passed);
    let s = read(
        Dialect::Sinumerik,
        &["CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1)"],
    );
    for off in ["CYCLE800", "N20 CYCLE800 ; swivel off"] {
        let (q, remark) = s.line(Dialect::Sinumerik, off.as_bytes()).unwrap();
        assert_eq!(
            (q.frame, remark),
            (Frame::IDENTITY, Remark::Applied),
            "{off}"
        );
    }
    let e = s.line(Dialect::Sinumerik, b"CYCLE800 X").unwrap_err();
    assert_eq!(e.error, Error::MissingWord);
    for (line, z) in [
        (
            "N00 G1 G68.2 X0. Y0. Z0. I90. J90. K-90. F300. ( ROTATE )",
            [1.0, 0.0, 0.0],
        ),
        (
            "N30 G0 G90 G68.2 X0. Y0. Z0. I0. J90. K0.",
            [0.0, -1.0, 0.0],
        ),
    ] {
        let f = read(Dialect::Fanuc, &[line]).frame.rotation;
        for (k, zk) in z.iter().enumerate() {
            assert!((f[k][2] - zk).abs() < 1e-15, "{line}");
        }
    }
}

/// CAM output tilts with `STAY` (or cycle 19) and turns the rotary axes in the next block to
/// the positions the control left in `Q120`–`Q122`: that block is the turn (the state's
/// positioning, so a translation writes `G53.1`), the frame unchanged; any other `L` block
/// is a move.
#[test]
fn heidenhain_turns_to_the_plane_through_q120_to_q122() {
    use Remark::{Applied as A, Passed as P};
    let tilt = "55 PLANE SPATIAL SPA90 SPB0 SPC180 STAY SEQ- TABLE ROT";
    for (turn, feed) in [
        ("56 L A+Q120 C+Q122 R0 FMAX M126", (Feed::Rapid, 0.0)),
        ("56 L B+Q121 C+Q122 F MAX", (Feed::Rapid, 0.0)),
        ("L A+Q120 B+Q121 C+Q122 R0 F500 ; turn", (Feed::Rate, 500.0)),
        // The spindle and coolant switched on the same block: still the turn (a translation
        // keeps `M3 M8` as the block's rest).
        ("L A+Q120 C+Q122 R0 FMAX M3 M8", (Feed::Rapid, 0.0)),
    ] {
        let p = remarks(Dialect::Heidenhain, &[(tilt, A), (turn, A)]);
        let before = read(Dialect::Heidenhain, &[tilt]);
        assert_eq!(p.frame, before.frame, "{turn}");
        assert_eq!(p.choice, AxisChoice::Minus(0), "{turn}");
        assert_eq!(p.positioning, Positioning::Turn, "{turn}");
        assert_eq!((p.feed, p.feed_mm_min), feed, "{turn}");
    }
    let p = read(Dialect::Heidenhain, &["CYCL DEF 19.1 B+30"]);
    let (q, remark) = p.line(Dialect::Heidenhain, b"L B+Q121 R0 FMAX").unwrap();
    assert_eq!((q.positioning, remark), (Positioning::Turn, A));
    for other in [
        "L A+Q121 C+Q122 R0 FMAX",
        "L X+10 A+Q120 R0 FMAX",
        "L A+Q120 C+Q122 R0 FMAX M3.5",
        "L A+0 C+90 R0 FMAX",
        "L R0 FMAX",
    ] {
        let (q, remark) = p.line(Dialect::Heidenhain, other.as_bytes()).unwrap();
        assert_eq!((q, remark), (p, P), "{other}");
    }
    // Turned already (cycle 19 with its feed): the state unchanged.
    let turned = read(Dialect::Heidenhain, &["CYCL DEF 19.1 B+30 F1000"]);
    let (q, remark) = turned
        .line(Dialect::Heidenhain, b"L B+Q121 R0 FMAX")
        .unwrap();
    assert_eq!((q, remark), (turned, A));
    // Nothing active (the pair a post writes for a plane of zeros, as a hyperMILL post
    // for a DMU writes it): the turn to the untilted plane, which a translation says so.
    let zero = read(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA0 SPB0 SPC0 STAY SEQ+ TABLE ROT"],
    );
    assert!(!zero.is_active());
    let (q, remark) = zero
        .line(Dialect::Heidenhain, b"57 L A+Q120 C+Q122 R0 FMAX M126")
        .unwrap();
    assert_eq!(
        (q.frame, q.positioning, remark),
        (Frame::IDENTITY, Positioning::Turn, A)
    );
    let mut buf = [0u8; 512];
    let (n, _) = write_block(
        Dialect::Fanuc,
        b"G68.2",
        &zero,
        &q,
        b"57 L A+Q120 C+Q122 R0 FMAX M126",
        4,
        &mut buf,
    )
    .unwrap();
    assert_eq!(&buf[..n], b"G68.2 X0. Y0. Z0. I0. J0. K0.\nG53.1\nG69");
}

/// A datum shift under a plane that turned the axes (`PLANE … TURN MB MAX`, then cycle 7)
/// moves no rotary axis on the control: the shift is no positioning block. Written into a
/// target that says the shift beside the plane again, the plane again stays where it is:
/// Fanuc's `G68.2` without `G53.1`, SINUMERIK's `CYCLE800` with `_FR` 0 and `_DIR` 0 (no
/// retraction, no swivel). It was written with the state's `TURN MB MAX` (a helper's find:
/// `CYCLE800(4,…,1,…)`, a retraction to the travel end and a swivel at a datum shift). The
/// shift is (10·cos 30°, 0, −10·sin 30°), the tilted X' of SPB+30.
#[test]
fn a_shift_under_a_turned_plane_turns_nothing() {
    let d = Dialect::Heidenhain;
    let before = read(
        d,
        &[
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ+",
            "CYCL DEF 7.0 DATUM SHIFT",
        ],
    );
    let text = b"CYCL DEF 7.1 X+10";
    let (after, _) = before.line(d, text).unwrap();
    assert_eq!(after.positioning, Positioning::Turn);
    assert_eq!(
        block_in(Dialect::Fanuc, "G68.2", &before, &after, text),
        "G69\nG52 X8.6603 Y0. Z-5.\nG68.2 X0. Y0. Z0. I90. J30. K-90."
    );
    assert_eq!(
        block_in(Dialect::Sinumerik, "CYCLE800", &before, &after, text),
        "CYCLE800(0,\"\",0,57,8.6603,0,-5,0,30,0,0,0,0,0,0,0)"
    );
    // The plane itself still turns, as before.
    let p0 = Program::default();
    let plane = b"PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ+";
    let (p1, _) = p0.line(d, plane).unwrap();
    assert_eq!(
        block_in(Dialect::Fanuc, "G68.2", &p0, &p1, plane),
        "G68.2 X0. Y0. Z0. I90. J30. K-90.\nG53.1"
    );
}

/// A swivel to the plane the state is at already (a post's tool change: the same `CYCLE800`
/// again, or `G53.1` again, after the program moved the rotary axes) turns the axes again on
/// the control: it is written as that turn, though the state does not change. It was
/// written as nothing (a helper's find: the head stayed at B0 C0 after the tool change and
/// the program went on in the tilted frame). By hand: `_B` 30 of mode 57 is Ry(30°), SPB+30.
#[test]
fn a_swivel_to_the_same_plane_turns_again() {
    let d = Dialect::Sinumerik;
    let text = "CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)";
    let before = read(d, &[text]);
    let (after, _) = before.line(d, text.as_bytes()).unwrap();
    assert_eq!(after, before);
    let text = text.as_bytes();
    let heidenhain = |b: &Program, a: &Program, t: &[u8]| {
        block_in(Dialect::Heidenhain, "PLANE SPATIAL", b, a, t)
    };
    assert_eq!(
        heidenhain(&before, &after, text),
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ-"
    );
    assert_eq!(
        block_in(Dialect::Fanuc, "G68.2", &before, &after, text),
        "G53.1"
    );
    // Fanuc's `G53.1` again, into Heidenhain: the plane again with TURN.
    let f = Dialect::Fanuc;
    let before = read(f, &["G68.2 X0 Y0 Z0 I0 J30 K0", "G53.1", "T2 M6"]);
    let (after, _) = before.line(f, b"G53.1").unwrap();
    assert_eq!(
        heidenhain(&before, &after, b"G53.1"),
        "PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX"
    );
    // A block that states no way of moving under the same tilt stays written as nothing.
    let (after, _) = before.line(f, b"G0 X10").unwrap();
    assert_eq!(heidenhain(&before, &after, b"G0 X10"), "");
}

/// A block that changes nothing and states no way of moving under a plane that turned is
/// written as nothing: cycle 19's first line (`CYCL DEF 19.0 WORKING PLANE`, which only
/// names the cycle) where a program switches the cycle off after `L B+Q121 C+Q122`. It was
/// written as the plane again without its turn (`G68.2 …` in `G68.2` mode, just before the
/// `G69` of the cancel).
#[test]
fn a_block_that_changes_nothing_writes_nothing() {
    let h = Dialect::Heidenhain;
    let before = read(
        h,
        &[
            "CYCL DEF 19.0 WORKING PLANE",
            "CYCL DEF 19.1 B+30 C+0",
            "L B+Q121 C+Q122 R0 FMAX",
        ],
    );
    assert_eq!(before.positioning, Positioning::Turn);
    let text = b"CYCL DEF 19.0 WORKING PLANE";
    let (after, _) = before.line(h, text).unwrap();
    assert_eq!(after, before);
    assert_eq!(block_in(Dialect::Fanuc, "G68.2", &before, &after, text), "");
    assert_eq!(
        block_in(Dialect::Sinumerik, "CYCLE800", &before, &after, text),
        ""
    );
    // The cancel that follows is the cancel.
    let (off, _) = after.line(h, b"CYCL DEF 19.1").unwrap();
    assert_eq!(
        block_in(Dialect::Fanuc, "G68.2", &after, &off, b"CYCL DEF 19.1"),
        "G69"
    );
}

/// A reset that turns the axes home while a datum shift changes or stays apart from the
/// tilt: the cancel the shift needs first is that turn. Two helpers' finds: `PLANE RESET TURN
/// MB MAX` after `TRANS DATUM AXIS X+50` and a plane, into SINUMERIK, was `CYCLE800()` (the
/// turn lost, with a note that it had no word: `CYCLE800` of zeros with `_DIR` says it);
/// a `CYCLE800` of zeros with `_DIR` −1 after a swivel with `_Z0` 50 and `CYCLE800()`, into
/// Heidenhain, was `PLANE RESET STAY` and cycle 7 (the swivel home lost, no note).
#[test]
fn a_reset_that_turns_home_beside_a_shift_turns() {
    let h = Dialect::Heidenhain;
    let before = read(
        h,
        &[
            "TRANS DATUM AXIS X+50",
            "PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX",
        ],
    );
    let text = b"PLANE RESET TURN MB MAX FMAX";
    let (after, _) = before.line(h, text).unwrap();
    assert_eq!(
        block_in(Dialect::Sinumerik, "CYCLE800", &before, &after, text),
        "CYCLE800(4,\"\",0,57,0,0,0,0,0,0,0,0,0,-1,0,0)\nTRANS X=50 Y=0 Z=0"
    );
    // From a shift alone, the turn home is the zero tilt that turns, then the shift.
    let shifted = read(h, &["TRANS DATUM AXIS X+50"]);
    let text = b"PLANE RESET TURN FMAX";
    let (home, _) = shifted.line(h, text).unwrap();
    assert_eq!(
        block_in(Dialect::Sinumerik, "CYCLE800", &shifted, &home, text),
        "CYCLE800(0,\"\",0,57,0,0,0,0,0,0,0,0,0,-1,0,0)\nTRANS X=50 Y=0 Z=0"
    );
    let s = Dialect::Sinumerik;
    let before = read(
        s,
        &[
            "CYCLE800(1,\"TC1\",0,57,0,0,50,0,30,0,0,0,0,-1)",
            "CYCLE800()",
        ],
    );
    let text = b"CYCLE800(1,\"TC1\",0,57,0,0,0,0,0,0,0,0,0,-1)";
    let (after, _) = before.line(s, text).unwrap();
    let tilted = read(s, &["CYCLE800(1,\"TC1\",0,57,0,0,50,0,30,0,0,0,0,-1)"]);
    // The cancel and the swivel home written as one (a translator joins them).
    let mut buf = [0u8; 1024];
    let (n, _) = write_change(h, b"PLANE SPATIAL", &tilted, &after, 4, &mut buf).unwrap();
    assert_eq!(
        String::from_utf8_lossy(&buf[..n]),
        "PLANE RESET TURN MB MAX FMAX\nCYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\n\
         CYCL DEF 7.2 Y+0\nCYCL DEF 7.3 Z+0"
    );
}

/// The iTNC 530 manual's table of `SEQ` on an A/C table machine (A about X carrying C about
/// Z, no limit switches), `PLANE SPATIAL SPA+0 SPB+45 SPC+0`: from A0 C0 `SEQ+` gives
/// A+45 C+90, `SEQ-` A−45 C−90; without `SEQ` A+45 C+90 from A0 C0 (both are as far) and
/// the nearer A−45 C−90 from A0 C−105. By hand:
/// the table turns the workpiece by `Rx(A)·Rz(C)`, so the tool points along
/// `Rz(−90)·(0, sin 45°, cos 45°) = (sin 45°, 0, cos 45°)` in the workpiece, SPB+45's.
#[test]
fn heidenhain_seq_on_an_ac_table_as_the_manual_tabulates() {
    use cncrot::kinematics::{Machine, RotaryAxis, Side};
    let axis = |d: [f64; 3]| RotaryAxis::new(Side::Work, d, [0.0; 3]);
    let m = Machine::new([0.0, 0.0, 1.0])
        .unwrap()
        .with_axis(axis([1.0, 0.0, 0.0]))
        .unwrap()
        .with_axis(axis([0.0, 0.0, 1.0]))
        .unwrap();
    let plane = "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX";
    for (seq, current, want) in [
        (" SEQ+", [0.0, 0.0, 0.0], [45.0, 90.0]),
        (" SEQ-", [0.0, 0.0, 0.0], [-45.0, -90.0]),
        // Both equally far: the manual's pick.
        ("", [0.0, 0.0, 0.0], [45.0, 90.0]),
        ("", [0.0, -105.0, 0.0], [-45.0, -90.0]),
    ] {
        let line = format!("{plane}{seq}");
        let p = read(Dialect::Heidenhain, &[&line]);
        let c = p.axes(&m, current).unwrap();
        for (got, want) in c.axes.iter().zip(want) {
            assert!(
                (got - want).abs() < 1e-12,
                "{line} from {current:?}: {:?}",
                c.axes
            );
        }
    }
}

/// `TABLE ROT` and `COORD ROT` on a head B (about Y) with a table C (about Z): for `SPC+90`
/// the tool stays vertical, so B is 0 and C free. `COORD ROT` (and no word) leaves the
/// table where it is, the coordinate system turns; `TABLE ROT` turns the table so that the
/// machine makes the rotation. By hand: the table turns the workpiece by `Rz(C)`, so the
/// frame in the workpiece is `Rz(−C)`, and `Rz(90°)` needs C = −90° (from C = 0; from
/// C = 700° the turn nearest, 630°). Where the tool direction fixes C (`SPB+30 SPC+90`) the
/// words change nothing. The word is kept in the state and written back; a reset clears it.
#[test]
fn heidenhain_table_rot_turns_a_free_table() {
    use cncrot::kinematics::{Machine, RotaryAxis, Side};
    let m = Machine::new([0.0, 0.0, 1.0])
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Work, [0.0, 0.0, 1.0], [0.0; 3]))
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3]))
        .unwrap();
    let plane = "PLANE SPATIAL SPA+0 SPB+0 SPC+90 TURN FMAX";
    for (words, current, c_axis, free) in [
        ("", 0.0, 0.0, true),
        (" COORD ROT", 20.0, 20.0, true),
        (" TABLE ROT", 0.0, -90.0, false),
        (" SEQ+ TABLE ROT", 700.0, 630.0, false),
    ] {
        let line = format!("{plane}{words}");
        let p = read(Dialect::Heidenhain, &[&line]);
        assert_eq!(p.table_rot, words.contains("TABLE"), "{line}");
        let c = p.axes(&m, [current, 0.0, 0.0]).unwrap();
        assert!((c.axes[0] - c_axis).abs() < 1e-9, "{line}: {:?}", c.axes);
        assert!(c.axes[1].abs() < 1e-9, "{line}: {:?}", c.axes);
        assert_eq!(c.free, free, "{line}");
        if !free {
            let f = m.forward(c.axes).unwrap();
            assert!(dist(&f.rotation, &r(Axis::Z, 90.0)) < 1e-12, "{line}");
        }
        // Written back as read.
        let mut out = [0u8; MAX_CHANGE];
        let (n, _) = write_change(
            Dialect::Heidenhain,
            b"PLANE SPATIAL",
            &Program::default(),
            &p,
            -1,
            &mut out,
        )
        .unwrap();
        let text = std::str::from_utf8(&out[..n]).unwrap();
        assert_eq!(text.contains("TABLE ROT"), p.table_rot, "{text}");
        assert_eq!(read(Dialect::Heidenhain, &[text]).table_rot, p.table_rot);
    }
    let p = read(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA+0 SPB+30 SPC+90 TURN TABLE ROT"],
    );
    let q = read(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA+0 SPB+30 SPC+90 TURN COORD ROT"],
    );
    assert_eq!(p.axes(&m, [0.0; 3]), q.axes(&m, [0.0; 3]));
    let (off, _) = p.line(Dialect::Heidenhain, b"PLANE RESET STAY").unwrap();
    assert!(!off.table_rot);
    // Three axes (a table A under a head C carrying A) at their pole (C 0: both A about X)
    // make the whole rotation of SPA+30: nothing is left for a table, the choice (with its
    // free axis) as the machine makes it.
    let x = [1.0, 0.0, 0.0];
    let three = Machine::new([0.0, 0.0, 1.0])
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Work, x, [0.0; 3]))
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Tool, [0.0, 0.0, 1.0], [0.0; 3]))
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Tool, x, [0.0; 3]))
        .unwrap();
    let tilt = "PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN";
    let p = read(Dialect::Heidenhain, &[&format!("{tilt} TABLE ROT")]);
    let q = read(Dialect::Heidenhain, &[tilt]);
    let c = p.axes(&three, [10.0, 0.0, 0.0]).unwrap();
    assert!(c.free);
    assert_eq!(Ok(c), q.axes(&three, [10.0, 0.0, 0.0]));
}

/// Heidenhain's cycle 19, WORKING PLANE, as CAM posts write it. Spatial angles (the
/// default): about the fixed axes, A then B then C, `F = Rz(C)·Ry(B)·Rx(A)` (the manual:
/// "first around the A axis, then B, and then C"), those not written 0, about the shifted
/// datum; it replaces the active tilt; zero angles and a second line without angles cancel
/// it. With the machine set to axis angles: the rotary positions, a direct mode.
#[test]
fn heidenhain_cycle_19() {
    use Remark::Applied as A;
    let p = remarks(
        Dialect::Heidenhain,
        &[
            ("10 CYCL DEF 7.0 DATUM SHIFT", A),
            ("11 CYCL DEF 7.1 X+10", A),
            ("12 CYCL DEF 19.0 WORKING PLANE", A),
            ("13 CYCL DEF 19.1 A+30 C+90", A),
        ],
    );
    let want = mul(&r(Axis::Z, 90.0), &r(Axis::X, 30.0));
    assert!(dist(&p.frame.rotation, &want) < 1e-15);
    assert_eq!(p.frame.translation, [10.0, 0.0, 0.0]);
    assert_eq!((p.positioning, p.direct), (Positioning::Stay, None));
    // By hand: A+30 B+45 C+60 moves the tool axis to Rz(60)·Ry(45)·Rx(30)·e_z.
    let (s30, c30) = (0.5, 0.75f64.sqrt());
    let h = 0.5f64.sqrt();
    let z_after_a = [0.0, -s30, c30];
    let z_after_b = [h * z_after_a[2], z_after_a[1], h * z_after_a[2]];
    let (s60, c60) = (c30, s30);
    let z = [
        c60 * z_after_b[0] - s60 * z_after_b[1],
        s60 * z_after_b[0] + c60 * z_after_b[1],
        z_after_b[2],
    ];
    let q = read(Dialect::Heidenhain, &["CYCL DEF 19.1 B+45 C+60 A+30"]);
    for (k, zk) in z.iter().enumerate() {
        assert!((q.frame.rotation[k][2] - zk).abs() < 1e-15, "{k}");
    }
    // A second cycle 19 replaces the first; the automatic positioning's feed turns the axes.
    let q = p
        .line(Dialect::Heidenhain, b"14 CYCL DEF 19.1 B-20 F1000 DIST50")
        .unwrap()
        .0;
    assert!(dist(&q.frame.rotation, &r(Axis::Y, -20.0)) < 1e-15);
    assert_eq!(q.frame.translation, [10.0, 0.0, 0.0]);
    assert_eq!(
        (q.positioning, q.feed, q.feed_mm_min),
        (Positioning::Turn, Feed::Rate, 1000.0)
    );
    // The reset CAM posts write: all angles 0, then the cycle without angles.
    for reset in [
        &["CYCL DEF 19.0 WORKING PLANE", "CYCL DEF 19.1 A+0 B+0 C+0"][..],
        &["CYCL DEF 19.0", "CYCL DEF 19.1"],
    ] {
        let mut q = p;
        for l in reset {
            q = q.line(Dialect::Heidenhain, l.as_bytes()).unwrap().0;
        }
        assert_eq!(q.frame.rotation, cncrot::IDENTITY, "{reset:?}");
        assert_eq!(q.frame.translation, [10.0, 0.0, 0.0], "{reset:?}");
        assert_eq!(q.positioning, Positioning::Stay);
    }
    // Malformed: a line the cycle does not have, a word twice, a parameter for a number.
    for (line, error, column) in [
        ("CYCL DEF 19.2 A+0", Error::UnknownWord, 14),
        ("CYCL DEF 19.1 B+10 B+20", Error::UnknownWord, 20),
        ("CYCL DEF 19.1 B+Q121", Error::NotANumber, 17),
        ("CYCL DEF 19.1 X+10", Error::UnknownWord, 15),
    ] {
        let e = p.line(Dialect::Heidenhain, line.as_bytes()).unwrap_err();
        assert_eq!((e.error, e.column), (error, column), "{line}");
    }
    // Axis angles (a setting of the machine): the positions of B and C, as PLANE AXIAL.
    let axial = Program {
        axis_angles: true,
        ..Program::default()
    };
    let q = axial
        .line(Dialect::Heidenhain, b"CYCL DEF 19.1 B+30 C+45 F2000")
        .unwrap()
        .0;
    assert_eq!(
        q.direct,
        Some(Direct {
            by: DirectAxes::Letters,
            given: 0b110
        })
    );
    assert_eq!(q.angles, [0.0, 30.0, 45.0]);
    assert_eq!(q.positioning, Positioning::Turn);
    let q = q.line(Dialect::Heidenhain, b"CYCL DEF 19.1").unwrap().0;
    assert!(!q.is_active() && q.direct.is_none());
}

/// Posts written for a decimal comma (a Swedish post's cycles 7 and 19: `7.1 X+25,`,
/// `19.1 A-8,182 B+0, C-90,`): read as the same blocks written with points, bit for bit.
#[test]
fn heidenhain_reads_a_decimal_comma() {
    let comma = [
        "1 CYCL DEF 7.0 DATUM SHIFT",
        "2 CYCL DEF 7.1 X+25,",
        "3 CYCL DEF 7.2 Y-12,5",
        "4 CYCL DEF 7.3 Z+0,",
        "5 CYCL DEF 19.0 WORKING PLANE",
        "6 CYCL DEF 19.1 A-8,182 B+0, C-90,",
        "7 PLANE RELATIV SPB+2,25 TURN MB50, F2500, SEQ-",
    ];
    let point: Vec<String> = comma.iter().map(|l| l.replace(',', ".")).collect();
    let point: Vec<&str> = point.iter().map(String::as_str).collect();
    let (a, b) = (
        read(Dialect::Heidenhain, &comma),
        read(Dialect::Heidenhain, &point),
    );
    assert_eq!(a, b);
    assert_eq!(a.shift, [25.0, -12.5, 0.0]);
    assert_eq!((a.retract_mm, a.feed_mm_min), (50.0, 2500.0));
    // One mark per number: the second one is where the number goes wrong.
    let e = Program::default()
        .line(Dialect::Heidenhain, b"CYCL DEF 19.1 A-8,1,82")
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::Parse, 20));
    // The other dialects keep the comma for what separates: a cycle's arguments.
    let e = Program::default()
        .line(Dialect::Fanuc, b"G68.2 X0 Y0 Z0 I0 J8,5 K0")
        .unwrap_err();
    assert_eq!(e.error, Error::Parse);
}

/// The direct modes (`PLANE AXIAL`, `G158` mode 2, a `CYCLE800` with `_MODE` 192) keep the
/// rotary-axis positions; the machine gives the frame. Hand derivation: on a table whose B
/// (about Y) carries C (about Z), the workpiece turns by `W = Ry(B)·Rz(C)`, so the tilted
/// frame in workpiece coordinates is `W⁻¹ = Rz(−C)·Ry(−B)`.
#[test]
fn direct_modes_keep_the_positions_and_the_machine_gives_the_frame() {
    use cncrot::kinematics::{Machine, RotaryAxis, Side};
    let axis = |d: [f64; 3]| RotaryAxis::new(Side::Work, d, [0.0; 3]);
    let mut b = axis([0.0, 1.0, 0.0]);
    b.limits = Some([-10.0, 100.0]);
    let m = Machine::new([0.0, 0.0, 1.0])
        .unwrap()
        .with_axis(b)
        .unwrap()
        .with_axis(axis([0.0, 0.0, 1.0]))
        .unwrap();
    let want = |bb: f64, c: f64| mul(&r(Axis::Z, -c), &r(Axis::Y, -bb));
    let cases = [
        (
            Dialect::Heidenhain,
            "PLANE AXIAL B+30 C+45 TURN FMAX",
            [0.0; 3],
        ),
        (
            Dialect::Syntec,
            "G158 P10200 X0 Y0 Z10 A0 B30 C45 U0 V0 W0",
            [0.0, 0.0, 10.0],
        ),
        (
            Dialect::Sinumerik,
            "CYCLE800(0,\"TC1\",0,192,5,0,0,30,45,0,0,0,0,-1)",
            [5.0, 0.0, 0.0],
        ),
    ];
    for (d, line, origin) in cases {
        let p = read(d, &[line]);
        assert!(p.direct.is_some() && p.is_active(), "{line}");
        assert_eq!(p.positioning, Positioning::Turn, "{line}");
        let f = p.frame_on(&m).unwrap();
        assert!(dist(&f.rotation, &want(30.0, 45.0)) < 1e-15, "{line}");
        assert_eq!(f.translation, origin, "{line}");
        let c = p.axes(&m, [0.0; 3]).unwrap();
        assert_eq!(c.axes, [30.0, 45.0, 0.0], "{line}");
        assert!(!c.free && c.residual == [0.0; 3]);
    }
    // By letter: A on a machine without an A axis only at 0; B beyond its travel refused;
    // the modulo C's turn nearest the current position.
    let p = read(Dialect::Heidenhain, &["PLANE AXIAL A+10 B+30"]);
    assert_eq!(p.axes(&m, [0.0; 3]), Err(Error::BadArgument));
    assert_eq!(p.frame_on(&m), Err(Error::BadArgument));
    let p = read(Dialect::Heidenhain, &["PLANE AXIAL A+0 B+30"]);
    assert_eq!(p.axes(&m, [0.0; 3]).unwrap().axes, [30.0, 0.0, 0.0]);
    let p = read(Dialect::Heidenhain, &["PLANE AXIAL B+120"]);
    assert_eq!(p.axes(&m, [0.0; 3]), Err(Error::OutOfTravel));
    let p = read(Dialect::Heidenhain, &["PLANE AXIAL C+370 B+30"]);
    assert_eq!(p.axes(&m, [0.0, 0.0, 0.0]).unwrap().axes, [30.0, 10.0, 0.0]);
    assert_eq!(
        p.axes(&m, [0.0, 700.0, 0.0]).unwrap().axes,
        [30.0, 730.0, 0.0]
    );
    // The same plane: 370° and 10° differ by a whole turn.
    let f = p.frame_on(&m).unwrap();
    assert!(dist(&f.rotation, &want(30.0, 10.0)) < 1e-13);
    // Incremental commands need the rotation: not followed, the state kept. So is a datum
    // shift, along the tilted axes the machine makes; a cancel ends the direct mode.
    let p = read(Dialect::Heidenhain, &["PLANE AXIAL B+30"]);
    for block in [
        "PLANE RELATIV SPA+10",
        "TRANS DATUM AXIS X+5",
        "CYCL DEF 7.1 X+5",
    ] {
        assert_eq!(
            p.line(Dialect::Heidenhain, block.as_bytes()),
            Ok((p, Remark::NotFollowed)),
            "{block}"
        );
    }
    let q = read(
        Dialect::Heidenhain,
        &["PLANE AXIAL B+30", "PLANE RESET STAY"],
    );
    assert!(!q.is_active() && q.direct.is_none());
    let s = read(Dialect::Sinumerik, &[cases[2].1]);
    for additive in [
        "AROT Z10",
        "ATRANS X1",
        "CYCLE800(0,\"TC1\",1,57,0,0,0,0,0,10)",
    ] {
        assert_eq!(
            s.line(Dialect::Sinumerik, additive.as_bytes()),
            Ok((s, Remark::NotFollowed)),
            "{additive}"
        );
    }
    let y = read(Dialect::Syntec, &[cases[1].1]);
    assert_eq!(
        y.line(Dialect::Syntec, b"G68.4 I0 J10 K0"),
        Ok((y, Remark::NotFollowed))
    );
    // A direct-mode CYCLE800 with a third angle (SprutCAM writes one): refused at `_C`, with
    // what may stand there (the data set's two axes), not a missing machine.
    let block = "CYCLE800(0,\"\",100000,249,12.5,0,-20,0,-90,90,0,0,0,-1,0,0)";
    let e = Program::default()
        .line(Dialect::Sinumerik, block.as_bytes())
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::NotAvailable, 43));
    assert_eq!(
        e.expected,
        Some("0: a direct mode turns rotary axes 1 and 2 (_A, _B) only")
    );
    // Without the machine the frame is not known: the C boundary says so (test_program.c).
}

/// A direct mode is translated into the target's direct mode where it names the axes the
/// same way (letters: Heidenhain and Syntec; places: SINUMERIK), and reads back as the same
/// positions; elsewhere it cannot be written without the machine.
#[test]
fn direct_modes_are_translated_where_the_target_has_one() {
    // Source dialect and blocks, target dialect and form, the blocks written.
    type Case<'a> = (Dialect, &'a [&'a str], Dialect, &'a str, &'a [&'a str]);
    let cases: [Case; 5] = [
        // New positions are a new block, in every dialect.
        (
            Dialect::Heidenhain,
            &["PLANE AXIAL B+30 TURN", "PLANE AXIAL B+40 TURN"],
            Dialect::Syntec,
            "G158",
            &[
                "G158 P10200 X0. Y0. Z0. A0. B30. C0. U0. V0. W0.",
                "G158 P10200 X0. Y0. Z0. A0. B40. C0. U0. V0. W0.",
            ],
        ),
        (
            Dialect::Heidenhain,
            &["PLANE AXIAL B+30 C+45 TURN FMAX"],
            Dialect::Syntec,
            "G68.2",
            &["G158 P10200 X0. Y0. Z0. A0. B30. C45. U0. V0. W0."],
        ),
        // Syntec's origin becomes the datum shift of a PLANE, which has no origin words;
        // the positions not given by a PLANE AXIAL are those G158 gave as 0.
        (
            Dialect::Syntec,
            &["G158 P10200 X0 Y0 Z10 A0 B20 C45", "G158"],
            Dialect::Heidenhain,
            "PLANE SPATIAL",
            &[
                "CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\nCYCL DEF 7.2 Y+0\nCYCL DEF 7.3 Z+10\nPLANE AXIAL A+0 B+20 C+45 TURN FMAX",
                "PLANE RESET STAY\nCYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\nCYCL DEF 7.2 Y+0\nCYCL DEF 7.3 Z+0",
            ],
        ),
        (
            Dialect::Sinumerik,
            &["CYCLE800(0,\"TC1\",0,192,5,0,0,30,45,0,0,0,0,-1)", "CYCLE800()"],
            Dialect::Sinumerik,
            "ROT",
            &["CYCLE800(0,\"\",0,192,5,0,0,30,45,0,0,0,0,0,0,0)", "ROT"],
        ),
        (
            Dialect::Heidenhain,
            &["PLANE AXIAL B+30 STAY", "PLANE AXIAL B+30 MOVE"],
            Dialect::Heidenhain,
            "PLANE EULER",
            &["PLANE AXIAL B+30 STAY", "PLANE AXIAL B+30 MOVE FMAX"],
        ),
    ];
    for (from, src, to, form, want) in cases {
        assert_eq!(translate(from, src, to, form), want, "{from:?} -> {form}");
        // Read back in the target: the same positions and origin.
        let (mut p, mut q) = (Program::default(), Program::default());
        for l in src {
            let next = p.line(from, l.as_bytes()).unwrap().0;
            let mut buf = [0u8; MAX_CHANGE];
            let (n, _) = write_change(to, form.as_bytes(), &p, &next, -1, &mut buf).unwrap();
            for block in buf[..n].split(|&b| b == b'\n').filter(|b| !b.is_empty()) {
                q = q.line(to, block).unwrap().0;
            }
            assert_eq!(q.direct.map(|d| d.by), next.direct.map(|d| d.by));
            assert_eq!(q.angles, next.angles, "{l}");
            assert_eq!(q.frame, next.frame, "{l}");
            p = next;
        }
    }
    // Letters cannot become places, nor either a frame, without the machine.
    let p = read(Dialect::Heidenhain, &["PLANE AXIAL B+30"]);
    let mut buf = [0u8; MAX_CHANGE];
    for (to, form) in [
        (Dialect::Sinumerik, "CYCLE800"),
        (Dialect::Fanuc, "G68.2"),
        (Dialect::Haas, "G268"),
        (Dialect::Twincat, "ROT"),
    ] {
        let r = write_change(to, form.as_bytes(), &Program::default(), &p, 4, &mut buf);
        assert_eq!(r, Err(Error::NotAvailable), "{form}");
    }
}

/// A block that adds to the active tilt (`PLANE RELATIV`, `G68.4`, `CYCLE800` with `_ST` 1,
/// `AROT`, `G158 P01…`) is written as the target's incremental form, so that a loop which
/// repeats it adds as often: the source block read three times and the text written for its
/// first reading read three times give the same frames. Texts hand-derived: `SPC+15` is
/// `Rz(15)`, in G68.2's Z, X', Z'' angles `I15 J0 K0`; `Ry(30)` is `I90 J30 K-90` and `SPB+30`.
#[test]
fn incremental_tilts_stay_incremental() {
    let h = [
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
        "PLANE RELATIV SPC+15 TURN MB50 FMAX",
    ];
    let second = |to, form| translate(Dialect::Heidenhain, &h, to, form)[1].clone();
    assert_eq!(
        second(Dialect::Fanuc, "G68.2"),
        "G68.4 X0. Y0. Z0. I15. J0. K0.\nG53.1"
    );
    assert_eq!(
        second(Dialect::Sinumerik, "CYCLE800"),
        "CYCLE800(5,\"\",1,57,0,0,0,0,0,15,0,0,0,-1,50,0)"
    );
    assert_eq!(second(Dialect::Sinumerik, "ROT"), "AROT X=0 Y=0 Z=15");
    assert_eq!(
        second(Dialect::Syntec, "G158"),
        "G158 P01157 X0. Y0. Z0. A0. B0. C15. U0. V0. W0."
    );
    assert_eq!(
        second(Dialect::Syntec, "G68.2"),
        "G68.4 X0. Y0. Z0. I15. J0. K0.\nG53.1"
    );
    // With the block, in the shortest exact numbers: the words' own increment, not
    // `before⁻¹·after` (which reads `I14.999999999999996`).
    let p1 = read(Dialect::Heidenhain, &h[..1]);
    let p2 = p1.line(Dialect::Heidenhain, h[1].as_bytes()).unwrap().0;
    let mut buf = [0u8; MAX_CHANGE];
    let (n, _) = write_block(
        Dialect::Fanuc,
        b"G68.2",
        &p1,
        &p2,
        h[1].as_bytes(),
        -1,
        &mut buf,
    )
    .unwrap();
    assert_eq!(&buf[..n], b"G68.4 X0. Y0. Z0. I15. J0. K0.\nG53.1");
    // Haas has no incremental `G268`: the plane the block reaches.
    assert!(second(Dialect::Haas, "G268").starts_with("G269\nG268 "));
    let f = [
        "G68.2 X0 Y0 Z0 I0 J20 K0",
        "G68.4 X0 Y0 Z0 I90 J30 K-90",
        "G53.1",
        "G68.4 X5 Y0 Z2 I0 J0 K10",
    ];
    let heidenhain = translate(Dialect::Fanuc, &f, Dialect::Heidenhain, "PLANE SPATIAL");
    assert_eq!(heidenhain[1], "PLANE RELATIV SPB+30 STAY");
    // The same plane with another way of moving: a zero increment that turns.
    assert_eq!(heidenhain[2], "PLANE RELATIV SPA+0 TURN FMAX");
    assert_eq!(
        translate(Dialect::Fanuc, &f, Dialect::Fanuc, "G68.2")[2],
        "G53.1"
    );
    // An increment with an origin: `PLANE RELATIV` has no words for it.
    assert!(heidenhain[3].contains("PLANE SPATIAL"), "{}", heidenhain[3]);
    let sinumerik = translate(Dialect::Fanuc, &f, Dialect::Sinumerik, "CYCLE800");
    assert_eq!(
        sinumerik[3],
        "CYCLE800(0,\"\",1,57,5,0,2,0,0,10,0,0,0,0,0,0)"
    );

    // TwinCAT adds angles: one axis' is an increment on the frame, two axes' are not.
    let twincat = read(Dialect::Twincat, &["ROT X20 Y10", "AROT Z1 X90"]);
    assert!(!twincat.relative);
    let sources: [(Dialect, &[&str], &str); 9] = [
        (Dialect::Twincat, &["ROT X20 Y10"], "AROT Z15"),
        (Dialect::Twincat, &["ROT X20 Y10 Z5"], "AROT Y5"),
        (
            Dialect::Heidenhain,
            &[
                "CYCL DEF 7.0 DATUM SHIFT",
                "CYCL DEF 7.1 X+10",
                "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
            ],
            "PLANE RELATIV SPC+15 TURN FMAX",
        ),
        (
            Dialect::Fanuc,
            &["G52 X5 Y-3", "G68.2 X1 Y2 Z3 I10 J20 K30"],
            "G68.4 X2 Y0 Z1 I5 J10 K15",
        ),
        (Dialect::Fanuc, &["G68.2 I0 J20 K0"], "G68.4 I10 J20 K30"),
        (Dialect::Fanuc, &[], "G68.4 I0 J0 K25"),
        (
            Dialect::Sinumerik,
            &["CYCLE800(0,\"T\",0,57,1,2,3,10,20,30,0,0,0,1,0,0)"],
            "CYCLE800(0,\"T\",1,57,0,0,0,0,0,12,0,0,0,1,0,0)",
        ),
        (Dialect::Sinumerik, &["ROT X10 Y20"], "AROT Z12"),
        (
            Dialect::Syntec,
            &["G158 P10157 X1 Y2 Z3 A10 B20 C30"],
            "G158 P01157 A0 B5 C10",
        ),
    ];
    let targets = [
        (Dialect::Heidenhain, "PLANE SPATIAL"),
        (Dialect::Heidenhain, "PLANE VECTOR"),
        (Dialect::Fanuc, "G68.2"),
        (Dialect::Syntec, "G158"),
        (Dialect::Syntec, "G68.2"),
        (Dialect::Sinumerik, "CYCLE800"),
        (Dialect::Sinumerik, "ROT"),
    ];
    let write = |to: Dialect, form: &str, p: &Program, q: &Program| {
        let mut buf = [0u8; MAX_CHANGE];
        write_change(to, form.as_bytes(), p, q, -1, &mut buf)
            .map(|(n, _)| String::from_utf8(buf[..n].to_vec()).unwrap())
    };
    let run = |to: Dialect, q: Program, text: &str| {
        text.lines()
            .fold(q, |q, l| q.line(to, l.as_bytes()).unwrap().0)
    };
    let mut looped = 0;
    for (from, setup, block) in sources {
        for (to, form) in targets {
            let (mut p, mut q) = (Program::default(), Program::default());
            for l in setup {
                let next = p.line(from, l.as_bytes()).unwrap().0;
                let t =
                    write(to, form, &p, &next).unwrap_or_else(|e| panic!("{l} -> {form}: {e:?}"));
                q = run(to, q, &t);
                p = next;
            }
            let next = p.line(from, block.as_bytes()).unwrap().0;
            assert!(next.relative, "{block}");
            let text = write(to, form, &p, &next).unwrap();
            // Only where the form has words for the increment's origin (`ROT`'s whole frame
            // with an origin is `TRANS`, which replaces the frame, and `AROT` about it).
            let incremental = ["PLANE RELATIV", "G68.4", "\",1,", "AROT", "P01"]
                .iter()
                .any(|w| text.contains(w))
                && !text.contains("TRANS");
            let passes = if incremental { 3 } else { 1 };
            looped += usize::from(incremental);
            for pass in 0..passes {
                p = p.line(from, block.as_bytes()).unwrap().0;
                q = run(to, q, &text);
                assert!(
                    frame_dist(&q.frame, &p.frame) < 1e-9,
                    "{block} -> {form} pass {pass}: {text}\n{:?}\n{:?}",
                    q.frame,
                    p.frame
                );
            }
        }
    }
    // 63 pairs: `AROT` and `PLANE RELATIV` (two forms) have no words for an increment with
    // an origin (`G68.4 X2 Y0 Z1`): written whole.
    assert_eq!(looped, 63 - 1 - 2);
}

/// Fanuc's own rule for `G53.1` without `P` (its operator's manual, "output judgement
/// conditions"): the master (first rotation) axis moves the least, then the slave; on a
/// mixed machine the table axis first. Worked by hand (a helper's find: the closest pair by
/// the sum of squares was taken instead).
#[test]
fn fanuc_turns_its_master_axis_the_least() {
    use cncrot::kinematics::{Machine, RotaryAxis, Rule, Side};
    let z = [0.0, 0.0, 1.0];
    // An AC table: A about X carrying C. Tilt 30° about X: (A 30, C 180) or (A -30, C 0).
    let ac = Machine::new(z)
        .unwrap()
        .with_axis(RotaryAxis::new(
            Side::Work,
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 100.0],
        ))
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Work, z, [0.0; 3]))
        .unwrap();
    let p = read(Dialect::Fanuc, &["G68.2 X0. Y0. Z0. I0. J30. K0.", "G53.1"]);
    // From A 5, C 0: A moves 25° to 30 (C half a turn), 35° to -30: Fanuc takes A 30. The
    // sum of squares would take (-30, 0).
    let c = p.axes(&ac, [5.0, 0.0, 0.0]).unwrap();
    assert!(
        (c.axes[0] - 30.0).abs() < 1e-9 && (c.axes[1].abs() - 180.0).abs() < 1e-9,
        "{c:?}"
    );
    assert_eq!(
        c,
        ac.choose(&p.frame.rotation, [5.0, 0.0, 0.0], Rule::MasterFirst(0))
            .unwrap()
    );
    let closest = ac
        .choose(&p.frame.rotation, [5.0, 0.0, 0.0], Rule::Closest)
        .unwrap();
    assert!((closest.axes[0] + 30.0).abs() < 1e-9 && closest.axes[1].abs() < 1e-9);
    // `P0` is the same; `P1` the master's positive turn, as before.
    let p0 = read(
        Dialect::Fanuc,
        &["G68.2 X0. Y0. Z0. I0. J30. K0.", "G53.1 P0"],
    );
    assert_eq!(p0.axes(&ac, [5.0, 0.0, 0.0]).unwrap(), c);
    // A mixed machine (B head about Y, C table): the table moves least first. Tilt 30° about
    // Y: (B 30, C 0) or (B -30, C 180); from B 20, C 95 the table moves 85° to 180.
    let mixed = Machine::new(z)
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Tool, [0.0, 1.0, 0.0], [0.0; 3]))
        .unwrap()
        .with_axis(RotaryAxis::new(Side::Work, z, [0.0; 3]))
        .unwrap();
    let p = read(
        Dialect::Fanuc,
        &["G68.2 X0. Y0. Z0. I90. J30. K-90.", "G53.1"],
    );
    let c = p.axes(&mixed, [20.0, 95.0, 0.0]).unwrap();
    assert!(
        (c.axes[0] + 30.0).abs() < 1e-9 && (c.axes[1] - 180.0).abs() < 1e-9,
        "{c:?}"
    );
    // Other dialects keep the closest: Heidenhain without SEQ.
    let h = read(
        Dialect::Heidenhain,
        &["PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX"],
    );
    let c = h.axes(&ac, [5.0, 0.0, 0.0]).unwrap();
    assert!(
        (c.axes[0] + 30.0).abs() < 1e-9 && c.axes[1].abs() < 1e-9,
        "{c:?}"
    );
}

/// Heidenhain's `SEQ±` as the iTNC 530 manual's table gives it for a machine with a rotary
/// table C and a tilting table A, `PLANE SPATIAL SPA+0 SPB+45 SPC+0`: without limits, from A+0
/// and C−105 or C−135, `SEQ+` is A+45, C+90 (the angles themselves, not C−270 wound toward
/// C); with A limited to −90..+10, `SEQ+` is the control's error, not the other solution
/// (TNC7: "Entered angle not permitted"). Without `SEQ` the shortest way (a helper's finds).
#[test]
fn heidenhain_seq_as_the_manual_gives_it() {
    use cncrot::kinematics::{Machine, RotaryAxis, Side};
    let z = [0.0, 0.0, 1.0];
    let table = |a_limits: Option<[f64; 2]>| {
        Machine::new(z)
            .unwrap()
            .with_axis(RotaryAxis {
                limits: a_limits,
                ..RotaryAxis::new(Side::Work, [1.0, 0.0, 0.0], [0.0, 0.0, 100.0])
            })
            .unwrap()
            .with_axis(RotaryAxis::new(Side::Work, z, [0.0; 3]))
            .unwrap()
    };
    let seq = |w: &str| {
        read(
            Dialect::Heidenhain,
            &[&format!("PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX {w}")],
        )
    };
    let free = table(None);
    for c in [-105.0, -135.0] {
        let got = seq("SEQ+").axes(&free, [0.0, c, 0.0]).unwrap().axes;
        assert!(
            (got[0] - 45.0).abs() < 1e-9 && (got[1] - 90.0).abs() < 1e-9,
            "from C{c}: {got:?}"
        );
    }
    // Without SEQ from C-105: the shortest way, A-45 with C-90.
    let got = seq("").axes(&free, [0.0, -105.0, 0.0]).unwrap().axes;
    assert!(
        (got[0] + 45.0).abs() < 1e-9 && (got[1] + 90.0).abs() < 1e-9,
        "{got:?}"
    );
    let limited = table(Some([-90.0, 10.0]));
    assert_eq!(
        seq("SEQ+").axes(&limited, [0.0; 3]).unwrap_err(),
        Error::OutOfTravel
    );
    let got = seq("SEQ-").axes(&limited, [0.0; 3]).unwrap().axes;
    assert!((got[0] + 45.0).abs() < 1e-9, "{got:?}");
}

/// Blocks a hostile reading of real programs found misread (each a helper's find, with the
/// manual's words where it gives them): what each must do to the frame.
#[test]
fn blocks_real_programs_write() {
    let s = Dialect::Sinumerik;
    let h = Dialect::Heidenhain;
    let after = |d: Dialect, first: &str, block: &str| {
        read(d, &[first])
            .line(d, block.as_bytes())
            .map(|(p, r)| (p.frame, r))
    };
    let tilted = read(s, &["ROT Z30"]);
    assert_ne!(tilted.frame, Frame::IDENTITY);
    // SCALE and MIRROR without values replace the programmable frame with none ("SCALE ;
    // without values: clears the old instructions for offset, rotation, scaling factor,
    // mirroring"); with values they are not followed.
    for block in ["SCALE", "MIRROR", "N20 SCALE ; reset", "/N30 MIRROR"] {
        assert_eq!(
            after(s, "ROT Z30", block),
            Ok((Frame::IDENTITY, Remark::Applied)),
            "{block}"
        );
    }
    assert_eq!(
        after(s, "ROT Z30", "SCALE X2").unwrap().1,
        Remark::NotFollowed
    );
    // TRANS of a special axis: "the programmable offsets for all geometry axes and special
    // axes are specified with TRANS": not followed (it was an unknown word).
    for block in ["TRANS C90", "ATRANS A5", "TRANS X10 C5"] {
        assert_eq!(
            after(s, "ROT Z30", block).unwrap(),
            (tilted.frame, Remark::NotFollowed),
            "{block}"
        );
    }
    // `_TC` "0" deselects, with the parameters after it left out.
    for block in ["CYCLE800(0,\"0\")", "CYCLE800(,\"0\")"] {
        assert_eq!(
            after(
                s,
                "CYCLE800(0,\"TC1\",0,57,0,0,0,0,30,0,0,0,0,-1,0,0)",
                block
            )
            .unwrap()
            .0,
            Frame::IDENTITY,
            "{block}"
        );
    }
    // Heidenhain: the skip mark after the line number, where the TNC shows it.
    let p = read(h, &["12 /PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY"]);
    assert!(dist(&p.frame.rotation, &r(Axis::Y, 30.0)) < 1e-15);
    // PLANE AXIAL incremental: from where the axis stands, which the program does not say.
    assert_eq!(
        after(h, "BEGIN PGM A MM", "PLANE AXIAL IB+15 TURN FMAX")
            .unwrap()
            .1,
        Remark::NotFollowed
    );
    // A datum shift under PLANE AXIAL: along the machine's tilted axes, not known here (it
    // was taken along the untilted ones).
    assert_eq!(
        after(h, "PLANE AXIAL B+30 TURN FMAX", "CYCL DEF 7.1 X+10")
            .unwrap()
            .1,
        Remark::NotFollowed
    );
    // A rotary axis' datum shift, first or not: not followed (the first was an error).
    for block in [
        "TRANS DATUM AXIS A+5",
        "TRANS DATUM AXIS C+90",
        "TRANS DATUM AXIS X+5 C+90",
    ] {
        assert_eq!(
            after(h, "BEGIN PGM A MM", block).unwrap().1,
            Remark::NotFollowed,
            "{block}"
        );
    }
    // An axis twice is the control's error.
    let e = read(h, &["CYCL DEF 7.0 DATUM SHIFT"])
        .line(h, b"CYCL DEF 7.1 IX+10 IX+5")
        .unwrap_err();
    assert_eq!((e.error, e.column), (Error::UnknownWord, 20));
    // The probing cycles that set a datum or a basic rotation by what they measure; a
    // probing of the reference plane sets none.
    for block in [
        "5 TCH PROBE 410 DATUM INSIDE RECTAN",
        "5 TCH PROBE 400 BASIC ROTATION",
        "5 TCH PROBE 1410 PROBING TWO CIRCLES",
    ] {
        assert_eq!(
            after(h, "BEGIN PGM A MM", block).unwrap().1,
            Remark::NotFollowed,
            "{block}"
        );
    }
    assert_eq!(
        after(h, "BEGIN PGM A MM", "5 TCH PROBE 0.0 REF. PLANE Z-")
            .unwrap()
            .1,
        Remark::Passed
    );
}

/// Blanks within an ISO word carry no meaning (Fanuc: spaces are ignored; the library reads
/// `X 10.` already): `G 68.2`, `G 69`, Haas's `G 268`, Syntec's `G 158` are the
/// commands written without them, not blocks passed over (a `G53.1` after a `G 68.2` passed
/// over turned the machine to no tilt).
#[test]
fn iso_words_may_hold_blanks() {
    let read = |d: Dialect, lines: &[&str]| {
        lines.iter().fold(Program::default(), |p, l| {
            let (q, r) = p.line(d, l.as_bytes()).unwrap();
            assert_eq!(r, cncrot::dialects::program::Remark::Applied, "{l}");
            q
        })
    };
    let want = read(Dialect::Fanuc, &["G68.2 X0 Y0 Z0 I0 J30 K0"]);
    for spaced in ["G 68.2 X0 Y0 Z0 I0 J30 K0", "g  68.2 X 0 Y0 Z0 I0 J 30 K0"] {
        assert_eq!(
            read(Dialect::Fanuc, &[spaced]).frame,
            want.frame,
            "{spaced}"
        );
    }
    let cancelled = read(Dialect::Fanuc, &["G68.2 X0 Y0 Z0 I0 J30 K0", "G0 G 69"]);
    assert!(!cancelled.is_active());
    let haas = read(Dialect::Haas, &["G 268 X0 Y0 Z0 I0 J30 K0 Q123"]);
    assert_eq!(
        haas.frame,
        read(Dialect::Haas, &["G268 X0 Y0 Z0 I0 J30 K0 Q123"]).frame
    );
    let syntec = read(Dialect::Syntec, &["G 158 P10157 X0 Y0 Z0 A30 B0 C0"]);
    assert_eq!(
        syntec.frame,
        read(Dialect::Syntec, &["G158 P10157 X0 Y0 Z0 A30 B0 C0"]).frame
    );
}

/// The modal words a post writes before the tilt (`G0 G90 G268 …`, `G90 G158 …`), which
/// Fanuc's reader takes before `G68.2`, are taken before Haas's and Syntec's tilts too (they
/// were refused at the command).
#[test]
fn haas_and_syntec_tilts_after_modal_words() {
    let read = |d: Dialect, l: &str| Program::default().line(d, l.as_bytes()).unwrap();
    let (want, _) = read(Dialect::Haas, "G268 X0 Y0 Z0 I0 J30 K0 Q123");
    for l in [
        "G90 G268 X0 Y0 Z0 I0 J30 K0 Q123",
        "G0 G90 G268 X0 Y0 Z0 I0 J30 K0 Q123",
    ] {
        let (p, r) = read(Dialect::Haas, l);
        assert_eq!(
            (p.frame, r),
            (want.frame, cncrot::dialects::program::Remark::Applied),
            "{l}"
        );
    }
    let (on, _) = read(Dialect::Haas, "G268 X0 Y0 Z0 I0 J30 K0 Q123");
    assert!(!on.line(Dialect::Haas, b"G90 G269").unwrap().0.is_active());
    let (want, _) = read(Dialect::Syntec, "G158 P10157 X0 Y0 Z0 A30 B0 C0");
    let (p, _) = read(Dialect::Syntec, "G90 G158 P10157 X0 Y0 Z0 A30 B0 C0");
    assert_eq!(p.frame, want.frame);
    assert!(want.is_active());
}
