//! Curve tests: de Casteljau against the Bernstein form, exact NURBS circles, B-splines against
//! Bézier curves, Hermite end conditions, interpolation, derivatives against finite differences,
//! and closest points against brute-force dense sampling.

use super::*;
use crate::primitive::conformance::Rng;
use glam::DVec3;
use std::f64::consts::PI;

fn random_points(rng: &mut Rng, n: usize) -> Vec<DVec3> {
    (0..n).map(|_| rng.vec(2.0)).collect()
}

fn params(curve: &impl Curve3, n: usize) -> impl Iterator<Item = f64> {
    let (t0, t1) = curve.domain();
    (0..=n).map(move |i| t0 + (t1 - t0) * i as f64 / n as f64)
}

/// Checks the jet against central differences of points and first derivatives.
fn check_derivatives(curve: &impl Curve3, tolerance: f64) {
    let (t0, t1) = curve.domain();
    let h = 1e-6 * (t1 - t0);
    for t in params(curve, 97).skip(1).take(96) {
        let j = curve.jet(t);
        let fd1 = (curve.point(t + h) - curve.point(t - h)) / (2.0 * h);
        let fd2 = (curve.derivative(t + h) - curve.derivative(t - h)) / (2.0 * h);
        let scale = 1.0 + j.d1.length() + j.d2.length();
        assert!(
            (j.d1 - fd1).length() < tolerance * scale,
            "C' at {t}: {} vs {fd1}",
            j.d1
        );
        assert!(
            (j.d2 - fd2).length() < tolerance * scale,
            "C'' at {t}: {} vs {fd2}",
            j.d2
        );
    }
}

#[test]
fn de_casteljau_agrees_with_bernstein() {
    let mut rng = Rng::new(11);
    for degree in 0..=20 {
        let curve = Bezier::new(random_points(&mut rng, degree + 1)).unwrap();
        for t in params(&curve, 200) {
            let d = (curve.de_casteljau(t) - curve.bernstein(t)).length();
            assert!(d <= 1e-12, "degree {degree}, t {t}: {d}");
        }
    }
}

#[test]
fn bezier_interpolates_its_ends_and_derivatives_match_the_hodograph() {
    let mut rng = Rng::new(12);
    for degree in 1..=18 {
        let pts = random_points(&mut rng, degree + 1);
        let curve = Bezier::new(pts.clone()).unwrap();
        assert_eq!(curve.point(0.0), pts[0]);
        assert!((curve.point(1.0) - pts[degree]).length() < 1e-15);
        let hodograph = curve.hodograph();
        for t in params(&curve, 50) {
            assert!((curve.derivative(t) - hodograph.point(t)).length() < 1e-10);
            assert!((curve.jet(t).d2 - hodograph.derivative(t)).length() < 1e-8);
        }
        check_derivatives(&curve, 1e-5);
    }
}

#[test]
fn split_halves_trace_the_curve() {
    let mut rng = Rng::new(13);
    let curve = Bezier::new(random_points(&mut rng, 7)).unwrap();
    let (left, right) = curve.split(0.3);
    for u in params(&left, 40) {
        assert!((left.point(u) - curve.point(0.3 * u)).length() < 1e-13);
        assert!((right.point(u) - curve.point(0.3 + 0.7 * u)).length() < 1e-13);
    }
}

#[test]
fn nurbs_quarter_circle_lies_on_the_unit_circle() {
    let arc = Nurbs::quarter_circle(1.0).unwrap();
    for t in params(&arc, 1000) {
        let p = arc.point(t);
        assert!(
            (p.length() - 1.0).abs() <= 1e-12,
            "|C({t})| = {}",
            p.length()
        );
        assert_eq!(p.z, 0.0);
        // The derivative is tangent to the circle.
        assert!(arc.derivative(t).dot(p).abs() < 1e-12);
    }
    assert_eq!(arc.point(0.0), DVec3::X);
    assert!((arc.point(1.0) - DVec3::Y).length() < 1e-15);
    check_derivatives(&arc, 1e-5);
}

#[test]
fn nurbs_full_circle_is_exact_and_closed() {
    let c = DVec3::new(0.5, -1.0, 2.0);
    let circle = Nurbs::circle(c, 2.5).unwrap();
    assert_eq!(circle.domain(), (0.0, 4.0));
    for t in params(&circle, 4000) {
        assert!(((circle.point(t) - c).length() - 2.5).abs() <= 1e-12);
    }
    assert!(Curve::Nurbs(circle.clone()).is_closed());
    check_derivatives(&circle, 1e-5);
    // Arc length is the circumference.
    assert!((arc_length(&circle) - 2.0 * PI * 2.5).abs() < 1e-11);
}

#[test]
fn clamped_bspline_with_degree_plus_one_points_is_the_bezier_curve() {
    let mut rng = Rng::new(14);
    for degree in 1..=9 {
        let pts = random_points(&mut rng, degree + 1);
        let spline = BSpline::clamped(degree, pts.clone()).unwrap();
        let bezier = Bezier::new(pts).unwrap();
        assert_eq!(spline.domain(), (0.0, 1.0));
        for t in params(&spline, 100) {
            assert!((spline.point(t) - bezier.point(t)).length() <= 1e-12);
            assert!((spline.derivative(t) - bezier.derivative(t)).length() <= 1e-10);
        }
    }
}

#[test]
fn bspline_derivatives_and_pieces_agree_with_de_boor() {
    let mut rng = Rng::new(15);
    let pts = random_points(&mut rng, 9);
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.5, 1.25, 1.25, 2.0, 3.5, 4.0, 4.0, 4.0, 4.0,
    ];
    let curves = [
        BSpline::new(3, pts.clone(), knots).unwrap(),
        BSpline::uniform(3, pts.clone()).unwrap(),
        BSpline::clamped(2, pts.clone()).unwrap(),
        BSpline::periodic(3, pts.clone()).unwrap(),
    ];
    for curve in &curves {
        check_derivatives(curve, 1e-5);
        for piece in curve.pieces() {
            for k in 0..=10 {
                let t = piece.t0 + (piece.t1 - piece.t0) * k as f64 / 10.0;
                assert!((piece.point(t) - curve.point(t)).length() < 1e-12);
            }
        }
    }
    // The clamped curve interpolates its end points; the periodic one closes.
    assert!((curves[2].point(curves[2].domain().1) - pts[8]).length() < 1e-14);
    assert!(Curve::BSpline(curves[3].clone()).is_closed());
    // A uniform cubic at an interior knot: (P₀ + 4P₁ + P₂) / 6.
    let u = &curves[1];
    assert!((u.point(3.0) - (pts[0] + pts[1] * 4.0 + pts[2]) / 6.0).length() < 1e-14);
}

#[test]
fn nurbs_with_unit_weights_is_the_bspline() {
    let mut rng = Rng::new(16);
    let pts = random_points(&mut rng, 6);
    let b = BSpline::clamped(3, pts.clone()).unwrap();
    let n = Nurbs::clamped(3, pts, vec![1.0; 6]).unwrap();
    for t in params(&b, 60) {
        assert!((b.point(t) - n.point(t)).length() < 1e-14);
    }
    let weighted = Nurbs::new(
        3,
        random_points(&mut rng, 6),
        vec![1.0, 2.0, 0.5, 3.0, 1.0, 0.7],
        vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.6, 1.0, 1.0, 1.0, 1.0],
    )
    .unwrap();
    check_derivatives(&weighted, 1e-5);
}

#[test]
fn hermite_meets_its_end_conditions() {
    let (p0, m0) = (DVec3::new(-1.0, 0.5, 0.0), DVec3::new(2.0, 3.0, -1.0));
    let (p1, m1) = (DVec3::new(1.0, 1.0, 2.0), DVec3::new(0.0, -4.0, 1.0));
    let h = Hermite::new(p0, m0, p1, m1).unwrap();
    let (start, end) = (h.jet(0.0), h.jet(1.0));
    assert_eq!((start.point, start.d1), (p0, m0));
    assert_eq!((end.point, end.d1), (p1, m1));
    let bezier = Bezier::new(h.bezier_points(0).to_vec()).unwrap();
    for t in params(&h, 50) {
        assert!((h.point(t) - bezier.point(t)).length() < 1e-14);
    }
    check_derivatives(&h, 1e-5);
}

#[test]
fn interpolating_spline_passes_through_its_points_with_c2_joints() {
    let mut rng = Rng::new(17);
    let pts = random_points(&mut rng, 7);
    for closed in [false, true] {
        let s = Interpolating::new(pts.clone(), closed).unwrap();
        for (i, p) in pts.iter().enumerate() {
            assert!((s.point(i as f64) - *p).length() < 1e-14);
        }
        // Second derivatives agree from both sides of every interior joint.
        let joints = if closed {
            1..pts.len()
        } else {
            1..pts.len() - 1
        };
        for i in joints {
            let left = s.pieces()[i - 1].jet(i as f64).d2;
            let right = s.pieces()[i].jet(i as f64).d2;
            assert!(
                (left - right).length() < 1e-11,
                "joint {i}: {left} vs {right}"
            );
        }
        if closed {
            let (a, b) = (s.pieces()[0].jet(0.0), s.pieces()[6].jet(7.0));
            assert!((a.point - b.point).length() < 1e-14);
            assert!((a.d1 - b.d1).length() < 1e-12 && (a.d2 - b.d2).length() < 1e-11);
        } else {
            // Natural ends.
            assert!(s.jet(0.0).d2.length() < 1e-12 && s.jet(6.0).d2.length() < 1e-12);
        }
        check_derivatives(&s, 1e-5);
    }
}

#[test]
fn invalid_curves_are_reported_with_their_key() {
    let pts = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
    let e = BSpline::new(3, pts.clone(), vec![0.0; 7]).unwrap_err();
    assert_eq!(e.parameter(), "degree");
    let e = BSpline::new(2, pts.clone(), vec![0.0, 0.0, 1.0, 0.5, 1.0, 1.0]).unwrap_err();
    assert_eq!(e, CurveError::KnotsDecreasing { index: 3 });
    let e = BSpline::new(2, pts.clone(), vec![0.0; 6]).unwrap_err();
    assert_eq!(e.parameter(), "knots");
    let e = Nurbs::clamped(2, pts.clone(), vec![1.0, 0.0, 1.0]).unwrap_err();
    assert_eq!(e, CurveError::NonPositiveWeight { index: 1 });
    assert!(Bezier::new(vec![]).is_err());
    assert!(Bezier::new(vec![DVec3::new(f64::NAN, 0.0, 0.0)]).is_err());
    assert!(Interpolating::new(pts[..2].to_vec(), true).is_err());
}

/// Closest point by dense sampling then golden-section polishing of the best sample's
/// neighbourhood: an independent reference.
fn brute_force_distance(curve: &impl Curve3, p: DVec3) -> f64 {
    let n = 20_000;
    let (t0, t1) = curve.domain();
    let dt = (t1 - t0) / n as f64;
    let (mut best_i, mut best) = (0, f64::INFINITY);
    for i in 0..=n {
        let d = (curve.point(t0 + dt * i as f64) - p).length();
        if d < best {
            (best_i, best) = (i, d);
        }
    }
    let (mut a, mut b) = (
        (t0 + dt * (best_i as f64 - 1.0)).max(t0),
        (t0 + dt * (best_i as f64 + 1.0)).min(t1),
    );
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..100 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if (curve.point(c) - p).length() < (curve.point(d) - p).length() {
            b = d;
        } else {
            a = c;
        }
    }
    best.min((curve.point(0.5 * (a + b)) - p).length())
}

#[test]
fn closest_point_matches_brute_force_sampling() {
    let mut rng = Rng::new(18);
    let curves = [
        Curve::Bezier(Bezier::new(random_points(&mut rng, 6)).unwrap()),
        Curve::Hermite(
            Hermite::new(rng.vec(1.0), rng.vec(4.0), rng.vec(1.0), rng.vec(4.0)).unwrap(),
        ),
        Curve::BSpline(BSpline::clamped(3, random_points(&mut rng, 10)).unwrap()),
        Curve::Nurbs(Nurbs::circle(DVec3::new(0.2, 0.1, 0.0), 1.3).unwrap()),
        Curve::Interpolating(Interpolating::new(random_points(&mut rng, 8), true).unwrap()),
    ];
    for curve in &curves {
        let index = CurveIndex::new(curve);
        for _ in 0..300 {
            let p = rng.vec(3.0);
            let c = index.closest(p);
            let reference = brute_force_distance(curve, p);
            assert!(
                c.distance <= reference + 1e-12 && c.distance >= reference - 1e-9,
                "{}: {} vs brute force {reference} at {p}",
                curve.name(),
                c.distance
            );
            assert!((curve.point(c.t) - c.point).length() < 1e-12);
            assert!(((c.point - p).length() - c.distance).abs() < 1e-12);
        }
    }
}
