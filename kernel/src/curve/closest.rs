//! Closest point on a curve, for distance fields. The curve is split once into nearly straight
//! spans (at most ~17° of turning each) under a tree of boxes. A query searches the tree nearest
//! first, skipping every subtree whose box is farther than the best point so far; in each span it
//! keeps the end points and, when the distance decreases into the span from both ends, the
//! interior minimum found by Newton's method on `C'(t)·(C(t) − p) = 0`, safeguarded by bisection
//! inside the bracket (so it always converges to a local minimum within the span). Each span is
//! evaluated from its own Bézier piece (in the power basis by Horner's rule up to degree 7), which
//! is several times cheaper than evaluating the whole curve.
//!
//! Exactness: within a nearly straight span the squared distance has a single interior minimum
//! for every point closer to the span than its radius of curvature, so the result is the exact
//! closest point there (to rounding). Farther away a span can in principle hold two interior
//! minima, of which the search finds one; the value returned is then still the distance to a point
//! of the curve. No allocation per query.

use super::Curve3;
use super::piece::BezierPiece;
use super::piece::Jet;
use super::spans::{SpanTree, box_distance_squared, flat_spans};
use crate::Aabb;
use glam::{DVec3, DVec4};

/// One nearly straight span of a curve: its own Bézier piece (evaluated during refinement, much
/// cheaper than the whole curve) and its one-sided end jets.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Span {
    /// First parameter.
    pub t0: f64,
    /// Last parameter.
    pub t1: f64,
    /// Point and derivatives at `t0` (from the right).
    pub start: Jet,
    /// Point and derivatives at `t1` (from the left).
    pub end: Jet,
    /// The curve over `[t0, t1]`.
    pub piece: BezierPiece,
    /// The piece's homogeneous polynomial in the power basis of `s = (t − t0)/(t1 − t0)`, for
    /// degrees up to [`POWER_DEGREE`] (empty above: de Casteljau is used).
    power: Vec<DVec4>,
}

/// Highest degree evaluated in the power basis (well conditioned on `[0, 1]` at low degree).
const POWER_DEGREE: usize = 7;

/// Power-basis coefficients `aₖ = C(n, k) Σᵢ (−1)^(k−i) C(k, i) Pᵢ` of a Bézier polynomial.
fn power_basis(points: &[DVec4]) -> Vec<DVec4> {
    let n = points.len() - 1;
    let binomial =
        |n: usize, k: usize| (0..k).fold(1.0, |b, i| b * (n - i) as f64 / (i + 1) as f64);
    (0..=n)
        .map(|k| {
            let sum: DVec4 = (0..=k)
                .map(|i| {
                    let sign = if (k - i) % 2 == 0 { 1.0 } else { -1.0 };
                    points[i] * (sign * binomial(k, i))
                })
                .sum();
            sum * binomial(n, k)
        })
        .collect()
}

/// The parameter range and one-sided end jets of a span (what refinement needs besides the
/// evaluation itself).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Ends {
    pub t0: f64,
    pub t1: f64,
    pub start: Jet,
    pub end: Jet,
}

impl Span {
    /// Its parameter range and end jets.
    pub(crate) fn ends(&self) -> Ends {
        Ends {
            t0: self.t0,
            t1: self.t1,
            start: self.start,
            end: self.end,
        }
    }

    /// The span of `piece` with its end jets.
    pub(crate) fn of(piece: BezierPiece) -> Span {
        let power = if piece.points.len() <= POWER_DEGREE + 1 && piece.t1 > piece.t0 {
            power_basis(&piece.points)
        } else {
            Vec::new()
        };
        Span {
            t0: piece.t0,
            t1: piece.t1,
            start: piece.jet(piece.t0),
            end: piece.jet(piece.t1),
            piece,
            power,
        }
    }

    /// Point and derivatives at `t` (clamped to the span), by Horner's rule on the power basis.
    pub(crate) fn jet(&self, t: f64) -> Jet {
        let Some((&last, rest)) = self.power.split_last() else {
            return self.piece.jet(t);
        };
        let k = 1.0 / (self.t1 - self.t0);
        let s = ((t - self.t0) * k).clamp(0.0, 1.0);
        let (mut a, mut d1, mut d2) = (last, DVec4::ZERO, DVec4::ZERO);
        for &c in rest.iter().rev() {
            d2 = d2 * s + d1 * 2.0;
            d1 = d1 * s + a;
            a = a * s + c;
        }
        Jet::from_homogeneous([a, d1, d2]).rescaled(k)
    }
}

/// The closest point of a curve to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closest {
    /// Its parameter.
    pub t: f64,
    /// The point on the curve.
    pub point: DVec3,
    /// Its distance from the query point.
    pub distance: f64,
    /// Point and derivatives of the curve there (one-sided at a span's end).
    pub jet: Jet,
}

/// A curve's spans and box tree, built once per curve and shared by all queries.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveIndex {
    spans: Vec<Span>,
    tree: SpanTree,
    boxes: Vec<Aabb>,
}

impl CurveIndex {
    /// Splits `curve` into nearly straight spans and builds their box tree.
    pub fn new(curve: &impl Curve3) -> CurveIndex {
        let pieces = flat_spans(&curve.pieces());
        let span_boxes: Vec<Aabb> = pieces.iter().map(|p| p.bbox()).collect();
        let spans: Vec<Span> = pieces.into_iter().map(Span::of).collect();
        let tree = SpanTree::new(spans.len());
        let boxes = tree.boxes(&span_boxes);
        CurveIndex { spans, tree, boxes }
    }

    /// A box containing the curve (tighter than the control points' box).
    pub fn bbox(&self) -> Aabb {
        self.boxes[0]
    }

    /// The spans in parameter order.
    pub(crate) fn spans(&self) -> &[Span] {
        &self.spans
    }

    /// The closest point to `p` of the curve this index was built from.
    pub fn closest(&self, p: DVec3) -> Closest {
        self.closest_in(p, 0, self.spans.len() - 1)
    }

    /// The closest point to `p` among the spans `first..=last`.
    pub(crate) fn closest_in(&self, p: DVec3, first: usize, last: usize) -> Closest {
        let mut found = (self.spans[first].t0, self.spans[first].start);
        let best = self.tree.search(
            |node| {
                let (lo, hi) = self.tree.range(node);
                if hi < first || lo > last {
                    f64::INFINITY
                } else {
                    box_distance_squared(&self.boxes[node], p)
                }
            },
            |i, best| {
                let s = &self.spans[i];
                let (t, jet, d2) = refine(|t| s.jet(t), p, s.ends());
                if d2 < best {
                    found = (t, jet);
                    d2
                } else {
                    best
                }
            },
            f64::INFINITY,
        );
        Closest {
            t: found.0,
            point: found.1.point,
            distance: best.sqrt(),
            jet: found.1,
        }
    }

    /// A box containing the spans `first..=last`.
    pub(crate) fn spans_bbox(&self, first: usize, last: usize) -> Aabb {
        // Union of the largest tree nodes inside the range.
        let mut out = Aabb::empty();
        let mut work = vec![0usize];
        while let Some(node) = work.pop() {
            let (lo, hi) = self.tree.range(node);
            if hi < first || lo > last {
                continue;
            }
            if lo >= first && hi <= last {
                out = out.union(&self.boxes[node]);
            } else if let Some((a, b)) = self.tree.children(node) {
                work.push(a);
                work.push(b);
            }
        }
        out
    }
}

/// The closest point to `p` on one span of the curve with jets `jet`: an end, or the interior
/// minimum when the distance decreases into the span from both ends. Returns `(t, jet, d²)`.
pub(crate) fn refine(jet: impl Fn(f64) -> Jet, p: DVec3, span: Ends) -> (f64, Jet, f64) {
    let slope = |j: &Jet| j.d1.dot(j.point - p);
    let (d_start, d_end) = (
        (span.start.point - p).length_squared(),
        (span.end.point - p).length_squared(),
    );
    let mut best = if d_start <= d_end {
        (span.t0, span.start, d_start)
    } else {
        (span.t1, span.end, d_end)
    };
    let (ga, gb) = (slope(&span.start), slope(&span.end));
    if !(ga < 0.0 && gb > 0.0) {
        return best;
    }
    let (mut lo, mut hi) = (span.t0, span.t1);
    let mut t = lo + (hi - lo) * (ga / (ga - gb));
    let tolerance = 4.0 * f64::EPSILON * (span.t1 - span.t0).max(span.t0.abs().max(span.t1.abs()));
    let mut j = jet(t);
    for _ in 0..100 {
        let r = j.point - p;
        let g1 = j.d1.dot(r);
        if g1 == 0.0 {
            break;
        }
        if g1 < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let g2 = j.d2.dot(r) + j.d1.length_squared();
        let newton = t - g1 / g2;
        let next = if g2 > 0.0 && newton >= lo && newton <= hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        // Converged: the point at `t` is within rounding of the minimum.
        if (next - t).abs() <= tolerance || hi - lo <= tolerance {
            break;
        }
        t = next;
        j = jet(t);
    }
    let d2 = (j.point - p).length_squared();
    if d2 < best.2 {
        best = (t, j, d2);
    }
    best
}
