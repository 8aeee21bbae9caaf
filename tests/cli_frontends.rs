//! The front ends through the real binary: `.rhai` scripts and OpenSCAD `.csg` exports mesh like their `.json` twins, the
//! example scripts mesh closed and manifold with the expected genus, `convert` writes the tree,
//! and a hostile script is stopped with a one-line located error.

use serde_json::Value;
use solidkit_tests::{fixture, path_str};
use std::path::Path;
use std::process::Output;
use std::time::{Duration, Instant};

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

fn mesh_report(input: &Path, out: Option<&Path>) -> Value {
    let mut args = vec!["mesh", path_str(input), "-r", "64", "--json"];
    if let Some(out) = out {
        args.extend(["-o", path_str(out)]);
    }
    let o = solidkit(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON report")
}

#[test]
fn the_same_model_as_rhai_json_and_csg_meshes_identically() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut meshes = Vec::new();
    for ext in ["rhai", "json", "csg"] {
        let stl = dir.path().join(format!("{ext}.stl"));
        let input = fixture(&format!("examples/ball_with_holes.{ext}"));
        let report = mesh_report(&input, Some(&stl));
        assert_eq!(report["genus"], 5, "{ext}: {report}");
        let bytes = std::fs::read(&stl).expect("mesh file");
        assert!(bytes.len() > 84 + 50 * 1000, "{ext}: a real mesh");
        meshes.push((ext, bytes));
    }
    for (ext, bytes) in &meshes[1..] {
        assert!(*bytes == meshes[0].1, "the .{ext} and .rhai meshes differ");
    }
}

#[test]
fn example_scripts_mesh_closed_and_manifold_with_their_genus() {
    // (script, shells, total genus)
    let cases = [
        ("ball_with_holes.rhai", 1, 5),
        ("perforated_plate.rhai", 1, 4),
        ("blobs_and_ring.rhai", 2, 1),
    ];
    for (name, shells, genus) in cases {
        let r = mesh_report(&fixture(&format!("examples/{name}")), None);
        assert_eq!(r["closed"], true, "{name}");
        assert_eq!(r["manifold"], true, "{name}");
        assert_eq!(r["oriented"], true, "{name}");
        assert_eq!(r["shells"], shells, "{name}");
        assert_eq!(r["genus"], genus, "{name}");
        assert!(r["volume"].as_f64().expect("volume") > 0.0, "{name}");
    }
}

#[test]
fn convert_writes_the_json_tree_of_a_script() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("model.json");
    let o = solidkit(&[
        "convert",
        path_str(&fixture("examples/ball_with_holes.rhai")),
        "-o",
        path_str(&out),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let written = std::fs::read_to_string(&out).expect("written tree");
    assert!(written.contains("\"format\": \"solidkit-tree\""));
    // The written tree converts to itself.
    let again = dir.path().join("again.json");
    let o = solidkit(&["convert", path_str(&out), "-o", path_str(&again)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read_to_string(&again).expect("again"), written);
}

/// `convert --facets openscad` writes OpenSCAD's faceted construction (a twisted extrusion as its
/// stack of flat slices: a polyhedron), the default the exact twisted sweep; parts OpenSCAD skips
/// are warned about on standard error, as `mesh` does.
#[test]
fn convert_takes_facets_and_says_what_it_skips() {
    let dir = tempfile::tempdir().expect("temp dir");
    let csg = dir.path().join("twisted.csg");
    std::fs::write(
        &csg,
        concat!(
            "linear_extrude(height = 20, twist = 90, slices = 8) square(size = [10, 10], center = true);\n",
            "linear_extrude(height = 0) square(size = [1, 1]);\n",
        ),
    )
    .expect("write csg");
    let tree = |facets: &str| {
        let out = dir.path().join(format!("{facets}.json"));
        let o = solidkit(&[
            "convert",
            path_str(&csg),
            "--facets",
            facets,
            "-o",
            path_str(&out),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
        (std::fs::read_to_string(&out).expect("written tree"), stderr)
    };
    let (faceted, warned) = tree("openscad");
    let (exact, _) = tree("exact");
    assert!(faceted.contains("\"polyhedron\""), "{faceted}");
    assert!(!exact.contains("\"polyhedron\""), "{exact}");
    assert!(
        warned.contains("warning: ") && warned.contains("twisted.csg:2:"),
        "{warned}"
    );
}

#[test]
fn hostile_and_broken_scripts_fail_with_one_located_line() {
    let dir = tempfile::tempdir().expect("temp dir");
    let cases = [
        (
            "loop.rhai",
            "let i = 0;\nwhile true { i += 1; }\n",
            "loop.rhai:2:",
        ),
        (
            "double.rhai",
            "let s = sphere(1);\nfor i in 0..60 { s = s | s; }\ns\n",
            "nodes",
        ),
        (
            "syntax.rhai",
            "let a = sphere(1);\nlet b = a -;\n",
            "syntax.rhai:2:12: syntax error",
        ),
    ];
    for (name, script, expected) in cases {
        let path = dir.path().join(name);
        std::fs::write(&path, script).expect("write script");
        let out = dir.path().join("out.json");
        let start = Instant::now();
        let o = solidkit(&["convert", path_str(&path), "-o", path_str(&out)]);
        // The sandbox's own limits bound the time (1.5 s deadline); this only guards against a
        // hang, loosely enough that a loaded machine cannot make it flaky.
        assert!(
            start.elapsed() < Duration::from_secs(20),
            "{name}: too slow"
        );
        assert_eq!(o.status.code(), Some(2), "{name}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        assert!(err.contains(expected), "{name}: {err}");
        assert!(!out.exists(), "{name}: output written on failure");
    }
}

/// A `.csg` part OpenSCAD skips with a warning (an `inf` cube) is skipped by `solidkit mesh`
/// too: the rest meshes, the warning is a located line on standard error and an entry of the
/// JSON report's `warnings`.
#[test]
fn csg_warnings_reach_the_report_and_stderr() {
    let dir = tempfile::tempdir().expect("temp dir");
    let input = dir.path().join("warn.csg");
    std::fs::write(
        &input,
        "cube(size = [inf, inf, inf], center = false);\n%sphere(r = 9);\ncube(size = 2, center = true);\n",
    )
    .expect("write");
    let o = solidkit(&["mesh", path_str(&input), "-r", "32", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r: Value = serde_json::from_slice(&o.stdout).expect("JSON report");
    let expected = format!(
        "{}:1:1: a size or point is inf or nan: the object is skipped",
        input.display()
    );
    assert_eq!(r["warnings"], serde_json::json!([expected]));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        stderr.contains(&format!("warning: {expected}\n")),
        "{stderr}"
    );
    assert_eq!(r["closed"], true);
    let v = r["volume"].as_f64().expect("volume");
    assert!((v - 8.0).abs() < 0.05, "{v}");
}

#[test]
fn define_sets_rhai_constants_and_is_refused_for_json() {
    let dir = tempfile::tempdir().expect("temp dir");
    let script = dir.path().join("plate.rhai");
    std::fs::write(
        &script,
        "let w = if is_def_var(\"w\") { w } else { 2.0 };\nbox([w, 1.0, 1.0])\n",
    )
    .expect("write");
    let size = |defines: &[&str]| {
        let mut args = vec!["mesh", path_str(&script), "-r", "16", "--json"];
        args.extend(defines.iter().flat_map(|d| ["-D", *d]));
        let o = solidkit(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let r: Value = serde_json::from_slice(&o.stdout).expect("JSON report");
        let b = &r["bbox"];
        b[1][0].as_f64().expect("bbox") - b[0][0].as_f64().expect("bbox")
    };
    assert!((size(&[]) - 2.0).abs() < 0.1, "{}", size(&[]));
    assert!((size(&["w=6.0"]) - 6.0).abs() < 0.1);
    let o = solidkit(&["mesh", path_str(&script), "-D", "w=wide"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("-D w=wide: the value is not a Rhai literal"),
        "{err}"
    );
    let tree = fixture("examples/ball_with_holes.json");
    let o = solidkit(&["mesh", path_str(&tree), "-D", "w=1"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("-D NAME=VALUE applies to .scad and .rhai inputs only"),
        "{err}"
    );
}
