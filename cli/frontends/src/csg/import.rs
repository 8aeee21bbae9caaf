//! `import(file = …)`: mesh files (`.stl`, `.off`, `.obj`, `.ply`, `.3mf`) as 3D solids bounded by the
//! mesh, and `.dxf` drawings as 2D regions ([`super::dxf`]). The path is relative to the `.csg`
//! file's folder and read through the caller's [`MeshResolver`], so the confinement rules of
//! `solidkit_kernel::files` (and `--allow-path`) apply. As in OpenSCAD 2021.01, `layer`, `origin`
//! and `scale` apply to DXF only. Other formats (`.svg`, `.amf`) are errors.

use super::dxf::{self, DxfOptions};
use super::error::CsgError;
use super::flat::{Flat, Leaf2};
use super::parser::{Stmt, Value};
use glam::DVec2;
use solidkit_kernel::Solid;
use solidkit_kernel::files::FileError;
use solidkit_kernel::primitive::{
    MeshResolver, MeshSolid, MeshSolidError, Primitive, ResolveError,
};
use solidkit_meshing::io::MeshIoError;

/// What an `import` gives.
#[derive(Debug)]
pub enum Imported {
    /// A mesh file's solid.
    Solid(Solid),
    /// A drawing's region (`None`: no closed path).
    Flat(Option<Flat>),
}

/// A string argument, or `None` when absent or `undef`.
pub fn string_arg<'a>(stmt: &'a Stmt, name: &str, position: Option<usize>) -> Option<&'a str> {
    match stmt.arg(name, position) {
        Some(Value::Str(s)) => Some(s.as_str()),
        _ => None,
    }
}

/// True when a resolver's error is a file that does not exist (not one refused by the
/// confinement rules, unreadable or malformed: those stay errors).
pub(super) fn missing(error: &ResolveError) -> bool {
    let io = match error.inner().downcast_ref::<MeshIoError>() {
        Some(MeshIoError::File(FileError::Io { source, .. }) | MeshIoError::Io { source, .. }) => {
            Some(source)
        }
        _ => error
            .inner()
            .downcast_ref::<FileError>()
            .and_then(|e| match e {
                FileError::Io { source, .. } => Some(source),
                _ => None,
            }),
    };
    io.is_some_and(|e| e.kind() == std::io::ErrorKind::NotFound)
}

/// Reads the file of an `import` statement; `warn` receives one line per thing skipped.
pub fn import(
    stmt: &Stmt,
    files: &dyn MeshResolver,
    warn: &mut dyn FnMut(String),
) -> Result<Imported, CsgError> {
    let path = string_arg(stmt, "file", Some(0))
        .filter(|p| !p.is_empty())
        .ok_or_else(|| stmt.error("'file': expected a file name"))?;
    let ext = std::path::Path::new(path)
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    match ext.as_str() {
        "stl" | "off" | "obj" | "ply" | "3mf" => match MeshSolid::from_file(path, files) {
            Ok(mesh) => Ok(Imported::Solid(Solid::primitive(Primitive::Mesh(mesh)))),
            // OpenSCAD warns about a file it cannot open and imports nothing.
            Err(MeshSolidError::Load { error, .. }) if missing(&error) => {
                warn(format!("{error}: the import is empty"));
                Ok(Imported::Flat(None))
            }
            Err(e) => Err(stmt.error(e.to_string())),
        },
        "dxf" => {
            let bytes = match files.read_file(path) {
                Ok(b) => b,
                Err(error) if missing(&error) => {
                    warn(format!("{error}: the import is empty"));
                    return Ok(Imported::Flat(None));
                }
                Err(e) => return Err(stmt.error(e.to_string())),
            };
            let text = String::from_utf8_lossy(&bytes);
            let origin = stmt.size2("origin", None, 0.0)?;
            let scale = stmt.num("scale", None, 1.0)?;
            let layer = string_arg(stmt, "layer", None).filter(|l| !l.is_empty());
            let opts = DxfOptions {
                layer,
                origin: DVec2::new(origin.x, origin.y),
                scale,
                res: stmt.resolution()?,
            };
            let region = dxf::read(&text, opts).map_err(|e| stmt.error(format!("{path}: {e}")))?;
            for kind in &region.skipped {
                warn(format!("{path}: unsupported DXF entity {kind} skipped"));
            }
            if region.loops.is_empty() {
                warn(format!("{path}: no closed path: the import is empty"));
                return Ok(Imported::Flat(None));
            }
            Ok(Imported::Flat(Some(Flat::leaf(Leaf2::Polygon(
                region.loops,
            )))))
        }
        other => Err(stmt.error(format!(
            "'{path}': .{other} files are not read (supported: .stl, .off, .obj, .ply, .3mf, .dxf)"
        ))),
    }
}
