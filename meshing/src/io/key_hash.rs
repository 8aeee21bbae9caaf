//! A fast hasher for bit-pattern keys of vertex positions (the welders' hash maps): a folded
//! 64 × 64 → 128-bit multiply, far cheaper than the default SipHash. The keys come from files,
//! but a collision only costs time, and the multiply mixes every input bit into both halves, so
//! crafted inputs gain little over random ones.

use std::hash::{BuildHasherDefault, Hasher};

/// Build hasher of [`KeyHasher`].
pub(crate) type KeyHash = BuildHasherDefault<KeyHasher>;

/// Mixes 128 bits of key into 64 bits of hash with a multiplier pair `k`.
pub(super) fn fold(n: u128, k: [u64; 2]) -> u64 {
    let (lo, hi) = (n as u64 ^ k[0], (n >> 64) as u64 ^ k[1]);
    let m = u128::from(lo) * u128::from(hi);
    m as u64 ^ (m >> 64) as u64
}

/// The hasher's constants (digits of π).
const K: [u64; 2] = [0x243f_6a88_85a3_08d3, 0x1319_8a2e_0370_7344];

/// The hasher; see the [module docs](self).
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(16) {
            let mut word = [0u8; 16];
            word[..chunk.len()].copy_from_slice(chunk);
            self.write_u128(u128::from_le_bytes(word));
        }
    }

    fn write_u64(&mut self, n: u64) {
        self.write_u128(u128::from(n));
    }

    fn write_u128(&mut self, n: u128) {
        self.0 = fold(n ^ u128::from(self.0), K);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::hash::BuildHasher;

    #[test]
    fn nearby_keys_spread_over_buckets() {
        let build = KeyHash::default();
        let mut low_bits = std::collections::HashSet::new();
        for i in 0..1024u128 {
            low_bits.insert(build.hash_one(i << 64 | 0x3f80_0000) & 1023);
        }
        // 1024 keys into 1024 buckets: a random map fills about 63 % of them.
        assert!(low_bits.len() > 500, "{}", low_bits.len());
    }
}
