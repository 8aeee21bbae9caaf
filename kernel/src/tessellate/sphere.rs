//! Sphere and ellipsoid on the latitude–longitude grid of lecture notes 001: `n_u` samples around
//! (the last repeating the first), `n_v` from pole to pole (poles included). Welding the seam and
//! the poles leaves `(n_u − 1)(n_v − 2) + 2` vertices and `2(n_u − 1)(n_v − 2)` triangles (the
//! open grid's `2(n_u − 1)(n_v − 1)` less the `2(n_u − 1)` collapsed at the poles).

use super::Tessellation;
use super::chord::lat_long_error;
use super::error::{TessellationError, count, positive};
use super::grid::closed_rings;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Unit-sphere point at latitude index `k` of `n_v` samples and longitude index `i` of `n_u`.
fn unit(k: usize, nv: usize, i: usize, nu: usize) -> DVec3 {
    let phi = -0.5 * PI + PI * k as f64 / (nv - 1) as f64;
    let lambda = TAU * i as f64 / (nu - 1) as f64;
    DVec3::new(
        phi.cos() * lambda.cos(),
        phi.cos() * lambda.sin(),
        phi.sin(),
    )
}

/// The sphere of radius `r` centred at the origin, on the latitude–longitude grid: `n_u` samples
/// around (the last repeating the first), `n_v` from pole to pole (poles included). Welded, it has
/// `(n_u − 1)(n_v − 2) + 2` vertices and `2(n_u − 1)(n_v − 2)` triangles.
/// Chord error: [`lat_long_error`] with steps `π/(n_v − 1)` and `2π/(n_u − 1)`.
pub fn sphere(r: f64, nu: usize, nv: usize) -> Result<Tessellation, TessellationError> {
    ellipsoid(DVec3::splat(r), nu, nv)
}

/// The ellipsoid with semi-axes `radii`: the sphere grid scaled per axis. Chord error: the unit
/// sphere's scaled by the largest radius (a point `(1 − t)ŷ` of a unit-sphere facet maps within
/// `t |D ŷ| ≤ t max(radii)` of the ellipsoid point `Dŷ`).
pub fn ellipsoid(radii: DVec3, nu: usize, nv: usize) -> Result<Tessellation, TessellationError> {
    positive("radii", radii.min_element())?;
    if !radii.is_finite() {
        return Err(TessellationError::NotPositive("radii"));
    }
    count("n_u", nu, 4)?;
    count("n_v", nv, 3)?;
    let mesh = closed_rings(
        nv - 2,
        nu - 1,
        -DVec3::Z * radii,
        DVec3::Z * radii,
        |k, i| unit(k + 1, nv, i, nu) * radii,
    );
    let unit_error = lat_long_error(1.0, PI / (nv - 1) as f64, TAU / (nu - 1) as f64);
    Ok(Tessellation {
        mesh,
        chord_error: Some(unit_error * radii.max_element()),
    })
}

/// The capsule of radius `r` around the z axis: a cylinder of length `length` (from
/// `z = −length/2` to `length/2`) capped by hemispheres. The sphere grid with `n_v` odd is cut at
/// its equator ring, which is doubled (one copy per end of the cylinder):
/// `(n_u − 1)(n_v − 1) + 2` vertices, `2(n_u − 1)(n_v − 1)` triangles. Chord error as the sphere's.
pub fn capsule(
    r: f64,
    length: f64,
    nu: usize,
    nv: usize,
) -> Result<Tessellation, TessellationError> {
    positive("radius", r)?;
    positive("length", length)?;
    count("n_u", nu, 4)?;
    count("n_v", nv, 3)?;
    if nv.is_multiple_of(2) {
        return Err(TessellationError::Even {
            what: "n_v",
            got: nv,
        });
    }
    let equator = (nv - 1) / 2;
    let half = DVec3::Z * (0.5 * length);
    let mesh = closed_rings(
        nv - 1,
        nu - 1,
        -DVec3::Z * r - half,
        DVec3::Z * r + half,
        |k, i| {
            // Rings 0 ..= equator − 1 are southern latitudes 1 ..= equator; then the north.
            if k < equator {
                unit(k + 1, nv, i, nu) * r - half
            } else {
                unit(k, nv, i, nu) * r + half
            }
        },
    );
    Ok(Tessellation {
        mesh,
        chord_error: Some(lat_long_error(
            r,
            PI / (nv - 1) as f64,
            TAU / (nu - 1) as f64,
        )),
    })
}
