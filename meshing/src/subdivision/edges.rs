//! Shared plumbing of the schemes: numbering the undirected edges, walking a vertex ring from a
//! given half-edge, and the boundary neighbours of a boundary vertex.

use crate::halfedge::{HalfEdgeId, HalfEdgeMesh, VertexId};

/// A dense numbering of the undirected edges: edge `e` is the pair of half-edges whose smaller id
/// is the `e`-th smallest such id, so interior edges of earlier faces come first.
#[derive(Debug, Clone)]
pub(super) struct EdgeIndex {
    of_half_edge: Vec<u32>,
    representative: Vec<HalfEdgeId>,
}

impl EdgeIndex {
    /// Numbers the edges of `mesh`.
    pub(super) fn new(mesh: &HalfEdgeMesh) -> Self {
        let mut of_half_edge = vec![u32::MAX; mesh.half_edge_count()];
        let mut representative = Vec::with_capacity(mesh.edge_count());
        for h in mesh.half_edge_ids() {
            let twin = mesh.half_edge(h).twin;
            if h < twin {
                let e = representative.len() as u32;
                of_half_edge[h.index()] = e;
                of_half_edge[twin.index()] = e;
                representative.push(h);
            }
        }
        EdgeIndex {
            of_half_edge,
            representative,
        }
    }

    /// Number of edges.
    pub(super) fn count(&self) -> usize {
        self.representative.len()
    }

    /// The edge of half-edge `h`.
    pub(super) fn of(&self, h: HalfEdgeId) -> u32 {
        self.of_half_edge[h.index()]
    }

    /// The edges with one of their half-edges (the one with the smaller id).
    pub(super) fn half_edges(&self) -> impl ExactSizeIterator<Item = HalfEdgeId> + '_ {
        self.representative.iter().copied()
    }
}

/// The half-edges leaving the origin of `start`, from `start` on, in the order of
/// [`HalfEdgeMesh::vertex_outgoing`] (at most one full turn).
pub(super) fn ring_from(
    mesh: &HalfEdgeMesh,
    start: HalfEdgeId,
) -> impl Iterator<Item = HalfEdgeId> {
    let mut current = Some(start);
    let mut steps_left = mesh.half_edge_count();
    std::iter::from_fn(move || {
        let h = current?;
        steps_left = steps_left.checked_sub(1)?;
        let following = mesh.half_edge(mesh.half_edge(h).twin).next;
        current = (following != start).then_some(following);
        Some(h)
    })
}

/// The two boundary neighbours of a boundary vertex `v`: where the boundary comes from and where
/// it goes. `None` for an interior or isolated vertex.
pub(super) fn boundary_neighbors(mesh: &HalfEdgeMesh, v: VertexId) -> Option<(VertexId, VertexId)> {
    // A boundary vertex's stored outgoing half-edge is a boundary one.
    let out = mesh.vertex_half_edge(v)?;
    if !mesh.is_boundary_half_edge(out) {
        return None;
    }
    let incoming = mesh.half_edge(out).prev;
    Some((mesh.half_edge(incoming).origin, mesh.target(out)))
}
