//! The tree lowered to a flat program: the form every evaluator runs.
//!
//! [`Program`] is a list of instructions in SSA form (instruction `i` defines value `i`, operands are
//! earlier values). Lowering (`lower.rs`) folds every chain of transforms into one inverse affine map
//! per leaf ([`Frame`]), shares identical subtrees (the same node under the same frame, and
//! structurally equal leaves) and turns n-ary Booleans into binary `Min`/`Max` with `Neg` for
//! subtrahends. Registers are allocated by liveness so batch evaluation touches few buffers.
//!
//! Evaluators: [`batch`] (f32, structure of arrays, chunks of [`CHUNK`] points, loops written for
//! auto-vectorisation), [`gradients`] (f64 values and gradients over slices of points), [`scalar`]
//! (f64 value and gradient at one point), and [`interval`] (f64
//! interval over a box, recording which operand of each min/max can win so a box gets a shorter
//! program valid inside it).

pub mod batch;
mod frame;
pub mod gradients;
pub mod interval;
mod lower;
pub mod perturb;
mod regalloc;
pub mod scalar;

pub use crate::eval::Pruned;
pub use batch::{BatchScratch, CHUNK};
pub use frame::Frame;
pub use gradients::GradientScratch;
pub use interval::{Choice, IntervalScratch};

use crate::primitive::Primitive;
use std::sync::Arc;

/// One instruction; its result is the value with the instruction's index.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Instr {
    /// Primitive `prim` evaluated in frame `frame`, scaled by the frame's distance factor.
    Leaf {
        /// Index into the program's primitive list.
        prim: u32,
        /// Index into the program's frame list.
        frame: u32,
    },
    /// `min(a, b)`.
    Min(u32, u32),
    /// `max(a, b)`.
    Max(u32, u32),
    /// `−a`.
    Neg(u32),
    /// Quadratic smooth minimum of `a` and `b` with blend radius `r` (bits of an f64):
    /// `min(a, b) − r·h²/4` with `h = max(r − |a − b|, 0)/r`. Its gradient is a convex
    /// combination of the operands' gradients, so Lipschitz bounds are preserved.
    SmoothMin(u32, u32, Bits),
    /// `|a|`.
    Abs(u32),
    /// `a + c` (bits of an f64).
    AddConst(u32, Bits),
    /// The constant `+∞` (empty union) or `−∞` (empty intersection).
    Const(Infinity),
}

/// The bit pattern of an f64 parameter (so instructions can be hashed and compared).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Bits(pub u64);

impl Bits {
    /// Wraps a number.
    pub fn of(x: f64) -> Self {
        Bits(x.to_bits())
    }

    /// The number.
    pub fn get(self) -> f64 {
        f64::from_bits(self.0)
    }
}

/// Quadratic smooth minimum in double precision.
#[inline]
pub fn smooth_min(a: f64, b: f64, r: f64) -> f64 {
    let h = (r - (a - b).abs()).max(0.0) / r;
    a.min(b) - h * h * r * 0.25
}

/// Quadratic smooth minimum in single precision (same formula, same operation order).
#[inline(always)]
pub fn smooth_min_f32(a: f32, b: f32, r: f32) -> f32 {
    let h = (r - (a - b).abs()).max(0.0) / r;
    a.min(b) - h * h * r * 0.25
}

/// The two infinite constants.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Infinity {
    /// `+∞`: nothing is inside.
    Positive,
    /// `−∞`: everything is inside.
    Negative,
}

impl Infinity {
    /// As a number.
    pub fn value(self) -> f64 {
        match self {
            Infinity::Positive => f64::INFINITY,
            Infinity::Negative => f64::NEG_INFINITY,
        }
    }
}

/// A lowered solid.
#[derive(Debug, Clone)]
pub struct Program {
    pub(crate) instrs: Vec<Instr>,
    /// Shared by a program and every program pruned from it.
    pub(crate) primitives: Arc<Vec<Primitive>>,
    pub(crate) frames: Arc<Vec<Frame>>,
    /// Register of each instruction's result (registers are reused once values are dead).
    pub(crate) regs: Vec<u32>,
    pub(crate) register_count: usize,
}

impl Program {
    /// The instructions; the last one is the result.
    pub fn instrs(&self) -> &[Instr] {
        &self.instrs
    }

    /// Number of instructions.
    pub fn len(&self) -> usize {
        self.instrs.len()
    }

    /// Never true for a lowered solid.
    pub fn is_empty(&self) -> bool {
        self.instrs.is_empty()
    }

    /// Whether any instruction chooses between operands (min, max, smooth min).
    pub fn has_choices(&self) -> bool {
        self.instrs
            .iter()
            .any(|i| matches!(i, Instr::Min(..) | Instr::Max(..) | Instr::SmoothMin(..)))
    }

    /// Number of leaf instructions (primitive evaluations).
    pub fn leaf_count(&self) -> usize {
        self.instrs
            .iter()
            .filter(|i| matches!(i, Instr::Leaf { .. }))
            .count()
    }

    /// Registers a batch evaluation needs.
    pub fn register_count(&self) -> usize {
        self.register_count
    }

    /// Builds a program from instructions (in SSA order, result last) and allocates registers.
    pub(crate) fn from_parts(
        instrs: Vec<Instr>,
        primitives: Arc<Vec<Primitive>>,
        frames: Arc<Vec<Frame>>,
    ) -> Self {
        let (regs, register_count) = regalloc::allocate(&instrs);
        Self {
            instrs,
            primitives,
            frames,
            regs,
            register_count,
        }
    }
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod perturb_tests;
