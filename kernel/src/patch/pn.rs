//! Curved point-normal (PN) triangles (Vlachos, Peters, Boyd, Mitchell 2001; lecture notes 001):
//! each flat triangle with vertex normals becomes a cubic triangular Bézier patch
//!
//! `b300 = p1, b030 = p2, b003 = p3, b210 = (2p1 + p2 − w12 n1)/3, …, b111 = E + (E − V)/2`,
//! `w_ij = (p_j − p_i) · n_i`,
//!
//! and [`pn_refine`] turns a whole mesh into a finer one. A patch's boundary curve over an edge
//! depends only on the edge's two vertices and their normals, so neighbouring patches meet; the
//! refined mesh computes each edge's points once and shares them, so a closed manifold input gives
//! a closed manifold output with the same orientation.

use super::error::PatchError;
use super::triangle::{TriangleBezier, grid_triangles, net_size};
use crate::IndexedMesh;
use glam::DVec3;
use std::collections::HashMap;

/// The largest number of segments per edge [`pn_refine`] accepts.
pub const MAX_SEGMENTS: usize = 256;

/// The cubic control point `b_{2·i + j}`-style edge point next to `p` on the edge towards `q`:
/// `(2p + q − ((q − p)·n) n) / 3`, the projection of the third point onto `p`'s tangent plane.
#[inline]
fn edge_control(p: DVec3, q: DVec3, n: DVec3) -> DVec3 {
    (2.0 * p + q - (q - p).dot(n) * n) / 3.0
}

/// The cubic PN patch of a triangle `p` with unit vertex normals `n`; fails on non-finite input.
pub fn pn_triangle(p: [DVec3; 3], n: [DVec3; 3]) -> Result<TriangleBezier, PatchError> {
    let [p1, p2, p3] = p;
    let [n1, n2, n3] = n;
    let b210 = edge_control(p1, p2, n1);
    let b120 = edge_control(p2, p1, n2);
    let b021 = edge_control(p2, p3, n2);
    let b012 = edge_control(p3, p2, n3);
    let b102 = edge_control(p3, p1, n3);
    let b201 = edge_control(p1, p3, n1);
    let e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    let v = (p1 + p2 + p3) / 3.0;
    let b111 = e + (e - v) / 2.0;
    TriangleBezier::from_fn(3, |i, j, k| match (i, j, k) {
        (3, 0, 0) => p1,
        (0, 3, 0) => p2,
        (0, 0, 3) => p3,
        (2, 1, 0) => b210,
        (1, 2, 0) => b120,
        (0, 2, 1) => b021,
        (0, 1, 2) => b012,
        (1, 0, 2) => b102,
        (2, 0, 1) => b201,
        _ => b111,
    })
}

/// A point of the cubic boundary curve from `p` (normal `np`) to `q` (normal `nq`) at `t`.
fn edge_point(p: DVec3, q: DVec3, np: DVec3, nq: DVec3, t: f64) -> DVec3 {
    let (b1, b2) = (edge_control(p, q, np), edge_control(q, p, nq));
    let s = 1.0 - t;
    p * (s * s * s) + b1 * (3.0 * s * s * t) + b2 * (3.0 * s * t * t) + q * (t * t * t)
}

/// Angle-weighted vertex normals of a mesh (the normalised sum of incident face normals, each
/// weighted by the triangle's angle at the vertex). Vertices on no usable triangle get zero.
pub fn vertex_normals(mesh: &IndexedMesh) -> Vec<DVec3> {
    let mut normals = vec![DVec3::ZERO; mesh.positions.len()];
    for t in &mesh.triangles {
        if t.iter().any(|&i| i as usize >= mesh.positions.len()) {
            continue;
        }
        let p = t.map(|i| mesh.positions[i as usize]);
        let Some(face) = (p[1] - p[0]).cross(p[2] - p[0]).try_normalize() else {
            continue;
        };
        for c in 0..3 {
            let (a, b) = (p[(c + 1) % 3] - p[c], p[(c + 2) % 3] - p[c]);
            normals[t[c] as usize] += face * a.angle_between(b);
        }
    }
    normals.iter().map(|n| n.normalize_or_zero()).collect()
}

/// Checks a mesh's indices and finiteness, and the normals (count, finite, nonzero); returns the
/// unit normals.
fn checked_normals(
    mesh: &IndexedMesh,
    normals: Option<&[DVec3]>,
) -> Result<Vec<DVec3>, PatchError> {
    let count = mesh.positions.len();
    for (triangle, t) in mesh.triangles.iter().enumerate() {
        if let Some(&vertex) = t.iter().find(|&&i| i as usize >= count) {
            return Err(PatchError::IndexOutOfRange {
                triangle,
                vertex,
                count,
            });
        }
    }
    if let Some(index) = mesh.positions.iter().position(|p| !p.is_finite()) {
        return Err(PatchError::NonFinite {
            what: "vertex",
            index,
        });
    }
    let normals = match normals {
        Some(n) if n.len() != count => {
            return Err(PatchError::NormalCount {
                normals: n.len(),
                vertices: count,
            });
        }
        Some(n) => n.iter().map(|v| v.normalize_or_zero()).collect(),
        None => vertex_normals(mesh),
    };
    let mut used = vec![false; count];
    mesh.triangles
        .iter()
        .flatten()
        .for_each(|&i| used[i as usize] = true);
    if let Some(i) = (0..count).find(|&i| used[i] && normals[i] == DVec3::ZERO) {
        return Err(PatchError::ZeroNormal(i));
    }
    Ok(normals)
}

/// Replaces every triangle of `mesh` by its PN patch tessellated with `segments` segments per
/// edge (`segments²` triangles each). `normals` are per-vertex (normalised here); `None` uses
/// [`vertex_normals`]. Output vertices: the input's, then `segments − 1` per edge, then
/// `(segments − 1)(segments − 2)/2` per triangle.
pub fn pn_refine(
    mesh: &IndexedMesh,
    normals: Option<&[DVec3]>,
    segments: usize,
) -> Result<IndexedMesh, PatchError> {
    if segments == 0 || segments > MAX_SEGMENTS {
        return Err(PatchError::Count {
            what: "segments",
            got: segments,
            min: 1,
            max: MAX_SEGMENTS,
        });
    }
    let n = checked_normals(mesh, normals)?;
    let s = segments;
    let mut positions = mesh.positions.clone();
    // First new vertex of each undirected edge (smaller index first), in canonical direction.
    let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
    for t in &mesh.triangles {
        for c in 0..3 {
            let (a, b) = (t[c].min(t[(c + 1) % 3]), t[c].max(t[(c + 1) % 3]));
            edges.entry((a, b)).or_insert_with(|| {
                let start = positions.len() as u32;
                let (pa, pb) = (mesh.positions[a as usize], mesh.positions[b as usize]);
                for m in 1..s {
                    let t = m as f64 / s as f64;
                    positions.push(edge_point(pa, pb, n[a as usize], n[b as usize], t));
                }
                start
            });
        }
    }
    let mut triangles = Vec::with_capacity(mesh.triangles.len() * s * s);
    let mut scratch = Vec::new();
    let mut local = vec![0u32; net_size(s)];
    for t in &mesh.triangles {
        let p = t.map(|i| mesh.positions[i as usize]);
        let patch = pn_triangle(p, t.map(|i| n[i as usize]))?;
        // Number the barycentric grid (j along p1 → p2, k along p1 → p3).
        let on_edge = |from: u32, to: u32, m: usize| -> u32 {
            let start = edges[&(from.min(to), from.max(to))];
            let m = if from < to { m } else { s - m };
            start + (m - 1) as u32
        };
        let id = |j: usize, k: usize| k * (s + 1) - k * k.saturating_sub(1) / 2 + j;
        for k in 0..=s {
            for j in 0..=s - k {
                local[id(j, k)] = match (j, k) {
                    (0, 0) => t[0],
                    (j, 0) if j == s => t[1],
                    (0, k) if k == s => t[2],
                    (j, 0) => on_edge(t[0], t[1], j),
                    (0, k) => on_edge(t[0], t[2], k),
                    (j, k) if j + k == s => on_edge(t[1], t[2], k),
                    (j, k) => {
                        let (v, w) = (j as f64 / s as f64, k as f64 / s as f64);
                        positions
                            .push(patch.point_with(DVec3::new(1.0 - v - w, v, w), &mut scratch));
                        (positions.len() - 1) as u32
                    }
                };
            }
        }
        grid_triangles(s, |j, k| local[id(j, k)], &mut triangles);
    }
    Ok(IndexedMesh::new(positions, triangles))
}
