//! Quadrics: the general ten-coefficient form `ax² + by² + cz² + 2fyz + 2gzx + 2hxy + 2px + 2qy +
//! 2rz + d` (lecture notes 002) with its classification ([`classify`]), the named quadrics with
//! their natural parameters ([`QuadricForm`]), all as the solid `{Q ≤ 0}` bounded by a box where
//! unbounded ([`Quadric`]), and the [`Ellipsoid`] with a 1-Lipschitz field.
//!
//! # The field of a bounded quadric
//! With `B` the bounding box, `c(p)` the clamp of `p` into `B`, `M = max_B |∇Q|` and
//! `σ = max |eig A|`, `ℓ = M/(32σ)`: `φ₁ = Q/M` (1-Lipschitz on `B`) and
//! `φ₂ = clamp(Q / max(|∇Q|, 2σℓ), ±ℓ)` (Taubin's gradient-normalised distance `Q/|∇Q|` within
//! about `ℓ` of the surface, 2-Lipschitz), combined as
//! `φ = sign(Q)·max(|φ₁|, |φ₂|)`, and `F(p) = max(φ(c(p)), dist_B(p))`. `F` is 2-Lipschitz (1 for
//! a linear `Q`), its zero set is exactly the quadric inside `B` plus the box faces, and its gradient
//! is a unit vector on the surface wherever `|∇Q| ≥ 2σℓ = M/16`. `interval` bounds `Q` by its exact Taylor
//! expansion about the box centre and `|∇Q|` by its affine components.

mod classify;
mod coefficients;
mod eigen;
mod ellipsoid;
mod field;
mod form;
mod shape;

pub use classify::{Classification, QuadricKind, classify};
pub use coefficients::QuadricCoefficients;
pub use eigen::symmetric_eigen;
pub use ellipsoid::Ellipsoid;
pub use form::QuadricForm;
pub use shape::Quadric;

#[cfg(test)]
mod tests;
