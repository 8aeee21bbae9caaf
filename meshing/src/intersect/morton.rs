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
//! ([`LeafBoxes::meeting`], six four-lane vector compares).

use glam::{BVec4A, Vec4};
use rayon::prelude::*;

use crate::pieces::split_at;

/// Boxes per leaf.
pub(crate) const LEAF: usize = 4;

/// Leaves per tree query (a power of two): the leaves of one node query the tree once with the
/// node's box, then keep the leaves found that meet their own box, which gives each leaf the
/// same leaves as a query of its own at a quarter of the traversals.
pub(crate) const GROUP: usize = 4;

/// Bits of the Morton code (of 63) that the curve order's counting sort buckets by.
const TOP_BITS: u32 = 12;

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

/// The boxes of one leaf side by side, one four-lane vector per bound and axis (lanes past the
/// last box hold an empty box, which meets nothing), so one box is tested against all four with
/// six vector compares ([`LeafBoxes::meeting`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LeafBoxes {
    lo: [Vec4; 3],
    hi: [Vec4; 3],
}

impl LeafBoxes {
    /// The leaves of the `count` boxes `box_of(i)` (in curve order), [`LEAF`] boxes each.
    pub(crate) fn of(count: usize, box_of: impl Fn(usize) -> Box32 + Sync) -> Vec<Self> {
        (0..count.div_ceil(LEAF))
            .into_par_iter()
            .map(|l| {
                let mut lo = [[f32::INFINITY; LEAF]; 3];
                let mut hi = [[f32::NEG_INFINITY; LEAF]; 3];
                for lane in 0..LEAF.min(count - l * LEAF) {
                    let b = box_of(l * LEAF + lane);
                    for k in 0..3 {
                        lo[k][lane] = b.lo[k];
                        hi[k][lane] = b.hi[k];
                    }
                }
                Self {
                    lo: lo.map(Vec4::from_array),
                    hi: hi.map(Vec4::from_array),
                }
            })
            .collect()
    }

    /// The box of all its lanes (empty lanes add nothing).
    fn bounds(&self) -> Box32 {
        Box32 {
            lo: self.lo.map(Vec4::min_element),
            hi: self.hi.map(Vec4::max_element),
        }
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
        let mut meets = BVec4A::splat(true);
        for k in 0..3 {
            meets &=
                Vec4::splat(b.lo[k]).cmple(self.hi[k]) & self.lo[k].cmple(Vec4::splat(b.hi[k]));
        }
        meets.bitmask()
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

/// Cells of the Morton curve over a box: 2²¹ along each axis.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    lo: [f64; 3],
    scale: [f64; 3],
}

impl Frame {
    /// The frame over the box `[lo, hi]` (finite; an empty box gives one cell).
    pub(crate) fn new(lo: [f64; 3], hi: [f64; 3]) -> Self {
        let scale = [0, 1, 2].map(|k| {
            let extent = hi[k] - lo[k];
            if extent > 0.0 {
                f64::from((1u32 << 21) - 1) / extent
            } else {
                0.0
            }
        });
        Self { lo, scale }
    }

    /// The Morton code (63 bits) of the cell holding `p`; points outside the box go to the
    /// nearest cell.
    pub(crate) fn code(&self, p: [f64; 3]) -> u64 {
        // `as` saturates (NaN to 0), so this never wraps.
        let cell =
            [0, 1, 2].map(|k| (((p[k] - self.lo[k]) * self.scale[k]) as u32).min((1 << 21) - 1));
        spread(cell[0]) | spread(cell[1]) << 1 | spread(cell[2]) << 2
    }
}

/// `entries` in the order of their keys `key(e)` (a 63-bit Morton code and a distinct index):
/// a counting sort on the code's top bits, in input order, then each bucket sorted on its own,
/// in parallel. The order of one sort on the keys, at a fraction of its passes.
pub(crate) fn curve_sort<T: Copy + Send + Sync>(
    entries: Vec<T>,
    key: impl Fn(&T) -> (u64, u32) + Sync,
) -> Vec<T> {
    let Some(&first) = entries.first() else {
        return entries;
    };
    let top = |e: &T| (key(e).0 >> (63 - TOP_BITS)) as usize;
    let mut firsts = vec![0usize; (1 << TOP_BITS) + 1];
    for e in &entries {
        firsts[top(e) + 1] += 1;
    }
    for b in 0..1 << TOP_BITS {
        firsts[b + 1] += firsts[b];
    }
    let mut fill = firsts.clone();
    let mut sorted = vec![first; entries.len()];
    for e in &entries {
        let at = &mut fill[top(e)];
        sorted[*at] = *e;
        *at += 1;
    }
    drop(entries);
    split_at(&mut sorted, &firsts[..1 << TOP_BITS])
        .into_par_iter()
        .for_each(|bucket| bucket.sort_unstable_by_key(&key));
    sorted
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
    /// The tree over `leaves` (in curve order).
    pub(crate) fn new(leaves: &[LeafBoxes]) -> Self {
        let leaves: Vec<Box32> = leaves.par_iter().map(LeafBoxes::bounds).collect();
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
    use crate::intersect::tests_reference::Lcg;

    /// The bucketed sort gives the order of one sort on (code, index), whatever the spread of
    /// the codes: spread over the curve, all in one bucket, or on few distinct codes.
    #[test]
    fn curve_sort_is_one_sort_on_the_keys() {
        let mut rng = Lcg(7);
        let mut next = || rng.bits() >> 1;
        for (n, mask) in [
            (5000, u64::MAX >> 1),
            (3000, 0xffff),
            (3000, 0x7 << 59),
            (1, 3),
        ] {
            let entries: Vec<(u64, u32)> = (0..n).map(|i| (next() & mask, i)).collect();
            let mut want = entries.clone();
            want.sort_unstable();
            assert_eq!(curve_sort(entries, |e| *e), want, "{n} {mask:x}");
        }
        assert!(curve_sort(Vec::<(u64, u32)>::new(), |e| *e).is_empty());
    }

    /// Codes of a frame: the corners are the first and last cells, points outside go to the
    /// nearest cell, and a flat box gives one cell along its flat axis.
    #[test]
    fn frame_codes_clamp_to_the_box() {
        let frame = Frame::new([0.0, -1.0, 2.0], [1.0, 1.0, 2.0]);
        let last = spread((1 << 21) - 1) | spread((1 << 21) - 1) << 1;
        assert_eq!(frame.code([0.0, -1.0, 2.0]), 0);
        assert_eq!(frame.code([1.0, 1.0, 5.0]), last);
        assert_eq!(frame.code([9.0, 7.0, -3.0]), last);
        assert_eq!(frame.code([-9.0, -7.0, 3.0]), 0);
        assert!(frame.code([0.25, 0.0, 2.0]) < frame.code([0.75, 0.0, 2.0]));
    }

    /// `meeting` agrees with `meets` lane by lane, on boxes drawn from a small lattice (so that
    /// touching faces and equal bounds are common), and empty lanes meet nothing.
    #[test]
    fn four_lanes_agree_with_the_box_test() {
        let mut rng = Lcg(99);
        let mut next = || ((rng.bits() >> 33) % 6) as f32;
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
            let leaf = LeafBoxes::of(boxes.len(), |i| boxes[i])[0];
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
