//! Loading the mesh files named by `mesh` nodes of JSON trees (and the PNG height maps of
//! `heightfield` nodes), and subdividing the polygon meshes of `subdivide` nodes.
//!
//! The kernel reads no mesh files and runs no subdivision itself (the readers and the half-edge
//! mesh live in `solidkit-meshing`, which depends on the kernel), so the JSON reader asks a
//! [`MeshResolver`] for them; `solidkit-meshing` provides one (`io::FileMeshResolver`) that reads
//! files relative to the tree file's folder (confined to it, see [`crate::files::FileAccess`]) and
//! subdivides on its half-edge mesh.

use super::request::SubdivisionRequest;
use super::resolve_error::{ResolveError, ResolveKind};
use crate::IndexedMesh;

/// Loads the mesh named by a `mesh` node's `path` and the height map of a `heightfield` node's
/// `png`, and subdivides `subdivide` nodes.
pub trait MeshResolver {
    /// The triangle mesh at `path` (as written in the tree), or why not.
    fn load(&self, path: &str) -> Result<IndexedMesh, ResolveError>;

    /// The bytes of the file at `path` (as written in the tree: a PNG height map), or a one-line
    /// reason why not. The default reads no files and says so.
    fn read_file(&self, path: &str) -> Result<Vec<u8>, ResolveError> {
        let _ = path;
        Err(ResolveError::message(
            ResolveKind::Unsupported,
            "files named in a tree need a resolver (read the tree with json::from_str_with and \
             solidkit_meshing::io::FileMeshResolver)",
        ))
    }

    /// The polygon mesh of `request` subdivided, as triangles counter-clockwise from outside, or
    /// a one-line reason why not. The default has no subdivision and says so.
    fn subdivide(&self, request: &SubdivisionRequest<'_>) -> Result<IndexedMesh, ResolveError> {
        let _ = request;
        Err(ResolveError::message(
            ResolveKind::Unsupported,
            "subdivision needs a resolver that runs it (read the tree with json::from_str_with and \
             solidkit_meshing::io::FileMeshResolver)",
        ))
    }
}

/// The resolver of [`json::from_str`](crate::json::from_str): it loads nothing and says that mesh
/// files need a resolver.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoMeshResolver;

impl MeshResolver for NoMeshResolver {
    fn load(&self, _path: &str) -> Result<IndexedMesh, ResolveError> {
        Err(ResolveError::message(
            ResolveKind::Unsupported,
            "mesh files need a resolver (read the tree with json::from_str_with)",
        ))
    }
}
