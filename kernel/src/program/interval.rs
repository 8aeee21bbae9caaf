//! Interval evaluation over a box, recording for each min/max which operand can win, and pruning:
//! a box gets a shorter program that gives the same values (bit for bit, in single precision)
//! everywhere inside it.
//!
//! Bit-identity needs care because points are evaluated in f32 and intervals in f64: a branch is
//! only dropped when the other operand wins by more than a margin that covers single-precision
//! rounding (see [`margin`](crate::eval::margin)), and boxes are only classified inside/outside
//! with the same margin.

use super::{Instr, Program};
use crate::eval::{Pruned, box_scale};
use crate::primitive::Shape;
use crate::{Aabb, Interval};

/// Which operands of a min/max can win over a box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Choice {
    /// Either may win.
    Both,
    /// Only the first operand can win.
    Left,
    /// Only the second operand can win.
    Right,
}

/// Reusable buffers for interval evaluation; holds the choices of the last evaluation.
#[derive(Debug, Default, Clone)]
pub struct IntervalScratch {
    slots: Vec<Interval>,
    choices: Vec<Choice>,
    scale: f64,
    /// True when the last evaluation found a branch that cannot win.
    prunable: bool,
    /// True when the last evaluation found a choice that either operand can win while both may
    /// cross zero (where two pieces of the solid, or of its outside, touch at a point, both
    /// operands of the choice that joins them are zero there), or any such choice when the
    /// program shifts levels.
    contested: bool,
    /// Any choice that either operand can win.
    any_both: bool,
    /// The program moves levels after a choice (offsets, shells, blends), so the sides of a
    /// choice's operands are not the solid's.
    shifts: bool,
    live: Vec<bool>,
    map: Vec<u32>,
}

impl Program {
    /// Interval of the field over `b`; the choices are left in `s` for [`Program::prune`].
    pub fn interval_with(&self, b: &Aabb, s: &mut IntervalScratch) -> Interval {
        let n = self.instrs.len();
        // Every slot is written before it is read; choices are reset only where they are set.
        s.slots.resize(n, Interval::point(0.0));
        s.choices.resize(n, Choice::Both);
        s.scale = box_scale(b);
        s.prunable = false;
        s.contested = false;
        s.any_both = false;
        s.shifts = false;
        for (i, ins) in self.instrs.iter().enumerate() {
            let v = match *ins {
                Instr::Leaf { prim, frame } => {
                    let f = &self.frames[frame as usize];
                    let iv = self.primitives[prim as usize].interval(&f.apply_box(b));
                    if f.sigma == 1.0 {
                        iv
                    } else {
                        iv.scale(f.sigma)
                    }
                }
                Instr::Min(a, c) => {
                    let (x, y) = (s.slots[a as usize], s.slots[c as usize]);
                    s.choices[i] = choose(x, y, s.scale, true);
                    s.prunable |= s.choices[i] != Choice::Both;
                    let both = s.choices[i] == Choice::Both;
                    s.any_both |= both;
                    s.contested |= both && x.contains(0.0) && y.contains(0.0);
                    x.min(y)
                }
                Instr::Max(a, c) => {
                    let (x, y) = (s.slots[a as usize], s.slots[c as usize]);
                    s.choices[i] = choose(x, y, s.scale, false);
                    s.prunable |= s.choices[i] != Choice::Both;
                    let both = s.choices[i] == Choice::Both;
                    s.any_both |= both;
                    s.contested |= both && x.contains(0.0) && y.contains(0.0);
                    x.max(y)
                }
                Instr::Neg(a) => -s.slots[a as usize],
                Instr::SmoothMin(a, c, k) => {
                    let (x, y, r) = (s.slots[a as usize], s.slots[c as usize], k.get());
                    // Only a branch that wins by more than the blend radius is exact min.
                    let shifted = Interval::new(y.lo - r, y.hi + r);
                    s.choices[i] = match choose(x, shifted, s.scale, true) {
                        Choice::Left => Choice::Left,
                        _ => match choose(Interval::new(x.lo - r, x.hi + r), y, s.scale, true) {
                            Choice::Right => Choice::Right,
                            _ => Choice::Both,
                        },
                    };
                    s.prunable |= s.choices[i] != Choice::Both;
                    s.any_both |= s.choices[i] == Choice::Both;
                    s.shifts = true;
                    let m = x.min(y);
                    Interval::new(m.lo - 0.25 * r, m.hi)
                }
                Instr::Abs(a) => {
                    s.shifts = true;
                    s.slots[a as usize].abs()
                }
                Instr::AddConst(a, k) => {
                    s.shifts = true;
                    let x = s.slots[a as usize];
                    Interval::new(x.lo + k.get(), x.hi + k.get())
                }
                Instr::Const(c) => Interval::point(c.value()),
            };
            s.slots[i] = v;
        }
        s.slots[n - 1]
    }

    /// Whether the last [`Program::interval_with`] on `s` left a choice (min, max) that either
    /// operand can win while both may be zero in the box (any choice either can win when the
    /// program has offsets, shells or blends, which move the level that matters). Two pieces of
    /// the solid, or of its outside, that touch at a point meet where both operands of the
    /// choice between them are zero; where there is no such choice, none meet in the box.
    pub fn contested(&self, s: &IntervalScratch) -> bool {
        s.contested || (s.shifts && s.any_both)
    }

    /// Interval of the field over `b`.
    pub fn interval(&self, b: &Aabb) -> Interval {
        self.interval_with(b, &mut IntervalScratch::default())
    }

    /// The program with the branches that cannot win (per the last [`Program::interval_with`]
    /// in `s`) removed, or `None` when nothing can be removed. One backward pass marks what the
    /// result needs, following only the operands that can win; one forward pass copies it.
    pub fn prune(&self, s: &mut IntervalScratch) -> Option<Program> {
        if !s.prunable {
            return None;
        }
        let n = self.instrs.len();
        let winner = |i: usize| match (self.instrs[i], s.choices[i]) {
            (Instr::Min(a, _) | Instr::Max(a, _) | Instr::SmoothMin(a, _, _), Choice::Left) => {
                Some(a)
            }
            (Instr::Min(_, b) | Instr::Max(_, b) | Instr::SmoothMin(_, b, _), Choice::Right) => {
                Some(b)
            }
            _ => None,
        };
        s.live.clear();
        s.live.resize(n, false);
        s.live[n - 1] = true;
        for i in (0..n).rev() {
            if !s.live[i] {
                continue;
            }
            match winner(i) {
                Some(w) => s.live[w as usize] = true,
                None => {
                    let (ops, k) = super::regalloc::operands(&self.instrs[i]);
                    for &o in &ops[..k] {
                        s.live[o as usize] = true;
                    }
                }
            }
        }
        s.map.clear();
        s.map.resize(n, 0);
        let mut out = Vec::with_capacity(s.live.iter().filter(|&&l| l).count());
        for i in 0..n {
            if !s.live[i] {
                continue;
            }
            if let Some(w) = winner(i) {
                s.map[i] = s.map[w as usize];
                continue;
            }
            let map = &s.map;
            out.push(super::lower::remap(self.instrs[i], |v| map[v as usize]));
            s.map[i] = (out.len() - 1) as u32;
        }
        Some(Program::from_parts(
            out,
            self.primitives.clone(),
            self.frames.clone(),
        ))
    }

    /// Classifies the box (with the f32 safety margin, [`Pruned::classify`]) and prunes the
    /// program for it.
    pub fn prune_for_box(&self, b: &Aabb, s: &mut IntervalScratch) -> Pruned<Program> {
        let iv = self.interval_with(b, s);
        Pruned::classify(b, iv, || self.prune(s))
    }
}

fn choose(x: Interval, y: Interval, scale: f64, is_min: bool) -> Choice {
    // One margin for both comparisons, from the largest magnitude involved: at least the margin
    // of each pair, so it is as safe and cheaper.
    let big =
        x.lo.abs()
            .max(x.hi.abs())
            .max(y.lo.abs())
            .max(y.hi.abs())
            .min(1e30);
    let m = 3e-5 * (scale + 2.0 * big);
    // For min, x always wins when x.hi < y.lo (by the margin); for max when x.lo > y.hi.
    let (x_wins, y_wins) = if is_min {
        (x.hi < y.lo - m, y.hi < x.lo - m)
    } else {
        (x.lo > y.hi + m, y.lo > x.hi + m)
    };
    if x_wins {
        Choice::Left
    } else if y_wins {
        Choice::Right
    } else {
        Choice::Both
    }
}
