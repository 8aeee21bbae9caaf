//! Distances between surfaces: one-sided distances from a point set to a mesh, and the symmetric
//! Hausdorff distance between two meshes estimated on sample points.
//!
//! The Hausdorff distance of meshes `A` and `B` is `max(h(A, B), h(B, A))` with
//! `h(A, B) = max over points a of A of dist(a, B)`. Here `a` runs over the [`SurfaceSamples`] of
//! `A` (all its vertices and area-weighted points), and `dist(a, B)` is exact (the nearest point
//! of `B` through its [`TriangleTree`]), so the estimate never exceeds the true value and
//! converges to it as samples grow. Means are over the area samples (an estimate of the mean
//! distance over the surface), or over the vertices when there are none.
//!
//! Sums run over fixed-size chunks combined in order, so results do not depend on the thread count.

use glam::DVec3;
use rayon::prelude::*;

use super::tree::TriangleTree;
use super::{MeasureError, SurfaceSamples};
use crate::IndexedMesh;

/// Points per parallel work item.
const CHUNK: usize = 1 << 12;

/// Distances from a set of points to a mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OneSided {
    /// The largest distance (0 for no points).
    pub max: f64,
    /// The mean distance (0 for no points).
    pub mean: f64,
    /// Number of points measured.
    pub count: usize,
    /// The point with the largest distance (the origin for no points).
    pub farthest: DVec3,
}

/// The symmetric Hausdorff distance of two meshes and its one-sided parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hausdorff {
    /// `max(a_to_b.max, b_to_a.max)`.
    pub symmetric: f64,
    /// From samples of the first mesh to the second.
    pub a_to_b: OneSided,
    /// From samples of the second mesh to the first.
    pub b_to_a: OneSided,
}

/// The distances from `points` to the mesh of `tree`.
pub fn one_sided(points: &[DVec3], tree: &TriangleTree) -> OneSided {
    let partials: Vec<(f64, f64, DVec3)> = points
        .par_chunks(CHUNK)
        .map(|chunk| {
            let mut sum = 0.0;
            let (mut max, mut farthest) = (f64::NEG_INFINITY, DVec3::ZERO);
            for &p in chunk {
                let d = tree.nearest(p).distance;
                sum += d;
                if d > max {
                    (max, farthest) = (d, p);
                }
            }
            (sum, max, farthest)
        })
        .collect();
    let (mut sum, mut max, mut farthest) = (0.0, 0.0, DVec3::ZERO);
    for (s, m, f) in partials {
        sum += s;
        if m > max {
            (max, farthest) = (m, f);
        }
    }
    let count = points.len();
    OneSided {
        max,
        mean: if count > 0 { sum / count as f64 } else { 0.0 },
        count,
        farthest,
    }
}

/// The one-sided distance from the surface samples to `tree`: max over all points, mean over the
/// area samples (the vertices when there are none).
pub fn samples_to_mesh(samples: &SurfaceSamples, tree: &TriangleTree) -> OneSided {
    let vertices = one_sided(&samples.vertices, tree);
    if samples.area.is_empty() {
        return vertices;
    }
    let area = one_sided(&samples.area, tree);
    let (max, farthest) = if vertices.max > area.max {
        (vertices.max, vertices.farthest)
    } else {
        (area.max, area.farthest)
    };
    OneSided {
        max,
        mean: area.mean,
        count: samples.len(),
        farthest,
    }
}

/// The Hausdorff distance of `a` and `b`, each sampled with its vertices and `samples`
/// area-weighted points. Fails when either has no usable triangle or a non-finite vertex.
pub fn hausdorff(
    a: &IndexedMesh,
    b: &IndexedMesh,
    samples: usize,
) -> Result<Hausdorff, MeasureError> {
    let (tree_a, tree_b) = rayon::join(|| TriangleTree::new(a), || TriangleTree::new(b));
    Ok(hausdorff_with(a, &tree_a?, b, &tree_b?, samples))
}

/// [`hausdorff`] with the meshes' trees already built (`tree_a` of `a`, `tree_b` of `b`).
pub fn hausdorff_with(
    a: &IndexedMesh,
    tree_a: &TriangleTree,
    b: &IndexedMesh,
    tree_b: &TriangleTree,
    samples: usize,
) -> Hausdorff {
    let (samples_a, samples_b) = rayon::join(
        || SurfaceSamples::of(a, samples),
        || SurfaceSamples::of(b, samples),
    );
    let a_to_b = samples_to_mesh(&samples_a, tree_b);
    let b_to_a = samples_to_mesh(&samples_b, tree_a);
    Hausdorff {
        symmetric: a_to_b.max.max(b_to_a.max),
        a_to_b,
        b_to_a,
    }
}
