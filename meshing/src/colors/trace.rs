//! Tracing a point through a tree's min/max skeleton ([`ColorSkeleton`]) to the part whose value
//! the tree's field takes there: from the parts evaluated near the point, each node's value and
//! the operand that gives it are found bottom-up (only the nodes above those parts are touched),
//! then the winners are followed from the root.
//!
//! A part that was not evaluated (its box, grown by the margin, does not hold the point) counts
//! as far outside: `+∞`, or `−∞` where it enters negated. Ties between equal values go to the
//! operand that comes first in the tree (an evaluated operand before the far ones).

use solidkit_kernel::color::{ColorSkeleton, Operand};
use std::collections::{BinaryHeap, HashMap};

/// No parent: the skeleton's root.
const ROOT: u32 = u32::MAX;
/// The winner of a node is one of its far operands (none was evaluated).
const FAR: u32 = u32::MAX;

/// The skeleton with what tracing needs precomputed: parents, far values, operand counts.
pub(crate) struct Tracer {
    /// Per part: its node (`ROOT` when the part is the root), its place there, negated.
    part_at: Vec<(u32, u32, bool)>,
    /// Per node: its parent (`ROOT` for the root) and its place there.
    node_at: Vec<(u32, u32)>,
    /// Per node: the minimum (`false`) or maximum (`true`).
    max: Vec<bool>,
    /// Per node: its value when none of its parts is evaluated is `−∞` (else `+∞`).
    far_negative: Vec<bool>,
    /// Per node: how many operands are `−∞` and `+∞` when far.
    far_counts: Vec<(u32, u32)>,
    /// The operands of each node (to follow the winners).
    skeleton: ColorSkeleton,
}

/// One touched node during a trace.
#[derive(Debug, Clone, Copy)]
struct Entry {
    /// The best operand value so far and its place.
    value: f64,
    place: u32,
    /// How many evaluated operands are `−∞` and `+∞` when far.
    offered: (u32, u32),
}

/// Per-thread scratch of [`Tracer::trace`].
#[derive(Default)]
pub(crate) struct Scratch {
    index: HashMap<u32, u32>,
    entries: Vec<Entry>,
    heap: BinaryHeap<u32>,
}

impl Tracer {
    /// Precomputes the tracing tables of `skeleton` (linear in its size, no recursion).
    pub(crate) fn new(skeleton: ColorSkeleton) -> Tracer {
        let n = skeleton.nodes.len();
        let mut part_at = vec![(ROOT, 0, false); skeleton.parts.len()];
        let mut node_at = vec![(ROOT, 0); n];
        for (id, node) in skeleton.nodes.iter().enumerate() {
            for (place, op) in node.operands.iter().enumerate() {
                match *op {
                    Operand::Part { index, negated } => {
                        part_at[index as usize] = (id as u32, place as u32, negated);
                    }
                    Operand::Node(c) => node_at[c as usize] = (id as u32, place as u32),
                }
            }
        }
        let max: Vec<bool> = skeleton.nodes.iter().map(|n| n.max).collect();
        let mut far_negative = vec![false; n];
        let mut far_counts = vec![(0, 0); n];
        // operands have larger indices than their node: last to first sees them first
        for id in (0..n).rev() {
            let (mut neg, mut pos) = (0, 0);
            for op in &skeleton.nodes[id].operands {
                let negative = match *op {
                    Operand::Part { negated, .. } => negated,
                    Operand::Node(c) => far_negative[c as usize],
                };
                if negative {
                    neg += 1;
                } else {
                    pos += 1;
                }
            }
            far_counts[id] = (neg, pos);
            // min: −∞ if any operand is; max: +∞ if any is; no operand: +∞ / −∞
            far_negative[id] = if max[id] { pos == 0 } else { neg > 0 };
        }
        Tracer {
            part_at,
            node_at,
            max,
            far_negative,
            far_counts,
            skeleton,
        }
    }

    /// The skeleton traced.
    pub(crate) fn skeleton(&self) -> &ColorSkeleton {
        &self.skeleton
    }

    /// The part whose value the tree's field takes at a point, given the fields there of the
    /// parts evaluated (`(part, value)`; NaN counts as far outside). `None` when the field there
    /// is a far operand's (`±∞`: a point far from every surface).
    pub(crate) fn trace(&self, values: &[(u32, f64)], s: &mut Scratch) -> Option<u32> {
        s.index.clear();
        s.entries.clear();
        s.heap.clear();
        for &(k, v) in values {
            let (node, place, negated) = self.part_at[k as usize];
            if node == ROOT {
                return Some(k);
            }
            let v = if v.is_nan() { f64::INFINITY } else { v };
            self.offer(s, node, place, if negated { -v } else { v }, negated);
        }
        while let Some(id) = s.heap.pop() {
            let e = &mut s.entries[s.index[&id] as usize];
            let (neg, pos) = self.far_counts[id as usize];
            let (rest_neg, rest_pos) = (neg - e.offered.0, pos - e.offered.1);
            if self.max[id as usize] {
                let rest = if rest_pos > 0 {
                    f64::INFINITY
                } else if rest_neg > 0 {
                    f64::NEG_INFINITY
                } else {
                    f64::NAN
                };
                if rest > e.value {
                    (e.value, e.place) = (rest, FAR);
                }
            } else {
                let rest = if rest_neg > 0 {
                    f64::NEG_INFINITY
                } else if rest_pos > 0 {
                    f64::INFINITY
                } else {
                    f64::NAN
                };
                if rest < e.value {
                    (e.value, e.place) = (rest, FAR);
                }
            }
            let value = e.value;
            let (parent, place) = self.node_at[id as usize];
            if parent != ROOT {
                let negative = self.far_negative[id as usize];
                self.offer(s, parent, place, value, negative);
            }
        }
        let mut at = self.skeleton.root;
        loop {
            match at {
                Operand::Part { index, .. } => {
                    return values.iter().any(|v| v.0 == index).then_some(index);
                }
                Operand::Node(id) => {
                    let e = s.entries[*s.index.get(&id)? as usize];
                    if e.place == FAR {
                        return None;
                    }
                    at = self.skeleton.nodes[id as usize].operands[e.place as usize];
                }
            }
        }
    }

    /// Offers operand `place` of node `id` with `value` (`far_negative`: the operand is `−∞`
    /// when far). Ties go to the earlier place.
    fn offer(&self, s: &mut Scratch, id: u32, place: u32, value: f64, far_negative: bool) {
        let max = self.max[id as usize];
        let k = *s.index.entry(id).or_insert_with(|| {
            s.entries.push(Entry {
                value: if max {
                    f64::NEG_INFINITY
                } else {
                    f64::INFINITY
                },
                place: FAR,
                offered: (0, 0),
            });
            s.heap.push(id);
            (s.entries.len() - 1) as u32
        });
        let e = &mut s.entries[k as usize];
        if far_negative {
            e.offered.0 += 1;
        } else {
            e.offered.1 += 1;
        }
        let better = if max {
            value > e.value
        } else {
            value < e.value
        };
        if better || (value == e.value && place < e.place) {
            (e.value, e.place) = (value, place);
        }
    }
}
