//! `solidkit gen SUITE -o DIR`: builds a suite of test solids and writes one mesh per solid, the
//! JSON tree beside each CSG mesh, and `manifest.json` (library: `solidkit_meshing::suites`,
//! `write_suite`). Exit code 1 when a solid's own check fails (a measured value contradicts
//! a stated truth, a volume is outside its stated tolerance, or a broken mesh reports other
//! defects than the ones put in).

mod summary;

use crate::args::GenArgs;
use crate::output::{out, outln};
use anyhow::Result;
use solidkit_meshing::suites::write_suite;

/// Generates the suite; exit code 0, or 1 if a self-check failed.
pub fn run(a: &GenArgs) -> Result<u8> {
    let (suite, opts, format) = a.resolve()?;
    let manifest = write_suite(&a.output, suite, &opts, format)?;
    out!("{}", summary::summary(&manifest))?;
    outln!(
        "wrote: {} meshes and {} in {}",
        manifest.solids.len(),
        a.output.join("manifest.json").display(),
        a.output.display()
    )?;
    let failures = manifest.failures();
    for f in &failures {
        crate::output::errln!("check failed: {f}");
    }
    Ok(if failures.is_empty() { 0 } else { 1 })
}
