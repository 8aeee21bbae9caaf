//! The Platonic solids as primitives: tetrahedron, cube, octahedron, dodecahedron, icosahedron,
//! centred at the origin in the orientation of
//! [`Polyhedron::platonic`](crate::polyhedra::Polyhedron::platonic).
//!
//! Field: `f(p) = max_i (n̂_i · p) − r_in`, the largest signed distance to the face planes (all
//! at the inradius `r_in`). Inside it equals the exact signed distance; outside it is a lower
//! bound of the distance (exact where the nearest boundary point is inside a face, smaller near
//! edges and vertices). It is 1-Lipschitz and its zero set is exactly the polyhedron's surface,
//! so `field_error` (the distance between the zero set and the exact surface) is 0.

use super::super::{PrimitiveError, Shape, positive};
use crate::polyhedra::{PlatonicKind, PlatonicSize, unit_platonic};
use crate::{Aabb, Interval};
use glam::DVec3;

/// A Platonic solid centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Platonic {
    /// Which of the five.
    pub kind: PlatonicKind,
    /// Its size (circumradius or edge, kept as given).
    pub size: PlatonicSize,
}

impl Platonic {
    /// Distance between the field's zero set and the exact surface: 0 (the face planes are exact).
    pub const FIELD_ERROR: f64 = 0.0;

    /// A Platonic solid of the given kind and size.
    pub fn new(kind: PlatonicKind, size: PlatonicSize) -> Platonic {
        Platonic { kind, size }
    }

    /// Distance between the field's zero set and the exact surface (0).
    pub fn field_error(&self) -> f64 {
        Self::FIELD_ERROR
    }

    /// Distance from the centre to the vertices.
    pub fn circumradius(&self) -> f64 {
        self.size.circumradius(self.kind)
    }

    /// Distance from the centre to the face planes.
    pub fn inradius(&self) -> f64 {
        unit_platonic(self.kind).inradius * self.circumradius()
    }

    fn normals(&self) -> &'static [DVec3] {
        &unit_platonic(self.kind).normals
    }
}

impl Shape for Platonic {
    fn value(&self, p: DVec3) -> f64 {
        let m = self
            .normals()
            .iter()
            .fold(f64::NEG_INFINITY, |m, n| m.max(n.dot(p)));
        m - self.inradius()
    }

    fn gradient(&self, p: DVec3) -> DVec3 {
        let mut best = (f64::NEG_INFINITY, DVec3::Z);
        for n in self.normals() {
            let d = n.dot(p);
            if d > best.0 {
                best = (d, *n);
            }
        }
        best.1
    }

    fn interval(&self, b: &Aabb) -> Interval {
        // Each plane's range over the box is exact; the max of intervals bounds the max.
        let (c, h) = (b.center(), b.half_extents());
        let r = self.inradius();
        self.normals()
            .iter()
            .map(|n| Interval::around(n.dot(c) - r, n.abs().dot(h)))
            .reduce(Interval::max)
            .unwrap_or(Interval::entire())
    }

    fn bbox(&self) -> Aabb {
        let half = unit_platonic(self.kind).half_extents * self.circumradius();
        // Pad by a few ulps: the face planes and the vertices are rounded independently.
        Aabb::centered(half * (1.0 + 1e-12))
    }

    fn bbox_at(&self, level: f64) -> Aabb {
        // max nᵢ·p − r ≤ ℓ is the solid scaled by (r + ℓ)/r: its vertices move out by more than ℓ.
        let half = unit_platonic(self.kind).half_extents * self.circumradius();
        Aabb::centered(half * (1.0 + 1e-12) * (1.0 + level / self.inradius()))
    }

    fn validate(&self) -> Result<(), PrimitiveError> {
        positive(self.size.parameter(), self.size.value())
    }

    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len().min(x.len()).min(y.len()).min(z.len());
        let (x, y, z, out) = (&x[..n], &y[..n], &z[..n], &mut out[..n]);
        out.fill(f32::NEG_INFINITY);
        for normal in self.normals() {
            let [a, b, c] = normal.as_vec3().to_array();
            for (((o, &px), &py), &pz) in out.iter_mut().zip(x).zip(y).zip(z) {
                *o = o.max(a * px + b * py + c * pz);
            }
        }
        let r = self.inradius() as f32;
        out.iter_mut().for_each(|v| *v -= r);
    }
}
