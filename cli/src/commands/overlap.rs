//! The report while the disk catches up: `solidkit mesh` writes its mesh file under a temporary
//! name first (`io::stage_atomic`), then computes the report while a thread of its own waits
//! for the file to reach the disk (`fsync`, pure waiting: hundreds of milliseconds for a large
//! STL), and renames the file into place only once the report is printed. The formatting and the
//! kernel's copy of the bytes stay before the report, so the two never compete for the cores.

use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::{MeshIoError, StagedFile};
use std::time::Instant;

/// What [`report_while_syncing`] gives back.
pub(super) struct Overlapped {
    /// The report.
    pub(super) report: TopologyReport,
    /// Seconds the report took.
    pub(super) report_s: f64,
    /// How the early sync of the staged file went, when there was one.
    pub(super) synced: Option<Result<(), MeshIoError>>,
}

/// Runs `report` on this thread and syncs `staged` (when given) on a scoped thread of its own; a
/// panic in either goes on unwinding here.
pub(super) fn report_while_syncing(
    report: impl FnOnce() -> TopologyReport,
    staged: Option<&StagedFile>,
) -> Overlapped {
    std::thread::scope(|scope| {
        let syncer = staged.map(|file| scope.spawn(|| file.sync()));
        let start = Instant::now();
        let report = report();
        let report_s = start.elapsed().as_secs_f64();
        let synced = syncer.map(|s| s.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        Overlapped {
            report,
            report_s,
            synced,
        }
    })
}

/// Puts the staged file in place: the staging's error, else the early sync's (a failed `fsync`
/// must not be retried as if nothing happened), else the commit's.
pub(super) fn commit(
    staged: Result<StagedFile, MeshIoError>,
    synced: Option<Result<(), MeshIoError>>,
) -> Result<(), MeshIoError> {
    let file = staged?;
    synced.unwrap_or(Ok(()))?;
    file.commit()
}
