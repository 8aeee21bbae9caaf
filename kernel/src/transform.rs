//! Rigid, scaling, mirroring and general affine transforms of solids, with the distance bound
//! that keeps a transformed field conservative.
//!
//! A child field `f` transformed by `x ↦ A x + t` becomes `g(p) = σ · f(A⁻¹ (p − t))` where `σ` is
//! the smallest singular value of `A`. Distances shrink by at most `σ` under `A`, so when `f` is a
//! distance bound (Lipschitz 1), `g` is one too: `|g(p)|` never exceeds the true distance and the
//! zero set is exactly the image of the child's. For rotations, translations, mirrors and uniform
//! scales `σ` makes `g` an exact distance again.

use glam::{DAffine3, DMat3, DQuat, DVec3};

/// How a transform was specified; kept so trees print and serialise as they were written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TransformSpec {
    /// Move by a vector.
    Translate(DVec3),
    /// Rotate about an axis through the origin by an angle in degrees (right-hand rule).
    Rotate {
        /// Rotation axis (any non-zero length).
        axis: DVec3,
        /// Angle in degrees.
        degrees: f64,
    },
    /// Scale by per-axis factors (uniform when all are equal); negative factors mirror.
    Scale(DVec3),
    /// Reflect in the plane through the origin with this normal.
    Mirror(DVec3),
    /// A general affine map given as the 3 × 4 matrix `[A | t]`, row-major.
    Affine([[f64; 4]; 3]),
}

/// A validated transform: the forward map, its inverse and the distance factor `σ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transform {
    /// The specification the transform was built from.
    pub spec: TransformSpec,
    /// Maps child coordinates to parent coordinates.
    pub forward: DAffine3,
    /// Maps parent coordinates to child coordinates.
    pub inverse: DAffine3,
    /// Smallest singular value of the linear part: the factor applied to the child's field.
    pub sigma: f64,
}

/// Why a transform cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TransformError {
    /// A parameter is NaN or infinite.
    #[error("transform parameters must be finite numbers")]
    NotFinite,
    /// A rotation axis or mirror normal of zero length.
    #[error("axis or normal must have a non-zero length")]
    ZeroAxis,
    /// The linear part is singular (e.g. a zero scale factor) or numerically so.
    #[error("transform is singular (its linear part cannot be inverted)")]
    Singular,
    /// Scales by less than 1e-30 or more than 1e30, or moves by more than 1e30: beyond the range
    /// that single-precision evaluation handles faithfully.
    #[error(
        "transform scales by less than 1e-30 or more than 1e30, or moves by more than 1e30 \
         (beyond that range single-precision evaluation is not faithful)"
    )]
    OutOfRange,
}

impl TransformSpec {
    /// The forward affine map of this specification, without validation of invertibility.
    pub fn to_affine(&self) -> Result<DAffine3, TransformError> {
        let finite = |v: DVec3| v.is_finite();
        match *self {
            TransformSpec::Translate(v) if finite(v) => Ok(DAffine3::from_translation(v)),
            TransformSpec::Rotate { axis, degrees } if finite(axis) && degrees.is_finite() => {
                let n = axis.try_normalize().ok_or(TransformError::ZeroAxis)?;
                Ok(DAffine3::from_quat(DQuat::from_axis_angle(
                    n,
                    degrees.to_radians(),
                )))
            }
            TransformSpec::Scale(s) if finite(s) => Ok(DAffine3::from_scale(s)),
            TransformSpec::Mirror(n) if finite(n) => {
                let n = n.try_normalize().ok_or(TransformError::ZeroAxis)?;
                let m = DMat3::IDENTITY - 2.0 * outer(n, n);
                Ok(DAffine3::from_mat3(m))
            }
            TransformSpec::Affine(rows) if rows.iter().flatten().all(|x| x.is_finite()) => {
                let m = DMat3::from_cols(
                    DVec3::new(rows[0][0], rows[1][0], rows[2][0]),
                    DVec3::new(rows[0][1], rows[1][1], rows[2][1]),
                    DVec3::new(rows[0][2], rows[1][2], rows[2][2]),
                );
                let t = DVec3::new(rows[0][3], rows[1][3], rows[2][3]);
                Ok(DAffine3::from_mat3_translation(m, t))
            }
            _ => Err(TransformError::NotFinite),
        }
    }
}

impl Transform {
    /// Validates a specification and derives its inverse and distance factor.
    pub fn new(spec: TransformSpec) -> Result<Self, TransformError> {
        let forward = spec.to_affine()?;
        let (smin, smax) = singular_value_range(forward.matrix3);
        if smin.is_nan() || smin <= 0.0 || smin <= smax * 1e-12 {
            return Err(TransformError::Singular);
        }
        let far = forward.translation.abs().max_element();
        if smin < crate::primitive::MIN_MAGNITUDE
            || smax > crate::primitive::MAX_MAGNITUDE
            || far > crate::primitive::MAX_MAGNITUDE
        {
            return Err(TransformError::OutOfRange);
        }
        Ok(Self {
            spec,
            forward,
            inverse: forward.inverse(),
            sigma: smin,
        })
    }

    /// Maps a parent-space point into child space.
    pub fn to_child(&self, p: DVec3) -> DVec3 {
        self.inverse.transform_point3(p)
    }

    /// Maps a child-space field gradient to the parent-space gradient of `σ · f(A⁻¹(p − t))`.
    pub fn gradient_to_parent(&self, g: DVec3) -> DVec3 {
        self.sigma * (self.inverse.matrix3.transpose() * g)
    }
}

fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}

/// Smallest and largest singular values of a 3 × 3 matrix. The largest is the square root of the
/// largest eigenvalue of `AᵀA` (accurate relative to itself); the smallest is the reciprocal of
/// the largest singular value of `A⁻¹` (0 when `A` is singular). The smallest eigenvalue of
/// `AᵀA` is only accurate to `ε·σ_max²`: for an ill-conditioned matrix (a zero row beside an entry
/// of 6·10¹⁹, issue 15) it reported σ_min ≈ 10¹², so a singular map passed validation and scaled
/// the field by far more than a distance bound allows (open meshes).
pub fn singular_value_range(a: DMat3) -> (f64, f64) {
    let largest = |m: DMat3| symmetric_eigenvalues(m.transpose() * m)[2].max(0.0).sqrt();
    let hi = largest(a);
    let det = a.determinant();
    if det == 0.0 || !det.is_finite() {
        return (0.0, hi);
    }
    let inverse_hi = largest(a.inverse());
    let lo = if inverse_hi.is_finite() && inverse_hi > 0.0 {
        1.0 / inverse_hi
    } else {
        0.0
    };
    (lo.min(hi), hi)
}

/// Eigenvalues of a symmetric 3 × 3 matrix in ascending order (trigonometric closed form).
fn symmetric_eigenvalues(m: DMat3) -> [f64; 3] {
    let (a, b, c) = (m.x_axis.x, m.y_axis.y, m.z_axis.z);
    let (d, e, f) = (m.y_axis.x, m.z_axis.y, m.z_axis.x);
    let p1 = d * d + e * e + f * f;
    let q = (a + b + c) / 3.0;
    let p2 = (a - q).powi(2) + (b - q).powi(2) + (c - q).powi(2) + 2.0 * p1;
    if p2 <= f64::EPSILON * q.abs().max(1e-300) {
        return [q, q, q];
    }
    let p = (p2 / 6.0).sqrt();
    let bm = (m - DMat3::from_diagonal(DVec3::splat(q))) * (1.0 / p);
    let r = (bm.determinant() / 2.0).clamp(-1.0, 1.0);
    let phi = r.acos() / 3.0;
    let hi = q + 2.0 * p * phi.cos();
    let lo = q + 2.0 * p * (phi + 2.0 * std::f64::consts::PI / 3.0).cos();
    let mid = 3.0 * q - hi - lo;
    [lo, mid, hi]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn singular_values_of_known_matrices() {
        let (lo, hi) = singular_value_range(DMat3::from_diagonal(DVec3::new(2.0, -0.5, 3.0)));
        assert!((lo - 0.5).abs() < 1e-12 && (hi - 3.0).abs() < 1e-12);
        let r = DMat3::from_quat(DQuat::from_axis_angle(
            DVec3::new(1.0, 1.0, 0.0).normalize(),
            1.0,
        ));
        let (lo, hi) = singular_value_range(r * DMat3::from_diagonal(DVec3::new(1.0, 4.0, 2.0)));
        assert!(
            (lo - 1.0).abs() < 1e-9 && (hi - 4.0).abs() < 1e-9,
            "{lo} {hi}"
        );
        // A shear: singular values are not the diagonal.
        let s = DMat3::from_cols(DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Z);
        let (lo, hi) = singular_value_range(s);
        let golden = (1.0 + 5f64.sqrt()) / 2.0;
        assert!((hi - golden).abs() < 1e-9 && (lo - 1.0 / golden).abs() < 1e-9);
    }

    #[test]
    fn rejects_singular_and_non_finite() {
        assert_eq!(
            Transform::new(TransformSpec::Scale(DVec3::new(1.0, 0.0, 1.0))),
            Err(TransformError::Singular)
        );
        assert_eq!(
            Transform::new(TransformSpec::Translate(DVec3::new(f64::NAN, 0.0, 0.0))),
            Err(TransformError::NotFinite)
        );
        assert_eq!(
            Transform::new(TransformSpec::Mirror(DVec3::ZERO)),
            Err(TransformError::ZeroAxis)
        );
    }

    #[test]
    fn mirror_is_an_involution_with_unit_sigma() {
        let t = Transform::new(TransformSpec::Mirror(DVec3::new(1.0, 2.0, 2.0))).unwrap();
        let p = DVec3::new(0.3, -1.0, 2.0);
        assert!((t.forward.transform_point3(t.forward.transform_point3(p)) - p).length() < 1e-12);
        assert!((t.sigma - 1.0).abs() < 1e-12);
    }
}
