//! OpenSCAD `.csg` import: the flattened tree OpenSCAD writes with `openscad -o model.csg
//! model.scad` (`group`, `union`, `difference`, `intersection`, `multmatrix`, `sphere`, `cube`,
//! `cylinder`, `polyhedron`, `circle`, `square`, `polygon`, `linear_extrude`, `rotate_extrude`,
//! `color`, `render`, `hull`, `minkowski`, `import`, `surface`, `offset`, `resize`,
//! `projection`, `text`) to a [`Solid`].
//!
//! Pipeline: `lexer` (tokens with line/column) → `parser` (an arena of statements, explicit
//! stacks, so any nesting depth is safe) → `convert` (post-order over a work list).
//!
//! OpenSCAD's semantics: the modifiers `%` (background) and `*` (disabled) leave their subtree
//! out of the geometry, `#` (highlight) keeps it, the first `!` (root) is the whole model.
//! `inf`, `nan` (also signed) and `undef` are values. Where OpenSCAD warns, skips a part and
//! renders the rest, so does the importer, returning a [`Warning`] per skipped part
//! ([`import_with_warnings`]): a non-finite size or point, a non-finite matrix,
//! `polyhedron`/`polygon` without points, 3D children of an extrusion (an extrusion with nothing
//! 2D is empty), children of the other dimension than a group's first non-empty child.
//!
//! Round primitives are exact by default ([`Facets::Exact`]: a true sphere, cylinder, cone, disc);
//! [`Facets::OpenScad`] builds them as OpenSCAD's polyhedra and polygons (its `$fn/$fa/$fs`
//! fragment rule). Everything under `hull()` and `minkowski()` is built the OpenSCAD-faceted way.
//! `hull()` takes the convex hull of its children's points: exact for primitives, polyhedra,
//! polygons and their unions and transforms, the vertices of a fine marching-cubes mesh of the
//! operand otherwise (a difference, an extrusion). `minkowski()` of convex operands is the hull of
//! the sums of their vertices (exact); with a sphere operand (under translations) and exact facets,
//! or when another operand is not convex, it is that operand offset by the sphere's radius (exact
//! where the operand's field is a true distance); one operand built from convex parts by unions,
//! differences and intersections is cut into convex pieces (`pieces.rs`) and summed piece by piece
//! with the convex others; two non-convex 3D operands are refused. 2D operands of any shape are
//! summed through their polygons (`minkowski_flat.rs`, by polygon clipping in `region.rs`), and
//! `offset()` of any 2D region is OpenSCAD's Clipper offset (`offset.rs`, `offset_region.rs`).
//! Extrusions are exact sweeps of the profile (`scale = 0` is a cone to the apex,
//! `scale = [0, 1]` a wedge to a segment), except that under OpenSCAD's facets a twisted or
//! unevenly scaled `linear_extrude` of up to four 2D leaves is OpenSCAD's stack of flat slices
//! with its slice count and diagonals (`sliced.rs`), and a partial `rotate_extrude` its straight
//! steps (`turned.rs`; a full turn is the kernel's faceted revolution); `polyhedron` faces are cleaned
//! as OpenSCAD takes them (`faces.rs`: repeated points merged, collapsed faces dropped, degenerate or
//! twisted ones fanned), and 2D Booleans under an extrusion are replayed as 3D Booleans of the swept
//! leaves. `import` reads mesh files (`.stl`, `.off`, `.obj`, `.ply`) as solids and `.dxf`
//! drawings as 2D regions (`import.rs`, `dxf.rs`), `surface` reads `.dat` and PNG height maps
//! (`surface.rs`), both relative to the `.csg` file's folder under the confinement rules of
//! `solidkit_kernel::files` (`--allow-path` widens them); `offset` is exact where the result is a
//! union of leaves or one convex leaf (`offset.rs`). `resize` scales the children's own bounding
//! box (exact from the tree where it can be, else from a fine mesh; `resize.rs`, `bounds.rs`).
//! `projection` samples the slice (the field at z = 0) or the shadow (the projected triangles of a
//! mesh of the children) on a 2D grid and contours it into polygons (`projection.rs`,
//! `contour.rs`). `text` is drawn by the installed `openscad` program into a DXF read as
//! polygons (`text.rs`; an error naming the missing program where it is not installed).
//! Unsupported constructs (`offset` that would need polygon clipping, unknown modules) are
//! errors naming the construct and its line.

mod args;
mod bound;
mod bounds;
mod clip;
mod color;
mod contour;
mod convert;
mod convex;
mod dxf;
mod error;
mod faces;
mod facets;
mod flat;
mod geom;
mod hull;
mod hullable;
mod hulled;
mod import;
mod lexer;
mod minkowski;
mod minkowski_flat;
mod offset;
mod offset_region;
mod operand;
mod parser;
mod pieces;
mod polyhedral;
mod projection;
mod projection_grid;
mod region;
mod resize;
mod shadow;
mod shape_args;
mod sliced;
mod surface;
mod sweep;
mod text;
mod turned;

#[cfg(test)]
mod fuzz;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_color;
#[cfg(test)]
mod tests_lenient;
#[cfg(test)]
mod tests_offset;
#[cfg(test)]
mod tests_projection;
#[cfg(test)]
mod tests_resize;
#[cfg(test)]
mod tests_sliced;
#[cfg(test)]
mod tests_surface_png;
#[cfg(test)]
mod tests_text;

pub use error::{CsgError, Pos, Warning};
pub use polyhedral::NotPolyhedral;

use solidkit_kernel::Solid;
use solidkit_kernel::primitive::MeshResolver;

/// How round primitives are built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
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
    import_with_warnings(text, facets, &solidkit_kernel::primitive::NoMeshResolver).map(|(s, _)| s)
}

/// Imports `.csg` text as a solid (not yet validated), with a warning for each part skipped
/// the way OpenSCAD skips it (a non-finite size, `points = undef`, 3D children of an extrusion,
/// 2D and 3D children mixed in one group, …).
pub fn import_with_warnings(
    text: &str,
    facets: Facets,
    files: &dyn MeshResolver,
) -> Result<(Solid, Vec<Warning>), CsgError> {
    let tree = parser::parse(text)?;
    convert::convert(&tree, facets, files)
}

/// A model imported for `--method polyhedral`: the field solid (built with OpenSCAD's facets,
/// the fallback), the warnings, and the model's polyhedron built by mesh Booleans of OpenSCAD's
/// faceted parts, or the first statement that has no polyhedral form.
pub struct PolyhedralImport {
    /// The solid, as [`import_with_warnings`] with [`Facets::OpenScad`] gives it.
    pub solid: Solid,
    /// Parts skipped as OpenSCAD skips them.
    pub warnings: Vec<Warning>,
    /// The polyhedron, or why there is none.
    pub polyhedron: Result<solidkit_meshing::polyhedral::Polyhedral, NotPolyhedral>,
}

/// Imports `.csg` text with its polyhedron (see [`PolyhedralImport`]); with `part_grid`, a
/// statement with no polyhedral form is meshed on a grid of that many cells along its own
/// longest side and combined exactly with the rest (a warning names it), instead of leaving the
/// whole model without a polyhedron.
pub fn import_polyhedral(
    text: &str,
    files: &dyn MeshResolver,
    part_grid: Option<usize>,
) -> Result<PolyhedralImport, CsgError> {
    let tree = parser::parse(text)?;
    let (solid, warnings, track) =
        convert::convert_with(&tree, Facets::OpenScad, files, true, part_grid)?;
    Ok(PolyhedralImport {
        solid,
        warnings,
        polyhedron: track.expect("asked for"),
    })
}
