//! Cubic Hermite curves: given points `P₀ … Pₙ` and the derivatives `M₀ … Mₙ` there, segment `i`
//! (parameters `[i, i + 1]`) is `C(i + t) = h₀₀(t) Pᵢ + h₁₀(t) Mᵢ + h₀₁(t) Pᵢ₊₁ + h₁₁(t) Mᵢ₊₁`
//! with the Hermite basis `h₀₀ = 2t³ − 3t² + 1`, `h₁₀ = t³ − 2t² + t`, `h₀₁ = −2t³ + 3t²`,
//! `h₁₁ = t³ − t²`. Two points give the classic single segment on `[0, 1]`; more give a composite
//! curve that is C¹ at every joint by construction (both segments share the point and the
//! derivative there). Segment `i` is the cubic Bézier curve `Pᵢ, Pᵢ + Mᵢ/3, Pᵢ₊₁ − Mᵢ₊₁/3, Pᵢ₊₁`.

use super::bezier::points_bbox;
use super::error::{enough_points, finite_points};
use super::piece::{BezierPiece, Jet};
use super::{Curve3, CurveError};
use crate::Aabb;
use glam::DVec3;

/// A cubic Hermite curve through `n + 1 ≥ 2` points on `[0, n]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Hermite {
    points: Vec<DVec3>,
    tangents: Vec<DVec3>,
}

/// The Hermite basis `[h₀₀, h₁₀, h₀₁, h₁₁]` at `t`: the weights of `P₀, M₀, P₁, M₁`.
pub fn hermite_basis(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        2.0 * t3 - 3.0 * t2 + 1.0,
        t3 - 2.0 * t2 + t,
        -2.0 * t3 + 3.0 * t2,
        t3 - t2,
    ]
}

impl Hermite {
    /// The single segment from `p0` (derivative `m0`) to `p1` (derivative `m1`) on `[0, 1]`.
    pub fn new(p0: DVec3, m0: DVec3, p1: DVec3, m1: DVec3) -> Result<Hermite, CurveError> {
        Hermite::through(vec![p0, p1], vec![m0, m1])
    }

    /// The composite curve through `points` with derivatives `tangents` (one per point, at
    /// least two): segment `i` covers the parameters `[i, i + 1]`.
    pub fn through(points: Vec<DVec3>, tangents: Vec<DVec3>) -> Result<Hermite, CurveError> {
        enough_points("points", points.len(), 2)?;
        if tangents.len() != points.len() {
            return Err(CurveError::TangentCount {
                expected: points.len(),
                found: tangents.len(),
            });
        }
        finite_points("points", &points)?;
        finite_points("tangents", &tangents)?;
        Ok(Hermite { points, tangents })
    }

    /// The points `Pᵢ`.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The derivatives `Mᵢ`.
    pub fn tangents(&self) -> &[DVec3] {
        &self.tangents
    }

    /// The number of cubic segments.
    pub fn segments(&self) -> usize {
        self.points.len() - 1
    }

    /// The cubic Bézier control points of segment `i`.
    pub fn bezier_points(&self, i: usize) -> [DVec3; 4] {
        let (p0, m0) = (self.points[i], self.tangents[i]);
        let (p1, m1) = (self.points[i + 1], self.tangents[i + 1]);
        [p0, p0 + m0 / 3.0, p1 - m1 / 3.0, p1]
    }
}

/// Point and derivatives of the Hermite segment `(p0, m0, p1, m1)` at local `t ∈ [0, 1]`.
pub(crate) fn hermite_jet(p0: DVec3, m0: DVec3, p1: DVec3, m1: DVec3, t: f64) -> Jet {
    let [h00, h10, h01, h11] = hermite_basis(t);
    let point = p0 * h00 + m0 * h10 + p1 * h01 + m1 * h11;
    let t2 = t * t;
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
        (0.0, self.segments() as f64)
    }
    fn jet(&self, t: f64) -> Jet {
        let n = self.segments();
        let t = t.clamp(0.0, n as f64);
        let i = (t.floor() as usize).min(n - 1);
        let (p, m) = (&self.points, &self.tangents);
        hermite_jet(p[i], m[i], p[i + 1], m[i + 1], t - i as f64)
    }
    fn control_bbox(&self) -> Aabb {
        let all: Vec<DVec3> = (0..self.segments())
            .flat_map(|i| self.bezier_points(i))
            .collect();
        points_bbox(&all)
    }
    fn pieces(&self) -> Vec<BezierPiece> {
        (0..self.segments())
            .map(|i| BezierPiece::polynomial(i as f64, (i + 1) as f64, &self.bezier_points(i)))
            .collect()
    }
}
