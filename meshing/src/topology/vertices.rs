//! Vertex fans: how many edge-connected groups the faces around each vertex form.
//!
//! The corners at a vertex `v` are joined when their faces share an edge incident to `v` (through
//! any number of faces, so a non-manifold edge joins all its faces). A manifold vertex has exactly
//! one group (a closed disk or an open fan); two cones touching at a tip, or two boundary loops
//! passing through one vertex, give two or more. Computed with union-find over corners.

use super::edges::{CornerLoops, EdgeTable};
use super::union_find::UnionFind;

/// For every vertex `0..vertex_count`, the number of face groups around it (0 when unused).
///
/// Every corner's vertex must be below `vertex_count`.
pub(crate) fn fan_counts<C: CornerLoops + ?Sized>(
    loops: &C,
    table: &EdgeTable,
    vertex_count: usize,
) -> Vec<u32> {
    let mut fans = UnionFind::new(loops.corner_count());
    for edge in table.edges() {
        let [lo, _] = edge.vertices();
        let mut at_lo_first = None;
        let mut at_hi_first = None;
        for corner in edge.corners() {
            let other = loops.next(corner);
            let (at_lo, at_hi) = if loops.origin(corner) == lo {
                (corner, other)
            } else {
                (other, corner)
            };
            join(&mut fans, &mut at_lo_first, at_lo);
            join(&mut fans, &mut at_hi_first, at_hi);
        }
    }
    let mut counts = vec![0u32; vertex_count];
    for corner in 0..loops.corner_count() {
        if fans.is_root(corner) {
            let count = &mut counts[loops.origin(corner) as usize];
            *count = count.saturating_add(1);
        }
    }
    counts
}

/// Joins `corner` to the first corner seen so far (or records it as the first).
fn join(fans: &mut UnionFind, first: &mut Option<usize>, corner: usize) {
    match *first {
        Some(f) => {
            fans.union(f, corner);
        }
        None => *first = Some(corner),
    }
}

#[cfg(test)]
mod tests {
    use super::fan_counts;
    use crate::topology::edges::EdgeTable;

    #[test]
    fn closed_fan_open_fan_and_two_fans() {
        // A tetrahedron: every vertex has one closed fan.
        let tet: &[[u32; 3]] = &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        assert_eq!(
            fan_counts(tet, &EdgeTable::build(tet), 5),
            vec![1, 1, 1, 1, 0]
        );

        // Two triangles touching at vertex 0 only: two open fans there.
        let bowtie: &[[u32; 3]] = &[[0, 1, 2], [0, 3, 4]];
        let counts = fan_counts(bowtie, &EdgeTable::build(bowtie), 5);
        assert_eq!(counts, vec![2, 1, 1, 1, 1]);
    }
}
