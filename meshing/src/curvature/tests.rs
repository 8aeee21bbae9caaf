//! Discrete curvatures against spheres and a cylinder, and Gauss–Bonnet on closed and open meshes.

use super::*;
use crate::pipeline::{MeshOptions, mesh_solid};
use solidkit_kernel::primitive::{Primitive, Sphere};
use solidkit_kernel::{Solid, tessellate};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

#[test]
fn a_latitude_longitude_sphere_has_k_one_over_r_squared_and_h_one_over_r() {
    let r = 2.0;
    let m = tessellate::sphere(r, 97, 49).unwrap().mesh;
    let c = mesh_curvature(&m);
    assert_eq!(c.euler_characteristic, 2);
    assert!(c.gauss_bonnet_error() < 1e-9, "{}", c.total_angle_defect);
    // Away from the poles (the fans of thin triangles there).
    let body: Vec<&VertexCurvature> = m
        .positions
        .iter()
        .zip(&c.vertices)
        .filter(|(p, _)| p.z.abs() < 0.8 * r)
        .map(|(_, v)| v)
        .collect();
    for v in &body {
        assert!((v.gaussian * r * r - 1.0).abs() < 0.02, "{v:?}");
        assert!((v.mean * r - 1.0).abs() < 0.01, "{v:?}");
        assert!(
            (v.k1 * r - 1.0).abs() < 0.15 && (v.k2 * r - 1.0).abs() < 0.15,
            "{v:?}"
        );
    }
}

#[test]
fn a_marching_cubes_sphere_obeys_gauss_bonnet_exactly_and_curves_like_the_ball() {
    let r = 1.5;
    let ball = Solid::primitive(Primitive::Sphere(Sphere { radius: r }));
    let m = mesh_solid(&ball, &MeshOptions::new(64)).unwrap().mesh;
    let c = mesh_curvature(&m);
    assert_eq!((c.euler_characteristic, c.boundary_vertices), (2, 0));
    assert!(c.gauss_bonnet_error() < 1e-8, "{}", c.total_angle_defect);
    // Marching-cubes triangles are irregular: per-vertex values scatter, their medians and
    // area-weighted means do not.
    let k: Vec<f64> = c.vertices.iter().map(|v| v.gaussian * r * r).collect();
    let h: Vec<f64> = c.vertices.iter().map(|v| v.mean * r).collect();
    assert!((median(k) - 1.0).abs() < 0.1, "K r² median");
    assert!((median(h) - 1.0).abs() < 0.03, "H r median");
    let area: f64 = c.vertices.iter().map(|v| v.area).sum();
    let mean_h: f64 = c.vertices.iter().map(|v| v.mean * v.area).sum::<f64>() / area;
    assert!((mean_h * r - 1.0).abs() < 0.02, "{mean_h}");
    assert!((area / (4.0 * PI * r * r) - 1.0).abs() < 0.01, "{area}");
}

#[test]
fn an_open_grid_obeys_gauss_bonnet_with_its_boundary() {
    // A bumpy open sheet (a disc: χ = 1) and its flat twin (K = 0 inside).
    let bump = |x: f64, y: f64| 0.3 * (x * 2.0).sin() * (y * 3.0).cos();
    for f in [bump, |_: f64, _: f64| 0.0] {
        let m = tessellate::regular_grid(20, 15, |u, v| glam::DVec3::new(u, v, f(u, v))).unwrap();
        let c = mesh_curvature(&m);
        assert_eq!(c.euler_characteristic, 1);
        assert!(c.gauss_bonnet_error() < 1e-10, "{}", c.total_angle_defect);
        assert_eq!(c.boundary_vertices, 2 * (20 + 15) - 4);
    }
    let flat = tessellate::regular_grid(5, 5, |u, v| glam::DVec3::new(u, v, 0.0)).unwrap();
    let c = mesh_curvature(&flat);
    for v in c.vertices.iter().filter(|v| !v.boundary) {
        assert!(v.gaussian.abs() < 1e-12 && v.mean.abs() < 1e-12, "{v:?}");
    }
}
