//! Tests of the sweep family: conformance (Lipschitz bound, gradients, intervals, boxes),
//! exactness against primitives with known distances and brute-force references, frames,
//! volumes, tessellation counts, and the JSON round trip.

use super::*;
use crate::curve::{Bezier, Curve, Curve3, Interpolating, Nurbs, arc_length};
use crate::primitive::conformance::{Rng, check_shape};
use crate::primitive::{Cone, Cylinder, Shape, Torus};
use crate::profile::{Circle, Profile};
use crate::{Solid, json};
use glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

fn square(c: DVec2, h: f64) -> Vec<DVec2> {
    vec![
        c + DVec2::new(-h, -h),
        c + DVec2::new(h, -h),
        c + DVec2::new(h, h),
        c + DVec2::new(-h, h),
    ]
}

fn circle_at(center: DVec2, radius: f64) -> Profile {
    Profile::Circle(Circle { center, radius })
}

/// A helix of radius `r`, rising `pitch` per turn, as an interpolating spline through 16 points
/// per turn.
pub(crate) fn helix(r: f64, pitch: f64, turns: f64) -> Curve {
    let n = (16.0 * turns) as usize;
    let points = (0..=n)
        .map(|i| {
            let a = TAU * turns * i as f64 / n as f64;
            DVec3::new(
                r * a.cos(),
                r * a.sin(),
                pitch * a / TAU - 0.5 * pitch * turns,
            )
        })
        .collect();
    Curve::Interpolating(Interpolating::new(points, false).unwrap())
}

fn extrusions() -> Vec<Extrude> {
    let holed = Profile::polygon(
        square(DVec2::ZERO, 0.6),
        vec![square(DVec2::new(0.1, 0.0), 0.2)],
    )
    .unwrap();
    vec![
        Extrude::new(
            Profile::rectangle(DVec2::new(1.0, 0.6)).unwrap(),
            1.2,
            0.0,
            1.0,
        )
        .unwrap(),
        Extrude::new(holed.clone(), 1.0, 0.0, 1.0).unwrap(),
        Extrude::new(holed, 1.0, 120.0, 0.5).unwrap(),
        Extrude::new(
            Profile::rectangle(DVec2::new(1.0, 0.4)).unwrap(),
            1.4,
            90.0,
            1.0,
        )
        .unwrap(),
        Extrude::new(circle_at(DVec2::new(0.3, 0.1), 0.4), 1.0, -200.0, 1.6).unwrap(),
        // OpenSCAD's `scale = [sx, sy]`: anisotropic, with and without twist.
        Extrude::with_scale(
            Profile::rectangle(DVec2::new(0.8, 0.5)).unwrap(),
            1.0,
            0.0,
            DVec2::new(0.4, 1.5),
        )
        .unwrap(),
        Extrude::with_scale(
            circle_at(DVec2::new(0.2, 0.0), 0.3),
            1.2,
            75.0,
            DVec2::new(1.8, 0.5),
        )
        .unwrap(),
    ]
}

#[test]
fn extrusions_conform() {
    for e in extrusions() {
        check_shape(&e, 1.5);
    }
}

#[test]
fn plain_extrusion_of_a_circle_is_the_cylinder() {
    let e = Extrude::new(Profile::circle(0.5).unwrap(), 1.2, 0.0, 1.0).unwrap();
    let c = Cylinder {
        radius: 0.5,
        height: 1.2,
    };
    let mut rng = Rng::new(31);
    for _ in 0..2000 {
        let p = rng.vec(1.5);
        assert!((e.value(p) - c.value(p)).abs() < 1e-12, "{p}");
    }
}

/// `scale = 0` (OpenSCAD's `linear_extrude(scale = 0)`) is the cone to the apex: the same inside
/// as the exact cone, finite values up to and beyond the apex, the cone's volume, and a field
/// that passes the conformance checks; one zero scale factor alone is still refused.
#[test]
fn zero_scale_extrusion_is_the_cone_to_the_apex() {
    let e = Extrude::new(Profile::circle(0.5).unwrap(), 1.2, 0.0, 0.0).unwrap();
    let c = Cone {
        bottom_radius: 0.5,
        top_radius: 0.0,
        height: 1.2,
    };
    let mut rng = Rng::new(33);
    for _ in 0..4000 {
        let p = rng.vec(1.0);
        let (v, w) = (e.value(p), c.value(p));
        assert!(v.is_finite(), "{p}");
        if w.abs() > 1e-9 {
            assert_eq!(v < 0.0, w < 0.0, "{p}: {v} vs {w}");
        }
    }
    assert!(e.value(DVec3::new(0.0, 0.0, 0.6)).abs() < 1e-9);
    assert!(e.value(DVec3::new(0.0, 0.0, 0.7)) > 0.0);
    let volume = PI * 0.25 * 1.2 / 3.0;
    assert!((e.volume() - volume).abs() < 1e-12 * volume);
    check_shape(&e, 1.5);
    for bad in [DVec2::new(-0.5, 1.0), DVec2::new(1.0, f64::NAN)] {
        let e = Extrude::with_scale(Profile::circle(0.5).unwrap(), 1.0, 0.0, bad);
        assert!(e.is_err(), "{bad}");
    }
}

/// One zero scale (OpenSCAD's `linear_extrude(scale = [0, 1])`): the slices shrink to a segment
/// along one axis. The inside is the exact wedge's, the volume is half the prism's, and the field
/// passes the conformance checks.
#[test]
fn one_zero_scale_is_a_wedge_to_a_segment() {
    let profile = circle_at(DVec2::new(0.2, 0.1), 0.4);
    for scale in [DVec2::new(0.0, 1.0), DVec2::new(0.7, 0.0)] {
        let e = Extrude::with_scale(profile.clone(), 1.2, 0.0, scale).unwrap();
        let mut rng = Rng::new(34);
        for _ in 0..4000 {
            let p = rng.vec(1.0);
            let t = (p.z + 0.6) / 1.2;
            let k = DVec2::ONE + (scale - DVec2::ONE) * t;
            let w = DVec2::new(p.x, p.y) / k;
            let inside = p.z.abs() < 0.6 && profile.distance(w) < 0.0;
            let v = e.value(p);
            assert!(v.is_finite(), "{p}");
            if v.abs() > 1e-9 {
                assert_eq!(v < 0.0, inside, "{scale} at {p}: {v}");
            }
        }
        let area = PI * 0.16;
        let (a, b) = (scale.x - 1.0, scale.y - 1.0);
        let volume = area * 1.2 * (1.0 + (a + b) / 2.0 + a * b / 3.0);
        assert!((e.volume() - volume).abs() < 1e-9, "{scale}");
        check_shape(&e, 1.5);
    }
}

/// The field's gradient never exceeds 1 for anisotropic end scales, also where both scales are
/// below 1 (where the slice stretches most along the larger one) and where one is 0.
#[test]
fn anisotropic_extrusions_are_one_lipschitz() {
    let profile = circle_at(DVec2::new(0.5, -0.4), 0.3);
    for (scale, twist) in [
        (DVec2::new(0.1, 0.2), 0.0),
        (DVec2::new(0.2, 0.05), 40.0),
        (DVec2::new(0.0, 1.0), 0.0),
        (DVec2::new(0.0, 0.3), 0.0),
        (DVec2::new(2.0, 0.0), 90.0),
    ] {
        let e = Extrude::with_scale(profile.clone(), 1.0, twist, scale).unwrap();
        let mut rng = Rng::new(35);
        let mut worst = 0.0f64;
        for _ in 0..20000 {
            let p = rng.vec(1.2);
            if p.z.abs() >= 0.5 {
                continue;
            }
            worst = worst.max(e.gradient(p).length());
        }
        assert!(worst <= 1.0 + 1e-9, "{scale} twist {twist}: |grad| {worst}");
    }
}

#[test]
fn twisted_scaled_extrusion_has_the_right_inside() {
    let e = &extrusions()[2];
    let holed = e.profile();
    let mut rng = Rng::new(32);
    for _ in 0..3000 {
        let p = rng.vec(1.0);
        let (k, theta) = e.slice_transform(p.z);
        let w = DVec2::from_angle(-theta).rotate(DVec2::new(p.x, p.y)) / k;
        let inside = p.z.abs() < 0.5 && holed.distance(w) < 0.0;
        let v = e.value(p);
        if v.abs() > 1e-9 {
            assert_eq!(v < 0.0, inside, "{p}");
        }
    }
    // A distance bound inside: |f| never exceeds the distance to the slice's boundary or to the
    // end planes (both upper bounds of the distance to the surface).
    for _ in 0..1000 {
        let p = rng.vec(0.45);
        let (k, theta) = e.slice_transform(p.z);
        let w = DVec2::from_angle(-theta).rotate(DVec2::new(p.x, p.y)) / k;
        let sigma = k.x * holed.distance(w);
        if sigma < 0.0 {
            let bound = (-sigma).min(0.5 - p.z.abs());
            assert!(-e.value(p) <= bound + 1e-12 && e.value(p) < 0.0);
        }
    }
}

#[test]
fn revolutions_conform_and_are_exact() {
    let torus_like = Revolve::new(circle_at(DVec2::new(1.0, 0.2), 0.3), 360.0).unwrap();
    let torus = Torus {
        major_radius: 1.0,
        minor_radius: 0.3,
    };
    let cylinder_like = Revolve::new(
        Profile::Rectangle(crate::profile::Rectangle {
            center: DVec2::new(0.25, 0.0),
            size: DVec2::new(0.5, 1.2),
        }),
        360.0,
    )
    .unwrap();
    let cylinder = Cylinder {
        radius: 0.5,
        height: 1.2,
    };
    let mut rng = Rng::new(33);
    for _ in 0..2000 {
        let p = rng.vec(1.6);
        assert!((torus_like.value(p) - torus.value(p - DVec3::Z * 0.2)).abs() < 1e-12);
        assert!((cylinder_like.value(p) - cylinder.value(p)).abs() < 1e-12);
    }
    check_shape(&torus_like, 1.6);
    check_shape(&cylinder_like, 1.5);
    let l = Profile::polygon(
        vec![
            DVec2::new(0.0, -0.5),
            DVec2::new(0.8, -0.5),
            DVec2::new(0.8, -0.2),
            DVec2::new(0.3, -0.2),
            DVec2::new(0.3, 0.6),
            DVec2::new(0.0, 0.6),
        ],
        vec![],
    )
    .unwrap();
    for angle in [60.0, 180.0, 270.0] {
        check_shape(&Revolve::new(l.clone(), angle).unwrap(), 1.2);
        check_shape(
            &Revolve::new(circle_at(DVec2::new(0.8, 0.0), 0.3), angle).unwrap(),
            1.3,
        );
    }
}

/// Distance to the surface of the half cylinder `ρ ≤ r, |z| ≤ h/2, y ≥ 0` by dense sampling.
fn sampled_half_cylinder_distance(p: DVec3, r: f64, h: f64) -> f64 {
    let mut best = f64::INFINITY;
    let n = 120;
    for i in 0..=n {
        let a = PI * i as f64 / n as f64;
        for j in 0..=n {
            let s = j as f64 / n as f64;
            let z = -0.5 * h + h * s;
            let rho = r * s;
            let candidates = [
                DVec3::new(r * a.cos(), r * a.sin(), z),
                DVec3::new(rho * a.cos(), rho * a.sin(), 0.5 * h),
                DVec3::new(rho * a.cos(), rho * a.sin(), -0.5 * h),
                DVec3::new(-r + 2.0 * r * (i as f64 / n as f64), 0.0, z),
            ];
            for c in candidates {
                best = best.min((c - p).length());
            }
        }
    }
    best
}

#[test]
fn partial_revolution_is_the_exact_distance() {
    let half = Revolve::new(
        Profile::Rectangle(crate::profile::Rectangle {
            center: DVec2::new(0.4, 0.0),
            size: DVec2::new(0.8, 1.0),
        }),
        180.0,
    )
    .unwrap();
    let mut rng = Rng::new(34);
    for _ in 0..60 {
        let p = rng.vec(1.2);
        let reference = sampled_half_cylinder_distance(p, 0.8, 1.0);
        let v = half.value(p);
        assert!(
            (v.abs() - reference).abs() < 0.012,
            "{v} vs {reference} at {p}"
        );
        let inside = p.y > 0.0 && p.truncate().length() < 0.8 && p.z.abs() < 0.5;
        assert_eq!(v < 0.0, inside);
    }
    assert!((half.volume() - PI * 0.64 * 1.0 / 2.0).abs() < 1e-12);
}

fn torus_sweep() -> Sweep {
    Sweep::new(
        Profile::circle(0.3).unwrap(),
        Curve::Nurbs(Nurbs::circle(DVec3::ZERO, 1.0).unwrap()),
    )
    .unwrap()
}

#[test]
fn circle_swept_along_a_circle_is_the_exact_torus() {
    let s = torus_sweep();
    assert!(s.is_closed());
    assert!(s.holonomy().abs() < 1e-9, "planar path: {}", s.holonomy());
    let torus = Torus {
        major_radius: 1.0,
        minor_radius: 0.3,
    };
    let mut rng = Rng::new(35);
    for _ in 0..3000 {
        let p = rng.vec(1.6);
        assert!((s.value(p) - torus.value(p)).abs() < 1e-12, "{p}");
    }
    check_shape(&s, 1.6);
    assert!((s.volume() - 2.0 * PI * PI * 0.09).abs() < 1e-10);
}

#[test]
fn helix_tube_is_the_exact_tube_distance_away_from_its_ends() {
    let path = helix(0.8, 0.6, 2.0);
    let s = Sweep::new(Profile::circle(0.15).unwrap(), path.clone()).unwrap();
    assert!(!s.is_closed());
    check_shape(&s, 1.2);
    let (t0, t1) = path.domain();
    let mut rng = Rng::new(36);
    for _ in 0..200 {
        let p = rng.vec(1.0);
        let (mut best, mut arg) = (f64::INFINITY, t0);
        for i in 0..=20_000 {
            let t = t0 + (t1 - t0) * i as f64 / 20_000.0;
            let d = (path.point(t) - p).length();
            if d < best {
                (best, arg) = (d, t);
            }
        }
        if arg > t0 + 1.0 && arg < t1 - 1.0 {
            assert!((s.value(p) - (best - 0.15)).abs() < 1e-6, "{p}");
        }
    }
    let exact = PI * 0.15 * 0.15 * arc_length(&path);
    assert!((s.volume() - exact).abs() < 1e-12 * exact);
}

#[test]
fn rotation_minimising_frames_do_not_twist_and_close() {
    let s = Sweep::new(
        Profile::rectangle(DVec2::new(0.2, 0.1)).unwrap(),
        helix(0.8, 0.6, 2.0),
    )
    .unwrap();
    let (t0, t1) = s.path().domain();
    for i in 0..200 {
        let t = t0 + (t1 - t0) * i as f64 / 200.0;
        let dt = 1e-5;
        let [_, u, v] = s.frame(t);
        let [_, u2, _] = s.frame(t + dt);
        // Angular velocity about the tangent: (dU/dt)·V ≈ 0.
        assert!(((u2 - u) / dt).dot(v).abs() < 1e-5, "twist at {t}");
    }
    // A non-planar closed path: a (2, 3) torus knot-like closed spline.
    let points = (0..24)
        .map(|i| {
            let a = TAU * i as f64 / 24.0;
            DVec3::new(
                (2.0 + (3.0 * a).cos()) * (2.0 * a).cos(),
                (2.0 + (3.0 * a).cos()) * (2.0 * a).sin(),
                (3.0 * a).sin(),
            ) * 0.3
        })
        .collect();
    let knot = Curve::Interpolating(Interpolating::new(points, true).unwrap());
    let ring = Sweep::new(Profile::rectangle(DVec2::new(0.08, 0.04)).unwrap(), knot).unwrap();
    assert!(ring.is_closed());
    assert!(ring.holonomy().abs() > 1e-3, "holonomy {}", ring.holonomy());
    let (t0, t1) = ring.path().domain();
    let (a, b) = (ring.frame(t0), ring.frame(t1));
    assert!(
        (a[1] - b[1]).length() < 1e-9,
        "frames close: {} vs {}",
        a[1],
        b[1]
    );
    assert!(ring.lipschitz() > 1.0);
    check_shape(&ring, 1.1);
}

#[test]
fn square_swept_along_a_planar_curve_conforms() {
    let path = Curve::Bezier(
        Bezier::new(vec![
            DVec3::new(-1.0, 0.0, -0.5),
            DVec3::new(-0.3, 0.2, 1.0),
            DVec3::new(0.5, -0.2, 1.0),
            DVec3::new(1.0, 0.0, -0.2),
        ])
        .unwrap(),
    );
    let s = Sweep::new(Profile::rectangle(DVec2::new(0.3, 0.2)).unwrap(), path).unwrap();
    check_shape(&s, 1.4);
    // Past the start the field is the exact distance to the start face.
    let [t, u, v] = s.frame(0.0);
    let start = s.path().point(0.0);
    let p = start - t * 0.3 + u * 0.05 + v * 0.02;
    assert!((s.value(p) - 0.3).abs() < 1e-12);
    // Within the profile's radius of the path the cross-section distance is exact.
    let p = start - t * 0.3 + u * 0.16 + v * 0.05;
    let expected = (0.3f64.powi(2) + 0.01f64.powi(2)).sqrt();
    assert!(
        (s.value(p) - expected).abs() < 1e-12,
        "{} vs {expected}",
        s.value(p)
    );
}

#[test]
fn invalid_sweeps_are_rejected() {
    // A tube thicker than the path's radius of curvature would fold.
    let e = Sweep::new(
        Profile::circle(1.5).unwrap(),
        Curve::Nurbs(Nurbs::circle(DVec3::ZERO, 1.0).unwrap()),
    );
    assert_eq!(e.unwrap_err().parameter(), "profile");
    assert_eq!(
        Extrude::new(Profile::circle(1.0).unwrap(), 0.0, 0.0, 1.0)
            .unwrap_err()
            .parameter(),
        "height"
    );
    assert_eq!(
        Extrude::new(Profile::circle(1.0).unwrap(), 1.0, 0.0, -0.5)
            .unwrap_err()
            .parameter(),
        "scale"
    );
    assert_eq!(
        Revolve::new(circle_at(DVec2::new(0.1, 0.0), 0.5), 360.0)
            .unwrap_err()
            .parameter(),
        "profile"
    );
    assert_eq!(
        Revolve::new(Profile::circle(0.5).unwrap(), 400.0)
            .unwrap_err()
            .parameter(),
        "angle"
    );
    let e = Loft::new(
        Profile::circle(1.0).unwrap(),
        Profile::rectangle(DVec2::ONE).unwrap(),
        1.0,
    );
    assert_eq!(e.unwrap_err().parameter(), "top");
    let open = Curve::Bezier(Bezier::new(vec![DVec3::ZERO, DVec3::X]).unwrap());
    let circle = Curve::Nurbs(Nurbs::circle(DVec3::Z, 1.0).unwrap());
    assert_eq!(
        Ruled::new(open, circle.clone()).unwrap_err().parameter(),
        "bottom"
    );
    let low = Curve::Nurbs(Nurbs::circle(DVec3::ZERO, 1.0).unwrap());
    assert_eq!(Ruled::new(circle, low).unwrap_err().parameter(), "top");
}

fn lofts() -> Vec<Loft> {
    let rotated: Vec<DVec2> = square(DVec2::new(0.1, 0.0), 0.3)
        .iter()
        .map(|q| DVec2::from_angle(0.5).rotate(*q))
        .collect();
    vec![
        Loft::new(
            circle_at(DVec2::ZERO, 0.8),
            circle_at(DVec2::new(0.2, 0.1), 0.3),
            1.2,
        )
        .unwrap(),
        Loft::new(
            circle_at(DVec2::ZERO, 0.7),
            circle_at(DVec2::new(0.3, 0.0), 0.0),
            1.0,
        )
        .unwrap(),
        Loft::new(
            Profile::polygon(square(DVec2::ZERO, 0.6), vec![]).unwrap(),
            Profile::polygon(rotated, vec![]).unwrap(),
            1.0,
        )
        .unwrap(),
        Loft::new(
            Profile::rectangle(DVec2::new(1.2, 0.8)).unwrap(),
            Profile::rectangle(DVec2::new(0.4, 1.0)).unwrap(),
            0.8,
        )
        .unwrap(),
    ]
}

#[test]
fn lofts_conform_and_bound_the_frustum_distance() {
    for l in lofts() {
        check_shape(&l, 1.3);
    }
    let cone = Cone {
        bottom_radius: 0.8,
        top_radius: 0.2,
        height: 1.0,
    };
    let loft = Loft::new(
        Profile::circle(0.8).unwrap(),
        Profile::circle(0.2).unwrap(),
        1.0,
    )
    .unwrap();
    let mut rng = Rng::new(37);
    for _ in 0..3000 {
        let p = rng.vec(1.2);
        let (f, d) = (loft.value(p), cone.value(p));
        assert!(f.abs() <= d.abs() + 1e-12, "not a bound at {p}: {f} vs {d}");
        if d.abs() > 1e-9 {
            assert_eq!(f < 0.0, d < 0.0);
        }
    }
    assert!((loft.volume() - PI / 3.0 * (0.64 + 0.16 + 0.04)).abs() < 1e-12);
}

fn cone_ruled(apex: DVec3, h: f64) -> Ruled {
    Ruled::new(
        Curve::Bezier(Bezier::new(vec![apex]).unwrap()),
        Curve::Nurbs(Nurbs::circle(DVec3::new(0.0, 0.0, h), 0.8).unwrap()),
    )
    .unwrap()
}

#[test]
fn ruled_cone_and_cylinder_from_the_notes() {
    // s(u, v) = (1 − v)p + v c₂(u): the cone with apex p.
    let cone = cone_ruled(DVec3::new(0.0, 0.0, -0.6), 0.6);
    let exact = Cone {
        bottom_radius: 0.0,
        top_radius: 0.8,
        height: 1.2,
    };
    let mut rng = Rng::new(38);
    for _ in 0..2000 {
        let p = rng.vec(1.2);
        let (f, d) = (cone.value(p), exact.value(p));
        assert!(f.abs() <= d.abs() + 1e-9, "not a bound at {p}: {f} vs {d}");
        if d.abs() > 1e-6 {
            assert_eq!(f < 0.0, d < 0.0, "{p}: {f} vs {d}");
        }
    }
    check_shape(&cone, 1.2);
    assert!((cone.volume() - PI * 0.64 * 1.2 / 3.0).abs() < 1e-12);
    // Oblique apex.
    let oblique = cone_ruled(DVec3::new(0.5, -0.3, -0.6), 0.6);
    check_shape(&oblique, 1.2);
    assert!((oblique.volume() - PI * 0.64 * 1.2 / 3.0).abs() < 1e-12);
    // c₂ = c₁ + d: the (oblique) cylinder.
    let c1 = Curve::Nurbs(Nurbs::circle(DVec3::new(0.0, 0.0, -0.5), 0.6).unwrap());
    let c2 = Curve::Nurbs(Nurbs::circle(DVec3::new(0.0, 0.0, 0.5), 0.6).unwrap());
    let cylinder = Ruled::new(c1, c2).unwrap();
    let exact = Cylinder {
        radius: 0.6,
        height: 1.0,
    };
    for _ in 0..2000 {
        let p = rng.vec(1.2);
        assert!((cylinder.value(p) - exact.value(p)).abs() < 1e-12, "{p}");
    }
    let c1 = Curve::Nurbs(Nurbs::circle(DVec3::new(-0.3, 0.0, -0.5), 0.6).unwrap());
    let c2 = Curve::Nurbs(Nurbs::circle(DVec3::new(0.3, 0.2, 0.5), 0.6).unwrap());
    let leaning = Ruled::new(c1, c2).unwrap();
    check_shape(&leaning, 1.3);
    assert!((leaning.volume() - PI * 0.36).abs() < 1e-12);
}

#[test]
fn ruled_between_splines_conforms_and_signs_by_winding() {
    let blob = |z: f64, k: f64| {
        let pts = (0..7)
            .map(|i| {
                let a = TAU * i as f64 / 7.0;
                let r = 0.6 + 0.15 * (3.0 * a + k).cos();
                DVec3::new(r * a.cos(), r * a.sin(), z)
            })
            .collect();
        Curve::BSpline(crate::curve::BSpline::periodic(3, pts).unwrap())
    };
    let r = Ruled::new(blob(-0.5, 0.0), blob(0.6, 1.0)).unwrap();
    check_shape(&r, 1.2);
    // Clockwise curves give the same solid.
    let reversed = |c: Curve| match c {
        Curve::BSpline(b) => {
            let mut p = b.points()[..7].to_vec();
            p.reverse();
            Curve::BSpline(crate::curve::BSpline::periodic(3, p).unwrap())
        }
        _ => unreachable!(),
    };
    let cw = Ruled::new(reversed(blob(-0.5, 0.0)), reversed(blob(0.6, 1.0))).unwrap();
    let mut rng = Rng::new(39);
    for _ in 0..500 {
        let p = rng.vec(1.0);
        let (a, b) = (r.value(p), cw.value(p));
        if a.abs() > 1e-3 {
            assert_eq!(a < 0.0, b < 0.0, "{p}");
        }
    }
}

#[test]
fn tessellation_counts_and_converging_volumes() {
    // Full revolution: m·n vertices, 2mn triangles.
    let torus = Revolve::new(circle_at(DVec2::new(1.0, 0.0), 0.3), 360.0).unwrap();
    let mut previous = f64::INFINITY;
    for n in [8, 16, 32, 64] {
        let m = torus.tessellate(n, 2 * n).unwrap();
        assert_eq!(
            (m.vertex_count(), m.triangle_count()),
            (2 * n * n, 4 * n * n)
        );
        let err = (signed_volume(&m) - torus.volume()).abs();
        assert!(err < previous / 3.0, "volume error {err} after {previous}");
        previous = err;
    }
    assert!(previous < 3e-3 * torus.volume());
    // Partial revolution of a polygon: m·N vertices, 2(m − 1)N + 2(N − 2) triangles.
    let l = Profile::polygon(
        vec![
            DVec2::new(0.2, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 0.3),
            DVec2::new(0.5, 0.3),
            DVec2::new(0.5, 1.0),
            DVec2::new(0.2, 1.0),
        ],
        vec![],
    )
    .unwrap();
    let part = Revolve::new(l, 120.0).unwrap();
    assert!(part.tessellate(0, 0).is_err());
    let mesh = part.tessellate(3, 41).unwrap();
    assert_eq!(
        (mesh.vertex_count(), mesh.triangle_count()),
        (41 * 6, 2 * 40 * 6 + 2 * 4)
    );
    assert!((signed_volume(&mesh) / part.volume() - 1.0).abs() < 1e-3);
    // A profile touching the axis: poles welded (a cylinder from a rectangle).
    let cyl = Revolve::new(
        Profile::Rectangle(crate::profile::Rectangle {
            center: DVec2::new(0.5, 0.0),
            size: DVec2::new(1.0, 2.0),
        }),
        360.0,
    )
    .unwrap();
    let mesh = cyl.tessellate(3, 64).unwrap();
    assert_eq!(
        (mesh.vertex_count(), mesh.triangle_count()),
        (2 + 2 * 64, 4 * 64)
    );
    // Extrusion with a hole: (levels + 1)·N vertices, 2·levels·N + 2(N + 2h − 2) triangles.
    let e = &extrusions()[2];
    let mesh = e.tessellate(3, 30).unwrap();
    assert_eq!(
        (mesh.vertex_count(), mesh.triangle_count()),
        (31 * 8, 2 * 30 * 8 + 2 * 8)
    );
    assert!((signed_volume(&mesh) / e.volume() - 1.0).abs() < 1e-2);
    // Closed sweep: stations × segments, 2× triangles.
    let s = torus_sweep();
    let mesh = s.tessellate(24, 48).unwrap();
    assert_eq!(
        (mesh.vertex_count(), mesh.triangle_count()),
        (24 * 48, 2 * 24 * 48)
    );
    // Open sweep with caps.
    let tube = Sweep::new(Profile::circle(0.15).unwrap(), helix(0.8, 0.6, 2.0)).unwrap();
    let mesh = tube.tessellate(16, 200).unwrap();
    assert_eq!(
        (mesh.vertex_count(), mesh.triangle_count()),
        (200 * 16, 2 * 199 * 16 + 2 * 14)
    );
    assert!((signed_volume(&mesh) / tube.volume() - 1.0).abs() < 0.03);
    // Lofts and ruled solids: an apex collapses to one vertex.
    let cone = cone_ruled(DVec3::new(0.2, 0.0, -0.6), 0.6);
    let mesh = cone.tessellate(64).unwrap();
    assert_eq!((mesh.vertex_count(), mesh.triangle_count()), (65, 64 + 62));
    assert!((signed_volume(&mesh) / cone.volume() - 1.0).abs() < 3e-3);
    for l in lofts() {
        let mesh = l.tessellate(128).unwrap();
        assert!(
            (signed_volume(&mesh) / l.volume() - 1.0).abs() < 2e-3,
            "{}",
            signed_volume(&mesh) / l.volume()
        );
    }
}

#[test]
fn json_round_trip_is_lossless() {
    let prims: Vec<crate::Primitive> = vec![
        crate::Primitive::Extrude(std::sync::Arc::new(extrusions()[2].clone())),
        crate::Primitive::Extrude(std::sync::Arc::new(extrusions()[4].clone())),
        crate::Primitive::Revolve(std::sync::Arc::new(
            Revolve::new(circle_at(DVec2::new(1.0, 0.1), 0.3), 270.0).unwrap(),
        )),
        crate::Primitive::Sweep(std::sync::Arc::new(torus_sweep())),
        crate::Primitive::Sweep(std::sync::Arc::new(
            Sweep::new(Profile::circle(0.1).unwrap(), helix(0.8, 0.6, 1.5)).unwrap(),
        )),
        crate::Primitive::Loft(std::sync::Arc::new(lofts()[2].clone())),
        crate::Primitive::Loft(std::sync::Arc::new(lofts()[3].clone())),
        crate::Primitive::Ruled(std::sync::Arc::new(cone_ruled(
            DVec3::new(0.1, 0.2, -0.6),
            0.6,
        ))),
    ];
    let hermite = Curve::Hermite(
        crate::curve::Hermite::new(
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(1.0, 2.0, 0.5),
            DVec3::new(1.0, 0.2, 0.3),
            DVec3::new(2.0, -1.0, 0.0),
        )
        .unwrap(),
    );
    let blob = |z: f64| {
        let pts = (0..6)
            .map(|i| {
                let a = TAU * i as f64 / 6.0;
                DVec3::new(0.7 * a.cos(), 0.5 * a.sin(), z)
            })
            .collect();
        Curve::BSpline(crate::curve::BSpline::periodic(3, pts).unwrap())
    };
    let mut prims = prims;
    prims.push(crate::Primitive::Sweep(std::sync::Arc::new(
        Sweep::new(Profile::circle(0.05).unwrap(), hermite).unwrap(),
    )));
    prims.push(crate::Primitive::Ruled(std::sync::Arc::new(
        Ruled::new(blob(-0.3), blob(0.4)).unwrap(),
    )));
    let solid = Solid::union_all(prims.into_iter().map(Solid::primitive));
    let text = json::to_string(&solid);
    let back = json::from_str(&text).unwrap();
    assert!(back == solid, "{text}");
    assert_eq!(json::to_string(&back), text);
}

#[test]
fn json_reads_defaults_and_locates_errors() {
    let s = json::from_str(
        r#"{"type": "sweep", "profile": {"type": "circle", "radius": 0.2},
            "path": {"type": "bezier", "points": [[0, 0], [1, 1], [2, 0]]}}"#,
    )
    .unwrap();
    assert!(s.value(DVec3::new(1.0, 0.5, 0.0)) < 0.0);
    let s = json::from_str(
        r#"{"type": "revolve", "profile": {"type": "rectangle", "size": 1, "center": [1, 0]}}"#,
    )
    .unwrap();
    assert!((s.value(DVec3::new(0.0, 1.0, 0.0)) + 0.5).abs() < 1e-12);
    let err = |text: &str| json::from_str(text).unwrap_err().to_string();
    let e = err(r#"{"type": "extrude", "profile": {"type": "circle", "radius": -1}, "height": 1}"#);
    assert!(e.contains("profile") && e.contains("radius"), "{e}");
    let e = err(
        r#"{"type": "extrude", "profile": {"type": "circle", "radius": 1, "r": 2}, "height": 1}"#,
    );
    assert!(e.contains("profile.r") && e.contains("unknown key"), "{e}");
    let e = err(
        r#"{"type": "sweep", "profile": {"type": "circle", "radius": 0.1}, "path": {"type": "bspline", "degree": 3, "points": [[0,0,0],[1,0,0]]}}"#,
    );
    assert!(e.contains("path") && e.contains("degree"), "{e}");
    let e = err(
        r#"{"type": "ruled", "bottom": {"type": "spiral"}, "top": {"type": "bezier", "points": [[0,0,1]]}}"#,
    );
    assert!(
        e.contains("bottom.type") && e.contains("unknown curve type"),
        "{e}"
    );
}

/// A faceted full turn (OpenSCAD's `rotate_extrude` in `n` steps): a rectangle touching the axis
/// gives the regular `n`-gon prism (inside exactly where the polygon test says), a circle gives
/// a faceted torus whose ring corners lie on the surface; the field conforms (Lipschitz 1,
/// sound intervals) and the volume is `n sin(2π/n) A x̄`, with `n = 3` and a turned start.
#[test]
fn faceted_turns_are_regular_polygon_sweeps() {
    use std::f64::consts::{PI, TAU};
    let rect = Profile::Rectangle(crate::profile::Rectangle {
        center: DVec2::new(0.5, 0.0),
        size: DVec2::new(1.0, 1.0),
    });
    for (n, start) in [(3u32, 180.0f64), (5, 0.0), (12, 37.0)] {
        let prism = Revolve::faceted(rect.clone(), n, start).unwrap();
        let a0 = start.to_radians();
        let corners: Vec<DVec2> = (0..n)
            .map(|j| {
                let a = a0 + TAU * f64::from(j) / f64::from(n);
                DVec2::new(a.cos(), a.sin())
            })
            .collect();
        // Inside the convex n-gon: on the inner side of every edge.
        let in_polygon = |q: DVec2| {
            (0..corners.len()).all(|j| {
                let (a, b) = (corners[j], corners[(j + 1) % corners.len()]);
                (b - a).perp_dot(q - a) > 0.0
            })
        };
        let mut rng = Rng::new(u64::from(n));
        for _ in 0..4000 {
            let p = rng.vec(1.2);
            let v = prism.value(p);
            let inside = in_polygon(DVec2::new(p.x, p.y)) && p.z.abs() < 0.5;
            if v.abs() > 1e-9 {
                assert_eq!(v < 0.0, inside, "n = {n}, {p}");
            }
        }
        for c in &corners {
            assert!(prism.value(DVec3::new(c.x, c.y, 0.2)).abs() < 1e-12);
        }
        let exact = 0.5 * f64::from(n) * (TAU / f64::from(n)).sin();
        assert!((prism.volume() - exact).abs() < 1e-12, "{n}");
        check_shape(&prism, 1.5);
        assert_eq!(prism.segments(), Some((n, start)));
    }
    let ring = Revolve::faceted(circle_at(DVec2::new(1.0, 0.0), 0.25), 6, 0.0).unwrap();
    for j in 0..6 {
        let a = TAU * f64::from(j) / 6.0;
        let p = DVec3::new(1.25 * a.cos(), 1.25 * a.sin(), 0.0);
        assert!(ring.value(p).abs() < 1e-12, "{p}");
    }
    // Pappus with the hexagon's n sin(2π/n) = 3√3 for the smooth turn's 2π.
    let expected = 6.0 * (PI / 3.0).sin() * PI * 0.0625;
    assert!((ring.volume() - expected).abs() < 1e-12);
    check_shape(&ring, 1.6);
    for bad in [0u32, 2, 70_000] {
        assert!(Revolve::faceted(rect.clone(), bad, 0.0).is_err());
    }
}
