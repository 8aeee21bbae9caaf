//! Point-in-shell by ray crossings: for each (query point, containing shell) pair, the signed
//! number of the shell's faces that a ray from the point crosses, which is the shell's winding
//! number at the point when the shell is a 2-cycle (`cycles.rs`).
//!
//! All rays of one pass share a generic direction `d`, so the test is two-dimensional: every
//! vertex is projected once onto the plane across `d` (shared vertices project identically) and
//! a face counts when its projection contains the query's projection and it lies ahead of the
//! query along `d`, `+1` when it faces along `d` and `−1` against. Containment uses exact
//! orientation predicates with a symbolic perturbation of the query point (`q + (ε, ε²)`), so a
//! ray through an edge or a vertex of the projection counts exactly one of the faces around it,
//! as a generic ray would. Only the depth is rounded: when the crossing is within a tolerance
//! of the query point along `d` (the point is on or very near the shell) the pair is ambiguous,
//! cast again along a second direction, and left to the caller (`None`) if still ambiguous.
//!
//! One pass over the faces, in parallel chunks, with the queries binned in a grid over their
//! projections; integer sums, so the result does not depend on the thread count.

use glam::DVec3;
use rayon::prelude::*;
use robust::{Coord, orient2d};

/// The ray directions tried in turn (generic: no simple ratio between the components, so rays
/// from grid points do not run along the grid's edges or faces).
const DIRECTIONS: [[f64; 3]; 2] = [
    [
        0.572_061_402_817_684,
        0.609_566_303_141_045,
        0.548_848_976_390_329,
    ],
    [
        -0.316_227_766_016_838,
        0.838_116_354_287_417,
        0.444_151_604_110_229,
    ],
];

/// Faces per parallel chunk.
const CHUNK: usize = 1 << 14;

/// A frame `(e1, e2, d)`, right-handed: a face counter-clockwise in `(e1, e2)` faces along `d`.
#[derive(Clone, Copy)]
struct Frame {
    e1: DVec3,
    e2: DVec3,
    d: DVec3,
}

impl Frame {
    fn new(d: [f64; 3]) -> Self {
        let d = DVec3::from_array(d).normalize();
        let e1 = d.any_orthonormal_vector();
        Self {
            e1,
            e2: d.cross(e1),
            d,
        }
    }

    /// `(u, v, depth)`.
    fn project(&self, p: DVec3) -> [f64; 3] {
        [p.dot(self.e1), p.dot(self.e2), p.dot(self.d)]
    }
}

/// The pairs to decide: `queries[i]` is the point of query `i`, `containers[i]` the shells to
/// test it against (ascending); `face_shell[f]` is the shell of face `f` (`u32::MAX`: none).
pub(super) struct Pairs<'a> {
    /// Query points.
    pub queries: &'a [DVec3],
    /// Per query, the shells it is tested against, ascending.
    pub containers: &'a [Vec<u32>],
    /// Per face, its shell.
    pub face_shell: &'a [u32],
}

/// Per query, per container (in the order of [`Pairs::containers`]): whether the ray count is
/// non-zero, `None` when both directions were ambiguous. `scale` sets the depth tolerance (a
/// length of the order of the model's size).
pub(super) fn inside_by_rays(
    positions: &[DVec3],
    tris: &[[u32; 3]],
    pairs: &Pairs,
    scale: f64,
) -> Vec<Vec<Option<bool>>> {
    let mut result: Vec<Vec<Option<bool>>> = pairs
        .containers
        .iter()
        .map(|c| vec![None; c.len()])
        .collect();
    let mut todo: Vec<Vec<u32>> = pairs.containers.to_vec();
    for d in DIRECTIONS {
        if todo.iter().all(Vec::is_empty) {
            break;
        }
        let counts = cast(positions, tris, pairs, &todo, Frame::new(d), scale);
        for (i, c) in counts.into_iter().enumerate() {
            let mut left = Vec::new();
            for (&shell, n) in todo[i].iter().zip(c) {
                match n {
                    Some(n) => {
                        let k = pairs.containers[i].binary_search(&shell).unwrap_or(0);
                        result[i][k] = Some(n != 0);
                    }
                    None => left.push(shell),
                }
            }
            todo[i] = left;
        }
    }
    result
}

/// The queries binned in a grid over their projections.
struct Grid {
    lo: [f64; 2],
    inv: [f64; 2],
    n: usize,
    /// Per cell, the queries in it.
    cells: Vec<Vec<u32>>,
}

impl Grid {
    fn new(points: &[[f64; 3]], wanted: impl Fn(usize) -> bool) -> Self {
        let n = ((points.len() as f64).sqrt().ceil() as usize).clamp(1, 64);
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let inv = [0, 1].map(|k| {
            let w = hi[k] - lo[k];
            if w > 0.0 { n as f64 / w } else { 0.0 }
        });
        let mut grid = Self {
            lo,
            inv,
            n,
            cells: vec![Vec::new(); n * n],
        };
        for (i, p) in points.iter().enumerate() {
            if wanted(i) {
                let c = grid.cell(0, p[0]) + n * grid.cell(1, p[1]);
                grid.cells[c].push(i as u32);
            }
        }
        grid
    }

    /// The cell of coordinate `x` on axis `k` (monotonic in `x`, clamped to the grid).
    fn cell(&self, k: usize, x: f64) -> usize {
        let c = ((x - self.lo[k]) * self.inv[k]).floor();
        if c >= 0.0 {
            (c as usize).min(self.n - 1)
        } else {
            0
        }
    }
}

/// One direction's counts: per query, per shell of `todo[i]`, the signed crossing count or
/// `None` when a crossing was too close to the query along the ray.
fn cast(
    positions: &[DVec3],
    tris: &[[u32; 3]],
    pairs: &Pairs,
    todo: &[Vec<u32>],
    frame: Frame,
    scale: f64,
) -> Vec<Vec<Option<i64>>> {
    let mut shells_used: Vec<u32> = todo.iter().flatten().copied().collect();
    shells_used.sort_unstable();
    shells_used.dedup();
    let projected: Vec<[f64; 3]> = positions.par_iter().map(|&p| frame.project(p)).collect();
    let queries: Vec<[f64; 3]> = pairs.queries.iter().map(|&p| frame.project(p)).collect();
    let grid = Grid::new(&queries, |i| !todo[i].is_empty());
    // Pair slots: query i's pairs start at `start[i]`.
    let mut start = vec![0usize; todo.len() + 1];
    for (i, t) in todo.iter().enumerate() {
        start[i + 1] = start[i] + t.len();
    }
    let slots = start[todo.len()];
    let tolerance = 1e-9 * scale;
    let (lo, hi) = (
        [grid.lo[0], grid.lo[1]],
        queries.iter().fold([f64::NEG_INFINITY; 2], |h, q| {
            [h[0].max(q[0]), h[1].max(q[1])]
        }),
    );
    let tally = |range: std::ops::Range<usize>| {
        let mut count = vec![0i64; slots];
        let mut ambiguous = vec![false; slots];
        for f in range {
            let shell = pairs.face_shell[f];
            if shell == u32::MAX || shells_used.binary_search(&shell).is_err() {
                continue;
            }
            let [a, b, c] = tris[f].map(|v| projected[v as usize]);
            let umin = a[0].min(b[0]).min(c[0]);
            let umax = a[0].max(b[0]).max(c[0]);
            let vmin = a[1].min(b[1]).min(c[1]);
            let vmax = a[1].max(b[1]).max(c[1]);
            if umax < lo[0] || umin > hi[0] || vmax < lo[1] || vmin > hi[1] {
                continue;
            }
            for cv in grid.cell(1, vmin)..=grid.cell(1, vmax) {
                for cu in grid.cell(0, umin)..=grid.cell(0, umax) {
                    for &q in &grid.cells[cu + grid.n * cv] {
                        let q = q as usize;
                        let Ok(k) = todo[q].binary_search(&shell) else {
                            continue;
                        };
                        let p = queries[q];
                        if p[0] < umin || p[0] > umax || p[1] < vmin || p[1] > vmax {
                            continue;
                        }
                        let Some(sign) = crossing([a, b, c], p, tolerance) else {
                            ambiguous[start[q] + k] = true;
                            continue;
                        };
                        count[start[q] + k] += i64::from(sign);
                    }
                }
            }
        }
        (count, ambiguous)
    };
    let chunks: Vec<std::ops::Range<usize>> = (0..tris.len())
        .step_by(CHUNK)
        .map(|s| s..(s + CHUNK).min(tris.len()))
        .collect();
    let (count, ambiguous) = chunks.into_par_iter().map(tally).reduce(
        || (vec![0; slots], vec![false; slots]),
        |(mut c, mut a), (c2, a2)| {
            for (x, y) in c.iter_mut().zip(c2) {
                *x += y;
            }
            for (x, y) in a.iter_mut().zip(a2) {
                *x |= y;
            }
            (c, a)
        },
    );
    todo.iter()
        .enumerate()
        .map(|(i, t)| {
            (0..t.len())
                .map(|k| (!ambiguous[start[i] + k]).then_some(count[start[i] + k]))
                .collect()
        })
        .collect()
}

/// The face's contribution to the crossing count of the ray from `p` (projected: `(u, v,
/// depth)`): `0` when its projection misses `p` (perturbed) or it lies behind, `±1` when the ray
/// crosses it (sign: counter-clockwise), `None` when `p` is within `tolerance` of the face (in
/// projection and in depth): `p` is on or next to the face, and the perturbed answer could
/// differ from the winding number's.
fn crossing(t: [[f64; 3]; 3], p: [f64; 3], tolerance: f64) -> Option<i8> {
    let c = |x: [f64; 3]| Coord { x: x[0], y: x[1] };
    let o = [0, 1, 2].map(|k| orient2d(c(t[k]), c(t[(k + 1) % 3]), c(p)));
    // Within `tolerance` of the projected face (each edge's orientation is its length times
    // the distance of p to its line).
    let slack = [0, 1, 2].map(|k| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        tolerance * (b[0] - a[0]).hypot(b[1] - a[1])
    });
    let inside_ccw = (0..3).all(|k| o[k] >= -slack[k]);
    let inside_cw = (0..3).all(|k| o[k] <= slack[k]);
    if !inside_ccw && !inside_cw {
        return Some(0);
    }
    let area = orient2d(c(t[0]), c(t[1]), c(t[2]));
    let near = if area != 0.0 {
        // Depth of the face's plane at p, by barycentric weights (rounded: only compared with a
        // tolerance).
        let w = [o[1], o[2], o[0]];
        let depth = (w[0] * t[0][2] + w[1] * t[1][2] + w[2] * t[2][2]) / (w[0] + w[1] + w[2]);
        if (depth - p[2]).abs() > tolerance {
            Some(depth > p[2])
        } else {
            None
        }
    } else {
        // Seen edge-on: near when p's depth is within the face's depth range.
        let lo = t[0][2].min(t[1][2]).min(t[2][2]);
        let hi = t[0][2].max(t[1][2]).max(t[2][2]);
        (p[2] < lo - tolerance || p[2] > hi + tolerance).then_some(false)
    };
    let ahead = near?;
    let s = [0, 1, 2].map(|k| left_of(o[k], t[k], t[(k + 1) % 3]));
    Some(if !ahead || s[0] != s[1] || s[1] != s[2] {
        0
    } else if s[0] {
        1
    } else {
        -1
    })
}

/// Whether `p + (ε, ε²)` lies left of the line `a → b`, given `o = orient2d(a, b, p)` (exact;
/// see the [module docs](self)).
fn left_of(o: f64, a: [f64; 3], b: [f64; 3]) -> bool {
    if o != 0.0 {
        o > 0.0
    } else if a[1] != b[1] {
        a[1] > b[1]
    } else {
        b[0] > a[0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A closed axis-aligned box from `lo` to `hi`, wound outward, appended to the mesh.
    fn add_box(p: &mut Vec<DVec3>, t: &mut Vec<[u32; 3]>, lo: DVec3, hi: DVec3) {
        let base = p.len() as u32;
        for i in 0..8 {
            let pick = |bit: u32, k: usize| if i >> bit & 1 == 1 { hi[k] } else { lo[k] };
            p.push(DVec3::new(pick(0, 0), pick(1, 1), pick(2, 2)));
        }
        for q in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            t.push([q[0], q[1], q[2]].map(|v| v + base));
            t.push([q[0], q[2], q[3]].map(|v| v + base));
        }
    }

    #[test]
    fn rays_through_edges_and_vertices_count_once() {
        let (mut p, mut t) = (Vec::new(), Vec::new());
        add_box(&mut p, &mut t, DVec3::ZERO, DVec3::splat(4.0));
        let face_shell = vec![0u32; t.len()];
        // Grid points, on the box's diagonals and on its faces' planes (outside).
        let queries: Vec<DVec3> = (0..6)
            .flat_map(|x| (0..6).flat_map(move |y| (0..6).map(move |z| (x, y, z))))
            .map(|(x, y, z)| DVec3::new(x as f64, y as f64, z as f64) - DVec3::ONE)
            .collect();
        let containers = vec![vec![0u32]; queries.len()];
        let pairs = Pairs {
            queries: &queries,
            containers: &containers,
            face_shell: &face_shell,
        };
        let r = inside_by_rays(&p, &t, &pairs, 4.0);
        for (q, r) in queries.iter().zip(&r) {
            let strictly_in = q.cmpgt(DVec3::ZERO).all() && q.cmplt(DVec3::splat(4.0)).all();
            let on = q.cmpge(DVec3::ZERO).all() && q.cmple(DVec3::splat(4.0)).all() && !strictly_in;
            if on {
                assert_eq!(r[0], None, "{q}: on the surface is ambiguous");
            } else {
                assert_eq!(r[0], Some(strictly_in), "{q}");
            }
        }
    }

    #[test]
    fn counts_are_signed_and_per_shell() {
        let (mut p, mut t) = (Vec::new(), Vec::new());
        add_box(&mut p, &mut t, DVec3::ZERO, DVec3::splat(10.0));
        add_box(&mut p, &mut t, DVec3::ONE, DVec3::splat(9.0));
        // The inner box turned inward: a cavity; its winding number inside is -1, still inside.
        for f in &mut t[12..] {
            f.swap(1, 2);
        }
        let face_shell: Vec<u32> = (0..t.len()).map(|f| (f / 12) as u32).collect();
        let queries = vec![DVec3::splat(5.0), DVec3::splat(0.5), DVec3::splat(20.0)];
        let containers = vec![vec![0, 1], vec![0, 1], vec![1]];
        let pairs = Pairs {
            queries: &queries,
            containers: &containers,
            face_shell: &face_shell,
        };
        let r = inside_by_rays(&p, &t, &pairs, 10.0);
        assert_eq!(
            r,
            vec![
                vec![Some(true), Some(true)],
                vec![Some(true), Some(false)],
                vec![Some(false)]
            ]
        );
    }

    #[test]
    fn perturbed_rays_through_projected_vertices_and_edges_count_once() {
        // An octahedron given in (u, v, depth): rays along depth through its tips and along its
        // edges' projections.
        let mut faces = Vec::new();
        for sx in [-1.0, 1.0] {
            for sy in [-1.0, 1.0] {
                for sz in [-1.0, 1.0] {
                    let (x, y, z) = ([sx, 0.0, 0.0], [0.0, sy, 0.0], [0.0, 0.0, sz]);
                    faces.push(if sx * sy * sz > 0.0 {
                        [x, y, z]
                    } else {
                        [x, z, y]
                    });
                }
            }
        }
        let count = |p: [f64; 3]| -> Option<i64> {
            faces
                .iter()
                .map(|&t| crossing(t, p, 1e-12).map(i64::from))
                .sum()
        };
        for (p, inside) in [
            ([0.0, 0.0, -5.0], false),
            ([0.0, 0.0, 5.0], false),
            ([0.0, 0.0, 0.0], true),
            ([0.5, 0.0, -3.0], false),
            ([0.5, 0.0, 0.0], true),
            ([0.0, -0.25, 0.5], true),
            ([0.25, 0.25, -2.0], false),
            ([0.25, 0.25, 0.1], true),
        ] {
            let n = count(p).expect("off the surface");
            assert_eq!(n != 0, inside, "{p:?}: {n}");
            assert!(n.abs() <= 1, "{p:?}: {n}");
        }
        // On a face, an edge or a tip: ambiguous.
        for p in [[0.0, 0.0, 1.0], [0.5, 0.0, 0.5], [0.25, 0.25, 0.5]] {
            assert_eq!(count(p), None, "{p:?}");
        }
    }
}
