//! `.scad` inputs through the installed OpenSCAD (issue 14): `solidkit mesh model.scad -D
//! name=value` meshes what OpenSCAD exports, and without OpenSCAD the run ends with a located
//! error, exit 2 and no output file.

use std::path::Path;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

fn openscad_installed() -> bool {
    std::env::var_os("PATH")
        .is_some_and(|p| std::env::split_paths(&p).any(|d| d.join("openscad").is_file()))
}

fn write_model(dir: &Path) -> std::path::PathBuf {
    let file = dir.join("plate.scad");
    std::fs::write(
        &file,
        "w = 1;\nmodule plate(w) { difference() { cube([w, w, 1]); translate([w / 2, w / 2, -1]) \
         cylinder(r = w / 4, h = 3); } }\nplate(w);\n",
    )
    .unwrap();
    file
}

#[test]
fn scad_meshes_what_openscad_exports_with_defines() {
    if !openscad_installed() {
        eprintln!("skipped: openscad is not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = write_model(dir.path());
    let out = Command::new(BIN)
        .args([
            "mesh",
            file.to_str().unwrap(),
            "-D",
            "w=4",
            "--resolution",
            "64",
            "--json",
        ])
        .args(["--no-progress", "--no-self-intersections"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let r: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    // A 4 x 4 x 1 plate with an exact hole of radius 1: 16 - pi.
    let volume = r["volume"].as_f64().unwrap();
    assert!(
        (volume - (16.0 - std::f64::consts::PI)).abs() < 0.02,
        "{volume}"
    );
    assert_eq!(r["genus"], 1);
    assert_eq!(r["closed"], true);
}

#[test]
fn scad_without_openscad_is_a_located_error_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_model(dir.path());
    let stl = dir.path().join("out.stl");
    let out = Command::new(BIN)
        .args(["mesh", file.to_str().unwrap(), "-o", stl.to_str().unwrap()])
        .env("PATH", dir.path())
        .env_remove("SOLIDKIT_OPENSCAD")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(&format!("{}: openscad is not installed", file.display())),
        "{err}"
    );
    assert!(!stl.exists());
}
