//! CRC-32 (IEEE 802.3, reflected, the one zlib's `crc32`, PNG and Ethernet use), for the
//! integrity of states the caller stores and restores. Not mathematics of rotations: a
//! storage format detail, here so that the C boundary only calls it.

/// The lookup tables of slicing-by-16, built at compile time (16 KiB of read-only data):
/// `TABLES[0]` is the byte-wise table, `TABLES[k][b]` the CRC of byte `b` followed by `k`
/// zero bytes. Sixteen independent lookups per sixteen bytes replace sixteen dependent
/// ones: the byte-wise loop is bound by the latency of its chain (about 7 cycles a byte,
/// 1.2 µs for the two checksums of a CYCLE600 call), this one by throughput, at half the
/// chain length of slicing-by-8 (the two seals of a program line were half its time).
const TABLES: [[u32; 256]; 16] = {
    let mut t = [[0u32; 256]; 16];
    let mut i = 0;
    while i < 256 {
        let mut c = i as u32;
        let mut k = 0;
        while k < 8 {
            c = if c & 1 != 0 {
                0xEDB8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
            k += 1;
        }
        t[0][i] = c;
        i += 1;
    }
    let mut s = 1;
    while s < 16 {
        let mut i = 0;
        while i < 256 {
            let prev = t[s - 1][i];
            t[s][i] = (prev >> 8) ^ t[0][(prev & 0xff) as usize];
            i += 1;
        }
        s += 1;
    }
    t
};

/// The CRC-32 of `bytes`. It detects every change of up to 32 consecutive bits (so every
/// single-bit flip) and all but one in 2^32 random changes.
///
/// ```
/// // The standard check value of CRC-32.
/// assert_eq!(cncrot::crc32(b"123456789"), 0xCBF4_3926);
/// ```
pub fn crc32(bytes: &[u8]) -> u32 {
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    if bytes.len() >= 16
        && std::is_x86_feature_detected!("pclmulqdq")
        && std::is_x86_feature_detected!("sse4.1")
    {
        // SAFETY: the processor has the instructions `folded` is compiled for (checked
        // just above).
        return unsafe { folded::crc32(bytes) };
    }
    crc32_tables(bytes)
}

/// [`crc32`] with the tables, on every processor.
fn crc32_tables(bytes: &[u8]) -> u32 {
    let mut c = !0u32;
    let mut chunks = bytes.chunks_exact(16);
    for chunk in &mut chunks {
        let mut w = [0u8; 16];
        w.copy_from_slice(chunk);
        let word = |k: usize| u32::from_le_bytes([w[k], w[k + 1], w[k + 2], w[k + 3]]);
        let (a, b, d, e) = (word(0) ^ c, word(4), word(8), word(12));
        let t = |table: usize, x: u32, shift: u32| TABLES[table][((x >> shift) & 0xff) as usize];
        c = t(15, a, 0) ^ t(14, a, 8) ^ t(13, a, 16) ^ t(12, a, 24);
        c ^= t(11, b, 0) ^ t(10, b, 8) ^ t(9, b, 16) ^ t(8, b, 24);
        c ^= t(7, d, 0) ^ t(6, d, 8) ^ t(5, d, 16) ^ t(4, d, 24);
        c ^= t(3, e, 0) ^ t(2, e, 8) ^ t(1, e, 16) ^ t(0, e, 24);
    }
    for &b in chunks.remainder() {
        c = TABLES[0][((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8);
    }
    !c
}

/// CRC-32 by folding with carry-less multiplication (Gopal et al., "Fast CRC computation
/// for generic polynomials using PCLMULQDQ", Intel, 2009, in its bit-reflected form; the
/// constants are those of zlib's and Linux's implementations for this polynomial): 16 bytes
/// a step with two independent multiplications. The seals of a program line are two CRCs
/// of 132 bytes: a `G69` line took 275 ns with slicing-by-8, 215 with slicing-by-16 and 168
/// with this (docs/measurements.md). Same bits as the tables (tested against the bitwise
/// definition).
#[cfg(all(feature = "std", target_arch = "x86_64"))]
mod folded {
    use core::arch::x86_64::*;

    /// x^(128+32) mod P and x^(128-32) mod P, reflected: one 128-bit block folded onto the
    /// next.
    const K3: i64 = 0x1_7519_97d0;
    const K4: i64 = 0x0_ccaa_009e;
    /// x^64 mod P, reflected: 96 bits to 64.
    const K5: i64 = 0x1_63cd_6124;
    /// The polynomial and its Barrett constant ⌊x^64 / P⌋, reflected.
    const P_X: i64 = 0x1_DB71_0641;
    const U_PRIME: i64 = 0x1_F701_1641;

    #[inline(always)]
    unsafe fn fold(a: __m128i, b: __m128i, keys: __m128i) -> __m128i {
        let low = _mm_clmulepi64_si128(a, keys, 0x00);
        let high = _mm_clmulepi64_si128(a, keys, 0x11);
        _mm_xor_si128(_mm_xor_si128(b, low), high)
    }

    /// The CRC-32 of `bytes` (at least 16 of them; fewer give the tables' answer).
    ///
    /// # Safety
    /// The processor has PCLMULQDQ and SSE4.1.
    #[target_feature(enable = "pclmulqdq", enable = "sse2", enable = "sse4.1")]
    pub(super) unsafe fn crc32(bytes: &[u8]) -> u32 {
        let mut blocks = bytes.chunks_exact(16);
        let Some(first) = blocks.next() else {
            return super::crc32_tables(bytes);
        };
        let load = |b: &[u8]| _mm_loadu_si128(b.as_ptr().cast());
        // The initial value !0 enters as the complement of the first four bytes.
        let mut x = _mm_xor_si128(load(first), _mm_cvtsi32_si128(-1));
        let k3k4 = _mm_set_epi64x(K4, K3);
        for block in &mut blocks {
            x = fold(x, load(block), k3k4);
        }
        // 128 bits to 64, then Barrett's reduction to 32.
        let x = _mm_xor_si128(_mm_clmulepi64_si128(x, k3k4, 0x10), _mm_srli_si128(x, 8));
        let low32 = _mm_set_epi32(0, 0, 0, -1);
        let x = _mm_xor_si128(
            _mm_clmulepi64_si128(_mm_and_si128(x, low32), _mm_set_epi64x(0, K5), 0x00),
            _mm_srli_si128(x, 4),
        );
        let pu = _mm_set_epi64x(U_PRIME, P_X);
        let t1 = _mm_clmulepi64_si128(_mm_and_si128(x, low32), pu, 0x10);
        let t2 = _mm_clmulepi64_si128(_mm_and_si128(t1, low32), pu, 0x00);
        let c = _mm_extract_epi32(_mm_xor_si128(x, t2), 1) as u32;
        // The last bytes (fewer than 16) through the tables, from the running value.
        let mut c = c;
        for &b in blocks.remainder() {
            c = super::TABLES[0][((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8);
        }
        !c
    }
}

#[cfg(test)]
mod tests {
    use super::crc32;

    /// Against the plain bit-by-bit definition, for every length up to 300 (every
    /// remainder of the eight-byte loop) and random bytes.
    #[test]
    fn matches_the_bitwise_definition() {
        let bitwise = |bytes: &[u8]| {
            let mut c = !0u32;
            for &b in bytes {
                c ^= u32::from(b);
                for _ in 0..8 {
                    c = if c & 1 != 0 {
                        (c >> 1) ^ 0xEDB8_8320
                    } else {
                        c >> 1
                    };
                }
            }
            !c
        };
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let data: Vec<u8> = (0..300)
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state as u8
            })
            .collect();
        for n in 0..=data.len() {
            assert_eq!(crc32(&data[..n]), bitwise(&data[..n]), "{n}");
            assert_eq!(super::crc32_tables(&data[..n]), bitwise(&data[..n]), "{n}");
        }
    }

    #[test]
    fn known_values() {
        // Published check values of CRC-32/ISO-HDLC.
        assert_eq!(crc32(b""), 0);
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(
            crc32(b"The quick brown fox jumps over the lazy dog"),
            0x414F_A339
        );
    }
}
