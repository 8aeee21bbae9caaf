//! Joined faces everywhere: sign checkerboards, where every cell face is ambiguous and the
//! asymptotic decider resolves each from random magnitudes, so cells hold one to four patches in
//! every configuration the decider gives (tunnels through joined faces, split faces, several
//! patches side by side). Crossings are searched on a second field with the same signs but other
//! magnitudes, so they fall anywhere on their edges. Each mesh must be closed, oriented,
//! 2-manifold, of marching cubes' topology on the same samples and free of self-intersections.

use super::tests_manifold::{Crossings, Trilinear, assert_dual_of_mc};
use super::*;
use crate::marching_cubes::mesh_samples;
use glam::DVec3;
use solidkit_kernel::models::SplitMix64;

/// Samples of an `n`³-cell checkerboard (inside where `i + j + k` is odd) with magnitudes from
/// `rng` up to `spread`, outside on the border so the surface closes.
fn checkerboard(spec: GridSpec, rng: &mut SplitMix64, spread: f64) -> SampleGrid {
    let n = spec.cells[0];
    let mut values = vec![1.0f32; spec.sample_count()];
    for k in 1..n {
        for j in 1..n {
            for i in 1..n {
                let m = rng.range(0.05, spread) as f32;
                values[spec.index(i, j, k)] = if (i + j + k) % 2 == 1 { -m } else { m };
            }
        }
    }
    SampleGrid::from_values(spec, values).unwrap()
}

#[test]
fn checkerboards_with_decided_faces() {
    let mut rng = SplitMix64::new(33);
    let spec = GridSpec {
        origin: DVec3::new(-0.3, 0.1, 0.2),
        cell: 0.125,
        cells: [7, 7, 7],
    };
    let table = patches::patch_table();
    // Cells with joined faces: one patch (tunnels), several patches.
    let (mut tunnels, mut several) = (0, 0);
    let mut crossings = Crossings::default();
    for trial in 0..40 {
        let spread = [1.0, 4.0, 50.0][trial % 3];
        let samples = checkerboard(spec, &mut rng, spread);
        let other = checkerboard(spec, &mut rng, spread);
        let field = Trilinear(&other);
        for b in sources::dense_blocks(&field, &samples, 8, false) {
            for &config in &b.configs {
                let c = table.get(config);
                if c.joined != 0 {
                    tunnels += usize::from(c.edges.len() == 1);
                    several += usize::from(c.edges.len() > 1);
                }
            }
        }
        let dc = mesh_dc_samples(&field, &samples, None);
        let mc = mesh_samples(&samples);
        let what = format!("trial {trial}");
        let r = assert_dual_of_mc(&dc, &mc, &what);
        crossings.note(&r, &what);
    }
    crossings.assert_none("checkerboards");
    assert!(tunnels > 500 && several > 500, "{tunnels} {several}");
}
