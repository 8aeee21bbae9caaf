//! Test meshes built in code (cube, tetrahedron, octahedron, torus and the defect family that
//! mirrors `fixtures/meshes/defects/`), and a tiny OFF reader to check the fixtures against them.

use glam::DVec3;

use crate::IndexedMesh;

/// Unit cube corners: bottom square 0-3 (z = 0) and top square 4-7 (z = 1), CCW seen from above.
pub(crate) fn cube_positions() -> Vec<DVec3> {
    [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
    ]
    .map(DVec3::from)
    .to_vec()
}

/// The 12 outward (CCW) triangles of the unit cube, two per side.
pub(crate) const CUBE_TRIANGLES: [[u32; 3]; 12] = [
    [0, 2, 1],
    [0, 3, 2],
    [4, 5, 6],
    [4, 6, 7],
    [0, 1, 5],
    [0, 5, 4],
    [3, 7, 6],
    [3, 6, 2],
    [0, 4, 7],
    [0, 7, 3],
    [1, 2, 6],
    [1, 6, 5],
];

/// The six outward quads of the unit cube.
pub(crate) fn cube_quads() -> Vec<Vec<u32>> {
    vec![
        vec![0, 3, 2, 1],
        vec![4, 5, 6, 7],
        vec![0, 1, 5, 4],
        vec![3, 7, 6, 2],
        vec![0, 4, 7, 3],
        vec![1, 2, 6, 5],
    ]
}

/// The closed unit cube `[0,1]³`: V=8 E=18 F=12 χ=2.
pub(crate) fn cube() -> IndexedMesh {
    IndexedMesh::new(cube_positions(), CUBE_TRIANGLES.to_vec())
}

/// The cube translated by `offset`, with indices shifted by `base`.
fn cube_at(offset: DVec3, base: u32) -> IndexedMesh {
    IndexedMesh::new(
        cube_positions().into_iter().map(|p| p + offset).collect(),
        CUBE_TRIANGLES.map(|t| t.map(|i| i + base)).to_vec(),
    )
}

/// `a` followed by `b` (indices of `b` shifted).
pub(crate) fn concat(a: &IndexedMesh, b: &IndexedMesh) -> IndexedMesh {
    let base = a.positions.len() as u32;
    let mut out = a.clone();
    out.positions.extend_from_slice(&b.positions);
    out.triangles
        .extend(b.triangles.iter().map(|t| t.map(|i| i + base)));
    out
}

/// Two disjoint unit cubes, the second at x = 3.
pub(crate) fn two_cubes() -> IndexedMesh {
    concat(&cube(), &cube_at(DVec3::new(3.0, 0.0, 0.0), 0))
}

/// The cube without its last triangle `[1, 6, 5]`: 3 boundary edges.
pub(crate) fn cube_hole() -> IndexedMesh {
    let mut mesh = cube();
    mesh.triangles.pop();
    mesh
}

/// The cube with its last triangle wound backwards: 3 inconsistent edges.
pub(crate) fn cube_flipped() -> IndexedMesh {
    let mut mesh = cube();
    mesh.triangles[11] = [1, 5, 6];
    mesh
}

/// The cube plus triangle `[0, 1, 8]` on edge 0-1: one edge of three triangles, two boundary edges.
pub(crate) fn fin() -> IndexedMesh {
    let mut mesh = cube();
    mesh.positions.push(DVec3::new(0.5, -1.0, -1.0));
    mesh.triangles.push([0, 1, 8]);
    mesh
}

/// Two tetrahedra touching at vertex 0 only: one non-manifold vertex, one shell.
pub(crate) fn bowtie() -> IndexedMesh {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [-1.0, 0.0, 0.0],
        [-1.0, 1.0, 0.0],
        [-1.0, 0.0, 1.0],
    ]
    .map(DVec3::from)
    .to_vec();
    let triangles = vec![
        [0, 2, 1],
        [0, 1, 3],
        [0, 3, 2],
        [1, 2, 3],
        [4, 5, 0],
        [4, 0, 6],
        [4, 6, 5],
        [0, 5, 6],
    ];
    IndexedMesh::new(positions, triangles)
}

/// Two triangles sharing only vertex 0: two boundary loops through one vertex.
pub(crate) fn open_bowtie() -> IndexedMesh {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [-1.0, -1.0, 0.0],
    ]
    .map(DVec3::from)
    .to_vec();
    IndexedMesh::new(positions, vec![[0, 1, 2], [0, 3, 4]])
}

/// The cube with triangle `[0, 2, 1]` repeated: three edges used by three triangles.
pub(crate) fn duplicate_triangle() -> IndexedMesh {
    let mut mesh = cube();
    mesh.triangles.push([0, 2, 1]);
    mesh
}

/// The cube plus a collapsed triangle `[0, 0, 1]` (repeated index).
pub(crate) fn collapsed_triangle() -> IndexedMesh {
    let mut mesh = cube();
    mesh.triangles.push([0, 0, 1]);
    mesh
}

/// The cube plus a triangle `[0, 1, 99]` whose last index is out of range.
pub(crate) fn out_of_range_triangle() -> IndexedMesh {
    let mut mesh = cube();
    mesh.triangles.push([0, 1, 99]);
    mesh
}

/// The cube with the midpoint 8 of edge 0-1 inserted on the bottom side only, and the zero-area
/// sliver `[1, 0, 8]` closing the T-junction: a closed manifold with one degenerate face
/// (V=9 E=21 F=14 χ=2).
pub(crate) fn sliver_cube() -> IndexedMesh {
    let mut mesh = cube();
    mesh.positions.push(DVec3::new(0.5, 0.0, 0.0));
    // Bottom triangle [0, 2, 1] split at 8 (which lies on its edge 1-0).
    mesh.triangles[0] = [0, 2, 8];
    mesh.triangles.push([8, 2, 1]);
    mesh.triangles.push([1, 0, 8]);
    mesh
}

/// The regular tetrahedron corner `(0,0,0), e_x, e_y, e_z`: volume 1/6.
pub(crate) fn tetrahedron() -> IndexedMesh {
    let positions = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ]
    .map(DVec3::from)
    .to_vec();
    IndexedMesh::new(positions, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
}

/// The octahedron with vertices `±e_x, ±e_y, ±e_z`: volume 4/3, area 4√3.
pub(crate) fn octahedron() -> IndexedMesh {
    let positions = [
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ]
    .map(DVec3::from)
    .to_vec();
    let mut triangles = Vec::new();
    for x in [0u32, 1] {
        for y in [2u32, 3] {
            for z in [4u32, 5] {
                // Octant sign parity decides the winding.
                let positive = (x + y + z) % 2 == 0;
                triangles.push(if positive { [x, y, z] } else { [x, z, y] });
            }
        }
    }
    IndexedMesh::new(positions, triangles)
}

/// A torus (R = 2, r = 0.5) as an `n × m` grid of outward quads.
pub(crate) fn torus_quads(n: u32, m: u32) -> (Vec<DVec3>, Vec<Vec<u32>>) {
    let mut positions = Vec::with_capacity((n * m) as usize);
    for i in 0..n {
        let u = std::f64::consts::TAU * f64::from(i) / f64::from(n);
        for j in 0..m {
            let v = std::f64::consts::TAU * f64::from(j) / f64::from(m);
            let ring = 2.0 + 0.5 * v.cos();
            positions.push(DVec3::new(ring * u.cos(), ring * u.sin(), 0.5 * v.sin()));
        }
    }
    let id = |i: u32, j: u32| (i % n) * m + (j % m);
    let mut quads = Vec::with_capacity((n * m) as usize);
    for i in 0..n {
        for j in 0..m {
            quads.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    (positions, quads)
}

/// The torus grid with every quad split in two triangles: χ = 0, genus 1.
pub(crate) fn torus(n: u32, m: u32) -> IndexedMesh {
    let (positions, quads) = torus_quads(n, m);
    let triangles = quads
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    IndexedMesh::new(positions, triangles)
}

/// Reads a small OFF file (comments after `#`; faces must be triangles).
pub(crate) fn read_off(text: &str) -> IndexedMesh {
    let mut tokens = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .flat_map(str::split_whitespace);
    assert_eq!(tokens.next(), Some("OFF"));
    let mut number = || {
        tokens
            .next()
            .expect("truncated OFF")
            .parse::<f64>()
            .unwrap()
    };
    let (nv, nf, _) = (number() as usize, number() as usize, number());
    let positions = (0..nv)
        .map(|_| DVec3::new(number(), number(), number()))
        .collect();
    let triangles = (0..nf)
        .map(|_| {
            assert_eq!(number(), 3.0, "only triangles");
            [number() as u32, number() as u32, number() as u32]
        })
        .collect();
    IndexedMesh::new(positions, triangles)
}

/// The text of `fixtures/meshes/defects/<name>`.
pub(crate) fn fixture(name: &str) -> String {
    let path = format!(
        "{}/../fixtures/meshes/defects/{name}",
        env!("CARGO_MANIFEST_DIR")
    );
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}
