//! The undirected edge table.
//!
//! Faces are seen as loops of *corners*: corner `c` sits at vertex `origin(c)` and its face's
//! directed edge runs from `c` to corner `next(c)`. Every directed edge is filed under the smaller
//! of its two vertices (a counting sort into per-vertex buckets, linear time), then each small
//! bucket is sorted by the other vertex and the corner, so the corners whose edges share an
//! undirected edge are adjacent, in ascending (smaller, larger) vertex order. Eight bytes per
//! corner; deterministic; supports up to 2³² corners.
//!
//! The half-edge builder (polygons) and the repair use this table; the report uses vertex stars
//! (`crate::stars`).

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

/// The directed edges of all faces, grouped by undirected edge.
#[derive(Debug, Clone)]
pub(crate) struct EdgeTable {
    /// Start of each vertex's bucket in `entries` (vertex count + 1 entries).
    starts: Vec<usize>,
    /// `larger vertex << 32 | corner`, bucket by bucket, each bucket sorted.
    entries: Vec<u64>,
}

impl EdgeTable {
    /// The table of every corner's outgoing edge.
    pub(crate) fn build<C: CornerLoops + ?Sized>(loops: &C) -> Self {
        let n = loops.corner_count();
        assert!(
            n <= u32::MAX as usize,
            "edge table supports at most 2^32 corners"
        );
        let vertex_count = (0..n)
            .into_par_iter()
            .map(|c| loops.origin(c) as usize + 1)
            .max()
            .unwrap_or(0);
        let mut starts = vec![0usize; vertex_count + 1];
        for c in 0..n {
            starts[loops.origin(c).min(loops.dest(c)) as usize + 1] += 1;
        }
        for v in 0..vertex_count {
            starts[v + 1] += starts[v];
        }
        let mut cursor = starts.clone();
        let mut entries = vec![0u64; n];
        for c in 0..n {
            let (a, b) = (loops.origin(c), loops.dest(c));
            let slot = &mut cursor[a.min(b) as usize];
            entries[*slot] = (u64::from(a.max(b)) << 32) | c as u64;
            *slot += 1;
        }
        sort_buckets(&mut entries, &starts);
        Self { starts, entries }
    }

    /// Number of vertex buckets (one past the largest vertex of any edge).
    pub(crate) fn bucket_count(&self) -> usize {
        self.starts.len() - 1
    }

    /// The undirected edges whose smaller vertex is `v`, in ascending larger-vertex order.
    pub(crate) fn edges_at(&self, v: usize) -> impl Iterator<Item = Edge<'_>> {
        self.entries[self.starts[v]..self.starts[v + 1]]
            .chunk_by(|x, y| x >> 32 == y >> 32)
            .map(move |run| Edge { lo: v as u32, run })
    }

    /// The undirected edges in ascending (smaller, larger) vertex order.
    pub(crate) fn edges(&self) -> impl Iterator<Item = Edge<'_>> {
        (0..self.bucket_count()).flat_map(move |v| self.edges_at(v))
    }
}

/// Sorts every bucket, in parallel over groups of buckets.
fn sort_buckets(entries: &mut [u64], starts: &[usize]) {
    const GROUP: usize = 1 << 14;
    let mut pieces: Vec<&mut [u64]> = Vec::new();
    let mut rest = entries;
    let mut at = 0;
    for g in (0..starts.len() - 1).step_by(GROUP) {
        let end = starts[(g + GROUP).min(starts.len() - 1)];
        let (piece, tail) = rest.split_at_mut(end - at);
        pieces.push(piece);
        rest = tail;
        at = end;
    }
    pieces.into_par_iter().enumerate().for_each(|(i, piece)| {
        let first = i * GROUP;
        let base = starts[first];
        for v in first..(first + GROUP).min(starts.len() - 1) {
            piece[starts[v] - base..starts[v + 1] - base].sort_unstable();
        }
    });
}

/// One undirected edge: the corners whose outgoing edge it is, in ascending corner order.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Edge<'a> {
    lo: u32,
    run: &'a [u64],
}

impl Edge<'_> {
    /// The two vertices, smaller first.
    pub(crate) fn vertices(&self) -> [u32; 2] {
        [self.lo, (self.run[0] >> 32) as u32]
    }

    /// The corners whose outgoing edge this is (one per face use).
    pub(crate) fn corners(&self) -> impl Iterator<Item = usize> + '_ {
        self.run.iter().map(|&e| (e & 0xFFFF_FFFF) as usize)
    }

    /// How the faces use this edge.
    pub(crate) fn kind<C: CornerLoops + ?Sized>(&self, loops: &C) -> EdgeKind {
        let corner = |e: u64| (e & 0xFFFF_FFFF) as usize;
        match self.run {
            [_] => EdgeKind::Boundary,
            [a, b] if loops.origin(corner(*a)) == loops.origin(corner(*b)) => {
                EdgeKind::Inconsistent
            }
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
        assert_eq!(table.edges().count(), 5);
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
