//! Shared helpers of the integration suites: fixture paths and the tree → mesh → report path.
#![warn(missing_docs)]

use solidkit_kernel::{Solid, json};
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use solidkit_meshing::{IndexedMesh, TopologyReport};
use std::path::PathBuf;

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
    let spec = GridSpec::for_bounds(&solid.bbox(), resolution).expect("bounded solid");
    let (mesh, _) =
        mesh_sparse(&solid.compile(), spec, &SparseOptions::default()).expect("not cancelled");
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
