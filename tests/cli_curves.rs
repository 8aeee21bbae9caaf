//! `solidkit curve` through the real binary on the notes' curves in `fixtures/curves/`: points
//! and derivatives at a parameter, the de Casteljau split, arc length, polylines in OBJ, SVG and
//! JSON within the chord-error bound, and located one-line errors with exit code 2.

use solidkit_tests::{fixture, path_str, success_json};
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

fn curve(name: &str, extra: &[&str]) -> serde_json::Value {
    let f = fixture(&format!("curves/{name}"));
    let mut args = vec!["curve", path_str(&f), "--json"];
    args.extend_from_slice(extra);
    success_json(&solidkit(&args))
}

fn xyz(v: &serde_json::Value) -> [f64; 3] {
    let a = v.as_array().expect("a point");
    [0, 1, 2].map(|i| a[i].as_f64().unwrap())
}

fn near(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
}

#[test]
fn quadratic_bezier_point_tangent_and_split() {
    let r = curve(
        "quadratic_bezier.json",
        &["--at", "0.3", "--tangent", "--split", "0.5"],
    );
    assert_eq!(r["type"], "bezier");
    // (1-u)²P0 + 2u(1-u)P1 + u²P2 at 0.3 = (0.87, 0.26); C' = 2(1-u)(P1-P0) + 2u(P2-P1).
    assert!(near(xyz(&r["at"]["point"]), [0.87, 0.26, 0.0], 1e-14));
    assert!(near(xyz(&r["at"]["d1"]), [3.8, 2.4, 0.0], 1e-13));
    // Midpoint split: left P0, M01, M012; right M012, M12, P2.
    let left: Vec<[f64; 3]> = r["split"]["left"]["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(xyz)
        .collect();
    let right: Vec<[f64; 3]> = r["split"]["right"]["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(xyz)
        .collect();
    assert_eq!(
        left,
        vec![[0.0, -1.0, 0.0], [0.5, 0.5, 0.0], [1.75, 0.5, 0.0]]
    );
    assert_eq!(
        right,
        vec![[1.75, 0.5, 0.0], [3.0, 0.5, 0.0], [5.0, -1.0, 0.0]]
    );
    assert!(r["split"]["left"].get("weights").is_none());
}

#[test]
fn notes_curves_through_the_command() {
    // The interpolating cubic passes through its points at u = k/3.
    for (k, p) in [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
        .iter()
        .enumerate()
    {
        let u = format!("{}", k as f64 / 3.0);
        let r = curve("cubic_through.json", &["--at", &u]);
        assert!(
            near(xyz(&r["at"]["point"]), [p[0], p[1], 0.0], 1e-14),
            "k = {k}"
        );
    }
    // The uniform cubic B-spline starts at (P0 + 4P1 + P2)/6.
    let r = curve("uniform_bspline.json", &["--at", "3"]);
    let (p0, p1, p2) = (
        [-1.551545, 1.055903],
        [-0.490358, -0.738666],
        [0.238840, 0.988653],
    );
    let start = [0, 1].map(|i| (p0[i] + 4.0 * p1[i] + p2[i]) / 6.0);
    assert!(near(
        xyz(&r["at"]["point"]),
        [start[0], start[1], 0.0],
        1e-14
    ));
    // The rational quarter circle: on the unit circle, length π/2, rational halves.
    let r = curve("quarter_circle.json", &["--at", "0.37", "--split", "0.5"]);
    let p = xyz(&r["at"]["point"]);
    assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - 1.0).abs() < 1e-14);
    let length = r["arc_length"].as_f64().unwrap();
    assert!((length - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    assert!(r["split"]["left"]["weights"].is_array());
    // The rose at the notes' u = 5.739995, with the notes' derivative.
    let u: f64 = 5.739995;
    let r = curve("rose.json", &["--at", "5.739995", "--tangent"]);
    let d1 = [
        -2.0 * (2.0 * u).sin() * u.cos() - (2.0 * u).cos() * u.sin(),
        -2.0 * (2.0 * u).sin() * u.sin() + (2.0 * u).cos() * u.cos(),
        0.0,
    ];
    assert!(near(xyz(&r["at"]["d1"]), d1, 1e-13));
    assert_eq!(r["closed"], true);
    // The composite's pieces are mapped to [0, 1], [1, 2], [2, 3].
    let r = curve("composite_g1.json", &["--at", "1"]);
    assert_eq!(r["domain"], serde_json::json!([0.0, 3.0]));
    assert!(near(xyz(&r["at"]["point"]), [2.0, 1.0, 0.0], 1e-15));
    let r = curve("hermite_chain.json", &["--at", "2", "--tangent"]);
    assert!(near(xyz(&r["at"]["d1"]), [1.0, -1.0, 0.0], 1e-14));
}

#[test]
fn polylines_within_the_chord_error() {
    let dir = tempfile::tempdir().unwrap();
    for (name, certified) in [
        ("cubic_bezier.json", "certified"),
        ("rose.json", "estimated"),
    ] {
        for tol in ["0.01", "0.0001"] {
            let out = dir.path().join("line.json");
            let r = curve(name, &["-o", path_str(&out), "--chord-error", tol]);
            assert_eq!(r["polyline"]["bound"], certified);
            let line: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
            let points: Vec<[f64; 3]> =
                line["points"].as_array().unwrap().iter().map(xyz).collect();
            assert_eq!(r["polyline"]["points"], points.len());
            // The polyline's length approaches the arc length from below within the bound's
            // order: chords are shorter than arcs.
            let poly: f64 = points
                .windows(2)
                .map(|w| {
                    (0..3)
                        .map(|i| (w[1][i] - w[0][i]).powi(2))
                        .sum::<f64>()
                        .sqrt()
                })
                .sum();
            let arc = r["arc_length"].as_f64().unwrap();
            let tol: f64 = tol.parse().unwrap();
            assert!(
                poly <= arc + 1e-12 && arc - poly < 10.0 * tol * arc,
                "{name}: {poly} vs {arc}"
            );
        }
    }
    // OBJ: v lines then one l line through all of them; SVG: one path.
    let obj = dir.path().join("rose.obj");
    let r = curve("rose.json", &["-o", path_str(&obj), "--samples", "101"]);
    assert_eq!(r["polyline"]["bound"], "samples");
    let text = std::fs::read_to_string(&obj).unwrap();
    assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 101);
    let l = text.lines().find(|l| l.starts_with("l ")).unwrap();
    assert_eq!(l.split_whitespace().count(), 102);
    let svg = dir.path().join("rose.svg");
    curve("rose.json", &["-o", path_str(&svg)]);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains("<path d=\"M"));
}

#[test]
fn bad_curves_are_located_errors() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            r#"{"type": "composite", "pieces": [{"type": "bezier", "points": [[0, 0], [1, 1], [2, 1]]},
                {"type": "bezier", "points": [[2, 1], [3, 2], [4, 0]]}], "continuity": "G1"}"#,
            "2:17: pieces[1]: declared G1 but the tangents differ by",
        ),
        (
            r#"{"type": "bezier", "points": [[0, 0], [1, "a"]]}"#,
            "1:43: points[1]: expected a number",
        ),
        (
            r#"{"type": "formula", "x": "cos(w)", "y": "0", "domain": [0, 1]}"#,
            "x: column 5: unknown name 'w'",
        ),
        (
            r#"{"type": "hermite", "points": [[0, 0], [1, 1]], "tangents": [[1, 0]]}"#,
            "tangents: expected 2 tangents",
        ),
        (
            r#"{"type": "cubic_through", "points": [[0, 0], [1, 1]]}"#,
            "points: expected exactly 4 points, found 2",
        ),
        (
            r#"{"type": "spiral", "points": []}"#,
            "type: unknown curve type \"spiral\"",
        ),
        (r#"{"type": "bezier", "points": [[0, 0]"#, "1:"),
    ];
    for (i, (text, message)) in cases.iter().enumerate() {
        let f = dir.path().join(format!("bad{i}.json"));
        std::fs::write(&f, text).unwrap();
        let o = solidkit(&["curve", path_str(&f), "--at", "0"]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{text}: {err}");
        assert!(err.contains(message), "{text}: {err}");
        assert!(err.contains(&format!("bad{i}.json")), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    let rose = fixture("curves/rose.json");
    for (args, message) in [
        (vec!["--at", "7"], "outside the curve's domain"),
        (vec!["--split", "1"], "no control points to split"),
        (vec!["-o", "x.txt"], "unknown polyline format"),
        (
            vec!["-o", "x.obj", "--chord-error=-1"],
            "expected a positive number",
        ),
    ] {
        let mut a = vec!["curve", path_str(&rose)];
        a.extend(args);
        let o = solidkit(&a);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(message), "{err}");
    }
}

#[test]
fn bad_curve_profiles_are_located_errors() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            r#"{"type": "extrude", "height": 1, "profile": {"type": "curve",
                "curve": {"type": "bezier", "points": [[0, 0], [1, 1], [2, 0]]}}}"#,
            "profile: the curve must be closed",
        ),
        (
            r#"{"type": "extrude", "height": 1, "profile": {"type": "radial", "rho": "1",
                "chord_error": 0.01, "samples": 10}}"#,
            "profile.chord_error: give either chord_error or samples",
        ),
        (
            r#"{"type": "extrude", "height": 1, "profile": {"type": "radial", "rho": "1 + v"}}"#,
            "profile.rho: rho: column 5: unknown name 'v'",
        ),
        (
            r#"{"type": "sweep", "profile": {"type": "circle", "radius": 0.1},
                "path": {"type": "formula", "x": "u", "y": "0", "domain": [0, 1]}}"#,
            "path.type: a formula curve has no control points",
        ),
        (
            r#"{"type": "extrude", "height": 1, "profile": {"type": "curve",
                "curve": {"type": "composite", "continuity": "C1", "pieces": [
                  {"type": "bezier", "points": [[0, 0], [1, 1], [2, 0]]},
                  {"type": "bezier", "points": [[2, 0], [1, -1], [0, 0]]}]}}}"#,
            "profile.curve.pieces[1]: declared C1 but the derivative jumps",
        ),
    ];
    for (i, (text, message)) in cases.iter().enumerate() {
        let f = dir.path().join(format!("tree{i}.json"));
        std::fs::write(&f, text).unwrap();
        let o = solidkit(&["mesh", path_str(&f)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{text}: {err}");
        assert!(err.contains(message), "{text}: {err}");
    }
}

#[test]
fn costly_or_undefined_curves_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    // 300 control points: over the degree limit (every point counts at every parameter).
    let points: Vec<String> = (0..300).map(|i| format!("[{i}, {}]", i % 7)).collect();
    let big = dir.path().join("big.json");
    std::fs::write(
        &big,
        format!(r#"{{"type": "bezier", "points": [{}]}}"#, points.join(", ")),
    )
    .unwrap();
    // 1/u is infinite at u = 0: no polyline is written.
    let inf = dir.path().join("inf.json");
    std::fs::write(
        &inf,
        r#"{"type": "formula", "x": "1/u", "y": "u", "domain": [0, 1]}"#,
    )
    .unwrap();
    let out = dir.path().join("inf.obj");
    for (args, message) in [
        (vec![path_str(&big)], "300 control points: at most 256"),
        (
            vec![path_str(&inf), "-o", path_str(&out), "--samples", "5"],
            "not finite",
        ),
        (vec![path_str(&inf), "-o", path_str(&out)], "not finite"),
    ] {
        let mut a = vec!["curve"];
        a.extend(args);
        let o = solidkit(&a);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(message), "{err}");
    }
    assert!(!out.exists());
}
