//! Running the installed OpenSCAD: found on `PATH` (or at `SOLIDKIT_OPENSCAD`), run in a private
//! temporary folder that is removed afterwards, killed after a time limit, its messages kept.
//! `.scad` files are read through it ([`crate::scad`]).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Why OpenSCAD could not be run to the end.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunError {
    /// No `openscad` on `PATH` (and `SOLIDKIT_OPENSCAD` unset).
    #[error(
        "openscad is not installed (it is needed for .scad files: install it, or export a .csg \
         file with 'openscad -o model.csg model.scad' and read that)"
    )]
    Missing,
    /// The program could not be started.
    #[error("{program}: {error}")]
    Start {
        /// The program.
        program: String,
        /// Why.
        error: std::io::Error,
    },
    /// It ran past the time limit and was killed.
    #[error("openscad did not finish within {0} s")]
    Timeout(u64),
    /// The temporary folder or its files.
    #[error("temporary files: {0}")]
    Io(#[from] std::io::Error),
}

/// The OpenSCAD to run: `SOLIDKIT_OPENSCAD` if set, else `openscad` on `PATH`.
pub fn find() -> Result<PathBuf, RunError> {
    if let Some(p) = std::env::var_os("SOLIDKIT_OPENSCAD") {
        return Ok(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH").ok_or(RunError::Missing)?;
    std::env::split_paths(&path)
        .map(|d| d.join("openscad"))
        .find(|p| p.is_file())
        .ok_or(RunError::Missing)
}

/// A private temporary folder, removed with everything in it when dropped.
#[derive(Debug)]
pub struct TempDir(PathBuf);

impl TempDir {
    /// A new empty folder in the system's temporary folder, named after `prefix`.
    pub fn new(prefix: &str) -> std::io::Result<TempDir> {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let base = std::env::temp_dir();
        loop {
            let n = NEXT.fetch_add(1, Ordering::Relaxed);
            let dir = base.join(format!("solidkit-{prefix}-{}-{n}", std::process::id()));
            match std::fs::create_dir(&dir) {
                Ok(()) => return Ok(TempDir(dir)),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(e),
            }
        }
    }

    /// The folder.
    pub fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// How a run ended.
#[derive(Debug)]
pub struct Finished {
    /// Its exit status.
    pub status: ExitStatus,
    /// What it printed on standard error (OpenSCAD's echo, warnings and errors).
    pub messages: String,
}

impl Finished {
    /// The last non-empty line of the messages (OpenSCAD's reason for failing).
    pub fn last_message(&self) -> &str {
        self.messages
            .lines()
            .rev()
            .map(str::trim)
            .find(|l| !l.is_empty())
            .unwrap_or("no message")
    }
}

/// Runs `program` with `args` in `dir` (its standard error saved there), killed after `limit`.
pub fn run(
    program: &Path,
    args: &[OsString],
    dir: &TempDir,
    limit: Duration,
) -> Result<Finished, RunError> {
    let log = dir.path().join("openscad-messages.txt");
    let mut child = Command::new(program)
        .args(args)
        .current_dir(dir.path())
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(std::fs::File::create(&log)?)
        .spawn()
        .map_err(|error| RunError::Start {
            program: program.display().to_string(),
            error,
        })?;
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait()? {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return Err(RunError::Timeout(limit.as_secs()));
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let messages = String::from_utf8_lossy(&std::fs::read(&log)?).into_owned();
    Ok(Finished { status, messages })
}
