//! A loft between two profiles at the bottom (`z = −h/2`) and top (`z = h/2`) of a slab: every
//! horizontal slice is the profile whose defining points are interpolated linearly in height, so
//! corresponding boundary points are joined by straight rulings (a ruled lateral surface). Circle
//! to circle interpolates centre and radius (cones, frusta, oblique cylinders); polygons (and
//! rectangles, as their four corners) interpolate corner by corner and need the same loop
//! structure at both ends.
//!
//! Field. The slice's exact 2D distance `σ` has `|∂σ/∂q| = 1` and `|∂σ/∂z| ≤ s`, the largest
//! horizontal speed of a boundary point (`(|Δc| + |Δr|)/h` for circles, `max |Δcorner|/h` for
//! polygons), so `σ/L` with `L = √(1 + s²)` is 1-Lipschitz; it is combined with the slab
//! distance in the capped form (their gradients are orthogonal where both are positive). A
//! distance bound with the exact zero set (`field_error() = 0`), exact for prisms (`s = 0`).

use super::combine::{capped, slab};
use super::error::{SweepError, invalid, positive};
use crate::primitive::{PrimitiveError, Shape, lipschitz_interval};
use crate::profile::{Profile, loops_distance};
use crate::{Aabb, Interval};
use glam::{DVec2, DVec3};

/// The slices' shape: a circle, or polygon loops with matching corners.
#[derive(Debug, Clone, PartialEq)]
enum Slices {
    Circles {
        centers: [DVec2; 2],
        radii: [f64; 2],
    },
    Polygons {
        bottom: Vec<Vec<DVec2>>,
        top: Vec<Vec<DVec2>>,
    },
}

/// A loft between two profiles, centred at the origin along z.
#[derive(Debug, Clone, PartialEq)]
pub struct Loft {
    bottom: Profile,
    top: Profile,
    height: f64,
    slices: Slices,
    /// `L = √(1 + s²)`.
    slice_lipschitz: f64,
}

/// The corner loops of a rectangle or polygon profile.
fn corner_loops(p: &Profile) -> Option<Vec<Vec<DVec2>>> {
    match p {
        Profile::Circle(_) => None,
        Profile::Rectangle(r) => Some(vec![r.corners().to_vec()]),
        Profile::Polygon(poly) => Some(poly.loops().to_vec()),
    }
}

impl Loft {
    /// The loft from `bottom` (at `z = −height/2`) to `top` (at `z = height/2`). A circle may
    /// have radius 0 at one end (a cone's apex).
    pub fn new(bottom: Profile, top: Profile, height: f64) -> Result<Loft, SweepError> {
        positive("height", height)?;
        let check = |key: &'static str, p: &Profile| match p {
            Profile::Circle(c) if c.radius == 0.0 && c.center.is_finite() => Ok(()),
            _ => p
                .validate()
                .map_err(|error| SweepError::Profile { key, error }),
        };
        check("bottom", &bottom)?;
        check("top", &top)?;
        let slices = match (&bottom, &top) {
            (Profile::Circle(a), Profile::Circle(b)) => {
                if a.radius == 0.0 && b.radius == 0.0 {
                    return Err(invalid(
                        "bottom",
                        "one of the circles needs a positive radius",
                    ));
                }
                Slices::Circles {
                    centers: [a.center, b.center],
                    radii: [a.radius, b.radius],
                }
            }
            _ => match (corner_loops(&bottom), corner_loops(&top)) {
                (Some(b), Some(t))
                    if b.len() == t.len() && b.iter().zip(&t).all(|(x, y)| x.len() == y.len()) =>
                {
                    Slices::Polygons { bottom: b, top: t }
                }
                _ => {
                    return Err(invalid(
                        "top",
                        "the top profile must be of the bottom's kind, with the same loops and corner counts",
                    ));
                }
            },
        };
        let speed = match &slices {
            Slices::Circles { centers, radii } => {
                ((centers[1] - centers[0]).length() + (radii[1] - radii[0]).abs()) / height
            }
            Slices::Polygons { bottom, top } => {
                bottom
                    .iter()
                    .flatten()
                    .zip(top.iter().flatten())
                    .map(|(a, b)| (*b - *a).length())
                    .fold(0.0, f64::max)
                    / height
            }
        };
        Ok(Loft {
            bottom,
            top,
            height,
            slices,
            slice_lipschitz: (1.0 + speed * speed).sqrt(),
        })
    }

    /// The bottom profile.
    pub fn bottom(&self) -> &Profile {
        &self.bottom
    }

    /// The top profile.
    pub fn top(&self) -> &Profile {
        &self.top
    }

    /// The height.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// Distance between the field's zero set and the exact surface: 0.
    pub fn field_error(&self) -> f64 {
        0.0
    }

    /// The slice's area at `v ∈ [0, 1]` (quadratic in `v`).
    fn slice_area(&self, v: f64) -> f64 {
        match &self.slices {
            Slices::Circles { radii, .. } => {
                let r = radii[0] + (radii[1] - radii[0]) * v;
                std::f64::consts::PI * r * r
            }
            Slices::Polygons { bottom, top } => {
                let loops: Vec<Vec<DVec2>> = bottom
                    .iter()
                    .zip(top)
                    .map(|(b, t)| b.iter().zip(t).map(|(x, y)| x.lerp(*y, v)).collect())
                    .collect();
                match Profile::polygon(loops[0].clone(), loops[1..].to_vec()) {
                    Ok(p) => p.area_centroid().0,
                    Err(_) => 0.0,
                }
            }
        }
    }

    /// Exact volume: the slice area is quadratic in height, so Simpson's rule
    /// `h/6 (A₀ + 4A½ + A₁)` is exact.
    pub fn volume(&self) -> f64 {
        self.height / 6.0
            * (self.slice_area(0.0) + 4.0 * self.slice_area(0.5) + self.slice_area(1.0))
    }

    /// The slice distance at `(q, v)` with its gradient in `q` and derivative in `v`.
    fn slice(&self, q: DVec2, v: f64) -> (f64, DVec2, f64) {
        match &self.slices {
            Slices::Circles { centers, radii } => {
                let c = centers[0].lerp(centers[1], v);
                let r = radii[0] + (radii[1] - radii[0]) * v;
                let w = q - c;
                let l = w.length();
                let g = if l > 0.0 { w / l } else { DVec2::X };
                (
                    l - r,
                    g,
                    -g.dot(centers[1] - centers[0]) - (radii[1] - radii[0]),
                )
            }
            Slices::Polygons { bottom, top } => {
                let corner = |r: usize, i: usize| bottom[r][i].lerp(top[r][i], v);
                let n = loops_distance(q, bottom.len(), |r| bottom[r].len(), corner);
                let len = bottom[n.ring].len();
                let next = (n.edge + 1) % len;
                let speed = |i: usize| top[n.ring][i] - bottom[n.ring][i];
                let moving = speed(n.edge).lerp(speed(next), n.lambda);
                (n.distance, n.gradient, -n.gradient.dot(moving))
            }
        }
    }

    /// Field value and gradient.
    fn eval(&self, p: DVec3) -> (f64, DVec3) {
        let h2 = 0.5 * self.height;
        let v = (p.z.clamp(-h2, h2) + h2) / self.height;
        let (d, g, dv) = self.slice(DVec2::new(p.x, p.y), v);
        let gz = if p.z.abs() < h2 {
            dv / self.height
        } else {
            0.0
        };
        let l = self.slice_lipschitz;
        capped((d / l, DVec3::new(g.x, g.y, gz) / l), slab(p.z, h2))
    }
}

impl Shape for Loft {
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
        let (a0, a1) = self.bottom.bounds();
        let (b0, b1) = self.top.bounds();
        let h2 = 0.5 * self.height;
        Aabb::new(a0.min(b0).extend(-h2), a1.max(b1).extend(h2))
    }
    fn sublevel_boxes_hold(&self) -> bool {
        // A slope-divided distance bound: see `Shape::sublevel_boxes_hold`.
        false
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked when built: a `Loft` is always valid.
        Ok(())
    }
}
