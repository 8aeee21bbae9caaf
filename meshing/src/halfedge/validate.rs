//! Structural validation of a [`HalfEdgeMesh`]: every invariant the queries rely on.
//!
//! A mesh from the builders always passes; `validate` exists to check that claim (tests, fuzzing)
//! and to guard future editing operations. It never panics, whatever the corruption.

use super::{FaceId, HalfEdgeId, HalfEdgeMesh, VertexId};

/// The first broken invariant found by [`HalfEdgeMesh::validate`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum ValidationError {
    /// A field of the half-edge (origin, twin, next, prev or face) is out of range.
    #[error("half-edge {half_edge:?} refers to an element that does not exist")]
    DanglingId {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
    /// `twin(h) == h`.
    #[error("half-edge {half_edge:?} is its own twin")]
    SelfTwin {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
    /// `twin(twin(h)) != h`.
    #[error("the twin of the twin of half-edge {half_edge:?} is not itself")]
    TwinNotMutual {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
    /// Both halves of an edge lack a face.
    #[error("half-edge {half_edge:?} and its twin both have no face")]
    FacelessEdge {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
    /// `prev(next(h)) != h`.
    #[error("prev(next({half_edge:?})) is not {half_edge:?}")]
    NextPrevMismatch {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
    /// `origin(next(h)) != origin(twin(h))`: `h` does not end where its successor starts.
    #[error("half-edge {half_edge:?} does not end where its next half-edge starts")]
    OriginMismatch {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
    /// The face's first half-edge is out of range.
    #[error("face {face:?} starts at a half-edge that does not exist")]
    DanglingFace {
        /// The face.
        face: FaceId,
    },
    /// A half-edge on the loop of `face` belongs to another face (or none).
    #[error("half-edge {half_edge:?} on the loop of face {face:?} does not point to that face")]
    FaceMismatch {
        /// The face whose loop was walked.
        face: FaceId,
        /// The half-edge with the wrong face.
        half_edge: HalfEdgeId,
    },
    /// An interior half-edge is not on the loop of its own face.
    #[error("half-edge {half_edge:?} is not on the loop of its face")]
    NotInFaceLoop {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
    /// A vertex's outgoing half-edge does not exist or does not start at the vertex.
    #[error("the outgoing half-edge of vertex {vertex:?} does not start at it")]
    VertexMismatch {
        /// The vertex.
        vertex: VertexId,
    },
    /// A half-edge is not reached by walking around its origin vertex (or its origin has no
    /// outgoing half-edge): the vertex has more than one fan.
    #[error("half-edge {half_edge:?} is not reachable around its origin vertex")]
    Unreachable {
        /// The half-edge.
        half_edge: HalfEdgeId,
    },
}

impl HalfEdgeMesh {
    /// Checks every structural invariant and returns the first violation:
    /// ids in range; `twin(h) != h` and `twin(twin(h)) == h`; no edge without faces on both
    /// sides; `prev(next(h)) == h`; `origin(next(h)) == origin(twin(h))`; every face loop holds
    /// only half-edges of that face and every interior half-edge is on its face's loop; each
    /// vertex's outgoing half-edge starts at it; every half-edge is reached by walking around
    /// its origin vertex.
    ///
    /// # Errors
    /// The first broken invariant, as a [`ValidationError`].
    pub fn validate(&self) -> Result<(), ValidationError> {
        for h in self.half_edge_ids() {
            self.check_ids(h)?;
        }
        for h in self.half_edge_ids() {
            self.check_links(h)?;
        }
        self.check_faces()?;
        self.check_vertices()
    }

    /// Every id stored in half-edge `h` is in range.
    fn check_ids(&self, h: HalfEdgeId) -> Result<(), ValidationError> {
        let he = self.half_edge(h);
        let n = self.half_edges.len();
        let ok = he.origin.index() < self.positions.len()
            && he.twin.index() < n
            && he.next.index() < n
            && he.prev.index() < n
            && he.face.is_none_or(|f| f.index() < self.face_count());
        ok.then_some(())
            .ok_or(ValidationError::DanglingId { half_edge: h })
    }

    /// Twin, next/prev and origin consistency of `h` (ids already checked).
    fn check_links(&self, h: HalfEdgeId) -> Result<(), ValidationError> {
        let he = self.half_edge(h);
        let twin = self.half_edge(he.twin);
        let fail = |make: fn(HalfEdgeId) -> ValidationError| Err(make(h));
        if he.twin == h {
            return fail(|half_edge| ValidationError::SelfTwin { half_edge });
        }
        if twin.twin != h {
            return fail(|half_edge| ValidationError::TwinNotMutual { half_edge });
        }
        if he.face.is_none() && twin.face.is_none() {
            return fail(|half_edge| ValidationError::FacelessEdge { half_edge });
        }
        if self.half_edge(he.next).prev != h {
            return fail(|half_edge| ValidationError::NextPrevMismatch { half_edge });
        }
        if self.half_edge(he.next).origin != twin.origin {
            return fail(|half_edge| ValidationError::OriginMismatch { half_edge });
        }
        Ok(())
    }

    /// Face loops hold exactly their face's half-edges.
    fn check_faces(&self) -> Result<(), ValidationError> {
        let mut on_loop = vec![false; self.half_edges.len()];
        for f in self.face_ids() {
            if self.face_half_edge(f).index() >= self.half_edges.len() {
                return Err(ValidationError::DanglingFace { face: f });
            }
            for h in self.face_half_edges(f) {
                if self.half_edge(h).face != Some(f) {
                    return Err(ValidationError::FaceMismatch {
                        face: f,
                        half_edge: h,
                    });
                }
                on_loop[h.index()] = true;
            }
        }
        match self
            .half_edge_ids()
            .find(|h| self.half_edge(*h).face.is_some() && !on_loop[h.index()])
        {
            Some(half_edge) => Err(ValidationError::NotInFaceLoop { half_edge }),
            None => Ok(()),
        }
    }

    /// Each vertex's outgoing half-edge starts at it and its ring reaches all its half-edges.
    fn check_vertices(&self) -> Result<(), ValidationError> {
        let mut reached = vec![false; self.half_edges.len()];
        for v in self.vertex_ids() {
            let Some(start) = self.vertex_half_edge(v) else {
                continue;
            };
            let starts_here = self
                .half_edges
                .get(start.index())
                .is_some_and(|he| he.origin == v);
            if !starts_here {
                return Err(ValidationError::VertexMismatch { vertex: v });
            }
            for h in self.vertex_outgoing(v) {
                reached[h.index()] = true;
            }
        }
        match reached.iter().position(|&r| !r) {
            Some(h) => Err(ValidationError::Unreachable {
                half_edge: HalfEdgeId(h as u32),
            }),
            None => Ok(()),
        }
    }
}
