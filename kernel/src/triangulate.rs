//! Triangulation of planar polygons with spade's constrained Delaunay triangulation, the one
//! implementation behind polyhedron faces and prism caps ([`polyhedra`](crate::polyhedra)), the
//! caps of swept profiles ([`profile::triangulate`](crate::profile::triangulate)) and the n-gon
//! faces of the mesh readers of `solidkit-meshing`.
//!
//! [`triangulate_loops`] triangulates a region bounded by one outer loop and any number of hole
//! loops in the plane: the loop edges are constraints and a triangle is inside when reaching it
//! from outside the convex hull crosses an odd number of them. [`triangulate_polygon`]
//! triangulates one polygon in space (a face), after projection onto the plane of its Newell
//! normal ([`newell_normal`]), keeping its winding. Fans are never used, so non-convex polygons
//! come out right, and only the given corners are used (no new vertices).
//!
//! Every problem is reported as a [`TriangulationError`] rather than repaired: too few corners,
//! non-finite or coincident corners, edges that cross or touch, holes that are not inside the
//! outer loop (or are nested), loops of zero area and faces too far from planar. Nothing here
//! recurses: the inside is found by a flood fill with an explicit stack.

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

/// Triangulates the region inside `loops[0]` and outside every later loop (the holes, each
/// strictly inside the outer loop and outside the other holes). Corners are numbered over all
/// loops in order; the triangles are counter-clockwise in the plane whatever the orientation of
/// the loops, and there are `n + 2h − 2` of them for `n` corners in all and `h` holes.
///
/// ```
/// use glam::DVec2;
/// use solidkit_kernel::triangulate::triangulate_loops;
///
/// let square = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)].map(|(x, y)| DVec2::new(x, y));
/// let hole = [(1.0, 1.0), (1.0, 2.0), (2.0, 2.0), (2.0, 1.0)].map(|(x, y)| DVec2::new(x, y));
/// let triangles = triangulate_loops(&[&square, &hole]).unwrap();
/// assert_eq!(triangles.len(), 8 + 2 - 2);
/// ```
pub fn triangulate_loops(loops: &[&[DVec2]]) -> Result<Vec<[u32; 3]>, TriangulationError> {
    let Some(first) = loops.first() else {
        return Err(TriangulationError::TooFewCorners(0));
    };
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
    check_area(loops, first)?;
    let flat = scaled(loops);
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

/// Rejects regions whose outer loop has (nearly) zero area: twice its area, centred and scaled by
/// half the largest extent of all loops' bounding box, at most `1e-12`.
fn check_area(loops: &[&[DVec2]], outer: &[DVec2]) -> Result<(), TriangulationError> {
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
    let centred: Vec<DVec2> = outer.iter().map(|p| (*p - center) / extent).collect();
    if signed_area2(&centred).abs() <= 1e-12 {
        return Err(TriangulationError::Degenerate);
    }
    Ok(())
}

/// The corners of all loops as one list, scaled by a power of two so that the largest coordinate
/// magnitude is about 1: spade refuses coordinates too close to zero or too large, and a power of
/// two scales exactly, so the CDT's exact predicates see the given geometry (a corner exactly on
/// an edge stays on it). Coordinates below spade's smallest magnitude (about `2⁻¹⁴²` of the
/// largest) become zero.
fn scaled(loops: &[&[DVec2]]) -> Vec<Point2<f64>> {
    let largest = loops
        .iter()
        .flat_map(|l| l.iter())
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    // `largest` is finite and positive here (checked by the caller), so the exponent is within
    // [-1075, 1024] and each half of the scale is a normal power of two.
    let exponent = -(largest.log2().floor() as i32) - 1;
    let half = exponent / 2;
    let (a, b) = (pow2(half), pow2(exponent - half));
    loops
        .iter()
        .flat_map(|l| l.iter())
        .map(|p| {
            let q = *p * a * b;
            spade::mitigate_underflow(Point2::new(q.x, q.y))
        })
        .collect()
}

/// `2^k` exactly, for `-1022 ≤ k ≤ 1023`.
fn pow2(k: i32) -> f64 {
    f64::from_bits(((1023 + k) as u64) << 52)
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

/// Twice the vector area of a closed polygon in space: its normal, pointing to the side from
/// which the polygon is seen counter-clockwise, with a length of twice its area (the Newell
/// normal). Zero for fewer than three points.
pub fn newell_normal(points: &[DVec3]) -> DVec3 {
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

/// Triangulates the polygon with corners `points` (in boundary order, planar or nearly so) in the
/// plane of its Newell normal. The triangles are numbered by position along the polygon and
/// wound like it: each faces the side of [`newell_normal`]. A polygon of `n` corners gives
/// `n − 2` triangles.
///
/// ```
/// use glam::DVec3;
/// use solidkit_kernel::triangulate::triangulate_polygon;
///
/// // An L-shaped hexagon in the plane z = 1, clockwise seen from +z.
/// let l = [(0.0, 0.0), (0.0, 2.0), (1.0, 2.0), (1.0, 1.0), (2.0, 1.0), (2.0, 0.0)]
///     .map(|(x, y)| DVec3::new(x, y, 1.0));
/// let triangles = triangulate_polygon(&l).unwrap();
/// assert_eq!(triangles.len(), 4);
/// for t in triangles {
///     let [a, b, c] = t.map(|i| l[i as usize]);
///     assert!((b - a).cross(c - a).z < 0.0);
/// }
/// ```
pub fn triangulate_polygon(points: &[DVec3]) -> Result<Vec<[u32; 3]>, TriangulationError> {
    if points.len() < 3 {
        return Err(TriangulationError::TooFewCorners(points.len()));
    }
    if points.iter().any(|p| !p.is_finite()) {
        return Err(TriangulationError::NonFinite);
    }
    let normal = newell_normal(points);
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
    Ok(triangles)
}

/// Triangulates one polygonal face (`corners` index `positions`, which the caller has checked,
/// counter-clockwise seen from outside) and appends triangles with the face's winding to `out`.
/// Triangles pass through; on error nothing is appended.
pub(crate) fn triangulate_face(
    positions: &[DVec3],
    corners: &[u32],
    out: &mut Vec<[u32; 3]>,
) -> Result<(), TriangulationError> {
    if let [a, b, c] = *corners {
        out.push([a, b, c]);
        return Ok(());
    }
    let points: Vec<DVec3> = corners.iter().map(|&i| positions[i as usize]).collect();
    let triangles = triangulate_polygon(&points)?;
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
                assert!(
                    a2 > 0.0,
                    "triangle {t:?} is not counter-clockwise: {points:?} {tris:?}"
                );
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

    /// A xorshift generator of numbers below `n`.
    fn rng(mut state: u64) -> impl FnMut(u64) -> u64 {
        move |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        }
    }

    #[test]
    fn random_polygons_with_holes_triangulate_exactly_or_fail_cleanly() {
        let mut next = rng(0x2545_F491_4F6C_DD1D);
        let mut ok = [0usize; 3];
        for _ in 0..3000 {
            // An outer loop on a half-unit grid, either anywhere (many collinear, coincident
            // and crossing cases) or star-shaped around (8, 8), and up to two square holes near
            // (8, 8) (inside, touching, outside, overlapping or nested).
            let n = 3 + next(8) as usize;
            let star = next(2) == 0;
            let outer: Vec<DVec2> = (0..n)
                .map(|i| {
                    let p = if star {
                        let a = (i as f64 + next(8) as f64 / 10.0) * std::f64::consts::TAU;
                        let r = 3.0 + next(6) as f64;
                        DVec2::new(8.0, 8.0) + DVec2::from_angle(a / n as f64) * r
                    } else {
                        DVec2::new(next(17) as f64, next(17) as f64)
                    };
                    (p * 2.0).round() / 2.0
                })
                .collect();
            let holes: Vec<Vec<DVec2>> = (0..next(3))
                .map(|_| {
                    let c = DVec2::new(next(13) as f64, next(13) as f64) * 0.5 + 5.0;
                    square(c, 0.25 * (1 + next(2)) as f64, next(2) == 0)
                })
                .collect();
            let mut loops: Vec<&[DVec2]> = vec![&outer];
            loops.extend(holes.iter().map(Vec::as_slice));
            let Ok(tris) = triangulate_loops(&loops) else {
                continue;
            };
            ok[holes.len()] += 1;
            let all: Vec<DVec2> = loops.concat();
            assert_eq!(tris.len(), all.len() + 2 * holes.len() - 2);
            let expected = (signed_area2(&outer).abs()
                - holes.iter().map(|h| signed_area2(h).abs()).sum::<f64>())
                / 2.0;
            assert!(
                (area(&all, &tris) - expected).abs() < 1e-9,
                "{loops:?} {tris:?}"
            );
        }
        assert!(ok.iter().all(|&k| k > 100), "too few valid regions: {ok:?}");
    }

    #[test]
    fn random_tilted_polygons_far_from_the_origin_triangulate_or_fail_cleanly() {
        let mut next = rng(0xD1B5_4A32_D192_ED03);
        let mut valid = 0;
        for _ in 0..3000 {
            // Corners on a small grid (many collinear, coincident and crossing cases) in a plane
            // of random direction far from the origin, some slightly off the plane.
            let (azimuth, polar) = (next(628) as f64 / 100.0, next(314) as f64 / 100.0);
            let w = DVec3::new(
                polar.sin() * azimuth.cos(),
                polar.sin() * azimuth.sin(),
                polar.cos(),
            );
            let u = w.any_orthonormal_vector();
            let v = w.cross(u);
            let origin = DVec3::new(1e3, -2e3, 5e2);
            let corners = 3 + next(8) as usize;
            let polygon: Vec<DVec3> = (0..corners)
                .map(|_| {
                    let bump = next(2) as f64 * 1e-3;
                    origin + u * next(5) as f64 + v * next(5) as f64 + w * bump
                })
                .collect();
            let Ok(triangles) = triangulate_polygon(&polygon) else {
                continue;
            };
            valid += 1;
            assert_eq!(triangles.len() + 2, corners);
            // Each triangle faces the polygon's way, and their vector areas add up to the
            // polygon's, planar or not.
            let newell = newell_normal(&polygon);
            let total: DVec3 = triangles
                .iter()
                .map(|t| {
                    let [a, b, c] = t.map(|i| polygon[i as usize]);
                    let vector_area = (b - a).cross(c - a);
                    assert!(vector_area.dot(newell) > 0.0, "{polygon:?} {triangles:?}");
                    vector_area
                })
                .sum();
            assert!(
                (total - newell).length() < 1e-9,
                "{polygon:?} {triangles:?}"
            );
        }
        assert!(valid > 500, "only {valid} random polygons were simple");
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
        let n = newell_normal(&[4, 3, 2, 1, 0].map(|i| positions[i]));
        for t in out {
            let [a, b, c] = t.map(|i| positions[i as usize]);
            assert!((b - a).cross(c - a).dot(n) > 0.0);
        }
    }
}
