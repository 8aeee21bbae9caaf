//! Parametric surfaces as solids (lecture notes 001): tensor-product Bézier, B-spline and NURBS
//! patches, the interpolating bicubic patch through 16 points ([`InterpolatingPatch`]), triangular Bézier patches, curved PN triangles over a mesh with normals, and formula
//! surfaces `(x, y, z)(u, v)` or `z = f(u, v)`.
//!
//! A surface is a sheet, not a solid. A [`SurfaceSpec`] closes it:
//! - by a **thickness** `t`, offsetting along the unit normal `n = p_u × p_v / |p_u × p_v|`: both
//!   sides (`±t/2`, the default), the front (`0..t`) or the back (`−t..0`), joined by side walls
//!   along the boundary;
//! - by a **base** plane `z = z₀` below it (a graph over the `xy` plane, as height fields are): the
//!   surface, its projection onto the plane, and vertical walls;
//! - or not at all when the sheet is closed (a PN-refined closed mesh, a formula sphere or torus
//!   whose seams meet; seams are welded where points coincide to `10⁻⁹` of the size).
//!
//! **The field** is the exact signed distance to that closed triangle mesh (a
//! [`MeshSolid`](crate::primitive::MeshSolid)): 1-Lipschitz, sound intervals, and the zero set
//! is the mesh. The mesh is a tessellation of the surface whose vertices lie on it; its chord
//! error (the distance from a triangle to the surface) is bounded for Bézier and B-spline patches
//! by `(A Δs² + B Δt²)/8` with `A = M_ss + M_st`, `B = M_tt + M_st` bounds of the second
//! derivatives from the differenced control nets ([`TensorSurface::second_derivative_bounds`]),
//! and the sample counts are chosen to meet the node's `tolerance`; for NURBS and formula
//! surfaces the second derivatives are *estimated* from samples on a 65 × 65 grid (not a
//! bound). Triangular patches and PN triangles use a fixed number of segments per edge. The
//! offset faces of a thickness interpolate the exact offset surface at their vertices; a
//! thickness above a radius of curvature folds the offset (the mesh then intersects itself).

mod adaptive;
#[cfg(test)]
mod adaptive_tests;
mod basis;
mod bezier_bounds;
mod close;
mod derivs;
mod error;
mod formula;
mod sample;
mod solid;
mod spec;
mod tensor;
#[cfg(test)]
mod tests;
mod through;
#[cfg(test)]
mod through_tests;

pub use derivs::SurfaceDerivatives;
pub use error::SurfaceError;
pub use formula::FormulaSurface;
pub use sample::{MAX_SEGMENTS, Sampled};
pub use spec::{Closure, PnSource, Side, SurfaceKind, SurfaceSpec};
pub use tensor::{MAX_CONTROL_POINTS, MAX_DEGREE, TensorSurface, clamped_knots};
pub use through::{InterpolatingPatch, bezier_net};
