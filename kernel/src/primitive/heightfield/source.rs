//! Where the heights come from: a Bézier patch or samples with an interpolation, all over the unit
//! parameter square `(u, v) ∈ [0, 1]²`, with derivatives in `(u, v)` and global bounds of `h` and
//! its derivatives (the height field scales them to `(x, y)`).

use super::grid::HeightGrid;
use super::param::{ParamBounds, ParamDerivatives};
use super::{bezier, sampled};

/// How samples are interpolated between grid points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Interpolation {
    /// Bilinear per cell: continuous, with slopes that jump across cells.
    #[default]
    Bilinear,
    /// Bicubic Catmull–Rom: interpolating with continuous slopes.
    Bicubic,
    /// OpenSCAD's `surface()`: each cell is four flat triangles around its centre, which lies at
    /// the mean of the cell's corners (piecewise linear, continuous).
    Quads,
}

impl Interpolation {
    /// The name in the JSON tree format.
    pub fn name(self) -> &'static str {
        match self {
            Self::Bilinear => "bilinear",
            Self::Bicubic => "bicubic",
            Self::Quads => "quads",
        }
    }

    /// The interpolation with this JSON name.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "bilinear" => Some(Self::Bilinear),
            "bicubic" => Some(Self::Bicubic),
            "quads" => Some(Self::Quads),
            _ => None,
        }
    }
}

/// The height function over the unit parameter square.
#[derive(Debug, Clone, PartialEq)]
pub enum HeightSource {
    /// A tensor-product Bézier patch with these control heights (degrees `nx − 1`, `ny − 1`).
    Bezier(HeightGrid),
    /// Samples at `u = i / (nx − 1)`, `v = j / (ny − 1)`, interpolated.
    Samples {
        /// The samples.
        grid: HeightGrid,
        /// How they are interpolated.
        interpolation: Interpolation,
    },
}

impl HeightSource {
    /// The grid of samples or control heights.
    pub fn grid(&self) -> &HeightGrid {
        match self {
            Self::Bezier(g) | Self::Samples { grid: g, .. } => g,
        }
    }

    /// `h(u, v)`.
    #[inline]
    pub(crate) fn height(&self, u: f64, v: f64) -> f64 {
        match self {
            Self::Bezier(g) => bezier::height(g, u, v),
            Self::Samples {
                grid,
                interpolation: Interpolation::Bilinear,
            } => sampled::bilinear(grid, u, v).h,
            Self::Samples {
                grid,
                interpolation: Interpolation::Bicubic,
            } => sampled::bicubic(grid, u, v).h,
            Self::Samples {
                grid,
                interpolation: Interpolation::Quads,
            } => sampled::quads(grid, u, v).h,
        }
    }

    /// `h` and its derivatives in `(u, v)`; second derivatives of a Bézier patch only when `second`.
    #[inline]
    pub(crate) fn derivatives(&self, u: f64, v: f64, second: bool) -> ParamDerivatives {
        match self {
            Self::Bezier(g) => bezier::derivatives(g, u, v, second),
            Self::Samples {
                grid,
                interpolation: Interpolation::Bilinear,
            } => sampled::bilinear(grid, u, v),
            Self::Samples {
                grid,
                interpolation: Interpolation::Bicubic,
            } => sampled::bicubic(grid, u, v),
            Self::Samples {
                grid,
                interpolation: Interpolation::Quads,
            } => sampled::quads(grid, u, v),
        }
    }

    /// Global bounds of `h` and its derivatives.
    pub(crate) fn bounds(&self) -> ParamBounds {
        match self {
            Self::Bezier(g) => bezier::bounds(g),
            Self::Samples {
                grid,
                interpolation: Interpolation::Bilinear | Interpolation::Quads,
            } => sampled::bilinear_bounds(grid),
            Self::Samples {
                grid,
                interpolation: Interpolation::Bicubic,
            } => sampled::bicubic_bounds(grid),
        }
    }
}
