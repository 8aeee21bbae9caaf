//! `solidkit gen` end to end: every manifest value of `platonic` and `sponge` equals the exact
//! value computed here from textbook formulas, and the report of every written file agrees;
//! `random --seed 7` is byte-identical across runs and thread counts, each mesh volume within its
//! stated tolerance of the sampled volume and each tree rebuilds the same mesh; `csg` closed forms
//! within their tolerances; `smooth` counts and chord-error bounds; `broken`: `solidkit check`
//! reports exactly the listed defects in every format; 3MF and GLB files round-trip through the
//! small readers of `export_readers.rs`.

use crate::export_readers::{read_3mf, read_glb};
use glam::DVec3;
use serde_json::Value;
use solidkit_meshing::io::read_mesh;
use solidkit_meshing::{IndexedMesh, ReportOptions, TopologyReport};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Output;

fn solidkit(args: &[&str]) -> Output {
    solidkit_tests::run_cli(env!("CARGO_BIN_EXE_solidkit"), args)
}

/// Runs `solidkit gen SUITE -o DIR ARGS…`, expects success, returns the manifest.
fn generate(suite: &str, dir: &Path, args: &[&str]) -> Value {
    let d = dir.to_str().expect("UTF-8");
    let mut all = vec!["gen", suite, "-o", d];
    all.extend_from_slice(args);
    let o = solidkit(&all);
    assert!(
        o.status.success(),
        "gen {suite}: {}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&std::fs::read(dir.join("manifest.json")).expect("manifest"))
        .expect("manifest JSON")
}

/// The report without the self-intersection search.
fn report_fast(mesh: &IndexedMesh) -> TopologyReport {
    TopologyReport::with_options(
        mesh,
        &ReportOptions {
            self_intersections: false,
        },
    )
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn u(v: &Value) -> u64 {
    v.as_u64().unwrap_or_else(|| panic!("not a count: {v}"))
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(1e-300)
}

/// Exact values a solid must have: counts, χ, genus, shells, volume, area.
struct Exact {
    counts: [u64; 3],
    genus: i64,
    shells: u64,
    volume: f64,
    area: f64,
}

/// Checks the manifest's truth against `exact`, and the report of the written file (and the
/// manifest's own copy of it) against both.
fn check_exact(dir: &Path, solid: &Value, exact: &Exact) {
    let name = solid["name"].as_str().expect("name");
    let t = &solid["truth"];
    let chi = exact.counts[0] as i64 - exact.counts[1] as i64 + exact.counts[2] as i64;
    assert_eq!(chi, 2 * exact.shells as i64 - 2 * exact.genus, "{name}: χ");
    assert_eq!(
        [u(&t["vertices"]), u(&t["edges"]), u(&t["faces"])],
        exact.counts,
        "{name}: truth V, E, F"
    );
    assert_eq!(t["euler_characteristic"].as_i64(), Some(chi), "{name}");
    assert_eq!(t["genus"].as_i64(), Some(exact.genus), "{name}");
    assert_eq!(u(&t["shells"]), exact.shells, "{name}");
    assert!(
        close(f(&t["volume"]["value"]), exact.volume, 1e-14),
        "{name}: volume {} vs {}",
        t["volume"],
        exact.volume
    );
    assert!(
        close(f(&t["area"]["value"]), exact.area, 1e-14),
        "{name}: area {} vs {}",
        t["area"],
        exact.area
    );
    let file = dir.join(solid["file"].as_str().expect("file"));
    // The manifest's report counted self-intersections (none); recount the rest here.
    assert_eq!(solid["mesh"]["self_intersections"], 0, "{name}");
    let r = report_fast(&read_mesh(&file).expect("readable"));
    assert!(r.is_closed_manifold(), "{name}: {r:?}");
    assert_eq!(
        [r.vertices as u64, r.edges as u64, r.faces as u64],
        exact.counts,
        "{name}: file V, E, F"
    );
    assert_eq!(r.euler_characteristic, chi, "{name}");
    assert_eq!(r.genus, Some(exact.genus), "{name}");
    assert_eq!(r.shells as u64, exact.shells, "{name}");
    assert!(
        close(r.volume, exact.volume, 1e-12),
        "{name}: file volume {} vs {}",
        r.volume,
        exact.volume
    );
    assert!(
        close(r.area, exact.area, 1e-12),
        "{name}: file area {} vs {}",
        r.area,
        exact.area
    );
    let m = &solid["mesh"];
    // serde_json reads numbers to within an ulp (it writes them exactly).
    assert!(
        close(f(&m["volume"]), r.volume, 1e-15),
        "{name}: manifest mesh volume"
    );
    assert!(close(f(&m["area"]), r.area, 1e-15), "{name}");
    assert_eq!(u(&m["faces"]), r.faces as u64, "{name}");
    assert_eq!(solid["error"]["topology_matches"], true, "{name}");
    for (k, corner) in ["min", "max"].iter().enumerate() {
        for a in 0..3 {
            let want = f(&t["bbox"][k][a]);
            assert!((r.bbox[k][a] - want).abs() < 1e-14, "{name}: bbox {corner}");
        }
    }
}

/// Textbook values of a Platonic solid per unit edge: volume, area, circumradius, inradius,
/// (V, E, F) of the polyhedron, sides per face.
fn textbook(kind: &str) -> (f64, f64, f64, f64, [u64; 3], u64) {
    let (s2, s3, s5) = (2f64.sqrt(), 3f64.sqrt(), 5f64.sqrt());
    let phi = (1.0 + s5) / 2.0;
    match kind {
        "tetrahedron" => (
            1.0 / (6.0 * s2),
            s3,
            (3.0 / 8.0f64).sqrt(),
            1.0 / 24f64.sqrt(),
            [4, 6, 4],
            3,
        ),
        "cube" => (1.0, 6.0, s3 / 2.0, 0.5, [8, 12, 6], 4),
        "octahedron" => (
            s2 / 3.0,
            2.0 * s3,
            1.0 / s2,
            1.0 / 6f64.sqrt(),
            [6, 12, 8],
            3,
        ),
        "dodecahedron" => (
            (15.0 + 7.0 * s5) / 4.0,
            3.0 * (25.0 + 10.0 * s5).sqrt(),
            s3 * phi / 2.0,
            phi * phi / (2.0 * (3.0 - phi).sqrt()),
            [20, 30, 12],
            5,
        ),
        "icosahedron" => (
            5.0 * (3.0 + s5) / 12.0,
            5.0 * s3,
            (phi * s5).sqrt() / 2.0,
            phi * phi / (2.0 * s3),
            [12, 30, 20],
            3,
        ),
        other => panic!("unknown kind {other}"),
    }
}

fn platonic_exact(kind: &str, edge: f64) -> Exact {
    let (v, a, _, _, [nv, _, nf], sides) = textbook(kind);
    let faces = nf * (sides - 2);
    Exact {
        counts: [nv, 3 * faces / 2, faces],
        genus: 0,
        shells: 1,
        volume: v * edge.powi(3),
        area: a * edge * edge,
    }
}

fn tmp() -> tempfile::TempDir {
    tempfile::tempdir().expect("temp dir")
}

#[test]
fn platonic_manifest_values_are_exact_and_files_agree() {
    let dir = tmp();
    let m = generate("platonic", dir.path(), &[]);
    assert_eq!(m["format"], "solidkit-gen");
    assert_eq!(m["mesh_format"], "ply");
    let solids = m["solids"].as_array().expect("solids");
    assert_eq!(solids.len(), 14);
    let duals = [
        ("tetrahedron", "tetrahedron"),
        ("cube", "octahedron"),
        ("octahedron", "cube"),
        ("dodecahedron", "icosahedron"),
        ("icosahedron", "dodecahedron"),
    ];
    for s in solids {
        let name = s["name"].as_str().expect("name");
        let exact = if let Some(of) = name.strip_prefix("dual_of_") {
            let kind = duals.iter().find(|d| d.0 == of).expect("dual").1;
            // The dual's circumradius is the original's inradius.
            let edge = textbook(of).3 / textbook(kind).2;
            assert!(close(f(&s["parameters"]["edge"]), edge, 1e-14), "{name}");
            platonic_exact(kind, edge)
        } else if name.starts_with("prism_") {
            prism_exact(&s["parameters"])
        } else {
            platonic_exact(name, 1.0)
        };
        check_exact(dir.path(), s, &exact);
    }
}

/// Exact values of a prism from its parameters: shoelace area, perimeter, counts.
fn prism_exact(p: &Value) -> Exact {
    let pts = |l: &Value| -> Vec<[f64; 2]> {
        l.as_array()
            .expect("loop")
            .iter()
            .map(|q| [f(&q[0]), f(&q[1])])
            .collect()
    };
    let mut loops = vec![pts(&p["polygon"])];
    loops.extend(p["holes"].as_array().expect("holes").iter().map(pts));
    let area2 = |l: &[[f64; 2]]| -> f64 {
        (0..l.len())
            .map(|i| {
                let (a, b) = (l[i], l[(i + 1) % l.len()]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum::<f64>()
    };
    let section =
        area2(&loops[0]).abs() / 2.0 - loops[1..].iter().map(|l| area2(l).abs() / 2.0).sum::<f64>();
    let perimeter: f64 = loops
        .iter()
        .map(|l| {
            (0..l.len())
                .map(|i| {
                    let (a, b) = (l[i], l[(i + 1) % l.len()]);
                    (a[0] - b[0]).hypot(a[1] - b[1])
                })
                .sum::<f64>()
        })
        .sum();
    let h = f(&p["height"]);
    let n = loops.iter().map(Vec::len).sum::<usize>() as u64;
    let holes = loops.len() as u64 - 1;
    let faces = 2 * (n + 2 * holes - 2) + 2 * n;
    Exact {
        counts: [2 * n, 3 * faces / 2, faces],
        genus: holes as i64,
        shells: 1,
        volume: section * h,
        area: 2.0 * section + perimeter * h,
    }
}

#[test]
fn sponge_manifest_values_are_exact_and_files_agree() {
    let dir = tmp();
    let m = generate("sponge", dir.path(), &[]);
    let genus = [0i64, 5, 81, 1409, 26433];
    let solids = m["solids"].as_array().expect("solids");
    assert_eq!(solids.len(), 5);
    for (level, s) in solids.iter().enumerate() {
        let l = level as i32;
        let squares = 2 * 20u64.pow(level as u32) + 4 * 8u64.pow(level as u32);
        let exact = Exact {
            counts: [
                (2 - 2 * genus[level] + squares as i64) as u64,
                3 * squares,
                2 * squares,
            ],
            genus: genus[level],
            shells: 1,
            volume: (20.0f64 / 27.0).powi(l),
            area: squares as f64 / 9f64.powi(l),
        };
        assert_eq!(s["name"], format!("menger_{level}"));
        check_exact(dir.path(), s, &exact);
    }
}

/// Every file in `dir`, by name.
fn contents(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(dir)
        .expect("dir")
        .map(|e| {
            let e = e.expect("entry");
            (
                e.file_name().to_string_lossy().into_owned(),
                std::fs::read(e.path()).expect("file"),
            )
        })
        .collect()
}

#[test]
fn random_seed_7_is_byte_identical_and_within_stated_errors() {
    let (a, b) = (tmp(), tmp());
    let m = generate("random", a.path(), &["--seed", "7", "--threads", "1"]);
    generate("random", b.path(), &["--seed", "7", "--threads", "2"]);
    let (ca, cb) = (contents(a.path()), contents(b.path()));
    assert_eq!(ca.len(), 1 + 2 * 8, "8 meshes, 8 trees, the manifest");
    assert!(ca == cb, "two runs differ");
    // The rule: |mesh volume − sampled volume| ≤ volume_tolerance = 4σ + 2|V_N − V_N/2|.
    for s in m["solids"].as_array().expect("solids") {
        let name = s["name"].as_str().expect("name");
        let t = &s["truth"]["volume"];
        assert_eq!(t["method"], "sampling");
        let (sampled, sigma) = (f(&t["value"]), f(&t["standard_error"]));
        let tol = f(&s["error"]["volume_tolerance"]);
        let half = f(&s["parameters"]["half_resolution_volume"]);
        let mesh_volume = f(&s["mesh"]["volume"]);
        assert!(
            (tol - (4.0 * sigma + 2.0 * (mesh_volume - half).abs())).abs() < 1e-9 * sampled,
            "{name}: tolerance as stated"
        );
        assert!(
            (mesh_volume - sampled).abs() <= tol,
            "{name}: {mesh_volume} vs {sampled} ± {tol}"
        );
        // The statement has teeth: a few percent at most, sampling error far below it.
        assert!(
            tol < 0.05 * sampled && sigma < 2e-4 * sampled,
            "{name}: tol {tol}, σ {sigma}"
        );
        assert_eq!(s["error"]["volume_within_tolerance"], true);
        assert_eq!(s["mesh"]["self_intersections"], 0, "{name}");
        let file = a.path().join(s["file"].as_str().expect("file"));
        let stored = read_mesh(&file).expect("readable");
        let r = report_fast(&stored);
        assert!(r.is_closed_manifold(), "{name}");
        // The tree beside the mesh rebuilds the same mesh.
        let tree = std::fs::read_to_string(a.path().join(s["tree"].as_str().expect("tree")))
            .expect("tree");
        let solid = solidkit_kernel::json::from_str(&tree).expect("tree parses");
        let (again, _) = solidkit_tests::mesh(&solid, u(&s["parameters"]["resolution"]) as usize);
        assert_eq!(again, stored, "{name}: the tree rebuilds the mesh");
    }
    let other = tmp();
    generate("random", other.path(), &["--seed", "8", "--count", "2"]);
    assert_ne!(
        contents(other.path())["random_000.json"],
        ca["random_000.json"],
        "seeded"
    );
}

#[test]
fn csg_closed_forms_within_stated_tolerance() {
    let dir = tmp();
    let m = generate("csg", dir.path(), &[]);
    let solids = m["solids"].as_array().expect("solids");
    assert_eq!(solids.len(), 7);
    for s in solids {
        let name = s["name"].as_str().expect("name");
        let t = &s["truth"];
        let err = &s["error"];
        assert_eq!(err["volume_within_tolerance"], true, "{name}");
        let r = &s["mesh"];
        assert_eq!(r["closed"], true, "{name}");
        assert_eq!(r["manifold"], true, "{name}");
        assert_eq!(r["self_intersections"], 0, "{name}");
        if t["genus"].is_null() {
            assert_eq!(t["volume"]["method"], "sampling", "{name}");
            continue;
        }
        assert_eq!(err["topology_matches"], true, "{name}: {r}");
        assert!(f(&err["volume_relative"]).abs() < 0.03, "{name}: {err}");
        assert!(f(&err["area_relative"]).abs() < 0.03, "{name}: {err}");
    }
    // The tricylinder ∩ cube closed form, against brute-force integration of
    // V = ∫∫ 2 min(s, √(1 − x²), √(1 − y²)) over |x|, |y| ≤ s, x² + y² ≤ 1.
    let tri = solids
        .iter()
        .find(|s| s["name"] == "tricylinder_cube")
        .expect("tricylinder");
    let (s, n) = (0.9f64, 1500);
    let h = 2.0 * s / n as f64;
    let mut v = 0.0;
    for i in 0..n {
        for j in 0..n {
            let (x, y) = (-s + h * (i as f64 + 0.5), -s + h * (j as f64 + 0.5));
            if x * x + y * y <= 1.0 {
                v += 2.0 * s.min((1.0 - x * x).sqrt()).min((1.0 - y * y).sqrt()) * h * h;
            }
        }
    }
    assert!(
        close(f(&tri["truth"]["volume"]["value"]), v, 2e-4),
        "{v} vs {}",
        tri["truth"]["volume"]
    );
    let tangent = solids
        .iter()
        .find(|s| s["name"] == "tangent_spheres")
        .expect("tangent");
    assert_eq!(u(&tangent["mesh"]["shells"]), 2);
}

#[test]
fn smooth_counts_and_chord_error_bounds() {
    let dir = tmp();
    let m = generate("smooth", dir.path(), &["--resolution", "48"]);
    for s in m["solids"].as_array().expect("solids") {
        let name = s["name"].as_str().expect("name");
        let t = &s["truth"];
        let r = TopologyReport::of(
            &read_mesh(&dir.path().join(s["file"].as_str().expect("file"))).expect("mesh"),
        );
        assert!(r.is_closed_manifold(), "{name}");
        assert_eq!(s["mesh"]["self_intersections"], 0, "{name}");
        assert_eq!(
            [r.vertices as u64, r.edges as u64, r.faces as u64],
            [u(&t["vertices"]), u(&t["edges"]), u(&t["faces"])],
            "{name}"
        );
        assert_eq!(r.genus, t["genus"].as_i64(), "{name}");
        // A mesh within δ of the surface differs in volume by at most about δ · area.
        let bound = f(&s["error"]["chord_error_bound"]);
        let dv = f(&s["error"]["volume"]).abs();
        assert!(
            bound > 0.0 && dv <= 2.0 * bound * f(&t["area"]["value"]),
            "{name}: {dv} vs δ {bound}"
        );
        // The bound holds at triangle centroids where the distance is easy to compute.
        let mesh = read_mesh(&dir.path().join(s["file"].as_str().expect("file"))).expect("mesh");
        let distance: Option<Box<dyn Fn(DVec3) -> f64>> = match name {
            "sphere" => Some(Box::new(|p: DVec3| (p.length() - 1.0).abs())),
            "torus" | "swept_tube" => {
                let minor = if name == "torus" { 0.35 } else { 0.3 };
                Some(Box::new(move |p: DVec3| {
                    (DVec3::new(p.truncate().length() - 1.0, 0.0, p.z).length() - minor).abs()
                }))
            }
            "cylinder_extruded" => Some(Box::new(|p: DVec3| {
                // Distance to the side or to a cap, whichever is nearer.
                (p.truncate().length() - 0.6)
                    .abs()
                    .min((p.z.abs() - 0.75).abs())
            })),
            _ => None,
        };
        if let Some(d) = distance {
            let worst = centroid_distances(&mesh, d);
            assert!(worst <= bound * (1.0 + 1e-9), "{name}: {worst} > {bound}");
            assert!(
                worst > 0.2 * bound,
                "{name}: the bound is not loose by more than 5×"
            );
        }
    }
}

fn centroid_distances(mesh: &IndexedMesh, d: impl Fn(DVec3) -> f64) -> f64 {
    (0..mesh.triangle_count())
        .map(|t| {
            let [a, b, c] = mesh.triangle_positions(t);
            d((a + b + c) / 3.0)
        })
        .fold(0.0, f64::max)
}

#[test]
fn broken_check_finds_exactly_the_listed_defects() {
    for format in ["stl", "obj", "ply", "off"] {
        let dir = tmp();
        let m = generate("broken", dir.path(), &["--format", format]);
        let solids = m["solids"].as_array().expect("solids");
        assert_eq!(solids.len(), 7);
        for s in solids {
            let name = s["name"].as_str().expect("name");
            let file = dir.path().join(s["file"].as_str().expect("file"));
            let o = solidkit(&["check", "--json", file.to_str().expect("UTF-8")]);
            let report: Value = serde_json::from_slice(&o.stdout).expect("report");
            let expected = &s["defects"]["expected"];
            for (key, want) in expected.as_object().expect("expected") {
                assert_eq!(&report[key], want, "{format} {name}: {key}");
            }
            let good = expected["closed"] == true
                && expected["manifold"] == true
                && expected["oriented"] == true
                && expected["self_intersections"] == 0;
            assert_eq!(
                o.status.code(),
                Some(if good { 0 } else { 1 }),
                "{format} {name}"
            );
            let put_in = s["defects"]["put_in"].as_array().expect("defects");
            assert!(
                !put_in.is_empty() && put_in.iter().all(|d| u(&d["count"]) > 0),
                "{name}"
            );
        }
    }
}

fn ply_mesh(dir: &Path, name: &str) -> IndexedMesh {
    read_mesh(&dir.join(format!("{name}.ply"))).expect("ply")
}

#[test]
fn three_mf_and_glb_round_trip() {
    let ply = tmp();
    generate("platonic", ply.path(), &[]);
    for format in ["3mf", "glb"] {
        let dir = tmp();
        let m = generate("platonic", dir.path(), &["--format", format]);
        for s in m["solids"].as_array().expect("solids") {
            let name = s["name"].as_str().expect("name");
            let bytes =
                std::fs::read(dir.path().join(s["file"].as_str().expect("file"))).expect("file");
            let exact = ply_mesh(ply.path(), name);
            let read = if format == "3mf" {
                read_3mf(&bytes)
            } else {
                read_glb(&bytes)
            };
            let want = if format == "3mf" {
                exact.clone()
            } else {
                IndexedMesh::new(
                    exact
                        .positions
                        .iter()
                        .map(|p| p.as_vec3().as_dvec3())
                        .collect(),
                    exact.triangles.clone(),
                )
            };
            assert_eq!(read, want, "{format} {name}");
            // solidkit's own reader agrees with the independent one.
            let own = read_mesh(&dir.path().join(s["file"].as_str().expect("file")));
            assert_eq!(own.expect("read back"), want, "{format} {name}");
            // The manifest measured the mesh as the file stores it.
            let r = TopologyReport::of(&read);
            assert!(
                close(f(&s["mesh"]["volume"]), r.volume, 1e-15),
                "{format} {name}"
            );
            assert_eq!(u(&s["mesh"]["vertices"]), r.vertices as u64);
        }
    }
    // `solidkit mesh` writes them too, by extension.
    let dir = tmp();
    let tree = solidkit_tests::fixture("examples/bracket.json");
    let out = |ext: &str| dir.path().join(format!("bracket.{ext}"));
    for ext in ["ply", "3mf", "glb"] {
        let o = solidkit(&[
            "mesh",
            tree.to_str().expect("UTF-8"),
            "--resolution",
            "24",
            "-o",
            out(ext).to_str().expect("UTF-8"),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let exact = read_mesh(&out("ply")).expect("ply");
    assert_eq!(read_3mf(&std::fs::read(out("3mf")).expect("3mf")), exact);
    let glb = read_glb(&std::fs::read(out("glb")).expect("glb"));
    assert_eq!(glb.triangles, exact.triangles);
    assert!(
        glb.positions
            .iter()
            .zip(&exact.positions)
            .all(|(a, b)| a.distance(*b) < 1e-6)
    );
}

#[test]
fn bad_arguments_are_one_line_errors() {
    let dir = tmp();
    let d = dir.path().to_str().expect("UTF-8");
    let o = solidkit(&["gen", "random", "-o", d, "--resolution", "4"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("resolution must be 8 to 2048, got 4"), "{err}");
    let o = solidkit(&["gen", "random", "-o", d, "--count", "0"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(solidkit(&["gen", "nosuch", "-o", d]).status.code(), Some(2));
    // The output is a file, not a folder.
    let file: PathBuf = dir.path().join("a_file");
    std::fs::write(&file, b"x").expect("write");
    let o = solidkit(&["gen", "platonic", "-o", file.to_str().expect("UTF-8")]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("error: "));
}
