//! Twisted and unevenly scaled `linear_extrude` and partial `rotate_extrude` under
//! `--facets openscad`: OpenSCAD's stack of flat slices (`sliced.rs`) and its straight steps
//! (`turned.rs`), checked against volumes measured on OpenSCAD 2021.01's own renders of the same
//! statements (`openscad -o x.stl`, volume of its closed STL); with exact facets the exact solids.

use super::Facets;
use super::tests::warned;
use solidkit_kernel::primitive::sweep::signed_volume;
use solidkit_tests::{mesh, rel_err};

/// `linear_extrude(...) { body }` as OpenSCAD exports it, with `$fa = 12, $fs = 2`.
fn extrusion(args: &str, body: &str) -> String {
    format!("linear_extrude({args}, convexity = 1, $fn = 0, $fa = 12, $fs = 2) {{ {body} }}")
}

/// `text` under OpenSCAD's facets meshes closed with a volume within `tolerance` of
/// `openscad` (OpenSCAD's render); the volume.
fn meshes_as_openscad(text: &str, openscad: f64, tolerance: f64) -> f64 {
    let (s, w) = warned(text, Facets::OpenScad);
    assert!(w.is_empty(), "{text}: {w:?}");
    let (m, report) = mesh(&s, 128);
    assert!(report.is_closed_manifold(), "{text}: {report:?}");
    let v = signed_volume(&m);
    assert!(
        rel_err(v, openscad) < tolerance,
        "{text}: {v} vs OpenSCAD's {openscad}"
    );
    v
}

#[test]
fn twisted_extrusions_are_openscads_slices() {
    let square = "square(size = [10, 10], center = true);";
    let bar = "multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [6, 3]);";
    let holed = "difference() { square(size = [10, 10], center = true); \
                 multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [4, 4], center = true); }";
    let two = "multmatrix([[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) circle(r = 2, $fn = 0, $fa = 12, $fs = 2); \
               multmatrix([[1, 0, 0, -4], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [3, 3]);";
    let circle = "circle(r = 5, $fn = 0, $fa = 12, $fs = 2);";
    // (arguments, profile, OpenSCAD's volume, the exact solid's volume)
    let cases = [
        ("height = 20, twist = 90", square, 2117.250, 2000.0),
        (
            "height = 20, center = true, twist = -150",
            bar,
            381.578,
            360.0,
        ),
        ("height = 20, twist = 120", holed, 1784.194, 1680.0),
        ("height = 30, twist = 270", two, 605.057, 647.08),
        (
            "height = 20, twist = 200, scale = [0.4, 0.4]",
            "square(size = [10, 6], center = true);",
            679.011,
            0.0,
        ),
        ("height = 20, scale = [0.3, 1.8]", circle, 1317.013, 0.0),
    ];
    for (args, body, openscad, exact) in cases {
        let text = extrusion(args, body);
        let v = meshes_as_openscad(&text, openscad, 0.01);
        if exact > 0.0 {
            // The exact twisted solid is not OpenSCAD's, and exact facets keep it.
            assert!(rel_err(v, exact) > 0.03, "{text}: {v} is the exact {exact}");
            let (s, _) = warned(&text, Facets::Exact);
            let e = signed_volume(&mesh(&s, 128).0);
            assert!(
                rel_err(e, exact) < 0.01,
                "{text}: exact facets {e} vs {exact}"
            );
        }
    }
}

/// A twist so large that OpenSCAD's slices would need billions of vertices is meshed as the exact
/// twisted solid, with a located warning, instead of exhausting memory.
#[test]
fn too_many_slices_fall_back_to_the_exact_solid_with_a_warning() {
    let text = extrusion(
        "height = 10, twist = 1e9",
        "square(size = [2, 2], center = true);",
    );
    let (_, w) = warned(&text, Facets::OpenScad);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("exact twisted solid"), "{w:?}");
}

/// `rotate_extrude(angle = ...)` of less than a full turn: OpenSCAD's straight steps from +x,
/// clockwise for a negative angle, a profile at x < 0 where OpenSCAD sweeps it, corners on the
/// axis shared.
#[test]
fn partial_turns_are_openscads_steps() {
    let shift = |x: f64, body: &str| {
        format!("multmatrix([[1, 0, 0, {x}], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {body}")
    };
    let square5 = "square(size = [5, 5]);";
    let holed = "difference() { square(size = [10, 10]); \
                 multmatrix([[1, 0, 0, 3], [0, 1, 0, 3], [0, 0, 1, 0], [0, 0, 0, 1]]) square(size = [4, 4]); }";
    // (angle, $fn, profile, OpenSCAD's volume, the smooth sector's volume)
    let sector = |a: f64, area_moment: f64| a.to_radians() * area_moment;
    let cases = [
        (
            90.0,
            0,
            shift(10.0, square5),
            486.764,
            sector(90.0, 5.0 * (225.0 - 100.0) / 2.0),
        ),
        (
            -130.0,
            0,
            shift(10.0, square5),
            702.972,
            sector(130.0, 5.0 * (225.0 - 100.0) / 2.0),
        ),
        (
            200.0,
            0,
            shift(-15.0, square5),
            1082.2,
            sector(200.0, 5.0 * (225.0 - 100.0) / 2.0),
        ),
        (
            100.0,
            9,
            "square(size = [4, 3]);".to_string(),
            36.77,
            sector(100.0, 3.0 * 16.0 / 2.0),
        ),
        (
            250.0,
            0,
            shift(5.0, holed),
            3636.192,
            sector(
                250.0,
                10.0 * (225.0 - 25.0) / 2.0 - 4.0 * (144.0 - 64.0) / 2.0,
            ),
        ),
    ];
    for (angle, fn_, body, openscad, smooth) in cases {
        let text = format!(
            "rotate_extrude(angle = {angle}, convexity = 1, $fn = {fn_}, $fa = 12, $fs = 2) {{ {body} }}"
        );
        meshes_as_openscad(&text, openscad, 0.003);
        let (s, _) = warned(&text, Facets::Exact);
        let e = signed_volume(&mesh(&s, 128).0);
        assert!(
            rel_err(e, smooth) < 0.003,
            "{text}: exact facets {e} vs {smooth}"
        );
        assert!(
            rel_err(smooth, openscad) > 0.006,
            "{text}: the case does not tell them apart"
        );
    }
}
