//! `manifest.json`: the suite, its options and one [`SolidRecord`] per solid, in a fixed order
//! with shortest round-trip numbers, so the same suite and options always give the same bytes.
//! The schema is documented in `docs/gen.md`.

use super::record::SolidRecord;
use super::sampling::{REPLICATES, STRATA};
use super::{Suite, SuiteOptions};
use crate::io::MeshFormat;
use serde::Serialize;

/// The value of the manifest's `format` key.
pub const FORMAT: &str = "solidkit-gen";
/// The manifest schema version.
pub const VERSION: u32 = 1;

/// How sampled volumes were taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct SamplingInfo {
    /// `"jittered stratified"`.
    pub method: &'static str,
    /// Strata per axis of each replicate.
    pub strata: usize,
    /// Independent replicates (the standard error is their standard deviation over √R).
    pub replicates: usize,
}

/// The manifest of one suite.
#[derive(Debug, Clone, Serialize)]
pub struct Manifest {
    /// Always [`FORMAT`].
    pub format: &'static str,
    /// Always [`VERSION`].
    pub version: u32,
    /// The program that wrote it.
    pub generator: String,
    /// The suite's name.
    pub suite: &'static str,
    /// The mesh files' format (extension).
    pub mesh_format: &'static str,
    /// Options as given (each suite uses the ones it needs).
    pub seed: u64,
    /// See [`SuiteOptions::resolution`].
    pub resolution: usize,
    /// See [`SuiteOptions::count`].
    pub count: usize,
    /// How sampled volumes were taken.
    pub sampling: SamplingInfo,
    /// One entry per solid.
    pub solids: Vec<SolidRecord>,
}

impl Manifest {
    /// The manifest of `suite` with `opts`, for meshes written as `format`.
    pub fn new(
        suite: Suite,
        opts: &SuiteOptions,
        format: MeshFormat,
        solids: Vec<SolidRecord>,
    ) -> Manifest {
        Manifest {
            format: FORMAT,
            version: VERSION,
            generator: format!("solidkit {}", env!("CARGO_PKG_VERSION")),
            suite: suite.name(),
            mesh_format: format.extension(),
            seed: opts.seed,
            resolution: opts.resolution,
            count: opts.count,
            sampling: SamplingInfo {
                method: "jittered stratified",
                strata: STRATA,
                replicates: REPLICATES,
            },
            solids,
        }
    }

    /// The manifest as pretty-printed JSON (with a final newline).
    pub fn to_json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).unwrap_or_else(|e| {
            // Serialising plain structs of numbers and strings cannot fail.
            format!("{{\"error\": \"{e}\"}}")
        });
        s.push('\n');
        s
    }
}
