//! Welding within a tolerance on a grid hash: each vertex joins the nearest earlier
//! representative within the tolerance (searched in the 27 grid cells around it), or becomes one.
//! A vertex therefore moves at most the tolerance, to an input position.
//!
//! [`weld_mesh`] is the same weld on its own, for `solidkit check --weld`: a triangle soup's
//! corners within the tolerance become shared vertices, and nothing else changes.

use glam::DVec3;
use std::collections::HashMap;

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

/// Welds `positions` within `eps` (`0`: equal positions only; `-0.0` equals `0.0`).
pub(super) fn weld(positions: &[DVec3], eps: f64) -> Welded {
    let mut out = Welded {
        positions: Vec::new(),
        map: Vec::with_capacity(positions.len()),
        moved: Vec::new(),
    };
    let mut cells: HashMap<[i64; 3], Vec<u32>> = HashMap::with_capacity(positions.len());
    let cell_of = |p: DVec3| -> [i64; 3] {
        if eps > 0.0 {
            // `as` saturates: absurd ratios share border cells, distances stay exact.
            (p / eps).floor().to_array().map(|c| c as i64)
        } else {
            (p + DVec3::ZERO).to_array().map(|c| c.to_bits() as i64)
        }
    };
    for &p in positions {
        let c = cell_of(p);
        let mut best: Option<(f64, u32)> = None;
        let reach = if eps > 0.0 { 1 } else { 0 };
        for dx in -reach..=reach {
            for dy in -reach..=reach {
                for dz in -reach..=reach {
                    let k = [
                        c[0].saturating_add(dx),
                        c[1].saturating_add(dy),
                        c[2].saturating_add(dz),
                    ];
                    for &r in cells.get(&k).map_or(&[][..], Vec::as_slice) {
                        let d = p.distance(out.positions[r as usize]);
                        if d <= eps && best.is_none_or(|(bd, _)| d < bd) {
                            best = Some((d, r));
                        }
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
                cells.entry(c).or_default().push(r);
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
