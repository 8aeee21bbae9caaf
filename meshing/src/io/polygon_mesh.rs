//! Polygon meshes in files: reading OBJ, OFF and PLY faces as the polygons they are (STL gives
//! its triangles), writing polygons to OBJ, OFF and PLY, and triangulating them for formats that
//! only hold triangles (STL).
//!
//! The triangle readers and writers ([`read_mesh`](super::read_mesh),
//! [`write_mesh`](super::write_mesh)) share the format code; only what happens to a face differs.

use std::path::Path;

use glam::DVec3;

use super::faces::Polygons;
use super::{MeshFormat, MeshIoError, WriteOptions, read_mesh_bytes, triangulate_polygon};
use super::{obj, off, ply, write_atomic, write_mesh_with};
use crate::IndexedMesh;
use crate::halfedge::{HalfEdgeError, HalfEdgeMesh};

/// A mesh of polygonal faces (each a loop of at least three distinct vertex indices,
/// counter-clockwise seen from outside).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PolygonMesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Faces as vertex loops.
    pub faces: Vec<Vec<u32>>,
}

impl PolygonMesh {
    /// A polygon mesh from positions and faces.
    pub fn new(positions: Vec<DVec3>, faces: Vec<Vec<u32>>) -> Self {
        PolygonMesh { positions, faces }
    }

    /// The faces and positions of a half-edge mesh.
    pub fn from_half_edge(mesh: &HalfEdgeMesh) -> Self {
        PolygonMesh::new(mesh.positions().to_vec(), mesh.faces())
    }

    /// The half-edge mesh of these faces.
    ///
    /// # Errors
    /// See [`HalfEdgeError`]: non-manifold or inconsistently oriented faces, bad indices.
    pub fn to_half_edge(&self) -> Result<HalfEdgeMesh, HalfEdgeError> {
        HalfEdgeMesh::from_polygons(self.positions.clone(), &self.faces)
    }

    /// Triangles only, for formats and consumers that need them. Triangles are kept; larger
    /// faces are triangulated by [`triangulate_polygon`] (quads along a diagonal that keeps both
    /// halves facing like the quad, larger polygons by constrained Delaunay triangulation in
    /// their plane). A face too far from planar for that (a strongly bent quad or polygon) is
    /// split along its shorter diagonal (quads) or fanned around an added vertex at its centroid
    /// (larger faces), so every face gives triangles and a closed mesh stays closed.
    pub fn triangulated(&self) -> IndexedMesh {
        let mut positions = self.positions.clone();
        let mut triangles = Vec::with_capacity(self.faces.len() * 2);
        for face in &self.faces {
            if face.len() < 3 || triangulate_polygon(&positions, face, &mut triangles).is_ok() {
                continue;
            }
            let p = |k: usize| positions[face[k] as usize];
            if let [a, b, c, d] = face[..] {
                if p(0).distance_squared(p(2)) <= p(1).distance_squared(p(3)) {
                    triangles.extend([[a, b, c], [a, c, d]]);
                } else {
                    triangles.extend([[a, b, d], [b, c, d]]);
                }
                continue;
            }
            let centre =
                face.iter().map(|&i| positions[i as usize]).sum::<DVec3>() / face.len() as f64;
            let c = positions.len() as u32;
            positions.push(centre);
            for k in 0..face.len() {
                triangles.push([face[k], face[(k + 1) % face.len()], c]);
            }
        }
        IndexedMesh::new(positions, triangles)
    }

    /// Why the mesh cannot be written, if it cannot: a face of fewer than three corners, an
    /// index out of range, a non-finite coordinate.
    fn check_writable(&self) -> Result<(), String> {
        let count = self.positions.len();
        for (f, face) in self.faces.iter().enumerate() {
            if face.len() < 3 {
                return Err(format!("face {f} has {} corners (at least 3)", face.len()));
            }
            if let Some(&index) = face.iter().find(|&&i| i as usize >= count) {
                return Err(format!(
                    "face {f} refers to vertex {index} but the mesh has {count} vertices"
                ));
            }
        }
        match self.positions.iter().position(|p| !p.is_finite()) {
            Some(v) => Err(format!(
                "vertex {v} has a non-finite coordinate ({})",
                self.positions[v]
            )),
            None => Ok(()),
        }
    }
}

impl From<IndexedMesh> for PolygonMesh {
    fn from(mesh: IndexedMesh) -> Self {
        let faces = mesh.triangles.iter().map(|t| t.to_vec()).collect();
        PolygonMesh::new(mesh.positions, faces)
    }
}

/// Reads a mesh file with its polygonal faces kept (OBJ, OFF, PLY; an STL file gives its
/// triangles), in the format named by its extension. Errors as [`read_mesh`](super::read_mesh);
/// a face with fewer than three corners or a repeated vertex is reported at its line.
pub fn read_polygon_mesh(path: &Path) -> Result<PolygonMesh, MeshIoError> {
    let format = MeshFormat::from_path(path)?;
    let bytes = solidkit_kernel::files::read_regular_file(
        path,
        solidkit_kernel::files::DEFAULT_MAX_FILE_BYTES,
    )?;
    read_polygon_mesh_bytes(&bytes, format, &path.display().to_string())
}

/// Reads a polygon mesh from the content of a file; `name` stands for the file in messages.
pub fn read_polygon_mesh_bytes(
    bytes: &[u8],
    format: MeshFormat,
    name: &str,
) -> Result<PolygonMesh, MeshIoError> {
    let mut polygons = Polygons::default();
    let positions = match format {
        MeshFormat::Obj => obj::read_faces(bytes, name, &mut polygons)?,
        MeshFormat::Off => off::read_faces(bytes, name, &mut polygons)?,
        MeshFormat::Ply => ply::read_faces(bytes, name, &mut polygons)?,
        // Formats of triangles only.
        _ => return read_mesh_bytes(bytes, format, name).map(PolygonMesh::from),
    };
    Ok(PolygonMesh::new(positions, polygons.into_faces()))
}

/// Writes a polygon mesh in the format named by the extension of `path`, binary where the format
/// has a binary encoding; see [`write_polygon_mesh_with`].
pub fn write_polygon_mesh(path: &Path, mesh: &PolygonMesh) -> Result<(), MeshIoError> {
    write_polygon_mesh_with(path, mesh, &WriteOptions::default())
}

/// Writes a polygon mesh as `opts` says, atomically: OBJ, OFF and PLY keep the polygons;
/// formats of triangles only (STL) get [`PolygonMesh::triangulated`].
///
/// A mesh that would make an unreadable file (bad indices, non-finite coordinates) is refused
/// with [`MeshIoError::InvalidMesh`] and nothing is written.
pub fn write_polygon_mesh_with(
    path: &Path,
    mesh: &PolygonMesh,
    opts: &WriteOptions,
) -> Result<(), MeshIoError> {
    let format = match opts.format {
        Some(format) => format,
        None => MeshFormat::from_path(path)?,
    };
    let invalid = |message| MeshIoError::InvalidMesh {
        path: path.to_path_buf(),
        message,
    };
    mesh.check_writable().map_err(invalid)?;
    let (positions, faces) = (&mesh.positions, &mesh.faces);
    match format {
        MeshFormat::Obj => {
            write_atomic(path, |out| obj::write_faces(out, positions, faces, "faces"))
        }
        MeshFormat::Off => write_atomic(path, |out| off::write_faces(out, positions, faces)),
        MeshFormat::Ply => write_atomic(path, |out| {
            ply::write_faces(out, positions, faces, opts.encoding)
        }),
        _ => {
            let opts = WriteOptions {
                format: Some(format),
                ..*opts
            };
            write_mesh_with(path, &mesh.triangulated(), &opts)
        }
    }
}
