//! Solids that touch only along an edge stay apart, as exact Boolean kernels keep them.
//!
//! Boxes on a lattice often share an edge: the union is two solids meeting in a line, which
//! manifold3d (and any exact kernel) returns as two shells. Where that line falls between the
//! samples, a face of the grid holds one inside corner of each box on a diagonal, and the
//! asymptotic decider alone joins them into one shell at most resolutions. The pinch check
//! (`marching_cubes::pinch`) confirms every face the decider joins with the program's intervals,
//! so the contact stays apart on every grid, by marching cubes (sparse and dense, bit for bit
//! alike) and dual contouring; a neck that really joins the boxes still joins them.

use rayon::prelude::*;
use solidkit_kernel::{Program, json};
use solidkit_meshing::dual_contouring::{DcOptions, mesh_dc};
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_dense, mesh_sparse};
use solidkit_meshing::{IndexedMesh, ReportOptions, TopologyReport};

/// Box `[0,1]² × [−½,1]` and box `[−½,0] × [1,1½] × [−½,1]`: they share the edge x = 0, y = 1;
/// `overlap` moves the second box that far into the first (a neck of that width).
fn tree(overlap: f64) -> String {
    format!(
        r#"{{"format":"solidkit-tree","version":1,"root":{{"type":"union","children":[
        {{"type":"translate","offset":[0.5,0.5,0.25],"child":{{"type":"box","size":[1,1,1.5]}}}},
        {{"type":"translate","offset":[{x},{y},0.25],"child":{{"type":"box","size":[0.5,0.5,1.5]}}}}]}}}}"#,
        x = -0.25 + overlap,
        y = 1.25 - overlap
    )
}

fn compile(overlap: f64) -> (Program, solidkit_kernel::Aabb) {
    let solid = json::from_str(&tree(overlap)).expect("tree parses");
    solid.validate().expect("tree valid");
    (solid.compile(), solid.bbox())
}

/// The problems of one mesh, empty when it has `shells` closed manifold oriented shells of genus
/// 0 and a volume within 2% of `volume`.
fn problems(mesh: &IndexedMesh, shells: usize, volume: f64, full: bool) -> Vec<String> {
    let report = TopologyReport::with_options(
        mesh,
        &ReportOptions {
            self_intersections: full,
        },
    );
    let mut out = Vec::new();
    if !(report.closed && report.manifold && report.oriented) {
        out.push(format!(
            "closed {} manifold {} oriented {}",
            report.closed, report.manifold, report.oriented
        ));
    }
    if report.shells != shells || report.genus != Some(0) {
        out.push(format!(
            "{} shells of genus {:?} (want {shells})",
            report.shells, report.genus
        ));
    }
    if (report.volume - volume).abs() > 0.02 * volume {
        out.push(format!("volume {:.4} (exact {volume:.4})", report.volume));
    }
    if full && report.self_intersections != Some(0) {
        out.push(format!(
            "self-intersections {:?}",
            report.self_intersections
        ));
    }
    out
}

/// Every resolution from 40 to 140 on the CLI's grid: two shells by MC and DC, MC's sparse mesh
/// identical to the dense one.
#[test]
fn boxes_sharing_an_edge_stay_two_shells() {
    let (program, bbox) = compile(0.0);
    let volume = 1.5 + 0.25 * 1.5;
    let failures: Vec<String> = (40..=140usize)
        .into_par_iter()
        .flat_map_iter(|r| {
            let spec = GridSpec::for_bounds(&bbox, r).expect("bounded");
            let (mc, _) =
                mesh_sparse(&program, spec, &SparseOptions::default()).expect("not cancelled");
            let (dc, _) = mesh_dc(&program, spec, &DcOptions::default()).expect("not cancelled");
            let full = r % 20 == 0;
            let mut out: Vec<String> = [("MC", &mc), ("DC", &dc)]
                .into_iter()
                .flat_map(|(m, mesh)| {
                    problems(mesh, 2, volume, full)
                        .into_iter()
                        .map(move |p| format!("{m} res {r}: {p}"))
                })
                .collect();
            if r % 10 == 3 {
                let dense = mesh_dense(&program, spec);
                if dense.positions != mc.positions || dense.triangles != mc.triangles {
                    out.push(format!("res {r}: sparse MC differs from dense MC"));
                }
            }
            out
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Grids whose sample planes hold the contact edge in one axis, the other, both or neither
/// (the zero rule's pinch edges and the pinch check's faces), at a spread of resolutions.
#[test]
fn boxes_sharing_an_edge_stay_apart_on_sample_planes() {
    let (program, bbox) = compile(0.0);
    let volume = 1.5 + 0.25 * 1.5;
    // Fractions of a cell from the contact edge (x = 0, y = 1) to the nearest sample plane.
    let shifts = [[0.0, 0.4], [0.4, 0.0], [0.0, 0.0], [0.3, 0.7], [0.5, 0.5]];
    let jobs: Vec<(usize, usize)> = (41..=131)
        .step_by(6)
        .flat_map(|r| (0..shifts.len()).map(move |s| (r, s)))
        .collect();
    let failures: Vec<String> = jobs
        .par_iter()
        .flat_map_iter(|&(r, s)| {
            let mut spec = GridSpec::for_bounds(&bbox, r).expect("bounded");
            let [fx, fy] = shifts[s];
            // Sample planes through x = fx·cell and y = 1 + fy·cell, two cells of padding.
            let lo = bbox.min - glam::DVec3::splat(2.0 * spec.cell);
            let snap = |v: f64, at: f64| at + ((v - at) / spec.cell).floor() * spec.cell;
            spec.origin = glam::DVec3::new(
                snap(lo.x, fx * spec.cell),
                snap(lo.y, 1.0 + fy * spec.cell),
                lo.z,
            );
            let span = (bbox.max + glam::DVec3::splat(2.0 * spec.cell) - spec.origin) / spec.cell;
            spec.cells = span.ceil().to_array().map(|n| n as usize);
            let (mc, _) =
                mesh_sparse(&program, spec, &SparseOptions::default()).expect("not cancelled");
            let (dc, _) = mesh_dc(&program, spec, &DcOptions::default()).expect("not cancelled");
            [("MC", mc), ("DC", dc)]
                .into_iter()
                .flat_map(|(m, mesh)| {
                    problems(&mesh, 2, volume, false)
                        .into_iter()
                        .map(move |p| format!("{m} res {r} shift {:?}: {p}", shifts[s]))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A real neck (the second box pushed a tenth of a unit into the first, about five cells at
/// these resolutions) is one shell: the check only keeps apart what the field does not join.
#[test]
fn a_real_overlap_stays_one_shell() {
    let (program, bbox) = compile(0.1);
    let volume = 1.5 + 0.25 * 1.5 - 0.01 * 1.5;
    for r in [41, 64, 97] {
        let spec = GridSpec::for_bounds(&bbox, r).expect("bounded");
        let (mc, _) =
            mesh_sparse(&program, spec, &SparseOptions::default()).expect("not cancelled");
        let (dc, _) = mesh_dc(&program, spec, &DcOptions::default()).expect("not cancelled");
        for (m, mesh) in [("MC", &mc), ("DC", &dc)] {
            let p = problems(mesh, 1, volume, r == 64);
            assert!(p.is_empty(), "{m} res {r}: {p:?}");
        }
    }
}
