//! PN triangles on polyhedra inscribed in the unit sphere with exact normals: the refined meshes
//! stay closed and approach the sphere much more closely than the flat facets.

use super::*;
use crate::IndexedMesh;
use glam::DVec3;
use std::collections::HashMap;

fn octahedron() -> IndexedMesh {
    let p = vec![
        DVec3::X,
        DVec3::Y,
        -DVec3::X,
        -DVec3::Y,
        DVec3::Z,
        -DVec3::Z,
    ];
    let t = vec![
        [0, 1, 4],
        [1, 2, 4],
        [2, 3, 4],
        [3, 0, 4],
        [1, 0, 5],
        [2, 1, 5],
        [3, 2, 5],
        [0, 3, 5],
    ];
    IndexedMesh::new(p, t)
}

pub(crate) fn icosahedron() -> IndexedMesh {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let raw = [
        (-1.0, g, 0.0),
        (1.0, g, 0.0),
        (-1.0, -g, 0.0),
        (1.0, -g, 0.0),
        (0.0, -1.0, g),
        (0.0, 1.0, g),
        (0.0, -1.0, -g),
        (0.0, 1.0, -g),
        (g, 0.0, -1.0),
        (g, 0.0, 1.0),
        (-g, 0.0, -1.0),
        (-g, 0.0, 1.0),
    ];
    let p = raw
        .iter()
        .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
        .collect();
    let t = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    IndexedMesh::new(p, t)
}

/// Midpoint subdivision projected onto the unit sphere.
fn subdivide_on_sphere(m: &IndexedMesh) -> IndexedMesh {
    let mut p = m.positions.clone();
    let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
    let mut t = Vec::new();
    let mut midpoint = |a: u32, b: u32, p: &mut Vec<DVec3>| {
        *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
            p.push(((p[a as usize] + p[b as usize]) * 0.5).normalize());
            (p.len() - 1) as u32
        })
    };
    for &[a, b, c] in &m.triangles {
        let (ab, bc, ca) = (
            midpoint(a, b, &mut p),
            midpoint(b, c, &mut p),
            midpoint(c, a, &mut p),
        );
        t.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
    }
    IndexedMesh::new(p, t)
}

/// Largest `| |p| − 1 |` over the vertices and over points inside each triangle.
fn radial_deviation(m: &IndexedMesh) -> f64 {
    let mut worst = 0.0f64;
    for t in 0..m.triangle_count() {
        let [a, b, c] = m.triangle_positions(t);
        for &(u, v) in &[
            (1.0, 0.0),
            (0.0, 1.0),
            (0.0, 0.0),
            (1.0 / 3.0, 1.0 / 3.0),
            (0.5, 0.5),
            (0.5, 0.0),
            (0.0, 0.5),
        ] {
            let p = a * (1.0 - u - v) + b * u + c * v;
            worst = worst.max((p.length() - 1.0).abs());
        }
    }
    worst
}

/// Every undirected edge is used by exactly two triangles, in opposite directions.
fn is_closed_oriented(m: &IndexedMesh) -> bool {
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &m.triangles {
        for c in 0..3 {
            *directed.entry((t[c], t[(c + 1) % 3])).or_default() += 1;
        }
    }
    directed
        .iter()
        .all(|(&(a, b), &n)| n == 1 && directed.get(&(b, a)) == Some(&1))
}

fn signed_volume(m: &IndexedMesh) -> f64 {
    (0..m.triangle_count())
        .map(|t| {
            let [a, b, c] = m.triangle_positions(t);
            a.dot(b.cross(c)) / 6.0
        })
        .sum()
}

fn sphere_normals(m: &IndexedMesh) -> Vec<DVec3> {
    m.positions.iter().map(|p| p.normalize()).collect()
}

#[test]
fn pn_octahedron_and_icosahedron_approach_the_sphere() {
    for base in [octahedron(), icosahedron()] {
        let normals = sphere_normals(&base);
        let flat = radial_deviation(&base);
        let mut previous = flat;
        // Finer tessellations of the same patches converge to the PN surface, much closer to the
        // sphere than the facets.
        for s in [2, 4, 8] {
            let refined = pn_refine(&base, Some(&normals), s).unwrap();
            assert!(is_closed_oriented(&refined));
            assert_eq!(refined.triangle_count(), base.triangle_count() * s * s);
            let e = base.triangle_count() * 3 / 2;
            let v =
                base.vertex_count() + e * (s - 1) + base.triangle_count() * (s - 1) * (s - 2) / 2;
            assert_eq!(refined.vertex_count(), v);
            let d = radial_deviation(&refined);
            assert!(d < previous, "s {s}: {d} vs {previous}");
            previous = d;
        }
        // Octahedron: 0.23 vs 0.42; icosahedron: 0.06 vs 0.21.
        assert!(previous < 0.6 * flat, "{previous} vs flat {flat}");
    }
}

#[test]
fn pn_error_shrinks_fast_with_the_base_mesh() {
    // Finer inscribed base meshes: the PN surface's deviation falls much faster than the facets'.
    let mut base = icosahedron();
    let mut last: Option<(f64, f64)> = None;
    for _ in 0..3 {
        let normals = sphere_normals(&base);
        let pn = radial_deviation(&pn_refine(&base, Some(&normals), 6).unwrap());
        let flat = radial_deviation(&base);
        if let Some((pn0, flat0)) = last {
            // Facets improve ~4× per halving (second order), PN patches ~8× (third order).
            let (pn_gain, flat_gain) = (pn0 / pn, flat0 / flat);
            assert!(
                flat_gain > 3.0 && pn_gain > 1.4 * flat_gain,
                "pn {pn0} → {pn}, flat {flat0} → {flat}"
            );
        }
        last = Some((pn, flat));
        base = subdivide_on_sphere(&base);
    }
}

#[test]
fn pn_refined_volume_is_closer_to_the_ball() {
    let exact = 4.0 / 3.0 * std::f64::consts::PI;
    let mut base = icosahedron();
    for _ in 0..2 {
        let refined = pn_refine(&base, Some(&sphere_normals(&base)), 8).unwrap();
        let (flat, pn) = (signed_volume(&base), signed_volume(&refined));
        assert!(flat > 0.0 && pn > 0.0);
        assert!(
            (pn - exact).abs() < (flat - exact).abs() / 3.0,
            "{pn} vs {flat}"
        );
        base = subdivide_on_sphere(&base);
    }
}

#[test]
fn computed_normals_and_bad_input() {
    let base = octahedron();
    let computed = vertex_normals(&base);
    for (n, p) in computed.iter().zip(&base.positions) {
        assert!((*n - *p).length() < 1e-12);
    }
    let refined = pn_refine(&base, None, 3).unwrap();
    assert!(is_closed_oriented(&refined));
    let bad = IndexedMesh::new(base.positions.clone(), vec![[0, 1, 9]]);
    assert!(matches!(
        pn_refine(&bad, None, 2),
        Err(PatchError::IndexOutOfRange { .. })
    ));
    assert!(matches!(
        pn_refine(&base, Some(&[DVec3::Z]), 2),
        Err(PatchError::NormalCount { .. })
    ));
    assert!(pn_refine(&base, None, 0).is_err());
    let zero = vec![DVec3::ZERO; 6];
    assert!(matches!(
        pn_refine(&base, Some(&zero), 2),
        Err(PatchError::ZeroNormal(0))
    ));
    // One refinement level with one segment is the input itself.
    assert_eq!(pn_refine(&base, None, 1).unwrap().triangles, base.triangles);
}
