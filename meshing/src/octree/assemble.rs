//! Merging brick outputs into one mesh numbered exactly as the dense path numbers it, with linear
//! walks instead of sorts: vertices by grid row `(k, j)` then `(i, axis)`, then the centre
//! vertices of fanned loops by cell row, triangles by cell row then `i` and case order. Each grid row is covered by the bricks of one brick row, visited in
//! `x` order, so concatenating their row segments gives the dense order.
//!
//! A brick's triangle may use an edge owned by a neighbour only if that neighbour saw the same
//! sign change: true whenever the field's intervals bound its samples (culled boxes have no sign
//! change, pruned programs give the same values). A field that breaks this (a bug of a primitive
//! at extreme inputs) must not crash the mesher: such an edge gets one shared vertex at its
//! midpoint, numbered after all others, and the mesh reports the resulting boundary.

use super::brick::{
    BrickEdges, BrickTriangles, CENTRE_IDS, LOCAL_EDGE_IDS, local_edge, local_parts,
};
use crate::grid::GridSpec;
use crate::pieces::split_at;
use crate::sink::MeshSink;
use rayon::prelude::*;
use std::borrow::Cow;
use std::collections::HashMap;
use std::ops::Range;

/// Finds a brick by its coordinates: a dense table when small enough, else a hash map.
enum BrickIndex {
    Dense { dims: [usize; 3], slots: Vec<u32> },
    Sparse(HashMap<[usize; 3], u32>),
}

impl BrickIndex {
    fn new(bricks: &[BrickEdges], dims: [usize; 3]) -> Self {
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

/// Emits the vertices and triangles of the bricks (sorted by z, y, x brick coordinates) into
/// `sink` in the dense path's order. The brick lists are views into the stores of their groups
/// of bricks ([`super::brick::BrickStore`]), which the caller frees after assembly. Returns the number
/// of orphan edges (see the module docs; 0 for every field whose intervals bound its samples).
pub(crate) fn assemble(
    bricks: Vec<BrickEdges>,
    triangles: Vec<BrickTriangles>,
    spec: &GridSpec,
    brick: usize,
    sink: &mut impl MeshSink,
) -> usize {
    let cells = spec.cells;
    let dims = cells.map(|c| c.div_ceil(brick).max(1));
    let index = BrickIndex::new(&bricks, dims);
    let rows = BrickRows::new(&bricks, dims);
    let extents: Vec<[usize; 3]> = bricks.iter().map(|o| o.extent).collect();
    // The dense order runs through the brick layers (same `z` brick coordinate) one after the
    // other, and each layer's bricks are consecutive in `bricks`: every layer is numbered, filled
    // and emitted on its own, in parallel, from its own start.
    let layers = Layers::new(&bricks, dims, brick, cells);
    // Vertex numbering: the base index of every owned edge row of every brick, counted within
    // its layer, then moved by the vertices of the layers before it.
    let mut bases: Vec<Vec<u32>> = bricks.iter().map(|o| vec![0; o.edge_rows.len()]).collect();
    let edge_rows: Vec<(Vec<(u32, u32)>, usize)> = layers
        .split(&mut bases)
        .into_par_iter()
        .enumerate()
        .map(|(bk, layer_bases)| {
            let first = layers.bricks[bk].start;
            let mut order = Vec::new(); // (brick, row) in the dense order
            let mut count = 0u32;
            for k in layers.sample_rows(bk) {
                let kl = k - bk * brick;
                for j in 0..=cells[1] {
                    let (bj, jl) = owner(j, brick, dims[1]);
                    for b in rows.get(bk, bj) {
                        let o = &bricks[b];
                        if kl >= o.owned[2] || jl >= o.owned[1] {
                            continue;
                        }
                        let r = kl * o.owned[1] + jl;
                        layer_bases[b - first][r] = count;
                        count += o.edge_rows[r + 1] - o.edge_rows[r];
                        order.push((b as u32, r as u32));
                    }
                }
            }
            (order, count as usize)
        })
        .collect();
    let edge_counts: Vec<usize> = edge_rows.iter().map(|e| e.1).collect();
    let edge_starts = starts(&edge_counts, 0);
    layers.shift(&mut bases, &edge_starts);
    let edge_vertices = edge_counts.iter().sum::<usize>() as u32;
    // Centre vertices follow, by cell row.
    let mut centre_bases: Vec<Vec<u32>> = triangles
        .iter()
        .map(|t| vec![0; t.centre_rows.len()])
        .collect();
    let centre_counts: Vec<usize> = layers
        .split(&mut centre_bases)
        .into_par_iter()
        .enumerate()
        .map(|(bk, layer_bases)| {
            let first = layers.bricks[bk].start;
            let mut count = 0u32;
            layers.cell_rows(bk, &rows, &extents, |b, r| {
                let t = &triangles[b];
                if !t.centre_rows.is_empty() {
                    layer_bases[b - first][r] = count;
                    count += t.centre_rows[r + 1] - t.centre_rows[r];
                }
            });
            count as usize
        })
        .collect();
    let centre_starts = starts(&centre_counts, edge_vertices);
    layers.shift(&mut centre_bases, &centre_starts);
    let mut count = edge_vertices + centre_counts.iter().sum::<usize>() as u32;
    // Triangle corners to vertex numbers, brick by brick in parallel, consuming the local lists,
    // into one array where each brick's triangles are consecutive (one allocation: a list per
    // brick grew the threads' heaps page by page, a system call each time).
    // A per-thread table maps the brick's own edge ids to numbers; neighbours are searched.
    // Corners on an edge no neighbour lists (see the module docs) are `ORPHAN | i`, the `i`-th
    // of the brick's orphan edge keys.
    let firsts: Vec<usize> = triangles
        .iter()
        .scan(0, |next, t| {
            let at = *next;
            *next += t.triangles.len();
            Some(at)
        })
        .collect();
    let total = triangles.iter().map(|t| t.triangles.len()).sum();
    let mut resolved_triangles = vec![[0u32; 3]; total];
    type Resolved<'a> = (
        Cow<'a, [u32]>,
        Cow<'a, [glam::Vec3]>,
        Cow<'a, [u32]>,
        Vec<u64>,
    );
    let resolved: Vec<Resolved> = triangles
        .into_par_iter()
        .zip(split_at(&mut resolved_triangles, &firsts))
        .enumerate()
        .map_init(
            || Numbers {
                number: vec![UNKNOWN; LOCAL_EDGE_IDS],
                written: Vec::new(),
            },
            |own, (b, (t, tris))| {
                own.clear();
                let o = &bricks[b];
                own.fill(o, &bases[b], [0; 3], o.owned);
                // The neighbours' edges on the far faces (local coordinate `brick`), copied from
                // their rows once instead of searched per triangle corner.
                for code in 1..8usize {
                    let bit = [0, 1, 2].map(|a| (code >> a) & 1);
                    let c = [0, 1, 2].map(|a| o.coord[a] + bit[a]);
                    if (0..3).any(|a| c[a] >= dims[a]) {
                        continue; // beyond the grid
                    }
                    if let Some(n) = index.get(c) {
                        let span = [0, 1, 2].map(|a| if bit[a] == 1 { 1 } else { o.owned[a] });
                        own.fill(&bricks[n], &bases[n], bit.map(|x| x * brick), span);
                    }
                }
                let mut orphans = Vec::new();
                for (r, w) in t.triangle_rows.windows(2).enumerate() {
                    let span = w[0] as usize..w[1] as usize;
                    for (slot, tri) in tris[span.clone()].iter_mut().zip(&t.triangles[span]) {
                        *slot = tri.map(|id| {
                            if id >= CENTRE_IDS {
                                let first = centre_bases[b][r] - t.centre_rows[r];
                                return first + u32::from(id - CENTRE_IDS);
                            }
                            let v = own.number[id as usize];
                            if v != UNKNOWN {
                                return v;
                            }
                            neighbour_vertex(b, id, &bricks, &bases, &index, brick, dims)
                                .unwrap_or_else(|key| {
                                    orphans.push(key);
                                    ORPHAN | (orphans.len() - 1) as u32
                                })
                        });
                    }
                }
                (t.triangle_rows, t.centres, t.centre_rows, orphans)
            },
        )
        .collect();
    let mut orphan_keys: Vec<u64> = resolved.iter().flat_map(|r| r.3.iter().copied()).collect();
    orphan_keys.sort_unstable();
    orphan_keys.dedup();
    count += orphan_keys.len() as u32;
    sink.reserve(count as usize, total);
    // The vertices, layer by layer in parallel: edge vertices, centres, then orphans.
    let edge_ids = sink.add_vertex_blocks(&edge_counts, &|bk, out| {
        let mut at = 0;
        for &(b, r) in &edge_rows[bk].0 {
            let o = &bricks[b as usize];
            let r = r as usize;
            let row = &o.edges[o.edge_rows[r] as usize..o.edge_rows[r + 1] as usize];
            for (slot, e) in out[at..at + row.len()].iter_mut().zip(row) {
                *slot = e.1.as_dvec3();
            }
            at += row.len();
        }
    });
    // Thousands of small lists: freed in parallel.
    drop(index);
    rayon::join(
        || bricks.into_par_iter().for_each(drop),
        || {
            bases.into_par_iter().for_each(drop);
            edge_rows.into_par_iter().for_each(drop);
        },
    );
    let centre_ids = sink.add_vertex_blocks(&centre_counts, &|bk, out| {
        let mut at = 0;
        layers.cell_rows(bk, &rows, &extents, |b, r| {
            let (_, centres, centre_rows, _) = &resolved[b];
            if !centre_rows.is_empty() {
                let row = &centres[centre_rows[r] as usize..centre_rows[r + 1] as usize];
                for (slot, p) in out[at..at + row.len()].iter_mut().zip(row) {
                    *slot = p.as_dvec3();
                }
                at += row.len();
            }
        });
    });
    let orphan_ids: Vec<u32> = orphan_keys
        .iter()
        .map(|&key| {
            let (g, axis) = unpack_edge(key);
            let mut p = spec.point(g[0], g[1], g[2]);
            p[axis] += 0.5 * spec.cell;
            sink.add_vertex(p)
        })
        .collect();
    // Vertex `v` in this function's numbering to the sink's id.
    let id = |v: u32| {
        if v < edge_vertices {
            edge_ids.get(v)
        } else {
            centre_ids.get(v - edge_vertices)
        }
    };
    let identity = edge_ids.counts_from(0) && centre_ids.counts_from(edge_vertices);
    // The triangles, layer by layer in parallel; a brick's rows are copied as they are when the
    // sink numbers as this function does and the brick has no orphan corners.
    let triangle_counts: Vec<usize> = (0..layers.len())
        .into_par_iter()
        .map(|bk| {
            let mut n = 0;
            layers.cell_rows(bk, &rows, &extents, |b, r| {
                let tri_rows = &resolved[b].0;
                n += (tri_rows[r + 1] - tri_rows[r]) as usize;
            });
            n
        })
        .collect();
    sink.add_triangle_blocks(&triangle_counts, &|bk, out| {
        let mut at = 0;
        layers.cell_rows(bk, &rows, &extents, |b, r| {
            let (tri_rows, _, _, orphans) = &resolved[b];
            let tris = &resolved_triangles[firsts[b]..];
            let row = &tris[tri_rows[r] as usize..tri_rows[r + 1] as usize];
            let out = &mut out[at..at + row.len()];
            at += row.len();
            if identity && orphans.is_empty() {
                out.copy_from_slice(row);
                return;
            }
            for (slot, t) in out.iter_mut().zip(row) {
                *slot = t.map(|v| {
                    if v & ORPHAN == 0 {
                        return id(v);
                    }
                    let key = orphans[(v & !ORPHAN) as usize];
                    orphan_ids[orphan_keys.binary_search(&key).unwrap_or_default()]
                });
            }
        });
    });
    orphan_keys.len()
}

/// Exclusive prefix sums of `counts` from `from`.
fn starts(counts: &[usize], from: u32) -> Vec<u32> {
    counts
        .iter()
        .scan(from, |next, &n| {
            let at = *next;
            *next += n as u32;
            Some(at)
        })
        .collect()
}

/// The brick layers (bricks with the same `z` brick coordinate): their ranges in the sorted
/// brick list and the grid rows they cover.
struct Layers {
    /// The bricks of each layer.
    bricks: Vec<Range<usize>>,
    brick: usize,
    cells: [usize; 3],
}

impl Layers {
    fn new(bricks: &[BrickEdges], dims: [usize; 3], brick: usize, cells: [usize; 3]) -> Self {
        let ranges = (0..dims[2])
            .map(|bk| {
                bricks.partition_point(|o| o.coord[2] < bk)
                    ..bricks.partition_point(|o| o.coord[2] <= bk)
            })
            .collect();
        Layers {
            bricks: ranges,
            brick,
            cells,
        }
    }

    fn len(&self) -> usize {
        self.bricks.len()
    }

    /// `per_brick` cut into one slice per layer.
    fn split<'a, T>(&self, per_brick: &'a mut [T]) -> Vec<&'a mut [T]> {
        let mut rest = per_brick;
        let mut at = 0;
        self.bricks
            .iter()
            .map(|range| {
                let (layer, tail) = std::mem::take(&mut rest).split_at_mut(range.end - at);
                at = range.end;
                rest = tail;
                layer
            })
            .collect()
    }

    /// Adds each layer's start to the row bases of its bricks (counted from 0 within the layer),
    /// in parallel.
    fn shift(&self, bases: &mut [Vec<u32>], starts: &[u32]) {
        self.split(bases)
            .into_par_iter()
            .zip(starts)
            .for_each(|(layer_bases, &first)| {
                for v in layer_bases.iter_mut().flatten() {
                    *v += first;
                }
            });
    }

    /// The sample rows `k` layer `bk` owns (the last layer owns the far face).
    fn sample_rows(&self, bk: usize) -> Range<usize> {
        let end = if bk + 1 == self.len() {
            self.cells[2] + 1
        } else {
            (bk + 1) * self.brick
        };
        bk * self.brick..end
    }

    /// Calls `each(brick, local cell row kl · extent_y + jl)` for every cell row of layer `bk`
    /// in the dense path's order (`k`, then `j`, then the bricks of the brick row in `x` order).
    fn cell_rows(
        &self,
        bk: usize,
        rows: &BrickRows,
        extents: &[[usize; 3]],
        mut each: impl FnMut(usize, usize),
    ) {
        let (brick, cells) = (self.brick, self.cells);
        for k in bk * brick..((bk + 1) * brick).min(cells[2]) {
            let kl = k - bk * brick;
            for j in 0..cells[1] {
                let jl = j % brick;
                for b in rows.get(bk, j / brick) {
                    each(b, kl * extents[b][1] + jl);
                }
            }
        }
    }
}

/// A local edge id with no vertex number known in [`Numbers`].
const UNKNOWN: u32 = u32::MAX;

/// Per-thread table from a brick's local edge ids to vertex numbers: its own edges and its
/// neighbours' edges on its far faces; every other entry [`UNKNOWN`].
struct Numbers {
    number: Vec<u32>,
    /// The ids set for the current brick, reset by [`Numbers::clear`].
    written: Vec<u16>,
}

impl Numbers {
    /// Resets the entries of the last brick.
    fn clear(&mut self) {
        for &id in &self.written {
            self.number[id as usize] = UNKNOWN;
        }
        self.written.clear();
    }

    /// Numbers the edges of brick `o` (row bases `bases`) whose lower sample lies in its local
    /// box from `[0; 3]` to `span` (exclusive) and whose `x` is below `span[0]`, under the ids of
    /// the brick that sees `o`'s local origin at `offset`.
    fn fill(&mut self, o: &BrickEdges, bases: &[u32], offset: [usize; 3], span: [usize; 3]) {
        for kl in 0..span[2].min(o.owned[2]) {
            for jl in 0..span[1].min(o.owned[1]) {
                let r = kl * o.owned[1] + jl;
                let start = o.edge_rows[r] as usize;
                let row = &o.edges[start..o.edge_rows[r + 1] as usize];
                for (p, e) in row.iter().enumerate() {
                    let il = (e.0 >> 2) as usize;
                    if il >= span[0] {
                        break; // rows are sorted by `x`
                    }
                    let id = local_edge(
                        il + offset[0],
                        jl + offset[1],
                        kl + offset[2],
                        (e.0 & 3) as usize,
                    );
                    self.number[id as usize] = bases[r] + p as u32;
                    self.written.push(id);
                }
            }
        }
    }
}

/// Marks a triangle corner whose edge no brick lists (vertex numbers stay far below 2³¹).
const ORPHAN: u32 = 1 << 31;

/// Packs the grid edge along `axis` from sample `g` (each below 2²⁰) into one sortable key.
fn pack_edge(g: [usize; 3], axis: usize) -> u64 {
    ((g[2] as u64) << 42) | ((g[1] as u64) << 22) | ((g[0] as u64) << 2) | axis as u64
}

/// Inverse of [`pack_edge`].
fn unpack_edge(key: u64) -> ([usize; 3], usize) {
    let part = |shift: u32| ((key >> shift) & ((1 << 20) - 1)) as usize;
    ([part(2), part(22), part(42)], (key & 3) as usize)
}

/// The bricks of each brick row `(z, y)`, in `x` order (the input's order), as one flat list
/// with a start per row: looked up once per grid row by the serial numbering passes, where a
/// hash map's hashing cost more than the lookups' work.
struct BrickRows {
    dims_y: usize,
    starts: Vec<u32>,
    bricks: Vec<u32>,
}

impl BrickRows {
    fn new(bricks: &[BrickEdges], dims: [usize; 3]) -> Self {
        let row = |o: &BrickEdges| o.coord[2] * dims[1] + o.coord[1];
        let mut starts = vec![0u32; dims[1] * dims[2] + 1];
        for o in bricks {
            starts[row(o) + 1] += 1;
        }
        for r in 0..dims[1] * dims[2] {
            starts[r + 1] += starts[r];
        }
        let mut next = starts.clone();
        let mut list = vec![0u32; bricks.len()];
        for (b, o) in bricks.iter().enumerate() {
            let r = row(o);
            list[next[r] as usize] = b as u32;
            next[r] += 1;
        }
        BrickRows {
            dims_y: dims[1],
            starts,
            bricks: list,
        }
    }

    /// The bricks of brick row `(bk, bj)`.
    fn get(&self, bk: usize, bj: usize) -> impl Iterator<Item = usize> + '_ {
        let r = bk * self.dims_y + bj;
        self.bricks[self.starts[r] as usize..self.starts[r + 1] as usize]
            .iter()
            .map(|&b| b as usize)
    }
}

/// The number of the vertex on brick `b`'s local edge `id` when a neighbour owns it, or the
/// edge's key ([`pack_edge`]) when no brick lists it (see the module docs).
fn neighbour_vertex(
    b: usize,
    id: u16,
    bricks: &[BrickEdges],
    bases: &[Vec<u32>],
    index: &BrickIndex,
    brick: usize,
    dims: [usize; 3],
) -> Result<u32, u64> {
    let (l, axis) = local_parts(id);
    let o = &bricks[b];
    let g = [0, 1, 2].map(|a| o.coord[a] * brick + l[a]);
    let parts = [0, 1, 2].map(|a| owner(g[a], brick, dims[a]));
    let orphan = || pack_edge(g, axis);
    let owner_brick = index.get(parts.map(|p| p.0)).ok_or_else(orphan)?;
    let [il, jl, kl] = parts.map(|p| p.1);
    let o = &bricks[owner_brick];
    let r = kl * o.owned[1] + jl;
    let row = &o.edges[o.edge_rows[r] as usize..o.edge_rows[r + 1] as usize];
    let local = (il << 2 | axis) as u16;
    let at = row
        .binary_search_by_key(&local, |e| e.0)
        .map_err(|_| orphan())?;
    Ok(bases[owner_brick][r] + at as u32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::IndexedMesh;
    use glam::{DVec3, Vec3};

    /// Two 2 × 2 × 2 bricks side by side along `x` (grid of 4 × 2 × 2 cells): brick 0 owns the
    /// sample rows below 2 along `x`, brick 1 the rest. Brick 0's one triangle uses its own edge,
    /// then two edges on its far face `x = 2`, which brick 1 owns at its local `x = 0`.
    fn bricks(neighbour_lists: bool) -> (Vec<BrickEdges<'static>>, Vec<BrickTriangles<'static>>) {
        let row_of = |owned: [usize; 3], edges: &[(u16, [usize; 2])]| {
            // rows (k, j) in order; `edges` as (local `i << 2 | axis`, (j, k)).
            let mut list = Vec::new();
            let mut rows = vec![0u32];
            for k in 0..owned[2] {
                for j in 0..owned[1] {
                    for &(e, at) in edges {
                        if at == [j, k] {
                            list.push((e, Vec3::new(f32::from(e), j as f32, k as f32)));
                        }
                    }
                    rows.push(list.len() as u32);
                }
            }
            (list, rows)
        };
        let (e0, r0) = row_of([2, 3, 3], &[(1 << 2 | 1, [0, 0])]);
        let theirs: &[(u16, [usize; 2])] = if neighbour_lists {
            &[(1, [0, 0]), (2, [1, 0])]
        } else {
            &[(1, [0, 0])]
        };
        let (e1, r1) = row_of([3, 3, 3], theirs);
        let edges = vec![
            BrickEdges {
                coord: [0, 0, 0],
                owned: [2, 3, 3],
                extent: [2, 2, 2],
                edges: e0.into(),
                edge_rows: r0.into(),
            },
            BrickEdges {
                coord: [1, 0, 0],
                owned: [3, 3, 3],
                extent: [2, 2, 2],
                edges: e1.into(),
                edge_rows: r1.into(),
            },
        ];
        let mut rows = vec![0u32; 5];
        rows[1..].fill(1);
        let tri = [
            local_edge(1, 0, 0, 1),
            local_edge(2, 0, 0, 1),
            local_edge(2, 1, 0, 2),
        ];
        let triangles = vec![
            BrickTriangles {
                triangles: vec![tri].into(),
                triangle_rows: rows.into(),
                ..Default::default()
            },
            BrickTriangles {
                triangle_rows: vec![0; 5].into(),
                ..Default::default()
            },
        ];
        (edges, triangles)
    }

    fn spec() -> GridSpec {
        GridSpec {
            origin: DVec3::ZERO,
            cell: 1.0,
            cells: [4, 2, 2],
        }
    }

    /// The assembled mesh of [`bricks`] and its orphan count.
    fn assembled(neighbour_lists: bool) -> (IndexedMesh, usize) {
        let (edges, triangles) = bricks(neighbour_lists);
        let mut mesh = IndexedMesh::default();
        let orphans = assemble(edges, triangles, &spec(), 2, &mut mesh);
        (mesh, orphans)
    }

    #[test]
    fn corners_on_a_far_face_take_the_neighbours_vertices() {
        let (mesh, orphans) = assembled(true);
        assert_eq!(orphans, 0);
        // Dense order: row (0, 0) holds brick 0's edge then brick 1's (local x 0 → vertex 1);
        // row (k 0, j 1) holds brick 1's axis-2 edge (vertex 2).
        assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
        assert_eq!(mesh.positions.len(), 3);
    }

    #[test]
    fn a_corner_no_neighbour_lists_gets_one_midpoint_vertex() {
        let (mesh, orphans) = assembled(false);
        assert_eq!(orphans, 1);
        assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
        // The orphan: the z edge from sample (2, 1, 0), at its midpoint.
        assert_eq!(mesh.positions[2], DVec3::new(2.0, 1.0, 0.5));
    }
}
