//! A surface point with its first and second partial derivatives, and the curvatures from the
//! first and second fundamental forms (`E, F, G` and `L, M, N` with the unit normal
//! `n = p_u × p_v / |p_u × p_v|`):
//!
//! `K = (LN − M²) / (EG − F²)`, `H = (EN − 2FM + GL) / (2 (EG − F²))`,
//!
//! with `H` positive where the surface bends towards `n` (the sign convention of
//! [`crate::patch::curvature`]; on a graph `z = h(x, y)` parametrised by `(x, y)` the two agree).

use crate::patch::Curvature;
use glam::DVec3;

/// `p` and its partial derivatives up to second order at one parameter point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SurfaceDerivatives {
    /// The point.
    pub p: DVec3,
    /// `∂p/∂u`.
    pub pu: DVec3,
    /// `∂p/∂v`.
    pub pv: DVec3,
    /// `∂²p/∂u²`.
    pub puu: DVec3,
    /// `∂²p/∂u∂v`.
    pub puv: DVec3,
    /// `∂²p/∂v²`.
    pub pvv: DVec3,
}

impl SurfaceDerivatives {
    /// The unit normal `p_u × p_v / |p_u × p_v|` (zero where the parametrisation is singular).
    pub fn normal(&self) -> DVec3 {
        self.pu.cross(self.pv).normalize_or_zero()
    }

    /// Gaussian and mean curvature from the fundamental forms; NaN where the parametrisation is
    /// singular (`EG − F² = 0`).
    pub fn curvature(&self) -> Curvature {
        let n = self.normal();
        let (e, f, g) = (
            self.pu.dot(self.pu),
            self.pu.dot(self.pv),
            self.pv.dot(self.pv),
        );
        let (l, m, nn) = (self.puu.dot(n), self.puv.dot(n), self.pvv.dot(n));
        let det = e * g - f * f;
        if det <= 0.0 || n == DVec3::ZERO {
            return Curvature {
                gaussian: f64::NAN,
                mean: f64::NAN,
            };
        }
        Curvature {
            gaussian: (l * nn - m * m) / det,
            mean: (e * nn - 2.0 * f * m + g * l) / (2.0 * det),
        }
    }

    /// The derivatives after the change of parameters `u = u₀ + a s`, `v = v₀ + b t`.
    pub(crate) fn rescaled(self, a: f64, b: f64) -> Self {
        SurfaceDerivatives {
            p: self.p,
            pu: self.pu * a,
            pv: self.pv * b,
            puu: self.puu * (a * a),
            puv: self.puv * (a * b),
            pvv: self.pvv * (b * b),
        }
    }
}
