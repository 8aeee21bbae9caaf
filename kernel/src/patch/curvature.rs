//! Curvatures of a Monge patch `z = h(x, y)` from the derivatives of `h` (lecture notes 001):
//!
//! - Gaussian `K = (h_xx h_yy − h_xy²) / (1 + h_x² + h_y²)²`;
//! - mean `H = ((1 + h_y²) h_xx − 2 h_x h_y h_xy + (1 + h_x²) h_yy) / (2 (1 + h_x² + h_y²)^{3/2})`.
//!
//! (The notes print the Gaussian denominator without the square; the square is right: on a sphere
//! of radius `R` it gives `K = 1/R²` everywhere, which the tests check.) `H` is taken with the
//! upward normal `(−h_x, −h_y, 1)`: positive where the surface bends up, `−1/R` on the top of a
//! sphere.

/// The derivatives of a height function `h(x, y)` at one point, up to second order.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeightDerivatives {
    /// `h`.
    pub h: f64,
    /// `∂h/∂x`.
    pub hx: f64,
    /// `∂h/∂y`.
    pub hy: f64,
    /// `∂²h/∂x²`.
    pub hxx: f64,
    /// `∂²h/∂x∂y`.
    pub hxy: f64,
    /// `∂²h/∂y²`.
    pub hyy: f64,
}

/// Gaussian and mean curvature of a surface at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Curvature {
    /// Gaussian curvature `K = κ₁ κ₂`.
    pub gaussian: f64,
    /// Mean curvature `H = (κ₁ + κ₂) / 2`, for the upward normal.
    pub mean: f64,
}

impl Curvature {
    /// The principal curvatures `H ± √(H² − K)`, larger first (the radicand clamped at zero).
    pub fn principal(&self) -> (f64, f64) {
        let r = (self.mean * self.mean - self.gaussian).max(0.0).sqrt();
        (self.mean + r, self.mean - r)
    }
}

/// The curvatures of the graph of `h` from its derivatives; see the [module docs](self).
pub fn monge_curvature(d: &HeightDerivatives) -> Curvature {
    let w = 1.0 + d.hx * d.hx + d.hy * d.hy;
    let gaussian = (d.hxx * d.hyy - d.hxy * d.hxy) / (w * w);
    let mean = ((1.0 + d.hy * d.hy) * d.hxx - 2.0 * d.hx * d.hy * d.hxy
        + (1.0 + d.hx * d.hx) * d.hyy)
        / (2.0 * w * w.sqrt());
    Curvature { gaussian, mean }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Derivatives of the upper hemisphere `h = √(R² − x² − y²)`.
    fn cap(r: f64, x: f64, y: f64) -> HeightDerivatives {
        let h = (r * r - x * x - y * y).sqrt();
        let h3 = h * h * h;
        HeightDerivatives {
            h,
            hx: -x / h,
            hy: -y / h,
            hxx: -(r * r - y * y) / h3,
            hxy: -x * y / h3,
            hyy: -(r * r - x * x) / h3,
        }
    }

    #[test]
    fn sphere_cap_has_constant_curvature() {
        let r = 2.5;
        for &(x, y) in &[(0.0, 0.0), (1.0, 0.5), (-1.7, 1.2), (0.3, -2.2)] {
            let c = monge_curvature(&cap(r, x, y));
            assert!((c.gaussian - 1.0 / (r * r)).abs() < 1e-12, "{c:?}");
            assert!((c.mean + 1.0 / r).abs() < 1e-12, "{c:?}");
            let (k1, k2) = c.principal();
            assert!((k1 + 1.0 / r).abs() < 1e-6 && (k2 + 1.0 / r).abs() < 1e-6);
        }
    }

    #[test]
    fn paraboloid_matches_closed_form() {
        // h = (x² + y²) / (2R): K = 1 / (R² (1 + ρ²/R²)²), H = (2 + ρ²/R²) / (2R (1 + ρ²/R²)^{3/2}).
        let r = 1.3;
        for &(x, y) in &[(0.0, 0.0), (0.4, -0.9), (2.0, 1.0)] {
            let d = HeightDerivatives {
                h: (x * x + y * y) / (2.0 * r),
                hx: x / r,
                hy: y / r,
                hxx: 1.0 / r,
                hxy: 0.0,
                hyy: 1.0 / r,
            };
            let c = monge_curvature(&d);
            let q = (x * x + y * y) / (r * r);
            assert!((c.gaussian - 1.0 / (r * r * (1.0 + q) * (1.0 + q))).abs() < 1e-12);
            assert!((c.mean - (2.0 + q) / (2.0 * r * (1.0 + q).powf(1.5))).abs() < 1e-12);
        }
    }

    #[test]
    fn saddle_has_negative_gaussian_and_zero_mean_at_its_centre() {
        let d = HeightDerivatives {
            hxx: 2.0,
            hyy: -2.0,
            ..Default::default()
        };
        let c = monge_curvature(&d);
        assert_eq!((c.gaussian, c.mean), (-4.0, 0.0));
    }
}
