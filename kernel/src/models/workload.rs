//! Deterministic workloads of the raw evaluation benchmarks: point sets in structure-of-arrays
//! form (for `Program::eval_many`) and octree-like boxes (for `Program::interval_with`).

use super::SplitMix64;
use crate::Aabb;
use glam::DVec3;

/// Points as three coordinate arrays of equal length (single precision, as the batch evaluator
/// takes them).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Points {
    /// x coordinates.
    pub x: Vec<f32>,
    /// y coordinates.
    pub y: Vec<f32>,
    /// z coordinates.
    pub z: Vec<f32>,
}

impl Points {
    /// Number of points.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// True when there are no points.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }
}

/// The first `count` points of a regular `s³` lattice over `domain` (`s = ⌈∛count⌉`, cell
/// centres, x fastest): a spread of inside, outside and near-surface points.
pub fn lattice_points(domain: &Aabb, count: usize) -> Points {
    let s = (1..).find(|s: &usize| s.pow(3) >= count).unwrap_or(1);
    let step = domain.size() / s as f64;
    let mut p = Points {
        x: Vec::with_capacity(count),
        y: Vec::with_capacity(count),
        z: Vec::with_capacity(count),
    };
    for i in 0..count {
        let idx = DVec3::new((i % s) as f64, ((i / s) % s) as f64, (i / (s * s)) as f64);
        let q = domain.min + (idx + DVec3::splat(0.5)) * step;
        p.x.push(q.x as f32);
        p.y.push(q.y as f32);
        p.z.push(q.z as f32);
    }
    p
}

/// `count` octree cells of `domain`: each at a random level from 2 to 8 (side `size / 2^level`)
/// and a random position on that level's grid, drawn from `seed`.
pub fn octree_boxes(domain: &Aabb, count: usize, seed: u64) -> Vec<Aabb> {
    let mut rng = SplitMix64::new(seed);
    (0..count)
        .map(|_| {
            let level = 2 + (rng.next_u64() % 7) as u32;
            let cells = 1u64 << level;
            let side = domain.size() / cells as f64;
            let idx = DVec3::new(
                (rng.next_u64() % cells) as f64,
                (rng.next_u64() % cells) as f64,
                (rng.next_u64() % cells) as f64,
            );
            let min = domain.min + idx * side;
            Aabb::new(min, min + side)
        })
        .collect()
}
