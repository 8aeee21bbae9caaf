//! `.scad` files, read through the installed OpenSCAD: `openscad -o model.csg [-D name=value]...
//! FILE` exports the flattened tree into a private temporary folder, and the `.csg` text is read
//! as if it stood beside the `.scad` file (its `import()` and `surface()` paths resolve from
//! there). OpenSCAD's warnings come back as warnings; its errors, and a missing `openscad`, as
//! one message naming the file.

use crate::openscad::{self, RunError, TempDir};
use solidkit_kernel::files::{FileError, read_regular_file};
use std::ffi::OsString;
use std::path::Path;
use std::time::Duration;

/// How long OpenSCAD may take to export one model.
pub const TIMEOUT: Duration = Duration::from_secs(300);

/// Why a `.scad` file could not be exported.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ScadError {
    /// OpenSCAD could not be run to the end.
    #[error(transparent)]
    Run(#[from] RunError),
    /// OpenSCAD reported an error (its last message).
    #[error("openscad: {0}")]
    Failed(String),
    /// A `-D` definition that is not `name=value`.
    #[error("-D {0}: expected name=value")]
    Define(String),
    /// The exported `.csg` file could not be read (too large, ...).
    #[error("the exported .csg: {0}")]
    Read(FileError),
}

/// A model exported to `.csg`: the text and OpenSCAD's warnings.
#[derive(Debug)]
pub struct Exported {
    /// The `.csg` text.
    pub csg: String,
    /// OpenSCAD's `WARNING:` lines, one each.
    pub warnings: Vec<String>,
}

/// Exports `path` to `.csg` with the variable definitions `defines` (`name=value`, passed to
/// OpenSCAD's `-D`); the `.csg` text may have at most `max_bytes` bytes.
pub fn export(path: &Path, defines: &[String], max_bytes: u64) -> Result<Exported, ScadError> {
    let program = openscad::find()?;
    let dir = TempDir::new("scad").map_err(RunError::from)?;
    let out = dir.path().join("model.csg");
    let source = std::path::absolute(path).map_err(RunError::from)?;
    let mut args: Vec<OsString> = Vec::new();
    for d in defines {
        match d.split_once('=') {
            Some((name, _)) if !name.trim().is_empty() => {
                args.push("-D".into());
                args.push(d.into());
            }
            _ => return Err(ScadError::Define(d.clone())),
        }
    }
    args.extend([
        "-o".into(),
        out.clone().into_os_string(),
        source.into_os_string(),
    ]);
    let finished = openscad::run(&program, &args, &dir, TIMEOUT)?;
    if !finished.status.success() || !out.is_file() {
        return Err(ScadError::Failed(finished.last_message().to_string()));
    }
    let bytes = read_regular_file(&out, max_bytes).map_err(ScadError::Read)?;
    let csg = String::from_utf8_lossy(&bytes).into_owned();
    let warnings = finished
        .messages
        .lines()
        .filter(|l| l.starts_with("WARNING:"))
        .map(|l| format!("openscad: {}", l.trim()))
        .collect();
    Ok(Exported { csg, warnings })
}
