//! Small inputs with huge evaluation cost (issue 15), through the real binary in a 1 GiB address
//! space: a blob of 3000 balls (33 s before culling), an extrusion of a 30 000-point polygon (over
//! 60 s) and a 2000 × 2000 Bézier height field (minutes). Balls and edges are culled per sample
//! (the meshes are checked against references), and Bézier nets beyond the evaluation budget are
//! refused with a located error, exit 2 (a single patch of high degree has no local support to
//! cull). The inputs are generated here; nothing multi-megabyte is committed.

use serde_json::Value;
use solidkit_tests::path_str;
use std::fmt::Write;
use std::path::Path;
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

/// `solidkit mesh` on `input` with `args` in a 1 GiB address space where `prlimit` exists (two
/// threads, as on the CI machine).
fn mesh(input: &Path, args: &[&str]) -> Output {
    let limited = Command::new("prlimit").arg("--version").output().is_ok();
    let mut cmd = if limited {
        let mut c = Command::new("prlimit");
        c.arg("--as=1073741824").arg(BIN);
        c
    } else {
        Command::new(BIN)
    };
    cmd.arg("mesh")
        .arg(path_str(input))
        .args(args)
        .args(["--threads", "2", "--no-progress", "--json"])
        .output()
        .expect("run solidkit")
}

/// The report of a successful run, asserting a closed manifold mesh.
fn closed_manifold(o: &Output, what: &str) -> Value {
    let r = solidkit_tests::success_json(o);
    assert!(r["faces"].as_u64().unwrap() > 0, "{what}: {r}");
    assert_eq!(r["closed"], true, "{what}: {r}");
    assert_eq!(r["manifold"], true, "{what}: {r}");
    assert_eq!(r["boundary_edges"], 0, "{what}: {r}");
    r
}

/// A small deterministic generator (xorshift), uniform in `[0, 1)`.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A blob of `clusters` copies of one cluster of 20 random balls, 4 apart on a lattice (6 along
/// x, 5 along y and z): far enough that the copies do not interact (their terms are below 10⁻⁷
/// of the threshold between them), so the blob's volume is `clusters` times the cluster's.
fn clustered_blob(clusters: usize) -> String {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let cluster: Vec<[f64; 3]> = (0..20)
        .map(|_| [rng.next() * 1.2, rng.next() * 1.2, rng.next() * 1.2])
        .collect();
    let mut balls = Vec::new();
    for k in 0..clusters {
        let at = [(k % 6) as f64, ((k / 6) % 5) as f64, (k / 30) as f64].map(|c| 4.0 * c);
        for c in &cluster {
            balls.push(format!(
                r#"{{"center": [{}, {}, {}], "strength": 1, "sharpness": 4}}"#,
                at[0] + c[0],
                at[1] + c[1],
                at[2] + c[2]
            ));
        }
    }
    format!(
        r#"{{"type": "blob", "threshold": 0.5, "balls": [{}]}}"#,
        balls.join(",")
    )
}

#[test]
fn a_blob_of_3000_balls_meshes_as_150_copies_of_its_cluster() {
    let dir = tempfile::tempdir().unwrap();
    let (one, many) = (dir.path().join("one.json"), dir.path().join("many.json"));
    std::fs::write(&one, clustered_blob(1)).unwrap();
    std::fs::write(&many, clustered_blob(150)).unwrap();
    // The same cell size for both: 150 clusters span 21.2 × 17.2 × 17.2 (res 128: cell 0.166);
    // one spans about 2.4 (the padded box decides the exact cell, so compare loosely).
    let r = closed_manifold(&mesh(&many, &["--resolution", "128"]), "3000 balls");
    // The single cluster (20 balls: the plain full sum, no culling) is the reference.
    let reference = closed_manifold(&mesh(&one, &["--resolution", "16"]), "20 balls");
    let shells = reference["shells"].as_u64().unwrap();
    assert_eq!(r["shells"].as_u64(), Some(150 * shells), "{r}");
    let (v, v1) = (
        r["volume"].as_f64().unwrap(),
        reference["volume"].as_f64().unwrap(),
    );
    assert!((v / (150.0 * v1) - 1.0).abs() < 0.03, "{v} vs 150 × {v1}");
    // Finer, the single cluster converges to what the copies give.
    let fine = closed_manifold(&mesh(&one, &["--resolution", "64"]), "20 balls fine");
    let v_fine = fine["volume"].as_f64().unwrap();
    assert!(
        (v / (150.0 * v_fine) - 1.0).abs() < 0.02,
        "{v} vs 150 × {v_fine}"
    );
}

#[test]
fn an_extrusion_of_a_30000_point_polygon_meshes_to_its_volume() {
    let n = 30_000;
    let mut points = String::new();
    let mut twice_area = 0.0;
    let corner = |i: usize| {
        let t = std::f64::consts::TAU * i as f64 / n as f64;
        let r = 1.0 + 0.3 * (7.0 * t).cos();
        (r * t.cos(), r * t.sin())
    };
    for i in 0..n {
        let (x, y) = corner(i);
        let (x1, y1) = corner((i + 1) % n);
        twice_area += x * y1 - x1 * y;
        if i > 0 {
            points.push(',');
        }
        write!(points, "[{x:.9}, {y:.9}]").unwrap();
    }
    let dir = tempfile::tempdir().unwrap();
    let tree = dir.path().join("extrude.json");
    std::fs::write(
        &tree,
        format!(
            r#"{{"type": "extrude", "height": 1, "profile": {{"type": "polygon", "points": [{points}]}}}}"#
        ),
    )
    .unwrap();
    for method in ["mc", "dc"] {
        let r = closed_manifold(
            &mesh(&tree, &["--resolution", "96", "--method", method]),
            method,
        );
        assert_eq!(r["shells"], 1, "{r}");
        let v = r["volume"].as_f64().unwrap();
        let exact = 0.5 * twice_area;
        assert!((v / exact - 1.0).abs() < 0.005, "{method}: {v} vs {exact}");
    }
}

/// A `bezier` height field over the unit square with an `nx × ny` net of `z(i, j)`.
fn bezier_tree(nx: usize, ny: usize, z: impl Fn(usize, usize) -> f64) -> String {
    let mut rows = String::new();
    for j in 0..ny {
        rows.push_str(if j > 0 { ",[" } else { "[" });
        for i in 0..nx {
            if i > 0 {
                rows.push(',');
            }
            write!(rows, "{}", z(i, j)).unwrap();
        }
        rows.push(']');
    }
    format!(
        "{{\"type\": \"heightfield\", \"min\": [0, 0], \"max\": [1, 1], \"base\": 0,\n\"bezier\": [{rows}]}}"
    )
}

#[test]
fn a_2000_by_2000_bezier_net_is_refused_with_its_cost_and_location() {
    let dir = tempfile::tempdir().unwrap();
    let tree = dir.path().join("bezier.json");
    std::fs::write(&tree, bezier_tree(2000, 2000, |i, j| ((i + j) % 2) as f64)).unwrap();
    let o = mesh(&tree, &[]);
    assert_eq!(o.status.code(), Some(2), "{o:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("bezier.json:2:")
            && err.contains("bezier")
            && err.contains("2000 × 2000")
            && err.contains("4000000 multiply-adds")
            && err.contains("samples"),
        "{err}"
    );
    assert!(err.lines().count() <= 3, "{err}");
}

#[test]
fn a_bezier_net_at_the_budget_meshes_to_its_exact_volume() {
    // ∫∫ h = the mean control height (each Bernstein polynomial integrates to 1/(m + 1)).
    // A gentle surface: steeper nets send refinement after thin-feature suspicions at the
    // sides (a cost of its own, not of evaluation).
    let z = |i: usize, j: usize| 0.5 + 0.2 * ((i as f64 * 0.01).sin() * (j as f64 * 0.013).cos());
    let mean = (0..64 * 64).map(|k| z(k % 64, k / 64)).sum::<f64>() / 4096.0;
    let dir = tempfile::tempdir().unwrap();
    let tree = dir.path().join("bezier.json");
    std::fs::write(&tree, bezier_tree(64, 64, z)).unwrap();
    let r = closed_manifold(&mesh(&tree, &["--resolution", "48"]), "64 × 64");
    let v = r["volume"].as_f64().unwrap();
    assert!((v / mean - 1.0).abs() < 0.01, "{v} vs {mean}");
}
