//! A stable 64-bit hash for fingerprints and checksums of files rolldyn writes.

/// 64-bit FNV-1a hash of `bytes` (Fowler–Noll–Vo, offset basis 0xcbf29ce484222325, prime
/// 0x100000001b3): stable across platforms and versions, and any one changed byte changes it.
/// Not cryptographic: it detects damage and changed inputs, not tampering.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf29ce484222325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x100000001b3)
    })
}

#[cfg(test)]
mod tests {
    use super::fnv1a;

    /// Reference values of the FNV-1a 64 test suite (empty input, "a", "foobar").
    #[test]
    fn reference_values() {
        assert_eq!(fnv1a(b""), 0xcbf29ce484222325);
        assert_eq!(fnv1a(b"a"), 0xaf63dc4c8601ec8c);
        assert_eq!(fnv1a(b"foobar"), 0x85944171f73967e8);
    }
}
