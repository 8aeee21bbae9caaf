//! Parallel decoding and welding of binary STL records: the same vertex array and indices as the
//! serial reader's [`Welder`](super::weld::Welder) — bit-identical positions merged (`-0.0` as
//! `0.0`), vertices numbered in first-seen order — for any thread count.
//!
//! Every step reads memory in order; none looks a corner up at random in a file-sized array (on a
//! 1.8 M-triangle file those cache misses were most of the reader's time):
//! 1. chunks of records (in parallel) decode their corners and file them by a hash of the
//!    position into [`SHARDS`] shards, within the chunk (a counting sort): one 16-byte entry per
//!    corner, its position's bits and its corner number;
//! 2. each shard (in parallel) visits its entries chunk by chunk, so in file order, and gives
//!    each the shard's number of its position (a hash map small enough for the cache), marking
//!    the corner that first has each position in a bit set;
//! 3. the marked corners, ascending, are the vertices: a vertex's number is its first corner's
//!    rank in the bit set;
//! 4. each chunk (in parallel) writes its own corners' vertex numbers, from its entries.

use glam::DVec3;
use rayon::prelude::*;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};

use super::key_hash::{KeyHash, fold};

/// Number of shards.
const SHARDS: usize = 256;

/// Records per chunk (a chunk's bytes and entries stay in the cache between its passes).
const CHUNK: usize = 1 << 12;

/// Size of one binary STL triangle record: normal, three corners, attribute (the reader and
/// the writer use it too).
pub(super) const RECORD_LEN: u64 = 50;
/// [`RECORD_LEN`] as an index step.
const RECORD: usize = RECORD_LEN as usize;

/// Multipliers of the shard hash (different from the maps' own, so a shard's keys still spread
/// over its map).
const SHARD_K: [u64; 2] = [0x9e37_79b9_7f4a_7c15, 0xa409_3822_299f_31d0];

/// One corner filed under its shard: its position's bits (`-0.0` as `0.0`) and its number (an
/// array, so that a vector of them starts as zeroed pages rather than written ones).
type Entry = [u32; 4];

/// The position's bits of an entry.
fn key(e: &Entry) -> [u32; 3] {
    [e[0], e[1], e[2]]
}

/// The bits of corner `k` (0 to 2) of `record`, `-0.0` as `0.0`.
fn corner_bits(record: &[u8], k: usize) -> [u32; 3] {
    let at = 12 + 12 * k;
    [0, 4, 8].map(|d| {
        let b = &record[at + d..at + d + 4];
        let bits = u32::from_le_bytes([b[0], b[1], b[2], b[3]]);
        if bits == 0x8000_0000 { 0 } else { bits }
    })
}

/// The key of a position's bits for hashing.
fn wide(key: [u32; 3]) -> u128 {
    u128::from(key[0]) | u128::from(key[1]) << 32 | u128::from(key[2]) << 64
}

/// The shard of a position's bits.
fn shard_of(key: [u32; 3]) -> usize {
    (fold(wide(key), SHARD_K) >> 56) as usize % SHARDS
}

/// True when the bits are a finite `f32`.
fn finite(bits: u32) -> bool {
    bits & 0x7f80_0000 != 0x7f80_0000
}

/// The welded positions and the triangles of the binary STL records `body` (a whole number of
/// 50-byte records); `None` when a coordinate is not finite or there are more corners than
/// 32-bit numbers address (the serial reader then names the problem).
///
/// Memory: besides the result, 16 bytes and one `u32` per corner, and one bit.
pub(super) fn weld_records(body: &[u8]) -> Option<(Vec<DVec3>, Vec<[u32; 3]>)> {
    let count = body.len() / RECORD;
    let corners = 3 * count;
    u32::try_from(corners).ok()?;
    // 1. Each chunk's corners by shard, with where each shard's run starts in the chunk.
    let mut entries = vec![[0u32; 4]; corners];
    let starts: Vec<[u32; SHARDS + 1]> = entries
        .par_chunks_mut(3 * CHUNK)
        .zip(body.par_chunks(RECORD * CHUNK))
        .enumerate()
        .map(|(chunk, (out, bytes))| file_chunk(chunk, bytes, out))
        .collect::<Option<_>>()?;
    // 2. Each shard's number of every entry's position, in chunk order, and its first corners.
    let seen: Vec<AtomicU64> = (0..corners.div_ceil(64))
        .map(|_| AtomicU64::new(0))
        .collect();
    let mut shards: Vec<(Vec<u32>, Vec<u32>)> = (0..SHARDS)
        .into_par_iter()
        .map(|s| number_shard(s, &entries, &starts, &seen))
        .collect();
    // 3. The vertices: the first corners in file order, ranked through the bit set.
    let seen: Vec<u64> = seen.into_iter().map(AtomicU64::into_inner).collect();
    let mut ranks = Vec::with_capacity(seen.len());
    let mut total = 0u32;
    for word in &seen {
        ranks.push(total);
        total += word.count_ones();
    }
    let rank = |c: u32| {
        let (w, b) = ((c / 64) as usize, c % 64);
        ranks[w] + (seen[w] & ((1u64 << b) - 1)).count_ones()
    };
    let positions: Vec<DVec3> = seen
        .par_iter()
        .enumerate()
        .flat_map_iter(|(w, &word)| {
            BitIter(word).map(move |b| {
                let c = w * 64 + b;
                let record = &body[RECORD * (c / 3)..RECORD * (c / 3 + 1)];
                DVec3::from_array(corner_bits(record, c % 3).map(|x| f64::from(f32::from_bits(x))))
            })
        })
        .collect();
    shards.par_iter_mut().for_each(|(numbers, firsts)| {
        let global: Vec<u32> = firsts.iter().map(|&c| rank(c)).collect();
        for n in numbers.iter_mut() {
            *n = global[*n as usize];
        }
    });
    // 4. Every corner's vertex, chunk by chunk.
    let mut triangles = vec![[0u32; 3]; count];
    let mut cursors: Vec<[u32; SHARDS]> = Vec::with_capacity(starts.len());
    let mut cursor = [0u32; SHARDS];
    for chunk in &starts {
        cursors.push(cursor);
        for s in 0..SHARDS {
            cursor[s] += chunk[s + 1] - chunk[s];
        }
    }
    triangles
        .as_flattened_mut()
        .par_chunks_mut(3 * CHUNK)
        .zip(entries.par_chunks(3 * CHUNK))
        .zip(starts.par_iter().zip(&cursors))
        .enumerate()
        .for_each(|(chunk, ((out, entries), (starts, cursor)))| {
            let first = (3 * CHUNK * chunk) as u32;
            for (s, (numbers, _)) in shards.iter().enumerate() {
                let run = &entries[starts[s] as usize..starts[s + 1] as usize];
                let numbers = &numbers[cursor[s] as usize..];
                for (e, &n) in run.iter().zip(numbers) {
                    out[(e[3] - first) as usize] = n;
                }
            }
        });
    Some((positions, triangles))
}

/// Files the corners of chunk `chunk` (its record `bytes`) into `out` by shard, each shard's
/// in file order; returns where each shard's run starts (and the end). `None` when a coordinate
/// is not finite.
fn file_chunk(chunk: usize, bytes: &[u8], out: &mut [Entry]) -> Option<[u32; SHARDS + 1]> {
    let mut shard = vec![0u8; out.len()];
    let mut starts = [0u32; SHARDS + 1];
    let mut finite_all = true;
    for (r, record) in bytes.chunks_exact(RECORD).enumerate() {
        for k in 0..3 {
            let key = corner_bits(record, k);
            finite_all &= key.iter().all(|&b| finite(b));
            let s = shard_of(key);
            shard[3 * r + k] = s as u8;
            starts[s + 1] += 1;
        }
    }
    if !finite_all {
        return None;
    }
    for s in 0..SHARDS {
        starts[s + 1] += starts[s];
    }
    let mut fill = starts;
    let first = 3 * CHUNK * chunk;
    for (r, record) in bytes.chunks_exact(RECORD).enumerate() {
        for k in 0..3 {
            let at = &mut fill[usize::from(shard[3 * r + k])];
            let [x, y, z] = corner_bits(record, k);
            out[*at as usize] = [x, y, z, (first + 3 * r + k) as u32];
            *at += 1;
        }
    }
    Some(starts)
}

/// The shard's number of every entry of shard `s` (chunk by chunk, so in file order) and the
/// first corner of each number, which it marks in `seen`.
fn number_shard(
    s: usize,
    entries: &[Entry],
    starts: &[[u32; SHARDS + 1]],
    seen: &[AtomicU64],
) -> (Vec<u32>, Vec<u32>) {
    let total: usize = starts.iter().map(|c| (c[s + 1] - c[s]) as usize).sum();
    let mut numbers = Vec::with_capacity(total);
    let mut firsts = Vec::new();
    let mut map: HashMap<u128, u32, KeyHash> =
        HashMap::with_capacity_and_hasher(total / 4, KeyHash::default());
    for (chunk, at) in entries.chunks(3 * CHUNK).zip(starts) {
        for e in &chunk[at[s] as usize..at[s + 1] as usize] {
            let next = firsts.len() as u32;
            let n = *map.entry(wide(key(e))).or_insert(next);
            if n == next {
                let corner = e[3];
                firsts.push(corner);
                seen[(corner / 64) as usize].fetch_or(1 << (corner % 64), Ordering::Relaxed);
            }
            numbers.push(n);
        }
    }
    (numbers, firsts)
}

/// The set bits of a word, ascending.
struct BitIter(u64);

impl Iterator for BitIter {
    type Item = usize;

    fn next(&mut self) -> Option<usize> {
        (self.0 != 0).then(|| {
            let b = self.0.trailing_zeros() as usize;
            self.0 &= self.0 - 1;
            b
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::weld::Welder;
    use super::*;

    /// Binary STL records (zero normals and attributes) of `corners`, three per record.
    fn records(corners: &[[f32; 3]]) -> Vec<u8> {
        let mut bytes = Vec::new();
        for tri in corners.chunks_exact(3) {
            bytes.extend_from_slice(&[0u8; 12]);
            for c in tri {
                for x in c {
                    bytes.extend_from_slice(&x.to_le_bytes());
                }
            }
            bytes.extend_from_slice(&[0u8; 2]);
        }
        bytes
    }

    /// A small lattice of positions visited in a scrambled order, with signed zeros, over several
    /// chunks: the serial welder's vertices and indices, on one thread and on three.
    #[test]
    fn matches_the_serial_welder() {
        let mut corners = Vec::new();
        let mut state = 12345u64;
        for _ in 0..3 * (2 * CHUNK + 77) {
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
        let bytes = records(&corners);
        let mut welder = Welder::default();
        let serial: Vec<u32> = corners
            .iter()
            .map(|p| welder.index(DVec3::from_array(p.map(f64::from))).unwrap())
            .collect();
        let serial_positions = welder.into_positions();
        for threads in [1, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let (positions, triangles) = pool.install(|| weld_records(&bytes)).unwrap();
            assert_eq!(triangles.as_flattened(), serial.as_slice());
            assert_eq!(positions, serial_positions);
        }
        assert!(serial_positions.len() < 7 * 7 * 7 + 1);
    }

    /// Every corner distinct (a soup), and a non-finite coordinate anywhere, declined.
    #[test]
    fn distinct_corners_and_non_finite_coordinates() {
        let corners: Vec<[f32; 3]> = (0..3 * (CHUNK + 5))
            .map(|i| [i as f32, 0.5 * i as f32, -(i as f32)])
            .collect();
        let (positions, triangles) = weld_records(&records(&corners)).unwrap();
        assert_eq!(positions.len(), corners.len());
        assert!(
            triangles
                .as_flattened()
                .iter()
                .enumerate()
                .all(|(i, &v)| v as usize == i)
        );
        for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            let mut broken = corners.clone();
            broken[3 * CHUNK + 4][1] = bad;
            assert!(weld_records(&records(&broken)).is_none());
        }
    }
}
