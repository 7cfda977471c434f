//! Arbitrary bytes read as C arguments: integers biased towards the valid ranges and just
//! outside them, doubles that are often special (NaN, ±Inf, ±0, subnormal, huge, exact right
//! angles) and otherwise raw bit patterns, pointers that are sometimes NULL.
#![allow(dead_code)]

pub struct Input<'a>(pub &'a [u8]);

impl Input<'_> {
    pub fn u8(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }

    pub fn u64(&mut self) -> u64 {
        u64::from_le_bytes(core::array::from_fn(|_| self.u8()))
    }

    /// A flag or code: mostly 0..63 and its neighbours, sometimes any i32.
    pub fn int(&mut self) -> i32 {
        match self.u8() % 8 {
            0 => self.u64() as i32,
            1 => [i32::MIN, -1, 2, 64, 65, i32::MAX][usize::from(self.u8()) % 6],
            2..=4 => i32::from(self.u8() % 2),
            _ => i32::from(self.u8() % 66) - 1,
        }
    }

    pub fn f64(&mut self) -> f64 {
        const SPECIAL: [f64; 16] = [
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            5e-324,
            -2.2250738585072014e-308,
            f64::MAX,
            -f64::MAX,
            1e6,
            -1e15,
            90.0,
            -90.0,
            180.0,
            270.0,
            1e-300,
        ];
        match self.u8() % 4 {
            0 => SPECIAL[usize::from(self.u8()) % SPECIAL.len()],
            1 => f64::from_bits(self.u64()),
            2 => f64::from(self.u8() as i8) * 45.0,
            _ => (self.u64() >> 11) as f64 / (1u64 << 53) as f64 * 720.0 - 360.0,
        }
    }

    pub fn f64s<const N: usize>(&mut self) -> [f64; N] {
        core::array::from_fn(|_| self.f64())
    }

    /// True for a NULL pointer, one time in sixteen.
    pub fn null(&mut self) -> bool {
        self.u8().is_multiple_of(16)
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

/// The bit pattern outputs are filled with before each call: an error must leave it.
pub const SENTINEL: f64 = f64::from_bits(0x5A5A_5A5A_5A5A_5A5A);

/// A heap buffer of exactly `n` doubles (so that AddressSanitizer sees any access past it).
pub fn buffer(n: usize, fill: f64) -> Box<[f64]> {
    vec![fill; n].into_boxed_slice()
}

pub fn ptr(b: &[f64], null: bool) -> *const f64 {
    if null {
        core::ptr::null()
    } else {
        b.as_ptr()
    }
}

pub fn ptr_mut(b: &mut [f64], null: bool) -> *mut f64 {
    if null {
        core::ptr::null_mut()
    } else {
        b.as_mut_ptr()
    }
}

/// Every status a function returns is one `cncrot_status_str` names.
pub fn assert_known(status: i32) {
    // SAFETY: cncrot_status_str returns a static NUL-terminated string.
    let s = unsafe { core::ffi::CStr::from_ptr(cncrot::ffi::cncrot_status_str(status)) };
    assert!(
        !s.to_bytes().starts_with(b"CNCROT_STATUS_UNKNOWN:"),
        "unknown status {status}"
    );
    assert_ne!(status, -100, "internal failure (caught panic)");
}

/// After a call: on error every output is untouched, on success every output is finite.
pub fn check_outputs(status: i32, outputs: &[&[f64]]) {
    assert_known(status);
    for out in outputs {
        for &x in out.iter() {
            if status < 0 {
                assert_eq!(
                    x.to_bits(),
                    SENTINEL.to_bits(),
                    "status {status} wrote an output"
                );
            } else {
                assert!(x.is_finite(), "status {status} returned {x}");
            }
        }
    }
}
