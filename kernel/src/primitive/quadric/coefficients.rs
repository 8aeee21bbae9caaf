//! The ten coefficients of a quadric
//! `Q(x, y, z) = ax² + by² + cz² + 2fyz + 2gzx + 2hxy + 2px + 2qy + 2rz + d` (lecture notes 002),
//! with `Q` written as `xᵀAx + 2lᵀx + d` for the symmetric 3×3 part
//! `A = [[a, h, g], [h, b, f], [g, f, c]]` and the linear part `l = (p, q, r)`: value, gradient,
//! interval bounds over boxes, and the quadric's image under an affine map.

use super::super::PrimitiveError;
use crate::{Aabb, Interval};
use glam::{DAffine3, DMat3, DVec3};

/// The coefficients of `ax² + by² + cz² + 2fyz + 2gzx + 2hxy + 2px + 2qy + 2rz + d` (the lecture
/// notes' names; note the factor 2 on the mixed and linear terms).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct QuadricCoefficients {
    /// Coefficient of `x²`.
    pub a: f64,
    /// Coefficient of `y²`.
    pub b: f64,
    /// Coefficient of `z²`.
    pub c: f64,
    /// Half the coefficient of `yz`.
    pub f: f64,
    /// Half the coefficient of `zx`.
    pub g: f64,
    /// Half the coefficient of `xy`.
    pub h: f64,
    /// Half the coefficient of `x`.
    pub p: f64,
    /// Half the coefficient of `y`.
    pub q: f64,
    /// Half the coefficient of `z`.
    pub r: f64,
    /// Constant term.
    pub d: f64,
}

impl QuadricCoefficients {
    /// The coefficients of `xᵀAx + 2lᵀx + d` (only the symmetric part of `A` counts).
    pub fn from_parts(a: DMat3, l: DVec3, d: f64) -> Self {
        let s = (a + a.transpose()) * 0.5;
        Self {
            a: s.x_axis.x,
            b: s.y_axis.y,
            c: s.z_axis.z,
            f: s.z_axis.y,
            g: s.x_axis.z,
            h: s.y_axis.x,
            p: l.x,
            q: l.y,
            r: l.z,
            d,
        }
    }

    /// The coefficients in the order `[a, b, c, f, g, h, p, q, r, d]`.
    pub fn to_array(&self) -> [f64; 10] {
        [
            self.a, self.b, self.c, self.f, self.g, self.h, self.p, self.q, self.r, self.d,
        ]
    }

    /// The symmetric 3×3 part `A = [[a, h, g], [h, b, f], [g, f, c]]`.
    pub fn matrix3(&self) -> DMat3 {
        DMat3::from_cols(
            DVec3::new(self.a, self.h, self.g),
            DVec3::new(self.h, self.b, self.f),
            DVec3::new(self.g, self.f, self.c),
        )
    }

    /// The linear part `l = (p, q, r)`.
    pub fn linear(&self) -> DVec3 {
        DVec3::new(self.p, self.q, self.r)
    }

    /// The symmetric 4×4 matrix `E = [[A, l], [lᵀ, d]]` with `Q(x) = (x, 1)ᵀ E (x, 1)`.
    pub fn matrix4(&self) -> [[f64; 4]; 4] {
        [
            [self.a, self.h, self.g, self.p],
            [self.h, self.b, self.f, self.q],
            [self.g, self.f, self.c, self.r],
            [self.p, self.q, self.r, self.d],
        ]
    }

    /// `Q(x)`.
    #[inline]
    pub fn value(&self, x: DVec3) -> f64 {
        let ax = self.matrix_times(x);
        x.dot(ax + 2.0 * self.linear()) + self.d
    }

    /// `∇Q(x) = 2(Ax + l)`.
    #[inline]
    pub fn gradient(&self, x: DVec3) -> DVec3 {
        2.0 * (self.matrix_times(x) + self.linear())
    }

    /// `Ax` without building the matrix.
    #[inline]
    fn matrix_times(&self, x: DVec3) -> DVec3 {
        DVec3::new(
            self.a * x.x + self.h * x.y + self.g * x.z,
            self.h * x.x + self.b * x.y + self.f * x.z,
            self.g * x.x + self.f * x.y + self.c * x.z,
        )
    }

    /// An interval containing `Q` over the box, from the exact second-order Taylor expansion about
    /// the box centre `m`: `Q(m + e) = Q(m) + ∇Q(m)·e + eᵀAe` with `|e_i| ≤ w_i` (half extents),
    /// where `e_i² ∈ [0, w_i²]` and `e_i e_j ∈ [−w_i w_j, w_i w_j]`.
    pub fn interval(&self, b: &Aabb) -> Interval {
        let m = b.center();
        let w = b.half_extents();
        let g = self.gradient(m);
        let linear = g.abs().dot(w);
        let mut quad = Interval::point(0.0);
        let diag = [self.a, self.b, self.c];
        for (i, &aii) in diag.iter().enumerate() {
            quad = quad + Interval::new(0.0, w[i] * w[i]).scale(aii);
        }
        // Off-diagonal pairs (x, y), (y, z), (z, x) with their coefficients (each appears twice).
        let off = [(0, 1, self.h), (1, 2, self.f), (2, 0, self.g)];
        for (i, j, aij) in off {
            let k = 2.0 * aij.abs() * w[i] * w[j];
            quad = quad + Interval::new(-k, k);
        }
        Interval::point(self.value(m)) + Interval::new(-linear, linear) + quad
    }

    /// An interval containing `|∇Q|` over the box: each component of `2(Ax + l)` is affine, so its
    /// range over the box is exact, and the norm of the component ranges bounds the length.
    pub fn gradient_norm_interval(&self, b: &Aabb) -> Interval {
        let g = self.gradient(b.center());
        let w = b.half_extents();
        let a = self.matrix3();
        let rows = [a.row(0), a.row(1), a.row(2)];
        let comps = [0, 1, 2].map(|i| Interval::around(g[i], 2.0 * rows[i].abs().dot(w)));
        Interval::norm(&comps)
    }

    /// The largest `|∇Q|` over a finite box. `|∇Q|` is convex (the norm of an affine map), so its
    /// maximum over the box is attained at one of the eight corners.
    pub fn max_gradient_norm(&self, b: &Aabb) -> f64 {
        (0..8)
            .map(|k| {
                let t = DVec3::new((k & 1) as f64, ((k >> 1) & 1) as f64, ((k >> 2) & 1) as f64);
                self.gradient(b.min + (b.max - b.min) * t).length()
            })
            .fold(0.0, f64::max)
    }

    /// The quadric moved by an invertible affine map `m`: the coefficients of `Q(m⁻¹(x))`, whose
    /// zero set (and inside) is the image of this one's. `None` when `m` is singular.
    pub fn transformed(&self, m: &DAffine3) -> Option<Self> {
        let det = m.matrix3.determinant();
        if !det.is_finite() || det == 0.0 {
            return None;
        }
        // y = N(x − t) with N = M⁻¹: A' = NᵀAN, l' = Nᵀl − A't, d' = tᵀA't − 2(Nᵀl)·t + d.
        let n = m.matrix3.inverse();
        let t = m.translation;
        let a2 = n.transpose() * self.matrix3() * n;
        let nl = n.transpose() * self.linear();
        let l2 = nl - a2 * t;
        let d2 = t.dot(a2 * t) - 2.0 * nl.dot(t) + self.d;
        Some(Self::from_parts(a2, l2, d2))
    }

    /// Checks that every coefficient is finite and that `Q` is not constant.
    pub fn validate(&self) -> Result<(), PrimitiveError> {
        let all = self.to_array();
        if all.iter().any(|x| !x.is_finite()) {
            return Err(PrimitiveError {
                parameter: "coefficients",
                problem: "expected finite numbers",
            });
        }
        if all[..9].iter().all(|&x| x == 0.0) {
            return Err(PrimitiveError {
                parameter: "coefficients",
                problem: "the quadratic and linear parts are all zero (no surface)",
            });
        }
        Ok(())
    }
}
