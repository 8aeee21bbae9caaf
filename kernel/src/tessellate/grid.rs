//! Grid tessellations of a parameter rectangle (lecture notes 001, "discrétisation régulière"):
//! the open `n_u × n_v` grid (`n_u n_v` vertices, `2(n_u − 1)(n_v − 1)` triangles), and the closed
//! variants the surfaces here need: a periodic direction with its seam welded, and poles welded
//! into single vertices.

use super::error::{TessellationError, count};
use crate::IndexedMesh;
use glam::DVec3;

/// The open regular grid of lecture notes 001: vertex `i n_v + j` at `f(i/(n_u − 1), j/(n_v − 1))`,
/// triangles `(a, b, c)` and `(a, c, d)` per cell with `a = (i, j)`, `b = (i + 1, j)`,
/// `c = (i + 1, j + 1)`, `d = (i, j + 1)`, wound along `∂f/∂u × ∂f/∂v`.
pub fn regular_grid(
    nu: usize,
    nv: usize,
    f: impl Fn(f64, f64) -> DVec3,
) -> Result<IndexedMesh, TessellationError> {
    count("n_u", nu, 2)?;
    count("n_v", nv, 2)?;
    let mut positions = Vec::with_capacity(nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            positions.push(f(i as f64 / (nu - 1) as f64, j as f64 / (nv - 1) as f64));
        }
    }
    let mut triangles = Vec::with_capacity(2 * (nu - 1) * (nv - 1));
    let id = |i: usize, j: usize| (i * nv + j) as u32;
    for i in 0..nu - 1 {
        for j in 0..nv - 1 {
            quad(
                &mut triangles,
                id(i, j),
                id(i + 1, j),
                id(i + 1, j + 1),
                id(i, j + 1),
            );
        }
    }
    Ok(IndexedMesh::new(positions, triangles))
}

/// The two triangles `(a, b, c)`, `(a, c, d)` of a cell.
#[inline]
pub(crate) fn quad(out: &mut Vec<[u32; 3]>, a: u32, b: u32, c: u32, d: u32) {
    out.push([a, b, c]);
    out.push([a, c, d]);
}

/// A closed surface of genus 0 from `rings` circles of `segments` points each, ordered from the
/// south pole to the north pole, capped by the two pole vertices: `2 + rings·segments` vertices,
/// `2·segments·rings` triangles. `ring(k, i)` is point `i` of ring `k`; the winding is outward
/// when the segments turn counter-clockwise seen from the north pole.
pub(crate) fn closed_rings(
    rings: usize,
    segments: usize,
    south: DVec3,
    north: DVec3,
    ring: impl Fn(usize, usize) -> DVec3,
) -> IndexedMesh {
    let mut positions = Vec::with_capacity(2 + rings * segments);
    positions.push(south);
    for k in 0..rings {
        for i in 0..segments {
            positions.push(ring(k, i));
        }
    }
    positions.push(north);
    let north_id = (positions.len() - 1) as u32;
    let id = |k: usize, i: usize| (1 + k * segments + i % segments) as u32;
    let mut triangles = Vec::with_capacity(2 * segments * rings);
    for i in 0..segments {
        triangles.push([0, id(0, i + 1), id(0, i)]);
    }
    for k in 0..rings - 1 {
        for i in 0..segments {
            quad(
                &mut triangles,
                id(k, i),
                id(k, i + 1),
                id(k + 1, i + 1),
                id(k + 1, i),
            );
        }
    }
    for i in 0..segments {
        triangles.push([id(rings - 1, i), id(rings - 1, i + 1), north_id]);
    }
    IndexedMesh::new(positions, triangles)
}

/// A closed surface of genus 1 from a doubly periodic grid of `nu × nv` distinct points (both
/// seams welded): `nu·nv` vertices, `2·nu·nv` triangles, wound along `∂f/∂u × ∂f/∂v`.
pub(crate) fn closed_torus_grid(
    nu: usize,
    nv: usize,
    point: impl Fn(usize, usize) -> DVec3,
) -> IndexedMesh {
    let mut positions = Vec::with_capacity(nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            positions.push(point(i, j));
        }
    }
    let id = |i: usize, j: usize| ((i % nu) * nv + j % nv) as u32;
    let mut triangles = Vec::with_capacity(2 * nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            quad(
                &mut triangles,
                id(i, j),
                id(i + 1, j),
                id(i + 1, j + 1),
                id(i, j + 1),
            );
        }
    }
    IndexedMesh::new(positions, triangles)
}
