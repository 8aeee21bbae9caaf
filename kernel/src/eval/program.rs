//! [`Program`] as an [`Evaluator`]: every method forwards to the program's own method of the same
//! name and signature, so generic code compiles to the same calls.

use super::{Evaluator, Pruned, ZeroSide};
use crate::program::perturb::ZeroSlot;
use crate::program::{BatchScratch, GradientScratch, IntervalScratch};
use crate::{Aabb, Interval, Program};
use glam::DVec3;

impl Evaluator for Program {
    type BatchScratch = BatchScratch;
    type PointScratch = Vec<f64>;
    type GradientScratch = GradientScratch;
    type IntervalScratch = IntervalScratch;
    type ZeroScratch = Vec<ZeroSlot>;

    #[inline]
    fn len(&self) -> usize {
        Program::len(self)
    }

    #[inline]
    fn has_choices(&self) -> bool {
        Program::has_choices(self)
    }

    #[inline]
    fn eval_many(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32], s: &mut BatchScratch) {
        Program::eval_many(self, x, y, z, out, s);
    }

    #[inline]
    fn value_with(&self, p: DVec3, s: &mut Vec<f64>) -> f64 {
        Program::value_with(self, p, s)
    }

    #[inline]
    fn values_gradients(
        &self,
        points: &[DVec3],
        values: &mut [f64],
        gradients: &mut [DVec3],
        s: &mut GradientScratch,
    ) {
        Program::values_gradients(self, points, values, gradients, s);
    }

    #[inline]
    fn interval_with(&self, b: &Aabb, s: &mut IntervalScratch) -> Interval {
        Program::interval_with(self, b, s)
    }

    #[inline]
    fn contested(&self, s: &IntervalScratch) -> bool {
        Program::contested(self, s)
    }

    #[inline]
    fn prune(&self, s: &mut IntervalScratch) -> Option<Program> {
        Program::prune(self, s)
    }

    #[inline]
    fn prune_for_box(&self, b: &Aabb, s: &mut IntervalScratch) -> Pruned<Program> {
        Program::prune_for_box(self, b, s)
    }

    #[inline]
    fn zero_side(&self, p: DVec3, s: &mut Vec<ZeroSlot>) -> ZeroSide {
        Program::zero_side(self, p, s)
    }
}
