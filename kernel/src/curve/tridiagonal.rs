//! Tridiagonal solvers for the interpolating spline: the Thomas algorithm and its cyclic
//! (periodic) variant by the Sherman–Morrison correction. The matrices here are strictly
//! diagonally dominant, so no pivoting is needed.

use super::casteljau::Point;

/// Solves `a[i] x[i−1] + b[i] x[i] + c[i] x[i+1] = d[i]` (`a[0]` and `c[n−1]` unused).
pub(crate) fn solve<T: Point>(a: &[f64], b: &[f64], c: &[f64], d: &[T]) -> Vec<T> {
    let n = d.len();
    let mut cp = vec![0.0; n];
    let mut x = vec![T::default(); n];
    if n == 0 {
        return x;
    }
    cp[0] = c[0] / b[0];
    x[0] = d[0] * (1.0 / b[0]);
    for i in 1..n {
        let m = b[i] - a[i] * cp[i - 1];
        cp[i] = c[i] / m;
        x[i] = (d[i] - x[i - 1] * a[i]) * (1.0 / m);
    }
    for i in (0..n - 1).rev() {
        x[i] = x[i] - x[i + 1] * cp[i];
    }
    x
}

/// Solves the cyclic system with constant rows `sub·x[i−1] + diag·x[i] + sup·x[i+1] = d[i]`,
/// indices modulo `n ≥ 3`.
pub(crate) fn solve_cyclic<T: Point>(sub: f64, diag: f64, sup: f64, d: &[T]) -> Vec<T> {
    let n = d.len();
    let gamma = -diag;
    let a = vec![sub; n];
    let c = vec![sup; n];
    let mut b = vec![diag; n];
    b[0] = diag - gamma;
    b[n - 1] = diag - sub * sup / gamma;
    let x = solve(&a, &b, &c, d);
    // The corners: `sub` at the top right (row 0), `sup` at the bottom left (row n − 1).
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = sup;
    let z = solve(&a, &b, &c, &u);
    let denominator = 1.0 + z[0] + sub * z[n - 1] / gamma;
    let fact = (x[0] + x[n - 1] * (sub / gamma)) * (1.0 / denominator);
    x.iter().zip(&z).map(|(&xi, &zi)| xi - fact * zi).collect()
}
