//! Combining a cross-section distance with the distance to end planes: the capped form
//! `min(max(d, e), 0) + |(max(d, 0), max(e, 0))|`, exact for prisms (and 1-Lipschitz whenever the
//! two gradients are orthogonal where both terms are positive), with its gradient.

use glam::DVec3;

/// The capped combination of `(d, ∇d)` and `(e, ∇e)`.
pub(crate) fn capped(d: (f64, DVec3), e: (f64, DVec3)) -> (f64, DVec3) {
    if d.0 > 0.0 && e.0 > 0.0 {
        let l = (d.0 * d.0 + e.0 * e.0).sqrt();
        (l, (d.1 * d.0 + e.1 * e.0) / l)
    } else if d.0 >= e.0 {
        d
    } else {
        e
    }
}

/// The larger of two values with the gradient of the larger.
pub(crate) fn max(a: (f64, DVec3), b: (f64, DVec3)) -> (f64, DVec3) {
    if a.0 >= b.0 { a } else { b }
}

/// The distance beyond the slab `|z| ≤ h/2` (negative inside) and its gradient.
pub(crate) fn slab(z: f64, half_height: f64) -> (f64, DVec3) {
    (
        z.abs() - half_height,
        DVec3::new(0.0, 0.0, if z >= 0.0 { 1.0 } else { -1.0 }),
    )
}
