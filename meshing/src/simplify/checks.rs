//! Whether a collapse is allowed: the triangles around the merged vertex keep their orientation
//! and stay proper triangles, stay within the tolerance of the input mesh (sampled), every input
//! vertex they answer for stays within the tolerance of them, and none meets another triangle
//! beyond the vertices they share (exact predicates).

use super::spatial::Spatial;
use super::surface::{Star, Surface};
use crate::intersect::triangles::{Tri, meet_beyond_shared};
use glam::DVec3;
use solidkit_kernel::closest::closest_point_on_triangle;

/// Least cosine between a triangle's normal before and after a collapse.
const MIN_NORMAL_COSINE: f64 = 0.2;

/// Least cosine between a new triangle's normal and the field's gradient at its centre, when it
/// turned away from its old normal.
const SURFACE_NORMAL_COSINE: f64 = 0.7;

/// Most subdivisions per edge when sampling a triangle against the input.
const MAX_SUBDIVISIONS: usize = 16;

/// What the checks read: the field, the witnesses (the input's vertices moved onto the zero
/// set) and the limits.
pub(crate) struct Checker<'a> {
    /// The field's value at a point (a distance bound: Lipschitz constant at most 1).
    pub field: &'a dyn Fn(DVec3) -> f64,
    /// The field's gradient at a point.
    pub gradient: &'a dyn Fn(DVec3) -> DVec3,
    /// Points of the surface the result must pass near.
    pub witnesses: &'a [DVec3],
    /// Largest distance allowed, both ways.
    pub tolerance: f64,
    /// Sample spacing on the new triangles (the input's cell size).
    pub spacing: f64,
}

/// A collapse that passed: for every witness of the star's triangles, the new triangle that
/// answers for it now.
pub(crate) struct Passed {
    /// `(witness, triangle)` pairs.
    pub witnesses: Vec<(u32, u32)>,
}

impl Checker<'_> {
    /// Checks the collapse of `star` with the merged vertex at `at`; `owned` lists the witnesses
    /// of each triangle.
    pub fn check(
        &self,
        s: &Surface,
        star: &Star,
        at: DVec3,
        owned: &[Vec<u32>],
        index: &Spatial,
        scratch: &mut Vec<u32>,
    ) -> Option<Passed> {
        let new: Vec<([u32; 3], [DVec3; 3])> = star
            .kept
            .iter()
            .map(|&t| {
                let ids = s.after(star, t);
                let p = ids.map(|v| {
                    if v == star.into {
                        at
                    } else {
                        s.positions[v as usize]
                    }
                });
                (ids, p)
            })
            .collect();
        if !self.shapes_hold(s, star, &new) || !new.iter().all(|(_, p)| self.near_input(p, at)) {
            return None;
        }
        if self.meets_others(star, &new, index, s, scratch) {
            return None;
        }
        let witnesses = self.witnesses_covered(star, &new, owned)?;
        Some(Passed { witnesses })
    }

    /// Orientation kept, no degenerate triangle, no triangle twice.
    fn shapes_hold(&self, s: &Surface, star: &Star, new: &[([u32; 3], [DVec3; 3])]) -> bool {
        for (k, (ids, p)) in new.iter().enumerate() {
            let n1 = (p[1] - p[0]).cross(p[2] - p[0]);
            let longest = (p[1] - p[0])
                .length_squared()
                .max((p[2] - p[1]).length_squared())
                .max((p[0] - p[2]).length_squared());
            if n1
                .length_squared()
                .partial_cmp(&(1e-20 * longest * longest))
                != Some(std::cmp::Ordering::Greater)
            {
                return false;
            }
            let old = s.corners(star.kept[k]);
            let n0 = (old[1] - old[0]).cross(old[2] - old[0]);
            let n1 = n1.normalize();
            if n0.normalize_or_zero().dot(n1) < MIN_NORMAL_COSINE {
                // A turn away from a badly placed input triangle is fine when the new one faces
                // the way the surface does.
                let g = (self.gradient)((p[0] + p[1] + p[2]) / 3.0).normalize_or_zero();
                if g.dot(n1) < SURFACE_NORMAL_COSINE {
                    return false;
                }
            }
            let mut sorted = *ids;
            sorted.sort_unstable();
            for (other, _) in &new[..k] {
                let mut o = *other;
                o.sort_unstable();
                if o == sorted {
                    return false;
                }
            }
        }
        true
    }

    /// Samples of the triangle (the merged vertex `at`, and a barycentric lattice about
    /// `spacing` apart) all with field values within the tolerance, where a corner already
    /// farther out (an input vertex off the surface) raises the bound near it by its excess.
    fn near_input(&self, p: &[DVec3; 3], at: DVec3) -> bool {
        let longest = (p[1] - p[0])
            .length()
            .max((p[2] - p[1]).length())
            .max((p[0] - p[2]).length());
        let n = ((longest / self.spacing).ceil() as usize).clamp(1, MAX_SUBDIVISIONS);
        let excess = p.map(|c| {
            if c == at {
                0.0
            } else {
                ((self.field)(c).abs() - self.tolerance).max(0.0)
            }
        });
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let q = p[0] + (p[1] - p[0]) * u + (p[2] - p[0]) * v;
                let bound = self.tolerance
                    + excess[0] * (1.0 - u - v).max(0.0)
                    + excess[1] * u
                    + excess[2] * v;
                let f = (self.field)(q).abs();
                if f.is_nan() || f > bound {
                    return false;
                }
            }
        }
        true
    }

    /// Every witness of the star's triangles within the tolerance of a new triangle. A witness
    /// of a kept triangle stays with it when that triangle's new shape is within the tolerance
    /// (one distance per witness, the common case); any other goes to the nearest new triangle
    /// (triangles whose boxes are farther than the best distance so far are skipped).
    fn witnesses_covered(
        &self,
        star: &Star,
        new: &[([u32; 3], [DVec3; 3])],
        owned: &[Vec<u32>],
    ) -> Option<Vec<(u32, u32)>> {
        let limit = self.tolerance * self.tolerance;
        let boxes: Vec<(DVec3, DVec3)> = new
            .iter()
            .map(|(_, p)| (p[0].min(p[1]).min(p[2]), p[0].max(p[1]).max(p[2])))
            .collect();
        let mut out = Vec::new();
        let removed = star.removed.iter().map(|&t| (t, None));
        let kept = star.kept.iter().enumerate().map(|(k, &t)| (t, Some(k)));
        for (t, own) in removed.chain(kept) {
            for &w in &owned[t as usize] {
                let q = self.witnesses[w as usize];
                if let Some(k) = own
                    && closest_point_on_triangle(q, new[k].1).distance_squared(q) <= limit
                {
                    out.push((w, t));
                    continue;
                }
                let mut best = (f64::INFINITY, 0);
                for (k, (_, p)) in new.iter().enumerate() {
                    let (lo, hi) = boxes[k];
                    if (q.clamp(lo, hi) - q).length_squared() >= best.0 {
                        continue;
                    }
                    let d2 = closest_point_on_triangle(q, *p).distance_squared(q);
                    if d2 < best.0 {
                        best = (d2, k);
                    }
                }
                if best.0.is_nan() || best.0 > limit {
                    return None;
                }
                out.push((w, star.kept[best.1]));
            }
        }
        Some(out)
    }

    /// Whether a new triangle meets another live triangle, or another new one, beyond what they
    /// share.
    fn meets_others(
        &self,
        star: &Star,
        new: &[([u32; 3], [DVec3; 3])],
        index: &Spatial,
        s: &Surface,
        scratch: &mut Vec<u32>,
    ) -> bool {
        let mut tris = Vec::with_capacity(new.len());
        let mut lo = DVec3::INFINITY;
        let mut hi = DVec3::NEG_INFINITY;
        for (_, p) in new {
            match Tri::new(*p) {
                Some(t) => tris.push(t),
                None => return true,
            }
            lo = lo.min(p[0]).min(p[1]).min(p[2]);
            hi = hi.max(p[0]).max(p[1]).max(p[2]);
        }
        for (k, (ids, _)) in new.iter().enumerate() {
            for (m, (other, _)) in new[..k].iter().enumerate() {
                if meet_beyond_shared(*ids, &tris[k], *other, &tris[m]) {
                    return true;
                }
            }
        }
        index.near(lo, hi, scratch);
        for &c in scratch.iter() {
            if star.kept.binary_search(&c).is_ok() || star.removed.contains(&c) {
                continue;
            }
            let cp = s.corners(c);
            let clo = cp[0].min(cp[1]).min(cp[2]);
            let chi = cp[0].max(cp[1]).max(cp[2]);
            let Some(ct) = Tri::new(cp) else { continue };
            for (k, (ids, p)) in new.iter().enumerate() {
                let plo = p[0].min(p[1]).min(p[2]);
                let phi = p[0].max(p[1]).max(p[2]);
                if plo.cmple(chi).all()
                    && phi.cmpge(clo).all()
                    && meet_beyond_shared(*ids, &tris[k], s.triangles[c as usize], &ct)
                {
                    return true;
                }
            }
        }
        false
    }
}
