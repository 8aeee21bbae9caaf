//! Dual contouring that is always manifold, keeps sharp features, and adapts to an error budget.
//!
//! Per cell, the surface patches come from the cell's configuration (corner signs, and the
//! asymptotic decider on ambiguous faces) exactly as the marching-cubes loops do (`patches`),
//! so both methods give the same topology on the same samples: one vertex per patch, placed at the minimiser of a QEF built from the
//! crossings of the patch's edges (points found on the real field by safeguarded Newton steps,
//! normals from the gradient; `crossing`, `qef`), solved with a rank-revealing
//! eigen-decomposition about the mass point and clamped into the cell. Every sign-changing grid
//! edge becomes one polygon through the patch vertices of its four cells (`contour`), split into
//! triangles along the diagonal that agrees best with the surface normal (`emit`).
//!
//! Manifold by construction: the polygons are the dual of the marching-cubes surface, a closed
//! 2-manifold, so each dual edge lies in exactly two polygons. The only way two polygons can share
//! a vertex pair twice is an ambiguous face whose two segments join the same patch on both sides;
//! such a face gets one vertex per segment and the polygons through it are fanned from a centre
//! vertex, so no mesh edge ever has more than two triangles and every vertex link is one cycle.
//!
//! Free of self-intersections by construction (`certify`; a run claims it, so that the report
//! need not test it, when the premises of `claim` hold): every piece of surface inside a cell
//! lies in a cone from the cell's patch vertex (kept strictly inside the cell) over a zone of the
//! cell's boundary, and the zones of different crossing edges are disjoint. A quad stays two
//! triangles only where a local test shows its pieces keep to their cones; otherwise it is fanned
//! from its crossing, which always does. Cells with several patches keep each patch on its own
//! side of a separating plane, and dual edges whose face crossing breaks the zones are routed
//! through a face vertex (`faces`).
//!
//! `tolerance` collapses octree nodes topology-safely within the error budget (`adapt`); the
//! result is checked for non-manifold vertices and (exactly) for crossing triangles, and nodes
//! next to either are not collapsed.
//!
//! Files: `patches.rs` (cell patch table, separating planes), `qef.rs`, `crossing.rs`,
//! `block.rs` (one brick or tile), `sources.rs` (sparse octree or dense grid), `cells.rs` (cells
//! by global coordinates), `contour.rs` (polygons), `probe.rs` (field values at folded quads'
//! diagonals, batched per block), `certify.rs` (why no triangles cross; the quad certificate),
//! `faces.rs` (face vertices), `emit.rs` (triangles), `adapt.rs` (simplification).

mod adapt;
mod block;
mod cells;
mod certify;
mod claim;
mod contour;
mod crossing;
mod emit;
mod faces;
mod patches;
mod probe;
pub(crate) mod qef;
mod sources;

use crate::IndexedMesh;
use crate::grid::GridSpec;
use crate::marching_cubes::SampleGrid;
use crate::octree::{Cancelled, MeshStats, SparseOptions, now};
use crate::sink::MeshSink;
use glam::DVec3;
use rayon::prelude::*;
use solidkit_kernel::Evaluator;
#[cfg(doc)]
use solidkit_kernel::Program;

/// Options of dual contouring.
#[derive(Debug, Clone, Default)]
pub struct DcOptions {
    /// Octree, cancellation and progress options (as for marching cubes).
    pub sparse: SparseOptions,
    /// Adaptive simplification: collapse octree nodes whose vertex stays within this distance of
    /// every surface plane it replaces (world units). `None`: one vertex per patch of every cell.
    pub tolerance: Option<f64>,
}

/// Dual contouring of the zero set of `program` (any [`Evaluator`], usually a [`Program`]) over
/// `spec`, on the sparse octree.
pub fn mesh_dc<E: Evaluator>(
    program: &E,
    spec: GridSpec,
    opts: &DcOptions,
) -> Result<(IndexedMesh, MeshStats), Cancelled> {
    let mut mesh = IndexedMesh::default();
    let stats = mesh_dc_into(program, spec, opts, &mut mesh)?;
    Ok((mesh, stats))
}

/// [`mesh_dc`] into any sink.
pub fn mesh_dc_into<E: Evaluator>(
    program: &E,
    spec: GridSpec,
    opts: &DcOptions,
    sink: &mut impl MeshSink,
) -> Result<MeshStats, Cancelled> {
    let mut stats = MeshStats::default();
    let keep = opts.tolerance.is_some();
    let sources::SparseBlocks { blocks, evaluators } =
        sources::sparse_blocks(program, &spec, &opts.sparse, keep, &mut stats)?;
    if stats.over_budget {
        return Ok(stats);
    }
    let t = now(opts.sparse.clock.as_ref());
    let brick = opts.sparse.brick_size();
    let probe = probe::ProgramProbe(&evaluators);
    let mut contour = contour::assemble(&blocks, &spec, brick, &probe);
    // Taken, not copied: neither the emission nor the simplification reads them from `contour`.
    let mut positions = std::mem::take(&mut contour.positions);
    let triangles = match opts.tolerance {
        Some(tol) => {
            let dims = spec.cells.map(|c| c.div_ceil(brick).max(1));
            let index = cells::BlockIndex::new(&blocks, dims);
            let mut signs = sources::SparseSigns {
                blocks: &blocks,
                index: &index,
                block_size: brick,
                program,
                spec,
                cache: Default::default(),
                batch: E::BatchScratch::default(),
            };
            adapt::simplify(&blocks, &contour, &spec, &mut signs, tol, &mut positions)
        }
        None => emit::triangles(&contour, &mut positions, None),
    };
    let unreachable = blocks.iter().map(|b| b.unreachable).sum();
    stats.intersection_free = claim::claim(&spec, opts.tolerance, unreachable, contour.dropped);
    drop((blocks, evaluators));
    write(&positions, &triangles, sink);
    stats.assemble_s = now(opts.sparse.clock.as_ref()) - t;
    Ok(stats)
}

/// Dual contouring of a dense sample grid, searching crossings on `field` (any evaluator that
/// agrees in sign with the samples: tests use trilinear interpolants of arbitrary sign patterns;
/// only [`Evaluator::values_gradients`] is called).
pub fn mesh_dc_samples<F: Evaluator>(
    field: &F,
    samples: &SampleGrid,
    tolerance: Option<f64>,
) -> IndexedMesh {
    const TILE: usize = 8;
    let blocks = sources::dense_blocks(field, samples, TILE, tolerance.is_some());
    let mut contour = contour::assemble(&blocks, &samples.spec, TILE, &probe::FieldProbe(field));
    let mut positions = std::mem::take(&mut contour.positions);
    let triangles = match tolerance {
        Some(tol) => {
            let mut signs = samples;
            adapt::simplify(
                &blocks,
                &contour,
                &samples.spec,
                &mut signs,
                tol,
                &mut positions,
            )
        }
        None => emit::triangles(&contour, &mut positions, None),
    };
    let mut mesh = IndexedMesh::default();
    write(&positions, &triangles, &mut mesh);
    mesh
}

/// Writes the referenced vertices (in id order) and the triangles.
fn write(positions: &[DVec3], triangles: &[[u32; 3]], sink: &mut impl MeshSink) {
    /// Vertices or triangles per parallel block.
    const BLOCK: usize = 1 << 16;
    let used = crate::used::used_vertices(positions.len(), triangles);
    // Each used vertex's rank among the used ones, block by block in parallel.
    let counts: Vec<usize> = used
        .par_chunks(BLOCK)
        .map(|c| c.iter().filter(|&&u| u).count())
        .collect();
    let mut rank = vec![u32::MAX; positions.len()];
    let mut first = 0u32;
    let firsts: Vec<u32> = counts
        .iter()
        .map(|&n| {
            let at = first;
            first += n as u32;
            at
        })
        .collect();
    rank.par_chunks_mut(BLOCK)
        .zip(used.par_chunks(BLOCK))
        .zip(&firsts)
        .for_each(|((rank, used), &first)| {
            let mut next = first;
            for (r, &u) in rank.iter_mut().zip(used) {
                if u {
                    *r = next;
                    next += 1;
                }
            }
        });
    sink.reserve(first as usize, triangles.len());
    let ids = sink.add_vertex_blocks(&counts, &|b, out| {
        let span = b * BLOCK..((b + 1) * BLOCK).min(positions.len());
        let kept = positions[span.clone()]
            .iter()
            .zip(&used[span])
            .filter_map(|(p, &u)| u.then_some(*p));
        for (slot, p) in out.iter_mut().zip(kept) {
            *slot = p;
        }
    });
    let lens: Vec<usize> = triangles.chunks(BLOCK).map(<[_]>::len).collect();
    sink.add_triangle_blocks(&lens, &|b, out| {
        for (slot, t) in out.iter_mut().zip(&triangles[b * BLOCK..]) {
            *slot = t.map(|v| ids.get(rank[v as usize]));
        }
    });
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_accuracy;
#[cfg(test)]
mod tests_checkerboard;
#[cfg(test)]
mod tests_claim;
#[cfg(test)]
mod tests_manifold;
