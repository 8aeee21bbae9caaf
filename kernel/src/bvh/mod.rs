//! The one bounding volume hierarchy over triangles: shared by the mesh solid (signed distance
//! and fast winding numbers, `primitive::polyhedron`) and the meshing crate's measures (Hausdorff
//! distances, self-intersections).
//!
//! `obvhs` builds the topology (PLOC over single-precision triangle boxes, taken in coordinates
//! normalised to the triangles' bounding box so that any finite input fits in `f32`; leaf size a
//! parameter). The tree is then copied into a flat array of [`BvhNode`]s with **exact**
//! double-precision boxes refitted bottom-up, so no query ever depends on `f32` rounding. The
//! triangles are stored reordered into *slots*: every leaf, and every subtree, owns a contiguous
//! run of slots, and [`TriangleBvh::slot_index`] gives the input index of each slot.
//!
//! Layout: node 0 is the root; an inner node's two children sit side by side at `first` and
//! `first + 1`, always after their parent (so a reverse loop over the nodes visits children
//! before parents); a leaf has `count > 0` triangles in the slots `first .. first + count`. An
//! empty input gives a tree without nodes, on which every query finds nothing.
//!
//! Queries (all with explicit stacks, never recursion): the exact nearest point
//! ([`TriangleBvh::nearest`], `nearest.rs`), leaf ranges and box-overlap traversal
//! ([`TriangleBvh::leaves`], [`TriangleBvh::for_each_overlap`], `overlap.rs`). The construction
//! is in `build.rs`.

mod build;
mod nearest;
mod overlap;

#[cfg(test)]
mod tests;

use crate::Aabb;
use glam::DVec3;

pub use nearest::Nearest;

/// Why a tree cannot be built.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BvhError {
    /// More triangles than the tree's 32-bit node and slot indices can address.
    #[error("too many triangles: {count} (at most {max})", max = TriangleBvh::MAX_TRIANGLES)]
    TooLarge {
        /// Number of triangles given.
        count: usize,
    },
}

/// One node of a [`TriangleBvh`]: its exact box, and either two children (`count == 0`, at
/// `first` and `first + 1`) or a leaf's triangles (the slots `first .. first + count`).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct BvhNode {
    /// Minimum corner of the exact box of the node's triangles.
    pub min: DVec3,
    /// Maximum corner of that box.
    pub max: DVec3,
    /// First child (inner node) or first slot (leaf).
    pub first: u32,
    /// Number of triangles of a leaf; 0 for an inner node.
    pub count: u32,
}

impl BvhNode {
    /// True for a leaf.
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }

    /// The slots of a leaf (empty for an inner node).
    pub fn slots(&self) -> std::ops::Range<usize> {
        let first = self.first as usize;
        first..first + self.count as usize
    }
}

/// A bounding volume hierarchy over triangles with exact boxes; see the [module docs](self).
#[derive(Clone)]
pub struct TriangleBvh {
    /// Flat nodes, root first (empty for no triangles).
    nodes: Vec<BvhNode>,
    /// The corners of the triangle in each slot.
    corners: Vec<[DVec3; 3]>,
    /// The input index of the triangle in each slot.
    order: Vec<u32>,
}

impl TriangleBvh {
    /// The largest number of triangles a tree holds (its nodes, about twice as many with one
    /// triangle per leaf, are numbered in 32 bits).
    pub const MAX_TRIANGLES: usize = (u32::MAX / 2) as usize;

    /// The flat nodes, root first (see the [module docs](self) for the layout).
    pub fn nodes(&self) -> &[BvhNode] {
        &self.nodes
    }

    /// The corners of every slot's triangle, in slot order.
    pub fn corners(&self) -> &[[DVec3; 3]] {
        &self.corners
    }

    /// The input index of the triangle in `slot`.
    pub fn slot_index(&self, slot: usize) -> u32 {
        self.order[slot]
    }

    /// The input index of every slot's triangle, in slot order (a permutation of the input).
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.corners.len()
    }

    /// True when the tree holds no triangle.
    pub fn is_empty(&self) -> bool {
        self.corners.is_empty()
    }

    /// The exact bounding box of all triangles (empty for no triangles).
    pub fn bbox(&self) -> Aabb {
        self.nodes
            .first()
            .map_or_else(Aabb::empty, |root| Aabb::new(root.min, root.max))
    }
}

impl std::fmt::Debug for TriangleBvh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TriangleBvh")
            .field("nodes", &self.nodes.len())
            .field("triangles", &self.corners.len())
            .finish()
    }
}

/// Squared distance from `q` to the box `[lo, hi]` (zero inside).
pub(crate) fn box_distance2(lo: DVec3, hi: DVec3, q: DVec3) -> f64 {
    (lo - q).max(q - hi).max(DVec3::ZERO).length_squared()
}

/// Runs `f` with the thread's scratch vector behind `key`, cleared (a fresh one if it is in use,
/// e.g. by a query made from inside another query's callback). The traversal stacks of the tree
/// queries live in such buffers, so a query does not allocate.
pub(crate) fn with_scratch<T: 'static, R>(
    key: &'static std::thread::LocalKey<std::cell::RefCell<Vec<T>>>,
    f: impl FnOnce(&mut Vec<T>) -> R,
) -> R {
    key.with(|cell| match cell.try_borrow_mut() {
        Ok(mut v) => {
            v.clear();
            f(&mut v)
        }
        Err(_) => f(&mut Vec::new()),
    })
}
