//! Register allocation by liveness: a value's register is released after its last use, so batch
//! evaluation of long programs (thousands of instructions) cycles through a handful of buffers.

use super::Instr;

/// Operands of an instruction.
pub(crate) fn operands(i: &Instr) -> ([u32; 2], usize) {
    match *i {
        Instr::Min(a, b) | Instr::Max(a, b) | Instr::SmoothMin(a, b, _) => ([a, b], 2),
        Instr::Neg(a) | Instr::Abs(a) | Instr::AddConst(a, _) => ([a, 0], 1),
        Instr::Leaf { .. } | Instr::Const(_) => ([0, 0], 0),
    }
}

/// Register of every instruction's result, and the number of registers used.
pub(crate) fn allocate(instrs: &[Instr]) -> (Vec<u32>, usize) {
    let n = instrs.len();
    let mut last_use = vec![0usize; n];
    for (i, ins) in instrs.iter().enumerate() {
        let (ops, k) = operands(ins);
        for &o in &ops[..k] {
            last_use[o as usize] = i;
        }
    }
    if let Some(l) = last_use.last_mut() {
        *l = usize::MAX; // the result stays live
    }
    let mut regs = vec![0u32; n];
    let mut free: Vec<u32> = Vec::new();
    let mut count = 0u32;
    for (i, ins) in instrs.iter().enumerate() {
        let (ops, k) = operands(ins);
        // Release operands that die here first, so the result may reuse one (ops are elementwise).
        for (j, &o) in ops[..k].iter().enumerate() {
            let dup = j == 1 && ops[0] == o;
            if last_use[o as usize] == i && !dup {
                free.push(regs[o as usize]);
            }
        }
        regs[i] = free.pop().unwrap_or_else(|| {
            count += 1;
            count - 1
        });
    }
    (regs, count as usize)
}
