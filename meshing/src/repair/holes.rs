//! Hole filling: boundary loops traced from one-face edges, each closed by spade's constrained
//! Delaunay triangulation in its best-fit plane when the loop projects to a simple polygon, else
//! by the minimal-area triangulation of the loop (dynamic programming, up to
//! [`MAX_DP_EDGES`] edges), else by a fan from its first vertex.

use crate::io::triangulate_polygon;
use glam::DVec3;
use std::collections::HashMap;

/// Longest loop triangulated by the cubic minimal-area dynamic programme.
pub const MAX_DP_EDGES: usize = 400;

/// What the filling did.
#[derive(Debug, Default)]
pub(super) struct Filled {
    /// Copies of one split vertex found on one loop, merged (`from`, `to`); see
    /// [`split_at_copies`].
    pub merged: Vec<(u32, u32)>,
    pub filled: usize,
    pub triangles: usize,
    pub largest: usize,
    pub open: usize,
}

/// Fills every boundary loop of the (consistently oriented) faces, given their one-face edges
/// `a → b` as the faces traverse them (the fill traverses `b → a`); `parent` gives each
/// vertex the vertex it was copied from by the non-manifold split (itself for the others).
pub(super) fn fill_holes(
    positions: &[DVec3],
    tris: &mut Vec<[u32; 3]>,
    boundary: &[(u32, u32)],
    parent: &[u32],
) -> Filled {
    let mut next: HashMap<u32, Vec<u32>> = HashMap::new();
    let total = boundary.len();
    for &(a, b) in boundary {
        next.entry(a).or_default().push(b);
    }
    let mut out = Filled::default();
    let mut starts: Vec<u32> = next.keys().copied().collect();
    starts.sort_unstable();
    for s in starts {
        while let Some(first) = next.get_mut(&s).and_then(Vec::pop) {
            let mut loop_ = vec![s];
            let mut at = first;
            let mut closed = false;
            for _ in 0..=total {
                if at == s {
                    closed = true;
                    break;
                }
                loop_.push(at);
                match next.get_mut(&at).and_then(Vec::pop) {
                    Some(n) => at = n,
                    None => break,
                }
            }
            if !closed || loop_.len() < 3 {
                out.open += 1;
                continue;
            }
            loop_.reverse();
            for piece in split_at_copies(loop_, parent, &mut out.merged) {
                if piece.len() < 3 {
                    continue;
                }
                let added = triangulate_loop(positions, &piece, tris);
                out.filled += 1;
                out.triangles += added;
                out.largest = out.largest.max(piece.len());
            }
        }
    }
    if !out.merged.is_empty() {
        let mut to: HashMap<u32, u32> = out.merged.iter().copied().collect();
        // Merges always go to the smaller index, so following them ends.
        let resolve = |mut v: u32, to: &HashMap<u32, u32>| {
            while let Some(&w) = to.get(&v) {
                v = w;
            }
            v
        };
        let keys: Vec<u32> = to.keys().copied().collect();
        for k in keys {
            let r = resolve(k, &to);
            to.insert(k, r);
        }
        for t in tris.iter_mut() {
            *t = t.map(|v| to.get(&v).copied().unwrap_or(v));
        }
    }
    out
}

/// A boundary loop through two copies of one split vertex (two holes meeting at a vertex, whose
/// faces form two open fans there, so the split gave it a copy per fan) is cut there into two
/// loops, and the two copies become one vertex again (recorded in `merged` as (larger, smaller)
/// index): once both holes are filled, the vertex has one closed fan. Without this the copies
/// would stay apart by a few rounding units, their fans touching without sharing a vertex.
fn split_at_copies(loop_: Vec<u32>, parent: &[u32], merged: &mut Vec<(u32, u32)>) -> Vec<Vec<u32>> {
    let of = |v: u32| parent.get(v as usize).copied().unwrap_or(v);
    let mut work = vec![loop_];
    let mut done = Vec::new();
    while let Some(l) = work.pop() {
        let mut first: HashMap<u32, usize> = HashMap::with_capacity(l.len());
        let mut cut = None;
        for (k, &v) in l.iter().enumerate() {
            if let Some(&i) = first.get(&of(v)) {
                cut = Some((i, k));
                break;
            }
            first.insert(of(v), k);
        }
        let Some((i, j)) = cut else {
            done.push(l);
            continue;
        };
        let to = l[i].min(l[j]);
        let from = l[i].max(l[j]);
        if from != to {
            merged.push((from, to));
        }
        let mut a = vec![to];
        a.extend_from_slice(&l[i + 1..j]);
        let mut b = vec![to];
        b.extend_from_slice(&l[j + 1..]);
        b.extend_from_slice(&l[..i]);
        work.push(a);
        work.push(b);
    }
    done
}

/// Triangulates the polygon `corners` (winding kept) into `tris`; returns the triangles added.
fn triangulate_loop(positions: &[DVec3], corners: &[u32], tris: &mut Vec<[u32; 3]>) -> usize {
    let before = tris.len();
    if corners.len() == 3 {
        tris.push([corners[0], corners[1], corners[2]]);
    } else if triangulate_polygon(positions, corners, tris).is_err() {
        if corners.len() <= MAX_DP_EDGES {
            min_area(positions, corners, tris);
        } else {
            for k in 1..corners.len() - 1 {
                tris.push([corners[0], corners[k], corners[k + 1]]);
            }
        }
    }
    tris.len() - before
}

/// The triangulation of the polygon with the least total area (O(n³) dynamic programme over
/// sub-polygons `i..=j`, filled by increasing length: no recursion).
pub(super) fn min_area(positions: &[DVec3], corners: &[u32], tris: &mut Vec<[u32; 3]>) {
    let n = corners.len();
    let p = |i: usize| positions[corners[i] as usize];
    let area = |i: usize, k: usize, j: usize| (p(k) - p(i)).cross(p(j) - p(i)).length() * 0.5;
    let mut cost = vec![0.0f64; n * n];
    let mut best = vec![0usize; n * n];
    for len in 2..n {
        for i in 0..n - len {
            let j = i + len;
            let mut c = f64::INFINITY;
            for k in i + 1..j {
                let v = cost[i * n + k] + cost[k * n + j] + area(i, k, j);
                if v < c {
                    c = v;
                    best[i * n + j] = k;
                }
            }
            cost[i * n + j] = c;
        }
    }
    let mut stack = vec![(0usize, n - 1)];
    while let Some((i, j)) = stack.pop() {
        if j < i + 2 {
            continue;
        }
        let k = best[i * n + j];
        tris.push([corners[i], corners[k], corners[j]]);
        stack.push((i, k));
        stack.push((k, j));
    }
}
