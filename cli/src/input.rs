//! Loading a solid from a file, by extension; errors name the file and the place in it.
//!
//! The input is read as a regular file within the size cap; the files it names (`mesh` and
//! `heightfield` `png` paths, in JSON trees and Rhai scripts alike) resolve relative to its folder
//! and may not leave it, except into the folders given by `--allow-path`.

use anyhow::{Result, bail};
use solidkit_kernel::files::{DEFAULT_MAX_FILE_BYTES, FileAccess, read_regular_file};
use solidkit_kernel::{Solid, json};
use solidkit_meshing::io::FileMeshResolver;
use std::path::{Path, PathBuf};
use std::sync::Arc;

pub use crate::frontends::csg::Facets;

/// Reads and validates the solid in `path` (round `.csg` primitives exact); the files it names
/// may come from its folder and the folders `allow`.
pub fn load_solid(path: &Path, allow: &[PathBuf]) -> Result<Solid> {
    load_solid_with(path, Facets::Exact, allow)
}

/// The file access of the input `path`: its folder, plus the folders `allow` (`--allow-path`).
fn file_access(path: &Path, allow: &[PathBuf]) -> Result<FileAccess> {
    let mut access = FileAccess::for_tree_file(path);
    for dir in allow {
        access = access
            .allow(dir)
            .map_err(|e| anyhow::anyhow!("--allow-path {e}"))?;
    }
    Ok(access)
}

/// Reads and validates the solid in `path`; `facets` says how `.csg` round primitives are built,
/// `allow` lists the folders outside the input's own that its files may come from.
pub fn load_solid_with(path: &Path, facets: Facets, allow: &[PathBuf]) -> Result<Solid> {
    load_solid_warned(path, facets, allow).map(|(s, _)| s)
}

/// As [`load_solid_with`], with the front end's warnings, one line each as
/// `FILE:LINE:COLUMN: problem` (parts of a `.csg` model skipped the way OpenSCAD skips them).
pub fn load_solid_warned(
    path: &Path,
    facets: Facets,
    allow: &[PathBuf],
) -> Result<(Solid, Vec<String>)> {
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
    let access = file_access(path, allow)?;
    let bytes = read_regular_file(path, DEFAULT_MAX_FILE_BYTES)?;
    let text = match String::from_utf8(bytes) {
        Ok(t) => t,
        Err(e) => bail!(
            "{name}: byte {}: invalid UTF-8",
            e.utf8_error().valid_up_to()
        ),
    };
    // `mesh` and `png` paths are relative to the tree file's folder and confined to it.
    let resolver = FileMeshResolver::with_access(access);
    let mut warnings = Vec::new();
    let solid = match ext.as_deref() {
        Some("rhai") => crate::frontends::rhai::eval(&text, &name.to_string(), Arc::new(resolver))?,
        Some("csg") => {
            let (solid, w) = crate::frontends::csg::import_with_warnings(&text, facets, &resolver)
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
