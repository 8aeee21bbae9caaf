//! The check of a benchmark case's mesh against what is known of its model, so a fast but wrong
//! mesh shows.

use serde::{Deserialize, Serialize};

/// The check of a case's mesh.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Check {
    /// No boundary edges.
    pub closed: bool,
    /// No non-manifold edges or vertices.
    pub manifold: bool,
    /// Connected components.
    pub shells: usize,
    /// Genus of the mesh (`None` unless every shell is a closed oriented manifold).
    pub genus: Option<i64>,
    /// The model's exact genus, where known.
    pub expected_genus: Option<i64>,
    /// Volume of the mesh.
    pub volume: f64,
    /// The model's exact volume, where known.
    pub expected_volume: Option<f64>,
}

impl Check {
    /// Relative volume error, where the exact volume is known.
    pub fn volume_error(&self) -> Option<f64> {
        self.expected_volume.map(|v| (self.volume - v) / v)
    }

    /// Closed, manifold, and the genus is right where it is known.
    pub fn passed(&self) -> bool {
        self.closed && self.manifold && self.expected_genus.is_none_or(|g| self.genus == Some(g))
    }
}
