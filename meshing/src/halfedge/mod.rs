//! The half-edge mesh: a polygon mesh with explicit adjacency, for oriented 2-manifolds with or
//! without boundary.
//!
//! Every face is a loop of half-edges (`next`/`prev`); every half-edge has a `twin` running the other
//! way along the same edge. Edges on the boundary get a *boundary half-edge* (no face) as twin, and
//! boundary half-edges are linked into boundary loops, so `twin` is total and walking around a
//! vertex (`next(twin(h))`) always returns to its start, on the boundary too.
//!
//! - Construction ([`HalfEdgeMesh::from_indexed`], [`HalfEdgeMesh::from_polygons`]) rejects what
//!   the structure cannot represent with a [`HalfEdgeError`], never a panic: out-of-range indices,
//!   degenerate faces, edges of more than two faces, vertices with several fans and inconsistent
//!   orientation.
//! - Queries (`query.rs`) are iterators over face loops and vertex rings.
//! - [`HalfEdgeMesh::validate`] checks every structural invariant.
//! - [`HalfEdgeMesh::to_indexed`] and [`HalfEdgeMesh::faces`] convert back.
//!
//! Construction is O(n log n) (one sort of the directed edges) and uses no recursion.

mod build;
mod convert;
mod error;
mod ids;
mod query;
mod validate;

#[cfg(test)]
mod tests;

use glam::DVec3;

pub use error::HalfEdgeError;
pub use ids::{FaceId, HalfEdgeId, VertexId};
pub use query::{FaceHalfEdges, VertexOutgoing};
pub use validate::ValidationError;

/// One directed half of an edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct HalfEdge {
    /// The vertex it starts at.
    pub origin: VertexId,
    /// The half-edge along the same edge in the opposite direction.
    pub twin: HalfEdgeId,
    /// The next half-edge around the same face (or boundary loop).
    pub next: HalfEdgeId,
    /// The previous half-edge around the same face (or boundary loop).
    pub prev: HalfEdgeId,
    /// The face it bounds; `None` for a boundary half-edge.
    pub face: Option<FaceId>,
}

/// A half-edge mesh; see the [module docs](self).
///
/// Interior half-edges come first, face by face in input order (face `f`'s loop starts at its first
/// input vertex), followed by the boundary half-edges. Unreferenced (isolated) vertices are allowed
/// and have no outgoing half-edge.
#[derive(Debug, Clone, PartialEq)]
pub struct HalfEdgeMesh {
    positions: Vec<DVec3>,
    half_edges: Vec<HalfEdge>,
    /// One outgoing half-edge per vertex; a boundary one when the vertex is on the boundary.
    vertex_half_edge: Vec<Option<HalfEdgeId>>,
    /// The first half-edge of each face.
    face_half_edge: Vec<HalfEdgeId>,
}

impl HalfEdgeMesh {
    /// Number of vertices, isolated ones included.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.face_half_edge.len()
    }

    /// Number of half-edges, boundary half-edges included.
    pub fn half_edge_count(&self) -> usize {
        self.half_edges.len()
    }

    /// Number of undirected edges (every half-edge has a twin).
    pub fn edge_count(&self) -> usize {
        self.half_edges.len() / 2
    }

    /// All vertex positions.
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// All half-edges, indexed by [`HalfEdgeId`].
    pub fn half_edges(&self) -> &[HalfEdge] {
        &self.half_edges
    }

    /// The position of `v`. Panics when `v` is out of range, like slice indexing.
    pub fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }

    /// The half-edge `h`. Panics when `h` is out of range, like slice indexing.
    pub fn half_edge(&self, h: HalfEdgeId) -> &HalfEdge {
        &self.half_edges[h.index()]
    }

    /// One outgoing half-edge of `v` (a boundary one if `v` is on the boundary); `None` for an
    /// isolated vertex.
    pub fn vertex_half_edge(&self, v: VertexId) -> Option<HalfEdgeId> {
        self.vertex_half_edge[v.index()]
    }

    /// The first half-edge of face `f` (it starts at the face's first input vertex).
    pub fn face_half_edge(&self, f: FaceId) -> HalfEdgeId {
        self.face_half_edge[f.index()]
    }

    /// All vertex ids.
    pub fn vertex_ids(&self) -> impl ExactSizeIterator<Item = VertexId> + use<> {
        (0..self.positions.len() as u32).map(VertexId)
    }

    /// All face ids.
    pub fn face_ids(&self) -> impl ExactSizeIterator<Item = FaceId> + use<> {
        (0..self.face_half_edge.len() as u32).map(FaceId)
    }

    /// All half-edge ids.
    pub fn half_edge_ids(&self) -> impl ExactSizeIterator<Item = HalfEdgeId> + use<> {
        (0..self.half_edges.len() as u32).map(HalfEdgeId)
    }
}
