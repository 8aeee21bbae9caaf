//! Subdivision of a curve's Bézier pieces into nearly straight spans, and a balanced binary tree
//! of boxes over consecutive spans with a nearest-first search. Both use explicit work lists.

use super::piece::BezierPiece;
use crate::Aabb;
use glam::DVec3;

/// A span is subdivided until its control polygon turns by at most this angle (radians)…
const MAX_TURNING: f64 = 0.3;
/// …and its largest weight is at most this multiple of its smallest…
const MAX_WEIGHT_RATIO: f64 = 1.5;
/// …or it has been halved this many times (a safety net for cusps).
const MAX_DEPTH: u32 = 24;

/// Splits every piece at parameter midpoints until each part is nearly straight: the result
/// covers the same parameters in order.
pub(crate) fn flat_spans(pieces: &[BezierPiece]) -> Vec<BezierPiece> {
    let mut out = Vec::new();
    for piece in pieces {
        let mut work = vec![(piece.clone(), 0u32)];
        while let Some((p, depth)) = work.pop() {
            let turning = p.turning();
            let flat = turning <= MAX_TURNING && p.weight_ratio() <= MAX_WEIGHT_RATIO;
            // A piece whose arithmetic overflowed (turning NaN or infinite) is not split: halving
            // cannot mend it, and splitting to MAX_DEPTH everywhere exhausts memory.
            if flat || !turning.is_finite() || depth >= MAX_DEPTH || p.t1 <= p.t0 {
                out.push(p);
            } else {
                let (l, r) = p.halves();
                // Right first so the left part is handled (and emitted) first.
                work.push((r, depth + 1));
                work.push((l, depth + 1));
            }
        }
    }
    out
}

/// A node of the span tree: an inclusive range of spans and its first child (the second child
/// is `child + 1`); leaves have `child == 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct TreeNode {
    first: u32,
    last: u32,
    child: u32,
}

/// Capacity of the search stack: far more than the depth of a balanced tree over any number of
/// spans that fits in memory (each level holds at most two entries).
const STACK: usize = 128;

/// A balanced binary tree over consecutive spans (node 0 is the root), with one box per node
/// supplied by the owner.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SpanTree {
    nodes: Vec<TreeNode>,
}

impl SpanTree {
    /// The tree over `count ≥ 1` spans: each node's range is halved until single spans.
    pub(crate) fn new(count: usize) -> SpanTree {
        let mut nodes = vec![TreeNode {
            first: 0,
            last: count.saturating_sub(1) as u32,
            child: 0,
        }];
        let mut next = 0;
        while next < nodes.len() {
            let TreeNode { first, last, .. } = nodes[next];
            if first < last {
                let mid = first + (last - first) / 2;
                nodes[next].child = nodes.len() as u32;
                nodes.push(TreeNode {
                    first,
                    last: mid,
                    child: 0,
                });
                nodes.push(TreeNode {
                    first: mid + 1,
                    last,
                    child: 0,
                });
            }
            next += 1;
        }
        SpanTree { nodes }
    }

    /// The inclusive span range of node `i`.
    pub(crate) fn range(&self, i: usize) -> (usize, usize) {
        (self.nodes[i].first as usize, self.nodes[i].last as usize)
    }

    /// The two children of node `i` (none for a leaf).
    pub(crate) fn children(&self, i: usize) -> Option<(usize, usize)> {
        let c = self.nodes[i].child as usize;
        (c != 0).then_some((c, c + 1))
    }

    /// One box per node from one box per span (children are combined before parents).
    pub(crate) fn boxes(&self, span_boxes: &[Aabb]) -> Vec<Aabb> {
        let mut boxes = vec![Aabb::empty(); self.nodes.len()];
        for i in (0..self.nodes.len()).rev() {
            let n = self.nodes[i];
            boxes[i] = if n.child == 0 {
                span_boxes[n.first as usize]
            } else {
                boxes[n.child as usize].union(&boxes[n.child as usize + 1])
            };
        }
        boxes
    }

    /// Visits spans nearest first: `bound(node)` is a lower bound of what any span under the node
    /// can give, `visit(span, best)` returns the new best value. Nodes whose bound is not below
    /// the best so far are skipped. Returns the final best.
    pub(crate) fn search(
        &self,
        bound: impl Fn(usize) -> f64,
        mut visit: impl FnMut(usize, f64) -> f64,
        mut best: f64,
    ) -> f64 {
        let mut stack = [(0u32, 0.0f64); STACK];
        let mut top = 1;
        stack[0] = (0, bound(0));
        while top > 0 {
            top -= 1;
            let (i, lb) = stack[top];
            if lb >= best {
                continue;
            }
            let n = self.nodes[i as usize];
            if n.child == 0 {
                best = visit(n.first as usize, best);
                continue;
            }
            let (a, b) = (n.child, n.child + 1);
            let (la, lb2) = (bound(a as usize), bound(b as usize));
            // Push the farther child first so the nearer one is searched first.
            let (near, far) = if la <= lb2 {
                ((a, la), (b, lb2))
            } else {
                ((b, lb2), (a, la))
            };
            for entry in [far, near] {
                if entry.1 < best && top < STACK {
                    stack[top] = entry;
                    top += 1;
                }
            }
        }
        best
    }
}

/// Squared distance from `p` to the box (0 inside).
pub(crate) fn box_distance_squared(b: &Aabb, p: DVec3) -> f64 {
    let d = (b.min - p).max(p - b.max).max(DVec3::ZERO);
    d.length_squared()
}
