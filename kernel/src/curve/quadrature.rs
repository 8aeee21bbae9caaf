//! Gauss–Legendre quadrature (nodes by Newton's method on the Legendre polynomial), used for
//! areas and lengths of curves: exact for polynomials of degree `2n − 1`, exponentially
//! convergent for the smooth rational integrands of nearly straight NURBS spans.

/// Nodes and weights of the `n`-point rule on `[−1, 1]`.
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut rule = Vec::with_capacity(n);
    for i in 0..n {
        // Initial guess (Tricomi), then Newton on Pₙ.
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let k = k as f64;
                let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            let pn = if n == 0 { 1.0 } else { p1 };
            let pn1 = if n == 0 { 0.0 } else { p0 };
            derivative = n as f64 * (x * pn - pn1) / (x * x - 1.0);
            let step = pn / derivative;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        rule.push((x, 2.0 / ((1.0 - x * x) * derivative * derivative)));
    }
    rule
}

/// `∫ₐᵇ f` by the rule `rule` (from [`gauss_legendre`]).
pub fn integrate(rule: &[(f64, f64)], a: f64, b: f64, mut f: impl FnMut(f64) -> f64) -> f64 {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    rule.iter()
        .map(|&(x, w)| w * f(mid + half * x))
        .sum::<f64>()
        * half
}
