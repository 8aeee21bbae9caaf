//! The torus around the z axis on its `(θ, φ)` grid: `n_u` samples around the axis and `n_v`
//! around the tube (each repeating its first), both seams welded: `(n_u − 1)(n_v − 1)` vertices
//! and `2(n_u − 1)(n_v − 1)` triangles.

use super::Tessellation;
use super::chord::interpolation_error;
use super::error::{TessellationError, count, positive};
use super::grid::closed_torus_grid;
use glam::DVec3;
use std::f64::consts::TAU;

/// The torus with major radius `major` and tube radius `minor`, centred at the origin.
///
/// Chord error: `p(θ, φ) = ((R + r cos φ) cos θ, (R + r cos φ) sin θ, r sin φ)` has
/// `|p_θθ| ≤ R + r`, `|p_θφ| ≤ r`, `|p_φφ| = r`, so `|D²p| ≤ R + 2r` and the error is at most
/// `(R + 2r)(Δθ² + Δφ²)/8` ([`interpolation_error`]).
pub fn torus(
    major: f64,
    minor: f64,
    nu: usize,
    nv: usize,
) -> Result<Tessellation, TessellationError> {
    positive("major_radius", major)?;
    positive("minor_radius", minor)?;
    count("n_u", nu, 4)?;
    count("n_v", nv, 4)?;
    let (su, sv) = (nu - 1, nv - 1);
    let mesh = closed_torus_grid(su, sv, |i, j| {
        let (t, f) = (TAU * i as f64 / su as f64, TAU * j as f64 / sv as f64);
        let rho = major + minor * f.cos();
        DVec3::new(rho * t.cos(), rho * t.sin(), minor * f.sin())
    });
    let chord = interpolation_error(major + 2.0 * minor, TAU / su as f64, TAU / sv as f64);
    Ok(Tessellation {
        mesh,
        chord_error: Some(chord),
    })
}
