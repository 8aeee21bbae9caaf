//! Vertex stars: the triangles around every vertex, each as the pair of its other two vertices.
//!
//! Triangle `[v, b, a]` (in its winding order) is filed under each of its three vertices; under
//! `v` it is stored as `[b, a]`: `v → b` is the triangle's edge leaving `v` and `a → v` the edge
//! entering it. Everything the report asks of an edge `{v, x}` or of the fan around `v` can then be
//! answered from `v`'s star alone (`topology/local.rs`), in parallel over vertices, and the
//! self-intersection test certifies embedded fans from it (`intersect/fans.rs`); the report
//! builds the stars once for both (without the test it takes them a window of vertices at a time
//! instead, `crate::window_stars`).
//!
//! Built by a counting sort into one array (eight bytes per corner, no hashing). The work is
//! split into vertex ranges; each range scans the triangles that may use it (the chunks whose
//! vertex span meets the range) and fills only its own stars, so no two threads write one place
//! and each star lists its triangles in ascending triangle order whatever the thread count (the
//! result is deterministic).

use rayon::prelude::*;

use crate::pieces::split_at;

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
        let spans = chunk_spans(triangles, ranges.len());
        // The chunks of triangles that may use a vertex of `range`, with their numbers.
        let chunks_for = |range: &std::ops::Range<usize>| {
            let (lo, hi) = (range.start as u32, range.end as u32);
            triangles
                .chunks(CHUNK)
                .zip(&spans)
                .filter(move |&(_, &(min, max))| max >= lo && min < hi)
                .map(|(c, _)| c)
        };
        let mut starts = vec![0usize; vertex_count + 1];
        let firsts: Vec<usize> = ranges.iter().map(|r| r.start).collect();
        let mut pieces = split_at(&mut starts[..vertex_count], &firsts);
        let totals: Vec<usize> = pieces
            .par_iter_mut()
            .zip(&ranges)
            .map(|(piece, range)| {
                for chunk in chunks_for(range) {
                    for &v in chunk.as_flattened() {
                        if range.contains(&(v as usize)) {
                            piece[v as usize - range.start] += 1;
                        }
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
                let chunks: Vec<&[[u32; 3]]> = chunks_for(range).collect();
                for chunk in chunks.iter().rev() {
                    for tri in chunk.iter().rev() {
                        for k in 0..3 {
                            let v = tri[k] as usize;
                            if range.contains(&v) {
                                let end = &mut ends[v - range.start];
                                *end -= 1;
                                links[*end - base] = [tri[(k + 1) % 3], tri[(k + 2) % 3]];
                            }
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

/// Triangles per chunk of [`chunk_spans`].
const CHUNK: usize = 1 << 14;

/// The lowest and highest vertex of each chunk of [`CHUNK`] triangles, so that a vertex range
/// scans only the chunks that may use it: meshers number vertices and triangles in the same
/// spatial order, so each range meets few chunks (a mesh in random order meets them all, as
/// without the spans). With one range every chunk is scanned anyway and none is computed.
fn chunk_spans(triangles: &[[u32; 3]], ranges: usize) -> Vec<(u32, u32)> {
    if ranges < 2 {
        return vec![(0, u32::MAX); triangles.len().div_ceil(CHUNK)];
    }
    triangles
        .par_chunks(CHUNK)
        .map(|c| {
            c.as_flattened()
                .iter()
                .fold((u32::MAX, 0), |(lo, hi), &v| (lo.min(v), hi.max(v)))
        })
        .collect()
}

/// Vertex ranges, one per piece of work and thread, so the scans over all triangles that each
/// range makes stay few.
fn vertex_ranges(vertex_count: usize) -> Vec<std::ops::Range<usize>> {
    let pieces = rayon::current_num_threads().min(vertex_count.max(1));
    (0..pieces)
        .map(|i| vertex_count * i / pieces..vertex_count * (i + 1) / pieces)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{CHUNK, Stars};

    #[test]
    fn stars_over_many_chunks_match_a_direct_filing() {
        // Three parts: vertices in triangle order (each range meets few chunks), at random (every
        // chunk), and in reverse order; several chunks each.
        let n = 3 * CHUNK + 77;
        let vertex_count = 40_000;
        let mut seed = 7u64;
        let mut random = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            (seed >> 33) as u32 % vertex_count as u32
        };
        let mut tris = Vec::new();
        for i in 0..n {
            let v = (i * vertex_count / n) as u32;
            let local = [
                v,
                (v + 1) % vertex_count as u32,
                (v + 2) % vertex_count as u32,
            ];
            tris.push(if i < n / 3 {
                local
            } else if i < 2 * n / 3 {
                [random(), random(), random()]
            } else {
                local.map(|x| vertex_count as u32 - 1 - x)
            });
        }
        tris.retain(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
        let mut direct = vec![Vec::new(); vertex_count];
        for t in &tris {
            for k in 0..3 {
                direct[t[k] as usize].push([t[(k + 1) % 3], t[(k + 2) % 3]]);
            }
        }
        for threads in [1, 2, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let stars = pool.install(|| Stars::build(&tris, vertex_count));
            for (v, star) in direct.iter().enumerate() {
                assert_eq!(
                    stars.of(v),
                    star.as_slice(),
                    "vertex {v}, {threads} threads"
                );
            }
        }
    }

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
