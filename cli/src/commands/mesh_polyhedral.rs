//! `solidkit mesh --method polyhedral`: the model's polyhedron, built by mesh Booleans at load
//! time, reported and written like a grid mesh (no resolution, no refinement).

use crate::args::MeshArgs;
use crate::output::{out, outln};
use crate::report;
use anyhow::{Result, bail};
use serde_json::json;
use solidkit_kernel::Solid;
use solidkit_meshing::ReportOptions;
use solidkit_meshing::io::{MeshFormat, WriteOptions, write_colored_mesh_with};
use solidkit_meshing::pipeline::warnings;
use solidkit_meshing::polyhedral::Polyhedral;
use std::time::Instant;

/// Grid options mean nothing without a grid: refused (exit 2) rather than ignored.
pub fn refuse_grid_options(a: &MeshArgs) -> Result<()> {
    let given = [
        ("--tolerance", a.tolerance.is_some()),
        ("--simplify", a.simplify.is_some()),
        ("--target-error", a.target_error.is_some()),
        ("--bounds", a.bounds.is_some()),
    ];
    if let Some((name, _)) = given.iter().find(|(_, on)| *on) {
        bail!("{name} needs a grid: it does not go with --method polyhedral");
    }
    Ok(())
}

/// Reports and writes the polyhedron; `start` is when loading began (the Booleans run there).
pub fn finish(
    a: &MeshArgs,
    solid: &Solid,
    polyhedron: &Polyhedral,
    mut found: Vec<String>,
    start: Instant,
) -> Result<u8> {
    let input = a.input.display();
    let mesh = polyhedron.to_mesh();
    let time_s = start.elapsed().as_secs_f64();
    let report_start = Instant::now();
    let r = solidkit_meshing::TopologyReport::with_options(
        &mesh,
        &ReportOptions {
            self_intersections: !a.no_self_intersections,
        },
    );
    let report_s = report_start.elapsed().as_secs_f64();
    let carries = a
        .output
        .as_deref()
        .is_some_and(|out| MeshFormat::from_path(out).is_ok_and(MeshFormat::carries_colors));
    // The grid's empty-mesh warning speaks of sampling; an exact Boolean result is simply empty.
    let empty = (r.faces == 0).then(|| {
        "the mesh is empty: the polyhedral Booleans leave nothing (every part is cut away, or none is 3D)"
            .to_string()
    });
    let more = empty
        .or_else(|| warnings::not_closed_manifold(&r))
        .map(|w| format!("{input}: {w}"));
    found.extend(more);
    found.extend(super::mesh_extras::single_precision_warning(a, &mesh));
    // Each triangle takes the colour of the part its face comes from, traced through the tree's
    // Booleans as on the grid path; the faces lie on the parts' own faces, so the parts' boxes
    // need only a hair of margin.
    let colors = if carries && !a.no_colors {
        let [lo, hi] = r.bbox.map(glam::DVec3::from_array);
        let diagonal = if r.faces > 0 { (hi - lo).length() } else { 0.0 };
        solidkit_meshing::colors::assign(solid, &mesh, 1e-6 * diagonal + 1e-12)
    } else {
        None
    };
    for w in &found {
        crate::output::errln!("warning: {}", crate::escape::one_line(w));
    }
    let write = |out: &std::path::Path| {
        write_colored_mesh_with(out, &mesh, colors.as_ref(), &WriteOptions::default())
    };
    if a.json {
        if let Some(out) = &a.output {
            write(out)?;
        }
        let extra = [
            ("time_s", json!(time_s)),
            ("report_time_s", json!(report_s)),
            ("method", json!("polyhedral")),
            ("warnings", json!(found)),
            ("colors", json!(colors.as_ref().map_or(0, |c| c.used()))),
        ];
        outln!("{}", report::to_json(&r, &extra)?)?;
    } else {
        out!("{}", r.to_text())?;
        outln!("method: polyhedral (mesh Booleans, no grid)")?;
        outln!("time: {time_s:.3} s")?;
        outln!("report time: {report_s:.3} s")?;
        if let Some(out) = &a.output {
            write(out)?;
            outln!("wrote: {}", out.display())?;
        }
    }
    if let Some(path) = &a.preview {
        super::mesh_extras::write_preview(&mesh, path)?;
    }
    Ok(0)
}
