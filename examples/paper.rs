//! The paper's Examples 2 and 3, computed by the library: `cargo run --release --example paper`.

use cncrot::dialects::cycle600::{cycle600, Call, State};
use cncrot::{angles_from_matrix, matrix_from_angles, AxisCode, Convention, Kind, Sequence};

fn main() {
    let probe = [30.0, 45.0, 60.0];
    let xyz = AxisCode::from(Sequence::XYZ);
    println!("Example 2: extrinsic rotations X-Y-Z = (30, 45, 60) deg");
    let m = matrix_from_angles(Kind::Extrinsic, xyz, probe);
    for row in m {
        println!("  [{:8.4} {:8.4} {:8.4}]", row[0], row[1], row[2]);
    }
    let i57 = Convention::new(Kind::Intrinsic, Sequence::XYZ);
    let exact = angles_from_matrix(i57, &m).expect("a rotation");
    println!(
        "  as intrinsic X',Y',Z'' (exact matrix):      {}",
        fmt(exact.angles)
    );
    // The paper's printed matrix, digits as printed (-0.7071 is not meant as 1/sqrt(2)).
    #[allow(clippy::approx_constant)]
    let printed = [
        [0.3536, -0.5732, 0.7392],
        [0.6124, 0.7392, 0.2803],
        [-0.7071, 0.3536, 0.6124],
    ];
    let from_printed = angles_from_matrix(i57, &printed).expect("within tolerance");
    println!(
        "  as intrinsic X',Y',Z'' (4-decimal matrix):  {}",
        fmt(from_printed.angles)
    );
    println!("    (the paper prints -24.5939, 47.6633, 58.3301: its asin/atan formulas on the");
    println!("     rounded, slightly non-orthonormal matrix; the inputs carry +-5e-5)");

    println!("Example 3: N120 CYCLE600(0, \"UFK600\", 1, 57, 0,0,0, 30,45,60, 0,0,0, _INEXOUT, 39, 0,0,0)");
    for inexout in [1, 0] {
        let call = Call {
            inexin: 0,
            mihead: b"UFK600",
            sw_rec: 1,
            bin_in: 57,
            pos: [0.0; 3],
            ang: probe,
            pos_r: [0.0; 3],
            inexout,
            bin_out: 39,
            rot_ad: 0,
            rot_inv: 0,
            retr_z: 0,
        };
        let gud = cycle600(&State::default(), None, &call).expect("valid call");
        let r = gud.results.expect("stored");
        println!(
            "  _INEXOUT = {inexout}: _CYC600_1 = \"{}\", _CYC600_2.._4 = {}, _CYC600_5 = {}, _CYC600_6 = {}",
            String::from_utf8_lossy(gud.name()),
            fmt(r.angles),
            r.convention.kind.flag(),
            r.convention.sequence.code()
        );
    }
}

fn fmt(a: [f64; 3]) -> String {
    format!("({:.4}, {:.4}, {:.4})", a[0], a[1], a[2])
}
