//! The first self-intersection test (kernel BVH broad phase, hash-map grouping of repeated
//! triangles), kept for the tests as the reference the fast path in [`super`] must reproduce
//! pair for pair.

use rayon::prelude::*;
use std::collections::HashMap;

use super::SelfIntersections;
use super::copies::Copies;
use super::triangles::{Tri, meet_beyond_shared};
use crate::IndexedMesh;
use crate::measure::{MeasureError, TriangleTree};

/// Tree leaves per parallel work item.
const CHUNK: usize = 1 << 10;

/// The self-intersections of `mesh`, with at most `limit` example pairs. Fails only when a vertex
/// used by a triangle is not finite; a mesh without usable triangles has none.
pub(crate) fn reference_self_intersections(
    mesh: &IndexedMesh,
    limit: usize,
) -> Result<SelfIntersections, MeasureError> {
    let tree = match TriangleTree::new(mesh) {
        Ok(tree) => tree,
        Err(MeasureError::NoSurface) => return Ok(SelfIntersections::default()),
        Err(e) => return Err(e),
    };
    let n = tree.triangle_count();
    let mut tris: Vec<Option<Tri>> = (0..n)
        .into_par_iter()
        .map(|s| Tri::new(tree.slot_corners(s)))
        .collect();
    let copies = find_copies(&tree, mesh, &mut tris, limit);
    let leaves = tree.bvh().leaves();
    let total = leaves
        .par_chunks(CHUNK)
        .map_init(Scratch::default, |scratch, chunk| {
            let mut found = SelfIntersections::default();
            for leaf in chunk {
                let leaf = leaf.clone();
                leaf_pairs(
                    &tree, mesh, &tris, &copies, leaf, scratch, &mut found, limit,
                );
            }
            found
        })
        .collect::<Vec<_>>()
        .into_iter()
        .fold(copies.among_themselves(limit), |a, b| a.absorb(b, limit));
    Ok(total)
}

/// Groups the usable triangles by their vertex set (a hash map, the first method) and removes
/// all but the representative of each group from `tris`.
fn find_copies(
    tree: &TriangleTree,
    mesh: &IndexedMesh,
    tris: &mut [Option<Tri>],
    limit: usize,
) -> Copies {
    let mut by_key: HashMap<[u32; 3], Vec<(u32, usize)>> = HashMap::new();
    for (slot, tri) in tris.iter().enumerate() {
        if tri.is_some() {
            let i = tree.slot_triangle(slot);
            let mut key = mesh.triangles[i as usize];
            key.sort_unstable();
            by_key.entry(key).or_default().push((i, slot));
        }
    }
    let mut groups = HashMap::new();
    for mut members in by_key.into_values().filter(|m| m.len() > 1) {
        members.sort_unstable();
        for &(_, slot) in &members[1..] {
            tris[slot] = None;
        }
        // `limit + 1`: the smallest pairs among copies are the first with the next `limit`.
        let first = members.iter().take(limit + 1).map(|&(i, _)| i).collect();
        groups.insert(members[0].0, (members.len(), first));
    }
    Copies {
        groups,
        ..Copies::default()
    }
}

/// Reusable buffers of one worker.
#[derive(Debug, Default)]
struct Scratch {
    candidates: Vec<usize>,
    hits: Vec<[u32; 2]>,
}

/// Adds the intersecting pairs of the triangles in one leaf with higher-index triangles: one tree
/// query for the leaf's box, then the candidates per triangle.
#[allow(clippy::too_many_arguments)]
fn leaf_pairs(
    tree: &TriangleTree,
    mesh: &IndexedMesh,
    tris: &[Option<Tri>],
    copies: &Copies,
    leaf: std::ops::Range<usize>,
    scratch: &mut Scratch,
    found: &mut SelfIntersections,
    limit: usize,
) {
    let Some(leaf_box) = leaf
        .clone()
        .filter(|&s| tris[s].is_some())
        .map(|s| triangle_box(tree.slot_corners(s)))
        .reduce(|[l0, h0], [l1, h1]| [l0.min(l1), h0.max(h1)])
    else {
        return;
    };
    let Scratch { candidates, hits } = scratch;
    candidates.clear();
    let [leaf_lo, leaf_hi] = leaf_box;
    tree.bvh().for_each_overlap(leaf_lo, leaf_hi, |other| {
        if tris[other].is_some() {
            candidates.push(other);
        }
    });
    hits.clear();
    for slot in leaf {
        let Some(tri) = &tris[slot] else { continue };
        let i = tree.slot_triangle(slot);
        let ti = mesh.triangles[i as usize];
        let [lo, hi] = triangle_box(tri.p);
        for &other in candidates.iter() {
            let j = tree.slot_triangle(other);
            if j <= i {
                continue;
            }
            let [l, h] = triangle_box(tree.slot_corners(other));
            if !(l.cmple(hi).all() && lo.cmple(h).all()) {
                continue;
            }
            if let Some(trj) = &tris[other]
                && meet_beyond_shared(ti, tri, mesh.triangles[j as usize], trj)
            {
                if copies.groups.is_empty() {
                    found.count += 1;
                    hits.push([i, j]);
                } else {
                    // Every copy of one meets every copy of the other.
                    let ((ci, fi), (cj, fj)) = (copies.of(i), copies.of(j));
                    let (single_i, single_j) = ([i], [j]);
                    let fi = if fi.is_empty() { &single_i[..] } else { fi };
                    let fj = if fj.is_empty() { &single_j[..] } else { fj };
                    found.count += ci * cj;
                    for &a in fi {
                        hits.extend(fj.iter().map(|&b| [a.min(b), a.max(b)]));
                    }
                }
            }
        }
    }
    if !hits.is_empty() {
        found.examples.extend_from_slice(hits);
        found.examples.sort_unstable();
        found.examples.truncate(limit);
    }
}

/// The box `[min, max]` of a triangle.
fn triangle_box([a, b, c]: [glam::DVec3; 3]) -> [glam::DVec3; 2] {
    [a.min(b).min(c), a.max(b).max(c)]
}
