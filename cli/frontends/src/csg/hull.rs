//! Convex hulls of point sets: in 3D incremental with conflict lists (Quickhull's order: each
//! point outside the hull waits on one face that sees it; a face's farthest waiting point
//! replaces the cap of faces it sees, found across edges, by a fan to the cap's rim, and the
//! cap's waiting points move to the new faces), as vertices and outward triangles; in 2D by
//! Andrew's monotone chain, as a counter-clockwise ring.

use glam::{DVec2, DVec3};
use std::collections::HashMap;

/// A hull triangle, counter-clockwise seen from outside, with its plane `n · p = d`.
struct Face {
    v: [usize; 3],
    n: DVec3,
    d: f64,
    alive: bool,
}

impl Face {
    /// How far `p` lies outside the face's plane.
    fn height(&self, p: DVec3) -> f64 {
        self.n.dot(p) - self.d
    }

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
    // Each directed edge `a → b` of a live face, to that face: its neighbour across the edge
    // owns `b → a`.
    let mut owner: HashMap<(usize, usize), usize> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        let [a, b, c] = f.v;
        owner.extend([((a, b), i), ((b, c), i), ((c, a), i)]);
    }
    // Conflict lists: every point outside the hull waits on one face that sees it.
    let mut outside: Vec<Vec<usize>> = vec![Vec::new(); faces.len()];
    for (i, &q) in points.iter().enumerate() {
        if [p0, p1, p2, p3].contains(&i) {
            continue;
        }
        if let Some(f) = (0..faces.len()).find(|&f| faces[f].height(q) > vis) {
            outside[f].push(i);
        }
    }
    let mut queue: Vec<usize> = (0..faces.len()).rev().collect();
    let mut stamp: Vec<usize> = vec![usize::MAX; faces.len()];
    while let Some(f) = queue.pop() {
        if !faces[f].alive || outside[f].is_empty() {
            continue;
        }
        // The farthest point this face waits for is a hull vertex.
        let pending = std::mem::take(&mut outside[f]);
        let &apex = pending
            .iter()
            .max_by(|&&a, &&b| {
                let h = |i: usize| faces[f].height(points[i]);
                h(a).total_cmp(&h(b)).then(b.cmp(&a))
            })
            .expect("non-empty");
        let p = points[apex];
        // The faces it sees, found across edges from `f` (a connected cap), and the cap's rim.
        let mut cap = vec![f];
        stamp[f] = apex;
        let mut rim = Vec::new();
        let mut k = 0;
        while k < cap.len() {
            let g = cap[k];
            k += 1;
            let [a, b, c] = faces[g].v;
            for (u, v) in [(a, b), (b, c), (c, a)] {
                let Some(&h) = owner.get(&(v, u)) else {
                    continue;
                };
                if stamp[h] == apex {
                    continue;
                }
                if faces[h].height(p) > vis {
                    stamp[h] = apex;
                    cap.push(h);
                } else {
                    rim.push((u, v));
                }
            }
        }
        // Near-coplanar faces can leave the cap pinched at a vertex (two fans of seen faces
        // around it, split by faces the point is level with): the rim is then no simple loop.
        // Such a vertex's faces join the cap, the nearly level ones first, all if need be.
        for round in 0..8 {
            let mut starts: HashMap<usize, usize> = HashMap::new();
            let Some(&(w, _)) = rim.iter().find(|&&(u, _)| {
                let n = starts.entry(u).or_default();
                *n += 1;
                *n > 1
            }) else {
                break;
            };
            let level = if round == 0 {
                -1e3 * vis
            } else {
                f64::NEG_INFINITY
            };
            for g in 0..faces.len() {
                if faces[g].alive
                    && stamp[g] != apex
                    && faces[g].v.contains(&w)
                    && faces[g].height(p) > level
                {
                    stamp[g] = apex;
                    cap.push(g);
                }
            }
            rim.clear();
            for &g in &cap {
                let [a, b, c] = faces[g].v;
                for (u, v) in [(a, b), (b, c), (c, a)] {
                    if owner.get(&(v, u)).is_some_and(|&h| stamp[h] != apex) {
                        rim.push((u, v));
                    }
                }
            }
        }
        let mut waiting = pending;
        for &g in &cap {
            faces[g].alive = false;
            let [a, b, c] = faces[g].v;
            for e in [(a, b), (b, c), (c, a)] {
                if owner.get(&e) == Some(&g) {
                    owner.remove(&e);
                }
            }
            if g != f {
                waiting.append(&mut outside[g]);
            }
        }
        let first = faces.len();
        for (u, v) in rim {
            let i = faces.len();
            faces.push(Face::new(points, [u, v, apex]));
            outside.push(Vec::new());
            stamp.push(usize::MAX);
            owner.extend([((u, v), i), ((v, apex), i), ((apex, u), i)]);
        }
        for q in waiting {
            if q == apex {
                continue;
            }
            if let Some(g) = (first..faces.len()).find(|&g| faces[g].height(points[q]) > vis) {
                outside[g].push(q);
            }
        }
        queue.extend((first..faces.len()).filter(|&g| !outside[g].is_empty()));
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

    /// Many points, many of them coplanar or on a sphere (the sum of a cube and OpenSCAD's
    /// sphere of 128 fragments, 65 536 points; the faces through near-coplanar points once left
    /// a cap pinched at a vertex, so an edge was used twice): a closed hull (every edge used
    /// once each way, V − E + F = 2) that contains the points, with the volume of the rounded
    /// cube it approximates.
    #[test]
    fn large_minkowski_like_sums() {
        let (sphere, _) = super::super::facets::sphere(
            1.0,
            super::super::facets::Resolution {
                fn_: 128.0,
                fa: 12.0,
                fs: 2.0,
            },
        );
        let mut pts = Vec::new();
        for c in 0..8 {
            let corner = DVec3::new((c & 1) as f64, ((c >> 1) & 1) as f64, ((c >> 2) & 1) as f64);
            pts.extend(sphere.iter().map(|p| *p + corner * 2.0));
        }
        // A grid of coplanar points on the faces, inside the hull.
        for i in 0..=20 {
            for j in 0..=20 {
                let (u, v) = (i as f64 / 10.0, j as f64 / 10.0);
                pts.push(DVec3::new(u, v, 2.5));
                pts.push(DVec3::new(-0.5, u, v));
            }
        }
        let (v, f) = convex_hull(&pts).unwrap();
        let mut edges = HashMap::new();
        for t in &f {
            for k in 0..3 {
                *edges.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
            }
        }
        assert!(
            edges
                .iter()
                .all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1))
        );
        assert_eq!(
            v.len() as i64 - (edges.len() / 2) as i64 + f.len() as i64,
            2
        );
        let vol: f64 = f
            .iter()
            .map(|t| v[t[0] as usize].dot(v[t[1] as usize].cross(v[t[2] as usize])) / 6.0)
            .sum();
        // A 2-cube grown by 1: 8 + 6·4 + 12·π·... = 8 + 24 + 6π + 4π/3 (slightly less faceted).
        let exact = 8.0 + 24.0 + 6.0 * std::f64::consts::PI + 4.0 / 3.0 * std::f64::consts::PI;
        assert!(vol < exact && vol > exact * 0.999, "{vol} vs {exact}");
        // Every 50th point (the check is quadratic).
        for p in pts.iter().step_by(50) {
            let outside = f.iter().any(|t| {
                let [a, b, c] = [0, 1, 2].map(|k| v[t[k] as usize]);
                let n = (b - a).cross(c - a).normalize();
                n.dot(*p - a) > 1e-9
            });
            assert!(!outside, "{p}");
        }
    }
}
