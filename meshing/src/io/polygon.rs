//! Triangulation of one polygonal face (OBJ, PLY and OFF faces may have any number of corners).
//!
//! Triangles pass through unchanged and quads take a fast path that picks a diagonal keeping both
//! halves oriented like the quad. Larger polygons, which may be non-convex and slightly
//! non-planar, are triangulated by the kernel's constrained Delaunay triangulation
//! ([`solidkit_kernel::triangulate::triangulate_polygon`], with `spade`) in the plane of their
//! Newell normal; only the triangles inside the boundary are kept. Triangles are emitted with the
//! winding of the polygon, and fans are never used, so non-convex faces come out right.
//!
//! Invalid faces are reported, never "fixed": too few corners, corners out of range, coincident
//! corners, zero area, boundaries that cross or touch themselves, and faces so non-planar that a
//! triangle would face backwards. Every emitted triangle faces like the polygon's Newell normal.
//! The kernel's [`TriangulationError`] becomes a [`PolygonError`] (with corners counted from 1
//! along the face), which the readers locate at the face's line.

use glam::DVec3;
pub use solidkit_kernel::triangulate::newell_normal;
use solidkit_kernel::triangulate::{self, TriangulationError};

/// Why a polygonal face could not be triangulated.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PolygonError {
    /// Fewer than three corners.
    #[error("face has {0} vertices (at least 3 needed)")]
    TooFewCorners(usize),
    /// A corner refers to a vertex that does not exist.
    #[error("face refers to vertex {index} but there are only {count} vertices")]
    IndexOutOfRange {
        /// The 0-based vertex index of the corner.
        index: u32,
        /// The number of vertices.
        count: usize,
    },
    /// A corner position has a NaN or infinite coordinate.
    #[error("face has a vertex with a non-finite coordinate")]
    NonFinite,
    /// Two corners are at the same place (in the plane of the face).
    #[error("face vertices {first} and {second} coincide (counting from 1 along the face)")]
    CoincidentCorners {
        /// 1-based position of the earlier corner along the face.
        first: usize,
        /// 1-based position of the later corner along the face.
        second: usize,
    },
    /// The polygon has (nearly) zero area: all corners are collinear or coincident.
    #[error("degenerate face: its vertices are collinear (zero area)")]
    Degenerate,
    /// The boundary crosses or touches itself.
    #[error("face is self-intersecting (its edges cross or touch)")]
    SelfIntersecting,
    /// The face is so far from planar that a triangle would face backwards.
    #[error("face is folded: too far from planar to triangulate with its winding")]
    Folded,
}

impl From<TriangulationError> for PolygonError {
    /// The same problem of a face; corners are counted from 1 along the face.
    fn from(e: TriangulationError) -> PolygonError {
        match e {
            TriangulationError::TooFewCorners(n) => PolygonError::TooFewCorners(n),
            TriangulationError::NonFinite => PolygonError::NonFinite,
            TriangulationError::CoincidentCorners { first, second } => {
                PolygonError::CoincidentCorners {
                    first: first + 1,
                    second: second + 1,
                }
            }
            TriangulationError::Degenerate => PolygonError::Degenerate,
            // A face has no holes: a boundary that does not enclose its region consistently
            // crosses or touches itself.
            TriangulationError::SelfIntersecting | TriangulationError::HoleOutside => {
                PolygonError::SelfIntersecting
            }
            TriangulationError::Folded => PolygonError::Folded,
        }
    }
}

/// Triangulates the polygon whose corners are `corners` (indices into `positions`, in boundary
/// order) and appends `corners.len() - 2` triangles with the polygon's winding to `out`.
///
/// On error nothing is appended.
pub fn triangulate_polygon(
    positions: &[DVec3],
    corners: &[u32],
    out: &mut Vec<[u32; 3]>,
) -> Result<(), PolygonError> {
    if corners.len() < 3 {
        return Err(PolygonError::TooFewCorners(corners.len()));
    }
    let points = corner_positions(positions, corners)?;
    match *corners {
        [a, b, c] => {
            out.push([a, b, c]);
            Ok(())
        }
        [a, b, c, d] => triangulate_quad(&points, [a, b, c, d], out),
        _ => {
            let triangles = triangulate::triangulate_polygon(&points)?;
            out.extend(triangles.iter().map(|t| t.map(|i| corners[i as usize])));
            Ok(())
        }
    }
}

fn corner_positions(positions: &[DVec3], corners: &[u32]) -> Result<Vec<DVec3>, PolygonError> {
    corners
        .iter()
        .map(|&index| {
            let p =
                positions
                    .get(index as usize)
                    .copied()
                    .ok_or(PolygonError::IndexOutOfRange {
                        index,
                        count: positions.len(),
                    })?;
            if p.is_finite() {
                Ok(p)
            } else {
                Err(PolygonError::NonFinite)
            }
        })
        .collect()
}

/// The unit normal of a polygon, or `Degenerate` if its area is negligible for its size.
fn unit_normal(points: &[DVec3]) -> Result<DVec3, PolygonError> {
    let normal = newell_normal(points);
    let size = extent(points);
    let length = normal.length();
    if !length.is_finite() || length <= 16.0 * f64::EPSILON * size * size {
        return Err(PolygonError::Degenerate);
    }
    Ok(normal / length)
}

/// The largest edge of the bounding box.
fn extent(points: &[DVec3]) -> f64 {
    let (min, max) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(min, max), &p| {
            (min.min(p), max.max(p))
        });
    (max - min).max_element()
}

/// The first pair of corners (1-based) at exactly the same position.
fn coincident_corners(points: &[DVec3]) -> Option<(usize, usize)> {
    (0..points.len()).find_map(|i| {
        (i + 1..points.len())
            .find(|&j| points[i] == points[j])
            .map(|j| (i + 1, j + 1))
    })
}

/// The quad split along the shorter diagonal if both halves face like the quad, else along the
/// other one if they do; otherwise the quad is self-intersecting.
fn triangulate_quad(
    points: &[DVec3],
    corners: [u32; 4],
    out: &mut Vec<[u32; 3]>,
) -> Result<(), PolygonError> {
    if let Some((first, second)) = coincident_corners(points) {
        return Err(PolygonError::CoincidentCorners { first, second });
    }
    let normal = unit_normal(points)?;
    let along_02 = [[0, 1, 2], [0, 2, 3]];
    let along_13 = [[0, 1, 3], [1, 2, 3]];
    let splits = if points[0].distance_squared(points[2]) <= points[1].distance_squared(points[3]) {
        [along_02, along_13]
    } else {
        [along_13, along_02]
    };
    let split = splits
        .iter()
        .find(|split| split.iter().all(|t| facing(points, t, normal)))
        .ok_or(PolygonError::SelfIntersecting)?;
    out.extend(split.iter().map(|t| t.map(|i| corners[i])));
    Ok(())
}

/// Whether the triangle of corners `t` faces the same way as `normal`.
fn facing(points: &[DVec3], t: &[usize; 3], normal: DVec3) -> bool {
    let [a, b, c] = t.map(|i| points[i]);
    (b - a).cross(c - a).dot(normal) > 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area_and_check_winding(positions: &[DVec3], tris: &[[u32; 3]], normal: DVec3) -> f64 {
        tris.iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| positions[i as usize]);
                let n = (b - a).cross(c - a);
                assert!(
                    n.dot(normal) > 0.0,
                    "triangle {t:?} is wound against the face"
                );
                n.length() / 2.0
            })
            .sum()
    }

    fn check(points: &[DVec3]) -> Vec<[u32; 3]> {
        let corners: Vec<u32> = (0..points.len() as u32).collect();
        let mut tris = Vec::new();
        triangulate_polygon(points, &corners, &mut tris).expect("valid polygon");
        assert_eq!(tris.len(), points.len() - 2);
        let normal = newell_normal(points);
        let area = area_and_check_winding(points, &tris, normal);
        assert!(
            (area - normal.length() / 2.0).abs() < 1e-9,
            "{area} vs {normal}"
        );
        tris
    }

    fn xy(coords: &[(f64, f64)]) -> Vec<DVec3> {
        coords.iter().map(|&(x, y)| DVec3::new(x, y, 0.0)).collect()
    }

    #[test]
    fn triangles_pass_through() {
        let p = xy(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]);
        let mut out = Vec::new();
        triangulate_polygon(&p, &[2, 0, 1], &mut out).expect("triangle");
        assert_eq!(out, [[2, 0, 1]]);
    }

    #[test]
    fn convex_and_non_convex_quads() {
        check(&xy(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]));
        // Dart: corner 1 is reflex, so only the diagonal 1-3 lies inside.
        let dart = xy(&[(0.0, 0.0), (2.0, 1.0), (4.0, 0.0), (2.0, 3.0)]);
        let tris = check(&dart);
        assert!(tris.iter().all(|t| t.contains(&1) && t.contains(&3)));
        // Clockwise (seen from +z) keeps its clockwise winding.
        let cw = xy(&[(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]);
        check(&cw);
        assert!(newell_normal(&cw).z < 0.0);
    }

    #[test]
    fn pentagon_and_l_shaped_hexagon() {
        let pentagon: Vec<DVec3> = (0..5)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::TAU / 5.0;
                DVec3::new(a.cos(), a.sin(), 0.3)
            })
            .collect();
        check(&pentagon);
        let l_shape = xy(&[
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (1.0, 2.0),
            (0.0, 2.0),
        ]);
        check(&l_shape);
    }

    #[test]
    fn tilted_and_slightly_non_planar_polygons() {
        let tilt = |x: f64, y: f64, bump: f64| DVec3::new(x, y * 0.6, y * 0.8 + bump) * 10.0;
        let star: Vec<DVec3> = (0..10)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::TAU / 10.0;
                let r = if i % 2 == 0 { 1.0 } else { 0.4 };
                tilt(
                    r * a.cos(),
                    r * a.sin(),
                    if i % 3 == 0 { 1e-4 } else { 0.0 },
                )
            })
            .collect();
        let corners: Vec<u32> = (0..10).collect();
        let mut tris = Vec::new();
        triangulate_polygon(&star, &corners, &mut tris).expect("star");
        assert_eq!(tris.len(), 8);
        area_and_check_winding(&star, &tris, newell_normal(&star));
    }

    #[test]
    fn collinear_corner_is_fine() {
        check(&xy(&[
            (0.0, 0.0),
            (1.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (0.0, 1.0),
        ]));
    }

    #[test]
    fn invalid_faces_are_errors() {
        let mut out = Vec::new();
        let p = xy(&[
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 2.0),
            (0.0, 2.0),
            (2.0, 0.0),
            (1.0, 3.0),
        ]);
        let err = |corners: &[u32], out: &mut Vec<[u32; 3]>| {
            triangulate_polygon(&p, corners, out).expect_err("invalid")
        };
        assert_eq!(err(&[0, 1], &mut out), PolygonError::TooFewCorners(2));
        assert!(matches!(
            err(&[0, 1, 9], &mut out),
            PolygonError::IndexOutOfRange { index: 9, count: 6 }
        ));
        assert_eq!(
            err(&[0, 1, 2, 4, 3], &mut out),
            PolygonError::CoincidentCorners {
                first: 2,
                second: 4
            }
        );
        assert!(matches!(
            err(&[0, 1, 1, 2], &mut out),
            PolygonError::CoincidentCorners { .. }
        ));
        // Bow tie (quad) and a crossing pentagon.
        assert_eq!(err(&[0, 2, 1, 3], &mut out), PolygonError::Degenerate);
        assert_eq!(
            err(&[0, 2, 3, 1, 5], &mut out),
            PolygonError::SelfIntersecting
        );
        // All collinear.
        let line = xy(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0), (4.0, 0.0)]);
        assert_eq!(
            triangulate_polygon(&line, &[0, 1, 2, 3, 4], &mut out),
            Err(PolygonError::Degenerate)
        );
        assert!(out.is_empty());
    }

    #[test]
    fn corner_touching_an_edge_is_self_intersecting() {
        // Corner 4 (1, 0) lies on the edge from corner 0 to corner 1.
        let p = xy(&[
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 2.0),
            (1.0, 2.0),
            (1.0, 0.0),
            (0.0, 2.0),
        ]);
        let mut out = Vec::new();
        let corners = [0, 1, 2, 3, 4, 5];
        assert_eq!(
            triangulate_polygon(&p, &corners, &mut out),
            Err(PolygonError::SelfIntersecting)
        );
        assert!(out.is_empty());
    }

    #[test]
    fn non_finite_and_huge_inputs_do_not_panic() {
        let mut out = Vec::new();
        let mut p = xy(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.5, 2.0), (0.0, 1.0)]);
        p[3].x = f64::NAN;
        assert_eq!(
            triangulate_polygon(&p, &[0, 1, 2, 3, 4], &mut out),
            Err(PolygonError::NonFinite)
        );
        let huge: Vec<DVec3> = xy(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.5, 2.0), (0.0, 1.0)])
            .into_iter()
            .map(|v| v * 1e300)
            .collect();
        let _ = triangulate_polygon(&huge, &[0, 1, 2, 3, 4], &mut out);
        let tiny: Vec<DVec3> = huge.iter().map(|v| *v * 1e-300 * 1e-300).collect();
        let _ = triangulate_polygon(&tiny, &[0, 1, 2, 3, 4], &mut out);
    }

    #[test]
    fn random_polygons_triangulate_exactly_or_fail_cleanly() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        };
        let mut ok = 0;
        for _ in 0..3000 {
            let n = 3 + next(8) as usize;
            // A small grid: many collinear, coincident and crossing cases.
            let points: Vec<DVec3> = (0..n)
                .map(|_| DVec3::new(next(5) as f64, next(5) as f64, next(2) as f64 * 1e-3))
                .collect();
            let corners: Vec<u32> = (0..n as u32).collect();
            let mut tris = Vec::new();
            if triangulate_polygon(&points, &corners, &mut tris).is_err() {
                assert!(tris.is_empty());
                continue;
            }
            ok += 1;
            assert_eq!(tris.len(), n - 2);
            if n > 3 {
                // The vector areas of the triangles add up to that of the polygon, planar or
                // not, and each triangle faces the polygon's way.
                let normal = newell_normal(&points);
                area_and_check_winding(&points, &tris, normal);
                let sum: DVec3 = tris
                    .iter()
                    .map(|t| {
                        let [a, b, c] = t.map(|i| points[i as usize]);
                        (b - a).cross(c - a)
                    })
                    .sum();
                assert!((sum - normal).length() < 1e-9, "{points:?} {tris:?}");
            }
        }
        assert!(ok > 500, "only {ok} random polygons were simple");
    }
}
