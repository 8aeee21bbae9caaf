//! Loading the input solid: `solidkit_frontends::load` by extension (`.json`, `.rhai`, `.csg`,
//! `.scad` through the installed OpenSCAD),
//! with Rhai's `print` and `debug` lines on standard error, control characters escaped.
//! Errors name the file and the place in it; the files the input names are confined to its
//! folder and the folders given by `--allow-path`.

use crate::escape::one_line;
use crate::output::errln;
use anyhow::Result;
use solidkit_frontends::csg::Facets;
use solidkit_frontends::load::{LoadOptions, load_path};
use solidkit_kernel::Solid;
use solidkit_meshing::polyhedral::Polyhedral;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Reads and validates the solid in `path` (round `.csg` primitives exact); the files it names
/// may come from its folder and the folders `allow`; `defines` go to OpenSCAD for `.scad` files.
pub fn load_solid(path: &Path, allow: &[PathBuf], defines: &[String]) -> Result<Solid> {
    load_solid_warned(path, Facets::Exact, allow, defines).map(|(s, _)| s)
}

/// Reads and validates the solid in `path`, with the front end's warnings, one line each as
/// `FILE:LINE:COLUMN: problem`; `facets` says how `.csg` round primitives are built, `allow`
/// lists the folders outside the input's own that its files may come from, `defines` are
/// OpenSCAD's `-D NAME=VALUE` for `.scad` files.
pub fn load_solid_warned(
    path: &Path,
    facets: Facets,
    allow: &[PathBuf],
    defines: &[String],
) -> Result<(Solid, Vec<String>)> {
    load_solid_polyhedral(path, facets, allow, defines, None).map(|(s, w, _)| (s, w))
}

/// The model's polyhedron (when asked for), or why it has none.
pub type MaybePolyhedron = Option<Result<Polyhedral, String>>;

/// [`load_solid_warned`], and with `polyhedral` the model's polyhedron or why it has none: its
/// parts with no polyhedral form meshed on a grid of that many cells along their own longest
/// sides.
pub fn load_solid_polyhedral(
    path: &Path,
    facets: Facets,
    allow: &[PathBuf],
    defines: &[String],
    polyhedral: Option<usize>,
) -> Result<(Solid, Vec<String>, MaybePolyhedron)> {
    let mut options = LoadOptions::default();
    options.polyhedral = polyhedral.is_some();
    options.part_grid = polyhedral;
    options.facets = facets;
    options.allow = allow.to_vec();
    options.defines = defines.to_vec();
    options.script.print = Some(Arc::new(|line: &str| errln!("{}", one_line(line))));
    let loaded = load_path(path, &options)?;
    Ok((loaded.solid, loaded.warnings, loaded.polyhedron))
}
