//! `solidkit subdivide` through the real binary: polygon files in and out (quads stay quads in
//! OBJ, OFF and PLY, triangles in STL), the report, one-line errors with exit code 2 and no output
//! file on failure; `subdivide` nodes through `solidkit mesh` from JSON and Rhai; and `check
//! --polygons` on the Platonic table; `dual` from Rhai and JSON.

use solidkit_meshing::io::{read_mesh, read_polygon_mesh};
use solidkit_tests::{fixture, path_str, success_json};
use std::path::Path;
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

#[test]
fn quads_in_quads_out_and_the_report() {
    let dir = tempfile::tempdir().unwrap();
    let ring = fixture("polyhedra/quad_ring.obj");
    for ext in ["obj", "off", "ply"] {
        let out = dir.path().join(format!("ring.{ext}"));
        let o = solidkit(&[
            "subdivide",
            path_str(&ring),
            "-o",
            path_str(&out),
            "--scheme",
            "catmull-clark",
            "--levels",
            "2",
            "--json",
        ]);
        let r = success_json(&o);
        // 16 quads, V 16, E 32: one level gives V 64, E 128, F 64; two give V 256, E 512, F 256.
        assert_eq!(r["polygon_faces"], 256, "{ext}");
        assert_eq!(r["polygon_vertices"], 256);
        assert_eq!(r["polygon_edges"], 512);
        assert_eq!(r["largest_face"], 4);
        assert_eq!(
            (r["closed"].clone(), r["genus"].clone()),
            (true.into(), 1.into())
        );
        assert_eq!(r["euler_characteristic"], 0);
        assert_eq!(r["scheme"], "catmull-clark");
        let back = read_polygon_mesh(&out).unwrap();
        assert_eq!(back.faces.len(), 256, "{ext}");
        assert!(back.faces.iter().all(|f| f.len() == 4), "{ext}");
        // And `check` agrees on the written file.
        let o = solidkit(&["check", path_str(&out), "--json"]);
        let c = success_json(&o);
        assert_eq!(
            (c["genus"].clone(), c["closed"].clone()),
            (1.into(), true.into())
        );
        assert!((c["volume"].as_f64().unwrap() - r["volume"].as_f64().unwrap()).abs() < 1e-12);
    }
    // STL gets triangles: twice the quads, same topology.
    let out = dir.path().join("ring.stl");
    let o = solidkit(&[
        "subdivide",
        path_str(&ring),
        "-o",
        path_str(&out),
        "--scheme",
        "doo-sabin",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("scheme: doo-sabin, 1 level(s)"), "{text}");
    assert!(text.contains("64 faces"), "{text}");
    let triangles = read_mesh(&out).unwrap();
    assert_eq!(triangles.triangles.len(), 128);
}

#[test]
fn adaptive_subdivision_refines_only_the_curved_band() {
    // The 6 × 6 × 2 slab of unit quads: Catmull-Clark to 0.01 refines the 88 quads touching its
    // edges at every level and keeps the 4 × 4 middles of the top and bottom (24 of them gain
    // the edge points of split edges as extra corners).
    let dir = tempfile::tempdir().unwrap();
    let slab = fixture("polyhedra/gridded_slab.obj");
    let out = dir.path().join("slab.obj");
    let adaptive = |scheme: &str, levels: &str, tolerance: &str| {
        solidkit(&[
            "subdivide",
            path_str(&slab),
            "-o",
            path_str(&out),
            "--scheme",
            scheme,
            "--levels",
            levels,
            "--adaptive",
            tolerance,
            "--json",
        ])
    };
    let r = success_json(&adaptive("catmull-clark", "2", "0.01"));
    assert_eq!(r["adaptive"], 0.01);
    let levels = r["adaptive_levels"].as_array().unwrap();
    assert_eq!(levels.len(), 2);
    for l in levels {
        assert_eq!(
            (l["conformed"].as_u64(), l["kept"].as_u64()),
            (Some(24), Some(8)),
            "{l}"
        );
    }
    assert_eq!(levels[0]["refined"], 88);
    assert_eq!(r["polygon_faces"], 88 * 16 + 32);
    // A corner of the ring: a unit quad with two sides along the refined band, each cut into
    // 2^k pieces after k levels: 4 + 2 (2^k − 1) = 10 corners after two.
    assert_eq!(r["largest_face"], 10);
    assert_eq!(
        (r["closed"].clone(), r["genus"].clone()),
        (true.into(), 0.into())
    );
    assert_eq!(r["euler_characteristic"], 2);
    let back = read_polygon_mesh(&out).unwrap();
    assert_eq!(back.faces.len(), 88 * 16 + 32);
    // Loop on its triangles (STL): red-green closure, still closed and manifold, fewer
    // triangles than uniform (240 · 16 = 3840).
    let stl = dir.path().join("slab.stl");
    let o = solidkit(&[
        "subdivide",
        path_str(&slab),
        "-o",
        path_str(&stl),
        "--scheme",
        "catmull-clark",
        "--levels",
        "0",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let o = solidkit(&[
        "subdivide",
        path_str(&stl),
        "-o",
        path_str(&out),
        "--scheme",
        "loop",
        "--levels",
        "2",
        "--adaptive",
        "0.01",
        "--json",
    ]);
    let r = success_json(&o);
    assert_eq!(
        (r["closed"].clone(), r["manifold"].clone()),
        (true.into(), true.into())
    );
    assert_eq!(r["euler_characteristic"], 2);
    let l = &r["adaptive_levels"][0];
    assert!(
        l["conformed"].as_u64().unwrap() > 0 && l["kept"].as_u64().unwrap() > 0,
        "{l}"
    );
    let faces = r["polygon_faces"].as_u64().unwrap();
    assert!(faces < 240 * 16 && faces == read_mesh(&out).unwrap().triangles.len() as u64);
    // Refused: a scheme without an adaptive rule, a tolerance that is not positive.
    for (o, expected) in [
        (
            adaptive("butterfly", "1", "0.01"),
            "adaptive subdivision supports",
        ),
        (adaptive("catmull-clark", "1", "0"), "not a positive number"),
    ] {
        assert_eq!(o.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&o.stderr).contains(expected));
    }
}

#[test]
fn bad_requests_fail_with_one_line_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let ring = fixture("polyhedra/quad_ring.obj");
    let out = dir.path().join("out.obj");
    let run = |input: &Path, scheme: &str, levels: &str| {
        solidkit(&[
            "subdivide",
            path_str(input),
            "-o",
            path_str(&out),
            "--scheme",
            scheme,
            "--levels",
            levels,
        ])
    };
    let cases: Vec<(Output, &str)> = vec![
        (run(&ring, "loop", "1"), "needs a triangle mesh"),
        (run(&ring, "catmull-clark", "30"), "more than the limit"),
        (
            run(&fixture("meshes/defects/fin.off"), "loop", "1"),
            "non-manifold",
        ),
        (
            run(&dir.path().join("missing.obj"), "loop", "1"),
            "missing.obj",
        ),
    ];
    for (o, expected) in cases {
        assert_eq!(o.status.code(), Some(2));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.starts_with("error: ") && err.contains(expected),
            "{err}"
        );
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(!out.exists());
    }
    let o = run(&ring, "catmull", "1");
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn subdivide_nodes_mesh_from_json_and_rhai() {
    let dir = tempfile::tempdir().unwrap();
    let child = r#"#{type: "platonic", solid: "octahedron", circumradius: 1.0}"#;
    let script = format!(
        "let blob = node(#{{type: \"subdivide\", scheme: \"butterfly\", levels: 2, child: {child}}});\n\
         difference([blob, cylinder(0.2, 3.0)])"
    );
    let rhai = dir.path().join("octa.rhai");
    std::fs::write(&rhai, script).unwrap();
    let json = dir.path().join("octa.json");
    let o = solidkit(&["convert", path_str(&rhai), "-o", path_str(&json)]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let tree = std::fs::read_to_string(&json).unwrap();
    assert!(
        tree.contains(r#""type": "subdivide", "scheme": "butterfly", "levels": 2"#),
        "{tree}"
    );
    let mut volumes = Vec::new();
    for input in [&rhai, &json] {
        let o = solidkit(&["mesh", path_str(input), "--resolution", "64", "--json"]);
        let r = success_json(&o);
        assert_eq!(
            (r["closed"].clone(), r["manifold"].clone()),
            (true.into(), true.into())
        );
        assert_eq!(
            (r["shells"].clone(), r["genus"].clone()),
            (1.into(), 1.into())
        );
        volumes.push(r["volume"].as_f64().unwrap());
    }
    assert_eq!(volumes[0], volumes[1]);
}

/// The Platonic table of the notes (V, E, F of the polygon faces) for the five solids and their
/// duals, through files written by solidkit (OBJ, OFF and PLY in turn) and `check --polygons`.
#[test]
fn check_polygons_reports_the_platonic_table() {
    use solidkit_kernel::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron};
    use solidkit_meshing::io::{PolygonMesh, write_polygon_mesh};
    let table = [
        (PlatonicKind::Tetrahedron, [4, 6, 4], 3),
        (PlatonicKind::Cube, [8, 12, 6], 4),
        (PlatonicKind::Octahedron, [6, 12, 8], 3),
        (PlatonicKind::Dodecahedron, [20, 30, 12], 5),
        (PlatonicKind::Icosahedron, [12, 30, 20], 3),
    ];
    let dir = tempfile::tempdir().unwrap();
    let formats = ["obj", "off", "ply"];
    for (k, (kind, [v, e, f], sides)) in table.into_iter().enumerate() {
        let solid = Polyhedron::platonic(kind, PlatonicSize::Edge(1.0)).unwrap();
        // The dual swaps V and F: its faces have as many sides as the solid's vertex valence.
        let valence = 2 * e / v;
        for (p, counts, sides, what) in [
            (solid.clone(), [v, e, f], sides, "solid"),
            (solid.dual().unwrap(), [f, e, v], valence, "dual"),
        ] {
            let ext = formats[(2 * k + usize::from(what == "dual")) % 3];
            let path = dir.path().join(format!("{}_{what}.{ext}", kind.name()));
            let mesh = PolygonMesh::new(p.vertices().to_vec(), p.faces().to_vec());
            write_polygon_mesh(&path, &mesh).unwrap();
            let o = solidkit(&["check", path_str(&path), "--polygons", "--json"]);
            let r = success_json(&o);
            let got = &r["polygons"];
            let name = format!("{} {what} ({ext})", kind.name());
            assert_eq!(
                [&got["vertices"], &got["edges"], &got["faces"]],
                counts.map(serde_json::Value::from).each_ref(),
                "{name}"
            );
            assert_eq!(got["euler_characteristic"], 2, "{name}");
            assert_eq!(got["largest_face"], sides, "{name}");
            // The triangle counts beside them: each face of n sides is n − 2 triangles.
            let triangles = counts[2] * (sides - 2);
            assert_eq!(r["faces"], triangles, "{name}");
            assert_eq!(r["euler_characteristic"], 2, "{name}");
            let polygons = if sides > 3 { counts[2] } else { 0 };
            assert_eq!(got["polygons"], polygons, "{name}");
            // The text report has the same line.
            let o = solidkit(&["check", path_str(&path), "--polygons"]);
            let text = String::from_utf8_lossy(&o.stdout);
            let line = format!(
                "polygon mesh: V {}, E {}, F {}, V - E + F = 2",
                counts[0], counts[1], counts[2]
            );
            assert!(text.contains(&line), "{name}: {text}");
        }
    }
    // Without the flag there is no polygon line, and a bad file is still a located error, exit 2.
    let path = dir.path().join("cube_solid.off");
    let o = solidkit(&["check", path_str(&path)]);
    assert!(!String::from_utf8_lossy(&o.stdout).contains("polygon mesh"));
    let bad = dir.path().join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n").unwrap();
    let o = solidkit(&["check", path_str(&bad), "--polygons"]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// `dual(solid)` in Rhai and the `dual` node in JSON mesh to the same solid: the octahedron dual
/// to a cube of edge 2 (circumradius 1, volume 4/3).
#[test]
fn dual_meshes_from_rhai_and_json() {
    let dir = tempfile::tempdir().unwrap();
    let rhai = dir.path().join("dual.rhai");
    std::fs::write(
        &rhai,
        r#"dual(node(#{type: "platonic", solid: "cube", edge: 2.0}))"#,
    )
    .unwrap();
    let json = dir.path().join("dual.json");
    let o = solidkit(&["convert", path_str(&rhai), "-o", path_str(&json)]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let tree = std::fs::read_to_string(&json).unwrap();
    assert!(
        tree.contains(r#""type": "dual", "child": {"type": "platonic""#),
        "{tree}"
    );
    let mut volumes = Vec::new();
    for input in [&rhai, &json] {
        let o = solidkit(&["mesh", path_str(input), "--resolution", "96", "--json"]);
        let r = success_json(&o);
        assert_eq!(
            (r["closed"].clone(), r["manifold"].clone()),
            (true.into(), true.into())
        );
        let v = r["volume"].as_f64().unwrap();
        assert!((v - 4.0 / 3.0).abs() < 0.02 * 4.0 / 3.0, "{v}");
        volumes.push(v);
    }
    assert_eq!(volumes[0], volumes[1]);
    // A sphere has no dual: a one-line error, exit 2.
    std::fs::write(&rhai, "dual(sphere(1.0))").unwrap();
    let o = solidkit(&["mesh", path_str(&rhai), "--resolution", "32"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("dual needs a polyhedron"), "{err}");
}
