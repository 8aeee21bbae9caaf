//! The field of a quadric solid `{Q ≤ 0} ∩ B` for a finite box `B`, with an honest Lipschitz
//! constant and a zero set that is exactly the quadric inside `B` (plus the box faces).
//!
//! # Construction
//! Let `c(p)` be `p` clamped into `B` (a 1-Lipschitz projection), `M = max_B |∇Q|` (attained at a
//! corner, `|∇Q|` being convex), `σ = max |eig A|` (so `|∇Q|` is `2σ`-Lipschitz), a length
//! `ℓ = M/(32σ)` (a few percent of the box for typical shapes), `δ = ℓ` and `m = 2σℓ`. Two fields
//! with the sign of `Q`:
//! - `φ₁ = Q/M`, 1-Lipschitz on `B`: a global (if flat) distance bound;
//! - `φ₂ = clamp(Q/w, −δ, δ)` with `w = max(|∇Q|, m)`: Taubin's first-order distance `Q/|∇Q|`,
//!   gradient-normalised (unit gradient on the surface wherever `|∇Q| ≥ m`), damped by `m` near
//!   critical points (a cone's apex) and clamped where it would stop being Lipschitz. Where it is not
//!   clamped, `|∇(Q/w)| ≤ |∇Q|/w + |Q|·|∇w|/w² ≤ 1 + 2σ·δ/m = 2`.
//!
//! `φ = sign(Q) · max(|φ₁|, |φ₂|)` is 2-Lipschitz (on each side of `Q = 0` a max or min of
//! 2-Lipschitz functions, and 0 on the surface), and the solid's field is
//! `F(p) = max(φ(c(p)), dist_B(p))`, also 2-Lipschitz, negative exactly on the interior of
//! `{Q ≤ 0} ∩ B`. For a linear `Q` (σ = 0) `φ₂ = Q/|∇Q|` is the exact plane distance and `F` is
//! 1-Lipschitz.

use super::coefficients::QuadricCoefficients;
use crate::primitive::{Cuboid, Shape};
use crate::{Aabb, Interval};
use glam::DVec3;

/// Precomputed constants of the bounded quadric field; see the [module docs](self). Internal to
/// [`Quadric`](super::Quadric).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BoundedField {
    coefficients: QuadricCoefficients,
    bounds: Aabb,
    /// `max_B |∇Q|`.
    max_gradient: f64,
    /// Lower bound `m` of the normalising weight.
    min_weight: f64,
    /// Clamp `δ` of the normalised field (infinite for a linear `Q`).
    clamp: f64,
    /// The Lipschitz constant of the whole field.
    lipschitz: f64,
    /// The box as a centred cuboid and its centre.
    cuboid: Cuboid,
    center: DVec3,
}

impl BoundedField {
    /// The field of `{Q ≤ 0} ∩ bounds`; `sigma` is the largest `|eigenvalue|` of `A`. `None` when
    /// `∇Q` vanishes on the whole box (a constant `Q`).
    pub(crate) fn new(coefficients: QuadricCoefficients, bounds: Aabb, sigma: f64) -> Option<Self> {
        let max_gradient = coefficients.max_gradient_norm(&bounds);
        if !(max_gradient > 0.0 && max_gradient.is_finite()) {
            return None;
        }
        let (min_weight, clamp, lipschitz) = if sigma > 0.0 {
            let length = max_gradient / (32.0 * sigma);
            (2.0 * sigma * length, length, 2.0)
        } else {
            (0.0, f64::INFINITY, 1.0)
        };
        Some(Self {
            coefficients,
            bounds,
            max_gradient,
            min_weight,
            clamp,
            lipschitz,
            cuboid: Cuboid {
                size: bounds.size(),
            },
            center: bounds.center(),
        })
    }

    pub(crate) fn lipschitz(&self) -> f64 {
        self.lipschitz
    }

    pub(crate) fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// `φ` at a point of the box, with `Q` and `∇Q` there.
    #[inline]
    fn phi(&self, q: f64, grad: DVec3) -> f64 {
        let w = grad.length().max(self.min_weight);
        let phi2 = (q / w).clamp(-self.clamp, self.clamp);
        let phi1 = q / self.max_gradient;
        if q >= 0.0 {
            phi1.max(phi2)
        } else {
            phi1.min(phi2)
        }
    }

    #[inline]
    pub(crate) fn value(&self, p: DVec3) -> f64 {
        let x = p.clamp(self.bounds.min, self.bounds.max);
        let phi = self.phi(self.coefficients.value(x), self.coefficients.gradient(x));
        phi.max(self.cuboid.value(p - self.center))
    }

    pub(crate) fn gradient(&self, p: DVec3) -> DVec3 {
        let x = p.clamp(self.bounds.min, self.bounds.max);
        let (q, g) = (self.coefficients.value(x), self.coefficients.gradient(x));
        let phi = self.phi(q, g);
        let box_value = self.cuboid.value(p - self.center);
        if box_value >= phi {
            return self.cuboid.gradient(p - self.center);
        }
        let n = g.length();
        let w = n.max(self.min_weight);
        let phi1 = q / self.max_gradient;
        let inner = if phi == phi1 {
            g / self.max_gradient
        } else if (q / w).abs() >= self.clamp {
            DVec3::ZERO
        } else if n >= self.min_weight && n > 0.0 {
            // ∇(Q/|∇Q|) = ∇Q/|∇Q| − Q·∇|∇Q|/|∇Q|², with ∇|∇Q| = 2A∇Q/|∇Q|.
            let grad_n = 2.0 * (self.coefficients.matrix3() * g) / n;
            g / n - grad_n * (q / (n * n))
        } else {
            g / w
        };
        // The clamp freezes the coordinates outside the box.
        let inside = DVec3::select(
            p.cmpge(self.bounds.min) & p.cmple(self.bounds.max),
            DVec3::ONE,
            DVec3::ZERO,
        );
        inner * inside
    }

    pub(crate) fn interval(&self, b: &Aabb) -> Interval {
        let cb = Aabb::new(
            b.min.clamp(self.bounds.min, self.bounds.max),
            b.max.clamp(self.bounds.min, self.bounds.max),
        );
        let q = self.coefficients.interval(&cb);
        let n = self.coefficients.gradient_norm_interval(&cb);
        let w_lo = n.lo.max(self.min_weight);
        let w_hi = n.hi.min(self.max_gradient).max(self.min_weight).max(w_lo);
        let phi1 = Interval::new(q.lo / self.max_gradient, q.hi / self.max_gradient);
        let ratio = if w_lo <= 0.0 {
            Interval::entire()
        } else if q.lo >= 0.0 {
            Interval::new(q.lo / w_hi, q.hi / w_lo)
        } else if q.hi <= 0.0 {
            Interval::new(q.lo / w_lo, q.hi / w_hi)
        } else {
            Interval::new(q.lo / w_lo, q.hi / w_lo)
        };
        let phi2 = Interval::new(
            ratio.lo.clamp(-self.clamp, self.clamp),
            ratio.hi.clamp(-self.clamp, self.clamp),
        );
        let phi = if q.lo >= 0.0 {
            phi1.max(phi2)
        } else if q.hi <= 0.0 {
            phi1.min(phi2)
        } else {
            Interval::new(phi1.lo.min(phi2.lo), phi1.hi.max(phi2.hi))
        };
        let shifted = Aabb::new(b.min - self.center, b.max - self.center);
        phi.max(self.cuboid.interval(&shifted))
    }
}
