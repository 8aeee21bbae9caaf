//! `projection()` against the User Manual: `cut = true` is the slice at z = 0, `cut = false` the
//! union of the children projected onto the plane; both are 2D shapes for extrusions.

use super::{Facets, import_with_warnings};
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

/// Meshes `text`: closed, `shells` shells, the given volume within `tolerance`.
fn check(text: &str, shells: usize, volume: f64, tolerance: f64) {
    let (s, w) = solid(text);
    assert!(w.is_empty(), "{w:?}");
    let (m, report) = mesh(&s, 160);
    assert_eq!(report.boundary_edges, 0, "{text}");
    assert_eq!(report.non_manifold_edges, 0, "{text}");
    assert_eq!(report.shells, shells, "{text}");
    let v = signed_volume(&m);
    assert!(
        rel_err(v, volume) < tolerance,
        "{text}: volume {v} vs {volume}"
    );
}

#[test]
fn cut_of_a_sphere_is_its_great_disc() {
    check(
        "linear_extrude(height = 1) projection(cut = true) sphere(r = 5);",
        1,
        25.0 * PI,
        0.01,
    );
}

#[test]
fn cut_through_a_face_in_the_plane_is_the_face() {
    // The slice is closed: the cube's bottom face lies at z = 0.
    check(
        "linear_extrude(height = 1) projection(cut = true) cube(size = [3, 4, 5]);",
        1,
        12.0,
        0.005,
    );
    // Below the plane: nothing (the extrusion is empty, the other child remains).
    let (s, _) = solid(
        "linear_extrude(height = 1) projection(cut = true) \
         multmatrix([[1,0,0,0],[0,1,0,0],[0,0,1,1],[0,0,0,1]]) cube(1); cube(2);",
    );
    assert_eq!(s.bbox().max.x, 2.0);
}

#[test]
fn cut_keeps_holes() {
    check(
        "linear_extrude(height = 2) projection(cut = true) difference() { \
         cube(size = [10, 10, 10], center = true); cylinder(h = 20, r = 2, center = true); }",
        1,
        2.0 * (100.0 - 4.0 * PI),
        0.005,
    );
}

#[test]
fn shadow_of_a_lying_cylinder_is_a_rectangle() {
    // rotate([90, 0, 0]): the axis along y, 10 long, radius 2 → a 4 × 10 rectangle.
    check(
        "linear_extrude(height = 1) projection(cut = false) \
         multmatrix([[1,0,0,0],[0,0,-1,0],[0,1,0,0],[0,0,0,1]]) \
         cylinder(h = 10, r = 2, center = true);",
        1,
        40.0,
        0.005,
    );
}

#[test]
fn shadow_of_separate_parts_is_separate_regions() {
    check(
        "linear_extrude(height = 1) projection() group() { sphere(r = 2); \
         multmatrix([[1,0,0,10],[0,1,0,0],[0,0,1,7],[0,0,0,1]]) sphere(r = 3); }",
        2,
        13.0 * PI,
        0.01,
    );
}

#[test]
fn shadow_of_a_ring_has_its_hole() {
    // A torus-like ring lying flat: the shadow is an annulus 2..4.
    check(
        "linear_extrude(height = 1) projection() rotate_extrude() \
         multmatrix([[1,0,0,3],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) circle(r = 1);",
        1,
        12.0 * PI,
        0.01,
    );
}

#[test]
fn a_projection_revolves_like_any_profile() {
    // The slice of a unit sphere moved to x = 5, revolved: a torus.
    check(
        "rotate_extrude() projection(cut = true) \
         multmatrix([[1,0,0,5],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) sphere(r = 1);",
        1,
        2.0 * PI * PI * 5.0,
        0.01,
    );
}

#[test]
fn two_d_children_are_ignored_with_a_warning() {
    let (_, w) = solid("projection() square(1); cube(1);");
    assert_eq!(w, ["1:1: ignoring 2D child object for projection"]);
}

#[test]
fn shadow_of_openscad_facets_uses_their_faces() {
    // A $fn = 4 cylinder lying along y has corners at x = ±3: a 6 × 10 rectangle, from the
    // polyhedron's own faces (no meshing), so only the grid's corner cuts differ.
    let text = "linear_extrude(height = 1) projection() \
                multmatrix([[1,0,0,0],[0,0,-1,0],[0,1,0,0],[0,0,0,1]]) \
                cylinder(h = 10, r = 3, center = true, $fn = 4);";
    let (s, _) = import_with_warnings(text, Facets::OpenScad, &NoMeshResolver).unwrap();
    let (m, report) = mesh(&s, 160);
    assert_eq!(report.boundary_edges, 0);
    let v = signed_volume(&m);
    assert!(rel_err(v, 60.0) < 0.002, "{v}");
}
