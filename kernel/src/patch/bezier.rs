//! Tensor-product Bézier patches in space (lecture notes 001): `p(u, v) = Σ_i Σ_j B_i^m(u)
//! B_j^n(v) p_ij` over `[0, 1]²`, with partial derivatives from the differenced control net, the
//! normal `∂p/∂u × ∂p/∂v`, and a regular tessellation.

use super::bernstein::tensor_sum;
use super::error::PatchError;
use crate::IndexedMesh;
use crate::tessellate::{TessellationError, regular_grid};
use glam::DVec3;

/// A tensor-product Bézier patch of degrees `(m, n)` with `(m + 1) × (n + 1)` control points.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierPatch {
    m: usize,
    n: usize,
    points: Vec<DVec3>,
}

impl BezierPatch {
    /// A patch of degrees `(m, n)` from its control points `p_ij` stored at `j * (m + 1) + i`.
    pub fn new(m: usize, n: usize, points: Vec<DVec3>) -> Result<Self, PatchError> {
        let expected = (m + 1) * (n + 1);
        if points.len() != expected {
            return Err(PatchError::ControlCount {
                degree: m.max(n),
                expected,
                got: points.len(),
            });
        }
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(PatchError::NonFinite {
                what: "control point",
                index,
            });
        }
        Ok(Self { m, n, points })
    }

    /// Degrees `(m, n)`.
    pub fn degrees(&self) -> (usize, usize) {
        (self.m, self.n)
    }

    /// Control point `p_ij`.
    pub fn control(&self, i: usize, j: usize) -> DVec3 {
        self.points[j * (self.m + 1) + i]
    }

    /// `p(u, v)`.
    pub fn point(&self, u: f64, v: f64) -> DVec3 {
        tensor_sum(self.m, self.n, u, v, |i, j| self.control(i, j))
    }

    /// `∂p/∂u = m Σ (p_{i+1,j} − p_ij) B_i^{m−1}(u) B_j^n(v)`.
    pub fn du(&self, u: f64, v: f64) -> DVec3 {
        if self.m == 0 {
            return DVec3::ZERO;
        }
        let d = |i, j| self.control(i + 1, j) - self.control(i, j);
        tensor_sum(self.m - 1, self.n, u, v, d) * self.m as f64
    }

    /// `∂p/∂v = n Σ (p_{i,j+1} − p_ij) B_i^m(u) B_j^{n−1}(v)`.
    pub fn dv(&self, u: f64, v: f64) -> DVec3 {
        if self.n == 0 {
            return DVec3::ZERO;
        }
        let d = |i, j| self.control(i, j + 1) - self.control(i, j);
        tensor_sum(self.m, self.n - 1, u, v, d) * self.n as f64
    }

    /// The unnormalised normal `∂p/∂u × ∂p/∂v`.
    pub fn normal(&self, u: f64, v: f64) -> DVec3 {
        self.du(u, v).cross(self.dv(u, v))
    }

    /// The open regular tessellation of lecture notes 001: `n × n` samples, `2(n − 1)²` triangles
    /// wound along the normal `∂p/∂u × ∂p/∂v`.
    pub fn tessellate(&self, n: usize) -> Result<IndexedMesh, TessellationError> {
        regular_grid(n, n, |u, v| self.point(u, v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn saddle() -> BezierPatch {
        // Bilinear-in-disguise degree (2, 1) patch.
        let pts = (0..2)
            .flat_map(|j| {
                (0..3).map(move |i| {
                    DVec3::new(
                        i as f64 * 0.5,
                        j as f64,
                        if (i + j) % 2 == 0 { 0.3 } else { -0.2 },
                    )
                })
            })
            .collect();
        BezierPatch::new(2, 1, pts).unwrap()
    }

    #[test]
    fn corners_interpolate_and_derivatives_match_differences() {
        let p = saddle();
        assert_eq!(p.point(0.0, 0.0), p.control(0, 0));
        assert!((p.point(1.0, 1.0) - p.control(2, 1)).length() < 1e-15);
        let h = 1e-6;
        for &(u, v) in &[(0.2, 0.3), (0.7, 0.9), (0.5, 0.5)] {
            let fu = (p.point(u + h, v) - p.point(u - h, v)) / (2.0 * h);
            let fv = (p.point(u, v + h) - p.point(u, v - h)) / (2.0 * h);
            assert!((fu - p.du(u, v)).length() < 1e-8);
            assert!((fv - p.dv(u, v)).length() < 1e-8);
        }
    }

    #[test]
    fn regular_tessellation_counts() {
        let m = saddle().tessellate(9).unwrap();
        assert_eq!((m.vertex_count(), m.triangle_count()), (81, 2 * 64));
        assert!(BezierPatch::new(2, 2, vec![DVec3::ZERO; 8]).is_err());
    }
}
