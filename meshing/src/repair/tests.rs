//! Unit tests of the minimal repair on small hand-made meshes.

use super::*;
use crate::TopologyReport;

fn cube() -> IndexedMesh {
    let p: Vec<DVec3> = (0..8)
        .map(|i| DVec3::new(f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2)))
        .collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let t = quads
        .iter()
        .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
        .collect();
    IndexedMesh::new(p, t)
}

fn repaired(mesh: &IndexedMesh, weld: f64) -> Repaired {
    repair_minimal(mesh, &MinimalOptions { weld }).expect("repairable")
}

fn assert_solid(mesh: &IndexedMesh, volume: f64) {
    let r = TopologyReport::of(mesh);
    assert!(r.is_valid_solid(), "{}", r.to_text());
    assert!((r.volume - volume).abs() <= 0.005 * volume, "{}", r.volume);
}

#[test]
fn clean_cube_is_unchanged() {
    let r = repaired(&cube(), 1e-6);
    assert_eq!(r.counts, RepairCounts::default());
    assert_eq!(r.mesh, cube());
}

#[test]
fn soup_is_welded_and_inward_cube_turned_out() {
    let c = cube();
    let mut soup = IndexedMesh::default();
    for t in &c.triangles {
        for &v in &[t[0], t[2], t[1]] {
            soup.positions
                .push(c.positions[v as usize] + DVec3::splat(1e-9));
        }
        let n = soup.positions.len() as u32;
        soup.triangles.push([n - 3, n - 2, n - 1]);
    }
    let r = repaired(&soup, 1e-6);
    assert_eq!(r.counts.vertices_welded, 36 - 8);
    assert_eq!(r.counts.faces_flipped, 12);
    assert_solid(&r.mesh, 1.0);
}

#[test]
fn hole_is_filled_and_duplicates_removed() {
    let mut c = cube();
    c.triangles.truncate(10);
    c.triangles.push(c.triangles[0]);
    let r = repaired(&c, 0.0);
    assert_eq!(r.counts.duplicate_faces_removed, 1);
    assert_eq!(r.counts.holes_filled, 1);
    assert_solid(&r.mesh, 1.0);
}

#[test]
fn min_area_triangulates_a_square_into_two() {
    let p = vec![
        DVec3::ZERO,
        DVec3::X,
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::Y,
        DVec3::new(0.5, 0.5, 0.0),
    ];
    let mut out = Vec::new();
    holes::min_area(&p, &[0, 1, 2, 3], &mut out);
    assert_eq!(out.len(), 2);
}

#[test]
fn no_usable_triangle_is_an_error() {
    let m = IndexedMesh::new(vec![DVec3::ZERO], vec![[0, 0, 0]]);
    assert!(matches!(
        repair_minimal(&m, &MinimalOptions { weld: 0.0 }),
        Err(RepairError::NoUsableTriangles { faces: 1 })
    ));
}
