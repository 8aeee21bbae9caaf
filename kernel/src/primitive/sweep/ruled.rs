//! The solid between two closed plane curves in horizontal planes, bounded by the ruled surface
//! `s(u, v) = (1 − v)·c₁(u) + v·c₂(u)` (lecture notes 000) and the two plane regions the curves
//! enclose. Both curves' parameters are normalised to `u ∈ [0, 1]`. Either curve may be a single
//! point (all its control points equal): with `c₁ = p` the solid is the cone with apex `p`; with
//! `c₂ = c₁ + d` an (oblique) cylinder.
//!
//! Field. The slice at height `z` (`v = (z − z₁)/(z₂ − z₁)`) is the region enclosed by
//! `γᵥ = (1 − v)c₁ + v c₂`; its exact 2D signed distance `σ` comes from the closest point of `γᵥ`
//! ([`BlendIndex`](crate::curve)), signed by the outward normal there (the average of the two
//! one-sided normals at a corner). `|∂σ/∂q| = 1` and `|∂σ/∂z| ≤ s = max_u |c₂(u) − c₁(u)| / h`
//! (bounded from the two curves' span boxes), so `σ/√(1 + s²)` combined with the slab distance
//! in the capped form is 1-Lipschitz: a distance bound with the exact zero set
//! (`field_error() = 0`). The slices are assumed simple (true when both curves are simple and
//! convex, or nearly congruent); both curves must run the same way round.

use super::combine::{capped, slab};
use super::error::{SweepError, invalid};
use crate::curve::{BlendIndex, Curve, Curve3};
use crate::primitive::{PrimitiveError, Shape, lipschitz_interval};
use crate::{Aabb, Interval};
use glam::{DVec2, DVec3};

/// A solid bounded by the ruled surface between two closed horizontal plane curves.
#[derive(Debug, Clone, PartialEq)]
pub struct Ruled {
    bottom: Curve,
    top: Curve,
    /// Heights of the bottom and top planes.
    z0: f64,
    z1: f64,
    index: BlendIndex,
    /// +1 when the curves run counter-clockwise, −1 clockwise.
    orientation: f64,
    slice_lipschitz: f64,
}

/// The height of a curve's plane, if all its control points share it.
fn plane_height(c: &Curve) -> Option<f64> {
    let b = c.control_bbox();
    let scale = b.size().length().max(b.max.abs().max_element()).max(1.0);
    ((b.max.z - b.min.z) <= 1e-12 * scale).then_some(0.5 * (b.min.z + b.max.z))
}

/// True when the curve is a single point.
fn is_point(c: &Curve) -> bool {
    let b = c.control_bbox();
    b.min == b.max
}

impl Ruled {
    /// The solid between the closed curves `bottom` and `top`, each in a horizontal plane, the
    /// bottom's plane lower.
    pub fn new(bottom: Curve, top: Curve) -> Result<Ruled, SweepError> {
        for (key, c) in [("bottom", &bottom), ("top", &top)] {
            if !c.is_closed() {
                return Err(invalid(
                    key,
                    "the curve must be closed (end where it starts)",
                ));
            }
        }
        let z0 = plane_height(&bottom)
            .ok_or_else(|| invalid("bottom", "the curve must lie in a horizontal plane"))?;
        let z1 = plane_height(&top)
            .ok_or_else(|| invalid("top", "the curve must lie in a horizontal plane"))?;
        if z1 <= z0 {
            return Err(invalid(
                "top",
                "the top curve must lie above the bottom curve",
            ));
        }
        let index = BlendIndex::new(&bottom, &top);
        let (a0, a1) = (
            index.area(&bottom, &top, 0.0),
            index.area(&bottom, &top, 1.0),
        );
        let size = index.bbox().size().length();
        let tiny = 1e-12 * size * size;
        let orientation = if a0.abs() > tiny && a1.abs() > tiny {
            if a0.signum() != a1.signum() {
                return Err(invalid("top", "the curves must run the same way round"));
            }
            a0.signum()
        } else if a0.abs() > tiny || a1.abs() > tiny {
            if !(is_point(&bottom) || is_point(&top)) {
                return Err(invalid("bottom", "a curve encloses no area"));
            }
            (a0 + a1).signum()
        } else {
            return Err(invalid("bottom", "the curves enclose no area"));
        };
        let s = index.max_offset() / (z1 - z0);
        Ok(Ruled {
            bottom,
            top,
            z0,
            z1,
            index,
            orientation,
            slice_lipschitz: (1.0 + s * s).sqrt(),
        })
    }

    /// The bottom curve.
    pub fn bottom(&self) -> &Curve {
        &self.bottom
    }

    /// The top curve.
    pub fn top(&self) -> &Curve {
        &self.top
    }

    /// Distance between the field's zero set and the exact surface: 0.
    pub fn field_error(&self) -> f64 {
        0.0
    }

    /// The enclosed area of the slice at `v ∈ [0, 1]` (Gauss–Legendre quadrature).
    pub fn slice_area(&self, v: f64) -> f64 {
        self.orientation * self.index.area(&self.bottom, &self.top, v)
    }

    /// Volume: the slice area `A(v) = ½∮ γᵥ × γᵥ'` is quadratic in `v`, so Simpson's rule
    /// `h/6 (A₀ + 4A½ + A₁)` is exact (up to the quadrature of each area).
    pub fn volume(&self) -> f64 {
        (self.z1 - self.z0) / 6.0
            * (self.slice_area(0.0) + 4.0 * self.slice_area(0.5) + self.slice_area(1.0))
    }

    /// The point `s(u, v)` of the ruled surface (`u` normalised to `[0, 1]`).
    pub fn surface_point(&self, u: f64, v: f64) -> DVec3 {
        let at = |c: &Curve| {
            let (t0, t1) = c.domain();
            c.point(t0 + u * (t1 - t0))
        };
        at(&self.bottom).lerp(at(&self.top), v)
    }

    /// Field value and gradient.
    fn eval(&self, p: DVec3) -> (f64, DVec3) {
        let h = self.z1 - self.z0;
        let v = ((p.z - self.z0) / h).clamp(0.0, 1.0);
        let c = self.index.closest(v, p);
        let away = DVec2::new(p.x - c.point.x, p.y - c.point.y);
        let outside = self.orientation * away.dot(c.normal) >= 0.0;
        let (d, g) = if c.distance > 0.0 {
            let g = away / c.distance;
            if outside {
                (c.distance, g)
            } else {
                (-c.distance, -g)
            }
        } else {
            (0.0, (c.normal * self.orientation).normalize_or(DVec2::X))
        };
        let gz = if p.z > self.z0 && p.z < self.z1 {
            -g.dot(DVec2::new(c.offset.x, c.offset.y)) / h
        } else {
            0.0
        };
        let l = self.slice_lipschitz;
        let mid = 0.5 * (self.z0 + self.z1);
        capped(
            (d / l, DVec3::new(g.x, g.y, gz) / l),
            slab(p.z - mid, 0.5 * h),
        )
    }
}

impl Shape for Ruled {
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
        let b = self.index.bbox();
        Aabb::new(
            DVec3::new(b.min.x, b.min.y, self.z0),
            DVec3::new(b.max.x, b.max.y, self.z1),
        )
    }
    fn sublevel_boxes_hold(&self) -> bool {
        // A slope-divided distance bound: see `Shape::sublevel_boxes_hold`.
        false
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked when built: a `Ruled` is always valid.
        Ok(())
    }
}
