//! Height from a tensor-product Bézier patch of any degrees over `[0, 1]²` (lecture notes 001):
//! `h(u, v) = Σ_i Σ_j z_ij B_i^m(u) B_j^n(v)` with the control heights of a [`HeightGrid`]
//! (`m = nx − 1`, `n = ny − 1`), its derivatives from the differenced control net, and bounds from
//! the convex-hull property: `h`, `m Δ_u z`, `m(m − 1) Δ²_u z`, `mn Δ_u Δ_v z`… each lie between the
//! extremes of their coefficients.
//!
//! Cost (issue 15): a value takes `nx · ny` multiply-adds, every control height counting at every
//! point, so nets above [`MAX_CONTROL_HEIGHTS`] are refused when the height field is built (a
//! 2000 × 2000 net ran for minutes; a 64 × 64 one took 21 s at resolution 128; beyond degree
//! about 1000 the binomial weights overflow double precision anyway). Culling cannot help: a
//! single patch of high degree has no local support. Values weigh the columns once per point
//! and sweep the rows without divisions, in the same operations as
//! [`tensor_sum`](crate::patch::bernstein::tensor_sum), so the results are the same bits.

use super::grid::HeightGrid;
use super::param::{ParamBounds, ParamDerivatives};
use crate::patch::bernstein::{bezier_sum, tensor_sum};
use std::cell::RefCell;

/// The most control heights a Bézier height field may have (a 64 × 64 net, degree 63 both ways),
/// the multiply-adds of one evaluation: such a net meshes in about 3 s at the default resolution.
pub const MAX_CONTROL_HEIGHTS: usize = 1 << 12;

thread_local! {
    /// The column weights of the current point.
    static WEIGHTS: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
}

/// `h(u, v)`: [`tensor_sum`] of the control heights, with the weights `C(m, i) uⁱ` computed once
/// for all rows (the same operations, so the same result).
#[inline]
pub(super) fn height(g: &HeightGrid, u: f64, v: f64) -> f64 {
    let (m, n) = (g.nx() - 1, g.ny() - 1);
    let nx = g.nx();
    let values = g.values();
    let rows = |w: &mut Vec<f64>| {
        // bezier_sum's recurrence: binom · tⁿ for 1 ≤ i < m, then tⁿ⁻¹ · t for i = m.
        w.clear();
        w.resize(m + 1, 0.0);
        let (mut binom, mut tn) = (1.0, 1.0);
        for (i, wi) in w.iter_mut().enumerate().take(m).skip(1) {
            binom = binom * (m - i + 1) as f64 / i as f64;
            tn *= u;
            *wi = binom * tn;
        }
        w[m] = tn * u;
        let s = 1.0 - u;
        bezier_sum(n, v, |j| {
            let row = &values[j * nx..(j + 1) * nx];
            let mut acc = row[0] * s;
            for i in 1..m {
                acc = (acc + row[i] * w[i]) * s;
            }
            acc + row[m] * w[m]
        })
    };
    WEIGHTS.with(|cell| match cell.try_borrow_mut() {
        Ok(mut w) => rows(&mut w),
        Err(_) => rows(&mut Vec::new()),
    })
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
