//! Acceptance of the swept volume (issue 21) at resolution 128: the fixtures
//! `fixtures/sweeps/swept_*.json` mesh to closed, oriented manifolds without self-intersections,
//! with volumes against the exact ones: a sphere along a segment is the capsule
//! `πr²L + 4/3·πr³`, a sphere around a circle the torus `2π²Rr²` (Pappus), a box translated
//! along a segment the longer box. The copies are spaced within the tolerance (default: the
//! child's diagonal / 50), whose sampling error (`≤ τ/2` in distance) is far below 1 %.

use solidkit_kernel::NodeKind;
use solidkit_meshing::TopologyReport;
use solidkit_tests::{load_tree, mesh, rel_err};
use std::f64::consts::PI;

const RESOLUTION: usize = 128;

/// Meshes a fixture, checks it is a closed manifold with `shells` and `genus`, and returns the
/// report.
fn check(fixture: &str, shells: usize, genus: i64) -> TopologyReport {
    let solid = load_tree(&format!("sweeps/{fixture}"));
    assert!(
        matches!(solid.kind(), NodeKind::Union),
        "{fixture}: a swept volume reads as the union of its copies"
    );
    let (_, r) = mesh(&solid, RESOLUTION);
    assert!(r.is_closed_manifold(), "{fixture}: {r:?}");
    assert_eq!(r.shells, shells, "{fixture}: shells");
    assert_eq!(r.genus, Some(genus), "{fixture}: genus");
    println!(
        "{fixture}: {} copies, volume {:.6}",
        solid.children().len(),
        r.volume
    );
    r
}

fn assert_volume(fixture: &str, r: &TopologyReport, exact: f64, within: f64) {
    assert!(
        rel_err(r.volume, exact) < within,
        "{fixture}: volume {} vs exact {exact} ({:.3}%)",
        r.volume,
        100.0 * rel_err(r.volume, exact)
    );
}

#[test]
fn sphere_along_a_segment_is_a_capsule() {
    let (r, l) = (0.5, 2.0);
    let report = check("swept_capsule.json", 1, 0);
    let exact = PI * r * r * l + 4.0 / 3.0 * PI * r * r * r;
    assert_volume("swept_capsule.json", &report, exact, 0.01);
}

#[test]
fn sphere_around_a_circle_is_a_torus() {
    let (big, r) = (2.0, 0.5);
    let report = check("swept_torus.json", 1, 1);
    assert_volume(
        "swept_torus.json",
        &report,
        2.0 * PI * PI * big * r * r,
        0.01,
    );
}

#[test]
fn box_translated_along_a_segment_is_the_longer_box() {
    let report = check("swept_box_fixed.json", 1, 0);
    // Axis-aligned faces: marching cubes interpolates planar distances exactly.
    assert_volume("swept_box_fixed.json", &report, 4.0, 1e-3);
}

#[test]
fn holed_box_along_a_bezier_with_rmf_is_a_bent_tube() {
    let report = check("swept_holed_box_bezier.json", 1, 1);
    // The tube's cross-section (0.25 − π·0.12²) times its length lies between the path's chord
    // plus the cube's length and the control polygon's length plus it.
    let area = 0.25 - PI * 0.12 * 0.12;
    let chord = (3f64 * 3.0 + 2.0 * 2.0 + 0.8 * 0.8).sqrt();
    let polygon = 1.5 + (0.5f64 * 0.5 + 1.5 * 1.5 + 0.8 * 0.8).sqrt() + (1.0f64 + 0.25).sqrt();
    assert!(
        report.volume > 0.95 * area * (chord + 0.5)
            && report.volume < 1.05 * area * (polygon + 0.5),
        "volume {} outside [{}, {}]",
        report.volume,
        area * (chord + 0.5),
        area * (polygon + 0.5)
    );
}
