//! The interpolating cubic through four points at the parameters `0, 1/3, 2/3, 1`: the polynomial
//! curve `C(u) = c₀ + c₁u + c₂u² + c₃u³` with `C(k/3) = Pₖ`. Solving the 4×4 system gives
//! `c₀ = P₀`, `c₁ = −5.5P₀ + 9P₁ − 4.5P₂ + P₃`, `c₂ = 9P₀ − 22.5P₁ + 18P₂ − 4.5P₃`,
//! `c₃ = −4.5P₀ + 13.5P₁ − 13.5P₂ + 4.5P₃`; as a Bézier curve its control points are
//! `P₀, (−5P₀ + 18P₁ − 9P₂ + 2P₃)/6, (2P₀ − 9P₁ + 18P₂ − 5P₃)/6, P₃`. (Not to be confused with
//! [`Interpolating`](super::Interpolating), the natural C² spline through any number of points.)

use super::bezier::points_bbox;
use super::error::finite_points;
use super::piece::{BezierPiece, Jet};
use super::{Curve3, CurveError, casteljau};
use crate::Aabb;
use glam::DVec3;

/// The cubic through four points at `u = 0, 1/3, 2/3, 1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CubicThrough {
    points: [DVec3; 4],
    bezier: [DVec3; 4],
}

impl CubicThrough {
    /// The cubic through `points` (exactly four, finite).
    pub fn new(points: &[DVec3]) -> Result<CubicThrough, CurveError> {
        let points: [DVec3; 4] = points.try_into().map_err(|_| CurveError::PointCount {
            parameter: "points",
            expected: 4,
            found: points.len(),
        })?;
        finite_points("points", &points)?;
        let [p0, p1, p2, p3] = points;
        let bezier = [
            p0,
            (p0 * -5.0 + p1 * 18.0 - p2 * 9.0 + p3 * 2.0) / 6.0,
            (p0 * 2.0 - p1 * 9.0 + p2 * 18.0 - p3 * 5.0) / 6.0,
            p3,
        ];
        Ok(CubicThrough { points, bezier })
    }

    /// The four points the curve passes through.
    pub fn points(&self) -> &[DVec3; 4] {
        &self.points
    }

    /// The equivalent cubic Bézier control points.
    pub fn bezier_points(&self) -> &[DVec3; 4] {
        &self.bezier
    }

    /// The power-basis coefficients `[c₀, c₁, c₂, c₃]` of `C(u) = Σ cₖ uᵏ`.
    pub fn coefficients(&self) -> [DVec3; 4] {
        let [p0, p1, p2, p3] = self.points;
        [
            p0,
            p0 * -5.5 + p1 * 9.0 - p2 * 4.5 + p3,
            p0 * 9.0 - p1 * 22.5 + p2 * 18.0 - p3 * 4.5,
            p0 * -4.5 + p1 * 13.5 - p2 * 13.5 + p3 * 4.5,
        ]
    }
}

impl Curve3 for CubicThrough {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn jet(&self, t: f64) -> Jet {
        let [point, d1, d2] = casteljau::jet(&self.bezier, t.clamp(0.0, 1.0));
        Jet { point, d1, d2 }
    }
    fn control_bbox(&self) -> Aabb {
        points_bbox(&self.bezier)
    }
    fn pieces(&self) -> Vec<BezierPiece> {
        vec![BezierPiece::polynomial(0.0, 1.0, &self.bezier)]
    }
}
