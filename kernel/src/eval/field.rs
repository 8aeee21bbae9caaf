//! Any [`Evaluator`] as a [`Field`], for the dense reference path (`mesh_field`,
//! `SampleGrid::sample`) and anything else written against the simpler trait.

use super::Evaluator;
use crate::Field;
use crate::program::perturb::ZeroSide;
use glam::DVec3;

/// An evaluator seen as a [`Field`]: values in double precision ([`Evaluator::value_with`]) and
/// the evaluator's own zero rule. A wrapper rather than a blanket impl, which would overlap
/// `Field`'s impl for closures.
#[derive(Debug, Clone, Copy)]
pub struct AsField<'a, E>(pub &'a E);

impl<E: Evaluator> Field for AsField<'_, E> {
    fn value(&self, p: DVec3) -> f64 {
        self.0.value_with(p, &mut Default::default())
    }

    fn values(&self, points: &[DVec3], out: &mut [f64]) {
        let mut s = E::PointScratch::default();
        for (p, o) in points.iter().zip(out.iter_mut()) {
            *o = self.0.value_with(*p, &mut s);
        }
    }

    fn zero_side(&self, p: DVec3) -> ZeroSide {
        self.0.zero_side(p, &mut Default::default())
    }
}
