//! Block distance queries ([`Polygon::nearest_many`], [`Profile::distance_gradients`]) against
//! the plain loop over every edge, bit for bit: random many-edged profiles, blocks of every size
//! and distance (repeated points, points far away, on corners, on edges and on the crossing rays
//! of corners), and lattice ties.

use super::polygon::{Nearest, Polygon};
use super::*;
use crate::primitive::conformance::Rng;
use glam::DVec2;

fn same(a: &Nearest, b: &Nearest, q: DVec2) {
    assert_eq!(a.distance.to_bits(), b.distance.to_bits(), "{q}");
    assert_eq!(a.gradient.x.to_bits(), b.gradient.x.to_bits(), "{q}");
    assert_eq!(a.gradient.y.to_bits(), b.gradient.y.to_bits(), "{q}");
    assert_eq!((a.ring, a.edge), (b.ring, b.edge), "{q}");
    assert_eq!(a.lambda.to_bits(), b.lambda.to_bits(), "{q}");
}

/// The block answers of `qs` are the plain loop's, point by point.
fn check_block(p: &Polygon, qs: &[DVec2]) {
    let mut out = Vec::new();
    p.nearest_many(qs, &mut out);
    assert_eq!(out.len(), qs.len());
    for (n, &q) in out.iter().zip(qs) {
        same(n, &p.nearest_plain(q), q);
    }
    let profile = Profile::Polygon(p.clone());
    let mut dg = Vec::new();
    profile.distance_gradients(qs, &mut dg);
    for (&(d, g), n) in dg.iter().zip(&out) {
        assert_eq!((d.to_bits(), g), (n.distance.to_bits(), n.gradient));
    }
}

/// A random loop of `n` corners around `c`: a wavy star of random radius and waviness.
fn random_loop(rng: &mut Rng, c: DVec2, r: f64, n: usize) -> Vec<DVec2> {
    let (waves, depth) = (
        3.0 + (rng.next() + 1.0) * 6.0,
        0.1 + 0.15 * (rng.next() + 1.0),
    );
    (0..n)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / n as f64;
            let wobble = 1.0 + depth * (waves.floor() * t).cos() + 0.02 * rng.next();
            c + DVec2::new(t.cos(), t.sin()) * r * wobble
        })
        .collect()
}

#[test]
fn blocks_of_random_points_answer_as_the_plain_loop() {
    let mut rng = Rng::new(141);
    for case in 0..12 {
        let n = 64 + (case * 211) % 1500;
        let centre = DVec2::new(rng.next(), rng.next());
        let outer = random_loop(&mut rng, centre, 3.0, n);
        let hole = random_loop(&mut rng, DVec2::new(0.2, -0.1), 0.8, 40 + case * 13);
        let p = Polygon::new(outer, vec![hole]).unwrap();
        assert!(p.index.is_some());
        for _ in 0..40 {
            // A lattice block like a mesher's chunk (x fastest, rows repeated), anywhere from on
            // the boundary to far away, of any size.
            let far = [0.0, 1.0, 5.0, 100.0][(rng.next().abs() * 4.0) as usize % 4];
            let centre = DVec2::new(rng.next(), rng.next()) * 4.0 * (1.0 + far);
            let step = 10f64.powf(-3.0 + 3.0 * (rng.next() + 1.0));
            let mut qs = Vec::new();
            for k in 0..3 {
                for j in 0..6 {
                    for i in 0..8 {
                        let q = centre + DVec2::new(i as f64, j as f64) * step;
                        // Every third layer repeats the points (an axis along the rows).
                        qs.push(if k == 2 { qs[(i + 8 * j) as usize] } else { q });
                    }
                }
            }
            check_block(&p, &qs);
        }
        // Corners, edge midpoints, and points on the crossing rays of corners, in blocks.
        for l in p.loops() {
            for (i, &c) in l.iter().enumerate().step_by(5) {
                let d = l[(i + 1) % l.len()];
                let qs = [
                    c,
                    c.lerp(d, 0.5),
                    c + DVec2::new(0.01, 0.0),
                    c - DVec2::new(0.01, 0.0),
                    d,
                    c + DVec2::new(0.0, 1e-9),
                ];
                check_block(&p, &qs);
            }
        }
    }
}

#[test]
fn blocks_break_ties_as_the_plain_loop() {
    // A staircase on the unit lattice: many points at equal distances from several edges.
    let mut outline = vec![DVec2::new(0.0, 0.0)];
    for k in 0..40 {
        let k = k as f64;
        outline.push(DVec2::new(k + 1.0, k));
        outline.push(DVec2::new(k + 1.0, k + 1.0));
    }
    outline.push(DVec2::new(0.0, 40.0));
    let p = Polygon::new(outline, vec![]).unwrap();
    assert!(p.index.is_some());
    for bj in 0..23 {
        for bi in 0..23 {
            let qs: Vec<DVec2> = (0..64)
                .map(|k| DVec2::new((bi * 8 + k % 8) as f64, (bj * 8 + k / 8) as f64) * 0.25)
                .map(|q| q - DVec2::splat(1.0))
                .collect();
            check_block(&p, &qs);
        }
    }
}

#[test]
fn non_finite_points_and_small_polygons_answer_as_one_by_one() {
    let p = Polygon::new(random_loop(&mut Rng::new(5), DVec2::ZERO, 1.0, 200), vec![]).unwrap();
    let qs = [
        DVec2::new(0.1, 0.2),
        DVec2::new(f64::NAN, 0.0),
        DVec2::X * 1e300,
    ];
    let mut out = Vec::new();
    p.nearest_many(&qs, &mut out);
    for (n, &q) in out.iter().zip(&qs) {
        let one = p.nearest(q);
        assert_eq!(n.distance.to_bits(), one.distance.to_bits(), "{q}");
    }
    // Without an index (few edges) the batch is the one-point query.
    let small =
        Profile::polygon(random_loop(&mut Rng::new(6), DVec2::ZERO, 1.0, 20), vec![]).unwrap();
    let qs: Vec<DVec2> = (0..50)
        .map(|i| DVec2::new(i as f64 * 0.05 - 1.2, 0.3))
        .collect();
    let mut dg = Vec::new();
    small.distance_gradients(&qs, &mut dg);
    for (&(d, g), &q) in dg.iter().zip(&qs) {
        assert_eq!((d, g), small.distance_gradient(q));
    }
}

#[test]
fn extrusion_batches_give_the_one_point_field() {
    use crate::primitive::{Extrude, Shape};
    use glam::DVec3;
    let mut rng = Rng::new(77);
    let outer = random_loop(&mut rng, DVec2::ZERO, 2.0, 900);
    let hole = random_loop(&mut rng, DVec2::new(0.1, 0.2), 0.5, 120);
    let profile = Profile::polygon(outer, vec![hole]).unwrap();
    let extrusions = [
        Extrude::new(profile.clone(), 1.5, 0.0, 1.0).unwrap(),
        Extrude::new(profile.clone(), 1.5, 90.0, 0.6).unwrap(),
        Extrude::with_scale(profile.clone(), 1.5, 0.0, DVec2::new(1.3, 0.7)).unwrap(),
        Extrude::with_scale(profile, 1.5, 0.0, DVec2::ZERO).unwrap(),
    ];
    for e in &extrusions {
        for _ in 0..30 {
            // A mesher's chunk: a small lattice box (x fastest) somewhere around the solid.
            let corner = rng.vec(3.0);
            let step = 10f64.powf(-2.5 + 2.0 * (rng.next() + 1.0) / 2.0);
            let pts: Vec<DVec3> = (0..256)
                .map(|k| {
                    corner + DVec3::new((k % 8) as f64, (k / 8 % 8) as f64, (k / 64) as f64) * step
                })
                .collect();
            let (x, y, z): (Vec<f32>, Vec<f32>, Vec<f32>) = (
                pts.iter().map(|p| p.x as f32).collect(),
                pts.iter().map(|p| p.y as f32).collect(),
                pts.iter().map(|p| p.z as f32).collect(),
            );
            let mut out = vec![0.0f32; pts.len()];
            e.values_f32(&x, &y, &z, &mut out);
            let (mut values, mut gradients) = (vec![0.0; pts.len()], vec![DVec3::ZERO; pts.len()]);
            e.values_gradients(&pts, &mut values, &mut gradients);
            for (i, p) in pts.iter().enumerate() {
                let pf = DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64);
                assert_eq!(out[i].to_bits(), (e.value(pf) as f32).to_bits(), "{pf}");
                assert_eq!(values[i].to_bits(), e.value(*p).to_bits(), "{p}");
                assert_eq!(gradients[i], e.gradient(*p), "{p}");
            }
        }
    }
}
