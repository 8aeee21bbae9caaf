//! The undirected edge table.
//!
//! Faces are seen as loops of *corners*: corner `c` sits at vertex `origin(c)` and its face's
//! directed edge runs from `c` to corner `next(c)`. Every directed edge is keyed by its unordered
//! vertex pair and the table is sorted by key, so the corners whose edges share an undirected edge
//! are adjacent. Sorting is O(n log n), parallel and deterministic (keys are unique).
//!
//! Both the topology report (triangles) and the half-edge builder (polygons) use this table.

use rayon::prelude::*;

/// Faces as loops of corners, indexed `0..corner_count()`.
pub(crate) trait CornerLoops: Sync {
    /// Number of corners (= number of directed face edges).
    fn corner_count(&self) -> usize;
    /// The vertex of corner `corner`.
    fn origin(&self, corner: usize) -> u32;
    /// The next corner around the same face.
    fn next(&self, corner: usize) -> usize;
    /// The vertex the directed edge leaving `corner` points to.
    fn dest(&self, corner: usize) -> u32 {
        self.origin(self.next(corner))
    }
}

impl CornerLoops for [[u32; 3]] {
    fn corner_count(&self) -> usize {
        self.len() * 3
    }

    fn origin(&self, corner: usize) -> u32 {
        self[corner / 3][corner % 3]
    }

    fn next(&self, corner: usize) -> usize {
        if corner % 3 == 2 {
            corner - 2
        } else {
            corner + 1
        }
    }
}

/// How an undirected edge is used by the faces around it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum EdgeKind {
    /// Used by exactly one face.
    Boundary,
    /// Used by two faces in opposite directions.
    Manifold,
    /// Used by two faces in the same direction (one of them is flipped).
    Inconsistent,
    /// Used by more than two faces.
    NonManifold,
}

/// The key of the undirected edge `{a, b}`: smaller vertex in the high half.
fn edge_key(a: u32, b: u32) -> u64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    (u64::from(lo) << 32) | u64::from(hi)
}

/// The directed edges of all faces, sorted by undirected key.
#[derive(Debug, Clone)]
pub(crate) struct EdgeTable {
    entries: Vec<(u64, usize)>,
    edge_count: usize,
}

impl EdgeTable {
    /// The table of every corner's outgoing edge.
    pub(crate) fn build<C: CornerLoops + ?Sized>(loops: &C) -> Self {
        let mut entries: Vec<(u64, usize)> = (0..loops.corner_count())
            .into_par_iter()
            .map(|c| (edge_key(loops.origin(c), loops.dest(c)), c))
            .collect();
        entries.par_sort_unstable();
        let edge_count = entries.chunk_by(|a, b| a.0 == b.0).count();
        Self {
            entries,
            edge_count,
        }
    }

    /// Number of undirected edges.
    pub(crate) fn edge_count(&self) -> usize {
        self.edge_count
    }

    /// The undirected edges in ascending key order.
    pub(crate) fn edges(&self) -> impl Iterator<Item = Edge<'_>> {
        self.entries
            .chunk_by(|a, b| a.0 == b.0)
            .map(|run| Edge { run })
    }
}

/// One undirected edge: the corners whose outgoing edge it is, in ascending corner order.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Edge<'a> {
    run: &'a [(u64, usize)],
}

impl Edge<'_> {
    /// The two vertices, smaller first.
    pub(crate) fn vertices(&self) -> [u32; 2] {
        let key = self.run[0].0;
        [(key >> 32) as u32, key as u32]
    }

    /// The corners whose outgoing edge this is (one per face use).
    pub(crate) fn corners(&self) -> impl Iterator<Item = usize> + '_ {
        self.run.iter().map(|&(_, c)| c)
    }

    /// The lowest corner using this edge.
    pub(crate) fn first_corner(&self) -> usize {
        self.run[0].1
    }

    /// How the faces use this edge.
    pub(crate) fn kind<C: CornerLoops + ?Sized>(&self, loops: &C) -> EdgeKind {
        match self.run {
            [_] => EdgeKind::Boundary,
            [(_, a), (_, b)] if loops.origin(*a) == loops.origin(*b) => EdgeKind::Inconsistent,
            [_, _] => EdgeKind::Manifold,
            _ => EdgeKind::NonManifold,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{CornerLoops, EdgeKind, EdgeTable};

    #[test]
    fn triangle_corners_cycle() {
        let tris: &[[u32; 3]] = &[[4, 5, 6], [7, 8, 9]];
        assert_eq!(tris.corner_count(), 6);
        assert_eq!(tris.next(2), 0);
        assert_eq!(tris.next(3), 4);
        assert_eq!(tris.dest(5), 7);
    }

    #[test]
    fn two_triangles_share_one_edge() {
        let tris: &[[u32; 3]] = &[[0, 1, 2], [2, 1, 3]];
        let table = EdgeTable::build(tris);
        assert_eq!(table.edge_count(), 5);
        let kinds: Vec<([u32; 2], EdgeKind)> = table
            .edges()
            .map(|e| (e.vertices(), e.kind(tris)))
            .collect();
        assert_eq!(
            kinds,
            vec![
                ([0, 1], EdgeKind::Boundary),
                ([0, 2], EdgeKind::Boundary),
                ([1, 2], EdgeKind::Manifold),
                ([1, 3], EdgeKind::Boundary),
                ([2, 3], EdgeKind::Boundary),
            ]
        );
    }

    #[test]
    fn same_direction_is_inconsistent_and_three_uses_non_manifold() {
        let flipped: &[[u32; 3]] = &[[0, 1, 2], [1, 2, 3]];
        let shared = EdgeTable::build(flipped);
        let edge = shared.edges().find(|e| e.vertices() == [1, 2]).unwrap();
        assert_eq!(edge.kind(flipped), EdgeKind::Inconsistent);

        let fin: &[[u32; 3]] = &[[0, 1, 2], [1, 0, 3], [0, 1, 4]];
        let table = EdgeTable::build(fin);
        let edge = table.edges().find(|e| e.vertices() == [0, 1]).unwrap();
        assert_eq!(edge.corners().count(), 3);
        assert_eq!(edge.kind(fin), EdgeKind::NonManifold);
    }
}
