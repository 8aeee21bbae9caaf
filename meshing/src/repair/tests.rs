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

/// Appends the 12 faces of the box `lo..hi`, wound outward (`inward`: reversed); returns the
/// faces' group id `group` once per face.
fn add_box(m: &mut IndexedMesh, lo: DVec3, hi: DVec3, inward: bool, group: usize) -> Vec<usize> {
    let base = m.positions.len() as u32;
    for i in 0..8u32 {
        let pick = |k: usize| if i >> k & 1 == 1 { hi[k] } else { lo[k] };
        m.positions.push(DVec3::new(pick(0), pick(1), pick(2)));
    }
    for t in cube().triangles {
        let t = t.map(|v| v + base);
        m.triangles
            .push(if inward { [t[0], t[2], t[1]] } else { t });
    }
    vec![group; 12]
}

#[test]
fn nesting_turns_each_shell_by_its_depth_with_rays_through_grid_edges() {
    let mut m = IndexedMesh::default();
    let mut group = Vec::new();
    let v = DVec3::splat;
    // Depth 0 (wound inward: must turn), 1 (a cavity), 2 (an island).
    group.extend(add_box(&mut m, v(0.0), v(12.0), true, 0));
    group.extend(add_box(&mut m, v(1.0), v(11.0), false, 1));
    group.extend(add_box(&mut m, v(2.0), v(10.0), true, 2));
    // 27 unit boxes in the island (depth 3: cavities), corners on the grid, so rays from them
    // meet the others' edges and corners unless cast generically; and one touching the island's
    // wall from inside (its corners lie on the island's faces: ambiguous for a ray).
    let mut next = 3;
    for i in 0..27 {
        let lo = DVec3::new(
            f64::from(3 + 2 * (i % 3)),
            f64::from(3 + 2 * (i / 3 % 3)),
            f64::from(3 + 2 * (i / 9)),
        );
        group.extend(add_box(&mut m, lo, lo + 1.0, i % 2 == 0, next));
        next += 1;
    }
    let touching = next;
    group.extend(add_box(&mut m, v(2.0), v(2.5), false, touching));
    // An open box (one face missing: not a cycle, decided by the winding number) around a box.
    let open = touching + 1;
    group.extend(add_box(&mut m, v(20.0), v(30.0), false, open));
    m.triangles.truncate(m.triangles.len() - 2);
    group.truncate(group.len() - 2);
    group.extend(add_box(&mut m, v(24.0), v(25.0), false, open + 1));
    let mut tris = m.triangles.clone();
    let oriented = nesting::orient_shells(&m.positions, &mut tris);
    assert_eq!(oriented.removed, 0);
    let mut volume = vec![0.0; open + 2];
    for (t, &(f, _)) in tris.iter().zip(&oriented.from) {
        let [a, b, c] = t.map(|i| m.positions[i as usize]);
        volume[group[f as usize]] += a.dot(b.cross(c)) / 6.0;
    }
    let sign = |g: usize| volume[g] > 0.0;
    assert!(sign(0) && !sign(1) && sign(2), "{volume:?}");
    for (g, _) in volume.iter().enumerate().take(touching).skip(3) {
        assert!(
            !sign(g),
            "unit box {g} is a cavity in the island: {volume:?}"
        );
    }
    // The winding number at a corner on the island's wall is 1/8 of a turn: not inside it.
    let corner = v(2.0);
    let island: Vec<usize> = (24..36).collect();
    let w = nesting::winding(&m.positions, &m.triangles, &island, corner);
    assert!(w.abs() < 0.5, "{w}");
    assert!(
        sign(touching),
        "depth 2 (outer box, cavity): outward, {volume:?}"
    );
    assert!(!sign(open + 1), "inside the open box: inward, {volume:?}");
}
