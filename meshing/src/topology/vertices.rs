//! Vertex fans: how many edge-connected groups the faces around each vertex form.
//!
//! The corners at a vertex `v` are joined when their faces share an edge incident to `v` (through
//! any number of faces, so a non-manifold edge joins all its faces). A manifold vertex has exactly
//! one group (a closed disk or an open fan); two cones touching at a tip, or two boundary loops
//! passing through one vertex, give two or more. Computed with a concurrent union-find over
//! corners, in parallel over the edge table's vertex buckets.

use super::atomic_union_find::AtomicUnionFind;
use super::edges::{CornerLoops, EdgeTable};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU32, Ordering};

/// For every vertex `0..vertex_count`, the number of face groups around it (0 when unused).
///
/// Every corner's vertex must be below `vertex_count`.
pub(crate) fn fan_counts<C: CornerLoops + ?Sized>(
    loops: &C,
    table: &EdgeTable,
    vertex_count: usize,
) -> Vec<u32> {
    // In parallel over the edge table's vertex buckets: the corners at each end of an edge are
    // joined to the first corner at that end.
    let fans = AtomicUnionFind::new(loops.corner_count());
    (0..table.bucket_count())
        .into_par_iter()
        .with_min_len(1024)
        .for_each(|v| {
            for edge in table.edges_at(v) {
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
                    join(&fans, &mut at_lo_first, at_lo);
                    join(&fans, &mut at_hi_first, at_hi);
                }
            }
        });
    let counts: Vec<AtomicU32> = (0..vertex_count).map(|_| AtomicU32::new(0)).collect();
    (0..loops.corner_count())
        .into_par_iter()
        .with_min_len(4096)
        .filter(|&corner| fans.is_root(corner))
        .for_each(|corner| {
            counts[loops.origin(corner) as usize].fetch_add(1, Ordering::Relaxed);
        });
    counts.into_iter().map(AtomicU32::into_inner).collect()
}

fn join(fans: &AtomicUnionFind, first: &mut Option<usize>, corner: usize) {
    match *first {
        Some(f) => fans.union(f, corner),
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
