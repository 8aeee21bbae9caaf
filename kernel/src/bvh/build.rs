//! Building a [`TriangleBvh`]: the obvhs build over padded `f32` triangle boxes in normalised
//! coordinates, the copy into the flat layout (explicit stack; slots numbered leaf by leaf, so
//! every subtree owns a contiguous run), the triangles moved into slot order in place, and the
//! exact `f64` boxes refitted children first.

use super::{BvhError, BvhNode, TriangleBvh};
use glam::{DVec3, Vec3A};
use obvhs::aabb::Aabb as Box32;
use obvhs::bvh2::Bvh2;
use obvhs::{Boundable, BvhBuildParams};
use std::time::Duration;

/// A triangle's box for the builder.
struct TriangleBox(Box32);

impl Boundable for TriangleBox {
    fn aabb(&self) -> Box32 {
        self.0
    }
}

impl TriangleBvh {
    /// The tree of `triangles` with at most `leaf_size` triangles per leaf (clamped to 1..=255;
    /// obvhs decides by its cost model how full leaves get). Triangles are taken as given
    /// (degenerate ones too); callers keep non-finite corners out, since distances to them are
    /// meaningless. Fails only beyond [`TriangleBvh::MAX_TRIANGLES`].
    pub fn new(mut triangles: Vec<[DVec3; 3]>, leaf_size: u32) -> Result<Self, BvhError> {
        let count = triangles.len();
        if count > Self::MAX_TRIANGLES {
            return Err(BvhError::TooLarge { count });
        }
        if count == 0 {
            return Ok(Self {
                nodes: Vec::new(),
                corners: triangles,
                order: Vec::new(),
            });
        }
        let bvh = build(&triangles, leaf_size);
        let (mut nodes, order) = flatten(&bvh);
        drop(bvh);
        permute(&mut triangles, &order);
        refit(&mut nodes, &triangles);
        Ok(Self {
            nodes,
            corners: triangles,
            order,
        })
    }
}

/// The obvhs tree over the triangles' boxes in coordinates normalised to their bounding box.
fn build(triangles: &[[DVec3; 3]], leaf_size: u32) -> Bvh2 {
    let (lo, hi) = triangles
        .iter()
        .flatten()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
    // Builder coordinates: the box mapped to about [-0.5, 0.5]³ (everything at the origin if the
    // extent is zero or overflows, which only costs traversal speed).
    let extent = (hi - lo).max_element();
    let center = lo * 0.5 + hi * 0.5;
    let scale = if extent.is_finite() && extent > 0.0 {
        1.0 / extent
    } else {
        0.0
    };
    let normalised = |p: DVec3| {
        let v = Vec3A::from(((p - center) * scale).as_vec3());
        if v.is_finite() { v } else { Vec3A::ZERO }
    };
    let boxes: Vec<TriangleBox> = triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(normalised);
            // Padded: the builder's costs use box areas, which flat boxes would zero.
            TriangleBox(Box32::new(a.min(b).min(c) - 1e-6, a.max(b).max(c) + 1e-6))
        })
        .collect();
    let params = BvhBuildParams {
        max_prims_per_leaf: leaf_size.clamp(1, 255),
        ..BvhBuildParams::fast_build()
    };
    obvhs::bvh2::builder::build_bvh2(&boxes, params, &mut Duration::default())
}

/// Copies the builder's tree into the flat layout (children side by side, after their parent;
/// boxes left for [`refit`]) and lists the input index of each slot.
fn flatten(bvh: &Bvh2) -> (Vec<BvhNode>, Vec<u32>) {
    let mut nodes = vec![BvhNode::default()];
    let mut order = Vec::with_capacity(bvh.primitive_indices.len());
    let mut stack: Vec<(usize, usize)> = vec![(0, 0)];
    while let Some((src, dst)) = stack.pop() {
        let n = &bvh.nodes[src];
        if n.prim_count == 0 {
            let first = nodes.len();
            nodes.push(BvhNode::default());
            nodes.push(BvhNode::default());
            nodes[dst].first = first as u32;
            stack.push((n.first_index as usize, first));
            stack.push((n.first_index as usize + 1, first + 1));
        } else {
            nodes[dst].first = order.len() as u32;
            nodes[dst].count = n.prim_count;
            let run = n.first_index as usize..(n.first_index + n.prim_count) as usize;
            order.extend_from_slice(&bvh.primitive_indices[run]);
        }
    }
    (nodes, order)
}

/// Reorders `items` in place so that slot `s` holds the item that was at `order[s]` (`order` a
/// permutation), one cycle at a time.
fn permute<T: Copy>(items: &mut [T], order: &[u32]) {
    let mut placed = vec![false; items.len()];
    for start in 0..items.len() {
        if placed[start] {
            continue;
        }
        let first = items[start];
        let mut slot = start;
        loop {
            placed[slot] = true;
            let from = order[slot] as usize;
            if from == start {
                items[slot] = first;
                break;
            }
            items[slot] = items[from];
            slot = from;
        }
    }
}

/// Exact boxes, children before parents (children have larger indices).
fn refit(nodes: &mut [BvhNode], corners: &[[DVec3; 3]]) {
    for i in (0..nodes.len()).rev() {
        let node = nodes[i];
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        if node.is_leaf() {
            for p in corners[node.slots()].iter().flatten() {
                lo = lo.min(*p);
                hi = hi.max(*p);
            }
        } else {
            let first = node.first as usize;
            for child in &nodes[first..first + 2] {
                lo = lo.min(child.min);
                hi = hi.max(child.max);
            }
        }
        nodes[i].min = lo;
        nodes[i].max = hi;
    }
}
