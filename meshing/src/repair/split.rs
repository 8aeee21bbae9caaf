//! Non-manifold edges and vertices: faces join only across edges with exactly two faces, and
//! each vertex gets one copy per fan (group of its faces joined through its own edges).
//! Union-find over face corners; no recursion.

use super::edges::edge_faces;
use glam::DVec3;

/// What the split did.
pub(super) struct Split {
    /// Edges with more than two faces.
    pub edges_cut: usize,
    /// Vertices with more than one fan.
    pub vertices_split: usize,
    /// The vertex count before the split: vertices from here on are copies.
    pub first_copy: usize,
    /// Per vertex (after the split), the vertex it was copied from (itself for originals).
    pub parent: Vec<u32>,
}

/// Union-find over `u32` ids (path halving; the smaller root wins).
pub(super) struct UnionFind(pub(super) Vec<u32>);

impl UnionFind {
    pub(super) fn find(&mut self, mut x: u32) -> u32 {
        while self.0[x as usize] != x {
            let up = self.0[self.0[x as usize] as usize];
            self.0[x as usize] = up;
            x = up;
        }
        x
    }
    pub(super) fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            self.0[ra.max(rb) as usize] = ra.min(rb);
        }
    }
}

/// Cuts non-manifold edges and splits non-manifold vertices (appending copies to `positions`).
pub(super) fn split_non_manifold(positions: &mut Vec<DVec3>, tris: &mut [[u32; 3]]) -> Split {
    let map = edge_faces(tris);
    let edges_cut = map.values().filter(|f| f.len() > 2).count();
    let corner = |f: u32, v: u32, tris: &[[u32; 3]]| -> u32 {
        let k = tris[f as usize].iter().position(|&x| x == v).unwrap_or(0);
        f * 3 + k as u32
    };
    let mut uf = UnionFind((0..tris.len() as u32 * 3).collect());
    for (&(a, b), faces) in &map {
        if let [f, g] = faces[..] {
            for v in [a, b] {
                let (cf, cg) = (corner(f, v, tris), corner(g, v, tris));
                uf.union(cf, cg);
            }
        }
    }
    let first_copy = positions.len();
    let mut parent: Vec<u32> = (0..positions.len() as u32).collect();
    // Per vertex, the fan root that keeps the original index.
    let mut owner = vec![u32::MAX; positions.len()];
    let mut copy_of_root: std::collections::HashMap<u32, u32> = std::collections::HashMap::new();
    let mut split_vertices = std::collections::HashSet::new();
    for (f, t) in tris.iter_mut().enumerate() {
        for (k, v) in t.iter_mut().enumerate() {
            let root = uf.find((f * 3 + k) as u32);
            let o = &mut owner[*v as usize];
            if *o == u32::MAX {
                *o = root;
            } else if *o != root {
                let copy = *copy_of_root.entry(root).or_insert_with(|| {
                    positions.push(positions[*v as usize]);
                    parent.push(*v);
                    (positions.len() - 1) as u32
                });
                split_vertices.insert(*v);
                *v = copy;
            }
        }
    }
    Split {
        edges_cut,
        vertices_split: split_vertices.len(),
        first_copy,
        parent,
    }
}
