//! Benchmark and reference models, each with its exact ground truth.
//!
//! - `sphere` ([`sphere_bench`]), over `[-1, 1]³`: volume `4/3 π 0.6³`, genus 0.
//! - `gyroid-sphere` ([`gyroid_sphere`]), over `[-1, 1]³`: the zero set of
//!   `max(‖P‖ − 25, abs(g(P)) − 0.2)` with `P = 30 p`.
//! - `menger-L` ([`menger`]), over `[-0.5, 0.5]³` padded by [`MENGER_PAD`]: volume `(20/27)^L`,
//!   genus [`menger_genus`]; [`menger_mesh`] is the same solid as an exact polyhedral mesh.
//! - `many-N` ([`many`]), over `[-1, 1]³`: `N` primitives, `2N + 2` nodes.
//!
//! [`Model::by_name`] turns these names into a [`Model`]: the solid, the box the benchmarks mesh it
//! over (with `GridSpec::covering`: exactly `n` cells along the longest side, no padding) and the
//! facts a mesh of it can be checked against. [`workload`] holds the deterministic point sets and
//! boxes of the raw evaluation benchmarks.

mod gyroid_sphere;
mod many;
mod menger;
mod menger_mesh;
mod rng;
mod sphere;
pub mod workload;

pub use gyroid_sphere::{GYROID_SCALE, GYROID_SPHERE_RADIUS, GYROID_THICKNESS, gyroid_sphere};
pub use many::{MANY_DEFAULT_SEED, many};
pub use menger::{MENGER_PAD, menger, menger_bar_count, menger_genus, menger_volume};
pub use menger_mesh::{
    menger_area, menger_keeps, menger_mesh, menger_mesh_counts, menger_square_count, menger_voxels,
};
pub use rng::SplitMix64;
pub use sphere::{SPHERE_RADIUS, sphere_bench};

use crate::{Aabb, Solid};
use glam::DVec3;

/// Names of the benchmark models, in the order `solidkit bench` runs them by default.
pub const BENCH_MODELS: [&str; 4] = ["sphere", "gyroid-sphere", "menger-4", "many-8456"];

/// Highest Menger level [`Model::by_name`] accepts (level 5 has 22 143 bars).
pub const MAX_MENGER_LEVEL: u32 = 5;

/// Most primitives [`Model::by_name`] accepts for `many-N`.
pub const MAX_MANY: usize = 1 << 20;

/// A named model: the solid, where to mesh it, and what is exactly known about it.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    /// The name it was asked for (`sphere`, `menger-4`, …).
    pub name: String,
    /// The solid.
    pub solid: Solid,
    /// The box to mesh over; the solid lies strictly inside it.
    pub domain: Aabb,
    /// Exact volume, where known.
    pub volume: Option<f64>,
    /// Exact genus (summed over shells), where known.
    pub genus: Option<i64>,
    /// Resolutions (cells along the longest side of the domain) benchmarked by default.
    pub default_resolutions: Vec<usize>,
}

/// A model name that names no model.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ModelError {
    /// Not one of the known names.
    #[error("unknown model '{0}' (known: sphere, gyroid-sphere, menger-L, many-N)")]
    Unknown(String),
    /// A known family with a parameter out of range.
    #[error("model '{name}': {problem}")]
    BadParameter {
        /// The name as given.
        name: String,
        /// What is wrong with its parameter.
        problem: String,
    },
}

impl Model {
    /// The model called `name`: `sphere`, `gyroid-sphere`, `menger-L` (level `L` from 0 to
    /// [`MAX_MENGER_LEVEL`]) or `many-N` (`N` primitives, 2 to [`MAX_MANY`], default seed).
    pub fn by_name(name: &str) -> Result<Model, ModelError> {
        let cube = |h: f64| Aabb::centered(DVec3::splat(h));
        let model = |solid, domain, volume, genus, res: &[usize]| Model {
            name: name.to_owned(),
            solid,
            domain,
            volume,
            genus,
            default_resolutions: res.to_vec(),
        };
        if name == "sphere" {
            let r = SPHERE_RADIUS;
            let volume = 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
            return Ok(model(
                sphere_bench(),
                cube(1.0),
                Some(volume),
                Some(0),
                &[128, 256, 512, 1024],
            ));
        }
        if name == "gyroid-sphere" {
            return Ok(model(gyroid_sphere(), cube(1.0), None, None, &[128, 256]));
        }
        let bad = |problem: String| ModelError::BadParameter {
            name: name.to_owned(),
            problem,
        };
        if let Some(level) = name.strip_prefix("menger-") {
            let level: u32 = level
                .parse()
                .ok()
                .filter(|l| *l <= MAX_MENGER_LEVEL)
                .ok_or_else(|| bad(format!("level must be 0 to {MAX_MENGER_LEVEL}")))?;
            return Ok(model(
                menger(level),
                cube(0.5 + MENGER_PAD),
                Some(menger_volume(level)),
                Some(menger_genus(level)),
                &[512],
            ));
        }
        if let Some(count) = name.strip_prefix("many-") {
            let count: usize = count
                .parse()
                .ok()
                .filter(|n| (2..=MAX_MANY).contains(n))
                .ok_or_else(|| bad(format!("primitive count must be 2 to {MAX_MANY}")))?;
            return Ok(model(
                many(count, MANY_DEFAULT_SEED),
                cube(1.0),
                None,
                None,
                &[256],
            ));
        }
        Err(ModelError::Unknown(name.to_owned()))
    }
}

#[cfg(test)]
mod tests;
