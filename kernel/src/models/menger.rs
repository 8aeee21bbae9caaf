//! `menger-L`: the level-`L` Menger sponge as an explicit CSG tree.
//!
//! The unit cube `[-0.5, 0.5]³` minus the union of every axis-aligned bar ("tunnel") of levels
//! `1..=L`: at level `k` the cube is split into `3^(k−1)` parent cells per axis, and for each axis
//! and each of the `9^(k−1)` parent cells of the cross-section a bar of square section `3^−k`
//! runs through the middle of the parent cell. A point is removed exactly when, at some level, at
//! least two of its coordinates have the middle ternary digit, which is the Menger sponge.
//!
//! Exact ground truth:
//! - bars: `3 · (1 + 9 + … + 9^(L−1)) = 3 (9^L − 1) / 8` ([`menger_bar_count`]; 2460 at level 4);
//! - volume: `(20/27)^L` ([`menger_volume`]; 0.301068 at level 4);
//! - genus: `(21 · 20^L + 38 · 8^L − 59) / 133` ([`menger_genus`]): 0, 5, 81, 1409, 26433 for
//!   `L = 0..4` (one shell; the closed form solves `g(L) = a·20^L + b·8^L + c` through the first
//!   three values and matches the next two).
//!
//! Each bar is a box of length [`BAR_LENGTH`] (longer than the cube, so its ends lie outside the
//! cube and never show), so the tree has `2 + 2 · bars` nodes: a difference, the cube, and a
//! translate over a box per bar. Mesh it over `[-0.5, 0.5]³` padded by [`MENGER_PAD`] so the
//! cube's faces are inside the grid.

use crate::Solid;
use glam::DVec3;

/// Padding of the meshing domain around the unit cube on every side.
pub const MENGER_PAD: f64 = 1.0 / 32.0;

/// Length of every bar: longer than the cube's side 1, so bars cut clean through.
pub const BAR_LENGTH: f64 = 1.5;

/// Number of bars of a level-`level` sponge: `3 (9^level − 1) / 8`.
pub fn menger_bar_count(level: u32) -> usize {
    3 * (9usize.pow(level) - 1) / 8
}

/// Exact volume of a level-`level` sponge: `(20/27)^level`.
pub fn menger_volume(level: u32) -> f64 {
    (20.0f64 / 27.0).powi(level as i32)
}

/// Exact genus of a level-`level` sponge: `(21 · 20^level + 38 · 8^level − 59) / 133`.
pub fn menger_genus(level: u32) -> i64 {
    (21 * 20i64.pow(level) + 38 * 8i64.pow(level) - 59) / 133
}

/// The level-`level` Menger sponge of side 1 centred at the origin (see the module docs).
pub fn menger(level: u32) -> Solid {
    let mut bars = Vec::with_capacity(menger_bar_count(level));
    for k in 1..=level {
        let parents = 3usize.pow(k - 1);
        let section = 1.0 / 3f64.powi(k as i32);
        let parent = 3.0 * section;
        for axis in 0..3 {
            let mut size = DVec3::splat(section);
            size[axis] = BAR_LENGTH;
            let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
            for p in 0..parents {
                for q in 0..parents {
                    let mut centre = DVec3::ZERO;
                    centre[b] = -0.5 + (p as f64 + 0.5) * parent;
                    centre[c] = -0.5 + (q as f64 + 0.5) * parent;
                    bars.push(Solid::cuboid(size).translate(centre));
                }
            }
        }
    }
    Solid::difference_all(Solid::cube(1.0), bars)
}
