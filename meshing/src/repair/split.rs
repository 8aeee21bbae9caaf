//! Non-manifold edges and vertices: faces join only across edges with exactly two faces, and
//! each vertex gets one copy per fan (group of its faces joined through its own edges).
//! Union-find over face corners; no recursion.

use crate::topology::{CornerLoops, EdgeTable};
use glam::DVec3;
use std::collections::{HashMap, HashSet};

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

/// Cuts non-manifold edges and splits non-manifold vertices (appending copies to `positions`);
/// `table` is the edge table of `tris`.
pub(super) fn split_non_manifold(
    positions: &mut Vec<DVec3>,
    tris: &mut [[u32; 3]],
    table: &EdgeTable,
) -> Split {
    let loops: &[[u32; 3]] = tris;
    let mut edges_cut = 0;
    let mut uf = UnionFind((0..tris.len() as u32 * 3).collect());
    for edge in table.edges() {
        let [lo, _] = edge.vertices();
        let mut corners = edge.corners();
        match (corners.next(), corners.next(), corners.next()) {
            (Some(f), Some(g), None) => {
                // The corners of the two faces at each end of the edge join.
                let ends = |c: usize| {
                    let n = loops.next(c);
                    if loops.origin(c) == lo {
                        [c, n]
                    } else {
                        [n, c]
                    }
                };
                let (ef, eg) = (ends(f), ends(g));
                uf.union(ef[0] as u32, eg[0] as u32);
                uf.union(ef[1] as u32, eg[1] as u32);
            }
            (_, _, Some(_)) => edges_cut += 1,
            _ => {}
        }
    }
    let first_copy = positions.len();
    let mut parent: Vec<u32> = (0..positions.len() as u32).collect();
    // Per vertex, the fan root that keeps the original index.
    let mut owner = vec![u32::MAX; positions.len()];
    let mut copy_of_root: HashMap<u32, u32> = HashMap::new();
    let mut split_vertices = HashSet::new();
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
