//! Loading the mesh files named by `mesh` nodes of JSON trees.
//!
//! The kernel reads no mesh files itself (the readers live in `solidkit-meshing`, which depends on
//! the kernel), so the JSON reader asks a [`MeshResolver`] for them; `solidkit-meshing` provides
//! one that reads files relative to the tree file's folder.

use crate::IndexedMesh;

/// Loads the mesh named by a `mesh` node's `path`.
pub trait MeshResolver {
    /// The triangle mesh at `path` (as written in the tree), or a one-line reason why not.
    fn load(&self, path: &str) -> Result<IndexedMesh, String>;
}

/// The resolver of [`json::from_str`](crate::json::from_str): it loads nothing and says that mesh
/// files need a resolver.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoMeshResolver;

impl MeshResolver for NoMeshResolver {
    fn load(&self, _path: &str) -> Result<IndexedMesh, String> {
        Err("mesh files need a resolver (read the tree with json::from_str_with)".into())
    }
}
