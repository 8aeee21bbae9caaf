//! Parallel welding of `f32` corners (binary STL): the same vertex array and indices as the
//! serial [`Welder`](super::weld::Welder) — bit-identical positions merged (`-0.0` as `0.0`),
//! vertices numbered in first-seen order — for any thread count.
//!
//! Corners are split by a hash of their position into [`SHARDS`] shards, each small enough for
//! its hash map to stay in cache; within a shard, corners are visited in file order, so each
//! finds the first corner at its position (a shard writes only its own corners' entries, through
//! relaxed atomics: no ordering is needed, the parallel loop's end synchronises). One serial pass
//! then numbers the first corners in file order.

use glam::DVec3;
use rayon::prelude::*;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU32, Ordering};

use super::key_hash::{KeyHash, fold};

/// Number of shards (a power of two).
const SHARDS: usize = 256;

/// Multipliers of the shard hash (different from the maps' own, so a shard's keys still spread
/// over its map).
const SHARD_K: [u64; 2] = [0x9e37_79b9_7f4a_7c15, 0xa409_3822_299f_31d0];

/// The key of a position: its bits, `-0.0` as `0.0`.
fn key(p: [f32; 3]) -> u128 {
    let bits = p.map(|c| if c == 0.0 { 0 } else { c.to_bits() });
    u128::from(bits[0]) | u128::from(bits[1]) << 32 | u128::from(bits[2]) << 64
}

/// The welded positions and the vertex index of every corner; `None` when there are more than
/// 2³² distinct positions.
///
/// Memory: besides the result, one byte and two `u32` per corner (the keys are recomputed from
/// the corners rather than stored: on a large file every temporary array costs its page faults).
pub(super) fn weld(corners: &[[f32; 3]]) -> Option<(Vec<DVec3>, Vec<u32>)> {
    let n = corners.len();
    let shard_of = |c: usize| (fold(key(corners[c]), SHARD_K) >> 56) as usize % SHARDS;
    // Counting sort of the corners by shard, file order kept within each.
    let shards: Vec<u8> = (0..n).into_par_iter().map(|c| shard_of(c) as u8).collect();
    let mut starts = vec![0usize; SHARDS + 1];
    for &s in &shards {
        starts[usize::from(s) + 1] += 1;
    }
    for s in 0..SHARDS {
        starts[s + 1] += starts[s];
    }
    let mut fill = starts.clone();
    let mut by_shard = vec![0u32; n];
    for (c, &s) in shards.iter().enumerate() {
        let at = &mut fill[usize::from(s)];
        by_shard[*at] = c as u32;
        *at += 1;
    }
    drop(shards);
    // The first corner at each corner's position (each corner is written by its shard only).
    let first_of: Vec<AtomicU32> = (0..n).into_par_iter().map(|_| AtomicU32::new(0)).collect();
    (0..SHARDS).into_par_iter().for_each(|s| {
        let members = &by_shard[starts[s]..starts[s + 1]];
        let mut seen: HashMap<u128, u32, KeyHash> =
            HashMap::with_capacity_and_hasher(members.len(), KeyHash::default());
        for &c in members {
            let f = *seen.entry(key(corners[c as usize])).or_insert(c);
            first_of[c as usize].store(f, Ordering::Relaxed);
        }
    });
    drop(by_shard);
    // Number the first corners in file order.
    let mut index = vec![0u32; n];
    let mut positions = Vec::new();
    for c in 0..n {
        let f = first_of[c].load(Ordering::Relaxed) as usize;
        if f == c {
            index[c] = u32::try_from(positions.len()).ok()?;
            positions.push(DVec3::from_array(corners[c].map(f64::from)));
        } else {
            index[c] = index[f];
        }
    }
    Some((positions, index))
}

#[cfg(test)]
mod tests {
    use super::super::weld::Welder;
    use super::*;

    #[test]
    fn matches_the_serial_welder() {
        // A small lattice of positions visited in a scrambled order, with signed zeros.
        let mut corners = Vec::new();
        let mut state = 12345u64;
        for _ in 0..20_000 {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let pick = |shift: u32| ((state >> shift) % 7) as f32 - 3.0;
            let mut p = [pick(10), pick(20), pick(30)];
            if state >> 60 == 0 {
                p[0] = -0.0;
            }
            corners.push(p);
        }
        let (positions, index) = weld(&corners).unwrap();
        let mut welder = Welder::default();
        let serial: Vec<u32> = corners
            .iter()
            .map(|p| welder.index(DVec3::from_array(p.map(f64::from))).unwrap())
            .collect();
        assert_eq!(index, serial);
        assert_eq!(positions, welder.into_positions());
        assert!(positions.len() < 7 * 7 * 7 + 1);
    }
}
