//! Front ends of solidkit: the languages a solid can be written in besides building a
//! [`solidkit_kernel::Solid`] in Rust, read into that tree.
//!
//! - [`load`]: the usual entry point. [`load::load_path`] reads a `.json` tree, a `.rhai`
//!   script or an OpenSCAD `.csg` file by its extension, [`load::load_str`] text in a given
//!   [`load::Format`]; both validate the solid, confine the files the input names (meshes,
//!   height maps, `import()`ed drawings) to its folder and the folders allowed in
//!   [`load::LoadOptions`], and return the front end's warnings. Errors ([`load::LoadError`])
//!   read `FILE:LINE:COLUMN: problem`.
//! - [`rhai`]: Rhai scripts with every primitive, operation and transform of the kernel, run in a
//!   sandbox (operation, depth, size, time and tree-size limits; no modules, `eval` or `sleep`).
//!   What a script prints goes to a sink the caller gives, never to the process's own output.
//! - [`scad`]: OpenSCAD's `.scad` files, exported to `.csg` by the installed OpenSCAD
//!   ([`openscad`] runs it in a private temporary folder with a time limit).
//! - [`csg`]: OpenSCAD's flattened `.csg` trees with OpenSCAD's modifiers and lenient rules;
//!   round primitives exact or faceted as OpenSCAD does ([`csg::Facets`]).
//!
//! ```
//! use solidkit_frontends::load::{Format, LoadOptions, load_str};
//!
//! let model = "difference() {\n  cube(size = [2, 2, 2], center = true);\n  sphere(r = 1.2);\n}";
//! let loaded = load_str(model, Format::Csg, "model.csg", &LoadOptions::default())?;
//! let bbox = loaded.solid.bbox();
//! assert_eq!(bbox.min.to_array(), [-1.0; 3]);
//! assert_eq!(bbox.max.to_array(), [1.0; 3]);
//! assert!(loaded.warnings.is_empty());
//! # Ok::<(), solidkit_frontends::load::LoadError>(())
//! ```

pub mod csg;
pub mod load;
pub mod openscad;
pub mod rhai;
pub mod scad;
