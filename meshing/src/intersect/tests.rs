//! Tests of the self-intersection count: hand-made pairs for every sharing case (crossing,
//! touching, shared vertex or edge, coplanar overlap, fold-back), random pairs against an
//! independent floating-point test, the broad phase against all pairs, closed meshes with none,
//! a pushed-through vertex and the two-cube defect fixture.

use glam::DVec3;
use solidkit_kernel::tessellate;

use super::filter;
use super::triangles::{Tri, meet_beyond_shared, meet_beyond_shared_exact};
use super::*;
use crate::topology::test_meshes::{cube, fixture, octahedron, read_off, torus};

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// Number of intersecting pairs of a small mesh.
fn count(positions: &[DVec3], triangles: &[[u32; 3]]) -> usize {
    let mesh = IndexedMesh::new(positions.to_vec(), triangles.to_vec());
    self_intersections(&mesh, 8).unwrap().count
}

#[test]
fn separate_crossing_and_touching_triangles() {
    let p = [
        v(0.0, 0.0, 0.0),
        v(2.0, 0.0, 0.0),
        v(0.0, 2.0, 0.0),
        // A vertical triangle through the first one.
        v(0.5, 0.5, -1.0),
        v(0.5, 0.5, 1.0),
        v(3.0, 3.0, 0.0),
    ];
    assert_eq!(count(&p, &[[0, 1, 2], [3, 4, 5]]), 1);
    // Lifted clear of the plane: none.
    let lifted: Vec<DVec3> = p
        .iter()
        .enumerate()
        .map(|(i, &q)| if i >= 3 { q + v(0.0, 0.0, 1.5) } else { q })
        .collect();
    assert_eq!(count(&lifted, &[[0, 1, 2], [3, 4, 5]]), 0);
    // A vertex touching the interior of the other triangle counts (the surface touches itself).
    let touch = [
        p[0],
        p[1],
        p[2],
        v(0.5, 0.5, 0.0),
        v(0.5, 0.5, 1.0),
        v(1.0, 0.0, 1.0),
    ];
    assert_eq!(count(&touch, &[[0, 1, 2], [3, 4, 5]]), 1);
    // ... and so does an edge lying on another's edge without sharing vertices.
    let along = [
        p[0],
        p[1],
        p[2],
        v(0.5, 0.0, 0.0),
        v(1.5, 0.0, 0.0),
        v(1.0, -1.0, 1.0),
    ];
    assert_eq!(count(&along, &[[0, 1, 2], [3, 4, 5]]), 1);
    // Just beside that edge: none.
    let beside = [
        p[0],
        p[1],
        p[2],
        v(0.5, -1e-9, 0.0),
        v(1.5, -1e-9, 0.0),
        v(1.0, -1.0, 1.0),
    ];
    assert_eq!(count(&beside, &[[0, 1, 2], [3, 4, 5]]), 0);
}

#[test]
fn coplanar_overlaps() {
    let p = [
        v(0.0, 0.0, 0.0),
        v(2.0, 0.0, 0.0),
        v(0.0, 2.0, 0.0),
        v(1.0, 1.0, 0.0),
        v(-1.0, 1.0, 0.0),
        v(1.0, -1.0, 0.0),
        // A small triangle inside the first.
        v(0.2, 0.2, 0.0),
        v(0.5, 0.2, 0.0),
        v(0.2, 0.5, 0.0),
        // One entirely outside it.
        v(3.0, 3.0, 0.0),
        v(4.0, 3.0, 0.0),
        v(3.0, 4.0, 0.0),
    ];
    assert_eq!(count(&p, &[[0, 1, 2], [3, 4, 5]]), 1, "crossing edges");
    assert_eq!(
        count(&p, &[[0, 1, 2], [6, 7, 8]]),
        1,
        "one inside the other"
    );
    assert_eq!(count(&p, &[[6, 7, 8], [0, 1, 2]]), 1, "the other way round");
    assert_eq!(count(&p, &[[0, 1, 2], [9, 10, 11]]), 0, "apart");
}

#[test]
fn neighbours_count_only_beyond_what_they_share() {
    let p = [
        v(0.0, 0.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(0.0, 1.0, 0.0),
        v(1.0, 1.0, 0.0),   // 3: other side of edge 1-2, coplanar
        v(0.2, 0.2, 0.0),   // 4: same side of edge 1-2, coplanar (fold-back)
        v(0.3, 0.3, 1.0),   // 5: above
        v(-1.0, -1.0, 0.0), // 6: coplanar, wedge opposite vertex 0
        v(0.5, 0.1, 0.0),   // 7, 8: coplanar, wedge overlapping at vertex 0
        v(0.1, 0.5, 0.0),
        v(0.3, 0.3, -1.0), // 9, 10: a triangle from vertex 0 through the first one
        v(0.3, 0.3, 1.0),
    ];
    let base = [0, 1, 2];
    // Shared edge 1-2.
    assert_eq!(count(&p, &[base, [2, 1, 3]]), 0, "flat quad");
    assert_eq!(count(&p, &[base, [2, 1, 5]]), 0, "bent along the edge");
    assert_eq!(count(&p, &[base, [1, 2, 4]]), 1, "folded back flat");
    // Shared vertex 0.
    assert_eq!(
        count(&p, &[base, [0, 6, 5]]),
        0,
        "touching at the vertex only"
    );
    assert_eq!(
        count(&p, &[base, [0, 6, 3]]),
        0,
        "coplanar, opposite wedges"
    );
    assert_eq!(
        count(&p, &[base, [0, 7, 8]]),
        1,
        "coplanar, overlapping wedges"
    );
    assert_eq!(
        count(&p, &[base, [0, 9, 10]]),
        1,
        "the opposite edge pierces"
    );
    // Along the edge 0-1 from the shared vertex, on the other side of it: touching only at 0 ...
    let under = [p[0], p[1], p[2], v(-1.0, 0.0, 0.0), v(-0.5, -1.0, 0.0)];
    assert_eq!(count(&under, &[base, [0, 3, 4]]), 0);
    // ... but overlapping the edge 0-1 beyond the vertex counts.
    let over = [p[0], p[1], p[2], v(0.5, 0.0, 0.0), v(0.3, -1.0, 0.0)];
    assert_eq!(count(&over, &[base, [0, 4, 3]]), 1);
    // The same triangle twice, either winding.
    assert_eq!(count(&p, &[base, [2, 1, 0]]), 1);
    assert_eq!(count(&p, &[base, [1, 2, 0]]), 1);
    // Collinear triangles are skipped.
    let line = [
        p[0],
        p[1],
        v(2.0, 0.0, 0.0),
        v(0.5, -1.0, 0.0),
        v(0.5, 1.0, 0.0),
    ];
    assert_eq!(count(&line, &[[0, 1, 2], [3, 4, 0]]), 0);
}

/// A tiny deterministic generator (xorshift) for the random tests.
struct Xorshift(u64);

impl Xorshift {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn point(&mut self) -> DVec3 {
        v(self.unit(), self.unit(), self.unit()) * 2.0 - DVec3::ONE
    }
}

/// Whether segment `pq` pierces triangle `t` (counter-clockwise seen along its normal), in
/// floating point; `None` when too close to call.
fn float_pierces(p: DVec3, q: DVec3, [a, b, c]: [DVec3; 3]) -> Option<bool> {
    const EPS: f64 = 1e-9;
    let n = (b - a).cross(c - a).normalize();
    let (dp, dq) = (n.dot(p - a), n.dot(q - a));
    if dp.abs() < EPS || dq.abs() < EPS {
        return None;
    }
    if (dp > 0.0) == (dq > 0.0) {
        return Some(false);
    }
    let x = p + (q - p) * (dp / (dp - dq));
    let w = [(a, b), (b, c), (c, a)].map(|(u, w)| (w - u).cross(x - u).dot(n));
    if w.iter().any(|&w| w < -EPS) {
        Some(false)
    } else if w.iter().any(|w| w.abs() < EPS) {
        None
    } else {
        Some(true)
    }
}

/// Whether two generic triangles meet: some edge of one pierces the other.
fn float_meets(s: [DVec3; 3], t: [DVec3; 3]) -> Option<bool> {
    let mut any = false;
    for (tri, other) in [(s, t), (t, s)] {
        for k in 0..3 {
            any |= float_pierces(tri[k], tri[(k + 1) % 3], other)?;
        }
    }
    Some(any)
}

#[test]
fn random_pairs_agree_with_a_floating_point_test() {
    let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
    let (mut checked, mut meeting) = (0, 0);
    for _ in 0..50_000 {
        let s = [rng.point(), rng.point(), rng.point()];
        let t = [rng.point(), rng.point(), rng.point()].map(|p| p * 0.7 + v(0.3, 0.0, 0.0));
        let Some(want) = float_meets(s, t) else {
            continue;
        };
        let (a, b) = (Tri::new(s).unwrap(), Tri::new(t).unwrap());
        assert_eq!(
            meet_beyond_shared([0, 1, 2], &a, [3, 4, 5], &b),
            want,
            "{s:?} {t:?}"
        );
        assert_eq!(a.meets(&b), b.meets(&a));
        checked += 1;
        meeting += usize::from(want);
    }
    // Both outcomes are well represented.
    assert!(
        checked > 49_000 && meeting > 5_000 && checked - meeting > 5_000,
        "{checked} {meeting}"
    );
}

/// A random mesh of `n` triangles over a small pool of vertices, so that many share vertices.
fn random_mesh(rng: &mut Xorshift, n: usize, pool: usize) -> IndexedMesh {
    let positions: Vec<DVec3> = (0..pool).map(|_| rng.point()).collect();
    let mut pick = || (rng.unit() * pool as f64) as u32;
    let triangles = (0..n).map(|_| [pick(), pick(), pick()]).collect();
    IndexedMesh::new(positions, triangles)
}

/// Every pair tested, no tree.
fn all_pairs(mesh: &IndexedMesh) -> Vec<[u32; 2]> {
    let n = mesh.positions.len();
    let usable = |t: &[u32; 3]| {
        t.iter().all(|&i| (i as usize) < n) && t[0] != t[1] && t[1] != t[2] && t[0] != t[2]
    };
    let tri = |i: usize| Tri::new(mesh.triangle_positions(i));
    let mut pairs = Vec::new();
    for i in 0..mesh.triangles.len() {
        for j in i + 1..mesh.triangles.len() {
            let (ti, tj) = (mesh.triangles[i], mesh.triangles[j]);
            if !usable(&ti) || !usable(&tj) {
                continue;
            }
            if let (Some(a), Some(b)) = (tri(i), tri(j))
                && meet_beyond_shared(ti, &a, tj, &b)
            {
                pairs.push([i as u32, j as u32]);
            }
        }
    }
    pairs
}

#[test]
fn broad_phase_finds_every_pair() {
    let mut rng = Xorshift(12345);
    for (n, pool) in [(40, 30), (400, 60), (1500, 2000)] {
        let mesh = random_mesh(&mut rng, n, pool);
        let want = all_pairs(&mesh);
        let got = self_intersections(&mesh, 1000).unwrap();
        assert_eq!(got.count, want.len(), "n={n}");
        assert_eq!(got.examples, want[..want.len().min(1000)], "n={n}");
        assert!(!want.is_empty());
        let few = self_intersections(&mesh, 8).unwrap();
        assert_eq!(few.examples, want[..want.len().min(8)]);
    }
}

#[test]
fn closed_meshes_have_none() {
    let sphere = tessellate::sphere(1.0, 65, 33).unwrap().mesh;
    for (name, mesh) in [
        ("cube", cube()),
        ("octahedron", octahedron()),
        ("torus", torus(24, 12)),
        ("sphere", sphere),
    ] {
        assert_eq!(
            self_intersections(&mesh, 8).unwrap(),
            SelfIntersections::default(),
            "{name}"
        );
    }
    assert_eq!(
        self_intersections(&IndexedMesh::default(), 8)
            .unwrap()
            .count,
        0
    );
    let mut nan = cube();
    nan.positions[0].x = f64::NAN;
    assert!(self_intersections(&nan, 8).is_err());
}

#[test]
fn a_vertex_pushed_through_the_other_side() {
    let mut mesh = tessellate::sphere(1.0, 33, 17).unwrap().mesh;
    // The north pole, pushed down through the south half.
    let pole = (0..mesh.positions.len())
        .max_by(|&i, &j| mesh.positions[i].z.total_cmp(&mesh.positions[j].z))
        .unwrap();
    mesh.positions[pole] = v(0.01, 0.02, -1.5);
    let found = self_intersections(&mesh, 1_000_000).unwrap();
    assert!(found.count > 0);
    assert_eq!(found.examples, all_pairs(&mesh));
    // Every pair involves a moved triangle (the rest is the unchanged sphere).
    let moved = |t: u32| mesh.triangles[t as usize].contains(&(pole as u32));
    assert!(found.examples.iter().all(|&[i, j]| moved(i) || moved(j)));
}

#[test]
fn two_interpenetrating_cubes_fixture() {
    let mesh = read_off(&fixture("self_intersecting.off"));
    let found = self_intersections(&mesh, 1000).unwrap();
    // The same pairs as the floating-point test over all pairs (generic position).
    let mut want = Vec::new();
    for i in 0..12 {
        for j in 12..24 {
            let s = mesh.triangle_positions(i);
            let t = mesh.triangle_positions(j);
            if float_meets(s, t).unwrap_or_else(|| panic!("{i} {j} {s:?} {t:?}")) {
                want.push([i as u32, j as u32]);
            }
        }
    }
    assert!(!want.is_empty());
    assert_eq!(found.examples, want);
    assert_eq!(found.count, want.len());
    let half = IndexedMesh::new(mesh.positions.clone(), mesh.triangles[12..].to_vec());
    assert_eq!(self_intersections(&half, 8).unwrap().count, 0);
}

#[test]
fn filters_agree_with_exact_predicates() {
    // Small random meshes over a pool of points in a few kinds of position: exactly coplanar
    // (z = 0, grid-like coordinates with many collinear triples), nearly coplanar, general; every
    // pair that shares 0, 1 or 2 vertices, with and without the filters.
    let mut rng = Xorshift(777);
    let mut decided = [0usize; 2];
    let mut filtered_counts = [0usize; 3];
    for (kind, filtered) in filtered_counts.iter_mut().enumerate() {
        for _ in 0..40 {
            let pool: Vec<DVec3> = (0..12)
                .map(|_| {
                    let p = rng.point();
                    match kind {
                        0 => v((p.x * 4.0).round() / 4.0, (p.y * 4.0).round() / 4.0, 0.0),
                        1 => v(p.x, p.y, p.z * 1e-13),
                        _ => p,
                    }
                })
                .collect();
            let mesh = random_mesh_over(&mut rng, pool, 30);
            for i in 0..mesh.triangles.len() {
                for j in i + 1..mesh.triangles.len() {
                    let (ti, tj) = (mesh.triangles[i], mesh.triangles[j]);
                    if ti[0] == ti[1] || ti[1] == ti[2] || ti[0] == ti[2] {
                        continue;
                    }
                    if tj[0] == tj[1] || tj[1] == tj[2] || tj[0] == tj[2] {
                        continue;
                    }
                    let (Some(a), Some(b)) = (
                        Tri::new(mesh.triangle_positions(i)),
                        Tri::new(mesh.triangle_positions(j)),
                    ) else {
                        continue;
                    };
                    let exact = meet_beyond_shared_exact(ti, &a, tj, &b);
                    assert_eq!(
                        meet_beyond_shared(ti, &a, tj, &b),
                        exact,
                        "{ti:?} {tj:?} {:?}",
                        mesh.positions
                    );
                    assert_eq!(meet_beyond_shared_exact(tj, &b, ti, &a), exact);
                    decided[usize::from(exact)] += 1;
                    // The filters do settle pairs (here: those with no shared vertex).
                    if !ti.iter().any(|x| tj.contains(x)) && filter::separated(a.p, b.p) {
                        assert!(!exact);
                        *filtered += 1;
                    }
                }
            }
        }
    }
    assert!(decided[0] > 1000 && decided[1] > 1000, "{decided:?}");
    assert!(
        filtered_counts.iter().all(|&n| n > 100),
        "{filtered_counts:?}"
    );
}

/// `n` random triangles over the given points.
fn random_mesh_over(rng: &mut Xorshift, positions: Vec<DVec3>, n: usize) -> IndexedMesh {
    let pool = positions.len();
    let mut pick = || ((rng.unit() * pool as f64) as u32).min(pool as u32 - 1);
    let triangles = (0..n).map(|_| [pick(), pick(), pick()]).collect();
    IndexedMesh::new(positions, triangles)
}

/// Repeated triangles (same vertex indices, any order) are tested once for the whole group; the
/// count and the examples are still those of every pair.
#[test]
fn repeated_triangles_count_every_pair() {
    let mut rng = Xorshift(777);
    for (n, pool, copies) in [(60, 30, 40), (300, 80, 200), (800, 1000, 500)] {
        let mut mesh = random_mesh(&mut rng, n, pool);
        for _ in 0..copies {
            let k = (rng.unit() * mesh.triangles.len() as f64) as usize;
            let [a, b, c] = mesh.triangles[k];
            let copy = match (rng.unit() * 3.0) as u32 {
                0 => [a, b, c],
                1 => [b, c, a],
                _ => [a, c, b],
            };
            let at = (rng.unit() * mesh.triangles.len() as f64) as usize;
            mesh.triangles.insert(at, copy);
        }
        let want = all_pairs(&mesh);
        for limit in [1000, 8, 1] {
            let got = self_intersections(&mesh, limit).unwrap();
            assert_eq!(got.count, want.len(), "n={n} limit={limit}");
            assert_eq!(got.examples, want[..want.len().min(limit)], "n={n}");
        }
    }
}

/// 40 000 copies of one triangle (a 2 MB STL) take one test, not 8 · 10⁸.
#[test]
fn many_coincident_triangles_are_fast() {
    let positions = vec![
        v(0.0, 0.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(0.0, 1.0, 0.0),
        v(5.0, 5.0, 5.0),
    ];
    let mut triangles = vec![[0, 1, 2]; 40_000];
    triangles.push([1, 3, 2]);
    let mesh = IndexedMesh::new(positions, triangles);
    let start = std::time::Instant::now();
    let got = self_intersections(&mesh, 4).unwrap();
    assert!(start.elapsed().as_secs_f64() < 2.0, "{:?}", start.elapsed());
    assert_eq!(got.count, 40_000 * 39_999 / 2);
    assert_eq!(got.examples, [[0, 1], [0, 2], [0, 3], [0, 4]]);
}

/// Copies of an exactly collinear triangle take no part, like any degenerate face (the pairwise
/// definition skips them), while copies of a proper triangle still count every pair.
#[test]
fn repeated_collinear_triangles_take_no_part() {
    let positions = vec![
        v(0.0, 0.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(2.0, 0.0, 0.0),
        v(0.0, 1.0, 0.0),
    ];
    let mut triangles = vec![[0, 1, 2], [2, 1, 0], [1, 2, 0], [0, 1, 3], [3, 1, 0]];
    triangles.extend([[0, 2, 1]; 3]);
    let mesh = IndexedMesh::new(positions, triangles);
    let want = all_pairs(&mesh);
    assert_eq!(want, [[3, 4]]);
    let got = self_intersections(&mesh, 8).unwrap();
    assert_eq!(got.count, want.len());
    assert_eq!(got.examples, want);
}

/// [`none_meet`] (projections once, boxes apart skipped) says what testing every pair with
/// [`pair_meets`] says, on small sets of triangles over a shared vertex pool: some share
/// vertices, some lie apart, some cross.
#[test]
fn none_meet_agrees_with_every_pair_tested() {
    let mut rng = Xorshift(0x5eed_cafe_f00d_1234);
    let (mut disjoint, mut meeting) = (0, 0);
    for _ in 0..4000 {
        let pool: Vec<DVec3> = (0..8).map(|_| rng.point() * 0.5).collect();
        let count = 2 + (rng.unit() * 5.0) as usize;
        let mut tris = Vec::new();
        while tris.len() < count {
            let ids = [0, 1, 2].map(|_| (rng.unit() * 8.0) as u32);
            if ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2] {
                let shift = if rng.unit() < 0.5 {
                    rng.point()
                } else {
                    DVec3::ZERO
                };
                // A shifted triangle keeps its ids but not its corners: make its ids its own.
                let ids = if shift == DVec3::ZERO {
                    ids
                } else {
                    ids.map(|i| i + 100 * (tris.len() as u32 + 1))
                };
                let p = [0, 1, 2].map(|k| pool[(ids[k] % 100) as usize] + shift);
                tris.push((ids, p));
            }
        }
        let every_pair = (0..tris.len()).all(|i| {
            (i + 1..tris.len()).all(|j| !pair_meets(tris[i].0, tris[i].1, tris[j].0, tris[j].1))
        });
        assert_eq!(none_meet(&tris), every_pair, "{tris:?}");
        if every_pair {
            disjoint += 1;
        } else {
            meeting += 1;
        }
    }
    assert!(disjoint > 200 && meeting > 200, "{disjoint} {meeting}");
}
