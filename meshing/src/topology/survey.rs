//! The vertex pass of the report: every vertex's star analysed (`local.rs`) in parallel chunks,
//! the ends of every edge joined into shells, and the counts and first examples of each defect
//! kind gathered in vertex order.
//!
//! Chunks are fixed ranges of vertices whose partial results are combined in chunk order, so the
//! counts and examples (ascending `[smaller, larger]` edges, ascending vertices) are the same on
//! every thread count.

use rayon::prelude::*;

use super::atomic_union_find::AtomicUnionFind;
use super::edges::EdgeKind;
use super::local::{EdgeCounts, Local, Scratch, analyse};
use super::shells::Shells;
use super::{MAX_EXAMPLES, Offenders, push_example};
use crate::stars::Stars;

/// Vertices per parallel work item.
const CHUNK: usize = 1 << 12;

/// What the vertex pass found.
#[derive(Debug)]
pub(crate) struct Survey {
    /// The shell of every vertex.
    pub(crate) shells: Shells,
    /// Each vertex's share of `V − E + F` and whether it or an edge to a larger vertex is a
    /// defect.
    pub(crate) shares: Vec<(i32, bool)>,
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

    /// Adds one vertex's findings.
    fn add(&mut self, v: u32, local: &Local) {
        self.counts.add(&local.counts);
        if local.fans > 1 {
            self.non_manifold_vertices += 1;
            push_example(&mut self.examples.non_manifold_vertices, v);
        }
    }
}

impl Survey {
    /// The vertex pass over the usable `triangles` and their `stars`.
    pub(crate) fn of(triangles: &[[u32; 3]], stars: &Stars) -> Self {
        let vertex_count = stars.vertex_count();
        let sets = AtomicUnionFind::new(vertex_count);
        let mut shares = vec![(0i32, false); vertex_count];
        let total = shares
            .par_chunks_mut(CHUNK)
            .enumerate()
            .map_init(Scratch::default, |scratch, (i, shares)| {
                let mut partial = Partial::default();
                for (offset, share) in shares.iter_mut().enumerate() {
                    let v = (i * CHUNK + offset) as u32;
                    let star = stars.of(v as usize);
                    let examples = &mut partial.examples;
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
                    partial.add(v, &local);
                    *share = (
                        i32::try_from(local.chi).unwrap_or(i32::MIN),
                        local.defective(),
                    );
                    join_edges(&sets, v, star, &local);
                }
                partial
            })
            .collect::<Vec<_>>()
            .into_iter()
            .fold(Partial::default(), Partial::absorb);
        let shells = Shells::number(&sets, stars, triangles);
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
