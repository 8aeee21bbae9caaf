//! Typed options of the meshing pipeline: which mesher, how fine, over which domain, and the
//! controls (refinement limits, cancellation, progress) the caller supplies.

use crate::grid::GridSpec;
use crate::octree::{CancelToken, ClockFn, ProgressFn, SparseOptions};
use crate::refine::RefineOptions;
use solidkit_kernel::Aabb;

/// How the zero set is polygonized.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Marching cubes on the sparse octree (the default).
    #[default]
    Mc,
    /// Dual contouring on the sparse octree (sharp features; optional simplification).
    Dc,
}

impl Method {
    /// The short name used on the command line and in reports: `"mc"` or `"dc"`.
    pub fn name(self) -> &'static str {
        match self {
            Method::Mc => "mc",
            Method::Dc => "dc",
        }
    }
}

/// Where the grid lies.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Domain {
    /// The solid's bounding box, padded by one cell on every side (what `solidkit mesh` does).
    Solid,
    /// The solid clipped to this box (so the mesh is closed even for an unbounded solid), over
    /// the clipped bounding box, padded by one cell.
    Clip(Aabb),
    /// Exactly `resolution` cells along the longest side of this box, from its minimum corner,
    /// without padding or clipping (the benchmark convention: 256 cells over [-1, 1]³).
    Covering(Aabb),
    /// This grid, as given (the resolution is not used).
    Grid(GridSpec),
}

/// Options of [`super::mesh_solid`] and [`super::Prepared`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct MeshOptions {
    /// The polygonizer.
    pub method: Method,
    /// Cells along the longest side of the domain.
    pub resolution: usize,
    /// The grid's domain.
    pub domain: Domain,
    /// Dual contouring's simplification tolerance (world units); only with [`Method::Dc`].
    pub tolerance: Option<f64>,
    /// Simplify the mesh afterwards by edge collapses within this distance of it (world units;
    /// [`crate::simplify`]), for either method.
    pub simplify: Option<f64>,
    /// Limits of refinement for features thinner than a cell (`max_factor: 1` turns it off).
    pub refine: RefineOptions,
    /// Octree brick size, cancellation and progress.
    pub sparse: SparseOptions,
    /// Most memory the mesh and its report may be predicted to need, in bytes (from the
    /// surface bricks, before meshing; refinement stops below it). None: no limit.
    pub max_memory: Option<u64>,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions::new(128)
    }
}

impl MeshOptions {
    /// Marching cubes over the solid's bounding box at `resolution`, default refinement.
    pub fn new(resolution: usize) -> Self {
        MeshOptions {
            method: Method::Mc,
            resolution,
            domain: Domain::Solid,
            tolerance: None,
            simplify: None,
            refine: RefineOptions::default(),
            sparse: SparseOptions::default(),
            max_memory: None,
        }
    }

    /// With the polygonizer `method`.
    pub fn method(mut self, method: Method) -> Self {
        self.method = method;
        self
    }

    /// With the grid's domain.
    pub fn domain(mut self, domain: Domain) -> Self {
        self.domain = domain;
        self
    }

    /// With dual contouring's simplification tolerance.
    pub fn tolerance(mut self, tolerance: Option<f64>) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// With a simplification pass within `tolerance` of the mesh (None: none).
    pub fn simplify(mut self, tolerance: Option<f64>) -> Self {
        self.simplify = tolerance;
        self
    }

    /// With these refinement limits.
    pub fn refine(mut self, refine: RefineOptions) -> Self {
        self.refine = refine;
        self
    }

    /// Without refinement: one run at the requested grid, thin features only reported.
    pub fn no_refinement(mut self) -> Self {
        self.refine.max_factor = 1;
        self
    }

    /// Refused (or refinement stopped) when the mesh is predicted to need more than `bytes`.
    pub fn max_memory(mut self, bytes: Option<u64>) -> Self {
        self.max_memory = bytes;
        self
    }

    /// Stopped when `token` is cancelled.
    pub fn cancel(mut self, token: CancelToken) -> Self {
        self.sparse.cancel = Some(token);
        self
    }

    /// Timing the mesher's stages with `clock` (seconds; the stage timings of
    /// [`crate::octree::MeshStats`] are 0 without one: no clock is read here).
    pub fn clock(mut self, clock: ClockFn) -> Self {
        self.sparse.clock = Some(clock);
        self
    }

    /// Reporting progress to `progress`.
    pub fn progress(mut self, progress: ProgressFn) -> Self {
        self.sparse.progress = Some(progress);
        self
    }
}
