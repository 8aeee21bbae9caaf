//! The tree lowered to a flat postfix program ([`Tape`]) and its evaluators for values,
//! gradients and interval bounds.
//!
//! Lowering walks the tree once with a work list; evaluation is a loop over the instructions with
//! a value stack, so evaluation depth never touches the call stack. Transforms become an
//! `Enter`/`Leave` pair: `Enter` maps the current point (or box) into the child frame, `Leave`
//! restores it and applies the transform's distance factor (and chain rule for gradients).

mod compile;
mod eval;

pub use eval::Scratch;

use crate::primitive::Primitive;
use crate::transform::Transform;

/// One instruction of a [`Tape`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Op {
    /// Evaluate primitive `i` at the current point; push the result.
    Prim(u32),
    /// Save the current point and map it into the frame of transform `i`.
    Enter(u32),
    /// Restore the saved point; scale the top value by transform `i`'s distance factor.
    Leave(u32),
    /// Replace the top `n` values by their minimum (`+∞` when `n = 0`).
    Min(u32),
    /// Replace the top `n` values by their maximum (`−∞` when `n = 0`).
    Max(u32),
    /// Negate the top value.
    Neg,
}

/// A solid lowered to a flat program.
#[derive(Debug, Clone)]
pub struct Tape {
    pub(crate) ops: Vec<Op>,
    pub(crate) primitives: Vec<Primitive>,
    pub(crate) transforms: Vec<Transform>,
    /// Largest value-stack depth reached (for preallocation).
    pub(crate) max_stack: usize,
    /// Deepest nesting of transforms (for preallocation).
    pub(crate) max_frames: usize,
}

impl Tape {
    /// The instructions.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// Number of instructions.
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// True for a tape with no instructions (never produced by lowering a solid).
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }
}

#[cfg(test)]
mod tests;
