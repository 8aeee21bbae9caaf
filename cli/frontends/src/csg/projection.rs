//! `projection(cut)` as in OpenSCAD (the User Manual's `projection`): a 2D shape from 3D
//! children. `cut = true` is the slice of the children at z = 0 (closed: a face lying in the
//! plane is part of it); `cut = false` is the shadow, the union of the children projected onto
//! the plane.
//!
//! Both are sampled on a 2D grid ([`RESOLUTION`] cells along the longer side) and contoured by
//! marching squares ([`super::contour`]) with exact crossings: the slice samples the field at
//! z = 0 and places each crossing by bisection on it; the shadow meshes the children
//! ([`SHADOW_MESH_RESOLUTION`] cells), projects the triangles, marks the samples some triangle
//! covers and places each crossing where the union of the triangles along the grid edge ends.
//! The result is polygons (an outline with its holes per part), usable under extrusions like any
//! 2D child; corners are cut within a cell.

use super::contour::{Grid2, contour, region};
use super::convert::mesh_of;
use super::error::CsgError;
use super::flat::Flat;
use super::parser::Stmt;
use glam::DVec2;
use solidkit_kernel::Solid;

/// Cells of the 2D sampling grid along the longer side of the children's box.
pub const RESOLUTION: usize = 512;
/// Cells along the longest side of the grid on which the shadow's children are meshed.
pub const SHADOW_MESH_RESOLUTION: usize = 192;
/// Loops are simplified within this fraction of a cell.
const SIMPLIFY_CELLS: f64 = 0.05;
/// Bisection steps placing a slice crossing (the cell over 2³⁰).
const BISECTIONS: usize = 30;

/// The slice of `solid` at z = 0, or `None` when it is empty.
pub fn cut(stmt: &Stmt, solid: &Solid) -> Result<Option<Flat>, CsgError> {
    solid.validate().map_err(|e| stmt.error(e.to_string()))?;
    let b = solid.bbox();
    if b.is_empty() || b.min.z > 0.0 || b.max.z < 0.0 {
        return Ok(None);
    }
    if !(b.min.is_finite() && b.max.is_finite()) {
        return Err(stmt.error("the children are unbounded"));
    }
    let grid = Grid2::covering(b.min.truncate(), b.max.truncate(), RESOLUTION);
    let program = solid.compile();
    // Within f32 noise of zero counts as on the surface, hence inside (the slice is closed).
    let noise = 1e-6 * (b.max - b.min).max_element();
    let mut x = Vec::with_capacity(grid.samples());
    let mut y = Vec::with_capacity(grid.samples());
    for j in 0..=grid.ny {
        for i in 0..=grid.nx {
            let p = grid.point(i, j);
            x.push(p.x as f32);
            y.push(p.y as f32);
        }
    }
    let z = vec![0.0f32; x.len()];
    let mut values = vec![0.0f32; x.len()];
    let mut scratch = Default::default();
    program.eval_many(&x, &y, &z, &mut values, &mut scratch);
    let inside: Vec<bool> = values.iter().map(|&v| f64::from(v) <= noise).collect();
    let mut point_scratch = Default::default();
    let mut is_in = |p: DVec2| program.value_with(p.extend(0.0), &mut point_scratch) <= noise;
    let loops = contour(&grid, &inside, SIMPLIFY_CELLS * grid.cell, |a, b| {
        // Keep `a` inside and `b` outside (by the f64 field; the f32 samples may disagree).
        let (mut a, mut b) = (a, b);
        if !is_in(a) {
            return a;
        }
        if is_in(b) {
            return b;
        }
        for _ in 0..BISECTIONS {
            let m = (a + b) / 2.0;
            if is_in(m) {
                a = m;
            } else {
                b = m;
            }
        }
        (a + b) / 2.0
    });
    Ok(region(loops))
}

/// Triangles projected to the plane (counter-clockwise), bucketed by the cells of a grid.
struct Shadow {
    triangles: Vec<[DVec2; 3]>,
    grid: Grid2,
    /// Triangle indices per cell (`j * nx + i`), in one array with offsets.
    start: Vec<usize>,
    items: Vec<u32>,
}

/// `cross(b - a, p - a)`.
fn orient(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    (b - a).perp_dot(p - a)
}

impl Shadow {
    fn new(triangles: Vec<[DVec2; 3]>, grid: Grid2) -> Shadow {
        let cells = grid.nx * grid.ny;
        let range = |t: &[DVec2; 3]| {
            let lo = t[0].min(t[1]).min(t[2]);
            let hi = t[0].max(t[1]).max(t[2]);
            let c = |v: f64, n: usize| (v.floor().max(0.0) as usize).min(n - 1);
            let a = (lo - grid.origin) / grid.cell;
            let b = (hi - grid.origin) / grid.cell;
            (
                c(a.x - 1e-9, grid.nx),
                c(b.x + 1e-9, grid.nx),
                c(a.y - 1e-9, grid.ny),
                c(b.y + 1e-9, grid.ny),
            )
        };
        let mut count = vec![0usize; cells + 1];
        for t in &triangles {
            let (i0, i1, j0, j1) = range(t);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    count[j * grid.nx + i + 1] += 1;
                }
            }
        }
        for k in 0..cells {
            count[k + 1] += count[k];
        }
        let mut fill = count.clone();
        let mut items = vec![0u32; count[cells]];
        for (n, t) in triangles.iter().enumerate() {
            let (i0, i1, j0, j1) = range(t);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    let c = j * grid.nx + i;
                    items[fill[c]] = n as u32;
                    fill[c] += 1;
                }
            }
        }
        Shadow {
            triangles,
            grid,
            start: count,
            items,
        }
    }

    /// The triangles registered in the cells `i0..=i1 × j0..=j1` (clamped to the grid).
    fn near(&self, i: [isize; 2], j: [isize; 2]) -> impl Iterator<Item = &[DVec2; 3]> {
        let clamp = |v: isize, n: usize| v.clamp(0, n as isize - 1) as usize;
        let (i0, i1) = (clamp(i[0], self.grid.nx), clamp(i[1], self.grid.nx));
        let (j0, j1) = (clamp(j[0], self.grid.ny), clamp(j[1], self.grid.ny));
        (j0..=j1).flat_map(move |j| {
            (i0..=i1).flat_map(move |i| {
                let c = j * self.grid.nx + i;
                self.items[self.start[c]..self.start[c + 1]]
                    .iter()
                    .map(|&n| &self.triangles[n as usize])
            })
        })
    }

    /// The cell coordinates of `p` (rounded down).
    fn cell_of(&self, p: DVec2) -> [isize; 2] {
        let q = ((p - self.grid.origin) / self.grid.cell).floor();
        [q.x as isize, q.y as isize]
    }

    /// Whether a triangle covers `p` (closed).
    fn covers(&self, p: DVec2) -> bool {
        let [i, j] = self.cell_of(p + DVec2::splat(0.5 * self.grid.cell));
        let eps = 1e-12 * self.grid.cell * self.grid.cell;
        self.near([i - 1, i], [j - 1, j]).any(|t| {
            orient(t[0], t[1], p) >= -eps
                && orient(t[1], t[2], p) >= -eps
                && orient(t[2], t[0], p) >= -eps
        })
    }

    /// Where the union of the triangles along the segment from the covered `a` to the uncovered
    /// `b` (one grid edge) ends.
    fn crossing(&self, a: DVec2, b: DVec2) -> DVec2 {
        let d = b - a;
        let [i, j] = self.cell_of((a + b) / 2.0);
        let mut spans: Vec<(f64, f64)> = self
            .near([i - 1, i + 1], [j - 1, j + 1])
            .filter_map(|t| {
                let (mut lo, mut hi) = (0.0f64, 1.0f64);
                for k in 0..3 {
                    let (u, v) = (t[k], t[(k + 1) % 3]);
                    // orient(u, v, a + s·d) = g0 + s·g1 ≥ 0.
                    let g0 = orient(u, v, a);
                    let g1 = (v - u).perp_dot(d);
                    if g1 == 0.0 {
                        if g0 < 0.0 {
                            return None;
                        }
                    } else if g1 > 0.0 {
                        lo = lo.max(-g0 / g1);
                    } else {
                        hi = hi.min(-g0 / g1);
                    }
                }
                (lo <= hi).then_some((lo, hi))
            })
            .collect();
        spans.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut end = 0.0f64;
        for (lo, hi) in spans {
            if lo > end + 1e-9 {
                break;
            }
            end = end.max(hi);
        }
        a + d * end.min(1.0)
    }
}

/// The shadow of `solid` on the plane z = 0 (the union of its projection), or `None` when
/// empty.
pub fn shadow(stmt: &Stmt, solid: &Solid) -> Result<Option<Flat>, CsgError> {
    let mesh = mesh_of(stmt, solid, SHADOW_MESH_RESOLUTION)?;
    let mut triangles = Vec::with_capacity(mesh.triangles.len());
    let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|k| mesh.positions[k as usize].truncate());
        let area = orient(a, b, c);
        if area == 0.0 {
            continue;
        }
        lo = lo.min(a).min(b).min(c);
        hi = hi.max(a).max(b).max(c);
        triangles.push(if area > 0.0 { [a, b, c] } else { [a, c, b] });
    }
    if triangles.is_empty() {
        return Ok(None);
    }
    let grid = Grid2::covering(lo, hi, RESOLUTION);
    let shadow = Shadow::new(triangles, grid);
    let mut inside = vec![false; grid.samples()];
    for j in 0..=grid.ny {
        for i in 0..=grid.nx {
            inside[grid.index(i, j)] = shadow.covers(grid.point(i, j));
        }
    }
    let loops = contour(&grid, &inside, SIMPLIFY_CELLS * grid.cell, |a, b| {
        shadow.crossing(a, b)
    });
    Ok(region(loops))
}

/// `projection(cut)` of the 3D `solid`.
pub fn projection(stmt: &Stmt, solid: &Solid) -> Result<Option<Flat>, CsgError> {
    if stmt.flag("cut", Some(0), false)? {
        cut(stmt, solid)
    } else {
        shadow(stmt, solid)
    }
}
