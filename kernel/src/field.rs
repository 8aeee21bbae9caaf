//! The [`Field`] trait: what a polygonizer needs from a solid (values at points, in bulk).

use glam::DVec3;

/// A scalar field, negative inside the solid, sampled by polygonizers from many threads.
pub trait Field: Sync {
    /// Value at one point.
    fn value(&self, p: DVec3) -> f64;

    /// Values at many points (`out[i]` for `points[i]`); implementations batch the work.
    fn values(&self, points: &[DVec3], out: &mut [f64]) {
        for (p, o) in points.iter().zip(out.iter_mut()) {
            *o = self.value(*p);
        }
    }
}

impl<F: Fn(DVec3) -> f64 + Sync> Field for F {
    fn value(&self, p: DVec3) -> f64 {
        self(p)
    }
}
