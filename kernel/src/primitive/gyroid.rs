//! The gyroid sheet: `f(p) = |g(p)| − t` with `g = sin x cos y + sin y cos z + sin z cos x`, the
//! triply periodic minimal-surface approximation thickened to a sheet of half-width `t` (in units
//! of `g`). Scale it (e.g. `scale 1/30`) to set the period and intersect it with a bounded solid.
//!
//! Not a distance: each partial derivative of `g` is a dot product of two vectors of length at
//! most 1 and √2 (e.g. `∂g/∂x = (cos x, −sin x)·(cos y, sin z)`), so `|∇f| ≤ √6`, the Lipschitz
//! bound reported. Intervals use exact ranges of sin and cos over intervals. The single-precision
//! batch path uses branch-free polynomial sine (vectorised by the compiler), accurate to 1e-6 plus
//! the single-precision rounding of the argument; the double-precision paths use [`sincos_f64`]
//! (a few ulps from the C library's values, without its rounding-mode switches).

use super::sincos::sincos_f64;
use super::{PrimitiveError, Shape, positive};
use crate::{Aabb, Interval};
use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, TAU};

/// A gyroid sheet of half-thickness `thickness` (in units of the gyroid function).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gyroid {
    /// Half-width of the sheet, `|g| ≤ thickness` inside.
    pub thickness: f64,
}

/// Sines and cosines of the three coordinates ([`sincos_f64`]): every double-precision path
/// (value, gradient, both at once) takes them from here, so they agree bit for bit.
#[inline]
fn sin_cos(p: DVec3) -> [(f64, f64); 3] {
    [sincos_f64(p.x), sincos_f64(p.y), sincos_f64(p.z)]
}

/// `g` from the coordinates' sines and cosines.
#[inline]
fn g_of([(sx, cx), (sy, cy), (sz, cz)]: [(f64, f64); 3]) -> f64 {
    sx * cy + sy * cz + sz * cx
}

/// `∇f` from the coordinates' sines and cosines (the sign of `g` picks the sheet's side).
#[inline]
fn gradient_of(sc: [(f64, f64); 3]) -> DVec3 {
    let [(sx, cx), (sy, cy), (sz, cz)] = sc;
    let d = DVec3::new(cx * cy - sz * sx, -sx * sy + cy * cz, -sy * sz + cz * cx);
    if g_of(sc) >= 0.0 { d } else { -d }
}

/// Exact range of `sin` over an interval.
pub fn sin_interval(x: Interval) -> Interval {
    if x.width() >= TAU || !x.lo.is_finite() || !x.hi.is_finite() {
        return Interval::new(-1.0, 1.0);
    }
    let (a, b) = (x.lo.sin(), x.hi.sin());
    let (mut lo, mut hi) = (a.min(b), a.max(b));
    // Maxima at π/2 + 2kπ, minima at −π/2 + 2kπ inside the interval.
    let first = |phase: f64| ((x.lo - phase) / TAU).ceil() * TAU + phase;
    if first(FRAC_PI_2) <= x.hi {
        hi = 1.0;
    }
    if first(-FRAC_PI_2) <= x.hi {
        lo = -1.0;
    }
    Interval::new(lo, hi)
}

/// Exact range of `cos` over an interval.
pub fn cos_interval(x: Interval) -> Interval {
    sin_interval(Interval::new(x.lo + FRAC_PI_2, x.hi + FRAC_PI_2))
}

/// Branch-free single-precision sine and cosine of one argument, sharing one range reduction
/// (by π/2, Cody–Waite in three parts) and selecting the quadrant with bit operations, so loops
/// over it vectorise. Accurate to 1e-6 plus the rounding of the argument, for |x| below 10⁵.
/// Beyond, the reduction loses accuracy (from about 10⁹ its remainder is no longer small), so the
/// remainder is clamped to ±0.8 (beyond π/4, so ordinary arguments are untouched) and both results
/// always lie in [−1, 1]: inside the exact ranges the intervals assume, which culling and pruning
/// need. (Single-precision arguments that large are more than 2π apart: the values are noise.)
#[inline(always)]
pub fn sincos_f32(x: f32) -> (f32, f32) {
    const TWO_OVER_PI: f32 = 2.0 / std::f32::consts::PI;
    const MAGIC: f32 = 12_582_912.0; // 1.5 · 2²³: adding it rounds to an integer in the low bits
    const A: f32 = 3.140_625 * 0.5;
    const B: f32 = 9.676_536e-4 * 0.5;
    const C: f32 = 5.126_688e-12 * 0.5;
    let j = x * TWO_OVER_PI + MAGIC;
    let k = j - MAGIC;
    let q = j.to_bits();
    // Written as comparisons, each one `minps`/`maxps`, that also map a NaN remainder (∞ − ∞
    // near f32::MAX) to a finite one; `f32::min`/`max` and `clamp` cost several instructions
    // per lane on this hot path (and `clamp` keeps a NaN).
    let r = ((x - k * A) - k * B) - k * C;
    let r = if r < 0.8 { r } else { 0.8 };
    let r = if r > -0.8 { r } else { -0.8 };
    let r2 = r * r;
    let sp = 2.755_731_9e-6f32;
    let sp = sp * r2 - 1.984_127e-4;
    let sp = sp * r2 + 8.333_333e-3;
    let sp = sp * r2 - 1.666_666_7e-1;
    let s = r + r * r2 * sp;
    let cp = 2.480_158_7e-5f32;
    let cp = cp * r2 - 1.388_888_9e-3;
    let cp = cp * r2 + 4.166_666_8e-2;
    let cp = cp * r2 - 0.5;
    let c = 1.0 + r2 * cp;
    // Quadrant q: sin x = (s, c, −s, −c)[q], cos x = (c, −s, −c, s)[q].
    let swap = 0u32.wrapping_sub(q & 1);
    let (sb, cb) = (s.to_bits(), c.to_bits());
    let sin = (sb & !swap) | (cb & swap);
    let cos = (cb & !swap) | (sb & swap);
    let sin_sign = (q & 2) << 30;
    let cos_sign = (q.wrapping_add(1) & 2) << 30;
    (
        f32::from_bits(sin ^ sin_sign),
        f32::from_bits(cos ^ cos_sign),
    )
}

/// Single-precision sine (see [`sincos_f32`]).
#[inline(always)]
pub fn sin_f32(x: f32) -> f32 {
    sincos_f32(x).0
}

/// Single-precision cosine (see [`sincos_f32`]).
#[inline(always)]
pub fn cos_f32(x: f32) -> f32 {
    sincos_f32(x).1
}

crate::simd::wide_loop! {
    fn gyroid_f32(t: f32, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let n = out.len();
        let (x, y, z) = (&x[..n], &y[..n], &z[..n]);
        for i in 0..n {
            let (sx, cx) = sincos_f32(x[i]);
            let (sy, cy) = sincos_f32(y[i]);
            let (sz, cz) = sincos_f32(z[i]);
            out[i] = (sx * cy + sy * cz + sz * cx).abs() - t;
        }
    }
}

impl Shape for Gyroid {
    fn value(&self, p: DVec3) -> f64 {
        g_of(sin_cos(p)).abs() - self.thickness
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        gradient_of(sin_cos(p))
    }
    fn values_gradients(&self, pts: &[DVec3], values: &mut [f64], gradients: &mut [DVec3]) {
        // One sine and cosine per coordinate for both (the default evaluates them five times).
        for ((p, v), d) in pts.iter().zip(values.iter_mut()).zip(gradients.iter_mut()) {
            let sc = sin_cos(*p);
            *v = g_of(sc).abs() - self.thickness;
            *d = gradient_of(sc);
        }
    }
    fn interval(&self, b: &Aabb) -> Interval {
        let axis = |i: usize| Interval::new(b.min[i], b.max[i]);
        let (x, y, z) = (axis(0), axis(1), axis(2));
        let gi = sin_interval(x) * cos_interval(y)
            + sin_interval(y) * cos_interval(z)
            + sin_interval(z) * cos_interval(x);
        let lip = Interval::around(
            self.value(b.center()),
            self.lipschitz() * b.half_extents().length(),
        );
        let natural = gi.abs() - Interval::point(self.thickness);
        // Both are valid; their intersection is tighter than either.
        Interval::new(
            natural.lo.max(lip.lo),
            natural.hi.min(lip.hi).max(natural.lo.max(lip.lo)),
        )
    }
    fn bbox(&self) -> Aabb {
        Aabb::infinite()
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        positive("thickness", self.thickness)
    }
    fn lipschitz(&self) -> f64 {
        6f64.sqrt()
    }
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        gyroid_f32(self.thickness as f32, x, y, z, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitive::conformance::{Rng, check_shape};

    #[test]
    fn gyroid_conforms() {
        check_shape(&Gyroid { thickness: 0.2 }, 6.0);
    }

    #[test]
    fn fast_sine_is_accurate() {
        // Within 1e-6 plus the rounding of the argument itself (half an ulp of x, and of x + π/2).
        for i in -200_000..200_000 {
            let x = i as f32 * 1e-3;
            let tol = 1e-6 + 1.2e-7 * (x.abs() as f64 + 2.0);
            assert!(
                (sin_f32(x) as f64 - (x as f64).sin()).abs() < tol,
                "sin {x}"
            );
            assert!(
                (cos_f32(x) as f64 - (x as f64).cos()).abs() < tol,
                "cos {x}"
            );
        }
    }

    #[test]
    fn fast_sine_stays_in_range_for_huge_arguments() {
        // Issue 15: at 1e12 the unclamped remainder gave 1e38 and ∞, outside the intervals that
        // culled and pruned the boxes, so neighbouring bricks disagreed on signs (MC panicked).
        let mut x = 1e5f32;
        while x < f32::MAX / 1.1 {
            for v in [x, -x, x * 1.37, -x * 2.9] {
                let (s, c) = sincos_f32(v);
                assert!(
                    (-1.0..=1.0).contains(&s) && (-1.0..=1.0).contains(&c),
                    "{v}: {s} {c}"
                );
            }
            x *= 1.1;
        }
        for v in [f32::MAX, -f32::MAX] {
            let (s, c) = sincos_f32(v);
            assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{v}: {s} {c}");
        }
    }

    #[test]
    fn sine_intervals_are_exact_ranges() {
        let mut rng = Rng::new(4);
        for _ in 0..2000 {
            let a = rng.next() * 10.0;
            let w = (rng.next() + 1.0) * 2.0;
            let iv = sin_interval(Interval::new(a, a + w));
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for k in 0..=2000 {
                let s = (a + w * k as f64 / 2000.0).sin();
                lo = lo.min(s);
                hi = hi.max(s);
            }
            assert!(iv.lo <= lo + 1e-12 && iv.hi >= hi - 1e-12);
            assert!(
                iv.lo >= lo - 1e-5 && iv.hi <= hi + 1e-5,
                "{iv:?} vs [{lo}, {hi}]"
            );
        }
    }
}
