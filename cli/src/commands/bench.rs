//! `solidkit bench`: meshes the benchmark models (`solidkit_kernel::models`) at their benchmark
//! resolutions and prints one row per case: median / min / max time, triangles, points
//! evaluated per second, peak memory and the check of the mesh (closed, manifold, genus and
//! volume error where the model's are known), so a fast but wrong mesh shows. `--raw` measures
//! the single-thread evaluation rates instead.
//!
//! Each case runs in a child process (`solidkit bench-case`, hidden) so that its peak memory
//! (`VmHWM`) is its own; `--in-process` skips that. Times cover lowering the tree and sparse
//! meshing over `GridSpec::covering(domain, n)` (exactly `n` cells along the longest side, no
//! padding); the report (`solidkit mesh`'s, self-intersections included) is timed on its own
//! beside it (`report s`, and `total s` for the whole run), and says how it knew the
//! self-intersections (`construction` or `tested`). `--scaling 1,2` runs every case with each
//! thread count and adds the speed-up over the first count.

mod case;
mod case_table;
#[cfg(test)]
mod case_tests;
mod check;
mod memory;
mod raw;
mod raw_table;
#[cfg(test)]
mod raw_tests;
mod table;

use crate::args::{BenchArgs, BenchCaseArgs, Method};
use crate::output::{out, outln};
use anyhow::{Context, Result, bail};
use case::CaseResult;
use serde_json::json;
use solidkit_kernel::models::{BENCH_MODELS, Model};
use std::process::Command;

/// Runs the benchmark; exit code 0, or 1 when a mesh failed its check.
pub fn run(a: &BenchArgs) -> Result<u8> {
    if a.raw {
        let rows = raw::run(&raw::RawSizes::default(), a.repeat, &a.model)?;
        if a.json {
            outln!("{}", serde_json::to_string_pretty(&json!({ "raw": rows }))?)?;
        } else {
            out!("{}", raw_table::table(&rows).render())?;
            if let Some(r) = rows.iter().find(|r| r.model == "many-8456") {
                let samples = 257f64.powi(3);
                outln!(
                    "(the full many-8456 program at all 257^3 samples of a 256^3 grid: {:.0} s on \
                     one thread; compare `bench --model many-8456`)",
                    samples / r.rate_per_s
                )?;
            }
        }
        return Ok(0);
    }
    let names: Vec<String> = if a.model.is_empty() {
        BENCH_MODELS.iter().map(|s| s.to_string()).collect()
    } else {
        a.model.clone()
    };
    // Resolve every name first, so a typo fails before any long run.
    let models = names
        .iter()
        .map(|n| Model::by_name(n.trim()))
        .collect::<Result<Vec<_>, _>>()?;
    let counts = if a.scaling.is_empty() {
        vec![rayon::current_num_threads()]
    } else {
        a.scaling.clone()
    };
    let mut results = Vec::new();
    for model in &models {
        let resolutions = if a.resolution.is_empty() {
            &model.default_resolutions
        } else {
            &a.resolution
        };
        for &n in resolutions {
            for &method in &a.method {
                for &threads in &counts {
                    crate::output::errln!(
                        "bench: {} at {n}^3 ({}), {threads} threads, {} runs",
                        model.name,
                        method.name(),
                        a.repeat
                    );
                    let r = if a.in_process {
                        rayon::ThreadPoolBuilder::new()
                            .num_threads(threads)
                            .build()?
                            .install(|| case::run(model, n, a.repeat, method, false))?
                    } else {
                        run_child(&model.name, n, a.repeat, method, threads)?
                    };
                    results.push(r);
                }
            }
        }
    }
    if a.json {
        let cases: Vec<_> = results.iter().map(CaseResult::to_json).collect();
        outln!(
            "{}",
            serde_json::to_string_pretty(&json!({ "cases": cases }))?
        )?;
    } else {
        out!(
            "{}",
            case_table::table(&results, !a.scaling.is_empty()).render()
        )?;
    }
    Ok(if results.iter().all(|r| r.check.passed()) {
        0
    } else {
        1
    })
}

/// The hidden `bench-case`: runs one case and prints its result as one JSON line.
pub fn run_case(a: &BenchCaseArgs) -> Result<u8> {
    let model = Model::by_name(&a.model)?;
    let r = case::run(&model, a.resolution, a.repeat, a.method, true)?;
    outln!("{}", serde_json::to_string(&r)?)?;
    Ok(0)
}

/// Runs one case in a child process of this binary and reads its result.
fn run_child(
    model: &str,
    resolution: usize,
    repeat: u32,
    method: Method,
    threads: usize,
) -> Result<CaseResult> {
    let exe = std::env::current_exe().context("cannot find the solidkit binary")?;
    let out = Command::new(exe)
        .args([
            "--threads",
            &threads.to_string(),
            "bench-case",
            "--model",
            model,
        ])
        .args(["--resolution", &resolution.to_string()])
        .args(["--repeat", &repeat.to_string()])
        .args(["--method", method.name()])
        .output()
        .context("cannot run the benchmark child process")?;
    if !out.status.success() {
        bail!(
            "{model} at {resolution}: child process failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        );
    }
    let text = String::from_utf8_lossy(&out.stdout);
    serde_json::from_str(text.trim())
        .with_context(|| format!("{model} at {resolution}: unreadable child output"))
}
