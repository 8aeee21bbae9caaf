//! de Casteljau's algorithm over any vector type (3D points, or 4D homogeneous points of rational
//! curves): evaluation with the first two derivatives, and subdivision. Evaluation works in a
//! scratch buffer on the stack up to [`INLINE`] control points (degree 15), so the hot paths never
//! allocate; higher degrees fall back to a heap buffer.

use std::ops::{Add, Mul, Sub};

/// Control points kept on the stack during one evaluation.
pub(crate) const INLINE: usize = 16;

/// What de Casteljau's algorithm needs of a control point.
pub(crate) trait Point:
    Copy + Default + Add<Output = Self> + Sub<Output = Self> + Mul<f64, Output = Self>
{
}

impl<T> Point for T where
    T: Copy + Default + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T>
{
}

/// Runs `f` on a scratch slice of `len` default values: on the stack when `len <= INLINE` (a
/// small buffer for the common degrees up to 3).
pub(crate) fn with_scratch<T: Point, R>(len: usize, f: impl FnOnce(&mut [T]) -> R) -> R {
    if len <= 4 {
        let mut buffer = [T::default(); 4];
        f(&mut buffer[..len])
    } else if len <= INLINE {
        let mut buffer = [T::default(); INLINE];
        f(&mut buffer[..len])
    } else {
        let mut buffer = vec![T::default(); len];
        f(&mut buffer)
    }
}

/// The convex combination `(1 − s)·a + s·b`.
#[inline]
pub(crate) fn lerp<T: Point>(a: T, b: T, s: f64) -> T {
    a * (1.0 - s) + b * s
}

/// Point, first and second derivative (with respect to `s`) of the Bézier curve with control
/// points `points` at `s ∈ [0, 1]`. The derivatives come from the last levels of the triangle:
/// `C' = n (b₁ − b₀)` on level `n − 1` and `C'' = n (n − 1) (b₂ − 2b₁ + b₀)` on level `n − 2`.
pub(crate) fn jet<T: Point>(points: &[T], s: f64) -> [T; 3] {
    let n = points.len().saturating_sub(1);
    with_scratch(points.len(), |b: &mut [T]| {
        b.copy_from_slice(points);
        let (mut d1, mut d2) = (T::default(), T::default());
        for remaining in (2..=n + 1).rev() {
            if remaining == 3 {
                d2 = (b[2] - b[1] * 2.0 + b[0]) * (n * (n - 1)) as f64;
            }
            if remaining == 2 {
                d1 = (b[1] - b[0]) * n as f64;
            }
            for i in 0..remaining - 1 {
                b[i] = lerp(b[i], b[i + 1], s);
            }
        }
        [b[0], d1, d2]
    })
}

/// The point at `s` only.
pub(crate) fn point<T: Point>(points: &[T], s: f64) -> T {
    with_scratch(points.len(), |b: &mut [T]| {
        b.copy_from_slice(points);
        for remaining in (2..=b.len()).rev() {
            for i in 0..remaining - 1 {
                b[i] = lerp(b[i], b[i + 1], s);
            }
        }
        b[0]
    })
}

/// Splits the curve at `s`: the control points of the parts over `[0, s]` and `[s, 1]`, each
/// reparametrised to `[0, 1]`.
pub(crate) fn split<T: Point>(points: &[T], s: f64) -> (Vec<T>, Vec<T>) {
    let n = points.len();
    let mut b = points.to_vec();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![T::default(); n];
    for remaining in (1..=n).rev() {
        left.push(b[0]);
        right[remaining - 1] = b[remaining - 1];
        for i in 0..remaining.saturating_sub(1) {
            b[i] = lerp(b[i], b[i + 1], s);
        }
    }
    (left, right)
}

/// The control points of the part over `[a, b] ⊆ [0, 1]`, reparametrised to `[0, 1]`.
pub(crate) fn restrict<T: Point>(points: &[T], a: f64, b: f64) -> Vec<T> {
    let tail = if a > 0.0 {
        split(points, a).1
    } else {
        points.to_vec()
    };
    if b < 1.0 {
        let s = if a < 1.0 { (b - a) / (1.0 - a) } else { 1.0 };
        split(&tail, s).0
    } else {
        tail
    }
}
