//! Two curves blended: `γᵥ(u) = (1 − v)·a(u) + v·b(u)` in the xy plane, with both parameters
//! normalised to `u ∈ [0, 1]`; the slices of a ruled surface between two plane curves. One span
//! tree serves every `v`: the spans are cut at the breakpoints of both curves, and the box of `γᵥ`
//! over a span is the blend `(1 − v)·A + v·B` of the two curves' boxes there (each `γᵥ(u)` lies in
//! it). Closest points use the same nearest-first search and span refinement as single curves,
//! and report the outward normal needed to sign a distance (the average of the two one-sided
//! normals at a corner, which signs correctly for any point whose closest point is the corner).

use super::closest::{Ends, Span, refine};
use super::piece::{BezierPiece, Jet};
use super::quadrature::{gauss_legendre, integrate};
use super::spans::{SpanTree, box_distance_squared, flat_spans};
use super::{Curve, Curve3};
use crate::Aabb;
use glam::{DVec2, DVec3, DVec4};

/// One span of both curves over the same `[u0, u1]`, with one-sided end jets (in the xy plane,
/// derivatives with respect to `u`).
#[derive(Debug, Clone, PartialEq)]
struct BlendSpan {
    a: Span,
    b: Span,
}

/// The closest point of a blended curve `γᵥ` to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BlendClosest {
    /// Normalised parameter of the closest point.
    pub u: f64,
    /// The closest point (z = 0).
    pub point: DVec3,
    /// Its distance.
    pub distance: f64,
    /// Outward normal there for a counter-clockwise curve (not normalised; zero where the curve
    /// has no tangent).
    pub normal: DVec2,
    /// `b(u) − a(u)` there: how the slice's boundary point moves with `v`.
    pub offset: DVec3,
}

/// Span tree of a pair of curves.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BlendIndex {
    spans: Vec<BlendSpan>,
    tree: SpanTree,
    boxes_a: Vec<Aabb>,
    boxes_b: Vec<Aabb>,
    max_offset: f64,
}

/// The curve's pieces with parameters normalised to `[0, 1]` and z flattened to 0.
fn normalised_spans(curve: &Curve) -> Vec<BezierPiece> {
    let (t0, t1) = curve.domain();
    let k = 1.0 / (t1 - t0);
    let mut pieces = flat_spans(&curve.pieces());
    for p in &mut pieces {
        p.t0 = (p.t0 - t0) * k;
        p.t1 = (p.t1 - t0) * k;
        for q in &mut p.points {
            q.z = 0.0;
        }
    }
    pieces
}

/// The jet of `curve` at normalised `u`, flattened to the xy plane.
fn flat_jet(curve: &Curve, u: f64) -> Jet {
    let (t0, t1) = curve.domain();
    let k = t1 - t0;
    let j = curve.jet(t0 + u * k);
    let flat = |v: DVec3| DVec3::new(v.x, v.y, 0.0);
    Jet {
        point: flat(j.point),
        d1: flat(j.d1) * k,
        d2: flat(j.d2) * (k * k),
    }
}

fn lerp_jet(a: &Jet, b: &Jet, v: f64) -> Jet {
    Jet {
        point: a.point.lerp(b.point, v),
        d1: a.d1.lerp(b.d1, v),
        d2: a.d2.lerp(b.d2, v),
    }
}

fn blend_box(a: &Aabb, b: &Aabb, v: f64) -> Aabb {
    Aabb::new(a.min.lerp(b.min, v), a.max.lerp(b.max, v))
}

/// The outward normal `(T.y, −T.x)/|T|` of a counter-clockwise curve with tangent `t`.
fn normal(t: DVec3) -> DVec2 {
    DVec2::new(t.y, -t.x).normalize_or_zero()
}

/// The control points of the same curve one degree higher (homogeneous points elevate like
/// ordinary ones).
fn elevate(points: &[DVec4]) -> Vec<DVec4> {
    let n = points.len();
    let mut out = Vec::with_capacity(n + 1);
    out.push(points[0]);
    for i in 1..n {
        let a = i as f64 / n as f64;
        out.push(points[i - 1] * a + points[i] * (1.0 - a));
    }
    out.push(points[n - 1]);
    out
}

/// An upper bound of `|b(u) − a(u)|` over a common span of two pieces. When the pieces share
/// their weights (after raising to a common degree; a constant piece takes the other's weights)
/// the difference is a rational Bézier curve with control points `Pᵢ − Qᵢ`, so the largest
/// `|Pᵢ − Qᵢ|` bounds it tightly (zero for translated copies); otherwise the farthest points of
/// the two boxes do.
fn offset_bound(a: &BezierPiece, b: &BezierPiece) -> f64 {
    let (ba, bb) = (a.bbox(), b.bbox());
    let boxes = (ba.max - bb.min)
        .abs()
        .max((bb.max - ba.min).abs())
        .length();
    let constant = |p: &BezierPiece| {
        let first = p.points[0].truncate() / p.points[0].w;
        p.projected().all(|q| q == first).then_some(first)
    };
    let (mut pa, mut pb) = (a.points.clone(), b.points.clone());
    if let Some(x) = constant(a) {
        pa = pb.iter().map(|q| (x * q.w).extend(q.w)).collect();
    } else if let Some(x) = constant(b) {
        pb = pa.iter().map(|q| (x * q.w).extend(q.w)).collect();
    }
    while pa.len() < pb.len() {
        pa = elevate(&pa);
    }
    while pb.len() < pa.len() {
        pb = elevate(&pb);
    }
    let same_weights = pa
        .iter()
        .zip(&pb)
        .all(|(x, y)| (x.w - y.w).abs() <= 1e-14 * x.w.abs().max(y.w.abs()));
    if !same_weights {
        return boxes;
    }
    pa.iter()
        .zip(&pb)
        .map(|(x, y)| (y.truncate() / y.w - x.truncate() / x.w).length())
        .fold(0.0, f64::max)
        .min(boxes)
}

/// The restriction of the piece among `pieces` that contains `[u0, u1]`.
fn part(pieces: &[BezierPiece], u0: f64, u1: f64) -> Span {
    let mid = 0.5 * (u0 + u1);
    let i = pieces
        .partition_point(|p| p.t1 <= mid)
        .min(pieces.len() - 1);
    Span::of(pieces[i].restricted(u0, u1))
}

impl BlendIndex {
    /// The span tree of the pair `(a, b)`.
    pub(crate) fn new(a: &Curve, b: &Curve) -> BlendIndex {
        let (pa, pb) = (normalised_spans(a), normalised_spans(b));
        let mut cuts: Vec<f64> = pa.iter().chain(&pb).flat_map(|p| [p.t0, p.t1]).collect();
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|x, y| (*x - *y).abs() <= 1e-14);
        let mut spans = Vec::new();
        let (mut ba, mut bb) = (Vec::new(), Vec::new());
        let mut max_offset = 0.0f64;
        for w in cuts.windows(2) {
            let (a, b) = (part(&pa, w[0], w[1]), part(&pb, w[0], w[1]));
            max_offset = max_offset.max(offset_bound(&a.piece, &b.piece));
            ba.push(a.piece.bbox());
            bb.push(b.piece.bbox());
            spans.push(BlendSpan { a, b });
        }
        let tree = SpanTree::new(spans.len());
        let boxes_a = tree.boxes(&ba);
        let boxes_b = tree.boxes(&bb);
        BlendIndex {
            spans,
            tree,
            boxes_a,
            boxes_b,
            max_offset,
        }
    }

    /// A box containing `γᵥ` for every `v ∈ [0, 1]` (z = 0).
    pub(crate) fn bbox(&self) -> Aabb {
        self.boxes_a[0].union(&self.boxes_b[0])
    }

    /// An upper bound of `max_u |b(u) − a(u)|` (the horizontal speed of the slices in `v`): the
    /// largest distance between the two curves' boxes over the same span.
    pub(crate) fn max_offset(&self) -> f64 {
        self.max_offset
    }

    /// Signed area enclosed by `γᵥ` (positive counter-clockwise), by Gauss–Legendre quadrature of
    /// `½ ∮ (x y' − y x') du` over every span.
    pub(crate) fn area(&self, a: &Curve, b: &Curve, v: f64) -> f64 {
        let rule = gauss_legendre(24);
        self.spans
            .iter()
            .map(|s| {
                integrate(&rule, s.a.t0, s.a.t1, |u| {
                    let j = lerp_jet(&flat_jet(a, u), &flat_jet(b, u), v);
                    0.5 * (j.point.x * j.d1.y - j.point.y * j.d1.x)
                })
            })
            .sum()
    }

    /// The closest point of `γᵥ` to `q` (z ignored).
    pub(crate) fn closest(&self, v: f64, q: DVec3) -> BlendClosest {
        let q = DVec3::new(q.x, q.y, 0.0);
        let mut found = (0usize, 0.0, Jet::default());
        let best = self.tree.search(
            |node| box_distance_squared(&blend_box(&self.boxes_a[node], &self.boxes_b[node], v), q),
            |i, best| {
                let s = &self.spans[i];
                let ends = Ends {
                    t0: s.a.t0,
                    t1: s.a.t1,
                    start: lerp_jet(&s.a.start, &s.b.start, v),
                    end: lerp_jet(&s.a.end, &s.b.end, v),
                };
                let jet = |u: f64| lerp_jet(&s.a.jet(u), &s.b.jet(u), v);
                let (u, j, d2) = refine(jet, q, ends);
                if d2 < best {
                    found = (i, u, j);
                    d2
                } else {
                    best
                }
            },
            f64::INFINITY,
        );
        let (i, u, j) = found;
        let n = self.spans.len();
        let end_tangent = |k: usize| self.spans[k].a.end.d1.lerp(self.spans[k].b.end.d1, v);
        let start_tangent = |k: usize| self.spans[k].a.start.d1.lerp(self.spans[k].b.start.d1, v);
        let s = &self.spans[i];
        let normal = if u == s.a.t0 {
            normal(end_tangent((i + n - 1) % n)) + normal(start_tangent(i))
        } else if u == s.a.t1 {
            normal(end_tangent(i)) + normal(start_tangent((i + 1) % n))
        } else {
            normal(j.d1)
        };
        BlendClosest {
            u,
            point: j.point,
            distance: best.sqrt(),
            normal,
            offset: s.b.piece.point(u) - s.a.piece.point(u),
        }
    }
}
