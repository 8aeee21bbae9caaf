//! Box queries on a [`TriangleBvh`]: the slot ranges of its leaves, and every triangle whose box
//! meets a given box (explicit stack in a thread-local buffer). These drive the self-intersection
//! broad phase of the meshing crate: one overlap query per leaf box.

use super::{TriangleBvh, with_scratch};
use glam::DVec3;
use std::cell::RefCell;
use std::ops::Range;

thread_local! {
    static STACK: RefCell<Vec<u32>> = const { RefCell::new(Vec::new()) };
}

/// True when the closed boxes `[lo, hi]` and `[l, h]` meet.
fn meets(lo: DVec3, hi: DVec3, l: DVec3, h: DVec3) -> bool {
    l.cmple(hi).all() && lo.cmple(h).all()
}

impl TriangleBvh {
    /// The slot ranges of the leaves, ascending (together, every slot once).
    pub fn leaves(&self) -> Vec<Range<usize>> {
        let mut leaves: Vec<Range<usize>> = self
            .nodes
            .iter()
            .filter(|n| n.is_leaf())
            .map(|n| n.slots())
            .collect();
        leaves.sort_unstable_by_key(|r| r.start);
        leaves
    }

    /// Calls `f(slot)` for every triangle whose box meets the closed box `[lo, hi]` (touching
    /// counts), in no particular order.
    pub fn for_each_overlap(&self, lo: DVec3, hi: DVec3, mut f: impl FnMut(usize)) {
        if self.nodes.is_empty() {
            return;
        }
        with_scratch(&STACK, |stack| {
            stack.push(0);
            while let Some(i) = stack.pop() {
                let node = &self.nodes[i as usize];
                if !meets(lo, hi, node.min, node.max) {
                    continue;
                }
                if node.is_leaf() {
                    for slot in node.slots() {
                        let [a, b, c] = self.corners[slot];
                        if meets(lo, hi, a.min(b).min(c), a.max(b).max(c)) {
                            f(slot);
                        }
                    }
                } else {
                    stack.extend([node.first, node.first + 1]);
                }
            }
        });
    }
}
