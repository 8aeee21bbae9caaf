//! Acceptance of the quadric family (issue 5): quadric solids from JSON meshed at 128³ are closed
//! manifolds with the expected shells and genus, and their volumes are within 1% of the closed
//! forms.

use solidkit_kernel::json;
use solidkit_kernel::primitive::quadric::{QuadricCoefficients, QuadricKind};
use solidkit_kernel::{NodeKind, Primitive, Solid};
use solidkit_tests::{mesh, rel_err};
use std::f64::consts::PI;

const RESOLUTION: usize = 128;

fn solid(text: &str) -> Solid {
    let s = json::from_str(text).expect("parses");
    s.validate().expect("valid");
    s
}

/// Meshes at 128³ and checks closed manifold, shells, genus per shell and volume within 1%.
fn check(text: &str, shells: usize, exact: f64) {
    let (_, r) = mesh(&solid(text), RESOLUTION);
    assert!(r.is_closed_manifold(), "{text}: {r:?}");
    assert_eq!(r.shells, shells, "{text}");
    assert_eq!(r.genus_per_shell, vec![Some(0); shells], "{text}");
    eprintln!(
        "{text}\n  volume {} vs exact {exact} ({:.3}%), {} triangles",
        r.volume,
        100.0 * rel_err(r.volume, exact),
        r.faces
    );
    assert!(
        rel_err(r.volume, exact) < 0.01,
        "{text}: volume {} vs {exact}",
        r.volume
    );
}

#[test]
fn ellipsoid() {
    let exact = 4.0 / 3.0 * PI * 1.0 * 0.7 * 0.5;
    check(
        r#"{"type": "ellipsoid", "radii": [1.0, 0.7, 0.5]}"#,
        1,
        exact,
    );
}

#[test]
fn general_coefficients_of_a_moved_ellipsoid() {
    // x²/0.81 + y²/0.36 + z²/0.25 ≤ 1 rotated 30° about z and 50° about x, moved by (0.3, -0.2, 0.5):
    // written as general coefficients, classified as an ellipsoid and bounded by its own box.
    let base = QuadricCoefficients {
        a: 1.0 / 0.81,
        b: 1.0 / 0.36,
        c: 1.0 / 0.25,
        d: -1.0,
        ..Default::default()
    };
    let m = glam::DAffine3::from_translation(glam::DVec3::new(0.3, -0.2, 0.5))
        * glam::DAffine3::from_rotation_x(50f64.to_radians())
        * glam::DAffine3::from_rotation_z(30f64.to_radians());
    let c = base.transformed(&m).unwrap();
    let keys = ["a", "b", "c", "f", "g", "h", "p", "q", "r", "d"];
    let members: Vec<String> = keys
        .iter()
        .zip(c.to_array())
        .map(|(k, v)| format!("\"{k}\": {v:?}"))
        .collect();
    let text = format!(
        r#"{{"type": "quadric", "coefficients": {{{}}}}}"#,
        members.join(", ")
    );
    let s = solid(&text);
    let NodeKind::Primitive(Primitive::Quadric(q)) = s.kind() else {
        panic!("a quadric node")
    };
    assert_eq!(q.kind(), QuadricKind::Ellipsoid);
    check(&text, 1, 4.0 / 3.0 * PI * 0.9 * 0.6 * 0.5);
}

#[test]
fn hyperboloid_of_one_sheet_is_one_waisted_column() {
    // ∫ πab(1 + z²/c²) dz over |z| ≤ h = 2πab(h + h³/(3c²)).
    let (a, b, c, h) = (0.5, 0.4, 0.5, 1.0);
    let exact = 2.0 * PI * a * b * (h + h * h * h / (3.0 * c * c));
    check(
        r#"{"type": "hyperboloid_one_sheet", "radii": [0.5, 0.4, 0.5],
            "bounds": [[-1.2, -1.0, -1.0], [1.2, 1.0, 1.0]]}"#,
        1,
        exact,
    );
}

#[test]
fn hyperboloid_of_two_sheets_is_two_caps() {
    // 2 ∫_c^h πab(z²/c² − 1) dz = 2πab((h³ − c³)/(3c²) − (h − c)).
    let (a, b, c, h) = (0.6, 0.5, 0.4, 1.2);
    let exact = 2.0 * PI * a * b * ((h * h * h - c * c * c) / (3.0 * c * c) - (h - c));
    check(
        r#"{"type": "hyperboloid_two_sheets", "radii": [0.6, 0.5, 0.4],
            "bounds": [[-1.8, -1.5, -1.2], [1.8, 1.5, 1.2]]}"#,
        2,
        exact,
    );
}

#[test]
fn elliptic_paraboloid_cup() {
    // ∫_0^h πab z dz = πab h²/2 (the box floor below the apex does not cut).
    let exact = PI * 0.8 * 0.6 * 0.5;
    check(
        r#"{"type": "elliptic_paraboloid", "radii": [0.8, 0.6],
            "bounds": [[-1.0, -1.0, -0.3], [1.0, 1.0, 1.0]]}"#,
        1,
        exact,
    );
}

#[test]
fn hyperbolic_paraboloid_under_a_lid() {
    // ∫∫ over [−1, 1]² of (2 − x²/a² + y²/b²) = 8 − (4/3)/a² + (4/3)/b²; the saddle stays above −1.
    let (a, b) = (0.8f64, 1.25f64);
    let exact = 8.0 - 4.0 / 3.0 / (a * a) + 4.0 / 3.0 / (b * b);
    check(
        r#"{"type": "hyperbolic_paraboloid", "radii": [0.8, 1.25],
            "bounds": [[-1.0, -1.0, -1.0], [1.0, 1.0, 2.0]]}"#,
        1,
        exact,
    );
}

#[test]
fn elliptic_cylinder_and_cone_frustum() {
    check(
        r#"{"type": "elliptic_cylinder", "radii": [0.7, 0.4],
            "bounds": [[-1.0, -1.0, -0.6], [1.0, 1.0, 0.6]]}"#,
        1,
        PI * 0.7 * 0.4 * 1.2,
    );
    // ∫_{0.25}^{1} πab z² dz.
    check(
        r#"{"type": "elliptic_cone", "radii": [0.9, 0.6],
            "bounds": [[-1.0, -1.0, 0.25], [1.0, 1.0, 1.0]]}"#,
        1,
        PI * 0.9 * 0.6 * (1.0 - 0.25f64.powi(3)) / 3.0,
    );
}

#[test]
fn quadric_nodes_round_trip_through_json() {
    let texts = [
        r#"{"type": "ellipsoid", "radii": [1.0, 0.7, 0.5]}"#,
        r#"{"type": "quadric", "coefficients": {"a": 1, "b": -1, "r": -0.5}, "bounds": [[-1, -1, -1], [1, 1, 1]]}"#,
        r#"{"type": "hyperboloid_two_sheets", "radii": [0.6, 0.5, 0.4], "bounds": [[-2, -2, -2], [2, 2, 2]]}"#,
    ];
    for text in texts {
        let s = solid(text);
        let again = json::from_str(&json::to_string(&s)).expect("written tree parses");
        assert_eq!(s, again, "{text}");
    }
}

#[test]
fn bad_quadric_nodes_name_the_parameter() {
    let e = json::from_str(r#"{"type": "elliptic_cone", "radii": [1, 1]}"#).unwrap_err();
    assert!(e.to_string().contains("bounds"), "{e}");
    let e = json::from_str(r#"{"type": "quadric", "coefficients": {"a": 1, "k": 2}}"#).unwrap_err();
    assert!(e.to_string().contains("coefficients.k"), "{e}");
    let e = json::from_str(r#"{"type": "ellipsoid", "radii": [1, 0, 1]}"#).unwrap_err();
    assert!(e.to_string().contains("radii"), "{e}");
}
