//! Primitive solids in their canonical frames (centred at the origin, axis along z), each in its
//! own file or folder with its value, gradient, interval bound over a box, bounding box and
//! Lipschitz bound. A box's interval can always fall back to `f(centre) ± L · half-diagonal`.
//!
//! What each field is, and its `field_error` — the distance between the field's zero set and the
//! exact surface (the meshers add their own discretisation error on top):
//!
//! | primitive | field | L | field_error |
//! |---|---|---|---|
//! | sphere, box, cylinder, cone, torus, half-space | exact signed distance | 1 | 0 |
//! | gyroid | `|g| − t` (not a distance) | √6 | 0 |
//! | platonic | max of face-plane distances (exact inside, lower bound outside) | 1 | 0 |
//! | polyhedron / mesh / prism | exact distance to the triangles, sign by winding number | 1 | 0 for closed meshes |
//! | ellipsoid | `min(radii) · (|p / radii| − 1)`, a distance bound | 1 | 0 |
//! | quadric (general and named) | gradient-normalised `Q / |∇Q|` near the surface, bounded by its box | 2 | 0 inside the box |
//! | blob (metaballs) | `T − Σ bₖ exp(−aₖ rₖ²)` | `Σ |bₖ| √(2aₖ) e^{−1/2}` | 0 |
//! | height field | `(z − h) / √(1 + L_h²)` with the box sides | 1 | 0 (h as interpolated) |
//! | extrude, revolve, sweep, loft, ruled | exact distance where cheap, else slice distance / L | see each type | 0 |
//! | ruled_surface | exact distance to its tessellation (thick: minus t/2) | 1 | the chord error |
//! | expr (formula) | `max(g(clamp p), d_box)`: a distance only if `g` is | `max(1, L_g)`, from interval derivatives | 0 |

pub mod blob;
mod cone;
mod cuboid;
mod cylinder;
pub mod expr;
mod gyroid;
pub mod heightfield;
mod plane;
mod polyhedron;
pub mod quadric;
mod sincos;
mod sphere;
pub mod sweep;
mod torus;

pub use blob::Blob;
pub use cone::Cone;
pub use cuboid::Cuboid;
pub use cylinder::Cylinder;
pub use expr::Expr;
pub use gyroid::{Gyroid, cos_f32, cos_interval, sin_f32, sin_interval, sincos_f32};
pub use heightfield::HeightField;
pub use plane::HalfSpace;
pub use polyhedron::{
    MeshResolver, MeshSolid, MeshSolidError, MeshSource, NoMeshResolver, Platonic, ResolveError,
    ResolveKind,
};
pub use polyhedron::{SubdivisionInput, SubdivisionRequest, SubdivisionScheme};
pub use quadric::{Ellipsoid, Quadric};
pub use sincos::sincos_f64;
pub use sphere::Sphere;
pub use sweep::{Extrude, Loft, Revolve, Ruled, RuledSurface, Sweep};
pub use torus::Torus;

use crate::{Aabb, Interval};
use glam::DVec3;
use std::sync::Arc;

/// The operations every primitive provides.
pub trait Shape {
    /// Signed distance (negative inside) at `p`.
    fn value(&self, p: DVec3) -> f64;
    /// Gradient of the field at `p` (unit length where the field is a true distance).
    fn gradient(&self, p: DVec3) -> DVec3;
    /// An interval containing every value of the field over the box `b`.
    fn interval(&self, b: &Aabb) -> Interval;
    /// A box containing the solid (possibly infinite).
    fn bbox(&self) -> Aabb;

    /// A box containing `{p : f(p) ≤ level}` for `level ≥ 0` (offsets, shells and blends of the
    /// primitive reach there). The default, the box grown by `level`, holds for fields that are
    /// at least the distance to the box outside it (exact distances, and fields that are the
    /// maximum of such a distance and something else); distance bounds that fall below it
    /// (ellipsoids, Platonic solids, blobs) override it.
    fn bbox_at(&self, level: f64) -> Aabb {
        self.bbox().expanded(level)
    }

    /// Whether [`Shape::bbox_at`] holds at every level (the conformance tests check it). False
    /// for the sweeps other than revolutions and for height fields: their fields divide by slope
    /// bounds and fall up to a few times below the distance to their box (measured: 3.7 for a
    /// twisted, scaled extrusion), so an offset of one may reach past its box; the meshing
    /// pipeline then cuts it closed at the grid's edge and warns.
    fn sublevel_boxes_hold(&self) -> bool {
        true
    }
    /// Checks the parameters; the message names the bad parameter.
    fn validate(&self) -> Result<(), PrimitiveError>;

    /// An upper bound of `|∇f|` over all space: 1 for distance fields. Interval fallbacks use
    /// `f(centre) ± L · half-diagonal`, and meshing trusts `|f| / L` as a distance bound.
    fn lipschitz(&self) -> f64 {
        1.0
    }

    /// Values and gradients at many points, double precision (the gradient batch evaluator's
    /// entry point). Must give exactly [`Shape::value`] and [`Shape::gradient`] at each point;
    /// the default calls them, primitives whose per-point setup is costly (a normalisation)
    /// override it to do that setup once.
    fn values_gradients(&self, pts: &[DVec3], values: &mut [f64], gradients: &mut [DVec3]) {
        for ((p, v), g) in pts.iter().zip(values.iter_mut()).zip(gradients.iter_mut()) {
            *v = self.value(*p);
            *g = self.gradient(*p);
        }
    }

    /// Values at many points in structure-of-arrays form, single precision (the batch
    /// evaluator's entry point). The default calls [`Shape::value`] per point; hot primitives
    /// override it with loops the compiler vectorises.
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        for i in 0..out.len() {
            let p = DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64);
            out[i] = self.value(p) as f32;
        }
    }
}

/// A primitive parameter that makes no solid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{parameter}: {problem}")]
pub struct PrimitiveError {
    /// The parameter's name as in the JSON tree format.
    pub parameter: &'static str,
    /// What is wrong with it.
    pub problem: &'static str,
}

/// Largest magnitude of a primitive's length, size or coordinate parameter. Samples are evaluated
/// in single precision (largest finite `f32` about 3.4·10³⁸) and primitives square or divide by
/// their parameters, so beyond this the evaluators overflow, cancel catastrophically or disagree
/// with the interval bounds (open meshes from seemingly valid trees, issue 15).
pub const MAX_MAGNITUDE: f64 = 1e30;

/// Smallest magnitude of a non-zero primitive parameter: below it reciprocals overflow single
/// precision and products underflow to zero (subnormal radii gave NaN samples, issue 15). Such a
/// feature lies far below any grid cell the mesher accepts, so nothing meshable is lost.
pub const MIN_MAGNITUDE: f64 = 1e-30;

/// Whether `x` is zero or a finite number whose magnitude lies in
/// [`MIN_MAGNITUDE`]`..=`[`MAX_MAGNITUDE`]: a parameter every evaluator handles faithfully.
pub fn faithful(x: f64) -> bool {
    x == 0.0 || (MIN_MAGNITUDE..=MAX_MAGNITUDE).contains(&x.abs())
}

/// The problem with a finite `x` outside the faithful range.
const OUT_OF_RANGE: &str = "expected 0 or a magnitude between 1e-30 and 1e30 (beyond that range \
                            single-precision evaluation is not faithful)";

/// Checks that `x` is a finite number greater than zero, within the faithful range.
pub(crate) fn positive(parameter: &'static str, x: f64) -> Result<(), PrimitiveError> {
    if !x.is_finite() {
        Err(PrimitiveError {
            parameter,
            problem: "expected a finite number",
        })
    } else if x <= 0.0 {
        Err(PrimitiveError {
            parameter,
            problem: "expected a positive number",
        })
    } else if !faithful(x) {
        Err(PrimitiveError {
            parameter,
            problem: OUT_OF_RANGE,
        })
    } else {
        Ok(())
    }
}

/// Checks that `x` is a finite number not below zero, zero or within the faithful range.
pub(crate) fn non_negative(parameter: &'static str, x: f64) -> Result<(), PrimitiveError> {
    if !x.is_finite() {
        Err(PrimitiveError {
            parameter,
            problem: "expected a finite number",
        })
    } else if x < 0.0 {
        Err(PrimitiveError {
            parameter,
            problem: "expected a number not below zero",
        })
    } else if !faithful(x) {
        Err(PrimitiveError {
            parameter,
            problem: OUT_OF_RANGE,
        })
    } else {
        Ok(())
    }
}

/// `+1` for non-negative `x`, `-1` otherwise (a sign that never returns zero).
pub(crate) fn sign(x: f64) -> f64 {
    if x >= 0.0 { 1.0 } else { -1.0 }
}

/// Unit vector from the z axis towards `p` in the xy plane (x axis on the axis itself).
pub(crate) fn radial(p: DVec3) -> DVec3 {
    let r = (p.x * p.x + p.y * p.y).sqrt();
    if r > 0.0 {
        DVec3::new(p.x / r, p.y / r, 0.0)
    } else {
        DVec3::X
    }
}

/// Interval of the distance from the z axis over a box.
pub(crate) fn radial_interval(b: &Aabb) -> Interval {
    Interval::norm(&[
        Interval::new(b.min.x, b.max.x),
        Interval::new(b.min.y, b.max.y),
    ])
}

/// Lipschitz bound of a field over a box from its value at the centre.
pub(crate) fn lipschitz_interval(shape: &impl Shape, b: &Aabb) -> Interval {
    Interval::around(
        shape.value(b.center()),
        shape.lipschitz() * b.half_extents().length(),
    )
}

/// One of the primitive solids. Variants with large data hold it behind an `Arc`, so cloning a
/// primitive is always cheap.
#[derive(Debug, Clone, PartialEq)]
pub enum Primitive {
    /// A ball.
    Sphere(Sphere),
    /// An axis-aligned box centred at the origin.
    Cuboid(Cuboid),
    /// A capped cylinder along z.
    Cylinder(Cylinder),
    /// A capped (possibly truncated) cone along z.
    Cone(Cone),
    /// A torus around the z axis.
    Torus(Torus),
    /// A half-space `n · p ≤ d`.
    HalfSpace(HalfSpace),
    /// A gyroid sheet (triply periodic, unbounded).
    Gyroid(Gyroid),
    /// A Platonic solid centred at the origin (exact face-plane field).
    Platonic(Platonic),
    /// A solid bounded by a triangle mesh (inline polyhedron, mesh file or prism; exact distance).
    Mesh(MeshSolid),
    /// An axis-aligned ellipsoid.
    Ellipsoid(Ellipsoid),
    /// A quadric solid `{Q ≤ 0}`, bounded by a box where unbounded.
    Quadric(Arc<Quadric>),
    /// A blobby object (metaballs).
    Blob(Arc<Blob>),
    /// A height-field solid between a base plane and `z = h(x, y)`.
    HeightField(Arc<HeightField>),
    /// A profile extruded along z, optionally twisted and scaled.
    Extrude(Arc<Extrude>),
    /// A profile revolved about the z axis (full or partial turn).
    Revolve(Arc<Revolve>),
    /// A profile swept along a 3D curve with rotation-minimising frames.
    Sweep(Arc<Sweep>),
    /// A loft between two profiles at two heights.
    Loft(Arc<Loft>),
    /// The solid bounded by the ruled surface between two closed plane curves.
    Ruled(Arc<Ruled>),
    /// The solid of the ruled surface between any two curves, capped or thickened.
    RuledSurface(Arc<RuledSurface>),
    /// A formula `g(x, y, z) ≤ 0` cut by a box.
    Expr(Arc<Expr>),
}

macro_rules! dispatch {
    ($self:ident, $s:ident => $e:expr) => {
        match $self {
            Primitive::Sphere($s) => $e,
            Primitive::Cuboid($s) => $e,
            Primitive::Cylinder($s) => $e,
            Primitive::Cone($s) => $e,
            Primitive::Torus($s) => $e,
            Primitive::HalfSpace($s) => $e,
            Primitive::Gyroid($s) => $e,
            Primitive::Platonic($s) => $e,
            Primitive::Mesh($s) => $e,
            Primitive::Ellipsoid($s) => $e,
            Primitive::Quadric($s) => $e,
            Primitive::Blob($s) => $e,
            Primitive::HeightField($s) => $e,
            Primitive::Extrude($s) => $e,
            Primitive::Revolve($s) => $e,
            Primitive::Sweep($s) => $e,
            Primitive::Loft($s) => $e,
            Primitive::Ruled($s) => $e,
            Primitive::RuledSurface($s) => $e,
            Primitive::Expr($s) => $e,
        }
    };
}

impl Primitive {
    /// The name used for this primitive in the JSON tree format.
    pub fn name(&self) -> &'static str {
        match self {
            Primitive::Sphere(_) => "sphere",
            Primitive::Cuboid(_) => "box",
            Primitive::Cylinder(_) => "cylinder",
            Primitive::Cone(_) => "cone",
            Primitive::Torus(_) => "torus",
            Primitive::HalfSpace(_) => "plane",
            Primitive::Gyroid(_) => "gyroid",
            Primitive::Platonic(_) => "platonic",
            Primitive::Mesh(m) => m.name(),
            Primitive::Ellipsoid(_) => "ellipsoid",
            Primitive::Quadric(q) => q.name(),
            Primitive::Blob(_) => "blob",
            Primitive::HeightField(_) => "heightfield",
            Primitive::Extrude(_) => "extrude",
            Primitive::Revolve(_) => "revolve",
            Primitive::Sweep(_) => "sweep",
            Primitive::Loft(_) => "loft",
            Primitive::Ruled(_) => "ruled",
            Primitive::RuledSurface(_) => "ruled_surface",
            Primitive::Expr(_) => "expr",
        }
    }
}

impl Shape for Primitive {
    fn value(&self, p: DVec3) -> f64 {
        dispatch!(self, s => s.value(p))
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        dispatch!(self, s => s.gradient(p))
    }
    fn interval(&self, b: &Aabb) -> Interval {
        dispatch!(self, s => s.interval(b))
    }
    fn bbox(&self) -> Aabb {
        dispatch!(self, s => s.bbox())
    }
    fn bbox_at(&self, level: f64) -> Aabb {
        dispatch!(self, s => s.bbox_at(level))
    }
    fn sublevel_boxes_hold(&self) -> bool {
        dispatch!(self, s => s.sublevel_boxes_hold())
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        dispatch!(self, s => s.validate())
    }
    fn lipschitz(&self) -> f64 {
        dispatch!(self, s => s.lipschitz())
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        dispatch!(self, s => s.values_f32(x, y, z, out))
    }
    fn values_gradients(&self, pts: &[DVec3], values: &mut [f64], gradients: &mut [DVec3]) {
        dispatch!(self, s => s.values_gradients(pts, values, gradients))
    }
}

#[cfg(test)]
pub(crate) mod conformance;
