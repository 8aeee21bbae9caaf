//! A profile swept along a 3D path curve: the profile's plane stays normal to the path and its
//! axes follow the path's rotation-minimising frame ([`frames`](super::frames)); its origin rides
//! on the path. An open path is closed by flat caps in the end normal planes; a closed path (ends
//! meeting with the same tangent) makes a ring.
//!
//! Field. With `c` the closest path point and `(a, b)` the coordinates of `p − c` on the frame
//! axes there, the value is the profile distance of `(a, b)`. Where the closest point moves
//! smoothly (within the path's reach) rotation-minimising frames turn without twist, so
//! `∂(a, b)/∂p` are exactly the frame axes and the field is 1-Lipschitz; it is the exact distance
//! to the swept surface there. For a circle profile centred on the path it is the exact tube
//! distance `|p − c| − r` everywhere. For other profiles the profile distance is used up to an
//! extension radius `E ≥ R` (`R` the profile's radius) and extended beyond it by
//! `max(d(π(q)), |q| − E)` (π: radial projection onto the disc of radius `E`), which only depends
//! on `|q|` once `|q| ≥ E + M` (`M` the largest profile distance on that circle): the field stays
//! continuous where the closest path point jumps, provided the path keeps its reach above `E + M`.
//! `E` is as large as the path's curvature `κ` allows (`2E + R ≤ 0.9/κ`, so `E + M ≤ 0.9/κ`;
//! unbounded on a straight path) and never below `R`, where `R + M < 1/κ` is required; a path that
//! comes back near itself is not checked. Closed paths with a non-circular profile turn their
//! frames to close (holonomy correction), which adds `E·|Δ|` per path length to the gradient:
//! reported by [`Shape::lipschitz`] (and included in the gradient).
//!
//! Open paths are the union (minimum) of up to three overlapping parts, each searching its own
//! closest point: a start part carrying the start plane's distance (joined by `max`, or the exact
//! capped form past the plane), a middle part, and an end part likewise. Each part ends in a flat
//! cut where it hands over to the next; the cuts between parts lie where the slice is at least `R`
//! behind the end planes, and every part's slices lie behind its end plane (checked). A minimum of
//! parts never jumps where the closest path point would switch between an end and a far part of
//! the path (a coil next to a helix's end), so the field stays continuous and 1-Lipschitz there.
//! Zero set exact: `field_error() = 0`.

use super::combine::{capped, max};
use super::error::{SweepError, invalid};
use super::frames::{Frame, Frames};
use crate::curve::{Closest, Curve, Curve3, CurveIndex, Jet};
use crate::primitive::{PrimitiveError, Shape, lipschitz_interval};
use crate::profile::Profile;
use crate::{Aabb, Interval};
use glam::{DVec2, DVec3};

/// Frame samples per nearly straight span of the path.
const FRAME_SAMPLES: usize = 8;
/// Samples per span for the curvature and speed checks.
const CHECK_SAMPLES: usize = 32;

/// One end of a part: a point and unit tangent of the path, and whether it is the path's end (a
/// cap that bounds the solid) or a cut between overlapping parts.
#[derive(Debug, Clone, Copy, PartialEq)]
struct End {
    t: f64,
    point: DVec3,
    tangent: DVec3,
    cap: bool,
}

/// A stretch of an open path (spans `first..=last`) whose field is computed on its own.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Part {
    first: usize,
    last: usize,
    start: End,
    end: End,
    bbox: Aabb,
}

/// A profile swept along a path with rotation-minimising frames.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    profile: Profile,
    path: Curve,
    index: CurveIndex,
    frames: Frames,
    /// The profile's largest radius `R`.
    radius: f64,
    /// The extension radius `E ≥ R` beyond which the profile distance is extended radially.
    extension: f64,
    /// A circle centred at the profile origin (exact tube distance).
    circular: bool,
    /// The overlapping parts of an open path (empty for a closed path).
    parts: Vec<Part>,
    lipschitz: f64,
}

/// Path measurements from dense samples: smallest speed, largest curvature.
fn path_measures(path: &Curve, index: &CurveIndex) -> (f64, f64) {
    let (mut speed, mut curvature) = (f64::INFINITY, 0.0f64);
    for s in index.spans() {
        for k in 0..=CHECK_SAMPLES {
            let t = s.t0 + (s.t1 - s.t0) * k as f64 / CHECK_SAMPLES as f64;
            let j = path.jet(t);
            let v = j.d1.length();
            speed = speed.min(v);
            if v > 0.0 {
                curvature = curvature.max(j.d1.cross(j.d2).length() / (v * v * v));
            }
        }
    }
    (speed, curvature)
}

/// The largest profile distance on the circle of radius `r` (sampled every degree, plus the
/// most the distance can change between samples, `r·Δθ/2`).
fn max_on_circle(profile: &Profile, r: f64) -> f64 {
    let n = 360;
    let step = std::f64::consts::TAU / n as f64;
    (0..n)
        .map(|i| {
            let a = step * i as f64;
            profile.distance(DVec2::new(a.cos(), a.sin()) * r)
        })
        .fold(f64::NEG_INFINITY, f64::max)
        + 0.5 * r * step
}

impl Sweep {
    /// `profile` swept along `path`.
    pub fn new(profile: Profile, path: Curve) -> Result<Sweep, SweepError> {
        profile.validate().map_err(|error| SweepError::Profile {
            key: "profile",
            error,
        })?;
        let index = CurveIndex::new(&path);
        let size = index.bbox().size().length();
        if !size.is_finite() {
            return Err(invalid("path", "the path's coordinates are too large"));
        }
        let (speed, curvature) = path_measures(&path, &index);
        if speed <= 1e-12 * size.max(f64::MIN_POSITIVE) {
            return Err(invalid(
                "path",
                "the path must have a non-zero derivative everywhere",
            ));
        }
        let radius = profile.radius();
        let circular = matches!(&profile, Profile::Circle(c) if c.center == DVec2::ZERO);
        let extension = if curvature > 0.0 {
            radius.max(0.5 * (0.9 / curvature - radius))
        } else {
            f64::INFINITY
        };
        let reach = if circular {
            radius
        } else if extension > radius {
            // 2E + R ≤ 0.9/κ bounds E + M(E) (M(E) ≤ E + R).
            0.9 / curvature
        } else {
            radius + max_on_circle(&profile, radius).max(0.0)
        };
        if reach * curvature >= 1.0 {
            return Err(invalid(
                "profile",
                "the profile is too large for the path's curvature (the sweep would fold)",
            ));
        }
        let (t0, t1) = path.domain();
        let start = path.jet(t0);
        let end = path.jet(t1);
        let closed = path.is_closed();
        if closed && start.d1.normalize().dot(end.d1.normalize()) < 1.0 - 1e-9 {
            return Err(invalid(
                "path",
                "a closed path must end with the tangent it starts with",
            ));
        }
        let mut params = vec![t0];
        for s in index.spans() {
            for k in 1..=FRAME_SAMPLES {
                params.push(s.t0 + (s.t1 - s.t0) * k as f64 / FRAME_SAMPLES as f64);
            }
        }
        let frames = Frames::new(&path, &params, closed);
        let parts = if closed {
            Vec::new()
        } else {
            split_parts(&path, &index, &frames, radius)?
        };
        let lipschitz = if closed && !circular {
            let rate = frames.holonomy().abs() / (t1 - t0);
            let k = extension.min(reach) * rate / (speed * (1.0 - curvature * reach));
            (1.0 + k * k).sqrt()
        } else {
            1.0
        };
        Ok(Sweep {
            profile,
            path,
            index,
            frames,
            radius,
            extension,
            circular,
            parts,
            lipschitz,
        })
    }

    /// The profile.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// The path.
    pub fn path(&self) -> &Curve {
        &self.path
    }

    /// True when the path is closed (no caps).
    pub fn is_closed(&self) -> bool {
        self.parts.is_empty()
    }

    /// The holonomy angle (radians) the frames are turned by to close a closed path (0 for open
    /// and for planar paths, up to rounding).
    pub fn holonomy(&self) -> f64 {
        self.frames.holonomy()
    }

    /// Distance between the field's zero set and the exact surface: 0.
    pub fn field_error(&self) -> f64 {
        0.0
    }

    /// The frame (unit tangent, profile x and y axes) at path parameter `t`.
    pub fn frame(&self, t: f64) -> [DVec3; 3] {
        let j = self.path.jet(t);
        let f = self.frames.at(t, j.point, j.d1);
        [f.t, f.u, f.v]
    }

    /// Volume of the swept solid (when it does not overlap itself): the profile's area times the
    /// path length, less the area times `∫ T'(t)·(cₓ U + c_y V) dt` for a profile whose centroid
    /// `c` is off the path; by 24-point Gauss–Legendre quadrature on every span.
    pub fn volume(&self) -> f64 {
        let (area, c) = self.profile.area_centroid();
        let rule = crate::curve::gauss_legendre(24);
        let mut total = 0.0;
        for s in self.index.spans() {
            let (mid, half) = (0.5 * (s.t0 + s.t1), 0.5 * (s.t1 - s.t0));
            for &(x, w) in &rule {
                let t = mid + half * x;
                let j = self.path.jet(t);
                let speed = j.d1.length();
                let f = self.frames.at(t, j.point, j.d1);
                // Derivative of the unit tangent.
                let dt = (j.d2 - f.t * f.t.dot(j.d2)) / speed;
                total += w * half * (speed - dt.dot(f.u * c.x + f.v * c.y));
            }
        }
        area * total
    }

    /// The profile distance, extended radially beyond the extension radius, and its gradient.
    fn profile_field(&self, q: DVec2) -> (f64, DVec2) {
        let l = q.length();
        let unit = if l > 0.0 { q / l } else { DVec2::X };
        if self.circular {
            return (l - self.radius, unit);
        }
        let e = self.extension;
        if l <= e {
            return self.profile.distance_gradient(q);
        }
        let (d, g) = self.profile.distance_gradient(unit * e);
        let outward = l - e;
        if outward >= d {
            (outward, unit)
        } else {
            (d, (g - unit * g.dot(unit)) * (e / l))
        }
    }

    /// The cross-section field at the closest point `c`, with its gradient.
    fn section(&self, p: DVec3, c: &Closest) -> (f64, DVec3) {
        let j: Jet = c.jet;
        let Frame { u, v, .. } = self.frames.at(c.t, c.point, j.d1);
        let q = p - c.point;
        let (a, b) = (q.dot(u), q.dot(v));
        let (d, g) = self.profile_field(DVec2::new(a, b));
        let mut grad = u * g.x + v * g.y;
        let rate = self.frames.correction();
        if rate != 0.0 && !self.circular {
            // The holonomy correction turns the axes with t*, which moves with p:
            // ∇t* = C' / (|C'|² − C''·q); turning by dβ changes (a, b) by (b, −a) dβ.
            let denominator = j.d1.length_squared() - j.d2.dot(q);
            if denominator > 0.0 {
                grad += j.d1 * ((g.x * b - g.y * a) * rate / denominator);
            }
        }
        (d, grad)
    }

    /// The field of one part of an open path.
    fn part_field(&self, part: &Part, p: DVec3) -> (f64, DVec3) {
        let c = self.index.closest_in(p, part.first, part.last);
        let section = self.section(p, &c);
        let at_start = c.t <= part.start.t;
        let at_end = c.t >= part.end.t;
        let mut plane = (f64::NEG_INFINITY, DVec3::ZERO);
        if part.start.cap || at_start {
            let e = part.start;
            plane = max(plane, ((e.point - p).dot(e.tangent), -e.tangent));
        }
        if part.end.cap || at_end {
            let e = part.end;
            plane = max(plane, ((p - e.point).dot(e.tangent), e.tangent));
        }
        if plane.0 == f64::NEG_INFINITY {
            section
        } else if at_start || at_end {
            capped(section, plane)
        } else {
            max(section, plane)
        }
    }

    /// Field value and gradient.
    fn eval(&self, p: DVec3) -> (f64, DVec3) {
        if self.parts.is_empty() {
            let c = self.index.closest(p);
            return self.section(p, &c);
        }
        // A part's field is at least its distance from the part's path less R: search the
        // nearest part first and skip those that cannot beat the best so far.
        let mut order = [(f64::INFINITY, 0usize); 3];
        for (slot, (i, part)) in order.iter_mut().zip(self.parts.iter().enumerate()) {
            *slot = (box_distance(&part.bbox, p) - self.radius, i);
        }
        order[..self.parts.len()].sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut best = (f64::INFINITY, DVec3::Z);
        for &(bound, i) in &order[..self.parts.len()] {
            if bound >= best.0 {
                break;
            }
            let f = self.part_field(&self.parts[i], p);
            if f.0 < best.0 {
                best = f;
            }
        }
        best
    }
}

/// Distance from `p` to the box.
fn box_distance(b: &Aabb, p: DVec3) -> f64 {
    (b.min - p).max(p - b.max).max(DVec3::ZERO).length()
}

/// Splits an open path into parts (see the module notes): the start part hands over after the
/// first span boundary whose slice is `r` or more behind the start plane, the end part likewise;
/// with no room for a middle part, one part carries both caps. Every part's slices must lie behind
/// the planes of its caps.
fn split_parts(
    path: &Curve,
    index: &CurveIndex,
    frames: &Frames,
    r: f64,
) -> Result<Vec<Part>, SweepError> {
    let spans = index.spans();
    let n = spans.len();
    let end_of = |t: f64, cap: bool| {
        let j = path.jet(t);
        End {
            t,
            point: j.point,
            tangent: j.d1.normalize(),
            cap,
        }
    };
    let (first, last) = (end_of(spans[0].t0, true), end_of(spans[n - 1].t1, true));
    // How far the slice disc at `point` (tangent `tangent`) lies behind the plane through `e`
    // facing `out` (out of the solid); negative when the disc crosses the plane.
    let behind = |point: DVec3, tangent: DVec3, e: &End, out: DVec3| {
        // The sine of the angle between the slice's normal and the plane's: |t × n|.
        let tau = tangent.cross(out).length();
        (e.point - point).dot(out) - r * tau
    };
    // The parameter of span boundary k (0 = path start, n = path end).
    let at = |k: usize| if k == 0 { spans[0].t0 } else { spans[k - 1].t1 };
    let slice = |t: f64| {
        let j = path.jet(t);
        (j.point, j.d1.normalize())
    };
    let k_start = (1..=n).find(|&k| {
        let (x, t) = slice(at(k));
        behind(x, t, &first, -first.tangent) >= r
    });
    let k_end = (0..n).rev().find(|&k| {
        let (x, t) = slice(at(k));
        behind(x, t, &last, last.tangent) >= r
    });
    let tolerance = 1e-9 * r.max(index.bbox().size().length());
    let check = |t_lo: f64, t_hi: f64, caps: &[(&End, DVec3)]| -> Result<(), SweepError> {
        for (t, x, tangent) in frames.samples() {
            if t < t_lo || t > t_hi {
                continue;
            }
            for (e, out) in caps {
                if behind(x, tangent, e, *out) < -tolerance {
                    return Err(invalid(
                        "path",
                        "an end plane cuts through the swept solid (the path turns back too close to its end)",
                    ));
                }
            }
        }
        Ok(())
    };
    let part = |lo: usize, hi: usize, start: End, end: End| Part {
        first: lo,
        last: hi,
        start,
        end,
        bbox: index.spans_bbox(lo, hi),
    };
    match (k_start, k_end) {
        (Some(ks), Some(ke)) if ks + 1 < ke => {
            check(first.t, at(ks + 1), &[(&first, -first.tangent)])?;
            check(at(ke - 1), last.t, &[(&last, last.tangent)])?;
            Ok(vec![
                part(0, ks, first, end_of(at(ks + 1), false)),
                part(ks, ke - 1, end_of(at(ks), false), end_of(at(ke), false)),
                part(ke - 1, n - 1, end_of(at(ke - 1), false), last),
            ])
        }
        _ => {
            check(
                first.t,
                last.t,
                &[(&first, -first.tangent), (&last, last.tangent)],
            )?;
            Ok(vec![part(0, n - 1, first, last)])
        }
    }
}

impl Shape for Sweep {
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
        self.index.bbox().expanded(self.radius)
    }
    fn sublevel_boxes_hold(&self) -> bool {
        // A slope-divided distance bound: see `Shape::sublevel_boxes_hold`.
        false
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked when built: a `Sweep` is always valid.
        Ok(())
    }
    fn lipschitz(&self) -> f64 {
        self.lipschitz
    }
}
