//! Where blocks come from: the sparse octree's leaf bricks (sampled with their pruned evaluators,
//! searched with the same evaluators), or tiles of a dense [`SampleGrid`] searched with any
//! [`Evaluator`]. Also the sign lookup of any grid sample that adaptive simplification needs.

use super::block::{Block, BlockScratch, build};
use crate::grid::GridSpec;
use crate::marching_cubes::sign::{LONE_ZERO, lone_inside};
use crate::marching_cubes::{SampleGrid, inside, settle};
use crate::octree::{BoxSamples, Cancelled, MeshStats, Progress, SparseOptions};
use crate::octree::{grid_value, now};
use rayon::prelude::*;
use solidkit_kernel::Evaluator;
use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Blocks of the sparse octree's surface bricks, sorted by block coordinates (z, y, x), each with
/// the pruned evaluator of its brick (`evaluators[b]` for `blocks[b]`).
pub(crate) struct SparseBlocks<E> {
    pub blocks: Vec<Block>,
    pub evaluators: Vec<Arc<E>>,
}

/// The sparse octree's blocks.
pub(crate) fn sparse_blocks<E: Evaluator>(
    program: &E,
    spec: &GridSpec,
    opts: &SparseOptions,
    keep: bool,
    stats: &mut MeshStats,
) -> Result<SparseBlocks<E>, Cancelled> {
    let t0 = now(opts.clock.as_ref());
    let leaves = crate::octree::surface_nodes(program, spec, opts, stats)?;
    stats.octree_s = now(opts.clock.as_ref()) - t0;
    stats.surface_bricks = leaves.len();
    if opts.over_budget(leaves.len()) {
        stats.over_budget = true;
        return Ok(SparseBlocks {
            blocks: Vec::new(),
            evaluators: Vec::new(),
        });
    }
    let brick = opts.brick_size();
    let done = AtomicUsize::new(0);
    let total = leaves.len();
    let t1 = now(opts.clock.as_ref());
    let mut blocks: Vec<(Block, Arc<E>)> = leaves
        .par_iter()
        .map_init(
            || {
                (
                    BlockScratch::with_clock(opts.clock.clone()),
                    E::BatchScratch::default(),
                    BoxSamples::<E>::with_clock(opts.clock.clone()),
                )
            },
            |(scratch, batch, values), leaf| {
                if opts.is_cancelled() {
                    return (Block::default(), leaf.program.clone());
                }
                let e = leaf.extent(spec);
                let n = [e[0] + 1, e[1] + 1, e[2] + 1];
                let sampling =
                    values.sample(leaf.program.as_ref(), program, spec, leaf.min, n, batch);
                let mut b = build(
                    leaf.program.as_ref(),
                    program,
                    spec,
                    leaf.min,
                    e,
                    brick,
                    &values.values,
                    keep,
                    scratch,
                );
                b.evaluation_s += sampling;
                b.thin = values.thin;
                let d = done.fetch_add(1, Ordering::Relaxed) + 1;
                opts.report(Progress {
                    stage: "bricks",
                    done: d,
                    total,
                });
                (b, leaf.program.clone())
            },
        )
        .collect();
    if opts.is_cancelled() {
        return Err(Cancelled);
    }
    stats.bricks_s = now(opts.clock.as_ref()) - t1;
    stats.samples_evaluated = blocks.iter().map(|(b, _)| b.samples).sum();
    stats.evaluation_cpu_s = blocks.iter().map(|(b, _)| b.evaluation_s).sum();
    for (b, _) in &blocks {
        stats.thin.add(&b.thin);
    }
    blocks.sort_unstable_by_key(|(b, _)| (b.coord[2], b.coord[1], b.coord[0]));
    let (blocks, evaluators) = blocks.into_iter().unzip();
    Ok(SparseBlocks { blocks, evaluators })
}

/// Blocks of `block`³ cells tiling a dense sample grid, searched with `field`.
pub(crate) fn dense_blocks<F: Evaluator>(
    field: &F,
    samples: &SampleGrid,
    block: usize,
    keep: bool,
) -> Vec<Block> {
    let spec = &samples.spec;
    let dims = spec.cells.map(|c| c.div_ceil(block).max(1));
    let coords: Vec<[usize; 3]> = (0..dims[2])
        .flat_map(|z| (0..dims[1]).flat_map(move |y| (0..dims[0]).map(move |x| [x, y, z])))
        .collect();
    coords
        .par_iter()
        .map_init(BlockScratch::default, |scratch, c| {
            let min = c.map(|x| x * block);
            let e = [0, 1, 2].map(|a| block.min(spec.cells[a] - min[a]));
            let mut values = Vec::with_capacity((e[0] + 1) * (e[1] + 1) * (e[2] + 1));
            for k in 0..=e[2] {
                for j in 0..=e[1] {
                    for i in 0..=e[0] {
                        values.push(samples.at(min[0] + i, min[1] + j, min[2] + k));
                    }
                }
            }
            build(field, field, spec, min, e, block, &values, keep, scratch)
        })
        .filter(|b| !b.vertices.is_empty() || !b.edges.is_empty())
        .collect()
}

/// The inside test of any grid sample.
pub(crate) trait Signs {
    /// True when sample `s` (global indices) is inside.
    fn inside(&mut self, s: [usize; 3]) -> bool;
}

/// Signs of a dense grid.
impl Signs for &SampleGrid {
    fn inside(&mut self, s: [usize; 3]) -> bool {
        inside(self.at(s[0], s[1], s[2]))
    }
}

/// Signs of the sparse path: the samples of a block containing the sample, else (the sample lies
/// in a box the octree culled, whose samples all share one sign) the full evaluator's f32 value.
pub(crate) struct SparseSigns<'a, E: Evaluator> {
    pub blocks: &'a [Block],
    pub index: &'a super::cells::BlockIndex,
    pub block_size: usize,
    pub program: &'a E,
    pub spec: GridSpec,
    pub cache: HashMap<[usize; 3], bool>,
    pub batch: E::BatchScratch,
}

impl<E: Evaluator> Signs for SparseSigns<'_, E> {
    fn inside(&mut self, s: [usize; 3]) -> bool {
        let bs = self.block_size;
        for mask in 0..8 {
            let mut c = [0usize; 3];
            let mut ok = true;
            for a in 0..3 {
                let mut b = s[a] / bs;
                if mask >> a & 1 == 1 {
                    if !s[a].is_multiple_of(bs) || b == 0 {
                        ok = false;
                        break;
                    }
                    b -= 1;
                }
                c[a] = b;
            }
            if !ok {
                continue;
            }
            if let Some(b) = self.index.get(c) {
                let o = &self.blocks[b];
                let l = [0, 1, 2].map(|a| s[a].wrapping_sub(o.min[a]));
                if (0..3).all(|a| l[a] <= o.extent[a]) {
                    let n = [o.extent[0] + 1, o.extent[1] + 1];
                    return o.inside[l[0] + n[0] * (l[1] + n[1] * l[2])] == 1;
                }
            }
        }
        if let Some(&v) = self.cache.get(&s) {
            return v;
        }
        let (program, spec) = (self.program, &self.spec);
        let raw = grid_value(program, spec, s, &mut self.batch);
        let p = [0, 1, 2].map(|a| spec.coordinate(a, s[a]));
        let settled = settle(p[0], p[1], p[2], raw, |q| {
            program.zero_side(q, &mut Default::default())
        });
        let v = if settled == LONE_ZERO {
            lone_inside(
                s,
                spec.samples(),
                |_| None,
                |q| grid_value(program, spec, q, &mut self.batch),
            )
        } else {
            inside(settled)
        };
        self.cache.insert(s, v);
        v
    }
}
