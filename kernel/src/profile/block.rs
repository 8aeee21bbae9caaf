//! Distances from a block of nearby points at once (issue 14: the intersection of three extruded
//! offset letters, profiles of about a thousand edges, spent 95 % of its time in one edge-index
//! query per sample).
//!
//! The meshers sample a brick's points in chunks that fill a small box. For such a block the
//! edges that can be nearest to *some* point of the block are gathered once from the edge index,
//! and so are the edges that can cross the even-odd ray of some point; each point is then measured
//! against those alone. Repeated points (an extrusion along a world axis other than z sees whole
//! rows of samples at the same profile point) are measured once.
//!
//! Exactly the plain loop's answer, bit for bit:
//!
//! - if the nearest boundary point from the box's centre `c` is `d_c` away, every point `q` of
//!   the box (within the half-diagonal `h` of `c`) has a boundary point within `d_c + h`, so its
//!   nearest edge meets the box grown by `d_c + h`: the other edges are farther than that from
//!   every point of the box, by more than the rounding of the distance formula (the margin), so
//!   none of them can win. The candidates keep the plain loop's order and its strict comparison,
//!   so ties go to the same edge;
//! - an edge can cross the ray from `q` towards `+x` only if its `y` range holds `q.y` and it
//!   reaches right of `q.x` (up to rounding); the parity of the same crossing test over those edges
//!   is the plain loop's.
//!
//! A block whose box holds too many candidates (points spread over the profile) is measured point
//! by point through the index instead.

use super::nearest::{Best, Nearest, closest, crosses};
use super::polygon::Polygon;
use glam::DVec2;
use std::cell::RefCell;

/// Above this many nearest-edge candidates per distinct point a block is measured point by point.
const MAX_CANDIDATES_PER_POINT: usize = 48;

/// One candidate edge `a → b`, edge `g` in the plain loop's order.
#[derive(Debug, Clone, Copy)]
struct Edge {
    a: DVec2,
    b: DVec2,
    g: u32,
}

/// The buffers of one block query, reused by the thread.
#[derive(Debug, Default)]
struct Scratch {
    /// Distinct points: the index of each point's first occurrence in the block.
    first: Vec<u32>,
    /// Open-addressing table from point bits to `first` entries (+1; 0 empty).
    table: Vec<u32>,
    /// Candidate edges for the nearest edge, in the plain loop's order.
    near: Vec<Edge>,
    /// Candidate edges for the crossing test.
    cross: Vec<(DVec2, DVec2)>,
    /// Per point: its distinct point's position in `first`.
    which: Vec<u32>,
    /// The answer at each distinct point.
    distinct: Vec<Nearest>,
    /// Traversal stack.
    stack: Vec<u32>,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// The hash of a point's bits.
fn hash(q: DVec2) -> u64 {
    let h = q.x.to_bits() ^ q.y.to_bits().rotate_left(29);
    h.wrapping_mul(0x9E37_79B9_7F4A_7C15)
}

/// Squared distance between the boxes `[a0, a1]` and `[b0, b1]`.
fn boxes_distance2(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> f64 {
    (a0 - b1).max(b0 - a1).max(DVec2::ZERO).length_squared()
}

impl Polygon {
    /// [`Polygon::nearest`] of every point of `qs`, appended to `out` (the same answers; faster
    /// when the points lie close together, as a mesher's chunk of samples does).
    pub(crate) fn nearest_many(&self, qs: &[DVec2], out: &mut Vec<Nearest>) {
        let block = SCRATCH.with(|cell| match cell.try_borrow_mut() {
            Ok(mut s) => self.nearest_block(qs, out, &mut s),
            Err(_) => false,
        });
        if !block {
            out.extend(qs.iter().map(|&q| self.nearest(q)));
        }
    }

    /// The block query; false (`out` untouched) where it does not apply.
    fn nearest_block(&self, qs: &[DVec2], out: &mut Vec<Nearest>, s: &mut Scratch) -> bool {
        let Some(index) = &self.index else {
            return false;
        };
        if qs.len() < 2 || qs.iter().any(|q| !q.is_finite()) {
            return false;
        }
        let loops = self.loops();
        // Distinct points and their box.
        let size = (2 * qs.len()).next_power_of_two();
        let shift = 64 - size.trailing_zeros();
        s.table.clear();
        s.table.resize(size, 0);
        s.first.clear();
        let (mut lo, mut hi) = (qs[0], qs[0]);
        s.which.clear();
        for (i, &q) in qs.iter().enumerate() {
            let mut slot = (hash(q) >> shift) as usize;
            let found = loop {
                match s.table[slot] {
                    0 => {
                        s.first.push(i as u32);
                        s.table[slot] = s.first.len() as u32;
                        lo = lo.min(q);
                        hi = hi.max(q);
                        break s.first.len() - 1;
                    }
                    k => {
                        let j = s.first[k as usize - 1] as usize;
                        if qs[j].x.to_bits() == q.x.to_bits() && qs[j].y.to_bits() == q.y.to_bits()
                        {
                            break k as usize - 1;
                        }
                    }
                }
                slot = (slot + 1) & (size - 1);
            };
            s.which.push(found as u32);
        }
        // Every point of the box has a boundary point within `reach`.
        let centre = (lo + hi) * 0.5;
        let half = (hi - lo).length() * 0.5;
        let d_centre = index.nearest(loops, centre, |_, _| false).distance.abs();
        let margin = 1e-12 * (index.scale + lo.abs().max(hi.abs()).max_element());
        let reach = d_centre + half + margin;
        let limit = MAX_CANDIDATES_PER_POINT * s.first.len();
        if !index.block_candidates(
            loops,
            (lo, hi),
            reach * reach,
            margin,
            limit,
            &mut s.stack,
            &mut s.near,
            &mut s.cross,
        ) {
            return false;
        }
        if s.near.is_empty() {
            return false;
        }
        s.near.sort_unstable_by_key(|e| e.g);
        s.distinct.clear();
        for &i in &s.first {
            let q = qs[i as usize];
            // The first least squared distance in the plain loop's order.
            let mut best = (f64::INFINITY, 0);
            for (k, e) in s.near.iter().enumerate() {
                let d2 = closest(e.a, e.b, q).3;
                if d2 < best.0 {
                    best = (d2, k);
                }
            }
            let mut inside = false;
            for &(a, b) in &s.cross {
                inside ^= crosses(q, a, b);
            }
            let e = s.near[best.1];
            let (lambda, c, v, d2) = closest(e.a, e.b, q);
            let (r, i) = index.locate(e.g as usize);
            let n = loops[r].len();
            let found = Best {
                d2,
                ring: r,
                edge: (i + n - 1) % n,
                lambda,
                c,
                e: v,
            };
            s.distinct.push(found.signed(inside, q));
        }
        out.extend(s.which.iter().map(|&k| s.distinct[k as usize]));
        true
    }
}

impl super::edges::EdgeIndex {
    /// The edges that may be nearest to a point of the box `(lo, hi)` (whose box lies within
    /// `√reach2` of it) into `near`, and those that may cross the ray towards `+x` from one into
    /// `cross`; false when more than `limit` are near.
    #[allow(clippy::too_many_arguments)]
    fn block_candidates(
        &self,
        loops: &[Vec<DVec2>],
        (lo, hi): (DVec2, DVec2),
        reach2: f64,
        margin: f64,
        limit: usize,
        stack: &mut Vec<u32>,
        near: &mut Vec<Edge>,
        cross: &mut Vec<(DVec2, DVec2)>,
    ) -> bool {
        near.clear();
        cross.clear();
        stack.clear();
        let nodes = self.tree.nodes();
        stack.push(0);
        while let Some(index) = stack.pop() {
            let node = &nodes[index as usize];
            let (n0, n1) = (node.min.truncate(), node.max.truncate());
            let is_near = boxes_distance2(n0, n1, lo, hi) <= reach2;
            // An edge crossing a ray spans the ray's y and reaches right of its start.
            let may_cross = n0.y <= hi.y && n1.y >= lo.y && n1.x + margin >= lo.x;
            if !is_near && !may_cross {
                continue;
            }
            if !node.is_leaf() {
                stack.extend([node.first, node.first + 1]);
                continue;
            }
            for slot in node.slots() {
                let g = self.tree.slot_index(slot);
                let (r, i) = self.locate(g as usize);
                let n = loops[r].len();
                let (a, b) = (loops[r][(i + n - 1) % n], loops[r][i]);
                let (e0, e1) = (a.min(b), a.max(b));
                if boxes_distance2(e0, e1, lo, hi) <= reach2 {
                    near.push(Edge { a, b, g });
                    if near.len() > limit {
                        return false;
                    }
                }
                if e0.y <= hi.y && e1.y >= lo.y && e1.x + margin >= lo.x {
                    cross.push((a, b));
                }
            }
        }
        true
    }
}
