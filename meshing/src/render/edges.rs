//! Feature edges found in the image, so fields and meshes get the same lines: silhouettes (a hit
//! next to a miss), creases (normals of neighbouring pixels more than [`CREASE_DEGREES`] apart)
//! and occlusion edges (a depth step between neighbours far larger than the surface's slope
//! explains). Each pixel is compared with its right and lower neighbours only, and the line is
//! drawn on the nearer pixel of a pair, so the result depends on the buffer alone.

use super::Image;
use super::camera::Camera;
use super::gbuffer::GBuffer;
use rayon::prelude::*;

/// Colour of feature edges.
pub const EDGE: [u8; 3] = [35, 35, 45];

/// Angle between the normals of neighbouring pixels above which they are on two sides of a
/// crease.
pub const CREASE_DEGREES: f64 = 40.0;

/// Depth step between neighbours, in pixels, beyond what the slope predicts, above which one
/// surface hides another.
const STEP_PIXELS: f64 = 3.0;

/// Draws the feature edges of `g` (seen by `cam`) over `image` (same size).
pub fn draw_edges(image: &mut Image, g: &GBuffer, cam: &Camera) {
    let (w, h) = (g.size.width as usize, g.size.height as usize);
    let cos_crease = CREASE_DEGREES.to_radians().cos();
    let mark: Vec<bool> = (0..w * h)
        .into_par_iter()
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let mut neighbours = [None; 4];
            if x + 1 < w {
                neighbours[0] = Some(i + 1);
            }
            if y + 1 < h {
                neighbours[1] = Some(i + w);
            }
            if x > 0 {
                neighbours[2] = Some(i - 1);
            }
            if y > 0 {
                neighbours[3] = Some(i - w);
            }
            neighbours
                .into_iter()
                .flatten()
                .any(|j| edge_between(g, cam, i, j, cos_crease) && nearer(g, i, j))
        })
        .collect();
    for (p, m) in image.pixels.iter_mut().zip(mark) {
        if m {
            *p = EDGE;
        }
    }
}

/// True when `i` is drawn for the pair `(i, j)`: the nearer one, on a tie the lower index.
fn nearer(g: &GBuffer, i: usize, j: usize) -> bool {
    let (a, b) = (g.depth[i], g.depth[j]);
    a < b || (a == b && i < j)
}

/// True when neighbouring pixels `i` and `j` lie on two sides of a feature edge.
fn edge_between(g: &GBuffer, cam: &Camera, i: usize, j: usize, cos_crease: f64) -> bool {
    match (g.hit(i), g.hit(j)) {
        (false, false) => false,
        (true, false) | (false, true) => true,
        (true, true) => {
            let (n, m) = (g.normal_at(i), g.normal_at(j));
            if n.dot(m).abs() < cos_crease {
                return true;
            }
            // The depth change one pixel along the image predicts from each normal.
            let along = if j.abs_diff(i) == 1 {
                cam.right
            } else {
                cam.up
            };
            let slope = |n: glam::DVec3| {
                let d = n.dot(cam.dir).abs().max(0.05);
                n.dot(along).abs() / d * cam.pixel
            };
            let step = f64::from((g.depth[i] - g.depth[j]).abs());
            step > slope(n).max(slope(m)) + STEP_PIXELS * cam.pixel
        }
    }
}
