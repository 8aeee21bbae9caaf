//! Accuracy on a sharp rim: a unit sphere minus a cube whose face cuts off a cap, leaving a
//! circular rim with a 114° dihedral angle, at 128³. Two-sided Hausdorff distance near the rim
//! between the mesh and the exact surface, measured with the exact distance to the surface
//! (sphere, disc and rim pieces) one way and the BVH point-to-mesh distance (`measure`) from
//! points along the rim the other way, for dual contouring and for marching cubes.

use super::*;
use crate::measure::TriangleTree;
use crate::octree::mesh_sparse;
use glam::DVec3;
use solidkit_kernel::Solid;

const CUT: f64 = 0.4; // the cube's face plane x = CUT cuts the unit sphere
const SIDE: f64 = 3.0; // the cube (side SIDE, centred at x = CUT + SIDE / 2) swallows the whole cap

/// Radius of the rim circle (x = CUT).
fn rho() -> f64 {
    (1.0 - CUT * CUT).sqrt()
}

/// Exact distance from `q` to the surface: the sphere where x ≤ CUT, the disc x = CUT of radius
/// `rho`, and their common rim circle.
fn exact_distance(q: DVec3) -> f64 {
    let mut best = rim_distance(q);
    if q.length() > 0.0 && q.x / q.length() <= CUT {
        best = best.min((q.length() - 1.0).abs());
    }
    if q.y * q.y + q.z * q.z <= rho() * rho() {
        best = best.min((q.x - CUT).abs());
    }
    best
}

/// Points along the rim.
fn rim_points(count: usize) -> Vec<DVec3> {
    (0..count)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / count as f64;
            DVec3::new(CUT, rho() * t.cos(), rho() * t.sin())
        })
        .collect()
}

fn rim_distance(q: DVec3) -> f64 {
    let radial = (q.y * q.y + q.z * q.z).sqrt();
    ((q.x - CUT).powi(2) + (radial - rho()).powi(2)).sqrt()
}

/// Two-sided Hausdorff distance between the mesh and the exact surface within `band` of the rim.
fn rim_hausdorff(m: &IndexedMesh, band: f64) -> f64 {
    let near: Vec<[DVec3; 3]> = (0..m.triangles.len())
        .map(|t| m.triangle_positions(t))
        .filter(|t| t.iter().any(|p| rim_distance(*p) < 2.0 * band))
        .collect();
    // Mesh to surface: a barycentric lattice on each triangle near the rim.
    let mut worst: f64 = 0.0;
    const L: usize = 6;
    for [a, b, c] in &near {
        for i in 0..=L {
            for j in 0..=L - i {
                let (s, t) = (i as f64 / L as f64, j as f64 / L as f64);
                let q = *a + (*b - *a) * s + (*c - *a) * t;
                if rim_distance(q) < band {
                    worst = worst.max(exact_distance(q));
                }
            }
        }
    }
    // Surface to mesh: points along the rim, to the mesh's BVH.
    let tree = TriangleTree::new(m).unwrap();
    for q in rim_points(3000) {
        worst = worst.max(tree.nearest(q).distance);
    }
    worst
}

#[test]
fn exact_distance_is_zero_on_the_surface_and_positive_off_it() {
    for p in rim_points(5) {
        assert!(exact_distance(p) < 1e-12 && rim_distance(p) < 1e-12);
    }
    assert!((exact_distance(DVec3::new(0.3, 0.0, 0.0)) - 0.1).abs() < 1e-12);
    assert!((exact_distance(DVec3::new(0.0, 0.0, 0.8)) - 0.2).abs() < 1e-12);
    assert!((exact_distance(DVec3::new(0.9, 0.0, 0.0)) - 0.5).abs() < 1e-12);
}

#[test]
fn sharp_rim_is_kept_far_better_than_by_marching_cubes() {
    let cube = Solid::cube(SIDE).translate(DVec3::new(CUT + 0.5 * SIDE, 0.0, 0.0));
    let s = Solid::sphere(1.0).difference(&cube);
    let p = s.compile();
    let spec = GridSpec::for_bounds(&s.bbox(), 128).unwrap();
    let (dc, _) = mesh_dc(&p, spec, &DcOptions::default()).unwrap();
    let (mc, _) = mesh_sparse(&p, spec, &Default::default()).unwrap();
    let band = 2.0 * spec.cell;
    let (hd, hm) = (rim_hausdorff(&dc, band), rim_hausdorff(&mc, band));
    eprintln!(
        "rim Hausdorff: dc {:.4} cells, mc {:.4} cells",
        hd / spec.cell,
        hm / spec.cell
    );
    assert!(hd < 0.05 * spec.cell, "dc {} cells", hd / spec.cell);
    assert!(
        hm > 5.0 * hd,
        "mc {} dc {} cells",
        hm / spec.cell,
        hd / spec.cell
    );
}
