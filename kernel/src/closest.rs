//! The exact point of a triangle (or segment) nearest to a query point: shared by the mesh
//! solid's distance queries and the meshing crate's distance measures.
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
