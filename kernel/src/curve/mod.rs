//! Parametric curves in 3D, one file per kind: Bézier curves of any degree (de Casteljau),
//! cubic Hermite curves (one segment or a C¹ chain), B-splines (uniform, clamped, periodic or any
//! knot vector; de Boor), NURBS (exact conics), natural C² interpolating splines, the cubic
//! through four points at `u = 0, 1/3, 2/3, 1` ([`CubicThrough`]), composite chains with checked
//! continuity ([`Composite`]); formula curves ([`FormulaCurve`], no control points, so only in
//! [`Parametric`]); polylines within a chord-error bound ([`flatten`]); and closest-point queries
//! for distance fields ([`CurveIndex`]).
//!
//! Every kind implements [`Curve3`] (point, derivatives, parameter domain, bounding box from the
//! control points) and converts to rational Bézier pieces ([`BezierPiece`]), the common form used
//! for boxes and span subdivision. [`Curve`] holds any of them (as sweep paths and ruled-surface
//! rails do). Nothing here recurses or allocates per evaluation (up to degree 15; higher degrees
//! use one heap buffer per evaluation).

mod bezier;
mod blend;
mod bspline;
mod casteljau;
mod closest;
mod composite;
mod error;
pub mod flatten;
mod formula;
mod hermite;
mod interpolating;
mod measure;
mod nurbs;
mod parametric;
mod piece;
mod quadrature;
mod spans;
mod spline;
mod through;
mod tridiagonal;

#[cfg(test)]
mod notes_tests;
#[cfg(test)]
mod tests;

pub use bezier::Bezier;
pub(crate) use blend::BlendIndex;
pub use bspline::BSpline;
pub use closest::{Closest, CurveIndex};
pub use composite::{Composite, Continuity};
pub use error::CurveError;
pub use flatten::Polyline;
pub use formula::FormulaCurve;
pub use hermite::{Hermite, hermite_basis};
pub use interpolating::Interpolating;
pub use measure::arc_length;
pub use nurbs::Nurbs;
pub use parametric::{Parametric, Split};
pub use piece::{BezierPiece, Jet};
pub use quadrature::{gauss_legendre, integrate};
pub use through::CubicThrough;

use crate::Aabb;
use glam::DVec3;

/// What every curve provides. Parameters outside [`Curve3::domain`] are clamped to it.
pub trait Curve3 {
    /// The parameter interval `(t0, t1)`.
    fn domain(&self) -> (f64, f64);
    /// Point, first and second derivative at `t`.
    fn jet(&self, t: f64) -> Jet;
    /// The point at `t`.
    fn point(&self, t: f64) -> DVec3 {
        self.jet(t).point
    }
    /// The first derivative `C'(t)`.
    fn derivative(&self, t: f64) -> DVec3 {
        self.jet(t).d1
    }
    /// A box containing the curve: the box of its control points (convex hull property).
    fn control_bbox(&self) -> Aabb;
    /// The curve as consecutive rational Bézier pieces covering the domain in order.
    fn pieces(&self) -> Vec<BezierPiece>;
}

/// Any of the curve kinds.
#[derive(Debug, Clone, PartialEq)]
pub enum Curve {
    /// A Bézier curve.
    Bezier(Bezier),
    /// A cubic Hermite curve.
    Hermite(Hermite),
    /// A B-spline.
    BSpline(BSpline),
    /// A NURBS curve.
    Nurbs(Nurbs),
    /// A natural C² interpolating cubic spline through any number of points.
    Interpolating(Interpolating),
    /// The cubic through four points at `u = 0, 1/3, 2/3, 1`.
    CubicThrough(CubicThrough),
    /// A chain of curves with checked continuity.
    Composite(Composite),
}

macro_rules! each_curve {
    ($self:ident, $c:ident => $e:expr) => {
        match $self {
            Curve::Bezier($c) => $e,
            Curve::Hermite($c) => $e,
            Curve::BSpline($c) => $e,
            Curve::Nurbs($c) => $e,
            Curve::Interpolating($c) => $e,
            Curve::CubicThrough($c) => $e,
            Curve::Composite($c) => $e,
        }
    };
}

impl Curve {
    /// The curve's name in the JSON tree format.
    pub fn name(&self) -> &'static str {
        match self {
            Curve::Bezier(_) => "bezier",
            Curve::Hermite(_) => "hermite",
            Curve::BSpline(_) => "bspline",
            Curve::Nurbs(_) => "nurbs",
            Curve::Interpolating(_) => "interpolating",
            Curve::CubicThrough(_) => "cubic_through",
            Curve::Composite(_) => "composite",
        }
    }

    /// True when the curve ends where it starts (within `1e-9` of its size).
    pub fn is_closed(&self) -> bool {
        let (t0, t1) = self.domain();
        let size = self.control_bbox().size().length().max(f64::MIN_POSITIVE);
        (self.point(t1) - self.point(t0)).length() <= 1e-9 * size
    }
}

impl Curve3 for Curve {
    fn domain(&self) -> (f64, f64) {
        each_curve!(self, c => c.domain())
    }
    fn jet(&self, t: f64) -> Jet {
        each_curve!(self, c => c.jet(t))
    }
    fn point(&self, t: f64) -> DVec3 {
        each_curve!(self, c => c.point(t))
    }
    fn control_bbox(&self) -> Aabb {
        each_curve!(self, c => c.control_bbox())
    }
    fn pieces(&self) -> Vec<BezierPiece> {
        each_curve!(self, c => c.pieces())
    }
}
