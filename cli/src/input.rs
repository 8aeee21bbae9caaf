//! Loading a solid from a file, by extension; errors name the file and the place in it.

use anyhow::{Context, Result, bail};
use solidkit_kernel::{Solid, json};
use solidkit_meshing::io::FileMeshResolver;
use std::path::Path;
use std::sync::Arc;

pub use crate::frontends::csg::Facets;

/// Reads and validates the solid in `path` (round `.csg` primitives exact).
pub fn load_solid(path: &Path) -> Result<Solid> {
    load_solid_with(path, Facets::Exact)
}

/// Reads and validates the solid in `path`; `facets` says how `.csg` round primitives are built.
pub fn load_solid_with(path: &Path, facets: Facets) -> Result<Solid> {
    load_solid_warned(path, facets).map(|(s, _)| s)
}

/// Reads and validates the solid in `path`, with the front end's warnings, one line each as
/// `FILE:LINE:COLUMN: problem` (parts of a `.csg` model skipped the way OpenSCAD skips them).
pub fn load_solid_warned(path: &Path, facets: Facets) -> Result<(Solid, Vec<String>)> {
    let name = path.display();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("json" | "rhai" | "csg") => {}
        Some(other) => bail!(
            "{name}: unsupported input format '.{other}' (expected a .json tree, a .rhai script or a .csg file)"
        ),
        None => bail!(
            "{name}: no file extension (expected a .json tree, a .rhai script or a .csg file)"
        ),
    }
    let bytes = std::fs::read(path).with_context(|| format!("{name}"))?;
    let text = match String::from_utf8(bytes) {
        Ok(t) => t,
        Err(e) => bail!(
            "{name}: byte {}: invalid UTF-8",
            e.utf8_error().valid_up_to()
        ),
    };
    // `mesh` nodes name their files relative to the tree file's folder.
    let resolver = FileMeshResolver::for_tree_file(path);
    let mut warnings = Vec::new();
    let solid = match ext.as_deref() {
        Some("rhai") => crate::frontends::rhai::eval(&text, &name.to_string(), Arc::new(resolver))?,
        Some("csg") => {
            let (solid, w) = crate::frontends::csg::import_with_warnings(&text, facets)
                .map_err(|e| anyhow::anyhow!("{name}:{e}"))?;
            warnings.extend(w.iter().map(|w| format!("{name}:{w}")));
            solid
        }
        _ => json::from_str_with(&text, &resolver).map_err(|e| anyhow::anyhow!("{name}:{e}"))?,
    };
    solid
        .validate()
        .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
    Ok((solid, warnings))
}
