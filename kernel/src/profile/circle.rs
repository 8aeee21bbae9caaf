//! The disc profile: `d(q) = |q − c| − r`, an exact signed distance.

use super::error::{ProfileError, positive};
use glam::DVec2;

/// A disc of radius `radius` around `center`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Centre.
    pub center: DVec2,
    /// Radius.
    pub radius: f64,
}

impl Circle {
    /// Checks that the centre is finite and the radius positive.
    pub fn validate(&self) -> Result<(), ProfileError> {
        if !self.center.is_finite() {
            return Err(ProfileError::NonFinite {
                parameter: "center",
            });
        }
        positive("radius", self.radius)
    }

    /// Signed distance and its gradient.
    pub fn distance_gradient(&self, q: DVec2) -> (f64, DVec2) {
        let v = q - self.center;
        let l = v.length();
        let g = if l > 0.0 { v / l } else { DVec2::X };
        (l - self.radius, g)
    }

    /// `segments` points around the circle, counter-clockwise from angle 0.
    pub fn outline(&self, segments: usize) -> Vec<DVec2> {
        (0..segments)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / segments as f64;
                self.center + DVec2::new(a.cos(), a.sin()) * self.radius
            })
            .collect()
    }
}
