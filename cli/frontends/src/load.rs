//! Loading a solid from a file by its extension (`.json` tree, `.rhai` script, `.csg` file), or
//! from text in a given [`Format`]; the solid comes back validated, with the front end's
//! warnings.
//!
//! The input is read as a regular file within the size cap; the files it names (`mesh` and
//! `heightfield` `png` paths in JSON trees and Rhai scripts, `import()` and `surface()` in `.csg`
//! files) resolve relative to its folder and may not leave it, except into the folders of
//! [`LoadOptions::allow`] (the CLI's `--allow-path`). See `solidkit_kernel::files`.
//!
//! Every [`LoadError`] is one message naming the file and, where known, the place in it:
//! `FILE:LINE:COLUMN: problem`.

use crate::csg::{self, CsgError, Facets};
use crate::rhai::{self, ScriptError, ScriptOptions};
use solidkit_kernel::files::{DEFAULT_MAX_FILE_BYTES, FileAccess, FileError, read_regular_file};
use solidkit_kernel::{KernelError, Solid, json};
use solidkit_meshing::io::FileMeshResolver;
use solidkit_meshing::polyhedral::{Polyhedral, from_solid_gridding};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The languages a solid can be read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Format {
    /// solidkit's JSON tree (`.json`).
    Json,
    /// A Rhai script (`.rhai`), see [`crate::rhai`].
    Rhai,
    /// An OpenSCAD `.csg` file, see [`crate::csg`].
    Csg,
    /// An OpenSCAD `.scad` file, exported to `.csg` by the installed OpenSCAD ([`crate::scad`]);
    /// only from a file ([`load_path`]).
    Scad,
}

impl Format {
    /// The format of a file extension (without the dot, any case), if it is one of ours.
    pub fn from_extension(extension: &str) -> Option<Format> {
        match extension.to_ascii_lowercase().as_str() {
            "json" => Some(Format::Json),
            "rhai" => Some(Format::Rhai),
            "csg" => Some(Format::Csg),
            "scad" => Some(Format::Scad),
            _ => None,
        }
    }

    /// The format of the file `path`, by its extension.
    pub fn from_path(path: &Path) -> Result<Format, LoadError> {
        let name = path.display().to_string();
        match path.extension().and_then(|e| e.to_str()) {
            None => Err(LoadError::NoExtension { name }),
            Some(ext) => Format::from_extension(ext).ok_or_else(|| LoadError::UnsupportedFormat {
                name,
                extension: ext.to_ascii_lowercase(),
            }),
        }
    }
}

/// How a solid is loaded.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct LoadOptions {
    /// How the round primitives of `.csg` files are built (default: exact).
    pub facets: Facets,
    /// Folders, besides the input's own, that the files it names may come from (the CLI's
    /// `--allow-path`); each must exist.
    pub allow: Vec<PathBuf>,
    /// For [`load_str`]: the folder the files named in the text are relative to and confined
    /// to (default: the current directory). [`load_path`] uses the input file's folder.
    pub base_dir: Option<PathBuf>,
    /// The cap on the size of the input and of every file it names, in bytes (default
    /// [`DEFAULT_MAX_FILE_BYTES`]).
    pub max_file_bytes: u64,
    /// The sandbox limits of Rhai scripts and where their `print` and `debug` output goes
    /// (default: discarded).
    pub script: ScriptOptions,
    /// Variable definitions `name=value` (the CLI's `-D`): passed to OpenSCAD for `.scad` files,
    /// constants in the scope of `.rhai` scripts (the value a Rhai literal, see
    /// [`crate::rhai::ScriptOptions::defines`]); an error for `.json` and `.csg` inputs.
    pub defines: Vec<String>,
    /// Also build the model's polyhedron by mesh Booleans ([`Loaded::polyhedron`]): for `.csg`
    /// and `.scad` files from OpenSCAD's faceted parts (the solid is then built with
    /// [`Facets::OpenScad`] too), for trees and scripts where every leaf is a polyhedron.
    pub polyhedral: bool,
    /// With [`LoadOptions::polyhedral`]: a part with no polyhedral form (a sphere in a tree, a
    /// wedge extruded to a segment) is meshed by marching cubes with this many cells along its
    /// own longest side and combined exactly with the rest, with a warning; `None` (the
    /// default): the model has no polyhedron then, and [`Loaded::polyhedron`] says why.
    pub part_grid: Option<usize>,
}

impl Default for LoadOptions {
    fn default() -> Self {
        LoadOptions {
            facets: Facets::default(),
            allow: Vec::new(),
            base_dir: None,
            max_file_bytes: DEFAULT_MAX_FILE_BYTES,
            script: ScriptOptions::default(),
            defines: Vec::new(),
            polyhedral: false,
            part_grid: None,
        }
    }
}

/// A loaded, validated solid.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Loaded {
    /// The solid.
    pub solid: Solid,
    /// The front end's warnings, one line each as `FILE:LINE:COLUMN: problem` (parts of a `.csg`
    /// model skipped the way OpenSCAD skips them).
    pub warnings: Vec<String>,
    /// With [`LoadOptions::polyhedral`]: the model's polyhedron, or why it has none
    /// (`FILE:LINE:COLUMN: ...` for `.csg` statements).
    pub polyhedron: Option<Result<Polyhedral, String>>,
}

/// Why a solid could not be loaded. Each message is complete on its own and names the file
/// (`FILE: problem` or `FILE:LINE:COLUMN: problem`).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LoadError {
    /// The extension is not `.json`, `.rhai`, `.csg` or `.scad`.
    #[error(
        "{name}: unsupported input format '.{extension}' (expected a .json tree, a .rhai script, a .csg or a .scad file)"
    )]
    UnsupportedFormat {
        /// The input's name (its path).
        name: String,
        /// The extension, in lower case.
        extension: String,
    },
    /// The path has no extension (or one that is not UTF-8).
    #[error(
        "{name}: no file extension (expected a .json tree, a .rhai script, a .csg or a .scad file)"
    )]
    NoExtension {
        /// The input's name (its path).
        name: String,
    },
    /// A folder of [`LoadOptions::allow`] cannot be used (missing, not a folder).
    #[error("--allow-path {error}")]
    AllowPath {
        /// The folder.
        dir: PathBuf,
        /// Why (the message includes it).
        error: FileError,
    },
    /// The input cannot be read (missing, not a regular file, too large, ...).
    #[error(transparent)]
    Read(FileError),
    /// The input is not UTF-8 text.
    #[error("{name}: byte {valid_up_to}: invalid UTF-8")]
    Utf8 {
        /// The input's name (its path).
        name: String,
        /// The offset of the first invalid byte.
        valid_up_to: usize,
    },
    /// A JSON tree that does not parse or names unreadable files.
    #[error("{name}:{error}")]
    Json {
        /// The input's name (its path).
        name: String,
        /// Why, with the line and column.
        error: KernelError,
    },
    /// A Rhai script that does not run to a solid (the error names the file).
    #[error(transparent)]
    Script(ScriptError),
    /// A `.csg` file that cannot be imported.
    #[error("{name}:{error}")]
    Csg {
        /// The input's name (its path).
        name: String,
        /// Why, with the line and column.
        error: CsgError,
    },
    /// A `.scad` file that OpenSCAD could not export (or no OpenSCAD), or `.scad` text given to
    /// [`load_str`].
    #[error("{name}: {error}")]
    Scad {
        /// The input's name (its path).
        name: String,
        /// Why.
        error: crate::scad::ScadError,
    },
    /// `.scad` text without a file: OpenSCAD resolves its `include`s and `import`s from the
    /// file's folder, so only [`load_path`] reads `.scad`.
    #[error("{name}: .scad text can only be read from a file")]
    ScadText {
        /// The input's name.
        name: String,
    },
    /// `-D` definitions given for a `.json` tree or a `.csg` file, which have no variables.
    #[error("{name}: -D NAME=VALUE applies to .scad and .rhai inputs only")]
    Defines {
        /// The input's name.
        name: String,
    },
    /// The solid was built but is not valid (a parameter out of range, ...).
    #[error("{name}: {error}")]
    Invalid {
        /// The input's name (its path).
        name: String,
        /// Why, with the path of the offending node.
        error: KernelError,
    },
}

/// Reads and validates the solid in the file `path`, in the format of its extension; the files
/// it names may come from its folder and the folders `options.allow`.
pub fn load_path(path: &Path, options: &LoadOptions) -> Result<Loaded, LoadError> {
    let format = Format::from_path(path)?;
    let access = file_access(FileAccess::for_tree_file(path), options)?;
    let bytes = read_regular_file(path, options.max_file_bytes).map_err(LoadError::Read)?;
    let name = path.display().to_string();
    if format == Format::Scad {
        let exported = crate::scad::export(path, &options.defines, options.max_file_bytes)
            .map_err(|error| LoadError::Scad {
                name: name.clone(),
                error,
            })?;
        // Places in the exported text are named after the .scad file they come from.
        let csg_name = format!("{name} (exported .csg)");
        // The definitions went to OpenSCAD; the exported .csg has none.
        let csg_options = LoadOptions {
            defines: Vec::new(),
            ..options.clone()
        };
        let mut loaded = load_text(&exported.csg, Format::Csg, &csg_name, access, &csg_options)?;
        let mut warnings: Vec<String> = exported
            .warnings
            .iter()
            .map(|w| format!("{name}: {w}"))
            .collect();
        warnings.append(&mut loaded.warnings);
        loaded.warnings = warnings;
        return Ok(loaded);
    }
    let text = String::from_utf8(bytes).map_err(|e| LoadError::Utf8 {
        name: name.clone(),
        valid_up_to: e.utf8_error().valid_up_to(),
    })?;
    load_text(&text, format, &name, access, options)
}

/// Reads and validates the solid in `text`, written in `format` and called `name` in errors and
/// warnings; the files it names resolve from `options.base_dir` (default: the current
/// directory), confined to it and the folders `options.allow`.
pub fn load_str(
    text: &str,
    format: Format,
    name: &str,
    options: &LoadOptions,
) -> Result<Loaded, LoadError> {
    let base = options
        .base_dir
        .clone()
        .unwrap_or_else(|| PathBuf::from("."));
    let access = file_access(FileAccess::new(base), options)?;
    load_text(text, format, name, access, options)
}

/// `access` widened by the folders `options.allow`, with the size cap of `options`.
fn file_access(access: FileAccess, options: &LoadOptions) -> Result<FileAccess, LoadError> {
    let mut access = access.with_max_bytes(options.max_file_bytes);
    for dir in &options.allow {
        access = access.allow(dir).map_err(|error| LoadError::AllowPath {
            dir: dir.clone(),
            error,
        })?;
    }
    Ok(access)
}

fn load_text(
    text: &str,
    format: Format,
    name: &str,
    access: FileAccess,
    options: &LoadOptions,
) -> Result<Loaded, LoadError> {
    let resolver = FileMeshResolver::with_access(access);
    let mut warnings = Vec::new();
    let mut polyhedron = None;
    if !options.defines.is_empty() && matches!(format, Format::Json | Format::Csg) {
        return Err(LoadError::Defines {
            name: name.to_string(),
        });
    }
    let solid = match format {
        Format::Scad => {
            return Err(LoadError::ScadText {
                name: name.to_string(),
            });
        }
        Format::Rhai => {
            let mut script = options.script.clone();
            script.defines = options.defines.clone();
            rhai::eval_with_options(text, name, Arc::new(resolver), &script)
                .map_err(LoadError::Script)?
        }
        Format::Csg if options.polyhedral => {
            let got =
                csg::import_polyhedral(text, &resolver, options.part_grid).map_err(|error| {
                    LoadError::Csg {
                        name: name.to_string(),
                        error,
                    }
                })?;
            warnings.extend(got.warnings.iter().map(|w| format!("{name}:{w}")));
            polyhedron = Some(got.polyhedron.map_err(|e| format!("{name}:{e}")));
            got.solid
        }
        Format::Csg => {
            let (solid, w) =
                csg::import_with_warnings(text, options.facets, &resolver).map_err(|error| {
                    LoadError::Csg {
                        name: name.to_string(),
                        error,
                    }
                })?;
            warnings.extend(w.iter().map(|w| format!("{name}:{w}")));
            solid
        }
        Format::Json => json::from_str_with(text, &resolver).map_err(|error| LoadError::Json {
            name: name.to_string(),
            error,
        })?,
    };
    solid.validate().map_err(|error| LoadError::Invalid {
        name: name.to_string(),
        error,
    })?;
    if options.polyhedral && polyhedron.is_none() {
        polyhedron = Some(match from_solid_gridding(&solid, options.part_grid) {
            Ok((p, w)) => {
                warnings.extend(w.iter().map(|w| format!("{name}: {w}")));
                Ok(p)
            }
            Err(e) => Err(format!("{name}: {e}")),
        });
    }
    Ok(Loaded {
        solid,
        warnings,
        polyhedron,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_by_extension() {
        assert_eq!(Format::from_extension("CSG"), Some(Format::Csg));
        assert_eq!(
            Format::from_path(Path::new("a.Rhai")).ok(),
            Some(Format::Rhai)
        );
        let e = Format::from_path(Path::new("model.STL")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "model.STL: unsupported input format '.stl' (expected a .json tree, a .rhai script, \
             a .csg or a .scad file)"
        );
        let e = Format::from_path(Path::new("model")).unwrap_err();
        assert!(matches!(e, LoadError::NoExtension { .. }), "{e}");
    }

    #[test]
    fn text_in_each_format() {
        let options = LoadOptions::default();
        let csg = load_str("cube(size = [1, 2, 3]);", Format::Csg, "m.csg", &options).unwrap();
        assert_eq!(csg.solid.bbox().max.to_array(), [1.0, 2.0, 3.0]);
        let rhai = load_str("sphere(2.0)", Format::Rhai, "m.rhai", &options).unwrap();
        assert_eq!(rhai.solid.bbox().max.to_array(), [2.0, 2.0, 2.0]);
        let json = solidkit_kernel::json::to_string(&rhai.solid);
        let back = load_str(&json, Format::Json, "m.json", &options).unwrap();
        assert_eq!(back.solid, rhai.solid);
    }

    #[test]
    fn errors_name_the_input_and_place() {
        let options = LoadOptions::default();
        let e = load_str("cube(", Format::Csg, "m.csg", &options).unwrap_err();
        assert!(e.to_string().starts_with("m.csg:1:"), "{e}");
        let e = load_str("{", Format::Json, "t.json", &options).unwrap_err();
        assert!(e.to_string().starts_with("t.json:1:"), "{e}");
        let e = load_str("let x = ;", Format::Rhai, "s.rhai", &options).unwrap_err();
        assert!(e.to_string().starts_with("s.rhai:1:"), "{e}");
    }

    #[test]
    fn warnings_carry_the_name() {
        let text = "group() { cube(size = [1, 1, 1]); cube(size = [inf, 1, 1]); }";
        let loaded = load_str(text, Format::Csg, "w.csg", &LoadOptions::default()).unwrap();
        assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
        assert!(
            loaded.warnings[0].starts_with("w.csg:1:"),
            "{:?}",
            loaded.warnings
        );
    }

    #[test]
    fn defines_set_rhai_constants_and_are_refused_elsewhere() {
        let mut options = LoadOptions {
            defines: vec![
                "r=2.5".into(),
                "size = [1, 2, 3]".into(),
                "round=true".into(),
            ],
            ..LoadOptions::default()
        };
        let script = "let s = if round { sphere(r) } else { box(size) };\ns";
        let loaded = load_str(script, Format::Rhai, "d.rhai", &options).unwrap();
        assert_eq!(loaded.solid.bbox().max.to_array(), [2.5, 2.5, 2.5]);
        options.defines[2] = "round=false".into();
        let loaded = load_str(script, Format::Rhai, "d.rhai", &options).unwrap();
        assert_eq!(loaded.solid.bbox().max.to_array(), [0.5, 1.0, 1.5]);
        // A default in the script when -D does not give the value.
        let with_default = "let r = if is_def_var(\"r\") { r } else { 1.0 };\nsphere(r)";
        let loaded = load_str(with_default, Format::Rhai, "d.rhai", &options).unwrap();
        assert_eq!(loaded.solid.bbox().max.to_array(), [2.5, 2.5, 2.5]);
        let plain = LoadOptions::default();
        let loaded = load_str(with_default, Format::Rhai, "d.rhai", &plain).unwrap();
        assert_eq!(loaded.solid.bbox().max.to_array(), [1.0, 1.0, 1.0]);
        let e = load_str("sphere(1.0)", Format::Csg, "m.csg", &options).unwrap_err();
        assert_eq!(
            e.to_string(),
            "m.csg: -D NAME=VALUE applies to .scad and .rhai inputs only"
        );
        let e = load_str("{}", Format::Json, "t.json", &options).unwrap_err();
        assert!(matches!(e, LoadError::Defines { .. }), "{e}");
        options.defines = vec!["r=radius".into()];
        let e = load_str("sphere(r)", Format::Rhai, "d.rhai", &options).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("d.rhai: -D r=radius: the value is not a Rhai literal"),
            "{e}"
        );
    }

    #[test]
    fn script_output_goes_to_the_sink() {
        let lines = Arc::new(std::sync::Mutex::new(Vec::<String>::new()));
        let mut options = LoadOptions::default();
        let sink = lines.clone();
        options.script.print = Some(Arc::new(move |s: &str| {
            sink.lock().unwrap().push(s.to_string())
        }));
        let script = "print(\"hi\");\ndebug(3);\nsphere(1.0)";
        load_str(script, Format::Rhai, "p.rhai", &options).unwrap();
        assert_eq!(*lines.lock().unwrap(), ["hi", "2:1: 3"]);
    }

    #[test]
    fn missing_allow_path_is_named() {
        let mut options = LoadOptions::default();
        options
            .allow
            .push(PathBuf::from("/no/such/solidkit/folder"));
        let e = load_str("sphere(1.0)", Format::Rhai, "p.rhai", &options).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("--allow-path /no/such/solidkit/folder"),
            "{e}"
        );
    }

    /// The installed OpenSCAD, or `None` (the `.scad` tests then only check the message).
    fn openscad() -> Option<std::path::PathBuf> {
        crate::openscad::find().ok()
    }

    #[test]
    fn scad_files_go_through_openscad_with_defines_and_warnings() {
        let dir = std::env::temp_dir().join(format!("solidkit-scad-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("part.scad");
        std::fs::write(
            &file,
            "size = 1;\nmodule part(s) { cube([s, 2 * s, 3]); }\npart(size);\n\
             translate([10, 0, 0]) sphere(r = 1);\n",
        )
        .unwrap();
        let mut options = LoadOptions::default();
        let loaded = load_path(&file, &options);
        if openscad().is_none() {
            let e = loaded.unwrap_err().to_string();
            assert!(e.contains("openscad is not installed"), "{e}");
            return;
        }
        let loaded = loaded.unwrap();
        let b = loaded.solid.bbox();
        assert_eq!(b.min.to_array(), [0.0, -1.0, -1.0]);
        assert_eq!(b.max.to_array(), [11.0, 2.0, 3.0]);
        options.defines = vec!["size=2".into()];
        let b = load_path(&file, &options).unwrap().solid.bbox();
        assert_eq!(b.max.to_array(), [11.0, 4.0, 3.0]);
        options.defines = vec!["=2".into()];
        let e = load_path(&file, &options).unwrap_err().to_string();
        assert!(e.contains("expected name=value"), "{e}");
        // OpenSCAD's own errors come back with the file's name.
        std::fs::write(&file, "cube([1, 1, 1]\n").unwrap();
        let e = load_path(&file, &LoadOptions::default())
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(&format!("{}: openscad:", file.display())),
            "{e}"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn scad_text_needs_a_file() {
        let e = load_str("cube(1);", Format::Scad, "m.scad", &LoadOptions::default());
        assert!(matches!(e, Err(LoadError::ScadText { .. })));
    }
}
