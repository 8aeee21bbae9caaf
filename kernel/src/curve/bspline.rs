//! B-spline curves of any degree with any valid knot vector (uniform, clamped, periodic or
//! non-uniform), evaluated by de Boor's algorithm.

use super::CurveError;
use super::error::finite_points;
use super::spline::{Core, Rational, check_knots, clamped_knots, spline_curve3, uniform_knots};
use glam::DVec3;

/// A B-spline curve `C(t) = Σ Nᵢ,ₚ(t) Pᵢ` on `[knots[p], knots[n]]`.
#[derive(Debug, Clone, PartialEq)]
pub struct BSpline {
    degree: usize,
    points: Vec<DVec3>,
    knots: Vec<f64>,
    spline: Rational,
}

impl BSpline {
    /// The curve of degree `degree` with these control points and `points + degree + 1` knots.
    pub fn new(degree: usize, points: Vec<DVec3>, knots: Vec<f64>) -> Result<BSpline, CurveError> {
        finite_points("points", &points)?;
        check_knots(degree, points.len(), &knots)?;
        let core = Core::new(
            degree,
            knots.clone(),
            points.iter().map(|p| p.extend(1.0)).collect(),
        );
        Ok(BSpline {
            degree,
            points,
            knots,
            spline: Rational::new(core),
        })
    }

    /// Clamped (open uniform) knots: the curve starts at the first control point and ends at the
    /// last, tangent to the control polygon; with `degree + 1` points it is the Bézier curve.
    pub fn clamped(degree: usize, points: Vec<DVec3>) -> Result<BSpline, CurveError> {
        let knots = clamped_knots(degree, points.len());
        BSpline::new(degree, points, knots)
    }

    /// Uniform knots `0, 1, 2, …`: the curve starts and ends inside the control polygon.
    pub fn uniform(degree: usize, points: Vec<DVec3>) -> Result<BSpline, CurveError> {
        let knots = uniform_knots(degree, points.len());
        BSpline::new(degree, points, knots)
    }

    /// A closed uniform curve through the cycle of control points: the first `degree` points are
    /// repeated at the end, so the curve closes with continuous derivatives up to `degree − 1`.
    pub fn periodic(degree: usize, mut points: Vec<DVec3>) -> Result<BSpline, CurveError> {
        super::error::enough_points("points", points.len(), (degree + 1).max(3))?;
        let head: Vec<DVec3> = points[..degree].to_vec();
        points.extend(head);
        BSpline::uniform(degree, points)
    }

    /// The degree.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control points.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The knot vector.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
}

spline_curve3!(BSpline);
