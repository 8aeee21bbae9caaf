//! Face clean-up: zero-area faces with three distinct collinear corners (T-junctions) and
//! duplicate faces.

use super::RepairCounts;
use super::edges::{canonical, directed, key};
use crate::io::key_hash::KeyHash;
use crate::topology::EdgeTable;
use glam::DVec3;
use rayon::prelude::*;
use std::collections::{HashMap, HashSet};

/// Whether the triangle has zero area by the topology report's rule
/// (`|cross| <= 1e-12 * longest_edge²`).
pub(super) fn is_zero_area(p: [DVec3; 3]) -> bool {
    let cross = (p[1] - p[0]).cross(p[2] - p[0]).length();
    let longest = (p[1] - p[0])
        .length_squared()
        .max((p[2] - p[1]).length_squared())
        .max((p[0] - p[2]).length_squared());
    cross <= 1e-12 * longest
}

/// Removes zero-area faces; the other faces on the long edge of each are split at its middle
/// corner first, so the surface keeps no crack (a T-junction becomes shared vertices).
/// `src` runs along `tris` (the input face of each, `u32::MAX` for the new halves).
pub(super) fn split_zero_area(
    positions: &[DVec3],
    tris: &mut Vec<[u32; 3]>,
    src: &mut Vec<u32>,
    counts: &mut RepairCounts,
) {
    let corners = |t: [u32; 3]| t.map(|i| positions[i as usize]);
    let slivers: Vec<usize> = (0..tris.len())
        .into_par_iter()
        .filter(|&f| is_zero_area(corners(tris[f])))
        .collect();
    if slivers.is_empty() {
        return;
    }
    let mut alive = vec![true; tris.len()];
    let mut map = super::edges::edge_faces(tris);
    for &s in &slivers {
        alive[s] = false;
        remove_face(&mut map, tris[s], s as u32);
        counts.zero_area_faces_removed += 1;
    }
    for &s in &slivers {
        let t = tris[s];
        // The long edge is the one opposite the corner lying between the other two.
        let p = corners(t);
        let mid = (0..3)
            .max_by(|&i, &j| {
                let opp = |k: usize| p[(k + 1) % 3].distance_squared(p[(k + 2) % 3]);
                opp(i).total_cmp(&opp(j))
            })
            .unwrap_or(0);
        let (m, a, b) = (t[mid], t[(mid + 1) % 3], t[(mid + 2) % 3]);
        let neighbours: Vec<u32> = map.get(&key(a, b)).cloned().unwrap_or_default();
        for g in neighbours {
            let gt = tris[g as usize];
            if !alive[g as usize] {
                continue;
            }
            let Some(&(x, y)) = directed(gt).iter().find(|&&(x, y)| key(x, y) == key(a, b)) else {
                continue;
            };
            let c = gt.iter().copied().find(|&v| v != x && v != y).unwrap_or(x);
            if c == m {
                continue;
            }
            alive[g as usize] = false;
            remove_face(&mut map, gt, g);
            for nt in [[x, m, c], [m, y, c]] {
                let id = tris.len() as u32;
                tris.push(nt);
                src.push(u32::MAX);
                alive.push(true);
                for (u, v) in directed(nt) {
                    map.entry(key(u, v)).or_default().push(id);
                }
            }
            counts.faces_split_at_zero_area += 1;
        }
    }
    retain(tris, src, |f, _| alive[f]);
}

/// Keeps the faces (and their entries in `src`) for which `keep(index, face)` holds.
fn retain(
    tris: &mut Vec<[u32; 3]>,
    src: &mut Vec<u32>,
    mut keep: impl FnMut(usize, [u32; 3]) -> bool,
) {
    let mut kept = 0;
    for f in 0..tris.len() {
        if keep(f, tris[f]) {
            tris[kept] = tris[f];
            src[kept] = src[f];
            kept += 1;
        }
    }
    tris.truncate(kept);
    src.truncate(kept);
}

fn remove_face(map: &mut HashMap<(u32, u32), Vec<u32>>, t: [u32; 3], id: u32) {
    for (u, v) in directed(t) {
        if let Some(list) = map.get_mut(&key(u, v)) {
            list.retain(|&g| g != id);
        }
    }
}

/// Whether two faces have the same three vertices: such faces share every edge, so only the
/// faces of edges used more than once are compared (runs longer than two are assumed to hold
/// some, and [`remove_duplicates`] decides).
pub(super) fn may_have_duplicates(tris: &[[u32; 3]], table: &EdgeTable) -> bool {
    let sorted = |f: usize| {
        let mut t = tris[f];
        t.sort_unstable();
        t
    };
    table.edges().any(|e| {
        let mut corners = e.corners();
        match (corners.next(), corners.next(), corners.next()) {
            (Some(a), Some(b), None) => sorted(a / 3) == sorted(b / 3),
            (_, _, Some(_)) => true,
            _ => false,
        }
    })
}

/// Removes faces on the same three vertices as an earlier one. Copies of one winding cancel
/// copies of the other (an internal double wall disappears); of the surplus winding one face
/// stays. Returns how many faces were removed; `src` runs along `tris`.
pub(super) fn remove_duplicates(tris: &mut Vec<[u32; 3]>, src: &mut Vec<u32>) -> usize {
    // Net count per vertex set: +1 for the winding of the set's first face, -1 for the other.
    let mut net: HashMap<[u32; 3], (i64, [u32; 3]), KeyHash> =
        HashMap::with_capacity_and_hasher(tris.len(), KeyHash::default());
    for &t in tris.iter() {
        let c = canonical(t);
        let mut sorted = t;
        sorted.sort_unstable();
        let entry = net.entry(sorted).or_insert((0, c));
        entry.0 += if entry.1 == c { 1 } else { -1 };
    }
    let before = tris.len();
    let mut kept: HashSet<[u32; 3], KeyHash> = HashSet::default();
    retain(tris, src, |_, t| {
        let mut sorted = t;
        sorted.sort_unstable();
        let (n, first) = net[&sorted];
        let c = canonical(t);
        let wanted = if n > 0 {
            c == first
        } else {
            n < 0 && c != first
        };
        wanted && kept.insert(sorted)
    });
    before - tris.len()
}
