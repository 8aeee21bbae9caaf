//! The torus around the z axis with major radius `R` (centre circle) and minor radius `r` (tube),
//! `f(p) = |(ρ − R, z)| − r` with `ρ` the distance from the axis: an exact distance.

use super::{PrimitiveError, Shape, positive, radial, radial_interval};
use crate::{Aabb, Interval};
use glam::DVec3;

crate::simd::wide_loop! {
    fn torus_f32(big: f32, small: f32, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len();
        let (x, y, z) = (&x[..n], &y[..n], &z[..n]);
        for i in 0..n {
            let q = (x[i] * x[i] + y[i] * y[i]).sqrt() - big;
            out[i] = (q * q + z[i] * z[i]).sqrt() - small;
        }
    }
}

/// A torus around the z axis, centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Torus {
    /// Radius of the centre circle of the tube.
    pub major_radius: f64,
    /// Radius of the tube.
    pub minor_radius: f64,
}

impl Shape for Torus {
    fn value(&self, p: DVec3) -> f64 {
        let q = (p.x * p.x + p.y * p.y).sqrt() - self.major_radius;
        (q * q + p.z * p.z).sqrt() - self.minor_radius
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        let q = (p.x * p.x + p.y * p.y).sqrt() - self.major_radius;
        let l = (q * q + p.z * p.z).sqrt();
        if l == 0.0 {
            return radial(p);
        }
        radial(p) * (q / l) + DVec3::Z * (p.z / l)
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let q = radial_interval(b) - Interval::point(self.major_radius);
        Interval::norm(&[q, Interval::new(b.min.z, b.max.z)]) - Interval::point(self.minor_radius)
    }
    fn bbox(&self) -> Aabb {
        let r = self.major_radius + self.minor_radius;
        Aabb::centered(DVec3::new(r, r, self.minor_radius))
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        positive("major_radius", self.major_radius)?;
        positive("minor_radius", self.minor_radius)
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        torus_f32(
            self.major_radius as f32,
            self.minor_radius as f32,
            x,
            y,
            z,
            out,
        );
    }
}
