//! Triangulation of planar regions bounded by one outer loop and any number of hole loops, with
//! spade's constrained Delaunay triangulation (never fans): the loop edges are constraints and a
//! triangle is inside when reaching it from outside the convex hull crosses an odd number of them.
//!
//! Every problem is reported rather than repaired: too few corners, non-finite or coincident
//! corners, edges that cross or touch, holes that are not inside the outer loop (or are nested),
//! and loops of zero area. Polygonal faces of polyhedra are triangulated here too, after
//! projection onto the plane of their Newell normal.

use glam::{DVec2, DVec3};
use spade::handles::{FixedFaceHandle, FixedVertexHandle, InnerTag};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

/// Why a polygon (with or without holes) cannot be triangulated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum TriangulationError {
    /// A loop has fewer than three corners.
    #[error("a loop has {0} corners (at least 3 needed)")]
    TooFewCorners(usize),
    /// A corner has a NaN or infinite coordinate.
    #[error("a corner has a non-finite coordinate")]
    NonFinite,
    /// Two corners are at the same point (counting corners from 0 over all loops in order).
    #[error("corners {first} and {second} coincide")]
    CoincidentCorners {
        /// The earlier corner.
        first: usize,
        /// The later corner.
        second: usize,
    },
    /// The region has (nearly) zero area: its corners are collinear.
    #[error("the polygon has zero area (its corners are collinear)")]
    Degenerate,
    /// Two edges cross, or an edge passes through a corner.
    #[error("edges cross or touch each other")]
    SelfIntersecting,
    /// A hole is not strictly inside the outer loop, or holes are nested.
    #[error("a hole is not inside the outer loop, or holes are nested")]
    HoleOutside,
    /// A face is so far from planar that a triangle of it would face backwards.
    #[error("the face is folded (too far from planar)")]
    Folded,
}

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// Twice the signed area of a closed 2D loop (positive when counter-clockwise).
pub(crate) fn signed_area2(points: &[DVec2]) -> f64 {
    let next = points.iter().skip(1).chain(points.first());
    points.iter().zip(next).map(|(p, q)| p.perp_dot(*q)).sum()
}

/// Triangulates the region inside `loops[0]` and outside every later loop. Corners are numbered
/// over all loops in order; the triangles are counter-clockwise in the plane whatever the
/// orientation of the loops.
pub(crate) fn triangulate_loops(loops: &[&[DVec2]]) -> Result<Vec<[u32; 3]>, TriangulationError> {
    let mut total = 0usize;
    for l in loops {
        if l.len() < 3 {
            return Err(TriangulationError::TooFewCorners(l.len()));
        }
        if l.iter().any(|p| !p.is_finite()) {
            return Err(TriangulationError::NonFinite);
        }
        total += l.len();
    }
    let flat = normalised(loops)?;
    let outer: Vec<DVec2> = flat[..loops[0].len()]
        .iter()
        .map(|p| DVec2::new(p.x, p.y))
        .collect();
    if signed_area2(&outer).abs() <= 1e-12 {
        return Err(TriangulationError::Degenerate);
    }
    let mut cdt = Cdt::new();
    let mut handles: Vec<FixedVertexHandle> = Vec::with_capacity(total);
    for (corner, point) in flat.iter().enumerate() {
        let before = cdt.num_vertices();
        let handle = cdt
            .insert(*point)
            .map_err(|_| TriangulationError::Degenerate)?;
        if cdt.num_vertices() == before {
            let first = handles.iter().position(|&h| h == handle).unwrap_or(corner);
            return Err(TriangulationError::CoincidentCorners {
                first,
                second: corner,
            });
        }
        handles.push(handle);
    }
    let mut start = 0;
    for l in loops {
        let ring = &handles[start..start + l.len()];
        for (i, &from) in ring.iter().enumerate() {
            let to = ring[(i + 1) % ring.len()];
            if !cdt.can_add_constraint(from, to) {
                return Err(TriangulationError::SelfIntersecting);
            }
            let added = cdt.try_add_constraint(from, to);
            if added.len() != 1 || !cdt.exists_constraint(from, to) {
                return Err(TriangulationError::SelfIntersecting);
            }
        }
        start += l.len();
    }
    let outer_len = loops.first().map_or(0, |l| l.len());
    check_hull_is_outer_loop(&cdt, &handles, outer_len)?;
    let triangles = odd_faces(&cdt, &handles)?;
    // A polygon with n corners in all and h holes has exactly n + 2h − 2 triangles; anything else
    // means a hole outside the outer loop, nested holes or a zero-area loop.
    let holes = loops.len().saturating_sub(1);
    if triangles.len() + 2 != total + 2 * holes {
        return Err(TriangulationError::HoleOutside);
    }
    Ok(triangles)
}

/// The corners of all loops as one list, centred and scaled to about `[-1, 1]` (the CDT's
/// predicates are exact, but spade refuses coordinates too close to zero or too large).
fn normalised(loops: &[&[DVec2]]) -> Result<Vec<Point2<f64>>, TriangulationError> {
    let (min, max) = loops
        .iter()
        .flat_map(|l| l.iter())
        .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    let center = (min + max) * 0.5;
    let extent = (max - min).max_element() * 0.5;
    if !extent.is_finite() || extent <= 0.0 {
        return Err(TriangulationError::Degenerate);
    }
    Ok(loops
        .iter()
        .flat_map(|l| l.iter())
        .map(|p| {
            let d = (*p - center) / extent;
            spade::mitigate_underflow(Point2::new(d.x, d.y))
        })
        .collect())
}

/// Every corner on the convex hull must belong to the outer loop: a hole corner there is outside
/// the outer loop (or on it).
fn check_hull_is_outer_loop(
    cdt: &Cdt,
    handles: &[FixedVertexHandle],
    outer_len: usize,
) -> Result<(), TriangulationError> {
    let mut is_outer = vec![false; cdt.num_vertices()];
    for h in &handles[..outer_len] {
        if let Some(slot) = is_outer.get_mut(h.index()) {
            *slot = true;
        }
    }
    for edge in cdt.convex_hull() {
        if !is_outer
            .get(edge.from().fix().index())
            .copied()
            .unwrap_or(false)
        {
            return Err(TriangulationError::HoleOutside);
        }
    }
    if cdt.convex_hull_size() < 3 {
        return Err(TriangulationError::Degenerate);
    }
    Ok(())
}

/// The triangles reached from outside the hull by crossing an odd number of constraint edges, as
/// corner numbers (counter-clockwise). The parity is found by a flood fill with an explicit stack.
fn odd_faces(
    cdt: &Cdt,
    handles: &[FixedVertexHandle],
) -> Result<Vec<[u32; 3]>, TriangulationError> {
    let mut parity: Vec<Option<bool>> = vec![None; cdt.num_all_faces()];
    let mut stack: Vec<(FixedFaceHandle<InnerTag>, bool)> = Vec::new();
    for edge in cdt.convex_hull() {
        for e in [edge, edge.rev()] {
            if let Some(face) = e.face().as_inner() {
                stack.push((face.fix(), e.is_constraint_edge()));
            }
        }
    }
    while let Some((face, odd)) = stack.pop() {
        let slot = parity
            .get_mut(face.index())
            .ok_or(TriangulationError::SelfIntersecting)?;
        match *slot {
            Some(p) if p == odd => continue,
            Some(_) => return Err(TriangulationError::SelfIntersecting),
            None => *slot = Some(odd),
        }
        for edge in cdt.face(face).adjacent_edges() {
            if let Some(beyond) = edge.rev().face().as_inner() {
                stack.push((beyond.fix(), odd ^ edge.is_constraint_edge()));
            }
        }
    }
    let mut corner_of = vec![u32::MAX; cdt.num_vertices()];
    for (corner, h) in handles.iter().enumerate() {
        if let Some(slot) = corner_of.get_mut(h.index()) {
            *slot = corner as u32;
        }
    }
    let corner = |v: FixedVertexHandle| {
        corner_of
            .get(v.index())
            .copied()
            .filter(|&c| c != u32::MAX)
            .ok_or(TriangulationError::SelfIntersecting)
    };
    let mut out = Vec::new();
    for face in cdt.inner_faces() {
        if parity.get(face.fix().index()).copied().flatten() == Some(true) {
            let [a, b, c] = face.vertices();
            out.push([corner(a.fix())?, corner(b.fix())?, corner(c.fix())?]);
        }
    }
    Ok(out)
}

/// Twice the vector area of a closed 3D polygon (its Newell normal).
pub(crate) fn newell(points: &[DVec3]) -> DVec3 {
    let Some(&origin) = points.first() else {
        return DVec3::ZERO;
    };
    let next = points.iter().skip(1).chain(points.first());
    points
        .iter()
        .zip(next)
        .map(|(&p, &q)| (p - origin).cross(q - origin))
        .sum()
}

/// Triangulates one polygonal face (corners index `positions`, counter-clockwise seen from
/// outside) and appends triangles with the face's winding to `out`. Triangles pass through.
pub(crate) fn triangulate_face(
    positions: &[DVec3],
    corners: &[u32],
    out: &mut Vec<[u32; 3]>,
) -> Result<(), TriangulationError> {
    if let [a, b, c] = *corners {
        out.push([a, b, c]);
        return Ok(());
    }
    if corners.len() < 3 {
        return Err(TriangulationError::TooFewCorners(corners.len()));
    }
    let points: Vec<DVec3> = corners.iter().map(|&i| positions[i as usize]).collect();
    let normal = newell(&points);
    let scale = points
        .iter()
        .map(|p| (*p - points[0]).length_squared())
        .fold(0.0, f64::max);
    let area2 = normal.length_squared();
    if !area2.is_finite() || area2 <= (1e-24 * scale) * scale {
        return Err(TriangulationError::Degenerate);
    }
    let n = normal.normalize();
    let u = n.any_orthonormal_vector();
    let v = n.cross(u);
    let flat: Vec<DVec2> = points
        .iter()
        .map(|p| DVec2::new(p.dot(u), p.dot(v)))
        .collect();
    let triangles = triangulate_loops(&[&flat])?;
    for t in &triangles {
        let [a, b, c] = t.map(|i| points[i as usize]);
        if (b - a).cross(c - a).dot(normal) <= 0.0 {
            return Err(TriangulationError::Folded);
        }
    }
    out.extend(triangles.iter().map(|t| t.map(|i| corners[i as usize])));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(c: DVec2, h: f64, ccw: bool) -> Vec<DVec2> {
        let mut s = vec![
            c + DVec2::new(-h, -h),
            c + DVec2::new(h, -h),
            c + DVec2::new(h, h),
            c + DVec2::new(-h, h),
        ];
        if !ccw {
            s.reverse();
        }
        s
    }

    fn area(points: &[DVec2], tris: &[[u32; 3]]) -> f64 {
        tris.iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| points[i as usize]);
                let a2 = (b - a).perp_dot(c - a);
                assert!(a2 > 0.0, "triangle {t:?} is not counter-clockwise");
                a2 / 2.0
            })
            .sum()
    }

    #[test]
    fn square_with_two_holes_has_the_right_area_and_count() {
        let outer = square(DVec2::ZERO, 2.0, false);
        let h1 = square(DVec2::new(-1.0, 0.0), 0.5, true);
        let h2 = square(DVec2::new(1.0, 0.5), 0.25, false);
        let tris = triangulate_loops(&[&outer, &h1, &h2]).unwrap();
        assert_eq!(tris.len(), 12 + 4 - 2);
        let all: Vec<DVec2> = [outer, h1, h2].concat();
        assert!((area(&all, &tris) - (16.0 - 1.0 - 0.25)).abs() < 1e-12);
    }

    #[test]
    fn concave_polygon_is_not_fanned() {
        // A comb: a fan from corner 0 would leave the polygon.
        let comb: Vec<DVec2> = [
            (0.0, 0.0),
            (5.0, 0.0),
            (5.0, 3.0),
            (4.0, 3.0),
            (4.0, 1.0),
            (3.0, 1.0),
            (3.0, 3.0),
            (2.0, 3.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (1.0, 3.0),
            (0.0, 3.0),
        ]
        .iter()
        .map(|&(x, y)| DVec2::new(x, y))
        .collect();
        let tris = triangulate_loops(&[&comb]).unwrap();
        assert_eq!(tris.len(), 10);
        assert!((area(&comb, &tris) - signed_area2(&comb) / 2.0).abs() < 1e-12);
    }

    #[test]
    fn invalid_regions_are_errors() {
        let outer = square(DVec2::ZERO, 1.0, true);
        let outside = square(DVec2::new(3.0, 0.0), 0.5, true);
        let nested_a = square(DVec2::ZERO, 0.6, true);
        let nested_b = square(DVec2::ZERO, 0.3, true);
        let crossing = square(DVec2::new(1.0, 0.0), 0.5, true);
        let e = |loops: &[&[DVec2]]| triangulate_loops(loops).unwrap_err();
        assert_eq!(e(&[&outer, &outside]), TriangulationError::HoleOutside);
        assert_eq!(
            e(&[&outer, &nested_a, &nested_b]),
            TriangulationError::HoleOutside
        );
        assert_eq!(e(&[&nested_a, &outer]), TriangulationError::HoleOutside);
        assert_eq!(
            e(&[&outer, &crossing]),
            TriangulationError::SelfIntersecting
        );
        let bow = [(0.0, 0.0), (3.0, 1.0), (3.0, 0.0), (0.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
        assert_eq!(e(&[&bow]), TriangulationError::SelfIntersecting);
        let line = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)].map(|(x, y)| DVec2::new(x, y));
        assert_eq!(e(&[&line]), TriangulationError::Degenerate);
        let dup = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (2.0, 0.0)]
            .map(|(x, y)| DVec2::new(x, y));
        assert_eq!(
            e(&[&dup]),
            TriangulationError::CoincidentCorners {
                first: 1,
                second: 4
            }
        );
        assert_eq!(e(&[&outer[..2]]), TriangulationError::TooFewCorners(2));
        let nan = [(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)].map(|(x, y)| DVec2::new(x, y));
        assert_eq!(e(&[&nan]), TriangulationError::NonFinite);
    }

    #[test]
    fn tilted_pentagon_face_keeps_its_winding() {
        let positions: Vec<DVec3> = (0..5)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::TAU / 5.0;
                DVec3::new(a.cos(), a.sin() * 0.6, a.sin() * 0.8 + 3.0)
            })
            .collect();
        let mut out = Vec::new();
        triangulate_face(&positions, &[4, 3, 2, 1, 0], &mut out).unwrap();
        assert_eq!(out.len(), 3);
        let n = newell(&[4, 3, 2, 1, 0].map(|i| positions[i]));
        for t in out {
            let [a, b, c] = t.map(|i| positions[i as usize]);
            assert!((b - a).cross(c - a).dot(n) > 0.0);
        }
    }
}
