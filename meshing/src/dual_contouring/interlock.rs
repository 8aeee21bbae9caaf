//! The separating plane of an interlocked cell ([`Interlock`]), which depends on its crossings.
//!
//! In an interlocked cell the low patch holds the four edges of face (`axis`, 0) and two edges
//! along `axis` on one diagonal of the cross-section; the high patch the four edges of face
//! (`axis`, 1) and the other two. No plane separates the edges themselves, but the four faces
//! along `axis` each hold one edge of each pair, and on such a face the asymptotic decider orders
//! their *linear* crossings (the zeros of the linear interpolants of the samples): a separated
//! face with inside corners `a`, `c` and outside corners `b`, `d` has `a·c ≤ b·d`, which is exactly
//! the low patch's linear crossing lying no further along `axis` than the high patch's; on a
//! joined face the same order follows from `a·c > b·d`, as the patches are the complement's. Two
//! ties at once would need the products of both faces across `axis` to tie as well, which the
//! decider rules out (they are joined strictly, or separated with the faces along `axis` joined
//! strictly), so the low patch's linear crossings are always strictly separable from the high
//! patch's by a plane through the cell (tilted where one face ties).
//!
//! The cell's plane is the candidate (`axis` tilted by small steps towards the other two) that
//! separates both the real crossings and the linear ones with the widest margin, or, when the
//! real crossings cannot be separated (the field bends the two sheets across each other inside
//! the cell, against what its samples say), the one separating the linear crossings. Every plane
//! of every interlocked cell therefore has the linear crossing of each of its edges on the right
//! side: where a point on an edge along `axis` must lie on its patch's side in each cell around
//! it (the fan centre of a polygon, the crossings a face vertex is placed between, the mass point
//! a vertex is moved towards), the real crossing is used when it does in every such cell, else
//! the linear one, which does in all of them.

use super::certify::EPS;
use super::patches::{Interlock, Separator};
use glam::DVec3;

/// Linear crossings stay this far (of the edge) from the samples.
pub(crate) const LINEAR_MARGIN: f64 = 1e-6;

/// Margin (cell units) above which a plane separating the real crossings too is preferred.
const PLANE_MARGIN: f64 = 1e-6;

/// Tilts of the candidate planes towards each of the two other axes.
const TILTS: [f64; 7] = [
    0.0,
    1.0 / 64.0,
    -1.0 / 64.0,
    1.0 / 16.0,
    -1.0 / 16.0,
    0.25,
    -0.25,
];

/// The zero of the linear interpolant of `fa` at `a` and `fb` at `b` (of opposite signs), kept
/// [`LINEAR_MARGIN`] from both ends. The same inputs give the same point in every block.
pub(crate) fn linear_point(a: DVec3, b: DVec3, fa: f32, fb: f32) -> DVec3 {
    let (fa, fb) = (f64::from(fa).abs(), f64::from(fb).abs());
    let t = fa / (fa + fb);
    let t = if t.is_finite() {
        t.clamp(LINEAR_MARGIN, 1.0 - LINEAR_MARGIN)
    } else {
        0.5
    };
    a + (b - a) * t
}

/// The crossings of one edge along the interlock's axis, in cell units: the real one and the
/// linear one.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AxisEdge {
    pub real: DVec3,
    pub linear: DVec3,
    /// The edge belongs to the low patch.
    pub low: bool,
}

/// The half-space `a · x < b` (cell units) of the low patch of an interlocked cell (the high
/// patch keeps to its complement); `edges` are the cell's four edges along `i.axis`.
pub(crate) fn plane(i: Interlock, edges: &[AxisEdge; 4]) -> Separator {
    let axis = usize::from(i.axis);
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    // For a normal, the range of values on each side: (low max, high min) over the linear
    // crossings and over the real ones. The faces across the axis hold whole edges of one patch
    // each: their corners bound the values there.
    let gaps = |n: DVec3| {
        let corner_lo = n[u].max(0.0) + n[v].max(0.0);
        let corner_hi = 1.0 + n[u].min(0.0) + n[v].min(0.0);
        let (mut lin, mut real) = ((corner_lo, corner_hi), (corner_lo, corner_hi));
        for e in edges {
            let (l, r) = (n.dot(e.linear), n.dot(e.real));
            if e.low {
                lin.0 = lin.0.max(l);
                real.0 = real.0.max(r);
            } else {
                lin.1 = lin.1.min(l);
                real.1 = real.1.min(r);
            }
        }
        let both = (lin.0.max(real.0), lin.1.min(real.1));
        (lin, both)
    };
    let mut best_both: Option<(f64, DVec3, f64)> = None;
    let mut best_lin: Option<(f64, DVec3, f64)> = None;
    for tu in TILTS {
        for tv in TILTS {
            let mut n = DVec3::ZERO;
            n[axis] = 1.0;
            n[u] = tu;
            n[v] = tv;
            let (lin, both) = gaps(n);
            for (range, best) in [(both, &mut best_both), (lin, &mut best_lin)] {
                let gap = range.1 - range.0;
                if best.is_none_or(|b| gap > b.0) {
                    *best = Some((gap, n, 0.5 * (range.0 + range.1)));
                }
            }
        }
    }
    let (gap, n, c) = best_both.expect("candidates");
    let (_, n, c) = if gap >= 2.0 * PLANE_MARGIN {
        (gap, n, c)
    } else {
        best_lin.expect("candidates")
    };
    Separator { a: n, b: c }
}

/// The point of an edge to use where it must lie strictly on its patch's side in some cells
/// (`ok`): the real crossing if it does, else the linear one.
pub(crate) fn safe_point(real: DVec3, linear: DVec3, ok: impl Fn(DVec3) -> bool) -> DVec3 {
    if ok(real) { real } else { linear }
}

/// True when `x` lies strictly inside every half-space in `seps` (with the certificate's margin).
pub(crate) fn inside_all(seps: &[Separator], x: DVec3) -> bool {
    seps.iter().all(|s| s.value(x) < -EPS)
}
