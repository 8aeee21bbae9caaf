//! The capped cylinder of radius `r` and height `h` along z, centred at the origin
//! (`−h/2 ≤ z ≤ h/2`), as an exact distance.

use super::{PrimitiveError, Shape, positive, radial, radial_interval, sign};
use crate::{Aabb, Interval};
use glam::DVec3;

crate::simd::wide_loop! {
    fn cylinder_f32(r: f32, hh: f32, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len();
        let (x, y, z) = (&x[..n], &y[..n], &z[..n]);
        for i in 0..n {
            let dx = (x[i] * x[i] + y[i] * y[i]).sqrt() - r;
            let dz = z[i].abs() - hh;
            let (ox, oz) = (dx.max(0.0), dz.max(0.0));
            out[i] = dx.max(dz).min(0.0) + (ox * ox + oz * oz).sqrt();
        }
    }
}

/// A capped cylinder along z, centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    /// Radius.
    pub radius: f64,
    /// Height (length along z).
    pub height: f64,
}

impl Shape for Cylinder {
    fn value(&self, p: DVec3) -> f64 {
        let dx = (p.x * p.x + p.y * p.y).sqrt() - self.radius;
        let dz = p.z.abs() - self.height * 0.5;
        dx.max(dz).min(0.0) + (dx.max(0.0).powi(2) + dz.max(0.0).powi(2)).sqrt()
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        let dx = (p.x * p.x + p.y * p.y).sqrt() - self.radius;
        let dz = p.z.abs() - self.height * 0.5;
        let (gr, gz) = if dx > 0.0 || dz > 0.0 {
            let (a, b) = (dx.max(0.0), dz.max(0.0));
            let l = (a * a + b * b).sqrt();
            (a / l, b / l)
        } else if dx >= dz {
            (1.0, 0.0)
        } else {
            (0.0, 1.0)
        };
        radial(p) * gr + DVec3::Z * (gz * sign(p.z))
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let dx = radial_interval(b) - Interval::point(self.radius);
        let dz = Interval::new(b.min.z, b.max.z).abs() - Interval::point(self.height * 0.5);
        let zero = Interval::point(0.0);
        dx.max(dz).min(zero) + Interval::norm(&[dx.max(zero), dz.max(zero)])
    }
    fn bbox(&self) -> Aabb {
        Aabb::centered(DVec3::new(self.radius, self.radius, self.height * 0.5))
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        positive("radius", self.radius)?;
        positive("height", self.height)
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        cylinder_f32(self.radius as f32, (self.height * 0.5) as f32, x, y, z, out);
    }
}
