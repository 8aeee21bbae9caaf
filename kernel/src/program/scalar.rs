//! Double-precision evaluation at one point: values, and values with gradients (the gradient of
//! the operand that wins each min/max, chained through each leaf's frame).

use super::{Instr, Program};
use crate::Field;
use crate::primitive::Shape;
use glam::DVec3;

impl Program {
    /// Field value at `p`, with `slots` as scratch (resized as needed).
    pub fn value_with(&self, p: DVec3, slots: &mut Vec<f64>) -> f64 {
        slots.clear();
        slots.resize(self.register_count, 0.0);
        for (i, ins) in self.instrs.iter().enumerate() {
            let r = |v: u32| self.regs[v as usize] as usize;
            let v = match *ins {
                Instr::Leaf { prim, frame } => {
                    let f = &self.frames[frame as usize];
                    f.sigma * self.primitives[prim as usize].value(f.apply(p))
                }
                Instr::Min(a, b) => slots[r(a)].min(slots[r(b)]),
                Instr::Max(a, b) => slots[r(a)].max(slots[r(b)]),
                Instr::Neg(a) => -slots[r(a)],
                Instr::SmoothMin(a, b, k) => super::smooth_min(slots[r(a)], slots[r(b)], k.get()),
                Instr::Abs(a) => slots[r(a)].abs(),
                Instr::AddConst(a, k) => slots[r(a)] + k.get(),
                Instr::Const(c) => c.value(),
            };
            slots[self.regs[i] as usize] = v;
        }
        slots[*self.regs.last().expect("non-empty") as usize]
    }

    /// Field value at `p`.
    pub fn value(&self, p: DVec3) -> f64 {
        self.value_with(p, &mut Vec::new())
    }

    /// Field value and gradient at `p`, with `slots` as scratch.
    pub fn value_gradient_with(&self, p: DVec3, slots: &mut Vec<(f64, DVec3)>) -> (f64, DVec3) {
        slots.clear();
        slots.resize(self.register_count, (0.0, DVec3::ZERO));
        for (i, ins) in self.instrs.iter().enumerate() {
            let r = |v: u32| self.regs[v as usize] as usize;
            let v = match *ins {
                Instr::Leaf { prim, frame } => {
                    let f = &self.frames[frame as usize];
                    let q = f.apply(p);
                    let s = &self.primitives[prim as usize];
                    (f.sigma * s.value(q), f.gradient_to_world(s.gradient(q)))
                }
                Instr::Min(a, b) => {
                    let (x, y) = (slots[r(a)], slots[r(b)]);
                    if y.0 < x.0 { y } else { x }
                }
                Instr::Max(a, b) => {
                    let (x, y) = (slots[r(a)], slots[r(b)]);
                    if y.0 > x.0 { y } else { x }
                }
                Instr::Neg(a) => {
                    let x = slots[r(a)];
                    (-x.0, -x.1)
                }
                Instr::SmoothMin(a, b, k) => {
                    let (x, y, rad) = (slots[r(a)], slots[r(b)], k.get());
                    // d/da and d/db of min − r·h²/4: weights (1 − w, w) with w = h/2 for the
                    // larger operand.
                    let h = (rad - (x.0 - y.0).abs()).max(0.0) / rad;
                    let w = 0.5 * h;
                    let (lo, hi) = if x.0 <= y.0 { (x, y) } else { (y, x) };
                    (
                        super::smooth_min(x.0, y.0, rad),
                        lo.1 * (1.0 - w) + hi.1 * w,
                    )
                }
                Instr::Abs(a) => {
                    let x = slots[r(a)];
                    if x.0 < 0.0 { (-x.0, -x.1) } else { x }
                }
                Instr::AddConst(a, k) => {
                    let x = slots[r(a)];
                    (x.0 + k.get(), x.1)
                }
                Instr::Const(c) => (c.value(), DVec3::ZERO),
            };
            slots[self.regs[i] as usize] = v;
        }
        slots[*self.regs.last().expect("non-empty") as usize]
    }

    /// Field gradient at `p`.
    pub fn gradient(&self, p: DVec3) -> DVec3 {
        self.value_gradient_with(p, &mut Vec::new()).1
    }
}

impl Field for Program {
    fn value(&self, p: DVec3) -> f64 {
        Program::value(self, p)
    }

    fn values(&self, points: &[DVec3], out: &mut [f64]) {
        let mut slots = Vec::new();
        for (p, o) in points.iter().zip(out.iter_mut()) {
            *o = self.value_with(*p, &mut slots);
        }
    }

    fn zero_side(&self, p: DVec3) -> super::perturb::ZeroSide {
        Program::zero_side(self, p, &mut Vec::new())
    }
}
