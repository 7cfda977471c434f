//! The timing a controller cares about: the distribution, not only the mean, of each hot
//! exported C function, call by call, per input class (random, exact right angles, singular,
//! near-singular, huge angles such as 1e6°). Prints median, p99, p99.99, maximum, max/median
//! and each class's median relative to the function's random class (goal: at most 2×).
//!
//! `cargo bench --bench timing` (10^7 calls per function and class; `-- --calls N` for
//! fewer), `--features pure-rust-math` for the real-time build's arithmetic (libm crate).
//! Each call is timed alone with the time-stamp counter (x86_64; elsewhere the monotonic
//! clock, coarser); the cost of an empty measurement is subtracted. Samples go into a
//! fixed histogram allocated before the loop, so the measurement itself allocates nothing
//! and makes no system call: `benches/syscalls.sh` checks that with strace.

#[path = "../tests/common/mod.rs"]
mod common;

use cncrot::ffi::*;
use cncrot::{matrix_from_angles, AxisCode, Convention, Kind, Sequence};
use common::Rng;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Histogram buckets of one tick; slower calls are counted in `over` with their maximum.
const BUCKETS: usize = 1 << 16;
/// Inputs per class, cycled through (fits in L1/L2 like a controller's working set).
const POOL: usize = 1024;

#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn ticks() -> u64 {
    // lfence on both sides: the counter is read after the previous instructions completed
    // and before the next ones start.
    use core::arch::x86_64::{_mm_lfence, _rdtsc};
    unsafe {
        _mm_lfence();
        let t = _rdtsc();
        _mm_lfence();
        t
    }
}

#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn ticks() -> u64 {
    use std::sync::OnceLock;
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_nanos() as u64
}

/// Nanoseconds per tick, from the tick count over 200 ms of the monotonic clock.
fn ns_per_tick() -> f64 {
    let (t0, i0) = (ticks(), Instant::now());
    while i0.elapsed() < Duration::from_millis(200) {}
    let (t1, dt) = (ticks(), i0.elapsed());
    dt.as_nanos() as f64 / (t1 - t0) as f64
}

struct Histogram {
    counts: Vec<u64>,
    over: u64,
    max: u64,
    n: u64,
}

impl Histogram {
    fn new() -> Histogram {
        Histogram {
            counts: vec![0; BUCKETS],
            over: 0,
            max: 0,
            n: 0,
        }
    }
    fn clear(&mut self) {
        self.counts.iter_mut().for_each(|c| *c = 0);
        (self.over, self.max, self.n) = (0, 0, 0);
    }
    #[inline(always)]
    fn add(&mut self, t: u64) {
        self.n += 1;
        self.max = self.max.max(t);
        match self.counts.get_mut(t as usize) {
            Some(c) => *c += 1,
            None => self.over += 1,
        }
    }
    /// The smallest t with at least fraction `q` of the samples at or below it.
    fn quantile(&self, q: f64) -> u64 {
        let want = (q * self.n as f64).ceil().max(1.0) as u64;
        let mut seen = 0;
        for (t, &c) in self.counts.iter().enumerate() {
            seen += c;
            if seen >= want {
                return t as u64;
            }
        }
        self.max
    }
}

/// Times `calls` calls of `f` on the inputs in turn, each call alone.
fn measure<T>(
    h: &mut Histogram,
    calls: usize,
    overhead: u64,
    inputs: &[T],
    f: &mut impl FnMut(&T) -> i32,
) {
    h.clear();
    for k in 0..calls {
        let x = &inputs[k % inputs.len()];
        let t0 = ticks();
        let s = one_call(f, x);
        let t1 = ticks();
        black_box(s);
        h.add((t1 - t0).saturating_sub(overhead));
    }
}

/// One call, never inlined: benches/instructions.sh counts the instructions inside it.
#[inline(never)]
fn one_call<T>(f: &mut impl FnMut(&T) -> i32, x: &T) -> i32 {
    f(x)
}

struct Row {
    function: &'static str,
    class: &'static str,
    median: f64,
    p99: f64,
    p9999: f64,
    max: f64,
    base: f64,
}

/// What every group of rows shares: the harness, its calibration and the rows so far.
struct Bench {
    h: Histogram,
    calls: usize,
    only: Option<String>,
    overhead: u64,
    ns: f64,
    rows: Vec<Row>,
}

impl Bench {
    /// The calls for a row: all of them, or none when `--only` names other rows.
    fn n(&self, function: &str, class: &str) -> usize {
        let row = format!("{function}/{class}");
        match &self.only {
            Some(rows) if !rows.split(',').any(|r| r == row) => 0,
            _ => self.calls,
        }
    }

    /// Times `f` over `inputs` for the row `function`/`class` and prints it.
    fn time<T>(
        &mut self,
        function: &'static str,
        class: &'static str,
        inputs: &[T],
        f: &mut impl FnMut(&T) -> i32,
    ) {
        let calls = self.n(function, class);
        measure(&mut self.h, calls, self.overhead, inputs, f);
        self.report(function, class);
    }

    /// Prints the row just measured, with its class's median relative to the function's
    /// first (random) class.
    fn report(&mut self, function: &'static str, class: &'static str) {
        let (h, ns) = (&self.h, self.ns);
        if h.n == 0 {
            return;
        }
        let t = |q: f64| h.quantile(q) as f64 * ns;
        let base = self
            .rows
            .iter()
            .find(|r| r.function == function)
            .map_or(t(0.5), |r| r.median);
        self.rows.push(Row {
            function,
            class,
            median: t(0.5),
            p99: t(0.99),
            p9999: t(0.9999),
            max: h.max as f64 * ns,
            base,
        });
        let r = self.rows.last().unwrap();
        println!(
            "{:<30} {:<20} {:>8.1} {:>8.1} {:>9.1} {:>10.1} {:>8.1} {:>7.2}{}",
            r.function,
            r.class,
            r.median,
            r.p99,
            r.p9999,
            r.max,
            r.max / r.median.max(ns),
            r.median / r.base.max(ns),
            if r.median > 2.0 * r.base {
                "  > 2x: GOAL MISSED"
            } else {
                ""
            }
        );
    }
}

/// The input pools the groups draw from (POOL inputs each), made once from one seed.
struct Inputs {
    /// Angle triples per class: random, right angles, huge, extreme.
    angle_classes: Vec<(&'static str, Vec<[f64; 3]>)>,
    /// Row-major rotations per class: random, singular, near-singular, from huge angles.
    matrix_classes: Vec<(&'static str, Vec<[f64; 9]>)>,
    /// Matrices for the nearest rotation: exact, noisy, ill-conditioned.
    nearest_classes: Vec<(&'static str, Vec<[f64; 9]>)>,
    /// Random frames with origins, row-major 4x4.
    frames: Vec<[f64; 16]>,
    /// Pairs of them.
    frame_pairs: Vec<([f64; 16], [f64; 16])>,
    /// CYCLE800's sequence code (intrinsic Z, X', Y'').
    code: i32,
}

/// Rotations: matrices from angles and back, conversions, the closest and the nearest
/// rotation, the check, a vector rotated, additive rotations.
fn rotations(b: &mut Bench, i: &Inputs) {
    let mut out9 = [0.0; 9];
    let mut out3 = [0.0; 3];
    for (class, inputs) in &i.angle_classes {
        b.time(
            "cncrot_matrix_from_angles",
            class,
            inputs,
            &mut |a| unsafe { cncrot_matrix_from_angles(1, i.code, a.as_ptr(), out9.as_mut_ptr()) },
        );
    }
    for (class, inputs) in &i.matrix_classes {
        b.time(
            "cncrot_angles_from_matrix",
            class,
            inputs,
            &mut |m| unsafe { cncrot_angles_from_matrix(1, i.code, m.as_ptr(), out3.as_mut_ptr()) },
        );
    }
    for (class, inputs) in &i.angle_classes {
        b.time("cncrot_convert", class, inputs, &mut |a| unsafe {
            cncrot_convert(0, 57, a.as_ptr(), 1, i.code, out3.as_mut_ptr())
        });
    }
    let reference = [10.0, 20.0, 30.0];
    for (class, inputs) in &i.matrix_classes {
        b.time("cncrot_closest_angles", class, inputs, &mut |m| unsafe {
            cncrot_closest_angles(1, i.code, m.as_ptr(), reference.as_ptr(), out3.as_mut_ptr())
        });
    }
    for (class, inputs) in &i.nearest_classes {
        b.time("cncrot_nearest_rotation", class, inputs, &mut |m| unsafe {
            cncrot_nearest_rotation(m.as_ptr(), out9.as_mut_ptr())
        });
    }
    b.time(
        "cncrot_check_rotation",
        "random",
        &i.matrix_classes[0].1,
        &mut |m| unsafe { cncrot_check_rotation(m.as_ptr()) },
    );
    b.time(
        "cncrot_rotate_vector",
        "random",
        &i.matrix_classes[0].1,
        &mut |m| unsafe { cncrot_rotate_vector(m.as_ptr(), reference.as_ptr(), out3.as_mut_ptr()) },
    );
    for (class, inputs) in &i.angle_classes {
        b.time("cncrot_add_rotation", class, inputs, &mut |a| unsafe {
            cncrot_add_rotation(
                1,
                i.code,
                a.as_ptr(),
                i.matrix_classes[0].1[0].as_ptr(),
                out9.as_mut_ptr(),
            )
        });
    }
    black_box((out3, out9));
}

/// Frames: composition, inverse, a point transformed.
fn transforms(b: &mut Bench, i: &Inputs) {
    let (mut out3, mut out16) = ([0.0; 3], [0.0; 16]);
    let reference = [10.0, 20.0, 30.0];
    b.time(
        "cncrot_frame_compose",
        "random",
        &i.frame_pairs,
        &mut |(a, b)| unsafe { cncrot_frame_compose(a.as_ptr(), b.as_ptr(), out16.as_mut_ptr()) },
    );
    b.time(
        "cncrot_frame_inverse",
        "random",
        &i.frames,
        &mut |f| unsafe { cncrot_frame_inverse(f.as_ptr(), out16.as_mut_ptr()) },
    );
    b.time(
        "cncrot_frame_transform_point",
        "random",
        &i.frames,
        &mut |f| unsafe {
            cncrot_frame_transform_point(f.as_ptr(), reference.as_ptr(), out3.as_mut_ptr())
        },
    );
    black_box((out3, out16));
}

/// The dialects' forms: words to a frame and a frame to words.
fn forms(b: &mut Bench, i: &Inputs) {
    // The dialects' forms: words to a frame and a frame to words, for the random angles
    // (G68.2, the projection of CYCLE800, and PLANE POINTS, the form with the most work).
    {
        let random = &i.angle_classes[0].1;
        let g68: Vec<[f64; 9]> = random
            .iter()
            .map(|a| [1.0, 2.0, 3.0, a[0], a[1], a[2], 0.0, 0.0, 0.0])
            .collect();
        let mut f = [0.0; 16];
        let mut w = [0.0; 9];
        for (class, form, selector, count) in [
            ("G68.2", CNCROT_FORM_G68_2, 0, 6),
            ("CYCLE800 projection", CNCROT_FORM_CYCLE800, 128 + 57, 9),
            ("PLANE POINTS", CNCROT_FORM_PLANE_POINTS, 0, 9),
        ] {
            b.time("cncrot_form_frame", class, &g68, &mut |x| unsafe {
                cncrot_form_frame(form, selector, x.as_ptr(), count, f.as_mut_ptr())
            });
        }
        for (class, form, selector, count) in [
            ("G68.2", CNCROT_FORM_G68_2, 0, 6),
            ("CYCLE800 projection", CNCROT_FORM_CYCLE800, 128 + 57, 9),
            ("G268 Q321", CNCROT_FORM_G268, 321, 6),
        ] {
            b.time("cncrot_form_values", class, &i.frames, &mut |x| unsafe {
                cncrot_form_values(form, selector, x.as_ptr(), w.as_mut_ptr(), count)
            });
        }
    }
}

/// Probing: a flange, a least-squares plane, an edge in a tilted plane.
fn probing(b: &mut Bench, i: &Inputs) {
    // Probing: a flange from four points, a least-squares plane of four points (the time is
    // linear in the number of points), an edge in a tilted plane.
    {
        let random = &i.angle_classes[0].1;
        let flanges: Vec<[[f64; 3]; 4]> = random
            .iter()
            .map(|a| {
                let (sx, sy) = (a[0] / 400.0, a[1] / 400.0);
                [
                    [0.0, 0.0, 0.0],
                    [100.0, 0.0, 100.0 * sx],
                    [0.0, 0.0, 0.0],
                    [0.0, 100.0, 100.0 * sy],
                ]
            })
            .collect();
        let (mut ang, mut f) = ([0.0; 3], [0.0; 16]);
        b.time("cncrot_probe_flange", "random", &flanges, &mut |p| unsafe {
            cncrot_probe_flange(
                p[0].as_ptr(),
                p[1].as_ptr(),
                p[2].as_ptr(),
                p[3].as_ptr(),
                ang.as_mut_ptr(),
                f.as_mut_ptr(),
            )
        });
        // Four probed points on a tilted plane, exactly planar or with one 0.02 mm off.
        let cloud = |a: &[f64; 3], off: f64| -> Vec<f64> {
            (0..4)
                .flat_map(|k| {
                    let (x, y) = ((k % 2) as f64 * 100.0, (k / 2) as f64 * 80.0);
                    let bump = if k == 3 { off } else { 0.0 };
                    [x, y, 5.0 + a[0] / 1000.0 * x + a[1] / 1000.0 * y + bump]
                })
                .collect()
        };
        let mut res = [0.0; 2];
        for (class, off) in [("4 points", 0.0), ("4 points, one off", 0.02)] {
            let clouds: Vec<Vec<f64>> = random.iter().map(|a| cloud(a, off)).collect();
            b.time("cncrot_probe_plane", class, &clouds, &mut |p| unsafe {
                cncrot_probe_plane(p.as_ptr(), 4, f.as_mut_ptr(), res.as_mut_ptr())
            });
        }
        let clouds: Vec<Vec<f64>> = random.iter().map(|a| cloud(a, 0.0)).collect();
        let order = [0.0; 3];
        b.time(
            "cncrot_probe_plane_toward",
            "4 points, order",
            &clouds,
            &mut |p| unsafe {
                cncrot_probe_plane_toward(
                    p.as_ptr(),
                    4,
                    order.as_ptr(),
                    f.as_mut_ptr(),
                    res.as_mut_ptr(),
                )
            },
        );
        let edges: Vec<[f64; 16]> = i.frames.clone();
        let mut angle = 0.0;
        let (e1, e2) = ([0.0; 3], [100.0, 30.0, 7.0]);
        b.time("cncrot_probe_edge", "random", &edges, &mut |fr| unsafe {
            cncrot_probe_edge(
                fr.as_ptr(),
                e1.as_ptr(),
                e2.as_ptr(),
                &mut angle,
                f.as_mut_ptr(),
            )
        });
    }
}

/// Program lines (setup time, but bounded): read, column, frame, init, write.
fn programs(b: &mut Bench, i: &Inputs) {
    {
        let random = &i.angle_classes[0].1;
        let mut f = [0.0; 16];
        let edges: Vec<[f64; 16]> = i.frames.clone();
        // Program lines (setup time, but bounded): a CYCLE800 call and a PLANE line read on
        // the random angles, the active frame read, the lines written back.
        let c800: Vec<Vec<u8>> = random
            .iter()
            .map(|a| {
                let l = format!(
                    "N10 CYCLE800(1,\"TC1\",0,57,10,0,0,{},{},{},0,0,0,-1,100,1)",
                    a[0], a[1], a[2]
                );
                l.into_bytes()
            })
            .collect();
        let plane: Vec<Vec<u8>> = random
            .iter()
            .map(|a| {
                format!(
                    "5 PLANE SPATIAL SPA{:+} SPB{:+} SPC{:+} TURN MB MAX FMAX",
                    a[0], a[1], a[2]
                )
                .into_bytes()
            })
            .collect();
        let mut p = cncrot_program::default();
        for (class, dialect, lines) in [
            ("CYCLE800 line", CNCROT_DIALECT_SINUMERIK, &c800),
            ("PLANE SPATIAL line", CNCROT_DIALECT_HEIDENHAIN, &plane),
        ] {
            b.time("cncrot_program_line", class, lines, &mut |l| unsafe {
                p = cncrot_program::default();
                cncrot_program_line(&mut p, dialect, l.as_ptr().cast(), l.len())
            });
        }
        let mut col = 0usize;
        let bad = b"5 PLANE SPATIAL SPA+30 SPB+Q12 SPC+0".to_vec();
        b.time(
            "cncrot_program_column",
            "variable",
            &[bad],
            &mut |l| unsafe {
                cncrot_program_column(
                    &p,
                    CNCROT_DIALECT_HEIDENHAIN,
                    l.as_ptr().cast(),
                    l.len(),
                    &mut col,
                )
            },
        );
        let mut what = [0u8; CNCROT_PROGRAM_EXPECTED_SIZE];
        let missing = b"PLANE SPATIAL SPA+30 SPB+0".to_vec();
        b.time(
            "cncrot_program_expected",
            "missing word",
            &[missing],
            &mut |l| unsafe {
                cncrot_program_expected(
                    &p,
                    CNCROT_DIALECT_HEIDENHAIN,
                    l.as_ptr().cast(),
                    l.len(),
                    what.as_mut_ptr().cast(),
                    what.len(),
                )
            },
        );
        b.time("cncrot_program_frame", "active", &[p], &mut |q| unsafe {
            cncrot_program_frame(q, f.as_mut_ptr())
        });
        let mut q = cncrot_program::default();
        b.time(
            "cncrot_program_init",
            "Euler",
            &[CNCROT_PROGRAM_SINUMERIK_EULER],
            &mut |&o| unsafe { cncrot_program_init(&mut q, o) },
        );
        let mut out = [0u8; CNCROT_PROGRAM_LINE_MAX + 1];
        for (class, dialect, form, decimals) in [
            ("G68.2 shortest", CNCROT_DIALECT_FANUC, c"G68.2", -1),
            (
                "PLANE 4 decimals",
                CNCROT_DIALECT_HEIDENHAIN,
                c"PLANE SPATIAL",
                4,
            ),
        ] {
            b.time("cncrot_program_write", class, &edges, &mut |fr| unsafe {
                let mut g = *fr;
                if dialect == CNCROT_DIALECT_HEIDENHAIN {
                    g[3] = 0.0;
                    g[7] = 0.0;
                    g[11] = 0.0;
                }
                cncrot_program_write(
                    dialect,
                    form.as_ptr(),
                    g.as_ptr(),
                    decimals,
                    out.as_mut_ptr().cast(),
                    out.len(),
                )
            });
        }
        // A translated block: a tilt with an origin after a datum shift, into PLANE (the
        // origin as cycle 7, then the plane) and into CYCLE800.
        let mut shifted = cncrot_program::default();
        let (g52, g682) = (&b"G52 X10 Y20 Z-5"[..], &b"G68.2 X1 Y2 Z3 I30 J40 K50"[..]);
        // SAFETY: valid pointers and lengths.
        unsafe {
            cncrot_program_line(
                &mut shifted,
                CNCROT_DIALECT_FANUC,
                g52.as_ptr().cast(),
                g52.len(),
            )
        };
        let mut tilted = shifted;
        // SAFETY: as above.
        unsafe {
            cncrot_program_line(
                &mut tilted,
                CNCROT_DIALECT_FANUC,
                g682.as_ptr().cast(),
                g682.len(),
            )
        };
        // A safety cancel read with nothing active: the state names its dialect.
        let (zero, mut cancelled) = (cncrot_program::default(), cncrot_program::default());
        // SAFETY: valid pointers and lengths.
        unsafe { cncrot_program_line(&mut cancelled, CNCROT_DIALECT_FANUC, c"G69".as_ptr(), 3) };
        // Whether two blocks join: a shift and a tilt (no), a tilt and its turn (yes).
        let mut turned = tilted;
        // SAFETY: valid pointers and lengths.
        unsafe { cncrot_program_line(&mut turned, CNCROT_DIALECT_FANUC, c"G53.1".as_ptr(), 5) };
        let mut join = 0i32;
        b.time(
            "cncrot_program_joins",
            "random",
            &[(zero, shifted, tilted), (shifted, tilted, turned)],
            &mut |(a, z, n)| unsafe { cncrot_program_joins(a, z, n, &mut join) },
        );
        // What a translator keeps of a block: a cancel among a retract's words, a tilt with
        // its motion mode and feed.
        let mut kept = [0u8; CNCROT_PROGRAM_LINE_MAX + 3];
        b.time(
            "cncrot_program_rest",
            "random",
            &[
                &b"G91 G28 Z0. G69"[..],
                b"N40 G1 G68.2 X0. Y0. Z0. I90. J30. K-90. F300.",
            ],
            &mut |l| unsafe {
                cncrot_program_rest(
                    CNCROT_DIALECT_FANUC,
                    l.as_ptr().cast(),
                    l.len(),
                    kept.as_mut_ptr().cast(),
                    kept.len(),
                )
            },
        );
        let mut change = [0u8; CNCROT_PROGRAM_CHANGE_MAX + 1];
        for (class, dialect, form) in [
            (
                "into PLANE SPATIAL",
                CNCROT_DIALECT_HEIDENHAIN,
                c"PLANE SPATIAL",
            ),
            ("into CYCLE800", CNCROT_DIALECT_SINUMERIK, c"CYCLE800"),
        ] {
            b.time(
                "cncrot_program_write_change",
                class,
                &[(shifted, tilted)],
                &mut |(a, z)| unsafe {
                    cncrot_program_write_change(
                        a,
                        z,
                        dialect,
                        form.as_ptr(),
                        4,
                        change.as_mut_ptr().cast(),
                        change.len(),
                    )
                },
            );
            // The same block through `cncrot_program_write_block` (read twice more on its
            // probes), and a safety cancel with nothing active (written again).
            b.time(
                "cncrot_program_write_block",
                class,
                &[(shifted, tilted, g682), (zero, cancelled, &b"G69"[..])],
                &mut |(a, z, text)| unsafe {
                    cncrot_program_write_block(
                        a,
                        z,
                        text.as_ptr().cast(),
                        text.len(),
                        dialect,
                        form.as_ptr(),
                        4,
                        change.as_mut_ptr().cast(),
                        change.len(),
                    )
                },
            );
        }
    }
}

/// Kinematics: forward, inverse, choice, follow-up, swivel data, CYCLE600 positions.
fn machines(b: &mut Bench, _: &Inputs) {
    {
        // Kinematics: a fork head from swivel data (two axes) and the paper's three-axis
        // machine (table C, head about Y then X), at random positions.
        const CARR: &[u8] =
            b"$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1 $TC_CARR10[1]=0 $TC_CARR11[1]=1
$TC_CARR12[1]=0 $TC_CARR6[1]=-150 $TC_CARR23[1]=\"T\" $TC_CARR31[1]=-100 $TC_CARR33[1]=100
$TC_CARR34[1]=\"HEAD_CB\"
";
        let mut head: cncrot_machine = unsafe { std::mem::zeroed() };
        let mut three: cncrot_machine = unsafe { std::mem::zeroed() };
        unsafe {
            cncrot_machine_from_carr(&mut head, CARR.as_ptr().cast(), CARR.len(), 1);
            let (z, y, x) = ([0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]);
            cncrot_machine_add_axis(
                &mut three,
                1,
                z.as_ptr(),
                [500.0, 300.0, 0.0].as_ptr(),
                0.0,
                0.0,
            );
            cncrot_machine_add_axis(
                &mut three,
                0,
                y.as_ptr(),
                [0.0, 0.0, 540.0].as_ptr(),
                -120.0,
                120.0,
            );
            cncrot_machine_add_axis(
                &mut three,
                0,
                x.as_ptr(),
                [0.0, 0.0, 250.0].as_ptr(),
                0.0,
                0.0,
            );
        }
        let mut seed = 0x1234_5678_9abc_def0u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let positions: Vec<[f64; 3]> = (0..1024)
            .map(|_| {
                [
                    360.0 * next() - 180.0,
                    200.0 * next() - 100.0,
                    360.0 * next() - 180.0,
                ]
            })
            .collect();
        let mut f = [0.0; 16];
        for (class, m) in [("fork head", &head), ("three axes", &three)] {
            let pos: Vec<[f64; 3]> = positions
                .iter()
                .map(|p| {
                    if class == "fork head" {
                        [p[0], p[1], 0.0]
                    } else {
                        *p
                    }
                })
                .collect();
            let targets: Vec<[f64; 16]> = pos
                .iter()
                .map(|p| {
                    let mut g = [0.0; 16];
                    unsafe { cncrot_machine_forward(m, p.as_ptr(), g.as_mut_ptr()) };
                    g
                })
                .collect();
            b.time("cncrot_machine_forward", class, &pos, &mut |p| unsafe {
                cncrot_machine_forward(m, p.as_ptr(), f.as_mut_ptr())
            });
            let (mut sol, mut cnt) = ([0.0; 6], 0usize);
            b.time("cncrot_machine_inverse", class, &targets, &mut |t| unsafe {
                cncrot_machine_inverse(m, t.as_ptr(), sol.as_mut_ptr(), 2, &mut cnt)
            });
            let (mut ax, mut res, mut rem) = ([0.0; 3], [0.0; 3], [0.0; 16]);
            let cur = [750.0, 0.0, 0.0];
            b.time("cncrot_machine_choose", class, &targets, &mut |t| unsafe {
                cncrot_machine_choose(
                    m,
                    t.as_ptr(),
                    cur.as_ptr(),
                    0,
                    0,
                    ax.as_mut_ptr(),
                    res.as_mut_ptr(),
                    rem.as_mut_ptr(),
                )
            });
            // The same orientations as program states (a G68.2 line each): the positions a
            // program's tilt moves the machine to.
            let states: Vec<cncrot_program> = targets
                .iter()
                .map(|t| unsafe {
                    let mut line = [0u8; CNCROT_PROGRAM_LINE_MAX + 1];
                    cncrot_program_write(
                        CNCROT_DIALECT_FANUC,
                        c"G68.2".as_ptr(),
                        t.as_ptr(),
                        -1,
                        line.as_mut_ptr().cast(),
                        line.len(),
                    );
                    let n = line.iter().position(|&c| c == 0).unwrap_or(0);
                    let mut p = cncrot_program::default();
                    cncrot_program_line(&mut p, CNCROT_DIALECT_FANUC, line.as_ptr().cast(), n);
                    p
                })
                .collect();
            b.time("cncrot_program_axes", class, &states, &mut |p| unsafe {
                cncrot_program_axes(p, m, cur.as_ptr(), ax.as_mut_ptr())
            });
            // Direct modes (a CYCLE800 with _MODE 192 at the same positions of axes 1 and 2):
            // the frame the machine gives there.
            let direct: Vec<cncrot_program> = pos
                .iter()
                .map(|a| unsafe {
                    let line = format!(
                        "CYCLE800(0,\"TC1\",0,192,0,0,0,{},{},0,0,0,0,-1)",
                        a[0], a[1]
                    );
                    let mut p = cncrot_program::default();
                    let s = cncrot_program_line(
                        &mut p,
                        CNCROT_DIALECT_SINUMERIK,
                        line.as_ptr().cast(),
                        line.len(),
                    );
                    assert_eq!(s, 0, "{line}");
                    p
                })
                .collect();
            b.time("cncrot_program_frame_on", class, &direct, &mut |p| unsafe {
                cncrot_program_frame_on(p, m, f.as_mut_ptr())
            });
            // The five-axis transformation: poses (tip and direction) at random axes, and back
            // from previous positions a cycle away (0.1° off on every rotary axis).
            let six: Vec<[f64; 6]> = pos
                .iter()
                .map(|p| [10.0 * p[0], 5.0 * p[1], 2.0 * p[2], p[0], p[1], p[2]])
                .collect();
            let tcp: Vec<([f64; 16], [f64; 6])> = six
                .iter()
                .map(|a| {
                    let mut pose = [0.0; 16];
                    unsafe { cncrot_machine_tcp_forward(m, a.as_ptr(), 120.0, pose.as_mut_ptr()) };
                    let mut prev = *a;
                    for (k, x) in prev.iter_mut().enumerate().skip(3) {
                        if *x != 0.0 || k == 3 {
                            *x += 0.1;
                        }
                    }
                    (pose, prev)
                })
                .collect();
            let mut out6 = [0.0; 6];
            b.time("cncrot_machine_tcp_forward", class, &six, &mut |a| unsafe {
                cncrot_machine_tcp_forward(m, a.as_ptr(), 120.0, f.as_mut_ptr())
            });
            b.time(
                "cncrot_machine_tcp_inverse",
                class,
                &tcp,
                &mut |(pose, prev)| unsafe {
                    cncrot_machine_tcp_inverse(
                        m,
                        pose.as_ptr(),
                        120.0,
                        prev.as_ptr(),
                        out6.as_mut_ptr(),
                    )
                },
            );
            b.time(
                "cncrot_machine_tcp_inverse_rule",
                class,
                &tcp,
                &mut |(pose, prev)| unsafe {
                    cncrot_machine_tcp_inverse_rule(
                        m,
                        pose.as_ptr(),
                        120.0,
                        prev.as_ptr(),
                        CNCROT_CHOOSE_MINUS,
                        2,
                        out6.as_mut_ptr(),
                    )
                },
            );
            // The same description edited by hand (its seal no longer matches): checked whole
            // on every call, as every description was before seals.
            let mut edited = *m;
            edited.reserved ^= 1;
            let unsealed = if class == "fork head" {
                "fork head, unsealed"
            } else {
                "three axes, unsealed"
            };
            b.time(
                "cncrot_machine_tcp_inverse",
                unsealed,
                &tcp,
                &mut |(pose, prev)| unsafe {
                    cncrot_machine_tcp_inverse(
                        &edited,
                        pose.as_ptr(),
                        120.0,
                        prev.as_ptr(),
                        out6.as_mut_ptr(),
                    )
                },
            );
            // A five-axis program's block read, and its CL point's axes on the machine.
            let mut tp: cncrot_tool_path = unsafe { std::mem::zeroed() };
            let on = b"G43.5 H1";
            unsafe {
                cncrot_tool_path_line(&mut tp, CNCROT_DIALECT_FANUC, on.as_ptr().cast(), on.len())
            };
            let block: &[u8] = b"G1 X12.5 Y-3.25 Z40. I0.3 J-0.2 K0.9";
            b.time("cncrot_tool_path_line", class, &[block], &mut |l| unsafe {
                let mut t = tp;
                cncrot_tool_path_line(&mut t, CNCROT_DIALECT_FANUC, l.as_ptr().cast(), l.len())
            });
            let mut point = tp;
            unsafe {
                cncrot_tool_path_line(
                    &mut point,
                    CNCROT_DIALECT_FANUC,
                    block.as_ptr().cast(),
                    block.len(),
                )
            };
            let prev6 = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
            b.time("cncrot_tool_path_axes", class, &[()], &mut |_| unsafe {
                cncrot_tool_path_axes(&point, m, 120.0, prev6.as_ptr(), 0, 0, out6.as_mut_ptr())
            });
            let mut pose16 = [0.0; 16];
            b.time("cncrot_cl_pose", class, &pos, &mut |p| unsafe {
                cncrot_cl_pose([1.0, 2.0, 3.0].as_ptr(), p.as_ptr(), pose16.as_mut_ptr())
            });
            // Carried from the pose of the tool along (0.3, 0.1, 0.9) to each direction.
            let mut from = [0.0; 16];
            unsafe {
                cncrot_cl_pose(
                    [0.0; 3].as_ptr(),
                    [0.3, 0.1, 0.9].as_ptr(),
                    from.as_mut_ptr(),
                )
            };
            b.time("cncrot_cl_pose_toward", class, &pos, &mut |p| unsafe {
                cncrot_cl_pose_toward(
                    [1.0, 2.0, 3.0].as_ptr(),
                    p.as_ptr(),
                    from.as_ptr(),
                    pose16.as_mut_ptr(),
                )
            });
            let mut copy = edited;
            b.time("cncrot_machine_seal", class, &[()], &mut |_| unsafe {
                copy.reserved ^= 1;
                cncrot_machine_seal(&mut copy)
            });
            let mut lin = [0.0; 3];
            b.time("cncrot_machine_follow", class, &pos, &mut |p| unsafe {
                cncrot_machine_follow(
                    m,
                    [0.0; 3].as_ptr(),
                    p.as_ptr(),
                    [1.0, 2.0, 3.0].as_ptr(),
                    100.0,
                    lin.as_mut_ptr(),
                )
            });
        }
        let mut m: cncrot_machine = unsafe { std::mem::zeroed() };
        b.time(
            "cncrot_machine_from_carr",
            "4 lines",
            &[CARR],
            &mut |t| unsafe { cncrot_machine_from_carr(&mut m, t.as_ptr().cast(), t.len(), 1) },
        );
        let mut gud: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
        unsafe {
            cncrot_cycle600(
                &mut gud,
                std::ptr::null(),
                1,
                c"H".as_ptr(),
                0,
                7,
                0.0,
                0.0,
                0.0,
                30.0,
                40.0,
                0.0,
                0.0,
                0.0,
                0.0,
                1,
                39,
                0,
                0,
                0,
            );
        }
        let (mut ax, mut res, mut rem) = ([0.0; 3], [0.0; 3], [0.0; 16]);
        b.time(
            "cncrot_cycle600_position",
            "fork head",
            &positions,
            &mut |p| unsafe {
                cncrot_cycle600_position(
                    &gud,
                    &head,
                    [p[0], 0.0, 0.0].as_ptr(),
                    ax.as_mut_ptr(),
                    res.as_mut_ptr(),
                    rem.as_mut_ptr(),
                )
            },
        );
    }
}

/// CYCLE600: the recalculation, the additive call, a full head table.
fn cycle600(b: &mut Bench, i: &Inputs) {
    for (class, inputs) in &i.angle_classes {
        // CYCLE600 recalculation (paper, Example 3 with these angles), then the additive call.
        let mut gud: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
        let name = c"UFK600";
        b.time("cncrot_cycle600", class, inputs, &mut |a| unsafe {
            cncrot_cycle600(
                &mut gud,
                std::ptr::null(),
                0,
                name.as_ptr(),
                1,
                57,
                1.0,
                2.0,
                3.0,
                a[0],
                a[1],
                a[2],
                4.0,
                5.0,
                6.0,
                1,
                39,
                0,
                0,
                0,
            )
        });
    }
    {
        let mut gud: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
        let name = c"UFK600";
        b.time(
            "cncrot_cycle600",
            "additive (_ROT_AD=1)",
            &i.angle_classes[0].1,
            &mut |a| unsafe {
                cncrot_cycle600(
                    &mut gud,
                    std::ptr::null(),
                    1,
                    name.as_ptr(),
                    1,
                    57,
                    0.0,
                    0.0,
                    0.0,
                    a[0],
                    a[1],
                    a[2],
                    0.0,
                    0.0,
                    0.0,
                    1,
                    39,
                    1,
                    0,
                    0,
                )
            },
        );
    }
    {
        // With a full head table whose last entry is the one named: the lookup reads the
        // table in place, so this costs about what a call without a table costs.
        let mut text = String::new();
        for k in 0..15 {
            text.push_str(&format!("_HEAD_NAME=\"HEAD{k}\" _DELTA_L1={k}\n"));
        }
        text.push_str("_HEAD_NAME=\"UFK600\" _DELTA_L1=540.735\n");
        let mut table: cncrot_head_table = unsafe { std::mem::zeroed() };
        let parsed = unsafe {
            cncrot_head_table_parse(
                &mut table,
                text.as_ptr().cast(),
                text.len(),
                std::ptr::null_mut(),
            )
        };
        assert_eq!((parsed, table.count), (0, 16));
        let mut gud: cncrot_cycle600_gud = unsafe { std::mem::zeroed() };
        let name = c"UFK600";
        b.time(
            "cncrot_cycle600",
            "16 heads, last named",
            &i.angle_classes[0].1,
            &mut |a| unsafe {
                cncrot_cycle600(
                    &mut gud,
                    &table,
                    0,
                    name.as_ptr(),
                    1,
                    57,
                    1.0,
                    2.0,
                    3.0,
                    a[0],
                    a[1],
                    a[2],
                    4.0,
                    5.0,
                    6.0,
                    1,
                    39,
                    0,
                    0,
                    0,
                )
            },
        );
    }
}

/// Batches of 64 rows per call.
fn batches(b: &mut Bench, i: &Inputs) {
    // Batches of 64 rows per call (the per-row cost is the median / 64): random rows, and
    // every row singular.
    const BATCH: usize = 64;
    let batch_of =
        |v: &[[f64; 3]]| -> Vec<f64> { v.iter().cycle().take(BATCH).flatten().copied().collect() };
    let batch_m =
        |v: &[[f64; 9]]| -> Vec<f64> { v.iter().cycle().take(BATCH).flatten().copied().collect() };
    let angle_batch = [batch_of(&i.angle_classes[0].1)];
    let matrix_batches = [
        ("64 random rows", batch_m(&i.matrix_classes[0].1)),
        ("64 singular rows", batch_m(&i.matrix_classes[1].1)),
    ];
    let mut many9 = vec![0.0; 9 * BATCH];
    let mut many3 = vec![0.0; 3 * BATCH];
    b.time(
        "cncrot_matrices_from_angles",
        "64 random rows",
        &angle_batch,
        &mut |a| unsafe {
            cncrot_matrices_from_angles(
                1,
                i.code,
                a.as_ptr(),
                BATCH,
                many9.as_mut_ptr(),
                std::ptr::null_mut(),
            )
        },
    );
    for (class, m) in &matrix_batches {
        b.time(
            "cncrot_angles_from_matrices",
            class,
            std::slice::from_ref(m),
            &mut |m| unsafe {
                cncrot_angles_from_matrices(
                    1,
                    i.code,
                    m.as_ptr(),
                    BATCH,
                    many3.as_mut_ptr(),
                    std::ptr::null_mut(),
                )
            },
        );
    }
    b.time(
        "cncrot_convert_many",
        "64 random rows",
        &angle_batch,
        &mut |a| unsafe {
            cncrot_convert_many(
                0,
                57,
                a.as_ptr(),
                BATCH,
                1,
                i.code,
                many3.as_mut_ptr(),
                std::ptr::null_mut(),
            )
        },
    );
    for r in b.rows.iter().filter(|r| r.class.starts_with("64 ")) {
        println!(
            "per row: {} {}: {:.1} ns",
            r.function,
            r.class,
            r.median / BATCH as f64
        );
    }
}

fn main() {
    let calls: usize = std::env::args()
        .skip_while(|a| a != "--calls")
        .nth(1)
        .map(|n| n.parse().expect("--calls N"))
        .unwrap_or(10_000_000);
    // `--only "FUNCTION/CLASS[,FUNCTION/CLASS…]"` runs those rows alone (benches/instructions.sh counts a row's
    // instructions under callgrind); the other rows get no calls and are not printed.
    let only: Option<String> = std::env::args().skip_while(|a| a != "--only").nth(1);
    let ns = ns_per_tick();
    let mut h = Histogram::new();
    // The cost of the measurement alone: the median of empty measurements.
    let calibration = if only.is_some() { 1000 } else { 1_000_000 };
    measure(&mut h, calibration, 0, &[0u8], &mut |_| 0);
    let overhead = h.quantile(0.5);
    // The clock's resolution: the smallest step between two different readings (a virtual
    // machine may advance the time-stamp counter in steps).
    let resolution = (0..10_000)
        .map(|_| {
            let t0 = ticks();
            let mut t1 = ticks();
            while t1 == t0 {
                t1 = ticks();
            }
            t1 - t0
        })
        .min()
        .unwrap_or(1);

    let mut rng = Rng::new(2026);
    let conv = Convention::new(Kind::Intrinsic, Sequence::ZXY); // CYCLE800's Z, X', Y''
    let code = i32::from(conv.sequence.code());
    let flat = |m: cncrot::Matrix| -> [f64; 9] { core::array::from_fn(|i| m[i / 3][i % 3]) };
    let pool =
        |f: &mut dyn FnMut() -> [f64; 3]| -> Vec<[f64; 3]> { (0..POOL).map(|_| f()).collect() };
    let angle_classes: Vec<(&str, Vec<[f64; 3]>)> = vec![
        (
            "random",
            pool(&mut || [0; 3].map(|_| rng.range(-180.0, 180.0))),
        ),
        (
            "right angles",
            pool(&mut || [0; 3].map(|_| 90.0 * (rng.next_u64() % 8) as f64 - 360.0)),
        ),
        (
            "huge (1e6 deg)",
            pool(&mut || [0; 3].map(|_| rng.range(-1e6, 1e6))),
        ),
        (
            "extreme (to 1e308)",
            pool(&mut || [0; 3].map(|_| rng.range(-1.0, 1.0) * 10f64.powf(rng.range(0.0, 308.0)))),
        ),
    ];
    let mat = |a: &[f64; 3]| {
        flat(matrix_from_angles(
            Kind::Intrinsic,
            AxisCode::from(conv.sequence),
            *a,
        ))
    };
    let matrix_classes: Vec<(&str, Vec<[f64; 9]>)> = vec![
        ("random", (0..POOL).map(|_| flat(rng.rotation())).collect()),
        (
            "singular",
            (0..POOL)
                .map(|_| flat(rng.near_singular(conv, 0.0)))
                .collect(),
        ),
        (
            "near-singular 1e-9",
            (0..POOL)
                .map(|_| flat(rng.near_singular(conv, 1e-9)))
                .collect(),
        ),
        (
            "near-singular 1e-15",
            (0..POOL)
                .map(|_| flat(rng.near_singular(conv, 1e-15)))
                .collect(),
        ),
        (
            "from huge angles",
            angle_classes[2].1.iter().map(mat).collect(),
        ),
    ];
    let noisy = |rng: &mut Rng, scale: f64| -> Vec<[f64; 9]> {
        (0..POOL)
            .map(|_| flat(rng.rotation()).map(|x| x + scale * rng.range(-1.0, 1.0)))
            .collect()
    };
    let nearest_classes: Vec<(&str, Vec<[f64; 9]>)> = vec![
        ("exact rotation", matrix_classes[0].1.clone()),
        ("noise 1e-6", noisy(&mut rng, 1e-6)),
        ("noise 1e-3", noisy(&mut rng, 1e-3)),
        ("noise 1e-1", noisy(&mut rng, 1e-1)),
        // A rotation with one axis squashed to 1e-6 of its length: the slowest convergence
        // of the polar iteration that is still not refused as degenerate.
        (
            "ill-conditioned 1e-6",
            (0..POOL)
                .map(|_| {
                    let mut m = flat(rng.rotation());
                    // The third column: elements 2, 5 and 8 of the row-major matrix.
                    for k in [2, 5, 8] {
                        m[k] *= 1e-6;
                    }
                    m
                })
                .collect(),
        ),
    ];
    let frames: Vec<[f64; 16]> = (0..POOL)
        .map(|_| {
            let m = rng.rotation();
            let t = [0; 3].map(|_| rng.range(-500.0, 500.0));
            core::array::from_fn(|k| match (k / 4, k % 4) {
                (3, 3) => 1.0,
                (3, _) => 0.0,
                (i, 3) => t[i],
                (i, j) => m[i][j],
            })
        })
        .collect();
    let frame_pairs: Vec<([f64; 16], [f64; 16])> = (0..POOL)
        .map(|k| (frames[k], frames[(k * 7 + 3) % POOL]))
        .collect();

    println!("cncrot timing distribution: {calls} calls per row, ns per call (measurement overhead of {:.1} ns subtracted)", overhead as f64 * ns);
    println!(
        "math: {}",
        if cfg!(feature = "pure-rust-math") {
            "pure-Rust libm (the real-time build's arithmetic)"
        } else {
            "platform libm (std build)"
        }
    );
    println!(
        "machine: {}; clock resolution {:.1} ns",
        cpu_name(),
        resolution as f64 * ns
    );
    println!(
        "{:<30} {:<20} {:>8} {:>8} {:>9} {:>10} {:>8} {:>7}",
        "function", "input class", "median", "p99", "p99.99", "max", "max/med", "class"
    );
    let mut b = Bench {
        h,
        calls,
        only,
        overhead,
        ns,
        rows: Vec::new(),
    };
    // The environment's own outliers: the same measurement around no call at all. Its
    // p99.99 and maximum are what interrupts and the hypervisor add to any row.
    b.time("(no call: the measurement)", "-", &[0u8], &mut |_| 0);
    let i = Inputs {
        angle_classes,
        matrix_classes,
        nearest_classes,
        frames,
        frame_pairs,
        code,
    };
    rotations(&mut b, &i);
    transforms(&mut b, &i);
    forms(&mut b, &i);
    probing(&mut b, &i);
    programs(&mut b, &i);
    machines(&mut b, &i);
    cycle600(&mut b, &i);
    batches(&mut b, &i);
    if std::env::args().any(|a| a == "--syscall-canary") {
        // For benches/syscalls.sh: a row that does make a system call per call, to show
        // that the check sees one.
        b.time("sched_yield (canary)", "-", &[0u8], &mut |_| {
            std::thread::yield_now();
            0
        });
    }
    let worst = b
        .rows
        .iter()
        .filter(|r| r.function.starts_with("cncrot_"))
        .map(|r| r.median / r.base)
        .fold(0.0, f64::max);
    println!("worst class median / random median: {worst:.2} (goal: at most 2)");
    // The five-axis transformation runs every interpolation cycle: its cost against a
    // conversion measured in the same run (goal: at most 3).
    let median = |f: &str, c: &str| {
        b.rows
            .iter()
            .find(|r| r.function == f && r.class == c)
            .map(|r| r.median)
    };
    if let Some(convert) = median("cncrot_convert", "random") {
        for f in ["cncrot_machine_tcp_forward", "cncrot_machine_tcp_inverse"] {
            for c in ["fork head", "three axes"] {
                if let Some(t) = median(f, c) {
                    let ratio = t / convert.max(ns);
                    println!(
                        "{f} {c} / cncrot_convert random: {ratio:.2} (goal: at most 3){}",
                        if ratio > 3.0 { "  GOAL MISSED" } else { "" }
                    );
                }
            }
        }
    }
}

fn cpu_name() -> String {
    let cpus = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let model = cpus
        .lines()
        .find(|l| l.starts_with("model name"))
        .and_then(|l| l.split(':').nth(1))
        .unwrap_or("unknown")
        .trim()
        .to_string();
    let n = cpus.lines().filter(|l| l.starts_with("processor")).count();
    format!("{model}, {n} logical CPUs")
}
