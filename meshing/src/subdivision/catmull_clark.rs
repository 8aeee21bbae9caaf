//! Catmull-Clark subdivision: any polygon mesh to a quad mesh whose limit is a bicubic B-spline
//! surface away from extraordinary vertices.
//!
//! One level, with `S` an old vertex position:
//! - face point: the centroid of the face's vertices;
//! - edge point: the average of the edge's two end points and the two adjacent face points;
//!   on the boundary, the edge midpoint;
//! - vertex point of an interior vertex of valence `n`: `(Q + 2R + (n − 3)S) / n`, with `Q` the
//!   average of the adjacent face points and `R` the average of the midpoints of the incident
//!   edges; of a boundary vertex with boundary neighbours `a` and `b`: `(a + 6S + b) / 8` (the
//!   boundary becomes a cubic B-spline curve of the boundary polygon, a crease); an isolated vertex
//!   stays;
//! - every face of degree `k` becomes `k` quads (vertex point, edge point, face point, edge point),
//!   wound as the face.

use glam::DVec3;

use super::SubdivisionError;
use super::edges::{EdgeIndex, boundary_neighbors};
use crate::halfedge::{FaceId, HalfEdgeMesh};

/// One level of Catmull-Clark subdivision (see the module docs).
pub(super) fn step(mesh: &HalfEdgeMesh) -> Result<HalfEdgeMesh, SubdivisionError> {
    let edges = EdgeIndex::new(mesh);
    let positions = points(mesh, &edges);
    let edge_base = mesh.vertex_count() as u32;
    let face_base = edge_base + edges.count() as u32;
    let mut quads: Vec<[u32; 4]> = Vec::new();
    for f in mesh.face_ids() {
        quads.extend(face_quads(mesh, &edges, f, edge_base, face_base));
    }
    Ok(HalfEdgeMesh::from_faces(positions, &quads)?)
}

/// The quads face `f` becomes (vertex, edge, face, edge point), with edge points numbered from
/// `edge_base` and face points from `face_base`.
pub(super) fn face_quads<'a>(
    mesh: &'a HalfEdgeMesh,
    edges: &'a EdgeIndex,
    f: FaceId,
    edge_base: u32,
    face_base: u32,
) -> impl Iterator<Item = [u32; 4]> + 'a {
    mesh.face_half_edges(f).map(move |h| {
        let he = mesh.half_edge(h);
        [
            he.origin.0,
            edge_base + edges.of(h),
            face_base + f.0,
            edge_base + edges.of(he.prev),
        ]
    })
}

/// The next level's points: the vertex points (old vertex ids), then one edge point per edge of
/// `edges`, then one face point per face.
pub(super) fn points(mesh: &HalfEdgeMesh, edges: &EdgeIndex) -> Vec<DVec3> {
    let p = mesh.positions();
    let face_points: Vec<DVec3> = mesh
        .face_ids()
        .map(|f| {
            let (sum, n) = mesh
                .face_vertices(f)
                .fold((DVec3::ZERO, 0.0), |(s, n), v| (s + p[v.index()], n + 1.0));
            sum / n
        })
        .collect();
    let mut positions = Vec::with_capacity(mesh.vertex_count() + edges.count() + face_points.len());
    for v in mesh.vertex_ids() {
        let s = p[v.index()];
        let moved = if let Some((a, b)) = boundary_neighbors(mesh, v) {
            (p[a.index()] + 6.0 * s + p[b.index()]) / 8.0
        } else {
            let (mut q, mut r, mut n) = (DVec3::ZERO, DVec3::ZERO, 0.0);
            for h in mesh.vertex_outgoing(v) {
                if let Some(f) = mesh.half_edge(h).face {
                    q += face_points[f.index()];
                }
                r += (s + p[mesh.target(h).index()]) * 0.5;
                n += 1.0;
            }
            if n == 0.0 {
                s
            } else {
                (q / n + 2.0 * (r / n) + (n - 3.0) * s) / n
            }
        };
        positions.push(moved);
    }
    for h in edges.half_edges() {
        let (a, b) = mesh.edge_vertices(h);
        let ends = p[a.index()] + p[b.index()];
        positions.push(match mesh.edge_faces(h) {
            (Some(f), Some(g)) => (ends + face_points[f.index()] + face_points[g.index()]) / 4.0,
            _ => ends * 0.5,
        });
    }
    positions.extend_from_slice(&face_points);
    positions
}
