//! One term of a blobby object, `b · exp(−a · |p − c|²)` (lecture notes 002): its value, gradient,
//! exact range over a box, steepest slope and reach.

use super::super::{MAX_MAGNITUDE, OUT_OF_RANGE, PrimitiveError, faithful, positive};

/// The problem with a strength outside the faithful range.
const STRENGTH_RANGE: &str = "expected a magnitude between 1e-30 and 1e30 (beyond that range \
                              single-precision evaluation is not faithful)";
use crate::{Aabb, Interval};
use glam::DVec3;

/// A metaball: the Gaussian bump `strength · exp(−sharpness · |p − center|²)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ball {
    /// Centre `c`.
    pub center: DVec3,
    /// Height `b` of the bump at its centre (negative for a subtractive ball).
    pub strength: f64,
    /// Decay rate `a > 0` (1/length²).
    pub sharpness: f64,
}

impl Ball {
    /// `b · exp(−a r²)` at `p`.
    #[inline]
    pub fn term(&self, p: DVec3) -> f64 {
        self.strength * (-self.sharpness * p.distance_squared(self.center)).exp()
    }

    /// Gradient of the term: `−2ab (p − c) exp(−a r²)`.
    #[inline]
    pub fn term_gradient(&self, p: DVec3) -> DVec3 {
        let d = p - self.center;
        d * (-2.0 * self.sharpness * self.strength * (-self.sharpness * d.length_squared()).exp())
    }

    /// The exact range of the term over a box: it depends on `r` alone and is monotone in it, so
    /// its extremes are at the box's nearest and farthest points from the centre.
    pub fn term_range(&self, b: &Aabb) -> Interval {
        let below = b.min - self.center;
        let above = self.center - b.max;
        let near = below.max(above).max(DVec3::ZERO).length_squared();
        let far = below.abs().max(above.abs()).length_squared();
        let (hi, lo) = (
            (-self.sharpness * near).exp() * self.strength,
            (-self.sharpness * far).exp() * self.strength,
        );
        Interval::new(lo, hi)
    }

    /// The largest `|∇|` of the term, `|b| · √(2a) · e^{−1/2}`, reached at `r = 1/√(2a)`.
    pub fn max_slope(&self) -> f64 {
        self.strength.abs() * (2.0 * self.sharpness).sqrt() * (-0.5f64).exp()
    }

    /// The radius beyond which the term stays below `level` (`0 < level`): `√(ln(b / level) / a)`,
    /// zero when `level ≥ b`.
    pub fn reach(&self, level: f64) -> f64 {
        if self.strength <= level {
            0.0
        } else {
            ((self.strength / level).ln() / self.sharpness).sqrt()
        }
    }

    /// Checks the ball's parameters.
    pub fn validate(&self) -> Result<(), PrimitiveError> {
        if !self.center.is_finite() {
            return Err(PrimitiveError {
                parameter: "center",
                problem: "expected finite numbers",
            });
        }
        if !self.strength.is_finite() || self.strength == 0.0 {
            return Err(PrimitiveError {
                parameter: "strength",
                problem: "expected a finite nonzero number",
            });
        }
        // Single precision evaluates the terms: a strength of 1e300 was ∞ there (an open mesh,
        // issue 15), and a centre beyond the faithful range cancels every sample.
        if !faithful(self.strength) {
            return Err(PrimitiveError {
                parameter: "strength",
                problem: STRENGTH_RANGE,
            });
        }
        if self.center.abs().max_element() > MAX_MAGNITUDE {
            return Err(PrimitiveError {
                parameter: "center",
                problem: OUT_OF_RANGE,
            });
        }
        positive("sharpness", self.sharpness)
    }
}
