//! The command-line contract: `solidkit mesh` and `solidkit check` outputs, exit codes, one-line
//! errors, and no output file left behind on failure. Runs the real binary.

use serde_json::Value;
use solidkit_tests::{fixture, path_str};
use std::path::Path;
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

fn stdout_json(o: &Output) -> Value {
    serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&o.stdout)))
}

const KEYS: [&str; 18] = [
    "vertices",
    "edges",
    "faces",
    "euler_characteristic",
    "shells",
    "genus",
    "boundary_edges",
    "non_manifold_edges",
    "non_manifold_vertices",
    "oriented",
    "closed",
    "manifold",
    "degenerate_faces",
    "volume",
    "area",
    "bbox",
    "self_intersections",
    "self_intersections_method",
];

#[test]
fn mesh_writes_the_file_and_reports_stable_keys() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("torus.stl");
    let tree = fixture("trees/torus.json");
    let o = solidkit(&[
        "mesh",
        path_str(&tree),
        "--resolution",
        "64",
        "-o",
        path_str(&out),
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let r = stdout_json(&o);
    for k in KEYS.iter().chain(&["time_s", "resolution"]) {
        assert!(r.get(k).is_some(), "missing key {k}");
    }
    assert_eq!(r["genus"], 1);
    assert_eq!(r["euler_characteristic"], 0);
    assert_eq!(r["self_intersections"], 0);
    assert_eq!(r["resolution"], 64);
    assert!(r["bbox"][0].as_array().unwrap().len() == 3);
    // The written mesh checks clean and has the same counts.
    let c = solidkit(&["check", path_str(&out), "--json"]);
    assert_eq!(c.status.code(), Some(0));
    let rc = stdout_json(&c);
    for k in [
        "vertices",
        "edges",
        "faces",
        "genus",
        "shells",
        "self_intersections",
    ] {
        assert_eq!(rc[k], r[k], "{k}");
    }
    // mesh knows marching cubes' self-intersections by construction; check always tests.
    assert_eq!(r["self_intersections_method"], "construction");
    assert_eq!(rc["self_intersections_method"], "tested");
}

#[test]
fn mesh_prints_a_readable_report() {
    let tree = fixture("trees/two_spheres.json");
    let o = solidkit(&["mesh", path_str(&tree), "--resolution", "48"]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("shells") && text.contains('2'), "{text}");
    assert!(text.contains("time"), "{text}");
}

#[test]
fn explicit_bounds_mesh_an_unbounded_solid() {
    let dir = tempfile::tempdir().unwrap();
    let tree = dir.path().join("half.json");
    std::fs::write(
        &tree,
        r#"{"type": "plane", "normal": [0, 0, 1], "offset": 0.25}"#,
    )
    .unwrap();
    let o = solidkit(&["mesh", path_str(&tree), "--resolution", "16", "--json"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--bounds"));
    let o = solidkit(&[
        "mesh",
        path_str(&tree),
        "--resolution",
        "16",
        "--bounds",
        "-1,-1,-1,1,1,1",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let r = stdout_json(&o);
    // The grid is padded by a cell, so the slab is closed: a box 2 x 2 x 1.25 (up to the padding).
    assert_eq!(r["closed"], true);
    assert_eq!(r["genus"], 0);
}

fn check_defect(file: &str) -> Value {
    let o = solidkit(&["check", path_str(&fixture(file)), "--json"]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{file}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    stdout_json(&o)
}

#[test]
fn check_reports_defects_with_exit_code_one() {
    let hole = check_defect("meshes/defects/cube_hole.off");
    assert_eq!(
        (hole["boundary_edges"].as_u64(), hole["closed"].as_bool()),
        (Some(3), Some(false))
    );
    assert_eq!(hole["faces"], 11);
    let flipped = check_defect("meshes/defects/cube_flipped.off");
    assert_eq!(flipped["oriented"], false);
    assert_eq!(flipped["boundary_edges"], 0);
    assert_eq!(flipped["inconsistent_edges"], 3);
    let fin = check_defect("meshes/defects/fin.off");
    assert_eq!(fin["non_manifold_edges"], 1);
    assert_eq!(fin["manifold"], false);
    assert_eq!(
        fin["examples"]["non_manifold_edges"]
            .as_array()
            .unwrap()
            .len(),
        1
    );
    let good = solidkit(&["check", path_str(&fixture("meshes/defects/cube.off"))]);
    assert_eq!(good.status.code(), Some(0));
}

#[test]
fn check_text_names_the_offending_edges() {
    let o = solidkit(&["check", path_str(&fixture("meshes/defects/fin.off"))]);
    assert_eq!(o.status.code(), Some(1));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("non-manifold edges"), "{text}");
}

/// Runs a failing command and checks the error contract: exit 2, one line on stderr naming the
/// file and the expected phrase, no panic, and no output file.
fn assert_clean_failure(args: &[&str], names: &str, phrase: &str, out: Option<&Path>) {
    let o = solidkit(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.contains(names) && err.contains(phrase), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    if let Some(out) = out {
        let left: Vec<_> = std::fs::read_dir(out.parent().unwrap()).unwrap().collect();
        assert!(!out.exists(), "output left behind");
        assert!(left.iter().all(|e| {
            !e.as_ref()
                .unwrap()
                .file_name()
                .to_string_lossy()
                .contains("out.stl")
        }));
    }
}

#[test]
fn bad_input_fails_cleanly_with_exit_two() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let out = d.join("out.stl");
    let o = path_str(&out);

    let malformed = d.join("malformed.json");
    std::fs::write(&malformed, "{\"type\": \"sphere\",\n \"radius\": 1,\n").unwrap();
    assert_clean_failure(
        &["mesh", path_str(&malformed), "-o", o],
        "malformed.json:3:1",
        "unexpected end of input",
        Some(&out),
    );

    let nan = d.join("nan.json");
    std::fs::write(&nan, "{\"type\": \"sphere\", \"radius\": NaN}").unwrap();
    assert_clean_failure(
        &["mesh", path_str(&nan), "-o", o],
        "nan.json:1:30",
        "NaN",
        Some(&out),
    );

    let negative = d.join("negative.json");
    std::fs::write(
        &negative,
        "{\"type\": \"union\", \"children\": [\n {\"type\": \"sphere\", \"radius\": -1}]}",
    )
    .unwrap();
    assert_clean_failure(
        &["mesh", path_str(&negative), "-o", o],
        "negative.json:2:31",
        "children[0].radius: expected a positive number",
        Some(&out),
    );

    // A binary STL whose header promises more triangles than the file holds.
    let stl = d.join("truncated.stl");
    let mut bytes = vec![0u8; 80];
    bytes.extend_from_slice(&12u32.to_le_bytes());
    bytes.extend_from_slice(&[0u8; 100]);
    std::fs::write(&stl, &bytes).unwrap();
    assert_clean_failure(&["check", path_str(&stl)], "truncated.stl", "byte", None);

    let obj = d.join("bad_index.obj");
    std::fs::write(&obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n").unwrap();
    assert_clean_failure(
        &["check", path_str(&obj)],
        "bad_index.obj:5",
        "out of range",
        None,
    );

    assert_clean_failure(
        &["check", path_str(&d.join("missing.stl"))],
        "missing.stl",
        "",
        None,
    );
    assert_clean_failure(
        &["mesh", path_str(&d.join("model.step"))],
        "model.step",
        "unsupported",
        None,
    );
    let tree = fixture("trees/sphere.json");
    assert_clean_failure(
        &["mesh", path_str(&tree), "-o", path_str(&d.join("out.xyz"))],
        "out.xyz",
        "",
        None,
    );
}

#[test]
fn a_failed_write_keeps_the_previous_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("keep.stl");
    std::fs::write(&out, b"previous").unwrap();
    let bad = dir.path().join("bad.json");
    std::fs::write(&bad, "{\"type\": \"box\", \"size\": [1, 0, 1]}").unwrap();
    let o = solidkit(&["mesh", path_str(&bad), "-o", path_str(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read(&out).unwrap(), b"previous");
}

#[test]
fn one_and_two_threads_write_identical_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let tree = fixture("examples/bracket.json");
    let mut outputs = Vec::new();
    for threads in ["1", "2"] {
        let out = dir.path().join(format!("bracket-{threads}.stl"));
        let o = solidkit(&[
            "--threads",
            threads,
            "mesh",
            path_str(&tree),
            "--resolution",
            "80",
            "-o",
            path_str(&out),
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        outputs.push(std::fs::read(&out).unwrap());
    }
    assert!(outputs[0].len() > 84);
    assert!(
        outputs[0] == outputs[1],
        "1 and 2 threads wrote different files"
    );
}

/// `--method dc` meshes a closed manifold of the right genus; `--tolerance` (dual contouring only)
/// gives fewer triangles with the same topology; a tolerance with marching cubes, or a
/// non-positive one, is a one-line error with exit code 2.
#[test]
fn mesh_with_dual_contouring_and_tolerance() {
    let tree = fixture("trees/torus.json");
    let run = |extra: &[&str]| {
        let mut args = vec!["mesh", path_str(&tree), "--resolution", "48", "--json"];
        args.extend_from_slice(extra);
        solidkit(&args)
    };
    let plain = run(&["--method", "dc"]);
    assert_eq!(
        plain.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&plain.stderr)
    );
    let plain = stdout_json(&plain);
    assert_eq!(
        (plain["genus"].as_i64(), plain["closed"].as_bool()),
        (Some(1), Some(true))
    );
    assert_eq!(plain["method"], "dc");
    let coarse = run(&["--method", "dc", "--tolerance", "0.01"]);
    assert_eq!(coarse.status.code(), Some(0));
    let coarse = stdout_json(&coarse);
    assert_eq!(coarse["genus"].as_i64(), Some(1));
    assert_eq!(coarse["manifold"].as_bool(), Some(true));
    assert!(coarse["faces"].as_u64() < plain["faces"].as_u64());
    for bad in [
        &["--tolerance", "0.01"][..],
        &["--method", "dc", "--tolerance", "-1"],
    ] {
        let o = run(bad);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.starts_with("error:") && err.contains("tolerance"),
            "{err}"
        );
    }
}

/// `--target-error` (dual contouring, then `--simplify`) meshes a box in at most 48 triangles
/// with the topology kept and self-intersections tested; `--simplify` works after marching cubes
/// too; a non-positive error, or one beside `--tolerance`, is an error with exit code 2.
#[test]
fn mesh_with_target_error_and_simplify() {
    let dir = tempfile::tempdir().unwrap();
    let tree = dir.path().join("box.json");
    std::fs::write(
        &tree,
        r#"{"format": "solidkit-tree", "version": 1, "root": {"type": "box", "size": [1, 2, 0.5]}}"#,
    )
    .unwrap();
    let run = |extra: &[&str]| {
        let mut args = vec!["mesh", path_str(&tree), "--resolution", "24", "--json"];
        args.extend_from_slice(extra);
        solidkit(&args)
    };
    let small = run(&["--target-error", "0.001"]);
    assert_eq!(
        small.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&small.stderr)
    );
    let small = stdout_json(&small);
    assert_eq!(small["method"], "dc");
    assert!(small["faces"].as_u64().unwrap() <= 48, "{small}");
    assert_eq!(small["genus"].as_i64(), Some(0));
    assert_eq!(small["closed"].as_bool(), Some(true));
    assert_eq!(small["self_intersections"].as_u64(), Some(0));
    assert_eq!(small["self_intersections_method"], "tested");
    let volume = small["volume"].as_f64().unwrap();
    assert!((volume - 1.0).abs() < 0.01, "{volume}");
    let mc = stdout_json(&run(&[]));
    let mc_small = stdout_json(&run(&["--simplify", "0.01"]));
    assert!(mc_small["faces"].as_u64() < mc["faces"].as_u64());
    assert_eq!(mc_small["manifold"].as_bool(), Some(true));
    for bad in [
        &["--target-error", "0"][..],
        &["--target-error", "0.01", "--tolerance", "0.01"],
    ] {
        let o = run(bad);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
    }
}

/// `bench` runs each case in a child process per method and reports both, with their checks.
#[test]
fn bench_runs_both_methods_in_child_processes() {
    let o = solidkit(&[
        "--threads",
        "1",
        "bench",
        "--model",
        "sphere",
        "--resolution",
        "24",
        "--method",
        "mc,dc",
        "--repeat",
        "1",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v = stdout_json(&o);
    let cases = v["cases"].as_array().expect("cases");
    let methods: Vec<&str> = cases
        .iter()
        .map(|c| c["method"].as_str().unwrap())
        .collect();
    assert_eq!(methods, ["mc", "dc"]);
    for c in cases {
        assert_eq!(c["check_passed"], Value::Bool(true), "{c}");
        assert!(c["peak_memory_bytes"].as_u64().is_some(), "{c}");
    }
    let bad = solidkit(&["bench", "--method", "xx"]);
    assert_eq!(bad.status.code(), Some(2));
}
