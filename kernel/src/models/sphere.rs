//! `sphere`: the ball of radius [`SPHERE_RADIUS`] = 0.6 centred at the origin, meshed over
//! `[-1, 1]³`. The field is the exact distance `|p| − 0.6`; volume `4/3 π 0.6³ ≈ 0.904779`,
//! area `4 π 0.6²`, genus 0, one shell.

use crate::Solid;

/// Radius of the benchmark sphere.
pub const SPHERE_RADIUS: f64 = 0.6;

/// The benchmark sphere: `|p| − 0.6` (the same tree as `fixtures/bench/sphere.json`).
pub fn sphere_bench() -> Solid {
    Solid::sphere(SPHERE_RADIUS)
}
