//! `offset(r)` and `offset(delta, chamfer)` of 2D regions, where the result is exact:
//! - `r > 0` (round) of any union of leaves: the Minkowski sum with a disc distributes over
//!   unions, and for a polygon `P ⊕ D(r) = P ∪ ⋃ edges (edge ⊕ D(r))`, each edge's sum being a
//!   rectangle and two discs: so the offset is a union of the polygon, one rectangle per edge and
//!   one disc per corner (exact discs, or OpenSCAD's n-gons of the `offset`'s `$fn/$fa/$fs` with
//!   `--facets openscad`). A disc grows by `r`.
//! - `r < 0`, and `delta` of either sign (mitred corners; `chamfer` cuts each corner at distance
//!   `delta` when growing), of one convex leaf: the intersection of the edges' half-planes moved
//!   by the offset (and of the corner cuts). A disc shrinks by `r` (`delta` offsets its n-gon).
//!
//! Shrinking or mitring a non-convex region, or offsetting a 2D difference or intersection, needs
//! polygon clipping this importer does not have: those are errors that say so.

use super::facets;
use super::facets::Resolution;
use super::flat::{Flat, Leaf2, Op2};
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

/// The region `flat` offset; `Ok(None)` when nothing is left.
pub fn offset(flat: Flat, how: Offset) -> Result<Option<Flat>, String> {
    match how {
        Offset::Round { r: 0.0, .. } => Ok(Some(flat)),
        Offset::Delta { delta: 0.0, .. } => Ok(Some(flat)),
        Offset::Round { r, res } if r > 0.0 => grow_round(flat, r, res).map(Some),
        _ => {
            let [Op2::Leaf(leaf)] = flat.0.as_slice() else {
                return Err(
                    "shrinking or mitring (r < 0, delta) a region of several parts is not \
                     supported (only a single convex polygon or circle)"
                        .into(),
                );
            };
            convex(leaf, how)
        }
    }
}

/// `offset(r > 0)` of a union of leaves.
fn grow_round(flat: Flat, r: f64, res: Resolution) -> Result<Flat, String> {
    let mut ops = Vec::new();
    for op in flat.0 {
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
            Op2::Difference(_) | Op2::Intersection(_) => {
                return Err(
                    "offset of a 2D difference or intersection is not supported (only of \
                     unions of polygons and circles)"
                        .into(),
                );
            }
        }
    }
    Ok(Flat(ops))
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

/// Offset of one convex leaf (any `how` but a positive round one).
fn convex(leaf: &Leaf2, how: Offset) -> Result<Option<Flat>, String> {
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
            return Ok((radius > 0.0).then(|| {
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
        (Leaf2::Polygon(_), _) => {
            return Err(
                "shrinking or mitring a polygon with several paths is not supported".into(),
            );
        }
    };
    let poly = convex_ccw(&corners).ok_or(
        "shrinking or mitring (r < 0, delta) a non-convex polygon is not supported (only convex \
         polygons and circles)",
    )?;
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
            return Ok(None);
        }
    }
    if area2(&out).abs() <= 1e-12 * reach * reach {
        return Ok(None);
    }
    Ok(Some(Flat::leaf(Leaf2::Polygon(vec![out]))))
}

#[cfg(test)]
mod tests {
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

    #[test]
    fn delta_and_negative_round_offsets_of_a_square() {
        let grown = offset(
            square(2.0),
            Offset::Delta {
                delta: 1.0,
                chamfer: false,
            },
        )
        .unwrap();
        assert!((area2(&only_polygon(&grown.unwrap())) / 2.0 - 16.0).abs() < 1e-9);
        let cut = offset(
            square(2.0),
            Offset::Delta {
                delta: 1.0,
                chamfer: true,
            },
        )
        .unwrap();
        // Each mitred corner loses a right triangle with legs 2 − √2 (cut 1 from the corner).
        let expected = 16.0 - 4.0 * (3.0 - 2.0 * 2f64.sqrt());
        assert!((area2(&only_polygon(&cut.unwrap())) / 2.0 - expected).abs() < 1e-9);
        let shrunk = offset(square(2.0), Offset::Round { r: -0.5, res: RES }).unwrap();
        assert!((area2(&only_polygon(&shrunk.unwrap())) / 2.0 - 1.0).abs() < 1e-9);
        assert_eq!(
            offset(square(2.0), Offset::Round { r: -1.0, res: RES }).unwrap(),
            None
        );
    }

    #[test]
    fn round_growth_is_polygon_rectangles_and_discs() {
        let f = offset(square(2.0), Offset::Round { r: 1.0, res: RES })
            .unwrap()
            .unwrap();
        let leaves = f.0.iter().filter(|o| matches!(o, Op2::Leaf(_))).count();
        assert_eq!(leaves, 9);
        assert_eq!(f.0.last(), Some(&Op2::Union(9)));
    }

    #[test]
    fn unsupported_cases_are_errors() {
        let l = Flat::leaf(Leaf2::Polygon(vec![vec![
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(1.0, 0.5),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ]]));
        assert!(offset(l, Offset::Round { r: -0.1, res: RES }).is_err());
        let d = Flat::combine(vec![square(2.0), square(1.0)], Op2::Difference);
        assert!(offset(d, Offset::Round { r: 0.1, res: RES }).is_err());
    }
}
