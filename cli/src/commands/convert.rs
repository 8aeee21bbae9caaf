//! `solidkit convert`: any input (JSON tree, Rhai script, …) → its JSON tree, written atomically.

use crate::args::ConvertArgs;
use crate::input;
use anyhow::Result;
use solidkit_kernel::json;
use solidkit_meshing::io::write_atomic;

/// Loads the input and writes its JSON tree; exit code 0.
pub fn run(a: &ConvertArgs) -> Result<u8> {
    let solid = input::load_solid(&a.input, &a.allow_path, &a.define)?;
    let text = json::to_string(&solid);
    write_atomic(&a.output, |w| w.write_all(text.as_bytes()))?;
    Ok(0)
}
