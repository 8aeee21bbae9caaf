//! Vertex stars: the triangles around every vertex, each as the pair of its other two vertices.
//!
//! Triangle `[v, b, a]` (in its winding order) is filed under each of its three vertices; under
//! `v` it is stored as `[b, a]`: `v → b` is the triangle's edge leaving `v` and `a → v` the edge
//! entering it. Everything the report asks of an edge `{v, x}` or of the fan around `v` can then be
//! answered from `v`'s star alone (`topology/local.rs`), in parallel over vertices, and the
//! self-intersection test certifies embedded fans from it (`intersect/fans.rs`); the report
//! builds the stars once for both.
//!
//! Built by a counting sort into one array (eight bytes per corner, no hashing). The work is
//! split into vertex ranges; each range scans every triangle and fills only its own stars, so no
//! two threads write one place and each star lists its triangles in ascending triangle order
//! whatever the thread count (the result is deterministic).

use std::borrow::Cow;

use rayon::prelude::*;

use crate::IndexedMesh;
use crate::intersect::is_usable;

/// The usable triangles (see [`is_usable`]), borrowed when all are.
pub(crate) fn usable_triangles(mesh: &IndexedMesh) -> Cow<'_, [[u32; 3]]> {
    let n = mesh.positions.len();
    if mesh.triangles.par_iter().all(|t| is_usable(t, n)) {
        Cow::Borrowed(&mesh.triangles)
    } else {
        Cow::Owned(
            mesh.triangles
                .iter()
                .filter(|t| is_usable(t, n))
                .copied()
                .collect(),
        )
    }
}

/// The star of every vertex `0..vertex_count`.
#[derive(Debug, Clone)]
pub(crate) struct Stars {
    /// Start of each vertex's star in `links` (vertex count + 1 entries).
    starts: Vec<usize>,
    /// `[next, previous]` vertex of each corner, star by star.
    links: Vec<[u32; 2]>,
}

impl Stars {
    /// The stars of `triangles` (usable: indices below `vertex_count` and distinct).
    pub(crate) fn build(triangles: &[[u32; 3]], vertex_count: usize) -> Self {
        let ranges = vertex_ranges(vertex_count);
        let mut counts = vec![0usize; vertex_count];
        let mut count_pieces = split_by(&mut counts, &ranges, |r| r.start);
        count_pieces
            .par_iter_mut()
            .zip(&ranges)
            .for_each(|(piece, range)| {
                for &v in triangles.as_flattened() {
                    if range.contains(&(v as usize)) {
                        piece[v as usize - range.start] += 1;
                    }
                }
            });
        let mut starts = Vec::with_capacity(vertex_count + 1);
        let mut total = 0;
        starts.push(0);
        for c in counts {
            total += c;
            starts.push(total);
        }
        let mut links = vec![[0u32; 2]; total];
        let mut cursors = starts[..vertex_count].to_vec();
        let link_pieces = split_by(&mut links, &ranges, |r| starts[r.start]);
        let cursor_pieces = split_by(&mut cursors, &ranges, |r| r.start);
        link_pieces
            .into_par_iter()
            .zip(cursor_pieces)
            .zip(&ranges)
            .for_each(|((links, cursors), range)| {
                let base = starts[range.start];
                for tri in triangles {
                    for k in 0..3 {
                        let v = tri[k] as usize;
                        if range.contains(&v) {
                            let slot = &mut cursors[v - range.start];
                            links[*slot - base] = [tri[(k + 1) % 3], tri[(k + 2) % 3]];
                            *slot += 1;
                        }
                    }
                }
            });
        Self { starts, links }
    }

    /// Number of vertices (stars, some empty).
    pub(crate) fn vertex_count(&self) -> usize {
        self.starts.len() - 1
    }

    /// The star of `v`: `[next, previous]` for each triangle at `v`, in triangle order.
    pub(crate) fn of(&self, v: usize) -> &[[u32; 2]] {
        &self.links[self.starts[v]..self.starts[v + 1]]
    }

    /// True when some triangle uses `v`.
    pub(crate) fn is_referenced(&self, v: usize) -> bool {
        self.starts[v + 1] > self.starts[v]
    }
}

/// Vertex ranges, one per piece of work and thread, so the scans over all triangles that each
/// range makes stay few.
fn vertex_ranges(vertex_count: usize) -> Vec<std::ops::Range<usize>> {
    let pieces = rayon::current_num_threads().min(vertex_count.max(1));
    (0..pieces)
        .map(|i| vertex_count * i / pieces..vertex_count * (i + 1) / pieces)
        .collect()
}

/// `items` cut into consecutive mutable pieces, piece `i` starting at `start(&ranges[i])`
/// (ascending) and ending where the next starts.
fn split_by<'a, T>(
    items: &'a mut [T],
    ranges: &[std::ops::Range<usize>],
    start: impl Fn(&std::ops::Range<usize>) -> usize,
) -> Vec<&'a mut [T]> {
    let mut pieces = Vec::with_capacity(ranges.len());
    let mut rest = items;
    let mut at = ranges.first().map_or(0, &start);
    for next in ranges.iter().skip(1).map(&start).chain([at + rest.len()]) {
        let (piece, tail) = rest.split_at_mut(next - at);
        pieces.push(piece);
        rest = tail;
        at = next;
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::Stars;

    #[test]
    fn each_triangle_is_filed_under_its_three_vertices_in_triangle_order() {
        let tris = [[0, 1, 2], [2, 1, 3], [4, 0, 2]];
        for threads in [1, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let stars = pool.install(|| Stars::build(&tris, 6));
            assert_eq!(stars.vertex_count(), 6);
            assert_eq!(stars.of(0), &[[1, 2], [2, 4]]);
            assert_eq!(stars.of(1), &[[2, 0], [3, 2]]);
            assert_eq!(stars.of(2), &[[0, 1], [1, 3], [4, 0]]);
            assert_eq!(stars.of(3), &[[2, 1]]);
            assert_eq!(stars.of(4), &[[0, 2]]);
            assert!(stars.of(5).is_empty() && !stars.is_referenced(5));
        }
    }
}
