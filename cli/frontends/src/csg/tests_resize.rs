//! `resize()` against the User Manual: the children's bounding box gets the new size (scaled
//! about the origin), 0 keeps an axis unless `auto`, 2D children use x and y.

use super::{Facets, import_with_warnings};
use glam::DVec3;
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::NoMeshResolver;
use solidkit_kernel::primitive::sweep::signed_volume;
use solidkit_tests::{mesh, rel_err};
use std::f64::consts::PI;

fn solid(text: &str) -> (Solid, Vec<String>) {
    let (s, w) = import_with_warnings(text, Facets::Exact, &NoMeshResolver)
        .unwrap_or_else(|e| panic!("{text}: {e}"));
    s.validate().unwrap_or_else(|e| panic!("{text}: {e}"));
    (s, w.iter().map(|w| w.to_string()).collect())
}

/// Meshes `text` and checks its volume and bounding box.
fn check(text: &str, volume: f64, min: DVec3, max: DVec3) {
    let (s, w) = solid(text);
    assert!(w.is_empty(), "{w:?}");
    let (m, report) = mesh(&s, 160);
    assert_eq!(report.boundary_edges, 0, "{text}");
    let v = signed_volume(&m);
    assert!(rel_err(v, volume) < 0.01, "{text}: volume {v} vs {volume}");
    let (lo, hi) = m.positions.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let tol = 0.01 * (max - min).max_element();
    assert!(
        (lo - min).abs().max_element() < tol && (hi - max).abs().max_element() < tol,
        "{text}: box {lo} {hi} vs {min} {max}"
    );
}

#[test]
fn auto_scales_a_sphere_uniformly() {
    check(
        "resize(newsize = [10,0,0], auto = [1,1,1], convexity = 0) { sphere(r = 1); }",
        4.0 / 3.0 * PI * 125.0,
        DVec3::splat(-5.0),
        DVec3::splat(5.0),
    );
}

#[test]
fn each_axis_to_its_size_about_the_origin() {
    // Scaling is about the origin: the box from x = 1 to 2 goes to 4 to 8.
    check(
        "resize(newsize = [4,5,6], auto = [0,0,0]) { \
         multmatrix([[1,0,0,1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(size = [1, 2, 3]); }",
        120.0,
        DVec3::new(4.0, 0.0, 0.0),
        DVec3::new(8.0, 5.0, 6.0),
    );
    // 0 keeps the axis; auto only on z follows the largest new size (x: 4 / 1).
    check(
        "resize(newsize = [4,0,0], auto = [0,0,1]) { cube(size = [1, 2, 3]); }",
        4.0 * 2.0 * 12.0,
        DVec3::ZERO,
        DVec3::new(4.0, 2.0, 12.0),
    );
}

#[test]
fn a_two_d_child_is_resized_in_x_and_y() {
    // An ellipse with semi-axes 5 and 10 (a 360-gon), extruded by 1.
    check(
        "linear_extrude(height = 1) resize(newsize = [10,20,0], auto = [0,0,0]) \
         circle(r = 1, $fn = 360);",
        50.0 * PI * (2.0 * PI / 360.0).sin() * 360.0 / (2.0 * PI),
        DVec3::new(-5.0, -10.0, 0.0),
        DVec3::new(5.0, 10.0, 1.0),
    );
}

#[test]
fn the_box_of_a_difference_is_its_geometry_not_its_first_operand() {
    // The tree's box is the 10-wide cube; the solid is 5 wide, so x scales by 4.
    check(
        "resize(newsize = [20,0,0]) difference() { cube(size = [10, 10, 10]); \
         multmatrix([[1,0,0,5],[0,1,0,-1],[0,0,1,-1],[0,0,0,1]]) cube(size = [6, 12, 12]); }",
        2000.0,
        DVec3::ZERO,
        DVec3::new(20.0, 10.0, 10.0),
    );
}

#[test]
fn a_rotated_faceted_cylinder_uses_its_vertices() {
    // OpenSCAD's cylinder with $fn = 4 is a square prism with corners on the axes; rotated by 45°
    // about z its box is the corners' box: side √2·r·… → resized to 2 × 2 × 2.
    let text = "resize(newsize = [2,2,2]) multmatrix([[0.7071067811865476,-0.7071067811865476,0,0],\
                [0.7071067811865476,0.7071067811865476,0,0],[0,0,1,0],[0,0,0,1]]) \
                cylinder(h = 1, r = 1, $fn = 4);";
    let (s, _) = import_with_warnings(text, Facets::OpenScad, &NoMeshResolver).unwrap();
    let b = super::bounds::tight_bbox(&s).expect("exact");
    assert!(
        (b.size() - DVec3::splat(2.0)).abs().max_element() < 1e-9,
        "{b:?}"
    );
}

#[test]
fn non_finite_sizes_warn_and_remove_the_object() {
    let (_, w) = solid(
        "linear_extrude(height = 1) resize(newsize = [inf, 1, 0]) square(size = [1, 1]); cube(1);",
    );
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("inf or nan"), "{w:?}");
}
