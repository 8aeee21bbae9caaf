//! The polygon profile with holes: loops of corners, inside by the **even-odd rule** (a point is
//! inside when a ray from it crosses the loops an odd number of times), so the orientation of
//! the loops does not matter and a hole is simply a loop inside the outline. The signed distance
//! is exact: the distance to the nearest edge of any loop, negative inside.
//!
//! The distance is computed from corner accessors, so lofts evaluate it on interpolated corners
//! without building a polygon.

use super::edges::EdgeIndex;
use super::error::ProfileError;
pub(crate) use super::nearest::Nearest;
use super::nearest::{Best, closest, crosses};
use glam::DVec2;

/// A polygon: an outline and holes, each a closed loop of corners (last joined to first).
#[derive(Debug, Clone)]
pub struct Polygon {
    loops: Vec<Vec<DVec2>>,
    /// The edge index of a polygon with many edges (`edges.rs`): same answers, found faster.
    pub(super) index: Option<EdgeIndex>,
}

impl PartialEq for Polygon {
    fn eq(&self, other: &Self) -> bool {
        // The index is derived from the loops.
        self.loops == other.loops
    }
}

/// The signed distance from `q` to the loops `0..loops`, loop `r` having `len(r)` corners
/// `corner(r, i)`.
pub(crate) fn loops_distance(
    q: DVec2,
    loops: usize,
    len: impl Fn(usize) -> usize,
    corner: impl Fn(usize, usize) -> DVec2,
) -> Nearest {
    loops_distance_skipping(q, loops, len, corner, |_, _| false)
}

/// [`loops_distance`] ignoring the edges `skip` selects for the distance (they still bound the
/// region): a revolved profile's edges on the axis are inside the solid, not on its surface.
pub(crate) fn loops_distance_skipping(
    q: DVec2,
    loops: usize,
    len: impl Fn(usize) -> usize,
    corner: impl Fn(usize, usize) -> DVec2,
    skip: impl Fn(DVec2, DVec2) -> bool,
) -> Nearest {
    let mut inside = false;
    let mut best = Best::NONE;
    for r in 0..loops {
        let n = len(r);
        let mut a = corner(r, n - 1);
        for i in 0..n {
            let b = corner(r, i);
            let (lambda, c, e, d2) = closest(a, b, q);
            if d2 < best.d2 && !skip(a, b) {
                best = Best {
                    d2,
                    ring: r,
                    edge: (i + n - 1) % n,
                    lambda,
                    c,
                    e,
                };
            }
            if crosses(q, a, b) {
                inside = !inside;
            }
            a = b;
        }
    }
    best.signed(inside, q)
}

/// Twice the signed area of a loop (positive counter-clockwise).
pub(crate) fn signed_area2(corners: &[DVec2]) -> f64 {
    let n = corners.len();
    (0..n)
        .map(|i| corners[i].perp_dot(corners[(i + 1) % n]))
        .sum()
}

/// Whether `q` is inside the loop (crossing rule).
pub(crate) fn inside_loop(q: DVec2, corners: &[DVec2]) -> bool {
    let n = corners.len();
    let mut inside = false;
    for i in 0..n {
        if crosses(q, corners[(i + n - 1) % n], corners[i]) {
            inside = !inside;
        }
    }
    inside
}

fn check_loop(parameter: &'static str, corners: &[DVec2]) -> Result<(), ProfileError> {
    if corners.len() < 3 {
        return Err(ProfileError::TooFewPoints {
            parameter,
            found: corners.len(),
        });
    }
    if corners.iter().any(|c| !c.is_finite()) {
        return Err(ProfileError::NonFinite { parameter });
    }
    let n = corners.len();
    if let Some(index) = (0..n).find(|&i| corners[i] == corners[(i + 1) % n]) {
        return Err(ProfileError::RepeatedPoint { parameter, index });
    }
    let scale = corners
        .iter()
        .map(|c| c.length_squared())
        .fold(0.0, f64::max);
    if signed_area2(corners).abs() <= 1e-14 * scale {
        return Err(ProfileError::ZeroArea { parameter });
    }
    Ok(())
}

impl Polygon {
    /// The polygon with outline `points` and `holes` (each at least 3 corners, finite, no two
    /// consecutive corners equal, non-zero area).
    pub fn new(points: Vec<DVec2>, holes: Vec<Vec<DVec2>>) -> Result<Polygon, ProfileError> {
        check_loop("points", &points)?;
        for h in &holes {
            check_loop("holes", h)?;
        }
        let mut loops = vec![points];
        loops.extend(holes);
        let index = EdgeIndex::new(&loops);
        Ok(Polygon { loops, index })
    }

    /// The outline's corners.
    pub fn points(&self) -> &[DVec2] {
        &self.loops[0]
    }

    /// The holes' corners.
    pub fn holes(&self) -> &[Vec<DVec2>] {
        &self.loops[1..]
    }

    /// Every loop: the outline first, then the holes.
    pub fn loops(&self) -> &[Vec<DVec2>] {
        &self.loops
    }

    /// Signed distance and gradient with details of the nearest edge.
    pub(crate) fn nearest(&self, q: DVec2) -> Nearest {
        self.nearest_skipping(q, |_, _| false)
    }

    /// [`Polygon::nearest`] ignoring the edges `skip` selects for the distance (by the index
    /// when there is one: the same answer).
    fn nearest_skipping(&self, q: DVec2, skip: impl Fn(DVec2, DVec2) -> bool) -> Nearest {
        match &self.index {
            Some(index) if q.is_finite() => index.nearest(&self.loops, q, skip),
            _ => loops_distance_skipping(
                q,
                self.loops.len(),
                |r| self.loops[r].len(),
                |r, i| self.loops[r][i],
                skip,
            ),
        }
    }

    /// [`Polygon::nearest`] by the plain loop over every edge (the reference of the index).
    #[cfg(test)]
    pub(crate) fn nearest_plain(&self, q: DVec2) -> Nearest {
        loops_distance(
            q,
            self.loops.len(),
            |r| self.loops[r].len(),
            |r, i| self.loops[r][i],
        )
    }

    /// Signed distance and its gradient.
    pub fn distance_gradient(&self, q: DVec2) -> (f64, DVec2) {
        let n = self.nearest(q);
        (n.distance, n.gradient)
    }

    /// Signed distance and gradient ignoring the edges on the y axis (both corners at x = 0).
    pub(crate) fn distance_gradient_off_axis(&self, q: DVec2) -> (f64, DVec2) {
        let n = self.nearest_skipping(q, |a, b| a.x == 0.0 && b.x == 0.0);
        (n.distance, n.gradient)
    }

    /// Area and centroid of the even-odd region, for loops that do not cross: a loop inside an
    /// even number of others adds its area, inside an odd number subtracts it.
    pub fn area_centroid(&self) -> (f64, DVec2) {
        let mut area = 0.0;
        let mut moment = DVec2::ZERO;
        for (r, corners) in self.loops.iter().enumerate() {
            let depth = self
                .loops
                .iter()
                .enumerate()
                .filter(|&(o, other)| o != r && inside_loop(corners[0], other))
                .count();
            let sign = if depth.is_multiple_of(2) { 1.0 } else { -1.0 };
            let a2 = signed_area2(corners);
            let n = corners.len();
            let c: DVec2 = (0..n)
                .map(|i| {
                    let (p, q) = (corners[i], corners[(i + 1) % n]);
                    (p + q) * p.perp_dot(q)
                })
                .sum::<DVec2>()
                / (3.0 * a2);
            let a = 0.5 * a2.abs();
            area += sign * a;
            moment += c * (sign * a);
        }
        (area, moment / area)
    }
}
