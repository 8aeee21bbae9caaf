//! The ball of radius `r` centred at the origin: `f(p) = |p| − r`, an exact distance.

use super::{PrimitiveError, Shape, positive};
use crate::{Aabb, Interval};
use glam::DVec3;

crate::simd::wide_loop! {
    fn sphere_f32(r: f32, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len();
        let (x, y, z) = (&x[..n], &y[..n], &z[..n]);
        for i in 0..n {
            out[i] = (x[i] * x[i] + y[i] * y[i] + z[i] * z[i]).sqrt() - r;
        }
    }
}

/// A ball centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    /// Radius.
    pub radius: f64,
}

impl Shape for Sphere {
    fn value(&self, p: DVec3) -> f64 {
        p.length() - self.radius
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        p.try_normalize().unwrap_or(DVec3::Z)
    }
    fn interval(&self, b: &Aabb) -> Interval {
        // Nearest and farthest points of the box from the centre, per axis.
        let near = b.min.max(-b.max).max(DVec3::ZERO);
        let far = b.min.abs().max(b.max.abs());
        Interval::new(near.length() - self.radius, far.length() - self.radius)
    }
    fn bbox(&self) -> Aabb {
        Aabb::centered(DVec3::splat(self.radius))
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        positive("radius", self.radius)
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        sphere_f32(self.radius as f32, x, y, z, out);
    }
}
