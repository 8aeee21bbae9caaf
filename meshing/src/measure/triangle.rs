//! The exact point of a triangle nearest to a query point.
//!
//! The plane of the triangle is split into seven Voronoi regions (three vertices, three edges, the
//! face); the query's region follows from signs of dot products with the edge vectors, and the
//! nearest point is the vertex, the projection onto the edge or the projection onto the plane
//! (Ericson, *Real-Time Collision Detection*, §5.1.5). A collinear or point-like triangle has no
//! plane; it falls back to the nearest point of its three edges.

use glam::DVec3;

/// The point of the triangle `[a, b, c]` nearest to `q`.
pub fn closest_point_on_triangle(q: DVec3, [a, b, c]: [DVec3; 3]) -> DVec3 {
    let p = by_regions(q, a, b, c);
    if p.is_finite() {
        return p;
    }
    // Degenerate: the regions divided by a zero area.
    let candidates = [
        closest_point_on_segment(q, a, b),
        closest_point_on_segment(q, b, c),
        closest_point_on_segment(q, c, a),
    ];
    candidates
        .into_iter()
        .min_by(|x, y| q.distance_squared(*x).total_cmp(&q.distance_squared(*y)))
        .unwrap_or(a)
}

/// The point of the segment `[a, b]` nearest to `q` (`a` when the segment is a point).
pub fn closest_point_on_segment(q: DVec3, a: DVec3, b: DVec3) -> DVec3 {
    let ab = b - a;
    let len2 = ab.length_squared();
    if len2 > 0.0 {
        a + ab * ((q - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        a
    }
}

/// The Voronoi-region computation; non-finite for a zero-area triangle whose query falls in the
/// face region.
fn by_regions(q: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    let (ab, ac) = (b - a, c - a);
    // Vertex a.
    let aq = q - a;
    let (qa_ab, qa_ac) = (ab.dot(aq), ac.dot(aq));
    if qa_ab <= 0.0 && qa_ac <= 0.0 {
        return a;
    }
    // Vertex b.
    let bq = q - b;
    let (qb_ab, qb_ac) = (ab.dot(bq), ac.dot(bq));
    if qb_ab >= 0.0 && qb_ac <= qb_ab {
        return b;
    }
    // Edge ab: the barycentric weight of c is proportional to `wc`.
    let wc = qa_ab * qb_ac - qb_ab * qa_ac;
    if wc <= 0.0 && qa_ab >= 0.0 && qb_ab <= 0.0 {
        return a + ab * (qa_ab / (qa_ab - qb_ab));
    }
    // Vertex c.
    let cq = q - c;
    let (qc_ab, qc_ac) = (ab.dot(cq), ac.dot(cq));
    if qc_ac >= 0.0 && qc_ab <= qc_ac {
        return c;
    }
    // Edge ac.
    let wb = qc_ab * qa_ac - qa_ab * qc_ac;
    if wb <= 0.0 && qa_ac >= 0.0 && qc_ac <= 0.0 {
        return a + ac * (qa_ac / (qa_ac - qc_ac));
    }
    // Edge bc.
    let wa = qb_ab * qc_ac - qc_ab * qb_ac;
    let (from_b, from_c) = (qb_ac - qb_ab, qc_ab - qc_ac);
    if wa <= 0.0 && from_b >= 0.0 && from_c >= 0.0 {
        return b + (c - b) * (from_b / (from_b + from_c));
    }
    // Face: barycentric weights (wa, wb, wc) / sum.
    let inv = 1.0 / (wa + wb + wc);
    a + ab * (wb * inv) + ac * (wc * inv)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::rng::Rng;

    /// An independent reference: the plane projection when it falls inside the triangle (signs of
    /// the sub-triangle normals), else the nearest of the three edges.
    fn reference(q: DVec3, [a, b, c]: [DVec3; 3]) -> DVec3 {
        let n = (b - a).cross(c - a);
        let edges = [
            closest_point_on_segment(q, a, b),
            closest_point_on_segment(q, b, c),
            closest_point_on_segment(q, c, a),
        ];
        let best_edge = edges
            .into_iter()
            .min_by(|x, y| q.distance_squared(*x).total_cmp(&q.distance_squared(*y)))
            .unwrap();
        if n.length_squared() == 0.0 {
            return best_edge;
        }
        let p = q - n * ((q - a).dot(n) / n.length_squared());
        let inside = [(a, b), (b, c), (c, a)]
            .iter()
            .all(|&(u, v)| (v - u).cross(p - u).dot(n) >= 0.0);
        if inside { p } else { best_edge }
    }

    fn random_point(rng: &mut Rng, scale: f64) -> DVec3 {
        DVec3::new(rng.signed(), rng.signed(), rng.signed()) * scale
    }

    #[test]
    fn agrees_with_the_reference_on_random_triangles() {
        let mut rng = Rng::new(7);
        for case in 0..20_000 {
            let tri = [0; 3].map(|_| random_point(&mut rng, 1.0));
            // Queries near the triangle and far from it, so every region is hit.
            let q = random_point(&mut rng, if case % 2 == 0 { 1.5 } else { 20.0 });
            let p = closest_point_on_triangle(q, tri);
            let r = reference(q, tri);
            let scale = 1.0 + q.length();
            assert!(
                (q.distance(p) - q.distance(r)).abs() <= 1e-12 * scale,
                "case {case}: {tri:?} q={q} got {p} want {r}"
            );
            assert!(p.distance(r) <= 1e-9 * scale, "case {case}: {p} vs {r}");
        }
    }

    #[test]
    fn no_point_of_the_triangle_is_nearer() {
        let mut rng = Rng::new(11);
        for _ in 0..300 {
            let tri = [0; 3].map(|_| random_point(&mut rng, 1.0));
            let q = random_point(&mut rng, 2.0);
            let d = q.distance(closest_point_on_triangle(q, tri));
            let n = 40;
            for i in 0..=n {
                for j in 0..=n - i {
                    let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                    let s = tri[0] + (tri[1] - tri[0]) * u + (tri[2] - tri[0]) * v;
                    assert!(d <= q.distance(s) + 1e-12);
                }
            }
        }
    }

    #[test]
    fn regions_give_the_expected_points() {
        let tri = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let cases = [
            (DVec3::new(0.25, 0.25, 3.0), DVec3::new(0.25, 0.25, 0.0)),
            (DVec3::new(-1.0, -1.0, 1.0), DVec3::ZERO),
            (DVec3::new(2.0, -0.5, 0.0), DVec3::X),
            (DVec3::new(-0.5, 3.0, 0.0), DVec3::Y),
            (DVec3::new(0.5, -2.0, 1.0), DVec3::new(0.5, 0.0, 0.0)),
            (DVec3::new(-2.0, 0.5, 0.0), DVec3::new(0.0, 0.5, 0.0)),
            (DVec3::new(1.0, 1.0, -1.0), DVec3::new(0.5, 0.5, 0.0)),
        ];
        for (q, want) in cases {
            assert!(
                closest_point_on_triangle(q, tri).distance(want) < 1e-15,
                "{q}"
            );
        }
    }

    #[test]
    fn degenerate_triangles_use_their_edges() {
        let line = [DVec3::ZERO, DVec3::X, DVec3::X * 2.0];
        let p = closest_point_on_triangle(DVec3::new(1.5, 1.0, 0.0), line);
        assert!(p.distance(DVec3::new(1.5, 0.0, 0.0)) < 1e-15);
        let point = [DVec3::ONE; 3];
        assert_eq!(closest_point_on_triangle(DVec3::ZERO, point), DVec3::ONE);
    }
}
