//! The measurement commands through the real binary: `solidkit compare` (key measures of two
//! meshes and their Hausdorff distance, the JSON keys the cross-check harness reads) and its
//! error contract; self-intersections in `check` and `mesh` (exit code, `--no-self-intersections`).

use serde_json::Value;
use solidkit_tests::{fixture, path_str, success_json};
use std::path::Path;
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

fn compare_json(a: &Path, b: &Path, extra: &[&str]) -> Value {
    let mut args = vec!["compare", path_str(a), path_str(b), "--json"];
    args.extend_from_slice(extra);
    success_json(&solidkit(&args))
}

/// The unit cube scaled by `s` about its centre, as OFF text.
fn scaled_cube_off(s: f64) -> String {
    let cube = std::fs::read_to_string(fixture("meshes/defects/cube.off")).unwrap();
    let mut out = String::new();
    let mut vertex_lines = 0;
    for line in cube.lines() {
        let numbers: Vec<f64> = line
            .split_whitespace()
            .map_while(|w| w.parse().ok())
            .collect();
        if numbers.len() == 3 && !line.starts_with('#') && vertex_lines < 9 {
            // The first 3-number line is the counts; the next eight are vertices.
            if vertex_lines > 0 {
                let p = numbers.iter().map(|x| 0.5 + (x - 0.5) * s);
                let p: Vec<String> = p.map(|x| x.to_string()).collect();
                out.push_str(&p.join(" "));
                out.push('\n');
                vertex_lines += 1;
                continue;
            }
            vertex_lines += 1;
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}

#[test]
fn compare_reports_the_hausdorff_distance_of_a_scaled_cube() {
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.off");
    std::fs::write(&big, scaled_cube_off(1.5)).unwrap();
    let cube = fixture("meshes/defects/cube.off");
    let v = compare_json(&cube, &big, &["--samples", "5000"]);
    let (a, b, h) = (&v["a"], &v["b"], &v["hausdorff"]);
    assert_eq!(a["closed"], true);
    assert_eq!(b["genus"], 0);
    assert!(a["self_intersections"].is_null());
    assert!((a["volume"].as_f64().unwrap() - 1.0).abs() < 1e-12);
    assert!((b["volume"].as_f64().unwrap() - 3.375).abs() < 1e-12);
    let get = |k: &str| h[k].as_f64().unwrap_or_else(|| panic!("{k}: {h}"));
    // Inner to outer: 1/4 everywhere; outer to inner: √3/4 at the corners.
    assert!((get("a_to_b") - 0.25).abs() < 1e-12, "{h}");
    assert!((get("mean_a_to_b") - 0.25).abs() < 1e-12, "{h}");
    assert!((get("b_to_a") - 3f64.sqrt() / 4.0).abs() < 1e-12, "{h}");
    assert!(get("mean_b_to_a") > 0.25 && get("mean_b_to_a") < get("b_to_a"));
    assert_eq!(get("symmetric"), get("b_to_a"));
    assert!((get("diagonal") - 3f64.sqrt()).abs() < 1e-12);
    assert!((get("relative") - 0.25).abs() < 1e-12);
    assert_eq!(h["samples"], 5000);
    assert_eq!(
        (h["points_a"].as_u64(), h["points_b"].as_u64()),
        (Some(5008), Some(5008))
    );
}

#[test]
fn compare_measures_open_meshes_and_exits_zero() {
    // The cube against itself less one triangle of its x = 1 side (legs 1): the deepest point of the missing
    // triangle is its incentre, (2 − √2)/2 from the rest of the cube.
    let (cube, hole) = (
        fixture("meshes/defects/cube.off"),
        fixture("meshes/defects/cube_hole.off"),
    );
    let v = compare_json(&cube, &hole, &[]);
    let h = &v["hausdorff"];
    assert_eq!(v["b"]["closed"], false);
    assert!(h["b_to_a"].as_f64().unwrap() < 1e-12, "{h}");
    let inradius = (2.0 - 2f64.sqrt()) / 2.0;
    let a_to_b = h["a_to_b"].as_f64().unwrap();
    assert!(a_to_b <= inradius + 1e-12 && a_to_b > 0.27, "{h}");
    // The text form names both files and the distance.
    let o = solidkit(&[
        "compare",
        path_str(&cube),
        path_str(&hole),
        "--samples",
        "100",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("cube_hole.off") && text.contains("hausdorff:"),
        "{text}"
    );
}

#[test]
fn compare_rejects_bad_input_with_exit_two() {
    let dir = tempfile::tempdir().unwrap();
    let cube = fixture("meshes/defects/cube.off");
    let flat = dir.path().join("collapsed.off");
    std::fs::write(&flat, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n").unwrap();
    let missing = dir.path().join("missing.stl");
    for (b, phrase) in [(&flat, "no usable triangles"), (&missing, "missing.stl")] {
        let o = solidkit(&["compare", path_str(&cube), path_str(b)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(phrase) && err.contains(path_str(b)), "{err}");
    }
}

#[test]
fn check_fails_a_self_intersecting_mesh_unless_skipped() {
    let file = fixture("meshes/defects/self_intersecting.off");
    let o = solidkit(&["check", path_str(&file), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let r: Value = serde_json::from_slice(&o.stdout).unwrap();
    // Topologically sound (two closed cubes), but crossing.
    assert_eq!(
        (r["closed"].as_bool(), r["manifold"].as_bool()),
        (Some(true), Some(true))
    );
    let count = r["self_intersections"].as_u64().unwrap();
    let pairs = r["examples"]["self_intersections"].as_array().unwrap();
    assert!(count > 0 && !pairs.is_empty() && pairs.len() as u64 <= count);
    let text = solidkit(&["check", path_str(&file)]);
    assert_eq!(text.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&text.stdout).contains("intersecting faces:"));

    let skipped = solidkit(&[
        "check",
        path_str(&file),
        "--json",
        "--no-self-intersections",
    ]);
    assert_eq!(skipped.status.code(), Some(0));
    let r: Value = serde_json::from_slice(&skipped.stdout).unwrap();
    assert!(r["self_intersections"].is_null());
    let clean = solidkit(&[
        "check",
        path_str(&fixture("meshes/defects/cube.off")),
        "--json",
    ]);
    assert_eq!(clean.status.code(), Some(0));
    let r: Value = serde_json::from_slice(&clean.stdout).unwrap();
    assert_eq!(r["self_intersections"], 0);
}

#[test]
fn mesh_counts_self_intersections_unless_skipped() {
    let tree = fixture("trees/torus.json");
    let run = |extra: &[&str]| {
        let mut args = vec!["mesh", path_str(&tree), "--resolution", "32", "--json"];
        args.extend_from_slice(extra);
        let o = solidkit(&args);
        assert_eq!(o.status.code(), Some(0));
        serde_json::from_slice::<Value>(&o.stdout).unwrap()
    };
    let full = run(&[]);
    assert_eq!(full["self_intersections"], 0);
    assert_eq!(full["self_intersections_method"], "construction");
    let dc = run(&["--method", "dc"]);
    assert_eq!(dc["self_intersections"], 0);
    assert_eq!(dc["self_intersections_method"], "construction");
    let skipped = run(&["--no-self-intersections"]);
    assert!(skipped["self_intersections"].is_null());
    assert!(skipped["self_intersections_method"].is_null());
}
