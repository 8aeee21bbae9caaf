//! Blobby objects (metaballs, lecture notes 002): `Σ_k b_k exp(−a_k r_k²) = T`, written in the
//! kernel's sign convention (negative inside) as
//!
//! `f(p) = T − Σ_k b_k exp(−a_k |p − c_k|²)`.
//!
//! - Interval over a box: each term's exact range (from the box's nearest and farthest points to
//!   its centre), summed.
//! - Lipschitz constant: `Σ_k |b_k| √(2 a_k) e^{−1/2}`, the sum of each term's steepest slope.
//! - Bounding box: with `S` the sum of the positive strengths, a point is inside only if some
//!   positive ball has `exp(−a_k r_k²) ≥ T / S`, i.e. `r_k ≤ √(ln(S/T) / a_k)`; the box is the
//!   union of those balls' boxes.
//!
//! `f` is not a distance: `|f| / L` is a (conservative) distance bound.
//!
//! Many balls (from `cull::MIN_BALLS`): the field is the sum truncated where a term falls below
//! `T · 2⁻⁶⁰ / N` (at most `T · 2⁻⁶⁰` in all, `cull.rs`), and values, gradients and intervals visit
//! only the balls whose reach meets the point, chunk or box, so a sample costs the balls near it
//! rather than all of them.

mod ball;
mod cull;

pub use ball::Ball;

use super::{PrimitiveError, Shape, positive};
use crate::{Aabb, Interval};
use cull::Cull;
use glam::DVec3;
use std::cell::RefCell;

thread_local! {
    /// The ball indices of the current query (no allocation per sample).
    static NEAR: RefCell<Vec<u32>> = const { RefCell::new(Vec::new()) };
}

/// A blobby object: the solid where the balls' summed field reaches the threshold.
#[derive(Debug, Clone)]
pub struct Blob {
    balls: Vec<Ball>,
    threshold: f64,
    lipschitz: f64,
    bbox: Aabb,
    /// The balls' reach index (many balls only).
    cull: Option<Cull>,
}

impl PartialEq for Blob {
    fn eq(&self, other: &Self) -> bool {
        // Everything else is derived from the balls and the threshold.
        self.balls == other.balls && self.threshold == other.threshold
    }
}

impl Blob {
    /// The solid `Σ b_k exp(−a_k r_k²) ≥ threshold`. Fails on an invalid ball, a threshold that is
    /// not positive (the solid would be unbounded), or one at or above the sum of the positive
    /// strengths (the solid would be empty).
    pub fn new(balls: Vec<Ball>, threshold: f64) -> Result<Self, PrimitiveError> {
        if balls.is_empty() {
            return Err(PrimitiveError {
                parameter: "balls",
                problem: "expected at least one ball",
            });
        }
        for b in &balls {
            b.validate()?;
        }
        positive("threshold", threshold)?;
        let total: f64 = balls.iter().map(|b| b.strength.max(0.0)).sum();
        if total <= threshold {
            return Err(PrimitiveError {
                parameter: "threshold",
                problem: "must be below the sum of the positive strengths (the solid is empty)",
            });
        }
        let bbox = density_box(&balls, threshold);
        let lipschitz = balls.iter().map(Ball::max_slope).sum();
        let cull = Cull::new(&balls, threshold);
        Ok(Self {
            balls,
            threshold,
            lipschitz,
            bbox,
            cull,
        })
    }

    /// The balls.
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }

    /// The threshold `T`.
    pub fn threshold(&self) -> f64 {
        self.threshold
    }

    /// `Σ b_k exp(−a_k r_k²)` at `p` (every term).
    pub fn density(&self, p: DVec3) -> f64 {
        self.balls.iter().map(|b| b.term(p)).sum()
    }

    /// The balls' terms at `p`, summed in input order: every term, or with an index the
    /// truncated sum (`cull.rs`; within `T · 2⁻⁶⁰` of [`Blob::density`]).
    fn sum_terms<T: std::ops::Add<Output = T>>(
        &self,
        p: DVec3,
        zero: T,
        term: impl Fn(&Ball, DVec3) -> T,
    ) -> T {
        let Some(cull) = &self.cull else {
            return self.balls.iter().fold(zero, |acc, b| acc + term(b, p));
        };
        with_near(cull, p, p, |near| {
            near.iter().fold(zero, |acc, &k| {
                let b = &self.balls[k as usize];
                if b.sharpness * p.distance_squared(b.center) < cull.cutoff(k as usize) {
                    acc + term(b, p)
                } else {
                    acc
                }
            })
        })
    }
}

/// Runs `f` with the indices of the balls whose reach box meets `[lo, hi]`, ascending.
fn with_near<R>(cull: &Cull, lo: DVec3, hi: DVec3, f: impl FnOnce(&[u32]) -> R) -> R {
    NEAR.with(|cell| match cell.try_borrow_mut() {
        Ok(mut near) => {
            cull.near(lo, hi, &mut near);
            f(&near)
        }
        Err(_) => {
            let mut near = Vec::new();
            cull.near(lo, hi, &mut near);
            f(&near)
        }
    })
}

/// A box holding every point where the density reaches `t > 0`: with `S` the sum of the
/// positive strengths, only within `√(ln(S/t) / a_k)` of a positive ball (empty when `t ≥ S`).
fn density_box(balls: &[Ball], t: f64) -> Aabb {
    let total: f64 = balls.iter().map(|b| b.strength.max(0.0)).sum();
    let mut bbox = Aabb::empty();
    for b in balls.iter().filter(|b| b.strength > 0.0) {
        let r = ((total / t).ln() / b.sharpness).sqrt();
        bbox = bbox.union(&Aabb::new(
            b.center - DVec3::splat(r),
            b.center + DVec3::splat(r),
        ));
    }
    bbox
}

impl Shape for Blob {
    fn value(&self, p: DVec3) -> f64 {
        self.threshold - self.sum_terms(p, 0.0, Ball::term)
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        -self.sum_terms(p, DVec3::ZERO, Ball::term_gradient)
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let zero = Interval::point(0.0);
        let Some(cull) = &self.cull else {
            let sum = (self.balls.iter()).fold(zero, |acc, ball| acc + ball.term_range(b));
            return Interval::point(self.threshold) - sum;
        };
        let sum = with_near(cull, b.min, b.max, |near| {
            near.iter()
                .fold(zero, |acc, &k| acc + self.balls[k as usize].term_range(b))
        });
        let tail = cull.tail();
        Interval::point(self.threshold) - Interval::new(sum.lo - tail, sum.hi + tail)
    }
    fn bbox(&self) -> Aabb {
        self.bbox
    }
    fn bbox_at(&self, level: f64) -> Aabb {
        // T − density ≤ ℓ ⇔ density ≥ T − ℓ: everywhere once ℓ reaches T (the density tends
        // to 0 far away), else the balls' reach at the lower threshold.
        if level <= 0.0 {
            self.bbox
        } else if level >= self.threshold {
            Aabb::infinite()
        } else {
            density_box(&self.balls, self.threshold - level)
        }
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked once by `Blob::new`; the fields are private.
        Ok(())
    }
    fn lipschitz(&self) -> f64 {
        self.lipschitz
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len().min(x.len()).min(y.len()).min(z.len());
        let out = &mut out[..n];
        out.fill(self.threshold as f32);
        let Some(cull) = &self.cull else {
            for ball in &self.balls {
                let c = ball.center.as_vec3();
                let (a, s) = (ball.sharpness as f32, ball.strength as f32);
                for (i, o) in out.iter_mut().enumerate() {
                    let (dx, dy, dz) = (x[i] - c.x, y[i] - c.y, z[i] - c.z);
                    *o -= s * (-a * (dx * dx + dy * dy + dz * dz)).exp();
                }
            }
            return;
        };
        if n == 0 {
            return;
        }
        let (lo, hi) = chunk_box(&x[..n], &y[..n], &z[..n]);
        with_near(cull, lo, hi, |near| {
            for &k in near {
                let ball = &self.balls[k as usize];
                let c = ball.center.as_vec3();
                let (a, s) = (ball.sharpness as f32, ball.strength as f32);
                let cutoff = cull.cutoff_f32(k as usize);
                for (i, o) in out.iter_mut().enumerate() {
                    let (dx, dy, dz) = (x[i] - c.x, y[i] - c.y, z[i] - c.z);
                    let e = a * (dx * dx + dy * dy + dz * dz);
                    if e < cutoff {
                        *o -= s * (-e).exp();
                    }
                }
            }
        });
    }
}

/// The box of a chunk of points (`n > 0`).
fn chunk_box(x: &[f32], y: &[f32], z: &[f32]) -> (DVec3, DVec3) {
    let (mut lo, mut hi) = (glam::Vec3::INFINITY, glam::Vec3::NEG_INFINITY);
    for i in 0..x.len() {
        let p = glam::Vec3::new(x[i], y[i], z[i]);
        lo = lo.min(p);
        hi = hi.max(p);
    }
    (lo.as_dvec3(), hi.as_dvec3())
}

#[cfg(test)]
mod tests;
