//! Polygonising the suites' CSG solids: sparse marching cubes over the solid's bounding box (as
//! `solidkit mesh` does), or over a grid whose samples include the origin.

use crate::IndexedMesh;
use crate::grid::GridSpec;
use crate::pipeline::{Domain, MeshOptions, mesh_solid};
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
    let domain = match grid {
        Grid::Bounds => Domain::Solid,
        Grid::Lattice => Domain::Grid(
            lattice(&solid.bbox(), resolution).map_err(|e| super::build_error(name, e))?,
        ),
    };
    let options = MeshOptions::new(resolution).domain(domain).no_refinement();
    let meshed = mesh_solid(solid, &options).map_err(|e| super::build_error(name, e))?;
    Ok(Polygonised {
        mesh: meshed.mesh,
        cell: meshed.spec.cell,
    })
}

/// A grid of samples at integer multiples of the cell over `bounds`, one cell to spare.
fn lattice(bounds: &Aabb, resolution: usize) -> Result<GridSpec, crate::grid::GridError> {
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
