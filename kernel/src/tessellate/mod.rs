//! Exact parametric tessellations (lecture notes 001, "discrétisation régulière"): a surface's
//! `(u, v)` parameter rectangle sampled on a regular grid and split into two triangles per cell.
//! [`regular_grid`] is the open grid of the notes; the solids (sphere, ellipsoid, capsule, torus,
//! height field) weld seams and poles into closed, outward-wound (counter-clockwise seen from
//! outside) manifolds and state a bound of their chord error (the largest distance from a triangle
//! to the exact surface, see [`chord`]).

pub mod chord;
mod error;
mod grid;
mod heightfield;
mod sphere;
mod torus;

pub use error::{MAX_SAMPLES, TessellationError};
pub use grid::regular_grid;
pub use heightfield::heightfield;
pub use sphere::{capsule, ellipsoid, sphere};
pub use torus::torus;

use crate::IndexedMesh;

/// A tessellation and the bound of its distance to the exact surface.
#[derive(Debug, Clone, PartialEq)]
pub struct Tessellation {
    /// The closed, outward-wound triangle mesh.
    pub mesh: IndexedMesh,
    /// An upper bound of the distance from any point of the mesh to the surface, where one is
    /// known.
    pub chord_error: Option<f64>,
}

#[cfg(test)]
mod tests;
