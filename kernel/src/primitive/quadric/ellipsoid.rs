//! The axis-aligned ellipsoid with semi-axes `r = (a, b, c)` centred at the origin, as the
//! sphere-scaled field `f(p) = min(r) · (|p / r| − 1)`: its zero set is exactly the ellipsoid, and
//! `|∇f| = min(r) · |p/r²| / |p/r| ≤ min(r) / min(r) = 1`, so it is 1-Lipschitz (a distance bound,
//! exact on the sphere).

use super::super::{PrimitiveError, Shape, positive};
use crate::{Aabb, Interval};
use glam::DVec3;

/// An axis-aligned ellipsoid centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipsoid {
    /// Semi-axes along x, y and z.
    pub radii: DVec3,
}

impl Shape for Ellipsoid {
    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        self.radii.min_element() * ((p / self.radii).length() - 1.0)
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        let s = p / self.radii;
        let l = s.length();
        if l == 0.0 {
            return DVec3::Z;
        }
        self.radii.min_element() * (s / self.radii) / l
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let c = [0, 1, 2].map(|i| Interval::new(b.min[i], b.max[i]).scale(1.0 / self.radii[i]));
        (Interval::norm(&c) - Interval::point(1.0)).scale(self.radii.min_element())
    }
    fn bbox(&self) -> Aabb {
        Aabb::centered(self.radii)
    }
    fn bbox_at(&self, level: f64) -> Aabb {
        // m·(|p / r| − 1) ≤ ℓ ⇔ |p / r| ≤ 1 + ℓ/m: the ellipsoid scaled by 1 + ℓ/m, which grows
        // the longer radii by more than ℓ.
        Aabb::centered(self.radii * (1.0 + level / self.radii.min_element()))
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        positive("radii", self.radii.x)?;
        positive("radii", self.radii.y)?;
        positive("radii", self.radii.z)
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let inv = (1.0 / self.radii).as_vec3();
        let m = self.radii.min_element() as f32;
        let n = out.len().min(x.len()).min(y.len()).min(z.len());
        for i in 0..n {
            let (u, v, w) = (x[i] * inv.x, y[i] * inv.y, z[i] * inv.z);
            out[i] = m * ((u * u + v * v + w * w).sqrt() - 1.0);
        }
    }
}
