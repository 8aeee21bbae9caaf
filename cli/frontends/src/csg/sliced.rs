//! OpenSCAD's twisted (and unevenly scaled) `linear_extrude` as OpenSCAD builds it: a stack of
//! flat slices. OpenSCAD does not sweep the profile continuously: it places the profile at
//! `slices + 1` heights, each copy turned by `-twist · j / slices` and scaled by
//! `1 − (1 − scale) · j / slices`, and joins consecutive copies by two flat triangles per
//! outline edge. Those triangles leave the exact twisted (ruled) wall by up to a few percent of
//! the profile's size, outward or inward by the diagonal chosen; under `--facets openscad`
//! solidkit meshes the same polyhedron, so its volume and shape are OpenSCAD's.
//!
//! The rules, from OpenSCAD 2021.01's extrusion:
//! - `slices` is the given number (truncated, at least 1), else OpenSCAD's count from `$fn`, or
//!   from `$fa` and `$fs` along the longest path a corner travels ([`slice_count`]);
//! - each quad between slice `j` and `j + 1` (corners `a`, `b` counter-clockwise along an
//!   outline, `1` below, `2` above) is split along its shorter diagonal in plan; where both are
//!   equally long (an edge in line with the axis) along `a1 b2` when the twist is positive and
//!   `b1 a2` otherwise on an outline, the other way on a hole. Counted in OpenSCAD 2021.01's own
//!   renders: a twisted square of 8 slices gets its volume to 10⁻⁶, and squares with an edge on
//!   the x axis, twisted either way, get its diagonals;
//! - the caps are the profile's triangulation, the top one turned and scaled.
//!
//! A top scale of zero on both axes ends in one apex, where each quad of the last slice is one
//! triangle and there is no top cap, as in OpenSCAD. Zero on one axis only (a wedge to a
//! segment) is left to the exact sweep, as is a profile the triangulation refuses, a profile of more than [`MAX_SLICED_LEAVES`] 2D leaves
//! (each leaf is its own polyhedron, and many are slow to mesh) and a stack beyond
//! [`MAX_SLICE_CORNERS`] corners (with a warning from the caller).

use super::facets::{GRID_FINE, Resolution};
use glam::{DVec2, DVec3};
use solidkit_kernel::profile::triangulate;

/// The most vertices (slices + 1 times the profile's corners) a sliced extrusion may have; a
/// bound on memory and meshing time for hostile input (`twist = 1e9`).
pub(super) const MAX_SLICE_CORNERS: usize = 2_000_000;

/// The most 2D leaves a sliced extrusion is built for: each becomes its own polyhedron, and a
/// field of many mesh solids is far slower to mesh than the exact sweeps (OpenSCAD's
/// `example020`, three extrusions of 8, 8 and 16 polygons, took over 120 s instead of 21 s);
/// beyond it the exact sweep.
pub(super) const MAX_SLICED_LEAVES: usize = 4;

/// What OpenSCAD's slice count depends on besides the statement's arguments: the largest
/// squared distance of a profile corner from the axis, and the largest squared distance a corner
/// moves under an uneven scale.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Reach {
    /// `max |v|²` over the profile's corners.
    pub r_sqr: f64,
    /// `max |v − scale ∘ v|²` over the profile's corners.
    pub delta_sqr: f64,
}

impl Reach {
    /// The reach of the corners of `loops` under `scale`.
    pub(super) fn of(loops: &[Vec<DVec2>], scale: DVec2) -> Reach {
        let corners = loops.iter().flatten();
        Reach {
            r_sqr: corners
                .clone()
                .map(|v| v.length_squared())
                .fold(0.0, f64::max),
            delta_sqr: corners
                .map(|v| (*v - *v * scale).length_squared())
                .fold(0.0, f64::max),
        }
    }
}

/// OpenSCAD's slice count for an extrusion of `height` turned by `twist` degrees and scaled to
/// `scale`: the statement's `slices` when given (truncated, at least 1), else from `$fn`, or the
/// smaller of the `$fa` count and the `$fs` count along the longest path a corner travels (a
/// helix, a conical helix or a straight diagonal), at least one slice per 120° of twist. A
/// non-finite or huge count comes back as is; the caller bounds it.
pub(super) fn slice_count(
    given: Option<f64>,
    height: f64,
    twist: f64,
    scale: DVec2,
    res: Resolution,
    reach: Reach,
) -> f64 {
    if let Some(n) = given {
        return n.trunc().max(1.0);
    }
    let fs = res.fs.max(0.01);
    let fa = res.fa.max(0.01);
    if twist != 0.0 {
        let turn = twist.abs();
        let least = (turn / 120.0).ceil().max(1.0);
        if reach.r_sqr.sqrt() < GRID_FINE || !res.fn_.is_finite() {
            return least;
        }
        if res.fn_ > 0.0 {
            return (turn / 360.0 * res.fn_).ceil().max(least);
        }
        let by_angle = (turn / fa).ceil();
        let path = if scale.x == scale.y && scale.x != 1.0 {
            conical_helix_length(reach.r_sqr.sqrt(), height, turn, scale.x)
        } else {
            helix_length(reach.r_sqr, height, turn)
        };
        let twisted = by_angle.min((path / fs).ceil()).max(least);
        if scale.x != scale.y {
            return twisted.max(diagonal_slices(reach.delta_sqr, height, res));
        }
        return twisted;
    }
    if scale.x != scale.y {
        return diagonal_slices(reach.delta_sqr, height, res);
    }
    1.0
}

/// The length of the helix of radius `sqrt(r_sqr)` rising `height` over `turn` degrees.
fn helix_length(r_sqr: f64, height: f64, turn: f64) -> f64 {
    let t = turn.to_radians();
    let c = height / t;
    t * (r_sqr + c * c).sqrt()
}

/// The length of the conical helix a corner at radius `r` travels turning `turn` degrees while
/// its radius scales linearly to `scale · r` and it rises `height`: the plan is a piece of an
/// Archimedes spiral, whose length is measured from the spiral's centre.
fn conical_helix_length(r: f64, height: f64, turn: f64, scale: f64) -> f64 {
    let t = turn.to_radians();
    let end = if scale > 1.0 {
        t * scale / (scale - 1.0)
    } else {
        t / (1.0 - scale)
    };
    let a = r / end;
    let spiral = |theta: f64| 0.5 * a * (theta * (1.0 + theta * theta).sqrt() + theta.asinh());
    let plan = spiral(end) - spiral(end - t);
    (plan * plan + height * height).sqrt()
}

/// Slices for an uneven scale: `$fn`, or the longest straight path a corner travels over `$fs`.
fn diagonal_slices(delta_sqr: f64, height: f64, res: Resolution) -> f64 {
    if delta_sqr.sqrt() < GRID_FINE || !res.fn_.is_finite() {
        return 1.0;
    }
    if res.fn_ > 0.0 {
        return res.fn_.floor().max(1.0);
    }
    ((delta_sqr + height * height).sqrt() / res.fs.max(0.01))
        .ceil()
        .max(1.0)
}

/// A closed triangle mesh (vertices; faces counter-clockwise from outside) of the sliced
/// extrusion of the even-odd region of `loops` from `z = -height / 2` to `height / 2`, turned by
/// `-twist` degrees and scaled to `scale` at the top over `slices` slices (to one apex where
/// `scale` is zero); `None` where just one top scale is zero (a wedge, left to the exact sweep)
/// or the profile cannot be triangulated.
pub(super) fn sliced_extrusion(
    loops: &[Vec<DVec2>],
    height: f64,
    twist: f64,
    scale: DVec2,
    slices: usize,
) -> Option<(Vec<DVec3>, Vec<Vec<u32>>)> {
    // A cone to an apex (OpenSCAD's scale = 0): the last slice is one point, each quad of the
    // last slice one triangle, and there is no top cap.
    let apex = scale == DVec2::ZERO;
    if !(apex || scale.x > 0.0 && scale.y > 0.0) || slices == 0 {
        return None;
    }
    let loops = oriented(loops);
    let cap = triangulate(&loops.iter().map(|(l, _)| l.clone()).collect::<Vec<_>>()).ok()?;
    let corners: usize = loops.iter().map(|(l, _)| l.len()).sum();
    let count = corners.checked_mul(slices + usize::from(!apex))? + usize::from(apex);
    if count > MAX_SLICE_CORNERS || count > u32::MAX as usize {
        return None;
    }
    // Positions as OpenSCAD computes them (turned by -twist j / slices degrees, then scaled), so
    // that its diagonal choice below sees the same rounding.
    let mut vertices = Vec::with_capacity(count);
    for j in 0..=slices - usize::from(apex) {
        let rot = twist * j as f64 / slices as f64;
        let (sin, cos) = (-rot * std::f64::consts::PI / 180.0).sin_cos();
        let s = DVec2::new(
            1.0 - (1.0 - scale.x) * j as f64 / slices as f64,
            1.0 - (1.0 - scale.y) * j as f64 / slices as f64,
        );
        let z = -height / 2.0 + height * j as f64 / slices as f64;
        for (l, _) in &loops {
            for p in l {
                let r = DVec2::new(cos * p.x - sin * p.y, sin * p.x + cos * p.y);
                vertices.push((r * s).extend(z));
            }
        }
    }
    if apex {
        vertices.push(DVec3::new(0.0, 0.0, height / 2.0));
    }
    let at = |j: usize, c: usize| {
        if apex && j == slices {
            (j * corners) as u32
        } else {
            (j * corners + c) as u32
        }
    };
    let mut faces: Vec<Vec<u32>> = Vec::with_capacity(2 * cap.len() + 2 * count);
    for t in &cap {
        faces.push(vec![
            at(0, t[0] as usize),
            at(0, t[2] as usize),
            at(0, t[1] as usize),
        ]);
        if !apex {
            faces.push(t.iter().map(|&c| at(slices, c as usize)).collect());
        }
    }
    let flat = |v: u32| vertices[v as usize].truncate();
    let split_first = (-twist / slices as f64).to_radians().sin() > 0.0;
    let mut start = 0;
    for (l, positive) in &loops {
        let n = l.len();
        for j in 0..slices {
            for i in 0..n {
                let (a, b) = (start + i, start + (i + 1) % n);
                let (a1, b1, a2, b2) = (at(j, a), at(j, b), at(j + 1, a), at(j + 1, b));
                if a2 == b2 {
                    faces.push(vec![a1, b1, a2]);
                    continue;
                }
                // The shorter diagonal in plan; a tie (an edge in line with the axis) is split
                // by the twist's sense (see the module docs).
                let (d1, d2) = (
                    flat(b1).distance_squared(flat(a2)),
                    flat(b2).distance_squared(flat(a1)),
                );
                let tie = (d1 - d2).abs() <= 1e-9 * (d1 + d2);
                if (!tie && d1 > d2) || (tie && split_first ^ positive) {
                    faces.push(vec![a1, b1, b2]);
                    faces.push(vec![a1, b2, a2]);
                } else {
                    faces.push(vec![a1, b1, a2]);
                    faces.push(vec![b1, b2, a2]);
                }
            }
        }
        start += n;
    }
    Some((vertices, faces))
}

/// The loops with their role (`true` for an outline, `false` for a hole, by the parity of the
/// loops around each), outlines counter-clockwise and holes clockwise.
pub(super) fn oriented(loops: &[Vec<DVec2>]) -> Vec<(Vec<DVec2>, bool)> {
    loops
        .iter()
        .enumerate()
        .map(|(k, l)| {
            let depth = loops
                .iter()
                .enumerate()
                .filter(|&(o, other)| o != k && !l.is_empty() && inside(l[0], other))
                .count();
            let positive = depth % 2 == 0;
            let mut l = l.clone();
            if (area(&l) > 0.0) != positive {
                l.reverse();
            }
            (l, positive)
        })
        .collect()
}

/// Twice the signed area of a loop (positive counter-clockwise).
fn area(l: &[DVec2]) -> f64 {
    (0..l.len())
        .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
        .sum()
}

/// Whether `p` is inside the loop (crossing number).
fn inside(p: DVec2, l: &[DVec2]) -> bool {
    let mut inside = false;
    for i in 0..l.len() {
        let (a, b) = (l[i], l[(i + 1) % l.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use solidkit_kernel::polyhedra::Polyhedron;

    fn square(c: DVec2, half: f64) -> Vec<DVec2> {
        [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .map(|(x, y)| c + DVec2::new(x, y) * half)
            .to_vec()
    }

    fn volume(loops: &[Vec<DVec2>], h: f64, twist: f64, scale: DVec2, slices: usize) -> f64 {
        let (v, f) = sliced_extrusion(loops, h, twist, scale, slices).unwrap();
        Polyhedron::new(v, f).unwrap().volume()
    }

    /// `square(10, center = true)` under `linear_extrude(height, twist, scale)` with `$fn`,
    /// `$fa`, `$fs`: OpenSCAD 2021.01's slice count (its STL has 8 triangles per slice and 4 in
    /// the caps).
    fn openscad_slices(h: f64, twist: f64, scale: DVec2, fn_: f64, fa: f64, fs: f64) -> f64 {
        let sq = [square(DVec2::ZERO, 5.0)];
        let res = Resolution { fn_, fa, fs };
        slice_count(None, h, twist, scale, res, Reach::of(&sq, scale))
    }

    #[test]
    fn slice_counts_follow_openscad() {
        let one = DVec2::ONE;
        // Counted in OpenSCAD 2021.01's own renders (see openscad_slices).
        assert_eq!(openscad_slices(20.0, 90.0, one, 0.0, 12.0, 2.0), 8.0);
        assert_eq!(openscad_slices(20.0, 45.0, one, 0.0, 12.0, 2.0), 4.0);
        assert_eq!(openscad_slices(20.0, -90.0, one, 0.0, 12.0, 2.0), 8.0);
        assert_eq!(openscad_slices(20.0, 90.0, one, 10.0, 12.0, 2.0), 3.0);
        assert_eq!(openscad_slices(20.0, 360.0, one, 0.0, 12.0, 2.0), 25.0);
        assert_eq!(openscad_slices(20.0, 90.0, one, 0.0, 5.0, 2.0), 12.0);
        assert_eq!(openscad_slices(2.0, 90.0, one, 0.0, 12.0, 2.0), 6.0);
        assert_eq!(openscad_slices(20.0, 10.0, one, 0.0, 12.0, 2.0), 1.0);
        assert_eq!(openscad_slices(20.0, 1000.0, one, 0.0, 12.0, 2.0), 63.0);
        assert_eq!(openscad_slices(20.0, 360.0, one, 7.0, 12.0, 2.0), 7.0);
        assert_eq!(openscad_slices(20.0, 30.0, one, 0.0, 100.0, 2.0), 1.0);
        let s = |k| DVec2::splat(k);
        assert_eq!(openscad_slices(20.0, 360.0, s(3.0), 0.0, 1.0, 2.0), 19.0);
        assert_eq!(openscad_slices(20.0, 360.0, s(0.5), 0.0, 1.0, 2.0), 20.0);
        let uneven = DVec2::new(0.5, 2.0);
        assert_eq!(openscad_slices(20.0, 0.0, uneven, 0.0, 12.0, 2.0), 11.0);
        assert_eq!(openscad_slices(20.0, 0.0, uneven, 10.0, 12.0, 2.0), 10.0);
        assert_eq!(openscad_slices(100.0, 0.0, uneven, 0.0, 12.0, 2.0), 51.0);
        assert_eq!(openscad_slices(2.0, 0.0, uneven, 0.0, 12.0, 2.0), 3.0);
        assert_eq!(openscad_slices(20.0, 0.0, uneven, 0.0, 12.0, 0.5), 42.0);
        assert_eq!(openscad_slices(20.0, 0.0, one, 0.0, 12.0, 2.0), 1.0);
        // A given count wins, truncated, at least 1.
        let res = Resolution {
            fn_: 0.0,
            fa: 12.0,
            fs: 2.0,
        };
        let reach = Reach::of(&[square(DVec2::ZERO, 5.0)], one);
        assert_eq!(slice_count(Some(3.7), 20.0, 90.0, one, res, reach), 3.0);
        assert_eq!(slice_count(Some(-2.0), 20.0, 90.0, one, res, reach), 1.0);
    }

    #[test]
    fn an_untwisted_stack_is_the_prism() {
        // Any slice count: the walls are flat, the volume is area × height, holes included.
        let loops = vec![square(DVec2::ZERO, 2.0), square(DVec2::ZERO, 1.0)];
        for slices in [1, 3] {
            let v = volume(&loops, 5.0, 0.0, DVec2::ONE, slices);
            assert!((v - 12.0 * 5.0).abs() < 1e-9, "{v}");
        }
    }

    #[test]
    fn a_twisted_square_bulges_as_openscads() {
        // OpenSCAD 2021.01: linear_extrude(height = 20, twist = 90) square(10, center = true)
        // renders (8 slices) to 2117.25 (trimesh on its STL); the exact twisted solid is 2000.
        let v = volume(&[square(DVec2::ZERO, 5.0)], 20.0, 90.0, DVec2::ONE, 8);
        assert!((v - 2117.25).abs() < 0.01, "{v}");
        // The diagonal follows the twist's sense: the mirror image has the same volume.
        let w = volume(&[square(DVec2::ZERO, 5.0)], 20.0, -90.0, DVec2::ONE, 8);
        assert!((w - v).abs() < 1e-9, "{w}");
    }

    #[test]
    fn a_closed_oriented_mesh_for_holes_and_uneven_scales() {
        let loops = vec![square(DVec2::ZERO, 2.0), square(DVec2::new(0.5, 0.0), 0.5)];
        let (v, f) = sliced_extrusion(&loops, 3.0, 120.0, DVec2::new(0.5, 1.5), 4).unwrap();
        let p = Polyhedron::new(v, f).unwrap();
        // Every edge used once in each direction.
        let mut edges = std::collections::HashMap::new();
        for face in p.faces() {
            for i in 0..face.len() {
                *edges
                    .entry((face[i], face[(i + 1) % face.len()]))
                    .or_insert(0) += 1;
            }
        }
        for (&(a, b), &n) in &edges {
            assert_eq!(n, 1);
            assert_eq!(edges.get(&(b, a)), Some(&1));
        }
        assert!(p.volume() > 0.0);
    }

    #[test]
    fn a_wedge_is_left_to_the_exact_sweep_and_a_cone_has_an_apex() {
        let s = [square(DVec2::ZERO, 1.0)];
        assert!(sliced_extrusion(&s, 1.0, 90.0, DVec2::new(0.0, 1.0), 4).is_none());
        // Untwisted: the pyramid, A h / 3, whatever the slice count.
        let v = volume(&s, 3.0, 0.0, DVec2::ZERO, 5);
        assert!((v - 4.0).abs() < 1e-9, "{v}");
        let (v, f) = sliced_extrusion(&s, 3.0, 200.0, DVec2::ZERO, 7).unwrap();
        assert_eq!(v.len(), 4 * 7 + 1);
        assert!(Polyhedron::new(v, f).unwrap().volume() > 0.0);
        assert!(sliced_extrusion(&s, 1.0, 1e9, DVec2::ONE, usize::MAX / 2).is_none());
    }
}
