//! The mesh-file resolver of JSON trees: `mesh` nodes name their file by a path, read here with
//! [`read_mesh`](super::read_mesh) relative to a base folder (the folder of the tree file), so a
//! tree and its meshes can move together. It also carries out the `subdivide` nodes the kernel
//! records: the child's polygon mesh (inline faces, or a file read with its polygons by
//! [`read_polygon_mesh`](super::read_polygon_mesh)) becomes a [`HalfEdgeMesh`], is subdivided by
//! [`crate::subdivision`] within the default [`Limits`], and goes back triangulated
//! ([`PolygonMesh::triangulated`]).

use std::path::{Path, PathBuf};

use solidkit_kernel::IndexedMesh;
use solidkit_kernel::json::MeshResolver;
use solidkit_kernel::primitive::{SubdivisionInput, SubdivisionRequest};

use super::PolygonMesh;
use crate::HalfEdgeMesh;
use crate::subdivision::{Limits, subdivide};

/// Reads the mesh files of `mesh` nodes; relative paths are taken from `base`, absolute ones as
/// they are.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileMeshResolver {
    base: PathBuf,
}

impl FileMeshResolver {
    /// Resolves relative paths from the folder `base`.
    pub fn new(base: impl Into<PathBuf>) -> Self {
        Self { base: base.into() }
    }

    /// Resolves relative paths from the folder holding the tree file `tree`.
    pub fn for_tree_file(tree: &Path) -> Self {
        Self::new(tree.parent().unwrap_or(Path::new("")))
    }

    /// Where the mesh named `path` is read from.
    pub fn resolve(&self, path: &str) -> PathBuf {
        self.base.join(path)
    }
}

impl MeshResolver for FileMeshResolver {
    fn load(&self, path: &str) -> Result<IndexedMesh, String> {
        super::read_mesh(&self.resolve(path)).map_err(|e| e.to_string())
    }

    fn subdivide(&self, request: &SubdivisionRequest<'_>) -> Result<IndexedMesh, String> {
        let mesh = match request.input {
            SubdivisionInput::Faces { vertices, faces } => {
                HalfEdgeMesh::from_polygons(vertices.to_vec(), faces)
            }
            SubdivisionInput::File { path } => super::read_polygon_mesh(&self.resolve(path))
                .map_err(|e| e.to_string())?
                .to_half_edge(),
        }
        .map_err(|e| format!("cannot subdivide the child: {e}"))?;
        let result = subdivide(&mesh, request.scheme, request.levels, &Limits::default())
            .map_err(|e| e.to_string())?;
        Ok(PolygonMesh::from_half_edge(&result).triangulated())
    }
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
