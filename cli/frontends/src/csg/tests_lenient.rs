//! OpenSCAD's lenient rules for parts it cannot build (OpenSCAD 2021.01, checked against its own
//! renders in the cross-check's test-data run): each such part is skipped with a located warning
//! and the rest of the model is kept; a profile on the negative side of the axis is swept as
//! OpenSCAD sweeps it; `$fn = inf` means three fragments.

use super::Facets;
use super::tests::{only_the_cube_is_kept, warned};
use glam::DVec3;
use solidkit_kernel::primitive::sweep::signed_volume;
use solidkit_tests::{mesh, rel_err};
use std::f64::consts::PI;

/// Parts OpenSCAD renders as nothing: a polyhedron without faces or with points that are not
/// 3-vectors, an extrusion of height 0 or less, a sweep of angle 0, and a profile that crosses
/// the axis of `rotate_extrude`.
#[test]
fn parts_openscad_renders_as_nothing_are_skipped_with_warnings() {
    let text = "polyhedron(points = [[0, 0, 0], [1, 1, 1]], faces = undef, convexity = 1);\n\
                polyhedron(points = [0], faces = [[0]], convexity = 1);\n\
                linear_extrude(height = 0, center = false) square(size = [1, 1]);\n\
                linear_extrude(height = -2, center = false) square(size = [1, 1]);\n\
                rotate_extrude(angle = 0) multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 1]);\n\
                rotate_extrude(angle = 360) multmatrix([[1, 0, 0, -0.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 1]);\n\
                cube(size = 1, center = true);\n";
    only_the_cube_is_kept(
        text,
        &[
            "1:1: 'faces' is undef: the object is skipped",
            "2:1: 'points': expected a list of points: the object is skipped",
            "3:1: height = 0 is not positive: the object is empty",
            "4:1: height = -2 is not positive: the object is empty",
            "5:1: angle = 0: the object is empty",
            "6:1: all points for rotate_extrude() must have the same X coordinate sign (range is -0.50 -> 0.50): the object is skipped",
        ],
    );
}

/// A profile at x ≤ 0 sweeps where its points go when turned: a square at x in [-5, -4] turned by
/// 45° lies at x ≤ 0 and y ≤ 0, with the volume of its mirror image's sweep.
#[test]
fn rotate_extrude_of_a_profile_left_of_the_axis() {
    let square = "multmatrix([[1, 0, 0, -5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [1, 1]);";
    let (s, w) = warned(
        &format!("rotate_extrude(angle = 45) {square}"),
        Facets::Exact,
    );
    assert!(w.is_empty(), "{w:?}");
    let (m, report) = mesh(&s, 128);
    assert_eq!((report.shells, report.genus), (1, Some(0)));
    let exact = PI / 4.0 * (25.0 - 16.0) / 2.0;
    let v = signed_volume(&m);
    assert!(rel_err(v, exact) < 0.01, "volume {v} vs {exact}");
    let hi = m
        .positions
        .iter()
        .fold(DVec3::NEG_INFINITY, |a, &p| a.max(p));
    let lo = m.positions.iter().fold(DVec3::INFINITY, |a, &p| a.min(p));
    assert!(
        hi.x < 1e-9 - 4.0 * (PI / 4.0).cos() + 0.05 && hi.y < 0.05,
        "{lo} {hi}"
    );
    assert!(
        (lo.x + 5.0).abs() < 0.05 && (lo.y + 5.0 * (PI / 4.0).sin()).abs() < 0.05,
        "{lo}"
    );
    // A full turn: the ring of the mirrored square.
    let (full, _) = warned(&format!("rotate_extrude() {square}"), Facets::Exact);
    let v = signed_volume(&mesh(&full, 128).0);
    assert!(rel_err(v, 8.0 * exact) < 0.01, "volume {v}");
}

/// `$fn = inf` (and nan) gives OpenSCAD's three fragments: a triangular prism.
#[test]
fn infinite_fn_means_three_fragments() {
    let (s, w) = warned(
        "cylinder($fn = inf, $fa = 12, $fs = 2, h = 1, r1 = 1, r2 = 1, center = false);",
        Facets::OpenScad,
    );
    assert!(w.is_empty(), "{w:?}");
    let v = signed_volume(&mesh(&s, 128).0);
    let triangle = 3.0 * 3f64.sqrt() / 4.0;
    assert!(rel_err(v, triangle) < 0.01, "volume {v} vs {triangle}");
}

/// The hull of operands that only touch (an intersection of two cubes meeting at a corner) has
/// nothing to hull: the rest of the model stays.
#[test]
fn hull_of_a_solid_without_volume_is_empty() {
    let text = "hull() { intersection() { cube(size = [1, 1, 1]); \
                multmatrix([[1, 0, 0, -1], [0, 1, 0, -1], [0, 0, 1, -1], [0, 0, 0, 1]]) cube(size = [1, 1, 1]); } }\n\
                cube(size = 2);";
    let (s, _) = warned(text, Facets::Exact);
    let v = signed_volume(&mesh(&s, 64).0);
    assert!(rel_err(v, 8.0) < 0.01, "volume {v}");
}

/// Generated polyhedra repeat their poles: a square pyramid whose apex is listed once per side
/// face (four copies of one point, each side a quad with two apex corners) and a face that is a
/// doubled edge. OpenSCAD renders the pyramid; so does solidkit, closed, with its volume 4/3,
/// one shell, and one warning that names what was merged and dropped.
#[test]
fn a_polyhedron_with_a_repeated_pole_is_the_solid_it_draws() {
    let text = "polyhedron(points = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], \
                [0, 0, 1], [0, 0, 1], [0, 0, 1], [0, 0, 1]], \
                faces = [[0, 1, 2, 3], [1, 0, 4, 5], [2, 1, 5, 6], [3, 2, 6, 7], [0, 3, 7, 4], \
                [1, 2, 2, 1]], convexity = 1);";
    let (s, w) = warned(text, Facets::OpenScad);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("3 repeated points merged") && w[0].contains("1 faces with fewer than 3"),
        "{w:?}"
    );
    let (m, report) = mesh(&s, 96);
    assert!(report.is_closed_manifold(), "{report:?}");
    assert_eq!(report.shells, 1);
    let v = signed_volume(&m);
    assert!(rel_err(v, 4.0 / 3.0) < 0.01, "{v}");
}

/// A polyhedron whose every face collapses encloses nothing: skipped with a warning, the rest is
/// kept.
#[test]
fn a_polyhedron_of_collapsed_faces_is_skipped() {
    let text = "polyhedron(points = [[0, -4, 1], [0, -5, 1], [0, -5, 2], [0, -4, 0]], \
                faces = [[1, 2, 2, 1], [0, 0, 3, 3]], convexity = 1);\n\
                cube(size = 1, center = true);\n";
    only_the_cube_is_kept(
        text,
        &[
            "1:1: polyhedron: 2 faces with fewer than 3 distinct corners dropped, as OpenSCAD does",
            "1:1: polyhedron: no face encloses anything: the object is empty",
        ],
    );
}
