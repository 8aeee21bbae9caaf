//! Acceptance of the foundation at resolution 128: shells, Euler characteristic, genus and volume
//! of the fixture trees against their analytic values.

use solidkit_tests::{load_tree, mesh, rel_err};
use std::f64::consts::PI;

const RESOLUTION: usize = 128;

#[test]
fn sphere_is_one_sphere_shell() {
    let (_, r) = mesh(&load_tree("trees/sphere.json"), RESOLUTION);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.euler_characteristic, r.genus), (1, 2, Some(0)));
    assert!(
        rel_err(r.volume, 4.0 / 3.0 * PI) < 0.01,
        "volume {}",
        r.volume
    );
    assert!(rel_err(r.area, 4.0 * PI) < 0.01, "area {}", r.area);
}

#[test]
fn torus_has_genus_one() {
    let (_, r) = mesh(&load_tree("trees/torus.json"), RESOLUTION);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.euler_characteristic, r.genus), (1, 0, Some(1)));
    let exact = 2.0 * PI * PI * 1.0 * 0.3 * 0.3;
    assert!((exact - 1.776529).abs() < 1e-6);
    assert!(rel_err(r.volume, exact) < 0.01, "volume {}", r.volume);
}

/// Volume of the unit ball minus the centred cube of side `2a` (a < 1 < a√3), in closed form:
/// ball − cube + (parts of the cube outside the ball). The cube's outside parts are computed by
/// inclusion–exclusion over the six caps cut off by the face planes, (the caps overlap along the
/// edges, and those overlaps again near the corners): V = V_ball − [V_cube − V_cube∖ball].
fn sphere_minus_cube_volume(a: f64) -> f64 {
    // Integrate the cube ∩ ball numerically in z with the exact area of square ∩ disc per slice.
    let square_disc_area = |h: f64, r: f64| -> f64 {
        // Area of [-h, h]² ∩ disc(r) by integrating over x exactly per quadrant (closed form).
        if r <= 0.0 {
            return 0.0;
        }
        if r <= h {
            return PI * r * r;
        }
        if r * r >= 2.0 * h * h {
            return 4.0 * h * h;
        }
        // Disc minus the four circular segments beyond |x| = h or |y| = h.
        let seg = r * r * (h / r).acos() - h * (r * r - h * h).sqrt();
        PI * r * r - 4.0 * seg
    };
    let n = 200_000;
    let dz = 2.0 * a / n as f64;
    let inter: f64 = (0..n)
        .map(|i| {
            let z = -a + (i as f64 + 0.5) * dz;
            square_disc_area(a, (1.0 - z * z).max(0.0).sqrt()) * dz
        })
        .sum();
    4.0 / 3.0 * PI - inter
}

#[test]
fn sphere_minus_cube_has_genus_seven() {
    let exact = sphere_minus_cube_volume(0.6);
    assert!((exact - 2.461221).abs() < 1e-5, "closed form {exact}");
    let (_, r) = mesh(&load_tree("trees/sphere_minus_cube.json"), RESOLUTION);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(7)));
    assert_eq!(r.euler_characteristic, -12);
    assert!(rel_err(r.volume, exact) < 0.01, "volume {}", r.volume);
}

#[test]
fn disjoint_spheres_are_two_shells() {
    let (_, r) = mesh(&load_tree("trees/two_spheres.json"), RESOLUTION);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.euler_characteristic, r.genus), (2, 4, Some(0)));
    assert_eq!(r.genus_per_shell, vec![Some(0), Some(0)]);
    assert!(
        rel_err(r.volume, 2.0 * 4.0 / 3.0 * PI * 0.125) < 0.01,
        "volume {}",
        r.volume
    );
}

#[test]
fn example_bracket_is_a_closed_genus_three_solid() {
    let (_, r) = mesh(&load_tree("examples/bracket.json"), 96);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(3)));
}
