//! Tests of the polyhedral primitives: conformance (Lipschitz, gradient, interval soundness,
//! bbox), distances and winding numbers against brute force, robustness on a mesh with a hole,
//! and agreement between the Platonic field and the mesh of the same solid.

use super::tree::MeshTree;
use super::*;
use crate::IndexedMesh;
use crate::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron, Prism};
use crate::primitive::Shape;
use crate::primitive::conformance::{Rng, check_shape};
use glam::{DVec2, DVec3};
use std::collections::BTreeMap;

/// An icosahedron subdivided `levels` times, projected onto the sphere of radius `r`.
pub(crate) fn icosphere(r: f64, levels: usize) -> IndexedMesh {
    let ico = Polyhedron::platonic(PlatonicKind::Icosahedron, PlatonicSize::Circumradius(1.0))
        .unwrap()
        .to_indexed();
    let (mut positions, mut triangles) = (ico.positions, ico.triangles);
    for _ in 0..levels {
        let mut mid: BTreeMap<(u32, u32), u32> = BTreeMap::new();
        let mut next = Vec::with_capacity(triangles.len() * 4);
        for t in &triangles {
            let mut m = [0u32; 3];
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                let key = (a.min(b), a.max(b));
                m[k] = *mid.entry(key).or_insert_with(|| {
                    positions
                        .push(((positions[a as usize] + positions[b as usize]) / 2.0).normalize());
                    positions.len() as u32 - 1
                });
            }
            next.push([t[0], m[0], m[2]]);
            next.push([t[1], m[1], m[0]]);
            next.push([t[2], m[2], m[1]]);
            next.push(m);
        }
        triangles = next;
    }
    IndexedMesh::new(positions.into_iter().map(|p| p * r).collect(), triangles)
}

fn square(c: DVec2, h: f64) -> Vec<DVec2> {
    [(-h, -h), (h, -h), (h, h), (-h, h)]
        .iter()
        .map(|&(x, y)| c + DVec2::new(x, y))
        .collect()
}

#[test]
fn platonic_solids_conform() {
    for kind in PlatonicKind::ALL {
        check_shape(&Platonic::new(kind, PlatonicSize::Circumradius(1.0)), 1.5);
        check_shape(&Platonic::new(kind, PlatonicSize::Edge(0.7)), 1.5);
    }
}

#[test]
fn mesh_solids_conform() {
    let ico =
        Polyhedron::platonic(PlatonicKind::Icosahedron, PlatonicSize::Circumradius(1.0)).unwrap();
    check_shape(&MeshSolid::from_polyhedron(&ico), 1.5);
    check_shape(&MeshSolid::from_mesh(&icosphere(1.0, 2)).unwrap(), 1.5);
    let holed = Prism::new(
        square(DVec2::ZERO, 1.0),
        vec![square(DVec2::new(0.3, 0.0), 0.4)],
        DVec3::new(0.2, 0.1, 1.0),
    );
    check_shape(&MeshSolid::from_prism(holed).unwrap(), 1.5);
    // An L-shaped (concave) prism swept downwards.
    let l = [
        (0.0, 0.0),
        (1.0, 0.0),
        (1.0, 0.4),
        (0.4, 0.4),
        (0.4, 1.0),
        (0.0, 1.0),
    ]
    .map(|(x, y)| DVec2::new(x - 0.5, y - 0.5));
    let l = Prism::new(l.to_vec(), vec![], DVec3::new(0.0, 0.0, -1.2));
    check_shape(&MeshSolid::from_prism(l).unwrap(), 1.5);
}

#[test]
fn platonic_field_is_exact_inside_and_agrees_in_sign_with_the_mesh() {
    let mut rng = Rng::new(5);
    for kind in PlatonicKind::ALL {
        let size = PlatonicSize::Edge(1.1);
        let field = Platonic::new(kind, size);
        let mesh = MeshSolid::from_polyhedron(&Polyhedron::platonic(kind, size).unwrap());
        for _ in 0..2000 {
            let p = rng.vec(1.6);
            let (f, d) = (field.value(p), mesh.value(p));
            assert_eq!(f < 0.0, d < 0.0, "{kind:?} at {p}: {f} vs {d}");
            if d < 0.0 {
                assert!((f - d).abs() < 1e-12, "{kind:?} inside at {p}: {f} vs {d}");
            } else {
                assert!(
                    f <= d + 1e-12,
                    "{kind:?} outside: the planes bound the distance"
                );
            }
        }
    }
}

#[test]
fn nearest_matches_brute_force() {
    let sphere = icosphere(1.0, 3);
    let tree = MeshTree::new(&sphere);
    let mut rng = Rng::new(9);
    for _ in 0..500 {
        let q = rng.vec(2.0);
        let brute = (0..sphere.triangles.len())
            .map(|t| {
                let [a, b, c] = sphere.triangle_positions(t);
                super::nearest::closest_point(q, a, b, c).distance_squared(q)
            })
            .fold(f64::INFINITY, f64::min);
        let got = tree.nearest(q);
        assert_eq!(got.distance2, brute, "at {q}");
        assert!((got.point.distance_squared(q) - brute).abs() <= 1e-15);
    }
}

#[test]
fn fast_winding_numbers_match_exact_ones() {
    let sphere = icosphere(1.0, 4);
    let tree = MeshTree::new(&sphere);
    let mut rng = Rng::new(21);
    let mut worst: f64 = 0.0;
    for _ in 0..2000 {
        let q = rng.vec(1.05);
        let (fast, exact) = (tree.winding_number(q), tree.winding_number_exact(q));
        worst = worst.max((fast - exact).abs());
        let inside = q.length() < 0.99;
        let outside = q.length() > 1.0 && tree.bbox.contains(q);
        if inside || outside {
            assert!(
                (exact - if inside { 1.0 } else { 0.0 }).abs() < 1e-9,
                "{q}: {exact}"
            );
        }
    }
    assert!(worst < 0.1, "dipole approximation error {worst}");
}

#[test]
fn a_mesh_with_a_hole_still_has_a_sensible_inside() {
    let mut sphere = icosphere(1.0, 3);
    // Remove one triangle (about 0.1% of the surface) near +x.
    let hole = (0..sphere.triangles.len())
        .max_by(|&a, &b| {
            let c = |t: usize| sphere.triangle_positions(t).iter().sum::<DVec3>().x;
            c(a).total_cmp(&c(b))
        })
        .unwrap();
    sphere.triangles.remove(hole);
    let solid = MeshSolid::from_mesh(&sphere).unwrap();
    let mut rng = Rng::new(2);
    for _ in 0..2000 {
        let q = rng.vec(1.2);
        let r = q.length();
        if (r - 1.0).abs() < 0.05 {
            continue;
        }
        assert_eq!(solid.value(q) < 0.0, r < 1.0, "at {q}");
    }
    // At the hole's centre the winding number is near ½ and the distance is small.
    let w = solid.winding_number(DVec3::X * 0.999);
    assert!(w > 0.3 && w < 1.0, "{w}");
}

#[test]
fn sphere_mesh_distance_is_close_to_the_true_sphere() {
    let solid = MeshSolid::from_mesh(&icosphere(1.0, 4)).unwrap();
    let mut rng = Rng::new(17);
    for _ in 0..1000 {
        let q = rng.vec(2.0);
        // The inscribed mesh lies within 0.002 of the unit sphere at 4 subdivisions.
        assert!((solid.value(q) - (q.length() - 1.0)).abs() < 5e-3, "{q}");
    }
    let g = solid.gradient(DVec3::new(1.5, 0.1, 0.0));
    assert!((g.length() - 1.0).abs() < 1e-12 && g.x > 0.99);
    let g = solid.gradient(DVec3::new(0.5, 0.0, 0.05));
    assert!(g.x > 0.9, "inside the gradient still points out: {g}");
}

#[test]
fn bad_meshes_are_errors_and_do_not_panic() {
    let e = MeshSolid::from_mesh(&IndexedMesh::default()).unwrap_err();
    assert!(e.to_string().contains("no faces"), "{e}");
    let mesh = IndexedMesh::new(vec![DVec3::ZERO, DVec3::X], vec![[0, 1, 2]]);
    let e = MeshSolid::from_mesh(&mesh).unwrap_err();
    assert!(e.to_string().contains("vertex 2"), "{e}");
    let mesh = IndexedMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::NAN], vec![[0, 1, 2]]);
    assert!(MeshSolid::from_mesh(&mesh).is_err());
    // Coordinates beyond ±1e30 are refused (single-precision evaluation overflows, issue 15).
    let huge = IndexedMesh::new(
        vec![DVec3::ZERO, DVec3::X * 1e300, DVec3::Y],
        vec![[0, 1, 2]],
    );
    let e = MeshSolid::from_mesh(&huge).unwrap_err();
    assert!(e.to_string().contains("beyond ±1e30"), "{e}");
    // Tiny, degenerate and single-triangle meshes build and answer queries.
    for scale in [1e-300, 0.0] {
        let tri = IndexedMesh::new(
            vec![
                DVec3::ZERO,
                DVec3::X * scale,
                DVec3::new(-1e308, 1e308, 1.0) * scale.min(1.0),
            ],
            vec![[0, 1, 2], [0, 0, 1]],
        );
        let s = MeshSolid::from_mesh(&tri).unwrap();
        let _ = (s.value(DVec3::ONE), s.gradient(DVec3::ONE));
    }
    let e =
        MeshSolid::from_faces(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![vec![0, 1]]).unwrap_err();
    assert!(e.to_string().contains("face 0 has 2 corners"), "{e}");
    assert!(MeshSolid::from_file("part.obj", &NoMeshResolver).is_err());
}

#[test]
fn equality_and_cloning_follow_the_source() {
    let cube = Polyhedron::platonic(PlatonicKind::Cube, PlatonicSize::Edge(1.0)).unwrap();
    let a = MeshSolid::from_polyhedron(&cube);
    let b = MeshSolid::from_faces(cube.vertices().to_vec(), cube.faces().to_vec()).unwrap();
    assert_eq!(a, b);
    assert_eq!(a.clone(), a);
    assert_eq!(a.name(), "polyhedron");
    assert_ne!(a, MeshSolid::from_polyhedron(&cube.scaled(2.0)));
}

/// Repeated triangles are stored once with their number of copies: the winding number is that of
/// every copy (three copies of a closed sphere wind 3 times inside), distances are unchanged,
/// and 40 000 copies of one triangle build and evaluate at once.
#[test]
fn repeated_triangles_keep_their_winding_weight() {
    let sphere = icosphere(1.0, 2);
    let mut tripled = sphere.clone();
    for t in &sphere.triangles {
        tripled.triangles.push([t[1], t[2], t[0]]);
        tripled.triangles.push(*t);
    }
    let (one, three) = (MeshTree::new(&sphere), MeshTree::new(&tripled));
    assert_eq!(three.triangles().len(), sphere.triangles.len());
    assert_eq!(three.count, 3 * sphere.triangles.len());
    let mut rng = Rng::new(4);
    for _ in 0..300 {
        let q = rng.vec(1.2);
        let brute: f64 = (0..tripled.triangles.len())
            .map(|t| {
                let [a, b, c] = tripled.triangle_positions(t);
                super::winding::solid_angle(a - q, b - q, c - q)
            })
            .sum::<f64>()
            / (4.0 * std::f64::consts::PI);
        assert!((three.winding_number_exact(q) - brute).abs() < 1e-9, "{q}");
        assert!((three.winding_number(q) - 3.0 * one.winding_number(q)).abs() < 1e-9);
        assert_eq!(three.nearest(q).distance2, one.nearest(q).distance2);
    }
    let solid = MeshSolid::from_mesh(&tripled).unwrap();
    assert_eq!(solid.triangle_count(), tripled.triangles.len());
    assert!(solid.value(DVec3::ZERO) < 0.0 && solid.value(DVec3::splat(0.9)) > 0.0);
    let flat = IndexedMesh::new(
        vec![DVec3::ZERO, DVec3::X, DVec3::Y],
        vec![[0, 1, 2]; 40_000],
    );
    let start = std::time::Instant::now();
    let solid = MeshSolid::from_mesh(&flat).unwrap();
    for k in 0..1000 {
        let _ = solid.value(DVec3::new(0.3, 0.3, k as f64 * 1e-3 - 0.5));
    }
    assert!(start.elapsed().as_secs_f64() < 1.0, "{:?}", start.elapsed());
}
