//! Options and controls of sparse meshing: brick size, cancellation, progress, statistics.

use std::sync::Arc;

/// Largest brick size: local sample coordinates `0..=MAX_BRICK` fit in 4 bits each.
pub(crate) const MAX_BRICK: usize = 8;
use std::sync::atomic::{AtomicBool, Ordering};

/// A cancellation flag shared between the caller and a running mesher.
#[derive(Debug, Clone, Default)]
pub struct CancelToken(Arc<AtomicBool>);

impl CancelToken {
    /// A token not yet cancelled.
    pub fn new() -> Self {
        Self::default()
    }

    /// Asks the mesher to stop as soon as it can.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// True once [`CancelToken::cancel`] was called.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

/// The mesher stopped because its token was cancelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("meshing was cancelled")]
pub struct Cancelled;

/// A progress report: `done` of `total` units of `stage` are finished.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// `"octree"` (levels) or `"bricks"`.
    pub stage: &'static str,
    /// Units finished.
    pub done: usize,
    /// Units in all.
    pub total: usize,
}

/// A progress callback (called from worker threads).
pub type ProgressFn = Arc<dyn Fn(Progress) + Send + Sync>;

/// A monotonic clock the caller supplies: seconds since a fixed instant of its choice. The
/// meshers read no clock of their own (an embedder may have none, e.g. a browser build); without
/// one, every timing in [`MeshStats`] is 0.
pub type ClockFn = Arc<dyn Fn() -> f64 + Send + Sync>;

/// Options of sparse meshing.
#[derive(Clone)]
pub struct SparseOptions {
    /// Cells per side of a leaf brick (a power of two, at most 8; 8 by default).
    pub brick_cells: usize,
    /// Stops the mesher when cancelled.
    pub cancel: Option<CancelToken>,
    /// Receives progress reports.
    pub progress: Option<ProgressFn>,
    /// Times the stages ([`MeshStats`]' seconds); none: no clock is read.
    pub clock: Option<ClockFn>,
    /// Most leaf bricks the surface may cross (the memory budget: the mesh and its report grow
    /// with them). Above it the mesher stops after the octree, with an empty mesh and
    /// [`MeshStats::over_budget`] set. None: no limit.
    pub max_surface_bricks: Option<usize>,
}

impl Default for SparseOptions {
    fn default() -> Self {
        Self {
            brick_cells: 8,
            cancel: None,
            progress: None,
            clock: None,
            max_surface_bricks: None,
        }
    }
}

impl std::fmt::Debug for SparseOptions {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SparseOptions")
            .field("brick_cells", &self.brick_cells)
            .field("cancel", &self.cancel)
            .field("progress", &self.progress.is_some())
            .field("clock", &self.clock.is_some())
            .field("max_surface_bricks", &self.max_surface_bricks)
            .finish()
    }
}

impl SparseOptions {
    /// Whether `bricks` surface bricks are more than the budget allows.
    pub(crate) fn over_budget(&self, bricks: usize) -> bool {
        self.max_surface_bricks.is_some_and(|max| bricks > max)
    }

    /// The caller's clock reading, or 0 without a clock.
    pub(crate) fn now(&self) -> f64 {
        now(self.clock.as_ref())
    }

    pub(crate) fn is_cancelled(&self) -> bool {
        self.cancel.as_ref().is_some_and(CancelToken::is_cancelled)
    }

    /// The brick size in cells (a power of two).
    pub(crate) fn brick_size(&self) -> usize {
        self.brick_cells.clamp(1, MAX_BRICK).next_power_of_two()
    }

    pub(crate) fn report(&self, p: Progress) {
        if let Some(f) = &self.progress {
            f(p);
        }
    }
}

/// What sparse meshing did.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MeshStats {
    /// Octree boxes whose interval was evaluated.
    pub boxes_evaluated: u64,
    /// Leaf bricks the surface may cross.
    pub surface_bricks: usize,
    /// Grid samples evaluated (points).
    pub samples_evaluated: u64,
    /// Sum over leaf bricks of their pruned program length (for the mean).
    pub leaf_instructions: u64,
    /// Seconds spent classifying and pruning octree boxes.
    pub octree_s: f64,
    /// Seconds spent sampling and triangulating leaf bricks.
    pub bricks_s: f64,
    /// Seconds of field evaluation (pruned programs) inside the bricks, summed over threads.
    pub evaluation_cpu_s: f64,
    /// Seconds spent numbering and emitting the mesh.
    pub assemble_s: f64,
    /// Features the grid thins or misses, over all leaf bricks ([`super::thin`]).
    pub thin: super::ThinCounts,
    /// The surface bricks were more than [`SparseOptions::max_surface_bricks`]: nothing was
    /// meshed (the mesh is empty; `surface_bricks` says how many there were).
    pub over_budget: bool,
    /// The mesh is free of self-intersections by construction ([`crate::marching_cubes::disjoint`]):
    /// every vertex strictly inside its rounded grid edge, every cell with a centre vertex tested
    /// locally and passed, no orphan edge; for dual contouring, the premises of its certificate
    /// (`dual_contouring/claim.rs`). `false` for the empty run of an over-budget grid.
    pub intersection_free: bool,
}

/// The reading of `clock`, or 0 without one.
pub(crate) fn now(clock: Option<&ClockFn>) -> f64 {
    clock.map_or(0.0, |c| c())
}
