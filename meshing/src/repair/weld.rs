//! Welding within a tolerance on a grid hash: each vertex joins the nearest earlier
//! representative within the tolerance (searched in the 27 grid cells around it), or becomes one.
//! A vertex therefore moves at most the tolerance, to an input position.

use glam::DVec3;
use std::collections::HashMap;

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
