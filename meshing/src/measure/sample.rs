//! Deterministic sample points of a mesh's surface: every vertex used by a usable triangle, plus a
//! requested number of area-weighted points.
//!
//! The area-weighted points are stratified: point `k` of `n` takes the triangle where the running
//! area crosses `(k + u_k) / n` of the total (`u_k` uniform in `[0, 1)`), so every triangle gets
//! about its share, and then a uniform point inside that triangle. The random numbers come from a
//! counter-based generator seeded per point, so the samples are the same on every run and thread
//! count. Vertices are kept apart from the area samples: they are where the largest distances of
//! a polyhedral surface usually are, but they are not an unbiased sample of the area (means use
//! the area samples only).

use glam::DVec3;
use rayon::prelude::*;

use super::rng::Rng;
use crate::IndexedMesh;
use crate::usable::is_usable;

/// Seed of the area samples' random stream.
const SEED: u64 = 0x5EED_0F5A_3FAC_E5E5;

/// Sample points of a surface; see the [`crate::measure`] docs.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SurfaceSamples {
    /// Every vertex used by a usable triangle, in index order.
    pub vertices: Vec<DVec3>,
    /// Area-weighted points (empty when the surface has zero area).
    pub area: Vec<DVec3>,
}

impl SurfaceSamples {
    /// The samples of `mesh`: its used vertices and `count` area-weighted points.
    pub fn of(mesh: &IndexedMesh, count: usize) -> Self {
        let n = mesh.positions.len();
        let usable: Vec<[u32; 3]> = mesh
            .triangles
            .iter()
            .filter(|t| is_usable(t, n))
            .copied()
            .collect();
        let mut used = vec![false; n];
        for t in &usable {
            for &i in t {
                used[i as usize] = true;
            }
        }
        let vertices = (0..n)
            .filter(|&v| used[v])
            .map(|v| mesh.positions[v])
            .collect();
        let corners = |t: &[u32; 3]| t.map(|i| mesh.positions[i as usize]);
        // Running area after each triangle.
        let mut cumulative = Vec::with_capacity(usable.len());
        let mut total = 0.0;
        for t in &usable {
            let [a, b, c] = corners(t);
            total += (b - a).cross(c - a).length() * 0.5;
            cumulative.push(total);
        }
        let area = if total > 0.0 && total.is_finite() {
            (0..count)
                .into_par_iter()
                .map(|k| {
                    let mut rng = Rng::for_item(SEED, k as u64);
                    let target = (k as f64 + rng.unit()) / count as f64 * total;
                    let t = cumulative
                        .partition_point(|&c| c <= target)
                        .min(usable.len() - 1);
                    point_in_triangle(corners(&usable[t]), rng.unit(), rng.unit())
                })
                .collect()
        } else {
            Vec::new()
        };
        Self { vertices, area }
    }

    /// All points: vertices, then area samples.
    pub fn all(&self) -> impl Iterator<Item = &DVec3> {
        self.vertices.iter().chain(&self.area)
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.vertices.len() + self.area.len()
    }

    /// True when there are no points.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// The uniform point of triangle `[a, b, c]` for two uniform numbers `r1`, `r2` in `[0, 1)`
/// (the square-root map of the unit square onto the triangle).
fn point_in_triangle([a, b, c]: [DVec3; 3], r1: f64, r2: f64) -> DVec3 {
    let s = r1.sqrt();
    a * (1.0 - s) + b * (s * (1.0 - r2)) + c * (s * r2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::topology::test_meshes::{cube, two_cubes};

    #[test]
    fn samples_lie_on_the_surface_and_spread_by_area() {
        let mesh = cube();
        let s = SurfaceSamples::of(&mesh, 6000);
        assert_eq!(s.vertices.len(), 8);
        assert_eq!(s.area.len(), 6000);
        // On the cube's boundary: some coordinate is 0 or 1 and all are inside [0, 1].
        for p in &s.area {
            assert!(p.min_element() >= -1e-15 && p.max_element() <= 1.0 + 1e-15);
            assert!(
                p.to_array()
                    .iter()
                    .any(|&x| x.abs() < 1e-12 || (x - 1.0).abs() < 1e-12)
            );
        }
        // Each face holds about a sixth (stratification keeps it within a couple of points).
        for axis in 0..3 {
            for side in [0.0, 1.0] {
                let on = s
                    .area
                    .iter()
                    .filter(|p| (p[axis] - side).abs() < 1e-12)
                    .count();
                assert!(
                    (on as i64 - 1000).abs() <= 4,
                    "axis {axis} side {side}: {on}"
                );
            }
        }
        // The mean of uniform surface points of the cube is its centre.
        let mean = s.area.iter().sum::<DVec3>() / s.area.len() as f64;
        assert!(mean.distance(DVec3::splat(0.5)) < 0.01, "{mean}");
    }

    #[test]
    fn samples_are_deterministic_and_skip_unused_vertices() {
        let mut mesh = two_cubes();
        mesh.positions.push(DVec3::splat(100.0));
        let a = SurfaceSamples::of(&mesh, 500);
        let b = SurfaceSamples::of(&mesh, 500);
        assert_eq!(a, b);
        assert_eq!(a.vertices.len(), 16);
        assert!(a.all().all(|p| p.max_element() < 100.0));
        assert!(SurfaceSamples::of(&IndexedMesh::default(), 10).is_empty());
    }
}
