//! Height fields: the solid between a base plane `z = z₀` and a Monge patch `z = h(x, y)` over a
//! rectangle `[x₀, x₁] × [y₀, y₁]` (lecture notes 001), with `h` from a tensor-product Bézier patch
//! of any degrees, a sampled grid (bilinear or bicubic) or a PNG height map.
//!
//! # Field
//! With `L` a bound of `|∇h|` over the rectangle (from the source's differenced control net or
//! samples, so honest rather than sampled), `g = (z − h(c(x, y))) / √(1 + L²)` with `c` the clamp
//! into the rectangle is 1-Lipschitz (`|∇(z − h)| = √(1 + |∇h|²) ≤ √(1 + L²)`), and the field is
//! `max(g, dist_box)` with the box `[x₀, x₁] × [y₀, y₁] × [z₀, 2 h_max − z₀]`: 1-Lipschitz, with the
//! solid `{z₀ ≤ z ≤ h}` as its negative set. Columns where `h ≤ z₀` are empty. Intervals bound `h`
//! over the box's footprint by `h(centre) ± (L_x w_x + L_y w_y)` within the global range.
//!
//! Curvatures of the top surface come from [`crate::patch::curvature`].

mod bezier;
mod error;
mod grid;
mod param;
mod png_map;
mod quad_mesh;
mod sampled;
mod source;

pub use bezier::MAX_CONTROL_HEIGHTS;
pub use error::HeightFieldError;
pub use grid::HeightGrid;
pub use png_map::{
    MAX_PNG_DECODER_BYTES, MAX_PNG_PIXELS, MAX_PNG_SIDE, decode_png, decode_png_luminance, load_png,
};
pub use quad_mesh::QuadMesh;
pub use source::{HeightSource, Interpolation};

use super::{Cuboid, PrimitiveError, Shape};
use crate::patch::curvature::{Curvature, HeightDerivatives, monge_curvature};
use crate::{Aabb, Interval};
use glam::{DVec2, DVec3};
use param::ParamBounds;
use std::path::Path;

/// Where a height field's samples were read from, kept so the JSON tree can name the file again.
#[derive(Debug, Clone, PartialEq)]
pub struct PngOrigin {
    /// The PNG file as given.
    pub path: String,
    /// Heights of black and white.
    pub heights: [f64; 2],
}

/// The solid between `z = base` and `z = h(x, y)` over a rectangle; build it with
/// [`HeightField::new`] or [`HeightField::from_png`].
#[derive(Debug, Clone, PartialEq)]
pub struct HeightField {
    min: DVec2,
    max: DVec2,
    base: f64,
    source: HeightSource,
    origin: Option<PngOrigin>,
    bounds: ParamBounds,
    /// `(L_x, L_y)`: bounds of `|h_x|`, `|h_y|`.
    slopes: DVec2,
    /// `1 / √(1 + L²)`.
    scale: f64,
    cuboid: Cuboid,
    center: DVec3,
}

fn parameter(parameter: &'static str, problem: &'static str) -> HeightFieldError {
    HeightFieldError::Parameter(PrimitiveError { parameter, problem })
}

impl HeightField {
    /// The solid between `z = base` and the heights of `source` mapped onto the rectangle
    /// `[min, max]`. Fails when the rectangle is not finite and non-empty, `base` is not finite, or
    /// `base` is not below the highest point of the surface.
    pub fn new(
        min: DVec2,
        max: DVec2,
        base: f64,
        source: HeightSource,
    ) -> Result<Self, HeightFieldError> {
        if !(min.is_finite() && max.is_finite() && min.cmplt(max).all()) {
            return Err(parameter(
                "min",
                "expected a finite rectangle with min below max",
            ));
        }
        if !base.is_finite() {
            return Err(parameter("base", "expected a finite number"));
        }
        if let HeightSource::Bezier(g) = &source
            && g.nx().saturating_mul(g.ny()) > MAX_CONTROL_HEIGHTS
        {
            return Err(HeightFieldError::TooManyControlHeights {
                nx: g.nx(),
                ny: g.ny(),
            });
        }
        let bounds = source.bounds();
        if bounds.hi.partial_cmp(&base) != Some(std::cmp::Ordering::Greater) {
            return Err(parameter(
                "base",
                "must be below the highest point of the height field",
            ));
        }
        let size = max - min;
        let slopes = DVec2::new(bounds.hu / size.x, bounds.hv / size.y);
        let top = 2.0 * bounds.hi - base;
        Ok(Self {
            min,
            max,
            base,
            source,
            origin: None,
            bounds,
            slopes,
            scale: 1.0 / (1.0 + slopes.length_squared()).sqrt(),
            cuboid: Cuboid {
                size: DVec3::new(size.x, size.y, top - base),
            },
            center: DVec3::new(
                0.5 * (min.x + max.x),
                0.5 * (min.y + max.y),
                0.5 * (base + top),
            ),
        })
    }

    /// A height field from a grayscale PNG: black at `heights[0]`, white at `heights[1]`.
    pub fn from_png(
        min: DVec2,
        max: DVec2,
        base: f64,
        path: &Path,
        heights: [f64; 2],
        interpolation: Interpolation,
    ) -> Result<Self, HeightFieldError> {
        if !heights.iter().all(|h| h.is_finite()) {
            return Err(parameter("heights", "expected finite numbers"));
        }
        let unit = load_png(path)?;
        Self::from_height_map(
            min,
            max,
            base,
            &path.to_string_lossy(),
            unit,
            heights,
            interpolation,
        )
    }

    /// A height field from the bytes of a grayscale PNG; `path` is the file's name as the tree
    /// writes it (kept for writing the tree back).
    pub fn from_png_bytes(
        min: DVec2,
        max: DVec2,
        base: f64,
        path: &str,
        bytes: &[u8],
        heights: [f64; 2],
        interpolation: Interpolation,
    ) -> Result<Self, HeightFieldError> {
        if !heights.iter().all(|h| h.is_finite()) {
            return Err(parameter("heights", "expected finite numbers"));
        }
        let unit = decode_png(bytes)?;
        Self::from_height_map(min, max, base, path, unit, heights, interpolation)
    }

    fn from_height_map(
        min: DVec2,
        max: DVec2,
        base: f64,
        path: &str,
        unit: HeightGrid,
        heights: [f64; 2],
        interpolation: Interpolation,
    ) -> Result<Self, HeightFieldError> {
        let values = unit
            .values()
            .iter()
            .map(|t| heights[0] + t * (heights[1] - heights[0]))
            .collect();
        let grid = HeightGrid::new(unit.nx(), unit.ny(), values)?;
        let mut field = Self::new(
            min,
            max,
            base,
            HeightSource::Samples {
                grid,
                interpolation,
            },
        )?;
        field.origin = Some(PngOrigin {
            path: path.to_owned(),
            heights,
        });
        Ok(field)
    }

    /// Lower corner of the rectangle.
    pub fn min(&self) -> DVec2 {
        self.min
    }

    /// Upper corner of the rectangle.
    pub fn max(&self) -> DVec2 {
        self.max
    }

    /// Height of the base plane.
    pub fn base(&self) -> f64 {
        self.base
    }

    /// The height function.
    pub fn source(&self) -> &HeightSource {
        &self.source
    }

    /// The PNG file the samples came from, if any.
    pub fn png_origin(&self) -> Option<&PngOrigin> {
        self.origin.as_ref()
    }

    /// Bounds `(lo, hi)` with `lo ≤ h ≤ hi` over the rectangle.
    pub fn height_range(&self) -> (f64, f64) {
        (self.bounds.lo, self.bounds.hi)
    }

    /// `L`, an upper bound of `|∇h|` over the rectangle.
    pub fn slope_bound(&self) -> f64 {
        self.slopes.length()
    }

    /// A bound of the spectral norm of the Hessian of `h` over the rectangle, where `h` is C¹
    /// (Bézier, bicubic); `None` for bilinear samples.
    pub fn hessian_bound(&self) -> Option<f64> {
        let (uu, uv, vv) = self.bounds.second?;
        let s = self.max - self.min;
        let (xx, xy, yy) = (uu / (s.x * s.x), uv / (s.x * s.y), vv / (s.y * s.y));
        Some((xx * xx + 2.0 * xy * xy + yy * yy).sqrt())
    }

    /// Parameters of a point of the plane, clamped into the rectangle.
    #[inline]
    fn uv(&self, x: f64, y: f64) -> (f64, f64) {
        let s = self.max - self.min;
        (
            ((x - self.min.x) / s.x).clamp(0.0, 1.0),
            ((y - self.min.y) / s.y).clamp(0.0, 1.0),
        )
    }

    /// `h(x, y)` (at the nearest point of the rectangle outside it).
    #[inline]
    pub fn height(&self, x: f64, y: f64) -> f64 {
        let (u, v) = self.uv(x, y);
        self.source.height(u, v)
    }

    /// `h` and its derivatives in `x` and `y` up to second order.
    pub fn derivatives(&self, x: f64, y: f64) -> HeightDerivatives {
        let (u, v) = self.uv(x, y);
        let d = self.source.derivatives(u, v, true);
        let s = self.max - self.min;
        HeightDerivatives {
            h: d.h,
            hx: d.hu / s.x,
            hy: d.hv / s.y,
            hxx: d.huu / (s.x * s.x),
            hxy: d.huv / (s.x * s.y),
            hyy: d.hvv / (s.y * s.y),
        }
    }

    /// Gaussian and mean curvature of the top surface at `(x, y)`.
    pub fn curvature(&self, x: f64, y: f64) -> Curvature {
        monge_curvature(&self.derivatives(x, y))
    }

    /// The top surface point over `(u, v)` in the unit parameter square.
    pub fn point_at(&self, u: f64, v: f64) -> DVec3 {
        let xy = self.min + (self.max - self.min) * DVec2::new(u, v);
        DVec3::new(
            xy.x,
            xy.y,
            self.source.height(u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)),
        )
    }
}

impl HeightField {
    /// The field at `p` given `h = h(p.x, p.y)`.
    #[inline]
    fn value_over(&self, p: DVec3, h: f64) -> f64 {
        let top = (p.z - h) * self.scale;
        top.max(self.cuboid.value(p - self.center))
    }
}

/// Slots of the column cache of [`HeightField::values_f32`] (a power of two).
const COLUMN_SLOTS: usize = 256;

impl Shape for HeightField {
    fn value(&self, p: DVec3) -> f64 {
        self.value_over(p, self.height(p.x, p.y))
    }
    /// Samples of a brick share their columns: `h` is computed once per column met in the chunk
    /// (a direct-mapped cache keyed by the coordinates' bits, so every value is the one
    /// [`Shape::value`] gives).
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let mut keys = [0u64; COLUMN_SLOTS];
        let mut heights = [0f64; COLUMN_SLOTS];
        let mut filled = [false; COLUMN_SLOTS];
        for (i, o) in out.iter_mut().enumerate() {
            let key = (u64::from(x[i].to_bits()) << 32) | u64::from(y[i].to_bits());
            let slot = (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 56) as usize % COLUMN_SLOTS;
            let p = DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64);
            let h = if filled[slot] && keys[slot] == key {
                heights[slot]
            } else {
                let h = self.height(p.x, p.y);
                (keys[slot], heights[slot], filled[slot]) = (key, h, true);
                h
            };
            *o = self.value_over(p, h) as f32;
        }
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        let (u, v) = self.uv(p.x, p.y);
        let d = self.source.derivatives(u, v, false);
        let top = (p.z - d.h) * self.scale;
        let q = p - self.center;
        if self.cuboid.value(q) >= top {
            return self.cuboid.gradient(q);
        }
        let s = self.max - self.min;
        let inside = |t: f64, lo: f64, hi: f64| if t >= lo && t <= hi { 1.0 } else { 0.0 };
        let hx = d.hu / s.x * inside(p.x, self.min.x, self.max.x);
        let hy = d.hv / s.y * inside(p.y, self.min.y, self.max.y);
        DVec3::new(-hx, -hy, 1.0) * self.scale
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let lo = b.min.truncate().clamp(self.min, self.max);
        let hi = b.max.truncate().clamp(self.min, self.max);
        let mid = 0.5 * (lo + hi);
        let half = 0.5 * (hi - lo);
        let spread = self.slopes.dot(half);
        let hm = self.height(mid.x, mid.y);
        let h = Interval::new(
            (hm - spread).max(self.bounds.lo),
            (hm + spread).min(self.bounds.hi),
        );
        let top = (Interval::new(b.min.z, b.max.z) - h).scale(self.scale);
        let shifted = Aabb::new(b.min - self.center, b.max - self.center);
        top.max(self.cuboid.interval(&shifted))
    }
    fn bbox(&self) -> Aabb {
        Aabb::new(self.min.extend(self.base), self.max.extend(self.bounds.hi))
    }
    fn sublevel_boxes_hold(&self) -> bool {
        // A slope-divided distance bound: see `Shape::sublevel_boxes_hold`.
        false
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked by the constructors; the fields are private.
        Ok(())
    }
}

#[cfg(test)]
mod tests;
