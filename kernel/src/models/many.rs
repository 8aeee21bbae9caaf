//! `many-N`: a large deterministic CSG tree, the union of small spheres on a jittered grid minus
//! as many small boxes, each primitive placed by its own translate.
//!
//! [`many`]`(count, seed)` has `count − count/2` spheres and `count/2` boxes: the tree is
//! `difference(union(translate(sphere) …), translate(box) …)` with `2·count + 2` nodes; as binary
//! operations that is `count − 1` Booleans and `count` transforms. `many-8456` (the default
//! benchmark) has 4228 spheres and 4228 boxes: 8455 Booleans plus 8456 translates, 16 914 nodes.
//!
//! Sphere `i` sits in cell `i` (x fastest) of an `n³` grid (`n = ⌈∛spheres⌉`) of pitch
//! `1.9 / (n + 0.6)`, its centre jittered by up to a quarter cell per axis and its radius drawn
//! from 0.3 to 0.55 cells; box `i` is centred 0.3 cell (per axis) from sphere `i`'s centre, with
//! sides from 0.2 to 0.4 cells, so every box notches its sphere. The grid is placed so that every
//! sphere lies inside `[-0.95, 0.95]³`, so meshes over `[-1, 1]³` are closed. The numbers come
//! from [`SplitMix64`] with `seed`: the same arguments always give the same tree.

use super::SplitMix64;
use crate::Solid;
use glam::DVec3;

/// The seed of the benchmark `many-N` models.
pub const MANY_DEFAULT_SEED: u64 = 8456;

/// Half-width of the box every sphere lies in.
const HALF_WIDTH: f64 = 0.95;

/// `count` primitives: spheres on a jittered grid minus boxes (see the module docs).
pub fn many(count: usize, seed: u64) -> Solid {
    let spheres = count - count / 2;
    let boxes = count / 2;
    let n = (1..).find(|n: &usize| n.pow(3) >= spheres).unwrap_or(1);
    // Spheres reach from 0.3 cell before the grid's start to 0.3 cell past its end.
    let pitch = 2.0 * HALF_WIDTH / (n as f64 + 0.6);
    let start = -HALF_WIDTH + 0.3 * pitch;
    let mut rng = SplitMix64::new(seed);
    let mut sphere_list = Vec::with_capacity(spheres);
    let mut box_list = Vec::with_capacity(boxes);
    for i in 0..spheres {
        let cell = DVec3::new((i % n) as f64, ((i / n) % n) as f64, (i / (n * n)) as f64);
        let jitter = DVec3::new(
            rng.range(-0.25, 0.25),
            rng.range(-0.25, 0.25),
            rng.range(-0.25, 0.25),
        );
        let centre = DVec3::splat(start) + (cell + DVec3::splat(0.5) + jitter) * pitch;
        let radius = rng.range(0.3, 0.55) * pitch;
        sphere_list.push(Solid::sphere(radius).translate(centre));
        if i < boxes {
            let size = DVec3::new(
                rng.range(0.2, 0.4),
                rng.range(0.2, 0.4),
                rng.range(0.2, 0.4),
            ) * pitch;
            let offset = DVec3::splat(0.3 * pitch);
            box_list.push(Solid::cuboid(size).translate(centre + offset));
        }
    }
    Solid::difference_all(Solid::union_all(sphere_list), box_list)
}
