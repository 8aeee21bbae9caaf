//! Mesh file input and output: STL (binary and ASCII), Wavefront OBJ, PLY (ASCII and binary)
//! and OFF, to and from [`IndexedMesh`]; 3MF and glTF binary (`.glb`) too (3MF packages may be
//! stored or deflated; build items, components and GLB node transforms are applied).
//!
//! The format follows the file extension (`.stl`, `.obj`, `.ply`, `.off`, `.3mf`, `.glb`, any
//! case). Readers
//! never panic, whatever the bytes: every problem is a [`MeshIoError`] whose message is one line
//! naming the file, the line or byte offset and the problem. Coordinates must be finite and
//! every face index in range. Polygonal faces are triangulated by [`triangulate_polygon`]
//! (never as fans), and the vertices of an STL file (which has no shared vertices) are welded
//! where bit-identical, so a closed STL becomes a closed indexed mesh.
//!
//! Files are read by [`read_regular_file`]: regular files only, at most
//! [`DEFAULT_MAX_FILE_BYTES`] (1 GiB); files named in trees go through [`FileMeshResolver`],
//! which confines them to the tree's folder. An error about a file that is not of the expected
//! format never quotes its content.
//!
//! Writers go through [`write_atomic`]: a failed write leaves no partial file behind and an
//! existing file untouched.
//!
//! [`read_polygon_mesh`] and [`write_polygon_mesh`] do the same for a [`PolygonMesh`], keeping
//! polygonal faces where the format has them (OBJ, OFF, PLY).

mod atomic;
mod bytes;
mod error;
mod faces;
mod glb;
mod glb_read;
mod gltf_json;
pub(crate) mod key_hash;
mod obj;
mod obj_scan;
mod off;
mod ply;
mod ply_colors;
mod ply_header;
mod ply_scalars;
mod polygon;
mod polygon_mesh;
mod resolver;
mod single_precision;
mod stl;
mod stored;
mod text;
mod threemf;
mod threemf_model;
mod threemf_read;
mod unzip;
mod weld;
mod weld_parallel;
mod xml;
mod zip;

#[cfg(test)]
mod color_tests;
#[cfg(test)]
mod container_tests;
#[cfg(test)]
mod polygon_mesh_tests;
#[cfg(test)]
mod tests;

use std::io::Write;
use std::path::Path;

use crate::IndexedMesh;
use solidkit_kernel::files::{DEFAULT_MAX_FILE_BYTES, read_regular_file};

use crate::colors::FaceColors;
pub use atomic::{StagedFile, remove_temporary_files_and_exit, stage_atomic, write_atomic};
pub use error::{Location, MeshIoError};
pub use ply_scalars::write_ply_with_scalars;
pub use polygon::{PolygonError, newell_normal, triangulate_polygon};
pub use polygon_mesh::{
    PolygonMesh, read_polygon_mesh, read_polygon_mesh_bytes, write_polygon_mesh,
    write_polygon_mesh_with,
};
pub use resolver::FileMeshResolver;
pub use single_precision::{is_single_precision, single_precision_collisions};
pub use stl::binary_records as stl_binary_records;
pub use stored::{encode_mesh, stored_mesh};
pub use threemf::MODEL_PATH as THREEMF_MODEL_PATH;
pub use zip::crc32;

/// A mesh file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    /// STL, binary or ASCII (triangles only, no shared vertices, 32-bit floats).
    Stl,
    /// Wavefront OBJ (positions and polygonal faces; everything else is ignored).
    Obj,
    /// Stanford PLY, ASCII or binary (`vertex` and `face` elements).
    Ply,
    /// Object File Format (OFF).
    Off,
    /// 3D Manufacturing Format (zip package with the model XML).
    ThreeMf,
    /// glTF 2.0 binary (32-bit float positions; 32-bit indices when written).
    Glb,
}

impl MeshFormat {
    /// The format named by the extension of `path` (case-insensitive).
    pub fn from_path(path: &Path) -> Result<MeshFormat, MeshIoError> {
        path.extension()
            .and_then(|ext| ext.to_str())
            .and_then(MeshFormat::from_extension)
            .ok_or_else(|| MeshIoError::UnsupportedFormat {
                path: path.to_path_buf(),
            })
    }

    /// Whether the writers store per-triangle colours in this format (3MF, PLY, GLB, OFF).
    pub fn carries_colors(self) -> bool {
        matches!(
            self,
            MeshFormat::Ply | MeshFormat::ThreeMf | MeshFormat::Glb | MeshFormat::Off
        )
    }

    /// The format of a file extension without the dot (`"stl"`, `"OBJ"`, ...), case-insensitive.
    pub fn from_extension(extension: &str) -> Option<MeshFormat> {
        let lower = extension.to_ascii_lowercase();
        match lower.as_str() {
            "stl" => Some(MeshFormat::Stl),
            "obj" => Some(MeshFormat::Obj),
            "ply" => Some(MeshFormat::Ply),
            "off" => Some(MeshFormat::Off),
            "3mf" => Some(MeshFormat::ThreeMf),
            "glb" => Some(MeshFormat::Glb),
            _ => None,
        }
    }

    /// The usual file extension, lower case and without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            MeshFormat::Stl => "stl",
            MeshFormat::Obj => "obj",
            MeshFormat::Ply => "ply",
            MeshFormat::Off => "off",
            MeshFormat::ThreeMf => "3mf",
            MeshFormat::Glb => "glb",
        }
    }
}

/// Binary or text encoding, for the formats that have both (STL and PLY); OBJ and OFF are always
/// text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Encoding {
    /// Binary (little endian for PLY): compact and exact.
    #[default]
    Binary,
    /// Human-readable text.
    Ascii,
}

/// How [`write_mesh_with`] writes a file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WriteOptions {
    /// The format; `None` takes it from the file extension.
    pub format: Option<MeshFormat>,
    /// Binary (default) or ASCII, for STL and PLY; ignored by OBJ and OFF.
    pub encoding: Encoding,
}

/// Reads a mesh file, in the format named by its extension: a regular file (no device, FIFO or
/// directory) of at most [`DEFAULT_MAX_FILE_BYTES`].
pub fn read_mesh(path: &Path) -> Result<IndexedMesh, MeshIoError> {
    let format = MeshFormat::from_path(path)?;
    let bytes = read_regular_file(path, DEFAULT_MAX_FILE_BYTES)?;
    read_mesh_bytes(&bytes, format, &path.display().to_string())
}

/// Reads a mesh from the content of a file; `name` stands for the file in error messages.
pub fn read_mesh_bytes(
    bytes: &[u8],
    format: MeshFormat,
    name: &str,
) -> Result<IndexedMesh, MeshIoError> {
    match format {
        MeshFormat::Stl => stl::read(bytes, name),
        MeshFormat::Obj => faces::triangles(bytes, name, obj::read_faces),
        MeshFormat::Ply => faces::triangles(bytes, name, ply::read_faces),
        MeshFormat::Off => faces::triangles(bytes, name, off::read_faces),
        MeshFormat::ThreeMf => threemf_read::read(bytes, name),
        MeshFormat::Glb => glb_read::read(bytes, name),
    }
}

/// Writes a mesh in the format named by the extension of `path`, binary where the format has a
/// binary encoding (STL, PLY).
pub fn write_mesh(path: &Path, mesh: &IndexedMesh) -> Result<(), MeshIoError> {
    write_mesh_with(path, mesh, &WriteOptions::default())
}

/// Writes a mesh as `opts` says, atomically (see [`write_atomic`]).
///
/// The mesh is checked first (indices in range, finite coordinates, and for STL coordinates that
/// fit in 32-bit floats); a mesh that would make an unreadable file is refused with
/// [`MeshIoError::InvalidMesh`] and nothing is written.
pub fn write_mesh_with(
    path: &Path,
    mesh: &IndexedMesh,
    opts: &WriteOptions,
) -> Result<(), MeshIoError> {
    let format = match opts.format {
        Some(format) => format,
        None => MeshFormat::from_path(path)?,
    };
    check_writable(mesh, format).map_err(|message| MeshIoError::InvalidMesh {
        path: path.to_path_buf(),
        message,
    })?;
    write_atomic(path, |out| encode(out, mesh, format, opts.encoding))
}

/// Writes a mesh with per-triangle colours as [`write_mesh_with`] does: 3MF (`<basematerials>`),
/// PLY (face `red green blue alpha`), GLB (one primitive and material per colour) and OFF
/// (`3 i j k r g b a` per face, 0..=255) carry them; STL and OBJ are written without. `colors: None` writes exactly what
/// [`write_mesh_with`] writes.
pub fn write_colored_mesh_with(
    path: &Path,
    mesh: &IndexedMesh,
    colors: Option<&FaceColors>,
    opts: &WriteOptions,
) -> Result<(), MeshIoError> {
    stage_colored_mesh_with(path, mesh, colors, opts)?.commit()
}

/// [`write_colored_mesh_with`] up to the disk sync and the rename ([`stage_atomic`]): the file is
/// complete under a temporary name, and appears at `path` only when the returned [`StagedFile`]
/// is committed (dropped, it is removed).
pub fn stage_colored_mesh_with(
    path: &Path,
    mesh: &IndexedMesh,
    colors: Option<&FaceColors>,
    opts: &WriteOptions,
) -> Result<StagedFile, MeshIoError> {
    let format = match opts.format {
        Some(format) => format,
        None => MeshFormat::from_path(path)?,
    };
    check_writable(mesh, format).map_err(|message| MeshIoError::InvalidMesh {
        path: path.to_path_buf(),
        message,
    })?;
    stage_atomic(path, |out| {
        encode_colored(out, mesh, colors, format, opts.encoding)
    })
}

/// Writes `mesh` to `out` in `format` (the mesh must pass [`check_writable`]).
fn encode(
    out: &mut dyn Write,
    mesh: &IndexedMesh,
    format: MeshFormat,
    encoding: Encoding,
) -> std::io::Result<()> {
    encode_colored(out, mesh, None, format, encoding)
}

/// [`encode`] with optional per-triangle colours.
pub(crate) fn encode_colored(
    out: &mut dyn Write,
    mesh: &IndexedMesh,
    colors: Option<&FaceColors>,
    format: MeshFormat,
    encoding: Encoding,
) -> std::io::Result<()> {
    match (format, colors) {
        (MeshFormat::Stl, _) => stl::write(out, mesh, encoding),
        (MeshFormat::Obj, _) => obj::write(out, mesh),
        (MeshFormat::Ply, Some(c)) => ply_colors::write(out, mesh, c, encoding),
        (MeshFormat::Ply, None) => ply::write(out, mesh, encoding),
        (MeshFormat::Off, Some(c)) => off::write_colored(out, mesh, c),
        (MeshFormat::Off, None) => off::write(out, mesh),
        (MeshFormat::ThreeMf, c) => threemf::write(out, mesh, c),
        (MeshFormat::Glb, c) => glb::write(out, mesh, c),
    }
}

/// Why `mesh` cannot be written as `format`, if it cannot.
fn check_writable(mesh: &IndexedMesh, format: MeshFormat) -> Result<(), String> {
    let count = mesh.positions.len();
    for (t, triangle) in mesh.triangles.iter().enumerate() {
        if let Some(&index) = triangle.iter().find(|&&i| i as usize >= count) {
            return Err(format!(
                "triangle {t} refers to vertex {index} but the mesh has {count} vertices"
            ));
        }
    }
    if let Some(v) = mesh.positions.iter().position(|p| !p.is_finite()) {
        return Err(format!(
            "vertex {v} has a non-finite coordinate ({})",
            mesh.positions[v]
        ));
    }
    match format {
        MeshFormat::Stl => stl::check_writable(mesh),
        MeshFormat::Glb => glb::check_writable(mesh),
        MeshFormat::Obj | MeshFormat::Ply | MeshFormat::Off | MeshFormat::ThreeMf => Ok(()),
    }
}

/// `mesh` with its positions rounded to `f32`, as a GLB file stores them.
fn glb_rounded(mesh: &IndexedMesh) -> IndexedMesh {
    IndexedMesh::new(
        mesh.positions
            .iter()
            .map(|p| p.as_vec3().as_dvec3())
            .collect(),
        mesh.triangles.clone(),
    )
}
