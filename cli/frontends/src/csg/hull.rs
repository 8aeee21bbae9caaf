//! Convex hulls of point sets: in 3D incremental (each point outside the current hull replaces
//! the faces it sees by a fan to their horizon), as vertices and outward triangles; in 2D by
//! Andrew's monotone chain, as a counter-clockwise ring.

use glam::{DVec2, DVec3};
use std::collections::{HashMap, HashSet};

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

/// The hull of `points` up to `eps`: points closer than `eps / 2` to a point kept before them
/// are dropped first ([`eps_net`]), so the result may miss points by up to `eps / 2`, and
/// points spanning less than `eps` of thickness have no hull. For approximate points, such as
/// mesh vertices, a larger `eps` gives far fewer faces, and the near-duplicates (vertices a
/// rounding error apart at a box's corner) are gone: their triangles' planes are noise.
pub fn convex_hull_within(points: &[DVec3], eps: f64) -> Option<(Vec<DVec3>, Vec<Vec<u32>>)> {
    let net = eps_net(points, 0.5 * eps);
    let points = &net[..];
    // Visibility is decided at rounding-noise scale: a larger tolerance lets points skip faces
    // they see, and the horizon of the faces a later point sees is then no simple loop.
    let size = points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    let vis = eps.min(1e-10 * size.max(1e-300));
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
            .filter(|&f| faces[f].alive && faces[f].n.dot(p) - faces[f].d > vis)
            .collect();
        if visible.is_empty() {
            continue;
        }
        // The visible faces' edges in face order (a hash set's order would make the hull, and
        // everything built from it, differ from run to run).
        let mut edges = Vec::with_capacity(3 * visible.len());
        for &f in &visible {
            let [a, b, c] = faces[f].v;
            edges.extend([(a, b), (b, c), (c, a)]);
            faces[f].alive = false;
        }
        let seen: HashSet<(usize, usize)> = edges.iter().copied().collect();
        let horizon: Vec<(usize, usize)> = edges
            .iter()
            .copied()
            .filter(|&(a, b)| !seen.contains(&(b, a)))
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

/// The points of `points` (in order) that lie at least `r` from every point kept before them: a
/// greedy `r`-net, found through a hash of cells of size `r` (a point's net neighbours lie in
/// the 27 cells around its own).
pub fn eps_net(points: &[DVec3], r: f64) -> Vec<DVec3> {
    if !(r > 0.0 && r.is_finite()) {
        return points.to_vec();
    }
    let key = |p: DVec3| (p / r).floor().as_i64vec3();
    let mut cells: HashMap<glam::I64Vec3, Vec<DVec3>> = HashMap::new();
    let mut kept = Vec::new();
    for &p in points {
        if !p.is_finite() {
            continue;
        }
        let k = key(p);
        let near = (0..27).any(|o| {
            let c = k + glam::I64Vec3::new(o % 3 - 1, o / 3 % 3 - 1, o / 9 - 1);
            cells
                .get(&c)
                .is_some_and(|v| v.iter().any(|q| q.distance_squared(p) < r * r))
        });
        if !near {
            cells.entry(k).or_default().push(p);
            kept.push(p);
        }
    }
    kept
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

    /// Mesh-like input: every corner of a box repeated with rounding-sized offsets, and points
    /// on its faces and edges. The near-duplicates are merged, so the hull is the box.
    #[test]
    fn near_duplicate_corners_give_the_box() {
        let mut pts = Vec::new();
        for i in 0..8 {
            let c = DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64);
            for j in 0..20 {
                let wobble = DVec3::new((j % 3) as f64, (j / 3 % 3) as f64, (j % 5) as f64);
                pts.push(c + (DVec3::splat(0.5) - c) * 1e-7 * wobble);
            }
        }
        for k in 0..1000 {
            let t = k as f64 / 1000.0;
            pts.push(DVec3::new(t, (t * 7.0).fract(), 1.0));
            pts.push(DVec3::new(0.0, t, (t * 13.0).fract()));
            pts.push(DVec3::new(t, 1.0, 0.0));
        }
        let (v, f) = convex_hull_within(&pts, 1e-3).unwrap();
        // The corners, each once (a point on a face may stay from the starting simplex).
        for i in 0..8 {
            let c = DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64);
            assert_eq!(
                v.iter().filter(|q| q.distance(c) < 1e-3).count(),
                1,
                "{c} in {v:?}"
            );
        }
        let vol: f64 = f
            .iter()
            .map(|t| v[t[0] as usize].dot(v[t[1] as usize].cross(v[t[2] as usize])) / 6.0)
            .sum();
        assert!((vol - 1.0).abs() < 1e-5, "{vol}");
        assert_eq!(
            eps_net(&[DVec3::ZERO, DVec3::X * 0.4, DVec3::X * 0.6], 0.5).len(),
            2
        );
    }

    /// The extreme vertices of a meshed `difference() { cube(2); cube(1); }` (one cell bevels at
    /// the corners): with the caller's tolerance for visibility the hull came out with faces
    /// 1.4 units inside some points (volume 11.5 for a solid inside the 2-cube).
    #[test]
    fn hull_contains_every_point() {
        let (a, e, h) = (1.9999984502792358, 1.56249996052793e-6, 0.015625);
        let b = 2.0 - h;
        let pts = [
            [a, b, 2.0],
            [e, b, 2.0],
            [b, e, 2.0],
            [b, a, 2.0],
            [e, h, 2.0],
            [a, h, 2.0],
            [h, a, 2.0],
            [h, e, 2.0],
            [e, 0.0, b],
            [e, 2.0, b],
            [2.0, a, b],
            [2.0, e, b],
            [2.0, e, h],
            [e, 2.0, h],
            [e, 0.0, 1.0 + h],
            [2.0, a, h],
            [b, 2.0, e],
            [2.0, b, e],
            [b, 0.0, e],
            [2.0, h, e],
            [1.0 + h, 0.0, e],
            [0.0, b, e],
            [h, 2.0, e],
            [0.0, 1.0 + h, e],
        ]
        .map(DVec3::from);
        let (v, f) = convex_hull_within(&pts, h / 2.0).unwrap();
        let mut vol = 0.0;
        for t in &f {
            let [a, b, c] = [0, 1, 2].map(|i| v[t[i] as usize]);
            vol += a.dot(b.cross(c)) / 6.0;
            let n = (b - a).cross(c - a).normalize();
            for p in pts {
                assert!(n.dot(p - a) < 1e-9, "{p} outside the face {a} {b} {c}");
            }
        }
        assert!(vol > 7.8 && vol < 8.0, "{vol}");
    }

    #[test]
    fn flat_points_have_no_hull() {
        let pts = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ONE.with_z(0.0)];
        assert!(convex_hull(&pts).is_none());
    }
}
