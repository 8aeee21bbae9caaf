//! The ruled surface `s(u, v) = (1 − v)·c₁(u) + v·c₂(u)` between any two curves (lecture notes
//! 000), open or closed, in any planes or none, as a solid (JSON `ruled_surface`):
//!
//! - without `thickness`, both curves must be closed and each plane (any plane, any position:
//!   two circles in the planes x = 0 and x = 2 give a cylinder along x); the solid is bounded by
//!   the ruled band and the two plane regions the curves enclose (a curve that is a single point
//!   is an apex: a cone);
//! - with `thickness` `t`, the curves may be anything (open, closed, twisted): the solid is every
//!   point within `t/2` of the ruled surface (the sheet thickened on both sides, rounded at its
//!   edges).
//!
//! Both curves are sampled at `samples` regular parameters (each normalised to `[0, 1]`, so `u`
//! pairs points by parameter, as the formula does) and each ruling strip is cut into as many
//! pieces along `v` as its twist needs; the field is the exact signed distance to that
//! tessellation (closed: [`MeshSolid`]; thick: the unsigned distance minus `t/2`), so it is
//! 1-Lipschitz and its zero set is within [`RuledSurface::field_error`] (the measured chord
//! error of the tessellation) of the exact surface. The horizontal closed case with an exact
//! field is the `ruled` node ([`Ruled`](super::Ruled)).

use super::error::{SweepError, invalid};
use crate::curve::{Curve, Curve3};
use crate::primitive::{MeshSolid, PrimitiveError, Shape, lipschitz_interval};
use crate::triangulate::{newell_normal, triangulate_face};
use crate::{Aabb, IndexedMesh, Interval};
use glam::DVec3;

/// The solid of a ruled surface between two curves: closed by its end caps, or thickened.
#[derive(Debug, Clone)]
pub struct RuledSurface {
    first: Curve,
    second: Curve,
    thickness: Option<f64>,
    samples: usize,
    mesh: MeshSolid,
    chord_error: f64,
}

impl PartialEq for RuledSurface {
    fn eq(&self, other: &Self) -> bool {
        (&self.first, &self.second, self.thickness, self.samples)
            == (&other.first, &other.second, other.thickness, other.samples)
    }
}

impl RuledSurface {
    /// Samples along the curves when none are given.
    pub const DEFAULT_SAMPLES: usize = 128;
    /// The most samples along the curves.
    pub const MAX_SAMPLES: usize = 4096;
    /// The most pieces a ruling strip is cut into along `v`.
    pub const MAX_PIECES: usize = 64;

    /// The solid of the ruled surface between `first` and `second` (see the module docs):
    /// closed by its plane end caps when `thickness` is `None`, else the surface thickened to
    /// `thickness`. `samples` (default [`Self::DEFAULT_SAMPLES`], 3 to [`Self::MAX_SAMPLES`]) is the
    /// number of segments along the curves.
    pub fn new(
        first: Curve,
        second: Curve,
        thickness: Option<f64>,
        samples: Option<usize>,
    ) -> Result<RuledSurface, SweepError> {
        let samples = samples.unwrap_or(Self::DEFAULT_SAMPLES);
        if !(3..=Self::MAX_SAMPLES).contains(&samples) {
            return Err(invalid("samples", "expected a whole number from 3 to 4096"));
        }
        if let Some(t) = thickness
            && !(t > 0.0 && t.is_finite() && crate::primitive::faithful(t))
        {
            return Err(invalid("thickness", "expected a finite positive number"));
        }
        let closed = thickness.is_none();
        if closed {
            for (key, c) in [("first", &first), ("second", &second)] {
                if !c.is_closed() {
                    return Err(invalid(
                        key,
                        "the curve must be closed (end where it starts) unless a thickness is given",
                    ));
                }
            }
        }
        let (mesh, chord_error) = tessellate(&first, &second, closed, samples)?;
        let mesh = MeshSolid::from_mesh(&mesh)
            .map_err(|_| invalid("first", "the ruled surface has no usable triangles"))?;
        if closed && mesh.open_edges() != 0 {
            return Err(invalid(
                "first",
                "the ruled surface and its caps do not close",
            ));
        }
        Ok(RuledSurface {
            first,
            second,
            thickness,
            samples,
            mesh,
            chord_error,
        })
    }

    /// The first curve (`v = 0`).
    pub fn first(&self) -> &Curve {
        &self.first
    }

    /// The second curve (`v = 1`).
    pub fn second(&self) -> &Curve {
        &self.second
    }

    /// The thickness, or `None` for the solid closed by its caps.
    pub fn thickness(&self) -> Option<f64> {
        self.thickness
    }

    /// Segments along the curves.
    pub fn samples(&self) -> usize {
        self.samples
    }

    /// Largest distance between the tessellation and the exact surface, measured at the middle of
    /// every segment and ruling strip (the field's zero set is the tessellation, offset by the
    /// thickness).
    pub fn field_error(&self) -> f64 {
        self.chord_error
    }

    /// The point `s(u, v)` (both curves' parameters normalised to `[0, 1]`).
    pub fn surface_point(&self, u: f64, v: f64) -> DVec3 {
        at(&self.first, u).lerp(at(&self.second, u), v)
    }

    /// Volume of the closed solid's tessellation (the caps and band as triangles); `None` for a
    /// thickened surface.
    pub fn volume(&self) -> Option<f64> {
        self.thickness.is_none().then(|| {
            let mesh = self.tessellation();
            (0..mesh.triangles.len())
                .map(|i| {
                    let [a, b, c] = mesh.triangle_positions(i);
                    a.dot(b.cross(c))
                })
                .sum::<f64>()
                / 6.0
        })
    }

    /// The tessellation the field measures the distance to (for the closed solid: its boundary,
    /// outward).
    pub fn tessellation(&self) -> IndexedMesh {
        let (mesh, _) = tessellate(
            &self.first,
            &self.second,
            self.thickness.is_none(),
            self.samples,
        )
        .expect("tessellated when built");
        mesh
    }

    fn eval(&self, p: DVec3) -> (f64, DVec3) {
        match self.thickness {
            None => (self.mesh.value(p), self.mesh.gradient(p)),
            Some(t) => {
                // Only the unsigned distance: no winding number.
                let (d, near) = self.mesh.unsigned_distance(p);
                let g = if d > 0.0 {
                    (p - near) / d
                } else {
                    self.mesh.gradient(p)
                };
                (d - 0.5 * t, g)
            }
        }
    }
}

/// The point of `c` at the normalised parameter `u ∈ [0, 1]`.
fn at(c: &Curve, u: f64) -> DVec3 {
    let (t0, t1) = c.domain();
    c.point(t0 + u * (t1 - t0))
}

/// True when every point of `points` is the first one.
fn all_equal(points: &[DVec3]) -> bool {
    points.iter().all(|p| *p == points[0])
}

/// The band (and, when `closed`, the caps) as an outward triangle mesh, and its chord error.
fn tessellate(
    first: &Curve,
    second: &Curve,
    closed: bool,
    samples: usize,
) -> Result<(IndexedMesh, f64), SweepError> {
    // Closed curves repeat no end point: `samples` distinct points around.
    let count = if closed { samples } else { samples + 1 };
    let u = |k: usize| k as f64 / samples as f64;
    let rails: [Vec<DVec3>; 2] = [first, second].map(|c| (0..count).map(|k| at(c, u(k))).collect());
    let size = rails
        .iter()
        .flatten()
        .fold(Aabb::empty(), |b, p| b.union(&Aabb::new(*p, *p)))
        .size()
        .length();
    if !size.is_finite() || size == 0.0 {
        return Err(invalid("first", "the curves span no surface"));
    }
    let point = [all_equal(&rails[0]), all_equal(&rails[1])];
    if point[0] && point[1] {
        return Err(invalid("first", "both curves are single points"));
    }
    // Chord error of the rails (curve midpoint against segment midpoint) and the twist of each
    // ruling strip: how far its bilinear patch's centre `(a + b + c + d)/4` lies off the plane of
    // the strip (normal `(c − a) × (d − b)`), which is where the two triangles leave the patch
    // most; a strip that is flat (a cone's, a cylinder's) has none.
    let mut chord: f64 = 0.0;
    let mut twist: f64 = 0.0;
    for k in 0..samples {
        let next = (k + 1) % count;
        for (c, rail) in [first, second].iter().zip(&rails) {
            let mid = at(c, (k as f64 + 0.5) / samples as f64);
            chord = chord.max(mid.distance(0.5 * (rail[k] + rail[next])));
        }
        let (a, b, c, d) = (rails[0][k], rails[0][next], rails[1][next], rails[1][k]);
        let normal = (c - a).cross(d - b).normalize_or_zero();
        twist = twist.max(0.25 * (a + c - b - d).dot(normal).abs());
    }
    // Cut strips so the twist left is at most the chord error (or a thousandth of the size):
    // the twist is the mixed derivative times `Δu Δv`, so `m` pieces along v leave a `m`-th.
    let target = chord.max(1e-3 * size);
    let pieces = ((twist / target).ceil() as usize).clamp(1, RuledSurface::MAX_PIECES);
    let left = twist / pieces as f64;
    // Rows v = j / pieces; a point row is one vertex.
    let mut positions = Vec::new();
    let mut rows: Vec<Vec<u32>> = Vec::with_capacity(pieces + 1);
    for j in 0..=pieces {
        let v = j as f64 / pieces as f64;
        let single = (j == 0 && point[0]) || (j == pieces && point[1]);
        let start = positions.len() as u32;
        if single {
            positions.push(rails[usize::from(j == pieces)][0]);
            rows.push(vec![start; count]);
        } else {
            positions.extend((0..count).map(|k| rails[0][k].lerp(rails[1][k], v)));
            rows.push((start..start + count as u32).collect());
        }
    }
    let mut triangles = Vec::new();
    let segments = if closed { count } else { count - 1 };
    for j in 0..pieces {
        for k in 0..segments {
            let next = (k + 1) % count;
            let (a, b) = (rows[j][k], rows[j][next]);
            let (c, d) = (rows[j + 1][next], rows[j + 1][k]);
            for t in [[a, b, c], [a, c, d]] {
                if t[0] != t[1] && t[1] != t[2] && t[2] != t[0] {
                    triangles.push(t);
                }
            }
        }
    }
    if closed {
        // Caps: the first rail's polygon reversed, the second's as it runs (the band runs
        // k → k + 1 along the rails, v upwards), each triangulated in its own plane.
        for (key, end, reversed) in [("first", 0, true), ("second", pieces, false)] {
            let end_point = if end == 0 { point[0] } else { point[1] };
            if end_point {
                continue;
            }
            let mut corners = rows[end].clone();
            if reversed {
                corners.reverse();
            }
            check_plane(key, &positions, &corners, size)?;
            triangulate_face(&positions, &corners, &mut triangles).map_err(|_| {
                invalid(
                    key,
                    "the curve must enclose a simple plane region (it crosses itself)",
                )
            })?;
        }
        let volume: f64 = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| positions[i as usize]);
                a.dot(b.cross(c))
            })
            .sum();
        if volume.abs() <= 1e-12 * size.powi(3) {
            return Err(invalid("first", "the ruled solid encloses no volume"));
        }
        if volume < 0.0 {
            for t in &mut triangles {
                t.swap(1, 2);
            }
        }
    }
    Ok((IndexedMesh::new(positions, triangles), chord.max(left)))
}

/// Fails unless the polygon `corners` lies in a plane (within `10⁻⁹` of the size).
fn check_plane(
    key: &'static str,
    positions: &[DVec3],
    corners: &[u32],
    size: f64,
) -> Result<(), SweepError> {
    let points: Vec<DVec3> = corners.iter().map(|&i| positions[i as usize]).collect();
    let normal = newell_normal(&points).normalize_or_zero();
    let centre = points.iter().sum::<DVec3>() / points.len() as f64;
    let off = points
        .iter()
        .map(|p| (*p - centre).dot(normal).abs())
        .fold(0.0, f64::max);
    if normal == DVec3::ZERO || off > 1e-9 * size {
        return Err(invalid(
            key,
            "a closed curve must lie in a plane to be capped (or give a thickness)",
        ));
    }
    Ok(())
}

impl Shape for RuledSurface {
    fn value(&self, p: DVec3) -> f64 {
        self.eval(p).0
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        self.eval(p).1
    }
    fn interval(&self, b: &Aabb) -> Interval {
        match self.thickness {
            None => self.mesh.interval(b),
            Some(_) => lipschitz_interval(self, b),
        }
    }
    fn bbox(&self) -> Aabb {
        self.mesh
            .bbox()
            .expanded(0.5 * self.thickness.unwrap_or(0.0))
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked when built: a `RuledSurface` is always valid.
        Ok(())
    }
}
