//! Every status an export returns is named in its documentation. Each export is called many
//! times with hostile arguments (bad flags and codes, NaN, infinities, huge and tiny
//! numbers, matrices that are not rotations, NULL pointers, random text) and with valid
//! ones; every status seen must appear as `CNCROT_STATUS_…` in the doc comment of that
//! function in `include/cncrot.h` (0 excepted), and `CNCROT_STATUS_INTERNAL` never.

mod common;

use cncrot::ffi::*;
use common::Rng;
use std::collections::{BTreeMap, BTreeSet};
use std::ptr::{null, null_mut};

/// Arguments drawn from the rng: mostly valid, often hostile.
struct Gen(Rng);

impl Gen {
    fn pick<T: Copy>(&mut self, from: &[T]) -> T {
        from[(self.0.next_u64() % from.len() as u64) as usize]
    }
    fn chance(&mut self, p: f64) -> bool {
        self.0.unit() < p
    }
    fn flag(&mut self) -> i32 {
        self.pick(&[0, 1, 0, 1, 0, 1, 2, -1])
    }
    fn code(&mut self) -> i32 {
        if self.chance(0.2) {
            (self.0.next_u64() % 70) as i32 - 2
        } else {
            self.pick(&[57, 39, 27, 30, 9, 21, 54, 7, 0, 64, 5])
        }
    }
    fn number(&mut self) -> f64 {
        if self.chance(0.1) {
            self.pick(&[
                f64::NAN,
                f64::INFINITY,
                -f64::INFINITY,
                1e300,
                -1e300,
                1e17,
                1e-300,
                5e-324,
                90.0,
                0.0,
            ])
        } else {
            self.0.range(-400.0, 400.0)
        }
    }
    fn numbers<const N: usize>(&mut self) -> [f64; N] {
        std::array::from_fn(|_| self.number())
    }
    /// A rotation, most of the time; else a matrix that may be anything.
    fn matrix(&mut self) -> [f64; 9] {
        let m = self.0.rotation();
        let mut v: [f64; 9] = std::array::from_fn(|k| m[k / 3][k % 3]);
        if self.chance(0.3) {
            let k = (self.0.next_u64() % 9) as usize;
            v[k] = self.number();
        }
        if self.chance(0.05) {
            v = self.numbers();
        }
        v
    }
    /// A frame: a rotation and a translation, sometimes broken.
    fn frame(&mut self) -> [f64; 16] {
        let m = self.matrix();
        let mut f = [0.0; 16];
        for i in 0..3 {
            f[4 * i..4 * i + 3].copy_from_slice(&m[3 * i..3 * i + 3]);
            f[4 * i + 3] = if self.chance(0.5) { 0.0 } else { self.number() };
        }
        f[15] = 1.0;
        if self.chance(0.05) {
            f[12] = self.number();
        }
        f
    }
    fn null(&mut self) -> bool {
        self.chance(0.03)
    }
    fn ptr<T>(&mut self, p: *const T) -> *const T {
        if self.null() {
            null()
        } else {
            p
        }
    }
    fn ptr_mut<T>(&mut self, p: *mut T) -> *mut T {
        if self.null() {
            null_mut()
        } else {
            p
        }
    }
}

const LINES: &[(i32, &str)] = &[
    (1, "ROT X10 Y20 Z30"),
    (1, "ROT X=R1"),
    (1, "AROT"),
    (1, "CYCLE800(0,\"TC1\",0,57,0,0,0,30,45,60,0,0,0,-1)"),
    (1, "CYCLE800(0,\"TC1\",0,192,0,0,0,30,45,60,0,0,0,-1)"),
    (1, "CYCLE800(0,\"TC1\",0,58,0,0,0,30,45,60,0,0,0,-1)"),
    (1, "CYCLE800(0,\"TC1\",7,57,0,0,0,30,45,60,0,0,0,-1)"),
    (1, "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39)"),
    (1, "CYCLE600(2,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,39)"),
    (1, "CYCLE600(0,\"UFK600\",1,58,0,0,0,30,45,60,0,0,0,1,39)"),
    (1, "CYCLE600(0,\"UFK600\",1,57,0,0,0,30,45,60,0,0,0,1,7)"),
    (
        1,
        "CYCLE600(0,\"A23456789012345678901234567890123\",1,57,0,0,0,1,2,3,0,0,0,1,39)",
    ),
    (1, "CYCLE600(0,\"U K\",1,57,0,0,0,30,45,60,0,0,0,1,39)"),
    (1, "CYCLE600(0,\"UFK600\",1,57"),
    (1, "ROT X1.5EX200"),
    (1, "ROT X1.5EX-200"),
    (1, "CYCLE800(0,\"TC1"),
    (2, "PLANE SPATIAL SPA+30 SPB+0 SPC+0 STAY"),
    (2, "PLANE VECTOR BX+1 BY+0 BZ+0 NX+1 NY+0 NZ+0"),
    (2, "PLANE VECTOR BX+1 BY+0 BZ+0 NX+0 NY+0 NZ+0"),
    (
        2,
        "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+0 P2Y+0 P2Z+0 P3X+1 P3Y+0 P3Z+0",
    ),
    (
        2,
        "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+1 P2Y+0 P2Z+0 P3X+2 P3Y+0 P3Z+0",
    ),
    (2, "PLANE AXIAL B+30"),
    (2, "PLANE SPATIAL SPA+30 SPB+0"),
    (3, "G68.2 X10 I0 J30 K0"),
    (3, "G68.2 X1 (comment"),
    (3, "G68.3 R0"),
    (3, "G68.2 J#100"),
    (3, "G69"),
    (4, "G158 P10157 X0 A30"),
    (4, "G158 P10122 X0"),
    (4, "G158 P10300 A0 B0 C0"),
    (4, "G158 P157"),
    (4, "G158 P10200 A0"),
    (5, "ROT Z30"),
    (5, "AROT X1e"),
    (6, "G268 Q123 J30"),
    (6, "G268 Q0"),
    (6, "G268 Q123.5"),
    (6, "G268 X0"),
    (7, "G69"),
];

fn census(calls: usize) -> BTreeMap<&'static str, BTreeSet<i32>> {
    let mut g = Gen(Rng::new(0x5EED_0F57_A7E5));
    let mut seen: BTreeMap<&'static str, BTreeSet<i32>> = BTreeMap::new();
    let mut record = |name: &'static str, s: i32| {
        seen.entry(name).or_default().insert(s);
    };
    for _ in 0..calls {
        // SAFETY: every pointer is NULL or points to a buffer of the size the function reads
        // or writes.
        unsafe {
            let (a, m, f, v) = (g.numbers::<3>(), g.matrix(), g.frame(), g.numbers::<3>());
            let (mut o3, mut o9, mut o16) = ([0.0; 3], [0.0; 9], [0.0; 16]);
            let (fl, co, fl2, co2) = (g.flag(), g.code(), g.flag(), g.code());
            let (pa, pm, pf, pv) = (
                g.ptr(a.as_ptr()),
                g.ptr(m.as_ptr()),
                g.ptr(f.as_ptr()),
                g.ptr(v.as_ptr()),
            );
            let (p3, p9, p16) = (
                g.ptr_mut(o3.as_mut_ptr()),
                g.ptr_mut(o9.as_mut_ptr()),
                g.ptr_mut(o16.as_mut_ptr()),
            );
            record(
                "cncrot_matrix_from_angles",
                cncrot_matrix_from_angles(fl, co, pa, p9),
            );
            record(
                "cncrot_angles_from_matrix",
                cncrot_angles_from_matrix(fl, co, pm, p3),
            );
            record("cncrot_convert", cncrot_convert(fl, co, pa, fl2, co2, p3));
            record("cncrot_second_solution", cncrot_second_solution(co, pa, p3));
            record(
                "cncrot_closest_angles",
                cncrot_closest_angles(fl, co, pm, pv, p3),
            );
            record("cncrot_check_rotation", cncrot_check_rotation(pm));
            record("cncrot_nearest_rotation", cncrot_nearest_rotation(pm, p9));
            record(
                "cncrot_add_rotation",
                cncrot_add_rotation(fl, co, pa, pm, p9),
            );
            record("cncrot_rotate_vector", cncrot_rotate_vector(pm, pv, p3));
            record(
                "cncrot_rotate_vector_inverse",
                cncrot_rotate_vector_inverse(pm, pv, p3),
            );
            let (b, c) = (g.numbers::<3>(), g.numbers::<3>());
            let (pb, pc) = (g.ptr(b.as_ptr()), g.ptr(c.as_ptr()));
            record(
                "cncrot_frame_from_angles",
                cncrot_frame_from_angles(fl, co, pa, pb, pc, p16),
            );
            record(
                "cncrot_frame_about_point",
                cncrot_frame_about_point(fl, co, pa, pb, p16),
            );
            let f2 = g.frame();
            let pf2 = g.ptr(f2.as_ptr());
            record("cncrot_frame_compose", cncrot_frame_compose(pf, pf2, p16));
            record("cncrot_frame_inverse", cncrot_frame_inverse(pf, p16));
            record(
                "cncrot_frame_transform_point",
                cncrot_frame_transform_point(pf, pv, p3),
            );
            // Batches of 0 to 3 rows.
            let n = (g.0.next_u64() % 4) as usize;
            let rows: Vec<f64> = (0..9 * n)
                .map(|k| if k % 9 < 3 { g.number() } else { m[k % 9] })
                .collect();
            let mut out = vec![0.0; 9 * n];
            let mut st = vec![0i32; n];
            let (pr, po, ps) = (
                g.ptr(rows.as_ptr()),
                g.ptr_mut(out.as_mut_ptr()),
                g.ptr_mut(st.as_mut_ptr()),
            );
            record(
                "cncrot_matrices_from_angles",
                cncrot_matrices_from_angles(fl, co, pr, n, po, ps),
            );
            record(
                "cncrot_angles_from_matrices",
                cncrot_angles_from_matrices(fl, co, pr, n, po, ps),
            );
            record(
                "cncrot_convert_many",
                cncrot_convert_many(fl, co, pr, n, fl2, co2, po, ps),
            );
            // Probing.
            let pts: Vec<f64> = (0..3 * n + 3)
                .map(|k| {
                    if g.chance(0.05) {
                        g.number()
                    } else {
                        [0.0, 100.0, 37.0, 5.0][k % 4] * ((k / 3) as f64)
                    }
                })
                .collect();
            let mut res = [0.0; 2];
            let (pp, pres) = (g.ptr(pts.as_ptr()), g.ptr_mut(res.as_mut_ptr()));
            record(
                "cncrot_probe_plane",
                cncrot_probe_plane(pp, n + 1, p16, pres),
            );
            let (d1, d2) = (g.numbers::<3>(), g.numbers::<3>());
            let (q1, q2) = (
                if g.chance(0.1) { a } else { d1 },
                if g.chance(0.1) { v } else { d2 },
            );
            record(
                "cncrot_probe_flange",
                cncrot_probe_flange(pa, g.ptr(q1.as_ptr()), pv, g.ptr(q2.as_ptr()), p3, p16),
            );
            let mut angle = 0.0;
            let pang = g.ptr_mut(&mut angle as *mut f64);
            record(
                "cncrot_probe_edge",
                cncrot_probe_edge(pf, pa, g.ptr(q1.as_ptr()), pang, p16),
            );
            // Forms.
            let form = (g.0.next_u64() % 15) as i32;
            let sel = g.pick(&[
                0, 1, 2, 57, 7, 185, 192, 64, 10157, 10122, 10200, 10300, 123, 313, 0, -1,
            ]);
            let words = g.numbers::<9>();
            let count = if g.chance(0.9) {
                let mut c = 0usize;
                cncrot_form_word_count(form, &mut c);
                c
            } else {
                (g.0.next_u64() % 10) as usize
            };
            let mut cnt = 0usize;
            record(
                "cncrot_form_word_count",
                cncrot_form_word_count(form, g.ptr_mut(&mut cnt as *mut usize)),
            );
            let mut w = [0.0; 9];
            record(
                "cncrot_form_frame",
                cncrot_form_frame(form, sel, g.ptr(words.as_ptr()), count, p16),
            );
            record(
                "cncrot_form_values",
                cncrot_form_values(form, sel, pf, g.ptr_mut(w.as_mut_ptr()), count),
            );
            // Program lines.
            let (d, line) = g.pick(LINES);
            let mut p = cncrot_program::default();
            let pp = g.ptr_mut(&mut p as *mut cncrot_program);
            record(
                "cncrot_program_init",
                cncrot_program_init(pp, g.pick(&[0, 1, 2, 3, 4])),
            );
            if g.chance(0.05) {
                p.origin[0] += 1.0;
            }
            let pl = g.ptr(line.as_ptr());
            let mut col = 0usize;
            record(
                "cncrot_program_column",
                cncrot_program_column(
                    pp,
                    d,
                    pl.cast(),
                    line.len(),
                    g.ptr_mut(&mut col as *mut usize),
                ),
            );
            let mut what = [0u8; CNCROT_PROGRAM_EXPECTED_SIZE + 1];
            let room = g.pick(&[0, 1, CNCROT_PROGRAM_EXPECTED_SIZE - 1, what.len()]);
            record(
                "cncrot_program_expected",
                cncrot_program_expected(
                    pp,
                    d,
                    pl.cast(),
                    line.len(),
                    g.ptr_mut(what.as_mut_ptr()).cast(),
                    room,
                ),
            );
            record(
                "cncrot_program_line",
                cncrot_program_line(pp, d, pl.cast(), line.len()),
            );
            record("cncrot_program_frame", cncrot_program_frame(pp, p16));
            let forms: &[&std::ffi::CStr] = &[
                c"CYCLE800",
                c"CYCLE800 7",
                c"CYCLE800 185",
                c"CYCLE800 192",
                c"ROT",
                c"PLANE POINTS",
                c"PLANE PROJECTED",
                c"G68.2",
                c"G158 P10200",
                c"G158 P1157",
                c"G268 Q0",
                c"G268",
                c"NOPE",
            ];
            let fm = g.pick(forms);
            let mut text = [0 as std::ffi::c_char; 600];
            let cap = g.pick(&[600usize, 8, 0]);
            let dec = g.pick(&[-1, 4, 18]);
            record(
                "cncrot_program_write",
                cncrot_program_write(
                    d,
                    g.ptr(fm.as_ptr()),
                    pf,
                    dec,
                    g.ptr_mut(text.as_mut_ptr()),
                    cap,
                ),
            );
            let (d2, line2) = g.pick(LINES);
            let mut after = p;
            cncrot_program_line(&mut after, d2, line2.as_ptr().cast(), line2.len());
            if g.chance(0.05) {
                after.shift[1] += 1.0;
            }
            let mut change = [0 as std::ffi::c_char; CNCROT_PROGRAM_CHANGE_MAX + 1];
            let cap = g.pick(&[change.len(), 16, 0]);
            record(
                "cncrot_program_write_change",
                cncrot_program_write_change(
                    g.ptr(&p as *const cncrot_program),
                    g.ptr(&after as *const cncrot_program),
                    g.pick(&[d, d2, 0, 7]),
                    g.ptr(fm.as_ptr()),
                    dec,
                    g.ptr_mut(change.as_mut_ptr()),
                    cap,
                ),
            );
            // CYCLE600 and its head table.
            let heads = g.pick(&[
                "_HEAD_NAME=\"UFK600\" _DELTA_L1=540 _DELTA_L2=250\n",
                "_HEAD_NAME=\"UFK600\" _DELTA_L1=5x40\n",
                "_HEAD_NAME=\"ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789\"\n",
                "_HEAD_NAME=\"A\"\n_HEAD_NAME=\"B\"\n_HEAD_NAME=\"C\"\n_HEAD_NAME=\"D\"\n_HEAD_NAME=\"E\"\n_HEAD_NAME=\"F\"\n_HEAD_NAME=\"G\"\n_HEAD_NAME=\"H\"\n_HEAD_NAME=\"I\"\n_HEAD_NAME=\"J\"\n_HEAD_NAME=\"K\"\n_HEAD_NAME=\"L\"\n_HEAD_NAME=\"M\"\n_HEAD_NAME=\"N\"\n_HEAD_NAME=\"O\"\n_HEAD_NAME=\"P\"\n_HEAD_NAME=\"Q\"\n",
            ]);
            let mut table: cncrot_head_table = std::mem::zeroed();
            let mut line = 0i32;
            record(
                "cncrot_head_table_parse",
                cncrot_head_table_parse(
                    g.ptr_mut(&mut table as *mut _),
                    g.ptr(heads.as_ptr()).cast(),
                    heads.len(),
                    &mut line,
                ),
            );
            let mut gud: cncrot_cycle600_gud = std::mem::zeroed();
            if g.chance(0.1) {
                gud.cyc600_2 = 1.0;
            }
            let name = g.pick(&[
                c"UFK600",
                c"NOPE",
                c"",
                c"U K",
                c"ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789",
            ]);
            let t = if g.chance(0.5) {
                &table as *const _
            } else {
                null()
            };
            let (x, y) = (g.numbers::<3>(), g.numbers::<3>());
            let (f3, f4, f5, f6) = (g.flag(), g.flag(), g.flag(), g.flag());
            let pg = g.ptr_mut(&mut gud as *mut _);
            let pn = g.ptr(name.as_ptr());
            record(
                "cncrot_cycle600",
                cncrot_cycle600(
                    pg, t, fl, pn, f3, co, x[0], x[1], x[2], a[0], a[1], a[2], y[0], y[1], y[2],
                    fl2, co2, f4, f5, f6,
                ),
            );
        }
    }
    // What random arguments rarely reach (a hostile caller's finds): a vector near the
    // largest double, every CYCLE800 selector, a length beyond the largest object.
    // SAFETY: the buffers are of the sizes the functions read and write; the oversized
    // length is refused before anything is read.
    unsafe {
        let (mut m, mut out) = ([0.0; 9], [0.0; 3]);
        cncrot_matrix_from_angles(1, 3, [45.0, 0.0, 0.0].as_ptr(), m.as_mut_ptr());
        let v = [f64::MAX, f64::MAX, 0.0];
        record(
            "cncrot_rotate_vector",
            cncrot_rotate_vector(m.as_ptr(), v.as_ptr(), out.as_mut_ptr()),
        );
        record(
            "cncrot_rotate_vector_inverse",
            cncrot_rotate_vector_inverse(m.as_ptr(), v.as_ptr(), out.as_mut_ptr()),
        );
        let mut f = [0.0; 16];
        for sel in -2..300 {
            let words = [0.0; 9];
            record(
                "cncrot_form_frame",
                cncrot_form_frame(CNCROT_FORM_CYCLE800, sel, words.as_ptr(), 9, f.as_mut_ptr()),
            );
        }
        let mut table: cncrot_head_table = std::mem::zeroed();
        let mut line = -7;
        record(
            "cncrot_head_table_parse",
            cncrot_head_table_parse(&mut table, c"M17\n".as_ptr(), usize::MAX, &mut line),
        );
        assert_eq!(line, 0, "a refusal before any line names none");
    }
    seen
}

#[test]
fn every_status_returned_is_documented() {
    let seen = census(20_000);
    for (name, statuses) in &seen {
        assert!(!statuses.contains(&-100), "{name} returned INTERNAL");
    }
    let missing = common::undocumented(&seen);
    assert!(
        missing.is_empty(),
        "statuses returned but not documented:\n{}",
        missing.join("\n")
    );
    // The census reaches the statuses it is meant to: a check that cannot fail is none.
    assert!(
        seen["cncrot_program_line"].len() >= 12,
        "{:?}",
        seen["cncrot_program_line"]
    );
    assert!(
        seen["cncrot_form_values"].len() >= 6,
        "{:?}",
        seen["cncrot_form_values"]
    );
    assert!(
        seen["cncrot_convert"].len() >= 5,
        "{:?}",
        seen["cncrot_convert"]
    );
}
