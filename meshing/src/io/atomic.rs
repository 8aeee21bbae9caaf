//! Atomic file output: write everything to a temporary file next to the target, then rename it
//! over the target.
//!
//! Readers of the target see either the old file or the complete new one, never a truncated or
//! half-written file: on any error (or a panic inside the writer) the temporary file is removed
//! and an existing target is left untouched.

use std::fs::{File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{SystemTime, UNIX_EPOCH};

use super::MeshIoError;

/// How many temporary names are tried before giving up (names collide only with leftovers or
/// concurrent writers).
const NAME_ATTEMPTS: u32 = 64;

/// Writes a file atomically: `write` produces the whole content into a buffered temporary file in
/// the same folder as `path` (named `.NAME.XXXX.tmp`), which is flushed, synced to disk and then
/// renamed over `path`.
///
/// If `write` fails (or panics), or flushing, syncing or renaming fails, the temporary file is
/// removed, `path` is not created and a file already at `path` keeps its old content. The
/// permissions of a replaced file are not carried over: the new file gets the default ones.
pub fn write_atomic(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), MeshIoError> {
    write_then_rename(path, write).map_err(|source| MeshIoError::Io {
        path: path.to_path_buf(),
        source,
    })
}

fn write_then_rename(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> io::Result<()> {
    let (file, temp) = create_temp_beside(path)?;
    let mut out = BufWriter::new(file);
    write(&mut out)?;
    let file = out.into_inner().map_err(io::IntoInnerError::into_error)?;
    file.sync_all()?;
    drop(file);
    std::fs::rename(&temp.path, path)?;
    temp.keep();
    sync_parent_folder(path);
    Ok(())
}

/// A temporary file that is deleted when dropped, unless [`TempFile::keep`] was called.
struct TempFile {
    path: PathBuf,
    armed: bool,
}

impl TempFile {
    /// The file was renamed into place: nothing to clean up.
    fn keep(mut self) {
        self.armed = false;
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if self.armed {
            // Best effort: the original error is what the caller needs to see.
            let _ = std::fs::remove_file(&self.path);
        }
    }
}

/// Creates a new, empty temporary file in the folder of `target`.
fn create_temp_beside(target: &Path) -> io::Result<(File, TempFile)> {
    let name = target.file_name().ok_or_else(|| {
        io::Error::new(io::ErrorKind::InvalidInput, "the path does not name a file")
    })?;
    let folder = match target.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    let mut last_error = None;
    for _ in 0..NAME_ATTEMPTS {
        let mut temp_name = std::ffi::OsString::from(".");
        temp_name.push(name);
        temp_name.push(format!(".{}.tmp", unique_suffix()));
        let temp_path = folder.join(temp_name);
        match OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temp_path)
        {
            Ok(file) => {
                let guard = TempFile {
                    path: temp_path,
                    armed: true,
                };
                return Ok((file, guard));
            }
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last_error = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last_error.unwrap_or_else(|| io::Error::other("no free temporary file name")))
}

/// A suffix that differs between processes, calls and (usually) runs.
fn unique_suffix() -> String {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let count = COUNTER.fetch_add(1, Ordering::Relaxed);
    let nanos = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    format!("{}-{count}-{nanos:08x}", std::process::id())
}

/// Makes the rename durable on Unix by syncing the folder entry (best effort).
fn sync_parent_folder(path: &Path) {
    #[cfg(unix)]
    {
        let folder = match path.parent() {
            Some(parent) if !parent.as_os_str().is_empty() => parent,
            _ => Path::new("."),
        };
        if let Ok(dir) = File::open(folder) {
            let _ = dir.sync_all();
        }
    }
    #[cfg(not(unix))]
    let _ = path;
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entries(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .expect("read temp dir")
            .map(|e| {
                e.expect("dir entry")
                    .file_name()
                    .to_string_lossy()
                    .into_owned()
            })
            .collect();
        names.sort();
        names
    }

    #[test]
    fn writes_the_whole_content_and_leaves_no_temp_file() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("out.json");
        write_atomic(&target, |w| w.write_all(b"{\"ok\":true}")).expect("write");
        assert_eq!(std::fs::read(&target).expect("read"), b"{\"ok\":true}");
        assert_eq!(entries(dir.path()), ["out.json"]);
    }

    #[test]
    fn failing_writer_leaves_no_file_behind() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("out.stl");
        let result = write_atomic(&target, |w| {
            w.write_all(&[7u8; 100_000])?;
            Err(io::Error::other("boom"))
        });
        let err = result.expect_err("the writer failed");
        assert!(matches!(err, MeshIoError::Io { .. }));
        assert!(err.to_string().contains("out.stl") && err.to_string().contains("boom"));
        assert!(entries(dir.path()).is_empty(), "{:?}", entries(dir.path()));
    }

    #[test]
    fn failing_writer_leaves_an_existing_target_unchanged() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("keep.obj");
        std::fs::write(&target, b"old content").expect("seed");
        let result = write_atomic(&target, |w| {
            w.write_all(b"new partial")?;
            Err(io::Error::other("disk on fire"))
        });
        assert!(result.is_err());
        assert_eq!(std::fs::read(&target).expect("read"), b"old content");
        assert_eq!(entries(dir.path()), ["keep.obj"]);
    }

    #[test]
    fn panicking_writer_leaves_no_temp_file() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("p.off");
        let outcome = std::panic::catch_unwind(|| {
            let _ = write_atomic(&target, |w| {
                w.write_all(b"partial")?;
                panic!("writer panicked");
            });
        });
        assert!(outcome.is_err());
        assert!(entries(dir.path()).is_empty());
    }

    #[test]
    fn replaces_an_existing_target() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("r.off");
        std::fs::write(&target, b"old").expect("seed");
        write_atomic(&target, |w| w.write_all(b"new")).expect("write");
        assert_eq!(std::fs::read(&target).expect("read"), b"new");
        assert_eq!(entries(dir.path()), ["r.off"]);
    }

    #[test]
    fn missing_folder_is_an_io_error_naming_the_target() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("no/such/folder/x.stl");
        let err = write_atomic(&target, |w| w.write_all(b"x")).expect_err("no folder");
        assert!(matches!(err, MeshIoError::Io { .. }));
        assert!(err.to_string().contains("x.stl"));
    }
}
