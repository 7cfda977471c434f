//! The one module through which all floating-point functions are called.
//!
//! The trigonometry in degrees (`sin_cos_deg`, `atan2_deg`) is the crate's own: exact
//! reductions in degrees and polynomials with proved error bounds, the same code and the
//! same bits in every build. For the rest (`sqrt`, `fmod`, `round`, `ceil`, all exact) the
//! `std` feature uses the platform's libm; without it the pure-Rust `libm` crate, so the
//! crate needs nothing from a C library. Since those four are exact, every build computes
//! the same bits. Everything else in the crate calls these functions, never `f64` methods
//! that need `std`. The feature `pure-rust-math` selects the `libm` crate with `std` too:
//! the no-panic proof, which needs unwinding and hence `std`, uses it to cover the
//! real-time build's code.

mod lanes;
mod tables;

pub(crate) use lanes::{Lanes, F4};

#[cfg(all(feature = "std", not(feature = "pure-rust-math")))]
mod imp {
    #[inline]
    pub fn sqrt(x: f64) -> f64 {
        x.sqrt()
    }
    #[inline]
    pub fn fmod(x: f64, y: f64) -> f64 {
        x % y
    }
    #[inline]
    pub fn round(x: f64) -> f64 {
        x.round()
    }
    #[inline]
    pub fn ceil(x: f64) -> f64 {
        x.ceil()
    }
}

#[cfg(any(not(feature = "std"), feature = "pure-rust-math"))]
mod imp {
    #[inline]
    pub fn sqrt(x: f64) -> f64 {
        libm::sqrt(x)
    }
    #[inline]
    pub fn fmod(x: f64, y: f64) -> f64 {
        libm::fmod(x, y)
    }
    #[inline]
    pub fn round(x: f64) -> f64 {
        libm::round(x)
    }
    #[inline]
    pub fn ceil(x: f64) -> f64 {
        libm::ceil(x)
    }
}

use imp::fmod;
pub use imp::{ceil, sqrt};

/// `x` rounded to the nearest integer, halves away from zero (C's `round`), exactly as the
/// library's: below 2⁵² in magnitude by truncation through an integer and the exact
/// remainder (no call: the five-axis transformation rounds on every axis of every
/// solution), the rest (already integers, infinities, NaN) by the library's.
#[inline]
pub fn round(x: f64) -> f64 {
    if abs(x) < 4_503_599_627_370_496.0 {
        // Exact: |x| < 2⁵² fits the integer, and x − t is then exact too.
        let t = x as i64 as f64;
        let f = x - t;
        let r = if f >= 0.5 {
            t + 1.0
        } else if f <= -0.5 {
            t - 1.0
        } else {
            t
        };
        // x's sign on a zero result (round(-0.3) is -0, as in C); a nonzero r has it.
        f64::from_bits(r.to_bits() | (x.to_bits() & (1 << 63)))
    } else {
        imp::round(x)
    }
}

/// `|x|` without `std` (clears the sign bit).
#[inline]
pub fn abs(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & !(1u64 << 63))
}

/// Degrees per radian as a double-double: `DEG_HI` is the correctly rounded 180/π (the
/// constant `f64::to_degrees` uses), `DEG_LO` the rest (180/π − DEG_HI, rounded).
const DEG_HI: f64 = 57.295_779_513_082_32;
const DEG_LO: f64 = -1.987_849_567_057_628_3e-15;
const RAD_PER_DEG: f64 = core::f64::consts::PI / 180.0;

/// Sine and cosine of an angle in degrees, exact where the answer is exact.
///
/// The argument is reduced in degrees, where the reduction is exact: whole turns for angles
/// beyond ±180° (`turn_reduced`), then the nearest whole degree j, whose sine and cosine
/// come from a table of double-doubles, and the rest `d = r − j` (|d| ≤ ½°, exact). Then
/// `sin(j + d) = sin j + (sin j·(cos d − 1) + cos j·sin d)` and likewise for the cosine,
/// with `sin d` and `cos d − 1` from their Taylor series (to d⁵ and d⁶; the remainders of
/// these alternating series are below d⁷/5040 ≤ 7.6e-19 and d⁸/40320 ≤ 8.4e-22). So
/// every whole degree whose sine or cosine is a double (0, ±1/2, ±1) gives it exactly, and
/// every other angle is within ½ ulp + 6e-18 of the true value (at most 6.2e-17): nearly
/// correctly rounded. The table index and the quadrant come from integer arithmetic, with
/// no branches (random angles would mispredict them).
#[inline(always)]
pub fn sin_cos_deg(deg: f64) -> (f64, f64) {
    sin_cos_deg_lanes(turn_reduced(deg))
}

/// [`sin_cos_deg`] of four angles at once, in vector registers: lane by lane the same
/// operations, hence the same bits.
#[inline(always)]
pub fn sin_cos_deg4(deg: [f64; 4]) -> ([f64; 4], [f64; 4]) {
    // Written out: `array::map` here was compiled as a call, its result read back through
    // memory with a store-forwarding stall.
    let [a, b, c, d] = deg;
    let reduced = [
        turn_reduced(a),
        turn_reduced(b),
        turn_reduced(c),
        turn_reduced(d),
    ];
    let (s, c) = sin_cos_deg_lanes(F4::new(reduced));
    (s.to_array(), c.to_array())
}

/// An angle within (-360°, 360°) that differs from `deg` by whole turns, exactly.
///
/// Within ±180° `deg` itself. Below 2^53, `deg − 360·q` with q the nearest whole number to
/// `deg/360`: `360·q` is exact (45·q < 2^53) and so is the difference (the two lie within a
/// factor 2 of each other, Sterbenz), five operations where `fmod` loops over the bits
/// between 360 and `deg` (a 1e6° angle cost 2.8 times a composition's instructions).
/// Above, [`rem360`]'s exact integer arithmetic. The kernels below depend only on the
/// angle modulo 360, so every representative gives the same bits.
#[inline(always)]
fn turn_reduced(deg: f64) -> f64 {
    const ROUNDER: f64 = 6_755_399_441_055_744.0;
    const TWO_53: f64 = 9_007_199_254_740_992.0;
    let size = abs(deg);
    if size <= 180.0 {
        deg
    } else if size < TWO_53 {
        // q may be one off where deg/360 is near a half; |deg − 360q| < 181 either way.
        let q = (deg * (1.0 / 360.0) + ROUNDER) - ROUNDER;
        deg - 360.0 * q
    } else {
        rem360_cold(deg)
    }
}

/// sin(q·90 + x), cos(q·90 + x) for q mod 4 = 0, 1, 2, 3 are (s, c), (c, −s), (−s, −c),
/// (−c, s): per quadrant `[a, b, c, d]` with sin = s·a + c·b, cos = s·c + c·d, exact
/// (products with 0 and ±1, sums with a zero).
const QUADRANT: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 1.0],
    [0.0, 1.0, -1.0, 0.0],
    [-1.0, 0.0, 0.0, -1.0],
    [0.0, -1.0, 1.0, 0.0],
];

/// [`sin_cos_deg`] of angles within (-360°, 360°).
#[inline(always)]
fn sin_cos_deg_lanes<V: Lanes>(r: V) -> (V, V) {
    // j, the whole degree nearest to r (ties to even), by the 1.5·2^52 trick: |r| < 360,
    // so the sum's mantissa holds j exactly, as a two's complement integer offset by 2^51.
    const ROUNDER: f64 = 6_755_399_441_055_744.0;
    let sum = r.add(V::splat(ROUNDER));
    let j = sum.sub(V::splat(ROUNDER));
    // Exact: |r − j| ≤ ½ and both have the same sign (or j = 0).
    let d = r.sub(j).mul(V::splat(RAD_PER_DEG));
    // j + 360, in 0..=720 (a NaN gives arbitrary bits here, and NaN results below):
    // 90·quadrant + within, within in 0..90, the quadrant taken modulo 4 (360° is four of
    // them). Unsigned, so that the division by 90 is a multiplication and a shift.
    let turned = |bits: u64| (bits.wrapping_sub(ROUNDER.to_bits()) as u32).wrapping_add(360);
    let [sin_hi, sin_lo, cos_hi, cos_lo] =
        sum.gather(&tables::SIN_COS, |bits| (turned(bits) % 90) as usize);
    let [ss, sc, cs, cc] = sum.gather(&QUADRANT, |bits| (turned(bits) / 90 % 4) as usize);
    let z = d.mul(d);
    let sin_d = d.add(
        d.mul(z)
            .mul(V::splat(-1.0 / 6.0).add(z.mul(V::splat(1.0 / 120.0)))),
    );
    let cos_d_minus_1 =
        z.mul(V::splat(-0.5).add(z.mul(V::splat(1.0 / 24.0).add(z.mul(V::splat(-1.0 / 720.0))))));
    let s = sin_hi.add(sin_lo.add(sin_hi.mul(cos_d_minus_1).add(cos_hi.mul(sin_d))));
    let c = cos_hi.add(cos_lo.add(cos_hi.mul(cos_d_minus_1).sub(sin_hi.mul(sin_d))));
    // `+ 0.0` turns -0 into +0 so that no caller ever sees a signed zero.
    let zero = V::splat(0.0);
    (
        s.mul(ss).add(c.mul(sc)).add(zero),
        s.mul(cs).add(c.mul(cc)).add(zero),
    )
}

/// `atan(num/den)` in degrees for `0 ≤ num ≤ den` (the first octant; `0/0` gives 0, as
/// `atan2(0, 0)`), without a radian `atan` and without rounding twice.
///
/// `t = num/den` (one rounding), `c = k/32` the nearest table point (|t − c| ≤ 1/64), and
/// `atan t = atan c + atan u` with `u = (t − c)/(1 + t·c)`, |u| ≤ 1/64. `t − c` is exact
/// (Sterbenz: c/2 ≤ t ≤ 2c for k ≥ 1). `atan u` is its alternating Taylor series to `u⁹/9`,
/// whose remainder is below `|u|¹¹/11 ≤ 2^-66/11`: the truncation error is proved, not
/// fitted. The result is `A_hi + (DEG_HI·u + (A_lo + u·(DEG_LO + DEG·(atan u − u)/u)))`.
///
/// Error bound (docs/measurements.md derives it), ε = 2^-53: the final rounding ≤ ½ ulp of
/// the result ≤ 3.56e-15°; the rounding of `t` moves the result by at most
/// `(180/π)·ε·t/(1+t²) ≤ 3.19e-15°`; the three roundings in `u` at most
/// `(180/π)·3ε·|u| ≤ 3.0e-16°`; `DEG_HI·u` and the inner sum ≤ 1.2e-16°; table, constants
/// and truncation below 1e-18°. In all ≤ 7.2e-15° (1.26e-16 rad): as accurate as a correctly
/// rounded radian `atan2` converted to degrees (≤ 5.6e-17 + 6.2e-17 + 8.7e-17 rad with the
/// rounding of the constant), at a fraction of the cost.
#[inline(always)]
fn atan_octant_deg<V: Lanes>(num: V, den: V) -> V {
    // The three odd Taylor coefficients after u, times 180/π (their own rounding is
    // relative 2^-53 of a term below 7.3e-5°).
    const P3: f64 = DEG_HI / -3.0;
    const P5: f64 = DEG_HI / 5.0;
    const P7: f64 = DEG_HI / -7.0;
    const P9: f64 = DEG_HI / 9.0;
    // k = 32t rounded to an integer (ties to even) by the 1.5·2^52 trick, read from the
    // sum's mantissa; t·32 is exact. A NaN gives arbitrary bits, and a NaN row.
    const ROUNDER: f64 = 6_755_399_441_055_744.0;
    let one = V::splat(1.0);
    // 0/0 (both zero) is 0, as atan2(0, 0): the least subnormal stands in for a zero
    // denominator, and leaves every other one as it is.
    let t = num.div(den.max(V::splat(f64::from_bits(1))));
    let sum = t.mul(V::splat(32.0)).add(V::splat(ROUNDER));
    let c = sum.sub(V::splat(ROUNDER)).mul(V::splat(1.0 / 32.0));
    let u = t.sub(c).div(one.add(t.mul(c)));
    // DEG_LO·u + DEG·(atan u − u), in one polynomial, evaluated in pairs of terms (Estrin):
    // a shorter chain of dependent operations than Horner's.
    let z = u.mul(u);
    let z2 = z.mul(z);
    let low = V::splat(DEG_LO).add(z.mul(V::splat(P3)));
    let high = V::splat(P5)
        .add(z.mul(V::splat(P7)))
        .add(z2.mul(V::splat(P9)));
    let tail = u.mul(low.add(z2.mul(high)));
    let [hi, lo] = sum.gather(&tables::ATAN_DEG, |bits| (bits & 63) as usize);
    hi.add(V::splat(DEG_HI).mul(u).add(lo.add(tail)))
}

/// `fmod(x, 360)`, exactly, in bounded time: the sign of `x`, magnitude below 360.
///
/// `fmod`'s cost grows with the exponent of `x` (2.2× the instructions of a whole
/// `cncrot_matrix_from_angles` at 1.8e308°). At or above 2^53 every double is an integer
/// `m·2^k` (m < 2^53), and `(m mod 360)·(2^k mod 360) mod 360` is exact integer arithmetic;
/// `2^k mod 360` repeats with period 12 from k = 3 on (360 = 8·45, and 2 has order 12
/// modulo 45), so it is a table lookup.
#[inline]
pub fn rem360(x: f64) -> f64 {
    const TWO_53: f64 = 9_007_199_254_740_992.0;
    if abs(x) < TWO_53 {
        return fmod(x, 360.0);
    }
    // 2^k mod 360 for k = 3 + j, j = 0..12 (k = 3..14): 8, 16, 32, 64, 128, 256, 152, 304,
    // 248, 136, 272, 184; then it repeats.
    const POW2_MOD_360: [u64; 12] = [8, 16, 32, 64, 128, 256, 152, 304, 248, 136, 272, 184];
    if !x.is_finite() {
        // Infinite or NaN: NaN, as fmod gives (the integer path below would make a finite
        // number of an infinity's or a NaN's bits).
        return f64::NAN;
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i64 - 1075; // x = m·2^exponent
    let m = (bits & ((1u64 << 52) - 1)) | (1u64 << 52);
    // |x| >= 2^53 makes exponent >= 1; finite x makes it at most 971.
    let k = exponent.max(1) as u64;
    let p = match k {
        1 => 2,
        2 => 4,
        _ => POW2_MOD_360[((k - 3) % 12) as usize],
    };
    let r = ((m % 360) * p % 360) as f64;
    if x < 0.0 {
        -r
    } else {
        r
    }
}

/// [`rem360`] kept out of line: the full-turn reduction is the rare path of
/// [`sin_cos_deg`], which is inlined three times into every composition, and of
/// [`wrap_deg`].
#[inline(never)]
fn rem360_cold(x: f64) -> f64 {
    rem360(x)
}

/// Brings an angle in degrees into (-180, 180], never -0.
#[inline]
pub fn wrap_deg(deg: f64) -> f64 {
    // Already in range (every decomposition's output): `fmod` would return it unchanged, at
    // about 60 instructions a call.
    if deg > -180.0 && deg <= 180.0 {
        return deg + 0.0;
    }
    // Out of line: the rare path, which would otherwise sit in every caller's frame.
    let mut r = rem360_cold(deg);
    if r > 180.0 {
        r -= 360.0;
    } else if r <= -180.0 {
        r += 360.0;
    }
    r + 0.0
}

/// `atan2` in degrees, in (-180, 180], never -0.
///
/// Reduced to the first octant (`0 ≤ num ≤ den`), where [`atan_octant_deg`] gives the angle
/// in degrees to 7.2e-15°; the octant is then added in degrees. Calling a radian `atan2`
/// directly and converting would round twice at up to 4.4e-16 rad near 180°, which alone
/// would break the 1e-15 reconstruction goal.
#[inline(always)]
pub fn atan2_deg(y: f64, x: f64) -> f64 {
    atan2_deg_lanes(y, x)
}

/// [`atan2_deg`] of four pairs at once, in vector registers: lane by lane the same
/// operations, hence the same bits. A decomposition's three angles cost about what two did.
#[inline(always)]
pub fn atan2_deg4(y: [f64; 4], x: [f64; 4]) -> [f64; 4] {
    atan2_deg_lanes(F4::new(y), F4::new(x)).to_array()
}

#[inline(always)]
fn atan2_deg_lanes<V: Lanes>(y: V, x: V) -> V {
    let zero = V::splat(0.0);
    let (ax, ay) = (x.abs(), y.abs());
    // The smaller over the larger (`min`/`max` are selects on the comparison, no branch).
    let t = atan_octant_deg(ay.min(ax), ay.max(ax));
    // The octant by masks (random quadrants would mispredict branches): the angle in the
    // upper half plane is off ± t, off = 90 when swapped, else 180 when west, else 0.
    let swap = ax.lt(ay);
    let west = x.lt(zero);
    let off = V::select(swap, V::splat(90.0), V::select(west, V::splat(180.0), zero));
    let upper = off.add(t.negate_where(swap.xor(west)));
    // (-0, negative x) is 180 like (+0, negative x): the range is (-180, 180].
    let south = y.lt(zero).and(upper.ne(V::splat(180.0)));
    let r = upper.negate_where(south).add(zero);
    V::select(x.unordered(y), V::splat(f64::NAN), r)
}

/// Whole turns (multiples of 360°) that bring `angle` nearest to `reference`.
#[inline]
pub fn turns_toward(angle: f64, reference: f64) -> f64 {
    360.0 * round((reference - angle) / 360.0)
}

#[cfg(test)]
mod round_tests {
    /// The inline rounding against the library's, bit for bit: halves, their neighbours,
    /// signed zeros, the 2⁵² boundary, large values, infinities, NaN.
    #[test]
    fn round_is_the_library_round() {
        let mut xs = vec![
            0.0,
            -0.0,
            0.3,
            -0.3,
            0.5,
            -0.5,
            1.5,
            -1.5,
            2.5,
            -2.5,
            0.499_999_999_999_999_94,
            -0.499_999_999_999_999_94,
            4_503_599_627_370_495.5,
            -4_503_599_627_370_495.5,
            4_503_599_627_370_496.0,
            9_007_199_254_740_993.0,
            1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        let mut rng = super::Xorshift(7);
        for _ in 0..100_000 {
            let scale = [1.0, 10.0, 1e3, 1e8, 1e15][(rng.bits() % 5) as usize];
            let x = (rng.unit() - 0.5) * scale;
            xs.extend([x, (2.0 * x).round() / 2.0, f64::from_bits(x.to_bits() + 1)]);
        }
        for x in xs {
            assert_eq!(super::round(x).to_bits(), libm::round(x).to_bits(), "{x}");
        }
        assert!(super::round(f64::NAN).is_nan());
    }
}

/// The xorshift generator the unit tests draw their inputs from.
#[cfg(test)]
pub(crate) struct Xorshift(pub(crate) u64);

#[cfg(test)]
impl Xorshift {
    /// The next state.
    pub(crate) fn bits(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// The next state as a number in [0, 1).
    pub(crate) fn unit(&mut self) -> f64 {
        (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rem360_is_fmod_exactly() {
        // fmod is exact, so the two must agree bit for bit, across the whole range.
        let mut special = vec![
            0.0,
            360.0,
            -360.0,
            9_007_199_254_740_992.0,  // 2^53
            -9_007_199_254_740_994.0, // -(2^53 + 2)
            1.8014398509481984e16,    // 2^54
            f64::MAX,
            -f64::MAX,
            1e300,
            1e6,
        ];
        special.extend((0..1024).map(|k| 2f64.powi(k)));
        let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
        for _ in 0..200_000 {
            let state = rng.bits();
            // Any finite double: random sign, exponent and mantissa bits.
            let x = f64::from_bits(state & !(0x7ffu64 << 52) | ((state >> 11) % 2047) << 52);
            special.push(x);
        }
        for x in special {
            assert_eq!(rem360(x).to_bits(), fmod(x, 360.0).to_bits(), "{x:e}");
        }
    }

    #[test]
    fn right_angles_are_exact() {
        // Values are the exact trigonometric results, written by hand.
        let cases = [
            (0.0, 0.0, 1.0),
            (90.0, 1.0, 0.0),
            (180.0, 0.0, -1.0),
            (-90.0, -1.0, 0.0),
            (-180.0, 0.0, -1.0),
            (270.0, -1.0, 0.0),
            (-270.0, 1.0, 0.0),
            (450.0, 1.0, 0.0),
            (360.0, 0.0, 1.0),
            (-720.0, 0.0, 1.0),
            (1e6 * 360.0 + 90.0, 1.0, 0.0),
        ];
        for (deg, s, c) in cases {
            let (gs, gc) = sin_cos_deg(deg);
            assert_eq!((gs, gc), (s, c), "{deg}");
            assert!(gs.is_sign_positive() || gs != 0.0);
            assert!(gc.is_sign_positive() || gc != 0.0);
        }
    }

    #[test]
    fn general_angles_match_radian_trig() {
        let mut deg = -1000.0;
        while deg < 1000.0 {
            let (s, c) = sin_cos_deg(deg);
            let rad = deg.to_radians();
            assert!(
                (s - rad.sin()).abs() < 2e-15 && (c - rad.cos()).abs() < 2e-15,
                "{deg}"
            );
            deg += 7.3;
        }
    }

    #[test]
    fn non_finite_in_non_finite_out() {
        for x in [f64::NAN, f64::INFINITY, -f64::INFINITY] {
            let (s, c) = sin_cos_deg(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
            assert!(rem360(x).is_nan() && turn_reduced(x).is_nan(), "{x}");
            assert!(atan2_deg(x, 1.0).is_nan() || x.is_infinite());
            assert!(atan2_deg(f64::NAN, x).is_nan() && atan2_deg(x, f64::NAN).is_nan());
        }
        let (s, c) = sin_cos_deg4([f64::NAN, f64::INFINITY, 30.0, -f64::INFINITY]);
        assert!(s[0].is_nan() && s[1].is_nan() && s[3].is_nan() && c[1].is_nan());
        assert_eq!(s[2], 0.5);
    }

    #[test]
    fn atan2_deg_range() {
        assert_eq!(atan2_deg(0.0, -1.0), 180.0);
        assert_eq!(atan2_deg(-0.0, -1.0), 180.0);
        assert_eq!(atan2_deg(1.0, 0.0), 90.0);
        assert_eq!(atan2_deg(-1.0, 0.0), -90.0);
        assert!(atan2_deg(-0.0, 1.0).is_sign_positive());
    }

    #[test]
    fn wrap_and_turns() {
        assert_eq!(wrap_deg(-180.0), 180.0);
        assert_eq!(wrap_deg(540.0), 180.0);
        assert_eq!(wrap_deg(-190.0), 170.0);
        // The fast path agrees with the reduction, -0 included.
        assert!(wrap_deg(-0.0).is_sign_positive());
        for x in [179.999, -179.999, 1e-300, -1e-300, 180.0 - 2.8e-14] {
            assert_eq!(wrap_deg(x).to_bits(), (x % 360.0 + 0.0).to_bits());
        }
        assert!(wrap_deg(-360.0).is_sign_positive());
        // Sinumerik: computed 10°, specified 750° -> 730° (the SINUMERIK manual's example).
        assert_eq!(10.0 + turns_toward(10.0, 750.0), 730.0);
    }

    /// Double-double arithmetic for the reference values: about 106 bits, from algorithms
    /// that share nothing with the code under test (argument halving and plain Taylor series,
    /// π from its two-double expansion).
    mod dd {
        #[derive(Clone, Copy, Debug)]
        pub struct Dd(pub f64, pub f64);

        fn two_sum(a: f64, b: f64) -> Dd {
            let s = a + b;
            let v = s - a;
            Dd(s, (a - (s - v)) + (b - v))
        }
        pub fn add(a: Dd, b: Dd) -> Dd {
            let s = two_sum(a.0, b.0);
            let t = two_sum(s.1 + a.1 + b.1, 0.0);
            let r = two_sum(s.0, t.0);
            Dd(r.0, r.1 + t.1)
        }
        pub fn neg(a: Dd) -> Dd {
            Dd(-a.0, -a.1)
        }
        pub fn mul(a: Dd, b: Dd) -> Dd {
            let p = a.0 * b.0;
            let e = a.0.mul_add(b.0, -p) + (a.0 * b.1 + a.1 * b.0);
            two_sum(p, e)
        }
        pub fn div(a: Dd, b: Dd) -> Dd {
            let q1 = a.0 / b.0;
            let r = add(a, neg(mul(Dd(q1, 0.0), b)));
            let q2 = r.0 / b.0;
            let r = add(r, neg(mul(Dd(q2, 0.0), b)));
            let q3 = r.0 / b.0;
            add(two_sum(q1, q2), Dd(q3, 0.0))
        }
        pub fn sqrt(a: Dd) -> Dd {
            if a.0 == 0.0 {
                return Dd(0.0, 0.0);
            }
            // One Newton step from the double square root doubles its 53 bits.
            let x = a.0.sqrt();
            let e = add(a, neg(mul(Dd(x, 0.0), Dd(x, 0.0))));
            two_sum(x, e.0 / (2.0 * x))
        }
        pub fn pi() -> Dd {
            Dd(core::f64::consts::PI, 1.224_646_799_147_353_2e-16)
        }
        /// atan of a double-double in [0, 1]: three halvings
        /// `atan x = 2 atan(x / (1 + sqrt(1 + x²)))` bring it below 0.1, then Taylor.
        pub fn atan(x: Dd) -> Dd {
            let one = Dd(1.0, 0.0);
            let mut x = x;
            for _ in 0..3 {
                x = div(x, add(one, sqrt(add(one, mul(x, x)))));
            }
            let x2 = mul(x, x);
            let mut term = x;
            let mut sum = Dd(0.0, 0.0);
            let mut n = 1.0;
            while term.0.abs() > 1e-40 * x.0.abs().max(1e-300) && n < 200.0 {
                sum = add(sum, div(term, Dd(n, 0.0)));
                term = neg(mul(term, x2));
                n += 2.0;
            }
            mul(sum, Dd(8.0, 0.0))
        }
        /// sin and cos of a double-double with |x| ≤ 0.8, by their Taylor series.
        pub fn sin_cos(x: Dd) -> (Dd, Dd) {
            let x2 = mul(x, x);
            let (mut s, mut c) = (Dd(0.0, 0.0), Dd(0.0, 0.0));
            let (mut ts, mut tc) = (x, Dd(1.0, 0.0));
            for k in 0..30 {
                s = add(s, ts);
                c = add(c, tc);
                let (a, b) = ((2 * k + 2) as f64, (2 * k + 3) as f64);
                ts = neg(div(mul(ts, x2), Dd(a * b, 0.0)));
                tc = neg(div(mul(tc, x2), Dd((2 * k + 1) as f64 * a, 0.0)));
            }
            (s, c)
        }
        /// 180/π.
        pub fn deg() -> Dd {
            div(Dd(180.0, 0.0), pi())
        }
    }

    /// num/den as a double-double (the remainder of a division is exact).
    fn ratio(num: f64, den: f64) -> dd::Dd {
        let q = num / den;
        dd::Dd(q, (-q).mul_add(den, num) / den)
    }

    fn reference_atan_deg(num: f64, den: f64) -> dd::Dd {
        dd::mul(dd::atan(ratio(num, den)), dd::deg())
    }

    /// |got − want| without rounding `want` to a double first (`got − want.0` is exact
    /// when the two are close).
    fn error(got: f64, want: dd::Dd) -> f64 {
        ((got - want.0) - want.1).abs()
    }

    /// Pairs 0 ≤ num ≤ den: random ratios over many magnitudes, and ratios within a few
    /// ulps of every table point and every midpoint between them (where the table index
    /// changes), of 0 and 1, tiny and subnormal.
    fn octant_inputs(random: usize) -> Vec<(f64, f64)> {
        let mut v = vec![
            (0.0, 0.0),
            (0.0, 1.0),
            (1.0, 1.0),
            (5e-324, 1.0),
            (1e-300, 1e300),
        ];
        v.extend([
            (1e300, 1e300),
            (f64::MAX, f64::MAX),
            (5e-324, 5e-324),
            (1.0, 3.0),
        ]);
        for j in 0..=64 {
            let t = j as f64 / 64.0;
            let mut x = t;
            let mut y = t;
            for _ in 0..40 {
                x = f64::from_bits(x.to_bits().saturating_add(1)).min(1.0);
                y = f64::from_bits(y.to_bits().saturating_sub(1)).max(0.0);
                v.push((x, 1.0));
                v.push((y, 1.0));
                // The same ratios from other numerators and denominators.
                v.push((x * 0.7, 0.7));
                v.push((y * 3.0e-200, 3.0e-200));
            }
        }
        let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
        for i in 0..random {
            let (a, b) = (rng.unit(), rng.unit());
            let scale = [1.0, 1e-150, 1e150, 3.7e-3][i % 4];
            let t = if i % 5 == 0 { a * a * a * 1e-6 } else { a };
            let (num, den) = (t * (b + 0.5) * scale, (b + 0.5) * scale);
            v.push((num.min(den), den));
        }
        v
    }

    /// The bound derived at `atan_octant_deg`, in degrees.
    const ATAN_OCTANT_BOUND: f64 = 7.2e-15;

    #[test]
    fn atan_table_is_right() {
        let deg = dd::deg();
        assert_eq!((DEG_HI, DEG_LO), (deg.0, deg.1));
        for (k, &[hi, lo]) in tables::ATAN_DEG.iter().take(33).enumerate() {
            let r = dd::mul(dd::atan(dd::Dd(k as f64 / 32.0, 0.0)), deg);
            // Both parts, to the double-double's own precision.
            assert_eq!(hi, r.0, "k = {k}");
            assert!(
                (lo - r.1).abs() <= 1e-30 * hi.max(1.0),
                "k = {k}: {lo:e} {:e}",
                r.1
            );
        }
    }

    #[test]
    fn atan_octant_within_its_bound_on_millions() {
        let inputs = octant_inputs(2_000_000);
        let (mut worst, mut worst_libm, mut worst_rust_libm) = (0.0f64, 0.0f64, 0.0f64);
        for &(num, den) in &inputs {
            let got = atan_octant_deg(num, den);
            let want = if den == 0.0 {
                dd::Dd(0.0, 0.0)
            } else {
                reference_atan_deg(num, den)
            };
            let e = error(got, want);
            assert!(
                e <= ATAN_OCTANT_BOUND,
                "atan({num:e}/{den:e}): {got} vs {want:?}"
            );
            worst = worst.max(e);
            worst_libm = worst_libm.max(error(num.atan2(den).to_degrees(), want));
            worst_rust_libm = worst_rust_libm.max(error(libm::atan2(num, den) * DEG_HI, want));
        }
        // Reported for docs/measurements.md (cargo test -- --nocapture).
        println!(
            "atan_octant_deg on {} inputs: worst {worst:.3e}°; platform atan2 → degrees \
             {worst_libm:.3e}°, libm crate {worst_rust_libm:.3e}°",
            inputs.len()
        );
        // No less accurate than converting a radian atan2, which it replaces.
        assert!(worst <= worst_libm.max(worst_rust_libm), "{worst:e}");
    }

    #[test]
    fn atan2_deg_in_every_octant() {
        // Each octant adds one rounding of the sum off ± t: ½ ulp(180°) = 1.43e-14°.
        let pi = dd::pi();
        assert_eq!(atan2_deg(0.0, 0.0), 0.0);
        for &(num, den) in octant_inputs(200_000).iter().step_by(3) {
            if den == 0.0 {
                continue;
            }
            let base = dd::mul(dd::atan(ratio(num, den)), dd::deg());
            let half = dd::mul(dd::div(pi, dd::Dd(2.0, 0.0)), dd::deg());
            let full = dd::mul(pi, dd::deg());
            // (y, x) of each octant and the exact angle there.
            let cases = [
                (num, den, base),
                (den, num, dd::add(half, dd::neg(base))),
                (den, -num, dd::add(half, base)),
                (num, -den, dd::add(full, dd::neg(base))),
                (-num, den, dd::neg(base)),
                (-den, num, dd::neg(dd::add(half, dd::neg(base)))),
                (-den, -num, dd::neg(dd::add(half, base))),
            ];
            for (y, x, want) in cases {
                let got = atan2_deg(y, x);
                assert!(got > -180.0 && got <= 180.0);
                // atan2(-0, -den) is 180, not -180.
                let e = if y == 0.0 && x < 0.0 {
                    (got - 180.0).abs()
                } else {
                    error(got, want)
                };
                assert!(
                    e <= ATAN_OCTANT_BOUND + 1.43e-14,
                    "atan2({y:e}, {x:e}) = {got}"
                );
            }
        }
    }

    #[test]
    fn sin_cos_table_is_right() {
        let rad = dd::div(dd::pi(), dd::Dd(180.0, 0.0));
        for (j, &[sh, sl, ch, cl]) in tables::SIN_COS.iter().enumerate() {
            // Above 45° through the complement, where the series converges well.
            let (s, c) = if j > 45 {
                let (s, c) = dd::sin_cos(dd::mul(dd::Dd(90.0 - j as f64, 0.0), rad));
                (c, s)
            } else {
                dd::sin_cos(dd::mul(dd::Dd(j as f64, 0.0), rad))
            };
            assert_eq!((sh, ch), (s.0, c.0), "{j}°");
            // To the double-double reference's own precision, a few units of 2^-106.
            assert!(
                (sl - s.1).abs() <= 5e-32 && (cl - c.1).abs() <= 5e-32,
                "{j}°"
            );
        }
        // The exact ones are exact.
        assert_eq!(sin_cos_deg(30.0).0, 0.5);
        assert_eq!(sin_cos_deg(60.0).1, 0.5);
        // cos 30° = √3/2, correctly rounded (halving is exact).
        assert_eq!(sin_cos_deg(-150.0), (-0.5, -(3f64.sqrt() / 2.0)));
    }

    /// The bound of `sin_cos_deg` derived at its definition: ½ ulp below 1 plus 6e-18.
    const SIN_COS_BOUND: f64 = 6.2e-17;

    /// `sin_cos_deg` as it was before its kernels: the same exact reduction, then the
    /// platform's `sin` and `cos` of the radian rest.
    fn sin_cos_deg_platform(d: f64) -> (f64, f64) {
        let r = rem360(d);
        let q = (r / 90.0).round();
        let x = (r - 90.0 * q) * RAD_PER_DEG;
        let (s, c) = (x.sin(), x.cos());
        match (q as i64).rem_euclid(4) {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }

    #[test]
    fn sin_cos_deg_within_its_bound_on_millions() {
        let rad = dd::div(dd::pi(), dd::Dd(180.0, 0.0));
        let mut degrees = Vec::new();
        for q in -8..=8 {
            // Within 50 ulps of every multiple of 45° (the quadrant changes at the odd ones).
            let at = 45.0 * q as f64;
            let ulp = f64::from_bits(at.abs().max(1.0).to_bits() + 1) - at.abs().max(1.0);
            degrees.extend((-50..=50).map(|k| at + k as f64 * ulp));
        }
        let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
        for i in 0..2_000_000u64 {
            let u = rng.unit();
            degrees.push(match i % 4 {
                0 => 360.0 * u - 180.0,
                1 => 1e-6 * u,
                2 => 7.2e5 * u - 3.6e5,
                _ => u * 90.0,
            });
        }
        let (mut worst, mut worst_libm) = (0.0f64, 0.0f64);
        for &d in &degrees {
            let (s, c) = sin_cos_deg(d);
            // Reference: the exactly reduced rest times π/180 in double-double.
            let r = rem360(d);
            let q = (r / 90.0).round();
            let rest = r - 90.0 * q;
            let (rs, rc) = dd::sin_cos(dd::mul(dd::Dd(rest, 0.0), rad));
            let (ws, wc) = match (q as i64).rem_euclid(4) {
                0 => (rs, rc),
                1 => (rc, dd::neg(rs)),
                2 => (dd::neg(rs), dd::neg(rc)),
                _ => (dd::neg(rc), rs),
            };
            let e = error(s, ws).max(error(c, wc));
            assert!(e <= SIN_COS_BOUND, "{d}: ({s}, {c}) vs ({ws:?}, {wc:?})");
            worst = worst.max(e);
            // What it replaces: the platform's sin and cos of the same radian argument.
            let (ps, pc) = sin_cos_deg_platform(d);
            worst_libm = worst_libm.max(error(ps, ws).max(error(pc, wc)));
        }
        println!(
            "sin_cos_deg on {} inputs: worst {worst:.3e}; with the platform's sin and cos \
             {worst_libm:.3e}",
            degrees.len()
        );
    }

    /// Equal bits, a NaN equal to any NaN.
    fn same(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    #[test]
    fn lanes_agree_bit_for_bit() {
        // The vector lanes (SSE2 on x86-64), the portable lanes of other targets and the
        // scalar function compute the same bits, specials included.
        use lanes::portable::P4;
        let specials = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f64::NAN,
            f64::INFINITY,
            -f64::INFINITY,
            f64::MAX,
            5e-324,
            -1e-300,
            180.0,
            -180.0,
            359.5,
            -359.5,
            45.0,
            0.5,
        ];
        let mut rng = Xorshift(0x5DEE_CE66_D1CE_4E5B);
        let mut next = |i: usize| {
            let state = rng.bits();
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            match i % 5 {
                0 => specials[(state % 16) as usize],
                1 => 720.0 * u - 360.0,
                2 => (u - 0.5) * 1e-6,
                _ => 2.0 * u - 1.0,
            }
        };
        for n in 0..200_000 {
            let y: [f64; 4] = core::array::from_fn(|i| next(n + i));
            let x: [f64; 4] = core::array::from_fn(|i| next(n + i + 2));
            let v = atan2_deg4(y, x);
            let p = atan2_deg_lanes(P4::new(y), P4::new(x)).to_array();
            for i in 0..4 {
                let s = atan2_deg(y[i], x[i]);
                assert!(same(v[i], s) && same(p[i], s), "atan2({}, {})", y[i], x[i]);
            }
            let (vs, vc) = sin_cos_deg4(y);
            let (ps, pc) = sin_cos_deg_lanes(P4::new(y.map(turn_reduced)));
            let (ps, pc) = (ps.to_array(), pc.to_array());
            for i in 0..4 {
                let (s, c) = sin_cos_deg(y[i]);
                assert!(same(vs[i], s) && same(vc[i], c), "sin_cos({})", y[i]);
                assert!(same(ps[i], s) && same(pc[i], c), "sin_cos({})", y[i]);
            }
        }
    }

    #[test]
    fn turn_reduction_is_exact() {
        // deg − reduced is a whole number of turns, exactly, and the reduced angle lies
        // within (-360, 360): checked in integers against the exact fmod.
        let mut rng = Xorshift(0x1357_9BDF_2468_ACE0);
        for n in 0..1_000_000u64 {
            let state = rng.bits();
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            let deg = match n % 4 {
                0 => (u - 0.5) * 1e6,
                1 => (u - 0.5) * 1.8e16,
                2 => 180.0 * (n as f64) + (u - 0.5) * 1e-9,
                _ => f64::from_bits(state & !(0x7ffu64 << 52) | ((state >> 11) % 1087) << 52),
            };
            let r = turn_reduced(deg);
            assert!(r.abs() < 360.0, "{deg:e} -> {r:e}");
            // Same angle modulo 360: the exact remainders agree modulo 360.
            let diff = (rem360(deg) - rem360(r)).abs();
            assert!(diff == 0.0 || diff == 360.0, "{deg:e} -> {r:e}");
        }
    }
}
