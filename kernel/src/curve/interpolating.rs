//! The interpolating cubic spline through a list of points: `C(i) = Pᵢ` at the integer
//! parameters `i = 0, 1, …` (uniform parametrisation), C² everywhere. An open spline has natural
//! ends (`C'' = 0` at both ends) and the domain `[0, n − 1]`; a closed one is periodic through
//! `Pₙ₋₁` back to `P₀` with the domain `[0, n]`. Each segment is the cubic Hermite segment between
//! consecutive points with the derivatives solved from the C² conditions
//! `Dᵢ₋₁ + 4Dᵢ + Dᵢ₊₁ = 3(Pᵢ₊₁ − Pᵢ₋₁)` (tridiagonal, or cyclic when closed).

use super::error::{enough_points, finite_points};
use super::hermite::hermite_jet;
use super::piece::{BezierPiece, Jet};
use super::{Curve3, CurveError, tridiagonal};
use crate::Aabb;
use glam::DVec3;

/// A C² cubic spline through its points.
#[derive(Debug, Clone, PartialEq)]
pub struct Interpolating {
    points: Vec<DVec3>,
    closed: bool,
    /// Derivative at each point (derived from the points).
    tangents: Vec<DVec3>,
}

impl Interpolating {
    /// The spline through `points` (at least 2, or 3 when `closed`).
    pub fn new(points: Vec<DVec3>, closed: bool) -> Result<Interpolating, CurveError> {
        enough_points("points", points.len(), if closed { 3 } else { 2 })?;
        finite_points("points", &points)?;
        let n = points.len();
        let tangents = if closed {
            let d: Vec<DVec3> = (0..n)
                .map(|i| (points[(i + 1) % n] - points[(i + n - 1) % n]) * 3.0)
                .collect();
            tridiagonal::solve_cyclic(1.0, 4.0, 1.0, &d)
        } else {
            let mut b = vec![4.0; n];
            b[0] = 2.0;
            b[n - 1] = 2.0;
            let d: Vec<DVec3> = (0..n)
                .map(|i| (points[(i + 1).min(n - 1)] - points[i.saturating_sub(1)]) * 3.0)
                .collect();
            tridiagonal::solve(&vec![1.0; n], &b, &vec![1.0; n], &d)
        };
        Ok(Interpolating {
            points,
            closed,
            tangents,
        })
    }

    /// The interpolated points.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// Whether the spline closes back to its first point.
    pub fn closed(&self) -> bool {
        self.closed
    }

    /// The derivative at each interpolated point.
    pub fn tangents(&self) -> &[DVec3] {
        &self.tangents
    }

    fn segments(&self) -> usize {
        if self.closed {
            self.points.len()
        } else {
            self.points.len() - 1
        }
    }

    /// End points and derivatives of segment `i`.
    fn segment(&self, i: usize) -> (DVec3, DVec3, DVec3, DVec3) {
        let j = (i + 1) % self.points.len();
        (
            self.points[i],
            self.tangents[i],
            self.points[j],
            self.tangents[j],
        )
    }
}

impl Curve3 for Interpolating {
    fn domain(&self) -> (f64, f64) {
        (0.0, self.segments() as f64)
    }
    fn jet(&self, t: f64) -> Jet {
        let last = self.segments() - 1;
        let t = t.clamp(0.0, self.segments() as f64);
        let i = (t.floor() as usize).min(last);
        let (p0, m0, p1, m1) = self.segment(i);
        hermite_jet(p0, m0, p1, m1, t - i as f64)
    }
    fn control_bbox(&self) -> Aabb {
        self.pieces()
            .iter()
            .fold(Aabb::empty(), |b, piece| b.union(&piece.bbox()))
    }
    fn pieces(&self) -> Vec<BezierPiece> {
        (0..self.segments())
            .map(|i| {
                let (p0, m0, p1, m1) = self.segment(i);
                let pts = [p0, p0 + m0 / 3.0, p1 - m1 / 3.0, p1];
                BezierPiece::polynomial(i as f64, (i + 1) as f64, &pts)
            })
            .collect()
    }
}
