//! `ruled_surface`: capped solids between closed curves in any planes (a cylinder along x, the
//! notes' cone with its apex at the origin and its circle in the plane y = 3) against the exact
//! volumes within the stated chord error, thickened open sheets against exact distances, located
//! errors and the JSON round trip.

use crate::json;
use crate::primitive::{Primitive, RuledSurface, Shape};
use crate::solid::NodeKind;
use glam::DVec3;
use std::f64::consts::PI;

/// The exact NURBS circle of radius `r` about `c` in the plane spanned by `e1`, `e2` (9 points,
/// degree 2, quarter arcs).
fn circle(c: DVec3, e1: DVec3, e2: DVec3, r: f64) -> String {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let corners = [
        (1., 0.),
        (1., 1.),
        (0., 1.),
        (-1., 1.),
        (-1., 0.),
        (-1., -1.),
        (0., -1.),
        (1., -1.),
        (1., 0.),
    ];
    let points: Vec<String> = corners
        .iter()
        .map(|&(a, b)| {
            let p = c + r * (a * e1 + b * e2);
            format!("[{:?}, {:?}, {:?}]", p.x, p.y, p.z)
        })
        .collect();
    format!(
        r#"{{"type": "nurbs", "degree": 2, "points": [{}], "weights": [1, {w:?}, 1, {w:?}, 1, {w:?}, 1, {w:?}, 1], "knots": [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]}}"#,
        points.join(", ")
    )
}

fn segment(a: [f64; 3], b: [f64; 3]) -> String {
    format!(r#"{{"type": "bezier", "points": [{a:?}, {b:?}]}}"#)
}

fn ruled(text: &str) -> std::sync::Arc<RuledSurface> {
    let s = json::from_str(text).unwrap_or_else(|e| panic!("{text}: {e}"));
    match s.kind() {
        NodeKind::Primitive(Primitive::RuledSurface(r)) => r.clone(),
        other => panic!("{}", other.name()),
    }
}

fn node(first: &str, second: &str, rest: &str) -> String {
    format!(r#"{{"type": "ruled_surface", "first": {first}, "second": {second}{rest}}}"#)
}

#[test]
fn two_parallel_congruent_circles_in_any_plane_give_a_cylinder() {
    // Radius 0.5 in the planes x = 0 and x = 2: a cylinder along x of volume π r² h.
    let (r, h) = (0.5, 2.0);
    let c1 = circle(DVec3::ZERO, DVec3::Y, DVec3::Z, r);
    let c2 = circle(DVec3::new(h, 0.0, 0.0), DVec3::Y, DVec3::Z, r);
    let exact = PI * r * r * h;
    for samples in [64, 128, 512] {
        let s = ruled(&node(&c1, &c2, &format!(r#", "samples": {samples}"#)));
        let e = s.field_error();
        // The rulings are parallel: no twist, the error is the chord error of the circle.
        assert!(
            e > 0.0 && e < r * (2.0 * PI / samples as f64).powi(2),
            "{samples}: {e}"
        );
        let v = s.volume().unwrap();
        // Inscribed: the section loses at most perimeter × chord error.
        assert!(
            v < exact && exact - v <= 2.0 * PI * r * e * h,
            "{samples}: {v} vs {exact}"
        );
        // The field: the distance to the tessellated cylinder.
        assert!((s.value(DVec3::new(1.0, 0.0, 0.0)) + r).abs() <= e);
        assert!((s.value(DVec3::new(1.0, 0.0, 0.8)) - (0.8 - r)).abs() <= e);
        assert!((s.value(DVec3::new(-0.3, 0.0, 0.0)) - 0.3).abs() < 1e-12);
        let g = s.gradient(DVec3::new(2.5, 0.1, 0.0));
        assert!(g.distance(DVec3::X) < 1e-9, "{g}");
    }
    // The same cylinder given with the circles swapped or its first circle reversed keeps its
    // volume (the orientation is found, not assumed).
    let swapped = ruled(&node(&c2, &c1, ""));
    let reversed = circle(DVec3::ZERO, DVec3::Z, DVec3::Y, r);
    let twisted = ruled(&node(
        &reversed,
        &circle(DVec3::new(h, 0.0, 0.0), DVec3::Z, DVec3::Y, r),
        "",
    ));
    let base = ruled(&node(&c1, &c2, "")).volume().unwrap();
    assert!((swapped.volume().unwrap() - base).abs() < 1e-12);
    assert!((twisted.volume().unwrap() - base).abs() < 1e-12);
}

#[test]
fn the_notes_cone_has_its_apex_at_the_point() {
    // s(u, v) = (1 − v) p + v c₂(u), p = 0, c₂ = (cos u, 3, sin u): a cone of volume π r² h / 3.
    let apex = r#"{"type": "bezier", "points": [[0, 0, 0]]}"#;
    let c2 = circle(DVec3::new(0.0, 3.0, 0.0), DVec3::X, DVec3::Z, 1.0);
    let s = ruled(&node(apex, &c2, r#", "samples": 256"#));
    let exact = PI * 3.0 / 3.0;
    let v = s.volume().unwrap();
    assert!(
        v < exact && exact - v <= 2.0 * PI * s.field_error() * 3.0,
        "{v} vs {exact}"
    );
    assert!(s.value(DVec3::ZERO).abs() < 1e-12);
    assert!(s.value(DVec3::new(0.0, 2.0, 0.0)) < 0.0);
    assert!(s.value(DVec3::new(0.0, -0.5, 0.0)) > 0.49);
    let p = s.surface_point(0.3, 0.5);
    assert!(s.value(p).abs() <= s.field_error());
}

#[test]
fn open_curves_with_a_thickness_give_a_rounded_sheet() {
    // Two parallel segments: the flat rectangle [0, 2] × [0, 1] in z = 0, thickened to 0.2.
    let s = ruled(&node(
        &segment([0.0, 0.0, 0.0], [2.0, 0.0, 0.0]),
        &segment([0.0, 1.0, 0.0], [2.0, 1.0, 0.0]),
        r#", "thickness": 0.2"#,
    ));
    assert_eq!(s.volume(), None);
    assert!(s.field_error() < 1e-15);
    for (p, d) in [
        (DVec3::new(1.0, 0.5, 0.0), -0.1),
        (DVec3::new(1.0, 0.5, 0.3), 0.2),
        (DVec3::new(1.0, 0.5, -0.05), -0.05),
        (DVec3::new(3.0, 0.5, 0.0), 0.9),
        (DVec3::new(3.0, 2.0, 0.0), 2f64.sqrt() - 0.1),
    ] {
        assert!((s.value(p) - d).abs() < 1e-12, "{p}: {} vs {d}", s.value(p));
    }
    let b = s.bbox();
    assert!(b.min.distance(DVec3::new(-0.1, -0.1, -0.1)) < 1e-12);
    assert!(b.max.distance(DVec3::new(2.1, 1.1, 0.1)) < 1e-12);
    // A twisted pair (a hyperbolic paraboloid, z = x y on the unit square): the strips are cut
    // along v so the tessellation stays within its stated error of the exact surface.
    let s = ruled(&node(
        &segment([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
        &segment([0.0, 1.0, 0.0], [1.0, 1.0, 1.0]),
        r#", "thickness": 0.1, "samples": 16"#,
    ));
    let e = s.field_error();
    assert!(e > 0.0 && e < 2e-3, "{e}");
    for (u, v) in [(0.5, 0.5), (0.31, 0.77), (0.9, 0.1)] {
        let p = s.surface_point(u, v);
        assert!((p.z - p.x * p.y).abs() < 1e-12);
        assert!((s.value(p) + 0.05).abs() <= e, "{p}: {}", s.value(p));
    }
}

#[test]
fn nodes_round_trip_and_errors_are_located() {
    let c1 = circle(DVec3::ZERO, DVec3::X, DVec3::new(0.0, 0.6, 0.8), 1.0);
    let c2 = circle(
        DVec3::new(0.0, -0.8, 0.6),
        DVec3::X,
        DVec3::new(0.0, 0.6, 0.8),
        0.5,
    );
    for rest in [
        "",
        r#", "samples": 40"#,
        r#", "thickness": 0.05, "samples": 200"#,
    ] {
        let text = node(&c1, &c2, rest);
        let s = json::from_str(&text).unwrap();
        let written = json::to_string(&s);
        let back = json::from_str(&written).unwrap();
        assert!(back == s, "{written}");
        assert_eq!(json::to_string(&back), written);
    }
    let open = segment([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    let bent = r#"{"type": "bezier", "points": [[1, 0, 0], [0, 1, 1], [-1, 0, 0], [0, -1, 1], [1, 0, 0]]}"#;
    let cases = [
        (node(&open, &c2, ""), "first: the curve must be closed"),
        (
            node(bent, &c2, ""),
            "first: a closed curve must lie in a plane",
        ),
        (node(&c1, &c2, r#", "samples": 2"#), "samples"),
        (node(&c1, &c2, r#", "samples": 10.5"#), "samples"),
        (node(&c1, &c2, r#", "thickness": -1"#), "thickness"),
        (node(&c1, &c2, r#", "height": 1"#), "unknown key \"height\""),
        (node(&c1, &c1, ""), "encloses no volume"),
        (
            format!(r#"{{"type": "ruled_surface", "first": {c1}}}"#),
            "missing key \"second\"",
        ),
    ];
    for (text, expected) in cases {
        let e = match json::from_str(&text) {
            Ok(_) => panic!("{expected}: read without error"),
            Err(e) => e.to_string(),
        };
        assert!(e.contains(expected), "{expected}: {e}");
    }
    // A non-plane closed curve is fine with a thickness.
    assert!(json::from_str(&node(bent, &c2, r#", "thickness": 0.1"#)).is_ok());
}

#[test]
fn capped_and_thickened_ruled_surfaces_conform() {
    let c1 = circle(DVec3::new(-0.6, 0.0, 0.0), DVec3::Y, DVec3::Z, 0.5);
    let c2 = circle(
        DVec3::new(0.6, 0.1, 0.0),
        DVec3::Y,
        DVec3::new(0.0, 0.6, 0.8),
        0.4,
    );
    crate::primitive::conformance::check_shape(&*ruled(&node(&c1, &c2, r#", "samples": 48"#)), 1.5);
    let saddle = node(
        &segment([-0.5, -0.5, 0.0], [0.5, -0.5, 0.0]),
        &segment([-0.5, 0.5, 0.0], [0.5, 0.5, 1.0]),
        r#", "thickness": 0.1, "samples": 24"#,
    );
    crate::primitive::conformance::check_shape(&*ruled(&saddle), 1.5);
}
