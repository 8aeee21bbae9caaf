//! Meshes of swept loops ("discrétisation régulière" of lecture notes 001 applied to sweeps):
//! a profile's boundary loops placed at `stations` positions along a sweep, consecutive
//! stations joined by two triangles per loop edge, open ends closed by the triangulated profile,
//! periodic sweeps joined back to their first station. Vertices that coincide exactly (a profile
//! corner on a revolution's axis, a ruled surface's apex) are welded and the triangles they
//! flatten dropped, which closes poles. The winding is made outward from the sign of the volume.
//!
//! Counts without welding: `S` stations of `N` loop points give `S·N` vertices; `2·(S − 1)·N`
//! side triangles (`2·S·N` when periodic) plus `2·(N + 2h − 2)` cap triangles for a profile with
//! `h` holes.

use super::error::SweepError;
use crate::IndexedMesh;
use crate::profile::triangulate;
use glam::{DVec2, DVec3};
use std::collections::HashMap;

/// Largest number of stations or loop points accepted.
pub const MAX_SAMPLES: usize = 1 << 14;

/// Checks a sample count.
pub(crate) fn count(parameter: &'static str, n: usize, min: usize) -> Result<(), SweepError> {
    if n < min || n > MAX_SAMPLES {
        Err(super::error::invalid(
            parameter,
            "sample count out of range (see MAX_SAMPLES)",
        ))
    } else {
        Ok(())
    }
}

/// Which loops to reverse so the region is on their left: outlines counter-clockwise, holes
/// (loops inside an odd number of others) clockwise.
pub(crate) fn flips(loops: &[Vec<DVec2>]) -> Vec<bool> {
    let area2 = |l: &[DVec2]| -> f64 {
        (0..l.len())
            .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
            .sum()
    };
    let inside = |q: DVec2, l: &[DVec2]| -> bool {
        let n = l.len();
        let mut c = false;
        for i in 0..n {
            let (a, b) = (l[(i + n - 1) % n], l[i]);
            if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y) {
                c = !c;
            }
        }
        c
    };
    (0..loops.len())
        .map(|r| {
            let depth = (0..loops.len())
                .filter(|&o| o != r && inside(loops[r][0], &loops[o]))
                .count();
            (area2(&loops[r]) > 0.0) != depth.is_multiple_of(2)
        })
        .collect()
}

/// The loops with those marked in `flips` reversed.
pub(crate) fn apply_flips(mut loops: Vec<Vec<DVec2>>, flips: &[bool]) -> Vec<Vec<DVec2>> {
    for (l, &f) in loops.iter_mut().zip(flips) {
        if f {
            l.reverse();
        }
    }
    loops
}

/// The loops oriented with the region on their left (see [`flips`]).
pub(crate) fn oriented(loops: Vec<Vec<DVec2>>) -> Vec<Vec<DVec2>> {
    let f = flips(&loops);
    apply_flips(loops, &f)
}

/// The counter-clockwise triangulation of oriented loops (`key`: the profile's key for errors).
pub(crate) fn cap(key: &'static str, loops: &[Vec<DVec2>]) -> Result<Vec<[u32; 3]>, SweepError> {
    triangulate(loops).map_err(|error| SweepError::Profile { key, error })
}

/// The mesh of loops of `sizes` points at `stations` positions: `place(s, k)` is point `k`
/// (counting over all loops, each oriented with the region on its left) at station `s`, the
/// stations following the direction `U × V` of the profile plane (the winding is fixed from the
/// volume's sign anyway). `periodic` joins the last station to the first; otherwise `caps[0]` and
/// `caps[1]` (counter-clockwise triangles over a station's points) close the first and last
/// station, skipped at an end whose points all coincide (welding closes it).
pub(crate) fn sweep_mesh(
    sizes: &[usize],
    stations: usize,
    periodic: bool,
    place: impl Fn(usize, usize) -> DVec3,
    caps: [&[[u32; 3]]; 2],
) -> IndexedMesh {
    let per_station: usize = sizes.iter().sum();
    let mut positions = Vec::with_capacity(stations * per_station);
    for s in 0..stations {
        for k in 0..per_station {
            positions.push(place(s, k));
        }
    }
    let id = |s: usize, k: usize| ((s % stations) * per_station + k) as u32;
    let mut triangles = Vec::new();
    let joins = if periodic { stations } else { stations - 1 };
    for s in 0..joins {
        let mut offset = 0;
        for &n in sizes {
            for i in 0..n {
                let (a, b) = (offset + i, offset + (i + 1) % n);
                // Diagonals alternate like a checkerboard, so the first-order volume bias of
                // twisted quads cancels between neighbours.
                if (s + i).is_multiple_of(2) {
                    triangles.push([id(s, a), id(s, b), id(s + 1, b)]);
                    triangles.push([id(s, a), id(s + 1, b), id(s + 1, a)]);
                } else {
                    triangles.push([id(s, a), id(s, b), id(s + 1, a)]);
                    triangles.push([id(s, b), id(s + 1, b), id(s + 1, a)]);
                }
            }
            offset += n;
        }
    }
    if !periodic {
        for (s, flip, tris) in [(0, true, caps[0]), (stations - 1, false, caps[1])] {
            let first = positions[id(s, 0) as usize];
            if (0..per_station).all(|k| positions[id(s, k) as usize] == first) {
                continue;
            }
            for t in tris {
                let [a, b, c] = t.map(|k| id(s, k as usize));
                triangles.push(if flip { [a, c, b] } else { [a, b, c] });
            }
        }
    }
    outward(weld(IndexedMesh::new(positions, triangles)))
}

/// Merges vertices at exactly the same position (−0 and +0 alike) and drops triangles that lose
/// a corner to the merge.
pub(crate) fn weld(mesh: IndexedMesh) -> IndexedMesh {
    let key = |p: DVec3| (p + DVec3::ZERO).to_array().map(f64::to_bits);
    let mut map: HashMap<[u64; 3], u32> = HashMap::with_capacity(mesh.positions.len());
    let mut positions = Vec::with_capacity(mesh.positions.len());
    let remap: Vec<u32> = mesh
        .positions
        .iter()
        .map(|&p| {
            *map.entry(key(p)).or_insert_with(|| {
                positions.push(p + DVec3::ZERO);
                (positions.len() - 1) as u32
            })
        })
        .collect();
    let triangles = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| remap[i as usize]))
        .filter(|[a, b, c]| a != b && b != c && a != c)
        .collect();
    IndexedMesh::new(positions, triangles)
}

/// Signed volume by the divergence theorem (positive for outward winding).
pub fn signed_volume(mesh: &IndexedMesh) -> f64 {
    (0..mesh.triangle_count())
        .map(|t| {
            let [a, b, c] = mesh.triangle_positions(t);
            a.dot(b.cross(c))
        })
        .sum::<f64>()
        / 6.0
}

/// The mesh with every triangle reversed if its volume is negative.
fn outward(mut mesh: IndexedMesh) -> IndexedMesh {
    if signed_volume(&mesh) < 0.0 {
        for t in &mut mesh.triangles {
            t.swap(1, 2);
        }
    }
    mesh
}
