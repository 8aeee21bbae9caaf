//! The axis-aligned box centred at the origin with the given side lengths, as an exact distance.

use super::{PrimitiveError, Shape, positive, sign};
use crate::{Aabb, Interval};
use glam::DVec3;

/// An axis-aligned box centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cuboid {
    /// Side lengths along x, y and z.
    pub size: DVec3,
}

impl Cuboid {
    fn half(&self) -> DVec3 {
        self.size * 0.5
    }
}

impl Shape for Cuboid {
    fn value(&self, p: DVec3) -> f64 {
        let q = p.abs() - self.half();
        q.max(DVec3::ZERO).length() + q.max_element().min(0.0)
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        let q = p.abs() - self.half();
        let s = DVec3::new(sign(p.x), sign(p.y), sign(p.z));
        if q.max_element() > 0.0 {
            return (q.max(DVec3::ZERO).normalize()) * s;
        }
        let k = if q.x >= q.y && q.x >= q.z {
            0
        } else if q.y >= q.z {
            1
        } else {
            2
        };
        let mut g = DVec3::ZERO;
        g[k] = s[k];
        g
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let h = self.half();
        let q = [0, 1, 2].map(|i| Interval::new(b.min[i], b.max[i]).abs() - Interval::point(h[i]));
        let zero = Interval::point(0.0);
        let outside = Interval::norm(&q.map(|x| x.max(zero)));
        let inside = q[0].max(q[1]).max(q[2]).min(zero);
        outside + inside
    }
    fn bbox(&self) -> Aabb {
        Aabb::centered(self.half())
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        positive("size", self.size.x)?;
        positive("size", self.size.y)?;
        positive("size", self.size.z)
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        cuboid_f32(self.half().as_vec3(), x, y, z, out);
    }
}

crate::simd::wide_loop! {
    fn cuboid_f32(h: glam::Vec3, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len();
        let (x, y, z) = (&x[..n], &y[..n], &z[..n]);
        for i in 0..n {
            let (qx, qy, qz) = (x[i].abs() - h.x, y[i].abs() - h.y, z[i].abs() - h.z);
            let (ox, oy, oz) = (qx.max(0.0), qy.max(0.0), qz.max(0.0));
            out[i] = (ox * ox + oy * oy + oz * oz).sqrt() + qx.max(qy).max(qz).min(0.0);
        }
    }
}
