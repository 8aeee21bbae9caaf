//! Non-uniform rational B-splines: a B-spline in homogeneous coordinates `(w·P, w)` projected
//! back by dividing by `w`. With positive weights they represent conics exactly; the circle
//! constructors use the standard degree-2 construction (corner weights `√2/2`).

use super::CurveError;
use super::error::finite_points;
use super::spline::{Core, Rational, check_knots, clamped_knots, spline_curve3};
use glam::DVec3;
use std::f64::consts::FRAC_1_SQRT_2;

/// A NURBS curve `C(t) = Σ Nᵢ,ₚ(t) wᵢ Pᵢ / Σ Nᵢ,ₚ(t) wᵢ`.
#[derive(Debug, Clone, PartialEq)]
pub struct Nurbs {
    degree: usize,
    points: Vec<DVec3>,
    weights: Vec<f64>,
    knots: Vec<f64>,
    spline: Rational,
}

impl Nurbs {
    /// The curve of degree `degree` with control points, positive weights (one per point) and
    /// `points + degree + 1` knots.
    pub fn new(
        degree: usize,
        points: Vec<DVec3>,
        weights: Vec<f64>,
        knots: Vec<f64>,
    ) -> Result<Nurbs, CurveError> {
        finite_points("points", &points)?;
        if weights.len() != points.len() {
            return Err(CurveError::WeightCount {
                expected: points.len(),
                found: weights.len(),
            });
        }
        if weights.iter().any(|w| !w.is_finite()) {
            return Err(CurveError::NonFinite {
                parameter: "weights",
            });
        }
        if let Some(index) = weights.iter().position(|&w| w <= 0.0) {
            return Err(CurveError::NonPositiveWeight { index });
        }
        check_knots(degree, points.len(), &knots)?;
        let homogeneous = points
            .iter()
            .zip(&weights)
            .map(|(p, &w)| (*p * w).extend(w))
            .collect();
        let core = Core::new(degree, knots.clone(), homogeneous);
        Ok(Nurbs {
            degree,
            points,
            weights,
            knots,
            spline: Rational::new(core),
        })
    }

    /// Clamped knots (see [`BSpline::clamped`](super::BSpline::clamped)).
    pub fn clamped(
        degree: usize,
        points: Vec<DVec3>,
        weights: Vec<f64>,
    ) -> Result<Nurbs, CurveError> {
        let knots = clamped_knots(degree, points.len());
        Nurbs::new(degree, points, weights, knots)
    }

    /// The quarter of the circle of radius `radius` around the origin in the xy plane from
    /// `(r, 0, 0)` to `(0, r, 0)`: degree 2, points `(r,0), (r,r), (0,r)`, weights `1, √2/2, 1`.
    pub fn quarter_circle(radius: f64) -> Result<Nurbs, CurveError> {
        let r = radius;
        Nurbs::clamped(
            2,
            vec![
                DVec3::new(r, 0.0, 0.0),
                DVec3::new(r, r, 0.0),
                DVec3::new(0.0, r, 0.0),
            ],
            vec![1.0, FRAC_1_SQRT_2, 1.0],
        )
    }

    /// The whole circle of radius `radius` around `center`, parallel to the xy plane,
    /// counter-clockwise from `center + (r, 0, 0)`: four quarter arcs, parameter `[0, 4]`.
    pub fn circle(center: DVec3, radius: f64) -> Result<Nurbs, CurveError> {
        let r = radius;
        let mut points = Vec::with_capacity(9);
        let mut weights = Vec::with_capacity(9);
        for quarter in 0..4 {
            for (j, (x, y)) in [(1.0, 0.0), (1.0, 1.0)].into_iter().enumerate() {
                // Rotate the first quarter's points by quarter · 90°.
                let (x, y) = rotate_quarter(x, y, quarter);
                points.push(center + DVec3::new(r * x, r * y, 0.0));
                weights.push(if j == 1 { FRAC_1_SQRT_2 } else { 1.0 });
            }
        }
        points.push(center + DVec3::new(r, 0.0, 0.0));
        weights.push(1.0);
        let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];
        Nurbs::new(2, points, weights, knots)
    }

    /// The degree.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control points.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The weights.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The knot vector.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
}

/// `(x, y)` rotated by `quarter · 90°` exactly.
fn rotate_quarter(x: f64, y: f64, quarter: usize) -> (f64, f64) {
    match quarter % 4 {
        0 => (x, y),
        1 => (-y, x),
        2 => (-x, -y),
        _ => (y, -x),
    }
}

spline_curve3!(Nurbs);
