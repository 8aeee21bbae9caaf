//! `solidkit render` and `check --render` (issue 18) through the binary: the field render and
//! the mesh render of one solid agree (silhouette masks at 512 × 512), the bytes do not depend on
//! the thread count, every defect of `gen broken` shows in its colour where it projects, and
//! hostile sizes are refused with exit 2.

use solidkit_meshing::ReportOptions;
use solidkit_meshing::io::read_mesh;
use solidkit_meshing::render::defects::{
    BOUNDARY_EDGE, INCONSISTENT_FACE, NON_MANIFOLD_EDGE, NON_MANIFOLD_VERTEX,
    SELF_INTERSECTING_FACE, defect_camera, line_width,
};
use solidkit_meshing::render::png_out::decode;
use solidkit_meshing::render::{ImageSize, View, shade};
use solidkit_meshing::topology::DefectItems;
use solidkit_tests::{path_str, run_cli};
use std::path::Path;

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

/// A rounded solid with a hole, a flat face and concave edges.
const TREE: &str = r#"{"format":"solidkit-tree","version":1,"root":{"type":"difference","children":[
  {"type":"union","children":[{"type":"sphere","radius":0.8},
    {"type":"translate","offset":[0.5,0,-0.3],"child":{"type":"box","size":[1.0,0.6,0.6]}}]},
  {"type":"cylinder","radius":0.25,"height":3.0}]}}"#;

/// Framing box shared by the two renders (so they frame alike).
const BOUNDS: &str = "-1,-1,-1,1.1,1,1";

/// Decoded RGB pixels and width of a PNG.
fn read_png(path: &Path) -> (Vec<[u8; 3]>, u32) {
    let image = decode(&std::fs::read(path).expect("png")).expect("an RGB png");
    (image.pixels, image.width)
}

fn ok(args: &[&str]) {
    let o = run_cli(BIN, args);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn field_and_mesh_silhouettes_agree() {
    let dir = tempfile::tempdir().expect("tempdir");
    let tree = dir.path().join("solid.json");
    std::fs::write(&tree, TREE).expect("write tree");
    let mesh = dir.path().join("solid.ply");
    let (field_png, mesh_png) = (dir.path().join("field.png"), dir.path().join("mesh.png"));
    ok(&[
        "mesh",
        path_str(&tree),
        "-r",
        "256",
        "-o",
        path_str(&mesh),
        "--no-self-intersections",
    ]);
    for view in ["iso", "front", "30,-20"] {
        for (input, out) in [(&tree, &field_png), (&mesh, &mesh_png)] {
            ok(&[
                "render",
                path_str(input),
                "-o",
                path_str(out),
                "--size",
                "512x512",
                "--view",
                view,
                "--bounds",
                BOUNDS,
            ]);
        }
        let (a, _) = read_png(&field_png);
        let (b, _) = read_png(&mesh_png);
        let solid = |p: &[u8; 3]| *p != shade::BACKGROUND;
        let differ = a
            .iter()
            .zip(&b)
            .filter(|(x, y)| solid(x) != solid(y))
            .count();
        let covered = a.iter().filter(|p| solid(p)).count();
        assert!(covered > 512 * 512 / 8, "{view}: {covered} pixels covered");
        let share = differ as f64 / (512.0 * 512.0);
        assert!(
            share < 0.005,
            "{view}: {differ} pixels differ ({:.3} %)",
            share * 100.0
        );
    }
}

#[test]
fn bytes_do_not_depend_on_the_thread_count() {
    let dir = tempfile::tempdir().expect("tempdir");
    let tree = dir.path().join("solid.json");
    std::fs::write(&tree, TREE).expect("write tree");
    let mesh = dir.path().join("solid.stl");
    ok(&[
        "mesh",
        path_str(&tree),
        "-r",
        "64",
        "-o",
        path_str(&mesh),
        "--no-self-intersections",
    ]);
    for (input, extra) in [(&tree, None), (&tree, Some("z=0.1")), (&mesh, None)] {
        let mut files = Vec::new();
        for threads in ["1", "2"] {
            let out = dir.path().join(format!("t{threads}.png"));
            let mut args = vec![
                "--threads",
                threads,
                "render",
                path_str(input),
                "-o",
                path_str(&out),
                "--size",
                "300x200",
            ];
            if let Some(s) = extra {
                args.extend(["--section", s]);
            }
            ok(&args);
            files.push(std::fs::read(&out).expect("png"));
        }
        assert!(files[0] == files[1], "{input:?} {extra:?}: bytes differ");
    }
}

#[test]
fn every_defect_shows_in_its_colour_where_it_is() {
    let dir = tempfile::tempdir().expect("tempdir");
    ok(&[
        "gen",
        "broken",
        "-o",
        path_str(dir.path()),
        "--format",
        "ply",
    ]);
    let size = ImageSize::new(512, 512).expect("size");
    let radius = i64::from(line_width(size)) + 2;
    let mut classes_seen = 0;
    for entry in std::fs::read_dir(dir.path()).expect("dir") {
        let file = entry.expect("entry").path();
        if file.extension().and_then(|e| e.to_str()) != Some("ply") {
            continue;
        }
        let png = file.with_extension("png");
        let o = run_cli(
            BIN,
            &[
                "check",
                path_str(&file),
                "--render",
                path_str(&png),
                "--size",
                "512x512",
            ],
        );
        assert!(matches!(o.status.code(), Some(0 | 1)), "{file:?}");
        let (pixels, width) = read_png(&png);
        let mesh = read_mesh(&file).expect("mesh");
        let items = DefectItems::of(&mesh, &ReportOptions::default());
        let bbox = mesh
            .positions
            .iter()
            .fold(solidkit_kernel::Aabb::empty(), |b, &p| {
                solidkit_kernel::Aabb::new(b.min.min(p), b.max.max(p))
            });
        let cam = defect_camera(View::Iso, &bbox, size).expect("camera");
        let find = |p: glam::DVec3, color: [u8; 3], what: &str| {
            let [x, y, _] = cam.project(p);
            let (x, y) = (x.floor() as i64, y.floor() as i64);
            let found = (y - radius..=y + radius).any(|yy| {
                (x - radius..=x + radius).any(|xx| {
                    xx >= 0
                        && yy >= 0
                        && xx < i64::from(width)
                        && yy < 512
                        && pixels[(yy * i64::from(width) + xx) as usize] == color
                })
            });
            assert!(
                found,
                "{file:?}: {what} at ({x}, {y}) not drawn in {color:?}"
            );
        };
        let at = |v: u32| mesh.positions[v as usize];
        let centroid = |t: u32| {
            mesh.triangles[t as usize]
                .map(at)
                .iter()
                .sum::<glam::DVec3>()
                / 3.0
        };
        for &[a, b] in &items.boundary_edges {
            find((at(a) + at(b)) * 0.5, BOUNDARY_EDGE, "boundary edge");
        }
        for &[a, b] in &items.non_manifold_edges {
            find(
                (at(a) + at(b)) * 0.5,
                NON_MANIFOLD_EDGE,
                "non-manifold edge",
            );
        }
        for &v in &items.non_manifold_vertices {
            find(at(v), NON_MANIFOLD_VERTEX, "non-manifold vertex");
        }
        for &t in &items.inconsistent_faces {
            find(centroid(t), INCONSISTENT_FACE, "flipped face");
        }
        for &t in &items.self_intersecting_faces {
            find(
                centroid(t),
                SELF_INTERSECTING_FACE,
                "self-intersecting face",
            );
        }
        classes_seen |= [
            !items.boundary_edges.is_empty(),
            !items.non_manifold_edges.is_empty(),
            !items.non_manifold_vertices.is_empty(),
            !items.inconsistent_faces.is_empty(),
            !items.self_intersecting_faces.is_empty(),
        ]
        .iter()
        .enumerate()
        .fold(0, |m, (i, &b)| m | (u32::from(b) << i));
    }
    assert_eq!(
        classes_seen, 0b11111,
        "every defect class occurs in gen broken"
    );
}

#[test]
fn hostile_sizes_are_refused_before_allocating() {
    let dir = tempfile::tempdir().expect("tempdir");
    let tree = dir.path().join("solid.json");
    std::fs::write(&tree, TREE).expect("write tree");
    let out = dir.path().join("out.png");
    for size in [
        "100000x100000",
        "65537x1",
        "0x10",
        "8193x8193",
        "18446744073709551616x1",
    ] {
        let o = run_cli(
            BIN,
            &[
                "render",
                path_str(&tree),
                "-o",
                path_str(&out),
                "--size",
                size,
            ],
        );
        assert_eq!(o.status.code(), Some(2), "--size {size}");
        assert!(!out.exists(), "--size {size} wrote a file");
    }
    let o = run_cli(
        BIN,
        &[
            "check",
            path_str(&tree),
            "--render",
            path_str(&out),
            "--size",
            "100000x100000",
        ],
    );
    assert_eq!(o.status.code(), Some(2));
}

/// A parsed `check --export-defects` file: per element, the rows after the header.
struct DefectsPly {
    vertices: Vec<Vec<f64>>,
    faces: Vec<Vec<f64>>,
    edges: Vec<Vec<f64>>,
}

fn read_defects_ply(path: &Path) -> DefectsPly {
    let text = std::fs::read_to_string(path).expect("ply text");
    let (header, body) = text.split_once("end_header\n").expect("header");
    let mut counts = Vec::new();
    for line in header.lines() {
        if let Some(rest) = line.strip_prefix("element ") {
            let (name, n) = rest.split_once(' ').expect("element line");
            counts.push((name.to_string(), n.parse::<usize>().expect("count")));
        }
    }
    let mut rows = body.lines().map(|l| {
        l.split(' ')
            .map(|t| t.parse::<f64>().expect("number"))
            .collect::<Vec<_>>()
    });
    let mut out = DefectsPly {
        vertices: Vec::new(),
        faces: Vec::new(),
        edges: Vec::new(),
    };
    for (name, n) in counts {
        let list = match name.as_str() {
            "vertex" => &mut out.vertices,
            "face" => &mut out.faces,
            "edge" => &mut out.edges,
            other => panic!("unexpected element {other}"),
        };
        list.extend(rows.by_ref().take(n));
    }
    assert!(
        rows.next().is_none(),
        "{path:?}: rows beyond the declared elements"
    );
    out
}

#[test]
fn exported_defects_match_the_report() {
    use solidkit_meshing::render::defects_ply::class_color;
    let dir = tempfile::tempdir().expect("tempdir");
    ok(&[
        "gen",
        "broken",
        "-o",
        path_str(dir.path()),
        "--format",
        "ply",
    ]);
    let mut files = 0;
    for entry in std::fs::read_dir(dir.path()).expect("dir") {
        let file = entry.expect("entry").path();
        if file.extension().and_then(|e| e.to_str()) != Some("ply") {
            continue;
        }
        files += 1;
        let out = file.with_extension("defects.ply");
        let o = run_cli(
            BIN,
            &[
                "check",
                path_str(&file),
                "--json",
                "--export-defects",
                path_str(&out),
            ],
        );
        assert!(matches!(o.status.code(), Some(0 | 1)), "{file:?}");
        let report: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
        let count = |key: &str| report[key].as_u64().expect(key) as usize;
        let ply = read_defects_ply(&out);
        let mesh = read_mesh(&file).expect("mesh");
        let items = DefectItems::of(&mesh, &ReportOptions::default());
        let class = |rows: &[Vec<f64>], c: f64| {
            rows.iter()
                .filter(|r| *r.last().expect("class") == c)
                .count()
        };
        assert_eq!(class(&ply.edges, 0.0), count("boundary_edges"), "{file:?}");
        assert_eq!(
            class(&ply.edges, 1.0),
            count("non_manifold_edges"),
            "{file:?}"
        );
        assert_eq!(
            class(&ply.vertices, 2.0),
            count("non_manifold_vertices"),
            "{file:?}"
        );
        assert_eq!(
            class(&ply.faces, 3.0),
            items.inconsistent_faces.len(),
            "{file:?}"
        );
        assert_eq!(
            class(&ply.faces, 4.0),
            items.self_intersecting_faces.len(),
            "{file:?}"
        );
        assert_eq!(ply.edges.len() + ply.faces.len(), {
            items.boundary_edges.len()
                + items.non_manifold_edges.len()
                + items.inconsistent_faces.len()
                + items.self_intersecting_faces.len()
        });
        // Colours are the legend's; the faces and edges name the mesh's own positions.
        for row in ply.faces.iter().chain(&ply.edges) {
            let n = row.len();
            let rgb = [row[n - 4], row[n - 3], row[n - 2]].map(|v| v as u8);
            assert_eq!(rgb, class_color(row[n - 1] as u8), "{file:?}");
        }
        for row in &ply.vertices {
            let p = glam::DVec3::new(row[0], row[1], row[2]);
            assert!(
                mesh.positions.contains(&p),
                "{file:?}: {p} is no vertex of the mesh"
            );
        }
        for e in &ply.edges {
            let [a, b] = [e[0], e[1]].map(|i| &ply.vertices[i as usize]);
            let [a, b] = [a, b].map(|v| glam::DVec3::new(v[0], v[1], v[2]));
            let named = items
                .boundary_edges
                .iter()
                .chain(&items.non_manifold_edges)
                .any(|&[u, v]| {
                    let (u, v) = (mesh.positions[u as usize], mesh.positions[v as usize]);
                    (u, v) == (a, b) || (u, v) == (b, a)
                });
            assert!(named, "{file:?}: edge {a} {b} is not a reported edge");
        }
        if !ply.faces.is_empty() {
            // Our own strict PLY reader takes it (the edge element is skipped).
            let faces = read_mesh(&out)
                .expect("exported PLY reads back")
                .triangles
                .len();
            assert_eq!(faces, ply.faces.len());
        }
    }
    assert!(files >= 5, "gen broken wrote {files} meshes");
}
