//! The vertex pass of the report: every vertex's star analysed (`local.rs`) in parallel chunks,
//! the ends of every edge joined into shells, and the counts and first examples of each defect
//! kind gathered in vertex order.
//!
//! The stars come from the whole mesh's [`Stars`] when the self-intersection test needs them too
//! ([`Survey::of`]), else a window of vertices at a time ([`Survey::windowed`],
//! `crate::window_stars`). Chunks are ranges of vertices whose partial results are combined in
//! vertex order, so the counts and examples (ascending `[smaller, larger]` edges, ascending
//! vertices) are the same on every thread count and either way.

use rayon::prelude::*;

use super::atomic_union_find::AtomicUnionFind;
use super::edges::EdgeKind;
use super::local::{EdgeCounts, Local, Scratch, Share, analyse};
use super::shells::Shells;
use super::{MAX_EXAMPLES, Offenders, push_example};
use crate::stars::Stars;
use crate::window_stars::{WindowPlan, WindowStars};

/// Vertices per parallel work item.
const CHUNK: usize = 1 << 12;

/// What the vertex pass found.
#[derive(Debug)]
pub(crate) struct Survey {
    /// The shell of every vertex.
    pub(crate) shells: Shells,
    /// Each vertex's share of `V − E + F`, defect flag and use.
    pub(crate) shares: Vec<Share>,
    /// Undirected edges by kind.
    pub(crate) counts: EdgeCounts,
    /// Vertices with more than one fan.
    pub(crate) non_manifold_vertices: usize,
    /// The first examples of the edge and vertex defects.
    pub(crate) examples: Offenders,
}

/// Counts of one chunk of vertices.
#[derive(Debug, Default)]
struct Partial {
    counts: EdgeCounts,
    non_manifold_vertices: usize,
    examples: Offenders,
}

impl Partial {
    /// Appends `other` (a later chunk) to `self`.
    fn absorb(mut self, other: Self) -> Self {
        self.counts.add(&other.counts);
        self.non_manifold_vertices += other.non_manifold_vertices;
        let (mine, theirs) = (&mut self.examples, other.examples);
        for (list, more) in [
            (&mut mine.boundary_edges, theirs.boundary_edges),
            (&mut mine.non_manifold_edges, theirs.non_manifold_edges),
            (&mut mine.inconsistent_edges, theirs.inconsistent_edges),
        ] {
            for e in more {
                push_example(list, e);
            }
        }
        for v in theirs.non_manifold_vertices {
            push_example(&mut mine.non_manifold_vertices, v);
        }
        self
    }

    /// Analyses the `star` of `v`: counts its findings, joins its edges in `sets`, and gives
    /// its share.
    fn visit(
        &mut self,
        v: u32,
        star: &[[u32; 2]],
        scratch: &mut Scratch,
        sets: &AtomicUnionFind,
    ) -> Share {
        let examples = &mut self.examples;
        let local = analyse(v, star, scratch, |x, kind| {
            let list = match kind {
                EdgeKind::Manifold => return,
                EdgeKind::Boundary => &mut examples.boundary_edges,
                EdgeKind::NonManifold => &mut examples.non_manifold_edges,
                EdgeKind::Inconsistent => &mut examples.inconsistent_edges,
            };
            if list.len() < MAX_EXAMPLES {
                list.push([v, x]);
            }
        });
        self.counts.add(&local.counts);
        if local.fans > 1 {
            self.non_manifold_vertices += 1;
            push_example(&mut self.examples.non_manifold_vertices, v);
        }
        join_edges(sets, v, star, &local);
        local.share()
    }
}

impl Survey {
    /// The vertex pass over the usable `triangles` and their `stars`.
    pub(crate) fn of(triangles: &[[u32; 3]], stars: &Stars) -> Self {
        let vertex_count = stars.vertex_count();
        let sets = AtomicUnionFind::new(vertex_count);
        let mut shares = vec![Share::default(); vertex_count];
        let partials = shares
            .par_chunks_mut(CHUNK)
            .enumerate()
            .map_init(Scratch::default, |scratch, (i, shares)| {
                let mut partial = Partial::default();
                for (offset, share) in shares.iter_mut().enumerate() {
                    let v = i * CHUNK + offset;
                    *share = partial.visit(v as u32, stars.of(v), scratch, &sets);
                }
                partial
            })
            .collect();
        Self::gather(partials, shares, &sets, triangles)
    }

    /// The vertex pass over the usable `triangles`, taking the stars a window of vertices at a
    /// time; `None` when the triangles are in too little spatial order for windows (then
    /// [`Survey::of`] over [`Stars::build`] is the way).
    pub(crate) fn windowed(triangles: &[[u32; 3]], vertex_count: usize) -> Option<Self> {
        let plan = WindowPlan::new(triangles, vertex_count)?;
        let sets = AtomicUnionFind::new(vertex_count);
        let mut shares = vec![Share::default(); vertex_count];
        let partials = shares
            .par_chunks_mut(plan.window())
            .enumerate()
            .map_init(
                || (Scratch::default(), WindowStars::default()),
                |(scratch, stars), (w, shares)| {
                    plan.stars(w, triangles, stars);
                    let mut partial = Partial::default();
                    for (v, share) in plan.vertices(w).zip(shares) {
                        *share = partial.visit(v as u32, stars.of(v), scratch, &sets);
                    }
                    partial
                },
            )
            .collect();
        Some(Self::gather(partials, shares, &sets, triangles))
    }

    /// The survey from the chunks' `partials` (in vertex order), the `shares` and the joined
    /// `sets`.
    fn gather(
        partials: Vec<Partial>,
        shares: Vec<Share>,
        sets: &AtomicUnionFind,
        triangles: &[[u32; 3]],
    ) -> Self {
        let total = partials
            .into_iter()
            .fold(Partial::default(), Partial::absorb);
        let shells = Shells::number(sets, |v| shares[v].used, triangles);
        Self {
            shells,
            shares,
            counts: total.counts,
            non_manifold_vertices: total.non_manifold_vertices,
            examples: total.examples,
        }
    }
}

/// Joins `v` to every larger neighbour. In a clean closed fan every neighbour is some
/// triangle's next vertex, so the next vertices suffice.
fn join_edges(sets: &AtomicUnionFind, v: u32, star: &[[u32; 2]], local: &Local) {
    let clean = local.fans == 1 && !local.defective();
    let larger = |x: u32| (x > v).then_some(x as usize);
    if clean {
        sets.union_all(v as usize, star.iter().filter_map(|l| larger(l[0])));
    } else {
        sets.union_all(
            v as usize,
            star.as_flattened().iter().filter_map(|&x| larger(x)),
        );
    }
}
