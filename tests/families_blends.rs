//! Blends, offsets and shells meshed at 128³: closed manifolds with the expected topology and
//! volumes within 1% of closed forms (Steiner's formula for the offset cube, concentric spheres for
//! the shell) or of an axisymmetric quadrature (the smooth union of two balls).

use glam::DVec3;
use solidkit_kernel::Solid;
use solidkit_tests::{mesh, rel_err};
use std::f64::consts::PI;

#[test]
fn offset_cube_follows_steiners_formula() {
    let (a, d) = (1.0, 0.1);
    let (_, r) = mesh(&Solid::cube(a).offset(d), 128);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(0)));
    let exact = a * a * a + 6.0 * a * a * d + 3.0 * PI * a * d * d + 4.0 / 3.0 * PI * d * d * d;
    assert!(rel_err(r.volume, exact) < 0.01, "{} vs {exact}", r.volume);
}

#[test]
fn shell_of_a_ball_is_two_concentric_spheres() {
    let (_, r) = mesh(&Solid::sphere(1.0).shell(0.2), 128);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (2, Some(0)));
    let exact = 4.0 / 3.0 * PI * (1.1f64.powi(3) - 0.9f64.powi(3));
    assert!(rel_err(r.volume, exact) < 0.01, "{} vs {exact}", r.volume);
    // Inner shell wound inward: the total is the difference of the two balls.
    assert!(r.volume > 0.0);
}

#[test]
fn smooth_union_of_two_balls_matches_quadrature() {
    let a = Solid::sphere(0.5).translate(DVec3::new(-0.4, 0.0, 0.0));
    let b = Solid::sphere(0.5).translate(DVec3::new(0.4, 0.0, 0.0));
    let s = a.smooth_union(&b, 0.25);
    let (_, r) = mesh(&s, 128);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(0)));
    // Axisymmetric about x: every cross-section is a disc; find its radius by bisection.
    let p = s.compile();
    let n = 20_000;
    let (x0, x1) = (-1.0, 1.0);
    let dx = (x1 - x0) / n as f64;
    let mut exact = 0.0;
    for i in 0..n {
        let x = x0 + (i as f64 + 0.5) * dx;
        if p.value(DVec3::new(x, 0.0, 0.0)) >= 0.0 {
            continue;
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if p.value(DVec3::new(x, mid, 0.0)) < 0.0 {
                lo = mid
            } else {
                hi = mid
            }
        }
        exact += PI * lo * lo * dx;
    }
    let union =
        2.0 * 4.0 / 3.0 * PI * 0.125 - 2.0 * PI * (0.1f64.powi(2)) * (3.0 * 0.5 - 0.1) / 3.0;
    assert!(exact > union, "the blend adds material: {exact} vs {union}");
    assert!(rel_err(r.volume, exact) < 0.01, "{} vs {exact}", r.volume);
}
