//! A solid's entry in the manifest: what it is, its truth, the mesh's own measured values (the
//! [`TopologyReport`] of the mesh as its file stores it) and the discretisation errors.

use super::GenSolid;
use super::broken::Defects;
use super::truth::Truth;
use crate::io::{MeshFormat, MeshIoError, WriteOptions, encode_mesh, stored_mesh};
use crate::{IndexedMesh, TopologyReport};
use serde::Serialize;

/// Measured minus true values, and the stated bounds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Errors {
    /// Mesh volume minus true volume.
    pub volume: Option<f64>,
    /// `volume / |true volume|`.
    pub volume_relative: Option<f64>,
    /// Mesh area minus true area.
    pub area: Option<f64>,
    /// `area / true area`.
    pub area_relative: Option<f64>,
    /// Bound of the distance from the mesh to the exact surface (0: exact polyhedron).
    pub chord_error_bound: Option<f64>,
    /// The error the mesh volume is stated to be within of the true volume.
    pub volume_tolerance: Option<f64>,
    /// `|volume| <= volume_tolerance`, where a tolerance is stated.
    pub volume_within_tolerance: Option<bool>,
    /// Whether the mesh's shells, genus and χ equal the true ones (where stated).
    pub topology_matches: Option<bool>,
}

/// One solid of the manifest.
#[derive(Debug, Clone, Serialize)]
pub struct SolidRecord {
    /// File stem.
    pub name: String,
    /// The mesh file, relative to the manifest.
    pub file: String,
    /// The JSON tree file beside the mesh, if any.
    pub tree: Option<String>,
    /// What the solid is.
    pub description: String,
    /// Its parameters.
    pub parameters: serde_json::Value,
    /// Ground truth.
    pub truth: Truth,
    /// The mesh's report as its file stores it (what `solidkit check --json` prints).
    pub mesh: TopologyReport,
    /// Measured minus true values and stated bounds.
    pub error: Errors,
    /// Defects put in (`broken` suite).
    pub defects: Option<Defects>,
}

/// A solid ready to write: its bytes, its tree (JSON text) and its manifest entry.
#[derive(Debug, Clone)]
pub struct Encoded {
    /// The mesh file's bytes.
    pub bytes: Vec<u8>,
    /// The tree file's text, if any.
    pub tree: Option<String>,
    /// The manifest entry.
    pub record: SolidRecord,
}

/// Encodes `solid` in `format` and measures the mesh as stored (see
/// [`stored_mesh`]): files named `NAME.EXT` and `NAME.json`.
pub fn encode(solid: &GenSolid, format: MeshFormat) -> Result<Encoded, MeshIoError> {
    let file = format!("{}.{}", solid.name, format.extension());
    let opts = WriteOptions {
        format: Some(format),
        ..WriteOptions::default()
    };
    let bytes = encode_mesh(&solid.mesh, &opts, &file)?;
    let stored = stored_mesh(&bytes, &solid.mesh, format, &file)?;
    let tree = solid.tree.as_ref().map(solidkit_kernel::json::to_string);
    let tree_file = tree.as_ref().map(|_| format!("{}.json", solid.name));
    Ok(Encoded {
        bytes,
        tree,
        record: SolidRecord::new(solid, file, tree_file, &stored),
    })
}

impl SolidRecord {
    /// The entry of `solid` whose mesh, as stored in `file`, is `stored`.
    pub fn new(
        solid: &GenSolid,
        file: String,
        tree: Option<String>,
        stored: &IndexedMesh,
    ) -> SolidRecord {
        let report = TopologyReport::of(stored);
        let t = &solid.truth;
        let diff = |measured: f64, truth: Option<f64>| truth.map(|v| measured - v);
        let rel = |measured: f64, truth: Option<f64>| {
            truth
                .filter(|v| *v != 0.0)
                .map(|v| (measured - v) / v.abs())
        };
        let volume = t.volume.map(|q| q.value);
        let area = t.area.map(|q| q.value);
        let dv = diff(report.volume, volume);
        let stated = [
            t.shells.map(|s| s == report.shells),
            t.genus.map(|g| Some(g) == report.genus),
            t.euler_characteristic
                .map(|c| c == report.euler_characteristic),
        ];
        let topology_matches = if stated.iter().all(Option::is_none) {
            None
        } else {
            Some(stated.iter().all(|s| s.unwrap_or(true)))
        };
        let error = Errors {
            volume: dv,
            volume_relative: rel(report.volume, volume),
            area: diff(report.area, area),
            area_relative: rel(report.area, area),
            chord_error_bound: solid.chord_error_bound,
            volume_tolerance: solid.volume_tolerance,
            volume_within_tolerance: solid
                .volume_tolerance
                .zip(dv)
                .map(|(tol, d)| d.abs() <= tol),
            topology_matches,
        };
        SolidRecord {
            name: solid.name.clone(),
            file,
            tree,
            description: solid.description.clone(),
            parameters: solid.parameters.clone(),
            truth: solid.truth.clone(),
            mesh: report,
            error,
            defects: solid.defects.clone(),
        }
    }
}
