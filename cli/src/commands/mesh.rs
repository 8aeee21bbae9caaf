//! `solidkit mesh`: tree → field → marching cubes → report (and mesh file).

use crate::args::{MeshArgs, Method};
use crate::output::{out, outln};
use crate::progress::MeshProgress;
use crate::{input, report};
use anyhow::{Result, anyhow};
use glam::DVec3;
use serde_json::json;
use solidkit_kernel::primitive::MeshSource;
use solidkit_kernel::{Aabb, NodeKind, Primitive, Solid};
use solidkit_meshing::dual_contouring::{DcOptions, mesh_dc};
use solidkit_meshing::io::write_mesh;
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use solidkit_meshing::refine::{RefineOptions, mesh_refined};
use solidkit_meshing::{ReportOptions, TopologyReport};
use std::time::Instant;

/// Meshes the input and prints the report; exit code 0, or 1 when the solid meshes empty though
/// it is inside somewhere.
pub fn run(a: &MeshArgs) -> Result<u8> {
    let (mut solid, mut warnings) =
        input::load_solid_warned(&a.input, a.facets.into(), &a.allow_path)?;
    warnings.extend(open_mesh_warnings(&solid, &a.input));
    for w in &warnings {
        crate::output::errln!("warning: {}", crate::escape::one_line(w));
    }
    let bounds = match a.bounds {
        Some(b) => {
            // Explicit bounds clip the solid, so the mesh is closed even for unbounded solids.
            let clip = Aabb::new(DVec3::new(b[0], b[1], b[2]), DVec3::new(b[3], b[4], b[5]));
            solid = solid.intersection(&Solid::cuboid(clip.size()).translate(clip.center()));
            clip.intersection(&solid.bbox())
        }
        None => solid.bbox(),
    };
    if bounds.is_empty() {
        return Err(anyhow!(
            "{}: the solid is empty (its bounding box is empty)",
            a.input.display()
        ));
    }
    if !bounds.is_finite() {
        return Err(anyhow!(
            "{}: the solid is unbounded; give meshing bounds with --bounds x0,y0,z0,x1,y1,z1",
            a.input.display()
        ));
    }
    if a.tolerance.is_some() && a.method != Method::Dc {
        return Err(anyhow!("--tolerance needs --method dc"));
    }
    let spec = GridSpec::for_bounds(&bounds, a.resolution)
        .map_err(|e| anyhow!("{}: {e}", a.input.display()))?;
    let start = Instant::now();
    let program = solid.compile();
    let progress = MeshProgress::new(!a.no_progress);
    let sparse = SparseOptions {
        progress: Some(progress.callback()),
        ..SparseOptions::default()
    };
    let dc = DcOptions {
        tolerance: a.tolerance,
        sparse: sparse.clone(),
    };
    let refine = RefineOptions {
        max_factor: a.refine,
        budget_samples: a.refine_budget,
    };
    let refined = mesh_refined(spec, &refine, |grid| match a.method {
        Method::Mc => mesh_sparse(&program, grid, &sparse),
        Method::Dc => mesh_dc(&program, grid, &dc),
    })?;
    progress.finish();
    for w in &refined.warnings {
        crate::output::errln!("warning: {}: {w}", a.input.display());
        warnings.push(format!("{}: {w}", a.input.display()));
    }
    let (mesh, stats, fine) = (refined.mesh, refined.stats, refined.spec);
    let time_s = start.elapsed().as_secs_f64();
    let options = ReportOptions {
        self_intersections: !a.no_self_intersections,
    };
    let report_start = Instant::now();
    let r = TopologyReport::with_options(&mesh, &options);
    let report_s = report_start.elapsed().as_secs_f64();
    // The mesher's output is closed and manifold by construction when the field's samples and
    // interval bounds agree; where they do not (parameters near the limits of floating point),
    // the result may be wrong and must not be silent.
    if r.faces > 0 && !(r.closed && r.manifold) {
        let w = format!(
            "{}: the mesh is not a closed manifold ({} boundary edges, {} non-manifold edges, {} non-manifold vertices): the field could not be evaluated faithfully everywhere, so the result may be wrong",
            a.input.display(),
            r.boundary_edges,
            r.non_manifold_edges,
            r.non_manifold_vertices
        );
        crate::output::errln!("warning: {}", crate::escape::one_line(&w));
        warnings.push(w);
    }
    // The text report goes out before the file is written, so a closed or full standard output
    // (exit 2) leaves an existing output file untouched; JSON only follows a written file.
    if a.json {
        if let Some(out) = &a.output {
            write_mesh(out, &mesh)?;
        }
        let extra = [
            ("time_s", json!(time_s)),
            ("report_time_s", json!(report_s)),
            ("resolution", json!(a.resolution)),
            ("cells", json!(fine.cells)),
            ("refinement", json!(refined.factor)),
            ("samples_total", json!(refined.samples_total)),
            ("thin", json!(stats.thin)),
            ("method", json!(a.method.name())),
            ("tolerance", json!(a.tolerance)),
            ("samples_evaluated", json!(stats.samples_evaluated)),
            ("program_length", json!(program.len())),
            ("warnings", json!(warnings)),
        ];
        outln!("{}", report::to_json(&r, &extra)?)?;
    } else {
        out!("{}", r.to_text())?;
        let [x, y, z] = fine.cells;
        outln!(
            "resolution: {} ({x} x {y} x {z} cells of {:.6}{})",
            a.resolution,
            fine.cell,
            if refined.factor > 1 {
                format!(", refined {} times for thin features", refined.factor)
            } else {
                String::new()
            }
        )?;
        outln!("time: {time_s:.3} s")?;
        outln!("report time: {report_s:.3} s")?;
        if let Some(out) = &a.output {
            write_mesh(out, &mesh)?;
            outln!("wrote: {}", out.display())?;
        }
    }
    if let Some(path) = &a.preview {
        write_preview(&mesh, path)?;
    }
    Ok(u8::from(refined.lost_solid))
}

/// `--preview`: the mesh written, rasterised (iso view, 1024 x 1024).
fn write_preview(mesh: &solidkit_meshing::IndexedMesh, path: &std::path::Path) -> Result<()> {
    use solidkit_meshing::render::{Camera, ImageSize, View, png_out, raster, shade};
    let frame = super::render::mesh_box(&mesh.positions);
    let size = ImageSize::new(1024, 1024)?;
    let cam = Camera::framing(View::Iso, &frame, size)?;
    png_out::write_png(path, &raster::render_mesh(mesh, &cam, shade::SOLID))?;
    Ok(())
}

/// One warning per open mesh operand (edges whose two directions are not used equally often):
/// such a solid is where the mesh's winding number is at least ½, which caps each hole.
fn open_mesh_warnings(solid: &Solid, input: &std::path::Path) -> Vec<String> {
    let mut warnings = Vec::new();
    solid.fold(|node, _: &[()]| {
        if let NodeKind::Primitive(Primitive::Mesh(m)) = node.kind()
            && m.open_edges() > 0
        {
            let what = match m.source() {
                MeshSource::File { path } => format!("mesh \"{path}\""),
                other => other.name().to_string(),
            };
            warnings.push(format!(
                "{}: {what} is not closed ({} open edges): its inside is where its winding number is at least 1/2, which caps each hole",
                input.display(),
                m.open_edges()
            ));
        }
    });
    warnings.sort();
    warnings.dedup();
    warnings
}
