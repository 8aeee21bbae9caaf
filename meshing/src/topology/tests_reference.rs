//! The report against a plain reference written from the definitions (a map of undirected edges,
//! a union-find per vertex fan and one over triangles for shells), on random meshes full of
//! defects: boundary, flipped, repeated and fin triangles, bow-ties, unused and collapsed
//! vertices, and closed solids glued at vertices. Every count, every example list, the shells and
//! the genus of each shell must agree, on one thread and on three.

use std::collections::BTreeMap;

use glam::DVec3;

use super::test_meshes::{concat, cube, torus};
use super::{MAX_EXAMPLES, ReportOptions, TopologyReport};
use crate::IndexedMesh;

/// What the reference computes.
#[derive(Debug, PartialEq)]
struct Expected {
    vertices: usize,
    edges: usize,
    faces: usize,
    shells: usize,
    genus_per_shell: Vec<Option<i64>>,
    boundary: (usize, Vec<[u32; 2]>),
    non_manifold: (usize, Vec<[u32; 2]>),
    inconsistent: (usize, Vec<[u32; 2]>),
    non_manifold_vertices: (usize, Vec<u32>),
}

/// Root of `x` in a plain union-find.
fn root(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// Joins the sets of `a` and `b`, the smaller root winning.
fn join(parent: &mut [usize], a: usize, b: usize) {
    let (ra, rb) = (root(parent, a), root(parent, b));
    parent[ra.max(rb)] = ra.min(rb);
}

/// The first examples of a kind, with the count.
fn listed<T: Copy>(all: &[T]) -> (usize, Vec<T>) {
    (all.len(), all.iter().take(MAX_EXAMPLES).copied().collect())
}

/// The report's topology computed from its definitions.
fn reference(mesh: &IndexedMesh) -> Expected {
    let n = mesh.positions.len();
    let tris: Vec<[u32; 3]> = mesh
        .triangles
        .iter()
        .filter(|t| {
            t.iter().all(|&i| (i as usize) < n) && t[0] != t[1] && t[1] != t[2] && t[0] != t[2]
        })
        .copied()
        .collect();
    // Directed uses of each undirected edge.
    let mut uses: BTreeMap<[u32; 2], Vec<(u32, u32)>> = BTreeMap::new();
    for t in &tris {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            uses.entry([a.min(b), a.max(b)]).or_default().push((a, b));
        }
    }
    let (mut boundary, mut non_manifold, mut inconsistent) = (vec![], vec![], vec![]);
    for (&key, list) in &uses {
        match list.as_slice() {
            [_] => boundary.push(key),
            [x, y] if x == y => inconsistent.push(key),
            [_, _] => {}
            _ => non_manifold.push(key),
        }
    }
    // Fans: the triangles at a vertex joined through shared edges at it.
    let mut non_manifold_vertices = vec![];
    let mut used = vec![false; n];
    for v in 0..n as u32 {
        let at: Vec<&[u32; 3]> = tris.iter().filter(|t| t.contains(&v)).collect();
        used[v as usize] = !at.is_empty();
        let mut parent: Vec<usize> = (0..at.len()).collect();
        for i in 0..at.len() {
            for j in 0..i {
                let shared = at[i].iter().any(|&x| x != v && at[j].contains(&x));
                if shared {
                    join(&mut parent, i, j);
                }
            }
        }
        let fans = (0..at.len()).filter(|&i| root(&mut parent, i) == i).count();
        if fans > 1 {
            non_manifold_vertices.push(v);
        }
    }
    // Shells over triangles (sharing a vertex connects), numbered by the smallest triangle.
    let mut parent: Vec<usize> = (0..tris.len()).collect();
    let mut first_at = vec![usize::MAX; n];
    for (t, tri) in tris.iter().enumerate() {
        for &v in tri {
            match first_at[v as usize] {
                usize::MAX => first_at[v as usize] = t,
                f => join(&mut parent, f, t),
            }
        }
    }
    let mut number = BTreeMap::new();
    let shell_of: Vec<usize> = (0..tris.len())
        .map(|t| {
            let r = root(&mut parent, t);
            let next = number.len();
            *number.entry(r).or_insert(next)
        })
        .collect();
    let shells = number.len();
    let (mut v_s, mut e_s, mut f_s) = (vec![0i64; shells], vec![0i64; shells], vec![0i64; shells]);
    let mut bad = vec![false; shells];
    for &s in &shell_of {
        f_s[s] += 1;
    }
    for v in 0..n {
        if first_at[v] != usize::MAX {
            v_s[shell_of[first_at[v]]] += 1;
        }
    }
    for v in &non_manifold_vertices {
        bad[shell_of[first_at[*v as usize]]] = true;
    }
    for (key, list) in &uses {
        let s = shell_of[first_at[key[0] as usize]];
        e_s[s] += 1;
        let fine = list.len() == 2 && list[0] != list[1];
        bad[s] |= !fine;
    }
    let genus_per_shell = (0..shells)
        .map(|s| {
            let twice = 2 - (v_s[s] - e_s[s] + f_s[s]);
            (!bad[s] && twice >= 0 && twice % 2 == 0).then_some(twice / 2)
        })
        .collect();
    Expected {
        vertices: used.iter().filter(|&&u| u).count(),
        edges: uses.len(),
        faces: tris.len(),
        shells,
        genus_per_shell,
        boundary: listed(&boundary),
        non_manifold: listed(&non_manifold),
        inconsistent: listed(&inconsistent),
        non_manifold_vertices: listed(&non_manifold_vertices),
    }
}

/// The same fields from the report.
fn reported(r: &TopologyReport) -> Expected {
    Expected {
        vertices: r.vertices,
        edges: r.edges,
        faces: r.faces,
        shells: r.shells,
        genus_per_shell: r.genus_per_shell.clone(),
        boundary: (r.boundary_edges, r.examples.boundary_edges.clone()),
        non_manifold: (r.non_manifold_edges, r.examples.non_manifold_edges.clone()),
        inconsistent: (r.inconsistent_edges, r.examples.inconsistent_edges.clone()),
        non_manifold_vertices: (
            r.non_manifold_vertices,
            r.examples.non_manifold_vertices.clone(),
        ),
    }
}

/// A tiny deterministic generator (xorshift).
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n as u64) as usize
    }
}

/// A random mess: pieces of closed solids (some triangles dropped, flipped, repeated or given a
/// fin), relabelled vertices, and random triangles over a small pool (bow-ties, fans of more than
/// 64 triangles at one vertex, out-of-range and collapsed indices).
fn random_mesh(rng: &mut Rng) -> IndexedMesh {
    let mut mesh = concat(&cube(), &torus(6 + rng.below(4) as u32, 5));
    mesh = concat(&mesh, &torus(4, 3));
    let n = mesh.positions.len();
    // Glue some vertices together (non-manifold vertices and edges, new genus).
    for _ in 0..rng.below(4) {
        let (a, b) = (rng.below(n) as u32, rng.below(n) as u32);
        for t in &mut mesh.triangles {
            for i in t.iter_mut() {
                if *i == a {
                    *i = b;
                }
            }
        }
    }
    let mut tris = Vec::new();
    for &t in &mesh.triangles {
        match rng.below(40) {
            0 => {}
            1 => tris.push([t[0], t[2], t[1]]),
            2 => tris.extend([t, t]),
            3 => tris.extend([t, [t[0], t[1], rng.below(n) as u32]]),
            _ => tris.push(t),
        }
    }
    let hub = rng.below(n) as u32;
    for _ in 0..rng.below(3) * 40 {
        tris.push([hub, rng.below(n) as u32, rng.below(n) as u32]);
    }
    for _ in 0..rng.below(10) {
        let k = rng.below(4);
        tris.push(match k {
            0 => [1, 1, 2],
            1 => [0, 1, n as u32 + 5],
            _ => [
                rng.below(n) as u32,
                rng.below(n) as u32,
                rng.below(n) as u32,
            ],
        });
    }
    // Relabel the vertices so that the smaller end of an edge is not always its first corner.
    let mut order: Vec<u32> = (0..n as u32 + 3).collect();
    for i in (1..order.len()).rev() {
        order.swap(i, rng.below(i + 1));
    }
    let relabel = |i: u32| order.get(i as usize).copied().unwrap_or(i + 100);
    let mut positions = mesh.positions.clone();
    positions.extend([DVec3::ZERO; 3]);
    let mut moved = positions.clone();
    for (i, p) in positions.iter().enumerate() {
        moved[order[i] as usize] = *p;
    }
    IndexedMesh::new(moved, tris.iter().map(|t| t.map(relabel)).collect())
}

#[test]
fn random_defective_meshes_match_the_reference_on_any_thread_count() {
    let skip = ReportOptions {
        self_intersections: false,
    };
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let pools: Vec<rayon::ThreadPool> = [1, 3]
        .iter()
        .map(|&t| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(t)
                .build()
                .unwrap()
        })
        .collect();
    let mut defective = 0;
    for _ in 0..200 {
        let mesh = random_mesh(&mut rng);
        let expected = reference(&mesh);
        defective += usize::from(expected.genus_per_shell.iter().any(Option::is_none));
        for pool in &pools {
            let report = pool.install(|| TopologyReport::with_options(&mesh, &skip));
            assert_eq!(reported(&report), expected);
        }
    }
    // The generator makes defects most of the time, and sound shells too.
    assert!(defective > 100, "{defective}");
}

#[test]
fn sound_solids_match_the_reference() {
    let mesh = concat(&concat(&torus(9, 7), &cube()), &torus(5, 4));
    let report = TopologyReport::of(&mesh);
    assert_eq!(reported(&report), reference(&mesh));
    assert_eq!(report.genus_per_shell, vec![Some(1), Some(0), Some(1)]);
}

/// `count` unit tetrahedra, tetrahedron `s` moved to `x = 2s`, with their triangles interleaved
/// (all first triangles, then all second ones, …) and their vertices numbered in reverse, so
/// that triangle order, vertex order and thread chunks all disagree; then `tail` (whose vertices
/// follow).
fn interleaved_tetrahedra(count: usize, tail: &IndexedMesh) -> IndexedMesh {
    let tet = super::test_meshes::tetrahedron();
    let mut positions = vec![DVec3::ZERO; 4 * count];
    for s in 0..count {
        let base = 4 * (count - 1 - s);
        for (k, p) in tet.positions.iter().enumerate() {
            positions[base + k] = *p + DVec3::X * (2 * s) as f64;
        }
    }
    let mut triangles = Vec::new();
    for t in &tet.triangles {
        for s in 0..count {
            let base = (4 * (count - 1 - s)) as u32;
            triangles.push(t.map(|i| i + base));
        }
    }
    let offset = positions.len() as u32;
    positions.extend(&tail.positions);
    triangles.extend(tail.triangles.iter().map(|t| t.map(|i| i + offset)));
    IndexedMesh::new(positions, triangles)
}

#[test]
fn many_shells_are_numbered_by_first_triangle_across_chunks() {
    // 200 shells and a large torus (parallel per-shell tallies, several triangle chunks), and
    // 40 000 shells (serial tallies).
    for (count, tail) in [(200, torus(220, 100)), (40_000, cube())] {
        let mesh = interleaved_tetrahedra(count, &tail);
        for threads in [1, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let r = pool.install(|| TopologyReport::of(&mesh));
            assert_eq!(r.shells, count + 1);
            assert!(r.genus_per_shell[..count].iter().all(|&g| g == Some(0)));
            assert!(r.is_closed_manifold());
            assert_eq!(r.vertices, mesh.positions.len());
            for (s, b) in r.shell_boxes[..count].iter().enumerate() {
                assert_eq!(b[0], DVec3::X * (2 * s) as f64, "shell {s}");
                assert_eq!(b[1], DVec3::X * (2 * s) as f64 + DVec3::ONE, "shell {s}");
            }
        }
    }
}

/// A large torus in spatial order (so the report takes its stars a window at a time) with
/// defects of every kind and a few vertices renumbered last (as marching cubes numbers its
/// centre vertices), whose corners are filed apart from their chunks: the windowed vertex pass
/// must agree with the reference, and with the pass over the whole mesh's stars.
#[test]
fn windowed_vertex_pass_matches_the_reference_with_far_vertices_and_defects() {
    let skip = ReportOptions {
        self_intersections: false,
    };
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    let base = torus(240, 100);
    let n = base.positions.len();
    // Every 50th vertex (and a random few) renumbered after all the others.
    let far: Vec<bool> = (0..n).map(|v| v % 50 == 7 || rng.below(300) == 0).collect();
    let mut order = vec![0u32; n];
    let mut next = 0u32;
    for pass in [false, true] {
        for v in 0..n {
            if far[v] == pass {
                order[v] = next;
                next += 1;
            }
        }
    }
    let mut positions = vec![DVec3::ZERO; n];
    for (v, p) in base.positions.iter().enumerate() {
        positions[order[v] as usize] = *p;
    }
    let mut tris = Vec::new();
    for (i, &t) in base.triangles.iter().enumerate() {
        let t = t.map(|v| order[v as usize]);
        match (i % 997, rng.below(2000)) {
            (0, _) => {}
            (1, _) => tris.push([t[0], t[2], t[1]]),
            (2, _) => tris.extend([t, t]),
            (_, 0) => tris.extend([t, [t[0], t[1], rng.below(n) as u32]]),
            _ => tris.push(t),
        }
    }
    // Two vertices glued: a non-manifold vertex.
    let (a, b) = (order[1000], order[n - 1000]);
    for t in &mut tris {
        for i in t.iter_mut() {
            if *i == a {
                *i = b;
            }
        }
    }
    let mesh = IndexedMesh::new(positions, tris);
    let expected = reference(&mesh);
    let usable = crate::usable::usable_triangles(&mesh);
    for threads in [1, 2, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let windowed = super::survey::Survey::windowed(&usable, n).expect("spatial order");
            let stars = crate::stars::Stars::build(&usable, n);
            let global = super::survey::Survey::of(&usable, &stars);
            assert_eq!(windowed.shares, global.shares, "{threads} threads");
            assert_eq!(windowed.counts, global.counts);
            let report = TopologyReport::with_options(&mesh, &skip);
            assert_eq!(reported(&report), expected, "{threads} threads");
        });
    }
    assert!(expected.boundary.0 > 0 && expected.inconsistent.0 > 0);
    assert!(expected.non_manifold.0 > 0 && expected.non_manifold_vertices.0 > 0);
}
