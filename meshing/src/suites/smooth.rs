//! The `smooth` suite: parametric tessellations (lecture notes 001, "discrétisation régulière")
//! of smooth solids, each with a bound of its chord error (the largest distance from the mesh to
//! the exact surface). `resolution` is the number of segments around a full turn.
//!
//! - sphere, ellipsoid, capsule, torus: `solidkit_kernel::tessellate` (bounds from
//!   `tessellate::chord`); truth in closed form except the ellipsoid's area (quadrature);
//! - revolved polygons (full turn: genus 1; 270°: genus 0 with planar ends): every mesh point
//!   lies on a chord of a circle of radius at most `ρ_max` spanning the angular step `Δ`, at the
//!   same height and angle as a point of the exact surface, so the error is at most
//!   `ρ_max (1 − cos(Δ/2))`; volume and area by Pappus (exact for straight profile edges);
//! - a cylinder as an extruded circle (the circle sampled at the segments): error
//!   `r (1 − cos(π/n))`;
//! - a tube swept along a closed path (a circle of radius 0.3 along the exact NURBS circle of
//!   radius 1 with rotation-minimising frames: a torus, whose stations are not evenly spaced in
//!   angle): every mesh vertex lies on the torus `p(θ, φ)`, and linear interpolation of `p` over a
//!   triangle of parameter circumradius `ρ` is within `½ |D²p| ρ²` of it (Taylor at each corner,
//!   weighted by the barycentric coordinates: `Σ λᵢ |x − xᵢ|² = ρ² − |x − o|²`), with
//!   `|D²p| ≤ R + 2r`; the bound is the largest over the triangles, from the vertices' parameters;
//! - a Bézier height field: volume and side areas exact (a Bernstein polynomial's integral is the
//!   mean of its coefficients), top area by quadrature, chord error from the Hessian bound.
//!
//! Counts (V, E, F) are the tessellations' formulas, so a reader can check them on the file.

use super::quadrature::{ellipsoid_area, graph_area};
use super::truth::{Quantity, Truth, TruthMethod};
use super::{GenSolid, SuiteError, build_error};
use crate::IndexedMesh;
use glam::{DVec2, DVec3};
use serde_json::json;
use solidkit_kernel::curve::{Curve, Nurbs};
use solidkit_kernel::primitive::heightfield::{HeightGrid, HeightSource};
use solidkit_kernel::primitive::{Extrude, HeightField, Revolve, Sweep};
use solidkit_kernel::profile::Profile;
use solidkit_kernel::tessellate;
use std::f64::consts::{PI, TAU};

/// The suite's solids with `segments` around a full turn.
pub fn solids(segments: usize) -> Result<Vec<GenSolid>, SuiteError> {
    let n = segments;
    Ok(vec![
        sphere(n)?,
        ellipsoid(n)?,
        capsule(n)?,
        torus(n)?,
        revolve(n, 360.0)?,
        revolve(n, 270.0)?,
        cylinder(n)?,
        swept_tube(n)?,
        heightfield(n)?,
    ])
}

/// A smooth solid from its mesh, truth and chord bound.
fn smooth(
    name: &str,
    description: String,
    parameters: serde_json::Value,
    mesh: IndexedMesh,
    truth: Truth,
    chord: Option<f64>,
) -> GenSolid {
    GenSolid {
        name: name.to_owned(),
        description,
        parameters,
        mesh,
        truth,
        chord_error_bound: chord,
        volume_tolerance: None,
        tree: None,
        defects: None,
    }
}

/// Closed-form volume and area.
fn exact(volume: f64, area: f64) -> Truth {
    Truth {
        volume: Some(Quantity::closed_form(volume)),
        area: Some(Quantity::closed_form(area)),
        ..Truth::default()
    }
}

/// Samples from pole to pole for `n` around: about half as many, at least 3.
fn half(n: usize) -> usize {
    (n / 2).max(2) + 1
}

fn sphere(n: usize) -> Result<GenSolid, SuiteError> {
    let (r, nu, nv) = (1.0, n + 1, half(n));
    let t = tessellate::sphere(r, nu, nv).map_err(|e| build_error("sphere", e))?;
    let truth = exact(4.0 / 3.0 * PI * r * r * r, 4.0 * PI * r * r)
        .with_topology(1, 0, TruthMethod::Construction)
        .with_closed_counts((2 * (nu - 1) * (nv - 2)) as u64)
        .with_bbox([-r; 3], [r; 3]);
    Ok(smooth(
        "sphere",
        format!("sphere of radius {r}, latitude-longitude grid {nu} x {nv}"),
        json!({"radius": r, "n_u": nu, "n_v": nv}),
        t.mesh,
        truth,
        t.chord_error,
    ))
}

fn ellipsoid(n: usize) -> Result<GenSolid, SuiteError> {
    let radii = DVec3::new(1.0, 0.75, 0.5);
    let (nu, nv) = (n + 1, half(n));
    let t = tessellate::ellipsoid(radii, nu, nv).map_err(|e| build_error("ellipsoid", e))?;
    let (area, area_err) = ellipsoid_area(radii);
    let truth = Truth {
        volume: Some(Quantity::closed_form(
            4.0 / 3.0 * PI * radii.x * radii.y * radii.z,
        )),
        area: Some(Quantity::quadrature(area, area_err)),
        ..Truth::default()
    }
    .with_topology(1, 0, TruthMethod::Construction)
    .with_closed_counts((2 * (nu - 1) * (nv - 2)) as u64)
    .with_bbox((-radii).to_array(), radii.to_array());
    Ok(smooth(
        "ellipsoid",
        format!("ellipsoid with semi-axes {radii}, latitude-longitude grid {nu} x {nv}"),
        json!({"radii": radii.to_array(), "n_u": nu, "n_v": nv}),
        t.mesh,
        truth,
        t.chord_error,
    ))
}

fn capsule(n: usize) -> Result<GenSolid, SuiteError> {
    let (r, length) = (0.5, 1.0);
    let (nu, nv) = (n + 1, 2 * n.div_ceil(4).max(1) + 1);
    let t = tessellate::capsule(r, length, nu, nv).map_err(|e| build_error("capsule", e))?;
    let truth = exact(
        PI * r * r * length + 4.0 / 3.0 * PI * r * r * r,
        2.0 * PI * r * length + 4.0 * PI * r * r,
    )
    .with_topology(1, 0, TruthMethod::Construction)
    .with_closed_counts((2 * (nu - 1) * (nv - 1)) as u64)
    .with_bbox([-r, -r, -r - length / 2.0], [r, r, r + length / 2.0]);
    Ok(smooth(
        "capsule",
        format!("capsule of radius {r} around z, cylinder length {length}, grid {nu} x {nv}"),
        json!({"radius": r, "length": length, "n_u": nu, "n_v": nv}),
        t.mesh,
        truth,
        t.chord_error,
    ))
}

fn torus(n: usize) -> Result<GenSolid, SuiteError> {
    let (major, minor) = (1.0, 0.35);
    let (nu, nv) = (n + 1, half(n));
    let t = tessellate::torus(major, minor, nu, nv).map_err(|e| build_error("torus", e))?;
    let truth = exact(
        2.0 * PI * PI * major * minor * minor,
        4.0 * PI * PI * major * minor,
    )
    .with_topology(1, 1, TruthMethod::Construction)
    .with_closed_counts((2 * (nu - 1) * (nv - 1)) as u64)
    .with_bbox(
        [-major - minor, -major - minor, -minor],
        [major + minor, major + minor, minor],
    );
    Ok(smooth(
        "torus",
        format!("torus around z, radii {major} and {minor}, grid {nu} x {nv}"),
        json!({"major_radius": major, "minor_radius": minor, "n_u": nu, "n_v": nv}),
        t.mesh,
        truth,
        t.chord_error,
    ))
}

/// The revolved profile: a pentagon in the half-plane `ρ ∈ [0.5, 1]` (away from the axis).
fn revolve_profile() -> Vec<DVec2> {
    vec![
        DVec2::new(0.5, -0.3),
        DVec2::new(1.0, -0.3),
        DVec2::new(1.0, 0.1),
        DVec2::new(0.75, 0.35),
        DVec2::new(0.5, 0.35),
    ]
}

fn revolve(n: usize, degrees: f64) -> Result<GenSolid, SuiteError> {
    let full = degrees >= 360.0;
    let name = if full { "revolve_full" } else { "revolve_270" };
    let points = revolve_profile();
    let profile = Profile::polygon(points.clone(), vec![]).map_err(|e| build_error(name, e))?;
    let solid = Revolve::new(profile, degrees).map_err(|e| build_error(name, e))?;
    let alpha = degrees.to_radians();
    // About n steps per full turn: the angular step is at most 2π/n.
    let steps = if full {
        n
    } else {
        (n as f64 * degrees / 360.0).ceil() as usize + 1
    };
    let step = if full {
        alpha / steps as f64
    } else {
        alpha / (steps - 1) as f64
    };
    let mesh = solid
        .tessellate(3, steps)
        .map_err(|e| build_error(name, e))?;
    let k = points.len();
    let (mut lateral, mut section, mut rho_max) = (0.0, 0.0, 0.0f64);
    for i in 0..k {
        let (a, b) = (points[i], points[(i + 1) % k]);
        lateral += alpha * 0.5 * (a.x + b.x) * a.distance(b);
        section += 0.5 * a.perp_dot(b);
        rho_max = rho_max.max(a.x);
    }
    let area = if full {
        lateral
    } else {
        lateral + 2.0 * section.abs()
    };
    let (genus, faces) = if full {
        (1, 2 * steps * k)
    } else {
        (0, 2 * (steps - 1) * k + 2 * (k - 2))
    };
    let mut truth = exact(solid.volume(), area)
        .with_topology(1, genus, TruthMethod::Construction)
        .with_closed_counts(faces as u64);
    if full {
        truth = truth.with_bbox([-rho_max, -rho_max, -0.3], [rho_max, rho_max, 0.35]);
    }
    let pts: Vec<[f64; 2]> = points.iter().map(|p| [p.x, p.y]).collect();
    Ok(smooth(
        name,
        format!(
            "pentagon (x: distance from the z axis, y: height) revolved {degrees} degrees about z, {steps} stations"
        ),
        json!({"profile": pts, "degrees": degrees, "stations": steps}),
        mesh,
        truth,
        Some(rho_max * (1.0 - (0.5 * step).cos())),
    ))
}

fn cylinder(n: usize) -> Result<GenSolid, SuiteError> {
    let (r, h) = (0.6, 1.5);
    let name = "cylinder_extruded";
    let profile = Profile::circle(r).map_err(|e| build_error(name, e))?;
    let solid = Extrude::new(profile, h, 0.0, 1.0).map_err(|e| build_error(name, e))?;
    let mesh = solid.tessellate(n, 1).map_err(|e| build_error(name, e))?;
    let truth = exact(PI * r * r * h, 2.0 * PI * r * r + 2.0 * PI * r * h)
        .with_topology(1, 0, TruthMethod::Construction)
        .with_closed_counts((4 * n - 4) as u64)
        .with_bbox([-r, -r, -h / 2.0], [r, r, h / 2.0]);
    Ok(smooth(
        name,
        format!("circle of radius {r} extruded along z by {h} (a cylinder), {n} segments"),
        json!({"radius": r, "height": h, "segments": n}),
        mesh,
        truth,
        Some(r * (1.0 - (PI / n as f64).cos())),
    ))
}

fn swept_tube(n: usize) -> Result<GenSolid, SuiteError> {
    let (major, minor) = (1.0, 0.3);
    let name = "swept_tube";
    let segments = half(n) - 1;
    let path = Nurbs::circle(DVec3::ZERO, major).map_err(|e| build_error(name, e))?;
    let profile = Profile::circle(minor).map_err(|e| build_error(name, e))?;
    let solid = Sweep::new(profile, Curve::Nurbs(path)).map_err(|e| build_error(name, e))?;
    let mesh = solid
        .tessellate(segments, n)
        .map_err(|e| build_error(name, e))?;
    let bound = torus_chord_bound(&mesh, major, minor);
    let truth = exact(
        2.0 * PI * PI * major * minor * minor,
        4.0 * PI * PI * major * minor,
    )
    .with_topology(1, 1, TruthMethod::Construction)
    .with_closed_counts((2 * n * segments) as u64)
    .with_bbox(
        [-major - minor, -major - minor, -minor],
        [major + minor, major + minor, minor],
    );
    Ok(smooth(
        name,
        format!(
            "circle of radius {minor} swept along the NURBS circle of radius {major} in the xy plane (a torus), {n} stations, {segments} segments"
        ),
        json!({"path": "nurbs circle", "path_radius": major, "profile_radius": minor, "stations": n, "segments": segments}),
        mesh,
        truth,
        bound,
    ))
}

/// The chord bound of a mesh whose vertices lie on the torus with radii `major`, `minor`:
/// `½ (R + 2r) ρ²` for the largest parameter circumradius `ρ` of a triangle (see the module
/// docs); `None` if a vertex is off the torus or a triangle is degenerate in parameters.
fn torus_chord_bound(mesh: &IndexedMesh, major: f64, minor: f64) -> Option<f64> {
    let params: Vec<DVec2> = mesh
        .positions
        .iter()
        .map(|p| {
            let rho = p.truncate().length() - major;
            DVec2::new(p.y.atan2(p.x), p.z.atan2(rho))
        })
        .collect();
    let on_torus = mesh.positions.iter().all(|p| {
        let d = DVec2::new(p.truncate().length() - major, p.z).length() - minor;
        d.abs() < 1e-12
    });
    if !on_torus {
        return None;
    }
    let unwrap = |a: f64, reference: f64| a - TAU * ((a - reference) / TAU).round();
    let mut worst = 0.0f64;
    for t in &mesh.triangles {
        let first = params[t[0] as usize];
        let [a, b, c] = t.map(|i| {
            let q = params[i as usize];
            DVec2::new(unwrap(q.x, first.x), unwrap(q.y, first.y))
        });
        // Circumradius: |ab| |bc| |ca| / (4 · area).
        let area2 = (b - a).perp_dot(c - a).abs();
        if area2 <= 0.0 {
            return None;
        }
        let r = a.distance(b) * b.distance(c) * c.distance(a) / (2.0 * area2);
        worst = worst.max(r);
    }
    Some(0.5 * (major + 2.0 * minor) * worst * worst)
}

/// Control heights of the height field's bicubic Bézier patch (`[i][j]`, `i` along x).
const CONTROL: [[f64; 4]; 4] = [
    [0.30, 0.45, 0.40, 0.25],
    [0.50, 0.90, 0.70, 0.35],
    [0.40, 0.80, 1.00, 0.45],
    [0.20, 0.35, 0.50, 0.30],
];

fn heightfield(n: usize) -> Result<GenSolid, SuiteError> {
    let name = "heightfield_bezier";
    let (min, max, base) = (DVec2::splat(-1.0), DVec2::splat(1.0), 0.0);
    let values: Vec<f64> = (0..4)
        .flat_map(|j| (0..4).map(move |i| CONTROL[i][j]))
        .collect();
    let grid = HeightGrid::new(4, 4, values).map_err(|e| build_error(name, e))?;
    let hf = HeightField::new(min, max, base, HeightSource::Bezier(grid.clone()))
        .map_err(|e| build_error(name, e))?;
    // Make sure the layout is the one the truth assumes.
    if grid.get(1, 0) != CONTROL[1][0] {
        return Err(build_error(name, "control grid layout"));
    }
    let samples = half(n);
    let t = tessellate::heightfield(&hf, samples).map_err(|e| build_error(name, e))?;
    let size = max - min;
    let mean = |f: &dyn Fn(usize) -> f64, k: usize| (0..k).map(f).sum::<f64>() / k as f64;
    let all = CONTROL.iter().flatten().sum::<f64>() / 16.0;
    let volume = size.x * size.y * (all - base);
    // Sides: ∫ (h − base) along each boundary curve = length × (mean of its control row − base).
    let sides = size.x * (mean(&|i| CONTROL[i][0], 4) - base)
        + size.x * (mean(&|i| CONTROL[i][3], 4) - base)
        + size.y * (mean(&|j| CONTROL[0][j], 4) - base)
        + size.y * (mean(&|j| CONTROL[3][j], 4) - base);
    let (top, top_err) = graph_area(
        |x, y| {
            let d = hf.derivatives(x, y);
            (d.hx, d.hy)
        },
        [min.x, max.x],
        [min.y, max.y],
    );
    let mut truth = Truth {
        volume: Some(Quantity::closed_form(volume)),
        area: Some(Quantity::quadrature(top + sides + size.x * size.y, top_err)),
        ..Truth::default()
    }
    .with_topology(1, 0, TruthMethod::Construction)
    .with_closed_counts((4 * (samples - 1) * (samples - 1) + 8 * (samples - 1)) as u64);
    truth =
        truth.with_note("bounding box not stated: the patch's highest point has no closed form");
    Ok(smooth(
        name,
        format!(
            "solid under a bicubic Bezier height patch over [-1, 1]^2 above z = {base}, {samples} x {samples} samples"
        ),
        json!({"control_heights": CONTROL, "min": [min.x, min.y], "max": [max.x, max.y], "base": base, "samples": samples}),
        t.mesh,
        truth,
        t.chord_error,
    ))
}
