//! `gen(suite, out_dir, ...)`: a suite of test solids with exact ground truth written to a
//! folder, as `solidkit gen` writes it; returns the manifest as a dict and raises when a solid's
//! own self-check fails.

use crate::errors;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use solidkit_meshing::io::MeshFormat;
use solidkit_meshing::suites::{Suite, SuiteOptions, write_suite};
use std::path::PathBuf;

/// Writes `suite` (platonic, sponge, smooth, csg, random or broken) into `out_dir` with meshes in
/// `format` (stl, obj, ply, off, 3mf or glb); returns the manifest (the dict of
/// `manifest.json`). Raises SolidkitError when a solid contradicts its stated truth.
#[pyfunction(signature = (suite, out_dir, *, format = "ply", seed = 0, resolution = 64, count = 8, threads = None))]
#[allow(clippy::too_many_arguments)]
fn r#gen<'py>(
    py: Python<'py>,
    suite: &str,
    out_dir: PathBuf,
    format: &str,
    seed: u64,
    resolution: usize,
    count: usize,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let s = Suite::from_name(suite).ok_or_else(|| {
        let names: Vec<&str> = Suite::ALL.iter().map(|s| s.name()).collect();
        PyValueError::new_err(format!(
            "unknown suite {suite:?} (expected one of {})",
            names.join(", ")
        ))
    })?;
    let f = MeshFormat::from_extension(format).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown mesh format {format:?} (expected stl, obj, ply, off, 3mf or glb)"
        ))
    })?;
    let options = SuiteOptions {
        seed,
        resolution,
        count,
    };
    let manifest = crate::run::interruptible(py, threads, None, &|| {}, || {
        write_suite(&out_dir, s, &options, f)
    })?
    .map_err(errors::other)?;
    let failures = manifest.failures();
    if !failures.is_empty() {
        return Err(errors::other(format!(
            "gen {suite}: self-check failed: {}",
            failures.join("; ")
        )));
    }
    py.import("json")?
        .call_method1("loads", (manifest.to_json(),))
}

/// Adds the function to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(r#gen, m)?)
}
