//! Reading input files safely: the files a tree names (mesh files of `mesh` nodes, PNG height
//! maps) and the files a user names on the command line.
//!
//! Two rules, applied by every reader of the workspace:
//! - **Only regular files, and not too large** ([`read_regular_file`]): devices, FIFOs, sockets
//!   and directories are refused before they are opened (a FIFO would block, `/dev/zero` never
//!   ends), the size is checked against a cap ([`DEFAULT_MAX_FILE_BYTES`] unless told otherwise)
//!   before anything is read, and the read itself stops one byte past the cap, so a file that
//!   grows while it is read cannot make it unbounded.
//! - **Confinement** ([`FileAccess`]): a path written inside a tree or script is relative to the
//!   folder of that file and must stay inside it once `..` and symbolic links are resolved
//!   (canonicalised). Absolute paths are refused. Folders the user allows explicitly (the CLI's
//!   `--allow-path DIR`) are accepted as well, for relative and absolute paths alike.

use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};

/// The default cap on the size of one input file: 1 GiB.
pub const DEFAULT_MAX_FILE_BYTES: u64 = 1 << 30;

/// Why a file cannot be read.
#[derive(Debug, thiserror::Error)]
pub enum FileError {
    /// An absolute path inside a tree, outside every folder the user allowed.
    #[error(
        "{path}: absolute paths are not allowed in a tree (write the path relative to the tree's \
         folder, or allow a folder with --allow-path DIR)"
    )]
    Absolute {
        /// The path as written.
        path: String,
    },
    /// A path that leaves the tree's folder (through `..` or a symbolic link).
    #[error(
        "{path}: outside the folder of the tree file ({}), through '..' or a symbolic link; \
         allow another folder with --allow-path DIR",
        .folder.display()
    )]
    Outside {
        /// The path as written.
        path: String,
        /// The folder it had to stay in.
        folder: PathBuf,
    },
    /// An empty path.
    #[error("empty file path")]
    Empty,
    /// Not a regular file (a directory, device, FIFO or socket).
    #[error("{}: not a regular file ({kind}); only regular files are read", .path.display())]
    NotRegular {
        /// The file.
        path: PathBuf,
        /// What it is instead.
        kind: &'static str,
    },
    /// Larger than the cap.
    #[error(
        "{}: file too large ({size} bytes; the limit is {limit} bytes)",
        .path.display()
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size (at least this many bytes).
        size: u64,
        /// The cap.
        limit: u64,
    },
    /// The operating system refused (missing file, no permission, ...).
    #[error("{}: {source}", .path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the operating system reported.
        source: std::io::Error,
    },
}

impl FileError {
    fn io(path: &Path, source: std::io::Error) -> Self {
        FileError::Io {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// What a non-regular file is, in a word.
fn kind_of(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else if t.is_symlink() {
        "a symbolic link"
    } else {
        "not a plain file"
    }
}

/// Opens `path` for reading without blocking on a FIFO that was put there after the check.
fn open_nonblocking(path: &Path) -> std::io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

/// Reads the whole of `path`, which must be a regular file (symbolic links are followed) of at
/// most `max_bytes` bytes.
///
/// The type and size are checked before the file is opened and again on the open file, and at
/// most `max_bytes + 1` bytes are ever read.
pub fn read_regular_file(path: &Path, max_bytes: u64) -> Result<Vec<u8>, FileError> {
    let meta = std::fs::metadata(path).map_err(|e| FileError::io(path, e))?;
    check_regular(path, &meta, max_bytes)?;
    let file = open_nonblocking(path).map_err(|e| FileError::io(path, e))?;
    let meta = file.metadata().map_err(|e| FileError::io(path, e))?;
    check_regular(path, &meta, max_bytes)?;
    let mut bytes = Vec::with_capacity(meta.len().min(max_bytes) as usize);
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| FileError::io(path, e))?;
    if bytes.len() as u64 > max_bytes {
        return Err(FileError::TooLarge {
            path: path.to_path_buf(),
            size: bytes.len() as u64,
            limit: max_bytes,
        });
    }
    Ok(bytes)
}

fn check_regular(path: &Path, meta: &std::fs::Metadata, max_bytes: u64) -> Result<(), FileError> {
    if !meta.file_type().is_file() {
        return Err(FileError::NotRegular {
            path: path.to_path_buf(),
            kind: kind_of(meta.file_type()),
        });
    }
    if meta.len() > max_bytes {
        return Err(FileError::TooLarge {
            path: path.to_path_buf(),
            size: meta.len(),
            limit: max_bytes,
        });
    }
    Ok(())
}

/// Where the files named inside a tree (or script) are looked for and which ones may be read.
///
/// Relative paths start at the base folder (the tree file's folder). A confined access (the
/// default of [`FileAccess::new`]) accepts a relative path only if its canonical form (`..` and
/// symbolic links resolved) lies inside the base folder or an allowed folder, and an absolute
/// path only if it lies inside an allowed folder ([`FileAccess::allow`]).
/// [`FileAccess::unconfined`] accepts any path (for trusted inputs and library use).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileAccess {
    base: PathBuf,
    confined: bool,
    allowed: Vec<PathBuf>,
    max_bytes: u64,
}

impl FileAccess {
    /// Files relative to the folder `base`, confined to it.
    pub fn new(base: impl Into<PathBuf>) -> Self {
        let base = base.into();
        let base = if base.as_os_str().is_empty() {
            PathBuf::from(".")
        } else {
            base
        };
        Self {
            base,
            confined: true,
            allowed: Vec::new(),
            max_bytes: DEFAULT_MAX_FILE_BYTES,
        }
    }

    /// Files relative to the folder holding the file `tree`, confined to it.
    pub fn for_tree_file(tree: &Path) -> Self {
        Self::new(tree.parent().unwrap_or(Path::new("")))
    }

    /// Files relative to `base`, any path accepted (`..`, absolute paths, links anywhere).
    pub fn unconfined(base: impl Into<PathBuf>) -> Self {
        Self {
            confined: false,
            ..Self::new(base)
        }
    }

    /// Also accepts files inside the folder `dir` (which must exist; it is canonicalised now).
    pub fn allow(mut self, dir: &Path) -> Result<Self, FileError> {
        let canonical = std::fs::canonicalize(dir).map_err(|e| FileError::io(dir, e))?;
        let meta = std::fs::metadata(&canonical).map_err(|e| FileError::io(dir, e))?;
        if !meta.is_dir() {
            return Err(FileError::io(
                dir,
                std::io::Error::new(std::io::ErrorKind::NotADirectory, "not a directory"),
            ));
        }
        self.allowed.push(canonical);
        Ok(self)
    }

    /// The same access with another cap on file sizes.
    pub fn with_max_bytes(mut self, max_bytes: u64) -> Self {
        self.max_bytes = max_bytes;
        self
    }

    /// The folder relative paths start from.
    pub fn base(&self) -> &Path {
        &self.base
    }

    /// The cap on file sizes.
    pub fn max_bytes(&self) -> u64 {
        self.max_bytes
    }

    /// The file that `path` (as written in the tree) names, checked against the confinement; the
    /// canonical path when confined.
    pub fn resolve(&self, path: &str) -> Result<PathBuf, FileError> {
        if path.is_empty() {
            return Err(FileError::Empty);
        }
        let written = Path::new(path);
        let joined = self.base.join(written);
        if !self.confined {
            return Ok(joined);
        }
        let absolute = written.is_absolute() || written.has_root();
        // Refused before touching the file system, so not even the existence of a file outside
        // is revealed.
        if absolute && self.allowed.is_empty() {
            return Err(FileError::Absolute { path: path.into() });
        }
        if !absolute && self.allowed.is_empty() && escapes_lexically(written) {
            return Err(FileError::Outside {
                path: path.into(),
                folder: self.base.clone(),
            });
        }
        let canonical = std::fs::canonicalize(&joined).map_err(|e| FileError::io(&joined, e))?;
        if self.allowed.iter().any(|dir| canonical.starts_with(dir)) {
            return Ok(canonical);
        }
        if absolute {
            return Err(FileError::Absolute { path: path.into() });
        }
        let folder = std::fs::canonicalize(&self.base).map_err(|e| FileError::io(&self.base, e))?;
        if canonical.starts_with(&folder) {
            Ok(canonical)
        } else {
            Err(FileError::Outside {
                path: path.into(),
                folder: self.base.clone(),
            })
        }
    }

    /// The file `path` names (see [`resolve`](Self::resolve)) and its bytes, read by
    /// [`read_regular_file`] within the size cap.
    pub fn read(&self, path: &str) -> Result<(PathBuf, Vec<u8>), FileError> {
        let file = self.resolve(path)?;
        let bytes = read_regular_file(&file, self.max_bytes)?;
        Ok((file, bytes))
    }
}

/// Whether the relative path `path` climbs above its starting folder by its `..` components
/// alone (before any symbolic link is looked at).
fn escapes_lexically(path: &Path) -> bool {
    use std::path::Component;
    let mut depth = 0usize;
    for component in path.components() {
        match component {
            Component::Normal(_) => depth += 1,
            Component::ParentDir if depth == 0 => return true,
            Component::ParentDir => depth -= 1,
            Component::CurDir | Component::RootDir | Component::Prefix(_) => {}
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!(
            "solidkit-files-{name}-{}-{:?}",
            std::process::id(),
            std::thread::current().id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("tree/sub")).unwrap();
        std::fs::write(dir.join("tree/sub/a.obj"), "inside").unwrap();
        std::fs::write(dir.join("tree/b.obj"), "inside too").unwrap();
        std::fs::write(dir.join("secret.obj"), "outside").unwrap();
        dir
    }

    #[test]
    fn relative_paths_inside_the_folder_are_read() {
        let dir = temp_dir("inside");
        let access = FileAccess::new(dir.join("tree"));
        assert_eq!(access.read("sub/a.obj").unwrap().1, b"inside");
        // `..` that stays inside is fine.
        assert_eq!(access.read("sub/../b.obj").unwrap().1, b"inside too");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn absolute_paths_and_dot_dot_escapes_are_refused() {
        let dir = temp_dir("escape");
        let access = FileAccess::new(dir.join("tree"));
        let abs = dir.join("secret.obj");
        let e = access.read(abs.to_str().unwrap()).unwrap_err();
        assert!(matches!(e, FileError::Absolute { .. }), "{e}");
        assert!(e.to_string().contains("--allow-path"), "{e}");
        let e = access.read("../secret.obj").unwrap_err();
        assert!(matches!(e, FileError::Outside { .. }), "{e}");
        let e = access.read("sub/../../secret.obj").unwrap_err();
        assert!(matches!(e, FileError::Outside { .. }), "{e}");
        // A missing file outside is refused the same way: its existence is not revealed.
        let e = access.read("../missing.obj").unwrap_err();
        assert!(matches!(e, FileError::Outside { .. }), "{e}");
        // Allowing the parent folder lets both through.
        let allowed = access.clone().allow(&dir).unwrap();
        assert_eq!(allowed.read("../secret.obj").unwrap().1, b"outside");
        assert_eq!(allowed.read(abs.to_str().unwrap()).unwrap().1, b"outside");
        // Unconfined reads anything.
        let open = FileAccess::unconfined(dir.join("tree"));
        assert_eq!(open.read("../secret.obj").unwrap().1, b"outside");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn symbolic_links_are_resolved_before_the_check() {
        let dir = temp_dir("links");
        let access = FileAccess::new(dir.join("tree"));
        std::os::unix::fs::symlink(dir.join("secret.obj"), dir.join("tree/link.obj")).unwrap();
        std::os::unix::fs::symlink(&dir, dir.join("tree/up")).unwrap();
        std::os::unix::fs::symlink("sub/a.obj", dir.join("tree/ok.obj")).unwrap();
        for path in ["link.obj", "up/secret.obj", "up/tree/../secret.obj"] {
            let e = access.read(path).unwrap_err();
            assert!(matches!(e, FileError::Outside { .. }), "{path}: {e}");
        }
        assert_eq!(access.read("ok.obj").unwrap().1, b"inside");
        assert_eq!(access.read("up/tree/b.obj").unwrap().1, b"inside too");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn only_regular_files_within_the_cap_are_read() {
        let dir = temp_dir("regular");
        let e = read_regular_file(&dir, 100).unwrap_err();
        assert!(
            matches!(
                e,
                FileError::NotRegular {
                    kind: "a directory",
                    ..
                }
            ),
            "{e}"
        );
        let e = read_regular_file(Path::new("/dev/zero"), 100).unwrap_err();
        assert!(matches!(e, FileError::NotRegular { .. }), "{e}");
        std::os::unix::fs::symlink("/dev/zero", dir.join("tree/zero.stl")).unwrap();
        let access = FileAccess::new(dir.join("tree"))
            .allow(Path::new("/dev"))
            .unwrap();
        let e = access.read("zero.stl").unwrap_err();
        assert!(e.to_string().contains("not a regular file"), "{e}");
        let e = read_regular_file(&dir.join("tree/b.obj"), 4).unwrap_err();
        assert!(
            matches!(
                e,
                FileError::TooLarge {
                    size: 10,
                    limit: 4,
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("limit is 4 bytes"), "{e}");
        assert_eq!(
            read_regular_file(&dir.join("tree/b.obj"), 10)
                .unwrap()
                .len(),
            10
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
