//! Spatial culling of a blob's balls (issue 15: 3000 balls took 33 s to mesh, every sample summing
//! every term, most of them underflowing `exp` on its slow path).
//!
//! With many balls the field is the **truncated sum**: ball `k` counts at `p` only while
//! `a_k |p − c_k|² < E_k`, its cut-off exponent `E_k = ln(|b_k| / ε)` with `ε = T · 2⁻⁶⁰ / N`
//! (0 when `|b_k| ≤ ε`). A dropped term is below `ε`, so all of them together stay below
//! `tail = Σ |b_k| e^{−E_k} ≤ T · 2⁻⁶⁰`, far under one rounding unit of the threshold in double
//! precision (and 2³⁶ times under it in single precision). The rule depends on the point alone
//! (the single-precision path tests it in single precision), so every chunk, brick, pruned or
//! full program and the dense path give a sample the same bits. Intervals sum the exact ranges of
//! the balls whose reach meets the box and widen by `tail` (a truncated term lies within its
//! range or at 0, within `|b_k| e^{−E_k}` of it; farther balls add 0).
//!
//! The reach boxes (radius `√(E_k / a_k)`, a little enlarged, around both the exact centre and
//! its `f32` rounding, which the batch path subtracts) are indexed by the kernel's
//! [`TriangleBvh`] (each box stored as the degenerate triangle `[min, max, max]`, whose box it
//! is). A query returns the balls whose reach box meets a box, in ascending order, so sums run in
//! input order.

use super::ball::Ball;
use crate::bvh::TriangleBvh;
use glam::DVec3;

/// Below this many balls the plain sum is as fast as a query.
pub(super) const MIN_BALLS: usize = 32;

/// The balls' reach boxes in a tree, their cut-off exponents, and the bound of what the dropped
/// terms add.
#[derive(Debug, Clone)]
pub(super) struct Cull {
    tree: TriangleBvh,
    /// `E_k` per ball.
    cutoff: Vec<f64>,
    /// `E_k` per ball in single precision (the batch path's test).
    cutoff_f32: Vec<f32>,
    /// `Σ |b_k| e^{−E_k}`: the dropped terms' total is within `±tail`.
    tail: f64,
}

impl Cull {
    /// The index of `balls` (valid balls, threshold `t > 0`); `None` for few balls (or a tree
    /// that cannot be built).
    pub(super) fn new(balls: &[Ball], t: f64) -> Option<Cull> {
        if balls.len() < MIN_BALLS {
            return None;
        }
        // ln(1/ε) = ln(N / T) + 60 ln 2.
        let log_inv_eps = (balls.len() as f64 / t).ln() + 60.0 * std::f64::consts::LN_2;
        let mut tail = 0.0;
        let cutoff: Vec<f64> = balls
            .iter()
            .map(|b| (b.strength.abs().ln() + log_inv_eps).max(0.0))
            .collect();
        let boxes = balls
            .iter()
            .zip(&cutoff)
            .map(|(b, &e)| {
                tail += b.strength.abs() * (-e).exp();
                // A little over the reach, so that no rounding of the radius, the differences or
                // the products (in either precision) lets a ball count outside its box.
                let r = (e / b.sharpness).sqrt() * (1.0 + 1e-4);
                let c32 = b.center.as_vec3().as_dvec3();
                let lo = b.center.min(c32) - DVec3::splat(r);
                let hi = b.center.max(c32) + DVec3::splat(r);
                [lo, hi, hi]
            })
            .collect();
        let tree = TriangleBvh::new(boxes, 4).ok()?;
        let cutoff_f32 = cutoff.iter().map(|&e| e as f32).collect();
        Some(Cull {
            tree,
            cutoff,
            cutoff_f32,
            tail,
        })
    }

    /// `E_k` of ball `k`.
    pub(super) fn cutoff(&self, k: usize) -> f64 {
        self.cutoff[k]
    }

    /// `E_k` of ball `k` in single precision.
    pub(super) fn cutoff_f32(&self, k: usize) -> f32 {
        self.cutoff_f32[k]
    }

    /// The bound of the culled terms' total.
    pub(super) fn tail(&self) -> f64 {
        self.tail
    }

    /// Sets `out` to the indices of the balls whose reach box meets the box `[lo, hi]`, ascending:
    /// every other ball's term is below its cut-off everywhere in the box.
    pub(super) fn near(&self, lo: DVec3, hi: DVec3, out: &mut Vec<u32>) {
        out.clear();
        self.tree
            .for_each_overlap(lo, hi, |slot| out.push(self.tree.slot_index(slot)));
        out.sort_unstable();
    }
}
