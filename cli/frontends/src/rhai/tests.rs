//! Scripts against the equivalent JSON trees, and hostile scripts against the sandbox.

use super::{ScriptError, eval};
use serde_json::Value;
use solidkit_kernel::Solid;
use solidkit_kernel::json::{self, NoMeshResolver};
use solidkit_meshing::io::FileMeshResolver;
use std::path::Path;
use std::sync::Arc;
use std::time::{Duration, Instant};

fn run(script: &str) -> Result<Solid, ScriptError> {
    eval(script, "test.rhai", Arc::new(NoMeshResolver))
}

fn solid(script: &str) -> Solid {
    run(script).unwrap_or_else(|e| panic!("{script}: {e}"))
}

fn tree(text: &str) -> Solid {
    json::from_str(text).unwrap_or_else(|e| panic!("{text}: {e}"))
}

#[test]
fn primitives_operations_and_transforms_match_json() {
    let cases = [
        ("sphere(1)", r#"{"type": "sphere", "radius": 1}"#),
        ("sphere(0.5)", r#"{"type": "sphere", "radius": 0.5}"#),
        ("cube(2)", r#"{"type": "box", "size": 2}"#),
        (
            "box([1, 2.5, 3])",
            r#"{"type": "box", "size": [1, 2.5, 3]}"#,
        ),
        (
            "cylinder(1, 2)",
            r#"{"type": "cylinder", "radius": 1, "height": 2}"#,
        ),
        (
            "cone(1, 0.5, 2)",
            r#"{"type": "cone", "bottom_radius": 1, "top_radius": 0.5, "height": 2}"#,
        ),
        (
            "torus(2, 0.5)",
            r#"{"type": "torus", "major_radius": 2, "minor_radius": 0.5}"#,
        ),
        (
            "plane([0, 0, 1], 0.5)",
            r#"{"type": "plane", "normal": [0, 0, 1], "offset": 0.5}"#,
        ),
        ("gyroid(0.3)", r#"{"type": "gyroid", "thickness": 0.3}"#),
        (
            "sphere(1) | cube(1)",
            r#"{"type": "union", "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}]}"#,
        ),
        (
            "sphere(1) & cube(1)",
            r#"{"type": "intersection", "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}]}"#,
        ),
        (
            "sphere(1) - cube(1)",
            r#"{"type": "difference", "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}]}"#,
        ),
        (
            "union([sphere(1), cube(1), sphere(2)])",
            r#"{"type": "union", "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}, {"type": "sphere", "radius": 2}]}"#,
        ),
        (
            "intersection([sphere(1), cube(1)])",
            r#"{"type": "intersection", "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}]}"#,
        ),
        (
            "difference([sphere(1), cube(1), sphere(2)])",
            r#"{"type": "difference", "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}, {"type": "sphere", "radius": 2}]}"#,
        ),
        (
            "sphere(1).translate([1, 2.0, 3])",
            r#"{"type": "translate", "offset": [1, 2, 3], "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).rotate([0, 0, 1], 45)",
            r#"{"type": "rotate", "axis": [0, 0, 1], "degrees": 45, "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).scale(2)",
            r#"{"type": "scale", "factor": 2, "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).scale([1, 2, 3])",
            r#"{"type": "scale", "factor": [1, 2, 3], "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).mirror([1, 0, 0])",
            r#"{"type": "mirror", "normal": [1, 0, 0], "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).affine([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]])",
            r#"{"type": "affine", "matrix": [[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]], "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).offset(0.1)",
            r#"{"type": "offset", "distance": 0.1, "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).shell(0.1)",
            r#"{"type": "shell", "thickness": 0.1, "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).color(\"red\")",
            r#"{"type": "color", "color": [1, 0, 0, 1], "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).color([0, 0.5, 1], 0.5)",
            r#"{"type": "color", "color": [0, 0.5, 1, 0.5], "child": {"type": "sphere", "radius": 1}}"#,
        ),
        (
            "sphere(1).color(\"#0000ff\").color(\"red\", 0.25)",
            r#"{"type": "color", "color": [1, 0, 0, 0.25], "child": {"type": "color", "color": "blue", "child": {"type": "sphere", "radius": 1}}}"#,
        ),
        (
            "smooth_union(sphere(1), cube(1), 0.2)",
            r#"{"type": "smooth_union", "radius": 0.2, "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}]}"#,
        ),
        (
            "smooth_intersection([sphere(1), cube(1)], 0.2)",
            r#"{"type": "smooth_intersection", "radius": 0.2, "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}]}"#,
        ),
        (
            "smooth_difference(sphere(1), cube(1), 0.2)",
            r#"{"type": "smooth_difference", "radius": 0.2, "children": [{"type": "sphere", "radius": 1}, {"type": "box", "size": 1}]}"#,
        ),
    ];
    for (script, text) in cases {
        assert_eq!(solid(script), tree(text), "{script}");
    }
}

/// `json` as a Rhai expression (`#{"key": value}` maps, `()` for null).
fn rhai_literal(v: &Value) -> String {
    match v {
        Value::Null => "()".into(),
        Value::Bool(b) => b.to_string(),
        Value::Number(n) => n.to_string(),
        Value::String(s) => Value::String(s.clone()).to_string(),
        Value::Array(a) => format!(
            "[{}]",
            a.iter().map(rhai_literal).collect::<Vec<_>>().join(", ")
        ),
        Value::Object(o) => format!(
            "#{{{}}}",
            o.iter()
                .map(|(k, v)| format!("{}: {}", Value::String(k.clone()), rhai_literal(v)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

const FAMILY_SAMPLES: [&str; 15] = [
    r#"{"type": "expr", "formula": "x*x + y*y - z", "bounds": [[-1, -1, -1], [1, 1, 1]]}"#,
    r#"{"type": "ellipsoid", "radii": [1.0, 0.7, 0.5]}"#,
    r#"{"type": "elliptic_cylinder", "radii": [0.7, 0.4], "bounds": [[-1, -1, -1], [1, 1, 1]]}"#,
    r#"{"type": "elliptic_cone", "radii": [0.9, 0.6], "bounds": [[-1, -1, -1], [1, 1, 1]]}"#,
    r#"{"type": "elliptic_paraboloid", "radii": [0.8, 0.6], "bounds": [[-1, -1, -1], [1, 1, 1]]}"#,
    r#"{"type": "hyperbolic_paraboloid", "radii": [0.8, 1.25], "bounds": [[-1, -1, -1], [1, 1, 1]]}"#,
    r#"{"type": "hyperboloid_one_sheet", "radii": [0.5, 0.4, 0.5], "bounds": [[-2, -2, -2], [2, 2, 2]]}"#,
    r#"{"type": "hyperboloid_two_sheets", "radii": [0.6, 0.5, 0.4], "bounds": [[-2, -2, -2], [2, 2, 2]]}"#,
    r#"{"type": "blob", "threshold": 0.5, "balls": [{"center": [0, 0, 0], "strength": 1, "sharpness": 3}, {"center": [1, 0, 0], "strength": 1.5, "sharpness": 2}]}"#,
    r#"{"type": "platonic", "solid": "icosahedron", "circumradius": 1}"#,
    r#"{"type": "platonic", "solid": "cube", "edge": 1}"#,
    r#"{"type": "polyhedron", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "faces": [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]}"#,
    r#"{"type": "prism", "polygon": [[0, 0], [1, 0], [1, 1], [0, 1]], "holes": [[[0.2, 0.2], [0.4, 0.2], [0.4, 0.4]]], "direction": [0, 0, 1]}"#,
    r#"{"type": "heightfield", "min": [0, 0], "max": [1, 1], "base": 0, "bezier": [[1, 2], [1, 3]]}"#,
    r#"{"type": "heightfield", "min": [0, 0], "max": [1, 1], "base": -0.5, "samples": [[1, 2], [1, 1]]}"#,
];

/// Every family through `node(map)`: the samples above and the sweep, polyhedron, tree and
/// parametric surface fixtures.
#[test]
fn every_family_through_node_matches_json() {
    let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
    let mut texts: Vec<(String, FileMeshResolver)> = FAMILY_SAMPLES
        .iter()
        .map(|t| (t.to_string(), FileMeshResolver::new(&fixtures)))
        .collect();
    for dir in ["sweeps", "polyhedra", "trees", "surfaces"] {
        for entry in std::fs::read_dir(fixtures.join(dir)).expect("fixture folder") {
            let path = entry.expect("entry").path();
            // The formula torus tessellates to ~60 000 triangles: past the script time limit in
            // debug builds (its JSON path is tested in tests/families_surfaces.rs).
            if path.extension().is_some_and(|e| e == "json")
                && !path.ends_with("surfaces/param_torus.json")
            {
                let text = std::fs::read_to_string(&path).expect("fixture");
                texts.push((text, FileMeshResolver::for_tree_file(&path)));
            }
        }
    }
    assert!(texts.len() > 25, "fixtures found: {}", texts.len());
    for (text, resolver) in texts {
        let v: Value = serde_json::from_str(&text).expect("JSON");
        let root = v.get("root").unwrap_or(&v);
        // Read back from serde_json's text so both sides see the same (serde-rounded) numbers.
        let expected =
            json::from_str_with(&root.to_string(), &resolver).unwrap_or_else(|e| panic!("{e}"));
        let script = format!("node({})", rhai_literal(root));
        let got = eval(&script, "t.rhai", Arc::new(resolver)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(got, expected, "{text}");
    }
}

#[test]
fn language_features_export_and_solids_inside_nodes() {
    let looped = solid(
        "fn ring(n) { let parts = []; for i in 0..n { parts.push(sphere(0.2).translate([1, 0, 0]).rotate([0, 0, 1], i * 360.0 / n)); } union(parts) }
         ring(4)",
    );
    assert_eq!(looped.children().len(), 4);
    // export wins over the last expression.
    assert_eq!(
        solid("export(sphere(2)); cube(1)"),
        tree(r#"{"type": "sphere", "radius": 2}"#)
    );
    // Solids as values of a node map.
    assert_eq!(
        solid(r#"node(#{"type": "translate", offset: [1, 0, 0], child: sphere(1) - cube(1)})"#),
        solid("(sphere(1) - cube(1)).translate([1, 0, 0])")
    );
    // A deep chain built in a loop survives embedding.
    let deep = solid(
        "let s = sphere(1); for i in 0..2000 { s = s.translate([0.001, 0, 0]); } node(#{type: \"offset\", distance: 0.1, child: s})",
    );
    assert_eq!(deep.depth(), 2002);
}

/// Runs a hostile script and checks that one of the sandbox limits stopped it. The limits
/// themselves bound the time (operation count, and a 1.5 s wall-clock deadline); the elapsed time
/// is only checked against a generous bound here so a loaded machine cannot make the test flaky.
fn hostile(script: &str, expected: &str) -> ScriptError {
    let start = Instant::now();
    let e = run(script).expect_err(script);
    let took = start.elapsed();
    assert!(took < Duration::from_secs(20), "{script}: took {took:?}");
    let text = e.to_string();
    let matches = expected.split(" | ").any(|want| text.contains(want));
    assert!(matches, "{script}: {e}");
    e
}

#[test]
fn hostile_scripts_stop_with_clear_errors() {
    // Whichever limit comes first on this machine: the operation count or the deadline.
    hostile("let i = 0; loop { i += 1; }", "operations | s time limit");
    hostile("let a = []; loop { a.push(1); }", "s time limit");
    hostile("fn f(x) { f(x + 1) } f(1)", "nested deeper than 64");
    hostile(
        r#"let s = "ab"; loop { s += s; }"#,
        "string grew beyond the limit",
    );
    hostile(
        "let s = sphere(1); for i in 0..60 { s = s | s; } s",
        "more than the limit of 1000000",
    );
    // `node` writes and reads the tree as JSON, which takes long for a large one: the deadline,
    // checked by every constructor, may come first on a loaded machine.
    hostile(
        "let s = sphere(1); for i in 0..60 { s = node(#{type: \"union\", children: [s, s]}); } s",
        "more than the limit of 1000000 | s time limit",
    );
    let deep = format!("{}1{}", "(".repeat(200), ")".repeat(200));
    hostile(&format!("sphere({deep})"), "nested too deeply");
    hostile(
        &format!("{}sphere(1){}", "[".repeat(200), "]".repeat(200)),
        "nested too deeply",
    );
    hostile(r#"import "os" as os; sphere(1)"#, "'import'");
    hostile(r#"eval("sphere(1)")"#, "'eval'");
    hostile(
        "let a = [1]; loop { a += a; }",
        "array/BLOB grew beyond the limit (100000)",
    );
}

#[test]
fn errors_name_line_column_and_source() {
    let e = run("let a = sphere(1);\nlet b = a |;\nb").expect_err("syntax error");
    assert_eq!((e.line, e.column), (Some(2), Some(12)), "{e}");
    assert!(
        e.to_string().starts_with("test.rhai:2:12: syntax error"),
        "{e}"
    );
    assert!(e.to_string().contains("(at: let b = a |;)"), "{e}");
    let e = run("let a = 1;\nsphere(\"big\")").expect_err("type error");
    assert!(
        e.to_string()
            .starts_with("test.rhai:2:1: sphere radius: expected a number"),
        "{e}"
    );
    let e = run("42").expect_err("no solid");
    assert!(e.to_string().contains("made no solid"), "{e}");
    let e = run(r#"node(#{type: "ellipsoid", radii: [1, 2]})"#).expect_err("bad node");
    assert!(e.to_string().contains("radii"), "{e}");
}

#[test]
fn sleep_and_curry_are_not_available() {
    // `sleep` ignored the deadline (and panicked on huge floats); it is an error at once.
    for script in [
        "sleep(1000000000); sphere(1)",
        "sleep(1e300); sphere(1)",
        "sleep(0.5); sphere(1)",
        r#"let f = Fn("sleep"); f.call(1000000000); sphere(1)"#,
    ] {
        let e = hostile(script, "'sleep' is not available");
        assert_eq!(e.line, Some(1), "{e}");
    }
    // Curried function pointers hold deep copies outside Rhai's size limits: doubling one 26
    // times took 8 GB. `curry` is refused when the script is read, in both spellings.
    for script in [
        r#"let f = Fn("sphere"); for i in 0..26 { f = f.curry(f); } sphere(1)"#,
        r#"let f = Fn("sphere"); f = curry(f, 1); sphere(1)"#,
    ] {
        let e = hostile(script, "'curry' is not available");
        assert_eq!(e.line, Some(1), "{e}");
    }
    // Closures (which capture by sharing, not by copying) still work.
    assert_eq!(
        solid("let r = 2; let f = |x| sphere(x * r); f.call(1)"),
        solid("sphere(2)")
    );
}

#[test]
fn constructors_check_the_deadline() {
    // On a deadline already past, the first constructor stops the script, before Rhai's own
    // check (every 1024 operations) could.
    let limits = super::Limits {
        max_time: Duration::ZERO,
        ..super::Limits::default()
    };
    for script in [
        "sphere(1)",
        "cube(1) | sphere(1)",
        r#"node(#{type: "sphere", radius: 1})"#,
    ] {
        let e =
            super::eval_with(script, "t.rhai", Arc::new(NoMeshResolver), limits).expect_err(script);
        assert!(e.to_string().contains("0 s time limit"), "{script}: {e}");
    }
}

/// Curves from scripts: the notes' numbers through `curve(map)` and its methods, a polyline as
/// a profile, and located errors.
#[test]
fn curves_evaluate_split_and_flatten() {
    let checks = r#"
        let q = curve(#{type: "bezier", points: [[0, -1], [1, 2], [5, -1]]});
        let p = q.point(0.3);
        if (p[0] - 0.87).abs() > 1e-14 || (p[1] - 0.26).abs() > 1e-14 { throw `point ${p}`; }
        let d = q.derivative(0.3);
        if (d[0] - 3.8).abs() > 1e-13 || (d[1] - 2.4).abs() > 1e-13 { throw `derivative ${d}`; }
        let s = q.split(0.5);
        if s.left.points[2] != [1.75, 0.5, 0.0] || s.right.points[1] != [3.0, 0.5, 0.0] {
            throw `split ${s}`;
        }
        let t = curve(#{type: "cubic_through", points: [[0, 0], [1, 0], [1, 1], [0, 1]]});
        let m = t.point(2.0 / 3.0);
        if (m[0] - 1.0).abs() > 1e-14 || (m[1] - 1.0).abs() > 1e-14 { throw `through ${m}`; }
        let c = curve(#{type: "nurbs", degree: 2, points: [[1, 0], [1, 1], [0, 1]],
                        weights: [1, 0.7071067811865476, 1]});
        if (c.length() - 1.5707963267948966).abs() > 1e-12 { throw `length ${c.length()}`; }
        let line = c.polyline(0.0001);
        for v in line { if ((v[0] * v[0] + v[1] * v[1]).sqrt() - 1.0).abs() > 1e-14 { throw `on circle ${v}`; } }
        if c.samples(5).len() != 5 || c.domain() != [0.0, 1.0] || c.is_closed() { throw "samples"; }
        let rose = curve(#{type: "formula", x: "cos(2*u)*cos(u)", y: "cos(2*u)*sin(u)",
                           domain: [0, 6.283185307179586]});
        if !rose.is_closed() { throw "rose"; }
        sphere(1)
    "#;
    solid(checks);
    // The example script builds its solid from a polyline.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/curves/curves.rhai");
    let script = std::fs::read_to_string(&path).unwrap();
    let s = solid(&script);
    assert_eq!(s.kind().name(), "extrude");
    for (script, message) in [
        (
            r#"curve(#{type: "bezier", points: [[0, "a"]]})"#,
            "points[0]",
        ),
        (r#"curve(#{type: "spiral"})"#, "unknown curve type"),
        (
            r#"curve(#{type: "bezier", points: [[0, 0], [1, 1]]}).point(2)"#,
            "outside the curve's domain",
        ),
        (
            r#"curve(#{type: "formula", x: "u", y: "0", domain: [0, 1]}).split(0.5)"#,
            "no control points",
        ),
        (
            r#"curve(#{type: "bezier", points: [[0, 0], [1, 1]]}).polyline(0)"#,
            "chord_error",
        ),
    ] {
        let e = run(script).unwrap_err().to_string();
        assert!(e.contains(message), "{script}: {e}");
    }
}

#[test]
fn swept_along_is_the_json_swept_volume() {
    let path = r#"curve(#{type: "bezier", points: [[0, 0, 0], [1, 0.5, 0], [2, 0, 0]]})"#;
    let script = solid(&format!(
        "sphere(0.5).swept_along({path}, #{{tolerance: 0.1}})"
    ));
    let json = tree(
        r#"{"type": "swept_volume", "tolerance": 0.1, "child": {"type": "sphere", "radius": 0.5},
            "path": {"type": "bezier", "points": [[0, 0, 0], [1, 0.5, 0], [2, 0, 0]]}}"#,
    );
    assert!(script == json, "the script and the JSON node differ");
    assert!(
        script.children().len() > 20,
        "{} copies",
        script.children().len()
    );
    let fixed = solid(&format!(
        "cube(1).swept_along({path}, #{{frame: \"fixed\"}})"
    ));
    assert!(fixed.children().len() > 2);
    let bad = run(&format!(
        "sphere(1).swept_along({path}, #{{frame: \"twisted\"}})"
    ))
    .expect_err("bad frame");
    assert!(bad.to_string().contains("\"rmf\" or \"fixed\""), "{bad}");
    let tiny = run(&format!(
        "sphere(1).swept_along({path}, #{{tolerance: 1e-9}})"
    ))
    .expect_err("too many copies");
    assert!(
        tiny.to_string().contains("use a tolerance of at least"),
        "{tiny}"
    );
    let unbounded =
        run(&format!("plane([0, 0, 1], 0).swept_along({path})")).expect_err("unbounded");
    assert!(unbounded.to_string().contains("bounded"), "{unbounded}");
    let t = run("let t = swept_tolerance(sphere(1)); sphere(t)").expect("tolerance");
    assert!(
        t == tree(&format!(
            r#"{{"type": "sphere", "radius": {:?}}}"#,
            2.0 * 3f64.sqrt() / 50.0
        ))
    );
}
