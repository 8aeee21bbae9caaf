//! Tests of the quadric family: conformance of every form, the classification table on canonical
//! forms and under rigid motions, the exact zero set, and the distance-like field near the surface.

use super::*;
use crate::primitive::conformance::{Rng, check_shape};
use crate::primitive::{Shape, Sphere};
use crate::{Aabb, Interval};
use glam::{DAffine3, DMat3, DQuat, DVec3};

fn cube(h: f64) -> Option<Aabb> {
    Some(Aabb::centered(DVec3::splat(h)))
}

fn coeffs(a: [f64; 10]) -> QuadricCoefficients {
    let [a, b, c, f, g, h, p, q, r, d] = a;
    QuadricCoefficients {
        a,
        b,
        c,
        f,
        g,
        h,
        p,
        q,
        r,
        d,
    }
}

fn random_motion(rng: &mut Rng) -> DAffine3 {
    let axis = rng.vec(1.0).try_normalize().unwrap_or(DVec3::X);
    DAffine3::from_rotation_translation(
        DQuat::from_axis_angle(axis, 3.0 * rng.next()),
        rng.vec(2.0),
    )
}

fn named_forms() -> Vec<QuadricForm> {
    vec![
        QuadricForm::EllipticCylinder { radii: [0.6, 0.9] },
        QuadricForm::EllipticCone { radii: [0.7, 0.4] },
        QuadricForm::EllipticParaboloid { radii: [0.8, 0.5] },
        QuadricForm::HyperbolicParaboloid { radii: [0.9, 1.1] },
        QuadricForm::HyperboloidOfOneSheet {
            radii: [0.5, 0.6, 0.8],
        },
        QuadricForm::HyperboloidOfTwoSheets {
            radii: [0.7, 0.6, 0.4],
        },
    ]
}

#[test]
fn ellipsoid_conforms() {
    check_shape(
        &Ellipsoid {
            radii: DVec3::new(0.5, 1.0, 0.8),
        },
        1.5,
    );
}

#[test]
fn ellipsoid_with_equal_radii_is_the_sphere() {
    let e = Ellipsoid {
        radii: DVec3::splat(0.7),
    };
    let s = Sphere { radius: 0.7 };
    let mut rng = Rng::new(5);
    for _ in 0..1000 {
        let p = rng.vec(1.5);
        assert!((e.value(p) - s.value(p)).abs() < 1e-12);
    }
}

#[test]
fn named_quadrics_conform_and_have_their_kind() {
    for form in named_forms() {
        let q = Quadric::new(form, cube(1.2)).expect("valid");
        assert_eq!(Some(q.kind()), form.named_kind(), "{form:?}");
        check_shape(&q, 1.6);
    }
}

#[test]
fn general_quadrics_conform() {
    let mut rng = Rng::new(3);
    for form in named_forms() {
        let moved = form
            .coefficients()
            .transformed(&random_motion(&mut rng))
            .unwrap();
        let q = Quadric::general(moved, cube(1.0)).unwrap();
        check_shape(&q, 1.4);
    }
    // A rotated ellipsoid from its coefficients alone (its box is derived), and a plane.
    let e = QuadricForm::General(coeffs([4.0, 1.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]));
    let m = random_motion(&mut rng);
    let q = Quadric::general(e.coefficients().transformed(&m).unwrap(), None).unwrap();
    assert_eq!(q.kind(), QuadricKind::Ellipsoid);
    check_shape(&q, 3.0);
    let plane = Quadric::general(
        coeffs([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -2.0, 0.5, 0.3]),
        cube(1.0),
    )
    .unwrap();
    assert_eq!((plane.kind(), plane.lipschitz()), (QuadricKind::Plane, 1.0));
    check_shape(&plane, 1.4);
}

#[test]
fn derived_ellipsoid_box_is_tight() {
    // (x−1)²/4 + (y+2)² + z²/9 ≤ 1.
    let c = coeffs([
        0.25,
        1.0,
        1.0 / 9.0,
        0.0,
        0.0,
        0.0,
        -0.25,
        2.0,
        0.0,
        0.25 + 4.0 - 1.0,
    ]);
    let q = Quadric::general(c, None).unwrap();
    let b = q.bbox();
    let want = Aabb::new(DVec3::new(-1.0, -3.0, -3.0), DVec3::new(3.0, -1.0, 3.0));
    assert!((b.min - want.min).abs().max_element() < 1e-6, "{b:?}");
    assert!((b.max - want.max).abs().max_element() < 1e-6, "{b:?}");
    // Given bounds cut the ellipsoid.
    let given = Aabb::new(DVec3::new(0.0, -10.0, 0.0), DVec3::splat(10.0));
    let cut = Quadric::general(c, Some(given)).unwrap();
    assert!((cut.bbox().min - DVec3::new(0.0, -3.0, 0.0)).length() < 1e-6);
    assert!(
        cut.value(DVec3::new(1.0, -2.0, -1.0)) > 0.0 && cut.value(DVec3::new(1.0, -2.0, 1.0)) < 0.0
    );
}

/// One representative per row of the classification table, in canonical form.
fn canonical_table() -> Vec<(QuadricKind, [f64; 10])> {
    use QuadricKind::*;
    vec![
        (Ellipsoid, [1.0, 2.0, 3.0, 0., 0., 0., 0., 0., 0., -1.0]),
        (
            ImaginaryEllipsoid,
            [1.0, 2.0, 3.0, 0., 0., 0., 0., 0., 0., 1.0],
        ),
        (
            HyperboloidOfOneSheet,
            [1.0, 2.0, -3.0, 0., 0., 0., 0., 0., 0., -1.0],
        ),
        (
            HyperboloidOfTwoSheets,
            [1.0, -2.0, -3.0, 0., 0., 0., 0., 0., 0., -1.0],
        ),
        (Cone, [1.0, 2.0, -3.0, 0., 0., 0., 0., 0., 0., 0.0]),
        (Point, [1.0, 2.0, 3.0, 0., 0., 0., 0., 0., 0., 0.0]),
        (
            EllipticParaboloid,
            [1.0, 2.0, 0.0, 0., 0., 0., 0., 0., -1.0, 0.0],
        ),
        (
            HyperbolicParaboloid,
            [1.0, -2.0, 0.0, 0., 0., 0., 0., 0., -1.0, 0.0],
        ),
        (
            EllipticCylinder,
            [1.0, 2.0, 0.0, 0., 0., 0., 0., 0., 0., -1.0],
        ),
        (
            ImaginaryEllipticCylinder,
            [1.0, 2.0, 0.0, 0., 0., 0., 0., 0., 0., 1.0],
        ),
        (
            HyperbolicCylinder,
            [1.0, -2.0, 0.0, 0., 0., 0., 0., 0., 0., -1.0],
        ),
        (
            IntersectingPlanes,
            [1.0, -2.0, 0.0, 0., 0., 0., 0., 0., 0., 0.0],
        ),
        (Line, [1.0, 2.0, 0.0, 0., 0., 0., 0., 0., 0., 0.0]),
        (
            ParabolicCylinder,
            [1.0, 0.0, 0.0, 0., 0., 0., 0., -1.0, 0.0, 0.0],
        ),
        (
            ParallelPlanes,
            [1.0, 0.0, 0.0, 0., 0., 0., 0., 0., 0., -1.0],
        ),
        (
            ImaginaryParallelPlanes,
            [1.0, 0.0, 0.0, 0., 0., 0., 0., 0., 0., 1.0],
        ),
        (
            CoincidentPlanes,
            [1.0, 0.0, 0.0, 0., 0., 0., 0., 0., 0., 0.0],
        ),
        (Plane, [0.0, 0.0, 0.0, 0., 0., 0., 1.0, 0.0, 0.0, -1.0]),
        (Constant, [0.0, 0.0, 0.0, 0., 0., 0., 0.0, 0.0, 0.0, 2.0]),
    ]
}

/// Rank and determinant sign of a small matrix by Gaussian elimination with full pivoting.
fn rank_and_det_sign(m: [[f64; 4]; 4]) -> (u8, i8) {
    let mut a = m;
    let mut rank = 0;
    let mut sign = 1.0;
    for col in 0..4 {
        let (mut best, mut bi, mut bj) = (0.0, col, col);
        for (i, row) in a.iter().enumerate().skip(col) {
            for (j, x) in row.iter().enumerate().skip(col) {
                if x.abs() > best {
                    (best, bi, bj) = (x.abs(), i, j);
                }
            }
        }
        if best < 1e-9 {
            break;
        }
        if bi != col {
            a.swap(bi, col);
            sign = -sign;
        }
        if bj != col {
            for row in a.iter_mut() {
                row.swap(bj, col);
            }
            sign = -sign;
        }
        sign *= a[col][col].signum();
        rank += 1;
        let pivot = a[col];
        for row in a.iter_mut().skip(col + 1) {
            let f = row[col] / pivot[col];
            for (x, p) in row.iter_mut().zip(pivot).skip(col) {
                *x -= f * p;
            }
        }
    }
    (rank, if rank == 4 { sign as i8 } else { 0 })
}

#[test]
fn classification_table_on_canonical_forms() {
    for (kind, c) in canonical_table() {
        let q = coeffs(c);
        let cl = classify(&q);
        assert_eq!(cl.kind, kind, "{c:?}");
        // The congruence-based invariants agree with the 4×4 matrix read directly.
        let (rank4, det) = rank_and_det_sign(q.matrix4());
        assert_eq!((cl.rank4, cl.det_sign), (rank4, det), "{kind:?}");
    }
}

#[test]
fn classification_is_invariant_under_motion_scaling_and_sign() {
    let mut rng = Rng::new(17);
    for (kind, c) in canonical_table() {
        for _ in 0..20 {
            let m = random_motion(&mut rng);
            let moved = coeffs(c).transformed(&m).unwrap();
            let k = 0.1 + 5.0 * (rng.next() + 1.0);
            let scaled = QuadricCoefficients::from_parts(
                moved.matrix3() * -k,
                moved.linear() * -k,
                moved.d * -k,
            );
            assert_eq!(classify(&moved).kind, kind, "{c:?} moved by {m:?}");
            assert_eq!(classify(&scaled).kind, kind, "{c:?} scaled by {}", -k);
        }
    }
}

#[test]
fn zero_set_is_exactly_the_quadric() {
    // Points on a moved hyperboloid of one sheet, from its parametrisation.
    let (a, b, c) = (0.5, 0.7, 0.6);
    let form = QuadricForm::HyperboloidOfOneSheet { radii: [a, b, c] };
    let mut rng = Rng::new(23);
    let m = random_motion(&mut rng);
    let bounds = Aabb::new(
        m.translation - DVec3::splat(1.5),
        m.translation + DVec3::splat(1.5),
    );
    let q = Quadric::general(form.coefficients().transformed(&m).unwrap(), Some(bounds)).unwrap();
    let mut on = 0;
    for _ in 0..2000 {
        let (t, s) = (3.2 * rng.next(), 1.0 * rng.next());
        let local = DVec3::new(
            a * t.cos() * (1.0 + s * s).sqrt(),
            b * t.sin() * (1.0 + s * s).sqrt(),
            c * s,
        );
        let p = m.transform_point3(local);
        if bounds.expanded(-1e-6).contains(p) {
            on += 1;
            assert!(q.value(p).abs() < 1e-12, "{} at {p}", q.value(p));
            // Just inside and outside along the normal, with the sign of Q.
            let n = q.gradient(p).normalize();
            assert!(q.value(p - 1e-6 * n) < 0.0 && q.value(p + 1e-6 * n) > 0.0);
        }
    }
    assert!(on > 500);
}

#[test]
fn field_is_a_distance_near_the_surface() {
    // On a cylinder of radius 1, the field is the signed distance close to the surface.
    let q = Quadric::new(
        QuadricForm::EllipticCylinder { radii: [1.0, 1.0] },
        cube(3.0),
    )
    .unwrap();
    for &(r, z) in &[(0.9, 0.0), (1.05, 0.5), (1.2, -1.0), (0.8, 2.0)] {
        for k in 0..8 {
            let t = k as f64 * 0.8;
            let p = DVec3::new(r * t.cos(), r * t.sin(), z);
            let d = r - 1.0;
            // Taubin's distance (r² − 1)/(2r) agrees with r − 1 to second order.
            assert!(
                (q.value(p) - (r * r - 1.0) / (2.0 * r)).abs() < 1e-12,
                "{p}"
            );
            assert!((q.value(p) - d).abs() < d * d);
        }
    }
    assert_eq!(q.lipschitz(), 2.0);
}

#[test]
fn interval_of_q_is_tight_for_small_boxes() {
    let c = QuadricForm::HyperboloidOfOneSheet {
        radii: [0.5, 0.6, 0.8],
    }
    .coefficients();
    let b = Aabb::new(DVec3::new(0.1, 0.2, 0.3), DVec3::new(0.11, 0.21, 0.31));
    let iv = c.interval(&b);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..1331 {
        let t = DVec3::new((k % 11) as f64, ((k / 11) % 11) as f64, (k / 121) as f64) / 10.0;
        let v = c.value(b.min + (b.max - b.min) * t);
        (lo, hi) = (lo.min(v), hi.max(v));
    }
    // Sound, and within second-order terms of the true range.
    assert!(iv.lo <= lo && hi <= iv.hi, "{iv:?}");
    assert!(
        iv.width() <= (hi - lo) * 1.01 + 1e-4,
        "{iv:?} vs [{lo}, {hi}]"
    );
    let whole = c.interval(&Aabb::centered(DVec3::ONE));
    assert!(whole.contains(-1.0 - 1.0 / 0.64) && whole.contains(1.0 / 0.25 + 1.0 / 0.36 - 1.0));
    assert!(Interval::new(-2.57, 5.78).contains(whole.lo + 0.01));
}

#[test]
fn bad_parameters_are_named() {
    let cyl = QuadricForm::EllipticCylinder { radii: [1.0, 1.0] };
    assert_eq!(Quadric::new(cyl, None).unwrap_err().parameter, "bounds");
    let empty = coeffs([1.0, 1.0, 1.0, 0., 0., 0., 0., 0., 0., 1.0]);
    assert_eq!(
        Quadric::general(empty, None).unwrap_err().parameter,
        "coefficients"
    );
    let zero = coeffs([0.0; 10]);
    assert_eq!(
        Quadric::general(zero, cube(1.0)).unwrap_err().parameter,
        "coefficients"
    );
    let nan = QuadricForm::EllipticCone {
        radii: [f64::NAN, 1.0],
    };
    assert_eq!(Quadric::new(nan, cube(1.0)).unwrap_err().parameter, "radii");
    let flat = Some(Aabb::new(DVec3::ZERO, DVec3::new(1.0, 0.0, 1.0)));
    assert_eq!(Quadric::new(cyl, flat).unwrap_err().parameter, "bounds");
    let e = Ellipsoid {
        radii: DVec3::new(1.0, -1.0, 1.0),
    };
    assert_eq!(e.validate().unwrap_err().parameter, "radii");
}

#[test]
fn transformed_moves_the_zero_set() {
    let mut rng = Rng::new(29);
    let c = coeffs([1.0, -2.0, 0.5, 0.3, -0.2, 0.1, 0.4, 0.0, -0.3, -0.7]);
    for _ in 0..50 {
        let m = random_motion(&mut rng)
            * DAffine3::from_mat3(DMat3::from_diagonal(DVec3::new(1.0, 2.0, 0.5)));
        let t = c.transformed(&m).unwrap();
        let p = rng.vec(2.0);
        assert!(
            (t.value(m.transform_point3(p)) - c.value(p)).abs() < 1e-9 * (1.0 + c.value(p).abs())
        );
    }
}
