//! Polygons to triangles. A quad is split along the diagonal whose two triangles agree best with
//! the surface normal at the edge's crossing (the worse triangle of the other choice would be the
//! more tilted or flipped one); polygons through split-face vertices are fanned from a centre
//! vertex at the crossing, so every triangle edge inside the polygon is new.
//!
//! With a vertex map (adaptive simplification), each polygon's corners are mapped first; repeated
//! consecutive corners merge and polygons left with fewer than three corners vanish.

use super::contour::{Contour, FIRST, Quad, SECOND, better_by_normal};
use crate::sink::extend_in_blocks;
use glam::DVec3;

/// Triangles of a contour (vertex ids into `positions`, which gains the polygon centres).
pub(crate) fn triangles(
    c: &Contour,
    positions: &mut Vec<DVec3>,
    map: Option<&[u32]>,
) -> Vec<[u32; 3]> {
    let m = |v: u32| map.map_or(v, |m| m[v as usize]);
    let mut out = Vec::new();
    let mut ring: Vec<u32> = Vec::with_capacity(8);
    match map {
        None => {
            // Every quad as it stands: two triangles each, the blocks written in parallel.
            let lens: Vec<usize> = c.quads.iter().map(|q| 2 * q.len()).collect();
            extend_in_blocks(&mut out, [0; 3], &lens, &|i, out| {
                for (pair, q) in out.chunks_exact_mut(2).zip(&c.quads[i]) {
                    pair.copy_from_slice(&split_quad(q, &[], true));
                }
            });
        }
        Some(_) => {
            for q in c.quads.iter().flatten() {
                ring.clear();
                ring.extend(q.v.iter().map(|&v| m(v)));
                merge_repeats(&mut ring);
                match ring.len() {
                    3 => out.push([ring[0], ring[1], ring[2]]),
                    4 => out.extend(split_quad(
                        &Quad {
                            v: [ring[0], ring[1], ring[2], ring[3]],
                            ..*q
                        },
                        positions,
                        ring[..] == q.v[..],
                    )),
                    _ => {}
                }
            }
        }
    }
    for s in &c.specials {
        ring.clear();
        ring.extend(s.corners.iter().map(|&v| m(v)));
        merge_repeats(&mut ring);
        if ring.len() < 3 {
            continue;
        }
        let centre = positions.len() as u32;
        positions.push(s.point);
        for k in 0..ring.len() {
            out.push([centre, ring[k], ring[(k + 1) % ring.len()]]);
        }
    }
    out
}

/// Drops corners equal to their predecessor (cyclically).
fn merge_repeats(ring: &mut Vec<u32>) {
    ring.dedup();
    while ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
}

/// The two triangles of a quad, along the stored diagonal when its corners are unchanged, else
/// along the one agreeing better with the normal.
fn split_quad(q: &Quad, positions: &[DVec3], unchanged: bool) -> [[u32; 3]; 2] {
    let other = if unchanged {
        q.other_diagonal
    } else {
        better_by_normal(&q.v.map(|v| positions[v as usize]), q.normal)
    };
    let t = if other { SECOND } else { FIRST };
    t.map(|t| t.map(|k| q.v[k]))
}
