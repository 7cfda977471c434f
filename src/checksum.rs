//! CRC-32 (IEEE 802.3, reflected, the one zlib's `crc32`, PNG and Ethernet use), for the
//! integrity of states the caller stores and restores. Not mathematics of rotations: a
//! storage format detail, here so that the C boundary only calls it.

/// The byte-wise lookup table, built at compile time (1 KiB of read-only data).
const TABLE: [u32; 256] = {
    let mut table = [0u32; 256];
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
        table[i] = c;
        i += 1;
    }
    table
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
    for &b in bytes {
        c = TABLE[((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8);
    }
    !c
}

#[cfg(test)]
mod tests {
    use super::crc32;

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
