//! Random CSG trees for the `random` suite: Booleans (union of 2 or 3, difference, intersection)
//! over primitives (sphere, box, cylinder, cone, torus) each rotated about a random axis and
//! translated within `[-0.45, 0.45]³`, to a depth of at most [`MAX_DEPTH`] operations. All
//! numbers come from one [`SplitMix64`] stream, so a seed always gives the same tree. The
//! recursion is bounded by [`MAX_DEPTH`], not by any input.

use glam::DVec3;
use solidkit_kernel::Solid;
use solidkit_kernel::models::SplitMix64;

/// Most nested Boolean operations.
pub const MAX_DEPTH: u32 = 3;

/// A random tree with at least one and at most [`MAX_DEPTH`] levels of operations.
pub(crate) fn random_tree(rng: &mut SplitMix64) -> Solid {
    let depth = 1 + (rng.next_u64() % u64::from(MAX_DEPTH)) as u32;
    node(rng, depth)
}

fn node(rng: &mut SplitMix64, depth: u32) -> Solid {
    if depth == 0 {
        return leaf(rng);
    }
    let child = |rng: &mut SplitMix64| {
        // Subtrees are a little shallower on average.
        let d = if rng.next_f64() < 0.3 { 0 } else { depth - 1 };
        node(rng, d)
    };
    let op = rng.next_f64();
    if op < 0.45 {
        let n = if rng.next_f64() < 0.3 { 3 } else { 2 };
        Solid::union_all((0..n).map(|_| child(rng)).collect::<Vec<_>>())
    } else if op < 0.8 {
        let base = child(rng);
        let cutter = child(rng);
        base.difference(&cutter)
    } else {
        let a = child(rng);
        let b = child(rng);
        a.intersection(&b)
    }
}

fn leaf(rng: &mut SplitMix64) -> Solid {
    let kind = rng.next_u64() % 5;
    let shape = match kind {
        0 => Solid::sphere(rng.range(0.25, 0.55)),
        1 => Solid::cuboid(DVec3::new(
            rng.range(0.3, 0.9),
            rng.range(0.3, 0.9),
            rng.range(0.3, 0.9),
        )),
        2 => Solid::cylinder(rng.range(0.15, 0.4), rng.range(0.4, 1.0)),
        3 => Solid::cone(
            rng.range(0.2, 0.45),
            rng.range(0.05, 0.25),
            rng.range(0.4, 0.9),
        ),
        _ => Solid::torus(rng.range(0.25, 0.45), rng.range(0.08, 0.15)),
    };
    let axis = DVec3::new(
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
    )
    .try_normalize()
    .unwrap_or(DVec3::Z);
    let degrees = rng.range(0.0, 360.0);
    let offset = DVec3::new(
        rng.range(-0.45, 0.45),
        rng.range(-0.45, 0.45),
        rng.range(-0.45, 0.45),
    );
    shape.rotate(axis, degrees).translate(offset)
}
