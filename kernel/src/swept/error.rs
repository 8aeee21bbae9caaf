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
    /// A placement of the solid along the path is not a valid transform (too far away).
    #[error("path: a placement of the solid is not a valid transform: {0}")]
    Transform(#[from] TransformError),
}

impl SweptError {
    /// The JSON key the error is about (`tolerance`, `path` or `child`).
    pub fn parameter(&self) -> &'static str {
        match self {
            SweptError::UnboundedChild => "child",
            SweptError::Tolerance(_) | SweptError::TooManyCopies { .. } => "tolerance",
            SweptError::Path | SweptError::Transform(_) => "path",
        }
    }
}
