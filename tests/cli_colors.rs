//! `solidkit mesh` with `color()` (issue 14): `difference() { color("red") cube(10, center =
//! true); color("blue") sphere(6.5); }` and a nested colour, through the binary to 3MF, PLY and
//! GLB, read back by the small independent readers: every triangle on a cube face is red, every
//! one on the sphere blue, the inner colour wins, the geometry is the uncoloured file's bit for
//! bit, and `--no-colors` writes exactly the uncoloured files.

use crate::export_readers::{read_3mf, unzip};
use glam::DVec3;
use solidkit_meshing::IndexedMesh;
use solidkit_tests::{fixture, path_str, run_cli, success_json};
use std::path::Path;

fn run(args: &[&str]) -> serde_json::Value {
    success_json(&run_cli(env!("CARGO_BIN_EXE_solidkit"), args))
}

fn mesh_to(input: &Path, out: &Path, extra: &[&str]) -> serde_json::Value {
    let mut args = vec![
        "mesh",
        path_str(input),
        "--resolution",
        "64",
        "--json",
        "--no-progress",
        "-o",
        path_str(out),
    ];
    args.extend_from_slice(extra);
    run(&args)
}

/// Per-triangle colours of a 3MF's model part.
fn threemf_colors(bytes: &[u8]) -> Vec<[u8; 4]> {
    let entries = unzip(bytes);
    let model = &entries
        .iter()
        .find(|e| e.0 == "3D/3dmodel.model")
        .unwrap()
        .1;
    let text = std::str::from_utf8(model).unwrap();
    let attr = |line: &str, key: &str| -> Option<String> {
        let at = line.find(&format!(" {key}=\""))? + key.len() + 3;
        Some(line[at..].split('"').next()?.to_string())
    };
    let bases: Vec<[u8; 4]> = text
        .lines()
        .filter(|l| l.contains("<base "))
        .map(|l| {
            let hex = attr(l, "displaycolor").unwrap();
            let b = |i: usize| u8::from_str_radix(&hex[1 + 2 * i..3 + 2 * i], 16).unwrap();
            [b(0), b(1), b(2), b(3)]
        })
        .collect();
    let object = text.lines().find(|l| l.contains("<object ")).unwrap();
    let default: usize = attr(object, "pindex").unwrap().parse().unwrap();
    text.lines()
        .filter(|l| l.contains("<triangle "))
        .map(|l| bases[attr(l, "p1").map_or(default, |p| p.parse().unwrap())])
        .collect()
}

/// A binary PLY as written by solidkit with face colours: the mesh and each face's colour.
fn ply_colors(bytes: &[u8]) -> (IndexedMesh, Vec<[u8; 4]>) {
    let end = bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .unwrap()
        + 11;
    let header = std::str::from_utf8(&bytes[..end]).unwrap();
    let count = |what: &str| -> usize {
        let line = header
            .lines()
            .find(|l| l.starts_with(&format!("element {what} ")))
            .unwrap();
        line.rsplit(' ').next().unwrap().parse().unwrap()
    };
    assert!(header.contains(
        "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
    ));
    let (nv, nf) = (count("vertex"), count("face"));
    let mut at = end;
    let f64_at = |at: usize| f64::from_le_bytes(bytes[at..at + 8].try_into().unwrap());
    let positions: Vec<DVec3> = (0..nv)
        .map(|k| {
            DVec3::new(
                f64_at(at + 24 * k),
                f64_at(at + 24 * k + 8),
                f64_at(at + 24 * k + 16),
            )
        })
        .collect();
    at += 24 * nv;
    let (mut tris, mut colors) = (Vec::new(), Vec::new());
    for _ in 0..nf {
        assert_eq!(bytes[at], 3);
        let i = |k: usize| {
            u32::from_le_bytes(bytes[at + 1 + 4 * k..at + 5 + 4 * k].try_into().unwrap())
        };
        tris.push([i(0), i(1), i(2)]);
        colors.push(bytes[at + 13..at + 17].try_into().unwrap());
        at += 17;
    }
    assert_eq!(at, bytes.len());
    (IndexedMesh::new(positions, tris), colors)
}

/// The centroid of a triangle of `mesh`.
fn centroid(mesh: &IndexedMesh, tri: &[u32; 3]) -> DVec3 {
    tri.iter()
        .map(|&i| mesh.positions[i as usize])
        .sum::<DVec3>()
        / 3.0
}

/// Every triangle on a cube face red, on the sphere blue, on the small cube green.
fn check(mesh: &IndexedMesh, color: impl Fn(usize) -> [u8; 4]) {
    let mut counts = [0; 3];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let c = centroid(mesh, tri);
        if c.z > 5.2 {
            // the small cube (its concave seam with the big one is left out)
            assert_eq!(color(t), [0, 255, 0, 255], "small cube at {c}");
            counts[2] += 1;
            continue;
        }
        if c.z > 4.7 && c.x.min(c.y) > 3.2 {
            continue; // the small cube.s seam with the big one
        }
        // unambiguous triangles: on one surface and away from the other (bevels and rim
        // triangles of marching cubes lie on neither)
        let (dc, ds) = (
            (c.abs().max_element() - 5.0).abs(),
            (c.length() - 6.5).abs(),
        );
        let cube = dc < 0.01 && ds > 0.15;
        let sphere = ds < 0.03 && dc > 0.15;
        if cube && !sphere {
            assert_eq!(color(t), [255, 0, 0, 255], "cube face at {c}");
            counts[0] += 1;
        } else if sphere && !cube {
            assert_eq!(color(t), [0, 0, 255, 255], "sphere at {c}");
            counts[1] += 1;
        }
    }
    assert!(counts.iter().all(|&n| n > 50), "{counts:?}");
}

#[test]
fn colours_reach_3mf_ply_and_glb_and_never_change_geometry() {
    let dir = tempfile::tempdir().unwrap();
    let input = fixture("csg/colors.csg");
    let plain_text = std::fs::read_to_string(&input)
        .unwrap()
        .replace("color([1, 0, 0, 1])", "group()")
        .replace("color(\"blue\")", "group()")
        .replace("color(\"gray\")", "group()")
        .replace("color(\"#00ff00\")", "group()");
    assert!(!plain_text.contains("color("));
    let plain = dir.path().join("plain.csg");
    std::fs::write(&plain, plain_text).unwrap();
    let p = |name: &str| dir.path().join(name);

    let r = mesh_to(&input, &p("c.3mf"), &[]);
    assert_eq!(r["colors"], 3, "red, blue and green (grey is overridden)");
    let bytes = std::fs::read(p("c.3mf")).unwrap();
    let mesh = read_3mf(&bytes);
    let colors = threemf_colors(&bytes);
    assert_eq!(colors.len(), mesh.triangles.len());
    check(&mesh, |t| colors[t]);

    let r = mesh_to(&plain, &p("plain.3mf"), &[]);
    assert_eq!(r["colors"], 0);
    let plain_mesh = read_3mf(&std::fs::read(p("plain.3mf")).unwrap());
    assert_eq!(plain_mesh.positions, mesh.positions);
    assert_eq!(plain_mesh.triangles, mesh.triangles);

    mesh_to(&input, &p("c.ply"), &[]);
    let (ply, colors) = ply_colors(&std::fs::read(p("c.ply")).unwrap());
    assert_eq!(ply.triangles, mesh.triangles);
    check(&ply, |t| colors[t]);

    mesh_to(&input, &p("c.glb"), &[]);
    let glb_bytes = std::fs::read(p("c.glb")).unwrap();
    let glb = solidkit_meshing::io::read_mesh(&p("c.glb")).unwrap();
    assert_eq!(glb.triangles.len(), mesh.triangles.len());
    let json_len = u32::from_le_bytes(glb_bytes[12..16].try_into().unwrap()) as usize;
    let v: serde_json::Value = serde_json::from_slice(&glb_bytes[20..20 + json_len]).unwrap();
    assert_eq!(v["meshes"][0]["primitives"].as_array().unwrap().len(), 3);
    assert_eq!(v["materials"].as_array().unwrap().len(), 3);
    assert_eq!(
        v["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"],
        serde_json::json!([1, 0, 0, 1])
    );

    // formats without colours (and runs without a file) write none and count none
    for ext in ["stl", "obj"] {
        assert_eq!(
            mesh_to(&input, &p(&format!("c.{ext}")), &[])["colors"],
            0,
            "{ext}"
        );
    }
    // OFF carries a colour after each face's indices (as MeshLab writes it)
    assert_eq!(mesh_to(&input, &p("c.off"), &[])["colors"], 3);
    let off = std::fs::read_to_string(p("c.off")).unwrap();
    let face_rows: Vec<&str> = off.lines().filter(|l| l.starts_with("3 ")).collect();
    assert_eq!(face_rows.len(), mesh.triangles.len());
    assert!(face_rows.iter().all(|l| l.split_whitespace().count() == 8));
    assert!(
        face_rows.iter().any(|l| l.ends_with(" 255 0 0 255")),
        "red faces"
    );
    assert!(
        face_rows.iter().any(|l| l.ends_with(" 0 0 255 255")),
        "blue faces"
    );

    // --no-colors writes what the uncoloured tree gives, byte for byte
    for ext in ["3mf", "ply", "glb", "stl"] {
        let a = p(&format!("n.{ext}"));
        let b = p(&format!("plain.{ext}"));
        let r = mesh_to(&input, &a, &["--no-colors"]);
        assert_eq!(r["colors"], 0);
        mesh_to(&plain, &b, &[]);
        assert_eq!(
            std::fs::read(&a).unwrap(),
            std::fs::read(&b).unwrap(),
            "{ext}"
        );
    }
}

#[test]
fn unknown_colour_names_warn_and_json_trees_carry_colours() {
    let dir = tempfile::tempdir().unwrap();
    let csg = dir.path().join("w.csg");
    std::fs::write(&csg, "color(\"nosuchcolour\") cube(1);").unwrap();
    let out = dir.path().join("w.3mf");
    let r = mesh_to(&csg, &out, &[]);
    assert_eq!(r["colors"], 0);
    let w = r["warnings"].to_string();
    assert!(w.contains("nosuchcolour") && w.contains("w.csg:1:"), "{w}");

    let tree = dir.path().join("t.json");
    std::fs::write(
        &tree,
        r#"{"format": "solidkit-tree", "version": 1, "root": {"type": "color",
            "color": [0, 0, 1, 0.5], "child": {"type": "sphere", "radius": 1}}}"#,
    )
    .unwrap();
    let out = dir.path().join("t.3mf");
    assert_eq!(mesh_to(&tree, &out, &[])["colors"], 1);
    let colors = threemf_colors(&std::fs::read(&out).unwrap());
    assert!(colors.iter().all(|&c| c == [0, 0, 255, 128]));
}

/// A pocket cut into a red cube, its floor exactly the top of a green box buried in the cube:
/// the floor and walls are the cutter's blue (the operand the surface comes from), the cube's
/// top red. The rule these replaced, the part with the smallest |field|, gave the whole floor
/// the buried green box's colour (an exact tie it gave to the first part).
#[test]
fn cut_faces_are_the_cutters_even_where_a_buried_part_touches_them() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("pocket.csg");
    std::fs::write(
        &input,
        "difference() {\n\tunion() {\n\t\tcolor(\"red\") cube(size = [10, 10, 10], center = true);\n\
         \t\tcolor(\"lime\") multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1.5], [0, 0, 0, 1]]) \
         cube(size = [4, 4, 3], center = true);\n\t}\n\
         \tcolor(\"blue\") multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 4.5], [0, 0, 0, 1]]) \
         cube(size = [4, 4, 3], center = true);\n}\n",
    )
    .unwrap();
    let out = dir.path().join("pocket.ply");
    // red and blue: the buried green box colours nothing
    assert_eq!(mesh_to(&input, &out, &[])["colors"], 2);
    let (mesh, colors) = ply_colors(&std::fs::read(&out).unwrap());
    let mut counts = [0; 3];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let c = centroid(&mesh, tri);
        let m = c.x.abs().max(c.y.abs());
        if (c.z - 3.0).abs() < 1e-3 && m < 1.8 {
            assert_eq!(colors[t], [0, 0, 255, 255], "floor at {c}");
            counts[0] += 1;
        } else if (m - 2.0).abs() < 1e-3 && c.z > 3.2 && c.z < 4.8 {
            assert_eq!(colors[t], [0, 0, 255, 255], "wall at {c}");
            counts[1] += 1;
        } else if (c.z - 5.0).abs() < 1e-3 && m > 2.2 {
            assert_eq!(colors[t], [255, 0, 0, 255], "top at {c}");
            counts[2] += 1;
        }
    }
    assert!(counts.iter().all(|&n| n > 200), "{counts:?}");
}

#[test]
fn polyhedral_meshes_carry_the_parts_colours() {
    // The same model as exact polyhedra (OpenSCAD's 21-gon sphere): faces on the cube's planes
    // are red, the sphere's cut faces inside the cube blue, the small cube above green.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c.ply");
    let r = mesh_to(
        &fixture("csg/colors.csg"),
        &out,
        &["--method", "polyhedral"],
    );
    assert_eq!(
        (r["method"].as_str(), r["colors"].as_u64()),
        (Some("polyhedral"), Some(3)),
        "{r}"
    );
    let (mesh, colors) = ply_colors(&std::fs::read(&out).unwrap());
    let mut counts = [0; 3];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let c = centroid(&mesh, tri);
        let (big, side) = (c.abs().max_element(), c.x.abs().max(c.y.abs()));
        if c.z > 5.0 + 1e-6 {
            assert_eq!(colors[t], [0, 255, 0, 255], "small cube at {c}");
            counts[2] += 1;
        } else if big < 5.0 - 1e-6 {
            assert_eq!(colors[t], [0, 0, 255, 255], "sphere cut at {c}");
            counts[1] += 1;
        } else if side < 3.4 || c.z < 4.9 {
            assert_eq!(colors[t], [255, 0, 0, 255], "cube face at {c}");
            counts[0] += 1;
        }
    }
    assert!(counts.iter().all(|&n| n > 0), "{counts:?}");
}
