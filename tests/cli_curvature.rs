//! `solidkit curvature` through the real binary: discrete curvatures of a meshed sphere (K ≈ 1/r²,
//! H ≈ 1/r, Gauss–Bonnet to rounding), exact curvatures of the notes' z = sin(uv) written as PLY
//! vertex properties and read back against the closed forms, and errors with exit code 2 and no
//! output.

use solidkit_tests::{fixture, path_str, success_json};
use std::f64::consts::PI;
use std::path::Path;
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

/// The vertex rows (x y z, the five properties, and `laplacian` where written) of a binary PLY
/// written by `curvature`; whether `laplacian` is among them.
fn ply_rows(path: &Path) -> (Vec<Vec<f64>>, bool) {
    let bytes = std::fs::read(path).unwrap();
    let end = b"end_header\n";
    let at = bytes.windows(end.len()).position(|w| w == end).unwrap() + end.len();
    let header = std::str::from_utf8(&bytes[..at]).unwrap();
    for p in ["gaussian", "mean", "k1", "k2", "boundary"] {
        assert!(
            header.contains(&format!("property double {p}\n")),
            "{header}"
        );
    }
    let laplacian = header.contains("property double laplacian\n");
    let columns = 8 + usize::from(laplacian);
    let n: usize = header
        .lines()
        .find_map(|l| l.strip_prefix("element vertex "))
        .unwrap()
        .parse()
        .unwrap();
    let rows = (0..n)
        .map(|i| {
            let row = &bytes[at + 8 * columns * i..at + 8 * columns * (i + 1)];
            (0..columns)
                .map(|k| f64::from_le_bytes(row[8 * k..8 * k + 8].try_into().unwrap()))
                .collect()
        })
        .collect();
    (rows, laplacian)
}

#[test]
fn a_meshed_sphere_has_the_curvatures_of_the_ball_and_obeys_gauss_bonnet() {
    let dir = tempfile::tempdir().unwrap();
    let tree = dir.path().join("ball.json");
    std::fs::write(&tree, r#"{"type": "sphere", "radius": 2}"#).unwrap();
    let stl = dir.path().join("ball.stl");
    let o = solidkit(&[
        "mesh",
        path_str(&tree),
        "-o",
        path_str(&stl),
        "--resolution",
        "64",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let out = dir.path().join("ball.ply");
    let s = success_json(&solidkit(&[
        "curvature",
        path_str(&stl),
        "-o",
        path_str(&out),
        "--json",
    ]));
    assert_eq!(s["method"], "discrete");
    assert_eq!(s["euler_characteristic"], 2);
    assert!(s["gauss_bonnet_error"].as_f64().unwrap() < 1e-8, "{s}");
    assert!((s["total_angle_defect"].as_f64().unwrap() - 4.0 * PI).abs() < 1e-8);
    let k = s["gaussian"]["mean"].as_f64().unwrap();
    let h = s["mean"]["mean"].as_f64().unwrap();
    assert!((k * 4.0 - 1.0).abs() < 0.03, "K {k}");
    assert!((h * 2.0 - 1.0).abs() < 0.02, "H {h}");
    let (rows, laplacian) = ply_rows(&out);
    assert!(
        !laplacian && s["laplacian"].is_null(),
        "a mesh file has no Δh"
    );
    assert_eq!(rows.len(), s["vertices"].as_u64().unwrap() as usize);
    let mut hs: Vec<f64> = rows.iter().map(|r| r[4] * 2.0).collect();
    hs.sort_by(f64::total_cmp);
    assert!((hs[hs.len() / 2] - 1.0).abs() < 0.03, "median H r");
}

#[test]
fn the_notes_sin_uv_surface_has_its_closed_form_curvatures() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sin.ply");
    let tree = fixture("surfaces/param_surface.json");
    let s = success_json(&solidkit(&[
        "curvature",
        path_str(&tree),
        "-o",
        path_str(&out),
        "--json",
    ]));
    assert_eq!(s["method"], "parametric");
    assert_eq!(s["euler_characteristic"], 1);
    let (rows, laplacian) = ply_rows(&out);
    assert!(laplacian, "a graph z = h(x, y) gets Δh");
    assert!(rows.len() > 100);
    // Δh of h = sin(xy) is −(x² + y²) sin(xy), exact from the second derivatives.
    for r in &rows {
        let (x, y) = (r[0], r[1]);
        let exact = -(x * x + y * y) * (x * y).sin();
        assert!(
            (r[8] - exact).abs() < 1e-10,
            "Δh at {x}, {y}: {} vs {exact}",
            r[8]
        );
    }
    // |Δh| ≤ x² + y² ≤ 8, and it reaches about ±6 near the corners (−8 sin(±4)); in the summary.
    let (lo, hi) = (
        s["laplacian"]["min"].as_f64().unwrap(),
        s["laplacian"]["max"].as_f64().unwrap(),
    );
    assert!(lo < -4.0 && hi > 4.0 && lo > -8.0 && hi < 8.0, "{s}");
    for r in rows.iter().step_by(37) {
        let (u, v) = (r[0], r[1]);
        assert!((r[2] - (u * v).sin()).abs() < 1e-12);
        // Monge patch h = sin(uv): K = (h_uu h_vv − h_uv²) / W², H = … / (2 W^{3/2}) upwards;
        // the file's H is positive where the surface bends away from the upward normal.
        let (sn, cs) = (u * v).sin_cos();
        let (hu, hv) = (v * cs, u * cs);
        let (huu, huv, hvv) = (-v * v * sn, cs - u * v * sn, -u * u * sn);
        let w = 1.0 + hu * hu + hv * hv;
        let k = (huu * hvv - huv * huv) / (w * w);
        let h = ((1.0 + hv * hv) * huu - 2.0 * hu * hv * huv + (1.0 + hu * hu) * hvv)
            / (2.0 * w * w.sqrt());
        assert!((r[3] - k).abs() < 1e-10, "K at {u}, {v}: {} vs {k}", r[3]);
        assert!(
            (r[4] + h).abs() < 1e-10,
            "H at {u}, {v}: {} vs {}",
            r[4],
            -h
        );
        assert!(r[5] >= r[6] && (r[5] * r[6] - k).abs() < 1e-9);
    }
}

#[test]
fn a_formula_torus_is_welded_and_its_curvature_integrates_to_zero() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("torus.ply");
    let tree = fixture("surfaces/param_torus.json");
    let s = success_json(&solidkit(&[
        "curvature",
        path_str(&tree),
        "-o",
        path_str(&out),
        "--json",
    ]));
    assert_eq!(
        (
            s["euler_characteristic"].as_i64(),
            s["boundary_vertices"].as_u64()
        ),
        (Some(0), Some(0))
    );
    // Not a graph over xy: no Δh.
    assert!(s["laplacian"].is_null() && !ply_rows(&out).1, "{s}");
    assert!(s["gauss_bonnet_error"].as_f64().unwrap() < 1e-9, "{s}");
    // ∫K dA = 2πχ = 0 from the exact K and the mixed areas; K ranges over
    // [−1/(r(R − r)), 1/(r(R + r))] = [−4.76, 2.56] (to 1 %: the grid need not hit v = π).
    assert!(s["integral_gaussian"].as_f64().unwrap().abs() < 0.05, "{s}");
    let (lo, hi) = (
        s["gaussian"]["min"].as_f64().unwrap(),
        s["gaussian"]["max"].as_f64().unwrap(),
    );
    assert!(
        (lo * 0.3 * 0.7 + 1.0).abs() < 0.01 && (hi * 0.3 * 1.3 - 1.0).abs() < 0.01,
        "{s}"
    );
}

#[test]
fn a_height_field_gets_its_laplacian_and_monge_curvatures() {
    // Bézier heights (0, 0, 1) along x, the same along y: h = (x/2)² over [0, 2]² whichever way
    // the rows run, or (y/2)²: Δh = 1/2 everywhere, K = 0.
    let dir = tempfile::tempdir().unwrap();
    let tree = dir.path().join("hf.json");
    std::fs::write(
        &tree,
        r#"{"type": "heightfield", "min": [0, 0], "max": [2, 2], "base": -1,
            "bezier": [[0, 0, 1], [0, 0, 1], [0, 0, 1]]}"#,
    )
    .unwrap();
    let out = dir.path().join("hf.ply");
    let s = success_json(&solidkit(&[
        "curvature",
        path_str(&tree),
        "-o",
        path_str(&out),
        "--json",
    ]));
    assert_eq!(s["method"], "parametric");
    let (rows, laplacian) = ply_rows(&out);
    assert!(laplacian && rows.len() == 129 * 129, "{}", rows.len());
    for r in &rows {
        assert!((r[8] - 0.5).abs() < 1e-12, "Δh {}", r[8]);
        assert!(r[3].abs() < 1e-12, "K {}", r[3]);
        assert!(
            (r[2] - r[0] * r[0] / 4.0).abs() < 1e-12 || (r[2] - r[1] * r[1] / 4.0).abs() < 1e-12
        );
    }
    assert!(
        (s["laplacian"]["mean"].as_f64().unwrap() - 0.5).abs() < 1e-12,
        "{s}"
    );
}

#[test]
fn bad_inputs_exit_2_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x.ply");
    let ball = dir.path().join("ball.json");
    std::fs::write(&ball, r#"{"type": "sphere", "radius": 1}"#).unwrap();
    let broken = dir.path().join("broken.stl");
    std::fs::write(&broken, b"solid x\nfacet normal 0 0 1\n").unwrap();
    for (input, expected) in [
        (ball.as_path(), "not a parametric surface"),
        (broken.as_path(), "broken.stl"),
        (Path::new("/nonexistent/m.obj"), "m.obj"),
    ] {
        let o = solidkit(&["curvature", path_str(input), "-o", path_str(&out)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(expected), "{err}");
        assert!(!out.exists());
    }
}
