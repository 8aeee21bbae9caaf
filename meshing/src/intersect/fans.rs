//! Vertices whose star is certified embedded, so that the pair search can pass every pair of
//! triangles sharing such a vertex without testing it.
//!
//! A vertex `v` qualifies when, under one coordinate projection (exact 2D orientations,
//! [`Projection::orient`]):
//! 1. its star is one closed fan: every neighbour is the next vertex of exactly one triangle and
//!    the previous vertex of exactly one (at least three triangles, at most [`MAX_FAN`]);
//! 2. every triangle `v b a` of the star keeps its orientation, strictly, in the projection: its
//!    projected angular sector at `v` turns counter-clockwise (for the projection's sign) from
//!    `b` to `a` by more than 0 and less than π;
//! 3. the sectors wind around `v` exactly once: their turns add up to one full turn (in a
//!    pseudo-angle whose rounding can only add turns, see [`pseudo_angle`]).
//!
//! Then the projected sectors tile the turn around `v` without overlap, consecutive ones sharing
//! only the ray to their common neighbour, and no two neighbours lie on one ray. Each triangle
//! projects one-to-one (2), so a point common to two triangles of the star projects into both
//! sectors: onto the ray of their shared edge, where it is that edge's point, or onto `v` itself.
//! So two triangles sharing `v` meet exactly in what they share, which is what the exact pair test
//! would answer, and the count stays that of the pairwise definition. Pairs sharing an edge are
//! in the stars of both ends, so one certified end suffices.
//!
//! Repeated triangles, degenerate (collinear) ones and open or pinched fans fail (1) or (2), and
//! are tested as before. The test is exact; the projection only decides how often it succeeds,
//! and drops the axis of the star's summed normal.

use glam::DVec3;
use rayon::prelude::*;

use super::predicates::Projection;
use crate::stars::Stars;

/// Largest star the certificate examines (larger ones are tested pair by pair).
const MAX_FAN: usize = 32;

/// The certified vertices, one bit each.
#[derive(Debug, Clone)]
pub(crate) struct Embedded(Vec<u64>);

impl Embedded {
    /// The certified vertices of `stars` over `positions` (finite).
    pub(crate) fn of(stars: &Stars, positions: &[DVec3]) -> Self {
        let n = stars.vertex_count();
        let words = (0..n.div_ceil(64))
            .into_par_iter()
            .with_min_len(64)
            .map(|w| {
                (w * 64..(w * 64 + 64).min(n)).fold(0u64, |bits, v| {
                    let ok = embedded(positions[v], stars.of(v), positions);
                    bits | u64::from(ok) << (v % 64)
                })
            })
            .collect();
        Self(words)
    }

    /// True when `v` is certified.
    #[inline]
    pub(crate) fn contains(&self, v: u32) -> bool {
        let v = v as usize;
        self.0.get(v / 64).is_some_and(|w| w >> (v % 64) & 1 == 1)
    }

    /// True when some vertex of the triangle `t` (vertex indices) is certified.
    #[inline]
    pub(crate) fn touches(&self, t: [u32; 3]) -> bool {
        t.iter().any(|&v| self.contains(v))
    }

    /// True when the triangles `a` and `b` (vertex indices) share a certified vertex.
    #[inline]
    pub(crate) fn share_one(&self, a: [u32; 3], b: [u32; 3]) -> bool {
        a.iter()
            .any(|&v| (v == b[0] || v == b[1] || v == b[2]) && self.contains(v))
    }
}

/// True when the star of the vertex at `pv` (`[next, previous]` per triangle) is certified (see
/// the module docs).
fn embedded(pv: DVec3, star: &[[u32; 2]], positions: &[DVec3]) -> bool {
    if !(3..=MAX_FAN).contains(&star.len()) {
        return false;
    }
    // (1) One closed fan: each next vertex is exactly one triangle's next and one's previous;
    // with as many nexts as previouses, the previouses are then the nexts again, so the links
    // form cycles, and (3) leaves room for one.
    let balanced = star.iter().all(|&[b, _]| {
        star.iter().filter(|l| l[0] == b).count() == 1
            && star.iter().filter(|l| l[1] == b).count() == 1
    });
    if !balanced {
        return false;
    }
    let at = |i: u32| positions[i as usize];
    let normal: DVec3 = star
        .iter()
        .map(|&[b, a]| (at(b) - pv).cross(at(a) - pv))
        .sum();
    let axis = normal.abs().max_position();
    let proj = Projection::dropping(axis);
    let sign: i8 = if normal[axis] < 0.0 { -1 } else { 1 };
    // (2) Every sector turns the same way, strictly.
    if !star
        .iter()
        .all(|&[b, a]| proj.orient(pv, at(b), at(a)) == sign)
    {
        return false;
    }
    // (3) The turns of the sectors, in pseudo-angle (see [`pseudo_angle`]), add up to one
    // full turn.
    let [i, j] = proj.axes();
    let turn = |p: DVec3| pseudo_angle(sign, p[i] - pv[i], p[j] - pv[j]);
    let total: f64 = star
        .iter()
        .map(|&[b, a]| (turn(at(a)) - turn(at(b))).rem_euclid(4.0))
        .sum();
    total < 6.0
}

/// A pseudo-angle of the direction `(x, y)` (not zero) in `[0, 4)`: increasing with the angle,
/// counter-clockwise for `sign` 1, clockwise for -1, a quarter turn per unit, opposite
/// directions 2 apart. The sectors of (2) turn by less than π each, so in exact arithmetic their
/// pseudo-angle turns (differences taken modulo 4) are each below 2 and add up to 4 per winding.
/// Rounding moves each turn by far less than a unit, except that a turn close to 0 may wrap to
/// close to 4, which only adds; so a computed total below 6 proves a single winding.
fn pseudo_angle(sign: i8, x: f64, y: f64) -> f64 {
    let y = y * f64::from(sign);
    let t = y / (x.abs() + y.abs());
    if x >= 0.0 {
        if t >= 0.0 { t } else { 4.0 + t }
    } else {
        2.0 - t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::pair_meets;
    use crate::intersect::tests_reference::Lcg;

    /// A fan of `k` triangles around the origin: neighbours at the given angles and heights.
    fn fan(angles: &[f64], heights: &[f64]) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let mut positions = vec![DVec3::ZERO];
        positions.extend(
            angles
                .iter()
                .zip(heights)
                .map(|(&t, &h)| DVec3::new(t.cos(), t.sin(), h)),
        );
        let k = angles.len() as u32;
        let tris = (0..k).map(|i| [0, 1 + i, 1 + (i + 1) % k]).collect();
        (positions, tris)
    }

    fn certified(positions: &[DVec3], tris: &[[u32; 3]]) -> bool {
        let stars = Stars::build(tris, positions.len());
        Embedded::of(&stars, positions).contains(0)
    }

    #[test]
    fn a_flat_and_a_bumpy_fan_are_certified() {
        let angles: Vec<f64> = (0..6)
            .map(|i| f64::from(i) * std::f64::consts::TAU / 6.0)
            .collect();
        let (p, t) = fan(&angles, &[0.0; 6]);
        assert!(certified(&p, &t));
        let (p, t) = fan(&angles, &[0.3, -0.8, 2.0, 0.1, -1.5, 0.7]);
        assert!(certified(&p, &t));
        // Reversed winding: the projection's sign follows the normal.
        let reversed: Vec<[u32; 3]> = t.iter().map(|&[a, b, c]| [a, c, b]).collect();
        assert!(certified(&p, &reversed));
    }

    #[test]
    fn folded_open_repeated_and_double_fans_are_not() {
        let angles: Vec<f64> = (0..6)
            .map(|i| f64::from(i) * std::f64::consts::TAU / 6.0)
            .collect();
        // One neighbour pulled back across its predecessor: a fold.
        let mut folded = angles.clone();
        folded[2] = 0.5;
        let (p, t) = fan(&folded, &[0.0; 6]);
        assert!(!certified(&p, &t));
        // Open: one triangle removed.
        let (p, mut t) = fan(&angles, &[0.0; 6]);
        t.pop();
        assert!(!certified(&p, &t));
        // A repeated triangle.
        let (p, mut t) = fan(&angles, &[0.0; 6]);
        t.push(t[0]);
        assert!(!certified(&p, &t));
        // Winding twice: six neighbours at multiples of 4π/6.
        let twice: Vec<f64> = (0..6)
            .map(|i| f64::from(i) * 2.0 * std::f64::consts::TAU / 6.0)
            .collect();
        let (p, t) = fan(&twice, &[0.0; 6]);
        assert!(!certified(&p, &t));
        // A degenerate (collinear) triangle.
        let (mut p, t) = fan(&angles, &[0.0; 6]);
        p[2] = p[1] * 2.0;
        assert!(!certified(&p, &t));
        // Two cones pinched at the vertex.
        let (mut p, mut t) = fan(&angles[..3], &[1.0; 3]);
        let (q, u) = fan(&angles[..3], &[-1.0; 3]);
        let base = p.len() as u32 - 1;
        p.extend(&q[1..]);
        t.extend(u.iter().map(|&[a, b, c]| [a, b + base, c + base]));
        assert!(!certified(&p, &t));
    }

    /// The search's agreement with the reference (`tests_reference.rs`) covers the certificate
    /// only where it is given: on a tessellated sphere it is, at all but the poles' wide fans.
    #[test]
    fn a_tessellated_sphere_is_certified_but_at_its_poles() {
        let t = solidkit_kernel::tessellate::sphere(1.0, 48, 25)
            .unwrap()
            .mesh;
        let stars = Stars::build(&t.triangles, t.positions.len());
        let embedded = Embedded::of(&stars, &t.positions);
        let given = (0..t.positions.len() as u32)
            .filter(|&v| embedded.contains(v))
            .count();
        assert!(
            given + 2 >= t.positions.len(),
            "{given} of {}",
            t.positions.len()
        );
    }

    /// Random fans, some folded, some winding twice, some steep, some on an `f32` lattice with coplanar triangles:
    /// whenever the centre is certified, no two of its triangles meet beyond what they share by
    /// the exact pair test; and the certificate is given often enough to matter.
    #[test]
    fn certified_fans_never_hold_a_meeting_pair() {
        let mut rng = Lcg(7);
        let (mut given, mut meeting) = (0, 0);
        for round in 0..20_000 {
            let k = 3 + (rng.unit() * 9.0) as usize;
            let mut angles: Vec<f64> = (0..k)
                .map(|i| (i as f64 + 0.9 * rng.unit()) * std::f64::consts::TAU / k as f64)
                .collect();
            if round % 11 == 0 {
                // Around twice.
                angles.iter_mut().for_each(|t| *t *= 2.0);
            } else if round % 3 == 0 {
                let i = (rng.unit() * k as f64) as usize;
                angles[i] += (rng.unit() - 0.5) * 3.0;
            }
            let steep = if round % 5 == 0 { 30.0 } else { 1.0 };
            let mut heights: Vec<f64> = (0..k).map(|_| (rng.unit() - 0.5) * steep).collect();
            if round % 7 == 0 {
                heights.iter_mut().for_each(|h| *h = 0.0);
            }
            let (mut p, t) = fan(&angles, &heights);
            if round % 4 == 0 {
                // Coarse lattice: exact coplanarities and near-collinear corners.
                p.iter_mut().for_each(|x| *x = (*x * 4.0).round() / 4.0);
            }
            let all_apart = t.iter().enumerate().all(|(i, &a)| {
                t[i + 1..].iter().all(|&b| {
                    let corners = |x: [u32; 3]| x.map(|v| p[v as usize]);
                    !pair_meets(a, corners(a), b, corners(b))
                })
            });
            meeting += usize::from(!all_apart);
            if certified(&p, &t) {
                given += 1;
                assert!(
                    all_apart,
                    "round {round}: a certified fan holds a meeting pair"
                );
            }
        }
        assert!(
            given > 5_000 && meeting > 1_000,
            "given {given}, meeting {meeting}"
        );
    }
}
