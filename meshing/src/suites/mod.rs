//! Test solids with ground truth (`solidkit gen`): suites of meshes for checking other geometry
//! tools (slicers, mesh Booleans, remeshers, FEM meshers), each solid with its exact (or
//! quadrature, or sampled) volume, area, genus, shells, Euler characteristic and bounding box, and
//! a statement of how the truth was obtained.
//!
//! One file per suite: [`platonic`] (Platonic solids, duals, prisms), [`sponge`] (Menger sponges
//! as exact polyhedra), [`smooth`] (parametric tessellations with a chord-error bound), [`csg`]
//! (solids polygonised by solidkit), [`random`] (random CSG trees from a seed, volumes by
//! sampling) and [`broken`] (meshes with known defects). [`generate`] builds a suite's solids;
//! [`record::SolidRecord`] measures a solid as its file stores it and states the errors;
//! [`manifest::Manifest`] is the `manifest.json` written beside the files (schema in
//! `docs/gen.md`), [`write_suite`] writes a suite into a folder and [`Manifest::failures`]
//! lists what contradicts its stated truth.
//!
//! Everything is deterministic: the same suite and options give the same meshes, trees and
//! manifest, bit for bit, whatever the number of threads (solids are built in parallel, each on
//! its own; sampling sums integer counts).

pub mod broken;
pub mod csg;
pub mod manifest;
pub mod platonic;
mod polygonize;
pub mod quadrature;
pub mod random;
mod random_tree;
pub mod record;
pub mod sampling;
mod selfcheck;
pub mod smooth;
pub mod sponge;
pub mod truth;
mod write;

pub use manifest::Manifest;
pub use record::SolidRecord;
pub use truth::{Quantity, Truth, TruthMethod};
pub use write::{WriteSuiteError, write_suite};

use crate::IndexedMesh;
use solidkit_kernel::Solid;

/// A suite of test solids.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Suite {
    /// The five Platonic solids, their duals and four prisms, as exact polyhedral meshes.
    Platonic,
    /// Menger sponges of levels 0 to 4 as exact polyhedral meshes.
    Sponge,
    /// Parametric tessellations of smooth solids with a stated chord error.
    Smooth,
    /// CSG solids polygonised by solidkit (marching cubes).
    Csg,
    /// Random CSG trees from a seed, polygonised by solidkit, volumes by sampling.
    Random,
    /// Meshes with known defects, for testing mesh checkers.
    Broken,
}

impl Suite {
    /// Every suite, in documentation order.
    pub const ALL: [Suite; 6] = [
        Suite::Platonic,
        Suite::Sponge,
        Suite::Smooth,
        Suite::Csg,
        Suite::Random,
        Suite::Broken,
    ];

    /// The suite's name on the command line and in manifests.
    pub fn name(self) -> &'static str {
        match self {
            Suite::Platonic => "platonic",
            Suite::Sponge => "sponge",
            Suite::Smooth => "smooth",
            Suite::Csg => "csg",
            Suite::Random => "random",
            Suite::Broken => "broken",
        }
    }

    /// The suite called `name`.
    pub fn from_name(name: &str) -> Option<Suite> {
        Suite::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// Options of a suite; each suite reads the ones it needs and the manifest records them all.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SuiteOptions {
    /// Seed of the `random` suite's trees and of every sampling.
    pub seed: u64,
    /// `csg`, `random`: marching-cubes cells along the longest side of each solid's bounding
    /// box; `smooth`: segments around a full turn.
    pub resolution: usize,
    /// `random`: how many trees.
    pub count: usize,
}

/// Smallest and largest `resolution`.
pub const RESOLUTION_RANGE: (usize, usize) = (8, 2048);
/// Largest `count`.
pub const MAX_COUNT: usize = 10_000;

impl Default for SuiteOptions {
    fn default() -> Self {
        SuiteOptions {
            seed: 0,
            resolution: 64,
            count: 8,
        }
    }
}

/// Options out of range.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SuiteError {
    /// `resolution` outside [`RESOLUTION_RANGE`].
    #[error("resolution must be {lo} to {hi}, got {0}", lo = RESOLUTION_RANGE.0, hi = RESOLUTION_RANGE.1)]
    Resolution(usize),
    /// `count` zero or above [`MAX_COUNT`].
    #[error("count must be 1 to {MAX_COUNT}, got {0}")]
    Count(usize),
    /// A solid could not be built (a bug: the suites' parameters are fixed).
    #[error("{name}: {problem}")]
    Build {
        /// The solid.
        name: String,
        /// What went wrong.
        problem: String,
    },
}

impl SuiteOptions {
    /// Checks the ranges.
    pub fn check(&self) -> Result<(), SuiteError> {
        if !(RESOLUTION_RANGE.0..=RESOLUTION_RANGE.1).contains(&self.resolution) {
            return Err(SuiteError::Resolution(self.resolution));
        }
        if !(1..=MAX_COUNT).contains(&self.count) {
            return Err(SuiteError::Count(self.count));
        }
        Ok(())
    }
}

/// One generated solid: its mesh, its ground truth and what the manifest says about it.
#[derive(Debug, Clone)]
pub struct GenSolid {
    /// File stem, unique within the suite (`tetrahedron`, `menger_3`, `random_007`).
    pub name: String,
    /// One sentence on what it is.
    pub description: String,
    /// The parameters it was built from.
    pub parameters: serde_json::Value,
    /// The mesh to write.
    pub mesh: IndexedMesh,
    /// Ground truth of the solid the mesh stands for.
    pub truth: Truth,
    /// Bound of the distance from any point of the mesh to the exact surface (0 for exact
    /// polyhedra), where one is known.
    pub chord_error_bound: Option<f64>,
    /// The error the mesh's volume is stated to be within of the truth's, where one is stated.
    pub volume_tolerance: Option<f64>,
    /// The CSG tree to write beside the mesh (`csg`, `random`).
    pub tree: Option<Solid>,
    /// The defects built into the mesh (`broken`).
    pub defects: Option<broken::Defects>,
}

/// The solids of `suite` with `opts`, in manifest order.
pub fn generate(suite: Suite, opts: &SuiteOptions) -> Result<Vec<GenSolid>, SuiteError> {
    opts.check()?;
    match suite {
        Suite::Platonic => platonic::solids(),
        Suite::Sponge => sponge::solids(),
        Suite::Smooth => smooth::solids(opts.resolution),
        Suite::Csg => csg::solids(opts),
        Suite::Random => random::solids(opts),
        Suite::Broken => Ok(broken::solids()),
    }
}

/// A [`SuiteError::Build`] for solid `name`.
pub(crate) fn build_error(name: &str, problem: impl std::fmt::Display) -> SuiteError {
    SuiteError::Build {
        name: name.to_owned(),
        problem: problem.to_string(),
    }
}
