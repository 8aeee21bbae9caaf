//! Formula solids (`expr`, issue 21) through the binary: bad formulas and boxes end with a
//! located error, exit 2 and no output; the example meshes with its stated shells, genus and
//! volume.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

fn run_cli(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().expect("run solidkit")
}

fn path_str(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

fn fixture(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../fixtures")
        .join(rel)
}

fn rel_err(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn bad_formulas_and_boxes_are_located_errors() {
    let dir = tempfile::tempdir().expect("temp dir");
    let cases = [
        (
            r#"{"type": "expr", "formula": "x + foo(y)", "bounds": [[0, 0, 0], [1, 1, 1]]}"#,
            "unknown name 'foo'",
        ),
        (
            r#"{"type": "expr", "formula": "x ^ y", "bounds": [[0, 0, 0], [1, 1, 1]]}"#,
            "exponent must be a constant",
        ),
        (
            r#"{"type": "expr", "formula": "x", "bounds": [[0, 0, 0], [1, -1, 1]]}"#,
            "bounds",
        ),
        (
            r#"{"type": "expr", "formula": 3, "bounds": [[0, 0, 0], [1, 1, 1]]}"#,
            "expected a string",
        ),
        (
            r#"{"type": "expr", "formula": "x"}"#,
            "missing key \"bounds\"",
        ),
    ];
    for (i, (text, message)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("bad{i}.json"));
        std::fs::write(&path, text).expect("write");
        let out = dir.path().join("out.stl");
        let o = run_cli(&["mesh", path_str(&path), "-o", path_str(&out)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{text}: {err}");
        assert!(
            err.contains(message) && err.contains(&format!("bad{i}.json:1:")),
            "{err}"
        );
        assert!(!out.exists());
    }
}

#[test]
fn the_formula_example_meshes_from_the_command_line() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("f.stl");
    let example = fixture("examples/formula_solids.rhai");
    let o = run_cli(&[
        "mesh",
        path_str(&example),
        "--resolution",
        "96",
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
    let r: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON report");
    assert_eq!(
        (r["shells"].as_u64(), r["genus"].as_u64()),
        (Some(3), Some(1))
    );
    let exact = 2.0 * PI * PI * 0.09 + 4.0 / 3.0 * PI * 0.125 + 0.6 * 4.0 * PI * PI;
    let v = r["volume"].as_f64().expect("volume");
    assert!(rel_err(v, exact) < 0.01, "{v} vs {exact}");
}
