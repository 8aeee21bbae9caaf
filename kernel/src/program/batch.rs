//! Single-precision batch evaluation over structure-of-arrays points, [`CHUNK`] points at a time.
//!
//! Each instruction runs over the whole chunk before the next (so the inner loops are simple
//! element-wise loops the compiler vectorises), reading and writing registers allocated by
//! liveness. Leaves transform the chunk into their frame first (skipped for the identity frame).

use super::{Instr, Program};
use crate::primitive::Shape;

/// Points per chunk: registers of this many f32 stay in L1 cache for typical programs.
pub const CHUNK: usize = 256;

/// Reusable buffers for batch evaluation.
#[derive(Debug, Default, Clone)]
pub struct BatchScratch {
    regs: Vec<f32>,
    local: [Vec<f32>; 3],
}

impl BatchScratch {
    /// Buffers sized for `program`.
    pub fn new(program: &Program) -> Self {
        let mut s = Self::default();
        s.fit(program);
        s
    }

    fn fit(&mut self, program: &Program) {
        let need = program.register_count * CHUNK;
        if self.regs.len() < need {
            self.regs.resize(need, 0.0);
        }
        for l in &mut self.local {
            if l.len() < CHUNK {
                l.resize(CHUNK, 0.0);
            }
        }
    }
}

crate::simd::wide_loop! {
    fn min_into(dst: &mut [f32], src: &[f32]) {
        for (d, s) in dst.iter_mut().zip(src) {
            *d = d.min(*s);
        }
    }
}

crate::simd::wide_loop! {
    fn max_into(dst: &mut [f32], src: &[f32]) {
        for (d, s) in dst.iter_mut().zip(src) {
            *d = d.max(*s);
        }
    }
}

crate::simd::wide_loop! {
    fn scale_by(dst: &mut [f32], k: f32) {
        for d in dst.iter_mut() {
            *d *= k;
        }
    }
}

/// Mutable register `dst` and shared register `src` (distinct: callers handle an instruction
/// whose operands are one register themselves) of the register file.
fn pair(regs: &mut [f32], dst: usize, src: usize, n: usize) -> (&mut [f32], &[f32]) {
    if dst < src {
        let (lo, hi) = regs.split_at_mut(src * CHUNK);
        (&mut lo[dst * CHUNK..dst * CHUNK + n], &hi[..n])
    } else {
        let (lo, hi) = regs.split_at_mut(dst * CHUNK);
        (&mut hi[..n], &lo[src * CHUNK..src * CHUNK + n])
    }
}

crate::simd::wide_loop! {
    /// Adds a translation to coordinate arrays (all of the same length).
    fn translate_chunk(t: [f32; 3], x: &[f32], y: &[f32], z: &[f32], lx: &mut [f32], ly: &mut [f32], lz: &mut [f32]) {
        let n = lx.len();
        let (x, y, z, ly, lz) = (&x[..n], &y[..n], &z[..n], &mut ly[..n], &mut lz[..n]);
        for k in 0..n {
            lx[k] = x[k] + t[0];
            ly[k] = y[k] + t[1];
            lz[k] = z[k] + t[2];
        }
    }
}

crate::simd::wide_loop! {
    /// Applies a row-major 3 × 4 affine map to coordinate arrays (all of the same length).
    fn transform_chunk(m: &[[f32; 4]; 3], x: &[f32], y: &[f32], z: &[f32], lx: &mut [f32], ly: &mut [f32], lz: &mut [f32]) {
        let n = lx.len();
        let (x, y, z, ly, lz) = (&x[..n], &y[..n], &z[..n], &mut ly[..n], &mut lz[..n]);
        for k in 0..n {
            let (px, py, pz) = (x[k], y[k], z[k]);
            lx[k] = m[0][0] * px + m[0][1] * py + m[0][2] * pz + m[0][3];
            ly[k] = m[1][0] * px + m[1][1] * py + m[1][2] * pz + m[1][3];
            lz[k] = m[2][0] * px + m[2][1] * py + m[2][2] * pz + m[2][3];
        }
    }
}

impl Program {
    /// Values at up to [`CHUNK`] points given as coordinate arrays; `out.len()` points.
    pub fn eval_chunk(
        &self,
        x: &[f32],
        y: &[f32],
        z: &[f32],
        out: &mut [f32],
        s: &mut BatchScratch,
    ) {
        let n = out.len();
        debug_assert!(n <= CHUNK && x.len() >= n && y.len() >= n && z.len() >= n);
        s.fit(self);
        // Leaves in the same frame share the transformed coordinates.
        let mut local_frame = u32::MAX;
        for (i, ins) in self.instrs.iter().enumerate() {
            let dst = self.regs[i] as usize;
            let reg = |v: u32| self.regs[v as usize] as usize;
            match *ins {
                Instr::Leaf { prim, frame } => {
                    let f = &self.frames[frame as usize];
                    let out_reg = &mut s.regs[dst * CHUNK..dst * CHUNK + n];
                    let prim = &self.primitives[prim as usize];
                    if f.identity {
                        prim.values_f32(&x[..n], &y[..n], &z[..n], out_reg);
                    } else {
                        let [lx, ly, lz] = &mut s.local;
                        if local_frame != frame {
                            let (x, y, z) = (&x[..n], &y[..n], &z[..n]);
                            let (lx, ly, lz) = (&mut lx[..n], &mut ly[..n], &mut lz[..n]);
                            if f.translation {
                                let t = [f.rows_f32[0][3], f.rows_f32[1][3], f.rows_f32[2][3]];
                                translate_chunk(t, x, y, z, lx, ly, lz);
                            } else {
                                transform_chunk(&f.rows_f32, x, y, z, lx, ly, lz);
                            }
                            local_frame = frame;
                        }
                        prim.values_f32(&lx[..n], &ly[..n], &lz[..n], out_reg);
                        if f.sigma != 1.0 {
                            scale_by(out_reg, f.sigma as f32);
                        }
                    }
                }
                Instr::Min(a, b) | Instr::Max(a, b) | Instr::SmoothMin(a, b, _) => {
                    let (ra, rb) = (reg(a), reg(b));
                    // Bring one operand into `dst` (it may already be there), combine the other.
                    let other = if ra == dst {
                        rb
                    } else if rb == dst {
                        ra
                    } else {
                        s.regs.copy_within(ra * CHUNK..ra * CHUNK + n, dst * CHUNK);
                        rb
                    };
                    if other == dst {
                        // Both operands are the value already in `dst` (an instruction over one
                        // shared value, e.g. a blend of a subtree with itself): min(x, x) and
                        // max(x, x) are x; the blend combines each lane with itself.
                        if let Instr::SmoothMin(_, _, k) = *ins {
                            let r = k.get() as f32;
                            s.regs[dst * CHUNK..dst * CHUNK + n]
                                .iter_mut()
                                .for_each(|x| *x = super::smooth_min_f32(*x, *x, r));
                        }
                        continue;
                    }
                    let (d, o) = pair(&mut s.regs, dst, other, n);
                    match *ins {
                        Instr::Min(..) => min_into(d, o),
                        Instr::Max(..) => max_into(d, o),
                        Instr::SmoothMin(_, _, k) => {
                            let r = k.get() as f32;
                            for (x, y) in d.iter_mut().zip(o) {
                                *x = super::smooth_min_f32(*x, *y, r);
                            }
                        }
                        _ => unreachable!("binary instructions only"),
                    }
                }
                Instr::Neg(a) => {
                    let ra = reg(a);
                    if ra != dst {
                        s.regs.copy_within(ra * CHUNK..ra * CHUNK + n, dst * CHUNK);
                    }
                    s.regs[dst * CHUNK..dst * CHUNK + n]
                        .iter_mut()
                        .for_each(|v| *v = -*v);
                }
                Instr::Abs(a) | Instr::AddConst(a, _) => {
                    let ra = reg(a);
                    if ra != dst {
                        s.regs.copy_within(ra * CHUNK..ra * CHUNK + n, dst * CHUNK);
                    }
                    let d = &mut s.regs[dst * CHUNK..dst * CHUNK + n];
                    match *ins {
                        Instr::AddConst(_, k) => {
                            let c = k.get() as f32;
                            d.iter_mut().for_each(|v| *v += c);
                        }
                        _ => d.iter_mut().for_each(|v| *v = v.abs()),
                    }
                }
                Instr::Const(c) => {
                    s.regs[dst * CHUNK..dst * CHUNK + n].fill(c.value() as f32);
                }
            }
        }
        let r = *self.regs.last().expect("non-empty") as usize;
        out.copy_from_slice(&s.regs[r * CHUNK..r * CHUNK + n]);
    }

    /// Values at any number of points (chunked).
    pub fn eval_many(
        &self,
        x: &[f32],
        y: &[f32],
        z: &[f32],
        out: &mut [f32],
        s: &mut BatchScratch,
    ) {
        let mut start = 0;
        while start < out.len() {
            let end = (start + CHUNK).min(out.len());
            self.eval_chunk(
                &x[start..end],
                &y[start..end],
                &z[start..end],
                &mut out[start..end],
                s,
            );
            start = end;
        }
    }
}
