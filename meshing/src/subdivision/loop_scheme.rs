//! Loop subdivision: triangle meshes, each triangle split into four, converging to a surface that
//! is a quartic box spline away from extraordinary vertices (C² there, C¹ at them).
//!
//! One level:
//! - edge point of an interior edge `(a, b)` with opposite vertices `c` and `d`:
//!   `3/8 (a + b) + 1/8 (c + d)`; of a boundary edge: its midpoint;
//! - vertex point of an interior vertex of valence `n` with neighbours `qᵢ`:
//!   `(1 − nβ) S + β Σ qᵢ`, with Loop's original weight
//!   `β = (5/8 − (3/8 + 1/4 cos(2π/n))²) / n` (1/16 at the regular valence 6); of a boundary vertex
//!   with boundary neighbours `a` and `b`: `3/4 S + 1/8 (a + b)` (the cubic B-spline rule, so the
//!   boundary is a crease); an isolated vertex stays;
//! - triangle `(a, b, c)` with edge points `ab`, `bc`, `ca` becomes `(a, ab, ca)`,
//!   `(b, bc, ab)`, `(c, ca, bc)` and `(ab, bc, ca)`.

use glam::DVec3;

use super::SubdivisionError;
use super::edges::{EdgeIndex, boundary_neighbors};
use super::split::split_triangles;
use crate::halfedge::HalfEdgeMesh;

/// Loop's weight of each neighbour of an interior vertex of valence `n`.
pub(super) fn beta(n: usize) -> f64 {
    let n = n as f64;
    let c = 3.0 / 8.0 + 0.25 * (2.0 * std::f64::consts::PI / n).cos();
    (5.0 / 8.0 - c * c) / n
}

/// One level of Loop subdivision of a triangle mesh (see the module docs).
pub(super) fn step(mesh: &HalfEdgeMesh) -> Result<HalfEdgeMesh, SubdivisionError> {
    let edges = EdgeIndex::new(mesh);
    let positions = points(mesh, &edges);
    let triangles = split_triangles(mesh, &edges);
    Ok(HalfEdgeMesh::from_faces(positions, &triangles)?)
}

/// The next level's points: the vertex points (old vertex ids), then one edge point per edge of
/// `edges`.
pub(super) fn points(mesh: &HalfEdgeMesh, edges: &EdgeIndex) -> Vec<DVec3> {
    let p = mesh.positions();
    let mut positions = Vec::with_capacity(mesh.vertex_count() + edges.count());
    for v in mesh.vertex_ids() {
        let s = p[v.index()];
        let moved = if let Some((a, b)) = boundary_neighbors(mesh, v) {
            0.75 * s + 0.125 * (p[a.index()] + p[b.index()])
        } else {
            let (sum, n) = mesh
                .vertex_neighbors(v)
                .fold((DVec3::ZERO, 0usize), |(sum, n), q| {
                    (sum + p[q.index()], n + 1)
                });
            if n == 0 {
                s
            } else {
                let b = beta(n);
                (1.0 - n as f64 * b) * s + b * sum
            }
        };
        positions.push(moved);
    }
    for h in edges.half_edges() {
        let (a, b) = mesh.edge_vertices(h);
        let ends = p[a.index()] + p[b.index()];
        let twin = mesh.half_edge(h).twin;
        positions.push(match mesh.edge_faces(h) {
            (Some(_), Some(_)) => {
                let c = mesh.half_edge(mesh.half_edge(h).prev).origin;
                let d = mesh.half_edge(mesh.half_edge(twin).prev).origin;
                0.375 * ends + 0.125 * (p[c.index()] + p[d.index()])
            }
            _ => 0.5 * ends,
        });
    }
    positions
}
