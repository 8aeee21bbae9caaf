//! One leaf brick: sample its grid points with its pruned program, then list the crossing edges
//! it owns and its cells' triangles, both grouped by grid row in the dense path's order.
//!
//! Ownership: a brick owns the edges whose lower sample lies in it — local coordinates below the
//! brick size, or up to its extent for the last brick along an axis (the grid's far faces). An edge
//! on a face shared with a culled neighbour never crosses the surface, so nothing is lost.

use super::subdivide::Node;
use crate::marching_cubes::table::{case_table, edge_origin};
use crate::marching_cubes::{GridSpec, edge_vertex, inside};
use glam::DVec3;
use solidkit_kernel::program::BatchScratch;

/// Key of the grid edge along `axis` from global sample `(i, j, k)`.
pub(crate) fn edge_key(i: usize, j: usize, k: usize, axis: usize) -> u64 {
    ((((k as u64) << 20 | j as u64) << 20 | i as u64) << 2) | axis as u64
}

/// The sample coordinates and axis of an edge key.
pub(crate) fn edge_parts(key: u64) -> ([usize; 3], usize) {
    let axis = (key & 3) as usize;
    let rest = key >> 2;
    let mask = (1u64 << 20) - 1;
    (
        [
            (rest & mask) as usize,
            (rest >> 20 & mask) as usize,
            (rest >> 40) as usize,
        ],
        axis,
    )
}

/// What one brick contributes.
#[derive(Debug, Default)]
pub(crate) struct BrickOutput {
    /// Brick coordinates (cell minimum / brick size).
    pub coord: [usize; 3],
    /// Owned sample rows per axis: lower samples with local coordinate below this are owned.
    pub owned: [usize; 3],
    /// Cells per axis in the brick.
    pub extent: [usize; 3],
    /// Owned crossing edges as (local `i << 2 | axis`, vertex), row by row (`k`, then `j`).
    pub edges: Vec<(u16, DVec3)>,
    /// Start of each owned row `(k, j)` in `edges` (`owned[2] · owned[1] + 1` entries).
    pub edge_rows: Vec<u32>,
    /// Triangles as corner edge keys, in cell order (`k`, `j`, `i`) then case order.
    pub triangles: Vec<[u64; 3]>,
    /// Start of each cell row `(k, j)` in `triangles` (`extent[2] · extent[1] + 1` entries).
    pub triangle_rows: Vec<u32>,
    /// Samples evaluated.
    pub samples: u64,
}

/// Samples the brick's points (x fastest) with its program.
fn sample(node: &Node, spec: &GridSpec, n: [usize; 3]) -> Vec<f32> {
    let count = n[0] * n[1] * n[2];
    let xs: Vec<f32> = (0..n[0])
        .map(|i| spec.coordinate(0, node.min[0] + i))
        .collect();
    let (mut x, mut y, mut z) = (
        Vec::with_capacity(count),
        Vec::with_capacity(count),
        Vec::with_capacity(count),
    );
    for k in 0..n[2] {
        let zk = spec.coordinate(2, node.min[2] + k);
        for j in 0..n[1] {
            let yj = spec.coordinate(1, node.min[1] + j);
            x.extend_from_slice(&xs);
            y.extend(std::iter::repeat_n(yj, n[0]));
            z.extend(std::iter::repeat_n(zk, n[0]));
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
    values
}

pub(crate) fn process(node: &Node, spec: &GridSpec, brick: usize) -> BrickOutput {
    let e = node.extent(spec);
    let n = [e[0] + 1, e[1] + 1, e[2] + 1];
    let values = sample(node, spec, n);
    let at = |i: usize, j: usize, k: usize| values[i + n[0] * (j + n[1] * k)];
    let owned = [0, 1, 2].map(|a| {
        if node.min[a] + e[a] == spec.cells[a] {
            e[a] + 1
        } else {
            brick.min(e[a])
        }
    });
    let mut out = BrickOutput {
        coord: node.min.map(|m| m / brick),
        owned,
        extent: e,
        samples: values.len() as u64,
        ..Default::default()
    };
    let point = |i: usize, j: usize, k: usize| {
        spec.point(node.min[0] + i, node.min[1] + j, node.min[2] + k)
    };
    out.edge_rows.push(0);
    for k in 0..owned[2] {
        for j in 0..owned[1] {
            for i in 0..owned[0] {
                let v = at(i, j, k);
                let ends = [
                    (i + 1 < n[0], (i + 1, j, k)),
                    (j + 1 < n[1], (i, j + 1, k)),
                    (k + 1 < n[2], (i, j, k + 1)),
                ];
                for (axis, &(exists, (a, b, c))) in ends.iter().enumerate() {
                    if !exists {
                        continue;
                    }
                    if let Some(q) = edge_vertex(point(i, j, k), v, point(a, b, c), at(a, b, c)) {
                        out.edges.push(((i << 2 | axis) as u16, q));
                    }
                }
            }
            out.edge_rows.push(out.edges.len() as u32);
        }
    }
    let table = case_table();
    out.triangle_rows.push(0);
    for k in 0..e[2] {
        for j in 0..e[1] {
            for i in 0..e[0] {
                let mut mask = 0usize;
                for c in 0..8 {
                    if inside(at(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))) {
                        mask |= 1 << c;
                    }
                }
                let (gi, gj, gk) = (node.min[0] + i, node.min[1] + j, node.min[2] + k);
                for tri in &table.cases[mask] {
                    out.triangles.push(tri.map(|edge| {
                        let (axis, o) = edge_origin(edge);
                        edge_key(gi + o[0], gj + o[1], gk + o[2], axis)
                    }));
                }
            }
            out.triangle_rows.push(out.triangles.len() as u32);
        }
    }
    out
}
