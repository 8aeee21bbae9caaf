//! Coincident faces on the grid: solids whose faces are shared inside a union, or whose cutters
//! are flush with a face, must mesh as the one solid they are, at every resolution.
//!
//! Four models with integer (or half-integer) coordinates, where sample points land exactly on
//! the shared faces at many resolutions: two unit boxes sharing a face, a 3 × 3 × 3 stack of
//! unit cubes, three cylinders stacked cap to cap, and a 4 × 4 × 2 plate with 16 through-holes
//! whose cutters are flush with both faces. Each is meshed by marching cubes (sparse, as
//! `solidkit mesh` does) and by dual contouring at every `--resolution` from 60 to 260 on the
//! CLI's grid (aligned with the faces at many of them), and on grids shifted by a fraction of a
//! cell (never aligned). Every mesh must be one closed, manifold, oriented shell of the exact
//! genus with its area within 3% of the exact value (an internal wall or skin adds 20% or more);
//! a sample of them is also checked for self-intersections (the check is the slow part).

use rayon::prelude::*;
use solidkit_kernel::{Program, json};
use solidkit_meshing::dual_contouring::{DcOptions, mesh_dc};
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use solidkit_meshing::{IndexedMesh, ReportOptions, TopologyReport};
use std::f64::consts::PI;

/// A model: its JSON tree, exact genus and exact area.
struct Case {
    name: &'static str,
    tree: String,
    genus: i64,
    area: f64,
}

fn translate(offset: [f64; 3], child: &str) -> String {
    format!(r#"{{"type":"translate","offset":{offset:?},"child":{child}}}"#)
}

fn boxed(size: [f64; 3]) -> String {
    format!(r#"{{"type":"box","size":{size:?}}}"#)
}

fn cylinder(radius: f64, height: f64) -> String {
    format!(r#"{{"type":"cylinder","radius":{radius:?},"height":{height:?}}}"#)
}

fn tree(kind: &str, children: &[String]) -> String {
    format!(
        r#"{{"format":"solidkit-tree","version":1,"root":{{"type":"{kind}","children":[{}]}}}}"#,
        children.join(",")
    )
}

fn cases() -> Vec<Case> {
    let unit = boxed([1.0; 3]);
    let two_boxes = tree(
        "union",
        &[
            translate([0.5; 3], &unit),
            translate([1.5, 0.5, 0.5], &unit),
        ],
    );
    let stack: Vec<String> = (0..27)
        .map(|i| {
            let c = |k: usize| k as f64 + 0.5;
            translate([c(i % 3), c(i / 3 % 3), c(i / 9)], &unit)
        })
        .collect();
    let cylinders: Vec<String> = (0..3)
        .map(|k| translate([0.0, 0.0, k as f64 + 0.5], &cylinder(0.5, 1.0)))
        .collect();
    let mut plate = vec![translate([2.0, 2.0, 1.0], &boxed([4.0, 4.0, 2.0]))];
    plate.extend((0..16).map(|i| {
        let c = |k: usize| k as f64 + 0.5;
        translate([c(i % 4), c(i / 4), 1.0], &cylinder(0.3, 2.0))
    }));
    let holes = 16.0 * PI * 0.3 * 0.3;
    vec![
        Case {
            name: "two boxes sharing a face",
            tree: two_boxes,
            genus: 0,
            area: 10.0,
        },
        Case {
            name: "3×3×3 stack of unit cubes",
            tree: tree("union", &stack),
            genus: 0,
            area: 54.0,
        },
        Case {
            name: "three cylinders cap to cap",
            tree: tree("union", &cylinders),
            genus: 0,
            area: 2.0 * PI * 0.25 + 2.0 * PI * 0.5 * 3.0,
        },
        Case {
            name: "plate with 16 flush through-holes",
            tree: tree("difference", &plate),
            genus: 16,
            area: 2.0 * (16.0 - holes) + 32.0 + 16.0 * 2.0 * PI * 0.3 * 2.0,
        },
    ]
}

fn compile(case: &Case) -> (Program, solidkit_kernel::Aabb) {
    let solid = json::from_str(&case.tree).expect("tree parses");
    solid.validate().expect("tree valid");
    (solid.compile(), solid.bbox())
}

/// The problems of one mesh, empty when it is the single exact shell the case describes.
fn problems(case: &Case, mesh: &IndexedMesh, self_intersections: bool) -> Vec<String> {
    let report = TopologyReport::with_options(mesh, &ReportOptions { self_intersections });
    let mut out = Vec::new();
    if !(report.closed && report.manifold && report.oriented) {
        out.push(format!(
            "closed {} manifold {} oriented {}",
            report.closed, report.manifold, report.oriented
        ));
    }
    if report.shells != 1 || report.genus != Some(case.genus) {
        out.push(format!(
            "{} shells of genus {:?} (want 1 of genus {})",
            report.shells, report.genus, case.genus
        ));
    }
    let err = (report.area - case.area).abs() / case.area;
    if err > 0.03 {
        out.push(format!("area {:.4} vs exact {:.4}", report.area, case.area));
    }
    if self_intersections && report.self_intersections != Some(0) {
        out.push(format!(
            "self-intersections {:?}",
            report.self_intersections
        ));
    }
    out
}

/// Meshes `case` by both methods on `spec` and returns every failure, labelled.
fn check(case: &Case, program: &Program, spec: GridSpec, label: &str, full: bool) -> Vec<String> {
    let (mc, _) = mesh_sparse(program, spec, &SparseOptions::default()).expect("not cancelled");
    let (dc, _) = mesh_dc(program, spec, &DcOptions::default()).expect("not cancelled");
    let mut out = Vec::new();
    for (method, mesh) in [("MC", &mc), ("DC", &dc)] {
        for p in problems(case, mesh, full) {
            out.push(format!("{}: {method} {label}: {p}", case.name));
        }
    }
    out
}

fn report(failures: Vec<String>) {
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures[..failures.len().min(40)].join("\n")
    );
}

/// Every third `--resolution` from 60 to 258 on the CLI's grid (padded bounds, so the faces sit
/// on sample planes at many resolutions); every one with `SOLIDKIT_FULL_SWEEP=1` (7 minutes of
/// CI's two cores, a third of its time budget, for the other two thirds).
#[test]
fn one_exact_shell_at_every_resolution() {
    let cases = cases();
    let compiled: Vec<_> = cases.iter().map(compile).collect();
    let step = if std::env::var_os("SOLIDKIT_FULL_SWEEP").is_some() {
        1
    } else {
        3
    };
    let jobs: Vec<(usize, usize)> = (0..cases.len())
        .flat_map(|c| (60..=260).step_by(step).map(move |r| (c, r)))
        .collect();
    let failures: Vec<String> = jobs
        .par_iter()
        .flat_map_iter(|&(c, r)| {
            let (program, bbox) = &compiled[c];
            let spec = GridSpec::for_bounds(bbox, r).expect("bounded");
            // Self-intersections at five resolutions (the check dominates the run time).
            check(
                &cases[c],
                program,
                spec,
                &format!("res {r}"),
                (r - 60) % 45 == 0,
            )
        })
        .collect();
    report(failures);
}

/// Grids shifted by fractions of a cell, never aligned with the faces (and grids whose origin
/// sits exactly on a face), at a spread of resolutions.
#[test]
fn one_exact_shell_on_shifted_grids() {
    let cases = cases();
    let compiled: Vec<_> = cases.iter().map(compile).collect();
    let shifts = [
        [0.0, 0.0, 0.0],
        [0.37, 0.11, 0.73],
        [0.5, 0.5, 0.5],
        [0.01, 0.99, 0.5],
    ];
    let jobs: Vec<(usize, usize, usize)> = (0..cases.len())
        .flat_map(|c| {
            (61..=257)
                .step_by(28)
                .flat_map(move |r| (0..shifts.len()).map(move |s| (c, r, s)))
        })
        .collect();
    let failures: Vec<String> = jobs
        .par_iter()
        .flat_map_iter(|&(c, r, s)| {
            let (program, bbox) = &compiled[c];
            let mut spec = GridSpec::for_bounds(bbox, r).expect("bounded");
            // An origin on the lattice of the faces (multiples of ½), then shifted.
            let snapped = (bbox.min - glam::DVec3::splat(2.0 * spec.cell)).floor();
            spec.origin = snapped + glam::DVec3::from_array(shifts[s]) * spec.cell;
            let span = (bbox.max + glam::DVec3::splat(2.0 * spec.cell) - spec.origin) / spec.cell;
            spec.cells = span.ceil().to_array().map(|n| n as usize);
            let label = format!("res {r} shift {:?}", shifts[s]);
            check(&cases[c], program, spec, &label, s == 1)
        })
        .collect();
    report(failures);
}
