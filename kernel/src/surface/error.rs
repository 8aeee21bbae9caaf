//! Why a surface node makes no solid.

use crate::primitive::MeshSolidError;

/// A surface or closure parameter that cannot be used, located by its JSON key.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    /// A parameter is invalid.
    #[error("{problem}")]
    Invalid {
        /// The JSON key it is about.
        key: &'static str,
        /// What is wrong.
        problem: String,
    },
    /// The mesh of a `pn_triangles` node could not be loaded or is invalid.
    #[error(transparent)]
    Mesh(#[from] MeshSolidError),
}

impl SurfaceError {
    /// An invalid parameter.
    pub fn invalid(key: &'static str, problem: impl Into<String>) -> Self {
        SurfaceError::Invalid {
            key,
            problem: problem.into(),
        }
    }

    /// The JSON key the error is about.
    pub fn key(&self) -> &'static str {
        match self {
            SurfaceError::Invalid { key, .. } => key,
            SurfaceError::Mesh(MeshSolidError::Load { .. }) => "path",
            SurfaceError::Mesh(_) => "triangles",
        }
    }
}
