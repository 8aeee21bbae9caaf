//! Mesh rasterisation with a z-buffer: every pixel keeps the nearest triangle, on equal depth the
//! lowest index (a total order, so the result does not depend on the thread count or the order
//! triangles are drawn in). One thread draws all triangles in one pass; several bin them into
//! bands of rows, one task per band. Pixel centres are tested with edge functions, both windings
//! accepted; flat shading by the face normal. Triangles come from an indexed mesh or straight
//! from the records of a binary STL ([`Triangles`]).

use super::Image;
use super::camera::Camera;
use super::gbuffer::{GBuffer, to_f32};
use super::shade::unit_or;
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
    let (xmin, xmax) = (a[0].min(b[0]).min(c[0]), a[0].max(b[0]).max(c[0]));
    let (ymin, ymax) = (a[1].min(b[1]).min(c[1]), a[1].max(b[1]).max(c[1]));
    let x0 = ceil(xmin - 0.5).max(0.0);
    let x1 = floor(xmax - 0.5).min(f64::from(width) - 1.0);
    let y0 = ceil(ymin - 0.5).max(rows.start as f64);
    let y1 = floor(ymax - 0.5).min(rows.end as f64 - 1.0);
    if x0 > x1 || y0 > y1 {
        return;
    }
    let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if area == 0.0 || !area.is_finite() {
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

/// Triangles to rasterise: an indexed mesh, or the records of a binary STL read straight from
/// its bytes (no welding: a renderer does not need shared vertices).
pub trait Triangles: Sync {
    /// How many triangles.
    fn triangle_count(&self) -> usize;
    /// The corners of triangle `t`; `None` when an index is out of range.
    fn triangle(&self, t: usize) -> Option<[DVec3; 3]>;
}

impl Triangles for IndexedMesh {
    fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    fn triangle(&self, t: usize) -> Option<[DVec3; 3]> {
        let [a, b, c] = self.triangles[t].map(|i| self.positions.get(i as usize).copied());
        Some([a?, b?, c?])
    }
}

/// The triangle records of a binary STL (see [`crate::io::stl_binary_records`]).
#[derive(Debug, Clone, Copy)]
pub struct StlRecords<'a>(pub &'a [u8]);

impl Triangles for StlRecords<'_> {
    fn triangle_count(&self) -> usize {
        self.0.len() / 50
    }

    fn triangle(&self, t: usize) -> Option<[DVec3; 3]> {
        let r: &[u8; 36] = self.0.get(t * 50 + 12..t * 50 + 48)?.try_into().ok()?;
        let f = |k: usize| {
            f64::from(f32::from_le_bytes([
                r[4 * k],
                r[4 * k + 1],
                r[4 * k + 2],
                r[4 * k + 3],
            ]))
        };
        Some([
            DVec3::new(f(0), f(1), f(2)),
            DVec3::new(f(3), f(4), f(5)),
            DVec3::new(f(6), f(7), f(8)),
        ])
    }
}

/// The box of the finite corners of `mesh`'s triangles (empty when there are none) and whether
/// every corner was finite.
pub fn triangles_box(mesh: &impl Triangles) -> (solidkit_kernel::Aabb, bool) {
    let empty = || (DVec3::INFINITY, DVec3::NEG_INFINITY, true);
    let (lo, hi, all) = (0..mesh.triangle_count())
        .into_par_iter()
        .fold(empty, |(mut lo, mut hi, mut all), t| {
            if let Some([a, b, c]) = mesh.triangle(t) {
                if a.is_finite() && b.is_finite() && c.is_finite() {
                    lo = lo.min(a.min(b).min(c));
                    hi = hi.max(a.max(b).max(c));
                } else {
                    for p in [a, b, c] {
                        if p.is_finite() {
                            lo = lo.min(p);
                            hi = hi.max(p);
                        }
                    }
                    all = false;
                }
            }
            (lo, hi, all)
        })
        .reduce(empty, |(a, b, x), (c, d, y)| (a.min(c), b.max(d), x && y));
    let b = if lo.cmple(hi).all() {
        solidkit_kernel::Aabb::new(lo, hi)
    } else {
        solidkit_kernel::Aabb::empty()
    };
    (b, all)
}

/// `v.floor()` without a library call (the default x86-64 target has no rounding instruction):
/// exact for every finite `v`; values beyond ±2⁵² are integers already.
#[inline]
fn floor(v: f64) -> f64 {
    if v.abs() < 4_503_599_627_370_496.0 {
        let i = v as i64 as f64;
        if i > v { i - 1.0 } else { i }
    } else {
        v
    }
}

/// `v.ceil()`, as [`floor`].
#[inline]
fn ceil(v: f64) -> f64 {
    -floor(-v)
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

/// Triangle `t` of `mesh` in image coordinates.
#[inline]
fn projected(mesh: &impl Triangles, cam: &Projector, t: usize) -> Option<[[f64; 3]; 3]> {
    let [a, b, c] = mesh.triangle(t)?;
    Some([cam.project(a), cam.project(b), cam.project(c)])
}

/// [`Camera::project`] as one affine map (rows for x, y and depth), for the per-triangle loop.
struct Projector {
    rows: [DVec3; 3],
    offsets: [f64; 3],
}

impl Projector {
    fn new(cam: &Camera) -> Self {
        let origin = cam.project(DVec3::ZERO);
        let rows = [cam.right / cam.pixel, -cam.up / cam.pixel, cam.dir];
        Self {
            rows,
            offsets: origin,
        }
    }

    #[inline]
    fn project(&self, p: DVec3) -> [f64; 3] {
        let [r0, r1, r2] = &self.rows;
        [
            r0.dot(p) + self.offsets[0],
            r1.dot(p) + self.offsets[1],
            r2.dot(p) + self.offsets[2],
        ]
    }
}

/// Keeps triangle `t` at depth `z` in slot `i` when it is nearer, or as near with a lower index
/// (a total order, so the result does not depend on the order triangles come in).
#[inline]
fn keep(depth: &mut [f32], face: &mut [u32], i: usize, z: f32, t: u32) {
    if z < depth[i] || (z == depth[i] && t < face[i]) {
        depth[i] = z;
        face[i] = t;
    }
}

/// The z-buffer of `mesh` seen by `cam`.
///
/// On one thread the triangles are drawn in one pass; on several, they are binned into bands of
/// rows first and each band is drawn by one task. Both keep, per pixel, the nearest triangle and
/// on equal depth the lowest index, so the buffers are identical.
pub fn rasterize(mesh: &impl Triangles, cam: &Camera) -> ZBuffer {
    let (w, h) = (cam.size.width as usize, cam.size.height as usize);
    let mut depth = vec![f32::INFINITY; w * h];
    let mut face = vec![NO_FACE; w * h];
    let count = mesh.triangle_count().min(NO_FACE as usize);
    let cam = &Projector::new(cam);
    if rayon::current_num_threads() == 1 {
        for t in 0..count {
            if let Some(p) = projected(mesh, cam, t) {
                scan_triangle(p, 0..h as i64, w as u32, |x, y, z| {
                    keep(
                        &mut depth,
                        &mut face,
                        y as usize * w + x as usize,
                        z as f32,
                        t as u32,
                    );
                });
            }
        }
        return ZBuffer { depth, face };
    }
    let bands = h.div_ceil(BAND);
    let bins: Vec<Vec<u32>> = (0..count)
        .into_par_iter()
        .fold(
            || vec![Vec::new(); bands],
            |mut bins: Vec<Vec<u32>>, t| {
                if let Some(p) = projected(mesh, cam, t) {
                    let ymin = p[0][1].min(p[1][1]).min(p[2][1]);
                    let ymax = p[0][1].max(p[1][1]).max(p[2][1]);
                    if ymin.is_finite() && ymax.is_finite() && ymax >= 0.0 && ymin <= h as f64 {
                        let first = (ymin.max(0.0) as usize / BAND).min(bands - 1);
                        let last = (ymax.min(h as f64) as usize / BAND).min(bands - 1);
                        for bin in &mut bins[first..=last] {
                            bin.push(t as u32);
                        }
                    }
                }
                bins
            },
        )
        .reduce(
            || vec![Vec::new(); bands],
            |mut a, b| {
                for (x, y) in a.iter_mut().zip(b) {
                    x.extend(y);
                }
                a
            },
        );
    depth
        .par_chunks_mut(BAND * w)
        .zip(face.par_chunks_mut(BAND * w))
        .enumerate()
        .for_each(|(band, (d, f))| {
            let top = band * BAND;
            let rows = top as i64..(top + d.len() / w) as i64;
            for &t in &bins[band] {
                if let Some(p) = projected(mesh, cam, t as usize) {
                    scan_triangle(p, rows.clone(), w as u32, |x, y, z| {
                        keep(d, f, (y as usize - top) * w + x as usize, z as f32, t);
                    });
                }
            }
        });
    ZBuffer { depth, face }
}

/// The unit normal of triangle `t` (towards the viewer's side does not matter: shading is
/// two-sided).
pub fn face_normal(mesh: &impl Triangles, t: u32, fallback: DVec3) -> DVec3 {
    match mesh.triangle(t as usize) {
        Some([a, b, c]) => unit_or((b - a).cross(c - a), fallback),
        None => fallback,
    }
}

/// The surface of `mesh` as seen by `cam`: depth and face normal per pixel.
pub fn trace_mesh(mesh: &impl Triangles, cam: &Camera) -> GBuffer {
    let z = rasterize(mesh, cam);
    let normal = z
        .face
        .par_iter()
        .map(|&t| {
            if t == NO_FACE {
                [0.0; 3]
            } else {
                to_f32(face_normal(mesh, t, -cam.dir))
            }
        })
        .collect();
    GBuffer {
        size: cam.size,
        depth: z.depth,
        normal,
    }
}

/// The mesh flat-shaded in `base` over the background.
pub fn render_mesh(mesh: &impl Triangles, cam: &Camera, base: [u8; 3]) -> Image {
    trace_mesh(mesh, cam).shade(cam, base)
}

#[cfg(test)]
mod tests {
    use super::{StlRecords, Triangles, ceil, floor, scan_triangle, triangles_box};
    use glam::DVec3;

    #[test]
    fn floor_and_ceil_match_the_library() {
        let mut values = vec![
            0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.5e15, -2.5e15, 1e300, -1e300,
        ];
        for k in -2000..2000 {
            let v = f64::from(k) * 0.37 + 0.001;
            values.extend([v, -v, v.trunc(), f64::from(k) + 0.5]);
        }
        values.extend([
            4_503_599_627_370_495.5,
            -4_503_599_627_370_495.5,
            9.1e15 + 1.0,
        ]);
        for v in values {
            assert_eq!(floor(v), v.floor(), "floor {v}");
            assert_eq!(ceil(v), v.ceil(), "ceil {v}");
        }
    }

    #[test]
    fn stl_records_give_the_corners_in_order() {
        let corners = [[1.0f32, 2.0, 3.0], [-4.0, 5.5, 6.0], [7.0, -8.0, 0.25]];
        let mut record = vec![0u8; 12];
        for c in corners {
            for x in c {
                record.extend(x.to_le_bytes());
            }
        }
        record.extend([0, 0]);
        let mut bytes = record.clone();
        bytes.extend(&record);
        let stl = StlRecords(&bytes);
        assert_eq!(stl.triangle_count(), 2);
        let t = stl.triangle(1).expect("second triangle");
        assert_eq!(t[1], DVec3::new(-4.0, 5.5, 6.0));
        assert!(stl.triangle(2).is_none());
        let (b, finite) = triangles_box(&stl);
        assert!(finite);
        assert_eq!(
            (b.min, b.max),
            (DVec3::new(-4.0, -8.0, 0.25), DVec3::new(7.0, 5.5, 6.0))
        );
    }

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
