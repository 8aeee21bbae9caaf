//! A bounding volume hierarchy over the triangles of a mesh, for nearest-point queries (and the
//! overlap queries of the self-intersection test).
//!
//! `obvhs` builds the tree (PLOC over single-precision triangle boxes in coordinates normalised to
//! the mesh's bounding box, so any finite mesh fits in `f32`); its nodes are used as built, and an
//! exact double-precision box is computed for every node bottom-up, so that pruning never depends on
//! `f32` rounding. obvhs 0.4 has ray, box and point traversals but no nearest-point query:
//! [`TriangleTree::nearest`] is a best-first traversal (a priority queue of nodes ordered by the
//! distance to their boxes; it stops when the nearest queued box is farther than the best triangle).

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::time::Duration;

use glam::{DVec3, Vec3A};
use obvhs::aabb::Aabb as Box32;
use obvhs::bvh2::Bvh2;
use obvhs::{Boundable, BvhBuildParams};

use super::MeasureError;
use super::triangle::closest_point_on_triangle;
use crate::IndexedMesh;
use crate::topology::is_usable;

/// A triangle mesh ready for distance queries; see the [module docs](self).
pub struct TriangleTree {
    /// The tree as obvhs built it (node 0 is the root; an inner node's children are at
    /// `first_index` and `first_index + 1`; a leaf's triangles are the slots
    /// `first_index .. first_index + prim_count`).
    bvh: Bvh2,
    /// The exact box `[min, max]` of every node, indexed like `bvh.nodes`.
    boxes: Vec<[DVec3; 2]>,
    /// The corners of the triangle in each slot.
    corners: Vec<[DVec3; 3]>,
    /// The index in the input mesh of the triangle in each slot.
    ids: Vec<u32>,
}

/// The point of a mesh nearest to a query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// Distance from the query to `point`.
    pub distance: f64,
    /// The nearest point of the mesh.
    pub point: DVec3,
    /// The triangle it lies on (index into the input mesh's triangles).
    pub triangle: u32,
}

/// Reusable traversal state: a min-queue of `(squared box distance bits, node)`. Non-negative
/// finite `f64`s order like their bit patterns, so the queue needs no float ordering.
pub(crate) type Queue = BinaryHeap<Reverse<(u64, u32)>>;

/// A triangle's box for the builder.
struct TriangleBox(Box32);

impl Boundable for TriangleBox {
    fn aabb(&self) -> Box32 {
        self.0
    }
}

impl TriangleTree {
    /// The tree of the usable triangles of `mesh` (three distinct in-range indices; see the
    /// topology report). Fails when there are none or a used vertex is not finite.
    pub fn new(mesh: &IndexedMesh) -> Result<Self, MeasureError> {
        let n = mesh.positions.len();
        let usable: Vec<u32> = (0..mesh.triangles.len())
            .filter(|&t| is_usable(&mesh.triangles[t], n))
            .map(|t| u32::try_from(t).map_err(|_| MeasureError::TooLarge { count: t + 1 }))
            .collect::<Result<_, _>>()?;
        if usable.is_empty() {
            return Err(MeasureError::NoSurface);
        }
        let corners: Vec<[DVec3; 3]> = usable
            .iter()
            .map(|&t| mesh.triangle_positions(t as usize))
            .collect();
        for (&t, c) in usable.iter().zip(&corners) {
            if let Some(k) = (0..3).find(|&k| !c[k].is_finite()) {
                let vertex = mesh.triangles[t as usize][k] as usize;
                return Err(MeasureError::NonFiniteVertex { vertex });
            }
        }
        let bvh = build(&corners);
        let slots_corners = bvh
            .primitive_indices
            .iter()
            .map(|&p| corners[p as usize])
            .collect();
        let ids = bvh
            .primitive_indices
            .iter()
            .map(|&p| usable[p as usize])
            .collect();
        let mut tree = Self {
            boxes: Vec::new(),
            bvh,
            corners: slots_corners,
            ids,
        };
        tree.boxes = tree.exact_boxes();
        Ok(tree)
    }

    /// Number of triangles in the tree.
    pub fn triangle_count(&self) -> usize {
        self.corners.len()
    }

    /// The exact bounding box `[min, max]` of the triangles.
    pub fn bbox(&self) -> [DVec3; 2] {
        self.boxes[0]
    }

    /// The point of the mesh nearest to `q`.
    pub fn nearest(&self, q: DVec3) -> Nearest {
        self.nearest_with(q, &mut Queue::new())
    }

    /// [`nearest`](Self::nearest) with a reusable queue.
    pub(crate) fn nearest_with(&self, q: DVec3, queue: &mut Queue) -> Nearest {
        queue.clear();
        let mut best = Nearest {
            distance: f64::INFINITY,
            point: q,
            triangle: 0,
        };
        let mut best2 = f64::INFINITY;
        queue.push(Reverse((box_distance2(self.boxes[0], q).to_bits(), 0)));
        while let Some(Reverse((bits, node))) = queue.pop() {
            if f64::from_bits(bits) >= best2 {
                break;
            }
            let node = &self.bvh.nodes[node as usize];
            if node.is_leaf() {
                let first = node.first_index as usize;
                for slot in first..first + node.prim_count as usize {
                    let p = closest_point_on_triangle(q, self.corners[slot]);
                    let d2 = q.distance_squared(p);
                    if d2 < best2 {
                        best2 = d2;
                        best = Nearest {
                            distance: d2.sqrt(),
                            point: p,
                            triangle: self.ids[slot],
                        };
                    }
                }
                continue;
            }
            for child in [node.first_index, node.first_index + 1] {
                let d2 = box_distance2(self.boxes[child as usize], q);
                if d2 < best2 {
                    queue.push(Reverse((d2.to_bits(), child)));
                }
            }
        }
        best
    }

    /// The corners of the triangle in `slot` (slots are the tree's order, `0..triangle_count()`).
    pub(crate) fn slot_corners(&self, slot: usize) -> [DVec3; 3] {
        self.corners[slot]
    }

    /// The index in the input mesh of the triangle in `slot`.
    pub(crate) fn slot_triangle(&self, slot: usize) -> u32 {
        self.ids[slot]
    }

    /// The slot ranges of the leaves (together, every slot once).
    pub(crate) fn leaves(&self) -> Vec<std::ops::Range<usize>> {
        let mut leaves = Vec::new();
        let mut stack = vec![0u32];
        while let Some(i) = stack.pop() {
            let node = &self.bvh.nodes[i as usize];
            if node.is_leaf() {
                let first = node.first_index as usize;
                leaves.push(first..first + node.prim_count as usize);
            } else {
                stack.extend([node.first_index, node.first_index + 1]);
            }
        }
        leaves.sort_unstable_by_key(|r| r.start);
        leaves
    }

    /// Calls `f(slot)` for every triangle whose box meets the closed box `[lo, hi]`; `stack` is
    /// reusable scratch.
    pub(crate) fn for_each_overlap(
        &self,
        [lo, hi]: [DVec3; 2],
        stack: &mut Vec<u32>,
        mut f: impl FnMut(usize),
    ) {
        let meets = |[l, h]: [DVec3; 2]| l.cmple(hi).all() && lo.cmple(h).all();
        stack.clear();
        stack.push(0);
        while let Some(i) = stack.pop() {
            if !meets(self.boxes[i as usize]) {
                continue;
            }
            let node = &self.bvh.nodes[i as usize];
            if node.is_leaf() {
                let first = node.first_index as usize;
                for slot in first..first + node.prim_count as usize {
                    let [a, b, c] = self.corners[slot];
                    if meets([a.min(b).min(c), a.max(b).max(c)]) {
                        f(slot);
                    }
                }
            } else {
                stack.extend([node.first_index, node.first_index + 1]);
            }
        }
    }

    /// Exact node boxes: nodes listed parents first by an explicit-stack walk, then filled in
    /// reverse (children before parents).
    fn exact_boxes(&self) -> Vec<[DVec3; 2]> {
        let nodes = &self.bvh.nodes;
        let mut order = Vec::with_capacity(nodes.len());
        let mut stack = vec![0u32];
        while let Some(i) = stack.pop() {
            order.push(i);
            let node = &nodes[i as usize];
            if !node.is_leaf() {
                stack.extend([node.first_index, node.first_index + 1]);
            }
        }
        let empty = [DVec3::INFINITY, DVec3::NEG_INFINITY];
        let mut boxes = vec![empty; nodes.len()];
        for &i in order.iter().rev() {
            let node = &nodes[i as usize];
            let [mut lo, mut hi] = empty;
            if node.is_leaf() {
                let first = node.first_index as usize;
                for c in &self.corners[first..first + node.prim_count as usize] {
                    for p in c {
                        lo = lo.min(*p);
                        hi = hi.max(*p);
                    }
                }
            } else {
                for child in [node.first_index, node.first_index + 1] {
                    let [l, h] = boxes[child as usize];
                    lo = lo.min(l);
                    hi = hi.max(h);
                }
            }
            boxes[i as usize] = [lo, hi];
        }
        boxes
    }
}

/// Builds the obvhs tree over the triangles' boxes in normalised coordinates.
fn build(corners: &[[DVec3; 3]]) -> Bvh2 {
    let (lo, hi) = corners
        .iter()
        .flatten()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    let extent = (hi - lo).max_element();
    let center = lo * 0.5 + hi * 0.5;
    // A zero or overflowing extent maps everything to the origin: correct, only slower.
    let scale = if extent.is_finite() && extent > 0.0 {
        1.0 / extent
    } else {
        0.0
    };
    let normalised = |p: DVec3| {
        let v = Vec3A::from(((p - center) * scale).as_vec3());
        if v.is_finite() { v } else { Vec3A::ZERO }
    };
    let boxes: Vec<TriangleBox> = corners
        .iter()
        .map(|c| {
            let [a, b, c] = c.map(normalised);
            // Padded: the builder's costs use box areas, which flat boxes would zero.
            TriangleBox(Box32::new(a.min(b).min(c) - 1e-6, a.max(b).max(c) + 1e-6))
        })
        .collect();
    let params = BvhBuildParams {
        max_prims_per_leaf: 4,
        ..BvhBuildParams::fast_build()
    };
    obvhs::bvh2::builder::build_bvh2(&boxes, params, &mut Duration::default())
}

impl std::fmt::Debug for TriangleTree {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TriangleTree")
            .field("nodes", &self.bvh.nodes.len())
            .field("triangles", &self.corners.len())
            .finish()
    }
}

/// Squared distance from `q` to the box `[lo, hi]` (zero inside).
fn box_distance2([lo, hi]: [DVec3; 2], q: DVec3) -> f64 {
    (lo - q).max(q - hi).max(DVec3::ZERO).length_squared()
}
