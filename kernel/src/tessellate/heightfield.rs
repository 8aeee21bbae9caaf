//! The closed surface of a height-field solid: the top `n × n` regular grid of lecture notes 001
//! over the rectangle, the base as the same grid at `z = base` (wound downwards), and one strip of
//! side quads joining their boundaries: `2n²` vertices, `4(n − 1)² + 8(n − 1)` triangles.

use super::Tessellation;
use super::chord::interpolation_error;
use super::error::{TessellationError, count};
use super::grid::quad;
use crate::IndexedMesh;
use crate::primitive::heightfield::HeightField;

/// The closed, outward-wound tessellation of a height-field solid with `n × n` samples on top.
///
/// Chord error (where the height is C¹ with a Hessian bound `M`, see
/// [`HeightField::hessian_bound`]): `M (Δx² + Δy²) / 8` on top ([`interpolation_error`]), and
/// no more on the sides (the top's boundary curves, interpolated by chords) or the flat base.
/// `None` for bilinear samples, whose slope jumps between samples.
pub fn heightfield(hf: &HeightField, n: usize) -> Result<Tessellation, TessellationError> {
    count("n", n, 2)?;
    let mut positions = Vec::with_capacity(2 * n * n);
    for i in 0..n {
        for j in 0..n {
            let (u, v) = (i as f64 / (n - 1) as f64, j as f64 / (n - 1) as f64);
            positions.push(hf.point_at(u, v));
        }
    }
    let bottom: Vec<_> = positions
        .iter()
        .map(|p| p.truncate().extend(hf.base()))
        .collect();
    positions.extend(bottom);
    let top = |i: usize, j: usize| (i * n + j) as u32;
    let base = |i: usize, j: usize| (n * n + i * n + j) as u32;
    let mut triangles = Vec::with_capacity(4 * (n - 1) * (n - 1) + 8 * (n - 1));
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            quad(
                &mut triangles,
                top(i, j),
                top(i + 1, j),
                top(i + 1, j + 1),
                top(i, j + 1),
            );
            quad(
                &mut triangles,
                base(i, j),
                base(i, j + 1),
                base(i + 1, j + 1),
                base(i + 1, j),
            );
        }
    }
    // The boundary counter-clockwise seen from above: y = min, x = max, y = max, x = min.
    let mut ring = Vec::with_capacity(4 * (n - 1));
    ring.extend((0..n - 1).map(|i| (i, 0)));
    ring.extend((0..n - 1).map(|j| (n - 1, j)));
    ring.extend((1..n).rev().map(|i| (i, n - 1)));
    ring.extend((1..n).rev().map(|j| (0, j)));
    for k in 0..ring.len() {
        let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
        let (at, bt, ab, bb) = (top(a.0, a.1), top(b.0, b.1), base(a.0, a.1), base(b.0, b.1));
        triangles.push([at, ab, bt]);
        triangles.push([bt, ab, bb]);
    }
    let size = hf.max() - hf.min();
    let step = (n - 1) as f64;
    let chord = hf
        .hessian_bound()
        .map(|m| interpolation_error(m, size.x / step, size.y / step));
    Ok(Tessellation {
        mesh: IndexedMesh::new(positions, triangles),
        chord_error: chord,
    })
}
