//! Parametric patches (lecture notes 001): Bernstein polynomials, tensor-product Bézier patches,
//! triangular Bézier patches (de Casteljau on barycentric nets), curved PN triangles that refine
//! a mesh with vertex normals, and the curvatures of a Monge patch `z = h(x, y)`.

pub mod bernstein;
mod bezier;
pub mod curvature;
mod error;
mod pn;
mod triangle;

pub use bezier::BezierPatch;
pub use curvature::{Curvature, HeightDerivatives, monge_curvature};
pub use error::PatchError;
pub use pn::{MAX_SEGMENTS, pn_refine, pn_triangle, vertex_normals};
pub use triangle::{TriangleBezier, net_size};

#[cfg(test)]
mod tests;
