//! Shared helpers of the integration suites: fixture paths and the tree → mesh → report path.
#![warn(missing_docs)]

use solidkit_kernel::{Solid, json};
use solidkit_meshing::pipeline::{MeshOptions, mesh_solid};
use solidkit_meshing::{IndexedMesh, TopologyReport};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Absolute path of a file under `fixtures/`.
pub fn fixture(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("fixtures")
        .join(rel)
}

/// Reads a JSON tree fixture.
pub fn load_tree(rel: &str) -> Solid {
    let text = std::fs::read_to_string(fixture(rel)).expect("fixture readable");
    let solid = json::from_str(&text).expect("fixture parses");
    solid.validate().expect("fixture valid");
    solid
}

/// Meshes a solid by (sparse) marching cubes at `resolution` cells along its longest side, as
/// `solidkit mesh` does. Every such mesh is also checked to have no self-intersection (marching
/// cubes never folds a surface onto itself).
pub fn mesh(solid: &Solid, resolution: usize) -> (IndexedMesh, TopologyReport) {
    let options = MeshOptions::new(resolution).no_refinement();
    let mesh = mesh_solid(solid, &options).expect("bounded solid").mesh;
    let report = TopologyReport::of(&mesh);
    assert_eq!(
        (
            report.self_intersections,
            &report.examples.self_intersections
        ),
        (Some(0), &Vec::new()),
        "self-intersecting marching-cubes mesh"
    );
    (mesh, report)
}

/// Relative difference `|a − b| / |b|`.
pub fn rel_err(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Runs the `solidkit` binary at `bin` (a test's `env!("CARGO_BIN_EXE_solidkit")`) with `args`.
pub fn run_cli(bin: &str, args: &[&str]) -> Output {
    Command::new(bin).args(args).output().expect("run solidkit")
}

/// The JSON a CLI run printed, asserting it exited with 0 (its standard error in the message).
pub fn success_json(o: &Output) -> serde_json::Value {
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&o.stdout)))
}

/// A path as `&str` for command lines (test paths are UTF-8).
pub fn path_str(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}
