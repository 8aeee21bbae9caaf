//! The patch structure of a cell, generated from the marching-cubes case table: one dual vertex per
//! connected surface patch (one per marching-cubes loop), the patch each crossing edge belongs to,
//! and which faces need a split vertex. Like the case table it is keyed by the cell's
//! *configuration* (sign mask plus the asymptotic decider's joined bit per ambiguous face,
//! [`crate::marching_cubes::table::config`]), so the patches are always the marching-cubes loops
//! of the same samples.
//!
//! A cell face whose inside corners are diagonal (an ambiguous face) carries two surface segments:
//! each cuts off one inside corner, or one outside corner when the face joins its inside corners
//! ([`cut_corner`]). When both segments belong to one patch in the cell on each side, the two dual
//! edges across that face would join the same two vertices (a doubled edge, four triangles on one
//! mesh edge). Such a face gets one extra vertex per segment ([`Patches::split_face`]); the
//! polygons around the face's edges then go through it and every mesh edge keeps exactly two
//! triangles.
//!
//! A cell with several patches also gets, for every pair of its patches, a plane that separates
//! them for any crossing positions ([`Patches::separators`]): every edge of one patch lies in
//! one closed half-space with at least one end strictly inside it (so every crossing strictly
//! inside the edge is strictly inside the half-space), and the other patch's edges in the other.
//! Keeping each patch's surface in its own open half-spaces keeps the patches apart.

use crate::marching_cubes::table::{
    CONFIGS, case_table, corner_offset, edge_corners, face_corners,
};
use std::sync::LazyLock;

/// No patch: the edge does not cross.
pub(crate) const NO_PATCH: u8 = u8::MAX;

/// A cell configuration: sign mask in the low byte, joined ambiguous faces (bit `2·axis + side`)
/// above it, as [`crate::marching_cubes::table::cell_config`] computes it.
pub(crate) type Config = u16;

/// The patches of one configuration.
pub(crate) struct Patches {
    /// `patch_of_edge[edge]`: the patch (loop) containing the crossing edge, or [`NO_PATCH`].
    pub patch_of_edge: [u8; 12],
    /// `edges[patch]`: the cell edges of each patch.
    pub edges: Vec<Vec<u8>>,
    /// Bit `2·axis + side` set when that face has diagonal inside corners.
    pub ambiguous: u8,
    /// Bit `2·axis + side` set when that face is ambiguous and joins its inside corners.
    pub joined: u8,
    /// Bit `2·axis + side` set when that face is ambiguous and all four of its edges belong to
    /// one patch of the cell.
    pub split_face: u8,
    /// `separators[patch]`: half-spaces `a · x < b` (`x` in cell units from the cell's lower
    /// corner) holding every crossing of the patch strictly and every crossing of each other
    /// patch of the cell strictly outside; empty for a lone patch. Complete for every
    /// configuration the decider can give ([`reachable`]).
    pub separators: Vec<Vec<Separator>>,
}

/// The patches of every configuration.
pub(crate) struct PatchTable {
    /// The distinct configurations (joined faces among the ambiguous ones).
    distinct: Vec<Patches>,
    /// `slot[config]`: index into `distinct` (joined bits of faces that are not ambiguous are
    /// ignored, as the case table does).
    slot: Vec<u16>,
}

impl PatchTable {
    /// The patches of configuration `config`.
    #[inline]
    pub fn get(&self, config: Config) -> &Patches {
        &self.distinct[usize::from(self.slot[usize::from(config)])]
    }
}

/// A half-space `a · x < b` in cell units (see [`Patches::separators`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Separator {
    pub a: [i8; 3],
    pub b: i8,
}

impl Separator {
    /// `a · x − b` (negative inside).
    pub fn value(&self, x: glam::DVec3) -> f64 {
        f64::from(self.a[0]) * x.x + f64::from(self.a[1]) * x.y + f64::from(self.a[2]) * x.z
            - f64::from(self.b)
    }

    fn at_corner(&self, c: u8) -> i32 {
        let o = corner_offset(c);
        (0..3)
            .map(|k| i32::from(self.a[k]) * o[k] as i32)
            .sum::<i32>()
            - i32::from(self.b)
    }

    /// True when every edge in `edges` has both ends at `sign · value ≤ 0` and one `< 0`.
    fn holds(&self, edges: &[u8], sign: i32) -> bool {
        edges.iter().all(|&e| {
            let (p, q) = edge_corners(e);
            let (vp, vq) = (sign * self.at_corner(p), sign * self.at_corner(q));
            vp <= 0 && vq <= 0 && (vp < 0 || vq < 0)
        })
    }

    /// The complementary half-space (up to the plane itself).
    fn flipped(&self) -> Separator {
        Separator {
            a: self.a.map(|x| -x),
            b: -self.b,
        }
    }
}

/// A plane with small integer coefficients separating the edges of two patches: `a` strictly
/// negative side, `b` strictly positive side (as [`Separator::holds`] says).
fn separator(a: &[u8], b: &[u8]) -> Option<Separator> {
    for range in [1i8, 2] {
        let span = -range..=range;
        for x in span.clone() {
            for y in span.clone() {
                for z in span.clone() {
                    if (x, y, z) == (0, 0, 0) {
                        continue;
                    }
                    for c in -3 * range..=3 * range {
                        let s = Separator { a: [x, y, z], b: c };
                        if s.holds(a, 1) && s.holds(b, -1) {
                            return Some(s);
                        }
                    }
                }
            }
        }
    }
    None
}

/// True when the asymptotic decider can give configuration `config` on some corner values.
///
/// On a face with inside corners `a`, `c` and outside corners `b`, `d` the decider joins when
/// `|a|·|c| > b·d`. Two opposite faces together hold all eight corners, so when both join, the
/// product of the four inside magnitudes exceeds that of the four outside values, and when both
/// separate it does not. Where every face is ambiguous (the two checkerboard masks), a
/// configuration with one pair of opposite faces both joined and another pair both separated
/// therefore never occurs. Those are the only configurations whose patches lack a separating
/// plane (tested): the two patches interlock, each holding the four edges of one face of the
/// joined (or separated) pair and two diagonally opposite edges between them.
pub(crate) fn reachable(config: Config) -> bool {
    let t = case_table();
    let (mask, joined) = (usize::from(config & 255), (config >> 8) as u8);
    let amb = t.ambiguous[mask];
    let pairs = (0..3).map(|axis| {
        let both = 0b11 << (2 * axis);
        (amb & both == both).then_some(joined & both)
    });
    let (mut all_joined, mut all_separated) = (false, false);
    for (axis, p) in pairs.enumerate() {
        match p {
            Some(j) if j == 0b11 << (2 * axis) => all_joined = true,
            Some(0) => all_separated = true,
            _ => {}
        }
    }
    !(all_joined && all_separated)
}

static TABLE: LazyLock<PatchTable> = LazyLock::new(build);

/// The patch table (built on first use).
pub(crate) fn patch_table() -> &'static PatchTable {
    &TABLE
}

/// The cell edge along `axis` whose lower corner sits at unit `offset` within the cell (the
/// numbering of [`crate::marching_cubes::table::edge_origin`]).
pub(crate) fn edge_number(axis: usize, offset: [usize; 3]) -> u8 {
    // The other two axes in ascending order.
    let (a, b) = match axis {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    (4 * axis + (offset[a] | offset[b] << 1)) as u8
}

/// The four edges of face (`axis`, `side`) of a cell.
pub(crate) fn face_edges(axis: usize, side: u8) -> [u8; 4] {
    let f = face_corners(axis, side);
    let mut out = [0u8; 4];
    for i in 0..4 {
        let (a, b) = (f[i], f[(i + 1) % 4]);
        let lo = a & b;
        let along = ((a ^ b).trailing_zeros()) as usize;
        out[i] = edge_number(along, corner_offset(lo));
    }
    out
}

fn build() -> PatchTable {
    let mc = case_table();
    let mut distinct = Vec::new();
    let mut slot = vec![0u16; CONFIGS];
    for mask in 0..256usize {
        let amb = mc.ambiguous[mask];
        let first = distinct.len();
        // Each subset of the ambiguous faces joined, in increasing order of its bits.
        for joined in (0..64u8).filter(|j| j & !amb == 0) {
            distinct.push(patches(mask | usize::from(joined) << 8));
        }
        for joined in 0..64u8 {
            // The rank of `joined & amb` among the subsets of `amb`.
            let rank = (0..64u8)
                .filter(|j| j & !amb == 0 && *j < joined & amb)
                .count();
            slot[mask | usize::from(joined) << 8] = (first + rank) as u16;
        }
    }
    PatchTable { distinct, slot }
}

/// The patches of one distinct configuration (joined faces all ambiguous).
fn patches(config: usize) -> Patches {
    let mc = case_table();
    let mask = config & 255;
    let loops = mc.loops(config);
    let mut of = [NO_PATCH; 12];
    for (p, l) in loops.iter().enumerate() {
        for &e in l {
            of[e as usize] = p as u8;
        }
    }
    let amb = mc.ambiguous[mask];
    let mut split = 0u8;
    for axis in 0..3 {
        for side in 0..2u8 {
            let bit = 1 << (2 * axis + side as usize);
            let fe = face_edges(axis, side);
            if amb & bit != 0 && fe.iter().all(|&e| of[e as usize] == of[fe[0] as usize]) {
                split |= bit;
            }
        }
    }
    let mut seps = vec![Vec::new(); loops.len()];
    for i in 0..loops.len() {
        for j in i + 1..loops.len() {
            // Every pair of patches of every reachable configuration has one (tested below); a
            // missing one would leave that pair unseparated, never panic.
            if let Some(s) = separator(&loops[i], &loops[j]) {
                seps[i].push(s);
                seps[j].push(s.flipped());
            }
        }
    }
    Patches {
        patch_of_edge: of,
        edges: loops.to_vec(),
        ambiguous: amb,
        joined: (config >> 8) as u8,
        split_face: split,
        separators: seps,
    }
}

/// On an ambiguous face (`axis`, `side`) of a cell in `config`, the corner that the segment
/// through `edge` (an edge of the face) cuts off: the edge's inside end, or its outside end when
/// the face joins its inside corners.
pub(crate) fn cut_corner(config: Config, axis: usize, side: u8, edge: u8) -> u8 {
    let joined = config >> (8 + 2 * axis + side as usize) & 1 == 1;
    let (a, b) = edge_corners(edge);
    if (config >> a & 1 == 1) != joined {
        a
    } else {
        b
    }
}

/// On an ambiguous face, the segment (0 or 1) an edge of the face belongs to: the segment cutting
/// off the corner [`cut_corner`] names, numbered by the lower of the two cut-off corners (the
/// inside corners, or the outside ones on a joined face). Both cells sharing the face number its
/// segments alike.
pub(crate) fn face_segment(config: Config, axis: usize, side: u8, edge: u8) -> u8 {
    let joined = config >> (8 + 2 * axis + side as usize) & 1 == 1;
    let f = face_corners(axis, side);
    let cut = |c: u8| (config >> c & 1 == 1) != joined;
    let lowest = f.iter().copied().filter(|&c| cut(c)).min();
    u8::from(lowest != Some(cut_corner(config, axis, side, edge)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::marching_cubes::table::{cell_config, edge_origin};

    #[test]
    fn edge_numbers_invert_edge_origin() {
        for e in 0..12u8 {
            let (axis, o) = edge_origin(e);
            assert_eq!(edge_number(axis, o), e);
        }
    }

    #[test]
    fn face_edges_lie_on_their_face() {
        for axis in 0..3 {
            for side in 0..2u8 {
                let f = face_corners(axis, side);
                for e in face_edges(axis, side) {
                    let (a, b) = edge_corners(e);
                    assert!(f.contains(&a) && f.contains(&b));
                }
            }
        }
    }

    /// Every distinct configuration: each mask with each subset of its ambiguous faces joined.
    fn configs() -> impl Iterator<Item = Config> {
        (0..256u16).flat_map(|mask| {
            let amb = u16::from(case_table().ambiguous[usize::from(mask)]);
            (0..64u16)
                .filter(move |j| j & !amb == 0)
                .map(move |j| mask | j << 8)
        })
    }

    /// Every configuration, distinct or not, finds the patches of the case table's loops, with
    /// joined bits only on ambiguous faces.
    #[test]
    fn every_configuration_has_the_case_tables_loops() {
        let (t, mc) = (patch_table(), case_table());
        assert_eq!(t.distinct.len(), configs().count());
        for config in 0..CONFIGS {
            let p = t.get(config as Config);
            assert_eq!(p.edges, mc.loops(config), "config {config:#x}");
            assert_eq!(p.ambiguous, mc.ambiguous[config & 255]);
            assert_eq!(p.joined, (config >> 8) as u8 & p.ambiguous, "{config:#x}");
        }
    }

    /// Every crossing edge has a patch; split faces exist (the single-loop ambiguous cases, with
    /// and without joined faces) and each segment of an ambiguous face, as [`face_segment`]
    /// numbers them, is a side of a loop: two edges of that face around the corner
    /// [`cut_corner`] names, consecutive in one loop.
    #[test]
    fn patches_cover_crossing_edges_and_splits_occur() {
        let t = patch_table();
        let (mut splits, mut joined_splits) = (0, 0);
        for config in configs() {
            let p = t.get(config);
            let mask = config & 255;
            for e in 0..12u8 {
                let (a, b) = edge_corners(e);
                let crossing = (mask >> a & 1) != (mask >> b & 1);
                assert_eq!(p.patch_of_edge[e as usize] != NO_PATCH, crossing);
            }
            splits += p.split_face.count_ones();
            joined_splits += (p.split_face & p.joined).count_ones();
            let sides: Vec<(u8, u8)> = (p.edges.iter())
                .flat_map(|l| (0..l.len()).map(move |k| (l[k], l[(k + 1) % l.len()])))
                .collect();
            for axis in 0..3 {
                for side in 0..2u8 {
                    if p.ambiguous >> (2 * axis + side as usize) & 1 == 0 {
                        continue;
                    }
                    let fe = face_edges(axis, side);
                    for s in 0..2 {
                        let seg: Vec<u8> = (fe.iter().copied())
                            .filter(|&e| face_segment(config, axis, side, e) == s)
                            .collect();
                        assert_eq!(seg.len(), 2, "config {config:#x}");
                        let (c0, c1) = (
                            cut_corner(config, axis, side, seg[0]),
                            cut_corner(config, axis, side, seg[1]),
                        );
                        assert_eq!(c0, c1, "config {config:#x}");
                        let (e0, e1) = (seg[0], seg[1]);
                        assert!(
                            sides.contains(&(e0, e1)) || sides.contains(&(e1, e0)),
                            "config {config:#x}: face {axis} {side} segment {s}"
                        );
                    }
                }
            }
        }
        assert!(splits > 0 && joined_splits > 0);
    }

    /// The two cells sharing an ambiguous face number its segments alike: the upper face of any
    /// configuration against the lower face of a configuration with the same face corners and
    /// decision.
    #[test]
    fn both_sides_of_a_face_number_its_segments_alike() {
        for config in configs() {
            let mask = config & 255;
            for axis in 0..3 {
                let bit = 2 * axis + 1;
                if u16::from(case_table().ambiguous[usize::from(mask)]) >> bit & 1 == 0 {
                    continue;
                }
                // The cell above: its lower face has this cell's upper corners (both layers).
                let upper_face: u16 = (0..8u16)
                    .filter(|&c| c >> axis & 1 == 1 && mask >> c & 1 == 1)
                    .fold(0, |m, c| m | 1 << c | 1 << (c ^ 1 << axis));
                let upper = upper_face | (config >> (8 + bit) & 1) << (8 + 2 * axis);
                for e in face_edges(axis, 1) {
                    let (ea, mut o) = edge_origin(e);
                    o[axis] = 0;
                    let eu = edge_number(ea, o);
                    assert_eq!(
                        face_segment(config, axis, 1, e),
                        face_segment(upper, axis, 0, eu),
                        "config {config:#x} axis {axis}"
                    );
                }
            }
        }
    }

    /// Every pair of patches of every configuration the decider can give has a separating
    /// plane, and it separates: crossings anywhere strictly inside the edges land strictly on
    /// their own patch's side. The configurations it cannot give include the only ones without.
    #[test]
    fn every_pair_of_patches_is_separated() {
        let t = patch_table();
        let (mut pairs, mut joined_pairs) = (0, 0);
        let (mut unreachable, mut unseparated) = (0, 0);
        for config in configs() {
            let c = t.get(config);
            let n = c.edges.len();
            if !reachable(config) {
                unreachable += 1;
                unseparated += usize::from(c.separators.iter().any(|s| s.len() + 1 < n));
                continue;
            }
            for p in 0..n {
                assert_eq!(c.separators[p].len(), n - 1, "config {config:#x} patch {p}");
                pairs += c.separators[p].len();
                if c.joined != 0 {
                    joined_pairs += c.separators[p].len();
                }
                for s in &c.separators[p] {
                    for &e in &c.edges[p] {
                        let (axis, o) = edge_origin(e);
                        for f in [1e-9, 0.5, 1.0 - 1e-9] {
                            let mut x = glam::DVec3::new(o[0] as f64, o[1] as f64, o[2] as f64);
                            x[axis] += f;
                            assert!(s.value(x) < 0.0, "config {config:#x} patch {p} edge {e}");
                        }
                    }
                    // The same plane, negated, is listed for another patch.
                    let owners = (0..n)
                        .filter(|&q| q != p && c.separators[q].contains(&s.flipped()))
                        .count();
                    assert!(owners >= 1, "config {config:#x} patch {p}");
                }
            }
        }
        assert!(pairs > 0 && joined_pairs > 0);
        // Per checkerboard mask, 18 of the 64 joined sets mix a joined and a separated pair of
        // opposite faces; 6 of them give two interlocked patches without a plane.
        assert_eq!((unreachable, unseparated), (36, 12));
    }

    /// The decider never gives a configuration [`reachable`] excludes: random corner values for
    /// every mask (magnitudes over many orders, exact zeros outside), and for the checkerboard
    /// masks many more.
    #[test]
    fn decider_gives_only_reachable_configurations() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut seen = std::collections::HashSet::new();
        for trial in 0..200_000 {
            let mask = if trial % 2 == 0 {
                [0x69, 0x96][trial / 2 % 2]
            } else {
                (next() % 256) as usize
            };
            let values: Vec<f32> = (0..8)
                .map(|c| {
                    let r = next();
                    let magnitude = if r % 16 == 0 && mask >> c & 1 == 0 {
                        0.0
                    } else {
                        // 1e-6 to 1e6, log-uniform.
                        10f32.powf(((r >> 8) % 12_001) as f32 / 1000.0 - 6.0)
                    };
                    if mask >> c & 1 == 1 {
                        -magnitude - f32::MIN_POSITIVE
                    } else {
                        magnitude
                    }
                })
                .collect();
            let config = cell_config(mask, |c| values[usize::from(c)]) as Config;
            assert!(reachable(config), "config {config:#x} from {values:?}");
            seen.insert(config);
        }
        // Most reachable checkerboard configurations were met.
        let checkerboards = seen
            .iter()
            .filter(|&&c| matches!(c & 255, 0x69 | 0x96))
            .count();
        assert!(checkerboards > 2 * (64 - 18) / 2, "{checkerboards}");
    }
}
