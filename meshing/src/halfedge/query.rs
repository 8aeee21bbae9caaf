//! Adjacency queries: face loops, vertex rings, edge endpoints and faces, boundary tests.
//!
//! The traversals follow the classic half-edge recipes: the half-edges of a face are reached by
//! `next` until the start comes back; the half-edges leaving a vertex by `next(twin(h))`, which
//! turns clockwise seen from outside and, thanks to the boundary loops, also closes at boundary
//! vertices. Iterators borrow the mesh and allocate nothing; each stops after at most
//! `half_edge_count` steps, so even a corrupted structure cannot make them loop forever.

use super::{FaceId, HalfEdge, HalfEdgeId, HalfEdgeMesh, VertexId};

/// The half-edges of a face loop, from the face's first half-edge; see
/// [`HalfEdgeMesh::face_half_edges`].
#[derive(Debug, Clone)]
pub struct FaceHalfEdges<'a> {
    walk: Walk<'a>,
}

impl Iterator for FaceHalfEdges<'_> {
    type Item = HalfEdgeId;

    fn next(&mut self) -> Option<HalfEdgeId> {
        self.walk.step(|he| he.next)
    }
}

/// The half-edges leaving a vertex, clockwise seen from outside; see
/// [`HalfEdgeMesh::vertex_outgoing`].
#[derive(Debug, Clone)]
pub struct VertexOutgoing<'a> {
    walk: Walk<'a>,
}

impl Iterator for VertexOutgoing<'_> {
    type Item = HalfEdgeId;

    fn next(&mut self) -> Option<HalfEdgeId> {
        let (half_edges, start) = (self.walk.half_edges, self.walk.start);
        // A dangling twin (only in a corrupted mesh) ends the walk.
        self.walk.step(|he| {
            half_edges
                .get(he.twin.index())
                .map_or(start, |twin| twin.next)
        })
    }
}

/// A bounded walk along a cycle of half-edges.
#[derive(Debug, Clone)]
struct Walk<'a> {
    half_edges: &'a [HalfEdge],
    start: HalfEdgeId,
    current: Option<HalfEdgeId>,
    steps_left: usize,
}

impl<'a> Walk<'a> {
    /// A walk from `start` (none for `None`).
    fn new(mesh: &'a HalfEdgeMesh, start: Option<HalfEdgeId>) -> Self {
        Self {
            half_edges: &mesh.half_edges,
            start: start.unwrap_or(HalfEdgeId(0)),
            current: start,
            steps_left: mesh.half_edges.len(),
        }
    }

    /// Yields the current half-edge and moves to `advance(current)`, ending back at the start.
    fn step(&mut self, advance: impl Fn(&HalfEdge) -> HalfEdgeId) -> Option<HalfEdgeId> {
        let h = self.current?;
        self.steps_left = self.steps_left.checked_sub(1)?;
        let following = advance(self.half_edges.get(h.index())?);
        self.current = (following != self.start).then_some(following);
        Some(h)
    }
}

impl HalfEdgeMesh {
    /// The half-edges around face `f`, starting at the one leaving its first input vertex.
    pub fn face_half_edges(&self, f: FaceId) -> FaceHalfEdges<'_> {
        FaceHalfEdges {
            walk: Walk::new(self, Some(self.face_half_edge(f))),
        }
    }

    /// The vertices of face `f` in input order.
    pub fn face_vertices(&self, f: FaceId) -> impl Iterator<Item = VertexId> + '_ {
        self.face_half_edges(f).map(|h| self.half_edge(h).origin)
    }

    /// The half-edges leaving `v`, clockwise seen from outside (empty for an isolated vertex). At a
    /// boundary vertex the first one is the boundary half-edge.
    pub fn vertex_outgoing(&self, v: VertexId) -> VertexOutgoing<'_> {
        VertexOutgoing {
            walk: Walk::new(self, self.vertex_half_edge(v)),
        }
    }

    /// The faces around `v`, in the order of [`HalfEdgeMesh::vertex_outgoing`] (a fan at a
    /// boundary vertex).
    pub fn vertex_faces(&self, v: VertexId) -> impl Iterator<Item = FaceId> + '_ {
        self.vertex_outgoing(v)
            .filter_map(|h| self.half_edge(h).face)
    }

    /// The vertices joined to `v` by an edge, in the order of [`HalfEdgeMesh::vertex_outgoing`].
    pub fn vertex_neighbors(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        self.vertex_outgoing(v).map(|h| self.target(h))
    }

    /// The number of edges at `v`.
    pub fn valence(&self, v: VertexId) -> usize {
        self.vertex_outgoing(v).count()
    }

    /// The vertex `h` points to (the origin of its twin).
    pub fn target(&self, h: HalfEdgeId) -> VertexId {
        self.half_edge(self.half_edge(h).twin).origin
    }

    /// The two endpoints of `h`: `(origin, target)`.
    pub fn edge_vertices(&self, h: HalfEdgeId) -> (VertexId, VertexId) {
        (self.half_edge(h).origin, self.target(h))
    }

    /// The faces on both sides of the edge of `h`: `(face of h, face of its twin)`. One is `None`
    /// on the boundary.
    pub fn edge_faces(&self, h: HalfEdgeId) -> (Option<FaceId>, Option<FaceId>) {
        let he = self.half_edge(h);
        (he.face, self.half_edge(he.twin).face)
    }

    /// True when `h` is a boundary half-edge (has no face).
    pub fn is_boundary_half_edge(&self, h: HalfEdgeId) -> bool {
        self.half_edge(h).face.is_none()
    }

    /// True when `v` has a boundary half-edge leaving it (false for an isolated vertex).
    pub fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.vertex_outgoing(v)
            .any(|h| self.is_boundary_half_edge(h))
    }

    /// True when there is at least one face and no boundary half-edge.
    pub fn is_closed(&self) -> bool {
        self.face_count() > 0 && self.half_edges.iter().all(|he| he.face.is_some())
    }

    /// Number of boundary loops (cycles of boundary half-edges).
    pub fn boundary_loop_count(&self) -> usize {
        let mut seen = vec![false; self.half_edges.len()];
        let mut loops = 0;
        for start in self.half_edge_ids() {
            if seen[start.index()] || !self.is_boundary_half_edge(start) {
                continue;
            }
            loops += 1;
            let walk = FaceHalfEdges {
                walk: Walk::new(self, Some(start)),
            };
            for h in walk {
                seen[h.index()] = true;
            }
        }
        loops
    }

    /// `V − E + F`, counting only vertices that some face uses (as the topology report does).
    pub fn euler_characteristic(&self) -> i64 {
        let used = self.vertex_half_edge.iter().flatten().count();
        used as i64 - self.edge_count() as i64 + self.face_count() as i64
    }
}
