//! The TwinCAT and Syntec manuals' examples and the paper's probing use case, computed by the library:
//! `cargo run --release --example dialects`.

use cncrot::dialects::cycle600::{cycle600, Call, State};
use cncrot::dialects::form::{form_frame, form_values, Form};
use cncrot::dialects::twincat::Rotation;
use cncrot::probe::flange;
use cncrot::{matrix_from_angles, AxisCode, Kind};

fn main() {
    // TwinCAT NC I (its manual): ROT Z30, then AROT Z15, is a turn of 45°; after ROT Z45,
    // CalcInvRot of (40, 10, 0) is (35.36, -21.21, 0).
    let r = Rotation::default()
        .rot([0.0, 0.0, 30.0])
        .arot([0.0, 0.0, 15.0]);
    println!("TwinCAT ROT Z30, AROT Z15: angles {:?}", r.angles);
    let v = Rotation::default()
        .rot([0.0, 0.0, 45.0])
        .calc_inv_rot([40.0, 10.0, 0.0]);
    println!(
        "TwinCAT ROT Z45, CalcInvRot[40;10;0] = ({:.2}, {:.2}, {:.2})",
        v[0], v[1], v[2]
    );

    // Syntec (its manual): G158 L1 P10157 X2. Y0. Z10. A20 B20 C-30 U0 V10 W0.
    let f = form_frame(
        Form::G158,
        10157,
        &[2.0, 0.0, 10.0, 20.0, 20.0, -30.0, 0.0, 10.0, 0.0],
    )
    .expect("a valid G158 block");
    let t = f.translation;
    println!(
        "Syntec G158 P10157 ...: origin ({:.4}, {:.4}, {:.4})",
        t[0], t[1], t[2]
    );
    // The same plane in the other dialects.
    for (name, form, selector) in [
        ("CYCLE800 _MODE=57 (_X0.._C, _X1..)", Form::Cycle800, 57),
        ("G68.2 (X Y Z I J K)", Form::G68_2, 0),
        ("G268 Q123 (X Y Z I J K)", Form::G268, 123),
    ] {
        let mut w = [0.0; 9];
        let n = form.count();
        form_values(form, selector, &f, &mut w[..n]).expect("expressible");
        println!("  as {name}: {}", fmt(&w[..n]));
    }

    // The paper: a flange tilted 30° about the machine's X and 45° about Y, probed with two
    // points along X and two along Y, then CYCLE600 for CYCLE800's intrinsic Z, X', Y''.
    let tilt = matrix_from_angles(
        Kind::Extrinsic,
        AxisCode::new(57).expect("XYZ"),
        [30.0, 45.0, 0.0],
    );
    // The probe, moving along machine X or Y, touches the plane z = −(n_x·x + n_y·y)/n_z.
    let n = [tilt[0][2], tilt[1][2], tilt[2][2]];
    let z = |x: f64, y: f64| -(n[0] * x + n[1] * y) / n[2];
    let (a1, a2, b2) = (
        [0.0, 0.0, z(0.0, 0.0)],
        [100.0, 0.0, z(100.0, 0.0)],
        [0.0, 100.0, z(0.0, 100.0)],
    );
    let m = flange(a1, a2, a1, b2).expect("a flange");
    println!(
        "Paper: probed flange, extrinsic X, Y, Z: {}",
        fmt(&m.angles)
    );
    let call = Call {
        inexin: 0,
        mihead: b"UFK600",
        sw_rec: 1,
        bin_in: 57,
        pos: [0.0; 3],
        ang: m.angles,
        pos_r: [0.0; 3],
        inexout: 1,
        bin_out: 39,
        rot_ad: 0,
        rot_inv: 0,
        retr_z: 0,
    };
    let s = cycle600(&State::default(), None, &call).expect("CYCLE600");
    let r = s.results.expect("results");
    println!(
        "  CYCLE600 _INEXOUT=1 _BIN_OUT=39 (for CYCLE800): {}",
        fmt(&r.angles)
    );
}

fn fmt(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:.4}"))
        .collect::<Vec<_>>()
        .join(" ")
}
