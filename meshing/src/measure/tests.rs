//! Tests of the distance measures against brute force and analytic distances: nearest points of
//! random triangle soups, a cube against a scaled copy, a tessellated sphere against the exact
//! sphere within its stated chord error.

use glam::DVec3;
use solidkit_kernel::tessellate;

use super::rng::Rng;
use super::*;
use crate::IndexedMesh;
use crate::topology::test_meshes::cube;

fn random_point(rng: &mut Rng, scale: f64) -> DVec3 {
    DVec3::new(rng.signed(), rng.signed(), rng.signed()) * scale
}

/// A soup of `n` small random triangles in `[-1, 1]³`, with a few unusable triangles mixed in.
fn soup(rng: &mut Rng, n: usize) -> IndexedMesh {
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for t in 0..n as u32 {
        let centre = random_point(rng, 1.0);
        for _ in 0..3 {
            positions.push(centre + random_point(rng, 0.1));
        }
        triangles.push([3 * t, 3 * t + 1, 3 * t + 2]);
        if t % 50 == 0 {
            triangles.push([3 * t, 3 * t, 3 * t + 1]);
            triangles.push([3 * t, 3 * t + 1, u32::MAX]);
        }
    }
    IndexedMesh::new(positions, triangles)
}

/// The distance to the mesh by testing every usable triangle.
fn brute_force(mesh: &IndexedMesh, q: DVec3) -> f64 {
    let n = mesh.positions.len();
    let mut best = f64::INFINITY;
    for (t, tri) in mesh.triangles.iter().enumerate() {
        if tri.iter().any(|&i| i as usize >= n) || tri[0] == tri[1] || tri[1] == tri[2] {
            continue;
        }
        best = best.min(q.distance(closest_point_on_triangle(q, mesh.triangle_positions(t))));
    }
    best
}

#[test]
fn nearest_agrees_with_brute_force() {
    let mut rng = Rng::new(3);
    for n in [1, 2, 7, 300, 2000] {
        let mesh = soup(&mut rng, n);
        let tree = TriangleTree::new(&mesh).unwrap();
        assert_eq!(tree.triangle_count(), n);
        for _ in 0..300 {
            let q = random_point(&mut rng, 1.5);
            let got = tree.nearest(q);
            let d = brute_force(&mesh, q);
            assert_eq!(got.distance, d, "n={n} q={q}");
            // The reported triangle and point are at that distance.
            let on = closest_point_on_triangle(q, mesh.triangle_positions(got.triangle as usize));
            assert_eq!(q.distance(on), d);
            assert!((q.distance(got.point) - d).abs() <= 1e-15 * (1.0 + d));
        }
    }
}

#[test]
fn unusable_meshes_are_refused() {
    assert_eq!(
        TriangleTree::new(&IndexedMesh::default()).unwrap_err(),
        MeasureError::NoSurface
    );
    let collapsed = IndexedMesh::new(vec![DVec3::ZERO, DVec3::X], vec![[0, 1, 1]]);
    assert_eq!(
        TriangleTree::new(&collapsed).unwrap_err(),
        MeasureError::NoSurface
    );
    let mut nan = cube();
    nan.positions[5].y = f64::NAN;
    assert_eq!(
        TriangleTree::new(&nan).unwrap_err(),
        MeasureError::NonFiniteVertex { vertex: 5 }
    );
    assert!(hausdorff(&cube(), &IndexedMesh::default(), 10).is_err());
}

/// The unit cube `[0, 1]³` scaled by `s` about its centre.
fn scaled_cube(s: f64) -> IndexedMesh {
    let mut mesh = cube();
    for p in &mut mesh.positions {
        *p = DVec3::splat(0.5) + (*p - DVec3::splat(0.5)) * s;
    }
    mesh
}

/// Mean distance from the face `x = s/2, |y|, |z| ≤ s/2` of the cube of side `s` to the unit cube
/// (both centred), by the midpoint rule on an `n × n` grid.
fn scaled_face_mean(s: f64, n: usize) -> f64 {
    let h = (s - 1.0) / 2.0;
    let mut sum = 0.0;
    for i in 0..n {
        for j in 0..n {
            let y = (i as f64 + 0.5) / n as f64 * s - s / 2.0;
            let z = (j as f64 + 0.5) / n as f64 * s - s / 2.0;
            let (dy, dz) = ((y.abs() - 0.5).max(0.0), (z.abs() - 0.5).max(0.0));
            sum += (h * h + dy * dy + dz * dz).sqrt();
        }
    }
    sum / (n * n) as f64
}

#[test]
fn cube_against_a_scaled_copy() {
    let s = 1.5;
    let (a, b) = (cube(), scaled_cube(s));
    let h = hausdorff(&a, &b, 20_000).unwrap();
    // Every point of the inner cube is (s - 1)/2 from the outer one (its nearest face).
    assert!((h.a_to_b.max - (s - 1.0) / 2.0).abs() < 1e-12, "{h:?}");
    assert!((h.a_to_b.mean - (s - 1.0) / 2.0).abs() < 1e-12, "{h:?}");
    // The outer corners are farthest: √3 (s - 1)/2 from the inner corners.
    let corner = 3f64.sqrt() * (s - 1.0) / 2.0;
    assert!((h.b_to_a.max - corner).abs() < 1e-12, "{h:?}");
    assert_eq!(h.symmetric, h.b_to_a.max);
    let mean = scaled_face_mean(s, 1000);
    assert!(
        (h.b_to_a.mean - mean).abs() < 2e-3 * mean,
        "{} vs {mean}",
        h.b_to_a.mean
    );
    assert_eq!((h.a_to_b.count, h.b_to_a.count), (20_008, 20_008));
    // Symmetric in its arguments, and zero against itself.
    let swapped = hausdorff(&b, &a, 20_000).unwrap();
    assert_eq!(swapped.symmetric, h.symmetric);
    assert!(hausdorff(&a, &a, 1000).unwrap().symmetric < 1e-15);
}

/// `n` points spread evenly over the sphere of radius `r` (Fibonacci lattice).
fn fibonacci_sphere(r: f64, n: usize) -> Vec<DVec3> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (i as f64 + 0.5) / n as f64 * 2.0;
            let rho = (1.0 - z * z).sqrt();
            let phi = golden * i as f64;
            DVec3::new(rho * phi.cos(), rho * phi.sin(), z) * r
        })
        .collect()
}

#[test]
fn sphere_tessellation_within_its_chord_error() {
    let r = 2.0;
    for (nu, nv) in [(17, 9), (65, 33)] {
        let t = tessellate::sphere(r, nu, nv).unwrap();
        let bound = t.chord_error.unwrap();
        let tree = TriangleTree::new(&t.mesh).unwrap();
        // Exact sphere → mesh: within the bound, and the bound is not loose by much.
        let exact = fibonacci_sphere(r, 50_000);
        let to_mesh = one_sided(&exact, &tree);
        assert!(
            to_mesh.max <= bound * (1.0 + 1e-9),
            "{} > {bound}",
            to_mesh.max
        );
        assert!(to_mesh.max >= 0.5 * bound, "{} vs {bound}", to_mesh.max);
        // Mesh → exact sphere (distance | |p| − r |).
        let samples = SurfaceSamples::of(&t.mesh, 50_000);
        let worst = samples
            .all()
            .map(|p| (p.length() - r).abs())
            .fold(0.0, f64::max);
        assert!(worst <= bound * (1.0 + 1e-9), "{worst} > {bound}");
        assert!(worst >= 0.5 * bound, "{worst} vs {bound}");
        // Both directions see the same gap, up to sampling.
        assert!(
            (worst - to_mesh.max).abs() < 0.1 * bound,
            "{worst} vs {}",
            to_mesh.max
        );
    }
}
