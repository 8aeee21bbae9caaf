//! Linear extrusion of a profile along z over `[−h/2, h/2]`, optionally twisted (the profile turns
//! by `twist` degrees from bottom to top) and scaled (its size goes linearly from 1 at the bottom
//! to `scale` at the top, about the z axis; `scale` may differ along x and y, as OpenSCAD's
//! `linear_extrude(scale = [sx, sy])`, and be 0 along one axis or both: a wedge to a segment or a
//! cone to the apex, whose degenerate top slice is evaluated with the scale clamped to 10⁻¹²).
//!
//! Field. At height `z` (clamped to the slab) the slice is the profile scaled by
//! `k(z) = 1 + (s − 1)(z + h/2)/h` (per axis: `kx`, `ky`) and then turned by
//! `θ(z) = twist·(z + h/2)/h`, so with `u = R(−θ) q` and `w = (u.x / kx, u.y / ky)` the value
//! `σ = m·d(w)`, `m = min(kx, ky)`, has the slice as its zero set and `|∂σ/∂q| ≤ 1` (the map from
//! the profile to the slice stretches by at least `m`); for a uniform scale it is the exact 2D
//! distance. Without twist or scale the field is the exact prism distance
//! `capped(σ, |z| − h/2)`. With them `σ` is not a distance in 3D: `|∂σ/∂q| ≤ 1` and
//! `|∂σ/∂z| ≤ |k'|·r_p + |θ'|·|q| + |kx' − ky'|·|u|/K²` (`r_p` the largest radius of the profile;
//! for a distance `|d(w) − ∇d·w|` is at most the norm of the nearest boundary point; the last term
//! only for a non-uniform scale: with `m = kx ≤ ky` it is `∂d/∂w_y · u.y·(kx'·ky − kx·ky')/ky²`,
//! the bracket is `kx' − ky'` for linear scales, and `K = max(min(1, sx), min(1, sy))` bounds the
//! larger scale `ky` from below at every height), so `σ/L` with `L = √(1 + speed²)` is
//! 1-Lipschitz inside the cylinder `|q| ≤ R` of the solid's largest radius. One end scale may be
//! 0 (a wedge: the top slice is a segment, `K` stays positive); both 0 is the cone above. Outside that cylinder a
//! twisted or non-uniformly scaled extrusion evaluates the slice at the radial projection `π(q)`
//! onto it and takes `max(·, |q| − R)`: a composition with a projection onto a convex set and a
//! maximum of 1-Lipschitz functions, so the whole field is 1-Lipschitz and a distance bound
//! (`|f| ≤` the distance to the surface), with the exact zero set (`field_error() = 0`).

use super::combine::{capped, max, slab};
use super::error::{SweepError, invalid, positive};
use crate::primitive::{PrimitiveError, Shape, lipschitz_interval};
use crate::profile::Profile;
use crate::{Aabb, Interval};
use glam::{DVec2, DVec3};
use std::cell::RefCell;

/// Smallest slice scale used in the field (the top slice of a zero-scale extrusion is a point).
const MIN_SLICE_SCALE: f64 = 1e-12;

/// A profile extruded along z, centred at the origin, with optional twist and end scale.
#[derive(Debug, Clone, PartialEq)]
pub struct Extrude {
    profile: Profile,
    height: f64,
    twist: f64,
    scale: DVec2,
    /// `θ'` (radians per unit height) and `k'` per axis (per unit height).
    twist_rate: f64,
    scale_rate: DVec2,
    /// The largest radius of the solid (the clamp cylinder of twisted extrusions).
    radius: f64,
    /// The slice field's Lipschitz constant `L ≥ 1`.
    slice_lipschitz: f64,
}

impl Extrude {
    /// The extrusion of `profile` over height `height`, turned by `twist` degrees and scaled to
    /// `scale` at the top (1 keeps the size).
    pub fn new(
        profile: Profile,
        height: f64,
        twist: f64,
        scale: f64,
    ) -> Result<Extrude, SweepError> {
        Self::with_scale(profile, height, twist, DVec2::splat(scale))
    }

    /// The extrusion of `profile` over height `height`, turned by `twist` degrees and scaled to
    /// `scale.x` along x and `scale.y` along y at the top. Both scales at least 0: one zero is a
    /// wedge to a segment, both zero a cone from the profile to the point above the origin.
    pub fn with_scale(
        profile: Profile,
        height: f64,
        twist: f64,
        scale: DVec2,
    ) -> Result<Extrude, SweepError> {
        profile.validate().map_err(|error| SweepError::Profile {
            key: "profile",
            error,
        })?;
        positive("height", height)?;
        if !twist.is_finite() {
            return Err(invalid("twist", "expected a finite number"));
        }
        // Both zero: a cone to the apex over the profile (OpenSCAD's `scale = 0`); one zero: a
        // wedge whose top slice is a segment (OpenSCAD's `scale = [0, 1]`).
        if scale != DVec2::ZERO {
            for s in [scale.x, scale.y] {
                if !s.is_finite() {
                    return Err(invalid("scale", "expected a finite number"));
                }
                if s < 0.0 {
                    return Err(invalid("scale", "expected a number not below 0"));
                }
            }
        }
        let twist_rate = twist.to_radians() / height;
        let scale_rate = (scale - 1.0) / height;
        let rp = profile.radius();
        let radius = rp * scale.max_element().max(1.0);
        let mut speed = scale_rate.abs().max_element() * rp + twist_rate.abs() * radius;
        if scale.x != scale.y {
            // The larger of the two slice scales never drops below this (each is linear in z,
            // from 1 to its end scale): the term `|kx' − ky'|·|u|/K²` of the module docs.
            let k_big = scale.x.min(1.0).max(scale.y.min(1.0));
            speed += (scale_rate.x - scale_rate.y).abs() * radius / (k_big * k_big);
        }
        Ok(Extrude {
            profile,
            height,
            twist,
            scale,
            twist_rate,
            scale_rate,
            radius,
            slice_lipschitz: (1.0 + speed * speed).sqrt(),
        })
    }

    /// The profile.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// The height.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// The twist from bottom to top, in degrees.
    pub fn twist(&self) -> f64 {
        self.twist
    }

    /// The size at the top relative to the bottom, along x and y.
    pub fn scale(&self) -> DVec2 {
        self.scale
    }

    /// Whether the scale differs along x and y.
    fn anisotropic(&self) -> bool {
        self.scale.x != self.scale.y
    }

    /// The Lipschitz constant `L` the slice distance is divided by (1 for a plain prism).
    pub fn slice_lipschitz(&self) -> f64 {
        self.slice_lipschitz
    }

    /// Distance between the field's zero set and the exact surface: 0.
    pub fn field_error(&self) -> f64 {
        0.0
    }

    /// Exact volume: the slice area `A·kx(z)·ky(z)` integrated,
    /// `A·h·(1 + (α + β)/2 + αβ/3)` with `α = sx − 1`, `β = sy − 1` (`A·h·(1 + s + s²)/3` for a
    /// uniform scale; twist keeps it).
    pub fn volume(&self) -> f64 {
        let (a, b) = (self.scale.x - 1.0, self.scale.y - 1.0);
        self.profile.area_centroid().0 * self.height * (1.0 + (a + b) / 2.0 + a * b / 3.0)
    }

    /// Scale (per axis) and angle of the slice at height `z` (clamped to the slab): the slice is
    /// the profile scaled, then turned.
    pub(crate) fn slice_transform(&self, z: f64) -> (DVec2, f64) {
        let s = z.clamp(-0.5 * self.height, 0.5 * self.height) + 0.5 * self.height;
        (1.0 + self.scale_rate * s, self.twist_rate * s)
    }

    /// Where `p` meets its slice: everything the field needs besides the profile's distance at
    /// [`SlicePoint::w`].
    fn slice_point(&self, p: DVec3) -> SlicePoint {
        let q = DVec2::new(p.x, p.y);
        let rho = q.length();
        // Radial projection onto the clamp cylinder (twisted or anisotropic extrusions only).
        let (qc, clamped) = if self.bounded() && rho > self.radius {
            (q * (self.radius / rho), true)
        } else {
            (q, false)
        };
        let (k, theta) = self.slice_transform(p.z);
        // A zero scale shrinks the top slice to a point: keep the division finite there
        // (m·d(u/k) tends to |u|, the distance to the apex, as k → 0).
        let k = k.max(DVec2::splat(MIN_SLICE_SCALE));
        // Without twist the angle is zero: the same sine and cosine without the call.
        let (sin, cos) = if theta == 0.0 {
            (theta, 1.0)
        } else {
            theta.sin_cos()
        };
        let u = DVec2::new(cos * qc.x + sin * qc.y, -sin * qc.x + cos * qc.y);
        SlicePoint {
            q,
            rho,
            clamped,
            k,
            sin,
            cos,
            u,
            w: u / k,
        }
    }

    /// Whether the field is bounded by the clamp cylinder (twisted or anisotropic extrusions).
    fn bounded(&self) -> bool {
        self.twist_rate != 0.0 || self.anisotropic()
    }

    /// Field value and gradient at `p` from its slice point `s` and the profile's distance `d`
    /// and gradient `g` at `s.w`.
    fn finish(&self, p: DVec3, s: &SlicePoint, d: f64, g: DVec2) -> (f64, DVec3) {
        let h2 = 0.5 * self.height;
        let SlicePoint {
            q,
            rho,
            clamped,
            k,
            sin,
            cos,
            u,
            w,
        } = *s;
        // m = min(kx, ky) and its rate.
        let (m, dm) = if k.x <= k.y {
            (k.x, self.scale_rate.x)
        } else {
            (k.y, self.scale_rate.y)
        };
        let sigma = m * d;
        // ∂σ/∂u, then turned back: ∂σ/∂q = R(θ) ∂σ/∂u.
        let gu = g * m / k;
        let gq = DVec2::new(cos * gu.x - sin * gu.y, sin * gu.x + cos * gu.y);
        let gz = if p.z.abs() < h2 {
            // ∂w/∂t = −(k'/k)·w − θ'·(−u.y, u.x)/k, per component.
            let dw = -(self.scale_rate / k) * w - self.twist_rate * u.perp() / k;
            dm * d + m * g.dot(dw)
        } else {
            0.0
        };
        let l = self.slice_lipschitz;
        let gq = if clamped {
            // Chain rule through the projection: (R/ρ)(I − q̂q̂ᵀ).
            let u = q / rho;
            (gq - u * gq.dot(u)) * (self.radius / rho)
        } else {
            gq
        };
        let slice = (sigma / l, DVec3::new(gq.x, gq.y, gz) / l);
        let f = capped(slice, slab(p.z, h2));
        if self.bounded() {
            let u = if rho > 0.0 { q / rho } else { DVec2::X };
            max(f, (rho - self.radius, DVec3::new(u.x, u.y, 0.0)))
        } else {
            f
        }
    }

    /// The values of a plain prism (no twist, no scale) over the box `b` (finite): within the
    /// box's half-diagonal of the value at its centre (the Lipschitz bound), and also within
    /// the bound that the slice distance is 1-Lipschitz in the plane, so it lies within the
    /// rectangle's half-diagonal of its value at the rectangle's centre, the distance beyond
    /// the slab is known exactly, and the capped combination grows with both (tighter: issue 14,
    /// the octree keeps fewer of the many small extrusions of an offset text).
    fn prism_interval(&self, b: &Aabb) -> Interval {
        let (c, r) = (b.center(), b.half_extents());
        let d = self.profile.distance(DVec2::new(c.x, c.y));
        let h2 = 0.5 * self.height;
        let dz = DVec3::Z;
        // The Lipschitz bound: the value at the centre is the one `value` gives.
        let at_centre = capped((d, dz), slab(c.z, h2)).0;
        let loose = Interval::around(at_centre, r.length());
        let r2 = DVec2::new(r.x, r.y).length();
        let (z0, z1) = (b.min.z.abs(), b.max.z.abs());
        let e_lo = if b.min.z <= 0.0 && b.max.z >= 0.0 {
            -h2
        } else {
            z0.min(z1) - h2
        };
        let e_hi = z0.max(z1) - h2;
        let lo = capped((d - r2, dz), (e_lo, dz)).0;
        let hi = capped((d + r2, dz), (e_hi, dz)).0;
        if !(lo.is_finite() && hi.is_finite()) {
            return loose;
        }
        // Room for the rounding of the samples (single precision).
        let pad = 1e-6 * (lo.abs().max(hi.abs()) + r2);
        Interval::new(loose.lo.max(lo - pad), loose.hi.min(hi + pad))
    }

    /// Field value and gradient.
    fn eval(&self, p: DVec3) -> (f64, DVec3) {
        let s = self.slice_point(p);
        let (d, g) = self.profile.distance_gradient(s.w);
        self.finish(p, &s, d, g)
    }

    /// Field values and gradients at many points: the profile measures all slice points at once
    /// (a many-edged polygon is faster so), the answers are [`Extrude::eval`]'s.
    fn eval_many(
        &self,
        points: impl Iterator<Item = DVec3>,
        mut f: impl FnMut(usize, (f64, DVec3)),
    ) {
        BATCH.with(|cell| {
            let mut guard = cell.try_borrow_mut().ok();
            let mut fresh = Batch::default();
            let b = guard.as_deref_mut().unwrap_or(&mut fresh);
            b.points.clear();
            b.slices.clear();
            b.ws.clear();
            b.distances.clear();
            for p in points {
                let s = self.slice_point(p);
                b.points.push(p);
                b.ws.push(s.w);
                b.slices.push(s);
            }
            self.profile.distance_gradients(&b.ws, &mut b.distances);
            for (i, ((p, s), &(d, g))) in
                b.points.iter().zip(&b.slices).zip(&b.distances).enumerate()
            {
                f(i, self.finish(*p, s, d, g));
            }
        });
    }
}

/// Where a point meets its slice of an [`Extrude`].
#[derive(Debug, Clone, Copy)]
struct SlicePoint {
    /// The point's `x, y`.
    q: DVec2,
    /// Its distance from the axis.
    rho: f64,
    /// Whether it was projected onto the clamp cylinder.
    clamped: bool,
    /// The slice's scale per axis.
    k: DVec2,
    /// Sine and cosine of the slice's turn.
    sin: f64,
    cos: f64,
    /// The (projected) point turned back by the slice's angle.
    u: DVec2,
    /// The profile point: `u / k`.
    w: DVec2,
}

/// The buffers of [`Extrude::eval_many`], reused by the thread.
#[derive(Debug, Default)]
struct Batch {
    points: Vec<DVec3>,
    slices: Vec<SlicePoint>,
    ws: Vec<DVec2>,
    distances: Vec<(f64, DVec2)>,
}

thread_local! {
    static BATCH: RefCell<Batch> = RefCell::new(Batch::default());
}

impl Shape for Extrude {
    fn value(&self, p: DVec3) -> f64 {
        self.eval(p).0
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        self.eval(p).1
    }
    fn interval(&self, b: &Aabb) -> Interval {
        if self.bounded() || self.scale != DVec2::ONE || !b.min.is_finite() || !b.max.is_finite() {
            return lipschitz_interval(self, b);
        }
        self.prism_interval(b)
    }
    fn bbox(&self) -> Aabb {
        let h2 = 0.5 * self.height;
        if self.twist_rate != 0.0 {
            // The slice turns: the clamp cylinder bounds it.
            let r = self.radius;
            return Aabb::centered(DVec3::new(r, r, h2));
        }
        let (lo, hi) = self.profile.bounds();
        let (a, b) = (lo.min(lo * self.scale), hi.max(hi * self.scale));
        Aabb::new(DVec3::new(a.x, a.y, -h2), DVec3::new(b.x, b.y, h2))
    }
    fn values_gradients(&self, pts: &[DVec3], values: &mut [f64], gradients: &mut [DVec3]) {
        self.eval_many(pts.iter().copied(), |i, (v, g)| {
            values[i] = v;
            gradients[i] = g;
        });
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len();
        let points = (0..n).map(|i| DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64));
        self.eval_many(points, |i, (v, _)| out[i] = v as f32);
    }
    fn sublevel_boxes_hold(&self) -> bool {
        // A slope-divided distance bound: see `Shape::sublevel_boxes_hold`.
        false
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked when built: an `Extrude` is always valid.
        Ok(())
    }
}
