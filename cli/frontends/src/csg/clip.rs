//! The corners of a convex polyhedron given as a bounded part and half-spaces, as
//! [`super::convex`] builds OpenSCAD's faceted spheres and cylinders (a box intersected with face
//! planes): the box's faces clipped by each plane in turn, the cut closing each time as a new face.
//! Used by [`super::bounds`] so that `resize()` measures such a primitive exactly, rotated or not.

use super::bound::Bound;
use glam::DVec3;

/// The corners of the intersection of the children `c` of an intersection node, when exactly one
/// is bounded and known by its points (their hull is that child) and all others are half-spaces.
pub(super) fn convex_bound(c: &[Bound]) -> Option<Vec<DVec3>> {
    let mut points = None;
    let mut planes = Vec::new();
    for b in c {
        match b {
            Bound::Points(p) if points.is_none() => points = Some(p),
            Bound::Plane(n, d) => planes.push((n.try_normalize()?, *d)),
            _ => return None,
        }
    }
    let points = points?;
    // The hull of the bounded child's points, when it is a box: its six faces.
    let (lo, hi) = points.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let corner = |i: usize| {
        DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        )
    };
    if points.len() != 8 || !points.iter().all(|p| (0..8).any(|i| corner(i) == *p)) {
        return None;
    }
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let mut faces: Vec<Vec<DVec3>> = quads
        .iter()
        .map(|q| q.iter().map(|&i| corner(i)).collect())
        .collect();
    let eps = 1e-12 * (hi - lo).max_element().max(f64::MIN_POSITIVE);
    for (n, d) in planes {
        let mut cut = Vec::new();
        let mut kept = Vec::with_capacity(faces.len() + 1);
        for face in &faces {
            let mut out = Vec::with_capacity(face.len() + 1);
            for (k, &a) in face.iter().enumerate() {
                let b = face[(k + 1) % face.len()];
                let (da, db) = (n.dot(a) - d, n.dot(b) - d);
                if da <= eps {
                    out.push(a);
                    if da.abs() <= eps {
                        cut.push(a);
                    }
                }
                if (da < -eps && db > eps) || (da > eps && db < -eps) {
                    let p = a + (b - a) * (da / (da - db));
                    out.push(p);
                    cut.push(p);
                }
            }
            if out.len() >= 3 {
                kept.push(out);
            }
        }
        if cut.len() >= 3 {
            kept.push(ordered_in_plane(cut, n));
        }
        faces = kept;
    }
    let corners: Vec<DVec3> = faces.into_iter().flatten().collect();
    (!corners.is_empty()).then_some(corners)
}

/// `points` (in a plane of normal `n`) in angular order around their centroid.
fn ordered_in_plane(mut points: Vec<DVec3>, n: DVec3) -> Vec<DVec3> {
    let centre = points.iter().copied().sum::<DVec3>() / points.len() as f64;
    let u = n.any_orthonormal_vector();
    let v = n.cross(u);
    points.sort_by(|a, b| {
        let (pa, pb) = (*a - centre, *b - centre);
        pa.dot(v)
            .atan2(pa.dot(u))
            .total_cmp(&pb.dot(v).atan2(pb.dot(u)))
    });
    points
}
