//! `offset(r)` and `offset(delta, chamfer)` of 2D regions:
//! - `r > 0` (round) of any union of leaves with exact facets, exactly: the Minkowski sum with a
//!   disc distributes over unions, and for a polygon `P ⊕ D(r) = P ∪ ⋃ edges (edge ⊕ D(r))`,
//!   each edge's sum being a rectangle and two discs: so the offset is a union of the polygon, one
//!   rectangle per edge and one exact disc per corner. A disc grows by `r`.
//! - `r < 0`, and `delta` of either sign (mitred corners; `chamfer` cuts each corner at distance
//!   `delta` when growing), of one convex leaf, exactly: the intersection of the edges'
//!   half-planes moved by the offset (and of the corner cuts). A disc shrinks by `r` (`delta`
//!   offsets its n-gon).
//! - Anything else (shrinking or mitring a non-convex region, a region with holes or of several
//!   parts, any offset of a 2D difference or intersection, and every round growth under
//!   `--facets openscad`, whose corners are Clipper's arcs: `offset(r = 0.8)` with 5 fragments
//!   cuts a square's corners straight) through the region's polygons, as OpenSCAD's Clipper
//!   offsets build them ([`super::offset_region`]).

use super::Facets;
use super::facets;
use super::facets::Resolution;
use super::flat::{Flat, Leaf2, Op2};
use super::offset_region::{Join, offset_region};
use glam::DVec2;

/// The kind and size of an offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Offset {
    /// `offset(r)`: round corners, `res` facets them.
    Round {
        /// The distance (negative shrinks).
        r: f64,
        /// `$fn/$fa/$fs` of the `offset` statement.
        res: Resolution,
    },
    /// `offset(delta, chamfer)`.
    Delta {
        /// The distance (negative shrinks).
        delta: f64,
        /// Cut the corners when growing.
        chamfer: bool,
    },
}

/// The region `flat` offset; `None` when nothing is left; `Err` when clipping refuses its
/// coordinates.
pub fn offset(flat: Flat, how: Offset, facets: Facets) -> Result<Option<Flat>, String> {
    match how {
        Offset::Round { r: 0.0, .. } | Offset::Delta { delta: 0.0, .. } => Ok(Some(flat)),
        Offset::Round { r, res }
            if r > 0.0
                && facets == Facets::Exact
                && let Some(grown) = grow_round(&flat, r, res) =>
        {
            Ok(Some(grown))
        }
        _ => {
            let grows_round = matches!(how, Offset::Round { r, .. } if r > 0.0);
            if let [Op2::Leaf(leaf)] = flat.0.as_slice()
                && !grows_round
                && let Some(result) = convex(leaf, how)
            {
                return Ok(result);
            }
            let (d, join) = match how {
                Offset::Round { r, res } => (r, Join::Round(res)),
                Offset::Delta { delta, chamfer } => {
                    (delta, if chamfer { Join::Chamfer } else { Join::Miter })
                }
            };
            offset_region(&flat, d, join, facets)
        }
    }
}

/// `offset(r > 0)` of a union of leaves.
fn grow_round(flat: &Flat, r: f64, res: Resolution) -> Option<Flat> {
    let mut ops = Vec::new();
    for op in flat.0.iter().cloned() {
        match op {
            Op2::Leaf(Leaf2::Circle {
                center,
                radius,
                res: own,
            }) => ops.push(Op2::Leaf(Leaf2::Circle {
                center,
                radius: radius + r,
                res: own,
            })),
            Op2::Leaf(Leaf2::Polygon(loops)) => {
                let mut n = 1;
                ops.push(Op2::Leaf(Leaf2::Polygon(loops.clone())));
                for l in &loops {
                    for (k, &a) in l.iter().enumerate() {
                        let b = l[(k + 1) % l.len()];
                        let normal = (b - a).perp().normalize_or_zero() * r;
                        if normal == DVec2::ZERO {
                            continue;
                        }
                        let quad = vec![a + normal, b + normal, b - normal, a - normal];
                        ops.push(Op2::Leaf(Leaf2::Polygon(vec![quad])));
                        ops.push(Op2::Leaf(Leaf2::Circle {
                            center: a,
                            radius: r,
                            res,
                        }));
                        n += 2;
                    }
                }
                ops.push(Op2::Union(n));
            }
            Op2::Union(n) => ops.push(Op2::Union(n)),
            Op2::Difference(_) | Op2::Intersection(_) => return None,
        }
    }
    Some(Flat(ops))
}

/// Twice the signed area of a loop.
fn area2(l: &[DVec2]) -> f64 {
    (0..l.len())
        .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
        .sum()
}

/// The loop counter-clockwise, if it is convex.
fn convex_ccw(l: &[DVec2]) -> Option<Vec<DVec2>> {
    let mut l = l.to_vec();
    if area2(&l) < 0.0 {
        l.reverse();
    }
    let n = l.len();
    let turns_left = (0..n).all(|i| {
        let (a, b, c) = (l[i], l[(i + 1) % n], l[(i + 2) % n]);
        (b - a).perp_dot(c - b) >= 0.0
    });
    turns_left.then_some(l)
}

/// The part of `poly` (convex) where `n·x ≤ d`.
fn clip(poly: &[DVec2], n: DVec2, d: f64) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (k, &a) in poly.iter().enumerate() {
        let b = poly[(k + 1) % poly.len()];
        let (fa, fb) = (n.dot(a) - d, n.dot(b) - d);
        if fa <= 0.0 {
            out.push(a);
        }
        if (fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0) {
            out.push(a + (b - a) * (fa / (fa - fb)));
        }
    }
    out
}

/// Offset of one convex leaf (any `how` but a positive round one); `None` when the leaf is not
/// convex.
fn convex(leaf: &Leaf2, how: Offset) -> Option<Option<Flat>> {
    let corners = match (leaf, how) {
        (
            Leaf2::Circle {
                center,
                radius,
                res,
            },
            Offset::Round { r, .. },
        ) => {
            let radius = radius + r;
            return Some((radius > 0.0).then(|| {
                Flat::leaf(Leaf2::Circle {
                    center: *center,
                    radius,
                    res: *res,
                })
            }));
        }
        (
            Leaf2::Circle {
                center,
                radius,
                res,
            },
            Offset::Delta { .. },
        ) => facets::circle(*radius, facets::fragments(*radius, *res))
            .into_iter()
            .map(|p| p + *center)
            .collect(),
        (Leaf2::Polygon(loops), _) if loops.len() == 1 => loops[0].clone(),
        (Leaf2::Polygon(_), _) => return None,
    };
    let poly = convex_ccw(&corners)?;
    let (d, chamfer) = match how {
        Offset::Round { r, .. } => (r, false),
        Offset::Delta { delta, chamfer } => (delta, chamfer && delta > 0.0),
    };
    let (lo, hi) = poly.iter().fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    // A square around everything the result can reach (mitres reach far at sharp corners).
    let reach = (hi - lo).max_element() + 2.0 * d.abs() + 1.0;
    let (a, b) = (
        lo - DVec2::splat(reach * 10.0),
        hi + DVec2::splat(reach * 10.0),
    );
    let mut out = vec![a, DVec2::new(b.x, a.y), b, DVec2::new(a.x, b.y)];
    let n = poly.len();
    let normal = |k: usize| {
        let e = poly[(k + 1) % n] - poly[k];
        DVec2::new(e.y, -e.x).normalize_or_zero()
    };
    for (k, &corner) in poly.iter().enumerate() {
        let m = normal(k);
        if m == DVec2::ZERO {
            continue;
        }
        out = clip(&out, m, m.dot(corner) + d);
        if chamfer {
            let bisector = (normal((k + n - 1) % n) + m).normalize_or_zero();
            if bisector != DVec2::ZERO {
                out = clip(&out, bisector, bisector.dot(corner) + d);
            }
        }
        if out.len() < 3 {
            return Some(None);
        }
    }
    if area2(&out).abs() <= 1e-12 * reach * reach {
        return Some(None);
    }
    Some(Some(Flat::leaf(Leaf2::Polygon(vec![out]))))
}

#[cfg(test)]
mod tests {
    use super::super::region;
    use super::*;

    const RES: Resolution = Resolution {
        fn_: 0.0,
        fa: 12.0,
        fs: 2.0,
    };

    fn square(s: f64) -> Flat {
        Flat::leaf(Leaf2::Polygon(vec![vec![
            DVec2::ZERO,
            DVec2::new(s, 0.0),
            DVec2::new(s, s),
            DVec2::new(0.0, s),
        ]]))
    }

    fn only_polygon(f: &Flat) -> Vec<DVec2> {
        match f.0.as_slice() {
            [Op2::Leaf(Leaf2::Polygon(l))] => l[0].clone(),
            other => panic!("{other:?}"),
        }
    }

    fn area(f: Option<Flat>) -> f64 {
        f.map_or(0.0, |f| {
            region::area(&region::shapes(&f, Facets::Exact).unwrap())
        })
    }

    fn delta(delta: f64, chamfer: bool) -> Offset {
        Offset::Delta { delta, chamfer }
    }

    fn off(flat: Flat, how: Offset) -> Option<Flat> {
        offset(flat, how, Facets::Exact).unwrap()
    }

    #[test]
    fn delta_and_negative_round_offsets_of_a_square() {
        let grown = off(square(2.0), delta(1.0, false));
        assert!((area2(&only_polygon(&grown.unwrap())) / 2.0 - 16.0).abs() < 1e-9);
        let cut = off(square(2.0), delta(1.0, true));
        // Each mitred corner loses a right triangle with legs 2 − √2 (cut 1 from the corner).
        let expected = 16.0 - 4.0 * (3.0 - 2.0 * 2f64.sqrt());
        assert!((area2(&only_polygon(&cut.unwrap())) / 2.0 - expected).abs() < 1e-9);
        let shrunk = off(square(2.0), Offset::Round { r: -0.5, res: RES });
        assert!((area2(&only_polygon(&shrunk.unwrap())) / 2.0 - 1.0).abs() < 1e-9);
        assert_eq!(off(square(2.0), Offset::Round { r: -1.0, res: RES }), None);
    }

    #[test]
    fn round_growth_is_polygon_rectangles_and_discs() {
        let f = off(square(2.0), Offset::Round { r: 1.0, res: RES }).unwrap();
        let leaves = f.0.iter().filter(|o| matches!(o, Op2::Leaf(_))).count();
        assert_eq!(leaves, 9);
        assert_eq!(f.0.last(), Some(&Op2::Union(9)));
    }

    /// An L of three unit squares (area 3) with its reflex corner at (1, 1).
    fn ell() -> Flat {
        Flat::leaf(Leaf2::Polygon(vec![vec![
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 1.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(1.0, 2.0),
            DVec2::new(0.0, 2.0),
        ]]))
    }

    #[test]
    fn offsets_of_a_non_convex_polygon() {
        use std::f64::consts::PI;
        let d = 0.25;
        // Mitred growth: an L of two 2.5 × 1.5 arms overlapping in a 1.5-square.
        let grown = area(off(ell(), delta(d, false)));
        assert!(
            (grown - (2.5 * 1.5 * 2.0 - 1.5 * 1.5)).abs() < 1e-9,
            "{grown}"
        );
        // Mitred shrinking: arms of width 0.5 and length 1.5, sharp at the reflex corner.
        let shrunk = area(off(ell(), delta(-d, false)));
        assert!(
            (shrunk - (1.5 * 0.5 * 2.0 - 0.5 * 0.5)).abs() < 1e-9,
            "{shrunk}"
        );
        // Round shrinking rounds the reflex corner: of the square d × d the mitre takes there,
        // only a quarter disc of radius d is lost.
        let round = area(off(ell(), Offset::Round { r: -d, res: RES }));
        let expected = shrunk + d * d - PI * d * d / 4.0;
        assert!(
            (round - expected).abs() < 1e-4 * expected,
            "{round} {expected}"
        );
        // Chamfered shrinking cuts the mitre at distance d along its bisector: of the square
        // d × d the mitre takes, the triangle beyond the cut (legs d(2 − √2)) stays.
        let chamfer = area(off(ell(), delta(-d, true)));
        let kept = (d * (2.0 - 2f64.sqrt())).powi(2) / 2.0;
        assert!((chamfer - (shrunk + kept)).abs() < 1e-9, "{chamfer}");
        // Shrinking to nothing.
        assert_eq!(off(ell(), delta(-0.5, false)), None);
    }

    #[test]
    fn offsets_of_a_framed_square_and_of_a_difference() {
        // OpenSCAD's offset-tests shape1: a 20-square minus a 10-square.
        let frame = |w: f64| {
            let mut outer = square(w);
            outer.transform([[1.0, 0.0, -w / 2.0], [0.0, 1.0, -w / 2.0]]);
            let mut inner = square(10.0);
            inner.transform([[1.0, 0.0, -5.0], [0.0, 1.0, -5.0]]);
            Flat::combine(vec![outer, inner], Op2::Difference)
        };
        // delta 4: outer 28², the hole shrinks to 2².
        let a = area(off(frame(20.0), delta(4.0, false)));
        assert!((a - (28.0 * 28.0 - 4.0)).abs() < 1e-9, "{a}");
        // delta -5 of the 40-frame: outer 30², hole 20².
        let a = area(off(frame(40.0), delta(-5.0, false)));
        assert!((a - (900.0 - 400.0)).abs() < 1e-9, "{a}");
        // r = -10.01 of the 50-frame: the outline shrinks to a sharp 29.98-square, the hole
        // grows to a 30.02-square with corners rounded by 10.01, which leaves four corner
        // pieces of 9.99² less the quarter disc's part in them (21.12 each, by integration).
        let r = Offset::Round {
            r: -10.01,
            res: RES,
        };
        let corners = off(frame(50.0), r).map(|f| region::shapes(&f, Facets::Exact).unwrap());
        let corners = corners.unwrap_or_default();
        assert_eq!(corners.len(), 4);
        let a = region::area(&corners);
        assert!((a - 84.47998).abs() < 1e-3 * 84.48, "{a}");
        // r = 1 grows the outline with round corners and shrinks the hole to an 8-square.
        let a = area(off(frame(30.0), Offset::Round { r: 1.0, res: RES }));
        let expected = 32.0 * 32.0 - 4.0 + std::f64::consts::PI - 64.0;
        assert!((a - expected).abs() < 1e-3, "{a} {expected}");
    }
}
