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

mod ball;

pub use ball::Ball;

use super::{PrimitiveError, Shape, positive};
use crate::{Aabb, Interval};
use glam::DVec3;

/// A blobby object: the solid where the balls' summed field reaches the threshold.
#[derive(Debug, Clone, PartialEq)]
pub struct Blob {
    balls: Vec<Ball>,
    threshold: f64,
    lipschitz: f64,
    bbox: Aabb,
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
        Ok(Self {
            balls,
            threshold,
            lipschitz,
            bbox,
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

    /// `Σ b_k exp(−a_k r_k²)` at `p`.
    pub fn density(&self, p: DVec3) -> f64 {
        self.balls.iter().map(|b| b.term(p)).sum()
    }
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
        self.threshold - self.density(p)
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        -self
            .balls
            .iter()
            .fold(DVec3::ZERO, |acc, b| acc + b.term_gradient(p))
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let sum = self
            .balls
            .iter()
            .fold(Interval::point(0.0), |acc, ball| acc + ball.term_range(b));
        Interval::point(self.threshold) - sum
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
        for ball in &self.balls {
            let c = ball.center.as_vec3();
            let (a, s) = (ball.sharpness as f32, ball.strength as f32);
            for (i, o) in out.iter_mut().enumerate() {
                let (dx, dy, dz) = (x[i] - c.x, y[i] - c.y, z[i] - c.z);
                *o -= s * (-a * (dx * dx + dy * dy + dz * dz)).exp();
            }
        }
    }
}

#[cfg(test)]
mod tests;
