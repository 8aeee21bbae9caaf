//! Floating-point separation tests that settle most pairs before any exact predicate.
//!
//! Neighbouring triangles of a flat region are exactly coplanar, and an exact orientation test
//! that comes out exactly zero is the slow path of adaptive arithmetic (the whole expansion), so
//! the pairs are first tried against a few candidate separating planes in plain `f64`. A plane
//! separates only when every tested point is farther from it than a bound on the rounding error
//! (`TOL` times the product of the lengths involved, far above the few ulps a degree-4 polynomial
//! of coordinate differences can be off by), so a "separated" answer is always right; anything
//! closer is left to the exact tests.

use glam::DVec3;

/// Relative margin of the separation tests.
const TOL: f64 = 1e-11;

/// True when `x` is certainly positive given a magnitude bound `scale` of its terms.
fn positive(x: f64, scale: f64) -> bool {
    x > TOL * scale
}

/// True when the signed distances `s` (scaled by `scale`) are all certainly of the sign `sign`.
fn all_strictly(s: &[f64], sign: f64, scale: f64) -> bool {
    s.iter().all(|&x| positive(x * sign, scale))
}

/// Triangles `v a b` and `v c d` (one shared vertex `v`): true when a plane through `v` certainly
/// has one triangle in a closed half-space and the other's vertices `≠ v` strictly beyond it, so
/// they meet only at `v`. Candidate planes: each triangle's own plane, and for every edge through
/// `v` the plane through that edge perpendicular to its triangle.
pub(crate) fn separated_at_vertex(v: DVec3, [a, b]: [DVec3; 2], [c, d]: [DVec3; 2]) -> bool {
    let (a, b, c, d) = (a - v, b - v, c - v, d - v);
    let len = [a, b, c, d].map(DVec3::length);
    let (n1, n2) = (a.cross(b), c.cross(d));
    // Own planes: the other triangle strictly on one side.
    let scale1 = len[0] * len[1];
    let scale2 = len[2] * len[3];
    let s = [n1.dot(c), n1.dot(d)];
    if all_strictly(&s, 1.0, scale1 * len[2].max(len[3]))
        || all_strictly(&s, -1.0, scale1 * len[2].max(len[3]))
    {
        return true;
    }
    let s = [n2.dot(a), n2.dot(b)];
    if all_strictly(&s, 1.0, scale2 * len[0].max(len[1]))
        || all_strictly(&s, -1.0, scale2 * len[0].max(len[1]))
    {
        return true;
    }
    // Planes along an edge through `v`, perpendicular to its triangle: its own triangle is on
    // the side of its other vertex (exactly), the other triangle must be strictly opposite.
    let edge_planes = [
        (n1, a, b, [c, d], scale1, len[0], len[2].max(len[3])),
        (n1, b, a, [c, d], scale1, len[1], len[2].max(len[3])),
        (n2, c, d, [a, b], scale2, len[2], len[0].max(len[1])),
        (n2, d, c, [a, b], scale2, len[3], len[0].max(len[1])),
    ];
    edge_planes
        .into_iter()
        .any(|(n, edge, own, other, scale, edge_len, other_len)| {
            let m = n.cross(edge);
            let side = m.dot(own);
            let bound = scale * edge_len;
            if !positive(
                side.abs(),
                bound * len[0].max(len[1]).max(len[2]).max(len[3]),
            ) {
                return false;
            }
            let s = [m.dot(other[0]), m.dot(other[1])];
            all_strictly(&s, -side.signum(), bound * other_len)
        })
}

/// Triangles `u w a` and `u w b` sharing the edge `uw`: true when `a` and `b` certainly lie on
/// opposite sides of the edge (seen in the first triangle's plane), so the triangles cannot fold
/// onto each other and meet only along the edge.
pub(crate) fn apart_across_edge(u: DVec3, w: DVec3, a: DVec3, b: DVec3) -> bool {
    let e = w - u;
    let (pa, pb) = (e.cross(a - u), e.cross(b - u));
    let scale = e.length_squared() * (a - u).length() * (b - u).length();
    positive(-pa.dot(pb), scale)
}

/// Two triangles with no shared vertex: true when one's plane, or a plane through an edge of one
/// perpendicular to it, certainly has the two triangles strictly on opposite sides.
pub(crate) fn separated(s: [DVec3; 3], t: [DVec3; 3]) -> bool {
    separated_by_one(s, t) || separated_by_one(t, s)
}

/// [`separated`] with the candidate planes of `s` only.
fn separated_by_one(s: [DVec3; 3], t: [DVec3; 3]) -> bool {
    let o = s[0];
    let (e1, e2) = (s[1] - o, s[2] - o);
    // Squared lengths, and two square roots rather than one per length: the bounds only need to
    // be far above the rounding errors, which the margin `TOL` is.
    let (l1, l2) = (e1.length_squared(), e2.length_squared());
    let far = t
        .iter()
        .map(|p| (*p - o).length_squared())
        .fold(l1.max(l2), f64::max);
    let extent = far.sqrt();
    let n = e1.cross(e2);
    // Rounding errors scale with the edge lengths, not with |n| (small for a sliver).
    let scale = (l1 * l2).sqrt() * extent;
    // The plane of `s`.
    let d = t.map(|p| n.dot(p - o));
    if all_strictly(&d, 1.0, scale) || all_strictly(&d, -1.0, scale) {
        return true;
    }
    // Edge planes: `s` on the side of its third vertex, `t` strictly beyond.
    (0..3).any(|k| {
        let (p, q, r) = (s[k], s[(k + 1) % 3], s[(k + 2) % 3]);
        let m = n.cross(q - p);
        let bound = scale * (q - p).length();
        let own = m.dot(r - p);
        if !positive(own.abs(), bound * extent) {
            return false;
        }
        let d = t.map(|x| m.dot(x - p));
        all_strictly(&d, -own.signum(), bound * extent)
    })
}
