//! Hostile meshing through the real binary (issue 15): the reduced crash fixtures of
//! `fixtures/hostile/` mesh to closed manifolds with marching cubes and dual contouring, open
//! mesh operands warn, and grids that single precision cannot represent are refused up front.

use serde_json::Value;
use solidkit_tests::{fixture, path_str};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

/// Runs `solidkit mesh` with `args`, asserting it ended within a few seconds.
fn mesh(args: &[&str]) -> Output {
    let start = Instant::now();
    let o = Command::new(BIN)
        .arg("mesh")
        .args(args)
        .args(["--no-progress", "--json"])
        .output()
        .expect("run solidkit");
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "{args:?} took too long"
    );
    o
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The report of a successful run, asserting a non-empty closed manifold mesh.
fn closed_manifold(o: &Output, what: &str) -> Value {
    let r = solidkit_tests::success_json(o);
    assert!(r["faces"].as_u64().unwrap() > 0, "{what}: {r}");
    assert_eq!(r["closed"], true, "{what}: {r}");
    assert_eq!(r["manifold"], true, "{what}: {r}");
    assert_eq!(r["boundary_edges"], 0, "{what}: {r}");
    r
}

#[test]
fn a_gyroid_in_a_huge_box_meshes_closed() {
    // The f32 sine's range reduction broke down beyond 1e8 (values up to 1e38 and ∞), outside the
    // intervals that culled and pruned boxes: neighbouring bricks disagreed on a sign and MC
    // panicked ("the owner lists the edge"); DC wrote an open mesh.
    let tree = fixture("hostile/gyroid_huge_box.json");
    for method in ["mc", "dc"] {
        for resolution in ["20", "32"] {
            let o = mesh(&[
                path_str(&tree),
                "--method",
                method,
                "--resolution",
                resolution,
            ]);
            closed_manifold(&o, &format!("{method} {resolution}"));
        }
    }
    // The same through --bounds on the bare (unbounded) gyroid.
    let dir = tempfile::tempdir().unwrap();
    let bare = dir.path().join("gyroid.json");
    std::fs::write(&bare, r#"{"type": "gyroid", "thickness": 0.3}"#).unwrap();
    let bounds = "--bounds=-1e12,-1e12,-1e12,1e12,1e12,1e12";
    for method in ["mc", "dc"] {
        let o = mesh(&[
            path_str(&bare),
            bounds,
            "--method",
            method,
            "--resolution",
            "20",
        ]);
        closed_manifold(&o, method);
    }
}

#[test]
fn an_open_mesh_operand_warns_and_meshes_closed() {
    // A tetrahedron without one face: the winding-number sign changes across the hole, away
    // from the triangles, where the Lipschitz interval claimed a sign; a culled neighbour left
    // a crossing edge without an owner and MC panicked ("a crossing edge lies in a surface brick").
    let tree = fixture("hostile/open_mesh_operand.json");
    for method in ["mc", "dc"] {
        for resolution in ["20", "32", "48"] {
            let o = mesh(&[
                path_str(&tree),
                "--method",
                method,
                "--resolution",
                resolution,
            ]);
            let r = closed_manifold(&o, &format!("{method} {resolution}"));
            let err = stderr(&o);
            assert!(
                err.contains("warning:")
                    && err.contains("open_tetrahedron.off")
                    && err.contains("3 open edges"),
                "{err}"
            );
            assert_eq!(r["warnings"].as_array().map(Vec::len), Some(1), "{r}");
            // The hole is capped: the solid is the whole tetrahedron (volume 1/6).
            let volume = r["volume"].as_f64().unwrap();
            assert!(
                (volume - 1.0 / 6.0).abs() < 0.03,
                "{method} {resolution}: {volume}"
            );
        }
    }
}

#[test]
fn grids_below_single_precision_are_refused_naming_the_bound() {
    let tree = fixture("hostile/far_small_sphere.json");
    let o = mesh(&[path_str(&tree), "--resolution", "128"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with("error: ") && err.contains("far_small_sphere.json: "),
        "{err}"
    );
    assert!(
        err.contains("too small for single-precision") && err.contains("e5"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    // A coarse enough grid is faithful and meshes.
    let o = mesh(&[path_str(&tree), "--resolution", "8"]);
    closed_manifold(&o, "resolution 8");
    // Bounds beyond the f32 range are refused too.
    let dir = tempfile::tempdir().unwrap();
    let plane = dir.path().join("plane.json");
    std::fs::write(
        &plane,
        r#"{"type": "plane", "normal": [0, 0, 1], "offset": 0}"#,
    )
    .unwrap();
    let o = mesh(&[path_str(&plane), "--bounds=-1e39,-1,-1,1e39,1,1"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("beyond single precision"), "{err}");
}
