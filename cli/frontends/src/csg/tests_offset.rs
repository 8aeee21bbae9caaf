//! `offset()` of non-convex regions, regions with holes and of several paths, under
//! `--facets openscad`, against OpenSCAD 2021.01's own renders of its `offset-tests` shapes: each
//! statement extruded by 1 (`linear_extrude(1) offset(...) shape();`, `openscad -o x.stl`), the
//! volume of its closed STL being the area. The shapes are the test file's: `shape1(w)`, a
//! `w`-square with a centred 10-square hole; `shape2()`, a polygon of two paths (a long triangle
//! with a triangular hole).

use super::Facets;
use super::facets::Resolution;
use super::flat::{Flat, Leaf2, Op2};
use super::offset::{Offset, offset};
use super::region;
use glam::DVec2;

/// OpenSCAD's defaults as its `.csg` export writes them.
const RES: Resolution = Resolution {
    fn_: 0.0,
    fa: 12.0,
    fs: 2.0,
};

fn square(w: f64) -> Flat {
    let h = w / 2.0;
    Flat::leaf(Leaf2::Polygon(vec![vec![
        DVec2::new(-h, -h),
        DVec2::new(h, -h),
        DVec2::new(h, h),
        DVec2::new(-h, h),
    ]]))
}

fn shape1(w: f64) -> Flat {
    Flat::combine(vec![square(w), square(10.0)], Op2::Difference)
}

fn shape2() -> Flat {
    let p = |x: f64, y: f64| DVec2::new(x, y);
    Flat::leaf(Leaf2::Polygon(vec![
        vec![p(-15.0, 80.0), p(15.0, 80.0), p(0.0, -15.0)],
        vec![p(-8.0, 60.0), p(8.0, 60.0), p(0.0, 5.0)],
    ]))
}

fn round(r: f64) -> Offset {
    Offset::Round { r, res: RES }
}

fn delta(delta: f64, chamfer: bool) -> Offset {
    Offset::Delta { delta, chamfer }
}

#[test]
fn offsets_agree_with_openscads_renders() {
    // (statement, shape, offset, OpenSCAD's area, shapes)
    let cases = [
        (
            "offset(5) shape1()",
            shape1(20.0),
            round(5.0),
            876.536252,
            1,
        ),
        ("offset(5) shape2()", shape2(), round(5.0), 2579.021614, 1),
        (
            "offset(r = 1) shape1(30)",
            shape1(30.0),
            round(1.0),
            958.0,
            1,
        ),
        (
            "offset(r = 5) shape1(30)",
            shape1(30.0),
            round(5.0),
            1576.536252,
            1,
        ),
        (
            "offset(r = -5) shape1(40)",
            shape1(40.0),
            round(-5.0),
            523.463198,
            1,
        ),
        (
            "offset(r = -10.01) shape1(50)",
            shape1(50.0),
            round(-10.01),
            87.292052,
            4,
        ),
        (
            "offset(r = -1) shape2()",
            shape2(),
            round(-1.0),
            642.195825,
            1,
        ),
        ("offset() shape1()", shape1(20.0), round(1.0), 418.0, 1),
        (
            "offset(delta = 1) shape1()",
            shape1(20.0),
            delta(1.0, false),
            420.0,
            1,
        ),
        (
            "offset(delta = 4) shape1()",
            shape1(20.0),
            delta(4.0, false),
            780.0,
            1,
        ),
        (
            "offset(delta = 5) shape2()",
            shape2(),
            delta(5.0, false),
            2719.729050,
            1,
        ),
        (
            "offset(delta = -2) shape1(30)",
            shape1(30.0),
            delta(-2.0, false),
            480.0,
            1,
        ),
        (
            "offset(delta = -5) shape1(40)",
            shape1(40.0),
            delta(-5.0, false),
            500.0,
            1,
        ),
        (
            "offset(delta = -1) shape2()",
            shape2(),
            delta(-1.0, false),
            634.974082,
            1,
        ),
        (
            "offset(delta = 4, chamfer = true) shape1()",
            shape1(20.0),
            delta(4.0, true),
            769.019765,
            1,
        ),
        (
            "offset(delta = 1, chamfer = true) shape1()",
            shape1(20.0),
            delta(1.0, true),
            419.313677,
            1,
        ),
        (
            "offset(delta = 5, chamfer = true) shape2()",
            shape2(),
            delta(5.0, true),
            2591.695005,
            1,
        ),
        (
            "offset(delta = -2, chamfer = true) shape1(30)",
            shape1(30.0),
            delta(-2.0, true),
            482.745153,
            1,
        ),
        (
            "offset(delta = -5, chamfer = true) shape1(40)",
            shape1(40.0),
            delta(-5.0, true),
            517.157145,
            1,
        ),
        (
            "offset(delta = -1, chamfer = true) shape2()",
            shape2(),
            delta(-1.0, true),
            640.602673,
            1,
        ),
        // Clipper's round join steps 5 fragments a turn: one step per right angle, a straight cut.
        (
            "offset(r = 0.8) square(1)",
            square(1.0),
            round(0.8),
            5.480011,
            1,
        ),
    ];
    let wrong: Vec<String> = cases
        .into_iter()
        .filter_map(|(name, flat, how, openscad, parts)| {
            let result = offset(flat, how, Facets::OpenScad).unwrap();
            region::openscad_mismatch(result, openscad, parts).map(|m| format!("{name}: {m}"))
        })
        .collect();
    assert!(wrong.is_empty(), "{wrong:#?}");
}

/// Through the `.csg` reader and the mesher: `offset()` without arguments is `r = 1` (OpenSCAD's
/// default; with 5 fragments Clipper cuts a unit square's corners straight: 7, where
/// `delta = 1` gives 9), `r` is the one positional argument, and a 2D `minkowski()` of a framed
/// square and a 16-gon (OpenSCAD's `minkowski2-hole-tests`) meshes as OpenSCAD renders it.
#[test]
fn csg_offsets_and_2d_minkowski_mesh_as_openscad() {
    use super::tests::warned;
    use solidkit_kernel::primitive::sweep::signed_volume;
    use solidkit_tests::{mesh, rel_err};
    let frame = "difference() { square(size = [20, 20], center = true); \
                 square(size = [10, 10], center = true); }";
    let cases = [
        (
            "offset($fn = 0, $fa = 12, $fs = 2) square(size = 1);".to_string(),
            7.0,
        ),
        ("offset(delta = 1) square(size = 1);".to_string(), 9.0),
        (
            format!("offset(5, $fn = 0, $fa = 12, $fs = 2) {frame}"),
            876.536252,
        ),
        (
            format!("minkowski() {{ {frame} circle(r = 1, $fn = 16); }}"),
            419.061530,
        ),
    ];
    for (body, openscad) in cases {
        let text = format!("linear_extrude(height = 1) {body}");
        let (s, w) = warned(&text, Facets::OpenScad);
        assert!(w.is_empty(), "{text}: {w:?}");
        let (m, report) = mesh(&s, 128);
        assert!(report.is_closed_manifold(), "{text}: {report:?}");
        let v = signed_volume(&m);
        assert!(
            rel_err(v, openscad) < 0.01,
            "{text}: {v} vs OpenSCAD's {openscad}"
        );
    }
}
