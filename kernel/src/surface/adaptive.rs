//! Curvature-adaptive tessellation of a rectangle-parametrised surface (`"tessellation":
//! "adaptive"`): a balanced quadtree over the unit square, refined only where the surface bends,
//! each leaf a fan of triangles around its centre.
//!
//! **The bound.** For a triangle `T` of the parameter plane and the linear interpolant `L` of the
//! surface `S` at its corners, Taylor's theorem at each corner gives, for `x ∈ T` with
//! barycentric weights `λᵢ`, `|S(x) − L(x)| ≤ ½ Σ λᵢ Q(xᵢ − x)` with
//! `Q(d) = M_ss d_s² + 2 M_st |d_s d_t| + M_tt d_t² ≤ A d_s² + B d_t²` (`A = M_ss + M_st`,
//! `B = M_tt + M_st`, bounds of the second derivatives over `T`). In coordinates scaled by
//! `(√A, √B)`, `Σ λᵢ |xᵢ − x|² = R² − |x − c|²` (`R`, `c`: the circumcircle), whose largest value
//! over `T` is `R²` when `T` has no obtuse angle and `(ℓ/2)²` (`ℓ` its longest edge) when it has
//! one. So the chord error over `T` is at most half of that ([`fan_bound`]); on the regular grid's
//! right triangles it is the uniform tessellation's `(A Δs² + B Δt²)/8`. The quantity only falls
//! when a triangle is cut into triangles inside it (`I_T q − q` grows with `T` for the convex
//! `q = |x|²`), so a leaf's fan with hanging vertices on its edges is bounded by the fan of its
//! four corners alone.
//!
//! **The bounds of the second derivatives over a leaf.** For Bézier and B-spline surfaces, the
//! second derivatives at the leaf's centre plus the third-derivative bounds of the differenced
//! control nets times the leaf's half sizes (the mean value theorem along each axis), capped by
//! the global bounds: a bound. For NURBS and formula surfaces, the largest second derivatives of
//! 3 × 3 samples of the leaf, times 1.25 and capped by the global estimate: an estimate, as the
//! uniform tessellation's is.
//!
//! **The tree.** The base grid keeps the uniform tessellation's aspect (its counts divided by a
//! power of two), each base cell is split while the bound of its two diagonal triangles exceeds
//! the tolerance, down to a finest spacing between the uniform tessellation's and half of it
//! (where that bound is at most the uniform one's, so the tolerance is met wherever the grid's
//! is and the bounds are sound), then leaves are
//! split until neighbours differ by one level at most. A leaf with no finer neighbour is cut by
//! its diagonal as a grid cell is; any other fans from its centre through its corners and the
//! corners of finer neighbours on its sides (one per side at most), so the mesh has no
//! T-junction. A fan's bound is at most the diagonal cut's (both triangles of a cut are right
//! triangles of the leaf; a fan triangle's circumradius or half long edge is no larger). Directions whose opposite edges coincide (a formula torus or sphere: the
//! seams) are balanced across the seam, so the welded seam closes.

use super::derivs::SurfaceDerivatives;
use glam::{DVec2, DVec3};
use std::collections::HashMap;

/// A tessellation: positions and unit normals per vertex, triangles wound like the uniform grid's
/// (counter-clockwise in `(s, t)`), the bound (or estimate) of the chord error met, the finest
/// spacing's segment counts, and each vertex's parameters.
pub(super) struct Tessellation {
    pub positions: Vec<DVec3>,
    pub normals: Vec<DVec3>,
    pub triangles: Vec<[u32; 3]>,
    pub chord: f64,
    pub finest: [usize; 2],
    pub params: Vec<DVec2>,
}

/// Bounds `(M_ss, M_st, M_tt)` of the second derivatives over the rectangle `lo..hi` of the unit
/// square.
pub(super) type LocalBounds<'a> = dyn Fn(DVec2, DVec2) -> [f64; 3] + 'a;

/// The adaptive tessellation of the surface `at` (point and derivatives at `(s, t)`) meeting
/// `tol` with the second-derivative bounds `local`, its finest spacing at most that of `uniform`
/// segments per direction and more than half of it, balanced across the `seams` ([`seams`]).
pub(super) fn tessellate(
    at: &dyn Fn(f64, f64) -> SurfaceDerivatives,
    local: &LocalBounds<'_>,
    tol: f64,
    uniform: [usize; 2],
    seams: [Option<bool>; 2],
) -> Tessellation {
    // The base grid: the uniform counts divided by the largest power of two both allow.
    let mut levels = 0u32;
    while levels < 8 && uniform[0].min(uniform[1]) >= 2 << levels {
        levels += 1;
    }
    let base = uniform.map(|n| n.div_ceil(1 << levels));
    let finest = base.map(|b| b << levels);
    let mut tree = Tree::new(base, levels, seams);
    // Refinement by the bound.
    let mut stack: Vec<Leaf> = (0..base[1])
        .flat_map(|j| (0..base[0]).map(move |i| Leaf { level: 0, i, j }))
        .collect();
    let mut chord = 0.0f64;
    while let Some(leaf) = stack.pop() {
        let (lo, hi) = tree.rect(leaf);
        let bound = split_bound(local(lo, hi), hi - lo);
        if bound > tol && leaf.level < levels {
            stack.extend(tree.split(leaf));
        }
    }
    tree.balance();
    // Vertices on the doubled finest lattice (leaf centres sit on odd coordinates).
    let mut ids: HashMap<(usize, usize), u32> = HashMap::new();
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut params = Vec::new();
    let mut vertex = |(x, y): (usize, usize)| -> u32 {
        *ids.entry((x, y)).or_insert_with(|| {
            let p = DVec2::new(
                x as f64 / (2 * finest[0]) as f64,
                y as f64 / (2 * finest[1]) as f64,
            );
            let d = at(p.x, p.y);
            positions.push(d.p);
            normals.push(d.normal());
            params.push(p);
            (positions.len() - 1) as u32
        })
    };
    let mut triangles = Vec::new();
    for leaf in tree.leaves() {
        let (lo, hi) = tree.rect(leaf);
        let hanging = (0..4)
            .map(|side| tree.finer_beyond(leaf, side))
            .collect::<Vec<_>>();
        let m = local(lo, hi);
        let size = 2usize << (levels - leaf.level);
        let (x0, y0) = (leaf.i * size, leaf.j * size);
        let half = size / 2;
        let corners = [
            (x0, y0),
            (x0 + size, y0),
            (x0 + size, y0 + size),
            (x0, y0 + size),
        ];
        let mids = [
            (x0 + half, y0),
            (x0 + size, y0 + half),
            (x0 + half, y0 + size),
            (x0, y0 + half),
        ];
        if !hanging.contains(&true) {
            // Two triangles, as the regular grid's cell.
            chord = chord.max(split_bound(m, hi - lo));
            let c = corners.map(&mut vertex);
            triangles.push([c[0], c[1], c[2]]);
            triangles.push([c[0], c[2], c[3]]);
            continue;
        }
        chord = chord.max(fan_leaf_bound(m, hi - lo));
        let mut ring = Vec::with_capacity(8);
        for side in 0..4 {
            ring.push(corners[side]);
            if hanging[side] {
                ring.push(mids[side]);
            }
        }
        let centre = vertex((x0 + half, y0 + half));
        for k in 0..ring.len() {
            let (a, b) = (vertex(ring[k]), vertex(ring[(k + 1) % ring.len()]));
            triangles.push([centre, a, b]);
        }
    }
    Tessellation {
        positions,
        normals,
        triangles,
        chord,
        finest,
        params,
    }
}

/// How the domain's opposite edges meet, per direction: `Some(false)` where `s = 0` and `s = 1`
/// (`axis` 0; `t` for 1) coincide point for point, `Some(true)` where they coincide reversed,
/// `None` where they do not (17 points along them agreeing to 10⁻⁹ of the sampled size). `None`
/// overall when some other pair of edge points coincides (a seam the tree cannot follow: the
/// caller keeps the uniform grid), unless it lies on a collapsed edge (a pole).
pub(super) fn seams(at: &dyn Fn(f64, f64) -> SurfaceDerivatives) -> Option<[Option<bool>; 2]> {
    const N: usize = 16;
    // edges[e][k]: edge e (0: t = 0, 1: s = 1, 2: t = 1, 3: s = 0) at parameter k / N.
    let edges: Vec<Vec<DVec3>> = (0..4)
        .map(|e| {
            (0..=N)
                .map(|k| {
                    let b = k as f64 / N as f64;
                    match e {
                        0 => at(b, 0.0).p,
                        1 => at(1.0, b).p,
                        2 => at(b, 1.0).p,
                        _ => at(0.0, b).p,
                    }
                })
                .collect()
        })
        .collect();
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for p in edges.iter().flatten() {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    let size = (hi - lo).length();
    if !size.is_finite() {
        return None;
    }
    let eps = 1e-9 * size;
    let same = |a: DVec3, b: DVec3| a.distance(b) <= eps;
    let collapsed: Vec<bool> = edges
        .iter()
        .map(|e| e.iter().all(|p| same(*p, e[0])))
        .collect();
    let meet = |a: usize, b: usize, reversed: bool| {
        (0..=N).all(|k| same(edges[a][k], edges[b][if reversed { N - k } else { k }]))
    };
    let pair = |a: usize, b: usize| {
        if collapsed[a] && collapsed[b] {
            None
        } else if meet(a, b, false) {
            Some(false)
        } else if meet(a, b, true) {
            Some(true)
        } else {
            None
        }
    };
    let found = [pair(3, 1), pair(0, 2)];
    // Any other coincidence between interior points of edges that are not collapsed.
    for a in 0..4 {
        for b in a..4 {
            if collapsed[a] || collapsed[b] {
                continue;
            }
            let explained = (a == 1 && b == 3 && found[0].is_some())
                || (a == 0 && b == 2 && found[1].is_some());
            for i in 1..N {
                for j in 1..N {
                    if (a == b && i >= j) || explained {
                        continue;
                    }
                    if same(edges[a][i], edges[b][j]) {
                        return None;
                    }
                }
            }
        }
    }
    Some(found)
}

/// The leaf's sides `(a, b)` in the coordinates scaled by `(√A, √B)` of its second-derivative
/// bounds `m`.
fn scaled(m: [f64; 3], size: DVec2) -> (f64, f64) {
    (size.x * (m[0] + m[1]).sqrt(), size.y * (m[2] + m[1]).sqrt())
}

/// The chord-error bound of a leaf cut into two triangles by a diagonal (the regular grid's
/// `(A Δs² + B Δt²)/8`): [`fan_bound`] of a right triangle.
fn split_bound(m: [f64; 3], size: DVec2) -> f64 {
    let (a, b) = scaled(m, size);
    fan_bound([DVec2::ZERO, DVec2::new(a, 0.0), DVec2::new(a, b)])
}

/// The chord-error bound of a leaf fanned from its centre: the largest [`fan_bound`] of the four
/// triangles from its centre to its sides (at most [`split_bound`]; hanging vertices only lower
/// it).
fn fan_leaf_bound(m: [f64; 3], size: DVec2) -> f64 {
    let (a, b) = scaled(m, size);
    let c = DVec2::new(0.5 * a, 0.5 * b);
    let corners = [
        DVec2::ZERO,
        DVec2::new(a, 0.0),
        DVec2::new(a, b),
        DVec2::new(0.0, b),
    ];
    (0..4)
        .map(|k| fan_bound([c, corners[k], corners[(k + 1) % 4]]))
        .fold(0.0, f64::max)
}

/// Half the largest `Σ λᵢ |xᵢ − x|²` over the triangle `p` (already in scaled coordinates): its
/// circumradius squared, or a quarter of its longest edge squared when it has an obtuse angle.
pub(super) fn fan_bound(p: [DVec2; 3]) -> f64 {
    let e = [
        p[1].distance_squared(p[2]),
        p[2].distance_squared(p[0]),
        p[0].distance_squared(p[1]),
    ];
    let longest = e[0].max(e[1]).max(e[2]);
    let others = e[0] + e[1] + e[2] - longest;
    let twice_area = (p[1] - p[0]).perp_dot(p[2] - p[0]).abs();
    let r2 = if longest >= others || twice_area == 0.0 {
        0.25 * longest
    } else {
        // R = abc / (4K) with K = twice_area / 2: R² = a²b²c² / (4 twice_area²).
        e[0] * e[1] * e[2] / (4.0 * twice_area * twice_area)
    };
    0.5 * r2
}

/// A quadtree cell: `level` 0 is a base cell, `(i, j)` its index at that level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Leaf {
    level: u32,
    i: usize,
    j: usize,
}

/// The leaves as the level of the leaf over each finest cell.
struct Tree {
    base: [usize; 2],
    levels: u32,
    periodic: [bool; 2],
    /// Seams whose edges meet in reverse (`s = 0` at `t` with `s = 1` at `1 − t`).
    reversed: [bool; 2],
    /// Per finest cell (x fastest), the level of the leaf holding it.
    level: Vec<u8>,
}

impl Tree {
    fn new(base: [usize; 2], levels: u32, seams: [Option<bool>; 2]) -> Self {
        let n = (base[0] << levels) * (base[1] << levels);
        Tree {
            base,
            levels,
            periodic: seams.map(|s| s.is_some()),
            reversed: seams.map(|s| s == Some(true)),
            level: vec![0; n],
        }
    }

    fn finest(&self) -> [usize; 2] {
        self.base.map(|b| b << self.levels)
    }

    /// The leaf's rectangle of the unit square.
    fn rect(&self, leaf: Leaf) -> (DVec2, DVec2) {
        let n = self.base.map(|b| (b << leaf.level) as f64);
        let lo = DVec2::new(leaf.i as f64 / n[0], leaf.j as f64 / n[1]);
        let hi = DVec2::new((leaf.i + 1) as f64 / n[0], (leaf.j + 1) as f64 / n[1]);
        (lo, hi)
    }

    /// The finest cells of `leaf`: `(x0, y0, side)`.
    fn span(&self, leaf: Leaf) -> (usize, usize, usize) {
        let side = 1usize << (self.levels - leaf.level);
        (leaf.i * side, leaf.j * side, side)
    }

    fn set(&mut self, leaf: Leaf) {
        let (x0, y0, side) = self.span(leaf);
        let w = self.finest()[0];
        for y in y0..y0 + side {
            for x in x0..x0 + side {
                self.level[y * w + x] = leaf.level as u8;
            }
        }
    }

    /// Splits `leaf` into its four children (returned).
    fn split(&mut self, leaf: Leaf) -> [Leaf; 4] {
        let l = leaf.level + 1;
        let kids = [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(a, b)| Leaf {
            level: l,
            i: 2 * leaf.i + a,
            j: 2 * leaf.j + b,
        });
        for k in kids {
            self.set(k);
        }
        kids
    }

    /// The finest cells just across side `side` of `leaf` (0: t = lo, 1: s = hi, 2: t = hi,
    /// 3: s = lo), wrapped across seams; empty on a domain edge without one.
    fn across(&self, leaf: Leaf, side: usize) -> Vec<(usize, usize)> {
        let (x0, y0, n) = self.span(leaf);
        let [w, h] = self.finest();
        let wrap = |v: isize, len: usize, axis: usize| -> Option<usize> {
            if v >= 0 && (v as usize) < len {
                Some(v as usize)
            } else if self.periodic[axis] {
                Some(v.rem_euclid(len as isize) as usize)
            } else {
                None
            }
        };
        let (x0i, y0i, ni) = (x0 as isize, y0 as isize, n as isize);
        let cells: Box<dyn Iterator<Item = (isize, isize)>> = match side {
            0 => Box::new((0..ni).map(move |k| (x0i + k, y0i - 1))),
            1 => Box::new((0..ni).map(move |k| (x0i + ni, y0i + k))),
            2 => Box::new((0..ni).map(move |k| (x0i + k, y0i + ni))),
            _ => Box::new((0..ni).map(move |k| (x0i - 1, y0i + k))),
        };
        cells
            .filter_map(|(x, y)| {
                let (wx, wy) = (wrap(x, w, 0)?, wrap(y, h, 1)?);
                // A reversed seam meets the other edge at the mirrored position.
                let off_x = x < 0 || x as usize >= w;
                let off_y = y < 0 || y as usize >= h;
                let wy = if off_x && self.reversed[0] {
                    h - 1 - wy
                } else {
                    wy
                };
                let wx = if off_y && self.reversed[1] {
                    w - 1 - wx
                } else {
                    wx
                };
                Some((wx, wy))
            })
            .collect()
    }

    /// The finest level among the leaves just across side `side`, if any.
    fn level_across(&self, leaf: Leaf, side: usize) -> Option<u32> {
        let w = self.finest()[0];
        self.across(leaf, side)
            .into_iter()
            .map(|(x, y)| u32::from(self.level[y * w + x]))
            .max()
    }

    /// Whether the leaves across side `side` are finer than `leaf` (a hanging vertex at the
    /// side's midpoint).
    fn finer_beyond(&self, leaf: Leaf, side: usize) -> bool {
        self.level_across(leaf, side)
            .is_some_and(|l| l > leaf.level)
    }

    /// Every leaf, in row order of their lowest finest cell.
    fn leaves(&self) -> Vec<Leaf> {
        let [w, h] = self.finest();
        let mut out = Vec::new();
        for y in 0..h {
            for x in 0..w {
                let level = u32::from(self.level[y * w + x]);
                let side = 1usize << (self.levels - level);
                if x % side == 0 && y % side == 0 {
                    out.push(Leaf {
                        level,
                        i: x / side,
                        j: y / side,
                    });
                }
            }
        }
        out
    }

    /// Splits leaves until neighbours across every side differ by one level at most.
    fn balance(&mut self) {
        let mut work = self.leaves();
        while let Some(leaf) = work.pop() {
            let w = self.finest()[0];
            let (x0, y0, _) = self.span(leaf);
            if u32::from(self.level[y0 * w + x0]) != leaf.level {
                continue; // split since it was queued
            }
            let too_coarse = (0..4).any(|side| {
                self.level_across(leaf, side)
                    .is_some_and(|l| l > leaf.level + 1)
            });
            if !too_coarse {
                continue;
            }
            let kids = self.split(leaf);
            work.extend(kids);
            // The neighbours of the new leaves may now be too coarse in turn.
            for side in 0..4 {
                for (x, y) in self.across(leaf, side) {
                    let level = u32::from(self.level[y * w + x]);
                    let s = 1usize << (self.levels - level);
                    work.push(Leaf {
                        level,
                        i: x / s,
                        j: y / s,
                    });
                }
            }
        }
    }
}
