//! Atomic file output: write everything to a temporary file next to the target, then rename it
//! over the target.
//!
//! Readers of the target see either the old file or the complete new one, never a truncated or
//! half-written file: on any error (or a panic inside the writer) the temporary file is removed
//! and an existing target is left untouched.
//!
//! Destructors do not run when a signal ends the process, so the temporary files being written
//! are also listed in a registry: a program's signal handler calls
//! [`remove_temporary_files_and_exit`] (the `solidkit` binary does, for SIGINT, SIGTERM and
//! SIGHUP). Files left by a process that died anyway (SIGKILL, power loss) are removed by the
//! next write to the same target, once their writer's process is gone (Linux: `/proc`).

use std::fs::{File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard};
use std::time::{SystemTime, UNIX_EPOCH};

use super::MeshIoError;

/// Temporary files this process is writing (created, not yet renamed or removed).
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn pending() -> MutexGuard<'static, Vec<PathBuf>> {
    // A panic while holding the lock leaves a list that is still valid.
    PENDING.lock().unwrap_or_else(|e| e.into_inner())
}

fn unregister(path: &Path) {
    let mut list = pending();
    if let Some(i) = list.iter().position(|p| p == path) {
        list.swap_remove(i);
    }
}

/// Removes every temporary file this process is writing and exits with `code`, holding the
/// registry's lock so no writer can start another one meanwhile. For a signal handler that runs
/// as ordinary code (a thread woken by the signal, as `signal-hook`'s iterator does), since
/// destructors do not run when a signal ends the process.
pub fn remove_temporary_files_and_exit(code: i32) -> ! {
    let list = pending();
    for path in list.iter() {
        let _ = std::fs::remove_file(path);
    }
    std::process::exit(code)
}

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
    stage_atomic(path, write)?.commit()
}

/// The first half of [`write_atomic`]: the content written and flushed to its temporary file,
/// which [`StagedFile::commit`] then syncs and renames over `path`. Dropping the [`StagedFile`]
/// instead removes the temporary file and leaves `path` as it was.
///
/// Between the two a caller may work on something else while the disk catches up
/// ([`StagedFile::sync`] from another thread: `solidkit mesh` computes its report meanwhile) and
/// still decide afterwards whether the file appears at all.
pub fn stage_atomic(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<StagedFile, MeshIoError> {
    let stage = || {
        let (file, temp) = create_temp_beside(path)?;
        let mut out = BufWriter::new(file);
        write(&mut out)?;
        let file = out.into_inner().map_err(io::IntoInnerError::into_error)?;
        Ok((file, temp))
    };
    stage()
        .map(|(file, temp)| StagedFile {
            file,
            temp,
            target: path.to_path_buf(),
            synced: AtomicBool::new(false),
        })
        .map_err(|source| io_error(path, source))
}

/// A complete temporary file waiting to replace its target ([`stage_atomic`]); removed when
/// dropped uncommitted.
#[derive(Debug)]
pub struct StagedFile {
    file: File,
    temp: TempFile,
    target: PathBuf,
    /// Set by a successful [`StagedFile::sync`].
    synced: AtomicBool,
}

impl StagedFile {
    /// Waits until the content is on disk (`fsync`). Takes `&self`, so another thread may wait
    /// while this one goes on; [`Self::commit`] does it when nobody has.
    pub fn sync(&self) -> Result<(), MeshIoError> {
        self.file
            .sync_all()
            .map_err(|source| io_error(&self.target, source))?;
        self.synced.store(true, Ordering::Release);
        Ok(())
    }

    /// Syncs the file unless [`Self::sync`] already did, renames it over its target and syncs
    /// the folder entry (best effort).
    pub fn commit(self) -> Result<(), MeshIoError> {
        if !self.synced.load(Ordering::Acquire) {
            self.sync()?;
        }
        let Self {
            file, temp, target, ..
        } = self;
        drop(file);
        match std::fs::rename(&temp.path, &target) {
            Ok(()) => {
                temp.keep();
                sync_parent_folder(&target);
                Ok(())
            }
            Err(source) => Err(io_error(&target, source)),
        }
    }

    /// The path the file will have once committed.
    pub fn target(&self) -> &Path {
        &self.target
    }
}

/// An I/O error writing `path`.
fn io_error(path: &Path, source: io::Error) -> MeshIoError {
    MeshIoError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// A temporary file that is deleted when dropped, unless [`TempFile::keep`] was called.
#[derive(Debug)]
struct TempFile {
    path: PathBuf,
    armed: bool,
}

impl TempFile {
    /// The file was renamed into place: nothing to clean up.
    fn keep(mut self) {
        self.armed = false;
        unregister(&self.path);
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if self.armed {
            // Best effort: the original error is what the caller needs to see.
            let _ = std::fs::remove_file(&self.path);
            unregister(&self.path);
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
    remove_stale_temporaries(folder, name);
    let mut last_error = None;
    for _ in 0..NAME_ATTEMPTS {
        let mut temp_name = std::ffi::OsString::from(".");
        temp_name.push(name);
        temp_name.push(format!(".{}.tmp", unique_suffix()));
        let temp_path = folder.join(temp_name);
        // Listed before it exists, so a signal handler holding the list's lock either sees it
        // or keeps it from being created.
        pending().push(temp_path.clone());
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
            Err(e) => {
                unregister(&temp_path);
                if e.kind() != io::ErrorKind::AlreadyExists {
                    return Err(e);
                }
                last_error = Some(e);
            }
        }
    }
    Err(last_error.unwrap_or_else(|| io::Error::other("no free temporary file name")))
}

/// Removes the temporary files of `name` in `folder` (`.NAME.PID-COUNT-NANOS.tmp`) whose writing
/// process no longer runs: left by a process killed without a chance to clean up. Best effort,
/// and only where running processes can be told (Linux's `/proc`); files of running processes,
/// this one included, are left alone.
fn remove_stale_temporaries(folder: &Path, name: &std::ffi::OsStr) {
    let proc_root = Path::new("/proc");
    if !proc_root.join("self").exists() {
        return;
    }
    let Some(name) = name.to_str() else {
        return;
    };
    let prefix = format!(".{name}.");
    let Ok(entries) = std::fs::read_dir(folder) else {
        return;
    };
    for entry in entries.flatten() {
        let file_name = entry.file_name();
        let Some(rest) = file_name
            .to_str()
            .and_then(|f| f.strip_prefix(&prefix))
            .and_then(|f| f.strip_suffix(".tmp"))
        else {
            continue;
        };
        // PID-COUNT-NANOS, all digits (NANOS in hex): only our own names.
        let parts: Vec<&str> = rest.split('-').collect();
        let ours = parts.len() == 3
            && parts[0].bytes().all(|b| b.is_ascii_digit())
            && parts[1].bytes().all(|b| b.is_ascii_digit())
            && parts[2].bytes().all(|b| b.is_ascii_hexdigit())
            && parts.iter().all(|p| !p.is_empty());
        let is_file = entry.file_type().is_ok_and(|t| t.is_file());
        if ours && is_file && !proc_root.join(parts[0]).exists() {
            let _ = std::fs::remove_file(entry.path());
        }
    }
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
    fn a_staged_file_appears_only_when_committed() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("s.stl");
        std::fs::write(&target, b"old").expect("seed");
        // Dropped uncommitted: the temporary goes, the target keeps its content.
        let staged = stage_atomic(&target, |w| w.write_all(b"new")).expect("stage");
        assert_eq!(staged.target(), target.as_path());
        assert_eq!(entries(dir.path()).len(), 2, "{:?}", entries(dir.path()));
        assert_eq!(std::fs::read(&target).expect("read"), b"old");
        drop(staged);
        assert_eq!(entries(dir.path()), ["s.stl"]);
        assert_eq!(std::fs::read(&target).expect("read"), b"old");
        // Committed: the content replaces the target, nothing else is left.
        let staged = stage_atomic(&target, |w| w.write_all(b"new")).expect("stage");
        staged.commit().expect("commit");
        assert_eq!(std::fs::read(&target).expect("read"), b"new");
        assert_eq!(entries(dir.path()), ["s.stl"]);
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn stale_temporary_files_of_the_target_are_removed_by_the_next_write() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("out.stl");
        // A PID above Linux's maximum (2^22) never runs; our own PID does.
        let stale = dir.path().join(".out.stl.4194305-0-1f.tmp");
        let live = dir
            .path()
            .join(format!(".out.stl.{}-99-0.tmp", std::process::id()));
        let other_target = dir.path().join(".other.stl.4194305-0-1f.tmp");
        let not_ours = dir.path().join(".out.stl.notes.tmp");
        for p in [&stale, &live, &other_target, &not_ours] {
            std::fs::write(p, b"partial").expect("seed");
        }
        write_atomic(&target, |w| w.write_all(b"new")).expect("write");
        assert_eq!(std::fs::read(&target).expect("read"), b"new");
        assert!(!stale.exists(), "the stale file is left");
        for p in [&live, &other_target, &not_ours] {
            assert!(p.exists(), "{} was removed", p.display());
        }
        assert!(!pending().iter().any(|p| p.starts_with(dir.path())));
    }

    #[test]
    fn temporary_files_are_listed_while_written() {
        let dir = tempfile::tempdir().expect("temp dir");
        let target = dir.path().join("listed.off");
        write_atomic(&target, |w| {
            let list = pending();
            let mine: Vec<_> = list.iter().filter(|p| p.starts_with(dir.path())).collect();
            assert_eq!(mine.len(), 1, "{list:?}");
            assert!(mine[0].exists());
            w.write_all(b"x")
        })
        .expect("write");
        assert!(!pending().iter().any(|p| p.starts_with(dir.path())));
        let _ = write_atomic(&target, |_| Err(io::Error::other("fail")));
        assert!(!pending().iter().any(|p| p.starts_with(dir.path())));
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
