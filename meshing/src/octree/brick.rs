//! One leaf brick: sample its grid points with its pruned program, then emit its crossing-edge
//! vertices and its cells' triangles keyed by grid position, for global assembly.

use super::subdivide::Node;
use crate::marching_cubes::table::{case_table, edge_origin};
use crate::marching_cubes::{GridSpec, edge_vertex, inside};
use glam::DVec3;
use solidkit_kernel::program::BatchScratch;

/// Key of the grid edge along `axis` from sample `(i, j, k)`: sorts like the dense path's order.
pub(crate) fn edge_key(i: usize, j: usize, k: usize, axis: usize) -> u64 {
    ((((k as u64) << 20 | j as u64) << 20 | i as u64) << 2) | axis as u64
}

/// Key of cell `(i, j, k)` and the triangle's ordinal in its case: sorts like the dense path.
pub(crate) fn triangle_key(i: usize, j: usize, k: usize, ordinal: usize) -> u64 {
    ((((k as u64) << 20 | j as u64) << 20 | i as u64) << 4) | ordinal as u64
}

/// What one brick contributes.
#[derive(Debug, Default)]
pub(crate) struct BrickOutput {
    /// Crossing edges (key, vertex); edges on brick faces also appear in the neighbour.
    pub edges: Vec<(u64, DVec3)>,
    /// Triangles (key, edge keys of the corners).
    pub triangles: Vec<(u64, [u64; 3])>,
    /// Samples evaluated.
    pub samples: u64,
}

pub(crate) fn process(node: &Node, spec: &GridSpec) -> BrickOutput {
    let e = node.extent(spec);
    let n = [e[0] + 1, e[1] + 1, e[2] + 1];
    let count = n[0] * n[1] * n[2];
    let (mut x, mut y, mut z) = (
        Vec::with_capacity(count),
        Vec::with_capacity(count),
        Vec::with_capacity(count),
    );
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                x.push(spec.coordinate(0, node.min[0] + i));
                y.push(spec.coordinate(1, node.min[1] + j));
                z.push(spec.coordinate(2, node.min[2] + k));
            }
        }
    }
    let mut values = vec![0f32; count];
    node.program.eval_many(
        &x,
        &y,
        &z,
        &mut values,
        &mut BatchScratch::new(&node.program),
    );
    let at = |i: usize, j: usize, k: usize| values[i + n[0] * (j + n[1] * k)];
    let mut out = BrickOutput {
        samples: count as u64,
        ..Default::default()
    };
    let g = |i: usize, j: usize, k: usize| (node.min[0] + i, node.min[1] + j, node.min[2] + k);
    // Crossing edges among the brick's samples.
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                let v = at(i, j, k);
                let (gi, gj, gk) = g(i, j, k);
                let p = spec.point(gi, gj, gk);
                let ends = [
                    (i + 1 < n[0], (i + 1, j, k)),
                    (j + 1 < n[1], (i, j + 1, k)),
                    (k + 1 < n[2], (i, j, k + 1)),
                ];
                for (axis, &(exists, (a, b, c))) in ends.iter().enumerate() {
                    if !exists {
                        continue;
                    }
                    let (ga, gb, gc) = g(a, b, c);
                    if let Some(q) = edge_vertex(p, v, spec.point(ga, gb, gc), at(a, b, c)) {
                        out.edges.push((edge_key(gi, gj, gk, axis), q));
                    }
                }
            }
        }
    }
    // Triangles of the brick's cells.
    let table = case_table();
    for k in 0..e[2] {
        for j in 0..e[1] {
            for i in 0..e[0] {
                let mut mask = 0usize;
                for c in 0..8 {
                    if inside(at(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))) {
                        mask |= 1 << c;
                    }
                }
                let (gi, gj, gk) = g(i, j, k);
                for (ordinal, tri) in table.cases[mask].iter().enumerate() {
                    let corners = tri.map(|edge| {
                        let (axis, o) = edge_origin(edge);
                        edge_key(gi + o[0], gj + o[1], gk + o[2], axis)
                    });
                    out.triangles
                        .push((triangle_key(gi, gj, gk, ordinal), corners));
                }
            }
        }
    }
    out
}
