//! Long calls from Python: the work runs with the GIL released on a worker thread (inside a
//! rayon pool of the requested size), while the calling thread wakes every few milliseconds to
//! run Python's signal handlers (so Ctrl-C raises KeyboardInterrupt) and to pass progress to the
//! caller's callback. When either raises, the work is cancelled through its token and awaited
//! before the exception propagates, so nothing runs on after the call returns.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::sync::{Condvar, Mutex};
use std::time::Duration;

/// How often the calling thread checks for signals and progress.
const POLL: Duration = Duration::from_millis(20);

/// The most threads a call may ask for, as a multiple of the cores.
const MAX_THREADS_PER_CORE: usize = 8;

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

/// A rayon pool of `threads` threads, checked against the machine (None: rayon's default).
pub fn pool(threads: Option<usize>) -> PyResult<rayon::ThreadPool> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut b = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        let max = cores * MAX_THREADS_PER_CORE;
        if n == 0 || n > max {
            return Err(PyValueError::new_err(format!(
                "threads must be 1 to {max} ({MAX_THREADS_PER_CORE} per core), got {n}"
            )));
        }
        b = b.num_threads(n);
    }
    b.build().map_err(crate::errors::other)
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
            pool.install(work)
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
