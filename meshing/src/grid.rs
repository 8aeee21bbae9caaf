//! Uniform grids of cubic cells: where the samples are. Every mesher (dense and sparse marching
//! cubes, dual contouring, refinement, rebuild repair) takes a [`GridSpec`]; the grid is refused
//! ([`GridError`]) where single-precision sample coordinates could not represent it faithfully.

use crate::marching_cubes::sign::NOISE;
use glam::DVec3;
use solidkit_kernel::Aabb;

/// A uniform grid of cubic cells: `cells[a]` cells (so `cells[a] + 1` samples) along axis `a`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridSpec {
    /// Position of sample `(0, 0, 0)`.
    pub origin: DVec3,
    /// Edge length of a cell.
    pub cell: f64,
    /// Number of cells along x, y and z.
    pub cells: [usize; 3],
}

/// Why a grid cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GridError {
    /// The bounds are empty, infinite or NaN.
    #[error(
        "meshing bounds must be finite and non-empty (got {min:?} to {max:?}); give explicit bounds"
    )]
    BadBounds {
        /// Minimum corner given.
        min: [f64; 3],
        /// Maximum corner given.
        max: [f64; 3],
    },
    /// A resolution of zero.
    #[error("resolution must be at least 1")]
    ZeroResolution,
    /// More cells along an axis than vertex keys can address.
    #[error("grid of {cells:?} cells is too large (at most {limit} cells per axis)")]
    TooLarge {
        /// Cells per axis requested.
        cells: [usize; 3],
        /// The per-axis limit.
        limit: usize,
    },
    /// Sample coordinates beyond [`MAX_COORDINATE`]: their squares overflow single precision.
    #[error(
        "the meshing bounds reach {bound:e}, beyond single precision (coordinates up to ±5e18: their squares must stay below 3.4e38), where the samples are taken"
    )]
    BeyondSinglePrecision {
        /// The coordinate of largest magnitude.
        bound: f64,
    },
    /// Cells too small for the single precision the samples are taken in: sample values within
    /// [`NOISE`]` · (1 + |coordinate|)` of zero are rounding noise ([`crate::marching_cubes::snap_noise`]),
    /// so a cell must span several such bands for the surface to be placed faithfully.
    #[error(
        "cells of {cell:.3e} are too small for single-precision coordinates near {bound:.3e}: values \
         within {band:.3e} of zero are rounding noise there and a cell must span at least {min_bands} \
         such bands; lower the resolution or give bounds nearer the origin"
    )]
    BelowSinglePrecision {
        /// The cell size.
        cell: f64,
        /// The coordinate of largest magnitude.
        bound: f64,
        /// The noise band there.
        band: f64,
        /// The least number of noise bands per cell.
        min_bands: u32,
    },
}

/// The least number of single-precision noise bands ([`NOISE`]` · (1 + |coordinate|)`) a cell
/// must span: the snapped values then move the surface by at most half a cell.
pub const MIN_CELL_BANDS: u32 = 2;

/// Largest coordinate magnitude of a sample: primitives square their coordinates in single
/// precision (largest finite `f32` about 3.4·10³⁸), so beyond about 1.8·10¹⁹ samples inside a
/// sphere evaluated as outside (∞) and meshes came out open (issue 15); the margin covers a sum
/// of three squares and a translation.
pub const MAX_COORDINATE: f64 = 5e18;

/// Most cells along one axis (vertex and triangle keys pack sample indices in 20 bits).
pub const MAX_CELLS_PER_AXIS: usize = (1 << 20) - 2;

impl GridSpec {
    /// A grid over `bounds` with `resolution` cells along its longest side, padded by one cell on
    /// every side so a solid touching its bounds still meshes closed.
    pub fn for_bounds(bounds: &Aabb, resolution: usize) -> Result<Self, GridError> {
        let cell = Self::cell_size(bounds, resolution)?;
        let count = |extent: f64| ((extent / cell - 1e-9).ceil().max(1.0) as usize) + 2;
        let size = bounds.size();
        let cells = [count(size.x), count(size.y), count(size.z)];
        let half = DVec3::new(cells[0] as f64, cells[1] as f64, cells[2] as f64) * (cell * 0.5);
        Self::checked(Self {
            origin: bounds.center() - half,
            cell,
            cells,
        })
    }

    /// A grid of `resolution` cells along the longest side of `bounds`, starting exactly at
    /// `bounds.min`, without padding (the benchmark convention: 256 cells over [-1, 1]³).
    pub fn covering(bounds: &Aabb, resolution: usize) -> Result<Self, GridError> {
        let cell = Self::cell_size(bounds, resolution)?;
        let size = bounds.size();
        let cells = [0, 1, 2].map(|a| (size[a] / cell - 1e-9).ceil().max(1.0) as usize);
        Self::checked(Self {
            origin: bounds.min,
            cell,
            cells,
        })
    }

    fn cell_size(bounds: &Aabb, resolution: usize) -> Result<f64, GridError> {
        if resolution == 0 {
            return Err(GridError::ZeroResolution);
        }
        let longest = bounds.size().max_element();
        if !bounds.is_finite() || longest.is_nan() || longest <= 0.0 {
            return Err(GridError::BadBounds {
                min: bounds.min.to_array(),
                max: bounds.max.to_array(),
            });
        }
        Ok(longest / resolution as f64)
    }

    fn checked(spec: Self) -> Result<Self, GridError> {
        if spec.cells.iter().any(|&c| c > MAX_CELLS_PER_AXIS) {
            return Err(GridError::TooLarge {
                cells: spec.cells,
                limit: MAX_CELLS_PER_AXIS,
            });
        }
        // Samples are evaluated at single-precision coordinates: refuse a grid they cannot
        // represent faithfully (samples merged or unevenly spaced give wrong or broken meshes).
        let far = spec.point(spec.cells[0], spec.cells[1], spec.cells[2]);
        let bound = (0..3)
            .map(|a| spec.origin[a].abs().max(far[a].abs()))
            .fold(0.0, f64::max);
        if bound.is_nan() || bound > MAX_COORDINATE {
            return Err(GridError::BeyondSinglePrecision { bound });
        }
        let band = f64::from(NOISE) * (1.0 + bound);
        if spec.cell < f64::from(MIN_CELL_BANDS) * band {
            return Err(GridError::BelowSinglePrecision {
                cell: spec.cell,
                bound,
                band,
                min_bands: MIN_CELL_BANDS,
            });
        }
        Ok(spec)
    }

    /// Samples per axis.
    pub fn samples(&self) -> [usize; 3] {
        [self.cells[0] + 1, self.cells[1] + 1, self.cells[2] + 1]
    }

    /// Total number of samples (saturating).
    pub fn sample_count(&self) -> usize {
        let [x, y, z] = self.samples();
        x.saturating_mul(y).saturating_mul(z)
    }

    /// Position of sample `(i, j, k)`.
    pub fn point(&self, i: usize, j: usize, k: usize) -> DVec3 {
        self.origin + DVec3::new(i as f64, j as f64, k as f64) * self.cell
    }

    /// Single-precision coordinate of sample index `i` along `axis`, as every sampler computes it
    /// (so the dense and sparse paths evaluate at bit-identical points).
    pub fn coordinate(&self, axis: usize, i: usize) -> f32 {
        (self.origin[axis] + i as f64 * self.cell) as f32
    }

    /// Linear index of sample `(i, j, k)` (x fastest).
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        let [sx, sy, _] = self.samples();
        i + sx * (j + sy * k)
    }
}
