//! Volumes by sampling the exact field, with a standard error: jittered stratified sampling over
//! `n³` equal strata of a box, where strata the field's interval bound shows to be wholly inside
//! or outside are counted exactly and only the others (those the surface may cross) get one
//! uniform random point each, repeated over independent replicates.
//!
//! Each replicate gives an unbiased estimate `V_r = cell · (inside strata + inside points_r)`;
//! the result is their mean and the standard error `sd(V_r) / √R`. Only strata the surface
//! crosses vary, so `σ ≈ h² √(0.15 A / R)` for a surface of area `A` and strata of side `h`.
//! Strata are classified level by level (8³ boxes split in eight until they reach the strata
//! size; no recursion), with the program's conservative double-precision intervals.
//!
//! A point is inside when the double-precision field value is negative (an exact zero counts as
//! outside, as in the mesher). Classification and replicates run in parallel; results are
//! gathered in a fixed order and counts are integers, so the result is the same on every run
//! and thread count.

use glam::DVec3;
use rayon::prelude::*;
use serde::Serialize;
use solidkit_kernel::models::SplitMix64;
use solidkit_kernel::program::IntervalScratch;
use solidkit_kernel::{Aabb, Program};

/// Boxes per axis of the first classification level.
const BASE: usize = 8;
/// Strata per axis of the suites' sampling (a multiple of 8 by a power of two).
pub const STRATA: usize = 128;
/// Replicates of the suites' sampling.
pub const REPLICATES: usize = 16;

/// A sampled volume.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SampledVolume {
    /// Mean of the replicates.
    pub volume: f64,
    /// Standard error of the mean.
    pub standard_error: f64,
    /// Field values computed in all (points over all replicates).
    pub points: u64,
    /// Strata per axis.
    pub strata: usize,
    /// Strata the intervals could not classify (sampled in every replicate).
    pub sampled_strata: u64,
    /// Independent replicates.
    pub replicates: usize,
}

/// Strata wholly inside, and the ones to sample (as integer stratum coordinates).
struct Classified {
    inside: u64,
    ambiguous: Vec<[u32; 3]>,
}

/// Classifies the strata of `bounds` (`strata` per axis, `BASE · 2^k`).
fn classify(program: &Program, bounds: &Aabb, strata: usize) -> Classified {
    let levels = (strata / BASE).trailing_zeros();
    let stratum = bounds.size() / strata as f64;
    let mut inside = 0u64;
    // Boxes of the current level as (lowest stratum, strata per side).
    let side0 = (strata / BASE) as u32;
    let mut boxes: Vec<[u32; 3]> = Vec::with_capacity(BASE * BASE * BASE);
    for k in 0..BASE as u32 {
        for j in 0..BASE as u32 {
            for i in 0..BASE as u32 {
                boxes.push([i * side0, j * side0, k * side0]);
            }
        }
    }
    for level in 0..=levels {
        let side = side0 >> level;
        let split = level < levels;
        let results: Vec<(u64, Vec<[u32; 3]>)> = boxes
            .par_chunks(256)
            .map_init(IntervalScratch::default, |scratch, chunk| {
                let mut inside = 0u64;
                let mut next = Vec::new();
                for &b in chunk {
                    let lo =
                        bounds.min + DVec3::new(b[0] as f64, b[1] as f64, b[2] as f64) * stratum;
                    let hi = lo + stratum * side as f64;
                    let range = program.interval_with(&Aabb::new(lo, hi), scratch);
                    if range.hi < 0.0 {
                        inside += u64::from(side).pow(3);
                    } else if range.lo >= 0.0 {
                        // Wholly outside.
                    } else if split {
                        let h = side / 2;
                        for dz in [0, h] {
                            for dy in [0, h] {
                                for dx in [0, h] {
                                    next.push([b[0] + dx, b[1] + dy, b[2] + dz]);
                                }
                            }
                        }
                    } else {
                        next.push(b);
                    }
                }
                (inside, next)
            })
            .collect();
        boxes = Vec::new();
        for (n, next) in results {
            inside += n;
            boxes.extend(next);
        }
    }
    Classified {
        inside,
        ambiguous: boxes,
    }
}

/// The volume of `{program < 0}` inside `bounds` (see the module docs): `strata` per axis
/// (rounded up to `8 · 2^k`), `replicates ≥ 2`, streams picked by `seed`.
pub fn sample_volume(
    program: &Program,
    bounds: &Aabb,
    strata: usize,
    replicates: usize,
    seed: u64,
) -> SampledVolume {
    let n = (strata.max(BASE) / BASE).next_power_of_two() * BASE;
    let classified = classify(program, bounds, n);
    let stratum = bounds.size() / n as f64;
    let cell = stratum.x * stratum.y * stratum.z;
    let counts: Vec<u64> = (0..replicates)
        .into_par_iter()
        .map(|r| {
            let mut rng =
                SplitMix64::new(seed ^ (r as u64 + 1).wrapping_mul(0xA24B_AED4_963E_E407));
            let mut slots = Vec::new();
            let mut hits = 0u64;
            for s in &classified.ambiguous {
                let jitter = DVec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64());
                let at = DVec3::new(s[0] as f64, s[1] as f64, s[2] as f64) + jitter;
                if program.value_with(bounds.min + at * stratum, &mut slots) < 0.0 {
                    hits += 1;
                }
            }
            hits
        })
        .collect();
    let estimates: Vec<f64> = counts
        .iter()
        .map(|&c| cell * (classified.inside + c) as f64)
        .collect();
    let r = estimates.len() as f64;
    let mean = estimates.iter().sum::<f64>() / r;
    let variance = estimates.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (r - 1.0).max(1.0);
    let sampled = classified.ambiguous.len() as u64;
    SampledVolume {
        volume: mean,
        standard_error: (variance / r).sqrt(),
        points: sampled * replicates as u64,
        strata: n,
        sampled_strata: sampled,
        replicates,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use solidkit_kernel::Solid;

    #[test]
    fn sphere_volume_within_its_standard_error() {
        let program = Solid::sphere(0.8).compile();
        let bounds = Aabb::centered(DVec3::ONE);
        let s = sample_volume(&program, &bounds, 64, 16, 3);
        let exact = 4.0 / 3.0 * std::f64::consts::PI * 0.512;
        assert!(
            s.standard_error > 0.0 && s.standard_error < 2e-4 * exact,
            "{s:?}"
        );
        assert!(
            (s.volume - exact).abs() < 4.0 * s.standard_error,
            "{s:?} vs {exact}"
        );
        // Only strata near the sphere are sampled: far fewer than all 64³.
        assert!(s.sampled_strata < 64 * 64 * 64 / 8, "{s:?}");
        assert_eq!(
            s,
            sample_volume(&program, &bounds, 64, 16, 3),
            "deterministic"
        );
        assert_ne!(s.volume, sample_volume(&program, &bounds, 64, 16, 4).volume);
    }

    #[test]
    fn a_box_filling_whole_strata_is_exact() {
        // The box [-0.5, 0.5]³ in [-1, 1]³ with 16 strata: every stratum is wholly inside or
        // outside except those its faces pass through, and those are on the boundary.
        let program = Solid::cube(1.0).compile();
        let bounds = Aabb::centered(DVec3::ONE);
        let s = sample_volume(&program, &bounds, 16, 4, 1);
        assert!((s.volume - 1.0).abs() < 1e-12, "{s:?}");
    }
}
