//! The curve examples of the lecture notes with their own numbers: the quadratic Bézier curve at
//! u = 0.3, the cubic Bézier curve's closed form, de Casteljau midpoint subdivision, the Hermite
//! basis and composite Hermite curves, the interpolating cubic through four points at u = k/3,
//! the uniform cubic B-spline's start `(P0 + 4P1 + P2)/6`, the rational quarter circle, the rose
//! curve with its derivative; plus composite continuity checks and certified polylines.

use super::flatten::segment_distance;
use super::*;
use glam::{DVec3, dvec3};

fn p2(x: f64, y: f64) -> DVec3 {
    dvec3(x, y, 0.0)
}

fn close(a: DVec3, b: DVec3, tol: f64) -> bool {
    (a - b).length() <= tol
}

#[test]
fn quadratic_bezier_at_0_3() {
    // Control points (0, -1), (1, 2), (5, -1); c(u) = (1-u)²P0 + 2u(1-u)P1 + u²P2.
    let pts = vec![p2(0.0, -1.0), p2(1.0, 2.0), p2(5.0, -1.0)];
    let b = Bezier::new(pts.clone()).unwrap();
    let u: f64 = 0.3;
    let formula = pts[0] * (1.0 - u).powi(2) + pts[1] * (2.0 * u * (1.0 - u)) + pts[2] * u * u;
    assert!(close(b.point(u), formula, 1e-15));
    // By hand: 0.49·(0,-1) + 0.42·(1,2) + 0.09·(5,-1) = (0.87, 0.26).
    assert!(close(b.point(u), p2(0.87, 0.26), 1e-14), "{}", b.point(u));
    // Only the end points are interpolated; the curve stays in the control triangle's box.
    assert!(close(b.point(0.0), pts[0], 0.0) && close(b.point(1.0), pts[2], 0.0));
    assert!(!(0..=100).any(|i| close(b.point(i as f64 / 100.0), pts[1], 1e-3)));
}

#[test]
fn cubic_bezier_closed_form() {
    // (-2, 2), (0, -3), (3, 4), (7, 0): the notes expand
    // c(u) = (-2(1-u)³ + 9(1-u)u² + 7u³, 2(1-u)³ - 9(1-u)²u + 12(1-u)u²).
    let b = Bezier::new(vec![
        p2(-2.0, 2.0),
        p2(0.0, -3.0),
        p2(3.0, 4.0),
        p2(7.0, 0.0),
    ])
    .unwrap();
    for i in 0..=20 {
        let u = i as f64 / 20.0;
        let v = 1.0 - u;
        let x = -2.0 * v.powi(3) + 9.0 * v * u * u + 7.0 * u.powi(3);
        let y = 2.0 * v.powi(3) - 9.0 * v * v * u + 12.0 * v * u * u;
        assert!(close(b.point(u), p2(x, y), 1e-13), "u = {u}");
        assert!(close(b.bernstein(u), p2(x, y), 1e-13));
    }
    // Tangents at the ends along the first and last legs: C'(0) = 3(P1 - P0).
    assert!(close(b.derivative(0.0), p2(6.0, -15.0), 1e-13));
    assert!(close(b.derivative(1.0), p2(12.0, -12.0), 1e-13));
}

#[test]
fn de_casteljau_midpoint_subdivision() {
    let pts = [p2(-2.0, 2.0), p2(0.0, -3.0), p2(3.0, 4.0), p2(7.0, 0.0)];
    let b = Bezier::new(pts.to_vec()).unwrap();
    let (l, r) = b.split(0.5);
    // The notes' construction: M01, M12, M23, then M012, M123, then M0123.
    let m = |a: DVec3, b: DVec3| (a + b) / 2.0;
    let (m01, m12, m23) = (m(pts[0], pts[1]), m(pts[1], pts[2]), m(pts[2], pts[3]));
    let (m012, m123) = (m(m01, m12), m(m12, m23));
    let m0123 = m(m012, m123);
    assert_eq!(l.points(), &[pts[0], m01, m012, m0123]);
    assert_eq!(r.points(), &[m0123, m123, m23, pts[3]]);
    // The two halves trace the curve exactly.
    for i in 0..=16 {
        let s = i as f64 / 16.0;
        assert!(close(l.point(s), b.point(s / 2.0), 1e-13));
        assert!(close(r.point(s), b.point(0.5 + s / 2.0), 1e-13));
    }
}

#[test]
fn hermite_basis_and_composite() {
    for i in 0..=10 {
        let t = i as f64 / 10.0;
        let [h00, h10, h01, h11] = hermite_basis(t);
        assert!(
            (h00 + h01 - 1.0).abs() < 1e-15,
            "positions' weights sum to 1"
        );
        assert!((h00 - (2.0 * t.powi(3) - 3.0 * t * t + 1.0)).abs() < 1e-15);
        assert!((h10 - (t.powi(3) - 2.0 * t * t + t)).abs() < 1e-15);
        assert!((h11 - (t.powi(3) - t * t)).abs() < 1e-15);
    }
    assert_eq!(hermite_basis(0.0), [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(hermite_basis(1.0), [0.0, 0.0, 1.0, 0.0]);
    // The notes' Hermite example, then a three-segment chain: C¹ at every joint by construction.
    let pts = vec![
        p2(-0.204993, -0.961681),
        p2(0.832718, -0.185615),
        p2(1.5, 0.5),
        p2(2.0, -1.0),
    ];
    let tans = vec![
        p2(-0.128653, 1.718201),
        p2(1.006077, -1.378944),
        p2(0.0, 1.0),
        p2(1.0, 1.0),
    ];
    let h = Hermite::through(pts.clone(), tans.clone()).unwrap();
    assert_eq!(h.domain(), (0.0, 3.0));
    for (i, (p, m)) in pts.iter().zip(&tans).enumerate() {
        let j = h.jet(i as f64);
        assert!(
            close(j.point, *p, 1e-14) && close(j.d1, *m, 1e-13),
            "point {i}"
        );
    }
    let e = 1e-9;
    for k in 1..3 {
        let (a, b) = (h.derivative(k as f64 - e), h.derivative(k as f64 + e));
        assert!(close(a, b, 1e-7), "C¹ at {k}");
    }
    assert!(Hermite::through(pts, tans[..3].to_vec()).is_err());
}

#[test]
fn cubic_through_four_points_at_thirds() {
    // The notes' example: P = (0,0), (1,0), (1,1), (0,1) gives
    // x(u) = 4.5u − 4.5u², y(u) = −3.5u + 13.5u² − 9u³.
    let pts = [p2(0.0, 0.0), p2(1.0, 0.0), p2(1.0, 1.0), p2(0.0, 1.0)];
    let c = CubicThrough::new(&pts).unwrap();
    let [c0, c1, c2, c3] = c.coefficients();
    assert!(close(c0, p2(0.0, 0.0), 1e-15));
    assert!(close(c1, p2(4.5, -3.5), 1e-14));
    assert!(close(c2, p2(-4.5, 13.5), 1e-14));
    assert!(close(c3, p2(0.0, -9.0), 1e-14));
    for (k, p) in pts.iter().enumerate() {
        assert!(close(c.point(k as f64 / 3.0), *p, 1e-14), "through P{k}");
    }
    for i in 0..=12 {
        let u = i as f64 / 12.0;
        let power = c0 + c1 * u + c2 * u * u + c3 * u * u * u;
        assert!(close(c.point(u), power, 1e-13));
    }
    // The notes' second example passes through its points too.
    let pts2 = [p2(-1.5, 0.0), p2(0.25, 1.0), p2(0.75, -1.0), p2(1.5, 0.0)];
    let c = CubicThrough::new(&pts2).unwrap();
    for (k, p) in pts2.iter().enumerate() {
        assert!(close(c.point(k as f64 / 3.0), *p, 1e-14));
    }
    assert!(CubicThrough::new(&pts2[..3]).is_err());
}

#[test]
fn uniform_cubic_bspline_starts_at_one_four_one() {
    // The notes' B-spline example.
    let pts = vec![
        p2(-1.551545, 1.055903),
        p2(-0.490358, -0.738666),
        p2(0.238840, 0.988653),
        p2(1.269570, 0.369363),
    ];
    let b = BSpline::uniform(3, pts.clone()).unwrap();
    let (t0, t1) = b.domain();
    let start = (pts[0] + pts[1] * 4.0 + pts[2]) / 6.0;
    let end = (pts[1] + pts[2] * 4.0 + pts[3]) / 6.0;
    assert!(
        close(b.point(t0), start, 1e-14),
        "{} vs {start}",
        b.point(t0)
    );
    assert!(close(b.point(t1), end, 1e-14));
    // Tangent at the start: (P2 − P0)/2.
    assert!(close(b.derivative(t0), (pts[2] - pts[0]) / 2.0, 1e-13));
}

#[test]
fn rational_quarter_circle() {
    let q = Nurbs::quarter_circle(1.0).unwrap();
    for i in 0..=50 {
        let p = q.point(i as f64 / 50.0);
        assert!((p.length() - 1.0).abs() < 1e-14, "{p}");
        assert!(p.x >= -1e-15 && p.y >= -1e-15);
    }
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert!(close(q.point(0.5), p2(h, h), 1e-14));
    let length = Parametric::Curve(Curve::Nurbs(q)).arc_length();
    assert!(
        (length - std::f64::consts::FRAC_PI_2).abs() < 1e-12,
        "{length}"
    );
}

#[test]
fn rose_curve_and_its_derivative() {
    // x = cos(2u)cos(u), y = cos(2u)sin(u); the notes' u = 5.739995 with
    // dx/du = −2 sin(2u) cos(u) − cos(2u) sin(u), dy/du = −2 sin(2u) sin(u) + cos(2u) cos(u).
    let rose = FormulaCurve::new(
        ["cos(2*u)*cos(u)", "cos(2*u)*sin(u)", "0"],
        (0.0, std::f64::consts::TAU),
    )
    .unwrap();
    let u: f64 = 5.739995;
    let j = rose.jet(u);
    let point = p2((2.0 * u).cos() * u.cos(), (2.0 * u).cos() * u.sin());
    let d1 = p2(
        -2.0 * (2.0 * u).sin() * u.cos() - (2.0 * u).cos() * u.sin(),
        -2.0 * (2.0 * u).sin() * u.sin() + (2.0 * u).cos() * u.cos(),
    );
    assert!(close(j.point, point, 1e-15));
    assert!(close(j.d1, d1, 1e-14), "{} vs {d1}", j.d1);
    let h = 1e-5;
    let fd2 = (rose.jet(u + h).d1 - rose.jet(u - h).d1) / (2.0 * h);
    assert!(close(j.d2, fd2, 1e-8));
    // A four-petal rose: closed, and its length is 4 × the petal length (∫ √(1 + 3cos²2u) du).
    let rose = Parametric::Formula(rose);
    assert!(rose.is_closed());
    let rule = gauss_legendre(24);
    let exact: f64 = (0..256)
        .map(|i| {
            let (a, b) = (
                i as f64 * std::f64::consts::TAU / 256.0,
                (i + 1) as f64 * std::f64::consts::TAU / 256.0,
            );
            integrate(&rule, a, b, |t| {
                (1.0 + 3.0 * (2.0 * t).cos().powi(2)).sqrt()
            })
        })
        .sum();
    assert!((rose.arc_length() - exact).abs() < 1e-10 * exact);
    assert!(FormulaCurve::new(["cos(2*w)", "0", "0"], (0.0, 1.0)).is_err());
}

#[test]
fn composite_continuity_is_checked() {
    let a = Curve::Bezier(Bezier::new(vec![p2(0.0, 0.0), p2(1.0, 1.0), p2(2.0, 1.0)]).unwrap());
    // Starts where a ends with derivative 2·(1, 0): equal to a's end derivative 2·(1, 0): C¹.
    let b = Curve::Bezier(Bezier::new(vec![p2(2.0, 1.0), p2(3.0, 1.0), p2(4.0, 0.0)]).unwrap());
    // Same direction, twice the speed: G¹ but not C¹.
    let c = Curve::Bezier(Bezier::new(vec![p2(2.0, 1.0), p2(4.0, 1.0), p2(5.0, 0.0)]).unwrap());
    // A kink: C⁰ only.
    let d = Curve::Bezier(Bezier::new(vec![p2(2.0, 1.0), p2(3.0, 2.0), p2(4.0, 0.0)]).unwrap());
    let gap = Curve::Bezier(Bezier::new(vec![p2(2.0, 1.1), p2(3.0, 1.0)]).unwrap());
    use Continuity::*;
    let ok = |x: &Curve, j| Composite::new(vec![a.clone(), x.clone()], vec![j]).is_ok();
    assert!(ok(&b, C1) && ok(&b, G1) && ok(&b, C0));
    assert!(!ok(&c, C1) && ok(&c, G1));
    assert!(!ok(&d, G1) && !ok(&d, C1) && ok(&d, C0));
    assert!(!ok(&gap, C0));
    let err = Composite::new(vec![a.clone(), d], vec![G1]).unwrap_err();
    assert!(matches!(err, CurveError::Join { index: 1, .. }), "{err}");
    // The composite parameter runs over [0, 2]; the joint is at t = 1.
    let k = Composite::new(vec![a.clone(), b.clone()], vec![C1]).unwrap();
    assert!(close(k.point(1.0), p2(2.0, 1.0), 1e-15));
    assert!(close(k.point(1.5), b.point(0.5), 1e-15));
    assert_eq!(k.pieces().len(), 2);
    let nested = Composite::new(vec![Curve::Composite(k), a], vec![C0]);
    assert!(matches!(
        nested,
        Err(CurveError::NestedComposite { index: 0 })
    ));
}

#[test]
fn polylines_keep_the_chord_error_bound() {
    let curves = [
        Parametric::Curve(Curve::Nurbs(Nurbs::circle(DVec3::ZERO, 2.0).unwrap())),
        Parametric::Curve(Curve::Bezier(
            Bezier::new(vec![
                p2(-2.0, 2.0),
                p2(0.0, -3.0),
                p2(3.0, 4.0),
                p2(7.0, 0.0),
            ])
            .unwrap(),
        )),
        Parametric::Formula(
            FormulaCurve::new(["cos(2*u)*cos(u)", "cos(2*u)*sin(u)", "0"], (0.0, 6.3)).unwrap(),
        ),
    ];
    for curve in &curves {
        for tol in [1e-2, 1e-4] {
            let line = curve.polyline(tol).unwrap();
            assert!(line.params.windows(2).all(|w| w[0] < w[1]));
            let mut worst: f64 = 0.0;
            for (w, p) in line.params.windows(2).zip(line.points.windows(2)) {
                for i in 1..16 {
                    let q = curve.point(w[0] + (w[1] - w[0]) * i as f64 / 16.0);
                    worst = worst.max(segment_distance(q, p[0], p[1]));
                }
            }
            assert!(worst <= tol, "{}: {worst} > {tol}", curve.name());
            // And not wastefully fine: halving the tolerance adds points.
            assert!(worst > tol / 20.0, "{}: {worst} ≪ {tol}", curve.name());
        }
    }
}
