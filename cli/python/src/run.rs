//! Long calls from Python: the work runs with the GIL released on a worker thread (inside a
//! rayon pool of the requested size), while the calling thread wakes every few milliseconds to
//! run Python's signal handlers (so Ctrl-C raises KeyboardInterrupt) and to pass progress to the
//! caller's callback. When either raises, the work is cancelled through its token and awaited
//! before the exception propagates, so nothing runs on after the call returns.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

/// How often the calling thread checks for signals and progress.
const POLL: Duration = Duration::from_millis(20);

/// The most threads a call may ask for: this many per core, and at least [`MIN_MAX_THREADS`]
/// (the command line's `--threads` rule).
const MAX_THREADS_PER_CORE: usize = 16;

/// The thread limit on machines with few cores.
const MIN_MAX_THREADS: usize = 64;

/// The latest progress report of the work: stage, done, total; `None` once read.
#[derive(Default)]
pub struct ProgressSlot(Mutex<Option<(&'static str, usize, usize)>>);

impl ProgressSlot {
    /// Records a report (from any thread); the largest `done` of a stage wins.
    pub fn set(&self, stage: &'static str, done: usize, total: usize) {
        if let Ok(mut slot) = self.0.lock() {
            match *slot {
                Some((s, d, _)) if s == stage && d > done => {}
                _ => *slot = Some((stage, done, total)),
            }
        }
    }

    fn take(&self) -> Option<(&'static str, usize, usize)> {
        self.0.lock().ok().and_then(|mut s| s.take())
    }
}

/// Pools by thread count, built once (building one costs a thread start per worker).
static POOLS: Mutex<Vec<(usize, Arc<rayon::ThreadPool>)>> = Mutex::new(Vec::new());

/// A rayon pool of `threads` threads, checked against the machine (None: rayon's global pool,
/// all cores), built on first use and kept.
pub fn pool(threads: Option<usize>) -> PyResult<Option<Arc<rayon::ThreadPool>>> {
    let Some(n) = threads else {
        return Ok(None);
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let max = (cores * MAX_THREADS_PER_CORE).max(MIN_MAX_THREADS);
    if n == 0 || n > max {
        return Err(PyValueError::new_err(format!(
            "threads must be 1 to {max}, got {n}"
        )));
    }
    let mut pools = POOLS.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, p)) = pools.iter().find(|(k, _)| *k == n) {
        return Ok(Some(Arc::clone(p)));
    }
    let p = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(crate::errors::other)?,
    );
    pools.push((n, Arc::clone(&p)));
    Ok(Some(p))
}

/// Runs `work` in the pool of `threads` with the GIL released, on the calling thread (for short
/// calls that need no interruption).
pub fn detached<T: Send>(
    py: Python<'_>,
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> PyResult<T> {
    let pool = pool(threads)?;
    Ok(py.detach(|| match pool {
        Some(p) => p.install(work),
        None => work(),
    }))
}

/// Runs `work` in a pool of `threads` threads with the GIL released, polling for signals and
/// progress meanwhile; `cancel` asks the work to stop (it must then return soon).
pub fn interruptible<T: Send>(
    py: Python<'_>,
    threads: Option<usize>,
    progress: Option<(&Bound<'_, PyAny>, &ProgressSlot)>,
    cancel: &(dyn Fn() + Sync),
    work: impl FnOnce() -> T + Send,
) -> PyResult<T> {
    let pool = pool(threads)?;
    // Set by the worker when it ends (also by unwinding, through the guard).
    let done = (Mutex::new(false), Condvar::new());
    std::thread::scope(|scope| {
        let handle = scope.spawn(|| {
            let _guard = Finished(&done);
            match pool {
                Some(p) => p.install(work),
                None => work(),
            }
        });
        let mut raised: Option<PyErr> = None;
        loop {
            let finished = py.detach(|| {
                let flag = done.0.lock().unwrap_or_else(|e| e.into_inner());
                let (flag, _) = done
                    .1
                    .wait_timeout_while(flag, POLL, |f| !*f)
                    .unwrap_or_else(|e| e.into_inner());
                *flag
            });
            if finished {
                break;
            }
            if raised.is_some() {
                continue;
            }
            let mut check = py.check_signals();
            if check.is_ok()
                && let Some((callback, slot)) = progress
                && let Some((stage, done, total)) = slot.take()
            {
                check = callback.call1((stage, done, total)).map(|_| ());
            }
            if let Err(e) = check {
                cancel();
                raised = Some(e);
            }
        }
        let out = py.detach(|| handle.join());
        match (raised, out) {
            (Some(e), _) => Err(e),
            (None, Ok(v)) => Ok(v),
            (None, Err(_)) => Err(crate::errors::other(
                "internal error: a worker thread panicked (please report this input)",
            )),
        }
    })
}

/// Marks the work finished when dropped (normally or while unwinding).
struct Finished<'a>(&'a (Mutex<bool>, Condvar));

impl Drop for Finished<'_> {
    fn drop(&mut self) {
        let mut f = self.0.0.lock().unwrap_or_else(|e| e.into_inner());
        *f = true;
        self.0.1.notify_all();
    }
}
