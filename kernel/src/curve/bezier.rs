//! Bézier curves of any degree on `[0, 1]`: de Casteljau evaluation (with derivatives) and
//! subdivision, the Bernstein form, and the hodograph. A single control point is a degree-0
//! curve (a point), which is how a ruled surface expresses an apex.

use super::error::{enough_points, finite_points};
use super::piece::{BezierPiece, Jet};
use super::{Curve3, CurveError, casteljau};
use crate::Aabb;
use glam::DVec3;

/// A Bézier curve `C(t) = Σ Bᵢⁿ(t) Pᵢ`, `t ∈ [0, 1]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Bezier {
    points: Vec<DVec3>,
}

impl Bezier {
    /// The curve with these control points (at least one, all finite).
    pub fn new(points: Vec<DVec3>) -> Result<Bezier, CurveError> {
        enough_points("points", points.len(), 1)?;
        finite_points("points", &points)?;
        Ok(Bezier { points })
    }

    /// The control points.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The degree (number of control points − 1).
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The point at `t` by de Casteljau's algorithm (`t` clamped to `[0, 1]`).
    pub fn de_casteljau(&self, t: f64) -> DVec3 {
        casteljau::point(&self.points, t.clamp(0.0, 1.0))
    }

    /// The point at `t` from the Bernstein form `Σ C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ Pᵢ` (for checking; de
    /// Casteljau is the stabler evaluation).
    pub fn bernstein(&self, t: f64) -> DVec3 {
        let t = t.clamp(0.0, 1.0);
        let n = self.degree();
        let mut sum = DVec3::ZERO;
        let mut binomial = 1.0;
        for (i, p) in self.points.iter().enumerate() {
            if i > 0 {
                binomial = binomial * (n - i + 1) as f64 / i as f64;
            }
            let basis = binomial * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32);
            sum += *p * basis;
        }
        sum
    }

    /// The two curves over `[0, t]` and `[t, 1]` (each on `[0, 1]`) that together trace this one.
    pub fn split(&self, t: f64) -> (Bezier, Bezier) {
        let (l, r) = casteljau::split(&self.points, t.clamp(0.0, 1.0));
        (Bezier { points: l }, Bezier { points: r })
    }

    /// The hodograph: the Bézier curve of degree `n − 1` with points `n (Pᵢ₊₁ − Pᵢ)`, equal to
    /// `C'`. The derivative of a point (degree 0) is the zero point.
    pub fn hodograph(&self) -> Bezier {
        let n = self.degree() as f64;
        let points: Vec<DVec3> = if self.points.len() == 1 {
            vec![DVec3::ZERO]
        } else {
            self.points.windows(2).map(|w| (w[1] - w[0]) * n).collect()
        };
        Bezier { points }
    }
}

impl Curve3 for Bezier {
    fn domain(&self) -> (f64, f64) {
        (0.0, 1.0)
    }
    fn point(&self, t: f64) -> DVec3 {
        self.de_casteljau(t)
    }
    fn jet(&self, t: f64) -> Jet {
        let [point, d1, d2] = casteljau::jet(&self.points, t.clamp(0.0, 1.0));
        Jet { point, d1, d2 }
    }
    fn control_bbox(&self) -> Aabb {
        points_bbox(&self.points)
    }
    fn pieces(&self) -> Vec<BezierPiece> {
        vec![BezierPiece::polynomial(0.0, 1.0, &self.points)]
    }
}

/// The smallest box containing the points.
pub(crate) fn points_bbox(points: &[DVec3]) -> Aabb {
    points.iter().fold(Aabb::empty(), |b, p| {
        Aabb::new(b.min.min(*p), b.max.max(*p))
    })
}
