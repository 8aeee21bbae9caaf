//! The edge index of a polygon with many corners (issue 15: an extrusion of a 30 000-point polygon
//! took over a minute to mesh, every sample measuring every edge).
//!
//! The edges sit in the kernel's [`TriangleBvh`] (edge `a → b` stored as the flat triangle
//! `[a, b, b]` at `z = 0`, whose box is the edge's), numbered in loop order: edge `g` of the
//! whole polygon is the edge ending at corner `i` of loop `r`, as the plain loop
//! [`loops_distance_skipping`](super::polygon::loops_distance_skipping) visits them. A query gives
//! exactly the plain loop's answer:
//!
//! - the nearest edge is the least `(squared distance, number)` over the edges, each squared
//!   distance computed by the same formula; subtrees are skipped only when their box is farther
//!   than the best distance by more than the formula's rounding error;
//! - inside or outside is the parity of the same crossing test over the edges whose box spans the
//!   query's `y` and reaches right of it (the others cannot cross the ray), which does not depend
//!   on the order.

use super::nearest::{Best, Nearest, closest, crosses};
use crate::bvh::{TriangleBvh, box_distance2};
use glam::DVec2;
use std::cell::RefCell;

/// From this many edges a polygon builds an index.
pub(super) const MIN_EDGES: usize = 64;

thread_local! {
    static STACK: RefCell<Vec<(u32, f64)>> = const { RefCell::new(Vec::new()) };
}

/// The edges of a polygon's loops in a tree.
#[derive(Debug, Clone)]
pub(super) struct EdgeIndex {
    pub(super) tree: TriangleBvh,
    /// Number of the first edge of each loop, and the total at the end.
    starts: Vec<usize>,
    /// The largest coordinate magnitude of the corners (for the rounding margin).
    pub(super) scale: f64,
}

impl EdgeIndex {
    /// The index of `loops` (finite corners); `None` below [`MIN_EDGES`] edges.
    pub(super) fn new(loops: &[Vec<DVec2>]) -> Option<EdgeIndex> {
        let total: usize = loops.iter().map(Vec::len).sum();
        if total < MIN_EDGES {
            return None;
        }
        let mut starts = Vec::with_capacity(loops.len() + 1);
        let mut edges = Vec::with_capacity(total);
        let mut scale = 0.0f64;
        for corners in loops {
            starts.push(edges.len());
            let n = corners.len();
            for i in 0..n {
                let (a, b) = (corners[(i + n - 1) % n], corners[i]);
                scale = scale.max(b.abs().max_element());
                let (a, b) = (a.extend(0.0), b.extend(0.0));
                edges.push([a, b, b]);
            }
        }
        starts.push(edges.len());
        let tree = TriangleBvh::new(edges, 4).ok()?;
        Some(EdgeIndex {
            tree,
            starts,
            scale,
        })
    }

    /// Loop and corner of edge `g`.
    pub(super) fn locate(&self, g: usize) -> (usize, usize) {
        let r = self.starts.partition_point(|&s| s <= g) - 1;
        (r, g - self.starts[r])
    }

    /// The plain loop's answer ([`super::polygon::loops_distance_skipping`]) for `q` (finite).
    pub(super) fn nearest(
        &self,
        loops: &[Vec<DVec2>],
        q: DVec2,
        skip: impl Fn(DVec2, DVec2) -> bool,
    ) -> Nearest {
        let nodes = self.tree.nodes();
        let q3 = q.extend(0.0);
        // How far a computed edge distance may fall below the true one.
        let margin = 1e-14 * (self.scale + q.abs().max_element());
        // The best edge so far and its number.
        let (mut best, mut best_g) = (Best::NONE, usize::MAX);
        crate::bvh::with_scratch(&STACK, |stack| {
            stack.push((0, box_distance2(nodes[0].min, nodes[0].max, q3)));
            while let Some((index, d2)) = stack.pop() {
                let reach = best.d2.sqrt() + margin;
                if d2 > reach * reach {
                    continue;
                }
                let node = &nodes[index as usize];
                if node.is_leaf() {
                    for slot in node.slots() {
                        let g = self.tree.slot_index(slot) as usize;
                        let (r, i) = self.locate(g);
                        let n = loops[r].len();
                        let (a, b) = (loops[r][(i + n - 1) % n], loops[r][i]);
                        let (lambda, c, e, d2) = closest(a, b, q);
                        if (d2 < best.d2 || (d2 == best.d2 && g < best_g)) && !skip(a, b) {
                            best_g = g;
                            best = Best {
                                d2,
                                ring: r,
                                edge: (i + n - 1) % n,
                                lambda,
                                c,
                                e,
                            };
                        }
                    }
                } else {
                    let (l, h) = (node.first, node.first + 1);
                    let dl = box_distance2(nodes[l as usize].min, nodes[l as usize].max, q3);
                    let dh = box_distance2(nodes[h as usize].min, nodes[h as usize].max, q3);
                    // The nearer child is popped first.
                    if dl <= dh {
                        stack.extend([(h, dh), (l, dl)]);
                    } else {
                        stack.extend([(l, dl), (h, dh)]);
                    }
                }
            }
        });
        best.signed(self.crossings_odd(loops, q, margin), q)
    }

    /// Whether the ray from `q` towards `+x` crosses the edges an odd number of times.
    fn crossings_odd(&self, loops: &[Vec<DVec2>], q: DVec2, margin: f64) -> bool {
        let nodes = self.tree.nodes();
        let mut inside = false;
        crate::bvh::with_scratch(&STACK, |stack| {
            stack.push((0, 0.0));
            while let Some((index, _)) = stack.pop() {
                let node = &nodes[index as usize];
                // An edge crossing the ray spans q.y and reaches right of q.x (up to rounding).
                if node.min.y > q.y || node.max.y < q.y || node.max.x + margin < q.x {
                    continue;
                }
                if node.is_leaf() {
                    for slot in node.slots() {
                        let (r, i) = self.locate(self.tree.slot_index(slot) as usize);
                        let n = loops[r].len();
                        let (a, b) = (loops[r][(i + n - 1) % n], loops[r][i]);
                        if crosses(q, a, b) {
                            inside = !inside;
                        }
                    }
                } else {
                    stack.extend([(node.first, 0.0), (node.first + 1, 0.0)]);
                }
            }
        });
        inside
    }
}
