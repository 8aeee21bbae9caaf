//! Bounds of a Bézier patch's second derivatives over a rectangle of its unit square: the
//! control net of the sub-patch over the rectangle (de Casteljau along each direction), whose
//! differenced nets bound the derivatives by the convex hull property. The bounds tighten with
//! the rectangle (the sub-net converges to the surface), which is what lets the adaptive
//! tessellation leave flat regions coarse.

use glam::{DVec2, DVec3};

/// `(M_ss, M_st, M_tt)` over `lo..hi` for the Bézier net `points` (`counts = (n_s, n_t)`, point
/// `(i, j)` at `j n_s + i`), derivatives with respect to the unit square's `s`, `t`.
pub(super) fn second_bounds(
    counts: [usize; 2],
    points: &[DVec3],
    lo: DVec2,
    hi: DVec2,
) -> [f64; 3] {
    let [ns, nt] = counts;
    let mut net = points.to_vec();
    // Along s within every row, then along t within every column.
    let mut row = Vec::with_capacity(ns.max(nt));
    for j in 0..nt {
        row.clear();
        row.extend_from_slice(&net[j * ns..(j + 1) * ns]);
        restrict(&mut row, lo.x, hi.x);
        net[j * ns..(j + 1) * ns].copy_from_slice(&row);
    }
    for i in 0..ns {
        row.clear();
        row.extend((0..nt).map(|j| net[j * ns + i]));
        restrict(&mut row, lo.y, hi.y);
        for (j, p) in row.iter().enumerate() {
            net[j * ns + i] = *p;
        }
    }
    let (p, q) = (ns.saturating_sub(1) as f64, nt.saturating_sub(1) as f64);
    let at = |i: usize, j: usize| net[j * ns + i];
    let (mut ss, mut st, mut tt) = (0.0f64, 0.0f64, 0.0f64);
    for j in 0..nt {
        for i in 0..ns {
            if i + 2 < ns {
                ss = ss.max((at(i + 2, j) - 2.0 * at(i + 1, j) + at(i, j)).length());
            }
            if i + 1 < ns && j + 1 < nt {
                st = st.max((at(i + 1, j + 1) - at(i + 1, j) - at(i, j + 1) + at(i, j)).length());
            }
            if j + 2 < nt {
                tt = tt.max((at(i, j + 2) - 2.0 * at(i, j + 1) + at(i, j)).length());
            }
        }
    }
    let d = hi - lo;
    [
        p * (p - 1.0).max(0.0) * ss / (d.x * d.x),
        p * q * st / (d.x * d.y),
        q * (q - 1.0).max(0.0) * tt / (d.y * d.y),
    ]
}

/// Replaces the Bézier control polygon `c` (over `[0, 1]`) by that of its piece over `[a, b]`.
fn restrict(c: &mut [DVec3], a: f64, b: f64) {
    // The piece over [0, b] (the left points of de Casteljau at b) ...
    split_left(c, b);
    // ... then its piece over [a / b, 1] (the right points at a / b).
    if b > 0.0 && a > 0.0 {
        split_right(c, a / b);
    }
}

/// The left half's control points of de Casteljau at `t`, in place.
fn split_left(c: &mut [DVec3], t: f64) {
    let n = c.len();
    for r in 1..n {
        for k in (r..n).rev() {
            c[k] = c[k - 1].lerp(c[k], t);
        }
    }
}

/// The right half's control points of de Casteljau at `t`, in place.
fn split_right(c: &mut [DVec3], t: f64) {
    let n = c.len();
    for r in 1..n {
        for k in 0..n - r {
            c[k] = c[k].lerp(c[k + 1], t);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn restricted_pieces_reproduce_the_curve() {
        // A cubic: the piece over [0.2, 0.7] at u equals the curve at 0.2 + 0.5 u.
        let c = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(3.0, -1.0, 1.0),
            DVec3::new(4.0, 0.5, 2.0),
        ];
        let eval = |c: &[DVec3], u: f64| {
            let mut w = c.to_vec();
            split_left(&mut w, u);
            w[w.len() - 1]
        };
        let mut piece = c.to_vec();
        restrict(&mut piece, 0.2, 0.7);
        for k in 0..=10 {
            let u = k as f64 / 10.0;
            assert!(eval(&piece, u).distance(eval(&c, 0.2 + 0.5 * u)) < 1e-12);
        }
    }

    #[test]
    fn a_quadratic_has_its_exact_second_derivatives_on_any_rectangle() {
        // S(s, t) = (s, t, s² + 3 s t − t²) as a biquadratic net.
        let mut pts = Vec::new();
        for j in 0..3 {
            for i in 0..3 {
                let (s, t) = (i as f64 / 2.0, j as f64 / 2.0);
                // Bézier points of s² (0, 0, 1), s t (0, 0, 0, 0, 1/4, 1/2, 0, 1/2, 1), t².
                let s2 = [0.0, 0.0, 1.0][i];
                let t2 = [0.0, 0.0, 1.0][j];
                let st = [0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.0, 0.5, 1.0][3 * j + i];
                pts.push(DVec3::new(s, t, s2 + 3.0 * st - t2));
            }
        }
        let m = second_bounds([3, 3], &pts, DVec2::new(0.25, 0.5), DVec2::new(0.5, 0.625));
        assert!(
            (m[0] - 2.0).abs() < 1e-9 && (m[1] - 3.0).abs() < 1e-9 && (m[2] - 2.0).abs() < 1e-9,
            "{m:?}"
        );
    }
}
