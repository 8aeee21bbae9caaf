//! Errors of exact polyhedra: invalid vertex and face lists, faces that cannot be triangulated,
//! surfaces that are not closed oriented manifolds where one is needed, bad prism parameters.

use super::TriangulationError;

/// Why a polyhedron cannot be built (or an operation on it cannot be done).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PolyhedronError {
    /// There are no faces.
    #[error("the polyhedron has no faces")]
    NoFaces,
    /// A vertex has a NaN or infinite coordinate (or, in a mesh solid, one beyond
    /// [`crate::primitive::MAX_MAGNITUDE`]).
    #[error("vertex {vertex} has a non-finite coordinate or one beyond ±1e30")]
    NonFiniteVertex {
        /// The vertex index.
        vertex: usize,
    },
    /// More triangles than a mesh solid's tree can index.
    #[error("too many triangles: {count} (at most {max})")]
    TooManyFaces {
        /// Number of triangles.
        count: usize,
        /// The largest number allowed.
        max: usize,
    },
    /// A face has fewer than three corners.
    #[error("face {face} has {corners} corners (at least 3 needed)")]
    TooFewCorners {
        /// The face index.
        face: usize,
        /// Its number of corners.
        corners: usize,
    },
    /// A face refers to a vertex that does not exist.
    #[error("face {face} refers to vertex {index} but there are only {count} vertices")]
    IndexOutOfRange {
        /// The face index.
        face: usize,
        /// The bad vertex index.
        index: u32,
        /// The number of vertices.
        count: usize,
    },
    /// A face uses the same vertex twice.
    #[error("face {face} uses vertex {index} more than once")]
    RepeatedCorner {
        /// The face index.
        face: usize,
        /// The repeated vertex index.
        index: u32,
    },
    /// A polygonal face cannot be triangulated.
    #[error("face {face}: {problem}")]
    BadFace {
        /// The face index.
        face: usize,
        /// What is wrong with it.
        problem: TriangulationError,
    },
    /// Two faces traverse the same edge in the same direction.
    #[error(
        "edge {from}→{to} is used twice in the same direction (faces not consistently oriented, \
         or an edge shared by more than two faces)"
    )]
    RepeatedEdge {
        /// Start vertex.
        from: u32,
        /// End vertex.
        to: u32,
    },
    /// An edge has no face on its other side.
    #[error("edge {from}→{to} has no opposite edge (the surface is not closed)")]
    OpenEdge {
        /// Start vertex.
        from: u32,
        /// End vertex.
        to: u32,
    },
    /// The faces around a vertex form more than one fan.
    #[error("vertex {vertex} is not manifold (its faces form more than one fan)")]
    NonManifoldVertex {
        /// The vertex index.
        vertex: u32,
    },
    /// A vertex lies outside the plane of a face (the polyhedron is not convex).
    #[error("not convex: vertex {vertex} lies outside the plane of face {face}")]
    NotConvex {
        /// The face index.
        face: usize,
        /// The vertex index.
        vertex: usize,
    },
    /// A size parameter is not a finite positive number.
    #[error("{parameter}: expected a finite positive number")]
    InvalidSize {
        /// The parameter's name.
        parameter: &'static str,
    },
    /// A loop of a prism's cross-section cannot be triangulated; `part` is `polygon` or
    /// `holes` (the problem may involve several loops).
    #[error("{part}: {problem}")]
    BadCrossSection {
        /// `polygon` or `holes`.
        part: &'static str,
        /// What is wrong.
        problem: TriangulationError,
    },
    /// A prism's sweep direction does not leave the plane of its cross-section.
    #[error("direction: expected a finite vector with a non-zero z component")]
    FlatDirection,
}
