//! Self-intersections of a triangle mesh: the pairs of triangles that meet beyond the vertices
//! they share.
//!
//! Broad phase (`morton.rs`): the triangles' boxes, rounded outwards to `f32`, sorted along a
//! Morton curve and grouped under an implicit tree; every group of four leaves queries the tree
//! once for the leaves at or after it (each leaf keeps those that meet its own box), in parallel
//! (rayon); each triangle is tested against the four boxes of a found leaf at once, without a
//! branch per box, and the narrow phase reads the triangles in that curve order. Narrow
//! phase: exact triangle–triangle tests on orientation predicates, with neighbours (shared
//! vertex or edge) counted only when they meet beyond what they share (a fold-back, a coplanar
//! overlap); see `triangles.rs`.
//! Plain floating-point separation tests with a safe margin (`filter.rs`) settle most pairs
//! before any exact predicate: in flat regions neighbours are exactly coplanar, and an exact
//! zero is the slowest case of adaptive predicates. Pairs sharing a vertex whose star is
//! certified embedded (`fans.rs`, exact) are passed without a test: they meet only in what they
//! share.
//! Touching counts as meeting. Sharing means sharing a vertex index: two distinct vertices at
//! the same position (an unwelded seam) touch, so their triangles count. Exactly collinear
//! triangles are skipped (they are degenerate faces); triangles with unusable indices are left
//! out.
//!
//! The count and the examples (the smallest pairs) do not depend on the thread count, and are
//! those of the first implementation over the kernel's BVH (kept as `reference.rs` for the tests).
//!
//! Repeated triangles (the same three vertex indices, in any order) are tested once
//! (`copies.rs`): only the lowest-index copy takes part in the search, a pair of copies always
//! meets (they share all three vertices) and every pair found for a representative stands for
//! all pairs of the copies of both. So a file of 40 000 coincident triangles costs one test, not
//! 8 · 10⁸, while the count and the examples stay those of the pairwise definition.

mod copies;
mod corners;
mod fans;
mod filter;
mod morton;
mod predicates;
#[cfg(test)]
mod reference;
pub(crate) mod triangles;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_reference;

use glam::DVec3;
use rayon::prelude::*;

use crate::IndexedMesh;
use crate::measure::MeasureError;
use crate::stars::{Stars, usable_triangles};
use copies::Copies;
use corners::{Corners, Item};
use fans::Embedded;
use morton::{Box32, GROUP, LEAF, LeafBoxes, LeafTree, curve_order};
use predicates::Projection;
use triangles::{Tri, meet_beyond_shared};

/// Leaves per parallel work item.
const CHUNK: usize = 1 << 8;

/// The intersecting triangle pairs of a mesh.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SelfIntersections {
    /// Number of intersecting pairs.
    pub count: usize,
    /// The smallest pairs `[i, j]` (`i < j`, triangle indices into the mesh), ascending, at most
    /// the limit given.
    pub examples: Vec<[u32; 2]>,
}

impl SelfIntersections {
    /// Appends `other`'s pairs, keeping the `limit` smallest examples.
    fn absorb(mut self, other: Self, limit: usize) -> Self {
        self.count += other.count;
        self.examples.extend(other.examples);
        self.examples.sort_unstable();
        self.examples.truncate(limit);
        self
    }
}

/// True when the triangle's indices are inside a vertex array of `vertex_count` and distinct.
///
/// Only such triangles take part in adjacency and measures.
pub(crate) fn is_usable(tri: &[u32; 3], vertex_count: usize) -> bool {
    let [a, b, c] = *tri;
    tri.iter().all(|&i| (i as usize) < vertex_count) && a != b && b != c && a != c
}

/// True when two mesh triangles (vertex indices `ti`, `tj`, distinct within each, and their
/// corners) meet beyond the vertices they share, by the same exact test as
/// [`self_intersections`]. An exactly collinear triangle counts as meeting (a certificate built
/// on this test must not pass it). The exhaustive table test's pair test; [`none_meet`] is the
/// same test over the pairs of one marching-cubes cell.
#[cfg(test)]
pub(crate) fn pair_meets(ti: [u32; 3], pi: [DVec3; 3], tj: [u32; 3], pj: [DVec3; 3]) -> bool {
    match (Projection::of(pi), Projection::of(pj)) {
        (Some(a), Some(b)) => {
            meet_beyond_shared(ti, &Tri { p: pi, proj: a }, tj, &Tri { p: pj, proj: b })
        }
        _ => true,
    }
}

/// True when no two of the triangles `tris` (vertex indices, distinct within each, and corners)
/// meet beyond the vertices they share, by the same exact test as [`self_intersections`]
/// (without the search) for every pair: each triangle's projection is found once, and pairs
/// whose bounding boxes are apart along an axis are skipped (closed triangles in disjoint closed
/// boxes cannot meet). An exactly collinear triangle fails it.
pub(crate) fn none_meet(tris: &[([u32; 3], [DVec3; 3])]) -> bool {
    let mut prepared = Vec::with_capacity(tris.len());
    for &(ids, p) in tris {
        let Some(tri) = Tri::new(p) else {
            return false;
        };
        let lo = p[0].min(p[1]).min(p[2]);
        let hi = p[0].max(p[1]).max(p[2]);
        prepared.push((ids, tri, lo, hi));
    }
    prepared.iter().enumerate().all(|(i, (ia, a, alo, ahi))| {
        prepared[i + 1..].iter().all(|(ib, b, blo, bhi)| {
            let apart = ahi.cmplt(*blo).any() || bhi.cmplt(*alo).any();
            apart || !meet_beyond_shared(*ia, a, *ib, b)
        })
    })
}

/// The self-intersections of `mesh`, with at most `limit` example pairs. Fails only when a vertex
/// used by a triangle is not finite; a mesh without usable triangles has none.
pub fn self_intersections(
    mesh: &IndexedMesh,
    limit: usize,
) -> Result<SelfIntersections, MeasureError> {
    let stars = Stars::build(&usable_triangles(mesh), mesh.positions.len());
    self_intersections_among(mesh, &stars, limit)
}

/// [`self_intersections`] given the `stars` of the mesh's usable triangles (the topology report
/// builds them once for both).
pub(crate) fn self_intersections_among(
    mesh: &IndexedMesh,
    stars: &Stars,
    limit: usize,
) -> Result<SelfIntersections, MeasureError> {
    let n = mesh.positions.len();
    if mesh.triangles.len() > u32::MAX as usize {
        return Err(MeasureError::TooLarge {
            count: mesh.triangles.len(),
        });
    }
    let ids: Vec<u32> = (0..mesh.triangles.len() as u32)
        .into_par_iter()
        .filter(|&t| is_usable(&mesh.triangles[t as usize], n))
        .collect();
    // The first non-finite corner in triangle order, as the error.
    let bad = ids.par_iter().find_map_first(|&t| {
        let tri = mesh.triangles[t as usize];
        (0..3)
            .find(|&k| !mesh.positions[tri[k] as usize].is_finite())
            .map(|k| tri[k] as usize)
    });
    if let Some(vertex) = bad {
        return Err(MeasureError::NonFiniteVertex { vertex });
    }
    let embedded = Embedded::of(stars, &mesh.positions);
    // Each triangle's projection (`None`: exactly collinear, a degenerate face, which takes no
    // part) and box, in one pass over the corners.
    let prepared: Vec<(Option<Projection>, Box32)> = ids
        .par_iter()
        .map(|&t| {
            let p @ [a, b, c] = mesh.triangle_positions(t as usize);
            let lo = a.min(b).min(c).to_array();
            (
                Projection::of(p),
                Box32::outward(lo, a.max(b).max(c).to_array()),
            )
        })
        .collect();
    let mut keep: Vec<bool> = prepared.par_iter().map(|(p, _)| p.is_some()).collect();
    // Only triangles without a certified vertex can have copies (see `copies.rs`).
    let candidates: Vec<([u32; 3], u32)> = (0..ids.len() as u32)
        .into_par_iter()
        .filter_map(|k| {
            let mut key = mesh.triangles[ids[k as usize] as usize];
            (keep[k as usize] && !embedded.touches(key)).then(|| {
                key.sort_unstable();
                (key, k)
            })
        })
        .collect();
    let copies = Copies::find(&ids, candidates, &mut keep, limit);
    // The representatives, in curve order.
    let active: Vec<u32> = (0..ids.len() as u32)
        .into_par_iter()
        .filter(|&k| keep[k as usize])
        .collect();
    drop(keep);
    let box_of = |o: usize| prepared[active[o] as usize].1;
    let order = curve_order(active.len(), box_of);
    let boxes: Vec<Box32> = order.par_iter().map(|&o| box_of(o as usize)).collect();
    let sorted = Sorted {
        ids: &ids,
        prepared: &prepared,
        active: &active,
        order: &order,
        boxes,
    };
    let total = if <[[f32; 3]; 3]>::holds(&mesh.positions) {
        search::<[[f32; 3]; 3]>(mesh, sorted, &copies, &embedded, limit)
    } else {
        search::<[DVec3; 3]>(mesh, sorted, &copies, &embedded, limit)
    };
    Ok(copies.among_themselves(limit).absorb(total, limit))
}

/// The triangles taking part, in curve order.
struct Sorted<'a> {
    /// Usable triangles (mesh indices).
    ids: &'a [u32],
    /// Their projections (`None`: degenerate) and boxes.
    prepared: &'a [(Option<Projection>, Box32)],
    /// The representatives (positions in `ids`).
    active: &'a [u32],
    /// The curve order of `active`.
    order: &'a [u32],
    /// The boxes of `active` in curve order.
    boxes: Vec<Box32>,
}

/// The pair search over the triangles of `sorted`, their corners stored as `C`.
fn search<C: Corners>(
    mesh: &IndexedMesh,
    sorted: Sorted<'_>,
    copies: &Copies,
    embedded: &Embedded,
    limit: usize,
) -> SelfIntersections {
    let items: Vec<Item<C>> = sorted
        .order
        .par_iter()
        .filter_map(|&o| {
            let k = sorted.active[o as usize] as usize;
            let id = sorted.ids[k];
            sorted.prepared[k].0.map(|proj| Item {
                id,
                vertices: mesh.triangles[id as usize],
                corners: C::store(mesh.triangle_positions(id as usize)),
                proj,
            })
        })
        .collect();
    let tree = LeafTree::new(&sorted.boxes);
    let boxes = LeafBoxes::of(&sorted.boxes);
    drop(sorted);
    let level = tree.group_level();
    (0..tree.node_count(level))
        .into_par_iter()
        .with_min_len(CHUNK / GROUP)
        .fold(
            || (Scratch::default(), SelfIntersections::default()),
            |(mut scratch, mut found), group| {
                let search = Search {
                    tree: &tree,
                    items: &items,
                    boxes: &boxes,
                    copies,
                    embedded,
                    limit,
                };
                search.group_pairs(level, group, &mut scratch, &mut found);
                (scratch, found)
            },
        )
        .map(|(_, found)| found)
        .reduce(SelfIntersections::default, |a, b| a.absorb(b, limit))
}

/// Reusable buffers of one worker.
#[derive(Debug, Default)]
struct Scratch {
    stack: Vec<(u8, u32)>,
    /// The leaves found for a group.
    leaves: Vec<u32>,
    /// Those of them that meet one leaf of the group.
    mine: Vec<u32>,
    hits: Vec<[u32; 2]>,
}

/// What the workers of the pair search share.
struct Search<'a, C> {
    tree: &'a LeafTree,
    items: &'a [Item<C>],
    boxes: &'a [LeafBoxes],
    copies: &'a Copies,
    embedded: &'a Embedded,
    limit: usize,
}

impl<C: Corners> Search<'_, C> {
    /// Adds the intersecting pairs of the triangles in the leaves of node `group` at `level`
    /// with those of the same or later leaves (later slots within the same leaf).
    fn group_pairs(
        &self,
        level: usize,
        group: usize,
        scratch: &mut Scratch,
        found: &mut SelfIntersections,
    ) {
        let Scratch {
            stack,
            leaves,
            mine,
            hits,
        } = scratch;
        let first = group << level;
        let last = ((group + 1) << level).min(self.tree.leaf_count());
        leaves.clear();
        self.tree
            .leaves_after(first, &self.tree.node_box(level, group), stack, leaves);
        for leaf in first..last {
            let own = self.tree.leaf_box(leaf);
            mine.clear();
            mine.extend(leaves.iter().copied().filter(|&other| {
                other as usize >= leaf && self.tree.leaf_box(other as usize).meets(&own)
            }));
            hits.clear();
            self.leaf_pairs(leaf, mine, &mut found.count, hits);
            if !hits.is_empty() {
                found.examples.extend_from_slice(hits);
                found.examples.sort_unstable();
                found.examples.truncate(self.limit);
            }
        }
    }

    /// Adds the intersecting pairs of the triangles in leaf `leaf` with those of the leaves
    /// `others` (at or after it; later slots within the same leaf) to `count`, their pairs to
    /// `hits`.
    fn leaf_pairs(&self, leaf: usize, others: &[u32], count: &mut usize, hits: &mut Vec<[u32; 2]>) {
        let (items, boxes) = (self.items, self.boxes);
        let own = &boxes[leaf];
        for slot in 0..LEAF.min(items.len() - leaf * LEAF) {
            let a = leaf * LEAF + slot;
            let (ia, ba) = (&items[a], own.lane(slot));
            let ta = ia.tri();
            for &other in others {
                let other = other as usize;
                let mut mask = boxes[other].meeting(&ba);
                if other == leaf {
                    // Later slots of the same leaf only.
                    mask &= !0u32 << (slot + 1);
                }
                while mask != 0 {
                    let b = other * LEAF + mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    let ib = &items[b];
                    if self.embedded.share_one(ia.vertices, ib.vertices) {
                        continue;
                    }
                    let tb = ib.tri();
                    // Lower index first, as the pairwise definition reads.
                    let ((x, tx), (y, ty)) = if ia.id < ib.id {
                        ((ia, &ta), (ib, &tb))
                    } else {
                        ((ib, &tb), (ia, &ta))
                    };
                    if meet_beyond_shared(x.vertices, tx, y.vertices, ty) {
                        self.copies.add_pair(ia.id, ib.id, count, hits);
                    }
                }
            }
        }
    }
}
