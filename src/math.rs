//! The one module through which all floating-point functions are called.
//!
//! With the `std` feature the platform's libm is used (glibc's `atan2` is the fastest
//! measured here); without it the pure-Rust `libm` crate, so the crate needs nothing from a
//! C library. Everything else in the crate calls these functions, never `f64` methods that
//! need `std`, so that switching the feature switches every computation. The feature
//! `pure-rust-math` selects the `libm` crate with `std` too: the no-panic proof, which needs
//! unwinding and hence `std`, uses it to cover the real-time build's arithmetic.

#[cfg(all(feature = "std", not(feature = "pure-rust-math")))]
mod imp {
    #[inline]
    pub fn sin(x: f64) -> f64 {
        x.sin()
    }
    #[inline]
    pub fn cos(x: f64) -> f64 {
        x.cos()
    }
    #[inline]
    pub fn atan2(y: f64, x: f64) -> f64 {
        y.atan2(x)
    }
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
    pub fn sin(x: f64) -> f64 {
        libm::sin(x)
    }
    #[inline]
    pub fn cos(x: f64) -> f64 {
        libm::cos(x)
    }
    #[inline]
    pub fn atan2(y: f64, x: f64) -> f64 {
        libm::atan2(y, x)
    }
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

pub use imp::{atan2, ceil, round, sqrt};
use imp::{cos, fmod, sin};

/// `|x|` without `std` (clears the sign bit).
#[inline]
pub fn abs(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & !(1u64 << 63))
}

/// Degrees per radian, correctly rounded (the constant `f64::to_degrees` uses); with it
/// `atan2` results of exactly ±π/2 and π convert to exactly ±90 and 180.
const DEG_PER_RAD: f64 = 57.295_779_513_082_32;
const RAD_PER_DEG: f64 = core::f64::consts::PI / 180.0;

/// Converts radians to degrees.
#[inline]
pub fn to_degrees(rad: f64) -> f64 {
    rad * DEG_PER_RAD
}

/// Sine and cosine of an angle in degrees, exact where the answer is exact.
///
/// The argument is reduced in degrees, where the reduction is exact (`fmod` and the
/// subtraction of a nearby multiple of 90 lose no bits), so multiples of 90° of any size give
/// exact 0 and ±1 and the radian argument passed to `sin`/`cos` never exceeds 45°.
#[inline]
pub fn sin_cos_deg(deg: f64) -> (f64, f64) {
    // fmod is slow and exact; most angles need no full-turn reduction at all.
    let mut r = deg;
    if abs(r) > 180.0 {
        r = rem360(deg);
        if r > 180.0 {
            r -= 360.0;
        } else if r < -180.0 {
            r += 360.0;
        }
    }
    let q = round(r / 90.0);
    let rest = r - 90.0 * q;
    let (s, c) = if rest == 0.0 {
        (0.0, 1.0)
    } else {
        let rad = rest * RAD_PER_DEG;
        (sin(rad), cos(rad))
    };
    // `+ 0.0` turns -0 into +0 so that no caller ever sees a signed zero.
    let (s, c) = match q as i32 {
        1 => (c, -s),
        2 | -2 => (-s, -c),
        -1 => (-c, s),
        _ => (s, c),
    };
    (s + 0.0, c + 0.0)
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

/// Brings an angle in degrees into (-180, 180], never -0.
#[inline]
pub fn wrap_deg(deg: f64) -> f64 {
    // Already in range (every decomposition's output): `fmod` would return it unchanged, at
    // about 60 instructions a call.
    if deg > -180.0 && deg <= 180.0 {
        return deg + 0.0;
    }
    let mut r = rem360(deg);
    if r > 180.0 {
        r -= 360.0;
    } else if r <= -180.0 {
        r += 360.0;
    }
    r + 0.0
}

/// `atan2` in degrees, in (-180, 180], never -0.
///
/// The radian `atan2` is only ever asked for an angle within 0..45°, where its result
/// carries at most 1.1e-16 rad of rounding; the quadrant is then added in degrees. Calling
/// `atan2` directly and converting would round twice at up to 4.4e-16 rad near 180°, which
/// alone would break the 1e-15 reconstruction goal.
#[inline]
pub fn atan2_deg(y: f64, x: f64) -> f64 {
    let (ax, ay) = (abs(x), abs(y));
    let swap = ay > ax;
    let (num, den) = if swap { (ax, ay) } else { (ay, ax) };
    let t = to_degrees(atan2(num, den));
    // Branch-free selection of the octant (random quadrants would mispredict): the angle in
    // the upper half plane is off + sign·t.
    let west = x < 0.0;
    let off = if swap {
        90.0
    } else if west {
        180.0
    } else {
        0.0
    };
    let sign = if swap == west { 1.0 } else { -1.0 };
    let upper = off + sign * t;
    // (-0, negative x) is 180 like (+0, negative x): the range is (-180, 180].
    let r = if y < 0.0 && upper != 180.0 {
        -upper
    } else {
        upper
    };
    r + 0.0
}

/// Whole turns (multiples of 360°) that bring `angle` nearest to `reference`.
#[inline]
pub fn turns_toward(angle: f64, reference: f64) -> f64 {
    360.0 * round((reference - angle) / 360.0)
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
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
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
}
