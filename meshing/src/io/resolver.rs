//! The file resolver of JSON trees: `mesh` nodes name their file by a path, and `heightfield`
//! nodes their PNG height map, read here relative to a base folder (the folder of the tree file),
//! so a tree and its files can move together. Paths are confined by a [`FileAccess`]: they must
//! stay inside that folder (or a folder the user allowed) once `..` and symbolic links are
//! resolved, absolute paths are refused, and only regular files within the size cap are read.
//! Mesh files are parsed by [`read_mesh_bytes`](super::read_mesh_bytes) in the format of the
//! extension written in the tree; errors name the file as the tree writes it.
//!
//! It also carries out the `subdivide` nodes the kernel records: the child's polygon mesh (inline
//! faces, or a file read the same way with its polygons by
//! [`read_polygon_mesh_bytes`](super::read_polygon_mesh_bytes)) becomes a [`HalfEdgeMesh`], is
//! subdivided by [`crate::subdivision`] within the default [`Limits`], and goes back triangulated
//! ([`PolygonMesh::triangulated`]).

use std::path::{Path, PathBuf};

use solidkit_kernel::IndexedMesh;
use solidkit_kernel::files::{FileAccess, FileError};
use solidkit_kernel::json::MeshResolver;
use solidkit_kernel::primitive::{ResolveError, ResolveKind, SubdivisionInput, SubdivisionRequest};

use super::{MeshFormat, MeshIoError, PolygonMesh};
use crate::HalfEdgeMesh;
use crate::subdivision::{Limits, subdivide, subdivide_adaptive};

/// Reads the files of `mesh` and `heightfield` nodes as its [`FileAccess`] allows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileMeshResolver {
    access: FileAccess,
}

impl FileMeshResolver {
    /// Resolves relative paths from the folder `base`, confined to it.
    pub fn new(base: impl Into<PathBuf>) -> Self {
        Self::with_access(FileAccess::new(base))
    }

    /// Resolves relative paths from the folder holding the tree file `tree`, confined to it.
    pub fn for_tree_file(tree: &Path) -> Self {
        Self::with_access(FileAccess::for_tree_file(tree))
    }

    /// Resolves and reads as `access` says.
    pub fn with_access(access: FileAccess) -> Self {
        Self { access }
    }

    /// The rule files are read by.
    pub fn access(&self) -> &FileAccess {
        &self.access
    }

    /// Where the file named `path` is read from, or why it may not be read.
    pub fn resolve(&self, path: &str) -> Result<PathBuf, FileError> {
        self.access.resolve(path)
    }

    /// The bytes and format of the mesh file named `path` in a tree.
    fn mesh_bytes(&self, path: &str) -> Result<(MeshFormat, Vec<u8>), MeshIoError> {
        let format = MeshFormat::from_path(Path::new(path))?;
        let (_, bytes) = self.access.read(path)?;
        Ok((format, bytes))
    }
}

impl MeshResolver for FileMeshResolver {
    fn load(&self, path: &str) -> Result<IndexedMesh, ResolveError> {
        let (format, bytes) = self.mesh_bytes(path).map_err(file_error)?;
        super::read_mesh_bytes(&bytes, format, path)
            .map_err(|e| ResolveError::new(ResolveKind::Format, e))
    }

    fn read_file(&self, path: &str) -> Result<Vec<u8>, ResolveError> {
        self.access
            .read(path)
            .map(|(_, bytes)| bytes)
            .map_err(|e| ResolveError::new(ResolveKind::File, e))
    }

    fn subdivide(&self, request: &SubdivisionRequest<'_>) -> Result<IndexedMesh, ResolveError> {
        let mesh = match request.input {
            SubdivisionInput::Faces { vertices, faces } => {
                HalfEdgeMesh::from_polygons(vertices.to_vec(), faces)
            }
            SubdivisionInput::File { path } => {
                let (format, bytes) = self.mesh_bytes(path).map_err(file_error)?;
                super::read_polygon_mesh_bytes(&bytes, format, path)
                    .map_err(|e| ResolveError::new(ResolveKind::Format, e))?
                    .to_half_edge()
            }
        }
        .map_err(|e| {
            ResolveError::message(
                ResolveKind::Subdivision,
                format!("cannot subdivide the child: {e}"),
            )
        })?;
        let result = match request.adaptive {
            None => subdivide(&mesh, request.scheme, request.levels, &Limits::default()),
            Some(t) => {
                subdivide_adaptive(&mesh, request.scheme, request.levels, t, &Limits::default())
                    .map(|(m, _)| m)
            }
        }
        .map_err(|e| ResolveError::new(ResolveKind::Subdivision, e))?;
        Ok(PolygonMesh::from_half_edge(&result).triangulated())
    }
}

/// A mesh file that could not be read (`ResolveKind::File`) or whose extension names no format
/// (`ResolveKind::Format`), with the reader's error inside.
fn file_error(e: MeshIoError) -> ResolveError {
    let kind = match e {
        MeshIoError::Io { .. } | MeshIoError::File(_) => ResolveKind::File,
        _ => ResolveKind::Format,
    };
    ResolveError::new(kind, e)
}

#[cfg(test)]
mod tests {
    use super::*;
    use solidkit_kernel::json;

    #[test]
    fn tree_files_find_meshes_next_to_them() {
        let dir = tempfile::tempdir().unwrap();
        let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        std::fs::create_dir(dir.path().join("parts")).unwrap();
        std::fs::write(dir.path().join("parts/tet.obj"), obj).unwrap();
        let tree = dir.path().join("tree.json");
        let resolver = FileMeshResolver::for_tree_file(&tree);
        let text = r#"{"type": "mesh", "path": "parts/tet.obj"}"#;
        let solid = json::from_str_with(text, &resolver).unwrap();
        assert!(solid.value(glam::DVec3::splat(0.1)) < 0.0);
        assert!(solid.value(glam::DVec3::splat(1.0)) > 0.0);
        let err = json::from_str_with(r#"{"type": "mesh", "path": "nope.obj"}"#, &resolver)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("path: cannot load \"nope.obj\"") && err.contains("nope.obj"),
            "{err}"
        );
    }
}
