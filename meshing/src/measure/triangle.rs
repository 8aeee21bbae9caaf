//! Nearest points on triangles and segments, for the distance measures: the kernel's exact
//! Voronoi-region computation (`solidkit_kernel::closest`), re-exported here.

pub use solidkit_kernel::closest::{closest_point_on_segment, closest_point_on_triangle};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::rng::Rng;
    use glam::DVec3;

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
