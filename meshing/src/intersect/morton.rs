//! The broad phase of the self-intersection test: triangle boxes in single precision, rounded
//! outwards (so two boxes that meet in `f64` still meet), sorted along a Morton curve of their
//! centres, grouped in leaves of [`LEAF`] consecutive boxes, and an implicit binary tree of
//! bounding boxes over the leaves (node `i` of level `k` covers leaves `i·2ᵏ .. (i+1)·2ᵏ`).
//!
//! A surface mesh is two-dimensional, so consecutive triangles along the curve lie close
//! together and the tree's boxes stay small; building it is one sort and one pass per level, far
//! cheaper than a SAH or PLOC tree, and the narrow phase reads triangles in curve order
//! (cache-friendly). Each leaf is queried only against leaves at or after it, so every pair of
//! boxes is visited once; the leaves of one node at level 2 ([`GROUP`] leaves) share one query
//! with the node's box, and a box is tested against a leaf's four boxes at once
//! ([`LeafBoxes::meeting`]).

use rayon::prelude::*;

/// Boxes per leaf.
pub(crate) const LEAF: usize = 4;

/// Leaves per tree query (a power of two): the leaves of one node query the tree once with the
/// node's box, then keep the leaves found that meet their own box, which gives each leaf the
/// same leaves as a query of its own at a quarter of the traversals.
pub(crate) const GROUP: usize = 4;

/// An axis-aligned box in single precision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Box32 {
    pub(crate) lo: [f32; 3],
    pub(crate) hi: [f32; 3],
}

impl Box32 {
    /// The smallest `f32` box holding the `f64` box `[lo, hi]`.
    pub(crate) fn outward(lo: [f64; 3], hi: [f64; 3]) -> Self {
        Self {
            lo: lo.map(down),
            hi: hi.map(up),
        }
    }

    /// The box of both.
    fn union(&self, other: &Self) -> Self {
        Self {
            lo: [0, 1, 2].map(|k| self.lo[k].min(other.lo[k])),
            hi: [0, 1, 2].map(|k| self.hi[k].max(other.hi[k])),
        }
    }

    /// True when the closed boxes meet.
    #[inline]
    pub(crate) fn meets(&self, other: &Self) -> bool {
        self.lo[0] <= other.hi[0]
            && other.lo[0] <= self.hi[0]
            && self.lo[1] <= other.hi[1]
            && other.lo[1] <= self.hi[1]
            && self.lo[2] <= other.hi[2]
            && other.lo[2] <= self.hi[2]
    }
}

/// The boxes of one leaf side by side, one array per bound and axis (lanes past the last box
/// hold an empty box, which meets nothing), so one box is tested against all four with no
/// branch per lane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LeafBoxes {
    lo: [[f32; LEAF]; 3],
    hi: [[f32; LEAF]; 3],
}

impl LeafBoxes {
    /// The leaves of `boxes` (in curve order), [`LEAF`] boxes each.
    pub(crate) fn of(boxes: &[Box32]) -> Vec<Self> {
        boxes
            .par_chunks(LEAF)
            .map(|chunk| {
                let mut leaf = Self {
                    lo: [[f32::INFINITY; LEAF]; 3],
                    hi: [[f32::NEG_INFINITY; LEAF]; 3],
                };
                for (lane, b) in chunk.iter().enumerate() {
                    for k in 0..3 {
                        leaf.lo[k][lane] = b.lo[k];
                        leaf.hi[k][lane] = b.hi[k];
                    }
                }
                leaf
            })
            .collect()
    }

    /// The box in lane `lane`.
    #[inline]
    pub(crate) fn lane(&self, lane: usize) -> Box32 {
        Box32 {
            lo: [0, 1, 2].map(|k| self.lo[k][lane]),
            hi: [0, 1, 2].map(|k| self.hi[k][lane]),
        }
    }

    /// Bit `lane` set for every lane whose box meets `b` (closed boxes, as [`Box32::meets`]).
    #[inline]
    pub(crate) fn meeting(&self, b: &Box32) -> u32 {
        // Lane by lane over whole arrays, with `&` rather than `&&`: no branch per comparison,
        // and a shape the compiler turns into vector compares.
        let mut meets = [true; LEAF];
        for k in 0..3 {
            let (lo, hi) = (&self.lo[k], &self.hi[k]);
            for lane in 0..LEAF {
                meets[lane] &= (b.lo[k] <= hi[lane]) & (lo[lane] <= b.hi[k]);
            }
        }
        meets
            .iter()
            .enumerate()
            .fold(0, |mask, (lane, &m)| mask | u32::from(m) << lane)
    }
}

/// The largest `f32` not above `x`.
fn down(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) > x { y.next_down() } else { y }
}

/// The smallest `f32` not below `x`.
fn up(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) < x { y.next_up() } else { y }
}

/// The order of the `count` boxes `box_of(i)` along the Morton curve of their centres (ties by
/// index, so the order is the same on every run).
pub(crate) fn curve_order(count: usize, box_of: impl Fn(usize) -> Box32 + Sync) -> Vec<u32> {
    let whole = (0..count)
        .into_par_iter()
        .map(&box_of)
        .reduce_with(|a, b| a.union(&b))
        .unwrap_or(Box32 {
            lo: [0.0; 3],
            hi: [0.0; 3],
        });
    let lo = whole.lo.map(f64::from);
    let scale = [0, 1, 2].map(|k| {
        let extent = f64::from(whole.hi[k]) - lo[k];
        if extent > 0.0 {
            f64::from((1u32 << 21) - 1) / extent
        } else {
            0.0
        }
    });
    let mut keyed: Vec<(u64, u32)> = (0..count)
        .into_par_iter()
        .map(|i| {
            let b = box_of(i);
            let cell = [0, 1, 2].map(|k| {
                let centre = (f64::from(b.lo[k]) + f64::from(b.hi[k])) * 0.5;
                // Finite inputs give finite boxes; `as` saturates, so this never wraps.
                ((centre - lo[k]) * scale[k]) as u32 & ((1 << 21) - 1)
            });
            (
                spread(cell[0]) | spread(cell[1]) << 1 | spread(cell[2]) << 2,
                i as u32,
            )
        })
        .collect();
    keyed.par_sort_unstable();
    keyed.into_iter().map(|(_, i)| i).collect()
}

/// The low 21 bits of `x` spread to every third bit.
fn spread(x: u32) -> u64 {
    let mut x = u64::from(x) & 0x1f_ffff;
    x = (x | x << 32) & 0x001f_0000_0000_ffff;
    x = (x | x << 16) & 0x001f_0000_ff00_00ff;
    x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
    x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
    x = (x | x << 2) & 0x1249_2492_4924_9249;
    x
}

/// The implicit tree over boxes already in curve order.
#[derive(Debug)]
pub(crate) struct LeafTree {
    /// `levels[0]`: the leaf boxes; each next level halves the previous (last: the root).
    levels: Vec<Vec<Box32>>,
}

impl LeafTree {
    /// The tree of `boxes` (in curve order), [`LEAF`] boxes per leaf.
    pub(crate) fn new(boxes: &[Box32]) -> Self {
        let leaves: Vec<Box32> = boxes
            .par_chunks(LEAF)
            .map(|c| c.iter().skip(1).fold(c[0], |a, b| a.union(b)))
            .collect();
        let mut levels = vec![leaves];
        while levels.last().is_some_and(|l| l.len() > 1) {
            let next = levels
                .last()
                .map(|l| {
                    l.par_chunks(2)
                        .map(|c| c.iter().skip(1).fold(c[0], |a, b| a.union(b)))
                        .collect()
                })
                .unwrap_or_default();
            levels.push(next);
        }
        Self { levels }
    }

    /// Number of leaves.
    pub(crate) fn leaf_count(&self) -> usize {
        self.levels.first().map_or(0, Vec::len)
    }

    /// The box of leaf `leaf`.
    pub(crate) fn leaf_box(&self, leaf: usize) -> Box32 {
        self.levels[0][leaf]
    }

    /// The tree level whose nodes gather [`GROUP`] leaves (lower for a small tree).
    pub(crate) fn group_level(&self) -> usize {
        GROUP.trailing_zeros().min(self.levels.len() as u32 - 1) as usize
    }

    /// Number of nodes at `level`.
    pub(crate) fn node_count(&self, level: usize) -> usize {
        self.levels[level].len()
    }

    /// The box of node `i` at `level` (it covers leaves `i·2^level .. (i+1)·2^level`).
    pub(crate) fn node_box(&self, level: usize, i: usize) -> Box32 {
        self.levels[level][i]
    }

    /// Pushes onto `out` every leaf at or after `leaf` whose box meets `query`, using `stack`
    /// as the work list.
    pub(crate) fn leaves_after(
        &self,
        leaf: usize,
        query: &Box32,
        stack: &mut Vec<(u8, u32)>,
        out: &mut Vec<u32>,
    ) {
        stack.clear();
        let top = self.levels.len() - 1;
        stack.push((top as u8, 0));
        while let Some((level, i)) = stack.pop() {
            let (k, i) = (usize::from(level), i as usize);
            // Leaves covered by this node end before `leaf`: nothing to do.
            if ((i + 1) << k) <= leaf || !self.levels[k][i].meets(query) {
                continue;
            }
            if k == 0 {
                out.push(i as u32);
                continue;
            }
            let below = &self.levels[k - 1];
            for child in [2 * i + 1, 2 * i] {
                if child < below.len() {
                    stack.push((level - 1, child as u32));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `meeting` agrees with `meets` lane by lane, on boxes drawn from a small lattice (so that
    /// touching faces and equal bounds are common), and empty lanes meet nothing.
    #[test]
    fn four_lanes_agree_with_the_box_test() {
        let mut state = 99u64;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((state >> 33) % 6) as f32
        };
        let mut random_box = || {
            let (a, b) = ([next(), next(), next()], [next(), next(), next()]);
            Box32 {
                lo: [0, 1, 2].map(|k| a[k].min(b[k])),
                hi: [0, 1, 2].map(|k| a[k].max(b[k])),
            }
        };
        let (mut met, mut missed) = (0, 0);
        for round in 0..2000 {
            let lanes = 1 + round % LEAF;
            let boxes: Vec<Box32> = (0..lanes).map(|_| random_box()).collect();
            let leaf = LeafBoxes::of(&boxes)[0];
            let query = random_box();
            let mask = leaf.meeting(&query);
            for lane in 0..LEAF {
                let own = boxes.get(lane);
                let want = own.is_some_and(|b| b.meets(&query));
                assert_eq!(mask >> lane & 1 == 1, want, "round {round} lane {lane}");
                if let Some(b) = own {
                    assert_eq!(leaf.lane(lane), *b);
                    if want {
                        met += 1;
                    } else {
                        missed += 1;
                    }
                }
            }
        }
        assert!(met > 500 && missed > 500, "{met} {missed}");
    }
}
