//! `solidkit mesh`: tree → field → marching cubes → report (and mesh file).

use super::mesh_extras::{single_precision_warning, write_preview};
use super::overlap::{self, Overlapped, report_while_syncing};
use crate::args::{MeshArgs, MeshMethod};
use crate::output::{out, outln};
use crate::progress::MeshProgress;
use crate::{input, report};
use anyhow::{Result, anyhow};
use glam::DVec3;
use serde_json::json;
use solidkit_kernel::Aabb;
use solidkit_meshing::ReportOptions;
use solidkit_meshing::io::{MeshFormat, WriteOptions, stage_colored_mesh_with};
use solidkit_meshing::pipeline::{Domain, MeshOptions, PipelineError, Prepared, warnings};
use solidkit_meshing::refine::RefineOptions;
use std::time::Instant;

/// Meshes the input and prints the report; exit code 0, or 1 when the solid meshes empty though
/// it is inside somewhere.
pub fn run(a: &MeshArgs) -> Result<u8> {
    let input = a.input.display();
    let polyhedral = a.method == Some(MeshMethod::Polyhedral);
    if polyhedral {
        super::mesh_polyhedral::refuse_grid_options(a)?;
    }
    let start = Instant::now();
    let (solid, mut warnings, polyhedron) = input::load_solid_polyhedral(
        &a.input,
        a.facets.into(),
        &a.allow_path,
        &a.define,
        // A part with no polyhedral form: --resolution cells along its own longest side.
        polyhedral.then_some(a.resolution),
    )?;
    match polyhedron {
        Some(Ok(p)) => return super::mesh_polyhedral::finish(a, &solid, &p, warnings, start),
        Some(Err(why)) => {
            let w = format!("{why}: meshed by marching cubes instead");
            warnings.push(w);
        }
        None => {}
    }
    let domain = match a.bounds {
        Some(b) => Domain::Clip(Aabb::new(
            DVec3::new(b[0], b[1], b[2]),
            DVec3::new(b[3], b[4], b[5]),
        )),
        None => Domain::Solid,
    };
    let progress = MeshProgress::new(!a.no_progress);
    let method = match (a.method, a.target_error) {
        (Some(MeshMethod::Dc), _) | (None, Some(_)) => crate::args::Method::Dc,
        _ => crate::args::Method::Mc,
    };
    let (resolution, simplify) = match a.target_error {
        Some(e) => (a.resolution, Some(e)),
        None => (a.resolution, a.simplify),
    };
    let options = MeshOptions::new(resolution)
        .method(method.into())
        .domain(domain)
        .tolerance(a.tolerance)
        .simplify(simplify)
        .refine(RefineOptions {
            max_factor: a.refine,
            budget_samples: a.refine_budget,
        })
        .max_memory(Some(
            a.max_memory.unwrap_or_else(crate::args::default_max_memory),
        ))
        .progress(progress.callback());
    let fail = |e: PipelineError| match e {
        PipelineError::ToleranceNeedsDc | PipelineError::Cancelled(_) => anyhow!(e),
        _ => anyhow!("{input}: {e}"),
    };
    warnings.extend(
        warnings::open_operands(&solid)
            .into_iter()
            .map(|w| format!("{input}: {w}")),
    );
    let start = Instant::now();
    let prepared = Prepared::new(&solid, &options);
    for w in &warnings {
        crate::output::errln!("warning: {}", crate::escape::one_line(w));
    }
    let meshed = prepared.and_then(|p| p.mesh()).map_err(fail)?;
    progress.finish();
    for w in &meshed.warnings {
        crate::output::errln!("warning: {input}: {w}");
        warnings.push(format!("{input}: {w}"));
    }
    let time_s = start.elapsed().as_secs_f64();
    let (mesh, stats, fine) = (&meshed.mesh, &meshed.stats, &meshed.spec);
    // Colours only when the tree has `color` nodes and the output file can hold them (no cost
    // otherwise: STL, OBJ and OFF files and runs without a file write none).
    let carries = a
        .output
        .as_deref()
        .is_some_and(|out| MeshFormat::from_path(out).is_ok_and(MeshFormat::carries_colors));
    let colors = if a.no_colors || !carries {
        None
    } else {
        meshed.face_colors(&solid)
    };
    let precision = single_precision_warning(a, mesh);
    let staged = a
        .output
        .as_deref()
        .map(|out| stage_colored_mesh_with(out, mesh, colors.as_ref(), &WriteOptions::default()));
    let Overlapped {
        report: r,
        report_s,
        synced,
    } = report_while_syncing(
        || {
            meshed.report(&ReportOptions {
                self_intersections: !a.no_self_intersections,
            })
        },
        staged.as_ref().and_then(|s| s.as_ref().ok()),
    );
    let found = warnings::empty(&r).or_else(|| warnings::not_closed_manifold(&r));
    for w in found
        .into_iter()
        .chain(warnings::fragments(&r, meshed.spec.cell))
    {
        let w = format!("{input}: {w}");
        crate::output::errln!("warning: {}", crate::escape::one_line(&w));
        warnings.push(w);
    }
    if let Some(w) = precision {
        crate::output::errln!("warning: {}", crate::escape::one_line(&w));
        warnings.push(w);
    }
    // The file is complete under a temporary name; it takes its place once the report is out.
    let write = |staged| -> Result<()> { Ok(overlap::commit(staged, synced)?) };
    // The text report goes out before the file is renamed into place, so a closed or full
    // standard output (exit 2) leaves an existing output file untouched; JSON only follows a
    // written file.
    if a.json {
        if let Some(staged) = staged {
            write(staged)?;
        }
        let extra = [
            ("time_s", json!(time_s)),
            ("report_time_s", json!(report_s)),
            ("resolution", json!(resolution)),
            ("cells", json!(fine.cells)),
            ("cell", json!(fine.cell)),
            ("refinement", json!(meshed.factor)),
            ("samples_total", json!(meshed.samples_total)),
            ("thin", json!(stats.thin)),
            ("method", json!(method.name())),
            ("tolerance", json!(a.tolerance)),
            ("simplify", json!(simplify)),
            ("target_error", json!(a.target_error)),
            (
                "simplify_collapses",
                json!(meshed.simplified.map(|s| s.collapses)),
            ),
            ("samples_evaluated", json!(stats.samples_evaluated)),
            ("program_length", json!(meshed.program_length)),
            ("warnings", json!(warnings)),
            ("colors", json!(colors.as_ref().map_or(0, |c| c.used()))),
        ];
        outln!("{}", report::to_json(&r, &extra)?)?;
    } else {
        out!("{}", r.to_text())?;
        let [x, y, z] = fine.cells;
        outln!(
            "resolution: {} ({x} x {y} x {z} cells of {:.6}{})",
            resolution,
            fine.cell,
            if meshed.factor > 1 {
                format!(", refined {} times for thin features", meshed.factor)
            } else {
                String::new()
            }
        )?;
        outln!("time: {time_s:.3} s")?;
        outln!("report time: {report_s:.3} s")?;
        if let (Some(out), Some(staged)) = (&a.output, staged) {
            write(staged)?;
            match &colors {
                Some(c) => outln!("wrote: {} ({} colours)", out.display(), c.used())?,
                None => outln!("wrote: {}", out.display())?,
            }
        }
    }
    if let Some(path) = &a.preview {
        write_preview(mesh, path)?;
    }
    Ok(u8::from(meshed.lost_solid))
}
