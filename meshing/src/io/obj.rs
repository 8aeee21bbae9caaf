//! Wavefront OBJ reading (with `tobj`) and writing.
//!
//! Only positions and faces matter: texture coordinates, normals, materials, points and
//! polylines are ignored, and no `.mtl` file is ever opened. The file is first checked by our
//! own line scanner ([`super::obj_scan`]), which locates problems by line because `tobj` does
//! not. The objects and groups `tobj` returns are merged into one mesh; since `tobj` numbers
//! the vertices of each object separately, a vertex shared by two objects is re-joined by
//! position (bit-identical positions only, and only across objects). Vertices come out in
//! order of first use by a face (file order for most files); vertices no face uses are dropped. Polygonal faces are triangulated by
//! [`super::triangulate_polygon`] (or kept as polygons by [`read_faces`] with a polygon sink); a
//! face that cannot be is reported at its line.
//!
//! Without its `use_f64` feature `tobj` reads coordinates as `f32`, so OBJ positions have
//! single precision (exact for values an `f32` represents); the writer still prints full
//! `f64` precision for other tools.

use std::io::{self, Write};

use glam::DVec3;

use super::faces::FaceSink;
use super::obj_scan::{self, Bound, FaceLine};
use super::weld::Welder;
use super::{Location, MeshIoError};
use crate::IndexedMesh;

/// Reads an OBJ file's faces into `sink`; returns the positions.
pub(super) fn read_faces(
    bytes: &[u8],
    name: &str,
    sink: &mut dyn FaceSink,
) -> Result<Vec<DVec3>, MeshIoError> {
    let face_lines = obj_scan::scan(bytes, name, Bound::WholeFile)?;
    let models = load_models(bytes, name)?;
    assemble(&models, &face_lines, name, sink)
}

/// Parses with `tobj`: polygons kept as polygons, positions indexed on their own, no materials.
fn load_models(bytes: &[u8], name: &str) -> Result<Vec<tobj::Model>, MeshIoError> {
    #[allow(
        clippy::needless_update,
        reason = "tobj features enabled elsewhere in the build add fields"
    )]
    let options = tobj::LoadOptions {
        triangulate: false,
        single_index: false,
        ignore_points: true,
        ignore_lines: true,
        ..Default::default()
    };
    let mut reader = bytes;
    let no_materials = |_: &std::path::Path| Err(tobj::LoadError::OpenFileFailed);
    match tobj::load_obj_buf(&mut reader, &options, no_materials) {
        // Material errors are irrelevant: we never load materials.
        Ok((models, _materials)) => Ok(models),
        Err(error) => Err(locate(bytes, name, error)),
    }
}

/// Turns a `tobj` error into one with a line number when the scanner can find the line.
fn locate(bytes: &[u8], name: &str, error: tobj::LoadError) -> MeshIoError {
    match obj_scan::scan(bytes, name, Bound::SoFar) {
        Err(located) => located,
        Ok(_) => MeshIoError::invalid(name, error.to_string()),
    }
}

/// Merges the models into one mesh and gives their faces to `sink`.
fn assemble(
    models: &[tobj::Model],
    face_lines: &[FaceLine],
    name: &str,
    sink: &mut dyn FaceSink,
) -> Result<Vec<DVec3>, MeshIoError> {
    let mut welder = Welder::default();
    let mut lines = face_lines.iter();
    let mismatch = || MeshIoError::invalid(name, "tobj returned other faces than the file has");
    for model in models {
        let local_to_global = join_vertices(&model.mesh, &mut welder, name)?;
        for corners in face_slices(&model.mesh).ok_or_else(mismatch)? {
            let face_line = lines.next().ok_or_else(mismatch)?;
            if face_line.polyline {
                continue;
            }
            let global = corners
                .iter()
                .map(|&i| local_to_global.get(i as usize).copied())
                .collect::<Option<Vec<u32>>>()
                .ok_or_else(mismatch)?;
            sink.add(welder.positions(), &global).map_err(|e| {
                MeshIoError::parse(name, Location::Line(face_line.line), e.to_string())
            })?;
        }
    }
    if lines.next().is_some() {
        return Err(mismatch());
    }
    Ok(drop_unused(welder.into_positions(), sink.corners_mut()))
}

/// Drops the vertices no face uses (the points of dropped polylines), keeping the order of the
/// others and renumbering `corners`.
fn drop_unused(positions: Vec<DVec3>, corners: &mut [u32]) -> Vec<DVec3> {
    let mut used = vec![false; positions.len()];
    for &corner in corners.iter() {
        if let Some(flag) = used.get_mut(corner as usize) {
            *flag = true;
        }
    }
    if used.iter().all(|&u| u) {
        return positions;
    }
    let mut new_index = vec![0u32; positions.len()];
    let mut kept = Vec::with_capacity(positions.len());
    for (old, position) in positions.into_iter().enumerate() {
        if used[old] {
            new_index[old] = kept.len() as u32;
            kept.push(position);
        }
    }
    for corner in corners.iter_mut() {
        *corner = new_index.get(*corner as usize).copied().unwrap_or(*corner);
    }
    kept
}

/// Adds the vertices of one model; a position seen in an earlier model is that model's vertex.
fn join_vertices(
    mesh: &tobj::Mesh,
    welder: &mut Welder,
    name: &str,
) -> Result<Vec<u32>, MeshIoError> {
    let earlier_models = welder.positions().len();
    let too_many = || MeshIoError::invalid(name, "more vertices than 32-bit indices can address");
    mesh.positions
        .chunks_exact(3)
        .map(|xyz| {
            let p = DVec3::new(xyz[0], xyz[1], xyz[2]);
            if !p.is_finite() {
                return Err(MeshIoError::invalid(
                    name,
                    "a coordinate is not a finite number",
                ));
            }
            match welder.find(p) {
                Some(shared) if (shared as usize) < earlier_models => Ok(shared),
                _ => welder.push(p).ok_or_else(too_many),
            }
        })
        .collect()
}

/// The corner lists of a `tobj` mesh (no arities means all triangles); `None` if inconsistent.
fn face_slices(mesh: &tobj::Mesh) -> Option<Vec<&[u32]>> {
    if mesh.face_arities.is_empty() {
        let chunks = mesh.indices.chunks_exact(3);
        return chunks.remainder().is_empty().then(|| chunks.collect());
    }
    let mut start = 0usize;
    let mut faces = Vec::with_capacity(mesh.face_arities.len());
    for &arity in &mesh.face_arities {
        let end = start.checked_add(arity as usize)?;
        faces.push(mesh.indices.get(start..end)?);
        start = end;
    }
    (start == mesh.indices.len()).then_some(faces)
}

/// Writes `v x y z` and 1-based `f a b c` lines under a comment header.
pub(super) fn write(out: &mut dyn Write, mesh: &IndexedMesh) -> io::Result<()> {
    write_faces(out, &mesh.positions, &mesh.triangles, "triangles")
}

/// Writes `v x y z` and 1-based `f a b c …` lines (faces of any size) under a comment header
/// that counts the faces as `noun`.
pub(super) fn write_faces<F: AsRef<[u32]>>(
    out: &mut dyn Write,
    positions: &[DVec3],
    faces: &[F],
    noun: &str,
) -> io::Result<()> {
    writeln!(out, "# written by solidkit")?;
    writeln!(
        out,
        "# {} vertices, {} {noun}",
        positions.len(),
        faces.len()
    )?;
    for p in positions {
        writeln!(out, "v {} {} {}", p.x, p.y, p.z)?;
    }
    for face in faces {
        out.write_all(b"f")?;
        for &i in face.as_ref() {
            write!(out, " {}", u64::from(i) + 1)?;
        }
        writeln!(out)?;
    }
    Ok(())
}
