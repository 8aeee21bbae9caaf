//! Sparse meshing: an octree over the sample grid culls boxes the field's interval shows to be
//! wholly inside or outside, prunes the program for the boxes the surface may cross, and runs
//! marching cubes only in the surviving leaf bricks. Cost grows with the surface, not the volume.
//! Everything here is generic over the kernel's [`Evaluator`] (monomorphized: a [`Program`]
//! compiles to direct calls of its own methods).
//!
//! The output is identical, bit for bit, to dense marching cubes over the same grid with the full
//! program ([`mesh_dense`]), whatever the number of threads: pruned programs give the same f32
//! values inside their boxes, culled boxes contain no sign change, and vertices and triangles are
//! numbered by sorting on grid keys in the dense path's order.
//!
//! `subdivide.rs` builds the octree level by level (parallel within a level); `brick.rs` samples and
//! triangulates one leaf; `thin.rs` finds features the grid thins or misses; `assemble.rs` merges the bricks into a mesh.

mod assemble;
mod brick;
mod control;
pub(crate) use control::now;
mod subdivide;
pub mod thin;

/// The surface leaf bricks with their pruned programs (also used by dual contouring).
pub(crate) use brick::{BoxSamples, grid_value};
pub use control::{
    CancelToken, Cancelled, ClockFn, MeshStats, Progress, ProgressFn, SparseOptions,
};
pub(crate) use subdivide::surface_bricks as surface_nodes;
pub use thin::ThinCounts;

use crate::IndexedMesh;
use crate::grid::GridSpec;
use crate::marching_cubes::SampleGrid;
use crate::marching_cubes::pinch::Pinch;
use crate::marching_cubes::polygonize::polygonize_with;
use crate::sink::MeshSink;
use rayon::prelude::*;
use solidkit_kernel::Evaluator;
#[cfg(doc)]
use solidkit_kernel::Program;
use std::sync::atomic::Ordering;

/// Meshes the zero set of `program` (any [`Evaluator`], usually a [`Program`]) over `spec` with
/// the sparse octree.
pub fn mesh_sparse<E: Evaluator>(
    program: &E,
    spec: GridSpec,
    opts: &SparseOptions,
) -> Result<(IndexedMesh, MeshStats), Cancelled> {
    let mut mesh = IndexedMesh::default();
    let stats = mesh_sparse_into(program, spec, opts, &mut mesh)?;
    Ok((mesh, stats))
}

/// Meshes the zero set of `program` over `spec` with the sparse octree into `sink`.
pub fn mesh_sparse_into<E: Evaluator>(
    program: &E,
    spec: GridSpec,
    opts: &SparseOptions,
    sink: &mut impl MeshSink,
) -> Result<MeshStats, Cancelled> {
    let mut stats = MeshStats::default();
    let t0 = opts.now();
    let leaves = subdivide::surface_bricks(program, &spec, opts, &mut stats)?;
    let t1 = opts.now();
    stats.octree_s = t1 - t0;
    stats.surface_bricks = leaves.len();
    if opts.over_budget(leaves.len()) {
        stats.over_budget = true;
        return Ok(stats);
    }
    let done = std::sync::atomic::AtomicUsize::new(0);
    let total = leaves.len();
    // Bricks in groups: each group's lists go into one store (a few allocations per group);
    // groups small enough that every thread gets several.
    let group = (total / (8 * rayon::current_num_threads().max(1))).clamp(1, BRICK_GROUP);
    let stores: Vec<brick::BrickStore> = leaves
        .par_chunks(group)
        .map_init(
            || brick::BrickScratch::new(opts.clock.clone()),
            |scratch, group| {
                scratch.store.clear();
                for leaf in group {
                    if opts.is_cancelled() {
                        break; // the run returns `Cancelled` below
                    }
                    brick::process(leaf, program, &spec, opts.brick_size(), scratch);
                    let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                    opts.report(Progress {
                        stage: "bricks",
                        done: n,
                        total,
                    });
                }
                scratch.store.exact()
            },
        )
        .collect();
    if opts.is_cancelled() {
        return Err(Cancelled);
    }
    let mut outputs: Vec<brick::BrickOutput> = stores.iter().flat_map(|s| s.bricks()).collect();
    drop(leaves);
    stats.samples_evaluated = outputs.iter().map(|o| o.samples).sum();
    stats.evaluation_cpu_s = outputs.iter().map(|o| o.evaluation_s).sum();
    for o in &outputs {
        stats.thin.add(&o.thin);
    }
    let outputs_certified = outputs.iter().all(|o| o.certified);
    let t2 = opts.now();
    stats.bricks_s = t2 - t1;
    outputs.sort_unstable_by_key(|o| (o.edges.coord[2], o.edges.coord[1], o.edges.coord[0]));
    let (edges, triangles): (Vec<_>, Vec<_>) =
        outputs.into_iter().map(|o| (o.edges, o.triangles)).unzip();
    let certified = outputs_certified && crate::marching_cubes::disjoint::planes_distinct(&spec);
    let orphans = assemble::assemble(edges, triangles, &spec, opts.brick_size(), sink);
    stats.intersection_free = certified && orphans == 0;
    stats.assemble_s = opts.now() - t2;
    Ok(stats)
}

/// The most leaf bricks per group of [`brick::BrickStore`].
const BRICK_GROUP: usize = 32;

/// Dense marching cubes with the full program at every sample: the reference the sparse path
/// must reproduce exactly.
pub fn mesh_dense<E: Evaluator>(program: &E, spec: GridSpec) -> IndexedMesh {
    let samples = SampleGrid::sample_program(program, spec);
    let mut mesh = IndexedMesh::default();
    let rule = Pinch {
        program,
        spec: &samples.spec,
        choices: program.has_choices(),
    };
    polygonize_with(&samples, &rule, &mut mesh);
    mesh
}

#[cfg(test)]
mod tests;
