//! Profile tests: exact distances against brute-force boundary sampling, the even-odd rule,
//! areas and centroids, and cap triangulations covering the region exactly.

use super::*;
use crate::primitive::conformance::Rng;
use glam::DVec2;

fn square(c: DVec2, h: f64) -> Vec<DVec2> {
    vec![
        c + DVec2::new(-h, -h),
        c + DVec2::new(h, -h),
        c + DVec2::new(h, h),
        c + DVec2::new(-h, h),
    ]
}

/// Unsigned distance to the boundary loops by dense sampling of every edge.
fn sampled_boundary_distance(loops: &[Vec<DVec2>], q: DVec2) -> f64 {
    let mut best = f64::INFINITY;
    for l in loops {
        for i in 0..l.len() {
            let (a, b) = (l[i], l[(i + 1) % l.len()]);
            for k in 0..=2000 {
                best = best.min((a.lerp(b, k as f64 / 2000.0) - q).length());
            }
        }
    }
    best
}

#[test]
fn polygon_distance_is_exact_and_signed_by_even_odd() {
    let outer = vec![
        DVec2::new(-1.0, -1.0),
        DVec2::new(1.5, -0.8),
        DVec2::new(1.0, 1.2),
        DVec2::new(0.0, 0.4),
        DVec2::new(-1.2, 1.0),
    ];
    let hole = square(DVec2::new(0.2, -0.3), 0.25);
    let p = Profile::polygon(outer.clone(), vec![hole.clone()]).unwrap();
    let loops = vec![outer.clone(), hole.clone()];
    let mut rng = Rng::new(21);
    for _ in 0..400 {
        let q = DVec2::new(rng.next(), rng.next()) * 2.0;
        let (d, g) = p.distance_gradient(q);
        let reference = sampled_boundary_distance(&loops, q);
        assert!(
            (d.abs() - reference).abs() < 2e-3,
            "{d} vs {reference} at {q}"
        );
        let inside = polygon::inside_loop(q, &outer) && !polygon::inside_loop(q, &hole);
        assert_eq!(d < 0.0, inside, "sign at {q}");
        assert!((g.length() - 1.0).abs() < 1e-12);
        // The gradient points away from the nearest boundary point.
        let h = 1e-7;
        let fd = DVec2::new(
            p.distance(q + DVec2::X * h) - p.distance(q - DVec2::X * h),
            p.distance(q + DVec2::Y * h) - p.distance(q - DVec2::Y * h),
        ) / (2.0 * h);
        assert!(
            (fd - g).length() < 1e-5 || (fd.length() - 1.0).abs() > 1e-3,
            "{fd} vs {g}"
        );
    }
}

#[test]
fn circle_and_rectangle_match_their_polygon_forms() {
    let r = Profile::Rectangle(Rectangle {
        center: DVec2::new(0.3, -0.1),
        size: DVec2::new(1.2, 0.5),
    });
    let corners = match &r {
        Profile::Rectangle(x) => x.corners().to_vec(),
        _ => unreachable!(),
    };
    let poly = Profile::polygon(corners, vec![]).unwrap();
    let mut rng = Rng::new(22);
    for _ in 0..500 {
        let q = DVec2::new(rng.next(), rng.next()) * 1.5;
        assert!((r.distance(q) - poly.distance(q)).abs() < 1e-12);
        let c = Profile::circle(0.7).unwrap();
        assert!((c.distance(q) - (q.length() - 0.7)).abs() < 1e-15);
    }
}

#[test]
fn areas_and_centroids() {
    let p = Profile::polygon(
        square(DVec2::ZERO, 1.0),
        vec![square(DVec2::new(0.5, 0.5), 0.25)],
    )
    .unwrap();
    let (a, c) = p.area_centroid();
    assert!((a - (4.0 - 0.25)).abs() < 1e-14);
    // Moment of the hole removed from the square's (zero) moment.
    let expected = -(DVec2::new(0.5, 0.5) * 0.25) / 3.75;
    assert!((c - expected).length() < 1e-14);
    assert_eq!(Profile::circle(2.0).unwrap().radius(), 2.0);
    let rect = Profile::rectangle(DVec2::new(2.0, 4.0)).unwrap();
    assert!((rect.radius() - 5f64.sqrt()).abs() < 1e-15);
}

fn triangle_area(pts: &[DVec2], t: &[u32; 3]) -> f64 {
    let [a, b, c] = t.map(|i| pts[i as usize]);
    0.5 * (b - a).perp_dot(c - a)
}

#[test]
fn triangulation_covers_the_region_with_the_expected_count() {
    let outer = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(4.0, 0.0),
        DVec2::new(4.0, 3.0),
        DVec2::new(2.0, 1.5),
        DVec2::new(0.0, 3.0),
    ];
    // Clockwise outline and counter-clockwise holes: the orientation does not matter.
    let mut cw = outer.clone();
    cw.reverse();
    let holes = vec![
        square(DVec2::new(1.0, 0.8), 0.3),
        square(DVec2::new(3.0, 0.8), 0.4),
    ];
    let loops: Vec<Vec<DVec2>> = std::iter::once(cw).chain(holes.iter().cloned()).collect();
    let tris = triangulate(&loops).unwrap();
    let pts: Vec<DVec2> = loops.iter().flatten().copied().collect();
    assert_eq!(tris.len(), pts.len() + 2 * holes.len() - 2);
    let total: f64 = tris.iter().map(|t| triangle_area(&pts, t)).sum();
    let p = Profile::polygon(outer, holes).unwrap();
    assert!((total - p.area_centroid().0).abs() < 1e-12, "{total}");
    assert!(tris.iter().all(|t| triangle_area(&pts, t) > 0.0));
    // Every triangle's centroid is inside the region.
    for t in &tris {
        let c = t.iter().map(|&i| pts[i as usize]).sum::<DVec2>() / 3.0;
        assert!(p.distance(c) < 0.0);
    }
}

#[test]
fn triangulation_follows_the_even_odd_rule_for_nested_and_separate_loops() {
    // An outline with a hole holding an island, and a second outline beside it.
    let loops = vec![
        square(DVec2::ZERO, 2.0),
        square(DVec2::ZERO, 1.0),
        square(DVec2::ZERO, 0.5),
        square(DVec2::new(4.0, 0.0), 1.0),
    ];
    let tris = triangulate(&loops).unwrap();
    // Outline with one hole: 8 + 2 − 2; island and separate square: 4 − 2 each.
    assert_eq!(tris.len(), 8 + 2 + 2);
    let pts: Vec<DVec2> = loops.iter().flatten().copied().collect();
    assert!(tris.iter().all(|t| triangle_area(&pts, t) > 0.0));
    let total: f64 = tris.iter().map(|t| triangle_area(&pts, t)).sum();
    assert!((total - (16.0 - 4.0 + 1.0 + 4.0)).abs() < 1e-12, "{total}");
    let p = Profile::polygon(loops[0].clone(), loops[1..].to_vec()).unwrap();
    for t in &tris {
        let c = t.iter().map(|&i| pts[i as usize]).sum::<DVec2>() / 3.0;
        assert!(p.distance(c) < 0.0, "{c}");
    }
}

#[test]
fn crossing_loops_cannot_be_triangulated() {
    let loops = vec![square(DVec2::ZERO, 1.0), square(DVec2::new(0.9, 0.0), 0.5)];
    let e = triangulate(&loops).unwrap_err();
    assert_eq!(
        e,
        ProfileError::Triangulation {
            problem: crate::triangulate::TriangulationError::SelfIntersecting
        }
    );
    assert_eq!(e.parameter(), "points");
    let e = triangulate(&[square(DVec2::ZERO, 1.0), vec![DVec2::ZERO]]).unwrap_err();
    assert_eq!(
        e,
        ProfileError::Triangulation {
            problem: crate::triangulate::TriangulationError::TooFewCorners(1)
        }
    );
}

#[test]
fn invalid_profiles_name_their_key() {
    assert_eq!(Profile::circle(0.0).unwrap_err().parameter(), "radius");
    assert_eq!(
        Profile::rectangle(DVec2::new(1.0, f64::NAN))
            .unwrap_err()
            .parameter(),
        "size"
    );
    let e = Profile::polygon(vec![DVec2::ZERO, DVec2::X], vec![]).unwrap_err();
    assert_eq!(
        e,
        ProfileError::TooFewPoints {
            parameter: "points",
            found: 2
        }
    );
    let e = Profile::polygon(
        square(DVec2::ZERO, 1.0),
        vec![vec![DVec2::ZERO, DVec2::X, DVec2::X * 2.0]],
    );
    assert_eq!(e.unwrap_err().parameter(), "holes");
}

/// `n` corners of a wavy star around `c` (many edges, concave), counter-clockwise.
fn star(c: DVec2, r: f64, n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            c + DVec2::new(t.cos(), t.sin()) * r * (1.0 + 0.3 * (7.0 * t).cos())
        })
        .collect()
}

fn same_nearest(a: polygon::Nearest, b: polygon::Nearest, q: DVec2) {
    assert_eq!(a.distance.to_bits(), b.distance.to_bits(), "{q}");
    assert_eq!(a.gradient, b.gradient, "{q}");
    assert_eq!((a.ring, a.edge), (b.ring, b.edge), "{q}");
    assert_eq!(a.lambda.to_bits(), b.lambda.to_bits(), "{q}");
}

#[test]
fn the_edge_index_answers_exactly_as_the_plain_loop() {
    // A wavy outline with a wavy hole and a square hole: 2000 + 300 + 4 edges.
    let p = Polygon::new(
        star(DVec2::ZERO, 2.0, 2000),
        vec![
            star(DVec2::new(0.3, 0.1), 0.5, 300),
            square(DVec2::new(-1.0, 0.4), 0.2),
        ],
    )
    .unwrap();
    assert!(p.index.is_some());
    let mut rng = Rng::new(61);
    for _ in 0..20000 {
        let q = DVec2::new(rng.next(), rng.next()) * 3.5;
        same_nearest(p.nearest(q), p.nearest_plain(q), q);
    }
    // On corners, on edges, and on the crossing rays of corners (parity ties).
    for l in p.loops() {
        for (i, &c) in l.iter().enumerate().step_by(7) {
            let d = l[(i + 1) % l.len()];
            for q in [c, c.lerp(d, 0.5), c + DVec2::new(0.25, 0.0), c - DVec2::X] {
                same_nearest(p.nearest(q), p.nearest_plain(q), q);
            }
        }
    }
}

#[test]
fn the_edge_index_breaks_ties_as_the_plain_loop() {
    // A staircase on the unit lattice: many points at equal distances from several edges.
    let mut outline = vec![DVec2::new(0.0, 0.0)];
    for k in 0..40 {
        let k = k as f64;
        outline.push(DVec2::new(k + 1.0, k));
        outline.push(DVec2::new(k + 1.0, k + 1.0));
    }
    outline.push(DVec2::new(0.0, 40.0));
    let p = Polygon::new(outline, vec![]).unwrap();
    assert!(p.index.is_some());
    for i in -4..=180 {
        for j in -4..=180 {
            let q = DVec2::new(i as f64, j as f64) * 0.25;
            same_nearest(p.nearest(q), p.nearest_plain(q), q);
            let (a, b) = (
                p.distance_gradient_off_axis(q),
                loops_distance_skipping_plain(&p, q),
            );
            assert_eq!(a, b, "{q}");
        }
    }
}

/// The revolve's off-axis distance by the plain loop.
fn loops_distance_skipping_plain(p: &Polygon, q: DVec2) -> (f64, DVec2) {
    let n = polygon::loops_distance_skipping(
        q,
        p.loops().len(),
        |r| p.loops()[r].len(),
        |r, i| p.loops()[r][i],
        |a, b| a.x == 0.0 && b.x == 0.0,
    );
    (n.distance, n.gradient)
}
