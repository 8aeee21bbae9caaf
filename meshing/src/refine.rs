//! Refinement below the requested resolution where the grid thins or misses features.
//!
//! Every leaf brick reports what its samples cannot hold ([`crate::octree::thin`]). When that
//! says a feature is lost, or thin features run all along the surface (a plate or a wall thinner
//! than two cells), the whole model is meshed again on a grid twice as fine, nested in the first
//! (every sample of the coarse grid is a sample of the fine one), and again, until the features
//! are held, the depth limit (default 32 times finer) or the work budget (samples evaluated) is
//! reached. The sparse octree only samples near the surface, so a finer grid costs in proportion
//! to the surface area, and models without thin features pay only the scan.
//!
//! Deviation from a locally adaptive octree: refinement is global (the whole surface is meshed at
//! the finer cell), which keeps every guarantee of the uniform grid (closed, manifold, no
//! self-intersections, sparse == dense, crack-free by construction) at the price of more
//! triangles than a local refinement would make. What is left (limit or budget hit, or a solid
//! that meshes empty while the search found points inside it) is reported in [`Refined::warnings`].

use crate::IndexedMesh;
use crate::grid::GridSpec;
use crate::grid::MAX_CELLS_PER_AXIS;
use crate::octree::{Cancelled, MeshStats};

/// Limits of refinement.
#[derive(Debug, Clone, Copy)]
pub struct RefineOptions {
    /// Largest refinement factor (a power of two; 1 turns refinement off). Default 32.
    pub max_factor: usize,
    /// Most samples one refined run may be expected to evaluate. Default 64 million.
    pub budget_samples: u64,
}

impl Default for RefineOptions {
    fn default() -> Self {
        RefineOptions {
            max_factor: 32,
            budget_samples: 64_000_000,
        }
    }
}

/// A mesh with the grid it was made on and what refinement did.
#[derive(Debug)]
pub struct Refined {
    /// The mesh.
    pub mesh: IndexedMesh,
    /// Statistics of the last run (the one that made the mesh).
    pub stats: MeshStats,
    /// The grid of the last run.
    pub spec: GridSpec,
    /// How many times finer than the requested grid (1: not refined).
    pub factor: usize,
    /// Samples evaluated over all runs.
    pub samples_total: u64,
    /// Whether the mesh is empty though the search found the solid's inside.
    pub lost_solid: bool,
    /// What may be missing, one line each.
    pub warnings: Vec<String>,
}

/// The grid `factor` times finer than `spec`, nested in it.
pub fn finer(spec: &GridSpec, factor: usize) -> Option<GridSpec> {
    let cells = spec.cells.map(|c| c.saturating_mul(factor));
    (cells.iter().all(|&c| c <= MAX_CELLS_PER_AXIS)).then(|| GridSpec {
        origin: spec.origin,
        cell: spec.cell / factor as f64,
        cells,
    })
}

/// Meshes with `mesh_at` on `spec`, then on finer grids while the scan asks for it (see the
/// module docs).
pub fn mesh_refined(
    spec: GridSpec,
    opts: &RefineOptions,
    mut mesh_at: impl FnMut(GridSpec) -> Result<(IndexedMesh, MeshStats), Cancelled>,
) -> Result<Refined, Cancelled> {
    let (mut mesh, mut stats) = mesh_at(spec)?;
    let mut samples_total = stats.samples_evaluated;
    let mut factor = 1;
    let mut fine = spec;
    let mut warnings = Vec::new();
    while stats.thin.needs_refinement() {
        let next = factor * 2;
        let expected = stats.samples_evaluated.saturating_mul(4);
        let why = if next > opts.max_factor.max(1) {
            Some(format!(
                "the refinement limit ({} times finer)",
                opts.max_factor.max(1)
            ))
        } else if expected > opts.budget_samples {
            Some(format!(
                "the refinement budget ({} samples; the next level needs about {expected})",
                opts.budget_samples
            ))
        } else {
            None
        };
        let finer_run = match finer(&spec, next).filter(|_| why.is_none()) {
            Some(grid) => Some((grid, mesh_at(grid)?)),
            None => None,
        };
        // A finer run over the memory budget meshed nothing: keep this one.
        let why = match &finer_run {
            Some((_, (_, s))) if s.over_budget => Some(format!(
                "the memory limit ({} surface bricks at the next level)",
                s.surface_bricks
            )),
            _ => why,
        };
        let Some((grid, (finer_mesh, finer_stats))) = finer_run.filter(|_| why.is_none()) else {
            let t = &stats.thin;
            let at = t
                .example
                .map(|p| format!(" (one near {:.6}, {:.6}, {:.6})", p[0], p[1], p[2]))
                .unwrap_or_default();
            warnings.push(format!(
                "features thinner than the cell {:.6} remain: {} lost ({} of a fifth of the cell or more), {} cut below the cell size, {} samples one cell thick{at}; stopped by {}; raise --resolution",
                fine.cell,
                t.detached,
                t.detached_substantial,
                t.attached,
                t.isolated_samples,
                why.unwrap_or_else(|| "the grid size limit".into()),
            ));
            break;
        };
        factor = next;
        fine = grid;
        (mesh, stats) = (finer_mesh, finer_stats);
        samples_total += stats.samples_evaluated;
    }
    let lost_solid = mesh.triangles.is_empty() && stats.thin.detached > 0;
    if lost_solid {
        warnings.push(
            "the solid is inside somewhere (the feature search found points inside it) but the mesh is empty".into(),
        );
    }
    Ok(Refined {
        mesh,
        stats,
        spec: fine,
        factor,
        samples_total,
        lost_solid,
        warnings,
    })
}
