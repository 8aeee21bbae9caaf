//! Chord-error bounds: how far a tessellation's triangles can be from the exact surface.
//!
//! - Triangle with vertices on a sphere of radius `r` and longest edge `L`: its points lie at least
//!   `√(r² − L²/3)` from the centre (the deepest point is the circumcentre, or the midpoint of the
//!   longest edge for an obtuse triangle, and the circumradius is at most `L/√3`), so the error is
//!   at most `r − √(r² − L²/3)`.
//! - On a latitude–longitude grid with steps `Δφ`, `Δλ`, every edge (diagonals included) is at
//!   most `r √(Δφ² + Δλ²)` long, since the metric is `r²(dφ² + cos²φ dλ²) ≤ r²(dφ² + dλ²)`.
//! - Linear interpolation of a C¹ map with `|D²p| ≤ M` (as a bilinear form) on a right triangle of
//!   legs `a`, `b` is off by at most `M (a² + b²) / 8` (Taylor about the point, weighted by the
//!   barycentric coordinates: `½ M Σ λ_i |x − x_i|² ≤ ½ M R²`, circumradius `R = hypotenuse/2`).

/// The largest distance from a sphere of radius `r` of a triangle with vertices on it and longest
/// edge `longest`.
pub fn sphere_triangle_error(r: f64, longest: f64) -> f64 {
    let d2 = r * r - longest * longest / 3.0;
    if d2 <= 0.0 { r } else { r - d2.sqrt() }
}

/// The chord error of a latitude–longitude grid on a sphere of radius `r` with steps `Δφ`, `Δλ`.
pub fn lat_long_error(r: f64, d_phi: f64, d_lambda: f64) -> f64 {
    sphere_triangle_error(r, r * (d_phi * d_phi + d_lambda * d_lambda).sqrt())
}

/// The chord error of a grid with cell legs `a`, `b` (in parameter units) over a map whose second
/// derivative is bounded by `m`.
pub fn interpolation_error(m: f64, a: f64, b: f64) -> f64 {
    m * (a * a + b * b) / 8.0
}

/// Sample counts `(n_u, n_v)` for [`sphere`](super::sphere) meeting a chord error `tol` on a
/// sphere of radius `r` (equal steps in latitude and longitude). `None` unless `0 < tol < r`.
pub fn sphere_counts(r: f64, tol: f64) -> Option<(usize, usize)> {
    if !(tol > 0.0 && tol < r && r.is_finite()) {
        return None;
    }
    // r − √(r² − 2r²Δ²/3) ≤ tol  ⇔  Δ² ≤ 3(2r·tol − tol²) / (2r²).
    let step = (3.0 * (2.0 * r * tol - tol * tol) / (2.0 * r * r)).sqrt();
    let half = (std::f64::consts::PI / step).ceil().max(2.0) as usize;
    Some((2 * half + 1, half + 1))
}
