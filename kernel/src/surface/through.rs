//! The interpolating bicubic patch through 16 points (the notes' "interpolerande polynomytor"):
//! the tensor product of the 4-point interpolating cubic ([`CubicThrough`](crate::curve::CubicThrough)),
//! `S(u, v) = Σ aₖₗ uᵏ vˡ` with `S(i/3, j/3) = Pᵢⱼ` for `i, j ∈ {0, 1, 2, 3}`.
//!
//! Setting `v = 0` gives the cubic through `P₀₀, P₁₀, P₂₀, P₃₀`, `v = 1` the one through
//! `P₀₃, …, P₃₃`, and `v = 1/3, 2/3` the two between: a linear system whose solution is, in the
//! Bézier basis, the curve map `T` applied along both directions, `B = T P Tᵀ` with
//! `T = [[6, 0, 0, 0], [−5, 18, −9, 2], [2, −9, 18, −5], [0, 0, 0, 6]] / 6` (the rows give the
//! Bézier points of the interpolating cubic). The patch is that bicubic [`TensorSurface`], so it
//! is tessellated, bounded and closed exactly as a `bezier_patch`.

use super::error::SurfaceError;
use super::tensor::TensorSurface;
use glam::DVec3;

/// The curve map from 4 interpolated points at `u = k/3` to 4 Bézier control points (× 6).
const T6: [[f64; 4]; 4] = [
    [6.0, 0.0, 0.0, 0.0],
    [-5.0, 18.0, -9.0, 2.0],
    [2.0, -9.0, 18.0, -5.0],
    [0.0, 0.0, 0.0, 6.0],
];

/// A bicubic patch through a 4 × 4 grid of points at `u, v ∈ {0, 1/3, 2/3, 1}`.
#[derive(Debug, Clone, PartialEq)]
pub struct InterpolatingPatch {
    points: Vec<DVec3>,
    bezier: TensorSurface,
}

impl InterpolatingPatch {
    /// The patch through `points` (16, finite), `Pᵢⱼ` at `4j + i`: rows along `v` of points
    /// along `u`, as a `bezier_patch` lists its control net.
    pub fn new(points: &[DVec3]) -> Result<Self, SurfaceError> {
        let points: [DVec3; 16] = points.try_into().map_err(|_| {
            SurfaceError::invalid(
                "points",
                format!(
                    "expected 4 rows of 4 points (16 points), got {}",
                    points.len()
                ),
            )
        })?;
        if let Some(k) = points.iter().position(|p| !p.is_finite()) {
            return Err(SurfaceError::invalid(
                "points",
                format!("point {k} is not finite"),
            ));
        }
        let bezier = TensorSurface::bezier([4, 4], bezier_net(&points).to_vec())?;
        Ok(InterpolatingPatch {
            points: points.to_vec(),
            bezier,
        })
    }

    /// The 16 points the patch passes through, `Pᵢⱼ` at `4j + i`.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The equivalent bicubic Bézier patch (its control net `T P Tᵀ`).
    pub fn bezier(&self) -> &TensorSurface {
        &self.bezier
    }
}

/// The Bézier control net `B = T P Tᵀ` of the interpolating patch through `p` (`Pᵢⱼ` at `4j + i`).
pub fn bezier_net(p: &[DVec3; 16]) -> [DVec3; 16] {
    // Along u within each row j, then along v within each column.
    let mut rows = [DVec3::ZERO; 16];
    for j in 0..4 {
        for (a, t) in T6.iter().enumerate() {
            rows[4 * j + a] = (0..4).map(|i| p[4 * j + i] * t[i]).sum::<DVec3>() / 6.0;
        }
    }
    let mut out = [DVec3::ZERO; 16];
    for a in 0..4 {
        for (b, t) in T6.iter().enumerate() {
            out[4 * b + a] = (0..4).map(|j| rows[4 * j + a] * t[j]).sum::<DVec3>() / 6.0;
        }
    }
    out
}
