//! `solidkit compare`: two meshes side by side (key measures) and their symmetric Hausdorff
//! distance, absolute and relative to the bounding-box diagonal of the first.

use crate::args::CompareArgs;
use crate::output::{out, outln};
use anyhow::{Context, Result};
use solidkit_meshing::io::read_mesh;
use solidkit_meshing::measure::{Comparison, TriangleTree, compare};
use solidkit_meshing::{IndexedMesh, TopologyReport};
use std::path::Path;

/// Prints the comparison; exit code 0 (bad input is an error, exit 2).
pub fn run(a: &CompareArgs) -> Result<u8> {
    let (mesh_a, tree_a) = load(&a.a)?;
    let (mesh_b, tree_b) = load(&a.b)?;
    let c = compare(&mesh_a, &tree_a, &mesh_b, &tree_b, a.samples);
    if a.json {
        outln!("{}", serde_json::to_string_pretty(&c.to_json())?)?;
    } else {
        out!("{}", text(a, &c))?;
    }
    Ok(0)
}

/// Reads a mesh and builds its distance tree; errors name the file.
fn load(path: &Path) -> Result<(IndexedMesh, TriangleTree)> {
    let mesh = read_mesh(path)?;
    let tree = TriangleTree::new(&mesh).with_context(|| format!("{}", path.display()))?;
    Ok((mesh, tree))
}

/// The text output: a two-column table of measures, then the distances.
fn text(a: &CompareArgs, c: &Comparison) -> String {
    let (ra, rb, h) = (&c.a, &c.b, &c.hausdorff);
    let (diagonal, relative) = (c.diagonal, c.relative);
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
