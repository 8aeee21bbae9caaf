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
    ///
    /// `starts` first holds each vertex's count, then (per range, in parallel, then shifted by the
    /// ranges before) where its star ends; the fill walks the triangles backwards and moves each
    /// end down by one per triangle, so every end becomes its star's start, each star ascending in
    /// triangle order. No other array of vertex size.
    pub(crate) fn build(triangles: &[[u32; 3]], vertex_count: usize) -> Self {
        let ranges = vertex_ranges(vertex_count);
        let mut starts = vec![0usize; vertex_count + 1];
        let firsts: Vec<usize> = ranges.iter().map(|r| r.start).collect();
        let mut pieces = split_at(&mut starts[..vertex_count], &firsts);
        let totals: Vec<usize> = pieces
            .par_iter_mut()
            .zip(&ranges)
            .map(|(piece, range)| {
                for &v in triangles.as_flattened() {
                    if range.contains(&(v as usize)) {
                        piece[v as usize - range.start] += 1;
                    }
                }
                let mut end = 0;
                for count in piece.iter_mut() {
                    end += *count;
                    *count = end;
                }
                end
            })
            .collect();
        let bases: Vec<usize> = totals
            .iter()
            .scan(0, |sum, &t| {
                let base = *sum;
                *sum += t;
                Some(base)
            })
            .collect();
        let total: usize = totals.iter().sum();
        pieces
            .par_iter_mut()
            .zip(&bases)
            .for_each(|(piece, &base)| piece.iter_mut().for_each(|end| *end += base));
        let mut links = vec![[0u32; 2]; total];
        let link_pieces = split_at(&mut links, &bases);
        link_pieces
            .into_par_iter()
            .zip(pieces)
            .zip(ranges.par_iter().zip(&bases))
            .for_each(|((links, ends), (range, &base))| {
                for tri in triangles.iter().rev() {
                    for k in 0..3 {
                        let v = tri[k] as usize;
                        if range.contains(&v) {
                            let end = &mut ends[v - range.start];
                            *end -= 1;
                            links[*end - base] = [tri[(k + 1) % 3], tri[(k + 2) % 3]];
                        }
                    }
                }
            });
        starts[vertex_count] = total;
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

/// `items` cut into consecutive mutable pieces, piece `i` from `firsts[i] - firsts[0]` to where
/// the next starts (`firsts` ascending, every difference within `items`).
pub(crate) fn split_at<'a, T>(items: &'a mut [T], firsts: &[usize]) -> Vec<&'a mut [T]> {
    let mut pieces = Vec::with_capacity(firsts.len());
    let mut rest = items;
    let mut at = firsts.first().copied().unwrap_or(0);
    for next in firsts.iter().skip(1).copied().chain([at + rest.len()]) {
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
