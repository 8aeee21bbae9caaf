//! Pruning's outcome over a box: inside, outside, or a surface box with a shorter evaluator.
//!
//! Evaluators compute intervals in double precision while samplers evaluate points in single
//! precision, so a box is only called inside or outside when its interval clears zero by the
//! safety [`margin`] (a few hundred single-precision ulps of the magnitudes involved): the `f32`
//! values in it then have that sign too, and the sparse meshers cull it without changing a
//! sample.

use crate::{Aabb, Interval};

/// The outcome of pruning an evaluator `E` over a box.
#[derive(Debug, Clone)]
pub enum Pruned<E> {
    /// The whole box is inside the solid.
    Inside,
    /// The whole box is outside the solid.
    Outside,
    /// The surface may cross the box; the shorter evaluator valid in it, or `None` when nothing
    /// could be cut (the original one applies).
    Surface(Option<E>),
}

/// Safety margin for comparisons between f64 intervals whose values will be evaluated in f32:
/// a few hundred single-precision ulps of the magnitudes involved.
pub fn margin(scale: f64, a: f64, b: f64) -> f64 {
    let m = scale + a.abs().min(1e30) + b.abs().min(1e30);
    3e-5 * m
}

/// The coordinate scale of a box for [`margin`]: one plus its largest coordinate magnitude
/// (capped at 10³⁰).
#[inline]
pub fn box_scale(b: &Aabb) -> f64 {
    1.0 + b.min.abs().max(b.max.abs()).max_element().min(1e30)
}

impl<E> Pruned<E> {
    /// Classifies the box `b` over which the field lies in `iv`: inside when `iv` lies below
    /// `−margin`, outside when above `+margin` (margin of [`box_scale`]`(b)` and `iv`), else a
    /// surface box with the evaluator `prune` returns (called only then).
    #[inline]
    pub fn classify(b: &Aabb, iv: Interval, prune: impl FnOnce() -> Option<E>) -> Self {
        let m = margin(box_scale(b), iv.lo, iv.hi);
        if iv.hi < -m {
            Pruned::Inside
        } else if iv.lo > m {
            Pruned::Outside
        } else {
            Pruned::Surface(prune())
        }
    }
}
