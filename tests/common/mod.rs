//! Helpers shared by the integration tests, the examples and the benchmarks: a seeded
//! PRNG (no dependency, reproducible) and generators of test rotations.
#![allow(dead_code)]

use cncrot::{matrix_from_angles, Convention, Kind, Matrix, Sequence};

/// SplitMix64: small, seedable, good enough to spread test inputs.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Standard normal (Box-Muller).
    pub fn normal(&mut self) -> f64 {
        let u = self.unit().max(1e-300);
        let v = self.unit();
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
    /// A uniformly distributed rotation, from a random quaternion (independent of the
    /// library's own composition). Built in double-double arithmetic and rounded once, so
    /// that each element is within about half an ulp of an exact rotation: a plain f64
    /// `1 - 2(y² + z²)` would leave the input up to 1e-15 from any rotation, and that error
    /// would be charged to the decomposition.
    pub fn rotation(&mut self) -> Matrix {
        let [w, x, y, z] = [self.normal(), self.normal(), self.normal(), self.normal()];
        let n2 = dd_sum(&[(w, w), (x, x), (y, y), (z, z)]);
        let e = |terms: &[(f64, f64)]| dd_div(dd_sum(terms), n2);
        [
            [
                e(&[(w, w), (x, x), (-y, y), (-z, z)]),
                e(&[(2.0 * x, y), (-2.0 * w, z)]),
                e(&[(2.0 * x, z), (2.0 * w, y)]),
            ],
            [
                e(&[(2.0 * x, y), (2.0 * w, z)]),
                e(&[(w, w), (-x, x), (y, y), (-z, z)]),
                e(&[(2.0 * y, z), (-2.0 * w, x)]),
            ],
            [
                e(&[(2.0 * x, z), (-2.0 * w, y)]),
                e(&[(2.0 * y, z), (2.0 * w, x)]),
                e(&[(w, w), (-x, x), (-y, y), (z, z)]),
            ],
        ]
    }
    /// A rotation whose middle angle in `conv` lies `delta_rad` (either sign, either pole)
    /// from its singular value; θ1, θ3 random.
    pub fn near_singular(&mut self, conv: Convention, delta_rad: f64) -> Matrix {
        let delta = delta_rad.to_degrees() * if self.unit() < 0.5 { 1.0 } else { -1.0 };
        let pole = if self.unit() < 0.5 { 0 } else { 1 };
        let mid = if conv.sequence.is_proper_euler() {
            [0.0, 180.0][pole] + delta
        } else {
            [90.0, -90.0][pole] + delta
        };
        let a = [self.range(-180.0, 180.0), mid, self.range(-180.0, 180.0)];
        matrix_from_angles(conv.kind, conv.sequence.into(), a)
    }
}

/// Σ a·b in double-double: (high, low) with the products and sums carried exactly.
fn dd_sum(terms: &[(f64, f64)]) -> (f64, f64) {
    let (mut hi, mut lo) = (0.0f64, 0.0f64);
    for &(a, b) in terms {
        let p = a * b;
        let pe = a.mul_add(b, -p);
        let s = hi + p;
        let bb = s - hi;
        let se = (hi - (s - bb)) + (p - bb);
        hi = s;
        lo += pe + se;
    }
    let s = hi + lo;
    (s, lo - (s - hi))
}

/// A double-double quotient rounded to f64.
fn dd_div(n: (f64, f64), d: (f64, f64)) -> f64 {
    let q = n.0 / d.0;
    let r = (-q).mul_add(d.0, n.0) + n.1 - q * d.1;
    q + r / d.0
}

pub fn max_diff(a: &Matrix, b: &Matrix) -> f64 {
    a.iter()
        .flatten()
        .zip(b.iter().flatten())
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// ‖R(decompose(m)) − m‖_max in convention `conv`.
pub fn reconstruction_error(conv: Convention, m: &Matrix) -> f64 {
    let d = cncrot::decompose(conv, m);
    max_diff(
        &matrix_from_angles(conv.kind, conv.sequence.into(), d.angles),
        m,
    )
}

pub fn all_conventions() -> Vec<Convention> {
    let mut v = Vec::new();
    for kind in [Kind::Intrinsic, Kind::Extrinsic] {
        for s in Sequence::ALL {
            v.push(Convention::new(kind, s));
        }
    }
    v
}

/// Statuses seen per function whose name (`CNCROT_STATUS_…`) the function's doc comment in
/// the committed header does not give, as "function returns NAME" lines (0 needs no name;
/// `cncrot_program_column` and `cncrot_program_expected` say they return what
/// `cncrot_program_line` does: a status is documented in their own doc or in that one).
pub fn undocumented(
    seen: &std::collections::BTreeMap<&'static str, std::collections::BTreeSet<i32>>,
) -> Vec<String> {
    let header = include_str!("../../include/cncrot.h");
    let mut missing = Vec::new();
    for (&function, statuses) in seen {
        let doc_of = |f: &str| {
            let decl = header
                .find(&format!("int32_t {f}("))
                .unwrap_or_else(|| panic!("{f} not in the header"));
            header[header[..decl].rfind("/**").expect("a doc comment")..decl].to_string()
        };
        let mut doc = doc_of(function);
        if matches!(
            function,
            "cncrot_program_column" | "cncrot_program_expected"
        ) {
            doc += &doc_of("cncrot_program_line");
        }
        for &s in statuses {
            // SAFETY: cncrot_status_str returns a static NUL-terminated string.
            let text = unsafe { std::ffi::CStr::from_ptr(cncrot::ffi::cncrot_status_str(s)) };
            let name = text
                .to_str()
                .unwrap()
                .split(':')
                .next()
                .unwrap()
                .to_string();
            if s != 0 && !doc.contains(&format!("`{name}`")) {
                missing.push(format!("{function} returns {name}"));
            }
        }
    }
    missing
}
