//! Tensor-product B-spline and NURBS surfaces (a Bézier patch is the B-spline with knots
//! `{0,…,0, 1,…,1}`): `S(u, v) = Σ N_i(u) M_j(v) w_ij P_ij / Σ N_i(u) M_j(v) w_ij`, evaluated with
//! its first and second derivatives (the quotient rule on the homogeneous sums), over the unit
//! square mapped onto the knot domain `[u_p, u_{n}] × [v_q, v_{m}]`.

use super::basis::{basis_derivatives, find_span};
use super::derivs::SurfaceDerivatives;
use super::error::SurfaceError;
use glam::DVec3;

/// Largest number of control points of one net.
pub const MAX_CONTROL_POINTS: usize = 1 << 16;

/// Largest degree in either direction.
pub const MAX_DEGREE: usize = 15;

/// A B-spline or NURBS surface; control point `P_ij` (`i` along `u`) is stored at `j n_u + i`.
#[derive(Debug, Clone, PartialEq)]
pub struct TensorSurface {
    degrees: [usize; 2],
    counts: [usize; 2],
    points: Vec<DVec3>,
    weights: Option<Vec<f64>>,
    knots: [Vec<f64>; 2],
}

/// Clamped uniform knots for `count` points of degree `p`: `p + 1` zeros, interior `1..`, `p + 1`
/// copies of the last value, normalised to `[0, 1]`.
pub fn clamped_knots(p: usize, count: usize) -> Vec<f64> {
    let inner = count - p; // number of spans
    let mut k = vec![0.0; p + 1];
    k.extend((1..inner).map(|i| i as f64 / inner as f64));
    k.extend(std::iter::repeat_n(1.0, p + 1));
    k
}

impl TensorSurface {
    /// A surface of degrees `(p, q)` with `counts = (n_u, n_v)` control points, optional weights
    /// (positive) and knot vectors (`n_u + p + 1` and `n_v + q + 1` non-decreasing values with a
    /// non-empty domain).
    pub fn new(
        degrees: [usize; 2],
        counts: [usize; 2],
        points: Vec<DVec3>,
        weights: Option<Vec<f64>>,
        knots: [Vec<f64>; 2],
    ) -> Result<Self, SurfaceError> {
        for d in 0..2 {
            let what = ["u", "v"][d];
            if degrees[d] == 0 || degrees[d] > MAX_DEGREE {
                return Err(SurfaceError::invalid(
                    "degree",
                    format!("{what} degree must be 1 to {MAX_DEGREE}"),
                ));
            }
            if counts[d] < degrees[d] + 1 {
                return Err(SurfaceError::invalid(
                    "points",
                    format!(
                        "degree {} needs at least {} control points along {what}, got {}",
                        degrees[d],
                        degrees[d] + 1,
                        counts[d]
                    ),
                ));
            }
        }
        let total = counts[0].saturating_mul(counts[1]);
        if total > MAX_CONTROL_POINTS || points.len() != total {
            return Err(SurfaceError::invalid(
                "points",
                format!(
                    "expected {} × {} control points (at most {MAX_CONTROL_POINTS}), got {}",
                    counts[0],
                    counts[1],
                    points.len()
                ),
            ));
        }
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(SurfaceError::invalid(
                "points",
                format!("control point {i} is not finite"),
            ));
        }
        if let Some(w) = &weights {
            if w.len() != total {
                return Err(SurfaceError::invalid(
                    "weights",
                    format!("expected {total} weights, got {}", w.len()),
                ));
            }
            if let Some(i) = w.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
                return Err(SurfaceError::invalid(
                    "weights",
                    format!("weight {i} is not a positive finite number"),
                ));
            }
        }
        for d in 0..2 {
            let key = ["knots_u", "knots_v"][d];
            let k = &knots[d];
            let (p, n) = (degrees[d], counts[d]);
            if k.len() != n + p + 1 {
                return Err(SurfaceError::invalid(
                    key,
                    format!("expected {} knots, got {}", n + p + 1, k.len()),
                ));
            }
            if k.iter().any(|x| !x.is_finite()) || k.windows(2).any(|w| w[1] < w[0]) {
                return Err(SurfaceError::invalid(
                    key,
                    "expected finite non-decreasing knots",
                ));
            }
            if k[n] <= k[p] {
                return Err(SurfaceError::invalid(key, "the knot domain is empty"));
            }
        }
        Ok(TensorSurface {
            degrees,
            counts,
            points,
            weights,
            knots,
        })
    }

    /// A Bézier patch of degrees `(n_u − 1, n_v − 1)`.
    pub fn bezier(counts: [usize; 2], points: Vec<DVec3>) -> Result<Self, SurfaceError> {
        let degrees = [counts[0].saturating_sub(1), counts[1].saturating_sub(1)];
        let knots = [0, 1].map(|d| {
            let mut k = vec![0.0; counts[d]];
            k.extend(std::iter::repeat_n(1.0, counts[d]));
            k
        });
        Self::new(degrees, counts, points, None, knots)
    }

    /// Degrees `(p, q)`.
    pub fn degrees(&self) -> [usize; 2] {
        self.degrees
    }

    /// Control point counts `(n_u, n_v)`.
    pub fn counts(&self) -> [usize; 2] {
        self.counts
    }

    /// The control points.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// The weights (NURBS), if any.
    pub fn weights(&self) -> Option<&[f64]> {
        self.weights.as_deref()
    }

    /// The knot vectors along `u` and `v`.
    pub fn knots(&self) -> &[Vec<f64>; 2] {
        &self.knots
    }

    /// The knot domain along direction `d`.
    fn domain(&self, d: usize) -> (f64, f64) {
        (
            self.knots[d][self.degrees[d]],
            self.knots[d][self.counts[d]],
        )
    }

    /// `S` and its derivatives at `(s, t)` of the unit square (clamped into it), derivatives
    /// taken with respect to `s` and `t`.
    pub fn derivatives(&self, s: f64, t: f64) -> SurfaceDerivatives {
        let (ua, ub) = self.domain(0);
        let (va, vb) = self.domain(1);
        let u = ua + s.clamp(0.0, 1.0) * (ub - ua);
        let v = va + t.clamp(0.0, 1.0) * (vb - va);
        let [p, q] = self.degrees;
        let [nu, nv] = self.counts;
        let su = find_span(p, nu, &self.knots[0], u);
        let sv = find_span(q, nv, &self.knots[1], v);
        let bu = basis_derivatives(p, su, &self.knots[0], u);
        let bv = basis_derivatives(q, sv, &self.knots[1], v);
        // Homogeneous sums A_{kl} = ∂^{k+l}/∂u^k∂v^l Σ N M w P and W_{kl} likewise.
        let mut a = [[DVec3::ZERO; 3]; 3];
        let mut w = [[0.0; 3]; 3];
        for (r, i) in (su - p..=su).enumerate() {
            for (c, j) in (sv - q..=sv).enumerate() {
                let idx = j * nu + i;
                let wt = self.weights.as_ref().map_or(1.0, |w| w[idx]);
                let pw = self.points[idx] * wt;
                for k in 0..3 {
                    for l in 0..3 - k {
                        let b = bu[k][r] * bv[l][c];
                        a[k][l] += pw * b;
                        w[k][l] += wt * b;
                    }
                }
            }
        }
        let w0 = w[0][0];
        let s0 = a[0][0] / w0;
        let su_ = (a[1][0] - s0 * w[1][0]) / w0;
        let sv_ = (a[0][1] - s0 * w[0][1]) / w0;
        let suu = (a[2][0] - 2.0 * su_ * w[1][0] - s0 * w[2][0]) / w0;
        let suv = (a[1][1] - su_ * w[0][1] - sv_ * w[1][0] - s0 * w[1][1]) / w0;
        let svv = (a[0][2] - 2.0 * sv_ * w[0][1] - s0 * w[0][2]) / w0;
        SurfaceDerivatives {
            p: s0,
            pu: su_,
            pv: sv_,
            puu: suu,
            puv: suv,
            pvv: svv,
        }
        .rescaled(ub - ua, vb - va)
    }

    /// Bounds `(M_uu, M_uv, M_vv)` of `|∂²S/∂s²|`, `|∂²S/∂s∂t|`, `|∂²S/∂t²|` over the unit square
    /// for a non-rational surface: the largest control point of each derivative's own B-spline
    /// net (convex hull property). `None` for NURBS.
    pub fn second_derivative_bounds(&self) -> Option<[f64; 3]> {
        Some([
            self.derivative_bound(2, 0)?,
            self.derivative_bound(1, 1)?,
            self.derivative_bound(0, 2)?,
        ])
    }

    /// A bound of `|∂^(du+dv) S / ∂s^du ∂t^dv|` over the unit square for a non-rational surface:
    /// the largest control point of that derivative's own B-spline net (convex hull property).
    /// `None` for NURBS.
    pub fn derivative_bound(&self, du: usize, dv: usize) -> Option<f64> {
        if self.weights.is_some() {
            return None;
        }
        let net = |du: usize, dv: usize| {
            let mut pts = self.points.clone();
            let mut counts = self.counts;
            let mut knots = self.knots.clone();
            let mut degrees = self.degrees;
            for (dir, times) in [(0, du), (1, dv)] {
                for _ in 0..times {
                    (pts, counts) = difference(&pts, counts, dir, degrees[dir], &knots[dir]);
                    knots[dir] = knots[dir][1..knots[dir].len() - 1].to_vec();
                    degrees[dir] = degrees[dir].saturating_sub(1);
                }
            }
            let (ua, ub) = self.domain(0);
            let (va, vb) = self.domain(1);
            let scale = (ub - ua).powi(du as i32) * (vb - va).powi(dv as i32);
            pts.iter().map(|p| p.length()).fold(0.0, f64::max) * scale
        };
        Some(net(du, dv))
    }
}

/// The control net of the derivative along `dir` of a B-spline net of degree `p`:
/// `Q_i = p (P_{i+1} − P_i) / (t_{i+p+1} − t_{i+1})` (0 over a repeated knot).
fn difference(
    pts: &[DVec3],
    counts: [usize; 2],
    dir: usize,
    p: usize,
    knots: &[f64],
) -> (Vec<DVec3>, [usize; 2]) {
    let mut out_counts = counts;
    out_counts[dir] = counts[dir].saturating_sub(1);
    if p == 0 || out_counts[dir] == 0 {
        out_counts[dir] = 1;
        return (vec![DVec3::ZERO; out_counts[0] * out_counts[1]], out_counts);
    }
    let mut out = Vec::with_capacity(out_counts[0] * out_counts[1]);
    for j in 0..out_counts[1] {
        for i in 0..out_counts[0] {
            let k = if dir == 0 { i } else { j };
            let (a, b) = if dir == 0 {
                (pts[j * counts[0] + i], pts[j * counts[0] + i + 1])
            } else {
                (pts[j * counts[0] + i], pts[(j + 1) * counts[0] + i])
            };
            let span = knots[k + p + 1] - knots[k + 1];
            out.push(if span > 0.0 {
                (b - a) * (p as f64 / span)
            } else {
                DVec3::ZERO
            });
        }
    }
    (out, out_counts)
}
