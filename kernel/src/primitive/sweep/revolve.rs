//! Revolution of a profile around the z axis. The profile lives in the half-plane `(ρ, z)`,
//! `ρ ≥ 0` (its x coordinate is the distance from the axis, its y is z); a full turn sweeps it
//! around the axis, a partial one from angle 0 (the +x half-plane) counter-clockwise to `angle`
//! degrees, closed by the two planar end faces.
//!
//! Field: exact signed distance everywhere. For a point at angle `φ` inside the swept wedge the
//! nearest copy of the profile is the one in its own half-plane (every profile point has `ρ ≥ 0`,
//! so `|p − x|² = ρ² − 2ρρ' cos Δφ + ρ'² + Δz²` is smallest at `Δφ = 0`): the value is the profile
//! distance of `(ρ, z)`, and inside the solid the end faces compete. Outside the wedge the nearest
//! copy is the nearer end face, at distance `√(b² + max(d(a, z), 0)²)` with `(a, b)` the in-plane
//! and out-of-plane coordinates. So `field_error() = 0` and the Lipschitz constant is 1.
//!
//! Faceted full turns ([`Revolve::faceted`], OpenSCAD's `rotate_extrude` with `n` fragments):
//! the profile is swept in `n` straight steps between the half-planes at angles
//! `start + 2πj/n`, so every circle the profile's points travel becomes the regular `n`-gon
//! inscribed in it (a chord between two consecutive copies of a point is parallel to the chord
//! of any other point, so each step's quads are planar trapezoids). A point `q` in the sector
//! with unit bisector `u` lies on the `n`-gon of circumradius `ρ_n(q) = (q·u) / cos(π/n)`, so
//! the solid is `{(ρ_n(q), z) ∈ profile}`. `ρ_n` is continuous and piecewise linear with gradient
//! norm `1 / cos(π/n)`, so the field `cos(π/n) · d(ρ_n, z)` has the exact zero set and a
//! gradient of norm at most 1 (a distance bound). The volume is `n sin(2π/n) · A · x̄` (the
//! `n`-gon of circumradius `ρ` has area `(n/2) ρ² sin(2π/n)`), against `2π · A · x̄` for the smooth
//! turn.

use super::error::{SweepError, invalid};
use crate::primitive::{PrimitiveError, Shape, lipschitz_interval};
use crate::profile::Profile;
use crate::{Aabb, Interval};
use glam::{DVec2, DVec3};
use std::f64::consts::{FRAC_PI_2, TAU};

/// A profile revolved around the z axis by `angle` degrees (360: a full turn).
#[derive(Debug, Clone, PartialEq)]
pub struct Revolve {
    profile: Profile,
    angle: f64,
    /// The angle in radians.
    alpha: f64,
    /// The straight steps of a faceted full turn.
    facets: Option<Facets>,
}

/// The steps of a faceted turn (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Facets {
    /// Number of steps `n ≥ 3`.
    n: u32,
    /// Angle of the first half-plane the profile stops at, radians.
    start: f64,
    /// `cos(π/n)`: the inradius of the unit `n`-gon.
    inradius: f64,
}

/// The most steps a faceted turn may take (a bound against hostile input; a turn that fine is
/// indistinguishable from the smooth one at any grid).
const MAX_SEGMENTS: u32 = 1 << 16;

impl Revolve {
    /// The revolution of `profile` (in the half-plane x ≥ 0 of its plane) by `angle` degrees,
    /// `0 < angle ≤ 360`.
    pub fn new(profile: Profile, angle: f64) -> Result<Revolve, SweepError> {
        profile.validate().map_err(|error| SweepError::Profile {
            key: "profile",
            error,
        })?;
        if !(angle.is_finite() && angle > 0.0 && angle <= 360.0) {
            return Err(invalid("angle", "expected degrees in (0, 360]"));
        }
        if profile.bounds().0.x < 0.0 {
            return Err(invalid(
                "profile",
                "the profile must lie at x ≥ 0 (x is the distance from the axis)",
            ));
        }
        Ok(Revolve {
            profile,
            angle,
            alpha: angle.to_radians(),
            facets: None,
        })
    }

    /// A full turn of `profile` in `segments` straight steps (3 to 65536),
    /// stopping at the half-planes at `start + 360·j/segments` degrees: the faceted solid
    /// OpenSCAD's `rotate_extrude` makes (see the module docs).
    pub fn faceted(profile: Profile, segments: u32, start: f64) -> Result<Revolve, SweepError> {
        if !(3..=MAX_SEGMENTS).contains(&segments) {
            return Err(invalid(
                "segments",
                "expected a whole number of steps from 3 to 65536",
            ));
        }
        if !start.is_finite() {
            return Err(invalid("start", "expected finite degrees"));
        }
        let mut r = Revolve::new(profile, 360.0)?;
        r.facets = Some(Facets {
            n: segments,
            start: start.rem_euclid(360.0).to_radians(),
            inradius: (std::f64::consts::PI / f64::from(segments)).cos(),
        });
        Ok(r)
    }

    /// The number of straight steps of a faceted turn and the angle of its first stop in
    /// degrees; `None` for a smooth revolution.
    pub fn segments(&self) -> Option<(u32, f64)> {
        self.facets.map(|f| (f.n, f.start.to_degrees()))
    }

    /// The profile (x: distance from the axis, y: height).
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// The angle swept, in degrees.
    pub fn angle(&self) -> f64 {
        self.angle
    }

    /// True for a full turn.
    pub fn is_full(&self) -> bool {
        self.angle >= 360.0
    }

    /// Distance between the field's zero set and the exact surface: 0.
    pub fn field_error(&self) -> f64 {
        0.0
    }

    /// Exact volume by Pappus's theorem: swept angle × centroid distance × area (for a faceted
    /// turn, `n sin(2π/n)` in place of the angle).
    pub fn volume(&self) -> f64 {
        let (area, centroid) = self.profile.area_centroid();
        let turn = match self.facets {
            Some(f) => f64::from(f.n) * (TAU / f64::from(f.n)).sin(),
            None => self.alpha,
        };
        turn * centroid.x * area
    }

    /// The profile distance in the meridian half-plane, ignoring profile edges on the axis (they
    /// are inside the solid): a rectangle touching the axis is read as its mirror-symmetric
    /// double, a polygon skips its edges on the axis.
    fn meridian(&self, q: DVec2) -> (f64, DVec2) {
        match &self.profile {
            Profile::Rectangle(r) if r.center.x - 0.5 * r.size.x <= 0.0 => {
                let outer = r.center.x + 0.5 * r.size.x;
                let symmetric = crate::profile::Rectangle {
                    center: DVec2::new(0.0, r.center.y),
                    size: DVec2::new(2.0 * outer, r.size.y),
                };
                symmetric.distance_gradient(q)
            }
            Profile::Polygon(p) => p.distance_gradient_off_axis(q),
            other => other.distance_gradient(q),
        }
    }

    /// Distance to the end face at angle `psi` and its gradient.
    fn face(&self, p: DVec3, psi: f64) -> (f64, DVec3) {
        let (s, c) = psi.sin_cos();
        let (along, across) = (DVec3::new(c, s, 0.0), DVec3::new(-s, c, 0.0));
        let (a, b) = (p.dot(along), p.dot(across));
        let (d, g) = self.profile.distance_gradient(DVec2::new(a, p.z));
        let d = d.max(0.0);
        let e = (b * b + d * d).sqrt();
        if e == 0.0 {
            return (0.0, across);
        }
        let grad = across * (b / e) + (along * g.x + DVec3::Z * g.y) * (d / e);
        (e, grad)
    }

    /// Field value and gradient of a faceted turn: the profile distance at the `n`-gon radius
    /// `ρ_n`, scaled by the inradius (see the module docs).
    fn eval_faceted(&self, p: DVec3, f: Facets) -> (f64, DVec3) {
        let step = TAU / f64::from(f.n);
        let phi = p.y.atan2(p.x) - f.start;
        let mid = f.start + ((phi / step).floor() + 0.5) * step;
        let (s, c) = mid.sin_cos();
        let rho = (p.x * c + p.y * s) / f.inradius;
        let (d, g) = self.meridian(DVec2::new(rho, p.z));
        (
            d * f.inradius,
            DVec3::new(c * g.x, s * g.x, f.inradius * g.y),
        )
    }

    /// Field value and gradient.
    fn eval(&self, p: DVec3) -> (f64, DVec3) {
        if let Some(f) = self.facets {
            return self.eval_faceted(p, f);
        }
        let rho = (p.x * p.x + p.y * p.y).sqrt();
        let radial = if rho > 0.0 {
            DVec3::new(p.x / rho, p.y / rho, 0.0)
        } else {
            DVec3::X
        };
        let (d, g) = self.meridian(DVec2::new(rho, p.z));
        let lateral = (d, radial * g.x + DVec3::Z * g.y);
        if self.is_full() {
            return lateral;
        }
        let mut phi = p.y.atan2(p.x);
        if phi < 0.0 {
            phi += TAU;
        }
        if phi <= self.alpha {
            if d >= 0.0 {
                return lateral;
            }
            // Inside: the nearest of the lateral surface and the two end faces.
            let mut best = lateral;
            for psi in [0.0, self.alpha] {
                let (e, ge) = self.face(p, psi);
                if e < -best.0 {
                    best = (-e, -ge);
                }
            }
            return best;
        }
        let psi = if TAU - phi <= phi - self.alpha {
            0.0
        } else {
            self.alpha
        };
        self.face(p, psi)
    }
}

impl Shape for Revolve {
    fn value(&self, p: DVec3) -> f64 {
        self.eval(p).0
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        self.eval(p).1
    }
    fn interval(&self, b: &Aabb) -> Interval {
        lipschitz_interval(self, b)
    }
    fn bbox(&self) -> Aabb {
        let (lo, hi) = self.profile.bounds();
        let (r0, r1) = (lo.x, hi.x);
        let mut points = vec![DVec2::new(r0, 0.0), DVec2::new(r1, 0.0)];
        let (s, c) = self.alpha.sin_cos();
        points.push(DVec2::new(c, s) * r0);
        points.push(DVec2::new(c, s) * r1);
        // Outer arc extremes at the axis directions the sweep passes.
        for k in 1..4 {
            let a = k as f64 * FRAC_PI_2;
            if a < self.alpha {
                points.push(DVec2::new(a.cos(), a.sin()) * r1);
            }
        }
        let (mut mn, mut mx) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        for q in points {
            mn = mn.min(q);
            mx = mx.max(q);
        }
        // Rounding of cos/sin at the axis directions: widen by a few ulps of the radius.
        let eps = 1e-12 * r1;
        Aabb::new(
            DVec3::new(mn.x - eps, mn.y - eps, lo.y),
            DVec3::new(mx.x + eps, mx.y + eps, hi.y),
        )
    }
    fn bbox_at(&self, level: f64) -> Aabb {
        // A faceted turn's value at `q` is `cos(π/n)` times the meridian distance of
        // `(ρ_n, z)`, and `|q| ≤ ρ_n`: within `level / cos(π/n)` of the profile's box of radii.
        let grow = self.facets.map_or(level, |f| level / f.inradius);
        self.bbox().expanded(grow)
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked when built: a `Revolve` is always valid.
        Ok(())
    }
}
