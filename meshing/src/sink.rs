//! Output sinks for polygonizers: where vertices and triangles go, so a polygonizer never picks an
//! output format (an [`IndexedMesh`] is the standard sink).

use crate::IndexedMesh;
use glam::DVec3;
use rayon::prelude::*;

/// Receives a polygonizer's output: vertices first, then triangles referring to the ids returned.
pub trait MeshSink {
    /// Hint of how much is coming.
    fn reserve(&mut self, _vertices: usize, _triangles: usize) {}
    /// Adds a vertex; returns its id for use in triangles.
    fn add_vertex(&mut self, p: DVec3) -> u32;
    /// Adds a triangle, counter-clockwise seen from outside.
    fn add_triangle(&mut self, t: [u32; 3]);
    /// Adds triangles in order (as [`MeshSink::add_triangle`] on each).
    fn add_triangles(&mut self, ts: &[[u32; 3]]) {
        for &t in ts {
            self.add_triangle(t);
        }
    }
    /// Adds vertices in blocks, in block order (as [`MeshSink::add_vertex`] on each): block `i`
    /// holds `lens[i]` vertices, which `fill(i, out)` writes into a slice of that length. Returns
    /// their ids. The default fills one block at a time; an [`IndexedMesh`] fills them in
    /// parallel.
    fn add_vertex_blocks(
        &mut self,
        lens: &[usize],
        fill: &(dyn Fn(usize, &mut [DVec3]) + Sync),
    ) -> VertexIds {
        let mut ids = Vec::new();
        let mut block = Vec::new();
        for (i, &n) in lens.iter().enumerate() {
            block.clear();
            block.resize(n, DVec3::ZERO);
            fill(i, &mut block);
            ids.extend(block.iter().map(|&p| self.add_vertex(p)));
        }
        VertexIds::from_list(ids)
    }
    /// Adds triangles in blocks, in block order (as [`MeshSink::add_triangles`] on each): block
    /// `i` holds `lens[i]` triangles, which `fill(i, out)` writes. The default fills one block at a
    /// time; an [`IndexedMesh`] fills them in parallel.
    fn add_triangle_blocks(
        &mut self,
        lens: &[usize],
        fill: &(dyn Fn(usize, &mut [[u32; 3]]) + Sync),
    ) {
        let mut block = Vec::new();
        for (i, &n) in lens.iter().enumerate() {
            block.clear();
            block.resize(n, [0; 3]);
            fill(i, &mut block);
            self.add_triangles(&block);
        }
    }
}

/// The ids a sink gave a run of vertices.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum VertexIds {
    /// `first`, `first + 1`, … (an [`IndexedMesh`] numbers this way).
    From(u32),
    /// One id per vertex, in order.
    Listed(Vec<u32>),
}

impl VertexIds {
    /// `From(first)` when the ids count up from `first` (or there are none), else `Listed`.
    pub fn from_list(ids: Vec<u32>) -> Self {
        match ids.first() {
            None => Self::Listed(ids),
            Some(&first) => {
                let counting = ids.iter().enumerate().all(|(i, &v)| {
                    u32::try_from(i).ok().and_then(|i| first.checked_add(i)) == Some(v)
                });
                if counting {
                    Self::From(first)
                } else {
                    Self::Listed(ids)
                }
            }
        }
    }

    /// The id of the `i`-th vertex of the run.
    #[inline]
    pub fn get(&self, i: u32) -> u32 {
        match self {
            Self::From(first) => first + i,
            Self::Listed(ids) => ids[i as usize],
        }
    }

    /// True when the `i`-th vertex has id `start + i` for every vertex of the run.
    pub fn counts_from(&self, start: u32) -> bool {
        match self {
            Self::From(first) => *first == start,
            Self::Listed(ids) => ids.is_empty(),
        }
    }
}

/// Appends `lens.iter().sum()` elements to `out`, block `i` written by `fill(i, …)`, the blocks in
/// parallel (rayon); the new elements start as `zero` (written in parallel too).
pub(crate) fn extend_in_blocks<T: Copy + Send + Sync>(
    out: &mut Vec<T>,
    zero: T,
    lens: &[usize],
    fill: &(dyn Fn(usize, &mut [T]) + Sync),
) {
    let start = out.len();
    out.par_extend(rayon::iter::repeat_n(zero, lens.iter().sum()));
    let mut rest = &mut out[start..];
    let mut blocks = Vec::with_capacity(lens.len());
    for &n in lens {
        let (block, tail) = rest.split_at_mut(n);
        blocks.push(block);
        rest = tail;
    }
    blocks
        .into_par_iter()
        .enumerate()
        .for_each(|(i, block)| fill(i, block));
}

impl MeshSink for IndexedMesh {
    fn reserve(&mut self, vertices: usize, triangles: usize) {
        self.positions.reserve(vertices);
        self.triangles.reserve(triangles);
    }

    fn add_vertex(&mut self, p: DVec3) -> u32 {
        self.positions.push(p);
        (self.positions.len() - 1) as u32
    }

    fn add_triangle(&mut self, t: [u32; 3]) {
        self.triangles.push(t);
    }

    fn add_triangles(&mut self, ts: &[[u32; 3]]) {
        self.triangles.extend_from_slice(ts);
    }

    fn add_vertex_blocks(
        &mut self,
        lens: &[usize],
        fill: &(dyn Fn(usize, &mut [DVec3]) + Sync),
    ) -> VertexIds {
        let first = self.positions.len() as u32;
        extend_in_blocks(&mut self.positions, DVec3::ZERO, lens, fill);
        VertexIds::From(first)
    }

    fn add_triangle_blocks(
        &mut self,
        lens: &[usize],
        fill: &(dyn Fn(usize, &mut [[u32; 3]]) + Sync),
    ) {
        extend_in_blocks(&mut self.triangles, [0; 3], lens, fill);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_counting_up_are_kept_as_a_start() {
        assert_eq!(VertexIds::from_list(vec![7, 8, 9]), VertexIds::From(7));
        assert_eq!(
            VertexIds::from_list(vec![9, 8]),
            VertexIds::Listed(vec![9, 8])
        );
        assert_eq!(
            VertexIds::from_list(vec![u32::MAX, 0]),
            VertexIds::Listed(vec![u32::MAX, 0])
        );
        let empty = VertexIds::from_list(Vec::new());
        assert!(empty.counts_from(5));
        assert!(VertexIds::From(5).counts_from(5) && !VertexIds::From(4).counts_from(5));
        assert_eq!(VertexIds::Listed(vec![4, 2]).get(1), 2);
    }

    #[test]
    fn blocks_land_in_order_in_memory_and_through_the_default() {
        let lens = [3, 0, 2, 1];
        let fill = |i: usize, out: &mut [DVec3]| {
            for (k, p) in out.iter_mut().enumerate() {
                *p = DVec3::new(i as f64, k as f64, 0.0);
            }
        };
        let mut mesh = IndexedMesh::default();
        mesh.add_vertex(DVec3::ONE);
        assert_eq!(mesh.add_vertex_blocks(&lens, &fill), VertexIds::From(1));
        /// A sink with only the required methods.
        #[derive(Default)]
        struct Plain(IndexedMesh);
        impl MeshSink for Plain {
            fn add_vertex(&mut self, p: DVec3) -> u32 {
                self.0.add_vertex(p)
            }
            fn add_triangle(&mut self, t: [u32; 3]) {
                self.0.add_triangle(t);
            }
        }
        let mut plain = Plain::default();
        plain.add_vertex(DVec3::ONE);
        assert_eq!(plain.add_vertex_blocks(&lens, &fill), VertexIds::From(1));
        assert_eq!(plain.0.positions, mesh.positions);
        assert_eq!(mesh.positions[4], DVec3::new(2.0, 0.0, 0.0));
        let tris = |i: usize, out: &mut [[u32; 3]]| out.fill([i as u32; 3]);
        mesh.add_triangle_blocks(&lens, &tris);
        plain.add_triangle_blocks(&lens, &tris);
        assert_eq!(plain.0.triangles, mesh.triangles);
        assert_eq!(mesh.triangles.len(), 6);
        assert_eq!(mesh.triangles[3], [2; 3]);
    }
}
