//! Thin and hidden features in one brick's samples: what the grid cannot represent faithfully.
//!
//! Marching cubes (and dual contouring, which uses its configurations) sees the solid only at the
//! samples. A feature thinner than a cell is either caught by a single layer of samples (the two
//! neighbours of a sample along some axis are on the other side: an *isolated* sample; the mesh
//! then holds the feature as a sliver of the wrong volume) or missed entirely (all corners of the
//! cells it lies in agree: a *hidden* feature). Both are found here, from the samples the brick
//! has anyway plus a search with the brick's pruned program where the samples hint at a feature:
//!
//! - along every grid line, an edge whose two samples are on the same side but whose outer
//!   neighbours slope towards it so steeply that the two slopes, extended, meet on the other
//!   side (the signature of a thin plate, a small ball or a narrow slot between samples) is a
//!   candidate;
//! - each cell around a candidate edge whose eight corners agree is searched: octants whose
//!   interval (pruned program) cannot rule out the other side are split, down to 1/32 of a cell,
//!   and their centres evaluated; a point of the other side is a hidden feature. It is *detached*
//!   when no sample of the 4 × 4 × 4 block around the cell is on its side (a part of the solid,
//!   or a gap in it, that the mesh loses), *attached* otherwise (a detail of a part the mesh has).
//!
//! The counts go into [`ThinCounts`]; [`crate::refine`] decides from them whether to mesh again on
//! a finer grid. The scan costs a few comparisons per sample where nothing hints at a feature.

use crate::marching_cubes::GridSpec;
use glam::DVec3;
use solidkit_kernel::program::IntervalScratch;
use solidkit_kernel::{Aabb, Program};
use std::collections::VecDeque;

/// Depth of the search below a cell: octants down to `1 / 2^SEARCH_DEPTH` of a cell.
pub const SEARCH_DEPTH: u32 = 5;

/// Search depth up to which a found point marks a substantial feature: the octant centres of
/// depth 2 are a quarter cell apart, so every ball of radius `√3/8` cell holds one.
pub const SUBSTANTIAL_DEPTH: u32 = 2;

/// Most octants one cell's search evaluates.
const SEARCH_BUDGET: usize = 600;

/// What the samples of some bricks say about features the grid cannot hold.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct ThinCounts {
    /// Samples with a 6-neighbour on the other side.
    pub surface_samples: u64,
    /// Samples whose two neighbours along some axis are both on the other side.
    pub isolated_samples: u64,
    /// Cells with agreeing corners that hold a point of the other side, far from any sample of
    /// that side (a feature the mesh loses).
    pub detached: u64,
    /// Such cells next to samples of that side (a detail below the cell size).
    pub attached: u64,
    /// Detached features found at a search depth of at most [`SUBSTANTIAL_DEPTH`] (features
    /// that hold a ball of a fifth of the cell or more, not slivers).
    pub detached_substantial: u64,
    /// Cells searched with the program.
    pub cells_searched: u64,
    /// A point of a detached feature (the first found), for the warning.
    pub example: Option<[f64; 3]>,
}

impl ThinCounts {
    /// Adds `other`'s counts (the example of `self` is kept if it has one).
    pub fn add(&mut self, other: &ThinCounts) {
        self.surface_samples += other.surface_samples;
        self.isolated_samples += other.isolated_samples;
        self.detached += other.detached;
        self.detached_substantial += other.detached_substantial;
        self.attached += other.attached;
        self.cells_searched += other.cells_searched;
        if self.example.is_none() {
            self.example = other.example;
        }
    }

    /// Whether the grid misses or thins features enough to mesh again finer: a substantial
    /// detached feature (a lost part or gap), or features one cell thick or below it making up
    /// more than 2% of the surface samples (a few are normal at the tips, sharp edges and
    /// intersection curves of any solid; a thin plate or wall has them all along).
    pub fn needs_refinement(&self) -> bool {
        self.detached_substantial > 0
            || (self.isolated_samples + self.attached + self.detached) * 50
                > self.surface_samples.max(1)
    }
}

/// Scans the settled `values` of the `n[0] × n[1] × n[2]` samples from grid index `min` (x
/// fastest), searching with `program` (valid in their box).
pub fn scan(
    values: &[f32],
    n: [usize; 3],
    min: [usize; 3],
    spec: &GridSpec,
    program: &Program,
    scratch: &mut IntervalScratch,
) -> ThinCounts {
    let mut counts = ThinCounts::default();
    let stride = [1, n[0], n[0] * n[1]];
    let ins = |i: usize| values[i] < 0.0;
    let mut searched: Vec<usize> = Vec::new();
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                let at = [i, j, k];
                let idx = i + stride[1] * j + stride[2] * k;
                let here = ins(idx);
                let (mut surface, mut isolated) = (false, false);
                for a in 0..3 {
                    let lo = (at[a] > 0).then(|| ins(idx - stride[a]));
                    let hi = (at[a] + 1 < n[a]).then(|| ins(idx + stride[a]));
                    surface |= lo == Some(!here) || hi == Some(!here);
                    isolated |= lo == Some(!here) && hi == Some(!here);
                    // The edge from here along `a`, with both outer neighbours.
                    if at[a] == 0 || at[a] + 2 >= n[a] || hi != Some(here) {
                        continue;
                    }
                    let f = |o: isize| {
                        let v = values[(idx as isize + o * stride[a] as isize) as usize];
                        if here { -v } else { v }
                    };
                    let (f0, f1, f2, f3) = (f(-1), f(0), f(1), f(2));
                    let (sl, sr) = (f1 - f0, f3 - f2);
                    if !(sl < 0.0 && sr > 0.0) {
                        continue;
                    }
                    // The two slopes extended meet at t (from sample here) with value `low`.
                    let t = (f2 - f1 - sr) / (sl - sr);
                    let low = f1 + sl * t;
                    if low >= 0.0 {
                        continue;
                    }
                    for c in 0..4 {
                        let mut cell = at;
                        let (b, d) = ((a + 1) % 3, (a + 2) % 3);
                        if c & 1 == 1 {
                            if cell[b] == 0 {
                                continue;
                            }
                            cell[b] -= 1;
                        }
                        if c & 2 == 2 {
                            if cell[d] == 0 {
                                continue;
                            }
                            cell[d] -= 1;
                        }
                        if (0..3).any(|x| cell[x] + 1 >= n[x]) {
                            continue;
                        }
                        let cidx = cell[0] + stride[1] * cell[1] + stride[2] * cell[2];
                        if searched.contains(&cidx) || !corners_agree(values, cidx, stride, here) {
                            continue;
                        }
                        searched.push(cidx);
                        counts.cells_searched += 1;
                        let lo = spec.point(min[0] + cell[0], min[1] + cell[1], min[2] + cell[2]);
                        let Some((p, depth)) = search(program, lo, spec.cell, here, scratch) else {
                            continue;
                        };
                        if near_other_side(values, cell, n, stride, here) {
                            counts.attached += 1;
                        } else {
                            counts.detached += 1;
                            counts.detached_substantial += u64::from(depth <= SUBSTANTIAL_DEPTH);
                            counts.example.get_or_insert(p.to_array());
                        }
                    }
                }
                counts.surface_samples += u64::from(surface);
                counts.isolated_samples += u64::from(isolated);
            }
        }
    }
    counts
}

/// Whether the eight corners of the cell at sample index `c` are all on side `here`.
fn corners_agree(values: &[f32], c: usize, s: [usize; 3], here: bool) -> bool {
    (0..8).all(|o| {
        let i = c + (o & 1) * s[0] + (o >> 1 & 1) * s[1] + (o >> 2) * s[2];
        (values[i] < 0.0) == here
    })
}

/// Whether a sample of the 4 × 4 × 4 block around the cell at `cell` is on the side `!here`.
fn near_other_side(
    values: &[f32],
    cell: [usize; 3],
    n: [usize; 3],
    s: [usize; 3],
    here: bool,
) -> bool {
    let range = |a: usize| cell[a].saturating_sub(1)..(cell[a] + 3).min(n[a]);
    range(2).any(|k| {
        range(1).any(|j| range(0).any(|i| (values[i + s[1] * j + s[2] * k] < 0.0) != here))
    })
}

/// A point of the cell `[lo, lo + h]³` on the other side of `here` (inside when `here` is
/// outside), by interval-pruned octant search down to [`SEARCH_DEPTH`].
fn search(
    program: &Program,
    lo: DVec3,
    h: f64,
    here: bool,
    scratch: &mut IntervalScratch,
) -> Option<(DVec3, u32)> {
    let mut queue = VecDeque::from([(lo, h, 0u32)]);
    let mut slots = Vec::new();
    let mut evaluated = 0;
    while let Some((lo, size, depth)) = queue.pop_front() {
        evaluated += 1;
        if evaluated > SEARCH_BUDGET {
            return None;
        }
        let iv = program.interval_with(&Aabb::new(lo, lo + DVec3::splat(size)), scratch);
        let possible = if here { iv.hi > 0.0 } else { iv.lo < 0.0 };
        if !possible {
            continue;
        }
        let centre = lo + DVec3::splat(size * 0.5);
        let v = program.value_with(centre, &mut slots);
        if (here && v > 0.0) || (!here && v < 0.0) {
            return Some((centre, depth));
        }
        if depth < SEARCH_DEPTH {
            let half = size * 0.5;
            for o in 0..8 {
                let off = DVec3::new((o & 1) as f64, (o >> 1 & 1) as f64, (o >> 2) as f64);
                queue.push_back((lo + off * half, half, depth + 1));
            }
        }
    }
    None
}
