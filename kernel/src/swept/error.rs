//! Errors of the swept volume.

use crate::TransformError;

/// Why a swept volume cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweptError {
    /// The moving solid has no finite bounding box (a half-space, a gyroid).
    #[error("the swept solid must be bounded (its bounding box is infinite)")]
    UnboundedChild,
    /// The tolerance is not a positive finite number.
    #[error("tolerance: expected a positive number, found {0}")]
    Tolerance(f64),
    /// The path's points or derivatives are not finite.
    #[error("path: the path has non-finite points or derivatives")]
    Path,
    /// More copies than [`super::MAX_COPIES`] would be needed for the tolerance.
    #[error(
        "tolerance: {tolerance} needs about {needed} copies of the solid along the path, more \
         than the limit of {limit}; use a tolerance of at least {minimum:.3e}"
    )]
    TooManyCopies {
        /// The tolerance asked for (or the default).
        tolerance: f64,
        /// About how many copies it needs.
        needed: usize,
        /// The limit, [`super::MAX_COPIES`].
        limit: usize,
        /// A tolerance that fits within the limit.
        minimum: f64,
    },
    /// The copies would make a tree of more than [`super::MAX_TREE_NODES`] nodes (a large
    /// child, or swept volumes nested in swept volumes).
    #[error(
        "tolerance: {copies} copies of a child of {child_nodes} nodes make {nodes} nodes, more \
         than the limit of {limit}; use a larger tolerance or a smaller child"
    )]
    TooLarge {
        /// Copies the tolerance needs.
        copies: usize,
        /// Nodes of the child (a shared subtree counted once per use).
        child_nodes: usize,
        /// Nodes of the whole swept volume.
        nodes: usize,
        /// The limit, [`super::MAX_TREE_NODES`].
        limit: usize,
    },
    /// A placement of the solid along the path is not a valid transform (too far away).
    #[error("path: a placement of the solid is not a valid transform: {0}")]
    Transform(#[from] TransformError),
}

impl SweptError {
    /// The JSON key the error is about (`tolerance`, `path` or `child`).
    pub fn parameter(&self) -> &'static str {
        match self {
            SweptError::UnboundedChild => "child",
            SweptError::Tolerance(_)
            | SweptError::TooManyCopies { .. }
            | SweptError::TooLarge { .. } => "tolerance",
            SweptError::Path | SweptError::Transform(_) => "path",
        }
    }
}
