//! One benchmark case: a model meshed at one resolution `repeat` times (lowering included), each
//! mesh followed by its full report (self-intersections included, as `solidkit mesh` gives it),
//! the peak memory read, then the last mesh checked against what is known of the model.

pub use super::check::Check;
use super::memory::peak_rss_bytes;
pub use super::table::median;
use crate::args::Method;
use anyhow::{Result, anyhow};
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};
use solidkit_kernel::models::Model;
use solidkit_meshing::ReportOptions;
use solidkit_meshing::pipeline::{Domain, MeshOptions, mesh_solid};
use std::time::Instant;

/// Result of one case (also the JSON line a `bench-case` child prints).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CaseResult {
    /// Model name.
    pub model: String,
    /// Cells along the longest side of the domain.
    pub resolution: usize,
    /// Rayon worker threads.
    pub threads: usize,
    /// Polygonization method.
    pub method: Method,
    /// Time of each run (lowering and meshing), seconds.
    pub times_s: Vec<f64>,
    /// Time of each run's full report (`solidkit mesh`'s), seconds.
    #[serde(default)]
    pub report_times_s: Vec<f64>,
    /// How the report knew the self-intersections: `construction` or `tested`.
    #[serde(default)]
    pub self_intersections_method: Option<String>,
    /// Triangles of the mesh.
    pub triangles: usize,
    /// Vertices of the mesh.
    pub vertices: usize,
    /// Grid samples evaluated in one run.
    pub samples_evaluated: u64,
    /// Octree boxes evaluated by interval in one run.
    pub boxes_evaluated: u64,
    /// Instructions of the full program.
    pub program_length: usize,
    /// Peak resident memory of the process that ran the case (child processes only).
    pub peak_memory_bytes: Option<u64>,
    /// The check of the last mesh.
    pub check: Check,
}

impl CaseResult {
    fn sorted(&self) -> Vec<f64> {
        let mut t = self.times_s.clone();
        t.sort_by(f64::total_cmp);
        t
    }

    /// Median time in seconds.
    pub fn median_s(&self) -> f64 {
        median(&self.sorted())
    }

    /// Fastest run.
    pub fn min_s(&self) -> f64 {
        self.sorted().first().copied().unwrap_or(f64::NAN)
    }

    /// Slowest run.
    pub fn max_s(&self) -> f64 {
        self.sorted().last().copied().unwrap_or(f64::NAN)
    }

    /// Median report time in seconds.
    pub fn report_median_s(&self) -> f64 {
        let mut t = self.report_times_s.clone();
        t.sort_by(f64::total_cmp);
        median(&t)
    }

    /// Median whole-run time (meshing and report) in seconds.
    pub fn total_median_s(&self) -> f64 {
        let mut t: Vec<f64> = (self.times_s.iter().zip(&self.report_times_s))
            .map(|(m, r)| m + r)
            .collect();
        t.sort_by(f64::total_cmp);
        median(&t)
    }

    /// Samples evaluated per second (at the median time).
    pub fn points_per_s(&self) -> f64 {
        self.samples_evaluated as f64 / self.median_s()
    }

    /// The result with the derived figures, as a JSON object.
    pub fn to_json(&self) -> Value {
        let mut v = serde_json::to_value(self).unwrap_or(Value::Null);
        if let Value::Object(map) = &mut v {
            map.insert("median_s".into(), json!(self.median_s()));
            map.insert("min_s".into(), json!(self.min_s()));
            map.insert("max_s".into(), json!(self.max_s()));
            map.insert("points_per_s".into(), json!(self.points_per_s()));
            map.insert("report_median_s".into(), json!(self.report_median_s()));
            map.insert("total_median_s".into(), json!(self.total_median_s()));
            map.insert("volume_error".into(), json!(self.check.volume_error()));
            map.insert("check_passed".into(), json!(self.check.passed()));
        }
        v
    }
}

/// Meshes `model` at `resolution` `repeat` times; reads the peak memory when `measure_memory`
/// (only meaningful in a process that runs nothing else).
pub fn run(
    model: &Model,
    resolution: usize,
    repeat: u32,
    method: Method,
    measure_memory: bool,
) -> Result<CaseResult> {
    // Exactly `resolution` cells over the model's domain, no refinement: the benchmark grid.
    let options = MeshOptions::new(resolution)
        .method(method.into())
        .domain(Domain::Covering(model.domain))
        .no_refinement();
    let mut times_s = Vec::new();
    let mut report_times_s = Vec::new();
    let mut last = None;
    for _ in 0..repeat.max(1) {
        // Free the previous mesh first so the peak is that of one run.
        drop(last.take());
        let start = Instant::now();
        let meshed = mesh_solid(&model.solid, &options)
            .map_err(|e| anyhow!("{} at {resolution}: {e}", model.name))?;
        times_s.push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        let report = meshed.report(&ReportOptions::default());
        report_times_s.push(start.elapsed().as_secs_f64());
        last = Some((meshed.mesh, meshed.stats, meshed.program_length, report));
    }
    let peak_memory_bytes = if measure_memory {
        peak_rss_bytes()
    } else {
        None
    };
    let (mesh, stats, program_length, r) = last.expect("at least one run");
    Ok(CaseResult {
        model: model.name.clone(),
        resolution,
        threads: rayon::current_num_threads(),
        method,
        times_s,
        report_times_s,
        self_intersections_method: r.self_intersections_method.map(|m| m.name().to_string()),
        triangles: mesh.triangle_count(),
        vertices: mesh.vertex_count(),
        samples_evaluated: stats.samples_evaluated,
        boxes_evaluated: stats.boxes_evaluated,
        program_length,
        peak_memory_bytes,
        check: Check {
            closed: r.closed,
            manifold: r.manifold,
            shells: r.shells,
            genus: r.genus,
            expected_genus: model.genus,
            volume: r.volume,
            expected_volume: model.volume,
        },
    })
}
