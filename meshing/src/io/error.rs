//! The error type of mesh I/O and the location of a problem inside a file.
//!
//! Every message is one line that names the file, the place in it (when known) and the problem,
//! e.g. `bad.obj:7: face index 12 out of range (the file has 8 vertices)` or
//! `broken.stl: byte 184: truncated binary STL: ...`.

use std::fmt;
use std::path::PathBuf;

/// Where in a file a problem was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Location {
    /// A 1-based line number (text formats).
    Line(usize),
    /// A 0-based byte offset from the start of the file (binary formats).
    Byte(u64),
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Line(line) => write!(f, "line {line}"),
            Location::Byte(offset) => write!(f, "byte {offset}"),
        }
    }
}

/// An error while reading or writing a mesh file.
#[derive(Debug, thiserror::Error)]
pub enum MeshIoError {
    /// The file could not be opened, read, created or written.
    #[error("{}: {source}", .path.display())]
    Io {
        /// The file concerned.
        path: PathBuf,
        /// What the operating system reported.
        source: std::io::Error,
    },
    /// The file could not be read: missing, not a regular file, too large, or (for files named in
    /// a tree) outside the folders it may read.
    #[error(transparent)]
    File(#[from] solidkit_kernel::files::FileError),
    /// The content of the file is invalid at a known place.
    #[error("{}: {message}", located(.path, .location))]
    Parse {
        /// The file name as given to the reader.
        path: String,
        /// Where the problem is.
        location: Location,
        /// What is wrong, in a few words.
        message: String,
    },
    /// The content of one entry of a package (a 3MF model part) is invalid at a known place.
    #[error("{path}: entry {entry}: {location}: {message}")]
    Entry {
        /// The file name as given to the reader.
        path: String,
        /// The entry's path inside the package.
        entry: String,
        /// Where in the entry the problem is.
        location: Location,
        /// What is wrong, in a few words.
        message: String,
    },
    /// The content of the file is invalid, but the place could not be determined.
    #[error("{path}: {message}")]
    Invalid {
        /// The file name as given to the reader.
        path: String,
        /// What is wrong, in a few words.
        message: String,
    },
    /// The file extension names no supported mesh format.
    #[error(
        "{}: unsupported mesh format (expected .stl, .obj, .ply, .off, .3mf or .glb)",
        .path.display()
    )]
    UnsupportedFormat {
        /// The file concerned.
        path: PathBuf,
    },
    /// The mesh cannot be stored in the requested format (nothing was written).
    #[error("{}: cannot write this mesh: {message}", .path.display())]
    InvalidMesh {
        /// The file that was to be written.
        path: PathBuf,
        /// Why the mesh cannot be written.
        message: String,
    },
}

impl MeshIoError {
    /// A [`MeshIoError::Parse`] error.
    pub fn parse(path: &str, location: Location, message: impl Into<String>) -> Self {
        MeshIoError::Parse {
            path: path.to_owned(),
            location,
            message: message.into(),
        }
    }

    /// A [`MeshIoError::Invalid`] error (no known location).
    pub fn invalid(path: &str, message: impl Into<String>) -> Self {
        MeshIoError::Invalid {
            path: path.to_owned(),
            message: message.into(),
        }
    }

    /// The location of a [`MeshIoError::Parse`] or [`MeshIoError::Entry`] error, `None` for the
    /// other variants.
    pub fn location(&self) -> Option<Location> {
        match self {
            MeshIoError::Parse { location, .. } | MeshIoError::Entry { location, .. } => {
                Some(*location)
            }
            _ => None,
        }
    }
}

/// `name:7` for a line, `name: byte 184` for a byte offset (the compiler-style prefix).
fn located(path: &str, location: &Location) -> String {
    match location {
        Location::Line(line) => format!("{path}:{line}"),
        Location::Byte(offset) => format!("{path}: byte {offset}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_are_one_line_with_file_and_location() {
        let e = MeshIoError::parse("bad.obj", Location::Line(7), "face index 12 out of range");
        assert_eq!(e.to_string(), "bad.obj:7: face index 12 out of range");
        let e = MeshIoError::parse("broken.stl", Location::Byte(184), "truncated binary STL");
        assert_eq!(e.to_string(), "broken.stl: byte 184: truncated binary STL");
        assert_eq!(e.location(), Some(Location::Byte(184)));
        let e = MeshIoError::invalid("m.obj", "face parse error");
        assert_eq!(e.to_string(), "m.obj: face parse error");
    }
}
