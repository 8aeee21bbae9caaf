//! Choosing the parameters `t_k` of the copies: between consecutive ones, every point of the
//! solid's box moves at most the tolerance.
//!
//! A point `p` of the child (`|p| ≤ ρ`, the box's radius about the child's origin) moves along
//! `C(t) + R(t)p` at speed at most `|C'(t)| + ρ·|ω(t)|` (`ω` the frame's angular velocity).
//! Over each fine step `[a, b]` (64 per Bézier piece) the path moves at most
//! `(b − a)·max(|C'(a)|, |C'(m)|, |C'(b)|)` (`m` the midpoint) and the frame turns by at most
//! `∠(R(a), R(m)) + ∠(R(m), R(b))`; their sum, with the box radius and a 10 % margin, bounds the
//! step's motion `dᵢ` wherever the speed and the turning rate vary by less than 10 % over a fine
//! step. The copies are placed greedily where the `dᵢ` add up to the tolerance (within a fine
//! step, by linear interpolation of the parameter), so a path of total bound `D` gets about
//! `D/τ + 1` copies.

use super::error::SweptError;
use super::motion::{Motion, angle_between};

/// Margin on the sampled speeds and angles of a fine step.
const MARGIN: f64 = 1.1;

/// The motion bound `dᵢ` of every fine step for a box of radius `rho`.
pub(super) fn step_bounds(motion: &Motion<'_>, rho: f64) -> Result<Vec<f64>, SweptError> {
    let fine = &motion.fine;
    let mut out = Vec::with_capacity(fine.len().saturating_sub(1));
    let mut prev = (motion.speed(fine[0]), motion.rotation(fine[0]));
    for w in fine.windows(2) {
        let (a, b) = (w[0], w[1]);
        let m = 0.5 * (a + b);
        let mid = (motion.speed(m), motion.rotation(m));
        let end = (motion.speed(b), motion.rotation(b));
        let speed = prev.0.max(mid.0).max(end.0);
        let turn = if motion.turns() {
            angle_between(prev.1, mid.1) + angle_between(mid.1, end.1)
        } else {
            0.0
        };
        let d = MARGIN * ((b - a) * speed + rho * turn);
        if !d.is_finite() {
            return Err(SweptError::Path);
        }
        out.push(d);
        prev = end;
    }
    Ok(out)
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
            let t = from + (b - from) * ((tolerance - acc) / rest);
            if t <= from || t >= b {
                // Rounding: the step's end is as far as this step can be cut.
                break;
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
        if acc > tolerance {
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
