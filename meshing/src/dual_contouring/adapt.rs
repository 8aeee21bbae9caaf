//! Adaptive simplification (`--tolerance`): octree nodes over the cell grid collapse bottom-up into
//! one vertex when
//! - every child collapsed (a cell counts as collapsed when it has exactly one patch and no
//!   ambiguous face) or holds no surface;
//! - the node passes the topology-safety tests of Ju et al. 2002 on the 27 samples of its children:
//!   the sign at the middle of each node edge agrees with one of the edge's ends, the sign at the
//!   middle of each node face with one of the face's corners, and the node's own corner signs
//!   form a single patch with no ambiguous face (a disk, as in the cell case);
//! - the merged QEF's minimiser in the node has an error of at most `tolerance²` (so every plane
//!   it was built from passes within `tolerance` of the vertex).
//!
//! Every fine vertex under a collapsed node maps to the node's vertex; polygons are then mapped
//! and merged ([`super::emit`]). The result is checked: any vertex whose neighbourhood is not a
//! closed oriented disk, or any triangle that intersects another (exact test, `crate::intersect`;
//! the argument of [`super::certify`] holds on the uniform grid only), forbids the collapsed nodes
//! around it, and the collapse is redone without them, until the mesh is clean (in the worst case
//! the plain mesh, which always is).

use super::block::{Block, NO_VERTEX};
use super::contour::Contour;
use super::emit;
use super::patches::patch_table;
use super::qef::Qef;
use super::sources::Signs;
use crate::IndexedMesh;
use crate::grid::GridSpec;
use crate::intersect::self_intersections;
use glam::DVec3;
use std::collections::{HashMap, HashSet};

/// Largest collapsed node: `2^MAX_LEVEL` cells per side.
pub(crate) const MAX_LEVEL: u32 = 6;

/// Rounds of forbidding nodes before giving up on simplification.
const MAX_ROUNDS: usize = 24;

#[derive(Clone, Copy)]
enum State {
    Blocked,
    Collapsed { qef: Qef, vertex: u32 },
}

/// A node: level and coordinates (cell minimum / 2^level).
type NodeId = (u32, [usize; 3]);

/// Simplifies the contour within `tolerance`; returns the triangles and extends `positions`.
pub(crate) fn simplify(
    blocks: &[Block],
    contour: &Contour,
    spec: &GridSpec,
    signs: &mut impl Signs,
    tolerance: f64,
    positions: &mut Vec<DVec3>,
) -> Vec<[u32; 3]> {
    let base_len = positions.len();
    let mut forbidden: HashSet<NodeId> = HashSet::new();
    for _ in 0..MAX_ROUNDS {
        positions.truncate(base_len);
        let (map, nodes) = collapse(
            blocks, contour, spec, signs, tolerance, &forbidden, positions,
        );
        let cluster_end = positions.len();
        let tris = emit::triangles(contour, positions, Some(&map));
        let mut bad = bad_vertices(&tris, positions.len());
        if bad.is_empty() {
            bad = crossing_vertices(&tris, positions, base_len..cluster_end);
            if bad.is_empty() {
                return tris;
            }
        }
        let mut progress = false;
        let mut touched: HashSet<u32> = HashSet::new();
        for t in &tris {
            if t.iter().any(|v| bad.contains(v)) {
                touched.extend(t.iter().copied());
            }
        }
        for v in touched {
            let v = v as usize;
            if (base_len..cluster_end).contains(&v) && forbidden.insert(nodes[v - base_len]) {
                progress = true;
            }
        }
        if !progress {
            break;
        }
    }
    positions.truncate(base_len);
    emit::triangles(contour, positions, None)
}

/// One collapse pass: the vertex map (over all ids, extended by the cluster vertices appended to
/// `positions`) and the node of each cluster vertex.
fn collapse(
    blocks: &[Block],
    contour: &Contour,
    spec: &GridSpec,
    signs: &mut impl Signs,
    tolerance: f64,
    forbidden: &HashSet<NodeId>,
    positions: &mut Vec<DVec3>,
) -> (Vec<u32>, Vec<NodeId>) {
    let table = patch_table();
    let base_len = positions.len();
    let mut parent: Vec<u32> = (0..base_len as u32).collect();
    let mut nodes: Vec<NodeId> = Vec::new();
    let mut level: HashMap<[usize; 3], State> = HashMap::new();
    for (b, o) in blocks.iter().enumerate() {
        for k in 0..o.extent[2] {
            for j in 0..o.extent[1] {
                for i in 0..o.extent[0] {
                    let local = o.cell_index([i, j, k]);
                    if o.first[local] == NO_VERTEX {
                        continue;
                    }
                    let cell = table.get(o.configs[local]);
                    let c = [o.min[0] + i, o.min[1] + j, o.min[2] + k];
                    let vertex = contour.bases[b] + o.first[local];
                    let state = if cell.edges.len() == 1
                        && cell.ambiguous == 0
                        && !forbidden.contains(&(0, c))
                    {
                        State::Collapsed {
                            qef: o.qefs[o.first[local] as usize],
                            vertex,
                        }
                    } else {
                        State::Blocked
                    };
                    level.insert(c, state);
                }
            }
        }
    }
    for l in 1..=MAX_LEVEL {
        let mut candidates: Vec<[usize; 3]> = level.keys().map(|c| c.map(|x| x / 2)).collect();
        candidates.sort_unstable_by_key(|c| (c[2], c[1], c[0]));
        candidates.dedup();
        let mut next = HashMap::with_capacity(candidates.len());
        let mut any = false;
        for p in candidates {
            let state = node_state(l, p, &level, spec, signs, tolerance, forbidden);
            if let State::Collapsed { qef, .. } = state {
                any = true;
                let w = positions.len() as u32;
                positions.push(qef_vertex(l, p, &qef, spec));
                parent.push(w);
                nodes.push((l, p));
                for c in 0..8 {
                    let child = [0, 1, 2].map(|a| 2 * p[a] + (c >> a & 1));
                    if let Some(State::Collapsed { vertex, .. }) = level.get(&child) {
                        parent[*vertex as usize] = w;
                    }
                }
                next.insert(p, State::Collapsed { qef, vertex: w });
            } else {
                next.insert(p, State::Blocked);
            }
        }
        level = next;
        if !any {
            break;
        }
    }
    // Follow parents to the top collapsed node.
    let map: Vec<u32> = (0..parent.len())
        .map(|v| {
            let mut r = v;
            while parent[r] as usize != r {
                r = parent[r] as usize;
            }
            r as u32
        })
        .collect();
    (map, nodes)
}

/// The node's box in world coordinates.
fn node_box(l: u32, p: [usize; 3], spec: &GridSpec) -> (DVec3, DVec3) {
    let size = 1usize << l;
    let lo = spec.point(p[0] * size, p[1] * size, p[2] * size);
    (lo, lo + DVec3::splat(spec.cell * size as f64))
}

fn qef_vertex(l: u32, p: [usize; 3], qef: &Qef, spec: &GridSpec) -> DVec3 {
    let (lo, hi) = node_box(l, p, spec);
    qef.solve(lo, hi).0
}

fn node_state(
    l: u32,
    p: [usize; 3],
    level: &HashMap<[usize; 3], State>,
    spec: &GridSpec,
    signs: &mut impl Signs,
    tolerance: f64,
    forbidden: &HashSet<NodeId>,
) -> State {
    let size = 1usize << l;
    if forbidden.contains(&(l, p)) || (0..3).any(|a| (p[a] + 1) * size > spec.cells[a]) {
        return State::Blocked;
    }
    let (lo, hi) = node_box(l, p, spec);
    let mut merged = Qef::new(0.5 * (lo + hi));
    for c in 0..8 {
        let child = [0, 1, 2].map(|a| 2 * p[a] + (c >> a & 1));
        match level.get(&child) {
            None => {}
            Some(State::Blocked) => return State::Blocked,
            Some(State::Collapsed { qef, .. }) => merged.merge(qef),
        }
    }
    // Signs of the 27 samples at half-node spacing.
    let h = size / 2;
    let mut s = [[[false; 3]; 3]; 3];
    for (k, plane) in s.iter_mut().enumerate() {
        for (j, row) in plane.iter_mut().enumerate() {
            for (i, v) in row.iter_mut().enumerate() {
                *v = signs.inside([
                    p[0] * size + i * h,
                    p[1] * size + j * h,
                    p[2] * size + k * h,
                ]);
            }
        }
    }
    let at = |q: [usize; 3]| s[q[2]][q[1]][q[0]];
    let mut mask = 0u16;
    for c in 0..8 {
        mask |= u16::from(at([c & 1, c >> 1 & 1, c >> 2 & 1].map(|x| 2 * x))) << c;
    }
    // Without ambiguous faces the mask is the whole configuration.
    let node = patch_table().get(mask);
    if mask == 0 || mask == 255 || node.edges.len() != 1 || node.ambiguous != 0 {
        return State::Blocked;
    }
    // Ju et al.: edge midpoints, face centres.
    for a in 0..3 {
        let (u, v) = ((a + 1) % 3, (a + 2) % 3);
        for cu in [0, 2] {
            for cv in [0, 2] {
                let mut q = [0; 3];
                q[u] = cu;
                q[v] = cv;
                let ends = [0, 2].map(|x| {
                    q[a] = x;
                    at(q)
                });
                q[a] = 1;
                if ends[0] == ends[1] && at(q) != ends[0] {
                    return State::Blocked;
                }
            }
        }
        for side in [0, 2] {
            let mut q = [0; 3];
            q[a] = side;
            let mut corners = Vec::with_capacity(4);
            for cu in [0, 2] {
                for cv in [0, 2] {
                    q[u] = cu;
                    q[v] = cv;
                    corners.push(at(q));
                }
            }
            q[u] = 1;
            q[v] = 1;
            if corners.iter().all(|&c| c == corners[0]) && at(q) != corners[0] {
                return State::Blocked;
            }
        }
    }
    let (x, err) = merged.solve(lo, hi);
    if merged.count == 0 || !x.is_finite() || err > tolerance * tolerance {
        return State::Blocked;
    }
    State::Collapsed {
        qef: merged,
        vertex: 0,
    }
}

/// The vertices of triangles that intersect another triangle (exact test, [`crate::intersect`]);
/// for a pair with no cluster vertex (ids in `clusters`), also the vertices of the triangles
/// sharing a vertex with it (a quad re-split next to a merged corner).
fn crossing_vertices(
    tris: &[[u32; 3]],
    positions: &[DVec3],
    clusters: std::ops::Range<usize>,
) -> HashSet<u32> {
    let mesh = IndexedMesh {
        positions: positions.to_vec(),
        triangles: tris.to_vec(),
    };
    let Ok(found) = self_intersections(&mesh, usize::MAX) else {
        // A vertex that is not finite: forbid everything touched by the clusters.
        return clusters.map(|v| v as u32).collect();
    };
    let mut out = HashSet::new();
    let mut lonely = HashSet::new();
    for pair in found.examples {
        for t in pair {
            let t = tris[t as usize];
            if t.iter().any(|&v| clusters.contains(&(v as usize))) {
                out.extend(t);
            } else {
                lonely.extend(t);
            }
        }
    }
    if !lonely.is_empty() {
        for t in tris {
            if t.iter().any(|v| lonely.contains(v)) {
                out.extend(t.iter().copied());
            }
        }
    }
    out
}

/// Vertices whose neighbourhood in `tris` is not a closed, oriented disk (also the corners of
/// triangles with a repeated vertex).
pub(crate) fn bad_vertices(tris: &[[u32; 3]], vertex_count: usize) -> HashSet<u32> {
    let mut bad = HashSet::new();
    let mut directed: Vec<(u32, u32)> = Vec::with_capacity(3 * tris.len());
    let mut start = vec![0u32; vertex_count + 1];
    for t in tris {
        if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            bad.extend(t.iter().copied());
            continue;
        }
        for k in 0..3 {
            directed.push((t[k], t[(k + 1) % 3]));
            start[t[k] as usize + 1] += 1;
        }
    }
    // Every directed edge once, and its reverse once.
    let mut sorted = directed.clone();
    sorted.sort_unstable();
    for w in sorted.windows(2) {
        if w[0] == w[1] {
            bad.insert(w[0].0);
            bad.insert(w[0].1);
        }
    }
    for &(a, b) in &sorted {
        if sorted.binary_search(&(b, a)).is_err() {
            bad.insert(a);
            bad.insert(b);
        }
    }
    // The link of each vertex is one cycle: b → c for each triangle (a, b, c) at a.
    for v in 1..=vertex_count {
        start[v] += start[v - 1];
    }
    let mut fill = start.clone();
    let mut link = vec![(0u32, 0u32); start[vertex_count] as usize];
    for t in tris {
        if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            continue;
        }
        for k in 0..3 {
            let a = t[k] as usize;
            link[fill[a] as usize] = (t[(k + 1) % 3], t[(k + 2) % 3]);
            fill[a] += 1;
        }
    }
    for v in 0..vertex_count {
        let l = &link[start[v] as usize..start[v + 1] as usize];
        if l.is_empty() || bad.contains(&(v as u32)) {
            continue;
        }
        let mut at = l[0].0;
        let mut steps = 0;
        while let Some(e) = l.iter().find(|e| e.0 == at) {
            at = e.1;
            steps += 1;
            if at == l[0].0 || steps > l.len() {
                break;
            }
        }
        if steps != l.len() {
            bad.insert(v as u32);
        }
    }
    bad
}
