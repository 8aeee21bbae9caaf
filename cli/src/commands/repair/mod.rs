//! `solidkit repair`: read a mesh, repair it (minimal, rebuild or auto), write it atomically and
//! print the reports before and after with the changes per kind.

mod report;

use crate::args::{MAX_RESOLUTION, RepairArgs, RepairMode};
use crate::output::{out, outln};
use anyhow::{Result, anyhow};
use glam::DVec3;
use report::{changes_text, mode_name, rebuild_json};
use serde_json::json;
use solidkit_meshing::io::{read_mesh, write_mesh};
use solidkit_meshing::repair::{MinimalOptions, RebuildOptions, rebuild, repair_minimal};
use solidkit_meshing::{IndexedMesh, ReportOptions, TopologyReport};

/// Default rebuild resolution (cells along the longest side).
const DEFAULT_RESOLUTION: usize = 128;
/// Default weld tolerance relative to the bounding-box diagonal.
const DEFAULT_WELD: f64 = 1e-6;
/// Samples per mesh for the Hausdorff distance of a rebuild.
const HAUSDORFF_SAMPLES: usize = 50_000;

/// Repairs, writes and reports; exit 0 when the result is a closed oriented manifold without
/// self-intersections, 1 otherwise (bad input: an error, exit 2).
pub fn run(a: &RepairArgs) -> Result<u8> {
    let name = a.mesh.display().to_string();
    let input = read_mesh(&a.mesh)?;
    if input.triangles.is_empty() {
        return Err(anyhow!("{name}: the mesh has no faces"));
    }
    // The input's self-intersections are not tested (as costly as the rest of the repair on a
    // large mesh, and minimal repair keeps them: the result's report has them).
    let skip = ReportOptions {
        self_intersections: false,
    };
    let after_options = if a.no_self_intersections {
        skip
    } else {
        ReportOptions::default()
    };
    let diagonal = bbox_diagonal(&input);
    let weld = a.weld.unwrap_or(DEFAULT_WELD * diagonal);
    // The input's report beside the repair (both parallel, with serial stretches that overlap).
    let (before, minimal) = rayon::join(
        || TopologyReport::with_options(&input, &skip),
        || repair_minimal(&input, &MinimalOptions { weld }),
    );
    // A mesh without any enclosing shell is bad input in every mode.
    let minimal = minimal.map_err(|e| anyhow!("{name}: {e}"))?;
    // In minimal mode the result is known: written beside its report (the outcome is handled
    // where the write would be).
    let (minimal_report, written) = if a.mode == RepairMode::Minimal {
        let (report, written) = rayon::join(
            || TopologyReport::with_options(&minimal.mesh, &after_options),
            || write_mesh(&a.output, &minimal.mesh),
        );
        (report, Some(written))
    } else {
        (
            TopologyReport::with_options(&minimal.mesh, &after_options),
            None,
        )
    };
    let mut written = written;
    let mut write = |mesh: &IndexedMesh| match written.take() {
        Some(done) => done,
        None => write_mesh(&a.output, mesh),
    };
    let need_rebuild = match a.mode {
        RepairMode::Minimal => false,
        RepairMode::Rebuild => true,
        RepairMode::Auto => !minimal_report.is_valid_solid(),
    };
    let rebuilt = if need_rebuild {
        // The winding-number solid of the cleaned mesh, so flipped shells and holes do not turn
        // into missing volume; the Hausdorff distance is measured to the input.
        let (resolution, tolerance) = grid(a, &input);
        let opts = RebuildOptions {
            resolution,
            tolerance,
            samples: HAUSDORFF_SAMPLES,
        };
        Some(rebuild(&minimal.mesh, &input, &opts).map_err(|e| anyhow!("{name}: {e}"))?)
    } else {
        None
    };
    let (result, after) = match &rebuilt {
        Some(r) => (
            &r.mesh,
            TopologyReport::with_options(&r.mesh, &after_options),
        ),
        None => (&minimal.mesh, minimal_report),
    };
    let counts = minimal.counts;
    let rebuild_json = rebuilt.as_ref().map(|r| rebuild_json(r, diagonal));
    if a.json {
        write(result)?;
        let v = json!({
            "file": name,
            "mode": mode_name(a.mode),
            "weld": weld,
            "before": serde_json::to_value(&before)?,
            "changes": serde_json::to_value(counts)?,
            "rebuilt": rebuilt.is_some(),
            "rebuild": rebuild_json,
            "after": serde_json::to_value(&after)?,
            "valid": after.is_valid_solid(),
        });
        outln!("{}", serde_json::to_string_pretty(&v)?)?;
    } else {
        outln!("== before: {name}")?;
        outln!("verdict: {}", before.verdict())?;
        out!("{}", before.to_text())?;
        out!("{}", changes_text(&counts, weld))?;
        if let Some(r) = &rebuilt {
            outln!(
                "== rebuild: dual contouring, {} x {} x {} cells of {:.6}",
                r.cells[0],
                r.cells[1],
                r.cells[2],
                r.cell
            )?;
            let h = r.hausdorff.symmetric;
            outln!(
                "hausdorff to input: {h} ({:.4}% of the bbox diagonal {diagonal})",
                100.0 * h / diagonal.max(f64::MIN_POSITIVE)
            )?;
        }
        outln!("== after ({})", mode_name(a.mode))?;
        outln!("verdict: {}", after.verdict())?;
        out!("{}", after.to_text())?;
        write(result)?;
        outln!("wrote: {}", a.output.display())?;
    }
    Ok(if after.is_valid_solid() { 0 } else { 1 })
}

/// The rebuild grid: `--resolution`, or cells of `--tolerance` (which also sets dual
/// contouring's collapse tolerance).
fn grid(a: &RepairArgs, input: &IndexedMesh) -> (usize, Option<f64>) {
    match a.tolerance {
        Some(t) => {
            let [lo, hi] = bbox(input);
            let longest = (hi - lo).max_element();
            let n = (longest / t).ceil().clamp(8.0, MAX_RESOLUTION as f64) as usize;
            (n, Some(t))
        }
        None => (a.resolution.unwrap_or(DEFAULT_RESOLUTION), None),
    }
}

fn bbox(mesh: &IndexedMesh) -> [DVec3; 2] {
    mesh.positions
        .iter()
        .fold([DVec3::INFINITY, DVec3::NEG_INFINITY], |[lo, hi], &p| {
            [lo.min(p), hi.max(p)]
        })
}

fn bbox_diagonal(mesh: &IndexedMesh) -> f64 {
    let [lo, hi] = bbox(mesh);
    if mesh.positions.is_empty() {
        0.0
    } else {
        lo.distance(hi)
    }
}
