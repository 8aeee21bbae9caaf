//! Whether a set of faces is a 2-cycle: every directed edge `a → b` is matched by as many
//! `b → a` (closed and consistently oriented, non-manifold edges allowed). On a cycle the
//! generalised winding number is an integer everywhere off the surface, equal to the signed
//! count of crossings of any ray from the point, so the nesting test may cast a ray instead of
//! summing solid angles (`rays.rs`).
//!
//! The test is a linear sketch: each directed edge adds `h(a, b) − h(b, a)` (wrapping, for two
//! independent 64-bit mixes `h`), so matched edges cancel exactly and a cycle sums to zero in any
//! order (deterministic in parallel). An unmatched edge leaves a non-zero sum unless the mixes
//! of the unmatched edges cancel by chance (probability about 2⁻¹²⁸).

use rayon::prelude::*;

/// The two mixes' seeds (digits of e).
const SEEDS: [u64; 2] = [0x2b7e_1516_28ae_d2a6, 0xabf7_1588_09cf_4f3c];

/// splitmix64's finaliser of `x ^ seed`.
fn mix(x: u64, seed: u64) -> u64 {
    let mut z = x ^ seed;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The sketch of one face: its three directed edges minus their reverses.
fn face_sketch(t: [u32; 3]) -> [u64; 2] {
    let mut s = [0u64; 2];
    for k in 0..3 {
        let (a, b) = (u64::from(t[k]), u64::from(t[(k + 1) % 3]));
        for (sum, &seed) in s.iter_mut().zip(&SEEDS) {
            *sum = sum
                .wrapping_add(mix(a << 32 | b, seed))
                .wrapping_sub(mix(b << 32 | a, seed));
        }
    }
    s
}

/// True when `faces` of `tris` form a 2-cycle (see the [module docs](self)); an empty set is
/// one.
pub(super) fn is_cycle(tris: &[[u32; 3]], faces: &[usize]) -> bool {
    let add = |x: [u64; 2], y: [u64; 2]| [x[0].wrapping_add(y[0]), x[1].wrapping_add(y[1])];
    faces
        .par_iter()
        .with_min_len(1 << 12)
        .map(|&f| face_sketch(tris[f]))
        .reduce(|| [0, 0], add)
        == [0, 0]
}

#[cfg(test)]
mod tests {
    use super::is_cycle;

    /// A tetrahedron wound outward.
    const TETRA: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];

    #[test]
    fn closed_oriented_sets_are_cycles_and_others_are_not() {
        let all: Vec<usize> = (0..4).collect();
        assert!(is_cycle(&TETRA, &all));
        assert!(is_cycle(&TETRA, &[]));
        // A hole, a flipped face, a doubled face.
        assert!(!is_cycle(&TETRA, &all[..3]));
        let mut flipped = TETRA;
        flipped[2].swap(1, 2);
        assert!(!is_cycle(&flipped, &all));
        let doubled = [TETRA[0], TETRA[1], TETRA[2], TETRA[3], TETRA[3]];
        assert!(!is_cycle(&doubled, &[0, 1, 2, 3, 4]));
        // A face and its reverse cancel: still a cycle (the winding number is unchanged).
        let cancelled = [TETRA[0], TETRA[1], TETRA[2], TETRA[3], [5, 6, 7], [5, 7, 6]];
        assert!(is_cycle(&cancelled, &[0, 1, 2, 3, 4, 5]));
    }
}
