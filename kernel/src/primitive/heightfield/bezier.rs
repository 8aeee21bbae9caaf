//! Height from a tensor-product Bézier patch of any degrees over `[0, 1]²` (lecture notes 001):
//! `h(u, v) = Σ_i Σ_j z_ij B_i^m(u) B_j^n(v)` with the control heights of a [`HeightGrid`]
//! (`m = nx − 1`, `n = ny − 1`), its derivatives from the differenced control net, and bounds from
//! the convex-hull property: `h`, `m Δ_u z`, `m(m − 1) Δ²_u z`, `mn Δ_u Δ_v z`… each lie between the
//! extremes of their coefficients.

use super::grid::HeightGrid;
use super::param::{ParamBounds, ParamDerivatives};
use crate::patch::bernstein::tensor_sum;

/// `h(u, v)`.
#[inline]
pub(super) fn height(g: &HeightGrid, u: f64, v: f64) -> f64 {
    tensor_sum(g.nx() - 1, g.ny() - 1, u, v, |i, j| g.get(i, j))
}

/// `h` and its derivatives in `(u, v)`; second derivatives only when `second` is set.
pub(super) fn derivatives(g: &HeightGrid, u: f64, v: f64, second: bool) -> ParamDerivatives {
    let (m, n) = (g.nx() - 1, g.ny() - 1);
    let (mf, nf) = (m as f64, n as f64);
    let mut d = ParamDerivatives {
        h: height(g, u, v),
        hu: mf * tensor_sum(m - 1, n, u, v, |i, j| g.get(i + 1, j) - g.get(i, j)),
        hv: nf * tensor_sum(m, n - 1, u, v, |i, j| g.get(i, j + 1) - g.get(i, j)),
        ..Default::default()
    };
    if second {
        if m >= 2 {
            d.huu = mf * (mf - 1.0) * tensor_sum(m - 2, n, u, v, |i, j| second_u(g, i, j));
        }
        if n >= 2 {
            d.hvv = nf * (nf - 1.0) * tensor_sum(m, n - 2, u, v, |i, j| second_v(g, i, j));
        }
        d.huv = mf * nf * tensor_sum(m - 1, n - 1, u, v, |i, j| twist(g, i, j));
    }
    d
}

fn second_u(g: &HeightGrid, i: usize, j: usize) -> f64 {
    g.get(i + 2, j) - 2.0 * g.get(i + 1, j) + g.get(i, j)
}

fn second_v(g: &HeightGrid, i: usize, j: usize) -> f64 {
    g.get(i, j + 2) - 2.0 * g.get(i, j + 1) + g.get(i, j)
}

fn twist(g: &HeightGrid, i: usize, j: usize) -> f64 {
    g.get(i + 1, j + 1) - g.get(i + 1, j) - g.get(i, j + 1) + g.get(i, j)
}

/// Bounds of `h` and its derivatives over the whole patch (convex hull of each differenced net).
pub(super) fn bounds(g: &HeightGrid) -> ParamBounds {
    let (m, n) = (g.nx() - 1, g.ny() - 1);
    let (mf, nf) = (m as f64, n as f64);
    let (lo, hi) = g.range();
    let (su, sv) = g.max_steps();
    let (mut suu, mut svv, mut suv) = (0.0f64, 0.0f64, 0.0f64);
    for j in 0..=n {
        for i in 0..=m {
            if i + 2 <= m {
                suu = suu.max(second_u(g, i, j).abs());
            }
            if j + 2 <= n {
                svv = svv.max(second_v(g, i, j).abs());
            }
            if i < m && j < n {
                suv = suv.max(twist(g, i, j).abs());
            }
        }
    }
    ParamBounds {
        lo,
        hi,
        hu: mf * su,
        hv: nf * sv,
        second: Some((mf * (mf - 1.0) * suu, mf * nf * suv, nf * (nf - 1.0) * svv)),
    }
}
