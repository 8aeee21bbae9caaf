//! Marching cubes over a [`SampleGrid`], in parallel over z-slices, with vertices welded by
//! construction: each grid edge that changes sign gets exactly one vertex, numbered by the slice
//! that owns the edge, and every cell using that edge refers to the same number.
//!
//! Sign rule: a sample is inside when its value is `< 0` (exact zeros are settled by
//! [`super::sign`] before they get here; NaN counts as outside); an ambiguous face is resolved by
//! the asymptotic decider on its four values. Vertex
//! positions interpolate linearly along the edge, kept at least [`EDGE_MARGIN`] of the edge away
//! from either end, so no two vertices coincide and no triangle is degenerate.

use super::pinch::{Decider, FaceRule};
use super::samples::SampleGrid;
use super::sign::inside;
use super::table::{CENTRE, NO_CENTRE, case_table, edge_origin};
use crate::sink::MeshSink;
use glam::DVec3;
use rayon::prelude::*;

/// Smallest distance, as a fraction of the cell edge, between a vertex and a grid sample.
pub const EDGE_MARGIN: f64 = 1e-4;

const NONE: u32 = u32::MAX;

/// The vertex on the edge from `pa` (value `va`) to `pb` (value `vb`), or `None` when the edge
/// does not change sign. Shared by every polygonizer, so equal samples give equal vertices.
/// Positions are rounded to single precision (what mesh files store), which also lets the sparse
/// mesher keep vertices in half the memory.
#[inline]
pub fn edge_vertex(pa: DVec3, va: f32, pb: DVec3, vb: f32) -> Option<DVec3> {
    if inside(va) == inside(vb) {
        return None;
    }
    // A zero settled outside sits on the surface: the vertex goes to it (as to an exact 0).
    let on_surface = |v: f32| {
        if v == super::OUTSIDE_ZERO {
            0.0
        } else {
            v as f64
        }
    };
    let (va, vb) = (on_surface(va), on_surface(vb));
    let t = va / (va - vb);
    let t = if t.is_finite() {
        t.clamp(EDGE_MARGIN, 1.0 - EDGE_MARGIN)
    } else {
        0.5
    };
    Some((pa + (pb - pa) * t).as_vec3().as_dvec3())
}

/// Crossing vertices owned by one sample slice `k`: edges along x and y within the slice, and
/// along z from slice `k` to `k + 1`.
struct SliceVertices {
    /// Local vertex number of each edge (`NONE` when it does not cross), per axis, x fastest.
    ids: [Vec<u32>; 3],
    positions: Vec<DVec3>,
}

fn crossing(g: &SampleGrid, a: (usize, usize, usize), b: (usize, usize, usize)) -> Option<DVec3> {
    let (va, vb) = (g.at(a.0, a.1, a.2), g.at(b.0, b.1, b.2));
    edge_vertex(
        g.spec.point(a.0, a.1, a.2),
        va,
        g.spec.point(b.0, b.1, b.2),
        vb,
    )
}

fn slice_vertices(g: &SampleGrid, k: usize) -> SliceVertices {
    let [sx, sy, sz] = g.spec.samples();
    let mut ids = [
        vec![NONE; sx * sy],
        vec![NONE; sx * sy],
        vec![NONE; sx * sy],
    ];
    let mut positions = Vec::new();
    for j in 0..sy {
        for i in 0..sx {
            let neighbours = [
                (i + 1 < sx, (i + 1, j, k)),
                (j + 1 < sy, (i, j + 1, k)),
                (k + 1 < sz, (i, j, k + 1)),
            ];
            for (axis, &(exists, b)) in neighbours.iter().enumerate() {
                if let Some(p) = exists.then(|| crossing(g, (i, j, k), b)).flatten() {
                    ids[axis][i + sx * j] = positions.len() as u32;
                    positions.push(p);
                }
            }
        }
    }
    SliceVertices { ids, positions }
}

/// The centre vertex of a loop fanned from the centroid of its crossings `positions` (in loop
/// order), rounded to single precision like every vertex. Shared by the dense and sparse paths.
pub fn loop_centre(positions: impl ExactSizeIterator<Item = DVec3>) -> DVec3 {
    let n = positions.len() as f64;
    let sum = positions.fold(DVec3::ZERO, |a, p| a + p);
    (sum / n).as_vec3().as_dvec3()
}

/// Marks a triangle corner as the layer's `n`-th centre vertex.
const CENTRE_FLAG: u32 = 1 << 31;

/// Triangles of cell layer `k` (between slices `k` and `k + 1`) in global vertex numbers, centre
/// vertices as `CENTRE_FLAG | n` with their positions in the second list.
fn layer_triangles<R: FaceRule>(
    g: &SampleGrid,
    rule: &R,
    k: usize,
    slices: &[SliceVertices],
    offsets: &[u32],
) -> (Vec<[u32; 3]>, Vec<DVec3>) {
    let table = case_table();
    let [cx, cy, _] = g.spec.cells;
    let sx = cx + 1;
    let mut out = Vec::new();
    let mut centres = Vec::new();
    let mut scratch = R::Scratch::default();
    for j in 0..cy {
        for i in 0..cx {
            let mut mask = 0usize;
            for c in 0..8 {
                let (di, dj, dk) = (c & 1, c >> 1 & 1, c >> 2 & 1);
                if inside(g.at(i + di, j + dj, k + dk)) {
                    mask |= 1 << c;
                }
            }
            let config = table.cell_config_with(
                mask,
                |c| {
                    let c = usize::from(c);
                    g.at(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))
                },
                |bit, corners, values| rule.joined([i, j, k], bit, corners, values, &mut scratch),
            );
            let vertex = |e: u8| {
                let (axis, o) = edge_origin(e);
                let slice = k + o[2];
                let local = slices[slice].ids[axis][(i + o[0]) + sx * (j + o[1])];
                debug_assert_ne!(local, NONE, "case table uses only crossing edges");
                (slice, local)
            };
            let centre = table.centre_loop[config];
            if centre != NO_CENTRE {
                let l = &table.loops(config)[centre as usize];
                centres.push(loop_centre(l.iter().map(|&e| {
                    let (slice, local) = vertex(e);
                    slices[slice].positions[local as usize]
                })));
            }
            for tri in table.triangles(config) {
                out.push(tri.map(|e| {
                    if e == CENTRE {
                        return CENTRE_FLAG | (centres.len() - 1) as u32;
                    }
                    let (slice, local) = vertex(e);
                    offsets[slice] + local
                }));
            }
        }
    }
    (out, centres)
}

/// Polygonizes the zero level set of the samples into `sink`. Deterministic: the output does not
/// depend on the number of threads.
pub fn polygonize_into(g: &SampleGrid, sink: &mut impl MeshSink) {
    polygonize_with(g, &Decider, sink);
}

/// [`polygonize_into`] with the faces the decider joins confirmed by `rule` ([`super::pinch`]).
pub fn polygonize_with(g: &SampleGrid, rule: &impl FaceRule, sink: &mut impl MeshSink) {
    let [_, _, sz] = g.spec.samples();
    let slices: Vec<SliceVertices> = (0..sz)
        .into_par_iter()
        .map(|k| slice_vertices(g, k))
        .collect();
    let mut offsets = Vec::with_capacity(sz);
    let mut total = 0u32;
    for s in &slices {
        offsets.push(total);
        total += s.positions.len() as u32;
    }
    let layers: Vec<(Vec<[u32; 3]>, Vec<DVec3>)> = (0..g.spec.cells[2])
        .into_par_iter()
        .map(|k| layer_triangles(g, rule, k, &slices, &offsets))
        .collect();
    let triangles: usize = layers.iter().map(|l| l.0.len()).sum();
    let centres: usize = layers.iter().map(|l| l.1.len()).sum();
    sink.reserve(total as usize + centres, triangles);
    let mut ids = Vec::with_capacity(total as usize + centres);
    for s in &slices {
        ids.extend(s.positions.iter().map(|&p| sink.add_vertex(p)));
    }
    // Centre vertices after every edge vertex, in cell order.
    let mut centre_base = Vec::with_capacity(layers.len());
    for (_, c) in &layers {
        centre_base.push(ids.len() as u32);
        ids.extend(c.iter().map(|&p| sink.add_vertex(p)));
    }
    for ((tris, _), &base) in layers.iter().zip(&centre_base) {
        for t in tris {
            sink.add_triangle(t.map(|v| {
                if v & CENTRE_FLAG != 0 {
                    ids[(base + (v & !CENTRE_FLAG)) as usize]
                } else {
                    ids[v as usize]
                }
            }));
        }
    }
}
