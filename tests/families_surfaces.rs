//! Parametric surfaces as solids (issue 21): every fixture under `fixtures/surfaces/` meshed
//! closed and manifold with its volume against an exact value or against the closed
//! tessellation's own volume at a ten times finer chord error; JSON written back equal; bad
//! input refused with its place.

use solidkit_kernel::primitive::{MeshSource, NoMeshResolver, Primitive};
use solidkit_kernel::surface::{SurfaceKind, SurfaceSpec};
use solidkit_kernel::{NodeKind, Solid, json};
use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::FileMeshResolver;
use solidkit_tests::{fixture, load_tree, mesh, rel_err};
use std::f64::consts::PI;

/// The surface node at the root of a tree.
fn spec(solid: &Solid) -> SurfaceSpec {
    let NodeKind::Primitive(Primitive::Mesh(m)) = solid.kind() else {
        panic!("not a surface node");
    };
    let MeshSource::Surface(s) = m.source() else {
        panic!("not a surface node");
    };
    (**s).clone()
}

/// The volume of the closed tessellation refined ten times in chord error (twice the segments
/// for triangular patches).
fn finer_volume(s: &SurfaceSpec) -> f64 {
    let mut fine = s.clone();
    let sheet = s.sheet(&NoMeshResolver).expect("sheet");
    match sheet.chord_error {
        Some(c) => fine.tolerance = Some(c / 10.0),
        None => fine.segments = Some(2 * sheet.segments[0]),
    }
    let m = fine.closed_mesh(&NoMeshResolver).expect("closed mesh");
    let r = TopologyReport::of(&m);
    assert!(r.is_closed_manifold(), "{r:?}");
    r.volume
}

/// Meshes a fixture and checks it: closed manifold, one shell, volume within `tol` of `exact`
/// (or of the finer tessellation's volume when `None`).
fn check(name: &str, exact: Option<f64>, tol: f64) {
    let solid = load_tree(&format!("surfaces/{name}"));
    let s = spec(&solid);
    let reference = exact.unwrap_or_else(|| finer_volume(&s));
    let direct = TopologyReport::of(&s.closed_mesh(&NoMeshResolver).unwrap());
    assert!(direct.is_closed_manifold(), "{name}: {direct:?}");
    assert!(
        rel_err(direct.volume, reference) < 1e-2,
        "{name}: tessellation {} vs {reference}",
        direct.volume
    );
    let (_, r) = mesh(&solid, 96);
    assert!(r.is_closed_manifold(), "{name}: {r:?}");
    assert_eq!(r.shells, 1, "{name}");
    assert!(
        rel_err(r.volume, reference) < tol,
        "{name}: meshed {} vs {reference}",
        r.volume
    );
}

#[test]
fn bezier_and_bspline_patches() {
    check("bezier_patch.json", None, 0.03);
    check("bspline_surface.json", None, 0.01);
}

#[test]
fn interpolating_patch_through_16_points() {
    // x = 3u and y = 3v exactly (cubics through collinear equally spaced points), z the bicubic:
    // its integral is Simpson's 3/8 rule over the 16 heights, so the volume down to z = -0.5 is
    // 9 (Σ wᵢwⱼ zᵢⱼ + 0.5) = 12.965625.
    check("interpolating_patch.json", Some(12.965625), 0.01);
    let solid = load_tree("surfaces/interpolating_patch.json");
    let s = spec(&solid);
    let SurfaceKind::Interpolating(p) = &s.kind else {
        panic!("not an interpolating patch");
    };
    for (k, q) in p.points().iter().enumerate() {
        let d = s
            .kind
            .derivatives((k % 4) as f64 / 3.0, (k / 4) as f64 / 3.0);
        assert!((d.unwrap().p - *q).length() < 1e-12, "point {k}");
    }
}

#[test]
fn nurbs_half_cylinder_shell_has_its_exact_volume() {
    // π/2 (1.1² − 0.9²) × 3 = 0.6π.
    check("nurbs_surface.json", Some(0.6 * PI), 0.03);
}

#[test]
fn formula_surfaces_graph_and_closed_torus() {
    // z = sin(uv) over [-2, 2]² on z = -1.5: 16 × 1.5 exactly.
    check("param_surface.json", Some(24.0), 0.01);
    check("param_torus.json", Some(2.0 * PI * PI * 0.09), 0.02);
}

#[test]
fn adaptive_tessellation_closes_and_keeps_the_volume() {
    check("adaptive_bump.json", None, 0.03);
    check("adaptive_torus.json", Some(2.0 * PI * PI * 0.09), 0.02);
    // The bump with far fewer triangles than its regular grid at the same tolerance.
    let solid = load_tree("surfaces/adaptive_bump.json");
    let s = spec(&solid);
    let mut uniform = s.clone();
    uniform.adaptive = false;
    let (a, u) = (
        s.sheet(&NoMeshResolver).unwrap(),
        uniform.sheet(&NoMeshResolver).unwrap(),
    );
    assert!(a.chord_error.unwrap() <= 0.002 && u.chord_error.unwrap() <= 0.002);
    println!(
        "adaptive_bump: {} triangles (chord bound {:.2e}) against the grid's {} ({:.2e})",
        a.mesh.triangles.len(),
        a.chord_error.unwrap(),
        u.mesh.triangles.len(),
        u.chord_error.unwrap()
    );
    assert!(
        3 * a.mesh.triangles.len() < u.mesh.triangles.len(),
        "{} adaptive, {} uniform",
        a.mesh.triangles.len(),
        u.mesh.triangles.len()
    );
}

#[test]
fn triangular_patches() {
    check("bezier_triangle.json", None, 0.04);
    check("pn_triangles.json", None, 0.01);
}

#[test]
fn pn_triangles_from_a_mesh_file() {
    // The octahedron's angle-weighted normals are those of the sphere through its vertices, so
    // the solid is the closed PN octahedron of pn_triangles.json but with 10 segments.
    let path = fixture("surfaces/pn_mesh.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let solid = json::from_str_with(&text, &FileMeshResolver::for_tree_file(&path)).unwrap();
    solid.validate().unwrap();
    let m = spec(&solid)
        .closed_mesh(&FileMeshResolver::for_tree_file(&path))
        .unwrap();
    let r = TopologyReport::of(&m);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert!(
        r.volume > 4.0 / 3.0 + 0.5 && r.volume < 4.0 / 3.0 * PI,
        "{}",
        r.volume
    );
    let (_, meshed) = mesh(&solid, 64);
    assert!(meshed.is_closed_manifold() && rel_err(meshed.volume, r.volume) < 0.02);
    // Written back with its path; without a resolver the file is refused with its key.
    assert!(json::to_string(&solid).contains("\"path\": \"octahedron.obj\""));
    let e = json::from_str(&text).unwrap_err().to_string();
    assert!(e.contains("path"), "{e}");
}

#[test]
fn surfaces_round_trip_through_json() {
    for name in [
        "bezier_patch.json",
        "interpolating_patch.json",
        "bspline_surface.json",
        "nurbs_surface.json",
        "param_surface.json",
        "param_torus.json",
        "adaptive_bump.json",
        "adaptive_torus.json",
        "bezier_triangle.json",
        "pn_triangles.json",
    ] {
        let text = std::fs::read_to_string(fixture(&format!("surfaces/{name}"))).unwrap();
        let s = json::from_str(&text).expect("parses");
        let again = json::from_str(&json::to_string(&s)).expect("written JSON parses");
        assert_eq!(s, again, "{name}");
    }
}

#[test]
fn surfaces_in_csg() {
    // A bowl: a ball minus the z = sin(uv) solid (an exact-distance operand like any mesh).
    let text = r#"{"type": "difference", "children": [
        {"type": "box", "size": [3, 3, 2]},
        {"type": "param_surface", "z": "0.3*sin(u*v)", "u": [-2, 2], "v": [-2, 2], "base": -2}]}"#;
    let s = json::from_str(text).unwrap();
    s.validate().unwrap();
    let (_, r) = mesh(&s, 96);
    assert!(r.is_closed_manifold(), "{r:?}");
    // The box above the surface: ∫∫ (1 − 0.3 sin(uv)) over [-1.5, 1.5]² = 9 (odd integrand).
    assert!(rel_err(r.volume, 9.0) < 0.01, "{}", r.volume);
}

#[test]
fn bad_surfaces_are_refused_with_their_place() {
    let cases = [
        (
            r#"{"type": "param_surface", "z": "sin(u*q)", "u": [0, 1], "v": [0, 1], "base": -1}"#,
            "z: formula: column 7",
        ),
        (
            r#"{"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0]]], "thickness": 1}"#,
            "points[1]",
        ),
        (
            r#"{"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]]}"#,
            "give \"thickness\" or \"base\"",
        ),
        (
            r#"{"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]], "base": 1}"#,
            "base",
        ),
        (
            r#"{"type": "interpolating_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]], "base": -1}"#,
            "expected 4 rows of 4 points",
        ),
        (
            r#"{"type": "bspline_surface", "degree": 3, "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]], "base": -1}"#,
            "degree 3 needs at least 4",
        ),
        (
            r#"{"type": "nurbs_surface", "degree": 1, "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]], "weights": [[1, 0], [1, 1]], "base": -1}"#,
            "weights",
        ),
        (
            r#"{"type": "pn_triangles", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,5]], "thickness": 0.1}"#,
            "triangles",
        ),
        (
            r#"{"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]], "thickness": 1, "colour": 2}"#,
            "unknown key \"colour\"",
        ),
        (
            r#"{"type": "bezier_patch", "points": [[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]], "thickness": 1, "tessellation": "fine"}"#,
            "tessellation: expected \"uniform\" or \"adaptive\"",
        ),
        (
            r#"{"type": "bezier_triangle", "degree": 1, "points": [[0,0,0],[1,0,0],[0,1,0]], "thickness": 1, "tessellation": "adaptive"}"#,
            "unknown key \"tessellation\"",
        ),
    ];
    for (text, expected) in cases {
        let e = json::from_str(text).expect_err(text).to_string();
        assert!(e.contains(expected), "{text}: {e}");
        assert!(e.starts_with("1:"), "{e}");
    }
}
