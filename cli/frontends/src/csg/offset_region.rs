//! Offsets of any 2D region through its polygons ([`super::region`]), as OpenSCAD's Clipper
//! offsets build them:
//! - growing by `d > 0`: the region, a strip `d` wide on each side of every edge, and at every
//!   convex corner its join: a circular arc stepped from one edge's normal to the next (`offset(r)`,
//!   Clipper's round join with OpenSCAD's step angle `360°/$fn`), the mitre quad (`delta`; squared
//!   off at distance `d` past a mitre ratio of 10⁶, OpenSCAD's limit) or the mitre cut square at
//!   distance `d` from the corner (`chamfer`);
//! - shrinking by `d < 0`: the complement, in a frame well clear of the region, grown by `|d|`
//!   and taken away from the frame (so the joins fall on the region's reflex corners).
//!
//! The union is taken by polygon clipping; the result is polygons again.

use super::Facets;
use super::facets::{self, Resolution};
use super::flat::Flat;
use super::region::{self, RegionError, Shape};
use glam::DVec2;
use i_overlay::core::overlay_rule::OverlayRule;

/// How corners are joined when an outline grows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Join {
    /// Circular arcs of `$fn/$fa/$fs` (exact facets: a sagitta of [`region::EXACT_SAGITTA`]).
    Round(Resolution),
    /// Sharp mitres.
    Miter,
    /// Mitres cut square at the offset distance from the corner.
    Chamfer,
}

/// OpenSCAD's mitre limit (the mitre's length over the offset, past which a corner is squared).
const MITER_LIMIT: f64 = 1e6;

/// The region `flat` offset by `d` with corners joined by `join`; `None` when nothing is left.
pub fn offset_region(
    flat: &Flat,
    d: f64,
    join: Join,
    how: Facets,
) -> Result<Option<Flat>, RegionError> {
    let shapes = region::shapes(flat, how)?;
    Ok(region::to_flat(offset_shapes(&shapes, d, join, how)?))
}

/// [`offset_region`] on polygons.
pub fn offset_shapes(
    shapes: &[Shape],
    d: f64,
    join: Join,
    how: Facets,
) -> Result<Vec<Shape>, RegionError> {
    let Some((lo, hi)) = region::bounds(shapes) else {
        return Ok(Vec::new());
    };
    if d == 0.0 {
        return Ok(shapes.to_vec());
    }
    let size = (hi - lo).max_element();
    if -d >= size {
        return Ok(Vec::new()); // no disc of radius |d| fits
    }
    let limit = region::MAX_COORDINATE / 8.0;
    if d.abs() > limit {
        return Err(format!(
            "an offset of {d:e} is beyond ±{limit:e}, which polygon clipping does not take"
        ));
    }
    if d > 0.0 {
        return grow(shapes, d, join, how);
    }
    let margin = 4.0 * d.abs() + 0.1 * size + 1.0;
    let (a, b) = (lo - DVec2::splat(margin), hi + DVec2::splat(margin));
    let frame = vec![vec![a, DVec2::new(b.x, a.y), b, DVec2::new(a.x, b.y)]];
    let outside = region::boolean(
        std::slice::from_ref(&frame),
        shapes,
        OverlayRule::Difference,
    )?;
    let grown = grow(&outside, -d, join, how)?;
    region::boolean(&[frame], &grown, OverlayRule::Difference)
}

/// The shapes grown by `d > 0`.
fn grow(shapes: &[Shape], d: f64, join: Join, how: Facets) -> Result<Vec<Shape>, RegionError> {
    // The shapes' own loops keep their orientation (holes count −1), every added piece is
    // counter-clockwise: the positive winding is the union.
    let mut loops: Vec<Vec<DVec2>> = shapes.iter().flatten().cloned().collect();
    for l in shapes.iter().flatten() {
        let n = l.len();
        // Outward normals (the region lies left of each edge).
        let normal = |k: usize| {
            let e = l[(k + 1) % n] - l[k];
            DVec2::new(e.y, -e.x).normalize_or_zero()
        };
        for k in 0..n {
            let (a, b) = (l[k], l[(k + 1) % n]);
            let m = normal(k);
            if m == DVec2::ZERO {
                continue;
            }
            loops.push(region::ccw(vec![
                a + m * d,
                b + m * d,
                b - m * d,
                a - m * d,
            ]));
            // The corner at `b`, between edge k and the next edge of some length.
            let Some(next) = (1..n)
                .map(|s| normal((k + s) % n))
                .find(|q| *q != DVec2::ZERO)
            else {
                continue;
            };
            let turn = m.perp_dot(next);
            if turn < 0.0 || (turn == 0.0 && m.dot(next) > 0.0) {
                continue; // reflex or straight: the strips cover it
            }
            loops.push(region::ccw(corner(b, m, next, d, join, how)));
        }
    }
    region::positive(loops)
}

/// The join at a convex corner `v` from outward normal `n1` to `n2` (counter-clockwise; a
/// hairpin when they are opposite).
fn corner(v: DVec2, n1: DVec2, n2: DVec2, d: f64, join: Join, how: Facets) -> Vec<DVec2> {
    let cos = n1.dot(n2).clamp(-1.0, 1.0);
    match join {
        Join::Round(res) => {
            // Clipper's arithmetic, as OpenSCAD drives it: the arc tolerance from the fragment
            // count, the steps per turn back from the tolerance (so a right angle of 30
            // fragments takes 7 steps, not 7.5 rounded up), then whole steps per corner.
            let sides = region::disc_sides(facets::fragments(d, res), how) as f64;
            let tolerance = d * (1.0 - (std::f64::consts::PI / sides).cos());
            let per_turn = std::f64::consts::PI / (1.0 - tolerance / d).acos();
            let step = std::f64::consts::TAU / per_turn;
            let angle = n1.perp_dot(n2).atan2(cos);
            let steps = ((per_turn / std::f64::consts::TAU * angle).round() as usize).max(1);
            let mut piece = vec![v];
            for s in 0..steps {
                piece.push(v + DVec2::from_angle(s as f64 * step).rotate(n1) * d);
            }
            piece.push(v + n2 * d);
            piece
        }
        Join::Miter if 1.0 + cos >= 2.0 / (MITER_LIMIT * MITER_LIMIT) => {
            vec![v, v + n1 * d, v + (n1 + n2) * (d / (1.0 + cos)), v + n2 * d]
        }
        Join::Miter | Join::Chamfer => {
            // The mitre's two sides, cut where they reach `d` from `v` along the bisector
            // (Clipper's square join: `tan(θ/4)·d` along each side).
            let bisector = match (n1 + n2).normalize_or_zero() {
                DVec2::ZERO => n1.perp(),
                b => b,
            };
            let half = bisector.dot(n1).clamp(-1.0, 1.0).acos();
            let s = d * (half / 2.0).tan();
            vec![
                v,
                v + n1 * d,
                v + n1 * d + n1.perp() * s,
                v + n2 * d - n2.perp() * s,
                v + n2 * d,
            ]
        }
    }
}
