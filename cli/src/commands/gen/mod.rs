//! `solidkit gen SUITE -o DIR`: builds a suite of test solids (library: `solidkit_meshing::suites`)
//! and writes one mesh per solid, the JSON tree beside each CSG mesh, and `manifest.json`.
//! Solids are encoded and measured in parallel; files are written atomically in manifest order,
//! the manifest last. Exit code 1 when a solid's own check fails (a measured value contradicts
//! a stated truth, a volume is outside its stated tolerance, or a broken mesh reports other
//! defects than the ones put in).

mod selfcheck;

use crate::args::GenArgs;

use crate::output::{out, outln};
use anyhow::{Context, Result};
use rayon::prelude::*;
use solidkit_meshing::io::write_atomic;
use solidkit_meshing::suites::record::{Encoded, encode};
use solidkit_meshing::suites::{Manifest, generate};

/// Generates the suite; exit code 0, or 1 if a self-check failed.
pub fn run(a: &GenArgs) -> Result<u8> {
    let (suite, opts, format) = a.resolve()?;
    let dir = &a.output;
    std::fs::create_dir_all(dir).with_context(|| format!("{}", dir.display()))?;
    let solids = generate(suite, &opts)?;
    let encoded: Vec<Encoded> = solids
        .par_iter()
        .map(|s| encode(s, format))
        .collect::<Result<_, _>>()?;
    for e in &encoded {
        write_atomic(&dir.join(&e.record.file), |out| out.write_all(&e.bytes))?;
        if let (Some(text), Some(file)) = (&e.tree, &e.record.tree) {
            write_atomic(&dir.join(file), |out| out.write_all(text.as_bytes()))?;
        }
    }
    let records: Vec<_> = encoded.into_iter().map(|e| e.record).collect();
    let manifest = Manifest::new(suite, &opts, format, records);
    let manifest_path = dir.join("manifest.json");
    write_atomic(&manifest_path, |out| {
        out.write_all(manifest.to_json().as_bytes())
    })?;
    out!("{}", selfcheck::summary(&manifest))?;
    outln!(
        "wrote: {} meshes and {} in {}",
        manifest.solids.len(),
        manifest_path.display(),
        dir.display()
    )?;
    let failures = selfcheck::failures(&manifest);
    for f in &failures {
        crate::output::errln!("check failed: {f}");
    }
    Ok(if failures.is_empty() { 0 } else { 1 })
}
