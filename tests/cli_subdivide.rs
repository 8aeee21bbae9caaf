//! `solidkit subdivide` through the real binary: polygon files in and out (quads stay quads in
//! OBJ, OFF and PLY, triangles in STL), the report, one-line errors with exit code 2 and no output
//! file on failure; and `subdivide` nodes through `solidkit mesh` from JSON and Rhai.

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
