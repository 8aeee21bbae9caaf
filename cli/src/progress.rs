//! The progress bar of long meshing runs: the mesher's progress reports (octree levels, then
//! bricks, from worker threads) drawn by `indicatif` on standard error, only when it is a
//! terminal and only once a run has taken longer than [`DELAY`], so short runs and pipes stay
//! silent.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use solidkit_meshing::octree::{Progress, ProgressFn};
use std::io::IsTerminal;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// How long a run goes unreported before the bar appears.
pub const DELAY: Duration = Duration::from_millis(500);

/// A bar fed by the mesher's progress callback.
pub struct MeshProgress {
    bar: ProgressBar,
    start: Instant,
    shown: AtomicBool,
    visible: bool,
}

impl MeshProgress {
    /// A bar drawn on standard error if `enabled` and standard error is a terminal.
    pub fn new(enabled: bool) -> Arc<Self> {
        Self::with_visibility(enabled && std::io::stderr().is_terminal())
    }

    fn with_visibility(visible: bool) -> Arc<Self> {
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
        bar.set_style(
            ProgressStyle::with_template("{prefix:>6} [{bar:40}] {pos}/{len} {elapsed}")
                .unwrap_or_else(|_| ProgressStyle::default_bar())
                .progress_chars("=> "),
        );
        Arc::new(Self {
            bar,
            start: Instant::now(),
            shown: AtomicBool::new(false),
            visible,
        })
    }

    /// The callback to put in the mesher's options.
    pub fn callback(self: &Arc<Self>) -> ProgressFn {
        let me = Arc::clone(self);
        Arc::new(move |p: Progress| me.report(p))
    }

    fn report(&self, p: Progress) {
        if self.bar.prefix() != p.stage {
            self.bar.set_prefix(p.stage);
            self.bar.set_length(p.total as u64);
            self.bar.set_position(0);
        }
        if self.bar.length() != Some(p.total as u64) {
            self.bar.set_length(p.total as u64);
        }
        // Reports from several threads may arrive out of order: keep the largest.
        if p.done as u64 > self.bar.position() {
            self.bar.set_position(p.done as u64);
        }
        if self.visible
            && self.start.elapsed() >= DELAY
            && !self.shown.swap(true, Ordering::Relaxed)
        {
            self.bar
                .set_draw_target(ProgressDrawTarget::stderr_with_hz(10));
        }
    }

    /// Removes the bar (if it was drawn) before the report is printed.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_move_the_bar_per_stage_and_never_back() {
        let p = MeshProgress::with_visibility(false);
        let f = p.callback();
        f(Progress {
            stage: "octree",
            done: 3,
            total: 9,
        });
        assert_eq!((p.bar.prefix(), p.bar.position()), ("octree".into(), 3));
        f(Progress {
            stage: "bricks",
            done: 5,
            total: 40,
        });
        f(Progress {
            stage: "bricks",
            done: 4,
            total: 40,
        });
        assert_eq!(p.bar.prefix(), "bricks");
        assert_eq!((p.bar.position(), p.bar.length()), (5, Some(40)));
        // Never drawn when not visible, however long the run.
        assert!(!p.shown.load(Ordering::Relaxed));
        p.finish();
        assert!(p.bar.is_finished());
    }
}
