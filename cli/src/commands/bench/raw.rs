//! Raw single-thread evaluation rates, no pruning: `Program::eval_many` over a lattice of points
//! (points/s) and `Program::interval_with` over octree-like boxes (boxes/s). Also the full
//! `many-8456` program, whose rate tells what dense evaluation of every sample would cost, and the
//! rate of the pruned programs the sparse mesher actually evaluates for that model (samples per
//! second of evaluation inside the leaf bricks, one thread).

use super::case::median;
use anyhow::{Result, bail};
use serde::Serialize;
use solidkit_kernel::models::Model;
use solidkit_kernel::models::workload::{lattice_points, octree_boxes};
use solidkit_kernel::program::{BatchScratch, IntervalScratch};
use solidkit_meshing::pipeline::{Domain, MeshOptions, mesh_solid};
use std::hint::black_box;
use std::time::Instant;

/// How much work each raw measurement does.
#[derive(Debug, Clone, Copy)]
pub struct RawSizes {
    /// Points for `sphere` and `gyroid-sphere`.
    pub points: usize,
    /// Points for `many-8456` (its full program is thousands of times longer).
    pub many_points: usize,
    /// Boxes for the interval rate.
    pub boxes: usize,
    /// Resolution at which `many-8456` is meshed for the pruned evaluation rate.
    pub many_resolution: usize,
}

impl Default for RawSizes {
    fn default() -> Self {
        Self {
            points: 1 << 22,
            many_points: 1 << 14,
            boxes: 1 << 20,
            many_resolution: 256,
        }
    }
}

/// One raw measurement.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RawRow {
    /// `eval` or `interval`.
    pub kind: &'static str,
    /// Model name.
    pub model: String,
    /// Instructions of the program.
    pub program_length: usize,
    /// Points or boxes per run.
    pub count: usize,
    /// `points` or `boxes`.
    pub unit: &'static str,
    /// Time of each run, seconds.
    pub times_s: Vec<f64>,
    /// `count` / median time.
    pub rate_per_s: f64,
}

fn timed(repeat: u32, mut f: impl FnMut()) -> Vec<f64> {
    (0..repeat.max(1))
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .collect()
}

fn row(kind: &'static str, model: &Model, len: usize, count: usize, times: Vec<f64>) -> RawRow {
    let mut sorted = times.clone();
    sorted.sort_by(f64::total_cmp);
    RawRow {
        kind,
        model: model.name.clone(),
        program_length: len,
        count,
        unit: if kind == "eval" { "points" } else { "boxes" },
        rate_per_s: count as f64 / median(&sorted),
        times_s: times,
    }
}

/// The models the raw rates are measured on.
pub const RAW_MODELS: [&str; 3] = ["sphere", "gyroid-sphere", "many-8456"];

/// Measures the raw rates on this thread, `repeat` runs each, of the models in `only` (all of
/// [`RAW_MODELS`] when empty; the interval rate is the sphere's, the pruned rate many-8456's).
pub fn run(sizes: &RawSizes, repeat: u32, only: &[String]) -> Result<Vec<RawRow>> {
    if let Some(bad) = only.iter().find(|m| !RAW_MODELS.contains(&m.trim())) {
        bail!(
            "--raw measures the models {}, not '{bad}'",
            RAW_MODELS.join(", ")
        );
    }
    let wanted = |name: &str| only.is_empty() || only.iter().any(|m| m.trim() == name);
    let mut rows = Vec::new();
    for (name, count) in [
        ("sphere", sizes.points),
        ("gyroid-sphere", sizes.points),
        ("many-8456", sizes.many_points),
    ] {
        if !wanted(name) {
            continue;
        }
        let model = Model::by_name(name)?;
        let program = model.solid.compile();
        let pts = lattice_points(&model.domain, count);
        let mut out = vec![0.0f32; count];
        let mut scratch = BatchScratch::new(&program);
        let times = timed(repeat, || {
            program.eval_many(&pts.x, &pts.y, &pts.z, &mut out, &mut scratch);
            black_box(&mut out);
        });
        rows.push(row("eval", &model, program.len(), count, times));
    }
    if wanted("sphere") {
        let model = Model::by_name("sphere")?;
        let program = model.solid.compile();
        let boxes = octree_boxes(&model.domain, sizes.boxes, 1);
        let mut scratch = IntervalScratch::default();
        let times = timed(repeat, || {
            for b in &boxes {
                black_box(program.interval_with(black_box(b), &mut scratch));
            }
        });
        rows.push(row("interval", &model, program.len(), sizes.boxes, times));
    }
    if wanted("many-8456") {
        rows.push(pruned_row(sizes.many_resolution)?);
    }
    Ok(rows)
}

/// Meshes `many-8456` on one thread and reports the evaluation rate of the pruned brick programs.
fn pruned_row(resolution: usize) -> Result<RawRow> {
    let model = Model::by_name("many-8456")?;
    let start = Instant::now();
    let options = MeshOptions::new(resolution)
        .domain(Domain::Covering(model.domain))
        .no_refinement()
        .clock(std::sync::Arc::new(move || start.elapsed().as_secs_f64()));
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let stats = pool.install(|| mesh_solid(&model.solid, &options))?.stats;
    let mean = stats.leaf_instructions / stats.surface_bricks.max(1) as u64;
    Ok(RawRow {
        kind: "pruned-eval",
        model: model.name.clone(),
        program_length: mean as usize,
        count: stats.samples_evaluated as usize,
        unit: "points",
        rate_per_s: stats.samples_evaluated as f64 / stats.evaluation_cpu_s.max(1e-9),
        times_s: vec![stats.evaluation_cpu_s],
    })
}
