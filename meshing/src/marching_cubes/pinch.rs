//! Pinches: ambiguous faces whose inside corners the field joins only through a point (or a neck
//! too thin to find), kept apart instead of joined.
//!
//! The asymptotic decider ([`super::table::face_joined`]) reads only a face's four samples. Two
//! solids touching along an edge that crosses a face between its samples (boxes on a lattice
//! sharing an edge: the union is two shells meeting in a line, which exact Boolean kernels keep
//! as two shells) give such a face two inside corners on one diagonal; the bilinear saddle is
//! inside as often as not, and the decider then joins the two solids into one shell. No rule on
//! four values can tell that contact from a real neck, so a face the decider joins is confirmed
//! with the program itself:
//!
//! - only a face where the program has a choice (min, max) that either operand can win while
//!   both may be zero ([`Evaluator::contested`]) can hold such a contact: two pieces touching
//!   at a point are joined there by the choice between them, with both operands zero; any
//!   other face keeps the decider's answer after one interval;
//! - first the polyline from one inside corner through the saddle of the face's bilinear
//!   interpolant to the other is covered by [`PATH_BOXES`] boxes per leg: when every box's
//!   interval is wholly negative the polyline is an inside path and the face stays joined (a
//!   pinch cannot be crossed that way: the box over the contact holds points of neither
//!   piece). On gyroid-sphere at 256³ this settles all 1945 contested faces with 8 intervals
//!   each;
//! - otherwise the face (a square of the grid, zero thickness across it) is searched as a
//!   quadtree down to `1 / 2^DEPTH` of a cell: a square whose interval is wholly negative is
//!   *certainly inside*, one whose interval is nowhere negative is dropped, the rest are
//!   split. The 4 × 4 squares of level 2 are first walked from one inside corner through
//!   certainly inside squares;
//! - after each level the certainly inside squares, rasterised on the `2^DEPTH`² pixel grid
//!   (they are aligned, so pixel adjacency is exactly adjacency along an edge of positive
//!   length), are flood-filled from one inside corner's pixel: reaching the other's keeps the
//!   face joined (the field provably connects them inside the face);
//! - when both corners' pixels are certainly inside and no level connects them, the face is
//!   separated: the inside of the field on this face meets itself only where no square of
//!   `1 / 2^DEPTH` of a cell is inside (a contact along a line, a neck thinner than that);
//! - a corner that is a zero settled inside ([`super::sign`]: a sample on a surface) is
//!   anchored by any certainly inside pixel of the 2 × 2 beside it; with none, its inside lies
//!   off the face (a box whose face holds the sample, on the far side of the contact), it joins
//!   nothing here and the face is separated;
//! - otherwise (a sample corner within a pixel of the surface, an evaluator without interval
//!   arithmetic, more than [`BUDGET`] intervals) the decider's answer stands.
//!
//! Contacts on sample planes are the zero rule's ([`super::sign::lone_inside`]); together they
//! keep solids touching along an edge apart wherever the edge lies. Limit: two solids sharing
//! a face *strip* narrower than a cell that lies between samples are one solid, but interval
//! arithmetic cannot show the union's field negative across the shared plane (each operand is
//! positive on the other's side), so such a face is separated too (the decider alone joined
//! it about half the time).
//!
//! The check reads only the face's geometry and the full program (pruned for the face itself
//! when long, never for a brick), so both cells sharing a face, the sparse and the dense paths
//! and every thread count decide it alike, and the surface stays closed and manifold as with
//! the decider alone: the case table has triangles for every combination of joined faces.
//! Separating faces can give a cell a configuration the decider alone never gives (the
//! checkerboard masks with one pair of opposite faces joined and another separated); dual
//! contouring then claims nothing about self-intersections (its `unreachable` count) and the
//! report tests them. Cost: nothing in a brick whose pruned program has no choice left (most
//! of a gyroid away from its trim: [`Pinch::choices`]), elsewhere one interval per face the
//! decider joins, the polyline's boxes on the contested ones (8 intervals), the quadtree only
//! where they fail (contacts, thin necks).

use super::sign::INSIDE_ZERO;
use crate::grid::GridSpec;
use glam::DVec3;
use solidkit_kernel::{Aabb, Evaluator};
use std::collections::HashMap;

/// Depth of the face quadtree: squares down to `1 / 2^DEPTH` of a cell.
pub const DEPTH: u32 = 5;

/// Most intervals one face's check evaluates; beyond it the decider's answer stands.
pub const BUDGET: usize = 1024;

const SIDE: usize = 1 << DEPTH;

/// How ambiguous faces the decider joins are confirmed.
pub trait FaceRule: Sync {
    /// Per-thread scratch.
    type Scratch: Default + Send;

    /// Whether the face `bit` (`2·axis + side`) of the cell whose lowest sample is `cell` keeps
    /// its inside corners `corners[0]`, `corners[1]` joined (the decider joined them; the outside
    /// corners are `corners[2]`, `corners[3]`; corner numbers as in the case table; `values`
    /// are theirs, in the same order).
    fn joined(
        &self,
        cell: [usize; 3],
        bit: u8,
        corners: [u8; 4],
        values: [f32; 4],
        s: &mut Self::Scratch,
    ) -> bool;
}

/// The decider alone (values without a program: nothing to confirm with).
#[derive(Debug, Clone, Copy, Default)]
pub struct Decider;

impl FaceRule for Decider {
    type Scratch = ();

    #[inline]
    fn joined(&self, _: [usize; 3], _: u8, _: [u8; 4], _: [f32; 4], _: &mut ()) -> bool {
        true
    }
}

/// The decider confirmed by the full program's intervals over the face (see the module docs).
pub struct Pinch<'a, E: Evaluator> {
    /// The full program (never a pruned one).
    pub program: &'a E,
    /// The grid.
    pub spec: &'a GridSpec,
    /// False when the cells asked lie in a box where an evaluator valid there has no choice
    /// ([`Evaluator::has_choices`]: a brick's pruned program): the full program's choices are
    /// all decided over every face there, none is contested, and every face keeps the
    /// decider's answer without an interval (the answer the check gives, at no cost).
    pub choices: bool,
}

/// Per-thread scratch of [`Pinch`]: interval buffers and the faces decided lately (each face is
/// asked by the two cells that share it).
pub struct PinchScratch<I> {
    interval: I,
    decided: HashMap<([u32; 3], u8), bool>,
}

impl<I: Default> Default for PinchScratch<I> {
    fn default() -> Self {
        Self {
            interval: I::default(),
            decided: HashMap::new(),
        }
    }
}

/// Most decisions a scratch keeps (it is emptied when full).
const REMEMBERED: usize = 1 << 12;

/// Programs up to this length are not pruned for a face (pruning would cost more than it saves).
const PRUNE_LEN: usize = 16;

impl<E: Evaluator> FaceRule for Pinch<'_, E> {
    type Scratch = PinchScratch<E::IntervalScratch>;

    fn joined(
        &self,
        cell: [usize; 3],
        bit: u8,
        corners: [u8; 4],
        values: [f32; 4],
        s: &mut Self::Scratch,
    ) -> bool {
        if !self.choices {
            return true;
        }
        let axis = usize::from(bit >> 1);
        let mut q = cell;
        q[axis] += usize::from(bit & 1);
        let uv = match axis {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        let key = (q.map(|c| c as u32), bit >> 1);
        if let Some(&joined) = s.decided.get(&key) {
            return joined;
        }
        let joined = self.decide(q, uv, corners, values, &mut s.interval);
        if s.decided.len() >= REMEMBERED {
            s.decided.clear();
        }
        s.decided.insert(key, joined);
        joined
    }
}

impl<E: Evaluator> Pinch<'_, E> {
    /// The check of the face from sample `q` spanning axes `u`, `v`.
    fn decide(
        &self,
        q: [usize; 3],
        (u, v): (usize, usize),
        corners: [u8; 4],
        values: [f32; 4],
        s: &mut E::IntervalScratch,
    ) -> bool {
        let lo = self.spec.point(q[0], q[1], q[2]);
        let face = Aabb::new(lo, lo + (unit(u) + unit(v)) * self.spec.cell);
        self.program.interval_with(&face, s);
        if !self.program.contested(s) {
            // No two pieces of the solid (or of its outside) meet on the face.
            return true;
        }
        let pruned = if self.program.len() > PRUNE_LEN {
            self.program.prune(s)
        } else {
            None
        };
        let program = pruned.as_ref().unwrap_or(self.program);
        let step = self.spec.cell / SIDE as f64;
        let (eu, ev) = (unit(u) * step, unit(v) * step);
        let at = |c: u8| {
            let o = [c & 1, c >> 1 & 1, c >> 2 & 1];
            (usize::from(o[u]), usize::from(o[v]))
        };
        let pixel = |c: u8| {
            let (x, y) = at(c);
            (x * (SIDE - 1), y * (SIDE - 1))
        };
        // The common case first: the polyline from one inside corner through the saddle of
        // the face's bilinear interpolant to the other, covered by boxes that are all wholly
        // inside, is an inside path (no pinch can be crossed: it would leave a box partly
        // outside).
        let mut grid = [[0.0f64; 2]; 2];
        for (&c, &value) in corners.iter().zip(&values) {
            let (x, y) = at(c);
            grid[x][y] = f64::from(value);
        }
        let saddle = saddle(grid);
        let point = |(x, y): (f64, f64)| {
            lo + unit(u) * (x * self.spec.cell) + unit(v) * (y * self.spec.cell)
        };
        let ends = [at(corners[0]), at(corners[1])].map(|(x, y)| (x as f64, y as f64));
        let mut covered = true;
        'legs: for end in ends {
            for k in 0..PATH_BOXES {
                let t = |k: usize| k as f64 / PATH_BOXES as f64;
                let along = |t: f64| {
                    (
                        end.0 + (saddle.0 - end.0) * t,
                        end.1 + (saddle.1 - end.1) * t,
                    )
                };
                let (p, q) = (point(along(t(k))), point(along(t(k + 1))));
                if program.interval_with(&Aabb::new(p.min(q), p.max(q)), s).hi >= 0.0 {
                    covered = false;
                    break 'legs;
                }
            }
        }
        if covered {
            return true;
        }
        let zeros = [values[0] == INSIDE_ZERO, values[1] == INSIDE_ZERO];
        let mut interval = |x: usize, y: usize, size: usize| {
            let a = lo + eu * x as f64 + ev * y as f64;
            let b = a + (eu + ev) * size as f64;
            program.interval_with(&Aabb::new(a.min(b), a.max(b)), s)
        };
        face_connected(
            [
                Corner::new(pixel(corners[0]), zeros[0]),
                Corner::new(pixel(corners[1]), zeros[1]),
            ],
            &mut interval,
        )
    }
}

/// Boxes covering each leg of the polyline through the saddle.
pub const PATH_BOXES: usize = 4;

/// The saddle of the bilinear interpolant of `f[x][y]` (values at the unit square's corners),
/// kept a tenth of the face inside it.
fn saddle(f: [[f64; 2]; 2]) -> (f64, f64) {
    let e = f[0][0] - f[1][0] - f[0][1] + f[1][1];
    let (x, y) = if e != 0.0 {
        ((f[0][0] - f[0][1]) / e, (f[0][0] - f[1][0]) / e)
    } else {
        (0.5, 0.5)
    };
    let keep = |t: f64| {
        if t.is_finite() {
            t.clamp(0.1, 0.9)
        } else {
            0.5
        }
    };
    (keep(x), keep(y))
}

fn unit(axis: usize) -> DVec3 {
    let mut e = DVec3::ZERO;
    e[axis] = 1.0;
    e
}

/// Rows of the pixel grid, bit `x` of row `y` set when pixel `(x, y)` is certainly inside.
type Bitmap = [u32; SIDE];

/// An inside corner of the face in pixels: the pixels that anchor it.
#[derive(Clone, Copy)]
struct Corner {
    /// Its pixel.
    pixel: (usize, usize),
    /// Its anchor pixels: the corner's own, or for a zero the 2 × 2 block at it.
    anchor: Bitmap,
    /// A zero settled inside: its inside lies off the face unless a pixel beside it is inside.
    zero: bool,
}

impl Corner {
    fn new((x, y): (usize, usize), zero: bool) -> Self {
        let mut anchor: Bitmap = [0; SIDE];
        if zero {
            let (x0, y0) = (x.min(SIDE - 2), y.min(SIDE - 2));
            anchor[y0] = 3 << x0;
            anchor[y0 + 1] = 3 << x0;
        } else {
            anchor[y] = 1 << x;
        }
        Self {
            pixel: (x, y),
            anchor,
            zero,
        }
    }
}

/// The quadtree search of the module docs between inside corners `ends`; `interval(x, y, size)`
/// bounds the field over the square of `size` pixels from pixel `(x, y)`. False when the face
/// is to be separated.
fn face_connected(
    ends: [Corner; 2],
    interval: &mut impl FnMut(usize, usize, usize) -> solidkit_kernel::Interval,
) -> bool {
    let mut inside: Bitmap = [0; SIDE];
    let mut spent = 0usize;
    // Level 2, a 4 × 4 grid of squares, walked first from the square at one corner through
    // inside squares: on most faces the decider joins rightly, and a chain of a few inside
    // squares to the other corner's square proves it. (Level 1 is skipped: a quadrant holds a
    // corner of each sign, so it is never wholly inside or outside.)
    const GRID: usize = 4;
    let size = SIDE / GRID;
    let mut class = [[None::<Class>; GRID]; GRID];
    let mut classify = |(gx, gy): (usize, usize), spent: &mut usize| {
        *class[gy][gx].get_or_insert_with(|| {
            *spent += 1;
            Class::of(interval(gx * size, gy * size, size))
        })
    };
    let square = |(x, y): (usize, usize)| (x / size, y / size);
    let goal = square(ends[1].pixel);
    let mut stack = vec![square(ends[0].pixel)];
    let mut seen = 1u16 << (stack[0].0 + GRID * stack[0].1);
    while let Some(g) = stack.pop() {
        if classify(g, &mut spent) != Class::Inside {
            continue;
        }
        if g == goal {
            return true;
        }
        let (gx, gy) = g;
        for n in [
            (gx.wrapping_sub(1), gy),
            (gx + 1, gy),
            (gx, gy.wrapping_sub(1)),
            (gx, gy + 1),
        ] {
            if n.0 >= GRID || n.1 >= GRID {
                continue;
            }
            let bit = 1u16 << (n.0 + GRID * n.1);
            if seen & bit == 0 {
                seen |= bit;
                stack.push(n);
            }
        }
    }
    // No chain: classify the rest of level 2 and refine its mixed squares.
    let mut mixed = Vec::new();
    for gy in 0..GRID {
        for gx in 0..GRID {
            match classify((gx, gy), &mut spent) {
                Class::Inside => mark(&mut inside, gx * size, gy * size, size),
                Class::Mixed => mixed.push((gx * size, gy * size)),
                Class::Outside => {}
            }
        }
    }
    let mut next = Vec::new();
    for level in 3..=DEPTH {
        if spent + 4 * mixed.len() > BUDGET {
            return true;
        }
        let size = SIDE >> level;
        next.clear();
        for &(x, y) in &mixed {
            for (dx, dy) in [(0, 0), (size, 0), (0, size), (size, size)] {
                let (x, y) = (x + dx, y + dy);
                spent += 1;
                match Class::of(interval(x, y, size)) {
                    Class::Inside => mark(&mut inside, x, y, size),
                    Class::Mixed => next.push((x, y)),
                    Class::Outside => {}
                }
            }
        }
        std::mem::swap(&mut mixed, &mut next);
        let seeds = ends.map(|e| and(&e.anchor, &inside));
        if seeds.iter().all(|s| s.iter().any(|&r| r != 0)) && flood(&inside, &seeds[0], &seeds[1]) {
            return true;
        }
        if level == DEPTH {
            let anchored = seeds.map(|s| s.iter().any(|&r| r != 0));
            // A zero corner with no inside pixel beside it joins nothing in this face; a sample
            // corner within a pixel of the surface leaves the face to the decider.
            let lost_zero = (0..2).any(|i| ends[i].zero && !anchored[i]);
            let apart = anchored[0] && anchored[1];
            return !(lost_zero || apart);
        }
    }
    true
}

/// What an interval says of a square.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Class {
    /// Wholly inside (negative).
    Inside,
    /// Nowhere inside.
    Outside,
    /// Either (NaN included).
    Mixed,
}

impl Class {
    fn of(iv: solidkit_kernel::Interval) -> Self {
        if iv.hi < 0.0 {
            Class::Inside
        } else if iv.lo >= 0.0 {
            Class::Outside
        } else {
            Class::Mixed
        }
    }
}

/// Sets the pixels of the square of `size` from `(x, y)`.
fn mark(m: &mut Bitmap, x: usize, y: usize, size: usize) {
    let row = if size == SIDE {
        u32::MAX
    } else {
        ((1u32 << size) - 1) << x
    };
    for r in &mut m[y..y + size] {
        *r |= row;
    }
}

fn and(a: &Bitmap, b: &Bitmap) -> Bitmap {
    std::array::from_fn(|y| a[y] & b[y])
}

/// Whether a pixel of `to` is reachable from a pixel of `from` through set pixels of `m`
/// (4-neighbours).
fn flood(m: &Bitmap, from: &Bitmap, to: &Bitmap) -> bool {
    let mut reach = *from;
    loop {
        if reach.iter().zip(to).any(|(r, t)| r & t != 0) {
            return true;
        }
        let mut changed = false;
        for y in 0..SIDE {
            let mut r = reach[y] | reach[y] << 1 | reach[y] >> 1;
            if y > 0 {
                r |= reach[y - 1];
            }
            if y + 1 < SIDE {
                r |= reach[y + 1];
            }
            r &= m[y];
            if r != reach[y] {
                reach[y] = r;
                changed = true;
            }
        }
        if !changed {
            return false;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use solidkit_kernel::Interval;

    /// Exact intervals of a field given as a pixel predicate: inside where `inside(x, y)`, at
    /// every pixel of the square.
    fn by_pixels(
        inside: impl Fn(usize, usize) -> bool,
    ) -> impl FnMut(usize, usize, usize) -> Interval {
        move |x, y, size| {
            let n = (x..x + size)
                .flat_map(|i| (y..y + size).map(move |j| (i, j)))
                .filter(|&(i, j)| inside(i, j))
                .count();
            match n {
                0 => Interval::new(1.0, 2.0),
                _ if n == size * size => Interval::new(-2.0, -1.0),
                _ => Interval::new(-1.0, 1.0),
            }
        }
    }

    /// Inside corners at pixels (0, 0) and (31, 31), each a settled zero or not.
    fn ends(zero_a: bool, zero_c: bool) -> [Corner; 2] {
        [
            Corner::new((0, 0), zero_a),
            Corner::new((SIDE - 1, SIDE - 1), zero_c),
        ]
    }

    #[test]
    fn quadrants_touching_at_a_point_stay_apart() {
        // Inside: x < 13, y < 21 and x ≥ 13, y ≥ 21: two rectangles meeting at one corner.
        for (px, py) in [(13, 21), (1, 30), (16, 16), (31, 1)] {
            let mut f = by_pixels(|x, y| (x < px) == (y < py));
            assert!(!face_connected(ends(false, false), &mut f), "{px} {py}");
        }
    }

    #[test]
    fn a_neck_one_pixel_wide_joins() {
        // The same two rectangles plus a diagonal staircase of single pixels between them.
        let mut f =
            by_pixels(|x, y| (x < 13) == (y < 21) || (y == 20 && x == 13) || (y == 20 && x == 12));
        assert!(face_connected(ends(false, false), &mut f));
        let mut band = by_pixels(|x, y| x.abs_diff(y) <= 2);
        assert!(face_connected(ends(false, false), &mut band));
    }

    #[test]
    fn unanchored_corners_keep_the_decider() {
        // Corner `a` on the surface (its pixel is never certainly inside): the decider stands.
        let mut f = by_pixels(|x, y| (x >= 13) == (y >= 21) && (x, y) != (0, 0));
        assert!(face_connected(ends(false, false), &mut f));
    }

    #[test]
    fn a_zero_corner_joins_only_what_lies_beside_it() {
        // Corner c on the surface of a solid off the face: nothing inside near it.
        let mut f = by_pixels(|x, y| x < 13 && y < 21);
        assert!(!face_connected(ends(false, true), &mut f));
        // The same zero corner at the end of a band along the diagonal: joined.
        let mut band = by_pixels(|x, y| x.abs_diff(y) <= 2 && (x, y) != (SIDE - 1, SIDE - 1));
        assert!(face_connected(ends(false, true), &mut band));
        // A corner (not a zero) with nothing beside it: the decider stands.
        let mut f = by_pixels(|x, y| x < 13 && y < 21);
        assert!(face_connected(ends(false, false), &mut f));
    }

    #[test]
    fn the_budget_keeps_the_decider() {
        // Everything mixed: every square split until the budget runs out.
        let mut calls = 0;
        let mut f = |_: usize, _: usize, _: usize| {
            calls += 1;
            Interval::new(-1.0, 1.0)
        };
        assert!(face_connected(ends(false, false), &mut f));
        assert!(calls <= BUDGET, "{calls}");
    }
}
