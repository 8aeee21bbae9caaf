//! OpenSCAD `.csg` constructs that read other files or reshape 2D regions, through the real
//! binary: `import` of STL, 3MF and DXF (relative to the `.csg`, confined to its folder), `surface`
//! of a `.dat` height map and `offset` (round, delta, chamfer), each against its exact volume;
//! bad input exits 2 with `FILE:LINE:COL`.

use serde_json::Value;
use solidkit_tests::path_str;
use std::f64::consts::PI;
use std::path::Path;
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

/// Writes `files` into a fresh folder and meshes `model.csg` there (exact facets, 128 cells).
fn mesh(files: &[(&str, &str)]) -> (tempfile::TempDir, Output) {
    let dir = tempfile::tempdir().expect("temp dir");
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).expect("write");
    }
    let model = dir.path().join("model.csg");
    let o = solidkit(&[
        "mesh",
        path_str(&model),
        "--json",
        "--no-self-intersections",
    ]);
    (dir, o)
}

fn volume_of(files: &[(&str, &str)]) -> (f64, Value) {
    let (_dir, o) = mesh(files);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: Value = serde_json::from_slice(&o.stdout).expect("JSON report");
    assert_eq!(r["closed"], true, "{r}");
    (r["volume"].as_f64().expect("volume"), r)
}

fn assert_close(got: f64, want: f64, rel: f64) {
    assert!(((got - want) / want).abs() <= rel, "volume {got} vs {want}");
}

/// An ASCII STL of the box `[0, 2] × [0, 3] × [0, 4]`, triangles counter-clockwise from outside.
fn box_stl() -> String {
    let c = |i: usize| {
        [
            (i & 1) as f64 * 2.0,
            (i >> 1 & 1) as f64 * 3.0,
            (i >> 2) as f64 * 4.0,
        ]
    };
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let mut s = String::from("solid box\n");
    for q in quads {
        for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
            s += "facet normal 0 0 0\nouter loop\n";
            for v in t {
                let p = c(v);
                s += &format!("vertex {} {} {}\n", p[0], p[1], p[2]);
            }
            s += "endloop\nendfacet\n";
        }
    }
    s + "endsolid box\n"
}

/// A DXF with the given entities.
fn dxf(entities: &str) -> String {
    format!("0\nSECTION\n2\nENTITIES\n{entities}0\nENDSEC\n0\nEOF\n")
}

fn line(layer: &str, a: (f64, f64), b: (f64, f64)) -> String {
    format!(
        "0\nLINE\n8\n{layer}\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
        a.0, a.1, b.0, b.1
    )
}

/// A 10 × 10 square on layer `sq` (lines in scrambled order) and a circle of radius 2 in its
/// middle on layer `sq` too (a hole by the even-odd rule), and a second square on layer `other`.
fn drawing() -> String {
    let e = [
        line("sq", (10.0, 0.0), (10.0, 10.0)),
        line("sq", (0.0, 10.0), (0.0, 0.0)),
        line("sq", (0.0, 0.0), (10.0, 0.0)),
        line("sq", (0.0, 10.0), (10.0, 10.0)),
        "0\nCIRCLE\n8\nsq\n10\n5\n20\n5\n40\n2\n".to_string(),
        line("other", (20.0, 0.0), (21.0, 0.0)),
        line("other", (21.0, 0.0), (21.0, 1.0)),
        line("other", (21.0, 1.0), (20.0, 0.0)),
    ];
    dxf(&e.concat())
}

/// Area of OpenSCAD's n-gon of radius r.
fn ngon(r: f64, n: f64) -> f64 {
    0.5 * n * r * r * (2.0 * PI / n).sin()
}

#[test]
fn imported_stl_is_a_solid_in_booleans() {
    let stl = box_stl();
    let (v, _) = volume_of(&[
        ("box.stl", &stl),
        ("model.csg", "import(file = \"box.stl\");"),
    ]);
    assert_close(v, 24.0, 0.01);
    let csg = "difference() {\n\timport(file = \"box.stl\", convexity = 3);\n\tcube(size = [1, 1, 10], center = true);\n}\n";
    let (v, _) = volume_of(&[("box.stl", &stl), ("model.csg", csg)]);
    assert_close(v, 23.0, 0.01);
}

/// A 3MF file (written here by `solidkit repair --mode minimal` from the STL box, which changes
/// nothing in it) imports as the same solid.
#[test]
fn imported_3mf_is_a_solid() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (stl, three) = (dir.path().join("box.stl"), dir.path().join("box.3mf"));
    std::fs::write(&stl, box_stl()).expect("write");
    let o = solidkit(&[
        "repair",
        path_str(&stl),
        "-o",
        path_str(&three),
        "--mode",
        "minimal",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let model = dir.path().join("model.csg");
    std::fs::write(&model, "import(file = \"box.3mf\");").expect("write");
    let o = solidkit(&[
        "mesh",
        path_str(&model),
        "--json",
        "--no-self-intersections",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: Value = serde_json::from_slice(&o.stdout).expect("JSON report");
    assert_close(r["volume"].as_f64().expect("volume"), 24.0, 0.01);
}

/// A file that does not exist imports nothing, with a located warning, as in OpenSCAD (which
/// warns "Can't open import file" and renders the rest); STL, 3MF and DXF alike.
#[test]
fn missing_import_files_are_empty_with_a_warning() {
    for file in ["missing.stl", "missing.3mf", "missing.dxf"] {
        let csg = format!("cube(1);\nimport(file = \"{file}\");");
        let (v, r) = volume_of(&[("model.csg", &csg)]);
        assert_close(v, 1.0, 0.01);
        let w = r["warnings"].to_string();
        assert!(
            w.contains("model.csg:2:1:") && w.contains(file) && w.contains("the import is empty"),
            "{w}"
        );
    }
    // `surface` too (OpenSCAD: "Can't open DAT file", nothing rendered for it).
    let (v, r) = volume_of(&[("model.csg", "cube(1);\nsurface(file = \"gone.dat\");")]);
    assert_close(v, 1.0, 0.01);
    let w = r["warnings"].to_string();
    assert!(
        w.contains("model.csg:2:1:") && w.contains("the surface is empty"),
        "{w}"
    );
    // A model with nothing else is empty, and the error says what was skipped.
    let (_dir, o) = mesh(&[("model.csg", "surface(file = \"gone.dat\");")]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("the model is empty") && err.contains("gone.dat"),
        "{err}"
    );
}

#[test]
fn imported_dxf_layers_join_lines_and_holes_by_even_odd() {
    let d = drawing();
    // Circle r = 2 at $fs = 2: 7 fragments (OpenSCAD's rule); extruded 5 high.
    let csg = "linear_extrude(height = 5) {\n\timport(file = \"d.dxf\", layer = \"sq\", origin = [0, 0], scale = 1, $fn = 0, $fa = 12, $fs = 2);\n}\n";
    let (v, _) = volume_of(&[("d.dxf", &d), ("model.csg", csg)]);
    assert_close(v, 5.0 * (100.0 - ngon(2.0, 7.0)), 0.01);
    // All layers: the triangle of layer `other` too; origin and scale: (p − origin)·scale.
    let csg = "linear_extrude(height = 10) {\n\timport(file = \"d.dxf\", origin = [20, 0], scale = 2, $fn = 12);\n}\n";
    let (v, r) = volume_of(&[("d.dxf", &d), ("model.csg", csg)]);
    assert_close(v, 40.0 * (100.0 - ngon(2.0, 12.0) + 0.5), 0.01);
    assert_eq!(r["shells"], 2, "{r}");
}

#[test]
fn dxf_entities_that_are_not_read_are_warnings() {
    let d = dxf(&[
        line("0", (0.0, 0.0), (1.0, 0.0)),
        line("0", (1.0, 0.0), (0.0, 1.0)),
        line("0", (0.0, 1.0), (0.0, 0.0)),
        "0\nSPLINE\n8\n0\n".to_string(),
    ]
    .concat());
    let csg = "linear_extrude(height = 2) import(\"d.dxf\");\n";
    let (v, r) = volume_of(&[("d.dxf", &d), ("model.csg", csg)]);
    assert_close(v, 1.0, 0.01);
    let w = r["warnings"][0].as_str().expect("a warning");
    assert!(
        w.ends_with("model.csg:1:28: d.dxf: unsupported DXF entity SPLINE skipped"),
        "{w}"
    );
}

#[test]
fn surface_of_a_dat_file_has_its_base_one_below_the_lowest_point() {
    // 3 × 3 heights, all 2 except the middle 6: base at z = 0 (min(0, 2 − 1)). The four cells
    // each have corners 2, 2, 2, 6 and centre 3; volume over a cell of the piecewise-linear
    // surface: triangles (centre, two corners) of area 1/4.
    let dat = "# heights\n2 2 2\n2 6 2\n2 2 2\n";
    let cell = 0.25 * ((3.0 + 2.0 + 2.0) / 3.0 * 2.0 + (3.0 + 2.0 + 6.0) / 3.0 * 2.0);
    let csg = "surface(file = \"h.dat\", center = true, invert = false);\n";
    let (v, r) = volume_of(&[("h.dat", dat), ("model.csg", csg)]);
    assert_close(v, 4.0 * cell, 0.01);
    let bbox = &r["bbox"];
    assert!(bbox[0][0].as_f64().expect("x") < -0.9, "centred: {bbox}");
}

#[test]
fn offsets_round_delta_and_chamfer() {
    let square = "square(size = [10, 10], center = true);";
    let cases = [
        ("r = 1, $fn = 64", 140.0 + PI),
        ("r = -1", 64.0),
        ("delta = 1, chamfer = false", 144.0),
        (
            "delta = 1, chamfer = true",
            144.0 - 4.0 * (3.0 - 2.0 * 2f64.sqrt()),
        ),
        ("delta = -2", 36.0),
    ];
    for (args, area) in cases {
        let csg =
            format!("linear_extrude(height = 2) {{\n\toffset({args}) {{\n\t\t{square}\n\t}}\n}}\n");
        let (v, _) = volume_of(&[("model.csg", &csg)]);
        assert_close(v, 2.0 * area, 0.01);
    }
    // A circle grows and shrinks exactly.
    let csg = "linear_extrude(height = 1) offset(r = -1) circle(r = 3);";
    let (v, _) = volume_of(&[("model.csg", csg)]);
    assert_close(v, PI * 4.0, 0.01);
}

fn assert_located_error(files: &[(&str, &str)], wanted: &str) {
    let (dir, o) = mesh(files);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let err = String::from_utf8_lossy(&o.stderr);
    let model = dir.path().join("model.csg");
    let prefix = format!("error: {}:", model.display());
    assert!(err.starts_with(&prefix), "{err}");
    assert!(err.contains(wanted), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    let _ = Path::new(&model);
}

#[test]
fn bad_imports_and_offsets_exit_2_with_a_located_line() {
    assert_located_error(
        &[("model.csg", "import(file = \"../outside.stl\");")],
        "--allow-path",
    );
    assert_located_error(
        &[("model.csg", "import(file = \"/etc/hostname.stl\");")],
        "absolute paths are not allowed",
    );
    assert_located_error(
        &[("model.csg", "import(file = \"logo.svg\");")],
        ".svg files are not read",
    );
    assert_located_error(
        &[
            ("x.png", "not a PNG"),
            ("model.csg", "cube(1);\nsurface(file = \"x.png\");"),
        ],
        "model.csg:2:1: surface: x.png: ",
    );
    assert_located_error(
        &[
            ("h.dat", "1 2\n3 x\n"),
            ("model.csg", "surface(file = \"h.dat\");"),
        ],
        "h.dat: line 2: expected finite numbers",
    );
    assert_located_error(
        &[(
            "model.csg",
            "linear_extrude(height = 1) offset(r = 1e300) difference() { square(2); square(1); }",
        )],
        "model.csg:1:28: offset: an offset of 1e300 is beyond",
    );
    assert_located_error(
        &[(
            "model.csg",
            "linear_extrude(height = 1) minkowski() { square([1e200, 1]); difference() { square(2); square(1); } }",
        )],
        "model.csg:1:28: minkowski: a 2D coordinate",
    );
}
