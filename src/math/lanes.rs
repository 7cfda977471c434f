//! The few vector operations the trigonometry needs, over one lane (`f64`) or four (`F4`),
//! so that the kernels are written once and a decomposition's three `atan2` run side by
//! side in vector registers.
//!
//! Every operation is the IEEE operation of each lane, so one lane of `F4` gives exactly the
//! bits of `f64`, on every target: on x86-64 `F4` is two SSE2 registers (SSE2 is part of the
//! architecture, so no feature detection is needed, in any build), elsewhere an array
//! worked lane by lane. Comparisons give masks, all ones or all zeros per lane, as SSE2's do.

/// Operations on lanes of `f64`.
pub(crate) trait Lanes: Copy {
    /// Every lane `x`.
    fn splat(x: f64) -> Self;
    fn add(self, o: Self) -> Self;
    fn sub(self, o: Self) -> Self;
    fn mul(self, o: Self) -> Self;
    fn div(self, o: Self) -> Self;
    /// Bitwise and, or, xor of the lanes' bits.
    fn and(self, o: Self) -> Self;
    fn or(self, o: Self) -> Self;
    fn xor(self, o: Self) -> Self;
    /// Bitwise `!self & o`.
    fn and_not(self, o: Self) -> Self;
    /// `self < o ? self : o` per lane (SSE2's `minpd`: the second operand when either is
    /// NaN).
    fn min(self, o: Self) -> Self;
    /// `self > o ? self : o` per lane.
    fn max(self, o: Self) -> Self;
    /// Masks of `self < o`, `self <= o`, `self != o` (true for NaN), and of "either is NaN".
    fn lt(self, o: Self) -> Self;
    fn le(self, o: Self) -> Self;
    fn ne(self, o: Self) -> Self;
    fn unordered(self, o: Self) -> Self;
    /// Whether every lane of a mask is set.
    fn all(self) -> bool;
    /// The table rows `index` chooses from each lane's bits, as `K` lane vectors (row
    /// element k of every lane in vector k). An index beyond the table gives NaN.
    fn gather<const K: usize, const N: usize>(
        self,
        table: &[[f64; K]; N],
        index: impl Fn(u64) -> usize,
    ) -> [Self; K];

    /// `mask ? a : b` per lane.
    #[inline(always)]
    fn select(mask: Self, a: Self, b: Self) -> Self {
        mask.and(a).or(mask.and_not(b))
    }
    /// `|self|`.
    #[inline(always)]
    fn abs(self) -> Self {
        Self::splat(-0.0).and_not(self)
    }
    /// `-self` where `mask`, else `self` (flips the sign bit).
    #[inline(always)]
    fn negate_where(self, mask: Self) -> Self {
        self.xor(mask.and(Self::splat(-0.0)))
    }
}

/// Row `i` of a table, or a row of NaN beyond it (never a panic).
#[inline(always)]
fn row<const K: usize, const N: usize>(table: &[[f64; K]; N], i: usize) -> &[f64; K] {
    table.get(i).unwrap_or(&[f64::NAN; K])
}

#[inline(always)]
fn mask(cond: bool) -> f64 {
    f64::from_bits(if cond { u64::MAX } else { 0 })
}

#[inline(always)]
fn bits2(a: f64, b: f64, op: impl Fn(u64, u64) -> u64) -> f64 {
    f64::from_bits(op(a.to_bits(), b.to_bits()))
}

impl Lanes for f64 {
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn add(self, o: f64) -> f64 {
        self + o
    }
    #[inline(always)]
    fn sub(self, o: f64) -> f64 {
        self - o
    }
    #[inline(always)]
    fn mul(self, o: f64) -> f64 {
        self * o
    }
    #[inline(always)]
    fn div(self, o: f64) -> f64 {
        self / o
    }
    #[inline(always)]
    fn and(self, o: f64) -> f64 {
        bits2(self, o, |a, b| a & b)
    }
    #[inline(always)]
    fn or(self, o: f64) -> f64 {
        bits2(self, o, |a, b| a | b)
    }
    #[inline(always)]
    fn xor(self, o: f64) -> f64 {
        bits2(self, o, |a, b| a ^ b)
    }
    #[inline(always)]
    fn and_not(self, o: f64) -> f64 {
        bits2(self, o, |a, b| !a & b)
    }
    #[inline(always)]
    fn min(self, o: f64) -> f64 {
        if self < o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn max(self, o: f64) -> f64 {
        if self > o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn lt(self, o: f64) -> f64 {
        mask(self < o)
    }
    #[inline(always)]
    fn le(self, o: f64) -> f64 {
        mask(self <= o)
    }
    #[inline(always)]
    fn all(self) -> bool {
        self.to_bits() == u64::MAX
    }
    #[inline(always)]
    fn ne(self, o: f64) -> f64 {
        mask(self != o)
    }
    #[inline(always)]
    fn unordered(self, o: f64) -> f64 {
        mask(self.is_nan() | o.is_nan())
    }
    #[inline(always)]
    fn gather<const K: usize, const N: usize>(
        self,
        table: &[[f64; K]; N],
        index: impl Fn(u64) -> usize,
    ) -> [f64; K] {
        *row(table, index(self.to_bits()))
    }
}

#[cfg(target_arch = "x86_64")]
pub(crate) use sse2::F4;

#[cfg(not(target_arch = "x86_64"))]
pub(crate) use portable::P4 as F4;

#[cfg(target_arch = "x86_64")]
mod sse2 {
    use super::Lanes;
    use core::arch::x86_64::*;

    /// Four lanes in two SSE2 registers.
    #[derive(Clone, Copy)]
    pub(crate) struct F4(__m128d, __m128d);

    impl F4 {
        #[inline(always)]
        pub(crate) fn new(v: [f64; 4]) -> F4 {
            // SAFETY: SSE2 is part of x86-64; these intrinsics only read their arguments.
            unsafe { F4(_mm_set_pd(v[1], v[0]), _mm_set_pd(v[3], v[2])) }
        }
        #[inline(always)]
        pub(crate) fn to_array(self) -> [f64; 4] {
            let mut v = [0.0; 4];
            // SAFETY: SSE2 is part of x86-64; the stores write the four elements of `v`.
            unsafe {
                _mm_storeu_pd(v.as_mut_ptr(), self.0);
                _mm_storeu_pd(v.as_mut_ptr().add(2), self.1);
            }
            v
        }
    }

    macro_rules! binary {
        ($($name:ident => $intrinsic:ident),* $(,)?) => {$(
            #[inline(always)]
            fn $name(self, o: F4) -> F4 {
                // SAFETY: SSE2 is part of x86-64; lane-wise arithmetic on registers.
                unsafe { F4($intrinsic(self.0, o.0), $intrinsic(self.1, o.1)) }
            }
        )*};
    }

    impl Lanes for F4 {
        #[inline(always)]
        fn splat(x: f64) -> F4 {
            // SAFETY: SSE2 is part of x86-64.
            unsafe { F4(_mm_set1_pd(x), _mm_set1_pd(x)) }
        }
        binary! {
            add => _mm_add_pd, sub => _mm_sub_pd, mul => _mm_mul_pd, div => _mm_div_pd,
            and => _mm_and_pd, or => _mm_or_pd, xor => _mm_xor_pd, and_not => _mm_andnot_pd,
            min => _mm_min_pd, max => _mm_max_pd, lt => _mm_cmplt_pd, le => _mm_cmple_pd,
            ne => _mm_cmpneq_pd, unordered => _mm_cmpunord_pd,
        }
        #[inline(always)]
        fn all(self) -> bool {
            // SAFETY: SSE2 is part of x86-64.
            unsafe { (_mm_movemask_pd(self.0) & _mm_movemask_pd(self.1)) == 3 }
        }
        #[inline(always)]
        fn gather<const K: usize, const N: usize>(
            self,
            table: &[[f64; K]; N],
            index: impl Fn(u64) -> usize,
        ) -> [F4; K] {
            // Four row references, then each vector loaded from the rows: gathering the
            // values into arrays first took K·64 bytes of stack.
            let [a, b, c, d] = self.to_array().map(f64::to_bits);
            let (a, b) = (super::row(table, index(a)), super::row(table, index(b)));
            let (c, d) = (super::row(table, index(c)), super::row(table, index(d)));
            core::array::from_fn(|k| F4::new([a[k], b[k], c[k], d[k]]))
        }
    }
}

/// The lanes of other targets, compiled on every target so that the tests compare it with
/// the vector version bit for bit.
#[cfg_attr(target_arch = "x86_64", allow(dead_code))]
pub(crate) mod portable {
    use super::Lanes;

    /// Four lanes, worked one by one.
    #[derive(Clone, Copy)]
    pub(crate) struct P4([f64; 4]);

    impl P4 {
        #[inline(always)]
        pub(crate) fn new(v: [f64; 4]) -> P4 {
            P4(v)
        }
        #[inline(always)]
        pub(crate) fn to_array(self) -> [f64; 4] {
            self.0
        }
    }

    macro_rules! binary {
        ($($name:ident),* $(,)?) => {$(
            #[inline(always)]
            fn $name(self, o: P4) -> P4 {
                P4(core::array::from_fn(|i| <f64 as Lanes>::$name(self.0[i], o.0[i])))
            }
        )*};
    }

    impl Lanes for P4 {
        #[inline(always)]
        fn splat(x: f64) -> P4 {
            P4([x; 4])
        }
        binary!(add, sub, mul, div, and, or, xor, and_not, min, max, lt, le, ne, unordered);
        #[inline(always)]
        fn all(self) -> bool {
            self.0.iter().all(|&m| m.all())
        }
        #[inline(always)]
        fn gather<const K: usize, const N: usize>(
            self,
            table: &[[f64; K]; N],
            index: impl Fn(u64) -> usize,
        ) -> [P4; K] {
            let [a, b, c, d] = self.0.map(f64::to_bits);
            let (a, b) = (super::row(table, index(a)), super::row(table, index(b)));
            let (c, d) = (super::row(table, index(c)), super::row(table, index(d)));
            core::array::from_fn(|k| P4([a[k], b[k], c[k], d[k]]))
        }
    }
}
