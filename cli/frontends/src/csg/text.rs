//! `text(...)` through the installed OpenSCAD: glyph outlines need a font library, which the
//! importer does not carry, so the statement is written back as a one-line `.scad` file
//! (the same arguments), `openscad -o text.dxf text.scad` renders it in a private temporary
//! folder (killed after [`TIMEOUT`]), and the drawing is read with [`super::dxf`] as polygons
//! (one leaf per glyph outline with its holes); each distinct text is drawn once per import.
//! Without an `openscad` program on `PATH`, `text` is an error that says so. The DXF carries
//! OpenSCAD's 6 significant digits.

use super::contour::region;
use super::dxf::{self, DxfOptions};
use super::error::CsgError;
use super::flat::Flat;
use super::parser::{Stmt, Value};
use crate::openscad::{self, RunError, TempDir};
use glam::DVec2;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// How long OpenSCAD may take to render one `text`.
pub const TIMEOUT: Duration = Duration::from_secs(60);

/// Why a `text` could not be rendered.
#[derive(Debug, thiserror::Error)]
pub enum TextError {
    /// No `openscad` on `PATH`.
    #[error(
        "text() needs the 'openscad' program to draw glyphs, and none was found on PATH \
         (install OpenSCAD, or replace the text by polygons)"
    )]
    NoOpenScad,
    /// An argument that cannot be written back (a vector, inf or nan).
    #[error("'{0}': expected a string, number or boolean")]
    Argument(String),
    /// The temporary folder or its files.
    #[error("temporary files: {0}")]
    Io(#[from] std::io::Error),
    /// OpenSCAD ran past [`TIMEOUT`].
    #[error("openscad did not finish within {} s", TIMEOUT.as_secs())]
    Timeout,
    /// OpenSCAD failed.
    #[error("openscad failed: {0}")]
    Failed(String),
    /// Its drawing could not be read.
    #[error("reading openscad's drawing: {0}")]
    Drawing(String),
}

/// The OpenSCAD to run, if any (see [`crate::openscad::find`]).
pub fn find_openscad() -> Option<PathBuf> {
    openscad::find().ok()
}

/// An OpenSCAD string literal.
fn quoted(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            c if (c as u32) < 0x20 || c as u32 == 0x7f => {
                out.push_str(&format!("\\x{:02x}", c as u32))
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The `.scad` line drawing the same text as `stmt`.
pub fn scad_source(stmt: &Stmt) -> Result<String, TextError> {
    let mut args = Vec::new();
    for a in &stmt.args {
        let name = a.name.clone().unwrap_or_default();
        let value = match &a.value {
            Value::Str(s) => quoted(s),
            Value::Num(n) if n.is_finite() => format!("{n:?}"),
            Value::Bool(b) => b.to_string(),
            Value::Undef => "undef".to_string(),
            _ => return Err(TextError::Argument(name)),
        };
        args.push(if name.is_empty() {
            value
        } else {
            format!("{name} = {value}")
        });
    }
    Ok(format!("text({});\n", args.join(", ")))
}

/// The loops of `source` drawn by the OpenSCAD at `program` (no loops: empty text).
pub fn render(program: &Path, source: &str, res_stmt: &Stmt) -> Result<Option<Flat>, TextError> {
    let dir = TempDir::new("text")?;
    let scad = dir.path().join("text.scad");
    let out = dir.path().join("text.dxf");
    std::fs::write(&scad, source)?;
    let args = [
        "-o".into(),
        out.clone().into_os_string(),
        scad.into_os_string(),
    ];
    let finished = openscad::run(program, &args, &dir, TIMEOUT).map_err(|e| match e {
        RunError::Timeout(_) => TextError::Timeout,
        RunError::Io(e) => TextError::Io(e),
        RunError::Missing => TextError::NoOpenScad,
        e => TextError::Failed(e.to_string()),
    })?;
    let (status, messages) = (finished.status, &finished.messages);
    // An empty text is an empty top level (2021.01 says "not a 2D object").
    if messages.contains("top level object is empty")
        || messages.contains("top level object is not a 2D object")
    {
        return Ok(None);
    }
    if !status.success() || !out.is_file() {
        return Err(TextError::Failed(format!(
            "{status}: {}",
            finished.last_message()
        )));
    }
    let text = std::fs::read_to_string(&out)?;
    let res = res_stmt
        .resolution()
        .map_err(|e| TextError::Drawing(e.to_string()))?;
    let opts = DxfOptions {
        layer: None,
        origin: DVec2::ZERO,
        scale: 1.0,
        res,
    };
    let drawing = dxf::read(&text, opts).map_err(|e| TextError::Drawing(e.to_string()))?;
    Ok(region(drawing.loops))
}

/// Drawings already made, by their `.scad` source.
pub type TextCache = HashMap<String, Option<Flat>>;

/// `text(...)`: its glyphs as polygons, `None` when it draws nothing; a text drawn before (same
/// arguments) comes from `cache`.
pub fn text(stmt: &Stmt, cache: &mut TextCache) -> Result<Option<Flat>, CsgError> {
    let located = |e: TextError| stmt.error(e.to_string());
    let source = scad_source(stmt).map_err(located)?;
    if let Some(done) = cache.get(&source) {
        return Ok(done.clone());
    }
    let program = find_openscad()
        .ok_or(TextError::NoOpenScad)
        .map_err(located)?;
    let drawn = render(&program, &source, stmt).map_err(located)?;
    cache.insert(source, drawn.clone());
    Ok(drawn)
}
