//! Lowering a [`Solid`] to a [`Tape`] with a work list (no recursion).

use super::{Op, Tape};
use crate::solid::{NodeKind, Solid};

impl Solid {
    /// Lowers the tree to a flat postfix program.
    pub fn compile(&self) -> Tape {
        let mut tape = Tape {
            ops: Vec::new(),
            primitives: Vec::new(),
            transforms: Vec::new(),
            max_stack: 0,
            max_frames: 0,
        };
        let mut depth = 0usize;
        let mut frames_depth = 0usize;
        let mut frames: Vec<(&Solid, usize)> = vec![(self, 0)];
        while let Some(top) = frames.last_mut() {
            let (solid, next) = *top;
            if next == 0
                && let NodeKind::Transform(t) = solid.kind()
            {
                tape.ops.push(Op::Enter(tape.transforms.len() as u32));
                tape.transforms.push(**t);
                frames_depth += 1;
                tape.max_frames = tape.max_frames.max(frames_depth);
            }
            // Children of a primitive (an invalid tree) are ignored rather than unbalancing the stack.
            let leaf = matches!(solid.kind(), NodeKind::Primitive(_));
            if let Some(child) = solid.children().get(next).filter(|_| !leaf) {
                top.1 += 1;
                frames.push((child, 0));
                continue;
            }
            frames.pop();
            let n = solid.children().len() as u32;
            match solid.kind() {
                NodeKind::Primitive(p) => {
                    tape.ops.push(Op::Prim(tape.primitives.len() as u32));
                    tape.primitives.push(p.clone());
                    depth += 1;
                }
                NodeKind::Union => {
                    tape.ops.push(Op::Min(n));
                    depth = depth + 1 - n as usize;
                }
                NodeKind::Intersection | NodeKind::Difference => {
                    tape.ops.push(Op::Max(n));
                    depth = depth + 1 - n as usize;
                }
                NodeKind::Transform(_) => {
                    // A transform has one child; any other count (an invalid tree) is read as a union.
                    if n != 1 {
                        tape.ops.push(Op::Min(n));
                        depth = depth + 1 - n as usize;
                    }
                    // Enter/Leave nest like brackets; `resolve_leaves` pairs them afterwards.
                    tape.ops.push(Op::Leave(u32::MAX));
                    frames_depth -= 1;
                }
            }
            tape.max_stack = tape.max_stack.max(depth);
            // A subtrahend of a difference is negated as soon as it is complete.
            if let Some(&(parent, visited)) = frames.last()
                && matches!(parent.kind(), NodeKind::Difference)
                && visited >= 2
            {
                tape.ops.push(Op::Neg);
            }
        }
        resolve_leaves(&mut tape.ops);
        tape
    }
}

/// Pairs every `Leave` placeholder with its `Enter` (they nest like brackets).
fn resolve_leaves(ops: &mut [Op]) {
    let mut open: Vec<u32> = Vec::new();
    for op in ops.iter_mut() {
        match *op {
            Op::Enter(i) => open.push(i),
            Op::Leave(_) => *op = Op::Leave(open.pop().expect("balanced transforms")),
            _ => {}
        }
    }
}
