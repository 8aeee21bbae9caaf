//! What `solidkit mesh` adds around a mesh on both of its paths (grid and polyhedral): the
//! single-precision warning for STL and GLB outputs and the `--preview` picture.

use crate::args::MeshArgs;
use anyhow::Result;
use solidkit_meshing::io::{MeshFormat, is_single_precision, single_precision_collisions};

/// `--preview`: the mesh written, rasterised (iso view, 1024 x 1024).
pub(super) fn write_preview(
    mesh: &solidkit_meshing::IndexedMesh,
    path: &std::path::Path,
) -> Result<()> {
    use solidkit_meshing::render::{Camera, ImageSize, View, png_out, raster, shade};
    let frame = super::render::mesh_box(&mesh.positions);
    let size = ImageSize::new(1024, 1024)?;
    let cam = Camera::framing(View::Iso, &frame, size)?;
    png_out::write_png(path, &raster::render_mesh(mesh, &cam, shade::SOLID))?;
    Ok(())
}

/// Single-precision formats can fold distinct vertices together: the warning that says so, with
/// the remedy, when the output file is one and the mesh has such vertices.
pub(super) fn single_precision_warning(
    a: &MeshArgs,
    mesh: &solidkit_meshing::IndexedMesh,
) -> Option<String> {
    let out = a.output.as_deref()?;
    if !MeshFormat::from_path(out).is_ok_and(is_single_precision) {
        return None;
    }
    let n = single_precision_collisions(mesh);
    (n > 0).then(|| {
        format!(
            "{}: {n} vertices fall on another vertex when rounded to the 32-bit floats of {}: read back, triangles there are degenerate or edges non-manifold (.ply, .obj, .off and .3mf keep double precision)",
            a.input.display(),
            out.display()
        )
    })
}
