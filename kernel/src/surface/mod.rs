//! Parametric surfaces as solids (lecture notes 001): tensor-product Bézier, B-spline and NURBS
//! patches, triangular Bézier patches, curved PN triangles over a mesh with normals, and formula
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

mod basis;
mod close;
mod derivs;
mod error;
mod formula;
mod sample;
mod solid;
mod tensor;
#[cfg(test)]
mod tests;

pub use derivs::SurfaceDerivatives;
pub use error::SurfaceError;
pub use formula::FormulaSurface;
pub use sample::{MAX_SEGMENTS, Sampled};
pub use tensor::{MAX_CONTROL_POINTS, MAX_DEGREE, TensorSurface, clamped_knots};

use crate::patch::TriangleBezier;
use glam::DVec3;

/// The surface of a surface node.
#[derive(Debug, Clone, PartialEq)]
pub enum SurfaceKind {
    /// `bezier_patch`: a tensor-product Bézier patch.
    Bezier(TensorSurface),
    /// `bspline_surface`: a tensor-product B-spline surface.
    BSpline(TensorSurface),
    /// `nurbs_surface`: a tensor-product NURBS surface.
    Nurbs(TensorSurface),
    /// `param_surface`: formulas in `u`, `v`.
    Formula(FormulaSurface),
    /// `bezier_triangle`: a triangular Bézier patch.
    Triangle(TriangleBezier),
    /// `pn_triangles`: every triangle of a mesh replaced by its PN patch.
    Pn(PnSource),
}

impl SurfaceKind {
    /// The JSON node type.
    pub fn name(&self) -> &'static str {
        match self {
            SurfaceKind::Bezier(_) => "bezier_patch",
            SurfaceKind::BSpline(_) => "bspline_surface",
            SurfaceKind::Nurbs(_) => "nurbs_surface",
            SurfaceKind::Formula(_) => "param_surface",
            SurfaceKind::Triangle(_) => "bezier_triangle",
            SurfaceKind::Pn(_) => "pn_triangles",
        }
    }

    /// The point and derivatives at `(s, t)` of the unit square, for the rectangle-parametrised
    /// kinds (tensor and formula surfaces); `None` for triangular patches and PN triangles.
    pub fn derivatives(&self, s: f64, t: f64) -> Option<SurfaceDerivatives> {
        match self {
            SurfaceKind::Bezier(p) | SurfaceKind::BSpline(p) | SurfaceKind::Nurbs(p) => {
                Some(p.derivatives(s, t))
            }
            SurfaceKind::Formula(f) => Some(f.derivatives(s, t)),
            SurfaceKind::Triangle(_) | SurfaceKind::Pn(_) => None,
        }
    }
}

/// The mesh a `pn_triangles` node refines.
#[derive(Debug, Clone, PartialEq)]
pub enum PnSource {
    /// Vertices, optional per-vertex normals (angle-weighted face normals when absent) and
    /// triangles given inline.
    Inline {
        /// Vertex positions.
        vertices: Vec<DVec3>,
        /// Per-vertex normals, if given.
        normals: Option<Vec<DVec3>>,
        /// Triangles (counter-clockwise seen from the side the normals point to).
        triangles: Vec<[u32; 3]>,
    },
    /// A mesh file (normals computed), by the path written in the tree.
    File {
        /// The path as written.
        path: String,
    },
}

/// Which side of the surface a thickness goes to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Side {
    /// `±t/2` about the surface.
    #[default]
    Both,
    /// `0..t` along the normal.
    Front,
    /// `−t..0` against the normal.
    Back,
}

impl Side {
    /// The JSON name.
    pub fn name(self) -> &'static str {
        match self {
            Side::Both => "both",
            Side::Front => "front",
            Side::Back => "back",
        }
    }

    /// The side of a JSON name.
    pub fn from_name(name: &str) -> Option<Side> {
        [Side::Both, Side::Front, Side::Back]
            .into_iter()
            .find(|s| s.name() == name)
    }
}

/// How a surface becomes a closed solid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Closure {
    /// The surface is already closed.
    Closed,
    /// A slab of this thickness along the normal.
    Thickness {
        /// The thickness (positive).
        thickness: f64,
        /// Where it goes.
        side: Side,
    },
    /// Down to the plane `z = base`.
    Base {
        /// The plane's height.
        z: f64,
    },
}

/// A surface node: the surface, how it is closed and how finely it is tessellated.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceSpec {
    /// The surface.
    pub kind: SurfaceKind,
    /// How it is closed.
    pub closure: Closure,
    /// The chord error to meet (tensor and formula surfaces); `None`: 10⁻³ of the size of the
    /// control net or sampled surface.
    pub tolerance: Option<f64>,
    /// Segments per edge (triangular patches, PN triangles); `None`: the default 16 (8 for PN).
    pub segments: Option<usize>,
}
