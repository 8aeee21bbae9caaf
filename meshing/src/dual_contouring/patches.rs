//! The patch structure of a cell, generated from the marching-cubes case table: one dual vertex per
//! connected surface patch (one per marching-cubes loop), the patch each crossing edge belongs to,
//! and which faces need a split vertex.
//!
//! A cell face whose inside corners are diagonal (an ambiguous face) carries two surface segments.
//! When both segments belong to one patch in the cell on each side, the two dual edges across that
//! face would join the same two vertices (a doubled edge, four triangles on one mesh edge). Such a
//! face gets one extra vertex per segment ([`PatchTable::split_face`]); the polygons around the
//! face's edges then go through it and every mesh edge keeps exactly two triangles.
//!
//! A cell with several patches also gets, for every pair of its patches, a plane that separates
//! them for any crossing positions ([`PatchTable::separators`]): every edge of one patch lies in
//! one closed half-space with at least one end strictly inside it (so every crossing strictly
//! inside the edge is strictly inside the half-space), and the other patch's edges in the other.
//! Keeping each patch's surface in its own open half-spaces keeps the patches apart.

use crate::marching_cubes::table::{case_table, corner_offset, edge_corners, face_corners};
use std::sync::LazyLock;

/// No patch: the edge does not cross.
pub(crate) const NO_PATCH: u8 = u8::MAX;

/// Per sign mask: the patches of a cell.
pub(crate) struct PatchTable {
    /// `patch_of_edge[mask][edge]`: the patch (loop) containing the crossing edge, or [`NO_PATCH`].
    pub patch_of_edge: Vec<[u8; 12]>,
    /// `edges[mask][patch]`: the cell edges of each patch.
    pub edges: Vec<Vec<Vec<u8>>>,
    /// `ambiguous[mask]`: bit `2·axis + side` set when that face has diagonal inside corners.
    pub ambiguous: Vec<u8>,
    /// `split_face[mask]`: bit `2·axis + side` set when that face is ambiguous and all four of its
    /// edges belong to one patch of the cell.
    pub split_face: Vec<u8>,
    /// `separators[mask][patch]`: half-spaces `a · x < b` (`x` in cell units from the cell's
    /// lower corner) holding every crossing of the patch strictly and every crossing of each
    /// other patch of the cell strictly outside; empty for a lone patch.
    pub separators: Vec<Vec<Vec<Separator>>>,
}

/// A half-space `a · x < b` in cell units (see [`PatchTable::separators`]).
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
    let mut patch_of_edge = Vec::with_capacity(256);
    let mut edges = Vec::with_capacity(256);
    let mut ambiguous = Vec::with_capacity(256);
    let mut split_face = Vec::with_capacity(256);
    let mut separators = Vec::with_capacity(256);
    for mask in 0..256usize {
        let mut of = [NO_PATCH; 12];
        for (p, l) in mc.loops(mask).iter().enumerate() {
            for &e in l {
                of[e as usize] = p as u8;
            }
        }
        let inside = |c: u8| mask >> c & 1 == 1;
        let (mut amb, mut split) = (0u8, 0u8);
        for axis in 0..3 {
            for side in 0..2u8 {
                let f = face_corners(axis, side);
                let diagonal = inside(f[0]) == inside(f[2])
                    && inside(f[1]) == inside(f[3])
                    && inside(f[0]) != inside(f[1]);
                if diagonal {
                    let bit = 1 << (2 * axis + side as usize);
                    amb |= bit;
                    let fe = face_edges(axis, side);
                    if fe.iter().all(|&e| of[e as usize] == of[fe[0] as usize]) {
                        split |= bit;
                    }
                }
            }
        }
        let loops = &mc.loops(mask);
        let mut seps = vec![Vec::new(); loops.len()];
        for i in 0..loops.len() {
            for j in i + 1..loops.len() {
                // Every pair of patches of a marching-cubes case has one (tested below); a
                // missing one would leave that pair unseparated, never panic.
                if let Some(s) = separator(&loops[i], &loops[j]) {
                    seps[i].push(s);
                    seps[j].push(Separator {
                        a: s.a.map(|x| -x),
                        b: -s.b,
                    });
                }
            }
        }
        separators.push(seps);
        patch_of_edge.push(of);
        edges.push(mc.loops(mask).to_vec());
        ambiguous.push(amb);
        split_face.push(split);
    }
    PatchTable {
        patch_of_edge,
        edges,
        ambiguous,
        split_face,
        separators,
    }
}

/// On an ambiguous face, the segment (0 or 1) an edge of the face belongs to: the segment cutting
/// off the inside corner the edge touches, numbered by the lower of the two inside corners.
pub(crate) fn face_segment(mask: u8, axis: usize, side: u8, edge: u8) -> u8 {
    let f = face_corners(axis, side);
    let mut ins: Vec<u8> = f.iter().copied().filter(|&c| mask >> c & 1 == 1).collect();
    ins.sort_unstable();
    let (a, b) = edge_corners(edge);
    u8::from(!(a == ins[0] || b == ins[0]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::marching_cubes::table::edge_origin;

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

    /// Every crossing edge has a patch; split faces exist (the single-loop ambiguous cases) and
    /// each segment of an ambiguous face joins two edges of that face touching one inside corner.
    #[test]
    fn patches_cover_crossing_edges_and_splits_occur() {
        let t = patch_table();
        let mut splits = 0;
        for mask in 0..256usize {
            for e in 0..12u8 {
                let (a, b) = edge_corners(e);
                let crossing = (mask >> a & 1) != (mask >> b & 1);
                assert_eq!(t.patch_of_edge[mask][e as usize] != NO_PATCH, crossing);
            }
            splits += t.split_face[mask].count_ones();
            for axis in 0..3 {
                for side in 0..2u8 {
                    if t.ambiguous[mask] >> (2 * axis + side as usize) & 1 == 1 {
                        let segs: Vec<u8> = face_edges(axis, side)
                            .iter()
                            .map(|&e| face_segment(mask as u8, axis, side, e))
                            .collect();
                        assert_eq!(segs.iter().filter(|&&s| s == 0).count(), 2);
                    }
                }
            }
        }
        assert!(splits > 0);
    }

    /// Every pair of patches of every case has a separating plane, and it separates: crossings
    /// anywhere strictly inside the edges land strictly on their own patch's side.
    #[test]
    fn every_pair_of_patches_is_separated() {
        let t = patch_table();
        let mut pairs = 0;
        for mask in 0..256usize {
            let n = t.edges[mask].len();
            for p in 0..n {
                assert_eq!(t.separators[mask][p].len(), n - 1, "mask {mask} patch {p}");
                pairs += t.separators[mask][p].len();
                for s in &t.separators[mask][p] {
                    for &e in &t.edges[mask][p] {
                        let (axis, o) = edge_origin(e);
                        for f in [1e-9, 0.5, 1.0 - 1e-9] {
                            let mut x = glam::DVec3::new(o[0] as f64, o[1] as f64, o[2] as f64);
                            x[axis] += f;
                            assert!(s.value(x) < 0.0, "mask {mask} patch {p} edge {e}");
                        }
                    }
                    // The same plane, negated, is listed for exactly one other patch.
                    let flipped = Separator {
                        a: s.a.map(|x| -x),
                        b: -s.b,
                    };
                    let owners = (0..n)
                        .filter(|&q| q != p && t.separators[mask][q].contains(&flipped))
                        .count();
                    assert!(owners >= 1, "mask {mask} patch {p}");
                }
            }
        }
        assert!(pairs > 0);
    }
}
