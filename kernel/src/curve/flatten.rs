//! Polylines of curves within a chord-error bound: the largest distance from a point of the curve
//! to the polyline's segment over the same parameters stays below the bound.
//!
//! - **Curves with control points** ([`flatten_pieces`]): each rational Bézier piece is halved
//!   (de Casteljau) until every projected control point lies within the bound of the chord
//!   between the piece's end points. The piece lies in the convex hull of its control points
//!   (positive weights) and the distance to a segment is convex, so the bound is **certified**.
//! - **Formula curves** ([`flatten_sampled`]): 64 equal spans, each halved until the points at a
//!   quarter, half and three quarters of it lie within the bound of its chord. The bound is
//!   **estimated** from samples (a feature narrower than a sixty-fourth of the domain that no
//!   sample sees can be missed).
//!
//! Both use a work stack (no recursion) and stop with an error past [`MAX_POINTS`] points.

use super::CurveError;
use super::piece::BezierPiece;
use glam::DVec3;

/// Most points a polyline may have.
pub const MAX_POINTS: usize = 4_000_000;

/// A polyline along a curve: the parameters and points of its vertices, in order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Polyline {
    /// Curve parameter of each vertex.
    pub params: Vec<f64>,
    /// The vertices (points of the curve).
    pub points: Vec<DVec3>,
    /// True when the chord-error bound is certified (control polygons), false when estimated
    /// from samples.
    pub certified: bool,
}

/// Distance from `p` to the segment `[a, b]`.
pub fn segment_distance(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let s = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * s)).length()
}

fn check_tolerance(tolerance: f64) -> Result<(), CurveError> {
    if tolerance.is_finite() && tolerance > 0.0 {
        Ok(())
    } else {
        Err(CurveError::BadTolerance(tolerance))
    }
}

/// The polyline of consecutive pieces with a certified chord error below `tolerance`.
pub fn flatten_pieces(pieces: &[BezierPiece], tolerance: f64) -> Result<Polyline, CurveError> {
    check_tolerance(tolerance)?;
    let mut out = Polyline {
        certified: true,
        ..Polyline::default()
    };
    for first in pieces {
        let mut stack = vec![first.clone()];
        while let Some(piece) = stack.pop() {
            let ctrl: Vec<DVec3> = piece.projected().collect();
            let (a, b) = (ctrl[0], ctrl[ctrl.len() - 1]);
            if out.points.is_empty() {
                out.params.push(piece.t0);
                out.points.push(a);
            }
            let flat = ctrl.iter().all(|&p| segment_distance(p, a, b) <= tolerance);
            // A span too short to halve in floating point is kept as it is.
            let tiny = piece.t1 - piece.t0 <= 1e-14 * (1.0 + piece.t0.abs());
            if flat || tiny {
                out.params.push(piece.t1);
                out.points.push(b);
                if out.points.len() > MAX_POINTS {
                    return Err(CurveError::TooManyPoints {
                        tolerance,
                        limit: MAX_POINTS,
                    });
                }
            } else {
                let (l, r) = piece.halves();
                stack.push(r);
                stack.push(l);
            }
        }
    }
    Ok(out)
}

/// The polyline of `point` over `domain` with a chord error below `tolerance` as estimated from
/// samples.
pub fn flatten_sampled(
    point: impl Fn(f64) -> DVec3,
    domain: (f64, f64),
    tolerance: f64,
) -> Result<Polyline, CurveError> {
    check_tolerance(tolerance)?;
    let (u0, u1) = domain;
    let start = 64;
    let at = |i: usize| u0 + (u1 - u0) * i as f64 / start as f64;
    let mut out = Polyline {
        params: vec![u0],
        points: vec![point(u0)],
        certified: false,
    };
    // Spans still to check, last first so they pop in order.
    let mut stack: Vec<(f64, f64, DVec3, DVec3)> = (0..start)
        .rev()
        .map(|i| (at(i), at(i + 1), point(at(i)), point(at(i + 1))))
        .collect();
    while let Some((a, b, pa, pb)) = stack.pop() {
        let q = |s: f64| point(a + (b - a) * s);
        let mid = q(0.5);
        let far = [q(0.25), mid, q(0.75)]
            .iter()
            .map(|&p| segment_distance(p, pa, pb))
            .fold(0.0, f64::max);
        let tiny = b - a <= 1e-14 * (1.0 + a.abs());
        if far <= tolerance || tiny || far.is_nan() {
            out.params.push(b);
            out.points.push(pb);
            if out.points.len() > MAX_POINTS {
                return Err(CurveError::TooManyPoints {
                    tolerance,
                    limit: MAX_POINTS,
                });
            }
        } else {
            let m = 0.5 * (a + b);
            stack.push((m, b, mid, pb));
            stack.push((a, m, pa, mid));
        }
    }
    Ok(out)
}

/// `count ≥ 2` points at equally spaced parameters over `domain`, ends included.
pub fn uniform_params(domain: (f64, f64), count: usize) -> Vec<f64> {
    let n = count.max(2) - 1;
    (0..=n)
        .map(|i| domain.0 + (domain.1 - domain.0) * i as f64 / n as f64)
        .collect()
}

/// The smallest box containing `points`.
pub fn bounds(points: &[DVec3]) -> crate::Aabb {
    super::bezier::points_bbox(points)
}
