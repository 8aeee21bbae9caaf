//! Lowering a [`Solid`] to a [`Program`] with a work list: transforms folded into per-leaf frames,
//! identical subtrees and equal leaves shared, trivial instructions simplified on the way.

use super::{Frame, Infinity, Instr, Program};
use crate::Aabb;
use crate::primitive::{Primitive, Shape};
use crate::solid::{NodeKind, Solid, node_bbox};
use glam::DVec3;
use std::collections::HashMap;

/// Bucket key for leaves that may be equal: frame, kind and bounding box bits.
type LeafKey = (u32, &'static str, [u64; 6]);

#[derive(Default)]
struct Lowerer {
    instrs: Vec<Instr>,
    primitives: Vec<Primitive>,
    frames: Vec<Frame>,
    frame_ids: HashMap<[u64; 13], u32>,
    instr_ids: HashMap<Instr, u32>,
    /// (node address, frame) → value: a shared subtree under the same frame is lowered once.
    memo: HashMap<(usize, u32), (u32, Aabb)>,
    leaves: HashMap<LeafKey, Vec<u32>>,
}

impl Lowerer {
    fn frame_id(&mut self, f: Frame) -> u32 {
        let next = self.frames.len() as u32;
        let id = *self.frame_ids.entry(f.key()).or_insert(next);
        if id == next {
            self.frames.push(f);
        }
        id
    }

    /// Appends an instruction, or returns an existing equal one, after local simplification.
    fn emit(&mut self, i: Instr) -> u32 {
        let konst = |s: &Self, v: u32| match s.instrs[v as usize] {
            Instr::Const(c) => Some(c),
            _ => None,
        };
        match i {
            Instr::Min(a, b) | Instr::Max(a, b) if a == b => return a,
            Instr::Min(a, b) if konst(self, a) == Some(Infinity::Positive) => return b,
            Instr::Min(a, b) if konst(self, b) == Some(Infinity::Positive) => return a,
            Instr::Max(a, b) if konst(self, a) == Some(Infinity::Negative) => return b,
            Instr::Max(a, b) if konst(self, b) == Some(Infinity::Negative) => return a,
            Instr::Neg(a) => {
                if let Instr::Neg(x) = self.instrs[a as usize] {
                    return x;
                }
            }
            _ => {}
        }
        // Idempotence: min(min(x, y), y) = min(x, y), and the same for max.
        if let Instr::Min(a, b) | Instr::Max(a, b) = i {
            let is_min = matches!(i, Instr::Min(..));
            for (v, w) in [(a, b), (b, a)] {
                match self.instrs[v as usize] {
                    Instr::Min(x, y) if is_min && (x == w || y == w) => return v,
                    Instr::Max(x, y) if !is_min && (x == w || y == w) => return v,
                    _ => {}
                }
            }
        }
        if let Some(&v) = self.instr_ids.get(&i) {
            return v;
        }
        self.instrs.push(i);
        let v = (self.instrs.len() - 1) as u32;
        self.instr_ids.insert(i, v);
        v
    }

    fn leaf(&mut self, p: &Primitive, frame: u32) -> u32 {
        let frame = if let Primitive::Gyroid(_) = p {
            // Periodic: a far offset only loses precision (see `Frame::reduced_offset`).
            let reduced = self.frames[frame as usize].reduced_offset(std::f64::consts::TAU);
            self.frame_id(reduced)
        } else {
            frame
        };
        let b = p.bbox();
        let key = (
            frame,
            p.name(),
            [b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z].map(f64::to_bits),
        );
        let bucket = self.leaves.entry(key).or_default();
        for &v in bucket.iter() {
            if let Instr::Leaf { prim, .. } = self.instrs[v as usize]
                && self.primitives[prim as usize] == *p
            {
                return v;
            }
        }
        self.primitives.push(p.clone());
        let prim = (self.primitives.len() - 1) as u32;
        let v = self.emit(Instr::Leaf { prim, frame });
        self.leaves.get_mut(&key).expect("bucket").push(v);
        v
    }

    /// The value of a node whose children's values are `c`.
    fn combine(&mut self, kind: &NodeKind, frame: u32, children: &[(u32, Aabb)]) -> u32 {
        let c: Vec<u32> = children.iter().map(|x| x.0).collect();
        let c = c.as_slice();
        // The children's values are in world units: the node's own lengths (blend radius,
        // offset distance, shell thickness) are in its frame's units and scale by the frame's
        // distance factor σ, like the leaves' values (the smooth minimum is 1-homogeneous:
        // smin(σa, σb, σr) = σ·smin(a, b, r)), so the zero set is the node's, transformed.
        let sigma = self.frames[frame as usize].sigma;
        match kind {
            NodeKind::Primitive(p) => self.leaf(p, frame),
            NodeKind::SmoothUnion { radius } => {
                let r = blend_radius(*radius * sigma);
                self.fold(c, |a, b| smooth_min(a, b, r), Infinity::Positive)
            }
            // smooth max(a, b) = −smooth min(−a, −b).
            NodeKind::SmoothIntersection { radius } => {
                let negated: Vec<u32> = c.iter().map(|&x| self.emit(Instr::Neg(x))).collect();
                let r = blend_radius(*radius * sigma);
                let m = self.fold(&negated, |a, b| smooth_min(a, b, r), Infinity::Positive);
                self.emit(Instr::Neg(m))
            }
            // a minus b = smooth max(a, −b) = −smooth min(−a, b).
            NodeKind::SmoothDifference { radius } => {
                let Some((&first, rest)) = c.split_first() else {
                    return self.emit(Instr::Const(Infinity::Positive));
                };
                let r = blend_radius(*radius * sigma);
                let start = self.emit(Instr::Neg(first));
                let m = rest
                    .iter()
                    .fold(start, |acc, &x| self.emit(smooth_min(acc, x, r)));
                self.emit(Instr::Neg(m))
            }
            NodeKind::Offset { distance } => {
                let child = self.fold(c, Instr::Min, Infinity::Positive);
                self.emit(Instr::AddConst(child, super::Bits::of(-distance * sigma)))
            }
            NodeKind::Shell { thickness } => {
                let child = self.fold(c, Instr::Min, Infinity::Positive);
                let a = self.emit(Instr::Abs(child));
                self.emit(Instr::AddConst(
                    a,
                    super::Bits::of(-0.5 * thickness * sigma),
                ))
            }
            // A colour changes nothing in the field: the child's value, no instruction.
            NodeKind::Transform(_) | NodeKind::Color(_) => {
                self.fold(c, Instr::Min, Infinity::Positive)
            }
            NodeKind::Union => self.balanced(children, Instr::Min, Infinity::Positive),
            NodeKind::Intersection => self.balanced(children, Instr::Max, Infinity::Negative),
            // max(a, −b₁, −b₂, …) = max(a, −min(b₁, b₂, …)), exactly.
            NodeKind::Difference => {
                let Some((first, rest)) = children.split_first() else {
                    return self.emit(Instr::Const(Infinity::Positive));
                };
                if rest.is_empty() {
                    return first.0;
                }
                let cutters = self.balanced(rest, Instr::Min, Infinity::Positive);
                let n = self.emit(Instr::Neg(cutters));
                self.emit(Instr::Max(first.0, n))
            }
        }
    }

    /// A balanced tree of `op` over the operands, ordered along a Morton curve of their box
    /// centres, so every subtree is spatially compact and interval pruning can drop whole
    /// subtrees far from a box. (Min and max are exact, so the shape does not change values.)
    fn balanced(
        &mut self,
        children: &[(u32, Aabb)],
        op: impl Fn(u32, u32) -> Instr,
        empty: Infinity,
    ) -> u32 {
        if children.is_empty() {
            return self.emit(Instr::Const(empty));
        }
        let finite = children
            .iter()
            .filter(|c| c.1.is_finite())
            .fold(Aabb::empty(), |a, c| a.union(&c.1));
        let mut items: Vec<(u64, u32)> = children
            .iter()
            .map(|(v, b)| {
                (
                    if b.is_finite() {
                        morton(b.center(), &finite)
                    } else {
                        0
                    },
                    *v,
                )
            })
            .collect();
        items.sort_by_key(|i| i.0);
        let mut level: Vec<u32> = items.into_iter().map(|i| i.1).collect();
        while level.len() > 1 {
            let next: Vec<u32> = level
                .chunks(2)
                .map(|pair| match *pair {
                    [a, b] => self.emit(op(a, b)),
                    [a] => a,
                    _ => unreachable!("chunks of two"),
                })
                .collect();
            level = next;
        }
        level[0]
    }

    fn fold(&mut self, c: &[u32], op: impl Fn(u32, u32) -> Instr, empty: Infinity) -> u32 {
        match c.split_first() {
            None => self.emit(Instr::Const(empty)),
            Some((&first, rest)) => rest.iter().fold(first, |acc, &x| self.emit(op(acc, x))),
        }
    }
}

impl Solid {
    /// Lowers the tree to a [`Program`] (no recursion; shared subtrees lowered once).
    pub fn lower(&self) -> Program {
        let mut l = Lowerer::default();
        let world = l.frame_id(Frame::identity());
        // Work list of (node, frame, children visited); values of finished children on `done`.
        let mut stack: Vec<(&Solid, u32, usize)> = vec![(self, world, 0)];
        // Values of finished children, with their boxes in their parent's coordinates.
        let mut done: Vec<(u32, Aabb)> = Vec::new();
        while let Some(top) = stack.last_mut() {
            let (solid, frame, next) = *top;
            let key = (std::sync::Arc::as_ptr(&solid.0) as usize, frame);
            if next == 0
                && let Some(&v) = l.memo.get(&key)
            {
                stack.pop();
                done.push(v);
                continue;
            }
            let leaf = matches!(solid.kind(), NodeKind::Primitive(_));
            if let Some(child) = solid.children().get(next).filter(|_| !leaf) {
                top.1 = frame;
                top.2 += 1;
                let child_frame = match solid.kind() {
                    NodeKind::Transform(t) => {
                        let f = l.frames[frame as usize].then(t);
                        l.frame_id(f)
                    }
                    _ => frame,
                };
                stack.push((child, child_frame, 0));
                continue;
            }
            stack.pop();
            let n = if leaf { 0 } else { solid.children().len() };
            let start = done.len() - n;
            let children: Vec<(u32, Aabb)> = done.split_off(start);
            let boxes: Vec<Aabb> = children.iter().map(|c| c.1).collect();
            let bbox = node_bbox(solid.kind(), &boxes);
            let v = l.combine(solid.kind(), frame, &children);
            l.memo.insert(key, (v, bbox));
            done.push((v, bbox));
        }
        let result = done.pop().expect("root value").0;
        let (instrs, result) = compact(&l.instrs, result);
        Program::from_parts(
            instrs,
            std::sync::Arc::new(l.primitives),
            std::sync::Arc::new(l.frames),
        )
        .with_result_last(result)
    }
}

/// The blend radius every evaluator uses for a blend of radius `r` (world units), or `None` for a
/// plain minimum. The f32 batch path divides by the radius rounded to single precision, so a
/// radius below the smallest normal `f32` (about 1.2·10⁻³⁸; the blend is far below any sampling
/// resolution there) is lowered as the exact minimum, and one above `f32::MAX` is clamped to it:
/// the f32 and f64 evaluators then run the same instruction and agree.
pub(crate) fn blend_radius(r: f64) -> Option<super::Bits> {
    let r = r.min(f32::MAX as f64);
    ((r as f32).is_normal() && r > 0.0).then(|| super::Bits::of(r))
}

/// The smooth minimum of `a` and `b` with radius `r`, or the plain minimum (see [`blend_radius`]).
fn smooth_min(a: u32, b: u32, r: Option<super::Bits>) -> Instr {
    match r {
        Some(r) => Instr::SmoothMin(a, b, r),
        None => Instr::Min(a, b),
    }
}

/// Morton code (10 bits per axis) of `p` within `domain`.
fn morton(p: DVec3, domain: &Aabb) -> u64 {
    let size = domain.size().max(DVec3::splat(1e-300));
    let q = ((p - domain.min) / size * 1023.0).clamp(DVec3::ZERO, DVec3::splat(1023.0));
    let spread = |v: f64| {
        let mut x = v as u64;
        let mut out = 0u64;
        for bit in 0..10 {
            out |= (x & 1) << (3 * bit);
            x >>= 1;
        }
        out
    };
    spread(q.x) | spread(q.y) << 1 | spread(q.z) << 2
}

/// Keeps only instructions the result depends on (in order) and renumbers operands; returns the
/// new list and the result's new index.
pub(crate) fn compact(instrs: &[Instr], result: u32) -> (Vec<Instr>, u32) {
    let mut live = vec![false; instrs.len()];
    live[result as usize] = true;
    for i in (0..=result as usize).rev() {
        if !live[i] {
            continue;
        }
        let (ops, k) = super::regalloc::operands(&instrs[i]);
        for &o in &ops[..k] {
            live[o as usize] = true;
        }
    }
    let mut new_index = vec![u32::MAX; instrs.len()];
    let mut out = Vec::new();
    for (i, ins) in instrs.iter().enumerate().take(result as usize + 1) {
        if !live[i] {
            continue;
        }
        let r = |v: u32| new_index[v as usize];
        out.push(remap(*ins, r));
        new_index[i] = (out.len() - 1) as u32;
    }
    let res = new_index[result as usize];
    (out, res)
}

/// The instruction with its operands renumbered by `r`.
pub(crate) fn remap(ins: Instr, r: impl Fn(u32) -> u32) -> Instr {
    match ins {
        Instr::Min(a, b) => Instr::Min(r(a), r(b)),
        Instr::Max(a, b) => Instr::Max(r(a), r(b)),
        Instr::SmoothMin(a, b, k) => Instr::SmoothMin(r(a), r(b), k),
        Instr::Neg(a) => Instr::Neg(r(a)),
        Instr::Abs(a) => Instr::Abs(r(a)),
        Instr::AddConst(a, k) => Instr::AddConst(r(a), k),
        other @ (Instr::Leaf { .. } | Instr::Const(_)) => other,
    }
}

impl Program {
    /// Checks the result is the last instruction (compaction guarantees it).
    fn with_result_last(self, result: u32) -> Self {
        debug_assert_eq!(result as usize + 1, self.instrs.len());
        self
    }
}
