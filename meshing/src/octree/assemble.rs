//! Merging brick outputs into one mesh numbered exactly as the dense path numbers it, with linear
//! walks instead of sorts: vertices by grid row `(k, j)` then `(i, axis)`, triangles by cell row
//! then `i` and case order. Each grid row is covered by the bricks of one brick row, visited in
//! `x` order, so concatenating their row segments gives the dense order.

use super::brick::{BrickOutput, edge_parts};
use crate::sink::MeshSink;
use rayon::prelude::*;
use std::collections::HashMap;

/// Finds a brick by its coordinates: a dense table when small enough, else a hash map.
enum BrickIndex {
    Dense { dims: [usize; 3], slots: Vec<u32> },
    Sparse(HashMap<[usize; 3], u32>),
}

impl BrickIndex {
    fn new(bricks: &[BrickOutput], dims: [usize; 3]) -> Self {
        let total = dims[0].saturating_mul(dims[1]).saturating_mul(dims[2]);
        if total <= 1 << 24 {
            let mut slots = vec![u32::MAX; total];
            for (b, o) in bricks.iter().enumerate() {
                slots[o.coord[0] + dims[0] * (o.coord[1] + dims[1] * o.coord[2])] = b as u32;
            }
            BrickIndex::Dense { dims, slots }
        } else {
            BrickIndex::Sparse(
                bricks
                    .iter()
                    .enumerate()
                    .map(|(b, o)| (o.coord, b as u32))
                    .collect(),
            )
        }
    }

    fn get(&self, c: [usize; 3]) -> Option<usize> {
        match self {
            BrickIndex::Dense { dims, slots } => {
                let s = slots[c[0] + dims[0] * (c[1] + dims[1] * c[2])];
                (s != u32::MAX).then_some(s as usize)
            }
            BrickIndex::Sparse(map) => map.get(&c).map(|&b| b as usize),
        }
    }
}

/// Owner brick coordinate and local index of global sample `g` along an axis.
fn owner(g: usize, brick: usize, bricks_along: usize) -> (usize, usize) {
    let b = (g / brick).min(bricks_along - 1);
    (b, g - b * brick)
}

pub(crate) fn assemble(
    mut bricks: Vec<BrickOutput>,
    cells: [usize; 3],
    brick: usize,
    sink: &mut impl MeshSink,
) {
    let dims = cells.map(|c| c.div_ceil(brick).max(1));
    bricks.sort_unstable_by_key(|b| (b.coord[2], b.coord[1], b.coord[0]));
    let index = BrickIndex::new(&bricks, dims);
    // Bricks of each brick row (z, y), in x order.
    let mut rows: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (b, o) in bricks.iter().enumerate() {
        rows.entry((o.coord[2], o.coord[1])).or_default().push(b);
    }
    // Vertex numbering: the base index of every owned edge row of every brick.
    let mut bases: Vec<Vec<u32>> = bricks.iter().map(|o| vec![0; o.edge_rows.len()]).collect();
    let mut order: Vec<(usize, usize)> = Vec::new(); // (brick, row) in global order
    let mut count = 0u32;
    for k in 0..=cells[2] {
        let (bk, kl) = owner(k, brick, dims[2]);
        for j in 0..=cells[1] {
            let (bj, jl) = owner(j, brick, dims[1]);
            for &b in rows.get(&(bk, bj)).map_or(&[][..], Vec::as_slice) {
                let o = &bricks[b];
                if kl >= o.owned[2] || jl >= o.owned[1] {
                    continue;
                }
                let r = kl * o.owned[1] + jl;
                bases[b][r] = count;
                count += o.edge_rows[r + 1] - o.edge_rows[r];
                order.push((b, r));
            }
        }
    }
    // Triangle corners to vertex numbers, brick by brick in parallel.
    let resolved: Vec<Vec<[u32; 3]>> = bricks
        .par_iter()
        .map(|o| {
            o.triangles
                .iter()
                .map(|t| t.map(|key| vertex_number(key, &bricks, &bases, &index, brick, dims)))
                .collect()
        })
        .collect();
    sink.reserve(count as usize, resolved.iter().map(Vec::len).sum());
    let mut ids = Vec::with_capacity(count as usize);
    for &(b, r) in &order {
        let o = &bricks[b];
        let span = o.edge_rows[r] as usize..o.edge_rows[r + 1] as usize;
        ids.extend(o.edges[span].iter().map(|e| sink.add_vertex(e.1)));
    }
    for k in 0..cells[2] {
        let (bk, kl) = (k / brick, k % brick);
        for j in 0..cells[1] {
            let (bj, jl) = (j / brick, j % brick);
            for &b in rows.get(&(bk, bj)).map_or(&[][..], Vec::as_slice) {
                let o = &bricks[b];
                let r = kl * o.extent[1] + jl;
                let span = o.triangle_rows[r] as usize..o.triangle_rows[r + 1] as usize;
                for t in &resolved[b][span] {
                    sink.add_triangle(t.map(|v| ids[v as usize]));
                }
            }
        }
    }
}

/// The number of the vertex on the edge with global key `key`.
fn vertex_number(
    key: u64,
    bricks: &[BrickOutput],
    bases: &[Vec<u32>],
    index: &BrickIndex,
    brick: usize,
    dims: [usize; 3],
) -> u32 {
    let (s, axis) = edge_parts(key);
    let (bx, il) = owner(s[0], brick, dims[0]);
    let (by, jl) = owner(s[1], brick, dims[1]);
    let (bz, kl) = owner(s[2], brick, dims[2]);
    let b = index
        .get([bx, by, bz])
        .expect("a crossing edge lies in a surface brick");
    let o = &bricks[b];
    let r = kl * o.owned[1] + jl;
    let row = &o.edges[o.edge_rows[r] as usize..o.edge_rows[r + 1] as usize];
    let local = (il << 2 | axis) as u16;
    let at = row
        .binary_search_by_key(&local, |e| e.0)
        .expect("the owner lists the edge");
    bases[b][r] + at as u32
}
