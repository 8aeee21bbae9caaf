//! The sign of a sample: the one rule every sampler (dense, sparse bricks, dual contouring's
//! extra samples) applies, so the sparse and dense paths and marching cubes and dual contouring
//! see the same inside/outside pattern.
//!
//! 1. Single-precision noise is removed ([`snap_noise`]): a value within [`NOISE`] of the
//!    coordinate scale is exactly zero.
//! 2. An exact zero is settled by symbolic perturbation ([`settle`], the field's
//!    [`Field::inside_at_zero`]): the sample takes the sign of the field an infinitesimal step
//!    along a fixed generic direction. A face shared inside a union, a stack of boxes touching
//!    face to face, or a cutter flush with a face then leaves no wall and no skin: the samples on
//!    the shared face are inside the union (one of the two fields decreases along the step), and
//!    the samples on a flush cutter's face are outside the difference (one of the two fields
//!    increases). A zero settled inside is stored as [`INSIDE_ZERO`], the negative number
//!    closest to zero in normal precision (a zero settled outside as [`OUTSIDE_ZERO`], its mirror), so everything downstream (inside test, asymptotic
//!    decider, vertex interpolation) reads the sign from the value alone and a vertex on an edge
//!    from it sits at the sample (kept [`super::EDGE_MARGIN`] away, as for any vertex).
//!
//! Why this keeps every guarantee: the settled sign is a function of the sample point and the
//! field only (not of the cell, the brick or the thread), so neighbouring cells agree on every
//! shared sample and the marching-cubes surface stays closed, 2-manifold and oriented; a pruned
//! program settles a zero exactly as the full program does (see
//! [`solidkit_kernel::program::perturb`]), so the sparse path reproduces the dense one bit for
//! bit; the band is far below the interval classifier's margin, so a box the octree culls as
//! inside or outside holds no zero to settle.

use glam::DVec3;
use solidkit_kernel::Field;

/// Relative size of the single-precision noise band around zero (see [`snap_noise`]).
pub const NOISE: f32 = 1e-6;

/// The stored value of a zero sample settled inside (negative, so [`inside`] holds; no field
/// value can be this small after [`snap_noise`]).
pub const INSIDE_ZERO: f32 = -f32::MIN_POSITIVE;

/// The stored value of a zero sample settled outside: the smallest positive normal number, the
/// mirror of [`INSIDE_ZERO`], so the asymptotic decider weighs the two alike (a stored 0 would
/// lose every product and join the inside diagonal of a face across an edge contact).
pub const OUTSIDE_ZERO: f32 = f32::MIN_POSITIVE;

/// A sample value with single-precision noise removed: a value within
/// `NOISE · (1 + max |coordinate|)` of zero is exactly zero. Sample positions are rounded to f32
/// (an error of up to half an ulp of the coordinates) and evaluated in f32, so such a value has
/// no reliable sign of its own; [`settle`] gives it the sign of the field beside it. The band is
/// far below the interval classifier's margin (`3e-5` of the same scale), so boxes the octree
/// culls as inside or outside never hold a snapped sample and the sparse and dense paths still
/// agree bit for bit.
#[inline]
pub fn snap_noise(x: f32, y: f32, z: f32, v: f32) -> f32 {
    let scale = 1.0 + x.abs().max(y.abs()).max(z.abs());
    if v.abs() <= NOISE * scale { 0.0 } else { v }
}

/// The inside test for settled samples: a value `< 0` (NaN counts as outside).
#[inline]
pub fn inside(v: f32) -> bool {
    v < 0.0
}

/// The settled value of the sample at `(x, y, z)` whose single-precision value is `v`: noise
/// snapped, then a zero replaced by [`INSIDE_ZERO`] when `zero_inside` (the field's symbolic
/// inside test at that point) says so. `zero_inside` is called only for zeros.
#[inline]
pub fn settle(x: f32, y: f32, z: f32, v: f32, zero_inside: impl FnOnce(DVec3) -> bool) -> f32 {
    let v = snap_noise(x, y, z, v);
    if v != 0.0 {
        v
    } else if zero_inside(DVec3::new(x as f64, y as f64, z as f64)) {
        INSIDE_ZERO
    } else {
        OUTSIDE_ZERO
    }
}

/// [`settle`] with a field's own [`Field::inside_at_zero`].
#[inline]
pub fn settle_field(field: &impl Field, x: f32, y: f32, z: f32, v: f32) -> f32 {
    settle(x, y, z, v, |p| field.inside_at_zero(p))
}
