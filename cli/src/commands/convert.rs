//! `solidkit convert`: any input (JSON tree, Rhai script, …) → its JSON tree, written atomically.

use crate::args::ConvertArgs;
use crate::input;
use anyhow::Result;
use solidkit_kernel::json;
use solidkit_meshing::io::write_atomic;

/// Loads the input (round `.csg` primitives as `--facets` says) and writes its JSON tree; the
/// front end's warnings (parts OpenSCAD skips) go to standard error, one line each, as `mesh`
/// prints them; exit code 0.
pub fn run(a: &ConvertArgs) -> Result<u8> {
    let (solid, warnings) =
        input::load_solid_warned(&a.input, a.facets.into(), &a.allow_path, &a.define)?;
    for w in &warnings {
        crate::output::errln!("warning: {}", crate::escape::one_line(w));
    }
    let text = json::to_string(&solid);
    write_atomic(&a.output, |w| w.write_all(text.as_bytes()))?;
    Ok(0)
}
