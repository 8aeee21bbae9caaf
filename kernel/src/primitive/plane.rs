//! The half-space `n̂ · p ≤ d` bounded by a plane, with `n̂` the unit normal: `f(p) = n̂ · p − d`,
//! an exact distance. Unbounded: intersect it with a bounded solid to mesh it.

use super::{PrimitiveError, Shape};
use crate::{Aabb, Interval};
use glam::DVec3;

/// The half-space on the side of the plane `normal · p = offset` opposite to `normal`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfSpace {
    /// Outward normal of the plane (any non-zero length; normalised when evaluated).
    pub normal: DVec3,
    /// Signed distance of the plane from the origin along the unit normal.
    pub offset: f64,
}

impl HalfSpace {
    fn unit(&self) -> DVec3 {
        self.normal.normalize_or_zero()
    }
}

impl Shape for HalfSpace {
    fn value(&self, p: DVec3) -> f64 {
        self.unit().dot(p) - self.offset
    }
    fn gradient(&self, _p: DVec3) -> DVec3 {
        self.unit()
    }
    fn values_gradients(&self, pts: &[DVec3], values: &mut [f64], gradients: &mut [DVec3]) {
        // One normalisation for the batch (the same bits as per point).
        let n = self.unit();
        for ((p, v), g) in pts.iter().zip(values.iter_mut()).zip(gradients.iter_mut()) {
            *v = n.dot(*p) - self.offset;
            *g = n;
        }
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let n = self.unit();
        let mut acc = Interval::point(-self.offset);
        for i in 0..3 {
            if n[i] != 0.0 {
                acc = acc + Interval::new(b.min[i], b.max[i]).scale(n[i]);
            }
        }
        acc
    }
    fn bbox(&self) -> Aabb {
        let n = self.unit();
        let mut b = Aabb::infinite();
        // Axis-aligned half-spaces are bounded on one side.
        for i in 0..3 {
            if n[i].abs() == 1.0 {
                if n[i] > 0.0 {
                    b.max[i] = self.offset;
                } else {
                    b.min[i] = -self.offset;
                }
            }
        }
        b
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        if !self.normal.is_finite() || !self.offset.is_finite() {
            return Err(PrimitiveError {
                parameter: "normal",
                problem: "expected finite numbers",
            });
        }
        if self.normal.length_squared() == 0.0 {
            return Err(PrimitiveError {
                parameter: "normal",
                problem: "expected a non-zero vector",
            });
        }
        Ok(())
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let m = self.unit().as_vec3();
        let d = self.offset as f32;
        let n = out.len();
        let (x, y, z) = (&x[..n], &y[..n], &z[..n]);
        for i in 0..n {
            out[i] = m.x * x[i] + m.y * y[i] + m.z * z[i] - d;
        }
    }
}
