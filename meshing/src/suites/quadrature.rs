//! Numerical quadrature for ground truth without a closed form: composite Gauss–Legendre rules,
//! with the error estimated by comparing a rule with its refinement (panels doubled). For the
//! smooth (analytic) integrands used here the refined value is far more accurate than the
//! difference, so the difference is a safe error bound in practice; it is stated as the
//! quantity's `error_bound`.

use glam::DVec3;
use std::f64::consts::{PI, TAU};

pub use solidkit_kernel::curve::gauss_legendre;

/// `∫_a^b f` by `panels` equal panels of the `order`-point Gauss–Legendre rule.
pub fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize, order: usize) -> f64 {
    let rule = gauss_legendre(order);
    let h = (b - a) / panels as f64;
    (0..panels)
        .map(|k| {
            let x0 = a + h * k as f64;
            solidkit_kernel::curve::integrate(&rule, x0, x0 + h, &f)
        })
        .sum()
}

/// `∫∫ f(x, y)` over `[x0, x1] × [y0, y1]` by the tensor product of composite rules.
pub fn integrate2(
    f: impl Fn(f64, f64) -> f64,
    [x0, x1]: [f64; 2],
    [y0, y1]: [f64; 2],
    panels: usize,
    order: usize,
) -> f64 {
    integrate(
        |x| integrate(|y| f(x, y), y0, y1, panels, order),
        x0,
        x1,
        panels,
        order,
    )
}

/// A value and the difference from its coarser estimate.
fn refined(estimate: impl Fn(usize) -> f64, panels: usize) -> (f64, f64) {
    let coarse = estimate(panels);
    let fine = estimate(2 * panels);
    (fine, (fine - coarse).abs())
}

/// Surface area of the ellipsoid with semi-axes `radii`, and an error bound: the integral of
/// `|r_θ × r_λ| = sin θ √(b²c² sin²θ cos²λ + a²c² sin²θ sin²λ + a²b² cos²θ)` over
/// `θ ∈ [0, π]` (Gauss–Legendre) and `λ ∈ [0, 2π]` (trapezoid rule, spectrally accurate for a
/// smooth periodic integrand).
pub fn ellipsoid_area(radii: DVec3) -> (f64, f64) {
    let (a, b, c) = (radii.x, radii.y, radii.z);
    let estimate = |panels: usize| {
        let around = 16 * panels;
        let h = TAU / around as f64;
        integrate(
            |theta| {
                let (s, co) = theta.sin_cos();
                (0..around)
                    .map(|k| {
                        let (sl, cl) = (h * k as f64).sin_cos();
                        s * (b * b * c * c * s * s * cl * cl
                            + a * a * c * c * s * s * sl * sl
                            + a * a * b * b * co * co)
                            .sqrt()
                    })
                    .sum::<f64>()
                    * h
            },
            0.0,
            PI,
            panels,
            16,
        )
    };
    refined(estimate, 16)
}

/// `∫∫ √(1 + h_x² + h_y²)` over a rectangle: the area of the graph of `h`, given its gradient.
pub fn graph_area(
    gradient: impl Fn(f64, f64) -> (f64, f64),
    xs: [f64; 2],
    ys: [f64; 2],
) -> (f64, f64) {
    let integrand = |x: f64, y: f64| {
        let (hx, hy) = gradient(x, y);
        (1.0 + hx * hx + hy * hy).sqrt()
    };
    refined(|panels| integrate2(integrand, xs, ys, panels, 12), 8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        for n in [1, 2, 5, 16] {
            let rule = gauss_legendre(n);
            assert!((rule.iter().map(|r| r.1).sum::<f64>() - 2.0).abs() < 1e-14);
            // Degree 2n − 1 exactly: ∫ x^(2n−2) = 2 / (2n − 1).
            let d = 2 * n - 2;
            let got: f64 = rule.iter().map(|&(x, w)| w * x.powi(d as i32)).sum();
            assert!((got - 2.0 / (d as f64 + 1.0)).abs() < 1e-14, "n {n}: {got}");
        }
    }

    #[test]
    fn ellipsoid_area_matches_the_sphere_and_a_spheroid() {
        let (sphere, err) = ellipsoid_area(DVec3::splat(2.0));
        assert!((sphere - 16.0 * PI).abs() < 1e-12, "{sphere}");
        assert!(err < 1e-12);
        // Prolate spheroid a = b = 1, c = 2: 2π a² (1 + c/(a e) asin e), e = √(1 − a²/c²).
        let e = (1.0f64 - 0.25).sqrt();
        let exact = TAU * (1.0 + 2.0 / e * e.asin());
        let (got, err) = ellipsoid_area(DVec3::new(1.0, 1.0, 2.0));
        assert!((got - exact).abs() < 1e-12, "{got} vs {exact}");
        assert!(err < 1e-10, "{err}");
    }

    #[test]
    fn graph_area_of_a_plane_and_a_paraboloid() {
        // z = x + 2y over the unit square: √6.
        let (plane, _) = graph_area(|_, _| (1.0, 2.0), [0.0, 1.0], [0.0, 1.0]);
        assert!((plane - 6f64.sqrt()).abs() < 1e-13);
        // z = (x² + y²)/2 over the disc of radius 1 is (2π/3)(2√2 − 1); over the square use
        // a polar check instead: ∫∫ √(1 + x² + y²) on [0,1]² by a fine midpoint rule.
        let (got, err) = graph_area(|x, y| (x, y), [0.0, 1.0], [0.0, 1.0]);
        let n = 1000;
        let mut mid = 0.0;
        for i in 0..n {
            for j in 0..n {
                let (x, y) = ((i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / n as f64);
                mid += (1.0 + x * x + y * y).sqrt();
            }
        }
        mid /= (n * n) as f64;
        assert!((got - mid).abs() < 1e-6, "{got} vs {mid}");
        assert!(err < 1e-12);
    }
}
