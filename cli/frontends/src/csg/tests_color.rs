//! `color()` in `.csg`: OpenSCAD's argument forms, the innermost colour, warnings for names
//! OpenSCAD does not know, and geometry unchanged by colours (hull and minkowski look through).

use super::{Facets, import, import_with_warnings};
use solidkit_kernel::primitive::NoMeshResolver;
use solidkit_kernel::{Rgba, Solid};

fn colors(text: &str) -> Vec<Option<[u8; 4]>> {
    let s = import(text, Facets::Exact).unwrap();
    s.validate().unwrap();
    s.colored_parts()
        .map(|p| p.iter().map(|p| p.color.map(Rgba::to_u8)).collect())
        .unwrap_or_default()
}

#[test]
fn openscad_argument_forms() {
    let cases = [
        ("color(\"red\") cube(1);", [255, 0, 0, 255]),
        ("color(\"Red\", 0.5) cube(1);", [255, 0, 0, 128]),
        (
            "color(c = \"blue\", alpha = 0.25) cube(1);",
            [0, 0, 255, 64],
        ),
        ("color([0, 1, 0]) cube(1);", [0, 255, 0, 255]),
        ("color([0, 1, 0], 0.5) cube(1);", [0, 255, 0, 128]),
        ("color([0, 1, 0, 0.5], 1) cube(1);", [0, 255, 0, 128]),
        ("color([2, -1, 0, 1]) cube(1);", [255, 0, 0, 255]),
        ("color(\"#ff8000\") cube(1);", [255, 128, 0, 255]),
        ("color(\"#ff800080\", 1) cube(1);", [255, 128, 0, 128]),
        ("color(\"#f80\", 0.5) cube(1);", [255, 136, 0, 128]),
        ("color([1, 0, 0, 1]) { cube(1); }", [255, 0, 0, 255]),
    ];
    for (text, want) in cases {
        assert_eq!(colors(text), vec![Some(want)], "{text}");
    }
}

#[test]
fn the_innermost_color_wins() {
    let text = "color(\"red\") union() { cube(1); color(\"blue\") sphere(1); \
                multmatrix([[1,0,0,5],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) color(\"lime\") cube(2); }";
    assert_eq!(
        colors(text),
        vec![
            Some([255, 0, 0, 255]),
            Some([0, 0, 255, 255]),
            Some([0, 255, 0, 255])
        ]
    );
}

#[test]
fn unknown_colors_warn_and_leave_the_part_uncoloured() {
    for text in [
        "color(\"nosuchcolour\") cube(1);",
        "color([1, 0]) cube(1);",
        "color(\"red\", \"x\") cube(1);",
    ] {
        let (s, warnings) = import_with_warnings(text, Facets::Exact, &NoMeshResolver).unwrap();
        assert_eq!(warnings.len(), 1, "{text}");
        assert!(!s.has_color(), "{text}");
    }
    let (s, warnings) =
        import_with_warnings("color() cube(1);", Facets::Exact, &NoMeshResolver).unwrap();
    assert!(warnings.is_empty() && !s.has_color());
}

#[test]
fn colours_never_change_geometry() {
    let plain = [
        "difference() { cube(10, center = true); sphere(6.5); }",
        "hull() { cube(1); multmatrix([[1,0,0,3],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) sphere(1); }",
        "minkowski() { cube(2); sphere(0.5); }",
        "linear_extrude(height = 1) projection(cut = true) difference() { cube(4, center = true); sphere(2.5); }",
        "resize([4, 4, 4]) union() { cube(1); multmatrix([[1,0,0,2],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(1); }",
    ];
    let painted = [
        "difference() { color(\"red\") cube(10, center = true); color(\"blue\") sphere(6.5); }",
        "hull() { color(\"red\") cube(1); multmatrix([[1,0,0,3],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) color(\"blue\") sphere(1); }",
        "minkowski() { color(\"red\") cube(2); color(\"blue\") sphere(0.5); }",
        "linear_extrude(height = 1) projection(cut = true) color(\"red\") difference() { cube(4, center = true); \
         color(\"blue\") sphere(2.5); }",
        "resize([4, 4, 4]) color(\"red\") union() { cube(1); multmatrix([[1,0,0,2],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(1); }",
    ];
    for (a, b) in plain.iter().zip(painted) {
        // The same field everywhere (a hull's faces may come in another order).
        let values = |t: &str| {
            let s: Solid = import(t, Facets::Exact).unwrap();
            let p = s.compile();
            let mut v = vec![s.bbox().min.x.to_bits(), s.bbox().max.z.to_bits()];
            for i in 0..9 {
                for j in 0..9 {
                    for k in 0..9 {
                        let q = glam::DVec3::new(i as f64, j as f64, k as f64) * 0.9 - 3.7;
                        v.push(p.value(q).to_bits());
                    }
                }
            }
            v
        };
        assert_eq!(values(a), values(b), "{b}");
    }
}
