//! OpenSCAD's faceting of round primitives (as in its `primitives.cc`, 2021.01): the fragment
//! rule, circles as regular n-gons, spheres as stacked rings, cylinders and cones as two n-gons.

use glam::{DVec2, DVec3};

/// OpenSCAD's `GRID_FINE`: radii below it get 3 fragments.
pub(super) const GRID_FINE: f64 = 0.000_000_953_674_316_406_25;

/// OpenSCAD's resolution settings `$fn`, `$fa`, `$fs`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// `$fn`: a fixed number of fragments when positive.
    pub fn_: f64,
    /// `$fa`: the largest angle of a fragment, degrees.
    pub fa: f64,
    /// `$fs`: the largest length of a fragment.
    pub fs: f64,
}

/// The most fragments a round primitive gets: a bound on memory for hostile input (a sphere of
/// `n` fragments has about `n²/2` vertices). `$fn` above it is an error (see
/// `Stmt::resolution`); a `$fa`/`$fs` rule asking for more is clamped.
pub const MAX_FRAGMENTS: usize = 1024;

/// The number of fragments OpenSCAD uses for a circle of radius `r` (its `get_fragments_from_r`,
/// with `$fa` and `$fs` raised to its minimum 0.01 and a `NaN` or infinite `$fn` read as 3),
/// at most [`MAX_FRAGMENTS`].
pub fn fragments(r: f64, res: Resolution) -> usize {
    let n = if r.is_nan() || r < GRID_FINE || !res.fn_.is_finite() {
        3.0
    } else if res.fn_ > 0.0 {
        res.fn_.max(3.0).floor()
    } else {
        (360.0 / res.fa.max(0.01))
            .min(r * 2.0 * std::f64::consts::PI / res.fs.max(0.01))
            .max(5.0)
            .ceil()
    };
    n.min(MAX_FRAGMENTS as f64) as usize
}

/// `sin` of degrees, exact at multiples of 90° like OpenSCAD's `sin_degrees`.
pub(super) fn sin_degrees(x: f64) -> f64 {
    let x = x.rem_euclid(360.0);
    if x.rem_euclid(90.0) == 0.0 {
        [0.0, 1.0, 0.0, -1.0][(x / 90.0) as usize % 4]
    } else {
        x.to_radians().sin()
    }
}

/// `cos` of degrees, exact at multiples of 90°.
pub(super) fn cos_degrees(x: f64) -> f64 {
    sin_degrees(x + 90.0)
}

/// The `n` corners of OpenSCAD's circle of radius `r`: angles `360·i/n`, counter-clockwise.
pub fn circle(r: f64, n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|i| {
            let phi = 360.0 * i as f64 / n as f64;
            DVec2::new(r * cos_degrees(phi), r * sin_degrees(phi))
        })
        .collect()
}

/// OpenSCAD's sphere: `n` fragments around, `(n + 1) / 2` rings at polar angles
/// `180·(i + ½)/rings`, the first at the top; faces counter-clockwise seen from outside.
pub fn sphere(r: f64, res: Resolution) -> (Vec<DVec3>, Vec<Vec<u32>>) {
    let n = fragments(r, res);
    let rings = n.div_ceil(2).max(1);
    let mut vertices = Vec::with_capacity(n * rings);
    for i in 0..rings {
        let phi = 180.0 * (i as f64 + 0.5) / rings as f64;
        let (ring_r, z) = (r * sin_degrees(phi), r * cos_degrees(phi));
        vertices.extend(circle(ring_r, n).into_iter().map(|p| p.extend(z)));
    }
    let at = |ring: usize, k: usize| (ring * n + k % n) as u32;
    // Top cap, seen from above: counter-clockwise.
    let mut faces = vec![(0..n).map(|k| at(0, k)).collect::<Vec<_>>()];
    for i in 0..rings - 1 {
        for k in 0..n {
            faces.push(vec![at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1)]);
        }
    }
    faces.push((0..n).rev().map(|k| at(rings - 1, k)).collect());
    (vertices, faces)
}

/// OpenSCAD's cylinder or cone from radius `r1` at `z1` to `r2` at `z2` (`z1 < z2`), with the
/// fragments of the larger radius; a zero radius becomes one apex vertex.
pub fn cylinder(
    r1: f64,
    r2: f64,
    z1: f64,
    z2: f64,
    res: Resolution,
) -> (Vec<DVec3>, Vec<Vec<u32>>) {
    let n = fragments(r1.max(r2), res);
    let mut vertices = Vec::new();
    let mut ring = |r: f64, z: f64| -> Vec<u32> {
        let start = vertices.len() as u32;
        if r > 0.0 {
            vertices.extend(circle(r, n).into_iter().map(|p| p.extend(z)));
            (0..n as u32).map(|k| start + k).collect()
        } else {
            vertices.push(DVec3::new(0.0, 0.0, z));
            vec![start; n]
        }
    };
    let bottom = ring(r1, z1);
    let top = ring(r2, z2);
    let mut faces = Vec::new();
    for k in 0..n {
        let j = (k + 1) % n;
        let mut quad = vec![bottom[k], bottom[j], top[j], top[k]];
        quad.dedup();
        if quad.first() == quad.last() {
            quad.pop();
        }
        faces.push(quad);
    }
    if r1 > 0.0 {
        faces.push(bottom.iter().rev().copied().collect());
    }
    if r2 > 0.0 {
        faces.push(top);
    }
    (vertices, faces)
}
