//! Rotation-minimising frames along a path by the double reflection method (Wang, Jüttler, Zheng
//! and Liu, "Computation of rotation minimizing frames", ACM TOG 27(1), 2008). Frames are computed
//! once at sample parameters; the frame at any parameter is one more double reflection from the
//! sample before it, so frames are continuous in the parameter and cost O(log n) to look up.
//!
//! On a closed path the propagated frame comes back turned by the path's holonomy angle `Δ`
//! about the tangent; the frame at `t` is then turned back by `Δ·(t − t₀)/(t₁ − t₀)` so it closes.
//! A planar closed path has `Δ = 0`.

use crate::curve::{Curve, Curve3, Jet};
use glam::DVec3;

/// A frame sample: parameter, point, unit tangent and unit reference vector normal to it.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Sample {
    t: f64,
    point: DVec3,
    tangent: DVec3,
    normal: DVec3,
}

/// Rotation-minimising frames of one path.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Frames {
    samples: Vec<Sample>,
    /// Holonomy correction in radians per unit parameter (0 for open paths).
    correction: f64,
}

/// A frame: unit tangent `t`, and the profile's axes `u` (its x) and `v = t × u` (its y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Frame {
    pub t: DVec3,
    pub u: DVec3,
    pub v: DVec3,
}

/// Steps shorter than this fraction of the points' size are taken as a projection onto the new
/// normal plane: the reflection planes of such steps are rounding noise (a step `h` has its
/// direction wrong by about `ε|x|/h`), while the projection is off the rotation-minimising frame
/// by about `(hκ)²` (κ the curvature); 1e-6 keeps both near 1e-10 or below.
const TINY_STEP: f64 = 1e-6;

/// One double reflection: the reference vector `r0` at `(x0, t0)` carried to `(x1, t1)`.
fn double_reflection(x0: DVec3, t0: DVec3, r0: DVec3, x1: DVec3, t1: DVec3) -> DVec3 {
    let v1 = x1 - x0;
    let c1 = v1.length_squared();
    let scale = x0
        .length_squared()
        .max(x1.length_squared())
        .max(f64::MIN_POSITIVE);
    if c1 <= TINY_STEP * TINY_STEP * scale {
        // A (nearly) zero step: the rotation-minimising frame is the projection, to first order.
        return (r0 - t1 * r0.dot(t1)).normalize_or(t1.any_orthonormal_vector());
    }
    let (r_l, t_l) = (
        r0 - v1 * (2.0 / c1 * v1.dot(r0)),
        t0 - v1 * (2.0 / c1 * v1.dot(t0)),
    );
    let v2 = t1 - t_l;
    let c2 = v2.length_squared();
    let r1 = if c2 > 0.0 {
        r_l - v2 * (2.0 / c2 * v2.dot(r_l))
    } else {
        r_l
    };
    // Remove rounding drift: keep the reference exactly normal to the tangent and unit.
    (r1 - t1 * r1.dot(t1)).normalize_or(t1.any_orthonormal_vector())
}

/// The profile's x axis at the start: the part of the global x axis normal to the start tangent
/// (the y axis when the path starts along x).
fn initial_normal(t: DVec3) -> DVec3 {
    let x = DVec3::X - t * t.x;
    if x.length_squared() > 1e-6 {
        x.normalize()
    } else {
        (DVec3::Y - t * t.y).normalize()
    }
}

/// Turns `u` (normal to the unit `t`) about `t` by `angle`.
fn turn(u: DVec3, t: DVec3, angle: f64) -> DVec3 {
    let (s, c) = angle.sin_cos();
    u * c + t.cross(u) * s
}

impl Frames {
    /// Frames at the parameters `params` (increasing, covering the domain) of `path`; `closed`
    /// paths get the holonomy correction.
    pub(crate) fn new(path: &Curve, params: &[f64], closed: bool) -> Frames {
        Frames::from_jets(|t| path.jet(t), params, closed)
    }

    /// Frames like [`Frames::new`] for any path given by its jets (formula curves too).
    pub(crate) fn from_jets(jet: impl Fn(f64) -> Jet, params: &[f64], closed: bool) -> Frames {
        let mut samples: Vec<Sample> = Vec::with_capacity(params.len());
        for &t in params {
            let j = jet(t);
            let tangent = j.d1.normalize_or(DVec3::Z);
            let normal = match samples.last() {
                None => initial_normal(tangent),
                Some(s) => double_reflection(s.point, s.tangent, s.normal, j.point, tangent),
            };
            samples.push(Sample {
                t,
                point: j.point,
                tangent,
                normal,
            });
        }
        let mut correction = 0.0;
        if closed && samples.len() > 1 {
            let (first, last) = (samples[0], samples[samples.len() - 1]);
            // Angle turning the returned normal back onto the starting one, about the tangent.
            let angle = last
                .normal
                .cross(first.normal)
                .dot(first.tangent)
                .atan2(last.normal.dot(first.normal));
            correction = angle / (last.t - first.t);
        }
        Frames {
            samples,
            correction,
        }
    }

    /// The holonomy correction's turning rate (radians per unit parameter).
    pub(crate) fn correction(&self) -> f64 {
        self.correction
    }

    /// The holonomy angle corrected over the whole closed path (radians).
    pub(crate) fn holonomy(&self) -> f64 {
        let n = self.samples.len();
        self.correction * (self.samples[n - 1].t - self.samples[0].t)
    }

    /// The frame at parameter `t` where the path has point `point` and derivative `d1`.
    pub(crate) fn at(&self, t: f64, point: DVec3, d1: DVec3) -> Frame {
        let i = self
            .samples
            .partition_point(|s| s.t <= t)
            .saturating_sub(1)
            .min(self.samples.len() - 1);
        let s = &self.samples[i];
        let tangent = d1.normalize_or(s.tangent);
        let mut u = double_reflection(s.point, s.tangent, s.normal, point, tangent);
        if self.correction != 0.0 {
            u = turn(u, tangent, self.correction * (t - self.samples[0].t));
        }
        Frame {
            t: tangent,
            u,
            v: tangent.cross(u),
        }
    }

    /// The sample parameters with their points and unit tangents.
    pub(crate) fn samples(&self) -> impl Iterator<Item = (f64, DVec3, DVec3)> + '_ {
        self.samples.iter().map(|s| (s.t, s.point, s.tangent))
    }
}
