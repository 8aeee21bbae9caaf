//! Thin and hidden features in one brick's samples: what the grid cannot represent faithfully.
//!
//! Marching cubes (and dual contouring, which uses its configurations) sees the solid only at the
//! samples. A feature thinner than a cell is either caught by a single layer of samples (the two
//! neighbours of a sample along some axis are on the other side: an *isolated* sample; the mesh
//! then holds the feature as a sliver of the wrong volume) or missed entirely (all corners of the
//! cells it lies in agree: a *hidden* feature). Both are found here, from the samples the brick
//! has anyway plus a search with the brick's pruned evaluator where the samples hint at a feature:
//!
//! - along every grid line, an edge whose two samples are on the same side but whose outer
//!   neighbours slope towards it so steeply that the two slopes, extended, meet on the other
//!   side (the signature of a thin plate, a small ball or a narrow slot between samples) is a
//!   candidate;
//! - each cell around a candidate edge whose eight corners agree is searched: octants whose
//!   interval (pruned program) cannot rule out the other side are split, down to 1/32 of a cell,
//!   and their centres evaluated (at most 96 octants); a point of the other side is a *detached*
//!   feature (a part of the solid, or a gap in it, that the mesh loses). Cells next to a sample
//!   of the other side (in the 4 × 4 × 4 block around them) are not searched: whatever they hide
//!   is a detail of a part the mesh has; they are counted as *attached* candidates.
//!
//! The counts go into [`ThinCounts`]; [`crate::refine`] decides from them whether to mesh again on
//! a finer grid. The scan costs a few comparisons per sample where nothing hints at a feature.

use crate::grid::GridSpec;
use glam::DVec3;
use solidkit_kernel::{Aabb, Evaluator};
use std::collections::VecDeque;

/// Depth of the search below a cell: octants down to `1 / 2^SEARCH_DEPTH` of a cell.
pub const SEARCH_DEPTH: u32 = 5;

/// Search depth up to which a found point marks a substantial feature: the octant centres of
/// depth 2 are a quarter cell apart, so every ball of radius `√3/8` cell holds one.
pub const SUBSTANTIAL_DEPTH: u32 = 2;

/// Most octants one cell's search evaluates.
const SEARCH_BUDGET: usize = 96;

/// What the samples of some bricks say about features the grid cannot hold.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct ThinCounts {
    /// Samples with a 6-neighbour on the other side.
    pub surface_samples: u64,
    /// Samples whose two neighbours along some axis are both on the other side.
    pub isolated_samples: u64,
    /// Cells with agreeing corners, far from any sample of the other side, that hold a point of
    /// the other side (a feature the mesh loses).
    pub detached: u64,
    /// Candidate cells next to samples of the other side (not searched: at most a detail below
    /// the cell size of a part the mesh has).
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
    /// detached feature (a lost part or gap), or samples one cell thick and lost features making
    /// up more than 2% of the surface samples (a few are normal at the tips, sharp edges and
    /// intersection curves of any solid; a thin plate or wall has them all along).
    pub fn needs_refinement(&self) -> bool {
        self.detached_substantial > 0
            || (self.isolated_samples + self.detached) * 50 > self.surface_samples.max(1)
    }
}

/// Scans the settled `values` of the `n[0] × n[1] × n[2]` samples from grid index `min` (x
/// fastest), searching with `program` (valid in their box). `outer` gives the settled side of a
/// grid sample outside the brick (`Some(true)`: inside; `None`: undecided), for the cells at the
/// brick's border whose 4 × 4 × 4 neighbourhood reaches into the next brick: without it a part
/// the next brick holds (a wedge whose edge runs along the border) would look detached.
pub fn scan<E: Evaluator>(
    values: &[f32],
    n: [usize; 3],
    min: [usize; 3],
    spec: &GridSpec,
    program: &E,
    scratch: &mut E::IntervalScratch,
    outer: &mut dyn FnMut([usize; 3]) -> Option<bool>,
) -> ThinCounts {
    let mut counts = ThinCounts::default();
    let stride = [1, n[0], n[0] * n[1]];
    count_layers(values, n, &mut counts);
    let mut searched: Vec<usize> = Vec::new();
    let mut dips = Vec::new();
    let mut flags = Vec::new();
    for a in 0..3 {
        if n[a] < 4 {
            continue;
        }
        // Edges (i, i + 1) along axis `a` with both outer neighbours (i in 1..n − 2): tested
        // over one index range per axis (vectorized), which also holds edges across the rows
        // and slices of lower axes; those are dropped afterwards.
        let s = stride[a];
        dips.clear();
        find_dips(values, s..values.len() - 2 * s, s, &mut flags, &mut dips);
        dips.retain(|&idx| {
            let i = idx / s % n[a];
            i >= 1 && i + 2 < n[a]
        });
        for &idx in &dips {
            let at = [idx % n[0], idx / n[0] % n[1], idx / stride[2]];
            let axes = [a, (a + 1) % 3, (a + 2) % 3];
            let here = values[idx] < 0.0;
            candidate(
                values,
                n,
                min,
                spec,
                program,
                scratch,
                at,
                axes,
                here,
                &mut searched,
                &mut counts,
                outer,
            );
        }
    }
    counts
}

/// Whether the edge from a sample of value `f1` to its neighbour `f2`, whose outer neighbours
/// along the line are `f0` and `f3`, is a candidate: `f1` and `f2` on the same side, and the
/// slopes from the outer neighbours, extended, meet on the other side (the signature of a thin
/// plate, a small ball or a narrow slot between the samples). With `g` the values oriented so
/// the side is positive and `l = g0 − g1 > 0`, `r = g3 − g2 > 0` the slopes, the line from the
/// left reaches zero at `g1 / l` and the one from the right at `1 − g2 / r`; they meet below
/// zero when the first comes before the second. Branch-free, so rows vectorize (settled values
/// are never zero; a NaN compares false).
#[inline(always)]
fn dip(f0: f32, f1: f32, f2: f32, f3: f32) -> bool {
    let m = 1f32.copysign(f1);
    let (g0, g1, g2, g3) = (f0 * m, f1 * m, f2 * m, f3 * m);
    let (l, r) = (g0 - g1, g3 - g2);
    (g2 > 0.0) & (l > 0.0) & (r > 0.0) & (g1 * r + g2 * l < l * r)
}

solidkit_kernel::wide_loop! {
    /// Sets `flags[i]` to 1 where lane `i` of the four equally long rows is a [`dip`], else 0.
    fn dip_flags(f0: &[f32], f1: &[f32], f2: &[f32], f3: &[f32], flags: &mut [u8]) {
        for ((((flag, &a), &b), &c), &d) in flags.iter_mut().zip(f0).zip(f1).zip(f2).zip(f3) {
            *flag = u8::from(dip(a, b, c, d));
        }
    }
}

/// Appends to `out` the indices `i` in `range` whose edge to `i + s` is a [`dip`] (outer
/// neighbours `i − s` and `i + 2s`). The whole range is flagged without branches into `flags`,
/// which are then read eight at a time: nearly every word is zero, and a range with a dip
/// mostly has one (a scalar pass over the range per dip cost more than the flags).
fn find_dips(
    values: &[f32],
    range: std::ops::Range<usize>,
    s: usize,
    flags: &mut Vec<u8>,
    out: &mut Vec<usize>,
) {
    let len = range.len();
    if len == 0 {
        return;
    }
    let f0 = &values[range.start - s..][..len];
    let f1 = &values[range.start..][..len];
    let f2 = &values[range.start + s..][..len];
    let f3 = &values[range.start + 2 * s..][..len];
    flags.clear();
    // Padded to whole words (the padding stays 0).
    flags.resize(len.div_ceil(8) * 8, 0);
    dip_flags(f0, f1, f2, f3, &mut flags[..len]);
    for (w, word) in flags.chunks_exact(8).enumerate() {
        let mut bits = u64::from_le_bytes(word.try_into().expect("eight bytes"));
        while bits != 0 {
            let lane = bits.trailing_zeros() as usize / 8;
            out.push(range.start + 8 * w + lane);
            bits &= !(0xff << (8 * lane));
        }
    }
}

/// Counts surface samples and samples one cell thick, with the inside flags of each row along x
/// as a bit mask.
fn count_layers(values: &[f32], n: [usize; 3], counts: &mut ThinCounts) {
    debug_assert!(n[0] < 32, "rows are 32-bit masks");
    let (mut stack, mut heap) = ([0u32; 1024], Vec::new());
    let rows: &mut [u32] = if n[1] * n[2] <= stack.len() {
        &mut stack[..n[1] * n[2]]
    } else {
        heap.resize(n[1] * n[2], 0);
        &mut heap
    };
    for (r, row) in rows.iter_mut().zip(values.chunks_exact(n[0])) {
        *r = row
            .iter()
            .enumerate()
            .fold(0u32, |m, (i, &v)| m | (u32::from(v < 0.0) << i));
    }
    let full = (1u32 << n[0]) - 1;
    for k in 0..n[2] {
        for j in 0..n[1] {
            let r = j + n[1] * k;
            let m = rows[r];
            // Differs from the neighbour below / above along each axis (bits off the grid: 0).
            let (xlo, xhi) = ((m ^ (m << 1)) & full & !1, (m ^ (m >> 1)) & (full >> 1));
            let (ylo, yhi) = (
                if j > 0 { m ^ rows[r - 1] } else { 0 },
                if j + 1 < n[1] { m ^ rows[r + 1] } else { 0 },
            );
            let (zlo, zhi) = (
                if k > 0 { m ^ rows[r - n[1]] } else { 0 },
                if k + 1 < n[2] { m ^ rows[r + n[1]] } else { 0 },
            );
            let surface = xlo | xhi | ylo | yhi | zlo | zhi;
            let isolated = (xlo & xhi) | (ylo & yhi) | (zlo & zhi);
            counts.surface_samples += u64::from(surface.count_ones());
            counts.isolated_samples += u64::from(isolated.count_ones());
        }
    }
}

/// Searches the cells around the candidate edge from sample `at` along `axes[0]` (whose two
/// samples are on side `here`).
#[allow(clippy::too_many_arguments)]
fn candidate<E: Evaluator>(
    values: &[f32],
    n: [usize; 3],
    min: [usize; 3],
    spec: &GridSpec,
    program: &E,
    scratch: &mut E::IntervalScratch,
    at: [usize; 3],
    axes: [usize; 3],
    here: bool,
    searched: &mut Vec<usize>,
    counts: &mut ThinCounts,
    outer: &mut dyn FnMut([usize; 3]) -> Option<bool>,
) {
    let stride = [1, n[0], n[0] * n[1]];
    let [_, b, d] = axes;
    for c in 0..4 {
        let mut cell = at;
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
        if near_other_side(values, cell, n, stride, here)
            || outer_near_other_side(cell, n, min, spec.samples(), here, outer)
        {
            // A detail of a part the mesh has: not worth a search.
            counts.attached += 1;
            continue;
        }
        counts.cells_searched += 1;
        let lo = spec.point(min[0] + cell[0], min[1] + cell[1], min[2] + cell[2]);
        if let Some((p, depth)) = search(program, lo, spec.cell, here, scratch) {
            counts.detached += 1;
            counts.detached_substantial += u64::from(depth <= SUBSTANTIAL_DEPTH);
            counts.example.get_or_insert(p.to_array());
        }
    }
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

/// Whether a grid sample of the 4 × 4 × 4 block around the cell at `cell` that lies outside the
/// brick (`n` samples from grid index `min`; the grid has `samples` per axis) is on the side
/// `!here` or undecided, by `outer`. Only reached for candidate cells, so rarely.
fn outer_near_other_side(
    cell: [usize; 3],
    n: [usize; 3],
    min: [usize; 3],
    samples: [usize; 3],
    here: bool,
    outer: &mut dyn FnMut([usize; 3]) -> Option<bool>,
) -> bool {
    // Global sample ranges of the block, clipped to the grid.
    let range = |a: usize| {
        let lo = (min[a] + cell[a]).saturating_sub(1);
        let hi = (min[a] + cell[a] + 3).min(samples[a]);
        lo..hi
    };
    let within = |a: usize, g: usize| g >= min[a] && g < min[a] + n[a];
    for k in range(2) {
        for j in range(1) {
            for i in range(0) {
                if within(0, i) && within(1, j) && within(2, k) {
                    continue; // seen by near_other_side
                }
                if outer([i, j, k]) != Some(here) {
                    return true;
                }
            }
        }
    }
    false
}

/// A point of the cell `[lo, lo + h]³` on the other side of `here` (inside when `here` is
/// outside), by interval-pruned octant search down to [`SEARCH_DEPTH`].
fn search<E: Evaluator>(
    program: &E,
    lo: DVec3,
    h: f64,
    here: bool,
    scratch: &mut E::IntervalScratch,
) -> Option<(DVec3, u32)> {
    let mut queue = VecDeque::from([(lo, h, 0u32)]);
    let mut slots = E::PointScratch::default();
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

#[cfg(test)]
mod tests {
    use super::{dip, find_dips};

    /// The flagged search finds exactly the dips of a plain scan, in order, for ranges of every
    /// length around the eight-lane words and strides of one row, slice and lane.
    #[test]
    fn find_dips_matches_a_plain_scan() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let values: Vec<f32> = (0..2000)
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                (state >> 40) as f32 / (1u64 << 23) as f32 - 1.0
            })
            .collect();
        let (mut flags, mut found) = (Vec::new(), Vec::new());
        let mut total = 0;
        for s in [1, 9, 81] {
            for len in (0..40).chain([700, 729, 1000]) {
                let range = s..s + len;
                found.clear();
                find_dips(&values, range.clone(), s, &mut flags, &mut found);
                let plain: Vec<usize> = range
                    .filter(|&i| dip(values[i - s], values[i], values[i + s], values[i + 2 * s]))
                    .collect();
                assert_eq!(found, plain, "stride {s}, length {len}");
                total += plain.len();
            }
        }
        assert!(total > 100, "the values hold dips: {total}");
    }

    /// The branch-free [`dip`] against the direct reading of its definition (orient, take the
    /// slopes, intersect the two lines, test the value there) on a million random quadruples of
    /// mixed signs and scales; they may differ only where the lines meet within rounding of 0.
    #[test]
    fn dip_matches_the_line_intersection() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let u = (state >> 40) as f32 / (1u64 << 24) as f32;
            let scale = [1e-3f32, 1.0, 1e3][(state & 3) as usize % 3];
            (2.0 * u - 1.0) * scale
        };
        let (mut found, mut close) = (0, 0);
        for _ in 0..1_000_000 {
            let f = [next(), next(), next(), next()];
            let here = f[1] < 0.0;
            let g = f.map(|v| if here { -v } else { v });
            let (sl, sr) = (g[1] - g[0], g[3] - g[2]);
            let direct = (f[2] < 0.0) == here && sl < 0.0 && sr > 0.0 && {
                let t = (g[2] - g[1] - sr) / (sl - sr);
                g[1] + sl * t < 0.0
            };
            if dip(f[0], f[1], f[2], f[3]) != direct {
                let t = (g[2] - g[1] - sr) / (sl - sr);
                let meet = g[1] + sl * t;
                assert!(
                    meet.abs() < 1e-4 * g.map(f32::abs).iter().fold(0f32, |a, &b| a.max(b)),
                    "{f:?}"
                );
                close += 1;
            }
            found += usize::from(direct);
        }
        assert!(found > 10_000, "the sample holds dips: {found}");
        assert!(close < 100, "{close} borderline disagreements");
    }
}
