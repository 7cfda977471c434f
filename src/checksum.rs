//! CRC-32 (IEEE 802.3, reflected, the one zlib's `crc32`, PNG and Ethernet use), for the
//! integrity of states the caller stores and restores. Not mathematics of rotations: a
//! storage format detail, here so that the C boundary only calls it.

/// The lookup tables of slicing-by-8, built at compile time (8 KiB of read-only data):
/// `TABLES[0]` is the byte-wise table, `TABLES[k][b]` the CRC of byte `b` followed by `k`
/// zero bytes. Eight independent lookups per eight bytes replace eight dependent ones: the
/// byte-wise loop is bound by the latency of its chain (about 7 cycles a byte, 1.2 µs for
/// the two checksums of a CYCLE600 call), this one by throughput.
const TABLES: [[u32; 256]; 8] = {
    let mut t = [[0u32; 256]; 8];
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
    while s < 8 {
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
    let mut c = !0u32;
    let mut chunks = bytes.chunks_exact(8);
    for chunk in &mut chunks {
        let mut w = [0u8; 8];
        w.copy_from_slice(chunk);
        let lo = u32::from_le_bytes([w[0], w[1], w[2], w[3]]) ^ c;
        let hi = u32::from_le_bytes([w[4], w[5], w[6], w[7]]);
        let b = |x: u32, shift: u32| ((x >> shift) & 0xff) as usize;
        c = TABLES[7][b(lo, 0)]
            ^ TABLES[6][b(lo, 8)]
            ^ TABLES[5][b(lo, 16)]
            ^ TABLES[4][b(lo, 24)]
            ^ TABLES[3][b(hi, 0)]
            ^ TABLES[2][b(hi, 8)]
            ^ TABLES[1][b(hi, 16)]
            ^ TABLES[0][b(hi, 24)];
    }
    for &b in chunks.remainder() {
        c = TABLES[0][((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8);
    }
    !c
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
