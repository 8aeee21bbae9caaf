//! `solidkit compare`: two meshes side by side (key measures) and their symmetric Hausdorff
//! distance, absolute and relative to the bounding-box diagonal of the first.

use crate::args::CompareArgs;
use crate::output::{out, outln};
use anyhow::{Context, Result};
use glam::DVec3;
use serde_json::{Value, json};
use solidkit_meshing::io::read_mesh;
use solidkit_meshing::measure::{Hausdorff, TriangleTree, hausdorff_with};
use solidkit_meshing::{IndexedMesh, ReportOptions, TopologyReport};
use std::path::Path;

/// Prints the comparison; exit code 0 (bad input is an error, exit 2).
pub fn run(a: &CompareArgs) -> Result<u8> {
    let (mesh_a, tree_a) = load(&a.a)?;
    let (mesh_b, tree_b) = load(&a.b)?;
    // The key measures only: self-intersections (`check`) would double the time.
    let options = ReportOptions {
        self_intersections: false,
    };
    let (report_a, report_b) = rayon::join(
        || TopologyReport::with_options(&mesh_a, &options),
        || TopologyReport::with_options(&mesh_b, &options),
    );
    let h = hausdorff_with(&mesh_a, &tree_a, &mesh_b, &tree_b, a.samples);
    let [lo, hi] = report_a.bbox;
    let diagonal = DVec3::from(hi).distance(DVec3::from(lo));
    let relative = (diagonal > 0.0).then(|| h.symmetric / diagonal);
    if a.json {
        let v = json!({
            "a": serde_json::to_value(&report_a)?,
            "b": serde_json::to_value(&report_b)?,
            "hausdorff": hausdorff_json(&h, diagonal, relative, a.samples),
        });
        outln!("{}", serde_json::to_string_pretty(&v)?)?;
    } else {
        out!(
            "{}",
            text(a, [&report_a, &report_b], &h, diagonal, relative)
        )?;
    }
    Ok(0)
}

/// Reads a mesh and builds its distance tree; errors name the file.
fn load(path: &Path) -> Result<(IndexedMesh, TriangleTree)> {
    let mesh = read_mesh(path)?;
    let tree = TriangleTree::new(&mesh).with_context(|| format!("{}", path.display()))?;
    Ok((mesh, tree))
}

/// The `hausdorff` object of the JSON output (keys documented in the README).
fn hausdorff_json(h: &Hausdorff, diagonal: f64, relative: Option<f64>, samples: usize) -> Value {
    json!({
        "symmetric": h.symmetric,
        "a_to_b": h.a_to_b.max,
        "b_to_a": h.b_to_a.max,
        "mean_a_to_b": h.a_to_b.mean,
        "mean_b_to_a": h.b_to_a.mean,
        "diagonal": diagonal,
        "relative": relative,
        "samples": samples,
        "points_a": h.a_to_b.count,
        "points_b": h.b_to_a.count,
    })
}

/// The text output: a two-column table of measures, then the distances.
fn text(
    a: &CompareArgs,
    [ra, rb]: [&TopologyReport; 2],
    h: &Hausdorff,
    diagonal: f64,
    relative: Option<f64>,
) -> String {
    let genus = |r: &TopologyReport| r.genus.map_or("-".to_string(), |g| g.to_string());
    let yes_no = |b: bool| if b { "yes" } else { "no" }.to_string();
    let rows: [(&str, String, String); 9] = [
        ("file", a.a.display().to_string(), a.b.display().to_string()),
        ("vertices", ra.vertices.to_string(), rb.vertices.to_string()),
        ("faces", ra.faces.to_string(), rb.faces.to_string()),
        ("volume", ra.volume.to_string(), rb.volume.to_string()),
        ("area", ra.area.to_string(), rb.area.to_string()),
        ("shells", ra.shells.to_string(), rb.shells.to_string()),
        ("genus", genus(ra), genus(rb)),
        ("closed", yes_no(ra.closed), yes_no(rb.closed)),
        ("manifold", yes_no(ra.manifold), yes_no(rb.manifold)),
    ];
    let mut out = String::new();
    out.push_str(&format!("{:<20}{:<28}{}\n", "", "A", "B"));
    for (key, x, y) in rows {
        out.push_str(&format!("{:<20}{x:<28}{y}\n", format!("{key}:")));
    }
    let percent = relative.map_or("-".to_string(), |r| format!("{:.4}%", r * 100.0));
    out.push_str(&format!(
        "{:<20}{} ({percent} of the bbox diagonal of A, {diagonal})\n",
        "hausdorff:", h.symmetric
    ));
    for (key, side) in [("A to B:", &h.a_to_b), ("B to A:", &h.b_to_a)] {
        out.push_str(&format!(
            "{key:<20}max {} mean {} ({} points)\n",
            side.max, side.mean, side.count
        ));
    }
    out
}
