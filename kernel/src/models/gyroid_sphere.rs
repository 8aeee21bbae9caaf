//! `gyroid-sphere`: a gyroid sheet clipped to a ball, meshed over `[-1, 1]³`.
//!
//! With `s = 30` and `(X, Y, Z) = s·(x, y, z)`, `g = sin X cos Y + sin Y cos Z + sin Z cos X`, the
//! solid is `{ max(|(X, Y, Z)| − 25, |g(X, Y, Z)| − 0.2) ≤ 0 }`. It is built as
//! `intersection(sphere(25), gyroid(0.2)).scale(1/30)`, whose field is that expression divided
//! by 30: the same zero set (a ball of radius 25/30 ≈ 0.833 cut to the sheet `|g| ≤ 0.2`).
//! No closed form of its volume or genus is used; meshes of it are checked for being closed and
//! manifold.

use crate::Solid;
use crate::primitive::{Gyroid, Primitive};

/// The scale `s` from model to gyroid coordinates.
pub const GYROID_SCALE: f64 = 30.0;
/// Radius of the clipping ball in gyroid coordinates (25 / 30 ≈ 0.833 in model coordinates).
pub const GYROID_SPHERE_RADIUS: f64 = 25.0;
/// Half-thickness of the sheet, in units of `g`.
pub const GYROID_THICKNESS: f64 = 0.2;

/// The benchmark gyroid sheet clipped to a ball (see the module docs for the exact field).
pub fn gyroid_sphere() -> Solid {
    let gyroid = Solid::primitive(Primitive::Gyroid(Gyroid {
        thickness: GYROID_THICKNESS,
    }));
    Solid::sphere(GYROID_SPHERE_RADIUS)
        .intersection(&gyroid)
        .scale_uniform(1.0 / GYROID_SCALE)
}
