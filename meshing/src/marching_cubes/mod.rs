//! Marching cubes: a closed, oriented 2-manifold triangulation of a field's zero set over a uniform
//! grid, for every sign pattern.
//!
//! [`table`] generates the case table from a face rule that neighbouring cells agree on;
//! [`pinch`] confirms the faces its decider joins with the program, so solids touching along a
//! line stay apart;
//! [`samples`] samples a field in parallel over a [`GridSpec`]; [`polygonize`] turns samples into triangles with vertices
//! shared by construction. [`mesh_field`] runs the whole path. [`disjoint`] says why the triangles never
//! intersect and what a run checks to claim it.

pub mod disjoint;
pub mod pinch;
pub mod polygonize;
pub mod samples;
pub mod sign;
pub mod table;

pub use crate::grid::{GridError, GridSpec};
pub use polygonize::{EDGE_MARGIN, edge_vertex, polygonize_into};
pub use samples::SampleGrid;
pub use sign::{INSIDE_ZERO, NOISE, OUTSIDE_ZERO, inside, settle, snap_noise};

use crate::IndexedMesh;
use solidkit_kernel::Field;

/// Samples `field` on `spec` and polygonizes its zero set.
pub fn mesh_field(field: &impl Field, spec: GridSpec) -> IndexedMesh {
    let samples = SampleGrid::sample(field, spec);
    mesh_samples(&samples)
}

/// Polygonizes already sampled values.
pub fn mesh_samples(samples: &SampleGrid) -> IndexedMesh {
    let mut mesh = IndexedMesh::default();
    polygonize_into(samples, &mut mesh);
    mesh
}

#[cfg(test)]
mod disjoint_tests;
#[cfg(test)]
pub(crate) mod tests;
