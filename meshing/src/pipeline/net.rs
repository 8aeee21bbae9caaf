//! The grid's edge (issue 15). Marching cubes and dual contouring are closed by construction
//! only where no sample on the outermost layer of the grid is inside: a solid that reaches the
//! layer is cut open there. A padded grid lies a cell beyond the solid's box, so that happens
//! only where the box is wrong (a field that does not keep to the box its tree claims, or that
//! single precision evaluates wrongly). The pipeline therefore meshes the solid intersected with
//! the grid's box shrunk by half a cell (the outermost samples are always outside: the mesh stays
//! closed, capped where it was cut), and [`reaches_edge`] says whether that cut removed anything
//! (a warning then says so).
//!
//! Where the box is right the cut changes no sign and no value next to the surface: inside the
//! solid a field that is at most the distance to the surface lies above the box's (negative)
//! distance, so the maximum keeps it; values change only on the outermost layer, all outside.

use crate::grid::GridSpec;
use solidkit_kernel::program::{BatchScratch, IntervalScratch};
use solidkit_kernel::{Aabb, Program};

/// The box the solid is cut to on `spec`: the grid's box shrunk by half a cell.
pub fn inner_box(spec: &GridSpec) -> Aabb {
    let far = spec.point(spec.cells[0], spec.cells[1], spec.cells[2]);
    Aabb::new(spec.origin, far).expanded(-0.5 * spec.cell)
}

/// Most samples of one face patch evaluated at once, after the interval could not clear it.
const PATCH: usize = 16;

/// Whether `program` (the solid before the cut) is inside, or not known to be outside, at a
/// sample of the outermost layer of `spec`: intervals over face patches first (a patch whose
/// interval is positive is cleared), then the single-precision samples of patches of at most
/// 16 × 16, at the coordinates every sampler uses.
pub fn reaches_edge(program: &Program, spec: &GridSpec) -> bool {
    let n = spec.cells;
    let mut intervals = IntervalScratch::default();
    let mut batch = BatchScratch::new(program);
    let (mut xs, mut ys, mut zs, mut out) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        for layer in [0, n[axis]] {
            // Patches of sample index ranges [u0, u1] × [v0, v1] (inclusive) on this face.
            let mut stack = vec![(0, n[u], 0, n[v])];
            while let Some((u0, u1, v0, v1)) = stack.pop() {
                let index = |a: usize, b: usize| {
                    let mut ijk = [0; 3];
                    ijk[axis] = layer;
                    ijk[u] = a;
                    ijk[v] = b;
                    ijk
                };
                let lo = index(u0, v0);
                let hi = index(u1, v1);
                let corner = |ijk: [usize; 3]| spec.point(ijk[0], ijk[1], ijk[2]);
                // The f32 coordinates may round away from the f64 points by a little.
                let slack = 1e-6 * (corner(hi).abs().max_element() + spec.cell);
                let patch = Aabb::new(corner(lo), corner(hi)).expanded(slack);
                if program.interval_with(&patch, &mut intervals).lo > 0.0 {
                    continue;
                }
                if u1 - u0 < PATCH && v1 - v0 < PATCH {
                    xs.clear();
                    ys.clear();
                    zs.clear();
                    for b in v0..=v1 {
                        for a in u0..=u1 {
                            let ijk = index(a, b);
                            xs.push(spec.coordinate(0, ijk[0]));
                            ys.push(spec.coordinate(1, ijk[1]));
                            zs.push(spec.coordinate(2, ijk[2]));
                        }
                    }
                    out.resize(xs.len(), 0.0);
                    program.eval_many(&xs, &ys, &zs, &mut out, &mut batch);
                    // NaN or a value at or below zero: the cut may have changed the mesh.
                    if out.iter().any(|&v| v.is_nan() || v <= 0.0) {
                        return true;
                    }
                    continue;
                }
                if u1 - u0 >= v1 - v0 {
                    let m = u0 + (u1 - u0) / 2;
                    stack.push((u0, m, v0, v1));
                    stack.push((m + 1, u1, v0, v1));
                } else {
                    let m = v0 + (v1 - v0) / 2;
                    stack.push((u0, u1, v0, m));
                    stack.push((u0, u1, m + 1, v1));
                }
            }
        }
    }
    false
}
