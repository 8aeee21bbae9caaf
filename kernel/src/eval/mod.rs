//! The one evaluation trait: what a mesher asks of a field.
//!
//! [`Evaluator`] gathers every way the meshers read a field, each with its reusable scratch as
//! an associated type (so a worker thread keeps one of each and the hot loops allocate nothing):
//!
//! | concept | method | used by |
//! |---|---|---|
//! | values over `f32` slices | [`Evaluator::eval_many`] | sample grids, octree bricks |
//! | one value in `f64` | [`Evaluator::value_with`] | feature search, DC diagonals |
//! | values and gradients in `f64` | [`Evaluator::values_gradients`] | DC crossings and normals |
//! | an interval over a box | [`Evaluator::interval_with`] | octree classification, search |
//! | pruning to a shorter evaluator | [`Evaluator::prune`], [`Evaluator::prune_for_box`] ([`Pruned`]) | octree |
//! | the sign of an exact zero | [`Evaluator::zero_side`] | every sampler's sign rule |
//! | a cost | [`Evaluator::len`] | statistics |
//!
//! [`Program`](crate::Program) implements it by forwarding to its own methods of the same names
//! and signatures (`program/`), so code generic over `E: Evaluator` compiles, once
//! monomorphized, to the same calls as code written for `Program`. The meshers of
//! `solidkit-meshing` (sparse marching cubes, dual contouring, dense sample grids) are generic
//! over it.
//!
//! # The contract
//! The meshers' guarantees (the sparse path reproduces the dense one bit for bit; zeros are
//! settled alike in every brick) rest on these rules, which `eval::conformance` (cargo feature
//! `eval-tests`) checks for any evaluator:
//! - batch values agree with the scalar value within single-precision rounding, and do not depend
//!   on how points are batched (a point gives the same bits alone or among others);
//! - the interval over a box contains the value at every point of it (the `f32` values within
//!   the safety margin [`margin`]);
//! - a box [`Pruned::Inside`] (`Outside`) has only negative (positive) values, and an evaluator
//!   pruned for a box gives the same `f32` values (bit for bit), `f64` values (up to rounding) and
//!   zero sides as the full one everywhere inside the box, and is no longer than it (pruning it
//!   again for a smaller box keeps this);
//! - gradients are those of the values (central differences agree away from creases);
//! - [`Evaluator::zero_side`] depends only on the point; it answers the sign of the value where
//!   the value is clearly nonzero, [`ZeroSide::Surface`] where it leaves the decision to the
//!   polygonizer, and `Inside` / `Outside` only with points of that side close by.
//!
//! # Relation to the other field traits
//! - [`Field`](crate::Field) stays the small closure-friendly trait of the dense reference path
//!   (`mesh_field`, `SampleGrid::sample`): a value per point, with a default batch and zero rule,
//!   implemented for every `Fn(DVec3) -> f64` and by `Program`. Every evaluator is a `Field`
//!   through the adapter [`AsField`] (an explicit wrapper: a blanket impl would overlap the one
//!   for closures).
//! - [`Shape`](crate::Shape) is one primitive's field (value, gradient, interval, bounds);
//!   programs combine shapes, and primitives are not evaluators themselves.
//! - Dual contouring's former `DcField` (values and gradients over points) is
//!   [`Evaluator::values_gradients`]; a field known only through samples implements the whole
//!   trait with whole-range or sample-bounded intervals and no pruning.

mod field;
mod program;
mod pruned;

#[cfg(any(test, feature = "eval-tests"))]
pub mod conformance;

#[cfg(test)]
mod tests;

pub use crate::program::perturb::ZeroSide;
pub use field::AsField;
pub use pruned::{Pruned, box_scale, margin};

use crate::{Aabb, Interval};
use glam::DVec3;

/// A field the meshers can evaluate: negative inside the solid, a distance bound (or at least a
/// sign-correct, locally Lipschitz field) everywhere. See the [module docs](self) for the
/// contract every implementation keeps.
///
/// Scratch types are per worker thread: a mesher creates them with `Default` and passes them to
/// every call of that worker, in any order and for evaluators pruned from one another (an
/// implementation grows them as needed and keeps no result in them that a later call of a
/// different method relies on, except [`Evaluator::prune`], which reads the choices the last
/// [`Evaluator::interval_with`] left in its scratch).
pub trait Evaluator: Clone + Send + Sync {
    /// Scratch of [`Evaluator::eval_many`].
    type BatchScratch: Default + Send;
    /// Scratch of [`Evaluator::value_with`].
    type PointScratch: Default + Send;
    /// Scratch of [`Evaluator::values_gradients`].
    type GradientScratch: Default + Send;
    /// Scratch of [`Evaluator::interval_with`] and pruning; holds what pruning needs from the
    /// last interval evaluation.
    type IntervalScratch: Default + Send;
    /// Scratch of [`Evaluator::zero_side`].
    type ZeroScratch: Default + Send;

    /// The cost of one evaluation (for `Program`, its number of instructions). Pruning never
    /// increases it.
    fn len(&self) -> usize;

    /// Whether the evaluator holds a choice between operands (a min, max or blend); true when it
    /// cannot tell. Where an evaluator valid over a box has none, no contact, crease or pinch
    /// between operands lies in that box.
    fn has_choices(&self) -> bool {
        true
    }

    /// True when [`Evaluator::len`] is 0.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Values in single precision at the points `(x[i], y[i], z[i])` for `i < out.len()` (the
    /// coordinate slices are at least that long), written to `out`.
    fn eval_many(
        &self,
        x: &[f32],
        y: &[f32],
        z: &[f32],
        out: &mut [f32],
        s: &mut Self::BatchScratch,
    );

    /// The value at `p` in double precision.
    fn value_with(&self, p: DVec3, s: &mut Self::PointScratch) -> f64;

    /// Values and gradients in double precision at `points` (any number), written to `values`
    /// and `gradients` (at least as long).
    fn values_gradients(
        &self,
        points: &[DVec3],
        values: &mut [f64],
        gradients: &mut [DVec3],
        s: &mut Self::GradientScratch,
    );

    /// An interval containing the field's values over `b`; leaves in `s` what
    /// [`Evaluator::prune`] needs. An evaluator without interval arithmetic returns
    /// [`Interval::entire`].
    fn interval_with(&self, b: &Aabb, s: &mut Self::IntervalScratch) -> Interval;

    /// Whether the last [`Evaluator::interval_with`] on `s` left a choice between operands (a
    /// min, max or blend) that either can win over its box; true when the evaluator cannot tell.
    /// Where it is false, no contact or crease between operands crosses the box.
    fn contested(&self, s: &Self::IntervalScratch) -> bool {
        let _ = s;
        true
    }

    /// A shorter evaluator valid in the box of the last [`Evaluator::interval_with`] on `s` (the
    /// same values, bit for bit, everywhere in that box), or `None` when nothing can be dropped.
    fn prune(&self, s: &mut Self::IntervalScratch) -> Option<Self>;

    /// Classifies `b` by the interval with the single-precision safety margin
    /// ([`Pruned::classify`]) and, where the surface may cross it, prunes for it.
    fn prune_for_box(&self, b: &Aabb, s: &mut Self::IntervalScratch) -> Pruned<Self> {
        let iv = self.interval_with(b, s);
        Pruned::classify(b, iv, || self.prune(s))
    }

    /// Where the (numerically) zero point `p` lies: the symbolic zero rule of
    /// [`crate::program::perturb`] for programs. Called by the samplers only where the
    /// single-precision value is within noise of zero; [`ZeroSide::Surface`] leaves the sample
    /// to the polygonizer's lattice rule (always a valid answer).
    fn zero_side(&self, p: DVec3, s: &mut Self::ZeroScratch) -> ZeroSide;
}
