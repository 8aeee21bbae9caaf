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
                // Every cell holds many periods: refinement would chase them to its budget.
                "--refine",
                "1",
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
            "--refine",
            "1",
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

/// Asserts a refusal (exit 2, one `error:` line naming the file and the node's path) containing
/// every piece of `expected`.
fn refused(o: &Output, file: &str, expected: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    let last = err.lines().last().unwrap_or_default();
    assert!(last.starts_with("error: ") && last.contains(file), "{err}");
    for e in expected {
        assert!(last.contains(e), "expected {e:?} in {err}");
    }
}

#[test]
fn parameters_beyond_faithful_evaluation_are_refused_with_their_path() {
    // Issue 15, second round (found by cli_hostile_fuzz): a radius of 5e-324 made 1/r overflow
    // and r round to 0 in f32 (0·∞ = NaN samples, open meshes); vertices of 1e300 overflowed the
    // f32 evaluation of a blend; an affine map with a zero row passed as regular because the
    // smallest singular value came from the smallest eigenvalue of AᵀA (accurate to ε·σ_max² only:
    // 10¹² here), so the field was scaled far beyond a distance bound.
    for (file, expected) in [
        (
            "subnormal_ellipsoid.json",
            &["children[0].radii", "between 1e-30 and 1e30"][..],
        ),
        (
            "huge_polyhedron_blend.json",
            &["children[1].vertices[1]", "beyond ±1e30"][..],
        ),
        ("ill_conditioned_affine.json", &["matrix", "singular"][..]),
        // A ball of strength 1e300 was ∞ in single precision (third round: 3 open meshes in
        // 6000 trees).
        (
            "blob_huge_strength.json",
            &["balls[0].strength", "between 1e-30 and 1e30"][..],
        ),
    ] {
        let tree = fixture(&format!("hostile/{file}"));
        for method in ["mc", "dc"] {
            let o = mesh(&[path_str(&tree), "--method", method, "--resolution", "20"]);
            refused(&o, file, expected);
        }
    }
}

#[test]
fn a_cone_taller_than_1e20_meshes_closed() {
    // The side distance |q − (a + t·ab)| cancelled catastrophically (errors of ε·h ≈ 10⁴ for a
    // height of 10²⁰): samples and the Lipschitz interval disagreed and the mesh was open (MC) or
    // non-manifold (under the mirror). Projection on the side's unit normal is stable.
    let tree = fixture("hostile/tall_cone.json");
    let bounds = "--bounds=-0.8667735304825666,-0.8667735304825666,-0.8667735304825666,\
                  1.8555791644806834,1.8555791644806834,1.8555791644806834";
    for method in ["mc", "dc"] {
        for resolution in ["20", "35"] {
            let o = mesh(&[
                path_str(&tree),
                bounds,
                "--method",
                method,
                "--resolution",
                resolution,
                // Every cell holds many periods: refinement would chase them to its budget.
                "--refine",
                "1",
            ]);
            closed_manifold(&o, &format!("{method} {resolution}"));
        }
    }
}

#[test]
fn the_offset_of_a_flat_ellipsoid_meshes_closed() {
    // Was the known open class of issue 15: the offset of a bound (not exact) distance field
    // reaches beyond the child's box grown by the distance (here an ellipsoid 1e-12 thick: its
    // field is about |z| over a plane 10⁹ wide), and the grid cut it. Boxes now follow the level
    // of the field the offset asks for (`Solid::bbox_at`).
    let tree = fixture("hostile/offset_flat_ellipsoid.json");
    let o = mesh(&[
        path_str(&tree),
        "--bounds=-1.7680091822836583,-1.7680091822836583,-1.7680091822836583,\
         0.9641244827936493,0.9641244827936493,0.9641244827936493",
        "--method",
        "mc",
        "--resolution",
        "27",
        "--refine",
        "2",
    ]);
    let r = closed_manifold(&o, "mc 27");
    assert!(!stderr(&o).contains("beyond its bounding box"), "{r}");
}

/// Meshes `file` of `fixtures/hostile/` with both methods at `resolution`, asserting a closed
/// manifold of one shell whose volume is within `tolerance` (relative) of `volume`, without the
/// warning that the solid left its box.
fn closed_with_volume(file: &str, resolution: &str, volume: f64, tolerance: f64) {
    let tree = fixture(&format!("hostile/{file}"));
    for method in ["mc", "dc"] {
        let o = mesh(&[
            path_str(&tree),
            "--method",
            method,
            "--resolution",
            resolution,
        ]);
        let what = format!("{file} {method} {resolution}");
        let r = closed_manifold(&o, &what);
        assert_eq!(r["shells"], 1, "{what}: {r}");
        let v = r["volume"].as_f64().unwrap();
        assert!(
            (v / volume - 1.0).abs() < tolerance,
            "{what}: {v} vs {volume}"
        );
        assert!(
            !stderr(&o).contains("beyond its bounding box"),
            "{what}: {r}"
        );
    }
}

#[test]
fn offsets_shells_and_blends_of_distance_bounds_stay_in_their_boxes() {
    // Issue 15, third round (cli_hostile_fuzz, 15 of 21 open meshes in 8000 trees): an offset,
    // shell or blend asks for its operand's field above zero, and fields that are only distance
    // bounds reach further there than their box grown by that level: the grid cut the solid and
    // the mesh was open (MC and DC). The level now travels down the tree and each primitive gives
    // the box of its own sublevel set.
    use std::f64::consts::PI;
    // m·(|p/r| − 1) ≤ d: the ellipsoid scaled by 1 + d/m (m the smallest radius).
    let k: f64 = 1.0 + 1.8297758351393059 / 1.0744303301159335;
    let radii = [1.9370455042262225, 1.705789465386635, 1.0744303301159335];
    let volume = 4.0 / 3.0 * PI * radii.iter().map(|r| r * k).product::<f64>();
    closed_with_volume("offset_ellipsoid.json", "13", volume, 0.02);
    // A shell t of a Platonic solid's face-plane field: the solid with inradius r + t/2 (the inner
    // wall vanishes as t/2 > r); an octahedron of inradius ρ has volume 4√3·ρ³.
    let edge: f64 = 0.6534511500411118;
    let rho = edge / 6f64.sqrt() + 0.8188478109155621 / 2.0;
    closed_with_volume(
        "shell_octahedron.json",
        "26",
        4.0 * 3f64.sqrt() * rho.powi(3),
        0.02,
    );
    // A blend of a solid with itself lies r/4 below it: the ellipsoid's sublevel set at 1/4,
    // radii × 3.5 (the box grown by the radius r held only 2).
    let volume = 4.0 / 3.0 * PI * 0.35 * 3.5 * 3.5;
    closed_with_volume("blend_of_equal_ellipsoids.json", "26", volume, 0.02);
}

#[test]
fn a_blob_offset_past_its_threshold_is_unbounded() {
    // T − density ≤ d holds everywhere once d reaches T (the density tends to zero far away):
    // the solid is all of space, which needs --bounds (the box used to be the blob's own).
    let tree = fixture("hostile/blob_offset_past_threshold.json");
    for method in ["mc", "dc"] {
        let o = mesh(&[path_str(&tree), "--method", method, "--resolution", "16"]);
        refused(
            &o,
            "blob_offset_past_threshold.json",
            &["unbounded", "--bounds"],
        );
        let o = mesh(&[
            path_str(&tree),
            "--method",
            method,
            "--resolution",
            "16",
            "--bounds=-1,-1,-1,1,1,1",
        ]);
        let r = closed_manifold(&o, method);
        // The whole bounds box.
        assert!((r["volume"].as_f64().unwrap() - 8.0).abs() < 0.01, "{r}");
    }
}

#[test]
fn coordinates_whose_squares_overflow_single_precision_are_refused() {
    // A sphere of radius 5.7e19 (cli_hostile_fuzz): |p|² overflows f32 beyond 1.8e19, samples
    // inside read +∞ (outside) while the intervals said inside, and the mesh was open (13
    // triangles at resolution 35, empty at 128). Grids reaching beyond ±5e18 are refused.
    let tree = fixture("hostile/huge_sphere.json");
    for method in ["mc", "dc"] {
        for resolution in ["12", "35"] {
            let o = mesh(&[
                path_str(&tree),
                "--method",
                method,
                "--resolution",
                resolution,
            ]);
            refused(&o, "huge_sphere.json", &["beyond single precision", "5e18"]);
        }
    }
}

#[test]
fn a_solid_beyond_its_box_is_cut_closed_at_the_grid_with_a_warning() {
    // A tetrahedron with vertices at 6.3e19: its point–triangle distances near the origin lose
    // thousands of units to cancellation, so the shell reaches past the box its tree claims and
    // the grid cut it open (MC and DC). The pipeline now cuts every solid half a cell inside the
    // grid's edge: the mesh is closed, and the warning says part of the solid may be missing.
    let tree = fixture("hostile/shell_of_huge_polyhedron.json");
    let bounds = "--bounds=-2.7799936327693935,-2.7799936327693935,-2.7799936327693935,\
                  2.7799936327693935,2.7799936327693935,2.7799936327693935";
    for method in ["mc", "dc"] {
        let o = mesh(&[
            path_str(&tree),
            bounds,
            "--method",
            method,
            "--resolution",
            "16",
        ]);
        let r = closed_manifold(&o, method);
        let warned = r["warnings"].as_array().unwrap().iter().any(|w| {
            w.as_str()
                .unwrap()
                .contains("reaches beyond its bounding box")
        });
        assert!(warned, "{r}");
        assert!(stderr(&o).contains("warning: "), "{}", stderr(&o));
    }
}

#[test]
fn a_cone_with_one_huge_radius_meshes_closed() {
    // Bottom radius 1.2e20, top 0.56, height 1.25 (cli_hostile_fuzz's 30-minute run: 8 of 11 open
    // meshes in 72 547 trees were such cones): the projection parameter (q − a)·ab/|ab|² rounded
    // to 1 for every point near the axis and a + ab·1 lost the top radius, so the field was the
    // distance to a point on the axis, far from 1-Lipschitz, and the octree's intervals culled
    // boxes the samples disagreed with. Within these bounds the solid is the box's slab
    // |z| ≤ h/2 (the side falls by 1e-20 per unit of radius).
    let tree = fixture("hostile/cone_huge_bottom.json");
    let side: f64 = 2.3678363835806655;
    let bounds = format!("--bounds={0},{0},{0},{1},{1},{1}", -side, side);
    let volume = (2.0 * side).powi(2) * 1.2525190746381607;
    for method in ["mc", "dc"] {
        for resolution in ["20", "28"] {
            let o = mesh(&[
                path_str(&tree),
                &bounds,
                "--method",
                method,
                "--resolution",
                resolution,
            ]);
            let what = format!("{method} {resolution}");
            let r = closed_manifold(&o, &what);
            assert_eq!(r["shells"], 1, "{what}: {r}");
            let v = r["volume"].as_f64().unwrap();
            assert!((v / volume - 1.0).abs() < 0.03, "{what}: {v} vs {volume}");
        }
    }
}

#[test]
fn a_far_translated_gyroid_is_the_gyroid_at_its_reduced_offset() {
    // A gyroid translated by 1.1e6 (3 of 11 open meshes in the 30-minute run, up to 1.4e12): in
    // single precision its local coordinates were 0.125 apart (65 536 at 1e12), samples and
    // intervals disagreed, and the mesh was open. The gyroid is 2π-periodic, so lowering reduces
    // a leaf's offset modulo 2π: the same field, evaluated near its origin.
    let dir = tempfile::tempdir().unwrap();
    let near = dir.path().join("near.json");
    std::fs::write(
        &near,
        r#"{"type": "translate", "offset": [-1.5616561418864876, 0.5606114804973388, -0.7482649913448092], "child": {"type": "gyroid", "thickness": 0.06479220955615479}}"#,
    )
    .unwrap();
    let far = fixture("hostile/gyroid_far_translation.json");
    let bounds = "--bounds=-2.204999687457148,-2.204999687457148,-2.204999687457148,\
                  2.204999687457148,2.204999687457148,2.204999687457148";
    for method in ["mc", "dc"] {
        let run = |tree: &std::path::Path| {
            let o = mesh(&[
                path_str(tree),
                bounds,
                "--method",
                method,
                "--resolution",
                "28",
                "--refine",
                "1",
            ]);
            closed_manifold(&o, method)
        };
        let (a, b) = (run(&far), run(&near));
        let (va, vb) = (a["volume"].as_f64().unwrap(), b["volume"].as_f64().unwrap());
        assert!((va / vb - 1.0).abs() < 0.01, "{method}: {va} vs {vb}");
        assert_eq!(a["shells"], b["shells"], "{method}");
    }
}

/// Small inputs with huge evaluation cost: many balls, many polygon edges, dense Bézier nets.
#[path = "cli_hostile_cost.rs"]
mod cost;
