//! Modified butterfly subdivision (Dyn, Levin and Gregory's butterfly with Zorin, Schröder and
//! Sweldens' rules for extraordinary vertices, 1996): an interpolating scheme on triangle meshes.
//! The old vertices keep their positions bit for bit; only the new edge vertices are computed.
//!
//! Edge vertex of an interior edge `(a, b)`:
//! - both ends interior of valence 6: the eight-point butterfly
//!   `1/2 (a + b) + 1/8 (c + d) − 1/16 (w₁ + w₂ + w₃ + w₄)`, with `c`, `d` the vertices opposite the
//!   edge and `wᵢ` the vertices opposite the other edges of its two triangles (tension `w = 0` in
//!   Zorin's ten-point form);
//! - one end `v` interior and extraordinary (valence `k ≠ 6`), the other regular: Zorin's stencil
//!   `3/4 v + Σ sⱼ qⱼ` over the neighbours `qⱼ` of `v`, `q₀` being the other end, with
//!   `s = (5/12, −1/12, −1/12)` for `k = 3`, `(3/8, 0, −1/8, 0)` for `k = 4` and
//!   `sⱼ = (1/4 + cos(2πj/k) + 1/2 cos(4πj/k)) / k` for `k ≥ 5`;
//! - both ends extraordinary: the average of their two stencils.
//!
//! Boundaries (a simplification of Zorin's boundary tables): a boundary edge uses the four-point
//! curve rule `9/16 (a + b) − 1/16 (a₋ + b₊)` along its boundary loop (the boundary stays an
//! interpolating curve of its own); an interior edge with one boundary end uses the stencil of its
//! interior end (whatever its valence); an interior edge between two boundary vertices uses
//! `3/8 (a + b) + 1/8 (c + d)`. A valence below 3 (degenerate) gives the midpoint.

use glam::DVec3;
use std::f64::consts::PI;

use super::SubdivisionError;
use super::edges::{EdgeIndex, ring_from};
use super::split::split_triangles;
use crate::halfedge::{HalfEdgeId, HalfEdgeMesh};

/// The regular valence of a triangle mesh.
const REGULAR: usize = 6;

/// One level of butterfly subdivision of a triangle mesh (see the module docs).
pub(super) fn step(mesh: &HalfEdgeMesh) -> Result<HalfEdgeMesh, SubdivisionError> {
    let edges = EdgeIndex::new(mesh);
    let vertices = VertexInfo::of(mesh);
    let mut positions = Vec::with_capacity(mesh.vertex_count() + edges.count());
    positions.extend_from_slice(mesh.positions());
    positions.extend(edges.half_edges().map(|h| edge_point(mesh, &vertices, h)));
    let triangles = split_triangles(mesh, &edges);
    Ok(HalfEdgeMesh::from_faces(positions, &triangles)?)
}

/// Valence and boundary flag of every vertex.
struct VertexInfo {
    valence: Vec<usize>,
    boundary: Vec<bool>,
}

impl VertexInfo {
    fn of(mesh: &HalfEdgeMesh) -> Self {
        VertexInfo {
            valence: mesh.vertex_ids().map(|v| mesh.valence(v)).collect(),
            boundary: mesh
                .vertex_ids()
                .map(|v| mesh.is_boundary_vertex(v))
                .collect(),
        }
    }
}

/// The new vertex on the edge of `h`.
fn edge_point(mesh: &HalfEdgeMesh, info: &VertexInfo, h: HalfEdgeId) -> DVec3 {
    let twin = mesh.half_edge(h).twin;
    let (a, b) = mesh.edge_vertices(h);
    if mesh.is_boundary_half_edge(h) {
        return four_point(mesh, h);
    }
    if mesh.is_boundary_half_edge(twin) {
        return four_point(mesh, twin);
    }
    let interior = |v: crate::halfedge::VertexId| !info.boundary[v.index()];
    let regular = |v: crate::halfedge::VertexId| info.valence[v.index()] == REGULAR;
    match (interior(a), interior(b)) {
        (true, true) => match (regular(a), regular(b)) {
            (true, true) => eight_point(mesh, h),
            (false, true) => stencil(mesh, info, h),
            (true, false) => stencil(mesh, info, twin),
            (false, false) => 0.5 * (stencil(mesh, info, h) + stencil(mesh, info, twin)),
        },
        (true, false) => stencil(mesh, info, h),
        (false, true) => stencil(mesh, info, twin),
        (false, false) => {
            let p = |v: crate::halfedge::VertexId| mesh.position(v);
            let c = opposite(mesh, h);
            let d = opposite(mesh, twin);
            0.375 * (p(a) + p(b)) + 0.125 * (p(c) + p(d))
        }
    }
}

/// The vertex opposite the edge of interior half-edge `h` in its triangle.
fn opposite(mesh: &HalfEdgeMesh, h: HalfEdgeId) -> crate::halfedge::VertexId {
    mesh.half_edge(mesh.half_edge(h).prev).origin
}

/// The vertex across the edge of `h` from `h`'s triangle (its twin's opposite vertex).
fn across(mesh: &HalfEdgeMesh, h: HalfEdgeId) -> crate::halfedge::VertexId {
    opposite(mesh, mesh.half_edge(h).twin)
}

/// The eight-point butterfly of an interior edge whose two ends are interior.
fn eight_point(mesh: &HalfEdgeMesh, h: HalfEdgeId) -> DVec3 {
    let p = |v| mesh.position(v);
    let t = mesh.half_edge(h).twin;
    let (a, b) = mesh.edge_vertices(h);
    let (c, d) = (opposite(mesh, h), opposite(mesh, t));
    let wings = [
        mesh.half_edge(h).next,
        mesh.half_edge(h).prev,
        mesh.half_edge(t).next,
        mesh.half_edge(t).prev,
    ]
    .map(|g| p(across(mesh, g)));
    0.5 * (p(a) + p(b)) + 0.125 * (p(c) + p(d))
        - 0.0625 * (wings[0] + wings[1] + wings[2] + wings[3])
}

/// Zorin's stencil around the origin `v` of `h` (an interior vertex), `h` pointing to `q₀`.
fn stencil(mesh: &HalfEdgeMesh, info: &VertexInfo, h: HalfEdgeId) -> DVec3 {
    let v = mesh.half_edge(h).origin;
    let k = info.valence[v.index()];
    if k < 3 {
        let (a, b) = mesh.edge_vertices(h);
        return 0.5 * (mesh.position(a) + mesh.position(b));
    }
    let mut sum = 0.75 * mesh.position(v);
    for (j, g) in ring_from(mesh, h).enumerate() {
        sum += weight(k, j) * mesh.position(mesh.target(g));
    }
    sum
}

/// Zorin's weight `sⱼ` of the `j`-th neighbour of a vertex of valence `k ≥ 3`.
fn weight(k: usize, j: usize) -> f64 {
    match (k, j) {
        (3, 0) => 5.0 / 12.0,
        (3, _) => -1.0 / 12.0,
        (4, 0) => 3.0 / 8.0,
        (4, 2) => -1.0 / 8.0,
        (4, _) => 0.0,
        _ => {
            let angle = 2.0 * PI * j as f64 / k as f64;
            (0.25 + angle.cos() + 0.5 * (2.0 * angle).cos()) / k as f64
        }
    }
}

/// The four-point rule along the boundary loop of the boundary half-edge `b`.
fn four_point(mesh: &HalfEdgeMesh, b: HalfEdgeId) -> DVec3 {
    let he = mesh.half_edge(b);
    let before = mesh.half_edge(he.prev).origin;
    let (x, y) = mesh.edge_vertices(b);
    let after = mesh.target(he.next);
    let p = |v| mesh.position(v);
    0.5625 * (p(x) + p(y)) - 0.0625 * (p(before) + p(after))
}

#[cfg(test)]
mod tests {
    use super::weight;

    /// Every stencil's neighbour weights sum to 1/4 (with 3/4 on the centre: affine invariance).
    #[test]
    fn stencil_weights_sum_to_a_quarter() {
        for k in 3..=12 {
            let sum: f64 = (0..k).map(|j| weight(k, j)).sum();
            assert!((sum - 0.25).abs() < 1e-14, "valence {k}: {sum}");
        }
    }
}
