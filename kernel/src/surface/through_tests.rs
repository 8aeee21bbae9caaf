//! The interpolating patch through 16 points: it passes through them, its Bézier net reproduces
//! it, it agrees with the curve version along its grid lines, and it closes into a solid.

use super::*;
use crate::curve::{CubicThrough, Curve3};
use crate::primitive::NoMeshResolver;
use glam::DVec3;

/// 16 points of a wavy graph over [0, 3]², `Pᵢⱼ` at `4j + i`.
fn grid_points() -> Vec<DVec3> {
    let mut p = Vec::new();
    for j in 0..4 {
        for i in 0..4 {
            let (x, y) = (i as f64, j as f64);
            p.push(DVec3::new(
                x + 0.1 * y,
                y - 0.05 * x * x,
                (x * 1.3).sin() * (0.7 * y).cos() + 0.2 * x * y,
            ));
        }
    }
    p
}

#[test]
fn passes_through_its_16_points() {
    let pts = grid_points();
    let patch = InterpolatingPatch::new(&pts).unwrap();
    for j in 0..4 {
        for i in 0..4 {
            let d = patch.bezier().derivatives(i as f64 / 3.0, j as f64 / 3.0);
            let err = (d.p - pts[4 * j + i]).length();
            assert!(err < 1e-12, "P{i}{j}: {err}");
        }
    }
}

#[test]
fn bezier_net_reproduces_the_power_form_and_the_curves() {
    let pts = grid_points();
    let patch = InterpolatingPatch::new(&pts).unwrap();
    let net = bezier_net(pts.as_slice().try_into().unwrap());
    assert_eq!(patch.bezier().points(), net.as_slice());
    assert_eq!(patch.bezier().degrees(), [3, 3]);
    // Along each row v = j/3 the patch is the 4-point cubic through the row; along u = i/3 the
    // cubic through the column. Between grid lines, the de Casteljau value of the net equals the
    // tensor product of the curves (row curves evaluated at u, then the cubic through them at v).
    for k in 0..=20 {
        let (u, v) = (k as f64 / 20.0, (20 - k) as f64 / 20.0 * 0.9 + 0.05);
        let column: Vec<DVec3> = (0..4)
            .map(|j| {
                CubicThrough::new(&pts[4 * j..4 * j + 4])
                    .unwrap()
                    .jet(u)
                    .point
            })
            .collect();
        let expected = CubicThrough::new(&column).unwrap().jet(v).point;
        let got = patch.bezier().derivatives(u, v).p;
        assert!((got - expected).length() < 1e-12, "({u}, {v})");
        // Bernstein sum over the net by hand.
        let b = |t: f64| {
            let s = 1.0 - t;
            [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
        };
        let (bu, bv) = (b(u), b(v));
        let mut sum = DVec3::ZERO;
        for j in 0..4 {
            for i in 0..4 {
                sum += net[4 * j + i] * (bu[i] * bv[j]);
            }
        }
        assert!((sum - got).length() < 1e-12, "({u}, {v})");
    }
}

#[test]
fn a_bicubic_through_its_own_samples_is_itself() {
    // Sampling a bicubic Bézier patch at the thirds and interpolating gives its net back.
    let net: Vec<DVec3> = (0..16)
        .map(|k| DVec3::new((k % 4) as f64, (k / 4) as f64, ((k * 7) % 5) as f64 * 0.3))
        .collect();
    let original = TensorSurface::bezier([4, 4], net.clone()).unwrap();
    let samples: Vec<DVec3> = (0..16)
        .map(|k| {
            original
                .derivatives((k % 4) as f64 / 3.0, (k / 4) as f64 / 3.0)
                .p
        })
        .collect();
    let again = InterpolatingPatch::new(&samples).unwrap();
    for (a, b) in again.bezier().points().iter().zip(&net) {
        assert!((*a - *b).length() < 1e-12, "{a} vs {b}");
    }
}

#[test]
fn closes_into_a_solid_and_refuses_bad_points() {
    let spec = SurfaceSpec {
        kind: SurfaceKind::Interpolating(InterpolatingPatch::new(&grid_points()).unwrap()),
        closure: Closure::Base { z: -3.0 },
        tolerance: Some(1e-3),
        segments: None,
        adaptive: false,
    };
    let sheet = spec.sheet(&NoMeshResolver).unwrap();
    assert!(!sheet.estimated && sheet.chord_error.unwrap() <= 1e-3);
    let m = spec.closed_mesh(&NoMeshResolver).unwrap();
    let mut count = std::collections::HashMap::new();
    for t in &m.triangles {
        for c in 0..3 {
            *count.entry((t[c], t[(c + 1) % 3])).or_insert(0) += 1;
        }
    }
    assert!(
        count
            .iter()
            .all(|(&(a, b), &n)| n == 1 && count.get(&(b, a)) == Some(&1))
    );
    assert_eq!(
        InterpolatingPatch::new(&grid_points()[..15])
            .unwrap_err()
            .key(),
        "points"
    );
    let mut bad = grid_points();
    bad[5].z = f64::NAN;
    assert!(InterpolatingPatch::new(&bad).is_err());
}
