//! Two meshes side by side: their key measures (topology reports without the self-intersection
//! count, which `check` gives) and their symmetric Hausdorff distance, absolute and relative to
//! the bounding-box diagonal of the first. What `solidkit compare` prints and the Python
//! package's `compare` returns, with the same JSON keys.

use super::{Hausdorff, TriangleTree, hausdorff_with};
use crate::{IndexedMesh, ReportOptions, TopologyReport};
use glam::DVec3;
use serde_json::{Value, json};

/// A comparison of meshes `a` and `b`.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Comparison {
    /// The first mesh's report.
    pub a: TopologyReport,
    /// The second mesh's report.
    pub b: TopologyReport,
    /// Their distances.
    pub hausdorff: Hausdorff,
    /// The bounding-box diagonal of `a`.
    pub diagonal: f64,
    /// `hausdorff.symmetric / diagonal`, when the diagonal is positive.
    pub relative: Option<f64>,
    /// Surface samples per mesh.
    pub samples: usize,
}

/// Compares `a` and `b` (with their distance trees) from `samples` area-weighted surface points
/// per mesh; the reports and the distances are computed in parallel.
pub fn compare(
    a: &IndexedMesh,
    tree_a: &TriangleTree,
    b: &IndexedMesh,
    tree_b: &TriangleTree,
    samples: usize,
) -> Comparison {
    let options = ReportOptions {
        self_intersections: false,
    };
    let ((ra, rb), h) = rayon::join(
        || {
            rayon::join(
                || TopologyReport::with_options(a, &options),
                || TopologyReport::with_options(b, &options),
            )
        },
        || hausdorff_with(a, tree_a, b, tree_b, samples),
    );
    let [lo, hi] = ra.bbox;
    let diagonal = DVec3::from(hi).distance(DVec3::from(lo));
    Comparison {
        relative: (diagonal > 0.0).then(|| h.symmetric / diagonal),
        a: ra,
        b: rb,
        hausdorff: h,
        diagonal,
        samples,
    }
}

impl Comparison {
    /// The JSON object of `solidkit compare --json`: `a` and `b` (reports) and `hausdorff`
    /// (keys documented in the README).
    pub fn to_json(&self) -> Value {
        let h = &self.hausdorff;
        json!({
            "a": serde_json::to_value(&self.a).unwrap_or(Value::Null),
            "b": serde_json::to_value(&self.b).unwrap_or(Value::Null),
            "hausdorff": {
                "symmetric": h.symmetric,
                "a_to_b": h.a_to_b.max,
                "b_to_a": h.b_to_a.max,
                "mean_a_to_b": h.a_to_b.mean,
                "mean_b_to_a": h.b_to_a.mean,
                "diagonal": self.diagonal,
                "relative": self.relative,
                "samples": self.samples,
                "points_a": h.a_to_b.count,
                "points_b": h.b_to_a.count,
            }
        })
    }
}
