//! Meshes as files store them: encoding to bytes in memory, and the mesh a reader of those bytes
//! gets back (STL rounds to `f32` and welds equal positions, GLB rounds to `f32`, the other
//! formats keep every `f64` and every index).

use super::{MeshFormat, MeshIoError, WriteOptions, check_writable, encode, glb_rounded};
use crate::IndexedMesh;

/// The bytes of `mesh` written as `opts` says (`opts.format` must be set), checked as
/// [`write_mesh_with`](super::write_mesh_with) checks it; `name` stands for the file in errors.
pub fn encode_mesh(
    mesh: &IndexedMesh,
    opts: &WriteOptions,
    name: &str,
) -> Result<Vec<u8>, MeshIoError> {
    let format = opts
        .format
        .ok_or_else(|| MeshIoError::invalid(name, "no output format given"))?;
    check_writable(mesh, format).map_err(|message| MeshIoError::InvalidMesh {
        path: name.into(),
        message,
    })?;
    let mut bytes = Vec::new();
    encode(&mut bytes, mesh, format, opts.encoding).map_err(|source| MeshIoError::Io {
        path: name.into(),
        source,
    })?;
    Ok(bytes)
}

/// The mesh a reader of `bytes` (the encoding of `mesh` as `format`) gets: read back from the
/// bytes for STL, OBJ, PLY and OFF; without parsing, `mesh` with positions rounded to `f32` for
/// GLB and `mesh` itself for 3MF (exact decimal coordinates), which is what the 3MF and GLB
/// readers give for these bytes (the I/O tests check it).
pub fn stored_mesh(
    bytes: &[u8],
    mesh: &IndexedMesh,
    format: MeshFormat,
    name: &str,
) -> Result<IndexedMesh, MeshIoError> {
    match format {
        MeshFormat::ThreeMf => Ok(mesh.clone()),
        MeshFormat::Glb => Ok(glb_rounded(mesh)),
        _ => super::read_mesh_bytes(bytes, format, name),
    }
}
