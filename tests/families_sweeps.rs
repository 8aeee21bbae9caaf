//! Acceptance of the sweep family (issue 5) at resolution 128: every fixture under
//! `fixtures/sweeps/` meshes to a closed, oriented manifold with the expected shells and genus and
//! a volume within 1% of its exact value; and the parametric tessellations are closed manifolds
//! with the stated vertex and triangle counts whose volumes converge to the exact ones.
//!
//! Exact volumes: Pappus's theorem for revolutions and the torus sweep; prism volume `A·h` for
//! twisted extrusions (a twist keeps every slice's area); `A·h·(1 + s + s²)/3` for a scaled one;
//! `πr²h/3` and `πr²h` for the ruled cone and cylinder (and `ruled_surface` cylinders in any
//! plane; Steiner's formula for a thickened flat sheet); the prismatoid formula for the loft (its
//! slice area is quadratic in height, so Simpson's rule is exact); `A·L` for tubes along open
//! curves, with the curve length `L` by 24-point Gauss–Legendre quadrature on nearly straight spans
//! (`solidkit_kernel::curve::arc_length`, relative error ~1e-14), since a spline has no closed form.

use glam::{DVec2, DVec3};
use solidkit_kernel::curve::{Curve, Nurbs, arc_length};
use solidkit_kernel::primitive::sweep::signed_volume;
use solidkit_kernel::primitive::{Extrude, Revolve, Sweep};
use solidkit_kernel::profile::{Circle, Profile};
use solidkit_kernel::{IndexedMesh, NodeKind, Primitive};
use solidkit_meshing::TopologyReport;
use solidkit_tests::{load_tree, mesh, rel_err};
use std::f64::consts::{PI, TAU};

const RESOLUTION: usize = 128;

/// Meshes a fixture and checks topology and volume.
fn check(fixture: &str, shells: usize, genus: i64, exact: f64) -> TopologyReport {
    let solid = load_tree(&format!("sweeps/{fixture}"));
    let (_, r) = mesh(&solid, RESOLUTION);
    assert!(r.is_closed_manifold(), "{fixture}: {r:?}");
    assert_eq!(r.shells, shells, "{fixture}: shells");
    assert_eq!(r.genus, Some(genus), "{fixture}: genus");
    assert!(
        rel_err(r.volume, exact) < 0.01,
        "{fixture}: volume {} vs exact {exact} ({:.3}%)",
        r.volume,
        100.0 * rel_err(r.volume, exact)
    );
    println!(
        "{fixture}: volume {:.6} exact {exact:.6} error {:.3}%",
        r.volume,
        100.0 * rel_err(r.volume, exact)
    );
    r
}

/// The primitive at the root of a fixture.
fn root(fixture: &str) -> Primitive {
    match load_tree(&format!("sweeps/{fixture}")).kind() {
        NodeKind::Primitive(p) => p.clone(),
        other => panic!("{fixture}: not a primitive: {}", other.name()),
    }
}

#[test]
fn extrusion_with_a_hole_is_a_genus_one_prism() {
    check("extrude_holed.json", 1, 1, (1.44 - 0.16) * 1.0);
}

#[test]
fn twisted_extrusion_keeps_the_prism_volume() {
    check("extrude_twisted.json", 1, 0, 1.0 * 0.5 * 1.5);
}

#[test]
fn twisted_scaled_extrusion_has_the_frustum_volume() {
    let (a, h, s) = (0.6, 1.2, 0.5);
    check(
        "extrude_twisted_scaled.json",
        1,
        0,
        a * h * (1.0 + s + s * s) / 3.0,
    );
}

#[test]
fn anisotropically_scaled_extrusion_has_its_volume_and_round_trips() {
    let (a, b) = (0.4 - 1.0, 1.5 - 1.0);
    let r = check(
        "extrude_anisotropic.json",
        1,
        0,
        0.6 * 1.2 * (1.0 + (a + b) / 2.0 + a * b / 3.0),
    );
    // The top face is 0.4 x 0.9, turned by 40 degrees.
    let top = r.bbox[1][2];
    assert!((top - 0.6).abs() < 0.02, "top at {top}");
    let solid = load_tree("sweeps/extrude_anisotropic.json");
    let text = solidkit_kernel::json::to_string(&solid);
    assert!(text.contains("[0.4, 1.5]"), "{text}");
    assert_eq!(solidkit_kernel::json::from_str(&text).unwrap(), solid);
}

/// OpenSCAD's `scale = [0, 1]`: a wedge whose top slice is a segment (a thin feature along the
/// whole top edge), half the prism's volume, its ridge at the full height.
#[test]
fn extrusion_scaled_to_zero_along_one_axis_is_a_wedge() {
    let r = check("extrude_wedge.json", 1, 0, 0.6 * 1.2 / 2.0);
    let top = r.bbox[1][2];
    assert!((top - 0.6).abs() < 0.02, "ridge at {top}");
}

#[test]
fn revolution_of_an_off_axis_circle_is_a_torus() {
    check("revolve_torus.json", 1, 1, TAU * 1.0 * PI * 0.35 * 0.35);
}

/// The same torus in six straight steps: a ring of six bent tubes, the volume of Pappus's
/// theorem with `6 sin 60° = 3√3` for `2π`, and the corners of the hexagonal rings on its
/// surface.
#[test]
fn faceted_revolution_is_a_ring_of_straight_steps() {
    let exact = 3.0 * 3f64.sqrt() * 1.0 * PI * 0.35 * 0.35;
    check("revolve_faceted.json", 1, 1, exact);
    let Primitive::Revolve(r) = root("revolve_faceted.json") else {
        panic!("not a revolution");
    };
    assert_eq!(r.segments(), Some((6, 0.0)));
    assert!(rel_err(r.volume(), exact) < 1e-12);
    use solidkit_kernel::primitive::Shape;
    for j in 0..6 {
        let a = TAU * f64::from(j) / 6.0;
        assert!(
            r.value(DVec3::new(1.35 * a.cos(), 1.35 * a.sin(), 0.0))
                .abs()
                < 1e-12
        );
    }
}

#[test]
fn partial_revolution_is_closed_by_its_end_faces() {
    check(
        "revolve_partial.json",
        1,
        0,
        1.5 * PI * 1.0 * PI * 0.3 * 0.3,
    );
}

/// The cup: a cylinder of radius 0.8 and height 1.1 less the cylinder of radius 0.65 and height
/// 0.9 above z = −0.3.
fn cup_volume() -> f64 {
    PI * (0.8 * 0.8 * 1.1 - 0.65 * 0.65 * 0.9)
}

#[test]
fn revolution_of_a_profile_on_the_axis_is_a_cup() {
    check("revolve_cup.json", 1, 0, cup_volume());
    check("revolve_cup_partial.json", 1, 0, cup_volume() / 3.0);
}

#[test]
fn circle_swept_along_a_nurbs_circle_is_the_torus() {
    check("sweep_torus.json", 1, 1, 2.0 * PI * PI * 1.0 * 0.3 * 0.3);
}

#[test]
fn tube_along_a_helix_has_volume_area_times_length() {
    let Primitive::Sweep(s) = root("sweep_helix.json") else {
        panic!("not a sweep")
    };
    let length = arc_length(s.path());
    // The spline through 16 points per turn is close to the helix it samples.
    let helix = 2.0 * ((TAU * 0.8f64).powi(2) + 0.36).sqrt();
    assert!(rel_err(length, helix) < 1e-3, "{length} vs {helix}");
    check("sweep_helix.json", 1, 0, PI * 0.12 * 0.12 * length);
}

#[test]
fn rectangle_swept_along_a_bezier_curve_has_volume_area_times_length() {
    let Primitive::Sweep(s) = root("sweep_square_bezier.json") else {
        panic!("not a sweep")
    };
    check(
        "sweep_square_bezier.json",
        1,
        0,
        0.3 * 0.2 * arc_length(s.path()),
    );
}

#[test]
fn ruled_cone_with_an_apex_and_oblique_cylinder() {
    check("ruled_cone.json", 1, 0, PI * 0.64 * 1.2 / 3.0);
    check("ruled_cylinder.json", 1, 0, PI * 0.36 * 1.2);
}

/// Shoelace area of a polygon.
#[test]
fn ruled_surfaces_in_any_plane_and_thickened_mesh_to_their_volumes() {
    // Two circles of radius 0.5 in the planes x = ±1: a cylinder along x. These fields measure
    // the distance to a tessellation through a BVH (microseconds a sample), so they mesh at 96.
    let r = check_bounds("ruled_surface_cylinder_x.json");
    let exact = PI * 0.25 * 2.0;
    assert!(rel_err(r.volume, exact) < 0.01, "{} vs {exact}", r.volume);
    // The saddle z = xy over the unit square thickened to 2r: the tube formula, 2rA + (π/2) r² P
    // + (4/3) π r³ with the saddle's area A = ∫∫ √(1 + x² + y²) = 1.2807893 and its rim
    // P = 2 + 2√2, up to curvature terms of order r³ (below 10⁻³ of it).
    let r = check_bounds("ruled_surface_saddle.json");
    let (rr, saddle_area, rim) = (0.05, 1.280_789_3, 2.0 + 2.0 * 2f64.sqrt());
    let tube = 2.0 * rr * saddle_area + 0.5 * PI * rr * rr * rim + 4.0 / 3.0 * PI * rr.powi(3);
    assert!(rel_err(r.volume, tube) < 0.015, "{} vs {tube}", r.volume);
    // A flat 2 × 1 rectangle between two segments thickened to 2r: Steiner's formula,
    // 2rA + (π/2) r² P + (4/3) π r³.
    let text = r#"{"type": "ruled_surface", "thickness": 0.2,
        "first": {"type": "bezier", "points": [[0, 0, 0], [2, 0, 0]]},
        "second": {"type": "bezier", "points": [[0, 1, 0], [2, 1, 0]]}}"#;
    let solid = solidkit_kernel::json::from_str(text).unwrap();
    let (_, r) = mesh(&solid, RESOLUTION);
    assert!(
        r.is_closed_manifold() && r.shells == 1 && r.genus == Some(0),
        "{r:?}"
    );
    let rr = 0.1;
    let exact = 2.0 * rr * 2.0 + 0.5 * PI * rr * rr * 6.0 + 4.0 / 3.0 * PI * rr.powi(3);
    assert!(rel_err(r.volume, exact) < 0.01, "{} vs {exact}", r.volume);
}

/// The resolution of the `ruled_surface` tests.
const RULED_RESOLUTION: usize = 96;

/// Meshes a fixture at [`RULED_RESOLUTION`]: one closed shell of genus 0; the report.
fn check_bounds(fixture: &str) -> TopologyReport {
    let solid = load_tree(&format!("sweeps/{fixture}"));
    let (_, r) = mesh(&solid, RULED_RESOLUTION);
    assert!(
        r.is_closed_manifold() && r.shells == 1 && r.genus == Some(0),
        "{fixture}: {r:?}"
    );
    r
}

fn area(points: &[DVec2]) -> f64 {
    let n = points.len();
    0.5 * (0..n)
        .map(|i| points[i].perp_dot(points[(i + 1) % n]))
        .sum::<f64>()
        .abs()
}

#[test]
fn loft_between_squares_has_the_prismatoid_volume() {
    let bottom: Vec<DVec2> = [(-0.7, -0.7), (0.7, -0.7), (0.7, 0.7), (-0.7, 0.7)]
        .map(|(x, y)| DVec2::new(x, y))
        .to_vec();
    let top: Vec<DVec2> = bottom
        .iter()
        .map(|p| DVec2::from_angle(PI / 4.0).rotate(*p * 0.5))
        .collect();
    let middle: Vec<DVec2> = bottom
        .iter()
        .zip(&top)
        .map(|(a, b)| a.lerp(*b, 0.5))
        .collect();
    let exact = 1.2 / 6.0 * (area(&bottom) + 4.0 * area(&middle) + area(&top));
    check("loft_squares.json", 1, 0, exact);
}

/// Topology of a tessellation: closed, oriented, manifold, one shell of the given genus.
fn check_tessellation(name: &str, m: &IndexedMesh, genus: i64) -> TopologyReport {
    let r = TopologyReport::of(m);
    assert!(r.is_closed_manifold(), "{name}: {r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(genus)), "{name}");
    assert_eq!(r.degenerate_faces, 0, "{name}");
    assert!(r.volume > 0.0, "{name}: inward winding");
    r
}

/// Relative volume errors of tessellations at increasing resolutions: each at most half the
/// previous (second-order convergence gives a quarter) and the last below `last`.
fn check_convergence(name: &str, errors: &[f64], last: f64) {
    for w in errors.windows(2) {
        assert!(w[1] < 0.5 * w[0], "{name}: errors {errors:?}");
    }
    assert!(*errors.last().unwrap() < last, "{name}: errors {errors:?}");
    println!("{name}: relative volume errors {errors:?}");
}

#[test]
fn revolution_tessellations_are_closed_with_grid_counts() {
    let torus = Revolve::new(
        Profile::Circle(Circle {
            center: DVec2::new(1.0, 0.0),
            radius: 0.35,
        }),
        360.0,
    )
    .unwrap();
    let exact = TAU * PI * 0.35 * 0.35;
    let mut errors = Vec::new();
    for n in [8, 16, 32, 64, 128] {
        let m = torus.tessellate(n, 2 * n).unwrap();
        // m·n vertices and 2mn triangles: the doubly periodic grid of a torus.
        assert_eq!(
            (m.vertex_count(), m.triangle_count()),
            (2 * n * n, 4 * n * n)
        );
        check_tessellation("torus", &m, 1);
        errors.push(rel_err(signed_volume(&m), exact));
    }
    check_convergence("revolved torus", &errors, 1e-3);
    // Profile corners on the axis become poles: the cup has 4 off-axis corners and 2 on it; its
    // 3 edges off the axis give 2 triangles per step, the 2 edges ending on it 1 (a fan), the
    // edge along the axis none.
    let Primitive::Revolve(cup) = root("revolve_cup.json") else {
        panic!("not a revolve")
    };
    let mut errors = Vec::new();
    for steps in [16, 32, 64, 128] {
        let m = cup.tessellate(3, steps).unwrap();
        assert_eq!(
            (m.vertex_count(), m.triangle_count()),
            (4 * steps + 2, 2 * 3 * steps + 2 * steps)
        );
        check_tessellation("cup", &m, 0);
        errors.push(rel_err(signed_volume(&m), cup_volume()));
    }
    check_convergence("revolved cup", &errors, 1e-3);
    // A partial revolution: m stations of 6 corners, caps of 6 − 2 triangles each; the two axis
    // corners are shared by all stations.
    let Primitive::Revolve(slice) = root("revolve_cup_partial.json") else {
        panic!("not a revolve")
    };
    let m = slice.tessellate(3, 33).unwrap();
    assert_eq!(
        (m.vertex_count(), m.triangle_count()),
        (4 * 33 + 2, 2 * 3 * 32 + 2 * 32 + 2 * 4)
    );
    check_tessellation("cup slice", &m, 0);
    assert!(rel_err(signed_volume(&m), cup_volume() / 3.0) < 1e-3);
}

#[test]
fn sweep_and_extrusion_tessellations_are_closed_with_grid_counts() {
    let torus = Sweep::new(
        Profile::circle(0.3).unwrap(),
        Curve::Nurbs(Nurbs::circle(DVec3::ZERO, 1.0).unwrap()),
    )
    .unwrap();
    let exact = 2.0 * PI * PI * 0.09;
    let mut errors = Vec::new();
    for n in [8, 16, 32, 64] {
        let m = torus.tessellate(n, 2 * n).unwrap();
        assert_eq!(
            (m.vertex_count(), m.triangle_count()),
            (2 * n * n, 4 * n * n)
        );
        check_tessellation("swept torus", &m, 1);
        errors.push(rel_err(signed_volume(&m), exact));
    }
    check_convergence("swept torus", &errors, 3e-3);
    // Open tube with caps: stations × segments vertices, 2(s − 1)n + 2(n − 2) triangles.
    let Primitive::Sweep(helix) = root("sweep_helix.json") else {
        panic!("not a sweep")
    };
    let exact = PI * 0.12 * 0.12 * arc_length(helix.path());
    let mut errors = Vec::new();
    for n in [8, 16, 32, 64] {
        let stations = 16 * n;
        let m = helix.tessellate(n, stations).unwrap();
        assert_eq!(
            (m.vertex_count(), m.triangle_count()),
            (stations * n, 2 * (stations - 1) * n + 2 * (n - 2))
        );
        check_tessellation("helix tube", &m, 0);
        errors.push(rel_err(signed_volume(&m), exact));
    }
    check_convergence("helix tube", &errors, 2e-3);
    // A twisted, scaled extrusion of a square with a hole: genus 1.
    let sq = |c: DVec2, h: f64| {
        vec![
            c + DVec2::new(-h, -h),
            c + DVec2::new(h, -h),
            c + DVec2::new(h, h),
            c + DVec2::new(-h, h),
        ]
    };
    let holed =
        Profile::polygon(sq(DVec2::ZERO, 0.6), vec![sq(DVec2::new(0.15, 0.0), 0.2)]).unwrap();
    let e = Extrude::new(holed, 1.0, 90.0, 0.6).unwrap();
    let mut errors = Vec::new();
    for levels in [4, 8, 16, 32] {
        let m = e.tessellate(3, levels).unwrap();
        assert_eq!(
            (m.vertex_count(), m.triangle_count()),
            ((levels + 1) * 8, 2 * levels * 8 + 2 * (8 + 2 - 2))
        );
        check_tessellation("twisted extrusion", &m, 1);
        errors.push(rel_err(signed_volume(&m), e.volume()));
    }
    check_convergence("twisted extrusion", &errors, 2e-3);
}

#[test]
fn ruled_and_loft_tessellations_are_closed() {
    let Primitive::Ruled(cone) = root("ruled_cone.json") else {
        panic!("not ruled")
    };
    let exact = PI * 0.64 * 1.2 / 3.0;
    let mut errors = Vec::new();
    for n in [16, 32, 64, 128] {
        let m = cone.tessellate(n).unwrap();
        // The apex is one vertex: n + 1 vertices, n side and n − 2 base triangles.
        assert_eq!((m.vertex_count(), m.triangle_count()), (n + 1, 2 * n - 2));
        check_tessellation("ruled cone", &m, 0);
        errors.push(rel_err(signed_volume(&m), exact));
    }
    check_convergence("ruled cone", &errors, 1e-3);
    let Primitive::Loft(loft) = root("loft_squares.json") else {
        panic!("not a loft")
    };
    let m = loft.tessellate(3).unwrap();
    assert_eq!((m.vertex_count(), m.triangle_count()), (8, 2 * 4 + 2 * 2));
    check_tessellation("loft", &m, 0);
    // Straight rulings between polygons: the lateral faces are bilinear patches, and triangles
    // approximate them, so the volume is close to (not exactly) the prismatoid's.
    assert!(rel_err(signed_volume(&m), loft.volume()) < 0.05);
}

#[test]
fn radial_profile_extrusion_has_the_polar_area() {
    // ρ(u) = 1 + 0.3 cos 5u: area ½∫ρ² du = ½(2π + 0.09π) = 1.045π; height 1.
    check("extrude_radial.json", 1, 0, 1.045 * PI);
}

#[test]
fn closed_bezier_profile_revolves_to_its_pappus_volume() {
    use solidkit_kernel::curve::{Curve3, gauss_legendre, integrate};
    // The profile's first moment ∫∫ x dA = ∮ x²/2 dy (Green), on the exact curve piece by piece.
    let pieces = [
        [[0.4, -0.5], [1.4, -0.6], [1.4, 0.6], [0.4, 0.5]],
        [[0.4, 0.5], [0.2, 0.3], [0.2, -0.3], [0.4, -0.5]],
    ];
    let rule = gauss_legendre(24);
    let moment: f64 = pieces
        .iter()
        .map(|p| {
            let points = p.iter().map(|q| DVec3::new(q[0], q[1], 0.0)).collect();
            let b = solidkit_kernel::curve::Bezier::new(points).unwrap();
            integrate(&rule, 0.0, 1.0, |t| {
                let j = b.jet(t);
                0.5 * j.point.x * j.point.x * j.d1.y
            })
        })
        .sum();
    check("revolve_bezier_profile.json", 1, 1, TAU * moment.abs());
}

#[test]
fn loft_between_sampled_radial_profiles_has_the_prismatoid_volume() {
    // 200 corners each at u = 2πk/200: ρ(u)(cos u, sin u); the loft joins corner k to corner k.
    let corners = |rho: &dyn Fn(f64) -> f64| -> Vec<DVec2> {
        (0..200)
            .map(|k| {
                let u = TAU * k as f64 / 200.0;
                DVec2::from_angle(u) * rho(u)
            })
            .collect()
    };
    let bottom = corners(&|u| 1.0 + 0.3 * (5.0 * u).cos());
    let top = corners(&|u| 0.6 - 0.1 * (5.0 * u).cos());
    let middle: Vec<DVec2> = bottom
        .iter()
        .zip(&top)
        .map(|(a, b)| a.lerp(*b, 0.5))
        .collect();
    let exact = 1.2 / 6.0 * (area(&bottom) + 4.0 * area(&middle) + area(&top));
    check("loft_radial.json", 1, 0, exact);
}
