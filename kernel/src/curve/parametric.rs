//! [`Parametric`]: any curve a user can give, the kinds with control points ([`Curve`]) and
//! formula curves ([`FormulaCurve`]), with what the `curve` command reports: points and
//! derivatives, arc length, the de Casteljau split of the Bézier piece at a parameter, and
//! polylines within a chord-error bound.

use super::flatten::{Polyline, flatten_pieces, flatten_sampled};
use super::quadrature::{gauss_legendre, integrate};
use super::{BezierPiece, Curve, Curve3, CurveError, FormulaCurve, Jet, arc_length};

/// A curve with control points, or a formula curve.
#[derive(Debug, Clone, PartialEq)]
pub enum Parametric {
    /// Bézier, Hermite, B-spline, NURBS, interpolating, cubic-through or composite.
    Curve(Curve),
    /// `(x(u), y(u), z(u))` given by formulas.
    Formula(FormulaCurve),
}

/// A Bézier piece of a curve split at a parameter by de Casteljau's algorithm.
#[derive(Debug, Clone, PartialEq)]
pub struct Split {
    /// Index of the piece (in [`Curve3::pieces`] order) holding the parameter.
    pub piece: usize,
    /// The piece's parameter interval.
    pub interval: (f64, f64),
    /// The local parameter `s ∈ [0, 1]` of the split within the piece.
    pub local: f64,
    /// The part over `[t0, t]` (homogeneous control points).
    pub left: BezierPiece,
    /// The part over `[t, t1]`.
    pub right: BezierPiece,
}

impl Parametric {
    /// The kind's name in the JSON format.
    pub fn name(&self) -> &'static str {
        match self {
            Parametric::Curve(c) => c.name(),
            Parametric::Formula(_) => "formula",
        }
    }

    /// The parameter interval.
    pub fn domain(&self) -> (f64, f64) {
        match self {
            Parametric::Curve(c) => c.domain(),
            Parametric::Formula(f) => f.domain(),
        }
    }

    /// Point, first and second derivative at `t` (clamped to the domain).
    pub fn jet(&self, t: f64) -> Jet {
        match self {
            Parametric::Curve(c) => c.jet(t),
            Parametric::Formula(f) => f.jet(t),
        }
    }

    /// The point at `t` (clamped to the domain).
    pub fn point(&self, t: f64) -> glam::DVec3 {
        match self {
            Parametric::Curve(c) => c.point(t),
            Parametric::Formula(f) => f.point(t),
        }
    }

    /// The rational Bézier pieces (none for a formula curve).
    pub fn pieces(&self) -> Option<Vec<BezierPiece>> {
        match self {
            Parametric::Curve(c) => Some(c.pieces()),
            Parametric::Formula(_) => None,
        }
    }

    /// The diagonal of a box around the curve: its control points' box, or for a formula curve
    /// the box of 257 equally spaced points.
    pub fn size(&self) -> f64 {
        match self {
            Parametric::Curve(c) => c.control_bbox().size().length(),
            Parametric::Formula(f) => {
                let p: Vec<_> = super::flatten::uniform_params(f.domain(), 257)
                    .into_iter()
                    .map(|u| f.point(u))
                    .collect();
                super::flatten::bounds(&p).size().length()
            }
        }
    }

    /// True when the curve ends where it starts (within `1e-9` of its size).
    pub fn is_closed(&self) -> bool {
        let (t0, t1) = self.domain();
        let (a, b) = (self.point(t0), self.point(t1));
        let (gap, size) = ((b - a).length(), self.size());
        if size.is_finite() {
            gap <= 1e-9 * size.max(f64::MIN_POSITIVE)
        } else {
            gap == 0.0
        }
    }

    /// The length `∫ |C'(t)| dt`: Gauss–Legendre quadrature on nearly straight spans for curves
    /// with control points (about machine precision), on 1024 equal spans for formula curves.
    pub fn arc_length(&self) -> f64 {
        match self {
            Parametric::Curve(c) => arc_length(c),
            Parametric::Formula(f) => {
                let rule = gauss_legendre(24);
                let (u0, u1) = f.domain();
                let n = 1024;
                (0..n)
                    .map(|i| {
                        let a = u0 + (u1 - u0) * i as f64 / n as f64;
                        let b = u0 + (u1 - u0) * (i + 1) as f64 / n as f64;
                        integrate(&rule, a, b, |t| f.jet(t).d1.length())
                    })
                    .sum()
            }
        }
    }

    /// The Bézier piece holding `t` split there (`None` for formula curves).
    pub fn split(&self, t: f64) -> Option<Split> {
        let pieces = self.pieces()?;
        let (d0, d1) = self.domain();
        let t = t.clamp(d0, d1);
        let piece = pieces
            .iter()
            .rposition(|p| p.t0 <= t)
            .unwrap_or(0)
            .min(pieces.len() - 1);
        let p = &pieces[piece];
        let local = if p.t1 > p.t0 {
            (t - p.t0) / (p.t1 - p.t0)
        } else {
            0.0
        };
        Some(Split {
            piece,
            interval: (p.t0, p.t1),
            local,
            left: p.restricted(p.t0, t),
            right: p.restricted(t, p.t1),
        })
    }

    /// A polyline whose chord error is below `tolerance` (certified for curves with control
    /// points, estimated from samples for formula curves; see [`super::flatten`]).
    pub fn polyline(&self, tolerance: f64) -> Result<Polyline, CurveError> {
        match self {
            Parametric::Curve(c) => flatten_pieces(&c.pieces(), tolerance),
            Parametric::Formula(f) => flatten_sampled(|u| f.point(u), f.domain(), tolerance),
        }
    }
}
