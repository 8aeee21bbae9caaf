//! `projection(cut)` as in OpenSCAD (the User Manual's `projection`): a 2D shape from 3D
//! children. `cut = true` is the slice of the children at z = 0 (closed: a face lying in the
//! plane is part of it); `cut = false` is the shadow, the union of the children projected onto
//! the plane.
//!
//! Both are sampled on a 2D grid ([`RESOLUTION`] cells along the longer side) and contoured by
//! marching squares ([`super::contour`]) with exact crossings: the slice samples the field at
//! z = 0 and places each crossing by bisection on it; the shadow ([`super::shadow`]) projects
//! triangles of the children.
//! The result is polygons (an outline with its holes per part), usable under extrusions like any
//! 2D child; corners are cut within a cell.

use super::contour::{Grid2, contour, region};
use super::error::CsgError;
use super::flat::Flat;
use super::parser::Stmt;
use super::projection_grid::{RESOLUTION, SIMPLIFY_CELLS};
use super::shadow::shadow;
use glam::DVec2;
use solidkit_kernel::eval::Pruned;
use solidkit_kernel::{Aabb, Program, Solid};

/// Bisection steps placing a slice crossing (the cell over 2³⁰).
const BISECTIONS: usize = 30;

/// Samples per side of the tiles classified by interval arithmetic before sampling.
const TILE: usize = 8;

/// Which samples of `grid` at z = 0 have a field value of at most `noise`: tiles that interval
/// arithmetic finds inside or outside are filled, the others sampled with their pruned program.
fn sample(grid: &Grid2, program: &Program, noise: f64) -> Vec<bool> {
    let mut inside = vec![false; grid.samples()];
    let mut interval = Default::default();
    let mut batch = Default::default();
    let (mut x, mut y, mut z, mut out) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for tj in (0..grid.ny).step_by(TILE) {
        for ti in (0..grid.nx).step_by(TILE) {
            let (i1, j1) = ((ti + TILE).min(grid.nx), (tj + TILE).min(grid.ny));
            let b = Aabb::new(
                grid.point(ti, tj).extend(0.0),
                grid.point(i1, j1).extend(0.0),
            );
            let pruned = match program.prune_for_box(&b, &mut interval) {
                Pruned::Outside => continue,
                Pruned::Inside => {
                    for j in tj..=j1 {
                        for i in ti..=i1 {
                            inside[grid.index(i, j)] = true;
                        }
                    }
                    continue;
                }
                Pruned::Surface(p) => p,
            };
            let e = pruned.as_ref().unwrap_or(program);
            x.clear();
            y.clear();
            for j in tj..=j1 {
                for i in ti..=i1 {
                    let p = grid.point(i, j);
                    x.push(p.x as f32);
                    y.push(p.y as f32);
                }
            }
            z.resize(x.len(), 0.0f32);
            out.resize(x.len(), 0.0f32);
            e.eval_many(&x, &y, &z, &mut out, &mut batch);
            let mut k = 0;
            for j in tj..=j1 {
                for i in ti..=i1 {
                    inside[grid.index(i, j)] = f64::from(out[k]) <= noise;
                    k += 1;
                }
            }
        }
    }
    inside
}

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
    let inside = sample(&grid, &program, noise);
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

/// `projection(cut)` of the 3D `solid`.
pub fn projection(stmt: &Stmt, solid: &Solid) -> Result<Option<Flat>, CsgError> {
    if stmt.flag("cut", Some(0), false)? {
        cut(stmt, solid)
    } else {
        shadow(stmt, solid)
    }
}
