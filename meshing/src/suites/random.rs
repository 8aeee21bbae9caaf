//! The `random` suite: `count` random CSG trees (see `random_tree.rs`: unions, differences and
//! intersections of rotated and translated spheres, boxes, cylinders, cones and tori) from a
//! seed, each polygonised by solidkit at `resolution` and written with its JSON tree beside the
//! mesh, so another tool can rebuild it.
//!
//! Truth: the volume by jittered stratified sampling of the exact field ([`sample_volume`],
//! [`STRATA`]³ points × [`REPLICATES`] replicates) with its standard error `σ`. The mesh volume is
//! stated to be within `volume_tolerance = 4σ + 2 |V_N − V_{N/2}|` of it (see
//! [`csg`](super::csg) for the rule). Genus, shells and bounding box are not stated.
//!
//! Tree `i` draws from its own stream, `SplitMix64(seed + i · φ64)`; a tree whose sampled volume
//! is below 2% of its bounding box or 0.01 (mostly empty intersections) is redrawn from the same
//! stream, so every tree is reproducible on its own.

use super::csg::meshed;
use super::polygonize::Grid;
use super::random_tree::random_tree;
use super::sampling::{REPLICATES, STRATA, sample_volume};
use super::truth::{Quantity, Truth};
use super::{GenSolid, SuiteError, SuiteOptions, build_error};
use rayon::prelude::*;
use serde_json::json;
use solidkit_kernel::models::SplitMix64;

/// Redraws allowed before giving up on a tree.
const ATTEMPTS: usize = 200;

/// The file stem of tree `i`.
pub fn name(i: usize) -> String {
    format!("random_{i:03}")
}

/// The suite's solids.
pub fn solids(opts: &SuiteOptions) -> Result<Vec<GenSolid>, SuiteError> {
    (0..opts.count)
        .into_par_iter()
        .map(|i| one(i, opts))
        .collect()
}

fn one(i: usize, opts: &SuiteOptions) -> Result<GenSolid, SuiteError> {
    let name = name(i);
    let stream = opts
        .seed
        .wrapping_add((i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    let mut rng = SplitMix64::new(stream);
    for attempt in 0..ATTEMPTS {
        let solid = random_tree(&mut rng);
        let bounds = solid.bbox();
        let size = bounds.size();
        if bounds.is_empty() || !bounds.is_finite() {
            continue;
        }
        let s = sample_volume(&solid.compile(), &bounds, STRATA, REPLICATES, stream);
        if s.volume < 0.02 * size.x * size.y * size.z || s.volume < 0.01 {
            continue;
        }
        let truth = Truth {
            volume: Some(Quantity::sampled(s.volume, s.standard_error)),
            ..Truth::default()
        }
        .with_note("volume by sampling; genus, shells and bounding box not stated");
        let parameters = json!({
            "index": i,
            "seed": opts.seed,
            "attempt": attempt,
            "nodes": solid.node_count(),
            "depth": solid.depth(),
            "resolution": opts.resolution,
            "sampled_points": s.points,
        });
        return meshed(
            name.clone(),
            format!("random CSG tree {i} of seed {}", opts.seed),
            parameters,
            solid,
            truth,
            opts.resolution,
            Grid::Bounds,
        );
    }
    Err(build_error(&name, "no usable tree in 200 draws"))
}
