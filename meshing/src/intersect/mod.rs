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
use crate::stars::Stars;
use crate::usable::{is_usable, usable_triangles};
use copies::Copies;
use corners::{Corners, Item};
use fans::Embedded;
use morton::{Box32, Frame, GROUP, LEAF, LeafBoxes, LeafTree, curve_sort};
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
    let usable = |t: usize| is_usable(&mesh.triangles[t], n);
    // The first non-finite corner in triangle order, as the error (looked for when some
    // position is not finite).
    if !mesh.positions.par_iter().all(|p| p.is_finite()) {
        let bad = (0..mesh.triangles.len())
            .into_par_iter()
            .filter(|&t| usable(t))
            .find_map_first(|t| {
                let tri = mesh.triangles[t];
                (0..3)
                    .find(|&k| !mesh.positions[tri[k] as usize].is_finite())
                    .map(|k| tri[k] as usize)
            });
        if let Some(vertex) = bad {
            return Err(MeasureError::NonFiniteVertex { vertex });
        }
    }
    let embedded = Embedded::of(stars, &mesh.positions);
    let frame = used_frame(stars, &mesh.positions);
    // In one pass over the corners: every usable triangle that is not exactly collinear (a
    // degenerate face, which takes no part), its projection and the curve code of its box.
    let coded: Vec<Coded> = (0..mesh.triangles.len())
        .into_par_iter()
        .filter_map(|t| {
            if !usable(t) {
                return None;
            }
            let p @ [a, b, c] = mesh.triangle_positions(t);
            let proj = Projection::of(p)?;
            let centre = (a.min(b).min(c) + a.max(b).max(c)) * 0.5;
            Some(Coded {
                code: frame.code(centre.to_array()),
                t: t as u32,
                proj,
            })
        })
        .collect();
    // Only triangles without a certified vertex can have copies (see `copies.rs`).
    let candidates: Vec<([u32; 3], u32)> = coded
        .par_iter()
        .filter_map(|c| {
            let mut key = mesh.triangles[c.t as usize];
            (!embedded.touches(key)).then(|| {
                key.sort_unstable();
                (key, c.t)
            })
        })
        .collect();
    let copies = Copies::find(candidates, mesh.triangles.len(), limit);
    let sorted = curve_sort(coded, |c| (c.code, c.t));
    let total = if <[[f32; 3]; 3]>::holds(&mesh.positions) {
        search::<[[f32; 3]; 3]>(mesh, &sorted, &copies, &embedded, limit)
    } else {
        search::<[DVec3; 3]>(mesh, &sorted, &copies, &embedded, limit)
    };
    Ok(copies.among_themselves(limit).absorb(total, limit))
}

/// A triangle taking part, before the curve order: the curve code of its box's centre, its mesh
/// index and its projection.
#[derive(Debug, Clone, Copy)]
struct Coded {
    code: u64,
    t: u32,
    proj: Projection,
}

/// The curve's frame: the box of the vertices that triangles use (any box gives a correct
/// search; a tight one a good order).
fn used_frame(stars: &Stars, positions: &[DVec3]) -> Frame {
    let used = (0..positions.len())
        .into_par_iter()
        .filter(|&v| stars.is_referenced(v))
        .map(|v| (positions[v], positions[v]))
        .reduce_with(|a, b| (a.0.min(b.0), a.1.max(b.1)));
    let (lo, hi) = used.unwrap_or((DVec3::ZERO, DVec3::ZERO));
    Frame::new(lo.to_array(), hi.to_array())
}

/// The pair search over the triangles `sorted` (in curve order; copies other than their
/// representative are left out here), their corners stored as `C`.
fn search<C: Corners>(
    mesh: &IndexedMesh,
    sorted: &[Coded],
    copies: &Copies,
    embedded: &Embedded,
    limit: usize,
) -> SelfIntersections {
    let items: Vec<Item<C>> = sorted
        .par_iter()
        .filter(|c| !copies.is_other(c.t))
        .map(|c| Item {
            id: c.t,
            vertices: mesh.triangles[c.t as usize],
            corners: C::store(mesh.triangle_positions(c.t as usize)),
            proj: c.proj,
        })
        .collect();
    let boxes = LeafBoxes::of(items.len(), |i| {
        let [a, b, c] = items[i].corners.load();
        Box32::outward(a.min(b).min(c).to_array(), a.max(b).max(c).to_array())
    });
    let tree = LeafTree::new(&boxes);
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
