//! The marching-cubes case table, generated from one rule instead of pasted.
//!
//! Corner `c` of a cell sits at `(c & 1, c >> 1 & 1, c >> 2 & 1)`. Edge `4a + j` runs along axis
//! `a` from the corner whose other two coordinates are `(j & 1, j >> 1)` (in axis order).
//!
//! The rule: on every face, walked counter-clockwise as seen from outside the cell, each maximal
//! run of inside corners is cut off by one segment from the edge where the walk enters the run to
//! the edge where it leaves. On an ambiguous face (inside corners diagonal) that separates the two
//! inside corners. Because the rule depends only on the face's own corners, two cells sharing a
//! face draw the same segments there (walked in opposite directions), so the surface is closed and
//! consistently oriented across cells. Every crossing edge is entered on one of its faces and left
//! on the other, so the segments chain into closed loops. Loop direction makes triangles
//! counter-clockwise seen from outside the solid (normals point towards positive values).
//!
//! Ambiguous faces are resolved by the asymptotic decider ([`face_joined`]): when the saddle of
//! the face's bilinear interpolant is inside, the two inside corners are *joined* and the segments
//! cut off the two outside corners instead. The decision reads only the face's four values, so
//! both cells sharing the face make it alike and the surface stays closed. This is what keeps a
//! sharp tip whose neighbouring samples lie exactly on the surface (exact zeros, counted as
//! outside) attached to its body instead of sealed off as a cell-sized bubble. A cell's
//! configuration is its sign mask plus one joined bit per ambiguous face ([`config`]).
//!
//! Each loop is triangulated so that no diagonal joins two vertices on the same cell face: such a
//! chord could be drawn by the neighbouring cell too, and the edge would then have four triangles.
//! With that constraint every diagonal is interior to its cell and the output is a 2-manifold.
//! Some loops through joined faces wind around the cell and have no such triangulation (the
//! tunnel cases of Chernyaev's marching cubes 33); they are fanned from one extra vertex at the
//! centroid of their crossings ([`CENTRE`]). A configuration has at most one such loop: it has at
//! least eight crossings, and a cell has twelve edges.

use std::sync::LazyLock;

/// Triangles of one case, as triples of cell edge numbers.
pub type CaseTriangles = Vec<[u8; 3]>;

/// Number of cell configurations: 256 sign masks times 64 joined-face sets.
pub const CONFIGS: usize = 256 * 64;

/// The corner number, in [`CaseTable::triangles`], of the centre vertex of a loop fanned from its
/// centroid (see [`CaseTable::centre_loop`]).
pub const CENTRE: u8 = 12;

/// No loop of the configuration needs a centre vertex.
pub const NO_CENTRE: u8 = u8::MAX;

/// The case table, indexed by configuration ([`config`]).
pub struct CaseTable {
    /// Triangles of every configuration, one after the other (see [`CaseTable::triangles`]).
    triangles: Vec<[u8; 3]>,
    /// `starts[config]..starts[config + 1]`: the range of that configuration in `triangles`.
    starts: Vec<u32>,
    /// The edge loops of each distinct configuration (see [`CaseTable::loops`]).
    loop_sets: Vec<Vec<Vec<u8>>>,
    /// `canonical[config]`: the index in `loop_sets` of the configuration with the same loops
    /// (joined bits of faces that are not ambiguous dropped).
    canonical: Vec<u16>,
    /// `centre_loop[config]`: the loop fanned from the centroid of its crossings (whose position
    /// is the vertex [`CENTRE`]), or [`NO_CENTRE`].
    pub centre_loop: Vec<u8>,
    /// `ambiguous[mask]`: bit `2·axis + side` set when that face has diagonal inside corners.
    pub ambiguous: [u8; 256],
    /// `deciders[mask]`: the ambiguous faces with their corners in decider order.
    deciders: Vec<Deciders>,
}

static TABLE: LazyLock<CaseTable> = LazyLock::new(build);

/// The case table (built on first use).
pub fn case_table() -> &'static CaseTable {
    &TABLE
}

/// The configuration of a cell with inside-corner `mask` whose ambiguous faces in `joined` (bit
/// `2·axis + side`) join their inside corners; bits of faces that are not ambiguous are ignored.
#[inline]
pub fn config(mask: usize, joined: u8) -> usize {
    mask | usize::from(joined & case_table().ambiguous[mask]) << 8
}

/// The asymptotic decider on an ambiguous face: `true` when the saddle of the bilinear
/// interpolant of corner values `a`, `c` (one diagonal, inside: `< 0`) and `b`, `d` (the other,
/// outside: `≥ 0`) is inside, i.e. `a·c > b·d`. The products are exact in double precision and a
/// tie (saddle exactly on the surface) keeps the corners apart.
#[inline]
pub fn face_joined(a: f32, c: f32, b: f32, d: f32) -> bool {
    f64::from(a) * f64::from(c) > f64::from(b) * f64::from(d)
}

impl CaseTable {
    /// The triangles of configuration `config`, as cell edge numbers or [`CENTRE`], in one flat
    /// array (the hot lookup of every polygonizer).
    #[inline]
    pub fn triangles(&self, config: usize) -> &[[u8; 3]] {
        &self.triangles[self.starts[config] as usize..self.starts[config + 1] as usize]
    }

    /// The closed edge loops of configuration `config` the triangles were made from (oriented:
    /// triangles follow their direction).
    #[inline]
    pub fn loops(&self, config: usize) -> &[Vec<u8>] {
        &self.loop_sets[usize::from(self.canonical[config])]
    }

    /// The configuration of a cell from its eight corner values (corner `c` at
    /// [`corner_offset`]), with the sign `mask` already computed from them.
    #[inline]
    pub fn cell_config(&self, mask: usize, value: impl Fn(u8) -> f32) -> usize {
        self.cell_config_with(mask, value, |_, _, _| true)
    }

    /// [`CaseTable::cell_config`] with each face the decider joins confirmed by `confirm(bit,
    /// [a, c, b, d], values)` (inside corners `a`, `c`, and the four corners' values in that
    /// order): a face stays joined only when it returns true ([`super::pinch`]).
    #[inline]
    pub fn cell_config_with(
        &self,
        mask: usize,
        value: impl Fn(u8) -> f32,
        mut confirm: impl FnMut(u8, [u8; 4], [f32; 4]) -> bool,
    ) -> usize {
        let faces = &self.deciders[mask];
        let mut joined = 0u8;
        for &(bit, corners @ [a, c, b, d]) in &faces.faces[..usize::from(faces.count)] {
            let values = [value(a), value(c), value(b), value(d)];
            if face_joined(values[0], values[1], values[2], values[3])
                && confirm(bit, corners, values)
            {
                joined |= 1 << bit;
            }
        }
        mask | usize::from(joined) << 8
    }
}

/// The ambiguous faces of one sign mask, ready for the decider: `(bit, [a, c, b, d])` with `a`,
/// `c` the inside diagonal's corners and `b`, `d` the outside one's.
#[derive(Debug, Clone, Copy, Default)]
pub struct Deciders {
    count: u8,
    faces: [(u8, [u8; 4]); 6],
}

impl Deciders {
    fn of(mask: u8) -> Self {
        let mut out = Self::default();
        for (bit, &f) in FACES.iter().enumerate() {
            if is_ambiguous(mask, f) {
                let corners = if mask >> f[0] & 1 == 1 {
                    [f[0], f[2], f[1], f[3]]
                } else {
                    [f[1], f[3], f[0], f[2]]
                };
                out.faces[usize::from(out.count)] = (bit as u8, corners);
                out.count += 1;
            }
        }
        out
    }
}

/// [`CaseTable::cell_config`] on the shared table.
#[inline]
pub fn cell_config(mask: usize, value: impl Fn(u8) -> f32) -> usize {
    case_table().cell_config(mask, value)
}

/// The six faces' corners in walk order, face `2·axis + side`.
const FACES: [[u8; 4]; 6] = {
    let mut out = [[0u8; 4]; 6];
    let mut axis = 0;
    while axis < 3 {
        let mut side = 0;
        while side < 2 {
            out[2 * axis + side] = face_corners_const(axis, side as u8);
            side += 1;
        }
        axis += 1;
    }
    out
};

/// Unit offset of corner `c`.
pub fn corner_offset(c: u8) -> [usize; 3] {
    [
        (c & 1) as usize,
        (c >> 1 & 1) as usize,
        (c >> 2 & 1) as usize,
    ]
}

/// The axis of edge `e` and the offset of its lower corner within the cell.
pub fn edge_origin(e: u8) -> (usize, [usize; 3]) {
    let (axis, j) = ((e / 4) as usize, (e % 4) as usize);
    let (lo, hi) = (j & 1, j >> 1);
    let offset = match axis {
        0 => [0, lo, hi],
        1 => [lo, 0, hi],
        _ => [lo, hi, 0],
    };
    (axis, offset)
}

/// The two corners joined by edge `e`.
pub fn edge_corners(e: u8) -> (u8, u8) {
    let (axis, o) = edge_origin(e);
    let a = (o[0] | o[1] << 1 | o[2] << 2) as u8;
    (a, a | 1 << axis)
}

/// The edge joining two corners that differ in exactly one coordinate.
fn edge_between(a: u8, b: u8) -> u8 {
    let diff = a ^ b;
    debug_assert!(diff.count_ones() == 1);
    let axis = diff.trailing_zeros() as u8;
    let lo = a & !diff;
    let others: Vec<u8> = (0..3).filter(|&k| k != axis).map(|k| lo >> k & 1).collect();
    4 * axis + (others[0] | others[1] << 1)
}

/// The four corners of face (`axis`, `side`) in counter-clockwise order seen from outside.
pub fn face_corners(axis: usize, side: u8) -> [u8; 4] {
    face_corners_const(axis, side)
}

const fn face_corners_const(axis: usize, side: u8) -> [u8; 4] {
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let base = side << axis;
    let ccw = [base, base | 1 << u, base | 1 << u | 1 << v, base | 1 << v];
    if side == 1 {
        ccw
    } else {
        [ccw[3], ccw[2], ccw[1], ccw[0]]
    }
}

/// True when face `f` (corners in walk order) has its inside corners on a diagonal.
fn is_ambiguous(mask: u8, f: [u8; 4]) -> bool {
    let inside = |c: u8| mask >> c & 1 == 1;
    inside(f[0]) == inside(f[2]) && inside(f[1]) == inside(f[3]) && inside(f[0]) != inside(f[1])
}

fn build() -> CaseTable {
    let mut ambiguous = [0u8; 256];
    for (mask, amb) in ambiguous.iter_mut().enumerate() {
        for (bit, &f) in FACES.iter().enumerate() {
            if is_ambiguous(mask as u8, f) {
                *amb |= 1 << bit;
            }
        }
    }
    // Distinct configurations (joined ⊆ ambiguous) first, then every configuration pointed to
    // the one with its ambiguous bits only.
    let mut loop_sets = Vec::new();
    let mut fans = Vec::new();
    let mut canonical = vec![0u16; CONFIGS];
    for mask in 0..256usize {
        let amb = ambiguous[mask];
        for joined in 0..64u8 {
            if joined & !amb == 0 {
                let l = case_loops(mask as u8, joined);
                canonical[mask | usize::from(joined) << 8] = loop_sets.len() as u16;
                fans.push(fan(&l));
                loop_sets.push(l);
            }
        }
    }
    let mut centre_loop = vec![NO_CENTRE; CONFIGS];
    let mut triangles = Vec::new();
    let mut starts = Vec::with_capacity(CONFIGS + 1);
    for i in 0..CONFIGS {
        let (mask, joined) = (i & 255, (i >> 8) as u8);
        canonical[i] = canonical[mask | usize::from(joined & ambiguous[mask]) << 8];
        let (tris, centre) = &fans[usize::from(canonical[i])];
        centre_loop[i] = *centre;
        starts.push(triangles.len() as u32);
        triangles.extend_from_slice(tris);
    }
    starts.push(triangles.len() as u32);
    CaseTable {
        deciders: (0..=255u8).map(Deciders::of).collect(),
        triangles,
        starts,
        loop_sets,
        canonical,
        centre_loop,
        ambiguous,
    }
}

/// The closed edge loops of one configuration, by the face rule: each run of inside corners is
/// cut off, except on ambiguous faces in `joined`, whose two outside corners are cut off.
fn case_loops(mask: u8, joined: u8) -> Vec<Vec<u8>> {
    let inside = |c: u8| mask >> c & 1 == 1;
    let mut next = [u8::MAX; 12];
    for (bit, &f) in FACES.iter().enumerate() {
        let join = joined >> bit & 1 == 1 && is_ambiguous(mask, f);
        for i in 0..4 {
            let (a, b) = (f[i], f[(i + 1) % 4]);
            if inside(a) || !inside(b) {
                continue;
            }
            // The walk enters a run of inside corners at edge (a, b); find where it leaves. On a
            // joined face the run continues across the saddle to the opposite inside corner.
            let exit = if join {
                edge_between(f[(i + 3) % 4], a)
            } else {
                let mut j = (i + 1) % 4;
                while inside(f[(j + 1) % 4]) {
                    j = (j + 1) % 4;
                }
                edge_between(f[j], f[(j + 1) % 4])
            };
            next[edge_between(a, b) as usize] = exit;
        }
    }
    let mut seen = [false; 12];
    let mut out = Vec::new();
    for start in 0..12u8 {
        if next[start as usize] == u8::MAX || seen[start as usize] {
            continue;
        }
        let mut l = Vec::new();
        let mut e = start;
        while !seen[e as usize] {
            seen[e as usize] = true;
            l.push(e);
            e = next[e as usize];
        }
        debug_assert_eq!(e, start, "segments close into loops");
        out.push(l);
    }
    out
}

/// True when edges `a` and `b` lie on a common face of the cell ([`CENTRE`] lies on none).
fn share_face(a: u8, b: u8) -> bool {
    if a == CENTRE || b == CENTRE {
        return false;
    }
    (0..3).any(|axis| {
        (0..2).any(|side| {
            let f = face_corners(axis, side);
            let on = |e: u8| {
                let (p, q) = edge_corners(e);
                f.contains(&p) && f.contains(&q)
            };
            on(a) && on(b)
        })
    })
}

/// The triangles of a configuration's loops and the loop fanned from a centre vertex, if any.
fn fan(loops: &[Vec<u8>]) -> (CaseTriangles, u8) {
    let mut tris = Vec::new();
    let mut centre = NO_CENTRE;
    for (n, l) in loops.iter().enumerate() {
        match triangulate_loop(l) {
            Some(t) => tris.extend(t),
            None => {
                debug_assert_eq!(centre, NO_CENTRE, "at most one centre loop");
                centre = n as u8;
                tris.extend((0..l.len()).map(|i| [l[i], l[(i + 1) % l.len()], CENTRE]));
            }
        }
    }
    (tris, centre)
}

/// A triangulation of the polygon `l` none of whose diagonals joins two edges on a common cell
/// face, found by dynamic programming over sub-polygons (`None` if there is none).
fn triangulate_loop(l: &[u8]) -> Option<CaseTriangles> {
    let n = l.len();
    let allowed =
        |i: usize, j: usize| j == i + 1 || (i == 0 && j == n - 1) || !share_face(l[i], l[j]);
    // split[i][j]: apex k of a valid triangulation of the sub-polygon i..=j (if any).
    let mut split = vec![vec![None::<usize>; n]; n];
    for gap in 2..n {
        for i in 0..n - gap {
            let j = i + gap;
            if !allowed(i, j) {
                continue;
            }
            split[i][j] = (i + 1..j).find(|&k| {
                (k == i + 1 || split[i][k].is_some()) && (k + 1 == j || split[k][j].is_some())
            });
        }
    }
    split[0][n - 1]?;
    let mut tris = Vec::new();
    let mut work = vec![(0, n - 1)];
    while let Some((i, j)) = work.pop() {
        let k = split[i][j]?;
        tris.push([l[i], l[k], l[j]]);
        if k > i + 1 {
            work.push((i, k));
        }
        if j > k + 1 {
            work.push((k, j));
        }
    }
    Some(tris)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every distinct configuration: each mask with each subset of its ambiguous faces joined.
    fn configs() -> impl Iterator<Item = usize> {
        (0..256usize).flat_map(|mask| {
            let amb = case_table().ambiguous[mask];
            (0..64u8)
                .filter(move |j| j & !amb == 0)
                .map(move |j| mask | usize::from(j) << 8)
        })
    }

    /// No diagonal lies on a cell face; centre vertices occur only in configurations with joined
    /// faces, fan loops of at least eight crossings, and are used by no other loop.
    #[test]
    fn no_diagonal_lies_on_a_cell_face() {
        let t = case_table();
        let mut centres = 0;
        for config in configs() {
            let sides: Vec<(u8, u8)> = t
                .loops(config)
                .iter()
                .flat_map(|l| (0..l.len()).map(move |k| (l[k], l[(k + 1) % l.len()])))
                .collect();
            for tri in t.triangles(config) {
                for k in 0..3 {
                    let (a, b) = (tri[k], tri[(k + 1) % 3]);
                    let side = sides.contains(&(a, b)) || sides.contains(&(b, a));
                    assert!(
                        side || !share_face(a, b),
                        "config {config:#x}: chord {a}-{b}"
                    );
                }
            }
            let with_centre = t
                .triangles(config)
                .iter()
                .filter(|tri| tri.contains(&CENTRE));
            let c = t.centre_loop[config];
            if c == NO_CENTRE {
                assert_eq!(with_centre.count(), 0);
            } else {
                centres += 1;
                assert_ne!(config >> 8, 0, "config {config:#x}");
                let l = &t.loops(config)[c as usize];
                assert!(l.len() >= 8);
                assert_eq!(with_centre.count(), l.len());
            }
        }
        assert!(centres > 0);
    }

    #[test]
    fn edges_and_faces_are_consistent() {
        for e in 0..12u8 {
            let (a, b) = edge_corners(e);
            assert_eq!(edge_between(a, b), e);
            assert_eq!(edge_between(b, a), e);
        }
        // Each edge lies on exactly two faces, walked in opposite directions.
        for e in 0..12u8 {
            let (a, b) = edge_corners(e);
            let mut dirs = Vec::new();
            for axis in 0..3 {
                for side in 0..2 {
                    let f = face_corners(axis, side);
                    for i in 0..4 {
                        let (p, q) = (f[i], f[(i + 1) % 4]);
                        if (p, q) == (a, b) {
                            dirs.push(1);
                        } else if (p, q) == (b, a) {
                            dirs.push(-1);
                        }
                    }
                }
            }
            dirs.sort();
            assert_eq!(dirs, vec![-1, 1], "edge {e}");
        }
    }

    /// All 256 cases: every crossing edge is used by exactly one loop, loops use only crossing
    /// edges, and the triangle count is the Euler count of the loops' fans.
    #[test]
    fn every_case_uses_each_crossing_edge_once() {
        let t = case_table();
        for config in configs() {
            let mask = (config & 255) as u8;
            let crossing: Vec<u8> = (0..12u8)
                .filter(|&e| {
                    let (a, b) = edge_corners(e);
                    (mask >> a & 1) != (mask >> b & 1)
                })
                .collect();
            let mut used: Vec<u8> = t.loops(config).iter().flatten().copied().collect();
            used.sort();
            assert_eq!(used, crossing, "config {config:#x}");
            let centre = t.centre_loop[config] as usize;
            let expected: usize = (t.loops(config).iter().enumerate())
                .map(|(n, l)| if n == centre { l.len() } else { l.len() - 2 })
                .sum();
            assert_eq!(t.triangles(config).len(), expected);
            assert!(t.loops(config).iter().all(|l| l.len() >= 3));
        }
        assert!(t.triangles(0).is_empty() && t.triangles(255).is_empty());
    }

    /// Each edge of a case's triangulation is either a loop side (on a cell face, shared with the
    /// neighbour) used once, or an interior diagonal used twice in opposite directions.
    #[test]
    fn every_case_is_an_oriented_surface_with_loop_boundaries() {
        let t = case_table();
        for mask in configs() {
            let mut directed: Vec<(u8, u8)> = Vec::new();
            for tri in t.triangles(mask) {
                for k in 0..3 {
                    directed.push((tri[k], tri[(k + 1) % 3]));
                }
            }
            let sides: Vec<(u8, u8)> = t
                .loops(mask)
                .iter()
                .flat_map(|l| (0..l.len()).map(move |k| (l[k], l[(k + 1) % l.len()])))
                .collect();
            for &(a, b) in &directed {
                let forward = directed.iter().filter(|&&d| d == (a, b)).count();
                let backward = directed.iter().filter(|&&d| d == (b, a)).count();
                assert_eq!(forward, 1, "mask {mask}: edge {a}-{b} repeated");
                if sides.contains(&(a, b)) {
                    assert_eq!(backward, 0, "mask {mask}: loop side {a}-{b} used twice");
                } else {
                    assert_eq!(backward, 1, "mask {mask}: diagonal {a}-{b} not shared");
                }
            }
        }
    }

    /// Flipping every sign and every ambiguous face's decision gives the same loops reversed: the
    /// joined rule is the separating rule seen from the other side.
    #[test]
    fn complement_reverses_loops() {
        let t = case_table();
        let canonical = |loops: &[Vec<u8>]| {
            let mut out: Vec<Vec<u8>> = loops
                .iter()
                .map(|l| {
                    let k = (0..l.len()).min_by_key(|&k| l[k]).unwrap();
                    (0..l.len()).map(|i| l[(k + i) % l.len()]).collect()
                })
                .collect();
            out.sort();
            out
        };
        for config in configs() {
            let (mask, joined) = (config & 255, (config >> 8) as u8);
            let flipped = config_of(255 - mask, t.ambiguous[mask] ^ joined);
            let reversed: Vec<Vec<u8>> = t
                .loops(flipped)
                .iter()
                .map(|l| l.iter().rev().copied().collect())
                .collect();
            assert_eq!(
                canonical(t.loops(config)),
                canonical(&reversed),
                "config {config:#x}"
            );
        }
    }

    fn config_of(mask: usize, joined: u8) -> usize {
        config(mask, joined)
    }

    /// On every face, each loop segment cuts off one corner run: inside runs, except on a joined
    /// ambiguous face, where it cuts off an outside corner.
    #[test]
    fn segments_cut_off_the_decided_corners() {
        let t = case_table();
        for config in configs() {
            let (mask, joined) = ((config & 255) as u8, (config >> 8) as u8);
            let segments: Vec<(u8, u8)> = t
                .loops(config)
                .iter()
                .flat_map(|l| (0..l.len()).map(move |k| (l[k], l[(k + 1) % l.len()])))
                .collect();
            for (bit, &f) in FACES.iter().enumerate() {
                if !is_ambiguous(mask, f) {
                    continue;
                }
                let cut_inside = joined >> bit & 1 == 0;
                for i in 0..4 {
                    let corner = f[i];
                    if (mask >> corner & 1 == 1) != cut_inside {
                        continue;
                    }
                    let e1 = edge_between(f[(i + 3) % 4], corner);
                    let e2 = edge_between(corner, f[(i + 1) % 4]);
                    assert!(
                        segments.contains(&(e1, e2)) || segments.contains(&(e2, e1)),
                        "config {config:#x}: face {bit} corner {corner} not cut off"
                    );
                }
            }
        }
    }

    /// The decider agrees with brute force: the two inside corners of random ambiguous faces are
    /// joined exactly when a flood fill of the negative region of the face's bilinear interpolant,
    /// sampled on a fine grid, reaches one from the other (faces whose saddle is within a grid
    /// step's worth of zero are skipped).
    #[test]
    fn decider_matches_a_flood_fill_of_the_bilinear_face() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        const N: usize = 101;
        let mut checked = [0; 2];
        for _ in 0..300 {
            let (a, c) = (-next() - 0.01, -next() - 0.01);
            let (b, d) = (next() + 0.01, next() + 0.01);
            // a at (0,0), b at (1,0), c at (1,1), d at (0,1).
            let f = |u: f64, v: f64| {
                let (a, b, c, d) = (a as f64, b as f64, c as f64, d as f64);
                a * (1.0 - u) * (1.0 - v) + b * u * (1.0 - v) + c * u * v + d * (1.0 - u) * v
            };
            let den = f64::from(a) + f64::from(c) - f64::from(b) - f64::from(d);
            let saddle = (f64::from(a) * f64::from(c) - f64::from(b) * f64::from(d)) / den;
            if saddle.abs() < 0.02 {
                continue;
            }
            let at = |i: usize, j: usize| f(i as f64 / (N - 1) as f64, j as f64 / (N - 1) as f64);
            let mut seen = vec![false; N * N];
            let mut stack = vec![(0usize, 0usize)];
            seen[0] = true;
            while let Some((i, j)) = stack.pop() {
                for (di, dj) in [(1i64, 0i64), (-1, 0), (0, 1), (0, -1)] {
                    let (p, q) = (i as i64 + di, j as i64 + dj);
                    if p < 0 || q < 0 || p >= N as i64 || q >= N as i64 {
                        continue;
                    }
                    let (p, q) = (p as usize, q as usize);
                    if !seen[p + N * q] && at(p, q) < 0.0 {
                        seen[p + N * q] = true;
                        stack.push((p, q));
                    }
                }
            }
            let connected = seen[(N - 1) + N * (N - 1)];
            assert_eq!(face_joined(a, c, b, d), connected, "{a} {b} {c} {d}");
            checked[usize::from(connected)] += 1;
        }
        assert!(checked[0] > 20 && checked[1] > 20, "{checked:?}");
        // Exact zeros on the outside diagonal always join; a tie keeps the corners apart.
        assert!(face_joined(-1e-30, -1e-30, 0.0, 0.0));
        assert!(!face_joined(-1.0, -1.0, 1.0, 1.0));
    }

    /// A tip sample whose three face neighbours lie exactly on the surface joins the rest of the
    /// cell: three small loops around those corners, not one around the tip.
    #[test]
    fn tip_with_zero_neighbours_stays_attached() {
        let values = [-0.1f32, 0.0, 0.0, -0.2, 0.0, -0.2, -0.2, -0.3];
        let mask = (0..8)
            .filter(|&c| values[c] < 0.0)
            .fold(0, |m, c| m | 1 << c);
        let config = cell_config(mask, |c| values[c as usize]);
        let loops = &case_table().loops(config);
        assert_eq!(loops.len(), 3);
        assert!(loops.iter().all(|l| l.len() == 3));
        assert_eq!(
            case_table().loops(mask).len(),
            2,
            "the separating rule seals the tip off"
        );
    }
}
