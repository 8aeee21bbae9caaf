//! OpenSCAD `.csg` import: the flattened tree OpenSCAD writes with `openscad -o model.csg
//! model.scad` (`group`, `union`, `difference`, `intersection`, `multmatrix`, `sphere`, `cube`,
//! `cylinder`, `polyhedron`, `circle`, `square`, `polygon`, `linear_extrude`, `rotate_extrude`,
//! `color`, `render`, `hull`) to a [`Solid`].
//!
//! Pipeline: [`lexer`] (tokens with line/column) → [`parser`] (an arena of statements, explicit
//! stacks, so any nesting depth is safe) → `convert` (post-order over a work list).
//!
//! Round primitives are exact by default ([`Facets::Exact`]: a true sphere, cylinder, cone, disc);
//! [`Facets::OpenScad`] builds them as OpenSCAD's polyhedra and polygons (its `$fn/$fa/$fs`
//! fragment rule). `hull()` always hulls the OpenSCAD-faceted versions of its children (a hull of
//! exact round solids is not a polyhedron). Extrusions are exact sweeps of the profile (OpenSCAD's
//! `slices` is ignored), and 2D Booleans under an extrusion are replayed as 3D Booleans of the
//! swept leaves. Unsupported constructs (`minkowski`, `offset`, `import`, `surface`, `text`,
//! `projection`, unknown modules) are errors naming the construct and its line.

pub mod args;
mod convert;
pub mod error;
pub mod facets;
pub mod flat;
pub mod hull;
pub mod lexer;
pub mod parser;

#[cfg(test)]
mod fuzz;
#[cfg(test)]
mod tests;

pub use error::{CsgError, Warning};

use solidkit_kernel::Solid;

/// How round primitives are built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Facets {
    /// Exact spheres, cylinders, cones and discs.
    #[default]
    Exact,
    /// Faceted exactly as OpenSCAD does.
    OpenScad,
}

/// Imports `.csg` text as a solid (not yet validated; see [`Solid::validate`]); warnings are
/// dropped (see [`import_with_warnings`]). Used by the tests.
#[cfg(test)]
pub fn import(text: &str, facets: Facets) -> Result<Solid, CsgError> {
    import_with_warnings(text, facets).map(|(s, _)| s)
}

/// Imports `.csg` text as a solid (not yet validated), with a warning for each part skipped
/// the way OpenSCAD skips it (a non-finite size, `points = undef`, 3D children of an extrusion,
/// 2D and 3D children mixed in one group, …).
pub fn import_with_warnings(text: &str, facets: Facets) -> Result<(Solid, Vec<Warning>), CsgError> {
    let tree = parser::parse(text)?;
    convert::convert(&tree, facets)
}
