//! The capped cone (frustum) along z, centred at the origin: radius `r₁` at `z = −h/2`, `r₂` at
//! `z = h/2`; either radius may be zero (a pointed cone). Exact distance, computed in the
//! half-plane `(ρ, z)` as the distance to the three profile segments (bottom cap, side, top cap).

use super::{PrimitiveError, Shape, lipschitz_interval, non_negative, positive, radial};
use crate::{Aabb, Interval};
use glam::{DVec2, DVec3};

/// A capped cone along z, centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cone {
    /// Radius at `z = −height/2`.
    pub bottom_radius: f64,
    /// Radius at `z = +height/2`.
    pub top_radius: f64,
    /// Height (length along z).
    pub height: f64,
}

impl Cone {
    /// Signed distance in the profile half-plane and the unit direction of increase.
    ///
    /// The caps are horizontal, so their distances are computed directly (`hypot(max(ρ − r, 0),
    /// z − z_cap)`), which is exactly zero on a cap: a cap lying on a sample plane then gives
    /// exact zeros (one fixed side) rather than rounding noise of either sign.
    fn profile(&self, q: DVec2) -> (f64, DVec2) {
        let h = self.height * 0.5;
        let (r1, r2) = (self.bottom_radius, self.top_radius);
        let cap = |r: f64, z: f64, normal: f64| {
            let (dx, dz) = ((q.x - r).max(0.0), q.y - z);
            let d = (dx * dx + dz * dz).sqrt();
            (d, DVec2::new(q.x.min(r), z), DVec2::new(0.0, normal))
        };
        let mut best = cap(r1, -h, -1.0);
        let top = cap(r2, h, 1.0);
        if top.0 < best.0 {
            best = top;
        }
        let (a, b) = (DVec2::new(r1, -h), DVec2::new(r2, h));
        let ab = b - a;
        // Which part of the side is nearest, measured from each end (`(q − a)·ab / |ab|²` rounds
        // to 1 near the smaller end when one radius dwarfs the other: bottom 1.2e20, top 0.56
        // gave the distance to the top rim for every point near the axis, a field far from
        // 1-Lipschitz, and open meshes in issue 15's fuzzing).
        let (from_a, from_b) = ((q - a).dot(ab), (q - b).dot(ab));
        // Between the ends, the distance to the side line by projection on its unit normal:
        // stable for any height. (`|q − (a + t·ab)|` cancels catastrophically when the height
        // dwarfs the radii: errors of ε·h, 10⁴ at h = 10²⁰, broke meshes in issue 15.)
        let (d, c) = if from_a > 0.0 && from_b < 0.0 {
            let n = DVec2::new(ab.y, -ab.x) / ab.length();
            let s = (q - a).dot(n);
            (s.abs(), q - n * s)
        } else {
            let c = if from_a <= 0.0 { a } else { b };
            ((q - c).length(), c)
        };
        if d < best.0 {
            best = (d, c, DVec2::new(ab.y, -ab.x).normalize());
        }
        let (d, c, n) = best;
        // The side's radius at q's height, from the nearer end (the other end's radius may
        // swallow the nearer one's).
        let side = if q.y >= 0.0 {
            r2 + (r1 - r2) * (h - q.y) / (2.0 * h)
        } else {
            r1 + (r2 - r1) * (q.y + h) / (2.0 * h)
        };
        let inside = q.y.abs() <= h && q.x <= side;
        let dir = if d > 1e-300 { (q - c) / d } else { n };
        if inside { (-d, -dir) } else { (d, dir) }
    }
}

fn to_profile(p: DVec3) -> DVec2 {
    DVec2::new((p.x * p.x + p.y * p.y).sqrt(), p.z)
}

impl Shape for Cone {
    fn value(&self, p: DVec3) -> f64 {
        self.profile(to_profile(p)).0
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        let g = self.profile(to_profile(p)).1;
        radial(p) * g.x + DVec3::Z * g.y
    }
    fn interval(&self, b: &Aabb) -> Interval {
        lipschitz_interval(self, b)
    }
    fn bbox(&self) -> Aabb {
        let r = self.bottom_radius.max(self.top_radius);
        Aabb::centered(DVec3::new(r, r, self.height * 0.5))
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        non_negative("bottom_radius", self.bottom_radius)?;
        non_negative("top_radius", self.top_radius)?;
        positive("height", self.height)?;
        if self.bottom_radius == 0.0 && self.top_radius == 0.0 {
            return Err(PrimitiveError {
                parameter: "bottom_radius",
                problem: "a cone needs at least one positive radius",
            });
        }
        Ok(())
    }
}
