//! 2D regions from samples: marching squares over a grid of inside/outside samples, with each
//! boundary crossing placed by the caller (exactly, where it can), the loops simplified within a
//! fraction of a cell and grouped into outlines with their holes as a [`Flat`] union.
//!
//! The samples on the grid's border count as outside, so every loop closes. A cell whose two
//! diagonal corners are inside keeps them apart (each run of inside corners is cut off by its own
//! segment), so loops never touch. Segments keep the inside on their left: outlines run
//! counter-clockwise and holes clockwise. [`region`] groups loops by nesting depth.

use super::flat::{Flat, Leaf2, Op2};
use glam::DVec2;
use std::collections::HashMap;

/// A grid of `(nx + 1) × (ny + 1)` samples, `cell` apart, from `origin`.
#[derive(Debug, Clone, Copy)]
pub struct Grid2 {
    /// The sample `(0, 0)`.
    pub origin: DVec2,
    /// Distance between neighbouring samples.
    pub cell: f64,
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
}

impl Grid2 {
    /// A grid over the box `lo..hi` with `cells` cells along its longer side and one cell of
    /// margin all round (so the border samples are outside the box).
    pub fn covering(lo: DVec2, hi: DVec2, cells: usize) -> Grid2 {
        let size = (hi - lo).max_element().max(f64::MIN_POSITIVE);
        let cell = size / cells as f64;
        let n = |extent: f64| (extent / cell).ceil() as usize + 2;
        Grid2 {
            origin: lo - DVec2::splat(cell),
            cell,
            nx: n(hi.x - lo.x),
            ny: n(hi.y - lo.y),
        }
    }

    /// The position of sample `(i, j)`.
    pub fn point(&self, i: usize, j: usize) -> DVec2 {
        self.origin + DVec2::new(i as f64, j as f64) * self.cell
    }

    /// Number of samples.
    pub fn samples(&self) -> usize {
        (self.nx + 1) * (self.ny + 1)
    }

    /// The index of sample `(i, j)` in row-major order.
    pub fn index(&self, i: usize, j: usize) -> usize {
        j * (self.nx + 1) + i
    }
}

/// The boundary loops of the samples marked inside, crossings placed by `crossing(inside point,
/// outside point)` (called once per grid edge that crosses). Outlines counter-clockwise, holes
/// clockwise; loops are simplified within `tolerance`.
pub fn contour(
    grid: &Grid2,
    inside: &[bool],
    tolerance: f64,
    mut crossing: impl FnMut(DVec2, DVec2) -> DVec2,
) -> Vec<Vec<DVec2>> {
    let (nx, ny) = (grid.nx, grid.ny);
    let is_in = |i: usize, j: usize| i > 0 && j > 0 && i < nx && j < ny && inside[grid.index(i, j)];
    let horizontal = (ny + 1) * nx;
    // Edge ids: horizontal (i, j)–(i + 1, j), then vertical (i, j)–(i, j + 1).
    let h = |i: usize, j: usize| j * nx + i;
    let v = |i: usize, j: usize| horizontal + j * (nx + 1) + i;
    let mut next: HashMap<usize, usize> = HashMap::new();
    for j in 0..ny {
        for i in 0..nx {
            let corner = [
                is_in(i, j),
                is_in(i + 1, j),
                is_in(i + 1, j + 1),
                is_in(i, j + 1),
            ];
            if corner.iter().all(|&c| c) || !corner.iter().any(|&c| c) {
                continue;
            }
            // Edge k joins corner k and corner k + 1 (counter-clockwise).
            let edge = [h(i, j), v(i + 1, j), h(i, j + 1), v(i, j)];
            for k in 0..4 {
                if corner[k] && !corner[(k + 1) % 4] {
                    // The run of inside corners ending at k starts after edge m - 1.
                    let mut m = k;
                    while corner[(m + 3) % 4] {
                        m = (m + 3) % 4;
                    }
                    next.insert(edge[k], edge[(m + 3) % 4]);
                }
            }
        }
    }
    // The crossing on each edge, inside end first.
    let mut position = |e: usize| -> DVec2 {
        let (a, b) = if e < horizontal {
            let (i, j) = (e % nx, e / nx);
            ((i, j), (i + 1, j))
        } else {
            let k = e - horizontal;
            let (i, j) = (k % (nx + 1), k / (nx + 1));
            ((i, j), (i, j + 1))
        };
        let (pa, pb) = (grid.point(a.0, a.1), grid.point(b.0, b.1));
        if is_in(a.0, a.1) {
            crossing(pa, pb)
        } else {
            crossing(pb, pa)
        }
    };
    let mut starts: Vec<usize> = next.keys().copied().collect();
    starts.sort_unstable();
    let mut done = vec![false; 0];
    done.resize(starts.len(), false);
    let rank: HashMap<usize, usize> = starts.iter().enumerate().map(|(k, &e)| (e, k)).collect();
    let mut loops = Vec::new();
    for (k, &start) in starts.iter().enumerate() {
        if done[k] {
            continue;
        }
        let mut ring = Vec::new();
        let mut e = start;
        loop {
            done[rank[&e]] = true;
            ring.push(position(e));
            e = next[&e];
            if e == start {
                break;
            }
        }
        let ring = simplify(&ring, tolerance);
        if ring.len() >= 3 && area(&ring) != 0.0 {
            loops.push(ring);
        }
    }
    loops
}

/// Signed area of a loop (shoelace; positive counter-clockwise).
pub fn area(l: &[DVec2]) -> f64 {
    (0..l.len())
        .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
        .sum::<f64>()
        / 2.0
}

/// Douglas–Peucker on a closed loop (explicit stack): the corners that keep every dropped one
/// within `tolerance` of the result.
pub fn simplify(ring: &[DVec2], tolerance: f64) -> Vec<DVec2> {
    let n = ring.len();
    if n < 4 {
        return ring.to_vec();
    }
    // Split at corner 0 and the corner farthest from it.
    let far = (1..n)
        .max_by(|&a, &b| {
            (ring[a] - ring[0])
                .length_squared()
                .total_cmp(&(ring[b] - ring[0]).length_squared())
        })
        .expect("corners");
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[far] = true;
    let mut stack = vec![(0, far), (far, n)];
    while let Some((a, b)) = stack.pop() {
        let (p, q) = (ring[a], ring[b % n]);
        let d = q - p;
        let len = d.length();
        let mut best = (0.0, 0);
        for (k, r) in ring.iter().enumerate().take(b).skip(a + 1) {
            let dist = if len > 0.0 {
                d.perp_dot(*r - p).abs() / len
            } else {
                (*r - p).length()
            };
            if dist > best.0 {
                best = (dist, k);
            }
        }
        if best.0 > tolerance {
            keep[best.1] = true;
            stack.push((a, best.1));
            stack.push((best.1, b));
        }
    }
    ring.iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(p, _)| *p)
        .collect()
}

/// Whether `p` is inside the loop `l` (crossing number).
fn contains(l: &[DVec2], p: DVec2) -> bool {
    let mut inside = false;
    let mut a = l[l.len() - 1];
    for &b in l {
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y) {
            inside = !inside;
        }
        a = b;
    }
    inside
}

/// Non-crossing loops (of any orientation) as a region by the even-odd rule: each loop inside an
/// even number of others is an outline, with the loops directly inside it as its holes; one
/// polygon leaf per outline, joined by a union. `None` when there are no loops.
pub fn region(loops: Vec<Vec<DVec2>>) -> Option<Flat> {
    let boxes: Vec<(DVec2, DVec2)> = loops
        .iter()
        .map(|l| {
            l.iter().fold(
                (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
                |(lo, hi), p| (lo.min(*p), hi.max(*p)),
            )
        })
        .collect();
    let areas: Vec<f64> = loops.iter().map(|l| area(l).abs()).collect();
    // The loops containing each loop (tested at its first corner), and the smallest of them.
    let mut depth = vec![0usize; loops.len()];
    let mut parent: Vec<Option<usize>> = vec![None; loops.len()];
    for (k, l) in loops.iter().enumerate() {
        let p = l[0];
        for (m, other) in loops.iter().enumerate() {
            let (lo, hi) = boxes[m];
            if m == k || !(p.cmpge(lo).all() && p.cmple(hi).all()) || !contains(other, p) {
                continue;
            }
            depth[k] += 1;
            if parent[k].is_none_or(|q| areas[m] < areas[q]) {
                parent[k] = Some(m);
            }
        }
    }
    let mut part_of = vec![usize::MAX; loops.len()];
    let mut parts: Vec<Vec<Vec<DVec2>>> = Vec::new();
    for k in 0..loops.len() {
        if depth[k].is_multiple_of(2) {
            part_of[k] = parts.len();
            parts.push(vec![loops[k].clone()]);
        }
    }
    for k in 0..loops.len() {
        if !depth[k].is_multiple_of(2)
            && let Some(q) = parent[k]
            && part_of[q] != usize::MAX
        {
            parts[part_of[q]].push(loops[k].clone());
        }
    }
    if parts.is_empty() {
        return None;
    }
    let leaves: Vec<Flat> = parts
        .into_iter()
        .map(|p| Flat::leaf(Leaf2::Polygon(p)))
        .collect();
    Some(Flat::combine(leaves, Op2::Union))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ring_of_samples_is_an_outline_with_a_hole() {
        // Inside: the annulus 1 ≤ |p| ≤ 3 sampled on a fine grid; crossings at edge midpoints.
        let g = Grid2::covering(DVec2::splat(-3.0), DVec2::splat(3.0), 60);
        let mut inside = vec![false; g.samples()];
        for j in 0..=g.ny {
            for i in 0..=g.nx {
                let r = g.point(i, j).length();
                inside[g.index(i, j)] = (1.0..=3.0).contains(&r);
            }
        }
        let loops = contour(&g, &inside, 0.0, |a, b| (a + b) / 2.0);
        assert_eq!(loops.len(), 2);
        let areas: Vec<f64> = loops.iter().map(|l| area(l)).collect();
        assert!(areas.iter().any(|&a| a > 0.0) && areas.iter().any(|&a| a < 0.0));
        let total: f64 = areas.iter().sum();
        let exact = std::f64::consts::PI * 8.0;
        assert!((total - exact).abs() < 0.03 * exact, "{total}");
        let Some(Flat(ops)) = region(loops) else {
            panic!("no region")
        };
        assert!(matches!(&ops[..], [Op2::Leaf(Leaf2::Polygon(l))] if l.len() == 2));
    }

    #[test]
    fn simplify_drops_collinear_corners_and_keeps_the_others() {
        let square: Vec<DVec2> = (0..4)
            .flat_map(|s| {
                (0..10).map(move |k| {
                    let t = k as f64 / 10.0;
                    match s {
                        0 => DVec2::new(t, 0.0),
                        1 => DVec2::new(1.0, t),
                        2 => DVec2::new(1.0 - t, 1.0),
                        _ => DVec2::new(0.0, 1.0 - t),
                    }
                })
            })
            .collect();
        let s = simplify(&square, 1e-9);
        assert_eq!(s.len(), 4, "{s:?}");
        assert!((area(&s) - 1.0).abs() < 1e-12);
    }
}
