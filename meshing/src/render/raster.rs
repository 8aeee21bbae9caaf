//! Mesh rasterisation with a z-buffer: triangles projected once, binned into bands of rows, each
//! band filled by one task in ascending triangle order (on equal depth the lower index stays), so
//! the result does not depend on the thread count. Pixel centres are tested with edge functions,
//! both windings accepted; flat shading by the face normal.

use super::camera::Camera;
use super::shade::{lambert, unit_or};
use super::{Image, shade};
use crate::IndexedMesh;
use glam::DVec3;
use rayon::prelude::*;
use std::ops::Range;

/// Rows per band.
const BAND: usize = 16;

/// No triangle covers the pixel.
pub const NO_FACE: u32 = u32::MAX;

/// The nearest triangle and its depth at every pixel.
#[derive(Debug, Clone)]
pub struct ZBuffer {
    /// Depth from the near plane (`f32::INFINITY` where empty).
    pub depth: Vec<f32>,
    /// Triangle index, or [`NO_FACE`].
    pub face: Vec<u32>,
}

/// Calls `f(x, y, depth)` for every pixel of rows `rows` (and columns `0..width`) whose centre
/// lies in the projected triangle `p` (pixel coordinates and depth); edges count as inside.
pub fn scan_triangle(
    p: [[f64; 3]; 3],
    rows: Range<i64>,
    width: u32,
    mut f: impl FnMut(u32, u32, f64),
) {
    let [a, b, c] = p;
    if !p.iter().flatten().all(|v| v.is_finite()) {
        return;
    }
    let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let (xmin, xmax) = (a[0].min(b[0]).min(c[0]), a[0].max(b[0]).max(c[0]));
    let (ymin, ymax) = (a[1].min(b[1]).min(c[1]), a[1].max(b[1]).max(c[1]));
    let x0 = (xmin - 0.5).ceil().max(0.0);
    let x1 = (xmax - 0.5).floor().min(f64::from(width) - 1.0);
    let y0 = (ymin - 0.5).ceil().max(rows.start as f64);
    let y1 = (ymax - 0.5).floor().min(rows.end as f64 - 1.0);
    if x0 > x1 || y0 > y1 {
        return;
    }
    let edge = |p: [f64; 3], q: [f64; 3], x: f64, y: f64| {
        (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0])
    };
    for y in y0 as i64..=y1 as i64 {
        let py = y as f64 + 0.5;
        for x in x0 as i64..=x1 as i64 {
            let px = x as f64 + 0.5;
            let l0 = edge(b, c, px, py) / area;
            let l1 = edge(c, a, px, py) / area;
            let l2 = edge(a, b, px, py) / area;
            if l0 >= 0.0 && l1 >= 0.0 && l2 >= 0.0 {
                f(x as u32, y as u32, l0 * a[2] + l1 * b[2] + l2 * c[2]);
            }
        }
    }
}

/// The mesh's vertices in image coordinates (pixels right, pixels down, depth).
pub fn project(mesh: &IndexedMesh, cam: &Camera) -> Vec<[f64; 3]> {
    mesh.positions.par_iter().map(|&p| cam.project(p)).collect()
}

/// The corners of triangle `t` in image coordinates, `None` when an index is out of range.
pub fn corners(mesh: &IndexedMesh, projected: &[[f64; 3]], t: usize) -> Option<[[f64; 3]; 3]> {
    let [a, b, c] = mesh.triangles[t].map(|i| projected.get(i as usize).copied());
    Some([a?, b?, c?])
}

/// The z-buffer of `mesh` seen by `cam`.
pub fn rasterize(mesh: &IndexedMesh, cam: &Camera) -> ZBuffer {
    let (w, h) = (cam.size.width as usize, cam.size.height as usize);
    let projected = project(mesh, cam);
    let bands = h.div_ceil(BAND);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); bands];
    for t in 0..mesh.triangles.len() {
        let Some(p) = corners(mesh, &projected, t) else {
            continue;
        };
        let ymin = p[0][1].min(p[1][1]).min(p[2][1]);
        let ymax = p[0][1].max(p[1][1]).max(p[2][1]);
        if !(ymin.is_finite() && ymax.is_finite()) || ymax < 0.0 || ymin > h as f64 {
            continue;
        }
        let first = (ymin.max(0.0) as usize / BAND).min(bands - 1);
        let last = (ymax.min(h as f64) as usize / BAND).min(bands - 1);
        for bin in &mut bins[first..=last] {
            bin.push(t as u32);
        }
    }
    let mut depth = vec![f32::INFINITY; w * h];
    let mut face = vec![NO_FACE; w * h];
    depth
        .par_chunks_mut(BAND * w)
        .zip(face.par_chunks_mut(BAND * w))
        .enumerate()
        .for_each(|(band, (d, f))| {
            let top = band * BAND;
            let rows = top as i64..(top + d.len() / w) as i64;
            for &t in &bins[band] {
                let Some(p) = corners(mesh, &projected, t as usize) else {
                    continue;
                };
                scan_triangle(p, rows.clone(), w as u32, |x, y, z| {
                    let i = (y as usize - top) * w + x as usize;
                    let z = z as f32;
                    if z < d[i] {
                        d[i] = z;
                        f[i] = t;
                    }
                });
            }
        });
    ZBuffer { depth, face }
}

/// The unit normal of triangle `t` (towards the viewer's side does not matter: shading is
/// two-sided).
pub fn face_normal(mesh: &IndexedMesh, t: u32, fallback: DVec3) -> DVec3 {
    let [a, b, c] = mesh.triangles[t as usize].map(|i| mesh.positions[i as usize]);
    unit_or((b - a).cross(c - a), fallback)
}

/// The mesh flat-shaded in `base` over the background.
pub fn render_mesh(mesh: &IndexedMesh, cam: &Camera, base: [u8; 3]) -> Image {
    let z = rasterize(mesh, cam);
    let light = cam.light();
    let pixels = z
        .face
        .par_iter()
        .map(|&t| {
            if t == NO_FACE {
                shade::BACKGROUND
            } else {
                lambert(face_normal(mesh, t, -cam.dir), light, base)
            }
        })
        .collect();
    Image {
        width: cam.size.width,
        height: cam.size.height,
        pixels,
    }
}

#[cfg(test)]
mod tests {
    use super::scan_triangle;

    #[test]
    fn shared_edge_leaves_no_gap_and_both_windings_fill() {
        let mut count = vec![0u32; 100];
        let quad = [
            [1.0, 1.0, 0.0],
            [9.0, 1.0, 0.0],
            [9.0, 9.0, 0.0],
            [1.0, 9.0, 0.0],
        ];
        for t in [[0, 1, 2], [0, 3, 2]] {
            scan_triangle(t.map(|i| quad[i]), 0..10, 10, |x, y, _| {
                count[(y * 10 + x) as usize] += 1
            });
        }
        let covered = count.iter().filter(|&&c| c > 0).count();
        assert_eq!(covered, 64);
    }
}
