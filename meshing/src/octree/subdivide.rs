//! Octree subdivision, level by level: each box's interval classifies it (inside, outside, or
//! surface) and prunes its evaluator; surface boxes split into eight until they are leaf bricks.

use super::control::{Cancelled, MeshStats, Progress, SparseOptions};
use crate::grid::GridSpec;
use rayon::prelude::*;
use solidkit_kernel::Aabb;
use solidkit_kernel::eval::{Evaluator, Pruned};
use std::sync::Arc;

/// An octree box: cells `[min, min + size)` along each axis (clipped to the grid), and the
/// evaluator (program) valid inside it.
pub(crate) struct Node<E> {
    pub min: [usize; 3],
    pub size: usize,
    pub program: Arc<E>,
}

impl<E> Node<E> {
    /// Cells per axis actually inside the grid.
    pub fn extent(&self, spec: &GridSpec) -> [usize; 3] {
        [0, 1, 2].map(|a| self.size.min(spec.cells[a].saturating_sub(self.min[a])))
    }

    /// World box of all samples the node's cells touch, grown slightly to cover the f32 rounding
    /// of sample coordinates.
    pub fn bounds(&self, spec: &GridSpec) -> Aabb {
        let e = self.extent(spec);
        let lo = spec.point(self.min[0], self.min[1], self.min[2]);
        let hi = spec.point(self.min[0] + e[0], self.min[1] + e[1], self.min[2] + e[2]);
        let pad = 1e-6 * (1.0 + lo.abs().max(hi.abs()).max_element());
        Aabb::new(lo, hi).expanded(pad)
    }
}

/// The leaf bricks the surface may cross, each with its pruned evaluator.
pub(crate) fn surface_bricks<E: Evaluator>(
    program: &E,
    spec: &GridSpec,
    opts: &SparseOptions,
    stats: &mut MeshStats,
) -> Result<Vec<Node<E>>, Cancelled> {
    let brick = opts.brick_size();
    let longest = spec.cells.iter().copied().max().unwrap_or(1);
    let mut size = brick;
    while size < longest {
        size *= 2;
    }
    let mut level = vec![Node {
        min: [0; 3],
        size,
        program: Arc::new(program.clone()),
    }];
    let mut leaves = Vec::new();
    let mut depth = 0;
    while !level.is_empty() {
        if opts.is_cancelled() {
            return Err(Cancelled);
        }
        stats.boxes_evaluated += level.len() as u64;
        let results: Vec<Split<E>> = level
            .into_par_iter()
            .map_init(E::IntervalScratch::default, |scratch, node| {
                split(node, spec, brick, scratch)
            })
            .collect();
        let mut next = Vec::new();
        for (children, leaf) in results {
            next.extend(children);
            leaves.extend(leaf);
        }
        level = next;
        depth += 1;
        opts.report(Progress {
            stage: "octree",
            done: depth,
            total: depth + usize::from(!level.is_empty()),
        });
    }
    stats.leaf_instructions = leaves.iter().map(|l| l.program.len() as u64).sum();
    Ok(leaves)
}

/// What [`split`] makes of a box: its children and, for a leaf brick, the leaf.
type Split<E> = (Vec<Node<E>>, Option<Node<E>>);

/// Classifies one box: culled (no output), a leaf brick, or eight children.
fn split<E: Evaluator>(
    node: Node<E>,
    spec: &GridSpec,
    brick: usize,
    scratch: &mut E::IntervalScratch,
) -> Split<E> {
    let program = match node.program.prune_for_box(&node.bounds(spec), scratch) {
        Pruned::Inside | Pruned::Outside => return (Vec::new(), None),
        Pruned::Surface(Some(p)) => Arc::new(p),
        Pruned::Surface(None) => node.program.clone(),
    };
    if node.size <= brick {
        return (Vec::new(), Some(Node { program, ..node }));
    }
    let half = node.size / 2;
    let mut children = Vec::with_capacity(8);
    for c in 0..8 {
        let min = [0, 1, 2].map(|a| node.min[a] + if c >> a & 1 == 1 { half } else { 0 });
        if (0..3).all(|a| min[a] < spec.cells[a]) {
            children.push(Node {
                min,
                size: half,
                program: program.clone(),
            });
        }
    }
    (children, None)
}
