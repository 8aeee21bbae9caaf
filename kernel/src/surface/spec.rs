//! What a surface node says: the surface ([`SurfaceKind`]), how it is closed into a solid
//! ([`Closure`], [`Side`]) and how finely it is tessellated ([`SurfaceSpec`]).

use super::derivs::SurfaceDerivatives;
use super::formula::FormulaSurface;
use super::tensor::TensorSurface;
use super::through::InterpolatingPatch;
use crate::patch::TriangleBezier;
use glam::DVec3;

/// The surface of a surface node.
#[derive(Debug, Clone, PartialEq)]
pub enum SurfaceKind {
    /// `bezier_patch`: a tensor-product Bézier patch.
    Bezier(TensorSurface),
    /// `interpolating_patch`: the bicubic patch through 16 points at `u, v ∈ {0, 1/3, 2/3, 1}`
    /// (kept with its points; tessellated as its Bézier patch).
    Interpolating(InterpolatingPatch),
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
            SurfaceKind::Interpolating(_) => "interpolating_patch",
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
            SurfaceKind::Interpolating(p) => Some(p.bezier().derivatives(s, t)),
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
    /// Curvature-adaptive tessellation (`"tessellation": "adaptive"`, rectangle-parametrised
    /// kinds) instead of the regular grid.
    pub adaptive: bool,
}
