//! A curve as consecutive rational Bézier pieces in homogeneous coordinates `(w·x, w·y, w·z, w)`:
//! the common form every curve kind converts to, used for bounding boxes (convex hull property:
//! with positive weights a piece lies in the box of its projected control points) and for the
//! span subdivision of closest-point queries.

use super::casteljau;
use crate::Aabb;
use glam::{DVec3, DVec4};

/// One rational Bézier piece of a curve, covering the curve's parameters `[t0, t1]` linearly.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPiece {
    /// First parameter of the piece.
    pub t0: f64,
    /// Last parameter of the piece.
    pub t1: f64,
    /// Homogeneous control points `(w·p, w)`; all weights are 1 for polynomial curves.
    pub points: Vec<DVec4>,
}

/// Point, first and second derivative of a curve at one parameter.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Jet {
    /// The point `C(t)`.
    pub point: DVec3,
    /// `C'(t)`.
    pub d1: DVec3,
    /// `C''(t)`.
    pub d2: DVec3,
}

impl Jet {
    /// The jet of the projection `A.xyz / A.w` of a homogeneous curve with jet `[A, A', A'']`
    /// (quotient rule).
    pub(crate) fn from_homogeneous([a, a1, a2]: [DVec4; 3]) -> Jet {
        let w = a.w;
        let point = a.truncate() / w;
        let d1 = (a1.truncate() - point * a1.w) / w;
        let d2 = (a2.truncate() - d1 * (2.0 * a1.w) - point * a2.w) / w;
        Jet { point, d1, d2 }
    }

    /// The jet with the parameter scaled: derivatives with respect to `t = t0 + s·k` from those
    /// with respect to `s` (`d/dt = (1/k) d/ds`).
    pub(crate) fn rescaled(self, inverse_k: f64) -> Jet {
        Jet {
            point: self.point,
            d1: self.d1 * inverse_k,
            d2: self.d2 * (inverse_k * inverse_k),
        }
    }
}

impl BezierPiece {
    /// A polynomial piece (all weights 1).
    pub fn polynomial(t0: f64, t1: f64, points: &[DVec3]) -> BezierPiece {
        BezierPiece {
            t0,
            t1,
            points: points.iter().map(|p| p.extend(1.0)).collect(),
        }
    }

    /// The local parameter `s ∈ [0, 1]` of the curve parameter `t`.
    fn local(&self, t: f64) -> f64 {
        if self.t1 > self.t0 {
            ((t - self.t0) / (self.t1 - self.t0)).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    /// The point at curve parameter `t` (clamped to the piece).
    pub fn point(&self, t: f64) -> DVec3 {
        let a = casteljau::point(&self.points, self.local(t));
        a.truncate() / a.w
    }

    /// Point and derivatives with respect to the curve parameter at `t` (one-sided at the ends).
    pub fn jet(&self, t: f64) -> Jet {
        let j = Jet::from_homogeneous(casteljau::jet(&self.points, self.local(t)));
        let span = self.t1 - self.t0;
        if span > 0.0 {
            j.rescaled(1.0 / span)
        } else {
            j
        }
    }

    /// The piece over `[a, b] ⊆ [t0, t1]`.
    pub fn restricted(&self, a: f64, b: f64) -> BezierPiece {
        BezierPiece {
            t0: a,
            t1: b,
            points: casteljau::restrict(&self.points, self.local(a), self.local(b)),
        }
    }

    /// The two halves at the parameter midpoint.
    pub fn halves(&self) -> (BezierPiece, BezierPiece) {
        let mid = 0.5 * (self.t0 + self.t1);
        let (l, r) = casteljau::split(&self.points, 0.5);
        (
            BezierPiece {
                t0: self.t0,
                t1: mid,
                points: l,
            },
            BezierPiece {
                t0: mid,
                t1: self.t1,
                points: r,
            },
        )
    }

    /// The control points projected to 3D.
    pub fn projected(&self) -> impl Iterator<Item = DVec3> + '_ {
        self.points.iter().map(|a| a.truncate() / a.w)
    }

    /// The box of the projected control points: it contains the piece (positive weights).
    pub fn bbox(&self) -> Aabb {
        self.projected()
            .fold(Aabb::empty(), |b, p| Aabb::new(b.min.min(p), b.max.max(p)))
    }

    /// Total turning of the projected control polygon: the sum of the angles between successive
    /// non-degenerate legs (radians). A piece whose polygon turns little is nearly straight.
    pub fn turning(&self) -> f64 {
        let mut total = 0.0;
        let mut previous: Option<DVec3> = None;
        let pts: Vec<DVec3> = self.projected().collect();
        for w in pts.windows(2) {
            let leg = w[1] - w[0];
            if leg.length_squared() <= f64::MIN_POSITIVE {
                continue;
            }
            if let Some(prev) = previous {
                total += prev.angle_between(leg);
            }
            previous = Some(leg);
        }
        total
    }

    /// Ratio of the largest to the smallest weight (1 for polynomial pieces).
    pub fn weight_ratio(&self) -> f64 {
        let (lo, hi) = self
            .points
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), a| {
                (lo.min(a.w), hi.max(a.w))
            });
        hi / lo
    }
}
