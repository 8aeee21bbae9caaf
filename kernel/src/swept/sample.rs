//! Choosing the parameters `t_k` of the copies: between consecutive ones, every point of the
//! solid's box moves at most the tolerance.
//!
//! A point `p` of the child (`|p| ≤ ρ`, the box's radius about the child's origin) moves from
//! `M(a)p` to `M(t)p` by at most `∫ₐᵗ |C'| + ρ·θ(a, t)`, `θ` the angle of the rotation between
//! them (`|(R(t) − R(a))p| ≤ 2 sin(θ/2)·ρ ≤ θ·ρ`). Over each fine step `[a, b]` (64 per Bézier
//! piece):
//! - the rotation turns at constant angular speed through the angle between the frames at `a`
//!   and `b` ([`Motion::step_turn`]): exactly known, and spread evenly over the step;
//! - the path's speed is bounded by the control points of the piece restricted to the step: for
//!   a polynomial piece of degree `n`, `n·max|Pᵢ₊₁ − Pᵢ| / (b − a)` (the hodograph's control
//!   points, convex hull property); for a rational one, `2n·(w_max/w_min)·D / (b − a)` (`D` the
//!   diagonal of the control points' box: from `C' = (n/W) Σ Bᵢⁿ⁻¹ (wᵢ₊₁(Pᵢ₊₁ − C) − wᵢ(Pᵢ − C))`
//!   with `C` in the hull and `W ≥ w_min`);
//! - for a formula curve, interval arithmetic on its derivative over the step
//!   ([`FormulaCurve::speed_bound`](crate::curve::FormulaCurve::speed_bound)); only where that
//!   range is unbounded (a division by a range holding 0, a NaN) is the speed *estimated*: the
//!   largest of `|C'|` at the step's ends and midpoint, with a 10 % margin
//!   ([`StepBounds::proven`] is then false).
//!
//! Each step's bound `dᵢ` is that speed bound times `b − a` plus `ρ` times the turn; both parts
//! grow linearly across the step, so the copies are placed greedily where the `dᵢ` add up to the
//! tolerance, within a step by linear interpolation of the parameter, and the travel between
//! consecutive copies is at most the tolerance (proven unless a speed was estimated). A
//! path of total bound `D` gets about `D/τ + 1` copies.

use super::error::SweptError;
use super::motion::Motion;

/// Margin on the sampled speeds of a fine step whose speed has no bound.
const MARGIN: f64 = 1.1;

/// The motion bound of every fine step, and whether they are proven bounds.
pub(super) struct StepBounds {
    /// `dᵢ` per fine step.
    pub bounds: Vec<f64>,
    /// False when a speed was estimated (formula curves).
    pub proven: bool,
}

/// The motion bound `dᵢ` of every fine step for a box of radius `rho`.
pub(super) fn step_bounds(motion: &Motion<'_>, rho: f64) -> Result<StepBounds, SweptError> {
    let fine = &motion.fine;
    let pieces = motion.pieces();
    let mut out = Vec::with_capacity(fine.len().saturating_sub(1));
    let mut piece = 0usize;
    let mut proven = true;
    for (i, w) in fine.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        let travel = match &pieces {
            Some(pieces) => {
                // The piece holding the step (pieces are in parameter order).
                let m = 0.5 * (a + b);
                while piece + 1 < pieces.len() && pieces[piece].t1 <= m {
                    piece += 1;
                }
                let p = &pieces[piece];
                let q = p.restricted(a.max(p.t0), b.min(p.t1));
                let n = (q.points.len().saturating_sub(1)) as f64;
                let pts: Vec<_> = q.projected().collect();
                if q.weight_ratio() == 1.0 && q.points.iter().all(|c| c.w == 1.0) {
                    n * pts
                        .windows(2)
                        .map(|w| w[1].distance(w[0]))
                        .fold(0.0, f64::max)
                } else {
                    2.0 * n * q.weight_ratio() * q.bbox().size().length()
                }
            }
            None => match motion.formula_speed(a, b) {
                Some(speed) => (b - a) * speed,
                None => {
                    proven = false;
                    let m = 0.5 * (a + b);
                    let speed = motion.speed(a).max(motion.speed(m)).max(motion.speed(b));
                    MARGIN * (b - a) * speed
                }
            },
        };
        let d = travel + rho * motion.step_turn(i);
        if !d.is_finite() {
            return Err(SweptError::Path);
        }
        out.push(d);
    }
    Ok(StepBounds {
        bounds: out,
        proven,
    })
}

/// The parameters of the copies for `tolerance`, at most `limit` of them.
pub(super) fn choose(
    fine: &[f64],
    bounds: &[f64],
    tolerance: f64,
    limit: usize,
) -> Result<Vec<f64>, SweptError> {
    let total: f64 = bounds.iter().sum();
    let too_many = |needed: usize| SweptError::TooManyCopies {
        tolerance,
        needed,
        limit,
        minimum: total / (limit as f64 * 0.9),
    };
    let estimate = total / tolerance;
    if estimate > (limit - 2) as f64 {
        return Err(too_many(estimate.min(1e18) as usize + 2));
    }
    let mut params = vec![fine[0]];
    let mut acc = 0.0;
    for (w, &d) in fine.windows(2).zip(bounds) {
        // Within a step the motion is taken as spread evenly over the parameter.
        let (mut from, b) = (w[0], w[1]);
        let mut rest = d;
        while acc + rest > tolerance {
            let mut t = from + (b - from) * ((tolerance - acc) / rest);
            if t >= b {
                // Rounding: the step's end is as far as this step can be cut.
                break;
            }
            if t <= from {
                // The travel to `from` is within the tolerance already (`acc`): a copy there,
                // unless there is one (then the step would need copies closer than a ulp).
                if from <= *params.last().expect("non-empty") {
                    return Err(too_many(limit.saturating_add(1)));
                }
                t = from;
            }
            params.push(t);
            rest -= tolerance - acc;
            from = t;
            acc = 0.0;
            if params.len() > limit {
                return Err(too_many(params.len()));
            }
        }
        acc += rest;
        if acc >= tolerance {
            params.push(b);
            acc = 0.0;
        }
    }
    let end = *fine.last().expect("non-empty");
    if *params.last().expect("non-empty") < end && acc > 0.0 {
        params.push(end);
    }
    if params.len() > limit {
        return Err(too_many(params.len()));
    }
    Ok(params)
}
