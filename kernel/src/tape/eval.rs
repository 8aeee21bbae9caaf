//! Evaluation of a [`Tape`]: values at points, values with gradients, and interval bounds over
//! boxes. Each evaluator is a loop over the instructions with explicit stacks kept in a reusable
//! [`Scratch`].

use super::{Op, Tape};
use crate::primitive::Shape;
use crate::{Aabb, Field, Interval};
use glam::DVec3;

/// Reusable stacks for tape evaluation (one per thread).
#[derive(Debug, Default, Clone)]
pub struct Scratch {
    values: Vec<f64>,
    grads: Vec<(f64, DVec3)>,
    intervals: Vec<Interval>,
    points: Vec<DVec3>,
    boxes: Vec<Aabb>,
}

impl Scratch {
    /// Stacks sized for `tape`.
    pub fn for_tape(tape: &Tape) -> Self {
        Self {
            values: Vec::with_capacity(tape.max_stack),
            grads: Vec::new(),
            intervals: Vec::new(),
            points: Vec::with_capacity(tape.max_frames),
            boxes: Vec::new(),
        }
    }
}

/// Replaces the top `n` entries of `stack` by their fold under `f` (or `empty` when `n = 0`).
fn reduce<T: Copy>(stack: &mut Vec<T>, n: u32, empty: T, f: impl Fn(T, T) -> T) {
    let start = stack.len() - n as usize;
    let r = stack[start..].iter().copied().reduce(&f).unwrap_or(empty);
    stack.truncate(start);
    stack.push(r);
}

impl Tape {
    /// Field value at `p` using caller-provided scratch stacks.
    pub fn value_with(&self, p: DVec3, s: &mut Scratch) -> f64 {
        let (values, points) = (&mut s.values, &mut s.points);
        values.clear();
        points.clear();
        let mut cur = p;
        for op in &self.ops {
            match *op {
                Op::Prim(i) => values.push(self.primitives[i as usize].value(cur)),
                Op::Enter(i) => {
                    points.push(cur);
                    cur = self.transforms[i as usize].to_child(cur);
                }
                Op::Leave(i) => {
                    cur = points.pop().expect("balanced");
                    *values.last_mut().expect("child value") *= self.transforms[i as usize].sigma;
                }
                Op::Min(n) => reduce(values, n, f64::INFINITY, f64::min),
                Op::Max(n) => reduce(values, n, f64::NEG_INFINITY, f64::max),
                Op::Neg => *values.last_mut().expect("operand") *= -1.0,
            }
        }
        values.pop().expect("one result")
    }

    /// Field value at `p`.
    pub fn value(&self, p: DVec3) -> f64 {
        self.value_with(p, &mut Scratch::for_tape(self))
    }

    /// Field value and gradient at `p` (the gradient of the winning operand at min/max).
    pub fn value_gradient_with(&self, p: DVec3, s: &mut Scratch) -> (f64, DVec3) {
        let (stack, points) = (&mut s.grads, &mut s.points);
        stack.clear();
        points.clear();
        let mut cur = p;
        let min = |a: (f64, DVec3), b: (f64, DVec3)| if b.0 < a.0 { b } else { a };
        let max = |a: (f64, DVec3), b: (f64, DVec3)| if b.0 > a.0 { b } else { a };
        for op in &self.ops {
            match *op {
                Op::Prim(i) => {
                    let prim = &self.primitives[i as usize];
                    stack.push((prim.value(cur), prim.gradient(cur)));
                }
                Op::Enter(i) => {
                    points.push(cur);
                    cur = self.transforms[i as usize].to_child(cur);
                }
                Op::Leave(i) => {
                    cur = points.pop().expect("balanced");
                    let t = &self.transforms[i as usize];
                    let top = stack.last_mut().expect("child value");
                    *top = (top.0 * t.sigma, t.gradient_to_parent(top.1));
                }
                Op::Min(n) => reduce(stack, n, (f64::INFINITY, DVec3::ZERO), min),
                Op::Max(n) => reduce(stack, n, (f64::NEG_INFINITY, DVec3::ZERO), max),
                Op::Neg => {
                    let top = stack.last_mut().expect("operand");
                    *top = (-top.0, -top.1);
                }
            }
        }
        stack.pop().expect("one result")
    }

    /// Field gradient at `p`.
    pub fn gradient(&self, p: DVec3) -> DVec3 {
        self.value_gradient_with(p, &mut Scratch::for_tape(self)).1
    }

    /// An interval containing every value of the field over the box `b`.
    pub fn interval_with(&self, b: &Aabb, s: &mut Scratch) -> Interval {
        let (stack, boxes) = (&mut s.intervals, &mut s.boxes);
        stack.clear();
        boxes.clear();
        let mut cur = *b;
        for op in &self.ops {
            match *op {
                Op::Prim(i) => stack.push(self.primitives[i as usize].interval(&cur)),
                Op::Enter(i) => {
                    boxes.push(cur);
                    cur = cur.transformed(&self.transforms[i as usize].inverse);
                }
                Op::Leave(i) => {
                    cur = boxes.pop().expect("balanced");
                    let top = stack.last_mut().expect("child interval");
                    *top = top.scale(self.transforms[i as usize].sigma);
                }
                Op::Min(n) => reduce(stack, n, Interval::point(f64::INFINITY), Interval::min),
                Op::Max(n) => reduce(stack, n, Interval::point(f64::NEG_INFINITY), Interval::max),
                Op::Neg => {
                    let top = stack.last_mut().expect("operand");
                    *top = -*top;
                }
            }
        }
        stack.pop().expect("one result")
    }

    /// An interval containing every value of the field over the box `b`.
    pub fn interval(&self, b: &Aabb) -> Interval {
        self.interval_with(b, &mut Scratch::for_tape(self))
    }
}

impl Field for Tape {
    fn value(&self, p: DVec3) -> f64 {
        Tape::value(self, p)
    }

    fn values(&self, points: &[DVec3], out: &mut [f64]) {
        let mut s = Scratch::for_tape(self);
        for (p, o) in points.iter().zip(out.iter_mut()) {
            *o = self.value_with(*p, &mut s);
        }
    }
}
