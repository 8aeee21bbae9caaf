//! Typed errors of the `.csg` importer; each carries the line and column of the offending text.

use thiserror::Error;

/// A place in the `.csg` text (1-based line and column, columns counted in characters).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Pos {
    /// Line, from 1.
    pub line: u32,
    /// Column, from 1.
    pub col: u32,
}

impl std::fmt::Display for Pos {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}", self.line, self.col)
    }
}

/// Why a `.csg` file could not be imported. Displayed as `line:col: problem`, so a caller
/// prefixing the file name gets `model.csg:12:3: unsupported OpenSCAD construct 'minkowski'`.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum CsgError {
    /// The text is not in OpenSCAD's `.csg` syntax.
    #[error("{pos}: syntax error: {message}")]
    Syntax {
        /// Where.
        pos: Pos,
        /// What was wrong.
        message: String,
    },
    /// A module this importer does not implement.
    #[error("{pos}: unsupported OpenSCAD construct '{name}'")]
    Unsupported {
        /// Where the statement starts.
        pos: Pos,
        /// The module's name.
        name: String,
    },
    /// A module's argument is missing or has the wrong type or value.
    #[error("{pos}: {module}: {message}")]
    Argument {
        /// Where the statement starts.
        pos: Pos,
        /// The module's name.
        module: String,
        /// What was wrong.
        message: String,
    },
    /// The model has no geometry at all; the text is empty or names what was skipped on the way
    /// (`"; skipped: ..."`, from the warnings), so that the error says why.
    #[error("1:1: the model is empty (no geometry){0}")]
    Empty(String),
    /// The model's top-level object is 2D: as OpenSCAD, which writes it only to 2D formats, no
    /// solid.
    #[error(
        "1:1: the top-level object is 2D, not a 3D solid (OpenSCAD exports it only as a 2D drawing); extrude it to get a solid"
    )]
    Flat,
}

impl CsgError {
    /// A syntax error at `pos`.
    pub fn syntax(pos: Pos, message: impl Into<String>) -> CsgError {
        CsgError::Syntax {
            pos,
            message: message.into(),
        }
    }

    /// An argument error of `module` at `pos`.
    pub fn argument(pos: Pos, module: &str, message: impl Into<String>) -> CsgError {
        CsgError::Argument {
            pos,
            module: module.to_string(),
            message: message.into(),
        }
    }
}

/// A part of the model that OpenSCAD warns about, skips and renders the rest without; the
/// importer does the same. Displayed as `line:col: problem`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Warning {
    /// Where the statement starts.
    pub pos: Pos,
    /// What was skipped and why.
    pub message: String,
}

impl std::fmt::Display for Warning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.pos, self.message)
    }
}
