//! Why the pipeline made no mesh.

use crate::grid::GridError;
use crate::octree::Cancelled;

/// Why [`super::mesh_solid`] made no mesh.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PipelineError {
    /// The solid (or its clipped part) has an empty bounding box.
    #[error("the solid is empty (its bounding box is empty)")]
    Empty,
    /// The solid is unbounded and no clipping box was given.
    #[error("the solid is unbounded; give meshing bounds with --bounds x0,y0,z0,x1,y1,z1")]
    Unbounded,
    /// A tolerance was given for a mesher that does not simplify.
    #[error("--tolerance needs --method dc")]
    ToleranceNeedsDc,
    /// The grid cannot be made.
    #[error(transparent)]
    Grid(#[from] GridError),
    /// The mesh would need more memory than the budget ([`super::MeshOptions::max_memory`]).
    #[error(
        "meshing needs about {} MiB ({bricks} surface bricks at about {} KiB each), above the memory limit of {} MiB; lower --resolution or raise --max-memory",
        .predicted >> 20, super::BYTES_PER_BRICK >> 10, .limit >> 20
    )]
    OverMemory {
        /// Leaf bricks the surface crosses at this resolution.
        bricks: usize,
        /// Predicted peak memory in bytes.
        predicted: u64,
        /// The budget in bytes.
        limit: u64,
    },
    /// The caller cancelled the run.
    #[error(transparent)]
    Cancelled(#[from] Cancelled),
}
