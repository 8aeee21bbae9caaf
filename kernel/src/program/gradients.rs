//! Double-precision values and gradients over slices of points, [`CHUNK`] points at a time in
//! structure-of-arrays registers (value and the three gradient components), with the same
//! register allocation as the value path. Leaves evaluate their primitive per point (in the leaf's
//! frame, chained back to world space); min/max select per lane the operand that wins, exactly as
//! [`Program::value_gradient_with`] does at one point.

use super::{CHUNK, Instr, Program};
use crate::primitive::Shape;
use glam::DVec3;

/// Reusable buffers for batch gradient evaluation.
#[derive(Debug, Default, Clone)]
pub struct GradientScratch {
    /// Register file: for register `r`, lanes `[4r·CHUNK, 4(r+1)·CHUNK)` hold value, gx, gy, gz.
    regs: Vec<f64>,
    /// A leaf's points in its frame, and its values and gradients there (`CHUNK` each).
    local: Vec<DVec3>,
    values: Vec<f64>,
    gradients: Vec<DVec3>,
}

impl GradientScratch {
    fn fit(&mut self, program: &Program) {
        let need = 4 * program.register_count * CHUNK;
        if self.regs.len() < need {
            self.regs.resize(need, 0.0);
        }
        if self.local.len() < CHUNK {
            self.local.resize(CHUNK, DVec3::ZERO);
            self.values.resize(CHUNK, 0.0);
            self.gradients.resize(CHUNK, DVec3::ZERO);
        }
    }
}

/// Copies register `src` over register `dst` (lanes `0..n` of all four components).
fn copy_reg(regs: &mut [f64], src: usize, dst: usize, n: usize) {
    if src != dst {
        for c in 0..4 {
            regs.copy_within(
                (4 * src + c) * CHUNK..(4 * src + c) * CHUNK + n,
                (4 * dst + c) * CHUNK,
            );
        }
    }
}

impl Program {
    /// Values and gradients at `points` (any number), written to `values` and `gradients`.
    pub fn values_gradients(
        &self,
        points: &[DVec3],
        values: &mut [f64],
        gradients: &mut [DVec3],
        s: &mut GradientScratch,
    ) {
        s.fit(self);
        for start in (0..points.len()).step_by(CHUNK) {
            let end = (start + CHUNK).min(points.len());
            self.chunk(&points[start..end], s);
            let r = *self.regs.last().expect("non-empty") as usize;
            let at = |c: usize, k: usize| s.regs[(4 * r + c) * CHUNK + k];
            for k in 0..end - start {
                values[start + k] = at(0, k);
                gradients[start + k] = DVec3::new(at(1, k), at(2, k), at(3, k));
            }
        }
    }

    fn chunk(&self, pts: &[DVec3], s: &mut GradientScratch) {
        let n = pts.len();
        for (i, ins) in self.instrs.iter().enumerate() {
            let dst = self.regs[i] as usize;
            let reg = |v: u32| self.regs[v as usize] as usize;
            match *ins {
                Instr::Leaf { prim, frame } => {
                    let f = &self.frames[frame as usize];
                    let shape = &self.primitives[prim as usize];
                    for (q, p) in s.local.iter_mut().zip(pts) {
                        *q = f.apply(*p);
                    }
                    // One dispatch per chunk: the primitive's own batch loop.
                    shape.values_gradients(
                        &s.local[..n],
                        &mut s.values[..n],
                        &mut s.gradients[..n],
                    );
                    let (head, rest) = s.regs[4 * dst * CHUNK..].split_at_mut(CHUNK);
                    let (gx, rest) = rest.split_at_mut(CHUNK);
                    let (gy, rest) = rest.split_at_mut(CHUNK);
                    let gz = &mut rest[..CHUNK];
                    for k in 0..n {
                        let g = f.gradient_to_world(s.gradients[k]);
                        head[k] = f.sigma * s.values[k];
                        gx[k] = g.x;
                        gy[k] = g.y;
                        gz[k] = g.z;
                    }
                }
                Instr::Min(a, b) | Instr::Max(a, b) => {
                    let (ra, rb) = (reg(a), reg(b));
                    let min = matches!(ins, Instr::Min(..));
                    for k in 0..n {
                        let va = s.regs[4 * ra * CHUNK + k];
                        let vb = s.regs[4 * rb * CHUNK + k];
                        let take_b = if min { vb < va } else { vb > va };
                        let src = if take_b { rb } else { ra };
                        if src != dst {
                            for c in 0..4 {
                                s.regs[(4 * dst + c) * CHUNK + k] =
                                    s.regs[(4 * src + c) * CHUNK + k];
                            }
                        }
                    }
                }
                Instr::SmoothMin(a, b, r) => {
                    let (ra, rb) = (reg(a), reg(b));
                    let r = r.get();
                    for k in 0..n {
                        let va = s.regs[4 * ra * CHUNK + k];
                        let vb = s.regs[4 * rb * CHUNK + k];
                        let h = (r - (va - vb).abs()).max(0.0) / r;
                        let w = 0.5 * h;
                        let (lo, hi) = if va <= vb { (ra, rb) } else { (rb, ra) };
                        let mut out = [super::smooth_min(va, vb, r), 0.0, 0.0, 0.0];
                        for (c, o) in out.iter_mut().enumerate().skip(1) {
                            let at = |q: usize| s.regs[(4 * q + c) * CHUNK + k];
                            *o = at(lo) * (1.0 - w) + at(hi) * w;
                        }
                        for (c, o) in out.into_iter().enumerate() {
                            s.regs[(4 * dst + c) * CHUNK + k] = o;
                        }
                    }
                }
                Instr::Neg(a) | Instr::Abs(a) | Instr::AddConst(a, _) => {
                    copy_reg(&mut s.regs, reg(a), dst, n);
                    for k in 0..n {
                        let v = s.regs[4 * dst * CHUNK + k];
                        let (scale, shift) = match *ins {
                            Instr::Neg(_) => (-1.0, 0.0),
                            Instr::Abs(_) => (if v < 0.0 { -1.0 } else { 1.0 }, 0.0),
                            Instr::AddConst(_, c) => (1.0, c.get()),
                            _ => unreachable!("unary instructions only"),
                        };
                        s.regs[4 * dst * CHUNK + k] = v * scale + shift;
                        for c in 1..4 {
                            s.regs[(4 * dst + c) * CHUNK + k] *= scale;
                        }
                    }
                }
                Instr::Const(c) => {
                    for k in 0..n {
                        s.regs[4 * dst * CHUNK + k] = c.value();
                        for comp in 1..4 {
                            s.regs[(4 * dst + comp) * CHUNK + k] = 0.0;
                        }
                    }
                }
            }
        }
    }
}
