//! `solidkit check`: read a mesh (welded within `--weld EPS` if asked), report its topology
//! under a one-line verdict with the coordinates of the first offenders, exit 1 unless it bounds
//! a solid (closed oriented manifold, no self-intersection). `--polygons` adds the counts of the
//! polygon mesh as the file has its faces (V, E, F of quads and pentagons, not of their triangles).

use crate::args::CheckArgs;
use crate::output::{out, outln};
use crate::report;
use anyhow::{Result, anyhow};
use serde_json::json;
use solidkit_meshing::IndexedMesh;
use solidkit_meshing::io::{read_mesh, read_polygon_mesh};
use solidkit_meshing::render::defects::{defect_camera, render_defects};
use solidkit_meshing::render::defects_ply::write_defects_ply;
use solidkit_meshing::render::png_out::write_png;
use solidkit_meshing::repair::weld_mesh;
use solidkit_meshing::topology::{DefectItems, PolygonCounts};
use solidkit_meshing::{ReportOptions, TopologyReport};
use std::path::Path;

/// Prints the report; exit code 0 for a closed oriented 2-manifold without self-intersections,
/// 1 otherwise.
pub fn run(a: &CheckArgs) -> Result<u8> {
    let mut mesh = read_mesh(&a.mesh)?;
    let polygons = if a.polygons {
        let p = read_polygon_mesh(&a.mesh)?;
        Some(PolygonCounts::of(p.positions.len(), &p.faces))
    } else {
        None
    };
    let mut welded = None;
    if let Some(eps) = a.weld {
        let w = weld_mesh(&mesh, eps).map_err(|e| anyhow!("{}: {e}", a.mesh.display()))?;
        welded = Some((eps, w.merged));
        mesh = w.mesh;
    }
    let options = ReportOptions {
        self_intersections: !a.no_self_intersections,
    };
    let r = TopologyReport::with_options(&mesh, &options);
    if a.render.is_some() || a.export_defects.is_some() {
        let items = DefectItems::of(&mesh, &options);
        if let Some(path) = &a.render {
            write_defect_picture(a, &mesh, &items, path)?;
        }
        if let Some(path) = &a.export_defects {
            write_defects_ply(path, &mesh, &items)?;
        }
    }
    if a.json {
        let mut extra = vec![
            ("verdict", json!(r.verdict())),
            (
                "example_positions",
                serde_json::to_value(r.offender_positions(&mesh))?,
            ),
        ];
        if let Some((eps, merged)) = welded {
            extra.push(("weld", json!(eps)));
            extra.push(("vertices_welded", json!(merged)));
        }
        if let Some(p) = &polygons {
            extra.push(("polygons", serde_json::to_value(p)?));
        }
        outln!("{}", report::to_json(&r, &extra)?)?;
    } else {
        outln!("verdict: {}", r.verdict())?;
        if let Some((eps, merged)) = welded {
            outln!("welded: {merged} vertices merged within {eps}")?;
        }
        if let Some(p) = &polygons {
            outln!("{}", p.to_text())?;
        }
        out!("{}", r.to_text())?;
        out!("{}", r.offender_positions_text(&mesh))?;
    }
    Ok(if r.is_valid_solid() { 0 } else { 1 })
}

/// `--render`: the mesh in grey, every defect in its colour, a legend.
fn write_defect_picture(
    a: &CheckArgs,
    mesh: &IndexedMesh,
    items: &DefectItems,
    path: &Path,
) -> Result<()> {
    let frame = super::render::mesh_box(&mesh.positions);
    let cam = defect_camera(a.view, &frame, a.size)
        .map_err(|e| anyhow::anyhow!("{}: {e}", a.mesh.display()))?;
    write_png(path, &render_defects(mesh, items, &cam))?;
    Ok(())
}
