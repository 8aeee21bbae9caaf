//! A rectangular array of heights: the samples of a sampled height field or the control heights of
//! a Bézier height patch. Index `(i, j)` is column `i` along x and row `j` along y.

use super::error::HeightFieldError;
use std::fmt;

/// `nx × ny` heights stored row by row (`j * nx + i`), at least 2 × 2, all finite.
#[derive(Clone, PartialEq)]
pub struct HeightGrid {
    nx: usize,
    ny: usize,
    values: Vec<f64>,
}

impl HeightGrid {
    /// A grid from its values row by row (`values[j * nx + i]`).
    pub fn new(nx: usize, ny: usize, values: Vec<f64>) -> Result<Self, HeightFieldError> {
        if nx < 2 || ny < 2 {
            return Err(HeightFieldError::GridTooSmall { nx, ny });
        }
        if nx.checked_mul(ny) != Some(values.len()) {
            return Err(HeightFieldError::GridShape {
                nx,
                ny,
                len: values.len(),
            });
        }
        if let Some(k) = values.iter().position(|v| !v.is_finite()) {
            return Err(HeightFieldError::NonFinite {
                column: k % nx,
                row: k / nx,
            });
        }
        Ok(Self { nx, ny, values })
    }

    /// A grid from rows of equal length (`rows[j][i]`, row `j` along y).
    pub fn from_rows(rows: &[Vec<f64>]) -> Result<Self, HeightFieldError> {
        let ny = rows.len();
        let nx = rows.first().map_or(0, Vec::len);
        if let Some(j) = rows.iter().position(|r| r.len() != nx) {
            return Err(HeightFieldError::RaggedRows {
                row: j,
                len: rows[j].len(),
                expected: nx,
            });
        }
        Self::new(nx, ny, rows.concat())
    }

    /// Columns (along x).
    pub fn nx(&self) -> usize {
        self.nx
    }

    /// Rows (along y).
    pub fn ny(&self) -> usize {
        self.ny
    }

    /// The height at column `i`, row `j`.
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.values[j * self.nx + i]
    }

    /// The height at a column and row clamped into the grid (signed indices, for stencils that
    /// reach past the border).
    #[inline]
    pub fn get_clamped(&self, i: isize, j: isize) -> f64 {
        let i = i.clamp(0, self.nx as isize - 1) as usize;
        let j = j.clamp(0, self.ny as isize - 1) as usize;
        self.get(i, j)
    }

    /// All values row by row.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The rows (`rows[j][i]`).
    pub fn rows(&self) -> impl Iterator<Item = &[f64]> {
        self.values.chunks(self.nx)
    }

    /// Smallest and largest value.
    pub fn range(&self) -> (f64, f64) {
        self.values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                (lo.min(v), hi.max(v))
            })
    }

    /// The largest `|z(i+1, j) − z(i, j)|` and `|z(i, j+1) − z(i, j)|`.
    pub fn max_steps(&self) -> (f64, f64) {
        let (mut sx, mut sy) = (0.0f64, 0.0f64);
        for j in 0..self.ny {
            for i in 0..self.nx {
                if i + 1 < self.nx {
                    sx = sx.max((self.get(i + 1, j) - self.get(i, j)).abs());
                }
                if j + 1 < self.ny {
                    sy = sy.max((self.get(i, j + 1) - self.get(i, j)).abs());
                }
            }
        }
        (sx, sy)
    }
}

/// Prints the size and range, not the (possibly millions of) values.
impl fmt::Debug for HeightGrid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (lo, hi) = self.range();
        f.debug_struct("HeightGrid")
            .field("nx", &self.nx)
            .field("ny", &self.ny)
            .field("range", &(lo, hi))
            .finish()
    }
}
