//! Doo-Sabin subdivision: the dual scheme, converging to a biquadratic B-spline surface away from
//! extraordinary faces.
//!
//! One level:
//! - one new vertex per face corner: in a face of degree `n` with vertices `v₀ … vₙ₋₁`, the corner
//!   at `vᵢ` becomes `Σⱼ αᵢⱼ vⱼ` with Doo and Sabin's weights `αᵢᵢ = (n + 5) / 4n` and
//!   `αᵢⱼ = (3 + 2 cos(2π(i − j)/n)) / 4n` (for quads: 9/16, 3/16, 3/16, 1/16);
//! - F-faces: each face becomes the smaller face of its corner points;
//! - E-faces: each interior edge becomes a quad of the four corner points at its ends;
//! - V-faces: each interior vertex of valence `k ≥ 3` becomes a `k`-gon of the corner points
//!   around it (a valence-2 vertex needs none: its two E-faces meet directly).
//!
//! Open meshes: boundary edges and boundary vertices make no E- or V-face, so the boundary of the
//! result runs along the F-faces and E-faces next to the old boundary (one new boundary loop per
//! old one; the boundary shrinks towards the interior, as Doo-Sabin surfaces do without extra
//! boundary rules). Isolated vertices are dropped.

use glam::DVec3;
use std::f64::consts::PI;

use super::SubdivisionError;
use crate::halfedge::{HalfEdgeId, HalfEdgeMesh};

/// One level of Doo-Sabin subdivision (see the module docs).
pub(super) fn step(mesh: &HalfEdgeMesh) -> Result<HalfEdgeMesh, SubdivisionError> {
    // The new vertex of each interior half-edge (the corner at its origin in its face).
    let mut corner = vec![u32::MAX; mesh.half_edge_count()];
    let mut positions = Vec::new();
    let mut faces: Vec<Vec<u32>> = Vec::with_capacity(mesh.face_count());
    let mut ring: Vec<DVec3> = Vec::new();
    for f in mesh.face_ids() {
        ring.clear();
        ring.extend(mesh.face_vertices(f).map(|v| mesh.position(v)));
        let first = positions.len() as u32;
        for (h, i) in mesh.face_half_edges(f).zip(0..) {
            corner[h.index()] = first + i as u32;
            positions.push(corner_point(&ring, i));
        }
        faces.push((first..positions.len() as u32).collect());
    }
    let at = |h: HalfEdgeId| corner[h.index()];
    for h in mesh.half_edge_ids() {
        let he = mesh.half_edge(h);
        let twin = mesh.half_edge(he.twin);
        if h < he.twin && he.face.is_some() && twin.face.is_some() {
            faces.push(vec![at(twin.next), at(he.twin), at(he.next), at(h)]);
        }
    }
    for v in mesh.vertex_ids() {
        if mesh.vertex_half_edge(v).is_none() || mesh.is_boundary_vertex(v) {
            continue;
        }
        // Outgoing half-edges turn clockwise seen from outside: reversed, the loop is
        // counter-clockwise.
        let mut loop_: Vec<u32> = mesh.vertex_outgoing(v).map(at).collect();
        if loop_.len() >= 3 {
            loop_.reverse();
            faces.push(loop_);
        }
    }
    Ok(HalfEdgeMesh::from_faces(positions, &faces)?)
}

/// The Doo-Sabin point of corner `i` of the face with vertex positions `ring`.
fn corner_point(ring: &[DVec3], i: usize) -> DVec3 {
    let n = ring.len();
    let scale = 1.0 / (4.0 * n as f64);
    ring.iter()
        .enumerate()
        .map(|(j, &p)| {
            let alpha = if j == i {
                (n as f64 + 5.0) * scale
            } else {
                let angle = 2.0 * PI * (i as f64 - j as f64) / n as f64;
                (3.0 + 2.0 * angle.cos()) * scale
            };
            alpha * p
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::corner_point;
    use glam::DVec3;

    /// The weights are an affine combination, and for a unit square the corner at the origin is
    /// at (1/4, 1/4): 9/16 of it, 3/16 of each neighbour, 1/16 of the opposite corner.
    #[test]
    fn weights_are_affine_and_bilinear_on_quads() {
        let square = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        assert!(corner_point(&square, 0).distance(DVec3::new(0.25, 0.25, 0.0)) < 1e-15);
        for n in 3..=9 {
            let ones = vec![DVec3::ONE; n];
            for i in 0..n {
                assert!(
                    corner_point(&ones, i).distance(DVec3::ONE) < 1e-14,
                    "n = {n}"
                );
            }
        }
    }
}
