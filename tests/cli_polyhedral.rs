//! `solidkit mesh --method polyhedral`: OpenSCAD models and JSON trees of polyhedra built by mesh
//! Booleans, checked against exact volumes and topology; a part with no polyhedral form falls
//! back to marching cubes with a warning naming it; grid options are refused.

use serde_json::Value;
use solidkit_tests::path_str;
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

fn polyhedral(name: &str, text: &str, extra: &[&str]) -> (Output, Option<Value>) {
    let dir = tempfile::tempdir().expect("temp dir");
    let model = dir.path().join(name);
    std::fs::write(&model, text).expect("write");
    let mut args = vec!["mesh", path_str(&model), "--method", "polyhedral", "--json"];
    args.extend(extra);
    let o = solidkit(&args);
    let r = serde_json::from_slice(&o.stdout).ok();
    (o, r)
}

/// Area of OpenSCAD's regular `n`-gon of circumradius `r`.
fn ngon(r: f64, n: f64) -> f64 {
    0.5 * n * r * r * (2.0 * std::f64::consts::PI / n).sin()
}

#[test]
fn a_box_with_faceted_holes_is_exact_and_small() {
    // Two through-holes of $fn = 16 flush with nothing: the volume is the prism arithmetic.
    let csg = "difference() { cube(size = [20, 20, 10]);
        multmatrix([[1,0,0,5],[0,1,0,10],[0,0,1,-1],[0,0,0,1]]) cylinder(h = 12, r = 3, $fn = 16);
        multmatrix([[1,0,0,15],[0,1,0,10],[0,0,1,-1],[0,0,0,1]]) cylinder(h = 12, r = 3, $fn = 16); }";
    let (o, r) = polyhedral("m.csg", csg, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    let exact = 20.0 * 20.0 * 10.0 - 2.0 * 10.0 * ngon(3.0, 16.0);
    assert!(
        (r["volume"].as_f64().unwrap() - exact).abs() < 1e-9 * exact,
        "{r}"
    );
    assert_eq!(
        (r["shells"].as_u64(), r["genus"].as_i64()),
        (Some(1), Some(2)),
        "{r}"
    );
    assert_eq!(r["closed"], true);
    assert_eq!(r["self_intersections"], 0);
    assert_eq!(r["method"], "polyhedral");
    // The faces of 2 sixteen-sided holes through a box: hundreds of triangles, not 10⁵.
    assert!(r["faces"].as_u64().unwrap() < 400, "{r}");
}

#[test]
fn coincident_faces_and_edge_contact_as_exact_kernels_keep_them() {
    // Three cubes: two sharing a face (one solid), one touching them along an edge only.
    let csg = "union() { cube(1); multmatrix([[1,0,0,1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(1);
        multmatrix([[1,0,0,2],[0,1,0,1],[0,0,1,0],[0,0,0,1]]) cube(1); }";
    let (o, r) = polyhedral("m.csg", csg, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    assert!((r["volume"].as_f64().unwrap() - 3.0).abs() < 1e-12, "{r}");
    // Two shells, as manifold3d keeps them; they touch along the edge, which the report's
    // self-intersection test sees as contact between the shells.
    assert_eq!(r["shells"].as_u64(), Some(2), "{r}");
    assert_eq!(r["faces"].as_u64(), Some(32), "{r}");
}

#[test]
fn extrusions_turns_and_hulls() {
    // A square frame extruded (a hole in the profile), a full turn of a square at $fn = 8.
    let csg = "linear_extrude(height = 2) difference() { square(4, center = true); square(2, center = true); }
        multmatrix([[1,0,0,20],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) rotate_extrude($fn = 8) multmatrix([[1,0,0,2],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) square(1);";
    let (o, r) = polyhedral("m.csg", csg, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    // The turned square: an octagonal ring between circumradii 2 and 3, height 1.
    let ring = ngon(3.0, 8.0) - ngon(2.0, 8.0);
    let exact = 2.0 * 12.0 + ring;
    assert!(
        (r["volume"].as_f64().unwrap() - exact).abs() < 1e-9 * exact,
        "{r}"
    );
    assert_eq!(
        (r["shells"].as_u64(), r["genus"].as_i64()),
        (Some(2), Some(2)),
        "{r}"
    );
    let hull = "hull() { cube(1); multmatrix([[1,0,0,3],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) cube(1); }";
    let (_, r) = polyhedral("h.csg", hull, &[]);
    assert!((r.expect("JSON")["volume"].as_f64().unwrap() - 4.0).abs() < 1e-12);
}

#[test]
fn json_trees_of_polyhedra_and_the_fallback() {
    let tree = r#"{"format":"solidkit-tree","version":1,"root":{"type":"difference","children":[
        {"type":"box","size":[2,2,2]},
        {"type":"translate","offset":[1,0,0],"child":{"type":"box","size":[2,1,1]}}]}}"#;
    let (o, r) = polyhedral("t.json", tree, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!((r.expect("JSON")["volume"].as_f64().unwrap() - 7.0).abs() < 1e-12);
    // A sphere has no polyhedral form: it alone is meshed on a grid of its own box (128 cells
    // by default, --resolution) and cut from the box exactly; a warning names it. The sphere
    // pokes through all six faces: genus 5.
    let round = r#"{"format":"solidkit-tree","version":1,"root":{"type":"difference","children":[
        {"type":"box","size":[2,2,2]},{"type":"sphere","radius":1.2}]}}"#;
    let (o, r) = polyhedral("s.json", round, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    let w = r["warnings"].to_string();
    assert!(
        w.contains("`sphere` is not a polyhedron") && w.contains("grid of 128 cells"),
        "{w}"
    );
    assert_eq!(r["method"], "polyhedral");
    assert_eq!(
        (r["shells"].as_u64(), r["genus"].as_i64()),
        (Some(1), Some(5)),
        "{r}"
    );
    let cap = std::f64::consts::PI * 0.04 * (3.6 - 0.2) / 3.0;
    let exact = 8.0 - (4.0 / 3.0 * std::f64::consts::PI * 1.728 - 6.0 * cap);
    let v = r["volume"].as_f64().unwrap();
    assert!((v - exact).abs() < 2e-3 * exact, "{v} vs {exact}");
    // The box's faces are exact: its corners are vertices of the mesh.
    assert_eq!(
        r["bbox"],
        serde_json::json!([[-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]]),
        "{r}"
    );
}

#[test]
fn a_wedge_extruded_to_a_segment_is_gridded_alone() {
    // linear_extrude with scale [1, 0] ends in a segment: no polyhedron of OpenSCAD's slices.
    // It is meshed on its own grid and united exactly with the cube (overlap 5/6).
    let csg = "linear_extrude(height = 3, scale = [1, 0]) square(2, center = true);\ncube(1);";
    let (o, r) = polyhedral("m.csg", csg, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    assert_eq!(r["method"], "polyhedral", "{r}");
    let w = r["warnings"].to_string();
    assert!(
        w.contains("m.csg:1:1:") && w.contains("grid of 128 cells"),
        "{w}"
    );
    let v = r["volume"].as_f64().unwrap();
    let exact = 6.0 + 1.0 - 5.0 / 6.0;
    assert!((v - exact).abs() < 5e-3 * exact, "{v} vs {exact}");
    assert_eq!(
        (r["shells"].as_u64(), r["closed"].as_bool()),
        (Some(1), Some(true)),
        "{r}"
    );
}

#[test]
fn grid_options_are_refused() {
    let (o, _) = polyhedral("m.csg", "cube(1);", &["--tolerance", "0.1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--tolerance"));
}

#[test]
fn half_turns_meet_flush_and_join() {
    // Debian's Basics/rotate_extrude.scad: two half rings of opposite sense end on the plane
    // y = 0, flush with each other and with a third ring of twice the radius, closing a loop.
    // Their end caps lie exactly in that plane (sin 180° is 0), so the union is one solid.
    let ring = |dx: f64, angle: f64, x: f64| {
        format!(
            "multmatrix([[1,0,0,{dx}],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) rotate_extrude(angle = {angle}) \
             multmatrix([[1,0,0,{x}],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) square(size = [5, 5]);"
        )
    };
    let csg = format!(
        "union() {{ {} {} {} }}",
        ring(0.0, 180.0, 12.5),
        ring(7.5, 180.0, 5.0),
        ring(-7.5, -180.0, 5.0)
    );
    let (o, r) = polyhedral("m.csg", &csg, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    assert_eq!(
        (r["shells"].as_u64(), r["genus"].as_i64()),
        (Some(1), Some(1)),
        "{r}"
    );
    assert_eq!(r["self_intersections"], 0, "{r}");
}

#[test]
fn projections_are_the_polyhedra_sections_and_shadows() {
    // The cut of OpenSCAD's 16-fragment sphere at its equator is the 16-gon between its two
    // middle rings (polar angles 78.75° and 101.25°); the shadow of a cube turned 45° about x
    // is a 10 × 10√2 rectangle. Both extruded 1 high: their areas are the volumes.
    let csg = "linear_extrude(height = 1) projection(cut = true) sphere(r = 10, $fn = 16);
        multmatrix([[1,0,0,30],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) linear_extrude(height = 1)
        projection(cut = false) multmatrix([[1,0,0,0],[0,0.70710678118654757,-0.70710678118654746,0],
        [0,0.70710678118654746,0.70710678118654757,0],[0,0,0,1]]) cube(10, center = true);";
    let (o, r) = polyhedral("m.csg", csg, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    let section = ngon(10.0 * 78.75f64.to_radians().sin(), 16.0);
    let shadow = 100.0 * 2f64.sqrt();
    let v = r["volume"].as_f64().unwrap();
    // Corners are rounded to a grid of 2⁻²⁰ of the extent (2⁻¹⁵ here), as OpenSCAD rounds
    // its 2D results to 2⁻¹⁶.
    assert!(
        (v - (section + shadow)).abs() < 1e-5 * v,
        "{v} vs {}",
        section + shadow
    );
    assert_eq!(r["shells"].as_u64(), Some(2), "{r}");
    assert_eq!(r["warnings"], serde_json::json!([]), "nothing sampled: {r}");
}

#[test]
fn resize_and_offset_profiles_stay_polyhedral() {
    // resize scales by the polyhedron's own box: [2, 4, 8] to x = 20 with auto is ×10 on every
    // axis. The round offset of a 48-gon leaves corners 1e-15 apart, which the triangulator
    // refused before the profile's corners were put on a grid.
    let csg = "resize(newsize = [20, 0, 0], auto = true) cube(size = [2, 4, 8]);
        multmatrix([[1,0,0,60],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) linear_extrude(height = 12)
        offset(r = 1, $fn = 48) circle(r = 8, $fn = 48);";
    let (o, r) = polyhedral("m.csg", csg, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = r.expect("JSON");
    assert_eq!(r["method"], "polyhedral", "{r}");
    assert_eq!(r["warnings"], serde_json::json!([]), "{r}");
    assert_eq!(r["shells"].as_u64(), Some(2), "{r}");
    // The offset disc lies between the 48-gon of radius 9 and the circle of radius 9.
    let v = r["volume"].as_f64().unwrap() - 64000.0;
    let (lo, hi) = (12.0 * ngon(9.0, 48.0), 12.0 * std::f64::consts::PI * 81.0);
    assert!(v > lo - 1e-6 && v < hi, "{lo} < {v} < {hi}");
}
