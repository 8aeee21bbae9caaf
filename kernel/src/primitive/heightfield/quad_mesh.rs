//! The polyhedron of a height field whose surface is flat triangles (samples with
//! [`Interpolation::Quads`], OpenSCAD's `surface()`): each cell four triangles around its centre
//! at the mean of its corners, walls straight down from the border to the base, and the base a
//! fan around its middle (OpenSCAD 2021.01's `surface.cc`). The solid is exactly this mesh.

use super::{HeightField, HeightSource, Interpolation};
use glam::DVec3;

/// Vertices and triangles (counter-clockwise seen from outside) of a closed polyhedron.
pub type QuadMesh = (Vec<DVec3>, Vec<[u32; 3]>);

impl HeightField {
    /// The solid as a closed polyhedron: `Some` for samples with [`Interpolation::Quads`] and
    /// every height above the base (the solid is then exactly this mesh), else `None`.
    pub fn quad_mesh(&self) -> Option<QuadMesh> {
        let HeightSource::Samples {
            grid,
            interpolation: Interpolation::Quads,
        } = &self.source
        else {
            return None;
        };
        let (nx, ny) = (grid.nx(), grid.ny());
        if grid.values().iter().any(|&h| h <= self.base) {
            return None;
        }
        let step = (self.max - self.min) / glam::DVec2::new(nx as f64 - 1.0, ny as f64 - 1.0);
        let at = |i: f64, j: f64, z: f64| {
            DVec3::new(self.min.x + i * step.x, self.min.y + j * step.y, z)
        };
        let mut v: Vec<DVec3> = Vec::with_capacity(2 * nx * ny + 2 * (nx + ny));
        for j in 0..ny {
            for i in 0..nx {
                v.push(at(i as f64, j as f64, grid.get(i, j)));
            }
        }
        let top = |i: usize, j: usize| (j * nx + i) as u32;
        let mut f: Vec<[u32; 3]> = Vec::with_capacity(4 * nx * ny + 6 * (nx + ny));
        for j in 1..ny {
            for i in 1..nx {
                let (a, b, d, e) = (top(i - 1, j - 1), top(i, j - 1), top(i, j), top(i - 1, j));
                let mean = (grid.get(i - 1, j - 1)
                    + grid.get(i, j - 1)
                    + grid.get(i - 1, j)
                    + grid.get(i, j))
                    / 4.0;
                let c = v.len() as u32;
                v.push(at(i as f64 - 0.5, j as f64 - 0.5, mean));
                f.extend([[c, a, b], [c, b, d], [c, d, e], [c, e, a]]);
            }
        }
        // The border, counter-clockwise seen from above (as (column, row)).
        let mut border: Vec<(usize, usize)> = (0..nx).map(|i| (i, 0)).collect();
        border.extend((1..ny).map(|j| (nx - 1, j)));
        border.extend((0..nx - 1).rev().map(|i| (i, ny - 1)));
        border.extend((1..ny - 1).rev().map(|j| (0, j)));
        let base = v.len() as u32;
        v.extend(
            border
                .iter()
                .map(|&(i, j)| at(i as f64, j as f64, self.base)),
        );
        let middle = v.len() as u32;
        v.push(at(
            (nx as f64 - 1.0) / 2.0,
            (ny as f64 - 1.0) / 2.0,
            self.base,
        ));
        let n = border.len();
        for k in 0..n {
            let (p, q) = (border[k], border[(k + 1) % n]);
            let (tp, tq) = (top(p.0, p.1), top(q.0, q.1));
            let (bp, bq) = (base + k as u32, base + ((k + 1) % n) as u32);
            f.extend([[bp, bq, tq], [bp, tq, tp], [middle, bq, bp]]);
        }
        Some((v, f))
    }
}
