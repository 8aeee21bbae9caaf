//! Vertex stars a window of vertices at a time, with no array for the whole mesh's stars.
//!
//! [`crate::stars::Stars`] files every corner of the mesh into one array (eight bytes per corner,
//! 88 MB for 3.7 M triangles) that is written once, read once and freed: on a fresh process most
//! of its cost is the kernel handing out and taking back its pages. When nothing else needs the
//! stars (the report without a self-intersection test), the vertex pass instead takes the stars of
//! one window of [`WindowPlan::window`] consecutive vertices at a time into a buffer of its
//! thread, which it reuses for the next window, and analyses them while they are in cache.
//!
//! A window finds its corners by scanning the chunks of [`CHUNK`] triangles that may use its
//! vertices. Meshers number vertices and triangles in the same spatial order, so a chunk's
//! vertices lie near its *anchor* (the median of a few sampled corners) and each chunk meets one
//! or two windows. The corners of a chunk further than four windows from its anchor (marching
//! cubes numbers the centre vertices of its fanned cells last) are *strays*: listed
//! once, by window, and filed from that list. A mesh in no spatial order has strays everywhere:
//! when they are more than an eighth of the corners (or the mesh has 2³² corners or more),
//! [`WindowPlan::new`] declines and the caller builds the global stars instead.
//!
//! A star lists the same `[next, previous]` pairs as [`crate::stars::Stars`], chunk corners in
//! triangle order, then strays in triangle order. Which corners are strays depends on the window
//! size, and so on the thread count, so the order within a star can differ between thread counts;
//! nothing the vertex pass finds depends on it (it counts and joins, and lists examples in
//! ascending order).

use std::ops::Range;

use rayon::prelude::*;

/// Triangles per chunk.
pub(crate) const CHUNK: usize = 1 << 10;

/// A chunk's anchor and the span of its vertices near the anchor.
#[derive(Debug, Clone, Copy)]
struct Chunk {
    anchor: u32,
    min: u32,
    max: u32,
}

/// A corner filed apart from its chunk: its vertex and `[next, previous]`.
type Stray = (u32, [u32; 2]);

/// Which chunks and strays each window of vertices takes its stars from.
#[derive(Debug)]
pub(crate) struct WindowPlan {
    vertex_count: usize,
    window: usize,
    reach: u32,
    chunks: Vec<Chunk>,
    /// Chunk numbers by window (`chunk_starts[w]..chunk_starts[w + 1]`).
    chunk_starts: Vec<usize>,
    chunk_list: Vec<u32>,
    /// Strays by window (`stray_starts[w]..stray_starts[w + 1]`).
    stray_starts: Vec<usize>,
    strays: Vec<Stray>,
}

/// A thread's reusable buffers: the stars of its current window.
#[derive(Debug, Default)]
pub(crate) struct WindowStars {
    first: usize,
    starts: Vec<u32>,
    cursor: Vec<u32>,
    links: Vec<[u32; 2]>,
}

impl WindowStars {
    /// The star of vertex `v` of the current window.
    pub(crate) fn of(&self, v: usize) -> &[[u32; 2]] {
        let i = v - self.first;
        &self.links[self.starts[i] as usize..self.starts[i + 1] as usize]
    }
}

impl WindowPlan {
    /// The plan for `triangles` (usable: indices below `vertex_count` and distinct), or `None`
    /// when the triangles are in too little spatial order (see the module docs).
    pub(crate) fn new(triangles: &[[u32; 3]], vertex_count: usize) -> Option<Self> {
        // A window's star offsets are `u32`: its corners must number below 2³², which every
        // window's do when the whole mesh's do (the global stars count in `usize`).
        if triangles.len() > u32::MAX as usize / 3 {
            return None;
        }
        // Windows small enough to keep their stars in cache (about six corners per vertex) and
        // several per thread, for balance; the reach covers a chunk's usual spread.
        let threads = rayon::current_num_threads().max(1);
        let window = (vertex_count / (4 * threads)).clamp(1 << 12, 1 << 17);
        let reach = u32::try_from(4 * window).unwrap_or(u32::MAX);
        let chunks: Vec<(Chunk, Vec<Stray>)> = triangles
            .par_chunks(CHUNK)
            .map(|c| survey_chunk(c, reach))
            .collect();
        let stray_count: usize = chunks.iter().map(|(_, s)| s.len()).sum();
        if stray_count > 3 * triangles.len() / 8 {
            return None;
        }
        let windows = vertex_count.div_ceil(window).max(1);
        let (chunks, strays): (Vec<Chunk>, Vec<Vec<Stray>>) = chunks.into_iter().unzip();
        // Chunk lists by window: a counting sort over the windows each chunk's span meets.
        let span = |c: &Chunk| c.min as usize / window..=c.max as usize / window;
        let mut chunk_starts = vec![0usize; windows + 1];
        for c in &chunks {
            for w in span(c) {
                chunk_starts[w + 1] += 1;
            }
        }
        prefix_sums(&mut chunk_starts);
        let mut chunk_list = vec![0u32; chunk_starts[windows]];
        let mut fill = chunk_starts.clone();
        for (i, c) in chunks.iter().enumerate() {
            for w in span(c) {
                chunk_list[fill[w]] = i as u32;
                fill[w] += 1;
            }
        }
        // Strays by window, in triangle order within each.
        let mut stray_starts = vec![0usize; windows + 1];
        for &(v, _) in strays.iter().flatten() {
            stray_starts[v as usize / window + 1] += 1;
        }
        prefix_sums(&mut stray_starts);
        let mut fill = stray_starts.clone();
        let mut sorted = vec![(0u32, [0u32; 2]); stray_count];
        for &s in strays.iter().flatten() {
            let w = s.0 as usize / window;
            sorted[fill[w]] = s;
            fill[w] += 1;
        }
        Some(Self {
            vertex_count,
            window,
            reach,
            chunks,
            chunk_starts,
            chunk_list,
            stray_starts,
            strays: sorted,
        })
    }

    /// Vertices per window.
    pub(crate) fn window(&self) -> usize {
        self.window
    }

    /// The vertices of window `w`.
    pub(crate) fn vertices(&self, w: usize) -> Range<usize> {
        let first = w * self.window;
        first..(first + self.window).min(self.vertex_count)
    }

    /// Files the stars of window `w`'s vertices into `out` (the window's previous stars are
    /// dropped, its buffers kept).
    pub(crate) fn stars(&self, w: usize, triangles: &[[u32; 3]], out: &mut WindowStars) {
        let range = self.vertices(w);
        let lo = range.start as u32;
        let chunks = &self.chunk_list[self.chunk_starts[w]..self.chunk_starts[w + 1]];
        let strays = &self.strays[self.stray_starts[w]..self.stray_starts[w + 1]];
        let n = range.len();
        out.first = range.start;
        out.starts.clear();
        out.starts.resize(n + 1, 0);
        let starts = &mut out.starts;
        self.corners(chunks, triangles, range.clone(), |v, _, _| {
            starts[v as usize + 1] += 1;
        });
        for &(v, _) in strays {
            starts[(v - lo) as usize + 1] += 1;
        }
        let mut sum = 0;
        for s in starts.iter_mut() {
            sum += *s;
            *s = sum;
        }
        out.cursor.clear();
        out.cursor.extend_from_slice(&starts[..n]);
        // Grown only: every place below `sum` is written before it is read.
        if out.links.len() < sum as usize {
            out.links.resize(sum as usize, [0; 2]);
        }
        let (cursor, links) = (&mut out.cursor, &mut out.links);
        self.corners(chunks, triangles, range, |v, tri, k| {
            let at = &mut cursor[v as usize];
            links[*at as usize] = [tri[(k + 1) % 3], tri[(k + 2) % 3]];
            *at += 1;
        });
        for &(v, link) in strays {
            let at = &mut cursor[(v - lo) as usize];
            links[*at as usize] = link;
            *at += 1;
        }
    }
}

impl WindowPlan {
    /// Calls `visit(v - range.start, triangle, k)` for every corner `k` of the `chunks` whose
    /// vertex `v` lies in `range` and near its chunk's anchor.
    fn corners(
        &self,
        chunks: &[u32],
        triangles: &[[u32; 3]],
        range: Range<usize>,
        mut visit: impl FnMut(u32, &[u32; 3], usize),
    ) {
        let (lo, hi) = (range.start as u32, range.end as u32);
        for &c in chunks {
            let c = c as usize;
            let anchor = self.chunks[c].anchor;
            let end = ((c + 1) * CHUNK).min(triangles.len());
            for tri in &triangles[c * CHUNK..end] {
                for (k, &v) in tri.iter().enumerate() {
                    if v >= lo && v < hi && v.abs_diff(anchor) <= self.reach {
                        visit(v - lo, tri, k);
                    }
                }
            }
        }
    }
}

/// A chunk's anchor (the median of eight sampled corners), the span of its corners within
/// `reach` of it, and its strays (the other corners).
fn survey_chunk(triangles: &[[u32; 3]], reach: u32) -> (Chunk, Vec<Stray>) {
    let corners = triangles.as_flattened();
    let mut sample: [u32; 8] = std::array::from_fn(|i| corners[i * corners.len() / 8]);
    sample.sort_unstable();
    let anchor = sample[4];
    let mut chunk = Chunk {
        anchor,
        min: anchor,
        max: anchor,
    };
    let mut strays = Vec::new();
    for tri in triangles {
        for (k, &v) in tri.iter().enumerate() {
            if v.abs_diff(anchor) <= reach {
                chunk.min = chunk.min.min(v);
                chunk.max = chunk.max.max(v);
            } else {
                strays.push((v, [tri[(k + 1) % 3], tri[(k + 2) % 3]]));
            }
        }
    }
    (chunk, strays)
}

/// Turns counts at `1..` into running sums (`s[0]` stays 0).
fn prefix_sums(s: &mut [usize]) {
    for i in 1..s.len() {
        s[i] += s[i - 1];
    }
}

#[cfg(test)]
mod tests {
    use super::{CHUNK, WindowPlan, WindowStars};
    use crate::stars::Stars;

    /// Triangles in spatial order with some far corners (like marching cubes' centre vertices).
    fn ordered(n: usize, vertex_count: u32, far_every: usize) -> Vec<[u32; 3]> {
        (0..n)
            .map(|i| {
                let v = (i as u64 * u64::from(vertex_count - 3) / n as u64) as u32;
                let far = vertex_count - 1 - (i as u32 % 7);
                if i % far_every == 0 && far > v + 2 {
                    [v, far, v + 1]
                } else {
                    [v, v + 1, v + 2]
                }
            })
            .collect()
    }

    fn assert_same_stars(tris: &[[u32; 3]], vertex_count: usize, threads: usize) {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let stars = Stars::build(tris, vertex_count);
            let plan = WindowPlan::new(tris, vertex_count).expect("ordered triangles");
            assert_eq!(
                plan.strays.is_empty(),
                tris.len() < 10,
                "far corners are strays"
            );
            let mut out = WindowStars::default();
            let windows = vertex_count.div_ceil(plan.window());
            for w in 0..windows {
                plan.stars(w, tris, &mut out);
                for v in plan.vertices(w) {
                    let mut a = out.of(v).to_vec();
                    let mut b = stars.of(v).to_vec();
                    a.sort_unstable();
                    b.sort_unstable();
                    assert_eq!(a, b, "vertex {v}, {threads} threads");
                }
            }
        });
    }

    #[test]
    fn window_stars_hold_the_same_corners_as_the_global_stars() {
        // Sparse vertices, so that the far ones lie beyond every window's reach.
        let vertex_count = 2_000_000;
        let tris = ordered(20 * CHUNK + 5, vertex_count as u32, 37);
        for threads in [1, 2, 3] {
            assert_same_stars(&tris, vertex_count, threads);
        }
        // A few triangles: one window.
        assert_same_stars(&[[0, 1, 2], [2, 1, 3], [4, 0, 2]], 6, 2);
    }

    #[test]
    fn triangles_in_no_order_are_declined() {
        let vertex_count = 1_000_000u32;
        let mut seed = 11u64;
        let mut random = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            (seed >> 33) as u32 % vertex_count
        };
        let tris: Vec<[u32; 3]> = (0..8 * CHUNK)
            .map(|_| [random(), random(), random()])
            .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
            .collect();
        assert!(WindowPlan::new(&tris, vertex_count as usize).is_none());
    }
}
