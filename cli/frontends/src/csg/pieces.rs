//! Convex pieces of a solid built from convex ones, for `minkowski()` with a non-convex operand
//! (the way OpenSCAD's CGAL backend goes: decompose, sum piece by piece, unite).
//!
//! A piece is the vertex set of a convex polytope. A union's pieces are its operands' pieces; an
//! intersection's are the pairwise intersections (a piece clipped by the other's face planes);
//! a difference `P \ Q` of two pieces is, for the face planes `h₁ … h_m` of `Q`, the union over
//! `k` of `P` clipped to the outside of `h_k` and the inside of `h₁ … h_{k−1}`: these pieces are
//! disjoint, and a point of `P` outside `Q` lies outside some first plane `h_k`. Pieces without
//! volume are dropped (the Booleans are regularized, as OpenSCAD's). Then the Minkowski sum of the
//! solid with a convex `B` is the union of the hulls of `piece + B` (the sum distributes over
//! unions, and the sum of two convex sets is the hull of the sums of their vertices).
//!
//! Clipping a polytope by a plane keeps its vertices on the inner side and adds the points where
//! its hull edges cross the plane; every piece is reduced to its hull's vertices.

use super::hull::convex_hull;
use glam::DVec3;

/// The vertices of a convex polytope.
pub(super) type Piece = Vec<DVec3>;

/// Most pieces a decomposition may reach before it is given up (the operand is then not
/// decomposed: `minkowski` refuses it, `hull` meshes it).
pub(super) const MAX_PIECES: usize = 512;

/// Most work one Boolean may take before the decomposition is given up, counted as the square of
/// each clipped piece's vertex count (a clip builds the piece's hull): a difference with a
/// finely faceted cutter clips its plane count times per piece, and the part inside the first
/// planes grows towards the cutter's size.
const MAX_WORK: usize = 50_000_000;

/// Most face planes of a piece that another is clipped by (a cylinder of `$fn = 128` has 130): a
/// thin wedge between two planes of a finer faceting costs the hull far more than its size.
const MAX_PLANES: usize = 130;

/// Adds the cost of clipping `piece` `clips` times to `work`; `false` once past [`MAX_WORK`].
fn afford(work: &mut usize, piece: &[DVec3], clips: usize) -> bool {
    *work += clips * piece.len() * piece.len();
    *work <= MAX_WORK
}

/// A plane `n · p = d` with unit outward normal `n`.
type Plane = (DVec3, f64);

/// The hull of `points` as (its vertices, its outward face planes, coplanar triangles merged), or
/// `None` when they span no volume.
fn hull_planes(points: &[DVec3]) -> Option<(Piece, Vec<Plane>, Vec<[usize; 2]>)> {
    let (v, faces) = convex_hull(points)?;
    let scale = v.iter().fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    let eps = 1e-9 * scale.max(1e-300);
    let mut planes: Vec<Plane> = Vec::new();
    let mut edges = Vec::new();
    for f in &faces {
        let [a, b, c] = [f[0], f[1], f[2]].map(|i| v[i as usize]);
        let n = (b - a).cross(c - a).normalize_or_zero();
        if n == DVec3::ZERO {
            continue;
        }
        let d = n.dot(a);
        if !planes
            .iter()
            .any(|(m, e)| (*m - n).length() <= 1e-9 && (e - d).abs() <= eps)
        {
            planes.push((n, d));
        }
        for k in 0..3 {
            let (i, j) = (f[k] as usize, f[(k + 1) % 3] as usize);
            if i < j {
                edges.push([i, j]);
            }
        }
    }
    Some((v, planes, edges))
}

/// `piece` clipped to the side `n · p ≤ d` (`None`: nothing of volume is left).
fn clip(piece: &[DVec3], (n, d): Plane) -> Option<Piece> {
    let (v, _, edges) = hull_planes(piece)?;
    let scale = v.iter().fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    let eps = 1e-12 * scale.max(1e-300);
    let side: Vec<f64> = v.iter().map(|p| n.dot(*p) - d).collect();
    if side.iter().all(|&s| s <= eps) {
        return Some(v);
    }
    let mut kept: Vec<DVec3> = v
        .iter()
        .zip(&side)
        .filter(|&(_, &s)| s <= eps)
        .map(|(p, _)| *p)
        .collect();
    if kept.is_empty() {
        return None;
    }
    for [i, j] in edges {
        let (si, sj) = (side[i], side[j]);
        if (si < -eps && sj > eps) || (si > eps && sj < -eps) {
            kept.push(v[i] + (v[j] - v[i]) * (si / (si - sj)));
        }
    }
    hull_planes(&kept).map(|h| h.0)
}

/// `p` clipped by every plane of `planes` in turn (`Ok(None)`: nothing is left; `Err`: past the
/// work budget).
fn clip_all(p: &[DVec3], planes: &[Plane], work: &mut usize) -> Result<Option<Piece>, ()> {
    let mut cur = p.to_vec();
    for &pl in planes {
        if !afford(work, &cur, 1) {
            return Err(());
        }
        match clip(&cur, pl) {
            Some(c) => cur = c,
            None => return Ok(None),
        }
    }
    Ok(Some(cur))
}

/// The face planes of the piece `q` that others are clipped by: `Some(None)` when it has no
/// volume, `None` past [`MAX_PLANES`].
fn cutter_planes(q: &[DVec3]) -> Option<Option<Vec<Plane>>> {
    match hull_planes(q) {
        None => Some(None),
        Some((_, planes, _)) => (planes.len() <= MAX_PLANES).then_some(Some(planes)),
    }
}

/// The pieces of the union of `a` and `b`.
pub(super) fn union(mut a: Vec<Piece>, b: Vec<Piece>) -> Option<Vec<Piece>> {
    a.extend(b);
    (a.len() <= MAX_PIECES).then_some(a)
}

/// The pieces of the intersection of the solids with pieces `a` and `b`.
pub(super) fn intersection(a: &[Piece], b: &[Piece]) -> Option<Vec<Piece>> {
    let mut out = Vec::new();
    let mut work = 0;
    for q in b {
        let Some(planes) = cutter_planes(q)? else {
            continue;
        };
        for p in a {
            if let Some(c) = clip_all(p, &planes, &mut work).ok()? {
                out.push(c);
                if out.len() > MAX_PIECES {
                    return None;
                }
            }
        }
    }
    Some(out)
}

/// The pieces of the solid with pieces `a` less the solid with pieces `b`.
pub(super) fn difference(a: Vec<Piece>, b: &[Piece]) -> Option<Vec<Piece>> {
    let mut cur = a;
    let mut work = 0;
    for q in b {
        let Some(planes) = cutter_planes(q)? else {
            continue;
        };
        let mut next = Vec::new();
        for p in &cur {
            // Inside the planes before `k`, outside plane `k`.
            let mut inner: Option<Piece> = Some(p.clone());
            for &(n, d) in &planes {
                let Some(rest) = inner else { break };
                if !afford(&mut work, &rest, 2) {
                    return None;
                }
                if let Some(out) = clip(&rest, (-n, -d)) {
                    next.push(out);
                    if next.len() > MAX_PIECES {
                        return None;
                    }
                }
                inner = clip(&rest, (n, d));
            }
        }
        cur = next;
    }
    Some(cur)
}

/// The vertex sets whose hulls unite to the Minkowski sum of the pieces `a` and the convex set
/// with vertices `b`.
pub(super) fn sum_with_convex(a: &[Piece], b: &[DVec3]) -> Vec<Piece> {
    a.iter()
        .map(|p| {
            p.iter()
                .flat_map(|x| b.iter().map(move |y| *x + *y))
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(lo: f64, hi: f64) -> Piece {
        (0..8)
            .map(|i| {
                DVec3::new(
                    if i & 1 == 0 { lo } else { hi },
                    if i & 2 == 0 { lo } else { hi },
                    if i & 4 == 0 { lo } else { hi },
                )
            })
            .collect()
    }

    fn volume(p: &[DVec3]) -> f64 {
        let (v, f) = convex_hull(p).unwrap();
        f.iter()
            .map(|t| {
                let [a, b, c] = [t[0], t[1], t[2]].map(|i| v[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    #[test]
    fn differences_are_disjoint_pieces_of_the_right_volume() {
        // A 4-cube less a 2-cube inside it: 64 − 8 = 56; less a 2 × 2 × 6 bar through it:
        // 64 − 16 = 48.
        let pieces = difference(vec![cube(-2.0, 2.0)], &[cube(-1.0, 1.0)]).unwrap();
        let total: f64 = pieces.iter().map(|p| volume(p)).sum();
        assert!((total - 56.0).abs() < 1e-9, "{total}");
        assert!(pieces.len() <= 6);
        let through = difference(
            vec![cube(-2.0, 2.0)],
            &[cube(-1.0, 1.0)
                .iter()
                .map(|p| *p * DVec3::new(1.0, 1.0, 3.0))
                .collect()],
        )
        .unwrap();
        let total: f64 = through.iter().map(|p| volume(p)).sum();
        assert!((total - 48.0).abs() < 1e-9, "{total}");
    }

    #[test]
    fn intersections_clip_and_disjoint_operands_vanish() {
        let both = intersection(&[cube(0.0, 2.0)], &[cube(1.0, 3.0)]).unwrap();
        assert_eq!(both.len(), 1);
        assert!((volume(&both[0]) - 1.0).abs() < 1e-12);
        let none = intersection(&[cube(0.0, 1.0)], &[cube(2.0, 3.0)]).unwrap();
        assert!(none.is_empty());
    }

    #[test]
    fn sums_distribute_over_pieces() {
        let s = sum_with_convex(&[cube(0.0, 1.0)], &cube(0.0, 1.0));
        assert!((volume(&s[0]) - 8.0).abs() < 1e-12);
    }
}
