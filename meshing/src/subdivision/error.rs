//! Why a subdivision request cannot be carried out.

use super::Scheme;
use crate::halfedge::HalfEdgeError;

/// A subdivision that cannot be carried out.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SubdivisionError {
    /// Loop and butterfly subdivide triangle meshes only (the first other face).
    #[error(
        "{scheme} subdivision needs a triangle mesh, but face {face} has {corners} corners \
         (use catmull-clark or doo-sabin for polygon meshes)"
    )]
    NotTriangles {
        /// The scheme asked for.
        scheme: Scheme,
        /// The first face that is not a triangle.
        face: usize,
        /// Its number of corners.
        corners: usize,
    },
    /// Some level would have more faces than the limit allows (nothing was computed).
    #[error(
        "{scheme} subdivision to {levels} levels would make {faces} faces at level {level}, more \
         than the limit of {limit}"
    )]
    TooLarge {
        /// The scheme asked for.
        scheme: Scheme,
        /// The levels asked for.
        levels: u32,
        /// The first level over the limit.
        level: u32,
        /// Its (predicted) face count.
        faces: u64,
        /// The limit.
        limit: u64,
    },
    /// Adaptive subdivision runs Loop and Catmull-Clark only.
    #[error("adaptive subdivision supports loop and catmull-clark, not {scheme}")]
    NotAdaptive {
        /// The scheme asked for.
        scheme: Scheme,
    },
    /// The adaptive tolerance is not a positive finite number (as written).
    #[error("the adaptive tolerance must be a positive finite number, got {0}")]
    Tolerance(String),
    /// A level's faces did not form a half-edge mesh (a bug, reported instead of a panic).
    #[error("subdivision made faces that do not form a manifold mesh: {0}")]
    Rebuild(#[from] HalfEdgeError),
}
