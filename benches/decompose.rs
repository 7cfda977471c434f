//! Composition, decomposition and conversion against nalgebra (`euler_angles_ordered`,
//! `from_euler_angles`) and glam (`to_euler`, `from_euler`), in the same run; prints the
//! ratios at the end. `cargo bench --bench decompose`.
//!
//! Each measurement covers a batch of 256 rotations (intrinsic Z, Y', X'', the convention
//! all three libraries share), so the ratios are per rotation. `cncrot` is the Rust call,
//! `cncrot_c` the exported C function one rotation at a time (checks of pointers,
//! finiteness and, for a matrix, orthonormality included), `cncrot_batch` the batch export
//! over all 256 in one call. Every library's whole result goes through `black_box`, so
//! that none is computed only in part (an inlined composition read for one element was
//! otherwise reduced to that element).

#[path = "../tests/common/mod.rs"]
mod common;

use cncrot::{Convention, Kind, Sequence};
use criterion::{black_box, criterion_group, Criterion, Throughput};
use glam::{DMat3, DQuat, EulerRot};
use nalgebra::{Matrix3, Rotation3, Unit, Vector3};

const BATCH: usize = 256;

fn inputs() -> (Vec<cncrot::Matrix>, Vec<[f64; 3]>) {
    let mut rng = common::Rng::new(99);
    let mats: Vec<_> = (0..BATCH).map(|_| rng.rotation()).collect();
    let conv = Convention::new(Kind::Intrinsic, Sequence::ZYX);
    let angles = mats
        .iter()
        .map(|m| cncrot::decompose(conv, m).angles)
        .collect();
    (mats, angles)
}

fn benches(c: &mut Criterion) {
    let (mats, angles) = inputs();
    let conv = Convention::new(Kind::Intrinsic, Sequence::ZYX);
    let na: Vec<Rotation3<f64>> = mats
        .iter()
        .map(|m| Rotation3::from_matrix_unchecked(Matrix3::from_fn(|i, j| m[i][j])))
        .collect();
    let gl: Vec<DMat3> = mats
        .iter()
        .map(|m| DMat3::from_cols_array_2d(&cncrot::transpose(m)))
        .collect();
    let rad: Vec<[f64; 3]> = angles.iter().map(|a| a.map(f64::to_radians)).collect();
    let axes = [Vector3::z_axis(), Vector3::y_axis(), Vector3::x_axis()];

    let mut g = c.benchmark_group("decompose");
    g.throughput(Throughput::Elements(BATCH as u64));
    g.bench_function("cncrot", |b| {
        b.iter(|| {
            mats.iter()
                .map(|m| black_box(cncrot::decompose(conv, black_box(m))).angles[0])
                .sum::<f64>()
        })
    });
    g.bench_function("cncrot_c", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for m in &mats {
                let mut out = [0.0; 3];
                // SAFETY: 9 readable and 3 writable doubles.
                unsafe {
                    cncrot::ffi::cncrot_angles_from_matrix(
                        1,
                        27,
                        black_box(m).as_ptr().cast(),
                        out.as_mut_ptr(),
                    )
                };
                sum += out[0];
            }
            sum
        })
    });
    g.bench_function("cncrot_batch", |b| {
        let flat: Vec<f64> = mats.iter().flatten().flatten().copied().collect();
        let mut out = vec![0.0; 3 * BATCH];
        b.iter(|| {
            // SAFETY: 9·BATCH readable and 3·BATCH writable doubles.
            unsafe {
                cncrot::ffi::cncrot_angles_from_matrices(
                    1,
                    27,
                    black_box(&flat).as_ptr(),
                    BATCH,
                    out.as_mut_ptr(),
                    core::ptr::null_mut(),
                )
            };
            out[0]
        })
    });
    g.bench_function("nalgebra", |b| {
        b.iter(|| {
            na.iter()
                .map(|r| black_box(black_box(r).euler_angles_ordered(axes, false)).0[0])
                .sum::<f64>()
        })
    });
    g.bench_function("glam", |b| {
        b.iter(|| {
            gl.iter()
                .map(|m| black_box(black_box(m).to_euler(EulerRot::ZYX)).0)
                .sum::<f64>()
        })
    });
    g.finish();

    let mut g = c.benchmark_group("compose");
    g.throughput(Throughput::Elements(BATCH as u64));
    g.bench_function("cncrot", |b| {
        b.iter(|| {
            angles
                .iter()
                .map(|a| {
                    black_box(cncrot::matrix_from_angles(
                        Kind::Intrinsic,
                        Sequence::ZYX.into(),
                        *black_box(a),
                    ))[0][0]
                })
                .sum::<f64>()
        })
    });
    g.bench_function("cncrot_c", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for a in &angles {
                let mut m = [0.0; 9];
                // SAFETY: 3 readable and 9 writable doubles.
                unsafe {
                    cncrot::ffi::cncrot_matrix_from_angles(
                        1,
                        27,
                        black_box(a).as_ptr(),
                        m.as_mut_ptr(),
                    )
                };
                sum += m[0];
            }
            sum
        })
    });
    g.bench_function("cncrot_batch", |b| {
        let flat: Vec<f64> = angles.iter().flatten().copied().collect();
        let mut out = vec![0.0; 9 * BATCH];
        b.iter(|| {
            // SAFETY: 3·BATCH readable and 9·BATCH writable doubles.
            unsafe {
                cncrot::ffi::cncrot_matrices_from_angles(
                    1,
                    27,
                    black_box(&flat).as_ptr(),
                    BATCH,
                    out.as_mut_ptr(),
                    core::ptr::null_mut(),
                )
            };
            out[0]
        })
    });
    g.bench_function("nalgebra", |b| {
        b.iter(|| {
            rad.iter()
                .map(|a| {
                    let a = black_box(a);
                    let r = Rotation3::from_axis_angle(&Unit::new_unchecked(*axes[0]), a[0])
                        * Rotation3::from_axis_angle(&axes[1], a[1])
                        * Rotation3::from_axis_angle(&axes[2], a[2]);
                    black_box(r)[(0, 0)]
                })
                .sum::<f64>()
        })
    });
    g.bench_function("glam", |b| {
        b.iter(|| {
            rad.iter()
                .map(|a| {
                    let a = black_box(a);
                    black_box(DMat3::from_quat(DQuat::from_euler(
                        EulerRot::ZYX,
                        a[0],
                        a[1],
                        a[2],
                    )))
                    .x_axis
                    .x
                })
                .sum::<f64>()
        })
    });
    g.finish();

    // Conversion: extrinsic X, Y, Z angles to intrinsic Z, X', Y'' (the paper's Example 3).
    let to = Convention::new(Kind::Intrinsic, Sequence::ZXY);
    let mut g = c.benchmark_group("convert");
    g.throughput(Throughput::Elements(BATCH as u64));
    g.bench_function("cncrot", |b| {
        b.iter(|| {
            angles
                .iter()
                .map(|a| {
                    black_box(cncrot::convert(
                        Kind::Extrinsic,
                        Sequence::XYZ.into(),
                        *black_box(a),
                        to,
                    ))
                    .angles[0]
                })
                .sum::<f64>()
        })
    });
    g.bench_function("cncrot_c", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for a in &angles {
                let mut out = [0.0; 3];
                // SAFETY: 3 readable and 3 writable doubles.
                unsafe {
                    cncrot::ffi::cncrot_convert(
                        0,
                        57,
                        black_box(a).as_ptr(),
                        1,
                        39,
                        out.as_mut_ptr(),
                    )
                };
                sum += out[0];
            }
            sum
        })
    });
    g.bench_function("cncrot_batch", |b| {
        let flat: Vec<f64> = angles.iter().flatten().copied().collect();
        let mut out = vec![0.0; 3 * BATCH];
        b.iter(|| {
            // SAFETY: 3·BATCH readable and 3·BATCH writable doubles.
            unsafe {
                cncrot::ffi::cncrot_convert_many(
                    0,
                    57,
                    black_box(&flat).as_ptr(),
                    BATCH,
                    1,
                    39,
                    out.as_mut_ptr(),
                    core::ptr::null_mut(),
                )
            };
            out[0]
        })
    });
    g.bench_function("nalgebra", |b| {
        let ext = [Vector3::x_axis(), Vector3::y_axis(), Vector3::z_axis()];
        let zxy = [Vector3::z_axis(), Vector3::x_axis(), Vector3::y_axis()];
        b.iter(|| {
            rad.iter()
                .map(|a| {
                    let a = black_box(a);
                    let r = Rotation3::from_axis_angle(&ext[2], a[2])
                        * Rotation3::from_axis_angle(&ext[1], a[1])
                        * Rotation3::from_axis_angle(&ext[0], a[0]);
                    black_box(r.euler_angles_ordered(zxy, false)).0[0]
                })
                .sum::<f64>()
        })
    });
    g.bench_function("glam", |b| {
        b.iter(|| {
            rad.iter()
                .map(|a| {
                    let a = black_box(a);
                    black_box(
                        DQuat::from_euler(EulerRot::ZYXEx, a[2], a[1], a[0])
                            .to_euler(EulerRot::ZXY),
                    )
                    .0
                })
                .sum::<f64>()
        })
    });
    g.finish();
}

/// The time of one iteration of a benchmark at its fastest tenth of samples (criterion's
/// own sample file): on a shared machine other work only ever adds time, and the mean
/// moved by ±30 % between runs here while this figure stays within a few percent.
fn fast_ns(group: &str, name: &str) -> Option<f64> {
    let dir = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    let path = format!("{dir}/criterion/{group}/{name}/new/sample.json");
    let text = std::fs::read_to_string(path).ok()?;
    let numbers = |key: &str| -> Option<Vec<f64>> {
        let start = text.find(&format!("\"{key}\":["))? + key.len() + 4;
        let end = start + text[start..].find(']')?;
        text[start..end]
            .split(',')
            .map(|v| v.trim().parse().ok())
            .collect()
    };
    let (iters, times) = (numbers("iters")?, numbers("times")?);
    let mut per: Vec<f64> = iters.iter().zip(&times).map(|(i, t)| t / i).collect();
    per.sort_by(f64::total_cmp);
    per.get(per.len() / 10).copied()
}

fn ratios() {
    println!(
        "\nper rotation (fastest tenth of the samples); in brackets the time over glam's \
         (<= 1: as fast or faster):"
    );
    for group in ["decompose", "compose", "convert"] {
        let Some(glam) = fast_ns(group, "glam") else {
            continue;
        };
        let per = |t: f64| t / BATCH as f64;
        let mut line = format!("  {group:<9}");
        for name in ["cncrot", "cncrot_c", "cncrot_batch", "nalgebra", "glam"] {
            if let Some(t) = fast_ns(group, name) {
                line += &format!("  {name} {:5.1} ns ({:.2})", per(t), t / glam);
            }
        }
        println!("{line}");
    }
}

criterion_group!(all, benches);

fn main() {
    all();
    Criterion::default().configure_from_args().final_summary();
    ratios();
}
