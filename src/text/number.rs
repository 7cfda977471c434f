//! Decimal numbers in program text, read and written exactly, without allocation and
//! provably without panics (`core`'s own float parsing and formatting are opaque calls that
//! the no-panic proof cannot see through, and they would accept `inf` and `nan`).
//!
//! Reading rounds correctly (to nearest, ties to even) whatever the number of digits;
//! writing gives either the shortest digits that read back to the same double or the value
//! correctly rounded to a number of decimals (ties to even, as C's `printf` does). Both work
//! on magnitudes from 1e-100 to 1e100 (and zero): beyond that no controller's number format
//! reaches, and the exact arithmetic stays within fixed-size integers.

use super::big::Big;
use crate::Error;
use core::cmp::Ordering;

/// Limbs of the reader's integers (1536 bits: the largest product of a comparison within the
/// documented range, 200 digits at 10^-100, is about 1340 bits).
const READ: usize = 48;

/// Limbs of the writer's integers (512 bits: a double below 1e100 or its scale 2^386 times a
/// digit is about 400 bits). Small, so that writing stays within the stack bound.
const WRITE: usize = 16;

/// The most significant digits a number may have (trailing zeros are not counted).
pub const MAX_DIGITS: usize = 200;

/// Numbers are read and written for magnitudes `10^-MAX_EXP10 ≤ |x| < 10^MAX_EXP10`.
pub const MAX_EXP10: i32 = 100;

/// The most decimals the fixed-point writer rounds to.
pub const MAX_DECIMALS: i32 = 17;

/// A positive normal double as `mant · 2^exp` with `2^52 ≤ mant < 2^53`.
fn split(v: f64) -> (u64, i32) {
    let bits = v.to_bits();
    let field = ((bits >> 52) & 0x7ff) as i32;
    ((bits & ((1 << 52) - 1)) | (1 << 52), field - 1075)
}

/// The powers of ten that are exact doubles.
const POWERS: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// 10^e as a double for |e| ≤ 200 (exact for 0 ≤ e ≤ 22, else a few ulps off: only a
/// starting point).
fn pow10_approx(e: i32) -> f64 {
    let mut n = e.unsigned_abs().min(300);
    let mut p = 1.0;
    while n > 22 {
        p *= 1e22;
        n -= 22;
    }
    p *= POWERS.get(n as usize).copied().unwrap_or(1.0);
    if e < 0 {
        1.0 / p
    } else {
        p
    }
}

/// Compares `n · 10^e` with `m · 2^k` exactly.
#[inline(never)]
fn cmp_exact(n: &Big<READ>, e: i32, m: u64, k: i32) -> Result<Ordering, Error> {
    let (mut l, mut r) = (*n, Big::from_u64(m));
    if e >= 0 {
        l.mul_pow5(e.unsigned_abs())?;
    } else {
        r.mul_pow5(e.unsigned_abs())?;
    }
    let p2 = e.saturating_sub(k);
    if p2 >= 0 {
        l.shl(p2.unsigned_abs())?;
    } else {
        r.shl(p2.unsigned_abs())?;
    }
    Ok(l.cmp(&r))
}

/// 10^0 … 10^19: every power of ten below 2^64.
const POW10: [u64; 20] = {
    let mut t = [1u64; 20];
    let mut i = 1;
    while i < 20 {
        t[i] = t[i - 1] * 10;
        i += 1;
    }
    t
};

/// 10^n for n ≤ 19 (`None` beyond).
fn pow10(n: u32) -> Option<u64> {
    POW10.get(n as usize).copied()
}

/// `w · 10^e` correctly rounded, when `w` has at most 19 digits and `-19 ≤ e ≤ 19`, with
/// nothing but exact 128-bit integer arithmetic and one correctly rounded conversion:
/// for `e ≥ 0` the product is exact in 128 bits; for `e < 0` the quotient of `w` shifted to
/// the top of 128 bits by `10^-e` has at least 64 bits, so its remainder folded into the
/// last bit (a sticky bit, far below the rounding position) makes the conversion round as
/// the exact quotient would, and the scaling back by a power of two is exact.
fn parse_fast(w: u64, e: i32) -> Option<f64> {
    if w == 0 {
        return Some(0.0);
    }
    let p = u128::from(pow10(e.unsigned_abs())?);
    if e >= 0 {
        return Some(to_f64(u128::from(w) * p));
    }
    let lz = w.leading_zeros();
    let top = u128::from(w) << (64 + lz);
    let q = top.checked_div(p)?;
    let sticky = u128::from(top.checked_rem(p)? != 0);
    // 2^-(64 + lz), a normal double (64 + lz ≤ 127).
    let scale = f64::from_bits(u64::from(1023 - 64 - lz) << 52);
    Some(to_f64(q | sticky) * scale)
}

/// `x` correctly rounded to a double, with 64-bit conversions only: Rust's `u128 as f64`
/// calls a runtime helper (`__floatuntidf`) that the real-time library for MSVC would need
/// from its host. Above 2^64 the top 64 bits with the rest folded into a sticky bit round
/// as the whole does (the rounding position is 11 bits above the sticky one), and the
/// scaling by a power of two is exact.
fn to_f64(x: u128) -> f64 {
    if x >> 64 == 0 {
        return x as u64 as f64;
    }
    let lz = x.leading_zeros(); // < 64
    let top = x << lz;
    let high = (top >> 64) as u64 | u64::from(top as u64 != 0);
    high as f64 * f64::from_bits(u64::from(1023 + 64 - lz) << 52)
}

/// The value of `digits` (ASCII digits with at most one `.` or `,`, the decimal comma that
/// [`scan_digits`] admits where a dialect has it; at least one digit) times
/// `10^exp10`, correctly rounded; `negative` gives the sign (never -0).
///
/// Refused: other characters ([`Error::Parse`]), more than [`MAX_DIGITS`] significant
/// digits ([`Error::Parse`]), a non-zero magnitude outside `10^±MAX_EXP10`
/// ([`Error::OutOfRange`]).
pub fn parse(negative: bool, digits: &[u8], exp10: i32) -> Result<f64, Error> {
    // Never -0: a zero is a zero whatever its sign.
    let sign = |v: f64| if negative && v != 0.0 { -v } else { v };
    if let Some(v) = parse_short(digits, exp10) {
        return Ok(sign(v));
    }
    let (mut sig, mut zeros, mut frac, mut point, mut any) = (0usize, 0usize, 0i32, false, false);
    // The first 19 significant digits: all of them in nearly every program.
    let (mut w, mut used) = (0u64, 0usize);
    for &b in digits {
        match b {
            b'.' | b',' if !point => point = true,
            b'0'..=b'9' => {
                any = true;
                frac = frac.saturating_add(i32::from(point));
                if b == b'0' {
                    // Held back: trailing zeros only scale the value.
                    if sig > 0 {
                        zeros = zeros.saturating_add(1);
                    }
                    continue;
                }
                let pending = zeros.saturating_add(1);
                if used == sig && sig + pending <= 19 {
                    // w < 10^sig, so w · 10^pending < 10^19 < 2^64.
                    let scale = POW10.get(pending).copied().unwrap_or(0);
                    w = w.wrapping_mul(scale).wrapping_add(u64::from(b - b'0'));
                    used += pending;
                }
                sig = sig.saturating_add(pending);
                if sig > MAX_DIGITS {
                    return Err(Error::Parse);
                }
                zeros = 0;
            }
            _ => return Err(Error::Parse),
        }
    }
    if !any {
        return Err(Error::Parse);
    }
    if sig == 0 {
        return Ok(0.0);
    }
    // value = (all significant digits) · 10^e; its decimal magnitude is sig + e.
    let e = i64::from(exp10) - i64::from(frac) + zeros as i64;
    let magnitude = e + sig as i64;
    if magnitude > i64::from(MAX_EXP10) || magnitude <= -i64::from(MAX_EXP10) {
        return Err(Error::OutOfRange);
    }
    let e = e as i32;
    if used == sig {
        if let Some(v) = parse_small(w, e) {
            return Ok(sign(v));
        }
    }
    parse_exact(digits, sig, e, w, used).map(sign)
}

/// The digits at the start of a number (digits with at most one point, or decimal comma
/// where the dialect has one; a second ends them), gathered in the same pass that finds
/// where they end.
#[derive(Clone, Copy, Debug)]
pub struct Scanned {
    /// How many bytes the digits and the point take.
    pub len: usize,
    /// The digits as one integer (meaningful for at most 19 of them).
    w: u64,
    /// How many digits.
    n: usize,
    /// How many digits after the point.
    frac: i32,
}

/// Finds the digits at the start of `text` (see [`Scanned`]); `comma`: a `,` may stand for
/// the point.
#[inline(always)]
pub fn scan_digits(text: &[u8], comma: bool) -> Scanned {
    let (mut w, mut n, mut frac, mut point, mut len) = (0u64, 0usize, 0i32, false, 0usize);
    for &b in text {
        let d = b.wrapping_sub(b'0');
        if d < 10 {
            w = w.wrapping_mul(10).wrapping_add(u64::from(d));
            n += 1;
            frac = frac.saturating_add(i32::from(point));
        } else if (b == b'.' || (comma && b == b',')) && !point {
            point = true;
        } else {
            break;
        }
        len += 1;
    }
    Scanned { len, w, n, frac }
}

/// [`parse`] of `digits` already scanned by [`scan_digits`] (`digits` is the text it
/// scanned, `s.len` bytes): the same value, without a second pass for numbers of at most
/// 19 digits.
#[inline(always)]
pub fn parse_scanned(negative: bool, digits: &[u8], s: &Scanned, exp10: i32) -> Result<f64, Error> {
    match short(s, exp10) {
        Some(v) if negative && v != 0.0 => Ok(-v),
        Some(v) => Ok(v),
        None => parse(negative, digits, exp10),
    }
}

/// The value of at most 19 scanned digits scaled by at most 10^±80 (every number of a
/// program in practice; no range to check), or `None`.
#[inline(always)]
fn short(s: &Scanned, exp10: i32) -> Option<f64> {
    let e = exp10.checked_sub(s.frac)?;
    // 1 to 19 digits: the magnitude stays within 10^±100.
    if s.n == 0 || s.n > 19 || !(-80..=80).contains(&e) {
        return None;
    }
    if s.w == 0 {
        return Some(0.0);
    }
    parse_small(s.w, e)
}

/// [`parse`] of at most 19 digits scaled by at most 10^±80, in one pass.
#[inline(always)]
fn parse_short(digits: &[u8], exp10: i32) -> Option<f64> {
    // `parse` takes either mark: the caller's scan said which one the text may have.
    let s = scan_digits(digits, true);
    if s.len != digits.len() {
        return None;
    }
    short(&s, exp10)
}

/// `w · 10^e` for `w < 10^19`: Clinger's case first (`w` and `10^|e|` exact doubles, one
/// correctly rounded operation: "30.5", "-20.125", most numbers people type), then the
/// 128-bit one.
#[inline(always)]
fn parse_small(w: u64, e: i32) -> Option<f64> {
    if w <= 1 << 53 {
        if let Some(&p) = POWERS.get(e.unsigned_abs() as usize) {
            return Some(if e >= 0 { w as f64 * p } else { w as f64 / p });
        }
    }
    parse_fast(w, e)
}

/// The general case of [`parse`] (more than 19 digits, or a scale beyond 10^±19): a
/// starting approximation moved one ulp at a time by exact comparisons with the
/// midpoints to its neighbours.
#[inline(never)]
fn parse_exact(digits: &[u8], sig: usize, e: i32, w: u64, used: usize) -> Result<f64, Error> {
    // The significant digits as one integer, nine at a time.
    let mut n = Big::<READ>::from_u64(0);
    let (mut taken, mut chunk, mut len) = (0usize, 0u32, 0usize);
    for &b in digits {
        if taken == sig {
            break;
        }
        if !b.is_ascii_digit() || (taken == 0 && b == b'0') {
            continue;
        }
        chunk = chunk.wrapping_mul(10).wrapping_add(u32::from(b - b'0'));
        taken += 1;
        len += 1;
        if len == 9 {
            n.mul_small(1_000_000_000)?;
            n.add_small(chunk)?;
            (chunk, len) = (0, 0);
        }
    }
    if len > 0 {
        n.mul_small(POW10.get(len).copied().unwrap_or(1) as u32)?;
        n.add_small(chunk)?;
    }
    let approx = w as f64 * pow10_approx(e + (sig - used) as i32);
    let mut c = approx;
    // The approximation is within a few ulps; each step moves one ulp towards the exact
    // value, and the bound keeps the reader's time bounded whatever happens.
    for _ in 0..64 {
        let (mant, exp) = split(c);
        let up = cmp_exact(&n, e, 2 * mant + 1, exp - 1)?;
        let down = if mant == 1 << 52 {
            cmp_exact(&n, e, 4 * mant - 1, exp - 2)?
        } else {
            cmp_exact(&n, e, 2 * mant - 1, exp - 1)?
        };
        let odd = mant & 1 == 1;
        let next = match (up, down) {
            (Ordering::Greater, _) => f64::from_bits(c.to_bits() + 1),
            (Ordering::Equal, _) if odd => f64::from_bits(c.to_bits() + 1),
            (_, Ordering::Less) => f64::from_bits(c.to_bits() - 1),
            (_, Ordering::Equal) if odd => f64::from_bits(c.to_bits() - 1),
            _ => return Ok(c),
        };
        // A tie moved to the even neighbour is final.
        if up == Ordering::Equal || down == Ordering::Equal {
            return Ok(next);
        }
        c = next;
    }
    Err(Error::Parse)
}

/// How a number is spelt in a dialect.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Style {
    /// Write `+` before positive numbers and zero (Heidenhain's `SPA+30`).
    pub plus: bool,
    /// Write a point after whole numbers (`30.`: Fanuc-style controls read `30` in the
    /// least input increment unless a parameter says otherwise).
    pub point: bool,
}

/// A caller's text buffer being filled; remembers whether anything did not fit, and the
/// longest line.
pub struct Out<'a> {
    buf: &'a mut [u8],
    len: usize,
    full: bool,
    /// Counts without storing: the length a text would have.
    counting: bool,
    line: usize,
    longest: usize,
}

impl<'a> Out<'a> {
    /// An empty text over `buf`.
    pub fn new(buf: &'a mut [u8]) -> Out<'a> {
        Out {
            buf,
            len: 0,
            full: false,
            counting: false,
            line: 0,
            longest: 0,
        }
    }

    /// A text that is only measured (its length and longest line), without a buffer: a
    /// writer called twice, to measure and then to write, needs no buffer of its own.
    pub fn counter() -> Out<'static> {
        Out {
            counting: true,
            ..Out::new(&mut [])
        }
    }

    /// Appends one byte (or remembers that it did not fit).
    pub fn byte(&mut self, b: u8) {
        if b == b'\n' {
            self.line = 0;
        } else {
            self.line += 1;
            self.longest = self.longest.max(self.line);
        }
        if self.counting {
            self.len = self.len.saturating_add(1);
            return;
        }
        match self.buf.get_mut(self.len) {
            Some(slot) => {
                *slot = b;
                self.len += 1;
            }
            None => self.full = true,
        }
    }

    /// The longest line appended so far, in bytes without its end.
    pub fn longest_line(&self) -> usize {
        self.longest
    }

    /// Appends bytes.
    pub fn text(&mut self, t: &[u8]) {
        for &b in t {
            self.byte(b);
        }
    }

    /// The length written, or `None` if something did not fit.
    pub fn finish(&self) -> Option<usize> {
        if self.full {
            None
        } else {
            Some(self.len)
        }
    }
}

/// Decimal digits with the position of the point: the value is `0.d1 d2 … × 10^point`.
struct Digits {
    d: [u8; 128],
    n: usize,
    point: i32,
}

impl Digits {
    fn push(&mut self, digit: u8) {
        if let Some(slot) = self.d.get_mut(self.n) {
            *slot = digit;
            self.n += 1;
        }
    }

    fn get(&self, i: usize) -> u8 {
        self.d.get(i).copied().unwrap_or(0)
    }
}

/// The shortest digits that read back (to nearest, ties to even) as `v` (positive, normal):
/// Steele and White's free-format algorithm with exact integers.
// Not inlined: its integers and those of `fixed` need not share one frame.
#[inline(never)]
fn shortest(v: f64) -> Result<Digits, Error> {
    let (mant, exp) = split(v);
    let even = mant & 1 == 0;
    let boundary = mant == 1 << 52 && (v.to_bits() >> 52) > 1;
    // v = r / s; the neighbours are (r ± m) / s (m_minus smaller at a binade's bottom).
    let (mut r, mut s, mut mp, mut mm): (Big<WRITE>, Big<WRITE>, Big<WRITE>, Big<WRITE>);
    if exp >= 0 {
        let sh = exp.unsigned_abs();
        r = Big::from_u64(mant);
        r.shl(sh + 1 + u32::from(boundary))?;
        s = Big::from_u64(2 << u32::from(boundary));
        mp = Big::from_u64(1);
        mp.shl(sh + u32::from(boundary))?;
        mm = Big::from_u64(1);
        mm.shl(sh)?;
    } else {
        r = Big::from_u64(mant << (1 + u32::from(boundary)));
        s = Big::from_u64(1);
        s.shl(exp.unsigned_abs() + 1 + u32::from(boundary))?;
        mp = Big::from_u64(1 << u32::from(boundary));
        mm = Big::from_u64(1);
    }
    // k ≈ ⌈log10 v⌉ from the binary exponent, then corrected exactly.
    let e2 = exp + 52;
    let mut k = ((f64::from(e2) * core::f64::consts::LOG10_2) as i32).saturating_add(1);
    if k >= 0 {
        s.mul_pow10(k.unsigned_abs())?;
    } else {
        let p = k.unsigned_abs();
        r.mul_pow10(p)?;
        mp.mul_pow10(p)?;
        mm.mul_pow10(p)?;
    }
    let high = |r: &Big<WRITE>, mp: &Big<WRITE>, s: &Big<WRITE>| -> Result<bool, Error> {
        let mut t = *r;
        t.add(mp)?;
        Ok(match t.cmp(s) {
            Ordering::Greater => true,
            Ordering::Equal => even,
            Ordering::Less => false,
        })
    };
    for _ in 0..4 {
        if high(&r, &mp, &s)? {
            s.mul_small(10)?;
            k += 1;
        } else {
            break;
        }
    }
    for _ in 0..4 {
        let mut t = r;
        t.add(&mp)?;
        t.mul_small(10)?;
        if t.cmp(&s) == Ordering::Less {
            r.mul_small(10)?;
            mp.mul_small(10)?;
            mm.mul_small(10)?;
            k -= 1;
        } else {
            break;
        }
    }
    let mut out = Digits {
        d: [0; 128],
        n: 0,
        point: k,
    };
    for _ in 0..20 {
        r.mul_small(10)?;
        mp.mul_small(10)?;
        mm.mul_small(10)?;
        let mut digit = 0u8;
        while r.cmp(&s) != Ordering::Less && digit < 10 {
            r.sub(&s);
            digit += 1;
        }
        let low = match r.cmp(&mm) {
            Ordering::Less => true,
            Ordering::Equal => even,
            Ordering::Greater => false,
        };
        let hi = high(&r, &mp, &s)?;
        if low || hi {
            let up = if low && hi {
                let mut twice = r;
                twice.shl(1)?;
                match twice.cmp(&s) {
                    Ordering::Less => false,
                    Ordering::Greater => true,
                    Ordering::Equal => digit & 1 == 1,
                }
            } else {
                hi
            };
            out.push(digit + u8::from(up));
            carry(&mut out);
            return Ok(out);
        }
        out.push(digit);
    }
    Err(Error::OutOfRange)
}

/// Propagates a last digit of 10 (a rounding up) to the digits before it.
fn carry(x: &mut Digits) {
    let mut i = x.n;
    while i > 0 {
        i -= 1;
        let Some(d) = x.d.get_mut(i) else { return };
        if *d < 10 {
            return;
        }
        *d = 0;
        if i == 0 {
            // 9.99… became 10: one digit more in front.
            let len = x.d.len();
            x.d.copy_within(0..len - 1, 1);
            if let Some(first) = x.d.first_mut() {
                *first = 1;
            }
            x.n = (x.n + 1).min(x.d.len());
            x.point += 1;
        } else if let Some(prev) = x.d.get_mut(i - 1) {
            *prev += 1;
        }
    }
}

/// The digits of `q` (trailing zeros dropped), the point after the last of them.
fn digits_of(q: u128) -> Digits {
    let mut out = Digits {
        d: [0; 128],
        n: 0,
        point: 0,
    };
    // Above 2^64: the last 19 digits apart, so that every division is a 64-bit one.
    const E19: u128 = 10_000_000_000_000_000_000;
    let (mut high, low, low_digits) = if q >> 64 == 0 {
        (q as u64, 0u64, 0u32)
    } else {
        ((q / E19) as u64, (q % E19) as u64, 19)
    };
    let mut rev = [0u8; 20];
    let mut n = 0;
    while high > 0 {
        if let Some(slot) = rev.get_mut(n) {
            *slot = (high % 10) as u8;
        }
        n += 1;
        high /= 10;
    }
    for i in (0..n).rev() {
        out.push(rev.get(i).copied().unwrap_or(0));
    }
    let (mut low, mut tail) = (low, [0u8; 19]);
    for i in (0..low_digits as usize).rev() {
        if let Some(slot) = tail.get_mut(i) {
            *slot = (low % 10) as u8;
        }
        low /= 10;
    }
    for &digit in tail.iter().take(low_digits as usize) {
        out.push(digit);
    }
    out.point = out.n as i32;
    while out.n > 0 && out.get(out.n - 1) == 0 {
        out.n -= 1;
    }
    out
}

/// `mant · 2^exp · 10^decimals` rounded to an integer, ties to even, when it fits the
/// exact 128-bit arithmetic (`None` otherwise).
fn fixed_fast(mant: u64, exp: i32, decimals: u32) -> Option<Digits> {
    // mant · 10^17 < 2^110.
    let n = u128::from(mant) * u128::from(pow10(decimals)?);
    let q = if exp >= 0 {
        if exp > 17 {
            return None;
        }
        n << exp
    } else {
        let s = exp.unsigned_abs();
        if s > 110 {
            // Below 2^110 / 2^111: less than a half, rounds to zero.
            0
        } else {
            let (quo, rem, half) = (n >> s, n & ((1u128 << s) - 1), 1u128 << (s - 1));
            quo + u128::from(rem > half || (rem == half && quo & 1 == 1))
        }
    };
    let mut out = digits_of(q);
    out.point -= decimals as i32;
    Some(out)
}

/// The shortest digits that read back as `v` (positive, normal), when `v · 10^k` fits the
/// exact 128-bit arithmetic for the scales it needs (about 1e-5 ≤ v < 2^53; `None`
/// otherwise), the same digits as [`shortest`] gives.
///
/// Every decimal of at most 15 significant digits lies more than an ulp from the next (for
/// `10^E ≤ v < 10^(E+1)` their spacing 10^(E-14) exceeds 2^-52 · 10^(E+1)), so at most one
/// of them reads back as `v`, and if one does it is `v` rounded to 15 digits (then shorter
/// once its trailing zeros go). Otherwise the answer has 16 or 17 digits and is the closest
/// such decimal that reads back: `v` rounded to that many digits, or, at the bottom of a
/// binade where the interval that reads back is narrower below `v`, the decimal one unit
/// above. Seventeen digits always read back.
fn shortest_fast(v: f64) -> Option<Digits> {
    let (mant, exp) = split(v);
    if !(-120..0).contains(&exp) {
        return None;
    }
    let s = exp.unsigned_abs();
    let even = mant & 1 == 0;
    let bottom = mant == 1 << 52;
    // ⌊log10 v⌋ is ⌊e2 · log10 2⌋ or one more (e2 = ⌊log2 v⌋); 78913 / 2^18 is log10 2 to
    // within what these exponents need.
    let e2 = exp + 52;
    let mut e10 = (e2 * 78913) >> 18;
    // v · 10^k exactly as n / 2^s, for 0 ≤ k ≤ 21 (n < 2^53 · 10^21 < 2^123).
    let scaled = |k: i32| -> Option<(u128, u128)> {
        if !(0..=21).contains(&k) {
            return None;
        }
        let k = k.unsigned_abs();
        let p = if k > 19 {
            u128::from(pow10(k - 19)?) * u128::from(pow10(19)?)
        } else {
            u128::from(pow10(k)?)
        };
        Some((u128::from(mant) * p, p))
    };
    if scaled(16 - e10)?.0 >> s >= u128::from(pow10(17)?) {
        e10 += 1;
    }
    let half_ulp_ok = |twice: u128, ulp: u128| twice < ulp || (twice == ulp && even);
    for digits in 15..=17 {
        let k = digits - 1 - e10;
        // The ulp of v is 10^k in units of 2^-s.
        let (n, ulp) = scaled(k)?;
        let (quo, rem, one) = (n >> s, n & ((1u128 << s) - 1), 1u128 << s);
        let half = one >> 1;
        let up = rem > half || (rem == half && quo & 1 == 1);
        let found = if up {
            half_ulp_ok(2 * (one - rem), ulp).then_some(quo + 1)
        } else if bottom {
            // Below v the interval is half as wide; one unit up may be inside instead.
            if half_ulp_ok(4 * rem, ulp) {
                Some(quo)
            } else {
                half_ulp_ok(2 * (one - rem), ulp).then_some(quo + 1)
            }
        } else {
            half_ulp_ok(2 * rem, ulp).then_some(quo)
        };
        if let Some(r) = found {
            let mut out = digits_of(r);
            out.point -= k;
            return Some(out);
        }
    }
    None
}

/// `v` (positive, normal) rounded to `decimals` decimals, ties to even.
#[inline(never)]
fn fixed(v: f64, decimals: u32) -> Result<Digits, Error> {
    let (mant, exp) = split(v);
    let mut q = Big::<WRITE>::from_u64(mant);
    q.mul_pow10(decimals)?;
    if exp >= 0 {
        q.shl(exp.unsigned_abs())?;
    } else {
        // q / 2^-exp, rounded: the remainder compared with half the divisor.
        let sh = exp.unsigned_abs();
        let mut rem = q;
        let mut quo = Big::from_u64(0);
        // Long division by a power of two: the quotient is q shifted right.
        for (i, x) in quo.d.iter_mut().enumerate() {
            let at = |j: usize| q.d.get(j).copied().unwrap_or(0);
            let (limbs, bits) = ((sh / 32) as usize, sh % 32);
            let lo = at(i + limbs);
            let hi = at(i + limbs + 1);
            *x = if bits == 0 {
                lo
            } else {
                (lo >> bits) | (hi << (32 - bits))
            };
        }
        let mut back = quo;
        back.shl(sh)?;
        rem.sub(&back);
        rem.shl(1)?;
        let mut half = Big::from_u64(1);
        half.shl(sh)?;
        let up = match rem.cmp(&half) {
            Ordering::Greater => true,
            Ordering::Less => false,
            Ordering::Equal => quo.d.first().is_some_and(|&x| x & 1 == 1),
        };
        q = quo;
        if up {
            q.add_small(1)?;
        }
    }
    // The digits of q, last first.
    let mut rev = [0u8; 128];
    let mut n = 0;
    while !q.is_zero() {
        let Some(slot) = rev.get_mut(n) else {
            return Err(Error::OutOfRange);
        };
        *slot = q.div_small(10) as u8;
        n += 1;
    }
    let mut out = Digits {
        d: [0; 128],
        n: 0,
        point: n as i32 - decimals as i32,
    };
    for i in (0..n).rev() {
        out.push(rev.get(i).copied().unwrap_or(0));
    }
    // Trailing zeros say nothing.
    while out.n > 0 && out.get(out.n - 1) == 0 {
        out.n -= 1;
    }
    Ok(out)
}

/// Writes `v` into `out`: the shortest digits that read back exactly (`decimals < 0`), or
/// rounded to `decimals` (0..=[`MAX_DECIMALS`]) decimals, trailing zeros dropped, never in
/// exponent notation and never `-0`.
///
/// Refused: a non-finite `v` ([`Error::NotFinite`]), a magnitude of `10^MAX_EXP10` or more,
/// or a non-zero magnitude below `10^-MAX_EXP10` to be written exactly
/// ([`Error::OutOfRange`]), `decimals` above [`MAX_DECIMALS`] ([`Error::BadArgument`]).
pub fn write(out: &mut Out, v: f64, decimals: i32, style: Style) -> Result<(), Error> {
    if !v.is_finite() {
        return Err(Error::NotFinite);
    }
    if decimals > MAX_DECIMALS {
        return Err(Error::BadArgument);
    }
    let a = crate::math::abs(v);
    if a >= 1e100 || (a != 0.0 && a < 1e-100 && decimals < 0) {
        return Err(Error::OutOfRange);
    }
    let digits = if a == 0.0 || (decimals >= 0 && a < 1e-100) {
        None
    } else if decimals < 0 {
        Some(match shortest_fast(a) {
            Some(digits) => digits,
            None => shortest(a)?,
        })
    } else {
        let (mant, exp) = split(a);
        let digits = match fixed_fast(mant, exp, decimals.unsigned_abs()) {
            Some(digits) => digits,
            None => fixed(a, decimals.unsigned_abs())?,
        };
        Some(digits).filter(|d| d.n > 0)
    };
    let Some(x) = digits else {
        if style.plus {
            out.byte(b'+');
        }
        out.text(if style.point { b"0." } else { b"0" });
        return Ok(());
    };
    if v < 0.0 {
        out.byte(b'-');
    } else if style.plus {
        out.byte(b'+');
    }
    let n = x.n as i32;
    if x.point <= 0 {
        out.text(b"0.");
        for _ in 0..x.point.unsigned_abs() {
            out.byte(b'0');
        }
        for i in 0..x.n {
            out.byte(b'0' + x.get(i));
        }
    } else if x.point < n {
        for i in 0..x.n {
            if i as i32 == x.point {
                out.byte(b'.');
            }
            out.byte(b'0' + x.get(i));
        }
    } else {
        for i in 0..x.n {
            out.byte(b'0' + x.get(i));
        }
        for _ in 0..(x.point - n) {
            out.byte(b'0');
        }
        if style.point {
            out.byte(b'.');
        }
    }
    Ok(())
}

/// Whether [`write`] writes `v` as `0` with `decimals` (a word a writer may leave out).
pub fn writes_zero(v: f64, decimals: i32) -> bool {
    let mut buf = [0u8; 1];
    let mut out = Out::new(&mut buf);
    let plain = Style {
        plus: false,
        point: false,
    };
    write(&mut out, v, decimals, plain).is_ok() && out.finish() == Some(1) && buf == *b"0"
}

/// Writes `<name><number>` (the name carries its leading space and any `=`).
pub fn write_word(
    out: &mut Out,
    name: &[u8],
    value: f64,
    decimals: i32,
    style: Style,
) -> Result<(), Error> {
    out.text(name);
    write(out, value, decimals, style)
}

/// Writes an integer (selectors: `_MODE`, `P`, `Q`).
pub fn write_integer(out: &mut Out, v: i32) {
    let mut digits = [0u8; 11];
    let mut n = 0;
    let mut x = v.unsigned_abs();
    loop {
        if let Some(d) = digits.get_mut(n) {
            *d = b'0' + (x % 10) as u8;
        }
        n += 1;
        x /= 10;
        if x == 0 || n >= digits.len() {
            break;
        }
    }
    if v < 0 {
        out.byte(b'-');
    }
    for i in (0..n).rev() {
        out.byte(digits.get(i).copied().unwrap_or(b'0'));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Zero as written: rounded away at the decimals asked for, never in the shortest
    /// exact digits unless it is 0.
    #[test]
    fn what_writes_as_zero() {
        assert!(writes_zero(0.0, 4) && writes_zero(-0.0, -1) && writes_zero(-4e-5, 4));
        assert!(writes_zero(1e-17, 12) && writes_zero(0.000_499_9, 3));
        assert!(!writes_zero(5e-4, 3) && !writes_zero(1e-17, -1) && !writes_zero(7.0, 0));
    }

    fn read(t: &str) -> Result<f64, Error> {
        let (neg, t) = match t.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, t),
        };
        parse(neg, t.as_bytes(), 0)
    }

    fn show(v: f64, decimals: i32, style: Style) -> String {
        let mut buf = [0u8; 400];
        let mut out = Out::new(&mut buf);
        write(&mut out, v, decimals, style).unwrap();
        let n = out.finish().unwrap();
        String::from_utf8(buf[..n].to_vec()).unwrap()
    }

    const PLAIN: Style = Style {
        plus: false,
        point: false,
    };

    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
    }

    /// The reader gives the bits of `str::parse` (correctly rounded, an independent
    /// implementation) for long and short numbers, ties and near-ties included.
    #[test]
    fn reads_as_the_standard_parser() {
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        for i in 0..300_000 {
            let mut t = String::new();
            let digits = 1 + (rng.next() % 40) as usize;
            let point = (rng.next() % (digits as u64 + 1)) as usize;
            for k in 0..digits {
                if k == point {
                    t.push('.');
                }
                t.push(char::from(b'0' + (rng.next() % 10) as u8));
            }
            let e = (rng.next() % 120) as i32 - 60;
            let theirs: f64 = format!("{t}e{e}").parse().unwrap();
            let ours = parse(false, t.as_bytes(), e);
            if theirs != 0.0 && (theirs.abs() >= 1e99 || theirs.abs() < 1e-99) {
                continue;
            }
            assert_eq!(ours.map(f64::to_bits), Ok(theirs.to_bits()), "{i}: {t}e{e}");
        }
        // Exact midpoints between neighbouring doubles round to the even one.
        for v in [1.0f64, 0.1, 123.456, 1e-50, 3e80, 0.7, 1.5] {
            let exact = exact_midpoint(v);
            let theirs: f64 = exact.parse().unwrap();
            assert_eq!(read(&exact).unwrap().to_bits(), theirs.to_bits(), "{exact}");
        }
    }

    /// The decimal expansion of the midpoint between `v` and the next double up (exact:
    /// a binary fraction has a finite decimal expansion).
    fn exact_midpoint(v: f64) -> String {
        let (mant, exp) = split(v);
        // (2·mant + 1) · 2^(exp − 1) = (2·mant + 1) · 5^(1−exp) / 10^(1−exp) for exp < 1.
        let mut n = Big::<READ>::from_u64(2 * mant + 1);
        let scale = if exp < 1 {
            n.mul_pow5((1 - exp) as u32).unwrap();
            (1 - exp) as usize
        } else {
            n.shl((exp - 1) as u32).unwrap();
            0
        };
        let mut s = Vec::new();
        while !n.is_zero() {
            s.push(b'0' + n.div_small(10) as u8);
        }
        while s.len() <= scale {
            s.push(b'0');
        }
        s.reverse();
        let (int, frac) = s.split_at(s.len() - scale);
        format!(
            "{}.{}",
            String::from_utf8(int.to_vec()).unwrap(),
            String::from_utf8(frac.to_vec()).unwrap()
        )
    }

    fn same(a: &Digits, b: &Digits) -> bool {
        a.n == b.n && a.point == b.point && a.d[..a.n] == b.d[..b.n]
    }

    /// Doubles that stress the fast writers: random bits in and around their range, short
    /// decimals, the bottoms of binades (where the interval that reads back is lopsided),
    /// the neighbours of powers of ten, and decimals halfway between 15-, 16- and
    /// 17-digit neighbours.
    fn hard_doubles(rng: &mut Rng) -> Vec<f64> {
        let mut v = Vec::new();
        for _ in 0..200_000 {
            let e = (rng.next() % 80) as i64 - 60;
            let bits = (((1023 + e) as u64) << 52) | (rng.next() >> 12);
            v.push(f64::from_bits(bits));
            v.push((rng.next() % 100_000_000) as f64 / 10_000.0);
            v.push((rng.next() % 10_000_000_000_000_000) as f64 / 1e12);
            // Integers and quarters of 16 and 17 digits: exact ties between 16- and
            // 17-digit decimals (…649.25 lies halfway between …649.2 and …649.3).
            v.push((rng.next() >> 11) as f64 / f64::from(1 << (rng.next() % 4)));
        }
        for e in -80..60 {
            let p = 2f64.powi(e);
            v.extend([
                p,
                f64::from_bits(p.to_bits() + 1),
                f64::from_bits(p.to_bits() - 1),
            ]);
        }
        for e in -20..=22 {
            let p: f64 = format!("1e{e}").parse().unwrap();
            for d in -3i64..=3 {
                v.push(f64::from_bits((p.to_bits() as i64 + d) as u64));
            }
        }
        for _ in 0..100_000 {
            // n + 1/2 units in the 16th or 17th digit: exact ties where n · 2 + 1 fits.
            let digits = 15 + (rng.next() % 3) as i32;
            let n = 10u64.pow(digits as u32 - 1) + rng.next() % (9 * 10u64.pow(digits as u32 - 1));
            let scale = (rng.next() % 20) as i32;
            v.push((2 * n + 1) as f64 / 2f64.powi(1) / 10f64.powi(scale));
        }
        v
    }

    /// The fast writers give exactly the digits of the exact ones wherever they answer,
    /// and answer for nearly every angle and coordinate.
    #[test]
    fn fast_writers_are_the_exact_ones() {
        let mut rng = Rng(0xD1B5_4A32_D192_ED03);
        let (mut fast, mut all) = (0usize, 0usize);
        for v in hard_doubles(&mut rng) {
            if !(1e-99..1e99).contains(&v) {
                continue;
            }
            all += 1;
            let exact = shortest(v).unwrap();
            if let Some(quick) = shortest_fast(v) {
                fast += 1;
                assert!(same(&quick, &exact), "shortest {v:e}");
            }
            let d = (rng.next() % 18) as u32;
            let (mant, exp) = split(v);
            if let Some(quick) = fixed_fast(mant, exp, d) {
                assert!(same(&quick, &fixed(v, d).unwrap()), "fixed {v:e} {d}");
            }
        }
        assert!(fast * 10 > all * 7, "fast path answered {fast} of {all}");
        // Angles and millimetres: always the fast path.
        for i in 0..100_000 {
            let v = (rng.next() % 720_000_000) as f64 / 1e6 + f64::from(i % 7) * 1e-9 + 1e-4;
            assert!(shortest_fast(v).is_some(), "{v}");
        }
    }

    /// The 64-bit conversion of 128-bit integers rounds as Rust's own (round to nearest,
    /// ties to even), ties and near-ties included.
    #[test]
    fn to_f64_rounds_as_the_language() {
        let mut rng = Rng(0xBB67_AE85_84CA_A73B);
        for k in 0..200_000 {
            let x = (u128::from(rng.next()) << 64 | u128::from(rng.next())) >> (k % 128);
            assert_eq!(to_f64(x).to_bits(), (x as f64).to_bits(), "{x}");
            // Exact ties and their neighbours: 54 significant bits ending in 1, then ± 1.
            let tie = (u128::from(rng.next() >> 10) | 1) << (k % 70);
            for y in [tie, tie + 1, tie - 1] {
                assert_eq!(to_f64(y).to_bits(), (y as f64).to_bits(), "{y}");
            }
        }
    }

    /// The 128-bit reader gives the exact reader's bits for every number it answers.
    #[test]
    fn fast_reader_is_the_exact_one() {
        let mut rng = Rng(0x6A09_E667_F3BC_C909);
        for _ in 0..300_000 {
            let digits = 1 + (rng.next() % 19) as u32;
            let w = rng.next() % 10u64.pow(digits) + 1;
            let e = (rng.next() % 45) as i32 - 25;
            let text = w.to_string();
            let exact = parse_exact(text.as_bytes(), text.len(), e, w, text.len());
            if let Some(quick) = parse_fast(w, e) {
                assert_eq!(Ok(quick.to_bits()), exact.map(f64::to_bits), "{w}e{e}");
            }
            let theirs: f64 = format!("{w}e{e}").parse().unwrap();
            assert_eq!(exact.map(f64::to_bits), Ok(theirs.to_bits()), "{w}e{e}");
        }
        // Ties: midpoints between neighbouring doubles with at most 19 digits.
        for v in [1.0f64, 1.5, 1e10, 123.25, 2f64.powi(60)] {
            let mid = exact_midpoint(v);
            let digits: String = mid.chars().filter(char::is_ascii_digit).collect();
            let digits = digits.trim_start_matches('0').trim_end_matches('0');
            if digits.len() <= 19 {
                let theirs: f64 = mid.parse().unwrap();
                assert_eq!(read(&mid).unwrap().to_bits(), theirs.to_bits(), "{mid}");
            }
        }
    }

    #[test]
    fn refusals() {
        assert_eq!(parse(false, b"", 0), Err(Error::Parse));
        assert_eq!(parse(false, b".", 0), Err(Error::Parse));
        assert_eq!(parse(false, b"1.2.3", 0), Err(Error::Parse));
        assert_eq!(parse(false, b"1e5", 0), Err(Error::Parse));
        assert_eq!(parse(false, b"1", 100), Err(Error::OutOfRange));
        assert_eq!(parse(false, b"1", -101), Err(Error::OutOfRange));
        assert_eq!(
            parse(false, b"1", -100).map(f64::to_bits),
            Ok(1e-100f64.to_bits())
        );
        assert_eq!(
            parse(false, b"1", 99).map(f64::to_bits),
            Ok(1e99f64.to_bits())
        );
        assert_eq!(parse(false, b"0", 5000).map(f64::to_bits), Ok(0));
        assert_eq!(parse(true, b"0.000", 0).map(f64::to_bits), Ok(0));
        let long = "1".repeat(MAX_DIGITS + 1);
        assert_eq!(parse(false, long.as_bytes(), 0), Err(Error::Parse));
        // Zeros are free: they only scale.
        let padded = format!("30{}", "0".repeat(200));
        assert_eq!(parse(false, padded.as_bytes(), -200), Ok(30.0));
    }

    /// Shortest output has Rust's (shortest round-trip) length and reads back exactly.
    #[test]
    fn shortest_round_trips() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for i in 0..300_000 {
            let v = match i % 3 {
                0 => f64::from_bits(rng.next() >> 1),
                1 => (rng.next() % 7_200_000) as f64 / 10_000.0 - 360.0,
                _ => (rng.next() as f64 / u64::MAX as f64 - 0.5) * 1000.0,
            };
            if v != 0.0 && !(1e-99..1e99).contains(&v.abs()) {
                continue;
            }
            let s = show(v, -1, PLAIN);
            assert_eq!(read(&s).unwrap().to_bits(), v.to_bits(), "{v:e} → {s}");
            let theirs = format!("{:e}", v);
            let sig = theirs
                .split('e')
                .next()
                .unwrap()
                .bytes()
                .filter(u8::is_ascii_digit)
                .count();
            let trimmed: String = s.chars().filter(|c| c.is_ascii_digit()).collect();
            let trimmed = trimmed.trim_start_matches('0').trim_end_matches('0');
            assert_eq!(trimmed.len(), sig, "{v:e}: {s} vs {theirs}");
        }
    }

    /// Fixed decimals give what C's printf gives (exact, ties to even), trailing zeros
    /// dropped.
    #[test]
    fn fixed_as_printf() {
        let cases: [(f64, i32, &str); 12] = [
            (30.0, 3, "30"),
            (28.481238, 3, "28.481"),
            (0.125, 2, "0.12"),
            (0.375, 2, "0.38"),
            (2.5, 0, "2"),
            (3.5, 0, "4"),
            (-0.0004, 3, "0"),
            (-0.0005, 3, "-0.001"), // 0.0005 is a little above 5e-4 in binary
            (1.005, 2, "1"),        // 1.005 is a little below in binary
            (123456789.12345679, 4, "123456789.1235"),
            (1e-120, 3, "0"),
            (-359.99999, 3, "-360"),
        ];
        for (v, d, want) in cases {
            assert_eq!(show(v, d, PLAIN), want, "{v} {d}");
        }
        let mut rng = Rng(77);
        for _ in 0..100_000 {
            let v = (rng.next() as f64 / u64::MAX as f64 - 0.5) * 2000.0;
            let d = (rng.next() % 7) as i32;
            let theirs = format!("{v:.*}", d as usize);
            let theirs = if theirs.contains('.') {
                theirs
                    .trim_end_matches('0')
                    .trim_end_matches('.')
                    .to_string()
            } else {
                theirs
            };
            let theirs = if theirs == "-0" {
                "0".to_string()
            } else {
                theirs
            };
            assert_eq!(show(v, d, PLAIN), theirs, "{v} {d}");
        }
    }

    #[test]
    fn styles() {
        let heidenhain = Style {
            plus: true,
            point: false,
        };
        let fanuc = Style {
            plus: false,
            point: true,
        };
        assert_eq!(show(27.0, -1, heidenhain), "+27");
        assert_eq!(show(0.0, -1, heidenhain), "+0");
        assert_eq!(show(-0.0, -1, heidenhain), "+0");
        assert_eq!(show(-20.5, -1, heidenhain), "-20.5");
        assert_eq!(show(30.0, -1, fanuc), "30.");
        assert_eq!(show(0.0, 3, fanuc), "0.");
        assert_eq!(show(1e-7, -1, PLAIN), "0.0000001");
        assert_eq!(show(1.5e20, -1, fanuc), "150000000000000000000.");
        assert_eq!(show(9.9999999, 3, PLAIN), "10");
        let mut small = [0u8; 3];
        let mut out = Out::new(&mut small);
        write(&mut out, 1234.0, -1, PLAIN).unwrap();
        assert_eq!(out.finish(), None);
        let mut buf = [0u8; 8];
        let mut out = Out::new(&mut buf);
        assert_eq!(write(&mut out, f64::NAN, -1, PLAIN), Err(Error::NotFinite));
        assert_eq!(write(&mut out, 1e100, -1, PLAIN), Err(Error::OutOfRange));
        assert_eq!(write(&mut out, 1e-101, -1, PLAIN), Err(Error::OutOfRange));
        assert_eq!(write(&mut out, 1.0, 18, PLAIN), Err(Error::BadArgument));
    }
}
