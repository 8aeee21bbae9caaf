//! The meshing pipeline, the one path from a solid to a mesh: domain → grid → program → mesher
//! (with refinement where features are thinner than a cell) → mesh and warnings. The command
//! line's `mesh` and `bench`, the generators and the tests all go through it.
//!
//! [`Prepared::new`] does everything before meshing (clipping, the grid, lowering the tree to a
//! [`Program`], warnings about the operands) so a caller can report them early; [`Prepared::mesh`]
//! runs the mesher; [`mesh_solid`] does both. The caller times the stages if it wants to (no
//! clock is read here) and runs them in the thread pool of its choice.
//!
//! ```
//! use solidkit_kernel::Solid;
//! use solidkit_meshing::pipeline::{MeshOptions, mesh_solid};
//!
//! let solid = Solid::sphere(1.0);
//! let meshed = mesh_solid(&solid, &MeshOptions::new(32)).unwrap();
//! let report = meshed.report(&Default::default());
//! assert!(report.closed && report.manifold);
//! assert_eq!(report.shells, 1);
//! ```

mod error;
pub mod limits;
mod net;
mod options;
pub mod warnings;

pub use error::PipelineError;
pub use options::{Domain, MeshOptions, Method};

use crate::IndexedMesh;
use crate::dual_contouring::{DcOptions, mesh_dc};
use crate::grid::GridSpec;
use crate::octree::{MeshStats, mesh_sparse};
use crate::refine::mesh_refined;
use crate::simplify::{SimplifyOptions, SimplifyStats, simplify};
use crate::{ReportOptions, TopologyReport};
use solidkit_kernel::{Aabb, Program, Solid};

/// Predicted peak memory per leaf brick the surface crosses, in bytes: the mesh, the mesher's
/// buffers and the topology report (measured: 46 KiB for a sphere, 84 KiB for the gyroid-sphere
/// at 256 cells, 171 KiB at 128 cells, where its bricks hold the most triangles).
pub const BYTES_PER_BRICK: u64 = 128 << 10;

/// A solid ready to mesh: clipped to its domain, its grid chosen and its program compiled.
#[derive(Debug)]
pub struct Prepared {
    options: MeshOptions,
    spec: GridSpec,
    program: Program,
    /// Warnings about the solid itself (open mesh operands), before any meshing.
    pub warnings: Vec<String>,
    /// The warning that the solid reaches the grid's edge, where it is cut (see `net`); the
    /// mesh's warnings start with it.
    cut_warning: Option<String>,
}

impl Prepared {
    /// Clips `solid` to the domain of `options`, chooses the grid and compiles the program.
    pub fn new(solid: &Solid, options: &MeshOptions) -> Result<Prepared, PipelineError> {
        let warnings = warnings::open_operands(solid);
        let clipped;
        let (solid, grid) = match options.domain {
            Domain::Solid => (solid, Grid::Padded(solid.bbox())),
            Domain::Clip(clip) => {
                // Explicit bounds clip the solid, so the mesh is closed even for unbounded solids.
                clipped = solid.intersection(&Solid::cuboid(clip.size()).translate(clip.center()));
                let bounds = clip.intersection(&clipped.bbox());
                (&clipped, Grid::Padded(bounds))
            }
            Domain::Covering(domain) => (solid, Grid::Covering(domain)),
            Domain::Grid(spec) => (solid, Grid::Given(spec)),
        };
        if let Grid::Padded(bounds) = &grid {
            if bounds.is_empty() {
                return Err(PipelineError::Empty);
            }
            if !bounds.is_finite() {
                return Err(PipelineError::Unbounded);
            }
        }
        if options.tolerance.is_some() && options.method != Method::Dc {
            return Err(PipelineError::ToleranceNeedsDc);
        }
        let (spec, padded) = match grid {
            Grid::Padded(bounds) => (GridSpec::for_bounds(&bounds, options.resolution)?, true),
            Grid::Covering(domain) => (GridSpec::covering(&domain, options.resolution)?, false),
            Grid::Given(spec) => (spec, false),
        };
        let program = solid.compile();
        let mut cut_warning = None;
        let program = if padded {
            // A grid padded around the solid's box: cut the solid half a cell inside the grid's
            // edge, so the mesh is closed even where the box is wrong, and say so if it was.
            if net::reaches_edge(&program, &spec) {
                cut_warning = Some(warnings::beyond_box(&solid.bbox()));
            }
            let cut = net::inner_box(&spec);
            solid
                .intersection(&Solid::cuboid(cut.size()).translate(cut.center()))
                .compile()
        } else {
            program
        };
        Ok(Prepared {
            options: options.clone(),
            spec,
            program,
            warnings,
            cut_warning,
        })
    }

    /// The grid the mesher starts from (refinement may nest finer ones in it).
    pub fn spec(&self) -> &GridSpec {
        &self.spec
    }

    /// The compiled program of the (clipped) solid.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// Meshes: the chosen mesher on the grid, then on finer nested grids while features are
    /// thinner than a cell (within the refinement limits).
    pub fn mesh(&self) -> Result<Meshed, PipelineError> {
        let mut options = self.options.clone();
        if let Some(limit) = options.max_memory {
            options.sparse.max_surface_bricks = Some((limit / BYTES_PER_BRICK) as usize);
        }
        let o = &options;
        let dc = DcOptions {
            tolerance: o.tolerance,
            sparse: o.sparse.clone(),
        };
        let refined = mesh_refined(self.spec, &o.refine, |grid| match o.method {
            Method::Mc => mesh_sparse(&self.program, grid, &o.sparse),
            Method::Dc => mesh_dc(&self.program, grid, &dc),
        })?;
        if refined.stats.over_budget {
            let bricks = refined.stats.surface_bricks;
            return Err(PipelineError::OverMemory {
                bricks,
                predicted: bricks as u64 * BYTES_PER_BRICK,
                // The budget as given, or as the brick limit a caller set on `sparse` directly.
                limit: o.max_memory.unwrap_or_else(|| {
                    o.sparse.max_surface_bricks.unwrap_or(0) as u64 * BYTES_PER_BRICK
                }),
            });
        }
        let mut stats = refined.stats;
        let (mesh, simplified) = match o.simplify {
            Some(tolerance) => {
                let options = SimplifyOptions {
                    tolerance,
                    spacing: refined.spec.cell,
                };
                let (mesh, s) = simplify(&refined.mesh, &self.program, &options);
                // The mesher's certificate was for its own triangles; the report tests these.
                stats.intersection_free &= s.collapses == 0;
                (mesh, Some(s))
            }
            None => (refined.mesh, None),
        };
        Ok(Meshed {
            mesh,
            stats,
            simplified,
            spec: refined.spec,
            factor: refined.factor,
            samples_total: refined.samples_total,
            lost_solid: refined.lost_solid,
            warnings: self
                .cut_warning
                .iter()
                .cloned()
                .chain(refined.warnings)
                .collect(),
            program_length: self.program.len(),
        })
    }
}

/// Where [`Prepared::new`] takes its grid from.
enum Grid {
    /// `GridSpec::for_bounds` of these bounds (refused when empty or unbounded).
    Padded(Aabb),
    /// `GridSpec::covering` of this box.
    Covering(Aabb),
    /// As given.
    Given(GridSpec),
}

/// A mesh made by the pipeline, with what the mesher and refinement did.
#[derive(Debug)]
#[non_exhaustive]
pub struct Meshed {
    /// The mesh.
    pub mesh: IndexedMesh,
    /// Statistics of the run that made the mesh.
    pub stats: MeshStats,
    /// The grid of that run.
    pub spec: GridSpec,
    /// How many times finer than the requested grid (1: not refined).
    pub factor: usize,
    /// Samples evaluated over all runs.
    pub samples_total: u64,
    /// Whether the mesh is empty though the feature search found the solid's inside.
    pub lost_solid: bool,
    /// What may be missing (refinement stopped by a limit, a lost solid), one line each.
    pub warnings: Vec<String>,
    /// Instructions in the solid's compiled program.
    pub program_length: usize,
    /// What the simplification pass did, when there was one.
    pub simplified: Option<SimplifyStats>,
}

impl Meshed {
    /// The topology report of the mesh. Self-intersections are known to be none by construction
    /// when the mesher certified the run ([`MeshStats::intersection_free`]: marching cubes or
    /// dual contouring whose conditions held), and tested otherwise.
    pub fn report(&self, options: &ReportOptions) -> TopologyReport {
        TopologyReport::with_certificate(&self.mesh, options, self.stats.intersection_free)
    }
}

/// [`Prepared::new`] then [`Prepared::mesh`]; the solid's own warnings come first in
/// [`Meshed::warnings`].
pub fn mesh_solid(solid: &Solid, options: &MeshOptions) -> Result<Meshed, PipelineError> {
    let prepared = Prepared::new(solid, options)?;
    let mut meshed = prepared.mesh()?;
    let mut warnings = prepared.warnings;
    warnings.append(&mut meshed.warnings);
    meshed.warnings = warnings;
    Ok(meshed)
}
