//! Tests of blobby objects: conformance, the Lipschitz constant is reached, the bounding box
//! holds the solid, and the f32 batch path.

use super::*;
use crate::primitive::conformance::{Rng, check_shape};

/// Five balls in a ring of radius 1 (as in the acceptance test): neighbours merge, the middle
/// stays open.
pub(crate) fn ring() -> Blob {
    let balls = (0..5)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 5.0;
            Ball {
                center: DVec3::new(t.cos(), t.sin(), 0.0),
                strength: 1.0,
                sharpness: 3.0,
            }
        })
        .collect();
    Blob::new(balls, 0.5).unwrap()
}

#[test]
fn ring_conforms() {
    check_shape(&ring(), 2.0);
}

#[test]
fn subtractive_balls_conform() {
    let balls = vec![
        Ball {
            center: DVec3::ZERO,
            strength: 2.0,
            sharpness: 1.0,
        },
        Ball {
            center: DVec3::new(0.5, 0.0, 0.2),
            strength: -1.0,
            sharpness: 6.0,
        },
    ];
    let blob = Blob::new(balls, 0.7).unwrap();
    check_shape(&blob, 2.0);
    assert!(blob.value(DVec3::new(0.5, 0.0, 0.2)) > blob.value(DVec3::new(-0.5, 0.0, -0.2)));
}

#[test]
fn lipschitz_constant_is_reached_by_one_ball() {
    let ball = Ball {
        center: DVec3::ZERO,
        strength: 1.5,
        sharpness: 2.0,
    };
    let blob = Blob::new(vec![ball], 0.3).unwrap();
    let r = 1.0 / (2.0f64 * 2.0).sqrt();
    let slope = blob.gradient(DVec3::new(r, 0.0, 0.0)).length();
    assert!((slope - blob.lipschitz()).abs() < 1e-12, "{slope}");
}

#[test]
fn bbox_holds_the_solid() {
    let blob = ring();
    let b = blob.bbox();
    let mut rng = Rng::new(31);
    // Every point on the box's faces is outside.
    for _ in 0..20000 {
        let mut p = b.center() + rng.vec(1.0) * b.half_extents();
        let axis = (rng.next().abs() * 3.0) as usize % 3;
        p[axis] = if rng.next() > 0.0 {
            b.max[axis]
        } else {
            b.min[axis]
        };
        assert!(blob.value(p) > 0.0, "{p}");
    }
    // The box is not far from tight: the single-ball reach along x is inside it.
    let reach = blob.balls()[0].reach(0.5);
    assert!(b.max.x >= 1.0 + reach);
}

#[test]
fn term_range_is_exact_for_a_box_around_the_centre() {
    let ball = Ball {
        center: DVec3::new(0.2, 0.1, 0.0),
        strength: 2.0,
        sharpness: 1.5,
    };
    let b = Aabb::new(DVec3::splat(-1.0), DVec3::new(1.0, 0.5, 0.25));
    let iv = ball.term_range(&b);
    assert!((iv.hi - 2.0).abs() < 1e-15);
    let far = DVec3::new(-1.0, -1.0, -1.0);
    assert!((iv.lo - ball.term(far)).abs() < 1e-15);
}

#[test]
fn invalid_blobs_are_rejected() {
    let ball = Ball {
        center: DVec3::ZERO,
        strength: 1.0,
        sharpness: 1.0,
    };
    assert_eq!(Blob::new(vec![], 0.5).unwrap_err().parameter, "balls");
    assert_eq!(
        Blob::new(vec![ball], 1.0).unwrap_err().parameter,
        "threshold"
    );
    assert_eq!(
        Blob::new(vec![ball], 0.0).unwrap_err().parameter,
        "threshold"
    );
    let bad = Ball {
        sharpness: -1.0,
        ..ball
    };
    assert_eq!(
        Blob::new(vec![bad], 0.5).unwrap_err().parameter,
        "sharpness"
    );
    let bad = Ball {
        strength: f64::NAN,
        ..ball
    };
    assert_eq!(Blob::new(vec![bad], 0.5).unwrap_err().parameter, "strength");
}

#[test]
fn batch_path_matches_scalar_on_many_points() {
    let blob = ring();
    let mut rng = Rng::new(37);
    let pts: Vec<DVec3> = (0..1000).map(|_| rng.vec(2.0)).collect();
    let x: Vec<f32> = pts.iter().map(|p| p.x as f32).collect();
    let y: Vec<f32> = pts.iter().map(|p| p.y as f32).collect();
    let z: Vec<f32> = pts.iter().map(|p| p.z as f32).collect();
    let mut out = vec![0f32; pts.len()];
    blob.values_f32(&x, &y, &z, &mut out);
    for (p, o) in pts.iter().zip(&out) {
        assert!((*o as f64 - blob.value(*p)).abs() < 1e-5);
    }
}

/// `n` balls of mixed strengths and sharpnesses scattered in a cube of side `side`.
fn scattered(n: usize, side: f64, seed: u64) -> Blob {
    let mut rng = Rng::new(seed);
    let balls = (0..n)
        .map(|k| Ball {
            center: DVec3::splat(0.5 * side) + rng.vec(0.5 * side),
            strength: if k % 7 == 3 {
                -0.5
            } else {
                1.0 + 0.5 * rng.next()
            },
            sharpness: 3.0 + 2.0 * rng.next(),
        })
        .collect();
    Blob::new(balls, 0.5).unwrap()
}

/// The batch values of every term, as before culling (the reference).
fn full_values_f32(blob: &Blob, x: &[f32], y: &[f32], z: &[f32]) -> Vec<f32> {
    let mut out = vec![blob.threshold() as f32; x.len()];
    for ball in blob.balls() {
        let c = ball.center.as_vec3();
        let (a, s) = (ball.sharpness as f32, ball.strength as f32);
        for (i, o) in out.iter_mut().enumerate() {
            let (dx, dy, dz) = (x[i] - c.x, y[i] - c.y, z[i] - c.z);
            *o -= s * (-a * (dx * dx + dy * dy + dz * dz)).exp();
        }
    }
    out
}

#[test]
fn many_balls_are_culled_and_each_sample_has_the_same_bits_in_any_chunk() {
    let blob = scattered(400, 12.0, 41);
    assert!(blob.cull.is_some());
    let mut rng = Rng::new(43);
    // Chunks of nearby points (as the mesher sends them) and of scattered ones.
    for spread in [0.05, 0.5, 3.0, 20.0] {
        for _ in 0..40 {
            let centre = DVec3::splat(6.0) + rng.vec(7.0);
            let pts: Vec<DVec3> = (0..256).map(|_| centre + rng.vec(spread)).collect();
            let x: Vec<f32> = pts.iter().map(|p| p.x as f32).collect();
            let y: Vec<f32> = pts.iter().map(|p| p.y as f32).collect();
            let z: Vec<f32> = pts.iter().map(|p| p.z as f32).collect();
            let mut out = vec![0f32; pts.len()];
            blob.values_f32(&x, &y, &z, &mut out);
            let full = full_values_f32(&blob, &x, &y, &z);
            for i in 0..out.len() {
                // Alone, the point gets the bits it got in the chunk.
                let mut one = [0f32];
                blob.values_f32(&x[i..=i], &y[i..=i], &z[i..=i], &mut one);
                assert_eq!(one[0].to_bits(), out[i].to_bits(), "{}", pts[i]);
                // The truncated sum is the full sum up to single-precision rounding.
                assert!(
                    (out[i] - full[i]).abs() <= 4e-6,
                    "{}: {} {}",
                    pts[i],
                    out[i],
                    full[i]
                );
            }
            for p in &pts {
                let (v, exact) = (blob.value(*p), blob.threshold() - blob.density(*p));
                assert!((v - exact).abs() <= 1e-15, "{p}: {v} vs {exact}");
            }
        }
    }
}

#[test]
fn many_balls_conform_and_their_culled_intervals_hold() {
    let blob = scattered(200, 8.0, 47);
    assert!(blob.cull.is_some());
    check_shape(&blob, 6.0);
    let mut rng = Rng::new(53);
    for _ in 0..300 {
        let c = DVec3::splat(4.0) + rng.vec(6.0);
        let h = DVec3::splat(0.01) + rng.vec(1.0).abs();
        let b = Aabb::new(c - h, c + h);
        let iv = blob.interval(&b);
        // The full sum of exact term ranges is inside the culled interval.
        let full = blob
            .balls()
            .iter()
            .fold(Interval::point(0.0), |acc, ball| acc + ball.term_range(&b));
        let full = Interval::point(blob.threshold()) - full;
        assert!(iv.lo <= full.lo && full.hi <= iv.hi, "{iv:?} {full:?}");
        assert!(iv.hi - iv.lo <= full.hi - full.lo + 1e-12);
    }
}
