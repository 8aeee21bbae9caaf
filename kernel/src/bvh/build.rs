//! Building a [`TriangleBvh`]: the obvhs build over padded `f32` triangle boxes in normalised
//! coordinates, the copy into the flat layout (explicit stack; slots numbered leaf by leaf, so
//! every subtree owns a contiguous run), the triangles moved into slot order in place, and the
//! exact `f64` boxes refitted children first.
//!
//! Repeated boxes: obvhs's PLOC build degenerates to quadratic time when many primitives have the
//! same box (40 000 copies of one triangle took 15 s). When some box occurs more than
//! [`REPEAT_LIMIT`] times, obvhs builds over the distinct boxes only and each of its leaves is
//! expanded into a balanced subtree of the triangles it stands for (leaves of at most
//! `leaf_size`). Inputs without such repeats are built exactly as before.

use super::{BvhError, BvhNode, TriangleBvh};
use glam::{DVec3, Vec3A};
use obvhs::aabb::Aabb as Box32;
use obvhs::bvh2::Bvh2;
use obvhs::{Boundable, BvhBuildParams};
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::time::Duration;

/// More triangles than this with one box switch the build to distinct boxes.
const REPEAT_LIMIT: usize = 32;

/// A multiplicative hasher for the box keys (fast; the keys are not adversarial to the table,
/// only to the builder).
#[derive(Default)]
struct BoxHasher(u64);

impl Hasher for BoxHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u32(&mut self, n: u32) {
        self.write_u64(u64::from(n));
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

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
        let leaf_size = leaf_size.clamp(1, 255);
        let boxes = builder_boxes(&triangles);
        let groups = repeated_boxes(&boxes);
        let (mut nodes, order) = match &groups {
            None => flatten(&build(&boxes, leaf_size), None, leaf_size),
            Some(groups) => {
                let distinct: Vec<TriangleBox> = groups
                    .iter()
                    .map(|g| TriangleBox(boxes[g[0] as usize].0))
                    .collect();
                flatten(&build(&distinct, leaf_size), Some(groups), leaf_size)
            }
        };
        drop(groups);
        permute(&mut triangles, &order);
        refit(&mut nodes, &triangles);
        Ok(Self {
            nodes,
            corners: triangles,
            order,
        })
    }
}

/// The triangles grouped by builder box (groups in order of first occurrence, indices
/// ascending), if some box occurs more than [`REPEAT_LIMIT`] times.
fn repeated_boxes(boxes: &[TriangleBox]) -> Option<Vec<Vec<u32>>> {
    let key = |b: &TriangleBox| {
        let (lo, hi) = (b.0.min, b.0.max);
        [lo.x, lo.y, lo.z, hi.x, hi.y, hi.z].map(f32::to_bits)
    };
    let mut ids: HashMap<[u32; 6], u32, BuildHasherDefault<BoxHasher>> = HashMap::default();
    let mut groups: Vec<Vec<u32>> = Vec::new();
    for (i, b) in boxes.iter().enumerate() {
        let next = groups.len() as u32;
        let id = *ids.entry(key(b)).or_insert(next);
        if id == next {
            groups.push(Vec::new());
        }
        groups[id as usize].push(i as u32);
    }
    groups
        .iter()
        .any(|g| g.len() > REPEAT_LIMIT)
        .then_some(groups)
}

/// The triangles' boxes for the builder, in coordinates normalised to their bounding box.
fn builder_boxes(triangles: &[[DVec3; 3]]) -> Vec<TriangleBox> {
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
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(normalised);
            // Padded: the builder's costs use box areas, which flat boxes would zero.
            TriangleBox(Box32::new(a.min(b).min(c) - 1e-6, a.max(b).max(c) + 1e-6))
        })
        .collect()
}

/// The obvhs tree over `boxes`.
fn build(boxes: &[TriangleBox], leaf_size: u32) -> Bvh2 {
    let params = BvhBuildParams {
        max_prims_per_leaf: leaf_size,
        ..BvhBuildParams::fast_build()
    };
    obvhs::bvh2::builder::build_bvh2(boxes, params, &mut Duration::default())
}

/// Copies the builder's tree into the flat layout (children side by side, after their parent;
/// boxes left for [`refit`]) and lists the input index of each slot. With `groups`, the
/// builder's primitives are groups of triangles and each leaf becomes a balanced subtree of its
/// groups' triangles, at most `leaf_size` per leaf.
fn flatten(bvh: &Bvh2, groups: Option<&[Vec<u32>]>, leaf_size: u32) -> (Vec<BvhNode>, Vec<u32>) {
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
            let run = n.first_index as usize..(n.first_index + n.prim_count) as usize;
            let Some(groups) = groups else {
                nodes[dst].first = order.len() as u32;
                nodes[dst].count = n.prim_count;
                order.extend_from_slice(&bvh.primitive_indices[run]);
                continue;
            };
            let list: Vec<u32> = bvh.primitive_indices[run]
                .iter()
                .flat_map(|&g| groups[g as usize].iter().copied())
                .collect();
            // Halves until each part fits a leaf; depth first, so slots stay contiguous.
            let mut parts = vec![(dst, 0..list.len())];
            while let Some((at, part)) = parts.pop() {
                if part.len() <= leaf_size as usize {
                    nodes[at].first = order.len() as u32;
                    nodes[at].count = part.len() as u32;
                    order.extend_from_slice(&list[part]);
                } else {
                    let first = nodes.len();
                    nodes.push(BvhNode::default());
                    nodes.push(BvhNode::default());
                    nodes[at].first = first as u32;
                    let mid = part.start + part.len() / 2;
                    parts.push((first + 1, mid..part.end));
                    parts.push((first, part.start..mid));
                }
            }
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
