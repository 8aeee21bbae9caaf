//! `minkowski()` of 2D regions of any shape (holes, several parts, non-convex), through their
//! polygons ([`super::region`]). For regions `P` and `Q` with boundaries `∂P`, `∂Q`:
//! - `Q` convex: `P ⊕ Q = (P + q₀) ∪ ⋃ e∈∂P (e ⊕ Q)`, each `e ⊕ Q` the convex hull of the two
//!   copies of `Q` at the edge's ends (a point `p + q` whose `p − Q`... is either met by the
//!   boundary, or lies wholly inside `P`);
//! - otherwise, by the same argument applied to each `e ⊕ Q`:
//!   `P ⊕ Q = (P + q₀) ∪ ⋃ v vertex of P (Q + v) ∪ ⋃ e∈∂P, f∈∂Q (e ⊕ f)`, each `e ⊕ f` a
//!   parallelogram.
//!
//! Both are exact for polygons; the union is taken by polygon clipping.

use super::Facets;
use super::flat::Flat;
use super::hull::convex_hull_2d;
use super::region::{self, Shape};
use glam::DVec2;

/// The most pieces one sum may take (edge pairs of two non-convex operands): a bound on memory.
pub const MAX_PIECES: usize = 1_000_000;

/// The Minkowski sum of the regions; `Err` names the bound when the sum is too large to build.
pub fn minkowski_flat(flats: &[Flat], how: Facets) -> Result<Option<Flat>, String> {
    let mut parts = flats.iter().map(|f| region::shapes(f, how));
    let Some(acc) = parts.next() else {
        return Ok(None);
    };
    let mut acc = acc?;
    for q in parts {
        acc = sum(&acc, &q?)?;
    }
    Ok(region::to_flat(acc))
}

/// The region's single convex outline, if it is one convex polygon.
fn convex_outline(shapes: &[Shape]) -> Option<Vec<DVec2>> {
    let [shape] = shapes else { return None };
    let [outline] = shape.as_slice() else {
        return None;
    };
    let hull = convex_hull_2d(outline);
    let same = hull.len() >= 3
        && (region::area2(&hull) - region::area2(outline)).abs()
            <= 1e-12 * region::area2(&hull).abs();
    same.then_some(hull)
}

/// The edges of every loop of the shapes.
fn edges(shapes: &[Shape]) -> impl Iterator<Item = (DVec2, DVec2)> + '_ {
    shapes
        .iter()
        .flatten()
        .flat_map(|l| (0..l.len()).map(move |k| (l[k], l[(k + 1) % l.len()])))
}

fn translated(shapes: &[Shape], t: DVec2) -> impl Iterator<Item = Vec<DVec2>> + '_ {
    shapes
        .iter()
        .flatten()
        .map(move |l| l.iter().map(|p| *p + t).collect())
}

/// `P ⊕ Q`.
fn sum(p: &[Shape], q: &[Shape]) -> Result<Vec<Shape>, String> {
    if p.is_empty() || q.is_empty() {
        return Ok(Vec::new());
    }
    let (p, q) = match (convex_outline(p), convex_outline(q)) {
        (_, Some(hull)) => return sum_convex(p, &hull),
        (Some(hull), None) => return sum_convex(q, &hull),
        (None, None) => (p, q),
    };
    let (np, nq) = (edges(p).count(), edges(q).count());
    if np.saturating_mul(nq) > MAX_PIECES {
        return Err(format!(
            "the Minkowski sum of two non-convex 2D operands of {np} and {nq} edges needs more \
             than {MAX_PIECES} pieces"
        ));
    }
    let q0 = q[0][0][0];
    let mut loops: Vec<Vec<DVec2>> = translated(p, q0).collect();
    for (v, _) in edges(p) {
        loops.extend(translated(q, v));
    }
    for (a, b) in edges(p) {
        for (c, d) in edges(q) {
            let quad = vec![a + c, b + c, b + d, a + d];
            if region::area2(&quad).abs() > 0.0 {
                loops.push(region::ccw(quad));
            }
        }
    }
    region::positive(loops)
}

/// `P ⊕ Q` for a convex `Q` (its outline counter-clockwise).
fn sum_convex(p: &[Shape], q: &[DVec2]) -> Result<Vec<Shape>, String> {
    let mut loops: Vec<Vec<DVec2>> = translated(p, q[0]).collect();
    for (a, b) in edges(p) {
        let ends: Vec<DVec2> = q.iter().flat_map(|c| [a + *c, b + *c]).collect();
        let hull = convex_hull_2d(&ends);
        if hull.len() >= 3 {
            loops.push(hull);
        }
    }
    region::positive(loops)
}

#[cfg(test)]
mod tests {
    use super::super::flat::{Leaf2, Op2};
    use super::*;

    fn rect(lo: DVec2, hi: DVec2) -> Flat {
        Flat::leaf(Leaf2::Polygon(vec![vec![
            lo,
            DVec2::new(hi.x, lo.y),
            hi,
            DVec2::new(lo.x, hi.y),
        ]]))
    }

    fn area(f: Option<Flat>) -> f64 {
        f.map_or(0.0, |f| {
            region::area(&region::shapes(&f, Facets::Exact).unwrap())
        })
    }

    fn frame(outer: f64, inner: f64) -> Flat {
        let (o, i) = (DVec2::splat(outer / 2.0), DVec2::splat(inner / 2.0));
        Flat::combine(vec![rect(-o, o), rect(-i, i)], Op2::Difference)
    }

    #[test]
    fn a_frame_plus_a_square_closes_or_keeps_its_hole() {
        // 20-frame with a 10-hole, plus a 2-square centred: outer 22, hole 8.
        let s = DVec2::splat(1.0);
        let f = minkowski_flat(&[frame(20.0, 10.0), rect(-s, s)], Facets::Exact).unwrap();
        assert!((area(f) - (22.0 * 22.0 - 8.0 * 8.0)).abs() < 1e-9);
        // Either order.
        let f = minkowski_flat(&[rect(-s, s), frame(20.0, 10.0)], Facets::Exact).unwrap();
        assert!((area(f) - (22.0 * 22.0 - 8.0 * 8.0)).abs() < 1e-9);
        // A 12-square closes the hole.
        let s = DVec2::splat(6.0);
        let f = minkowski_flat(&[frame(20.0, 10.0), rect(-s, s)], Facets::Exact).unwrap();
        assert!((area(f) - 32.0 * 32.0).abs() < 1e-9);
    }

    #[test]
    fn two_frames() {
        // An 18-frame with a 12-hole plus a 4-frame with a 2-hole: the outline grows by 2 on
        // each side; the hole of the first shrinks to 8 (the second's outline reaches 2 in),
        // and nothing of the second's hole survives (it is 1 from its centre, less than the
        // first frame's 3-wide wall).
        let f = minkowski_flat(&[frame(18.0, 12.0), frame(4.0, 2.0)], Facets::Exact).unwrap();
        assert!((area(f) - (22.0 * 22.0 - 8.0 * 8.0)).abs() < 1e-9);
    }

    #[test]
    fn a_non_convex_pair_is_the_union_of_its_convex_parts_sums() {
        // An L (two unit squares on a third) plus an L mirrored: the same as summing the
        // squares pairwise, checked against the rectangle sums united by clipping.
        let sq = |x: f64, y: f64| rect(DVec2::new(x, y), DVec2::new(x + 1.0, y + 1.0));
        let ell = Flat::combine(vec![sq(0.0, 0.0), sq(1.0, 0.0), sq(0.0, 1.0)], Op2::Union);
        let mirrored = Flat::combine(vec![sq(0.0, 0.0), sq(-1.0, 0.0), sq(0.0, 1.0)], Op2::Union);
        let got = area(minkowski_flat(&[ell, mirrored], Facets::Exact).unwrap());
        let mut pieces = Vec::new();
        for a in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)] {
            for b in [(0.0, 0.0), (-1.0, 0.0), (0.0, 1.0)] {
                let lo = DVec2::new(a.0 + b.0, a.1 + b.1);
                pieces.push(rect(lo, lo + DVec2::splat(2.0)));
            }
        }
        let expected = area(Some(Flat::combine(pieces, Op2::Union)));
        assert!((got - expected).abs() < 1e-9, "{got} {expected}");
        assert!(expected > 0.0);
    }

    /// Areas of OpenSCAD 2021.01's renders of the same sums (its `minkowski2-hole-tests`, and
    /// two pairs of non-convex polygons), each extruded by 1: the volume of its closed STL.
    #[test]
    fn sums_agree_with_openscads_renders() {
        use super::super::facets::Resolution;
        let disc = |r: f64| {
            Flat::leaf(Leaf2::Circle {
                center: DVec2::ZERO,
                radius: r,
                res: Resolution {
                    fn_: 16.0,
                    fa: 12.0,
                    fs: 2.0,
                },
            })
        };
        let polygon = |p: &[(f64, f64)]| {
            Flat::leaf(Leaf2::Polygon(vec![
                p.iter().map(|&(x, y)| DVec2::new(x, y)).collect(),
            ]))
        };
        let island = Flat::combine(
            vec![frame(20.0, 10.0), rect(-DVec2::ONE, DVec2::ONE)],
            Op2::Union,
        );
        let ring = Flat::combine(vec![disc(2.0), disc(1.0)], Op2::Difference);
        let star: Vec<(f64, f64)> = (0..10)
            .map(|i| {
                let (r, a) = (if i % 2 == 0 { 10.0 } else { 4.0 }, 36f64 * i as f64);
                (r * a.to_radians().cos(), r * a.to_radians().sin())
            })
            .collect();
        let cases = [
            (
                "frame + disc",
                vec![frame(20.0, 10.0), disc(1.0)],
                419.061530,
                1,
            ),
            (
                "disc + frame",
                vec![disc(1.0), frame(20.0, 10.0)],
                419.061530,
                1,
            ),
            (
                "frame with an island + disc",
                vec![island, disc(1.0)],
                434.122930,
                2,
            ),
            ("frame + ring", vec![frame(18.0, 12.0), ring], 416.245484, 1),
            (
                "L + L",
                vec![
                    polygon(&[
                        (0.0, 0.0),
                        (2.0, 0.0),
                        (2.0, 1.0),
                        (1.0, 1.0),
                        (1.0, 2.0),
                        (0.0, 2.0),
                    ]),
                    polygon(&[
                        (0.0, 0.0),
                        (1.0, 0.0),
                        (1.0, 2.0),
                        (0.5, 2.0),
                        (0.5, 1.0),
                        (0.0, 1.0),
                    ]),
                ],
                10.5,
                1,
            ),
            (
                "star + dart",
                vec![
                    polygon(&star),
                    polygon(&[(0.0, 0.0), (3.0, 0.0), (0.0, 1.0), (-2.0, 3.0)]),
                ],
                250.400861,
                1,
            ),
        ];
        let wrong: Vec<String> = cases
            .into_iter()
            .filter_map(|(name, flats, openscad, parts)| {
                let sum = minkowski_flat(&flats, Facets::OpenScad).unwrap();
                region::openscad_mismatch(sum, openscad, parts).map(|m| format!("{name}: {m}"))
            })
            .collect();
        assert!(wrong.is_empty(), "{wrong:#?}");
    }
}
