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
//! Open meshes (the boundary rule): each boundary edge `(a, b)` gets Chaikin's two points
//! `3/4 a + 1/4 b` and `1/4 a + 3/4 b` on it; its E-face is the quad of the two corner points at
//! its ends in its one face and those two points, and each boundary vertex's V-face is the polygon
//! of the corner points around it closed by the Chaikin points of its two boundary edges next to
//! it (a triangle at a vertex of one face). The new boundary is Chaikin's corner cutting of the
//! old boundary polygon, so it converges to the quadratic B-spline of the boundary polygon: it
//! keeps the midpoints of the boundary edges and straight boundary runs, and an open mesh does not
//! shrink away from its boundary. Counts per level: `V' = Σdeg + 2E_b`, `E' = Σdeg + 2E + 2E_b`,
//! `F' = F + E + V` (`E_b` boundary edges; closed meshes: `E_b = 0`). Isolated vertices are
//! dropped.

use glam::DVec3;
use std::f64::consts::PI;

use super::SubdivisionError;
use super::edges::ring_from;
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
    // Chaikin's points of each boundary half-edge `a → b`: `[3/4 a + 1/4 b, 1/4 a + 3/4 b]`.
    let mut chaikin = vec![[u32::MAX; 2]; mesh.half_edge_count()];
    for h in mesh.half_edge_ids() {
        if mesh.half_edge(h).face.is_none() {
            let a = mesh.position(mesh.half_edge(h).origin);
            let b = mesh.position(mesh.target(h));
            let first = positions.len() as u32;
            positions.push(0.75 * a + 0.25 * b);
            positions.push(0.25 * a + 0.75 * b);
            chaikin[h.index()] = [first, first + 1];
        }
    }
    let at = |h: HalfEdgeId| corner[h.index()];
    for h in mesh.half_edge_ids() {
        let he = mesh.half_edge(h);
        let twin = mesh.half_edge(he.twin);
        match (he.face.is_some(), twin.face.is_some()) {
            (true, true) if h < he.twin => {
                faces.push(vec![at(twin.next), at(he.twin), at(he.next), at(h)]);
            }
            // `h = a → b` in its face, its twin `b → a` on the boundary.
            (true, false) => {
                let [near_b, near_a] = chaikin[he.twin.index()];
                faces.push(vec![at(he.next), at(h), near_a, near_b]);
            }
            _ => {}
        }
    }
    for v in mesh.vertex_ids() {
        let Some(start) = mesh.vertex_half_edge(v) else {
            continue;
        };
        // Outgoing half-edges turn clockwise seen from outside: reversed, the loop is
        // counter-clockwise. A boundary vertex's ring starts at its outgoing boundary half-edge
        // `v → n` and ends at `v → p` (the twin of the incoming boundary half-edge `p → v`).
        let mut loop_: Vec<u32> = ring_from(mesh, start)
            .filter(|&h| mesh.half_edge(h).face.is_some())
            .map(at)
            .collect();
        loop_.reverse();
        if mesh.is_boundary_half_edge(start) {
            let incoming = mesh.half_edge(start).prev;
            loop_.push(chaikin[start.index()][0]);
            loop_.push(chaikin[incoming.index()][1]);
        }
        if loop_.len() >= 3 {
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
