//! Tests of dual contouring: closed oriented manifolds with the right topology on smooth, sharp,
//! tangent and adversarial inputs; sharp corners reproduced; the sparse path equal to the dense one.

use super::*;
use crate::TopologyReport;
use glam::{DQuat, DVec3};
use solidkit_kernel::Solid;

fn grid(s: &Solid, resolution: usize) -> GridSpec {
    GridSpec::for_bounds(&s.bbox(), resolution).unwrap()
}

fn dc(s: &Solid, resolution: usize) -> IndexedMesh {
    mesh_dc(&s.compile(), grid(s, resolution), &DcOptions::default())
        .unwrap()
        .0
}

#[track_caller]
fn assert_closed_manifold(m: &IndexedMesh, what: &str) -> TopologyReport {
    let r = TopologyReport::of(m);
    assert!(
        r.closed && r.manifold && r.oriented && r.faces > 0,
        "{what}: {} faces, {} boundary, {} non-manifold edges, {} non-manifold vertices, {} \
         inconsistent: {:?}",
        r.faces,
        r.boundary_edges,
        r.non_manifold_edges,
        r.non_manifold_vertices,
        r.inconsistent_edges,
        r.examples
    );
    assert_eq!(
        r.self_intersections,
        Some(0),
        "{what}: self-intersecting pairs {:?}",
        r.examples.self_intersections
    );
    r
}

#[test]
fn sphere_is_a_closed_sphere_with_the_right_volume() {
    let s = Solid::sphere(0.6);
    let m = dc(&s, 48);
    let r = assert_closed_manifold(&m, "sphere");
    assert_eq!((r.shells, r.genus), (1, Some(0)));
    let exact = 4.0 / 3.0 * std::f64::consts::PI * 0.6f64.powi(3);
    assert!((r.volume - exact).abs() / exact < 2e-3, "{}", r.volume);
    // Every vertex lies on the sphere (QEF of a smooth surface: within a small fraction of a cell).
    let cell = grid(&s, 48).cell;
    for p in &m.positions {
        assert!((p.length() - 0.6).abs() < 0.05 * cell, "{p}");
    }
}

/// A unit cube turned off the grid axes at 32³: each of its 8 corners is a mesh vertex within
/// 1e-3 cells.
#[test]
fn rotated_cube_corners_are_reproduced() {
    let rot = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.4);
    let (axis, angle) = rot.to_axis_angle();
    let offset = DVec3::new(0.013, -0.027, 0.031);
    let s = Solid::cube(1.0)
        .rotate(axis, angle.to_degrees())
        .translate(offset);
    let spec = grid(&s, 32);
    let m = mesh_dc(&s.compile(), spec, &DcOptions::default())
        .unwrap()
        .0;
    let r = assert_closed_manifold(&m, "cube");
    assert_eq!(r.genus, Some(0));
    assert!((r.volume - 1.0).abs() < 1e-3, "{}", r.volume);
    for c in 0..8 {
        let local = DVec3::new(
            (c & 1) as f64 - 0.5,
            (c >> 1 & 1) as f64 - 0.5,
            (c >> 2 & 1) as f64 - 0.5,
        );
        let corner = rot * local + offset;
        let best = m
            .positions
            .iter()
            .map(|p| (*p - corner).length())
            .fold(f64::MAX, f64::min);
        assert!(
            best < 1e-3 * spec.cell,
            "corner {c}: {} cells",
            best / spec.cell
        );
    }
}

/// The sparse octree path gives the same mesh as dense tiles over the full program.
#[test]
fn sparse_equals_dense() {
    let s = Solid::sphere(1.0).difference(&Solid::cube(1.2));
    let p = s.compile();
    let spec = grid(&s, 40);
    let (sparse, _) = mesh_dc(&p, spec, &DcOptions::default()).unwrap();
    let samples = SampleGrid::sample_program(&p, spec);
    let dense = mesh_dc_samples(&p, &samples, None);
    assert_closed_manifold(&sparse, "sparse");
    assert_eq!(sparse.triangles.len(), dense.triangles.len());
    assert_eq!(sparse.positions.len(), dense.positions.len());
    let bad = sparse
        .positions
        .iter()
        .zip(&dense.positions)
        .filter(|(a, b)| (**a - **b).length() > 1e-9)
        .count();
    assert_eq!(bad, 0);
}

/// A sink numbering its vertices downwards from 10⁹ − 1 (a sink's own ids must be honoured).
#[derive(Default)]
struct Backwards(IndexedMesh);

impl MeshSink for Backwards {
    fn add_vertex(&mut self, p: DVec3) -> u32 {
        self.0.positions.push(p);
        1_000_000_000 - self.0.positions.len() as u32
    }

    fn add_triangle(&mut self, t: [u32; 3]) {
        self.0.triangles.push(t);
    }
}

#[test]
fn a_sink_with_its_own_numbers_gets_the_same_mesh() {
    // More than one block of vertices and of triangles (2¹⁶ each), and unused vertices dropped.
    let s = Solid::sphere(1.0).union(&Solid::cuboid(DVec3::new(0.5, 1.5, 0.5)));
    let g = grid(&s, 160);
    let p = s.compile();
    let (mesh, _) = mesh_dc(&p, g, &DcOptions::default()).unwrap();
    assert!(mesh.triangles.len() > 1 << 17, "{}", mesh.triangles.len());
    let mut other = Backwards::default();
    mesh_dc_into(&p, g, &DcOptions::default(), &mut other).unwrap();
    assert_eq!(other.0.positions, mesh.positions);
    let renumbered: Vec<[u32; 3]> = other
        .0
        .triangles
        .iter()
        .map(|t| t.map(|v| 1_000_000_000 - 1 - v))
        .collect();
    assert_eq!(renumbered, mesh.triangles);
    // Every vertex is used.
    let mut used = vec![false; mesh.positions.len()];
    mesh.triangles
        .iter()
        .flatten()
        .for_each(|&v| used[v as usize] = true);
    assert!(used.iter().all(|&u| u));
}
