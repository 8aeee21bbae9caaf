//! A folded chain of transforms: one inverse affine map from world to primitive coordinates and
//! the product of the chain's distance factors.

use crate::{Aabb, Transform};
use glam::{DAffine3, DVec3};

/// World → primitive coordinates for one leaf, with single-precision copies for batch evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Maps world points into the primitive's frame.
    pub inverse: DAffine3,
    /// Product of the distance factors `σ` of the chain (a conservative distance bound).
    pub sigma: f64,
    /// True for the identity map with `σ = 1` (evaluators skip the transform).
    pub identity: bool,
    /// True when the map is a pure translation with `σ = 1` (evaluators only add).
    pub translation: bool,
    /// `inverse` as row-major 3 × 4 single-precision coefficients.
    pub rows_f32: [[f32; 4]; 3],
}

impl Frame {
    /// The world frame.
    pub fn identity() -> Self {
        Self::from_affine(DAffine3::IDENTITY, 1.0)
    }

    fn from_affine(inverse: DAffine3, sigma: f64) -> Self {
        let m = inverse.matrix3;
        let t = inverse.translation;
        let row = |r: usize| {
            [
                m.x_axis[r] as f32,
                m.y_axis[r] as f32,
                m.z_axis[r] as f32,
                t[r] as f32,
            ]
        };
        Self {
            inverse,
            sigma,
            identity: inverse == DAffine3::IDENTITY && sigma == 1.0,
            translation: inverse.matrix3 == glam::DMat3::IDENTITY && sigma == 1.0,
            rows_f32: [row(0), row(1), row(2)],
        }
    }

    /// This frame with its offset reduced modulo `period` on each axis, for a primitive periodic
    /// with that period along its own axes (the gyroid: 2π). A gyroid translated by 10⁶ or more
    /// was evaluated at single-precision coordinates a whole step of 0.1 or more apart, far from
    /// the intervals' idea of it, and meshed open (issue 15); the reduced map is the same field.
    pub(crate) fn reduced_offset(&self, period: f64) -> Self {
        let mut inverse = self.inverse;
        let t = inverse.translation;
        inverse.translation = t - (t / period).round() * period;
        Self::from_affine(inverse, self.sigma)
    }

    /// This frame entered into a child of transform `t`: points go through `t⁻¹` after this map.
    pub fn then(&self, t: &Transform) -> Self {
        Self::from_affine(t.inverse * self.inverse, self.sigma * t.sigma)
    }

    /// A world point in primitive coordinates.
    pub fn apply(&self, p: DVec3) -> DVec3 {
        if self.identity {
            p
        } else {
            self.inverse.transform_point3(p)
        }
    }

    /// A world box's image (bounding box) in primitive coordinates.
    pub fn apply_box(&self, b: &Aabb) -> Aabb {
        if self.identity {
            *b
        } else if self.translation {
            let t = self.inverse.translation;
            Aabb::new(b.min + t, b.max + t)
        } else {
            b.transformed(&self.inverse)
        }
    }

    /// A primitive-frame gradient as the world gradient of `σ · f(inverse(p))`.
    pub fn gradient_to_world(&self, g: DVec3) -> DVec3 {
        if self.identity {
            g
        } else {
            self.sigma * (self.inverse.matrix3.transpose() * g)
        }
    }

    /// Bit pattern identifying the frame, for sharing equal frames.
    pub(crate) fn key(&self) -> [u64; 13] {
        let m = self.inverse.to_cols_array();
        let mut k = [0u64; 13];
        for (o, x) in k.iter_mut().zip(m.iter()) {
            *o = x.to_bits();
        }
        k[12] = self.sigma.to_bits();
        k
    }
}
