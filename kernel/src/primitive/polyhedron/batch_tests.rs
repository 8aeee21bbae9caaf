//! The mesh solid's batch evaluation against its point evaluation: signs reused inside sign
//! balls and nearest-point searches started from the previous point's triangle must give exactly
//! [`Shape::value`] and [`Shape::gradient`] at every point, on closed meshes (where balls are
//! used), self-overlapping closed meshes (winding number 2 inside both) and open ones (where
//! they are not).

use super::tests::icosphere;
use super::tree::MeshTree;
use super::*;
use crate::IndexedMesh;
use crate::primitive::Shape;
use crate::primitive::conformance::Rng;
use glam::DVec3;

/// Two icospheres overlapping, as one closed mesh whose shells cross.
fn overlapping_spheres() -> IndexedMesh {
    let a = icosphere(1.0, 3);
    let mut positions = a.positions.clone();
    let mut triangles = a.triangles.clone();
    let n = positions.len() as u32;
    positions.extend(
        a.positions
            .iter()
            .map(|p| *p * 0.7 + DVec3::new(0.8, 0.1, 0.0)),
    );
    triangles.extend(a.triangles.iter().map(|t| t.map(|i| i + n)));
    IndexedMesh::new(positions, triangles)
}

/// Points of a grid block (x fastest, as the meshers batch them), then random points in a
/// random order (neighbours far apart, across the surface).
fn batches(rng: &mut Rng) -> Vec<Vec<DVec3>> {
    let mut out = Vec::new();
    for &(origin, h) in &[
        (DVec3::new(-1.3, -1.3, -1.3), 0.08),
        (DVec3::new(-0.2, -0.35, -0.3), 0.05),
        (DVec3::new(0.5, 0.0, -0.1), 0.021),
    ] {
        let mut block = Vec::new();
        for k in 0..16 {
            for j in 0..16 {
                for i in 0..16 {
                    block.push(origin + DVec3::new(i as f64, j as f64, k as f64) * h);
                }
            }
        }
        out.push(block);
    }
    out.push((0..3000).map(|_| rng.vec(1.6)).collect());
    out
}

fn check(solid: &MeshSolid) {
    let mut rng = Rng::new(31);
    let (mut inside, mut outside) = (0, 0);
    for batch in batches(&mut rng) {
        // The f32 path evaluates at the f32-rounded points.
        let batch: Vec<DVec3> = batch.iter().map(|p| p.as_vec3().as_dvec3()).collect();
        let x: Vec<f32> = batch.iter().map(|p| p.x as f32).collect();
        let y: Vec<f32> = batch.iter().map(|p| p.y as f32).collect();
        let z: Vec<f32> = batch.iter().map(|p| p.z as f32).collect();
        let mut out = vec![0.0f32; batch.len()];
        solid.values_f32(&x, &y, &z, &mut out);
        let mut values = vec![0.0; batch.len()];
        let mut gradients = vec![DVec3::ZERO; batch.len()];
        solid.values_gradients(&batch, &mut values, &mut gradients);
        for (i, p) in batch.iter().enumerate() {
            let v = solid.value(*p);
            assert_eq!(out[i], v as f32, "values_f32 at {p}");
            assert_eq!(values[i], v, "values_gradients at {p}");
            let g = solid.gradient(*p);
            // On exact ties of nearest triangles the gradient may come from another one.
            assert!(
                gradients[i].distance(g) < 1e-9 || v.abs() < 1e-12,
                "gradient at {p}"
            );
            if v < 0.0 {
                inside += 1;
            } else {
                outside += 1;
            }
        }
    }
    assert!(
        inside > 1000 && outside > 1000,
        "{inside} inside, {outside} outside"
    );
}

#[test]
fn batches_equal_points_on_closed_meshes() {
    let solid = MeshSolid::from_mesh(&icosphere(1.0, 3)).unwrap();
    assert_eq!(solid.open_edges(), 0);
    check(&solid);
}

#[test]
fn batches_equal_points_on_crossing_shells() {
    let solid = MeshSolid::from_mesh(&overlapping_spheres()).unwrap();
    assert_eq!(solid.open_edges(), 0);
    // Inside both shells: winding number 2, still inside.
    assert!(solid.value(DVec3::new(0.6, 0.1, 0.0)) < 0.0);
    check(&solid);
}

#[test]
fn batches_equal_points_on_open_meshes() {
    let mut sphere = icosphere(1.0, 3);
    sphere.triangles.truncate(sphere.triangles.len() - 7);
    let solid = MeshSolid::from_mesh(&sphere).unwrap();
    assert!(solid.open_edges() > 0);
    check(&solid);
}

#[test]
fn hinted_nearest_finds_the_same_distance() {
    let mesh = overlapping_spheres();
    let tree = MeshTree::new(&mesh);
    let mut rng = Rng::new(5);
    let slots = mesh.triangles.len() as u32;
    for i in 0..2000u32 {
        let q = rng.vec(2.5);
        let plain = tree.nearest(q);
        let hinted = tree.nearest_hinted(q, (i * 7919) % slots);
        assert_eq!(hinted.distance2, plain.distance2, "at {q}");
        assert!(hinted.point.distance_squared(q) == hinted.distance2);
    }
    // A hint out of range is ignored.
    let q = DVec3::new(0.3, 2.0, -0.1);
    assert_eq!(tree.nearest_hinted(q, u32::MAX), tree.nearest(q));
}
