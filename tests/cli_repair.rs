//! `solidkit repair` through the real binary: a built-in suite of broken meshes (triangle soup,
//! flipped shell, holes up to 50 edges, duplicate faces, a non-manifold fin, a bow-tie, two
//! overlapping closed meshes) and every mesh of `solidkit gen broken` must come out as closed
//! oriented manifolds without self-intersections, with the intended volume within 0.5%; minimal
//! mode must not move any vertex further than the weld tolerance; bad input exits 2 and writes
//! nothing.

use glam::DVec3;
use serde_json::Value;
use solidkit_meshing::io::{read_mesh, write_mesh};
use solidkit_meshing::{IndexedMesh, TopologyReport};
use solidkit_tests::{path_str, run_cli};
use std::f64::consts::PI;
use std::path::Path;
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

/// Corner `i` of the box `[lo, lo + size]`.
fn corner(lo: DVec3, size: f64, i: u32) -> DVec3 {
    lo + size * DVec3::new(f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2))
}

/// An outward cube as (positions, triangles), vertices appended to `m`.
fn add_cube(m: &mut IndexedMesh, lo: DVec3, size: f64) {
    let base = m.positions.len() as u32;
    m.positions.extend((0..8).map(|i| corner(lo, size, i)));
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    for [a, b, c, d] in quads {
        m.triangles.push([a, b, c].map(|x| x + base));
        m.triangles.push([a, c, d].map(|x| x + base));
    }
}

fn cube(lo: DVec3, size: f64) -> IndexedMesh {
    let mut m = IndexedMesh::default();
    add_cube(&mut m, lo, size);
    m
}

/// Every triangle with vertices of its own, jittered by up to `jitter`, wound inward.
fn soup(m: &IndexedMesh, jitter: f64) -> IndexedMesh {
    let mut out = IndexedMesh::default();
    for (f, t) in m.triangles.iter().enumerate() {
        for (k, &v) in [t[0], t[2], t[1]].iter().enumerate() {
            let wobble = ((f * 3 + k) as f64 * 0.7).sin() * jitter;
            out.positions
                .push(m.positions[v as usize] + DVec3::new(wobble, -wobble, wobble * 0.5));
        }
        let n = out.positions.len() as u32;
        out.triangles.push([n - 3, n - 2, n - 1]);
    }
    out
}

/// A prism over the regular `n`-gon of radius 1, height 1, outward.
fn prism(n: u32) -> IndexedMesh {
    let mut m = IndexedMesh::default();
    for z in [0.0, 1.0] {
        for i in 0..n {
            let a = 2.0 * PI * f64::from(i) / f64::from(n);
            m.positions.push(DVec3::new(a.cos(), a.sin(), z));
        }
    }
    for i in 0..n {
        let j = (i + 1) % n;
        m.triangles.push([i, j, n + j]);
        m.triangles.push([i, n + j, n + i]);
    }
    for i in 1..n - 1 {
        m.triangles.push([0, i + 1, i]);
        m.triangles.push([n, n + i, n + i + 1]);
    }
    m
}

fn ngon_area(n: u32) -> f64 {
    0.5 * f64::from(n) * (2.0 * PI / f64::from(n)).sin()
}

/// A tetrahedron with apex `apex` over a base triangle below it, outward.
fn add_tetra(m: &mut IndexedMesh, apex: u32, base: [DVec3; 3]) {
    let b = m.positions.len() as u32;
    m.positions.extend(base);
    m.triangles.extend([
        [b, b + 2, b + 1],
        [b, b + 1, apex],
        [b + 1, b + 2, apex],
        [b + 2, b, apex],
    ]);
}

/// The built-in broken suite: (name, mesh, intended volume, minimal mode expected to succeed).
fn suite() -> Vec<(&'static str, IndexedMesh, f64, bool)> {
    let mut cases = Vec::new();
    cases.push(("soup", soup(&cube(DVec3::ZERO, 1.0), 1e-9), 1.0, true));

    let mut flipped = cube(DVec3::ZERO, 3.0);
    let mut inner = cube(DVec3::splat(5.0), 1.0);
    inner.triangles.iter_mut().for_each(|t| t.swap(1, 2));
    let base = flipped.positions.len() as u32;
    flipped.positions.extend(inner.positions);
    flipped
        .triangles
        .extend(inner.triangles.iter().map(|t| t.map(|v| v + base)));
    cases.push(("flipped_shell", flipped, 28.0, true));

    // A prism without its top cap (a 50-edge hole, not planar after the wobble below) and a
    // cube missing one triangle (a 3-edge hole).
    let mut holes = prism(50);
    holes.triangles.retain(|t| !t.iter().all(|&v| v >= 50));
    for (i, p) in holes.positions.iter_mut().enumerate().skip(50) {
        p.z += 0.01 * (i as f64 * 1.3).sin();
    }
    let mut open_cube = cube(DVec3::splat(5.0), 1.0);
    open_cube.triangles.pop();
    let base = holes.positions.len() as u32;
    holes.positions.extend(open_cube.positions);
    holes
        .triangles
        .extend(open_cube.triangles.iter().map(|t| t.map(|v| v + base)));
    cases.push(("holes", holes, ngon_area(50) + 1.0, true));

    let mut dup = cube(DVec3::ZERO, 1.0);
    let copies: Vec<[u32; 3]> = dup.triangles.clone();
    dup.triangles.extend(copies);
    let t = dup.triangles[3];
    dup.triangles.push([t[0], t[2], t[1]]);
    dup.triangles.push([t[0], t[2], t[1]]);
    cases.push(("duplicate_faces", dup, 1.0, true));

    let mut fin = cube(DVec3::ZERO, 1.0);
    fin.positions.push(DVec3::new(0.5, -1.0, -1.0));
    fin.triangles.push([0, 1, 8]);
    cases.push(("fin", fin, 1.0, true));

    let mut bowtie = IndexedMesh::default();
    bowtie.positions.push(DVec3::ZERO);
    let tetra = 1.0 / 3.0 * 0.5 * 1.0;
    add_tetra(
        &mut bowtie,
        0,
        [
            DVec3::new(0.0, 0.0, -1.0),
            DVec3::new(1.0, 0.0, -1.0),
            DVec3::new(0.0, 1.0, -1.0),
        ],
    );
    add_tetra(
        &mut bowtie,
        0,
        [
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(0.0, 1.0, 1.0),
            DVec3::new(1.0, 0.0, 1.0),
        ],
    );
    cases.push(("bow_tie", bowtie, 2.0 * tetra, true));

    let mut overlap = cube(DVec3::ZERO, 2.0);
    add_cube(&mut overlap, DVec3::ONE, 2.0);
    cases.push(("overlapping", overlap, 15.0, false));
    cases
}

fn write(dir: &Path, name: &str, m: &IndexedMesh) -> std::path::PathBuf {
    let p = dir.join(format!("{name}.off"));
    write_mesh(&p, m).unwrap();
    p
}

/// Runs `repair --json`; returns the exit code, the JSON and the written mesh.
fn repair(input: &Path, out: &Path, extra: &[&str]) -> (i32, Value, IndexedMesh) {
    let mut args = vec!["repair", path_str(input), "-o", path_str(out), "--json"];
    args.extend_from_slice(extra);
    let o = solidkit(&args);
    let code = o.status.code().unwrap();
    let v: Value = serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&o.stderr)));
    (code, v, read_mesh(out).unwrap())
}

fn assert_valid(name: &str, m: &IndexedMesh, volume: Option<f64>) {
    let r = TopologyReport::of(m);
    assert!(r.is_valid_solid(), "{name}: {}", r.to_text());
    if let Some(v) = volume {
        let err = (r.volume - v).abs() / v;
        assert!(err <= 0.005, "{name}: volume {} vs {v}", r.volume);
    }
}

/// The largest distance from an output vertex to the nearest input vertex (hole filling and
/// splitting add no new positions, so minimal mode keeps each vertex near an input one).
fn max_distance_to_input(input: &IndexedMesh, output: &IndexedMesh) -> f64 {
    output
        .positions
        .iter()
        .map(|p| {
            input
                .positions
                .iter()
                .map(|q| p.distance(*q))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max)
}

#[test]
fn built_in_suite_repairs_in_auto_mode() {
    let dir = tempfile::tempdir().unwrap();
    for (name, mesh, volume, _) in suite() {
        let input = write(dir.path(), name, &mesh);
        let before = TopologyReport::of(&read_mesh(&input).unwrap());
        let wrong_volume = (before.volume - volume).abs() > 0.005 * volume;
        assert!(
            !before.is_valid_solid() || wrong_volume,
            "{name} is not broken"
        );
        let out = dir.path().join(format!("{name}.auto.off"));
        let (code, v, m) = repair(&input, &out, &[]);
        assert_eq!(code, 0, "{name}: {v}");
        assert_eq!(v["valid"], true);
        assert_valid(name, &m, Some(volume));
    }
}

#[test]
fn built_in_suite_minimal_mode_moves_no_vertex_beyond_the_weld() {
    let dir = tempfile::tempdir().unwrap();
    let weld = 1e-6;
    for (name, mesh, volume, fixable) in suite() {
        let input = write(dir.path(), name, &mesh);
        let stored = read_mesh(&input).unwrap();
        let out = dir.path().join(format!("{name}.min.off"));
        let (code, v, m) = repair(&input, &out, &["--mode", "minimal", "--weld", "1e-6"]);
        let moved = max_distance_to_input(&stored, &m);
        assert!(moved <= weld, "{name}: a vertex moved {moved}");
        let reported = v["changes"]["max_vertex_displacement"].as_f64().unwrap();
        assert!(
            reported <= weld && reported >= moved * (1.0 - 1e-9),
            "{name}: {reported}"
        );
        assert_eq!(v["rebuilt"], false);
        if fixable {
            assert_eq!(code, 0, "{name}: {v}");
            assert_valid(name, &m, Some(volume));
        } else {
            assert_eq!(code, 1, "{name}: minimal cannot remove overlaps");
        }
    }
}

#[test]
fn counts_name_what_was_fixed() {
    let dir = tempfile::tempdir().unwrap();
    let cases = suite();
    let get = |n: &str| cases.iter().find(|c| c.0 == n).unwrap().1.clone();
    let run = |n: &str| {
        let input = write(dir.path(), n, &get(n));
        let out = dir.path().join(format!("{n}.c.off"));
        repair(&input, &out, &["--mode", "minimal"]).1["changes"].clone()
    };
    let soup = run("soup");
    assert_eq!(soup["vertices_welded"], 36 - 8);
    assert_eq!(soup["faces_flipped"], 12);
    let holes = run("holes");
    assert_eq!(holes["holes_filled"], 2);
    assert_eq!(holes["largest_hole_edges"], 50);
    // 11 surplus copies, and the 4 copies of one face whose two windings cancel (then refilled).
    let dup = run("duplicate_faces");
    assert_eq!(dup["duplicate_faces_removed"], 15);
    assert_eq!(dup["holes_filled"], 1);
    let fin = run("fin");
    assert_eq!(fin["non_manifold_edges_cut"], 1);
    assert_eq!(fin["flat_shells_removed"], 1);
    assert_eq!(run("bow_tie")["non_manifold_vertices_split"], 1);
}

#[test]
fn rebuild_mode_reports_the_hausdorff_distance() {
    let dir = tempfile::tempdir().unwrap();
    let input = write(dir.path(), "soup", &suite()[0].1);
    let out = dir.path().join("rebuilt.off");
    let (code, v, m) = repair(&input, &out, &["--mode", "rebuild", "--resolution", "32"]);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["rebuilt"], true);
    let h = v["rebuild"]["hausdorff"].as_f64().unwrap();
    // Dual contouring keeps the cube's sharp edges: far below a cell (1/32 of the side).
    assert!(h < 0.01, "{h}");
    assert_valid("rebuilt soup", &m, Some(1.0));
}

#[test]
fn every_gen_broken_mesh_is_repaired() {
    let dir = tempfile::tempdir().unwrap();
    let suite_dir = dir.path().join("broken");
    for format in ["off", "stl"] {
        let o = solidkit(&[
            "gen",
            "broken",
            "-o",
            path_str(&suite_dir),
            "--format",
            format,
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let mut files: Vec<_> = std::fs::read_dir(&suite_dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == format))
            .collect();
        files.sort();
        assert_eq!(files.len(), 7);
        for input in files {
            let name = input.file_stem().unwrap().to_string_lossy().to_string();
            let out = dir.path().join(format!("{name}.{format}.repaired.off"));
            let (code, v, m) = repair(&input, &out, &[]);
            assert_eq!(code, 0, "{name}: {v}");
            // The intended solids: unit cubes (two for the non-manifold cases), the octahedron
            // (4/3), the cube with the tetrahedron poking out (union, not checked).
            let volume = match name.as_str() {
                "flipped_face" => Some(4.0 / 3.0),
                "non_manifold_edge" | "non_manifold_vertex" => Some(2.0),
                "self_intersection" => None,
                _ => Some(1.0),
            };
            assert_valid(&name, &m, volume);
        }
        std::fs::remove_dir_all(&suite_dir).unwrap();
    }
}

#[test]
fn bad_input_exits_2_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.off");
    let degenerate = dir.path().join("degenerate.off");
    std::fs::write(&degenerate, "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n").unwrap();
    let garbage = dir.path().join("garbage.off");
    std::fs::write(&garbage, "not a mesh").unwrap();
    for (input, words) in [(&degenerate, "encloses"), (&garbage, "garbage.off")] {
        let o = solidkit(&["repair", path_str(input), "-o", path_str(&out)]);
        assert_eq!(o.status.code(), Some(2));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains(words) && err.contains(path_str(input)),
            "{err}"
        );
        assert!(!out.exists());
    }
}

#[test]
fn check_compare_and_repair_read_3mf_and_glb() {
    let dir = tempfile::tempdir().unwrap();
    for (name, mesh, volume, _) in suite().into_iter().take(3) {
        for ext in ["3mf", "glb"] {
            let input = dir.path().join(format!("{name}.{ext}"));
            write_mesh(&input, &mesh).unwrap();
            let out = dir.path().join(format!("{name}-fixed.{ext}"));
            let (code, _, fixed) = repair(&input, &out, &[]);
            assert_eq!(code, 0, "{name}.{ext}");
            assert_valid(name, &fixed, Some(volume));
            let o = solidkit(&["check", path_str(&out)]);
            assert_eq!(o.status.code(), Some(0), "{name}.{ext}");
            let o = solidkit(&["compare", path_str(&input), path_str(&out), "--json"]);
            assert_eq!(o.status.code(), Some(0), "{name}.{ext}");
        }
    }
    let trimesh = solidkit_tests::fixture("meshes/io/trimesh_scene.3mf");
    assert_eq!(
        solidkit(&["check", path_str(&trimesh)]).status.code(),
        Some(0)
    );
}

#[test]
fn check_weld_shares_a_soup_and_prints_a_verdict_with_coordinates() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("soup.obj");
    write_mesh(&input, &soup(&cube(DVec3::ZERO, 1.0), 1e-7)).unwrap();
    let o = solidkit(&["check", path_str(&input), "--no-self-intersections"]);
    assert_eq!(o.status.code(), Some(1));
    let text = String::from_utf8_lossy(&o.stdout);
    let first = text.lines().next().unwrap();
    assert!(
        first.starts_with("verdict: NOT a solid: 36 boundary edges"),
        "{text}"
    );
    assert!(
        text.contains("first offenders at:\n  boundary edge 0-1 at ("),
        "{text}"
    );
    let o = solidkit(&["check", path_str(&input), "--weld", "1e-6"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.starts_with("verdict: closed oriented 2-manifold, no self-intersections\nwelded: 28 vertices merged within 0.000001\n"), "{text}");
    let o = solidkit(&["check", path_str(&input), "--weld", "1e-6", "--json"]);
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(
        (v["vertices"].as_u64(), v["vertices_welded"].as_u64()),
        (Some(8), Some(28))
    );
    assert_eq!(
        v["example_positions"]["boundary_edges"]
            .as_array()
            .map(Vec::len),
        Some(0)
    );
    assert!(v["verdict"].as_str().unwrap().starts_with("closed"));
    let o = solidkit(&["check", path_str(&input), "--weld", "-1"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn hostile_3mf_and_glb_exit_2_with_located_messages() {
    let dir = tempfile::tempdir().unwrap();
    // A stored entry whose headers declare 2 GiB: refused before anything is inflated.
    let data = b"<model/>";
    let mut zip = Vec::new();
    let header = |sig: u32, central: bool| {
        let mut h = sig.to_le_bytes().to_vec();
        h.extend(if central {
            &[20u8, 0, 20, 0][..]
        } else {
            &[20u8, 0][..]
        });
        h.extend([0, 0, 8, 0, 0, 0, 0x21, 0]); // flags, deflate, time, date
        h.extend([0u8; 4]); // CRC
        h.extend((data.len() as u32).to_le_bytes());
        h.extend((1u32 << 31).to_le_bytes());
        h.extend((16u16).to_le_bytes());
        h.extend([0u8; 2]);
        h
    };
    zip.extend(header(0x0403_4b50, false));
    zip.extend(b"3D/3dmodel.model");
    zip.extend(data);
    let start = zip.len() as u32;
    let mut central = header(0x0201_4b50, true);
    central.extend([0u8; 14]);
    central.extend(b"3D/3dmodel.model");
    zip.extend(&central);
    zip.extend(0x0605_4b50u32.to_le_bytes());
    zip.extend([0, 0, 0, 0, 1, 0, 1, 0]);
    zip.extend((central.len() as u32).to_le_bytes());
    zip.extend(start.to_le_bytes());
    zip.extend([0, 0]);
    let bomb = dir.path().join("bomb.3mf");
    std::fs::write(&bomb, &zip).unwrap();
    let glb = dir.path().join("cut.glb");
    let cube_glb = dir.path().join("cube.glb");
    write_mesh(&cube_glb, &cube(DVec3::ZERO, 1.0)).unwrap();
    let bytes = std::fs::read(&cube_glb).unwrap();
    std::fs::write(&glb, &bytes[..bytes.len() - 10]).unwrap();
    for (file, words) in [
        (
            &bomb,
            ": byte 0: entry 3D/3dmodel.model: 2147483648 bytes uncompressed, over the limit",
        ),
        (&glb, ": byte "),
    ] {
        for command in ["check", "repair", "compare"] {
            let out = dir.path().join("out.off");
            let args: Vec<&str> = match command {
                "check" => vec![command, path_str(file)],
                "repair" => vec![command, path_str(file), "-o", path_str(&out)],
                _ => vec![command, path_str(file), path_str(file)],
            };
            let o = solidkit(&args);
            assert_eq!(o.status.code(), Some(2), "{command} {file:?}");
            let err = String::from_utf8_lossy(&o.stderr);
            assert!(err.contains(&format!("{}{words}", path_str(file))), "{err}");
            assert!(!out.exists());
        }
    }
}

#[test]
fn repair_text_has_a_verdict_before_and_after() {
    let dir = tempfile::tempdir().unwrap();
    let (_, mesh, _, _) = suite().remove(0);
    let input = write(dir.path(), "soup", &mesh);
    let out = dir.path().join("fixed.off");
    let o = solidkit(&["repair", path_str(&input), "-o", path_str(&out)]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    let verdicts: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("verdict: "))
        .collect();
    assert_eq!(verdicts.len(), 2, "{text}");
    assert!(verdicts[0].starts_with("verdict: NOT a solid: "), "{text}");
    assert_eq!(
        verdicts[1],
        "verdict: closed oriented 2-manifold, no self-intersections"
    );
}

/// Hostile inputs end with a result or a clear message, never a panic: 10⁶ copies of one face
/// on a cube (the copies removed), a 20 000-edge hole (filled), and meshes whose faces are all
/// degenerate (collinear, or with repeated corners: exit 2, the file named).
#[test]
fn hostile_inputs_end_with_a_result_or_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.off");
    let mut cube_text = String::from("OFF\n8 1000012 0\n");
    let c = cube(DVec3::ZERO, 1.0);
    for p in &c.positions {
        cube_text.push_str(&format!("{} {} {}\n", p.x, p.y, p.z));
    }
    for t in &c.triangles {
        cube_text.push_str(&format!("3 {} {} {}\n", t[0], t[1], t[2]));
    }
    let t = c.triangles[0];
    cube_text.push_str(&format!("3 {} {} {}\n", t[0], t[1], t[2]).repeat(1_000_000));
    let copies = dir.path().join("copies.off");
    std::fs::write(&copies, cube_text).unwrap();
    let (code, v, m) = repair(&copies, &out, &["--mode", "minimal"]);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["changes"]["duplicate_faces_removed"], 1_000_000);
    assert_valid("copies", &m, Some(1.0));

    let mut tube = prism(20_000);
    tube.triangles.retain(|t| !t.iter().all(|&v| v >= 20_000));
    let hole = write(dir.path(), "hole", &tube);
    let (code, v, m) = repair(&hole, &out, &["--mode", "minimal"]);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["changes"]["largest_hole_edges"], 20_000);
    assert_valid("hole", &m, Some(ngon_area(20_000)));

    let n = 10_000;
    let flat = IndexedMesh::new(
        (0..n).map(|i| DVec3::new(f64::from(i), 0.0, 0.0)).collect(),
        (0..n).map(|i| [i, (i + 1) % n, (i + 2) % n]).collect(),
    );
    let mut repeated = flat.clone();
    repeated.triangles = (0..n).map(|i| [i, i, (i + 1) % n]).collect();
    for (name, mesh, words) in [
        ("collinear", flat, "nothing encloses a volume"),
        ("repeated", repeated, "no usable triangle"),
    ] {
        let input = write(dir.path(), name, &mesh);
        let o = solidkit(&["repair", path_str(&input), "-o", path_str(&out)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert!(
            err.contains(path_str(&input)) && err.contains(words),
            "{err}"
        );
        assert!(!err.contains("panicked"), "{err}");
    }
}
