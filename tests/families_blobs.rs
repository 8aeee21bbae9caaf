//! Acceptance of blobby objects (issue 5): five metaballs meshed at 128³ are closed manifolds with
//! the expected shells and genus, their volume matches a Monte Carlo integral (standard error
//! stated and bounded) within 1%, and the mesh lies on the exact zero set within a small fraction
//! of a cell.

use glam::DVec3;
use solidkit_kernel::primitive::blob::{Ball, Blob};
use solidkit_kernel::{Primitive, Shape, Solid, json};
use solidkit_tests::{mesh, rel_err};
use std::sync::Arc;

const RESOLUTION: usize = 128;

/// Five equal balls on a circle of radius 1: neighbours merge into a ring around an open middle.
fn ring() -> Blob {
    let balls = (0..5)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 5.0;
            Ball {
                center: DVec3::new(t.cos(), t.sin(), 0.1 * (2.0 * t).sin()),
                strength: 1.0,
                sharpness: 3.0,
            }
        })
        .collect();
    Blob::new(balls, 0.5).unwrap()
}

/// Three merged balls and, apart, two merged balls of different sizes.
fn two_clusters() -> Blob {
    let ball = |x: f64, y: f64, z: f64, b: f64, a: f64| Ball {
        center: DVec3::new(x, y, z),
        strength: b,
        sharpness: a,
    };
    Blob::new(
        vec![
            ball(-1.2, 0.0, 0.0, 1.0, 4.0),
            ball(-0.7, 0.4, 0.1, 0.8, 5.0),
            ball(-0.8, -0.35, -0.2, 1.2, 3.5),
            ball(1.1, 0.1, 0.0, 1.0, 4.0),
            ball(1.5, -0.1, 0.3, 0.9, 6.0),
        ],
        0.45,
    )
    .unwrap()
}

/// Monte Carlo volume over the bounding box with `n` samples: (estimate, standard error).
fn monte_carlo_volume(blob: &Blob, n: usize) -> (f64, f64) {
    let b = blob.bbox();
    let size = b.size();
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let inside = (0..n)
        .filter(|_| {
            let p = b.min + size * DVec3::new(next(), next(), next());
            blob.value(p) < 0.0
        })
        .count();
    let p = inside as f64 / n as f64;
    let v = size.x * size.y * size.z;
    (v * p, v * (p * (1.0 - p) / n as f64).sqrt())
}

/// Distance from `p` to the zero set along the gradient line, by bisection on a bracket found by
/// stepping out (the exact root-finding reference).
fn distance_to_surface(blob: &Blob, p: DVec3, reach: f64) -> f64 {
    let f0 = blob.value(p);
    if f0 == 0.0 {
        return 0.0;
    }
    let dir = blob.gradient(p).normalize() * -f0.signum();
    let mut hi = reach / 64.0;
    while blob.value(p + dir * hi).signum() == f0.signum() {
        hi *= 2.0;
        assert!(hi <= reach, "no sign change near {p}");
    }
    let mut lo = 0.0;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if blob.value(p + dir * mid).signum() == f0.signum() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

fn check(blob: Blob, shells: usize, genus: i64) {
    let solid = Solid::primitive(Primitive::Blob(Arc::new(blob.clone())));
    let (m, r) = mesh(&solid, RESOLUTION);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!(r.shells, shells);
    assert_eq!(r.genus, Some(genus));
    // Volume against Monte Carlo with 4·10⁶ samples; its standard error is well below 1%.
    let (reference, se) = monte_carlo_volume(&blob, 4_000_000);
    assert!(
        se / reference < 1.5e-3,
        "standard error {se} of {reference}"
    );
    assert!(
        rel_err(r.volume, reference) < 0.01,
        "volume {} vs {reference} ± {se}",
        r.volume
    );
    // Every vertex is within a tenth of a cell of the exact zero set.
    let cell = blob.bbox().size().max_element() / RESOLUTION as f64;
    let worst = m
        .positions
        .iter()
        .map(|&p| distance_to_surface(&blob, p, 4.0 * cell))
        .fold(0.0, f64::max);
    eprintln!(
        "blob: volume {} vs Monte Carlo {reference} ± {se} ({:.3}%), worst vertex {:.4} cells",
        r.volume,
        100.0 * rel_err(r.volume, reference),
        worst / cell
    );
    assert!(
        worst < 0.1 * cell,
        "vertex {worst} from the surface (cell {cell})"
    );
}

#[test]
fn five_metaballs_in_a_ring_have_genus_one() {
    check(ring(), 1, 1);
}

#[test]
fn five_metaballs_in_two_clusters_are_two_shells() {
    check(two_clusters(), 2, 0);
}

#[test]
fn blob_round_trips_through_json() {
    let text = r#"{"type": "blob", "threshold": 0.5, "balls": [
        {"center": [0, 0, 0], "strength": 1, "sharpness": 3},
        {"center": [1, 0, 0.5], "strength": -0.4, "sharpness": 8}]}"#;
    let s = json::from_str(text).unwrap();
    assert_eq!(s, json::from_str(&json::to_string(&s)).unwrap());
    let e = json::from_str(
        r#"{"type": "blob", "threshold": 0.5, "balls": [{"center": [0, 0, 0], "strength": 1, "sharpness": -3}]}"#,
    )
    .unwrap_err();
    assert!(e.to_string().contains("balls[0].sharpness"), "{e}");
}
