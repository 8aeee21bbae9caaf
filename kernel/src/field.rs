//! The [`Field`] trait: what a polygonizer needs from a solid (values at points, in bulk).
//!
//! The small, closure-friendly trait of the dense reference path. The meshers' full trait is
//! [`crate::Evaluator`]; [`crate::eval::AsField`] makes any evaluator a `Field` (see
//! [`crate::eval`] for how the traits relate).

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

    /// Where a sample whose value is zero lies: how polygonizers classify it. A
    /// [`crate::Program`] settles zeros where operands meet by symbolic perturbation
    /// ([`crate::program::perturb`]); this default knows no operands, so every zero lies on a
    /// lone surface and the polygonizer decides it from the lattice.
    fn zero_side(&self, p: DVec3) -> crate::program::perturb::ZeroSide {
        let _ = p;
        crate::program::perturb::ZeroSide::Surface
    }
}

impl<F: Fn(DVec3) -> f64 + Sync> Field for F {
    fn value(&self, p: DVec3) -> f64 {
        self(p)
    }
}
