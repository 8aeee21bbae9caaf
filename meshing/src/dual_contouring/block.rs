//! One block of cells (a leaf brick of the sparse octree, or a tile of a dense grid): from its
//! sample values, the crossings of every sign-changing edge between its samples, one QEF vertex per
//! surface patch of each cell, and the crossing edges it owns (each becomes one polygon).
//!
//! Ownership of edges follows the marching-cubes bricks: a block owns the edges whose lower sample
//! has local coordinates below the block size (or up to its extent for the last block along an
//! axis). Edges on block faces are searched by both blocks, with programs that agree there, so
//! both see the same crossings.

use super::certify::SEPARATOR_MARGIN;
use super::claim::vertex_margin;
use super::crossing::{
    CrossingScratch, EdgeQuery, GROUP_PRUNE_LEN, GroupScratch, refine, refine_grouped,
};
use super::patches::{Config, NO_PATCH, Separator, face_edges, patch_table, reachable};
use super::qef::Qef;
use crate::grid::GridSpec;
use crate::marching_cubes::inside;
use crate::marching_cubes::pinch::{FaceRule, Pinch, PinchScratch};
use crate::marching_cubes::table::{case_table, edge_origin};
use crate::octree::{ClockFn, now};
use glam::DVec3;
use solidkit_kernel::Evaluator;

/// Marks a cell without surface in [`Block::first`].
pub(crate) const NO_VERTEX: u32 = u32::MAX;

/// Block-local id of the edge along `axis` from local sample `(i, j, k)` (each in `0..=8`).
#[inline]
pub(crate) fn local_edge(s: [usize; 3], axis: usize) -> u16 {
    ((s[2] << 10) | (s[1] << 6) | (s[0] << 2) | axis) as u16
}

/// A crossing edge a block owns.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OwnedEdge {
    /// Local lower sample.
    pub sample: [u8; 3],
    /// Axis of the edge.
    pub axis: u8,
    /// The lower sample is inside.
    pub lower_inside: bool,
    /// Crossing point.
    pub point: DVec3,
    /// Unit normal there.
    pub normal: DVec3,
}

/// What one block contributes.
#[derive(Debug, Default)]
pub(crate) struct Block {
    /// Block coordinates (cell minimum / block size).
    pub coord: [usize; 3],
    /// Global index of the block's first cell.
    pub min: [usize; 3],
    /// Cells per axis.
    pub extent: [usize; 3],
    /// Configuration of every cell (x fastest): sign mask and joined ambiguous faces, as marching
    /// cubes decides them from the same samples.
    pub configs: Vec<Config>,
    /// Local number of each cell's first patch vertex ([`NO_VERTEX`] without surface).
    pub first: Vec<u32>,
    /// Patch vertices.
    pub vertices: Vec<DVec3>,
    /// QEF of each patch vertex (kept for adaptive simplification only).
    pub qefs: Vec<Qef>,
    /// Owned crossing edges.
    pub edges: Vec<OwnedEdge>,
    /// Crossings on ambiguous faces of the block's cells and on every edge of its cells with
    /// several patches (where dual edges may be routed through face vertices), by local edge id
    /// (sorted, unique).
    pub face_crossings: Vec<(u16, DVec3, DVec3)>,
    /// Inside flags of the samples (kept for adaptive simplification only).
    pub inside: Vec<u8>,
    /// Samples evaluated.
    pub samples: u64,
    /// Seconds of field evaluation.
    pub evaluation_s: f64,
    /// Thin and hidden features in the block (sparse path only).
    pub thin: crate::octree::ThinCounts,
    /// Cells whose configuration the decider alone never gives, which a separated pinch can
    /// (their patches may lack separating planes): the run then claims nothing
    /// ([`super::claim::claim`]).
    pub unreachable: usize,
}

impl Block {
    /// Local index of cell `c` (local coordinates).
    pub fn cell_index(&self, c: [usize; 3]) -> usize {
        c[0] + self.extent[0] * (c[1] + self.extent[1] * c[2])
    }
}

/// Per-thread buffers.
#[derive(Default)]
pub(crate) struct BlockScratch<S, I> {
    /// Inside flag per sample of the block.
    ins: Vec<u8>,
    ids: Vec<u32>,
    queries: Vec<EdgeQuery>,
    keys: Vec<u32>,
    crossings: Vec<(DVec3, DVec3)>,
    search: CrossingScratch,
    /// Group of each query (2 × 2 × 2 cells of its lower sample) for long programs.
    groups: Vec<u32>,
    grouped: GroupScratch,
    pub field: S,
    /// Interval buffers of the per-group pruning (long programs only).
    interval: I,
    /// Scratch of the pinch check.
    pinch: PinchScratch<I>,
    /// Times the crossing search, when the caller gave a clock.
    clock: Option<ClockFn>,
}

impl<S: Default, I: Default> BlockScratch<S, I> {
    /// Empty buffers; the crossing search is timed with `clock` when there is one.
    pub(crate) fn with_clock(clock: Option<ClockFn>) -> Self {
        BlockScratch {
            clock,
            ..Default::default()
        }
    }
}

/// Builds a block from its samples (`extent + 1` per axis, x fastest); `field` is the program
/// pruned for the block, `root` the full one (for the pinch check, [`crate::marching_cubes::pinch`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn build<F: Evaluator>(
    field: &F,
    root: &F,
    spec: &GridSpec,
    min: [usize; 3],
    extent: [usize; 3],
    block_size: usize,
    values: &[f32],
    keep: bool,
    s: &mut BlockScratch<F::GradientScratch, F::IntervalScratch>,
) -> Block {
    let e = extent;
    let n = [e[0] + 1, e[1] + 1, e[2] + 1];
    let (nx, nxy) = (n[0], n[0] * n[1]);
    s.ins.clear();
    s.ins.extend(values.iter().map(|&v| u8::from(inside(v))));
    let samples = s.ins.len();
    // Padding, so that the edge scan reads every sample's three forward neighbours without
    // bounds branches (the reads past an edge of the block are masked out).
    s.ins.resize(samples + nxy + nx + 1, 0);
    let ins = &s.ins;
    let point = |l: [usize; 3]| spec.point(min[0] + l[0], min[1] + l[1], min[2] + l[2]);
    // Every sign-changing edge between the block's samples.
    s.ids.clear();
    s.ids.resize(3 * nxy * n[2], NO_VERTEX);
    s.queries.clear();
    s.keys.clear();
    s.groups.clear();
    for k in 0..n[2] {
        for j in 0..n[1] {
            let (has_y, has_z) = (u8::from(j + 1 < n[1]), u8::from(k + 1 < n[2]));
            for i in 0..n[0] {
                let idx = i + nx * j + nxy * k;
                let here = ins[idx];
                // Bit `axis` set where the edge along it exists and changes sign: one branch
                // for the common sample without crossings.
                let changes = (ins[idx + 1] ^ here) & u8::from(i + 1 < n[0])
                    | ((ins[idx + nx] ^ here) & has_y) << 1
                    | ((ins[idx + nxy] ^ here) & has_z) << 2;
                if changes == 0 {
                    continue;
                }
                for (axis, step) in [1, nx, nxy].into_iter().enumerate() {
                    if changes >> axis & 1 == 0 {
                        continue;
                    }
                    let o = [0, 1, 2].map(|a| [i, j, k][a] + usize::from(a == axis));
                    s.ids[3 * idx + axis] = s.queries.len() as u32;
                    s.keys.push((3 * idx + axis) as u32);
                    let cell = |c: usize, m: usize| (c.min(m.saturating_sub(1)) / 2) as u32;
                    s.groups
                        .push(cell(i, e[0]) | cell(j, e[1]) << 10 | cell(k, e[2]) << 20);
                    s.queries.push(EdgeQuery {
                        a: point([i, j, k]),
                        b: point(o),
                        fa: values[idx],
                        fb: values[idx + step],
                    });
                }
            }
        }
    }
    s.crossings.clear();
    let start = now(s.clock.as_ref());
    if field.len() >= GROUP_PRUNE_LEN && s.queries.len() > 8 {
        refine_grouped(
            field,
            &s.queries,
            &s.groups,
            &mut s.crossings,
            &mut s.search,
            &mut s.grouped,
            &mut s.field,
            &mut s.interval,
        );
    } else {
        refine(
            field,
            &s.queries,
            &mut s.crossings,
            &mut s.search,
            &mut s.field,
        );
    }
    let evaluation_s = now(s.clock.as_ref()) - start;
    let table = patch_table();
    let cells = e[0] * e[1] * e[2];
    let mut b = Block {
        coord: min.map(|m| m / block_size),
        min,
        extent,
        configs: vec![0; cells],
        first: vec![NO_VERTEX; cells],
        samples: (nxy * n[2]) as u64,
        evaluation_s,
        ..Default::default()
    };
    let corner = [0, 1, nx, nx + 1, nxy, nxy + 1, nxy + nx, nxy + nx + 1];
    let half = 0.5 * spec.cell;
    let inner = DVec3::splat(vertex_margin(spec));
    let mc = case_table();
    let rule = Pinch {
        program: root,
        spec,
        choices: field.has_choices(),
    };
    let mut face_keys: Vec<u16> = Vec::new();
    // At most one owned edge per crossing edge, and on a surface about one vertex per crossing
    // edge: one allocation each (trimmed at the end), where pushes regrew and copied them.
    b.vertices.reserve_exact(s.keys.len());
    b.edges.reserve_exact(s.keys.len());
    for k in 0..e[2] {
        for j in 0..e[1] {
            // The corner mask slides along x: a cell's low-x corners (bits 0, 2, 4, 6) are the
            // previous cell's high-x ones (bits 1, 3, 5, 7).
            let mut mask = 0u8;
            for i in 0..e[0] {
                let base = i + nx * j + nxy * k;
                let high = base + 1;
                let high_x = ins[high] << 1
                    | ins[high + nx] << 3
                    | ins[high + nxy] << 5
                    | ins[high + nxy + nx] << 7;
                mask = if i == 0 {
                    let low_x = ins[base]
                        | ins[base + nx] << 2
                        | ins[base + nxy] << 4
                        | ins[base + nxy + nx] << 6;
                    low_x | high_x
                } else {
                    (mask >> 1) & 0x55 | high_x
                };
                let ci = i + e[0] * (j + e[1] * k);
                if mask == 0 || mask == 255 {
                    b.configs[ci] = Config::from(mask);
                    continue;
                }
                // The marching-cubes configuration, decided on the same f32 samples.
                let cell = [min[0] + i, min[1] + j, min[2] + k];
                let config = mc.cell_config_with(
                    usize::from(mask),
                    |c| values[base + corner[c as usize]],
                    |bit, corners, values| rule.joined(cell, bit, corners, values, &mut s.pinch),
                ) as Config;
                if !reachable(config) {
                    // Only a pinch check can give it (a separated face of a checkerboard cell).
                    b.unreachable += 1;
                }
                b.configs[ci] = config;
                let cell = table.get(config);
                b.first[ci] = b.vertices.len() as u32;
                let lo = point([i, j, k]);
                let hi = lo + DVec3::splat(spec.cell);
                let patches = &cell.edges;
                for (pi, patch) in patches.iter().enumerate() {
                    let mut q = Qef::new(lo + half);
                    let (mut plo, mut phi) = (hi, lo);
                    for &edge in patch {
                        let (axis, o) = edge_origin(edge);
                        let idx = base + o[0] + nx * o[1] + nxy * o[2];
                        let (p, nrm) = s.crossings[s.ids[3 * idx + axis] as usize];
                        q.add(p, nrm);
                        plo = plo.min(p);
                        phi = phi.max(p);
                    }
                    // A lone patch may sit anywhere strictly inside its cell (sharp features);
                    // several patches each stay within the box of their own crossings and on
                    // their own side of the planes separating them (see `certify`).
                    let v = if patches.len() == 1 {
                        q.solve(lo + inner, hi - inner).0
                    } else {
                        let clo = plo.max(lo + inner);
                        let v = q.solve(clo, phi.min(hi - inner).max(clo)).0;
                        let mass = q.reference + q.mass / f64::from(q.count.max(1));
                        separated(v, mass, lo, spec.cell, &cell.separators[pi])
                    };
                    b.vertices.push(v);
                    if keep {
                        b.qefs.push(q);
                    }
                }
                let amb = cell.ambiguous;
                if patches.len() > 1 {
                    // Dual edges next to this cell may be routed through its faces.
                    for edge in 0..12u8 {
                        if cell.patch_of_edge[edge as usize] != NO_PATCH {
                            let (ea, o) = edge_origin(edge);
                            face_keys.push(local_edge([i + o[0], j + o[1], k + o[2]], ea));
                        }
                    }
                } else if amb != 0 {
                    for axis in 0..3 {
                        for side in 0..2u8 {
                            if amb >> (2 * axis + side as usize) & 1 == 0 {
                                continue;
                            }
                            for edge in face_edges(axis, side) {
                                let (ea, o) = edge_origin(edge);
                                face_keys.push(local_edge([i + o[0], j + o[1], k + o[2]], ea));
                            }
                        }
                    }
                }
            }
        }
    }
    face_keys.sort_unstable();
    face_keys.dedup();
    b.face_crossings = face_keys
        .into_iter()
        .map(|key| {
            let l = [
                (key >> 2 & 15) as usize,
                (key >> 6 & 15) as usize,
                (key >> 10) as usize,
            ];
            let idx = l[0] + nx * l[1] + nxy * l[2];
            let (p, nrm) = s.crossings[s.ids[3 * idx + (key & 3) as usize] as usize];
            (key, p, nrm)
        })
        .collect();
    // Owned crossing edges.
    let owned = [0, 1, 2].map(|a| {
        if min[a] + e[a] == spec.cells[a] {
            e[a] + 1
        } else {
            block_size.min(e[a])
        }
    });
    for (q, &key) in s.keys.iter().enumerate() {
        let key = key as usize;
        let (idx, axis) = (key / 3, key % 3);
        let l = [idx % nx, idx / nx % n[1], idx / nxy];
        if (0..3).any(|a| l[a] >= owned[a]) {
            continue;
        }
        let (p, nrm) = s.crossings[q];
        b.edges.push(OwnedEdge {
            sample: l.map(|x| x as u8),
            axis: axis as u8,
            lower_inside: ins[idx] == 1,
            point: p,
            normal: nrm,
        });
    }
    if keep {
        b.inside = ins[..samples].to_vec();
    }
    b.vertices.shrink_to_fit();
    b.edges.shrink_to_fit();
    b
}

/// `v` moved towards `mass` (the mean of the patch's crossings, strictly inside every half-space
/// of `seps`) just as far as needed to lie [`SEPARATOR_MARGIN`] inside each of them; `lo` is the
/// cell's lower corner.
fn separated(v: DVec3, mass: DVec3, lo: DVec3, cell: f64, seps: &[Separator]) -> DVec3 {
    let (x, m) = ((v - lo) / cell, (mass - lo) / cell);
    let mut t: f64 = 1.0;
    for s in seps {
        let (fx, fm) = (s.value(x), s.value(m));
        if fx > -SEPARATOR_MARGIN {
            t = t.min(((-SEPARATOR_MARGIN - fm) / (fx - fm)).max(0.0));
        }
    }
    if t >= 1.0 { v } else { mass + (v - mass) * t }
}
