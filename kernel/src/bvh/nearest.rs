//! The exact nearest point of a [`TriangleBvh`]'s triangles to a query point.
//!
//! Depth-first with an explicit stack, the nearer child first: a node is skipped when its exact
//! box is no nearer than the best triangle so far, so the result is exact (the minimum of the
//! exact point–triangle distances of `crate::closest` over all triangles). The stack lives in a
//! thread-local buffer, so a query does not allocate.

use super::{TriangleBvh, box_distance2};
use crate::closest::closest_point_on_triangle;
use glam::DVec3;
use std::cell::RefCell;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// The point of the triangles nearest to a query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// Squared distance from the query to `point`.
    pub distance2: f64,
    /// The nearest point.
    pub point: DVec3,
    /// The slot of the triangle it lies on ([`TriangleBvh::slot_index`] gives its input index).
    pub slot: u32,
}

thread_local! {
    static STACK: RefCell<Vec<(u32, f64)>> = const { RefCell::new(Vec::new()) };
    static HEAP: RefCell<BinaryHeap<Reverse<(u64, u32)>>> = const { RefCell::new(BinaryHeap::new()) };
}

/// Runs `f` with the thread's cleared traversal stack (a fresh one if it is in use).
fn with_stack<R>(f: impl FnOnce(&mut Vec<(u32, f64)>) -> R) -> R {
    STACK.with(|cell| match cell.try_borrow_mut() {
        Ok(mut stack) => {
            stack.clear();
            f(&mut stack)
        }
        Err(_) => f(&mut Vec::new()),
    })
}

fn with_heap<R>(f: impl FnOnce(&mut BinaryHeap<Reverse<(u64, u32)>>) -> R) -> R {
    HEAP.with(|cell| match cell.try_borrow_mut() {
        Ok(mut stack) => {
            stack.clear();
            f(&mut stack)
        }
        Err(_) => f(&mut BinaryHeap::new()),
    })
}

impl TriangleBvh {
    /// The nearest point of the triangles to `q` (`None` for an empty tree). On exact ties the
    /// triangle reported is one of the nearest.
    pub fn nearest(&self, q: DVec3) -> Option<Nearest> {
        static BEST: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
        if *BEST.get_or_init(|| std::env::var_os("BVH_BEST_FIRST").is_some()) {
            self.nearest_best_first(q)
        } else {
            self.nearest_depth_first(q)
        }
    }

    fn nearest_depth_first(&self, q: DVec3) -> Option<Nearest> {
        let root = self.nodes.first()?;
        let mut best = Nearest {
            distance2: f64::INFINITY,
            point: q,
            slot: 0,
        };
        with_stack(|stack| {
            stack.push((0, box_distance2(root.min, root.max, q)));
            while let Some((index, d2)) = stack.pop() {
                if d2 >= best.distance2 {
                    continue;
                }
                let node = &self.nodes[index as usize];
                if node.is_leaf() {
                    for slot in node.slots() {
                        let p = closest_point_on_triangle(q, self.corners[slot]);
                        let d2 = p.distance_squared(q);
                        if d2 < best.distance2 {
                            best = Nearest {
                                distance2: d2,
                                point: p,
                                slot: slot as u32,
                            };
                        }
                    }
                    continue;
                }
                let (l, r) = (node.first, node.first + 1);
                let (nl, nr) = (&self.nodes[l as usize], &self.nodes[r as usize]);
                let dl = box_distance2(nl.min, nl.max, q);
                let dr = box_distance2(nr.min, nr.max, q);
                // Push the farther child first so the nearer one is visited next.
                let (near, far) = if dl <= dr {
                    ((l, dl), (r, dr))
                } else {
                    ((r, dr), (l, dl))
                };
                if far.1 < best.distance2 {
                    stack.push(far);
                }
                if near.1 < best.distance2 {
                    stack.push(near);
                }
            }
        });
        Some(best)
    }

    fn nearest_best_first(&self, q: DVec3) -> Option<Nearest> {
        let root = self.nodes.first()?;
        let mut best = Nearest {
            distance2: f64::INFINITY,
            point: q,
            slot: 0,
        };
        with_heap(|queue| {
            queue.push(Reverse((box_distance2(root.min, root.max, q).to_bits(), 0)));
            while let Some(Reverse((bits, index))) = queue.pop() {
                if f64::from_bits(bits) >= best.distance2 {
                    break;
                }
                let node = &self.nodes[index as usize];
                if node.is_leaf() {
                    for slot in node.slots() {
                        let p = closest_point_on_triangle(q, self.corners[slot]);
                        let d2 = p.distance_squared(q);
                        if d2 < best.distance2 {
                            best = Nearest {
                                distance2: d2,
                                point: p,
                                slot: slot as u32,
                            };
                        }
                    }
                    continue;
                }
                for child in [node.first, node.first + 1] {
                    let c = &self.nodes[child as usize];
                    let d2 = box_distance2(c.min, c.max, q);
                    if d2 < best.distance2 {
                        queue.push(Reverse((d2.to_bits(), child)));
                    }
                }
            }
        });
        Some(best)
    }
}
