//! Non-negative integers of a fixed number of limbs: the exact arithmetic behind reading and
//! writing decimal numbers (no allocation; every operation that would overflow says so).

use crate::Error;
use core::cmp::Ordering;

/// A non-negative integer of `L` 32-bit limbs, little-endian; every operation that would overflow
/// reports it instead.
#[derive(Clone, Copy)]
pub(crate) struct Big<const L: usize> {
    pub(crate) d: [u32; L],
}

impl<const L: usize> Big<L> {
    pub(crate) fn from_u64(v: u64) -> Self {
        let mut d = [0u32; L];
        for (k, x) in d.iter_mut().take(2).enumerate() {
            *x = (v >> (32 * k)) as u32;
        }
        Big { d }
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.d.iter().all(|&x| x == 0)
    }

    pub(crate) fn mul_small(&mut self, m: u32) -> Result<(), Error> {
        let mut carry = 0u64;
        for x in self.d.iter_mut() {
            let p = u64::from(*x) * u64::from(m) + carry;
            *x = p as u32;
            carry = p >> 32;
        }
        if carry == 0 {
            Ok(())
        } else {
            Err(Error::OutOfRange)
        }
    }

    pub(crate) fn add_small(&mut self, a: u32) -> Result<(), Error> {
        let mut carry = u64::from(a);
        for x in self.d.iter_mut() {
            let s = u64::from(*x) + carry;
            *x = s as u32;
            carry = s >> 32;
        }
        if carry == 0 {
            Ok(())
        } else {
            Err(Error::OutOfRange)
        }
    }

    pub(crate) fn mul_pow5(&mut self, mut n: u32) -> Result<(), Error> {
        const POW5_13: u32 = 1_220_703_125;
        while n >= 13 {
            self.mul_small(POW5_13)?;
            n -= 13;
        }
        self.mul_small(5u32.pow(n))
    }

    pub(crate) fn mul_pow10(&mut self, n: u32) -> Result<(), Error> {
        self.mul_pow5(n)?;
        self.shl(n)
    }

    pub(crate) fn shl(&mut self, n: u32) -> Result<(), Error> {
        let limbs = (n / 32) as usize;
        let bits = n % 32;
        if limbs >= L {
            return if self.is_zero() {
                Ok(())
            } else {
                Err(Error::OutOfRange)
            };
        }
        // Nothing may be shifted out at the top.
        let lost_limbs = self.d.iter().rev().take(limbs).any(|&x| x != 0);
        let top = self.d.get(L - 1 - limbs).copied().unwrap_or(0);
        let lost_bits = bits != 0 && (top >> (32 - bits)) != 0;
        if lost_limbs || lost_bits {
            return Err(Error::OutOfRange);
        }
        let old = self.d;
        for (i, x) in self.d.iter_mut().enumerate() {
            let at = |j: Option<usize>| j.and_then(|j| old.get(j)).copied().unwrap_or(0);
            let hi = at(i.checked_sub(limbs));
            let lo = at(i.checked_sub(limbs + 1));
            *x = if bits == 0 {
                hi
            } else {
                (hi << bits) | (lo >> (32 - bits))
            };
        }
        Ok(())
    }

    pub(crate) fn add(&mut self, o: &Self) -> Result<(), Error> {
        let mut carry = 0u64;
        for (x, &y) in self.d.iter_mut().zip(o.d.iter()) {
            let s = u64::from(*x) + u64::from(y) + carry;
            *x = s as u32;
            carry = s >> 32;
        }
        if carry == 0 {
            Ok(())
        } else {
            Err(Error::OutOfRange)
        }
    }

    /// `self -= o`; callers ensure `self >= o`.
    pub(crate) fn sub(&mut self, o: &Self) {
        let mut borrow = 0i64;
        for (x, &y) in self.d.iter_mut().zip(o.d.iter()) {
            let s = i64::from(*x) - i64::from(y) - borrow;
            *x = s as u32;
            borrow = i64::from(s < 0);
        }
    }

    /// `self /= m`, returning the remainder.
    pub(crate) fn div_small(&mut self, m: u32) -> u32 {
        let mut rem = 0u64;
        for x in self.d.iter_mut().rev() {
            let cur = (rem << 32) | u64::from(*x);
            *x = (cur / u64::from(m.max(1))) as u32;
            rem = cur % u64::from(m.max(1));
        }
        rem as u32
    }

    pub(crate) fn cmp(&self, o: &Self) -> Ordering {
        for (x, y) in self.d.iter().rev().zip(o.d.iter().rev()) {
            match x.cmp(y) {
                Ordering::Equal => {}
                other => return other,
            }
        }
        Ordering::Equal
    }
}
