//! The axis-aligned rectangle profile: the exact box distance
//! `|max(|q − c| − h, 0)| + min(max(dx, dy), 0)` with `h` the half size.

use super::error::{ProfileError, positive};
use glam::DVec2;

/// An axis-aligned rectangle of full size `size` centred at `center`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rectangle {
    /// Centre.
    pub center: DVec2,
    /// Width and height.
    pub size: DVec2,
}

impl Rectangle {
    /// Checks that the centre is finite and both sides positive.
    pub fn validate(&self) -> Result<(), ProfileError> {
        if !self.center.is_finite() {
            return Err(ProfileError::NonFinite {
                parameter: "center",
            });
        }
        positive("size", self.size.x)?;
        positive("size", self.size.y)
    }

    /// Signed distance and its gradient.
    pub fn distance_gradient(&self, q: DVec2) -> (f64, DVec2) {
        let v = q - self.center;
        let s = DVec2::new(sign(v.x), sign(v.y));
        let d = v.abs() - self.size * 0.5;
        if d.x > 0.0 || d.y > 0.0 {
            let o = d.max(DVec2::ZERO);
            let l = o.length();
            (l, o / l * s)
        } else if d.x > d.y {
            (d.x, DVec2::new(s.x, 0.0))
        } else {
            (d.y, DVec2::new(0.0, s.y))
        }
    }

    /// The four corners, counter-clockwise from the lower left.
    pub fn corners(&self) -> [DVec2; 4] {
        let h = self.size * 0.5;
        let c = self.center;
        [
            c + DVec2::new(-h.x, -h.y),
            c + DVec2::new(h.x, -h.y),
            c + DVec2::new(h.x, h.y),
            c + DVec2::new(-h.x, h.y),
        ]
    }
}

fn sign(x: f64) -> f64 {
    if x >= 0.0 { 1.0 } else { -1.0 }
}
