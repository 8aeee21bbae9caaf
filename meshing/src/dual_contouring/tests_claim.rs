//! The construction claim of dual contouring (`claim.rs`): where a run claims to be free of
//! self-intersections, the exact test of [`crate::intersect`] finds none, on inputs that push the
//! certificate's margins (crossings against the samples in every cell pattern, coincident faces
//! on a coarse lattice); and the runs whose premises fail claim nothing.

use super::tests_manifold::{Crossings, Trilinear, assert_dual_of_mc};
use super::*;
use crate::TopologyReport;
use crate::marching_cubes::mesh_samples;
use glam::DVec3;
use solidkit_kernel::Solid;
use solidkit_kernel::models::SplitMix64;

/// Every one of the 256 patterns of a cell, 16 random neighbourhoods each, with sample magnitudes
/// spread over seven decades so crossings land against the samples (where the crossing margin
/// holds them) and vertices against the cell walls.
#[test]
fn crossings_against_the_samples_in_every_cell_pattern() {
    let mut rng = SplitMix64::new(91);
    let spec = GridSpec {
        origin: DVec3::new(-0.3, 0.2, 0.1),
        cell: 0.25,
        cells: [5, 5, 5],
    };
    let mut crossings = Crossings::default();
    let mut meshed = 0;
    for mask in 0..256usize {
        for trial in 0..16 {
            let mut values = vec![1.0f32; spec.sample_count()];
            for k in 1..5 {
                for j in 1..5 {
                    for i in 1..5 {
                        let v = 10f64.powf(rng.range(-7.0, 0.0)) as f32;
                        let centre = [i, j, k].iter().all(|&x| x == 2 || x == 3);
                        let inside = if centre {
                            mask >> ((i - 2) | (j - 2) << 1 | (k - 2) << 2) & 1 == 1
                        } else {
                            rng.next_f64() < 0.5
                        };
                        values[spec.index(i, j, k)] = if inside { -v } else { v };
                    }
                }
            }
            let samples = SampleGrid::from_values(spec, values).unwrap();
            let field = Trilinear(&samples);
            let dc = mesh_dc_samples(&field, &samples, None);
            let mc = mesh_samples(&samples);
            if mc.triangles.is_empty() {
                continue;
            }
            let what = format!("mask {mask} trial {trial}");
            crossings.note(&assert_dual_of_mc(&dc, &mc, &what), &what);
            meshed += 1;
        }
    }
    crossings.assert_none("cell patterns, crossings against the samples");
    assert!(meshed > 3500, "{meshed}");
}

/// A random tree of boxes and cylinders with integer coordinates (faces coincide, samples land
/// exactly on faces).
fn lattice_tree(rng: &mut SplitMix64) -> Solid {
    let mut int = |lo: i64, hi: i64| lo + (rng.next_u64() % (hi - lo + 1) as u64) as i64;
    let count = int(2, 5);
    let mut acc: Option<Solid> = None;
    for _ in 0..count {
        let c = DVec3::new(int(-2, 2) as f64, int(-2, 2) as f64, int(-2, 2) as f64);
        let part = if int(0, 2) == 0 {
            Solid::cylinder(int(1, 2) as f64, int(1, 4) as f64)
        } else {
            Solid::cuboid(DVec3::new(
                int(1, 4) as f64,
                int(1, 4) as f64,
                int(1, 4) as f64,
            ))
        }
        .translate(c);
        acc = Some(match (acc, int(0, 3)) {
            (None, _) => part,
            (Some(a), 0 | 1) => a.union(&part),
            (Some(a), 2) => a.difference(&part),
            (Some(a), _) => a.intersection(&part).union(&part.scale_uniform(0.5)),
        });
    }
    acc.expect("at least two parts")
}

/// Random lattice trees at resolutions from 8 to 40 (even and odd, so sample planes hit the
/// faces or miss them): every run claims, and the exact test agrees.
#[test]
fn lattice_trees_claim_and_the_exact_test_agrees() {
    let mut rng = SplitMix64::new(5);
    let mut crossings = Crossings::default();
    let mut claimed = 0;
    for tree in 0..300 {
        let s = lattice_tree(&mut rng);
        let bounds = s.bbox();
        if bounds.is_empty() {
            continue;
        }
        let res = 8 + (rng.next_u64() % 33) as usize;
        let spec = GridSpec::for_bounds(&bounds, res).unwrap();
        let (m, stats) = mesh_dc(&s.compile(), spec, &DcOptions::default()).unwrap();
        if m.triangles.is_empty() {
            continue;
        }
        assert!(stats.intersection_free, "tree {tree}: a plain grid claims");
        claimed += 1;
        crossings.note(&TopologyReport::of(&m), &format!("tree {tree} at {res}"));
    }
    crossings.assert_none("lattice trees");
    assert!(claimed > 250, "{claimed}");
}

/// No claim where a premise fails: simplification, or a grid so far from the origin that the
/// rounding of its coordinates reaches the margins. The same solid near the origin claims.
#[test]
fn runs_outside_the_premises_claim_nothing() {
    let s = Solid::sphere(1.0);
    let spec = GridSpec::for_bounds(&s.bbox(), 24).unwrap();
    let plain = mesh_dc(&s.compile(), spec, &DcOptions::default())
        .unwrap()
        .1;
    assert!(plain.intersection_free);
    let simplified = DcOptions {
        tolerance: Some(0.01),
        ..Default::default()
    };
    assert!(
        !mesh_dc(&s.compile(), spec, &simplified)
            .unwrap()
            .1
            .intersection_free
    );
    let far = s.translate(DVec3::new(3e4, 0.0, 0.0));
    let spec = GridSpec::for_bounds(&far.bbox(), 24).unwrap();
    let (m, stats) = mesh_dc(&far.compile(), spec, &DcOptions::default()).unwrap();
    assert!(!m.triangles.is_empty());
    assert!(
        !stats.intersection_free,
        "cells of 0.08 at 3e4: rounding within 64 ulp of the margin"
    );
}
