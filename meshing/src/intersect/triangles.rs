//! Exact intersection tests of closed triangles, and of pairs of mesh triangles that share
//! vertices.
//!
//! Two triangles in different planes meet along the line where the planes cross; each cuts that
//! line in a segment whose ends lie on its edges, so they intersect exactly when an edge of one
//! meets the other. Coplanar triangles intersect when two edges cross or a vertex of one lies in
//! the other. Each test is a handful of exact orientation signs ([`predicates`](super::predicates)),
//! so touching counts as intersecting and nothing depends on rounding.
//!
//! Mesh neighbours touch by construction, so pairs sharing vertices ask whether they meet *beyond*
//! what they share:
//! - one shared vertex `v` (triangles `v a b`, `v c d`): the intersection, if more than `v`, is a
//!   segment from `v` whose far end lies on `ab` or `cd`, so they do exactly when `ab` meets the
//!   second triangle or `cd` the first; coplanar, exactly when their angular sectors at `v` share
//!   a ray (four 2D ray tests instead of the segment tests, which meet exact zeros at `v`);
//! - a shared edge `uw` (third vertices `a`, `b`): in different planes they meet only along `uw`;
//!   coplanar, they overlap when `a` and `b` lie on the same side of `uw` (a fold-back);
//! - three shared vertices: the same triangle twice, which overlaps itself.
//!
//! Exactly collinear triangles have no plane and are left out by the caller (they are reported as
//! degenerate faces).

use glam::DVec3;

use super::filter;
use super::predicates::{Projection, mixed, orient};

/// A non-degenerate triangle: its corners and a projection that keeps its area.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tri {
    pub(crate) p: [DVec3; 3],
    pub(crate) proj: Projection,
}

impl Tri {
    /// The triangle, or `None` when it is exactly collinear (the search builds its triangles from
    /// projections it has already found).
    pub(crate) fn new(p: [DVec3; 3]) -> Option<Self> {
        Projection::of(p).map(|proj| Self { p, proj })
    }

    /// True when the closed segment `[p, q]` meets the closed triangle.
    pub(crate) fn meets_segment(&self, p: DVec3, q: DVec3) -> bool {
        let [a, b, c] = self.p;
        let (sp, sq) = (orient(a, b, c, p), orient(a, b, c, q));
        if sp == sq && sp != 0 {
            return false;
        }
        if sp == 0 && sq == 0 {
            return self.meets_coplanar_segment(p, q);
        }
        // The segment crosses the plane at one point; it is in the triangle when the line `pq`
        // passes no edge on the wrong side.
        !mixed(&[orient(p, q, a, b), orient(p, q, b, c), orient(p, q, c, a)])
    }

    /// [`meets_segment`](Self::meets_segment) for a segment in the triangle's plane.
    fn meets_coplanar_segment(&self, p: DVec3, q: DVec3) -> bool {
        let [a, b, c] = self.p;
        self.contains_coplanar(p)
            || self.contains_coplanar(q)
            || [(a, b), (b, c), (c, a)]
                .iter()
                .any(|&(u, w)| segments_meet(self.proj, p, q, u, w))
    }

    /// True when `p`, in the triangle's plane, lies in the closed triangle.
    fn contains_coplanar(&self, p: DVec3) -> bool {
        let [a, b, c] = self.p;
        let o = self.proj;
        !mixed(&[o.orient(a, b, p), o.orient(b, c, p), o.orient(c, a, p)])
    }

    /// True when two triangles with no shared vertex meet (closed sets).
    pub(crate) fn meets(&self, other: &Tri) -> bool {
        let [a, b, c] = self.p;
        let [d, e, f] = other.p;
        let s = [orient(a, b, c, d), orient(a, b, c, e), orient(a, b, c, f)];
        if s[0] != 0 && s[0] == s[1] && s[1] == s[2] {
            return false;
        }
        if s == [0, 0, 0] {
            // Coplanar: crossing edges, or one inside the other.
            return self.contains_coplanar(d)
                || other.contains_coplanar(a)
                || edges(self.p).iter().any(|&(u, w)| {
                    edges(other.p)
                        .iter()
                        .any(|&(x, y)| segments_meet(self.proj, u, w, x, y))
                });
        }
        let t = [orient(d, e, f, a), orient(d, e, f, b), orient(d, e, f, c)];
        if t[0] != 0 && t[0] == t[1] && t[1] == t[2] {
            return false;
        }
        edges(self.p)
            .iter()
            .any(|&(u, w)| other.meets_segment(u, w))
            || edges(other.p)
                .iter()
                .any(|&(u, w)| self.meets_segment(u, w))
    }
}

/// The three edges of a triangle.
fn edges([a, b, c]: [DVec3; 3]) -> [(DVec3, DVec3); 3] {
    [(a, b), (b, c), (c, a)]
}

/// True when the closed segments `[p, q]` and `[r, s]`, all four points in one plane that `proj`
/// keeps non-degenerate, meet.
fn segments_meet(proj: Projection, p: DVec3, q: DVec3, r: DVec3, s: DVec3) -> bool {
    let (d1, d2) = (proj.orient(r, s, p), proj.orient(r, s, q));
    let (d3, d4) = (proj.orient(p, q, r), proj.orient(p, q, s));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    (d1 == 0 && proj.within(p, r, s))
        || (d2 == 0 && proj.within(q, r, s))
        || (d3 == 0 && proj.within(r, p, q))
        || (d4 == 0 && proj.within(s, p, q))
}

/// True when mesh triangles `i` and `j` (vertex indices `ti`, `tj`, each with distinct indices)
/// meet beyond the vertices they share; see the [module docs](self). Floating-point separation
/// tests ([`filter`](super::filter)) settle most pairs first.
pub(crate) fn meet_beyond_shared(ti: [u32; 3], i: &Tri, tj: [u32; 3], j: &Tri) -> bool {
    decide(ti, i, tj, j, true)
}

/// [`meet_beyond_shared`] by exact predicates alone (the reference the filters are tested
/// against).
#[cfg(test)]
pub(crate) fn meet_beyond_shared_exact(ti: [u32; 3], i: &Tri, tj: [u32; 3], j: &Tri) -> bool {
    decide(ti, i, tj, j, false)
}

/// The decision, with or without the floating-point filters.
fn decide(ti: [u32; 3], i: &Tri, tj: [u32; 3], j: &Tri, filter: bool) -> bool {
    // Bit `3·a + b` set when corner `a` of `ti` is corner `b` of `tj` (the indices are
    // distinct within each, so each row and column has at most one bit).
    let row =
        |v: u32| u32::from(v == tj[0]) | u32::from(v == tj[1]) << 1 | u32::from(v == tj[2]) << 2;
    let shared = row(ti[0]) | row(ti[1]) << 3 | row(ti[2]) << 6;
    match shared.count_ones() {
        0 => !(filter && filter::separated(i.p, j.p)) && i.meets(j),
        1 => {
            // The shared vertex and the corners other than it, in each triangle.
            let bit = shared.trailing_zeros() as usize;
            let (ki, kj) = (bit / 3, bit % 3);
            let (a, b) = (i.p[(ki + 1) % 3], i.p[(ki + 2) % 3]);
            let (c, d) = (j.p[(kj + 1) % 3], j.p[(kj + 2) % 3]);
            if filter && filter::separated_at_vertex(i.p[ki], [a, b], [c, d]) {
                return false;
            }
            meet_at_vertex(i.p[ki], i, [a, b], j, [c, d])
        }
        2 => {
            // The corner of each that is not shared: the empty row, the empty column.
            let ki = (0..3)
                .find(|&a| shared >> (3 * a) & 0b111 == 0)
                .unwrap_or(0);
            let kj = (0..3)
                .find(|&b| shared >> b & 0b1_001_001 == 0)
                .unwrap_or(0);
            let (u, w) = (i.p[(ki + 1) % 3], i.p[(ki + 2) % 3]);
            let (a, b) = (i.p[ki], j.p[kj]);
            if filter && filter::apart_across_edge(u, w, a, b) {
                return false;
            }
            orient(u, w, a, b) == 0 && i.proj.orient(u, w, a) == i.proj.orient(u, w, b)
        }
        _ => true,
    }
}

/// Triangles `i = v a b` and `j = v c d` meet beyond `v` when `ab` meets `j` or `cd` meets `i`.
/// When `a` and `b` both lie in `j`'s plane the triangles are coplanar: see [`sectors_meet`].
fn meet_at_vertex(v: DVec3, i: &Tri, [a, b]: [DVec3; 2], j: &Tri, [c, d]: [DVec3; 2]) -> bool {
    let [p, q, r] = j.p;
    let (sa, sb) = (orient(p, q, r, a), orient(p, q, r, b));
    if sa == 0 && sb == 0 {
        return sectors_meet(i.proj, v, [a, b], [c, d]);
    }
    let ab_meets_j = sa != sb || sa == 0;
    (ab_meets_j && j.meets_segment(a, b)) || i.meets_segment(c, d)
}

/// Coplanar triangles `v a b` and `v c d` meet beyond their one shared vertex `v` exactly when
/// their angular sectors at `v` share a ray: near `v` each triangle is its sector, and a common
/// point `p ≠ v` puts the whole segment `vp` (convexity) in both. Two convex sectors share a ray
/// exactly when a boundary ray of one lies in the other, so four ray tests of two exact 2D
/// orientations each decide it (`proj` keeps the plane non-degenerate, so signs are faithful).
fn sectors_meet(proj: Projection, v: DVec3, [a, b]: [DVec3; 2], [c, d]: [DVec3; 2]) -> bool {
    // The closed sector from ray `vx` to ray `vy` (less than a half-turn, as in a triangle)
    // holds ray `vr` when `r` is on the inner side of both bounding lines.
    let holds = |x: DVec3, y: DVec3, r: DVec3| {
        let o = proj.orient(v, x, y);
        proj.orient(v, x, r) * o >= 0 && proj.orient(v, r, y) * o >= 0
    };
    holds(a, b, c) || holds(a, b, d) || holds(c, d, a) || holds(c, d, b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (SplitMix64) of lattice coordinates.
    struct Rng(u64);

    impl Rng {
        fn below(&mut self, n: i64) -> i64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) % n as u64) as i64
        }
    }

    /// The sector test agrees with the segment tests it replaced (an edge of each triangle
    /// against the other), on coplanar pairs sharing one vertex drawn from a small lattice in an
    /// axis plane and in a tilted plane, where collinear rays and exact zeros are common.
    #[test]
    fn sectors_agree_with_the_segment_tests_on_lattice_fans() {
        let mut rng = Rng(7);
        let planes: [fn(i64, i64) -> DVec3; 2] = [
            |x, y| DVec3::new(x as f64, y as f64, 0.0),
            |x, y| DVec3::new(x as f64, y as f64, -(x + y) as f64),
        ];
        let (mut meeting, mut apart) = (0, 0);
        for plane in planes {
            for _ in 0..20_000 {
                let mut p = || plane(rng.below(5) - 2, rng.below(5) - 2);
                let (v, a, b, c, d) = (p(), p(), p(), p(), p());
                let (Some(i), Some(j)) = (Tri::new([v, a, b]), Tri::new([v, c, d])) else {
                    continue;
                };
                if [a, b].iter().any(|x| *x == c || *x == d) {
                    continue; // more than one shared vertex
                }
                let old = j.meets_coplanar_segment(a, b) || i.meets_coplanar_segment(c, d);
                let new = sectors_meet(i.proj, v, [a, b], [c, d]);
                assert_eq!(old, new, "v {v} a {a} b {b} c {c} d {d}");
                if new {
                    meeting += 1;
                } else {
                    apart += 1;
                }
            }
        }
        assert!(meeting > 1000 && apart > 1000, "{meeting} {apart}");
    }
}
