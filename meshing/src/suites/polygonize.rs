//! Polygonising the suites' CSG solids: sparse marching cubes over the solid's bounding box (as
//! `solidkit mesh` does), or over a grid whose samples include the origin.

use crate::IndexedMesh;
use crate::marching_cubes::GridSpec;
use crate::octree::{SparseOptions, mesh_sparse};
use glam::DVec3;
use solidkit_kernel::{Aabb, Solid};

/// A mesh and the cell size it was made with.
pub(crate) struct Polygonised {
    pub mesh: IndexedMesh,
    pub cell: f64,
}

/// Which sample grid to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Grid {
    /// `GridSpec::for_bounds` over the solid's bounding box (what `solidkit mesh` does).
    Bounds,
    /// Samples at integer multiples of the cell size (the origin is a sample), covering the
    /// bounding box with one cell to spare.
    Lattice,
}

/// `solid` polygonised with `resolution` cells along the longest side of its bounding box.
pub(crate) fn polygonise(
    name: &str,
    solid: &Solid,
    resolution: usize,
    grid: Grid,
) -> Result<Polygonised, super::SuiteError> {
    let bounds = solid.bbox();
    let spec = match grid {
        Grid::Bounds => GridSpec::for_bounds(&bounds, resolution),
        Grid::Lattice => lattice(&bounds, resolution),
    }
    .map_err(|e| super::build_error(name, e))?;
    let (mesh, _) = mesh_sparse(&solid.compile(), spec, &SparseOptions::default())
        .map_err(|e| super::build_error(name, e))?;
    Ok(Polygonised {
        mesh,
        cell: spec.cell,
    })
}

/// A grid of samples at integer multiples of the cell over `bounds`, one cell to spare.
fn lattice(bounds: &Aabb, resolution: usize) -> Result<GridSpec, crate::marching_cubes::GridError> {
    let probe = GridSpec::for_bounds(bounds, resolution)?;
    let cell = probe.cell;
    let lo = (bounds.min / cell).floor() - DVec3::ONE;
    let hi = (bounds.max / cell).ceil() + DVec3::ONE;
    let cells = (hi - lo).to_array().map(|c| c as usize);
    Ok(GridSpec {
        origin: lo * cell,
        cell,
        cells,
    })
}
