//! Faces of the convex hull of a small set of points in convex position (every point a vertex),
//! by brute force over point triples: enough for the Platonic solids (at most 20 points) and exact
//! about coplanar points, which form one polygonal face.

use glam::DVec3;

/// The hull's faces as counter-clockwise (seen from outside) lists of point indices. `O(n⁴)`:
/// meant for a few dozen points at most.
pub(crate) fn convex_faces(points: &[DVec3]) -> Vec<Vec<u32>> {
    let size = points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    let tolerance = 1e-9 * size;
    let mut faces: Vec<Vec<u32>> = Vec::new();
    let mut seen: Vec<Vec<u32>> = Vec::new();
    let n = points.len();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let (a, b, c) = (points[i], points[j], points[k]);
                let Some(normal) = (b - a).cross(c - a).try_normalize() else {
                    continue;
                };
                let side = |p: DVec3| normal.dot(p - a);
                let outward = if points.iter().all(|&p| side(p) <= tolerance) {
                    normal
                } else if points.iter().all(|&p| side(p) >= -tolerance) {
                    -normal
                } else {
                    continue;
                };
                let mut on_plane: Vec<u32> = (0..n as u32)
                    .filter(|&m| side(points[m as usize]).abs() <= tolerance)
                    .collect();
                if seen.contains(&on_plane) {
                    continue;
                }
                seen.push(on_plane.clone());
                sort_around(points, &mut on_plane, outward);
                faces.push(on_plane);
            }
        }
    }
    faces
}

/// Orders coplanar points counter-clockwise around their centroid, seen from the side `normal`
/// points to.
fn sort_around(points: &[DVec3], face: &mut [u32], normal: DVec3) {
    let center = face.iter().map(|&i| points[i as usize]).sum::<DVec3>() / face.len() as f64;
    let u = (points[face[0] as usize] - center).normalize();
    let v = normal.cross(u);
    let angle = |i: u32| {
        let d = points[i as usize] - center;
        d.dot(v).atan2(d.dot(u))
    };
    face.sort_by(|&p, &q| angle(p).total_cmp(&angle(q)));
}
