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

    /// Whether the solid contains `p + ε·d` for small `ε > 0`, with `d` the fixed direction
    /// [`crate::program::perturb::PERTURBATION`]: how polygonizers classify a sample whose value is
    /// zero. A [`crate::Program`] takes the exact limit by symbolic perturbation; this default
    /// looks a short finite step (`1e-5` of the coordinate scale) along `d`.
    fn inside_at_zero(&self, p: DVec3) -> bool {
        let step = 1e-5 * (1.0 + p.abs().max_element());
        self.value(p + crate::program::perturb::PERTURBATION * step) < 0.0
    }
}

impl<F: Fn(DVec3) -> f64 + Sync> Field for F {
    fn value(&self, p: DVec3) -> f64 {
        self(p)
    }
}
