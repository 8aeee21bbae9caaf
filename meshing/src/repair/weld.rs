//! Welding within a tolerance on a grid hash: each vertex joins the nearest earlier
//! representative within the tolerance (searched in its grid cell and the neighbouring cells it
//! lies within the tolerance of), or becomes one.
//! A vertex therefore moves at most the tolerance, to an input position.
//!
//! [`weld_mesh`] is the same weld on its own, for `solidkit check --weld`: a triangle soup's
//! corners within the tolerance become shared vertices, and nothing else changes.

use glam::DVec3;
use std::collections::HashMap;

use crate::io::key_hash::KeyHash;

use super::RepairError;
use crate::IndexedMesh;

/// A mesh welded by [`weld_mesh`].
#[derive(Debug, Clone)]
pub struct WeldedMesh {
    /// The mesh on the representative vertices (input positions, first-seen order).
    pub mesh: IndexedMesh,
    /// Input vertices merged into an earlier one.
    pub merged: usize,
    /// The largest distance from an input vertex to its representative.
    pub max_moved: f64,
}

/// `mesh` with every vertex joined to the nearest earlier representative within `eps` (`0`:
/// equal positions only), the triangles renumbered and kept as they are, even those that
/// collapse (the report counts them as degenerate). Indices out of range stay out of range;
/// non-finite positions are never merged. Refuses a negative or non-finite `eps`.
pub fn weld_mesh(mesh: &IndexedMesh, eps: f64) -> Result<WeldedMesh, RepairError> {
    if !(eps.is_finite() && eps >= 0.0) {
        return Err(RepairError::BadWeld(eps));
    }
    let welded = weld(&mesh.positions, eps);
    let triangles = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| welded.map.get(i as usize).copied().unwrap_or(u32::MAX)))
        .collect();
    Ok(WeldedMesh {
        merged: mesh.positions.len() - welded.positions.len(),
        max_moved: welded.moved.iter().copied().fold(0.0, f64::max),
        mesh: IndexedMesh::new(welded.positions, triangles),
    })
}

/// The welded vertices.
pub(super) struct Welded {
    /// Representative positions (input positions), in first-seen order.
    pub positions: Vec<DVec3>,
    /// Input vertex → welded vertex.
    pub map: Vec<u32>,
    /// Per welded vertex, the largest distance of an input vertex merged into it.
    pub moved: Vec<f64>,
}

/// Grid cells are this many weld tolerances wide, so a vertex is within the tolerance of a
/// neighbouring cell on an axis only near that side (an eighth of the time each): about 1.95
/// cells are searched per vertex instead of 27 (3.4 at four tolerances, which measured slower).
/// The cells hold only representatives, which lie more than the tolerance apart, so a cell of a
/// surface holds at most a few dozen of them.
const CELL_PER_EPS: f64 = 8.0;

/// Beyond this many cells from the origin the fraction of a coordinate inside its cell is not
/// reliable: all 27 cells around are searched.
const FAR_CELLS: f64 = (1u64 << 40) as f64;

/// Welds `positions` within `eps` (`0`: equal positions only; `-0.0` equals `0.0`).
pub(super) fn weld(positions: &[DVec3], eps: f64) -> Welded {
    let mut out = Welded {
        positions: Vec::with_capacity(positions.len()),
        map: Vec::with_capacity(positions.len()),
        moved: Vec::with_capacity(positions.len()),
    };
    // Cell → its last representative; `chain[r]` is the previous representative in r's cell.
    let mut cells: HashMap<[i64; 3], u32, KeyHash> =
        HashMap::with_capacity_and_hasher(positions.len(), KeyHash::default());
    let mut chain: Vec<u32> = Vec::with_capacity(positions.len());
    let size = eps * CELL_PER_EPS;
    let near = 1.0 / CELL_PER_EPS + 1e-6;
    for &p in positions {
        let (c, reach) = if eps > 0.0 {
            let q = p / size;
            let f = q.floor();
            let frac = q - f;
            let far = q.abs().max_element() > FAR_CELLS;
            // `as` saturates: absurd ratios share border cells, distances stay exact.
            let reach = [0, 1, 2].map(|i| {
                let lo = far || frac[i] <= near;
                let hi = far || frac[i] >= 1.0 - near;
                (if lo { -1 } else { 0 }, if hi { 1 } else { 0 })
            });
            (f.to_array().map(|x| x as i64), reach)
        } else {
            let bits = (p + DVec3::ZERO).to_array().map(|x| x.to_bits() as i64);
            (bits, [(0, 0); 3])
        };
        let mut best: Option<(f64, u32)> = None;
        for dx in reach[0].0..=reach[0].1 {
            for dy in reach[1].0..=reach[1].1 {
                for dz in reach[2].0..=reach[2].1 {
                    let k = [
                        c[0].saturating_add(dx),
                        c[1].saturating_add(dy),
                        c[2].saturating_add(dz),
                    ];
                    let mut at = cells.get(&k).copied().unwrap_or(u32::MAX);
                    while at != u32::MAX {
                        let d = p.distance(out.positions[at as usize]);
                        if d <= eps && best.is_none_or(|(bd, r)| d < bd || (d == bd && at < r)) {
                            best = Some((d, at));
                        }
                        at = chain[at as usize];
                    }
                }
            }
        }
        match best {
            Some((d, r)) => {
                out.map.push(r);
                let m = &mut out.moved[r as usize];
                *m = m.max(d);
            }
            None => {
                let r = out.positions.len() as u32;
                out.positions.push(p);
                out.moved.push(0.0);
                chain.push(cells.insert(c, r).unwrap_or(u32::MAX));
                out.map.push(r);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weld_mesh_shares_close_corners_and_keeps_everything_else() {
        let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        let soup = IndexedMesh::new(
            vec![
                p(0.0, 0.0),
                p(1.0, 0.0),
                p(0.0, 1.0),
                p(1.0, 1e-9),
                p(1.0, 1.0),
                p(0.0, 1.0),
            ],
            vec![[0, 1, 2], [3, 4, 5], [0, 1, 9]],
        );
        let w = weld_mesh(&soup, 1e-6).unwrap();
        assert_eq!(w.merged, 2);
        assert_eq!(w.mesh.positions.len(), 4);
        assert_eq!(
            w.mesh.triangles,
            vec![[0, 1, 2], [1, 3, 2], [0, 1, u32::MAX]]
        );
        assert!((w.max_moved - 1e-9).abs() < 1e-15);
        assert_eq!(weld_mesh(&soup, 0.0).unwrap().merged, 1);
        assert!(weld_mesh(&soup, -1.0).is_err() && weld_mesh(&soup, f64::NAN).is_err());
    }
}
