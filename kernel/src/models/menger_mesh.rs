//! The level-`L` Menger sponge as an exact polyhedral mesh: the boundary of the union of its
//! `20^L` kept cubes on the `3^L` grid over `[-0.5, 0.5]³` (the same solid as [`menger`](super::menger),
//! which is a CSG tree), built by [`VoxelGrid::boundary`].
//!
//! Exact ground truth of the mesh (closed forms, checked against the mesh in the tests):
//! - boundary squares `S = 2·20^L + 4·8^L` ([`menger_square_count`]), each `3^−L` on a side, so
//!   the area is `2 (20/9)^L + 4 (8/9)^L` ([`menger_area`]);
//! - `2S` triangles, `3S` edges, `V = χ + S` vertices with `χ = 2 − 2g` and the genus `g` of
//!   [`menger_genus`] ([`menger_mesh_counts`]);
//! - volume `(20/27)^L`, one shell.
//!
//! The surface is a 2-manifold: two kept cubes never meet only along an edge (if cubes `(x, y)`
//! and `(x+1, y+1)` are kept and `(x+1, y)`, `(x, y+1)` removed, the removals force digit `k` of
//! `x+1` and of `y` to be 1 and digit `j` of `x` and of `y+1` to be 1; a carry from `x` to `x+1`
//! at digit `k` makes every finer digit of `x` a 2, so `j ≤ k`, and symmetrically `k ≤ j`, but then
//! digit `k` of `y` is both 1 and not 1), nor only at a corner (checked by the tests: no
//! non-manifold vertex up to level 4).

use super::menger::menger_genus;
use crate::IndexedMesh;
use crate::polyhedra::{VoxelError, VoxelGrid};
use glam::DVec3;

/// True when the cube at grid position `(x, y, z)` of the `3^level` grid is kept: at no level do
/// two of its coordinates have the middle ternary digit.
pub fn menger_keeps(level: u32, x: usize, y: usize, z: usize) -> bool {
    let (mut x, mut y, mut z) = (x, y, z);
    for _ in 0..level {
        let middles = [x % 3, y % 3, z % 3].iter().filter(|&&d| d == 1).count();
        if middles >= 2 {
            return false;
        }
        (x, y, z) = (x / 3, y / 3, z / 3);
    }
    true
}

/// The voxels of the level-`level` sponge over `[-0.5, 0.5]³`.
pub fn menger_voxels(level: u32) -> Result<VoxelGrid, VoxelError> {
    let n = 3usize.checked_pow(level).ok_or(VoxelError::Size {
        dims: [usize::MAX; 3],
    })?;
    VoxelGrid::new([n; 3], DVec3::splat(-0.5), 1.0 / n as f64, |x, y, z| {
        menger_keeps(level, x, y, z)
    })
}

/// The level-`level` sponge's boundary mesh (see the module docs); level 5 needs about 2 GB.
pub fn menger_mesh(level: u32) -> Result<IndexedMesh, VoxelError> {
    Ok(menger_voxels(level)?.boundary())
}

/// Boundary squares of the level-`level` sponge: `2·20^L + 4·8^L`.
pub fn menger_square_count(level: u32) -> u64 {
    2 * 20u64.pow(level) + 4 * 8u64.pow(level)
}

/// Exact surface area of the level-`level` sponge of side 1: `2 (20/9)^L + 4 (8/9)^L`.
pub fn menger_area(level: u32) -> f64 {
    let l = level as i32;
    2.0 * (20.0f64 / 9.0).powi(l) + 4.0 * (8.0f64 / 9.0).powi(l)
}

/// `(V, E, F)` of [`menger_mesh`]: `(2 − 2g + S, 3S, 2S)`.
pub fn menger_mesh_counts(level: u32) -> (u64, u64, u64) {
    let s = menger_square_count(level);
    let chi = 2 - 2 * menger_genus(level);
    ((chi + s as i64) as u64, 3 * s, 2 * s)
}
