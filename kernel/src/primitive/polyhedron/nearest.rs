//! The nearest point of a mesh solid's triangles to a query point: the exact query of the
//! kernel's [`TriangleBvh`](crate::bvh::TriangleBvh) on the [`MeshTree`], and the exact
//! point–triangle distance it uses (Voronoi regions of the triangle, `crate::closest`).

use super::tree::MeshTree;
use crate::bvh::Nearest;
use glam::DVec3;

impl MeshTree {
    /// The nearest point of the mesh to `q` (its `slot` indexes [`MeshTree::triangles`]).
    pub(crate) fn nearest(&self, q: DVec3) -> Nearest {
        // The tree always has triangles (checked when made); an empty one would be infinitely far.
        self.bvh.nearest(q).unwrap_or(Nearest {
            distance2: f64::INFINITY,
            point: q,
            slot: 0,
        })
    }
}

impl MeshTree {
    /// [`MeshTree::nearest`] with the search bounded from the start by the triangle in slot
    /// `hint` (the same distance; see [`crate::bvh::TriangleBvh::nearest_hinted`]).
    pub(crate) fn nearest_hinted(&self, q: DVec3, hint: u32) -> Nearest {
        self.bvh.nearest_hinted(q, hint).unwrap_or(Nearest {
            distance2: f64::INFINITY,
            point: q,
            slot: 0,
        })
    }
}

/// The point of triangle `abc` nearest to `q` (the kernel's shared computation), for the tests.
#[cfg(test)]
pub(crate) fn closest_point(q: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    crate::closest::closest_point_on_triangle(q, [a, b, c])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitive::conformance::Rng;

    /// Brute-force distance to a triangle by dense sampling of barycentric coordinates.
    fn sampled_distance(q: DVec3, a: DVec3, b: DVec3, c: DVec3) -> f64 {
        let n = 200;
        let mut best = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let p = a + (b - a) * u + (c - a) * v;
                best = best.min(p.distance(q));
            }
        }
        best
    }

    #[test]
    fn closest_point_matches_sampling_and_is_never_farther() {
        let mut rng = Rng::new(11);
        for _ in 0..300 {
            let (a, b, c, q) = (rng.vec(1.0), rng.vec(1.0), rng.vec(1.0), rng.vec(2.0));
            let d = closest_point(q, a, b, c).distance(q);
            let s = sampled_distance(q, a, b, c);
            // Sampling can only overestimate, by at most the grid spacing.
            assert!(d <= s + 1e-12, "{d} > {s}");
            assert!(s - d < 0.02, "{d} vs {s}");
        }
    }

    #[test]
    fn degenerate_triangles_use_their_edges() {
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::X * 2.0);
        let q = DVec3::new(1.5, 1.0, 0.0);
        assert!((closest_point(q, a, b, c).distance(q) - 1.0).abs() < 1e-15);
        let p = DVec3::ONE;
        assert_eq!(closest_point(q, p, p, p), p);
    }
}
