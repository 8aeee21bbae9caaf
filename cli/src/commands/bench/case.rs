//! One benchmark case: a model meshed at one resolution `repeat` times (lowering included), the
//! peak memory read, then the last mesh checked against what is known of the model.

use super::memory::peak_rss_bytes;
use super::table::{Table, si};
use crate::args::Method;
use anyhow::{Result, anyhow};
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};
use solidkit_kernel::models::Model;
use solidkit_meshing::TopologyReport;
use solidkit_meshing::pipeline::{Domain, MeshOptions, mesh_solid};
use std::time::Instant;

/// The check of a case's mesh.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Check {
    /// No boundary edges.
    pub closed: bool,
    /// No non-manifold edges or vertices.
    pub manifold: bool,
    /// Connected components.
    pub shells: usize,
    /// Genus of the mesh (`None` unless every shell is a closed oriented manifold).
    pub genus: Option<i64>,
    /// The model's exact genus, where known.
    pub expected_genus: Option<i64>,
    /// Volume of the mesh.
    pub volume: f64,
    /// The model's exact volume, where known.
    pub expected_volume: Option<f64>,
}

impl Check {
    /// Relative volume error, where the exact volume is known.
    pub fn volume_error(&self) -> Option<f64> {
        self.expected_volume.map(|v| (self.volume - v) / v)
    }

    /// Closed, manifold, and the genus is right where it is known.
    pub fn passed(&self) -> bool {
        self.closed && self.manifold && self.expected_genus.is_none_or(|g| self.genus == Some(g))
    }
}

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
            map.insert("volume_error".into(), json!(self.check.volume_error()));
            map.insert("check_passed".into(), json!(self.check.passed()));
        }
        v
    }
}

/// Median of sorted values (mean of the middle two for an even count).
pub fn median(sorted: &[f64]) -> f64 {
    let n = sorted.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
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
    let mut last = None;
    for _ in 0..repeat.max(1) {
        // Free the previous mesh first so the peak is that of one run.
        drop(last.take());
        let start = Instant::now();
        let meshed = mesh_solid(&model.solid, &options)
            .map_err(|e| anyhow!("{} at {resolution}: {e}", model.name))?;
        times_s.push(start.elapsed().as_secs_f64());
        last = Some((meshed.mesh, meshed.stats, meshed.program_length));
    }
    let peak_memory_bytes = if measure_memory {
        peak_rss_bytes()
    } else {
        None
    };
    let (mesh, stats, program_length) = last.expect("at least one run");
    let r = TopologyReport::of(&mesh);
    Ok(CaseResult {
        model: model.name.clone(),
        resolution,
        threads: rayon::current_num_threads(),
        method,
        times_s,
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

/// Column titles of the case table.
pub const COLUMNS: [&str; 15] = [
    "model",
    "method",
    "res",
    "threads",
    "median s",
    "min s",
    "max s",
    "triangles",
    "points/s",
    "peak MiB",
    "closed",
    "manifold",
    "shells",
    "genus",
    "vol err",
];

fn yes(b: bool) -> String {
    if b { "yes" } else { "NO" }.to_string()
}

/// The results as a table, one row per case.
pub fn table(results: &[CaseResult]) -> Table {
    let mut t = Table::new(&COLUMNS);
    for r in results {
        let c = &r.check;
        let genus = match (c.genus, c.expected_genus) {
            (Some(g), Some(want)) if g == want => format!("{g}"),
            (got, Some(want)) => format!("{} (want {want})", opt(got)),
            (got, None) => opt(got),
        };
        t.rows.push(vec![
            r.model.clone(),
            r.method.name().to_string(),
            r.resolution.to_string(),
            r.threads.to_string(),
            format!("{:.3}", r.median_s()),
            format!("{:.3}", r.min_s()),
            format!("{:.3}", r.max_s()),
            r.triangles.to_string(),
            si(r.points_per_s()),
            r.peak_memory_bytes
                .map_or("-".into(), |b| format!("{:.0}", b as f64 / 1048576.0)),
            yes(c.closed),
            yes(c.manifold),
            c.shells.to_string(),
            genus,
            c.volume_error()
                .map_or("-".into(), |e| format!("{:+.3}%", 100.0 * e)),
        ]);
    }
    t
}

fn opt(g: Option<i64>) -> String {
    g.map_or("-".into(), |g| g.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tiny_case_fills_one_row_of_every_column() {
        let model = Model::by_name("sphere").expect("model");
        let r = run(&model, 16, 2, Method::Mc, false).expect("runs");
        assert_eq!(r.times_s.len(), 2);
        assert!(r.triangles > 0 && r.samples_evaluated > 0);
        assert!(r.check.passed(), "{:?}", r.check);
        assert!(r.check.volume_error().is_some());
        let text = table(std::slice::from_ref(&r)).render();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2);
        for (line, first) in lines.iter().zip(["model", "sphere"]) {
            let cells: Vec<&str> = line.split("  ").filter(|c| !c.trim().is_empty()).collect();
            assert_eq!(cells.len(), COLUMNS.len(), "{line}");
            assert_eq!(cells[0].trim(), first);
        }
        // The child-process protocol: the JSON line reads back to the same result.
        let line = serde_json::to_string(&r).expect("json");
        assert_eq!(serde_json::from_str::<CaseResult>(&line).expect("parse"), r);
        let v = r.to_json();
        for key in [
            "median_s",
            "points_per_s",
            "check_passed",
            "triangles",
            "check",
        ] {
            assert!(v.get(key).is_some(), "{key}");
        }
    }

    #[test]
    fn dual_contouring_cases_run_and_pass_their_check() {
        let model = Model::by_name("sphere").expect("model");
        let r = run(&model, 16, 1, Method::Dc, false).expect("runs");
        assert_eq!(r.method, Method::Dc);
        assert!(r.check.passed(), "{:?}", r.check);
        assert!(r.check.volume_error().is_some_and(|e| e.abs() < 0.02));
        let line = serde_json::to_string(&r).expect("json");
        assert!(line.contains("\"method\":\"dc\""), "{line}");
    }

    #[test]
    fn a_wrong_genus_fails_the_check() {
        let c = Check {
            closed: true,
            manifold: true,
            shells: 1,
            genus: Some(4),
            expected_genus: Some(5),
            volume: 1.0,
            expected_volume: None,
        };
        assert!(!c.passed());
        assert!(c.volume_error().is_none());
    }

    #[test]
    fn medians() {
        assert_eq!(median(&[1.0, 2.0, 9.0]), 2.0);
        assert_eq!(median(&[1.0, 2.0, 4.0, 9.0]), 3.0);
        assert!(median(&[]).is_nan());
    }
}
