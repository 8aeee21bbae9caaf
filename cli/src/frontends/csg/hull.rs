//! Convex hulls of point sets: in 3D incremental (each point outside the current hull replaces
//! the faces it sees by a fan to their horizon), as vertices and outward triangles; in 2D by
//! Andrew's monotone chain, as a counter-clockwise ring.

use glam::{DVec2, DVec3};
use std::collections::HashSet;

/// A hull triangle, counter-clockwise seen from outside, with its plane `n · p = d`.
struct Face {
    v: [usize; 3],
    n: DVec3,
    d: f64,
    alive: bool,
}

impl Face {
    fn new(points: &[DVec3], v: [usize; 3]) -> Face {
        let n = (points[v[1]] - points[v[0]])
            .cross(points[v[2]] - points[v[0]])
            .normalize_or_zero();
        Face {
            v,
            n,
            d: n.dot(points[v[0]]),
            alive: true,
        }
    }
}

/// The 2D convex hull of `points`, counter-clockwise without collinear corners (fewer than three
/// corners when the points span no area).
pub fn convex_hull_2d(points: &[DVec2]) -> Vec<DVec2> {
    let mut p: Vec<DVec2> = points.iter().copied().filter(|q| q.is_finite()).collect();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let turn = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut ring: Vec<DVec2> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = ring.len();
        let ordered: Box<dyn Iterator<Item = &DVec2>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in ordered {
            while ring.len() >= start + 2
                && turn(ring[ring.len() - 2], ring[ring.len() - 1], q) <= 0.0
            {
                ring.pop();
            }
            ring.push(q);
        }
        ring.pop();
    }
    ring
}

/// The hull's vertices and triangles, or `None` when the points span no volume.
pub fn convex_hull(points: &[DVec3]) -> Option<(Vec<DVec3>, Vec<Vec<u32>>)> {
    let size = points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    convex_hull_within(points, 1e-10 * size.max(1e-300))
}

/// The hull of `points`, a point within `eps` of the current hull counting as inside (so the
/// result may miss points by up to `eps`: for approximate points, such as mesh vertices, a
/// larger `eps` gives far fewer faces).
pub fn convex_hull_within(points: &[DVec3], eps: f64) -> Option<(Vec<DVec3>, Vec<Vec<u32>>)> {
    let far = |from: &dyn Fn(DVec3) -> f64| {
        (0..points.len()).max_by(|&a, &b| from(points[a]).total_cmp(&from(points[b])))
    };
    let p0 = far(&|p| -p.x)?;
    let p1 = far(&|p| (p - points[p0]).length())?;
    let axis = (points[p1] - points[p0]).normalize_or_zero();
    let p2 = far(&|p| (p - points[p0]).cross(axis).length())?;
    let normal = (points[p1] - points[p0])
        .cross(points[p2] - points[p0])
        .normalize_or_zero();
    let p3 = far(&|p| normal.dot(p - points[p0]).abs())?;
    if normal.dot(points[p3] - points[p0]).abs() <= eps || normal == DVec3::ZERO {
        return None;
    }
    let centre = (points[p0] + points[p1] + points[p2] + points[p3]) / 4.0;
    let mut faces: Vec<Face> = [[p0, p1, p2], [p0, p1, p3], [p0, p2, p3], [p1, p2, p3]]
        .into_iter()
        .map(|[a, b, c]| {
            let f = Face::new(points, [a, b, c]);
            if f.n.dot(centre) - f.d > 0.0 {
                Face::new(points, [a, c, b])
            } else {
                f
            }
        })
        .collect();
    for (i, &p) in points.iter().enumerate() {
        let visible: Vec<usize> = (0..faces.len())
            .filter(|&f| faces[f].alive && faces[f].n.dot(p) - faces[f].d > eps)
            .collect();
        if visible.is_empty() {
            continue;
        }
        let mut edges = HashSet::new();
        for &f in &visible {
            let [a, b, c] = faces[f].v;
            edges.extend([(a, b), (b, c), (c, a)]);
            faces[f].alive = false;
        }
        let horizon: Vec<(usize, usize)> = edges
            .iter()
            .copied()
            .filter(|&(a, b)| !edges.contains(&(b, a)))
            .collect();
        for (a, b) in horizon {
            faces.push(Face::new(points, [a, b, i]));
        }
        if faces.len() > 64 && faces.iter().filter(|f| !f.alive).count() * 2 > faces.len() {
            faces.retain(|f| f.alive);
        }
    }
    let mut remap = vec![u32::MAX; points.len()];
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for f in faces.iter().filter(|f| f.alive) {
        let tri = f.v.map(|v| {
            if remap[v] == u32::MAX {
                remap[v] = vertices.len() as u32;
                vertices.push(points[v]);
            }
            remap[v]
        });
        triangles.push(tri.to_vec());
    }
    Some((vertices, triangles))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hull_of_cube_corners_and_interior_points() {
        let mut pts: Vec<DVec3> = (0..8)
            .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64))
            .collect();
        pts.push(DVec3::splat(0.5));
        pts.push(DVec3::new(0.5, 0.5, 1.0));
        let (v, f) = convex_hull(&pts).unwrap();
        assert_eq!(v.len(), 8);
        assert_eq!(f.len(), 12);
        let vol: f64 = f
            .iter()
            .map(|t| v[t[0] as usize].dot(v[t[1] as usize].cross(v[t[2] as usize])) / 6.0)
            .sum();
        assert!((vol - 1.0).abs() < 1e-12, "{vol}");
    }

    #[test]
    fn hull_2d_of_square_corners_and_inner_points() {
        let mut pts: Vec<DVec2> = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0], [1.0, 0.5]]
            .map(DVec2::from)
            .to_vec();
        pts.push(DVec2::new(1.0, 0.0)); // collinear on an edge: dropped
        let ring = convex_hull_2d(&pts);
        assert_eq!(ring.len(), 4);
        let area: f64 = (0..4)
            .map(|i| ring[i].perp_dot(ring[(i + 1) % 4]))
            .sum::<f64>()
            / 2.0;
        assert_eq!(area, 2.0, "counter-clockwise, area 2");
        assert!(convex_hull_2d(&[DVec2::ZERO, DVec2::X, DVec2::X * 2.0]).len() < 3);
    }

    #[test]
    fn flat_points_have_no_hull() {
        let pts = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE.with_z(0.0)];
        assert!(convex_hull(&pts).is_none());
    }
}
