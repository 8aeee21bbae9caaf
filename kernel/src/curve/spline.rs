//! The B-spline machinery shared by [`BSpline`](super::BSpline) and [`Nurbs`](super::Nurbs): a
//! spline with homogeneous control points `(w·P, w)` evaluated by de Boor's algorithm, its
//! derivative splines (hodographs), Bézier extraction of each knot span by blossoming, and knot
//! vector validation.

use super::CurveError;
use super::casteljau::with_scratch;
use super::piece::{BezierPiece, Jet};
use glam::DVec4;

/// A spline of degree `p` with `n` homogeneous control points and `n + p + 1` knots; its domain is
/// `[knots[p], knots[n]]`. Built only from validated data.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Core {
    degree: usize,
    knots: Vec<f64>,
    points: Vec<DVec4>,
}

impl Core {
    pub(crate) fn new(degree: usize, knots: Vec<f64>, points: Vec<DVec4>) -> Core {
        debug_assert_eq!(knots.len(), points.len() + degree + 1);
        Core {
            degree,
            knots,
            points,
        }
    }

    pub(crate) fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.points.len()])
    }

    /// The knot span `k ∈ [p, n − 1]` with `knots[k] ≤ t < knots[k + 1]` (the last non-empty
    /// span at the end of the domain).
    fn span(&self, t: f64) -> usize {
        let (p, n) = (self.degree, self.points.len());
        if t >= self.knots[n] {
            let mut k = n - 1;
            while k > p && self.knots[k] >= self.knots[n] {
                k -= 1;
            }
            return k;
        }
        let below = self.knots[p..n].partition_point(|&u| u <= t);
        (p + below).saturating_sub(1).clamp(p, n - 1)
    }

    /// de Boor's algorithm at `t` where level `r` uses the parameter `arg(r)` (the blossom; a
    /// constant `arg` gives the point).
    fn de_boor(&self, k: usize, arg: impl Fn(usize) -> f64) -> DVec4 {
        let p = self.degree;
        with_scratch(p + 1, |d: &mut [DVec4]| {
            d.copy_from_slice(&self.points[k - p..=k]);
            for r in 1..=p {
                let x = arg(r);
                for j in (r..=p).rev() {
                    let i = j + k - p;
                    let denominator = self.knots[i + p + 1 - r] - self.knots[i];
                    let a = if denominator > 0.0 {
                        (x - self.knots[i]) / denominator
                    } else {
                        0.0
                    };
                    d[j] = d[j - 1] * (1.0 - a) + d[j] * a;
                }
            }
            d[p]
        })
    }

    /// The homogeneous point at `t` (clamped to the domain).
    pub(crate) fn eval(&self, t: f64) -> DVec4 {
        let (a, b) = self.domain();
        let t = t.clamp(a, b);
        self.de_boor(self.span(t), |_| t)
    }

    /// The derivative spline: degree `p − 1`, points `p (Pᵢ₊₁ − Pᵢ) / (uᵢ₊ₚ₊₁ − uᵢ₊₁)`, the knots
    /// without the first and last. `None` for degree 0 (its derivative is zero).
    pub(crate) fn derivative(&self) -> Option<Core> {
        let p = self.degree;
        if p == 0 {
            return None;
        }
        let points = self
            .points
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                let d = self.knots[i + p + 1] - self.knots[i + 1];
                if d > 0.0 {
                    (w[1] - w[0]) * (p as f64 / d)
                } else {
                    DVec4::ZERO
                }
            })
            .collect();
        Some(Core::new(
            p - 1,
            self.knots[1..self.knots.len() - 1].to_vec(),
            points,
        ))
    }

    /// Bézier pieces of the non-empty knot spans: control point `j` of the span `[a, b]` is the
    /// blossom `f(a, …, a, b, …, b)` with `j` arguments `b`.
    pub(crate) fn pieces(&self) -> Vec<BezierPiece> {
        let (p, n) = (self.degree, self.points.len());
        (p..n)
            .filter(|&k| self.knots[k] < self.knots[k + 1])
            .map(|k| {
                let (a, b) = (self.knots[k], self.knots[k + 1]);
                let points = (0..=p)
                    .map(|j| self.de_boor(k, |r| if r <= p - j { a } else { b }))
                    .collect();
                BezierPiece {
                    t0: a,
                    t1: b,
                    points,
                }
            })
            .collect()
    }
}

/// A spline with its first two derivative splines, evaluated as a rational curve.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Rational {
    core: Core,
    d1: Option<Core>,
    d2: Option<Core>,
}

impl Rational {
    pub(crate) fn new(core: Core) -> Rational {
        let d1 = core.derivative();
        let d2 = d1.as_ref().and_then(Core::derivative);
        Rational { core, d1, d2 }
    }

    pub(crate) fn domain(&self) -> (f64, f64) {
        self.core.domain()
    }

    pub(crate) fn point(&self, t: f64) -> glam::DVec3 {
        let a = self.core.eval(t);
        a.truncate() / a.w
    }

    pub(crate) fn jet(&self, t: f64) -> Jet {
        let eval = |c: &Option<Core>| c.as_ref().map_or(DVec4::ZERO, |c| c.eval(t));
        Jet::from_homogeneous([self.core.eval(t), eval(&self.d1), eval(&self.d2)])
    }

    pub(crate) fn pieces(&self) -> Vec<BezierPiece> {
        self.core.pieces()
    }
}

/// Implements [`Curve3`](super::Curve3) for a spline curve type (B-spline or NURBS) with the
/// fields `spline: Rational` (its homogeneous spline, evaluated by de Boor's algorithm and
/// projected by dividing by `w`) and `points: Vec<DVec3>` (its control points, whose box bounds
/// the curve).
macro_rules! spline_curve3 {
    ($curve:ty) => {
        impl $crate::curve::Curve3 for $curve {
            fn domain(&self) -> (f64, f64) {
                self.spline.domain()
            }
            fn point(&self, t: f64) -> ::glam::DVec3 {
                self.spline.point(t)
            }
            fn jet(&self, t: f64) -> $crate::curve::Jet {
                self.spline.jet(t)
            }
            fn control_bbox(&self) -> $crate::Aabb {
                $crate::curve::bezier::points_bbox(&self.points)
            }
            fn pieces(&self) -> Vec<$crate::curve::BezierPiece> {
                self.spline.pieces()
            }
        }
    };
}
pub(crate) use spline_curve3;

/// Checks a degree and knot vector against `n` control points: `1 ≤ p ≤ n − 1`, `n + p + 1`
/// finite non-decreasing knots, interior knots repeated at most `p` times (so the curve stays
/// connected), and a non-empty domain.
pub(crate) fn check_knots(degree: usize, n: usize, knots: &[f64]) -> Result<(), CurveError> {
    if degree == 0 || degree + 1 > n {
        return Err(CurveError::BadDegree {
            degree,
            max: n.saturating_sub(1),
        });
    }
    if knots.len() != n + degree + 1 {
        return Err(CurveError::KnotCount {
            expected: n + degree + 1,
            found: knots.len(),
        });
    }
    if knots.iter().any(|k| !k.is_finite()) {
        return Err(CurveError::NonFinite { parameter: "knots" });
    }
    if let Some(i) = (1..knots.len()).find(|&i| knots[i] < knots[i - 1]) {
        return Err(CurveError::KnotsDecreasing { index: i });
    }
    let (lo, hi) = (knots[degree], knots[n]);
    if lo >= hi {
        return Err(CurveError::EmptyDomain);
    }
    let mut start = 0;
    while start < knots.len() {
        let end = knots[start..].partition_point(|&u| u <= knots[start]) + start;
        let interior = knots[start] > lo && knots[start] < hi;
        let limit = if interior { degree } else { degree + 1 };
        if end - start > limit {
            return Err(CurveError::KnotMultiplicity { index: start });
        }
        start = end;
    }
    Ok(())
}

/// Uniform knots `0, 1, …, n + p` (domain `[p, n]`).
pub(crate) fn uniform_knots(degree: usize, n: usize) -> Vec<f64> {
    (0..n + degree + 1).map(|i| i as f64).collect()
}

/// Clamped (open uniform) knots: `p + 1` zeros, `1, …, n − p − 1`, `p + 1` copies of `n − p`
/// (domain `[0, n − p]`; the curve starts and ends at its end control points).
pub(crate) fn clamped_knots(degree: usize, n: usize) -> Vec<f64> {
    let last = n.saturating_sub(degree) as f64;
    (0..n + degree + 1)
        .map(|i| (i as f64 - degree as f64).clamp(0.0, last))
        .collect()
}
