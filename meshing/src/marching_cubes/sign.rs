//! The sign of a sample: the one rule every sampler (dense, sparse bricks, dual contouring's
//! extra samples) applies, so the sparse and dense paths and marching cubes and dual contouring
//! see the same inside/outside pattern.
//!
//! 1. Single-precision noise is removed ([`snap_noise`]): a value within [`NOISE`] of the
//!    coordinate scale is exactly zero.
//! 2. An exact zero where operands meet is settled by symbolic perturbation ([`settle`], the
//!    field's [`Field::zero_side`]): the sample takes the sign of the field an infinitesimal
//!    step along a fixed generic direction, unless the contact is a pinch. A face shared inside
//!    a union, a stack of boxes touching face to face, or a cutter flush with a face then
//!    leaves no wall and no skin: the samples on the shared face are inside the union (one of
//!    the two fields decreases along the step), and the samples on a flush cutter's face are
//!    outside the difference (one of the two fields increases).
//! 3. An exact zero on a surface no other operand touches (a box face lying on a sample plane)
//!    is inside exactly when one of its six lattice neighbours is strictly inside and it does not
//!    close a pinch edge with a lower neighbour ([`lone_inside`], applied after a box is sampled
//!    by [`resolve_lone`]). Faces on sample
//!    planes then keep their samples, and their edges are not bevelled by a cell (counting
//!    every such zero outside loses 0.59 cell of area per unit of edge length: 3% of two unit
//!    boxes at 60 cells), while a zero that would be an island (the vertex sample of a sharp
//!    tip, a plate thinner than a cell) stays outside, as marching cubes always had it: an
//!    inside zero always has an inside neighbour along a cell edge, so it joins its solid.
//!
//! A zero settled inside is stored as [`INSIDE_ZERO`], the negative number closest to zero in
//! normal precision (a zero settled outside as [`OUTSIDE_ZERO`], its mirror), so everything
//! downstream (inside test, asymptotic decider, vertex interpolation) reads the sign from the
//! value alone and a vertex on an edge from it sits at the sample (kept
//! [`super::EDGE_MARGIN`] away, as for any vertex).
//!
//! Why this keeps every guarantee: the settled sign is a function of the sample point, its
//! lattice neighbours and the field only (not of the cell, the brick or the thread), so
//! neighbouring cells agree on every shared sample and the marching-cubes surface stays closed,
//! 2-manifold and oriented; a pruned program settles a zero exactly as the full program does
//! (see [`solidkit_kernel::program::perturb`]) and a neighbour outside a brick is evaluated
//! with the full program, so the sparse path reproduces the dense one bit for bit; the band is
//! far below the interval classifier's margin, so a box the octree culls as inside or outside
//! holds no zero to settle.

use glam::DVec3;
use solidkit_kernel::Field;
use solidkit_kernel::program::perturb::ZeroSide;
use std::collections::HashMap;

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

/// The value of a zero on a lone surface until [`resolve_lone`] settles it: an exact 0, which
/// no settled value is.
pub const LONE_ZERO: f32 = 0.0;

/// The settled value of the sample at `(x, y, z)` whose single-precision value is `v`: noise
/// snapped, then a zero replaced by [`INSIDE_ZERO`] or [`OUTSIDE_ZERO`] as `zero_side` (the
/// field's symbolic test at that point) says, or left [`LONE_ZERO`] for [`resolve_lone`] on a
/// lone surface. `zero_side` is called only for zeros.
#[inline]
pub fn settle(x: f32, y: f32, z: f32, v: f32, zero_side: impl FnOnce(DVec3) -> ZeroSide) -> f32 {
    let v = snap_noise(x, y, z, v);
    if v != 0.0 {
        return v;
    }
    match zero_side(DVec3::new(x as f64, y as f64, z as f64)) {
        ZeroSide::Inside => INSIDE_ZERO,
        ZeroSide::Outside => OUTSIDE_ZERO,
        ZeroSide::Surface => LONE_ZERO,
    }
}

/// [`settle`] with a field's own [`Field::zero_side`].
#[inline]
pub fn settle_field(field: &impl Field, x: f32, y: f32, z: f32, v: f32) -> f32 {
    settle(x, y, z, v, |p| field.zero_side(p))
}

/// Whether the lone zero at grid sample `s` is inside: one of its six lattice neighbours in a
/// grid of `samples` points per axis has a value (noise snapped) below zero and not itself a
/// zero, and it is not the upper end of a *pinch edge*. `near` gives a grid sample's value
/// (settled or not) where it is at hand, `far` evaluates one that is not; `far` is asked only
/// where the samples at hand leave the answer open.
///
/// A pinch edge joins two zero samples whose strictly inside neighbours lie on opposite sides
/// across some other axis and on no common side: the edge lies in the surface of two solids that
/// touch only along a line crossing it (boxes sharing an edge that lies on a sample plane). Both
/// ends inside would join the two solids along the edge; its upper end (along the edge's axis)
/// goes outside instead, so the solids stay apart as exact Boolean kernels keep them (a bevel of
/// one sample row at the contact). The rule reads the samples within two lattice steps only.
pub fn lone_inside(
    s: [usize; 3],
    samples: [usize; 3],
    mut near: impl FnMut([usize; 3]) -> Option<f32>,
    mut far: impl FnMut([usize; 3]) -> f32,
) -> bool {
    let mut own = Sides::default();
    own.read(s, samples, &mut near, None::<&mut fn([usize; 3]) -> f32>);
    if own.inside == 0 {
        own.read(s, samples, &mut near, Some(&mut far));
        if own.inside == 0 {
            return false;
        }
    }
    // The lower neighbours along each axis: a zero there with opposite inside sides.
    !(0..3).any(|b| {
        if s[b] == 0 {
            return false;
        }
        let mut t = s;
        t[b] -= 1;
        if near(t).unwrap_or_else(|| far(t)).abs() > f32::MIN_POSITIVE {
            // Not a zero (NaN included).
            return false;
        }
        let mut other = Sides::default();
        other.read(t, samples, &mut near, None::<&mut fn([usize; 3]) -> f32>);
        if own.inside & other.inside != 0 {
            return false;
        }
        own.read(s, samples, &mut near, Some(&mut far));
        other.read(t, samples, &mut near, Some(&mut far));
        let (own, other) = (own.inside, other.inside);
        own & other == 0
            && (0..3).filter(|&a| a != b).any(|a| {
                let (lo, hi) = (1u8 << (2 * a), 2u8 << (2 * a));
                (own & lo != 0 && other & hi != 0) || (own & hi != 0 && other & lo != 0)
            })
    })
}

/// The sides of a grid sample (bit `2·axis` below, `2·axis + 1` above) whose lattice neighbour
/// is strictly inside (a value below zero and not itself a zero), read lazily.
#[derive(Clone, Copy, Default)]
struct Sides {
    /// The sides read so far (or off the grid).
    known: u8,
    /// The sides known to be strictly inside.
    inside: u8,
}

impl Sides {
    /// Reads the unknown sides of sample `s`: those `near` has, and with `far` all the rest.
    fn read<F: FnMut([usize; 3]) -> f32>(
        &mut self,
        s: [usize; 3],
        samples: [usize; 3],
        near: &mut impl FnMut([usize; 3]) -> Option<f32>,
        mut far: Option<&mut F>,
    ) {
        for a in 0..3 {
            for (bit, t) in [(0, s[a].wrapping_sub(1)), (1, s[a] + 1)] {
                let m = 1u8 << (2 * a + bit);
                if self.known & m != 0 {
                    continue;
                }
                if t >= samples[a] {
                    self.known |= m;
                    continue;
                }
                let mut q = s;
                q[a] = t;
                let v = match (near(q), far.as_deref_mut()) {
                    (Some(v), _) => v,
                    (None, Some(far)) => far(q),
                    (None, None) => continue,
                };
                self.known |= m;
                if v < INSIDE_ZERO {
                    self.inside |= m;
                }
            }
        }
    }
}

/// Settles the [`LONE_ZERO`]s of a box of samples: `values` holds the `n` points per axis from
/// grid sample `origin` (x fastest) in a grid of `samples` points per axis, `lone` the indices
/// of its lone zeros, and `outer` gives the snapped value of a grid sample outside the box.
pub fn resolve_lone(
    values: &mut [f32],
    n: [usize; 3],
    origin: [usize; 3],
    samples: [usize; 3],
    lone: &[usize],
    mut outer: impl FnMut([usize; 3]) -> f32,
) {
    let mut evaluated: HashMap<[usize; 3], f32> = HashMap::new();
    for &i in lone {
        let local = [i % n[0], i / n[0] % n[1], i / (n[0] * n[1])];
        let s = [0, 1, 2].map(|a| origin[a] + local[a]);
        let in_box = |q: [usize; 3]| {
            let l = [0, 1, 2].map(|a| q[a].wrapping_sub(origin[a]));
            (0..3)
                .all(|a| l[a] < n[a])
                .then(|| l[0] + n[0] * (l[1] + n[1] * l[2]))
        };
        // A sample outside the box costs an evaluation, once per box (settled zeros of the box
        // read as the zeros they are: the rule tells zeros by magnitude, and inside by
        // `< INSIDE_ZERO`).
        let inside = lone_inside(
            s,
            samples,
            |q| in_box(q).map(|l| values[l]),
            |q| *evaluated.entry(q).or_insert_with(|| outer(q)),
        );
        values[i] = if inside { INSIDE_ZERO } else { OUTSIDE_ZERO };
    }
}
