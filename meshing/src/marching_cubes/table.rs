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
//! Each loop is triangulated so that no diagonal joins two vertices on the same cell face: such a
//! chord could be drawn by the neighbouring cell too, and the edge would then have four triangles.
//! With that constraint every diagonal is interior to its cell and the output is a 2-manifold.

use std::sync::LazyLock;

/// Triangles of one case, as triples of cell edge numbers.
pub type CaseTriangles = Vec<[u8; 3]>;

/// The 256 cases, indexed by the bit mask of inside corners.
pub struct CaseTable {
    /// `cases[mask]`: triangles for that mask.
    pub cases: Vec<CaseTriangles>,
    /// `loops[mask]`: the edge loops the triangles were made from.
    pub loops: Vec<Vec<Vec<u8>>>,
}

static TABLE: LazyLock<CaseTable> = LazyLock::new(build);

/// The case table (built on first use).
pub fn case_table() -> &'static CaseTable {
    &TABLE
}

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
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let at = |du: u8, dv: u8| (side << axis) | (du << u) | (dv << v);
    let ccw = [at(0, 0), at(1, 0), at(1, 1), at(0, 1)];
    if side == 1 {
        ccw
    } else {
        [ccw[3], ccw[2], ccw[1], ccw[0]]
    }
}

fn build() -> CaseTable {
    let mut cases = Vec::with_capacity(256);
    let mut loops = Vec::with_capacity(256);
    for mask in 0..=255u8 {
        let l = case_loops(mask);
        cases.push(fan(&l));
        loops.push(l);
    }
    CaseTable { cases, loops }
}

/// The closed edge loops of one case, by the face rule.
fn case_loops(mask: u8) -> Vec<Vec<u8>> {
    let inside = |c: u8| mask >> c & 1 == 1;
    let mut next = [u8::MAX; 12];
    for axis in 0..3 {
        for side in 0..2 {
            let f = face_corners(axis, side);
            for i in 0..4 {
                let (a, b) = (f[i], f[(i + 1) % 4]);
                if inside(a) || !inside(b) {
                    continue;
                }
                // The walk enters a run of inside corners at edge (a, b); find where it leaves.
                let mut j = (i + 1) % 4;
                while inside(f[(j + 1) % 4]) {
                    j = (j + 1) % 4;
                }
                let exit = edge_between(f[j], f[(j + 1) % 4]);
                next[edge_between(a, b) as usize] = exit;
            }
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

/// True when edges `a` and `b` lie on a common face of the cell.
fn share_face(a: u8, b: u8) -> bool {
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

fn fan(loops: &[Vec<u8>]) -> CaseTriangles {
    let mut tris = Vec::new();
    for l in loops {
        tris.extend(triangulate_loop(l).expect("every loop has a face-free triangulation"));
    }
    tris
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

    #[test]
    fn no_diagonal_lies_on_a_cell_face() {
        let t = case_table();
        for mask in 0..256 {
            let sides: Vec<(u8, u8)> = t.loops[mask]
                .iter()
                .flat_map(|l| (0..l.len()).map(move |k| (l[k], l[(k + 1) % l.len()])))
                .collect();
            for tri in &t.cases[mask] {
                for k in 0..3 {
                    let (a, b) = (tri[k], tri[(k + 1) % 3]);
                    let side = sides.contains(&(a, b)) || sides.contains(&(b, a));
                    assert!(
                        side || !share_face(a, b),
                        "mask {mask}: chord {a}-{b} on a face"
                    );
                }
            }
        }
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
        for mask in 0..=255u8 {
            let crossing: Vec<u8> = (0..12u8)
                .filter(|&e| {
                    let (a, b) = edge_corners(e);
                    (mask >> a & 1) != (mask >> b & 1)
                })
                .collect();
            let mut used: Vec<u8> = t.loops[mask as usize].iter().flatten().copied().collect();
            used.sort();
            assert_eq!(used, crossing, "mask {mask:#010b}");
            let expected: usize = t.loops[mask as usize].iter().map(|l| l.len() - 2).sum();
            assert_eq!(t.cases[mask as usize].len(), expected);
            assert!(t.loops[mask as usize].iter().all(|l| l.len() >= 3));
        }
        assert!(t.cases[0].is_empty() && t.cases[255].is_empty());
    }

    /// Each edge of a case's triangulation is either a loop side (on a cell face, shared with the
    /// neighbour) used once, or an interior diagonal used twice in opposite directions.
    #[test]
    fn every_case_is_an_oriented_surface_with_loop_boundaries() {
        let t = case_table();
        for mask in 0..=255usize {
            let mut directed: Vec<(u8, u8)> = Vec::new();
            for tri in &t.cases[mask] {
                for k in 0..3 {
                    directed.push((tri[k], tri[(k + 1) % 3]));
                }
            }
            let sides: Vec<(u8, u8)> = t.loops[mask]
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
}
