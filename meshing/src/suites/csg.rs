//! The `csg` suite: CSG solids polygonised by solidkit (sparse marching cubes with `resolution`
//! cells along the longest side of each bounding box), each with its tree beside the mesh.
//!
//! Truth in closed form where it exists:
//! - `sphere_minus_octant`: the unit ball minus the octant `x, y, z > 0`: volume `7π/6`, area
//!   `7/8 · 4π + 3 · π/4`;
//! - `tricylinder_cube`: the Steinmetz solid of three unit cylinders cut by the cube
//!   `[-s, s]³`, `s = 0.9`: for `1/√2 ≤ s ≤ 1` every face of the cube meets the solid in the square
//!   `|u|, |v| ≤ √(1 − s²)`, so `dV/ds = 6 · 4(1 − s²)` and `V = 8(2 − √2) − 24((1 − s) − (1 − s³)/3)`;
//!   each cylinder contributes `16 (s − 1/√2)` of area (`2 min(|cos θ|, |sin θ|)` of height over
//!   the angles where `|cos θ|, |sin θ| ≤ s`), the faces `6 · 4(1 − s²)`;
//! - `nested_shells`: a ball of radius 1 hollowed to 0.8 with a ball of radius 0.5 inside (three
//!   surfaces);
//! - `tangent_spheres`: two balls of radius 0.5 touching at the origin, meshed on a grid with a
//!   sample at the origin (the field is exactly 0 there; the point is a pinch, which the zero rule
//!   settles outside, so the mesh has two shells a hair apart);
//! - `thin_plates`: three parallel plates 0.08 thick (three cells at resolution 64).
//!
//! By sampling ([`sample_volume`]): `gyroid_ball` (a gyroid sheet of period 1 cut by the unit
//! ball) and `metaballs` (three merged Gaussian blobs); their topology is not stated.
//!
//! Every mesh also states `volume_tolerance = 4σ + 2 |V_N − V_{N/2}|`: the sampling's standard
//! error (0 for closed forms) plus twice the change of the mesh volume from half the resolution.
//! Marching cubes' volume error shrinks like `h²`, so `|V_N − V_{N/2}| ≈ 3 |V_N − V|` once the
//! features are resolved; the factor 2 leaves a margin of 6 over that estimate. It is an estimate,
//! not a bound (see `docs/gen.md`); the tests check it on every closed form of this suite.

use super::polygonize::{Grid, polygonise};
use super::sampling::{REPLICATES, STRATA, sample_volume};
use super::truth::{Quantity, Truth, TruthMethod};
use super::{GenSolid, SuiteError, SuiteOptions, build_error};
use glam::DVec3;
use rayon::prelude::*;
use serde_json::json;
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::blob::Ball;
use solidkit_kernel::primitive::{Blob, Gyroid, Primitive};
use std::f64::consts::PI;
use std::sync::Arc;

/// What a recipe knows before meshing.
struct Recipe {
    name: &'static str,
    description: &'static str,
    solid: Solid,
    truth: Truth,
    grid: Grid,
}

/// Closed-form volume and area with the topology.
fn exact(volume: f64, area: f64, shells: usize, genus: i64) -> Truth {
    Truth {
        volume: Some(Quantity::closed_form(volume)),
        area: Some(Quantity::closed_form(area)),
        ..Truth::default()
    }
    .with_topology(shells, genus, TruthMethod::ClosedForm)
}

fn recipes() -> Result<Vec<Recipe>, SuiteError> {
    let s = 0.9f64;
    let long = 3.0;
    let tri = Solid::intersection_all([
        Solid::cylinder(1.0, long),
        Solid::cylinder(1.0, long).rotate(DVec3::X, 90.0),
        Solid::cylinder(1.0, long).rotate(DVec3::Y, 90.0),
        Solid::cube(2.0 * s),
    ]);
    let tri_volume = 8.0 * (2.0 - 2f64.sqrt()) - 24.0 * ((1.0 - s) - (1.0 - s.powi(3)) / 3.0);
    let tri_area = 24.0 * (1.0 - s * s) + 48.0 * (s - 0.5f64.sqrt());
    let plates: Vec<Solid> = [-0.2, 0.0, 0.2]
        .iter()
        .map(|&z| Solid::cuboid(DVec3::new(1.6, 1.6, 0.08)).translate(DVec3::Z * z))
        .collect();
    let plate_volume = 3.0 * 1.6 * 1.6 * 0.08;
    let plate_area = 3.0 * (2.0 * 1.6 * 1.6 + 4.0 * 1.6 * 0.08);
    let gyroid = Solid::primitive(Primitive::Gyroid(Gyroid { thickness: 0.5 }))
        .scale_uniform(1.0 / (2.0 * PI));
    let balls = [
        DVec3::new(-0.4, -0.25, 0.0),
        DVec3::new(0.4, -0.25, 0.0),
        DVec3::new(0.0, 0.45, 0.1),
    ]
    .map(|center| Ball {
        center,
        strength: 1.0,
        sharpness: 6.0,
    });
    let blob = Blob::new(balls.to_vec(), 0.3).map_err(|e| build_error("metaballs", e))?;
    let sampled = |note: &str| Truth::default().with_note(note);
    Ok(vec![
        Recipe {
            name: "sphere_minus_octant",
            description: "unit ball minus the octant x, y, z > 0 (a box of side 2 at (1, 1, 1))",
            solid: Solid::sphere(1.0)
                .difference(&Solid::cube(2.0).translate(DVec3::ONE)),
            truth: exact(7.0 * PI / 6.0, 4.25 * PI, 1, 0).with_bbox([-1.0; 3], [1.0; 3]),
            grid: Grid::Bounds,
        },
        Recipe {
            name: "tricylinder_cube",
            description: "three unit cylinders along x, y, z (Steinmetz solid) cut by the cube [-0.9, 0.9]^3",
            solid: tri,
            truth: exact(tri_volume, tri_area, 1, 0).with_bbox([-s; 3], [s; 3]),
            grid: Grid::Bounds,
        },
        Recipe {
            name: "nested_shells",
            description: "ball of radius 1 hollowed to radius 0.8, with a ball of radius 0.5 inside the cavity",
            solid: Solid::sphere(1.0)
                .difference(&Solid::sphere(0.8))
                .union(&Solid::sphere(0.5)),
            truth: exact(
                4.0 / 3.0 * PI * (1.0 - 0.512 + 0.125),
                4.0 * PI * (1.0 + 0.64 + 0.25),
                3,
                0,
            )
            .with_bbox([-1.0; 3], [1.0; 3]),
            grid: Grid::Bounds,
        },
        Recipe {
            name: "tangent_spheres",
            description: "two balls of radius 0.5 centred at (-0.5, 0, 0) and (0.5, 0, 0), touching at the origin",
            solid: Solid::sphere(0.5)
                .translate(DVec3::new(-0.5, 0.0, 0.0))
                .union(&Solid::sphere(0.5).translate(DVec3::new(0.5, 0.0, 0.0))),
            truth: exact(PI / 3.0, 2.0 * PI, 2, 0)
                .with_bbox([-1.0, -0.5, -0.5], [1.0, 0.5, 0.5])
                .with_note("the exact union is pinched at the origin (not a manifold); the grid has a sample there whose value is exactly 0, a pinch that the zero rule settles outside, so the mesh is two closed shells"),
            grid: Grid::Lattice,
        },
        Recipe {
            name: "thin_plates",
            description: "three parallel 1.6 x 1.6 plates 0.08 thick at z = -0.2, 0, 0.2",
            solid: Solid::union_all(plates),
            truth: exact(plate_volume, plate_area, 3, 0)
                .with_bbox([-0.8, -0.8, -0.24], [0.8, 0.8, 0.24]),
            grid: Grid::Bounds,
        },
        Recipe {
            name: "gyroid_ball",
            description: "gyroid sheet |g| <= 0.5 of period 1 cut by the unit ball",
            solid: Solid::sphere(1.0).intersection(&gyroid),
            truth: sampled("volume by sampling; genus and shells not stated"),
            grid: Grid::Bounds,
        },
        Recipe {
            name: "metaballs",
            description: "three Gaussian blobs (strength 1, sharpness 6) at threshold 0.3, merged",
            solid: Solid::primitive(Primitive::Blob(Arc::new(blob))),
            truth: sampled("volume by sampling; genus and shells not stated"),
            grid: Grid::Bounds,
        },
    ])
}

/// The suite's solids at `opts.resolution` (sampling seeded by `opts.seed`).
pub fn solids(opts: &SuiteOptions) -> Result<Vec<GenSolid>, SuiteError> {
    recipes()?
        .into_par_iter()
        .map(|r| {
            let mut truth = r.truth;
            if truth.volume.is_none() {
                let s = sample_volume(
                    &r.solid.compile(),
                    &r.solid.bbox(),
                    STRATA,
                    REPLICATES,
                    opts.seed,
                );
                truth.volume = Some(Quantity::sampled(s.volume, s.standard_error));
            }
            meshed(
                r.name.to_owned(),
                r.description.to_owned(),
                json!({"resolution": opts.resolution}),
                r.solid,
                truth,
                opts.resolution,
                r.grid,
            )
        })
        .collect()
}

/// Polygonises `solid` at `resolution` and half of it, and states the volume tolerance.
pub(crate) fn meshed(
    name: String,
    description: String,
    mut parameters: serde_json::Value,
    solid: Solid,
    truth: Truth,
    resolution: usize,
    grid: Grid,
) -> Result<GenSolid, SuiteError> {
    let fine = polygonise(&name, &solid, resolution, grid)?;
    let coarse = polygonise(&name, &solid, resolution / 2, grid)?;
    let (v_fine, v_coarse) = (signed_volume(&fine.mesh), signed_volume(&coarse.mesh));
    let sigma = truth.volume.and_then(|q| q.standard_error).unwrap_or(0.0);
    if let Some(map) = parameters.as_object_mut() {
        map.insert("cell".into(), json!(fine.cell));
        map.insert("half_resolution_volume".into(), json!(v_coarse));
    }
    Ok(GenSolid {
        name,
        description,
        parameters,
        mesh: fine.mesh,
        truth,
        chord_error_bound: None,
        volume_tolerance: Some(4.0 * sigma + 2.0 * (v_fine - v_coarse).abs()),
        tree: Some(solid),
        defects: None,
    })
}

/// Signed volume of a mesh by the divergence theorem.
fn signed_volume(mesh: &crate::IndexedMesh) -> f64 {
    (0..mesh.triangle_count())
        .map(|t| {
            let [a, b, c] = mesh.triangle_positions(t);
            a.dot(b.cross(c))
        })
        .sum::<f64>()
        / 6.0
}
