//! The `sponge` suite: Menger sponges of levels 0 to [`MAX_LEVEL`], side 1, centred at the
//! origin, as exact polyhedral meshes ([`menger_mesh`]: the boundary of the union of the kept
//! cubes, one square of two triangles per exposed cube face, welded on the lattice).
//!
//! Truth (closed forms, see `solidkit_kernel::models::menger_mesh`): volume `(20/27)^L`, area
//! `2 (20/9)^L + 4 (8/9)^L`, genus `0, 5, 81, 1409, 26433`, one shell, and the mesh counts
//! `F = 2S`, `E = 3S`, `V = 2 − 2g + S` with `S = 2·20^L + 4·8^L` squares.

use super::truth::{Quantity, Truth, TruthMethod};
use super::{GenSolid, SuiteError, build_error};
use serde_json::json;
use solidkit_kernel::models::{
    menger_area, menger_genus, menger_mesh, menger_mesh_counts, menger_volume,
};

/// The highest level generated (level 4: 672 768 triangles).
pub const MAX_LEVEL: u32 = 4;

/// Levels 0 to [`MAX_LEVEL`].
pub fn solids() -> Result<Vec<GenSolid>, SuiteError> {
    (0..=MAX_LEVEL).map(level).collect()
}

/// The level-`level` sponge.
pub fn level(level: u32) -> Result<GenSolid, SuiteError> {
    let name = format!("menger_{level}");
    let mesh = menger_mesh(level).map_err(|e| build_error(&name, e))?;
    let truth = Truth {
        volume: Some(Quantity::closed_form(menger_volume(level))),
        area: Some(Quantity::closed_form(menger_area(level))),
        ..Truth::default()
    }
    .with_topology(1, menger_genus(level), TruthMethod::ExactPolyhedron)
    .with_counts(menger_mesh_counts(level))
    .with_bbox([-0.5; 3], [0.5; 3]);
    Ok(GenSolid {
        name,
        description: format!(
            "Menger sponge of level {level}, side 1, centred at the origin: {} cubes of side 3^-{level}",
            20u64.pow(level)
        ),
        parameters: json!({"level": level, "side": 1.0}),
        mesh,
        truth,
        chord_error_bound: Some(0.0),
        volume_tolerance: None,
        tree: None,
        defects: None,
    })
}
