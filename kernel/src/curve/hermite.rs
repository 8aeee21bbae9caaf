//! The cubic Hermite curve on `[0, 1]`: given end points `P₀, P₁` and end derivatives `M₀, M₁`,
//! `C(t) = h₀₀(t) P₀ + h₁₀(t) M₀ + h₀₁(t) P₁ + h₁₁(t) M₁` with the Hermite basis
//! `h₀₀ = 2t³ − 3t² + 1`, `h₁₀ = t³ − 2t² + t`, `h₀₁ = −2t³ + 3t²`, `h₁₁ = t³ − t²`.
//! It is the cubic Bézier curve `P₀, P₀ + M₀/3, P₁ − M₁/3, P₁`.

use super::bezier::points_bbox;
use super::error::finite_points;
use super::piece::{BezierPiece, Jet};
use super::{Curve3, CurveError};
use crate::Aabb;
use glam::DVec3;

/// A cubic Hermite curve on `[0, 1]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hermite {
    p0: DVec3,
    m0: DVec3,
    p1: DVec3,
    m1: DVec3,
}

impl Hermite {
    /// The curve from `p0` (derivative `m0`) to `p1` (derivative `m1`).
    pub fn new(p0: DVec3, m0: DVec3, p1: DVec3, m1: DVec3) -> Result<Hermite, CurveError> {
        finite_points("points", &[p0, p1])?;
        finite_points("tangents", &[m0, m1])?;
        Ok(Hermite { p0, m0, p1, m1 })
    }

    /// The end points `[P₀, P₁]`.
    pub fn points(&self) -> [DVec3; 2] {
        [self.p0, self.p1]
    }

    /// The end derivatives `[M₀, M₁]`.
    pub fn tangents(&self) -> [DVec3; 2] {
        [self.m0, self.m1]
    }

    /// The equivalent cubic Bézier control points.
    pub fn bezier_points(&self) -> [DVec3; 4] {
        [
            self.p0,
            self.p0 + self.m0 / 3.0,
            self.p1 - self.m1 / 3.0,
            self.p1,
        ]
    }
}

/// Point and derivatives of the Hermite segment `(p0, m0, p1, m1)` at local `t ∈ [0, 1]`.
pub(crate) fn hermite_jet(p0: DVec3, m0: DVec3, p1: DVec3, m1: DVec3, t: f64) -> Jet {
    let (t2, t3) = (t * t, t * t * t);
    let point = p0 * (2.0 * t3 - 3.0 * t2 + 1.0)
        + m0 * (t3 - 2.0 * t2 + t)
        + p1 * (-2.0 * t3 + 3.0 * t2)
        + m1 * (t3 - t2);
    let d1 = p0 * (6.0 * t2 - 6.0 * t)
        + m0 * (3.0 * t2 - 4.0 * t + 1.0)
        + p1 * (-6.0 * t2 + 6.0 * t)
        + m1 * (3.0 * t2 - 2.0 * t);
    let d2 = p0 * (12.0 * t - 6.0)
        + m0 * (6.0 * t - 4.0)
        + p1 * (-12.0 * t + 6.0)
        + m1 * (6.0 * t - 2.0);
    Jet { point, d1, d2 }
}

impl Curve3 for Hermite {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn jet(&self, t: f64) -> Jet {
        hermite_jet(self.p0, self.m0, self.p1, self.m1, t.clamp(0.0, 1.0))
    }
    fn control_bbox(&self) -> Aabb {
        points_bbox(&self.bezier_points())
    }
    fn pieces(&self) -> Vec<BezierPiece> {
        vec![BezierPiece::polynomial(0.0, 1.0, &self.bezier_points())]
    }
}
