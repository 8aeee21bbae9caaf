//! Rendering a field directly: interval-culled ray casting, no mesh.
//!
//! The image is cut into tiles of `TILE × TILE` pixels. For each tile, the depth range of the
//! camera is split front to back (an explicit stack, halves pushed far half first) and the prism
//! of the tile's rays over each depth segment is classified by the program's interval evaluation
//! ([`Program::prune_for_box`]): outside segments are dropped, an inside segment ends the tile's
//! list, surface segments are split until `SEGMENT` pixels deep and kept with their pruned
//! program. The pixels not yet hit then walk the tile's segments in order: every ray is sampled
//! every half pixel of depth with the segment's pruned program (single-precision batches, as the
//! mesher samples), and the first sign change is placed by linear interpolation (a quarter pixel at
//! worst, enough for shading); the normal is the program's double-precision gradient there, shaded by [`lambert`].
//!
//! A feature thinner than half a pixel along the ray can fall between two samples; pixels are
//! independent, so the image does not depend on the thread count.

use super::Image;
use super::camera::Camera;
use super::shade::{self, lambert, unit_or};
use glam::DVec3;
use rayon::prelude::*;
use solidkit_kernel::program::{BatchScratch, IntervalScratch, Pruned};
use solidkit_kernel::{Aabb, Program};
use std::sync::Arc;

/// Tile side in pixels.
const TILE: u32 = 8;
/// Depth of the segments pixels sample, in pixels.
const SEGMENT: f64 = 4.0;
/// Samples per pixel of depth.
const SAMPLES_PER_PIXEL: f64 = 1.0;

/// Where the rays of a tile may meet the surface.
enum Segment {
    /// The solid's surface may cross `t0..t1`; the program valid there.
    Surface(f64, f64, usize),
    /// Every ray is inside from `t0` on.
    Inside(f64),
}

/// Per-thread buffers.
#[derive(Default)]
struct Scratch {
    interval: IntervalScratch,
    gradients: Vec<(f64, DVec3)>,
    batch: BatchScratch,
    xs: Vec<f32>,
    ys: Vec<f32>,
    zs: Vec<f32>,
    batch_out: Vec<f32>,
}

/// The field of `program` as seen by `cam`, shaded in `base` over the background.
pub fn render_field(program: &Program, cam: &Camera, base: [u8; 3]) -> Image {
    let (w, h) = (cam.size.width, cam.size.height);
    let (tiles_x, tiles_y) = (w.div_ceil(TILE), h.div_ceil(TILE));
    let root = Arc::new(program.clone());
    let tiles: Vec<Vec<[u8; 3]>> = (0..tiles_x * tiles_y)
        .into_par_iter()
        .map_init(Scratch::default, |s, i| {
            render_tile(&root, cam, i % tiles_x, i / tiles_x, base, s)
        })
        .collect();
    let mut image = Image {
        width: w,
        height: h,
        pixels: vec![shade::BACKGROUND; w as usize * h as usize],
    };
    for (i, tile) in tiles.iter().enumerate() {
        let (x0, y0) = ((i as u32 % tiles_x) * TILE, (i as u32 / tiles_x) * TILE);
        let tw = TILE.min(w - x0);
        for (k, &c) in tile.iter().enumerate() {
            let (x, y) = (x0 + k as u32 % tw, y0 + k as u32 / tw);
            image.pixels[y as usize * w as usize + x as usize] = c;
        }
    }
    image
}

/// The pixels of one tile, row by row.
fn render_tile(
    root: &Arc<Program>,
    cam: &Camera,
    tx: u32,
    ty: u32,
    base: [u8; 3],
    s: &mut Scratch,
) -> Vec<[u8; 3]> {
    let (x0, y0) = (tx * TILE, ty * TILE);
    let (x1, y1) = (
        (x0 + TILE).min(cam.size.width),
        (y0 + TILE).min(cam.size.height),
    );
    let mut programs = vec![root.clone()];
    let segments = tile_segments(cam, [x0, y0, x1, y1], &mut programs, s);
    let tw = x1 - x0;
    let mut out = vec![shade::BACKGROUND; (tw * (y1 - y0)) as usize];
    if segments.is_empty() {
        return out;
    }
    let origins: Vec<DVec3> = (0..out.len() as u32)
        .map(|k| cam.origin(f64::from(x0 + k % tw) + 0.5, f64::from(y0 + k / tw) + 0.5))
        .collect();
    let mut active: Vec<usize> = (0..out.len()).collect();
    let light = cam.light();
    for seg in &segments {
        match *seg {
            Segment::Inside(t0) => {
                for &k in &active {
                    let n = normal(root, origins[k] + cam.dir * t0, cam, s);
                    out[k] = lambert(n, light, base);
                }
                active.clear();
            }
            Segment::Surface(t0, t1, p) => {
                let program = &programs[p];
                let n = ((t1 - t0) / cam.pixel * SAMPLES_PER_PIXEL).ceil().max(1.0) as usize;
                let t = |k: usize| t0 + (t1 - t0) * k as f64 / n as f64;
                sample(program, cam, &origins, &active, n, &t, s);
                let mut still = Vec::with_capacity(active.len());
                for (j, &k) in active.iter().enumerate() {
                    let values = &s.batch_out[j * (n + 1)..(j + 1) * (n + 1)];
                    match values.iter().position(|&v| v <= 0.0) {
                        None => still.push(k),
                        Some(i) => {
                            let at = |t: f64| origins[k] + cam.dir * t;
                            let hit = if i == 0 {
                                t0
                            } else {
                                secant(t(i - 1), t(i), values[i - 1], values[i])
                            };
                            out[k] = lambert(normal(program, at(hit), cam, s), light, base);
                        }
                    }
                }
                active = still;
            }
        }
        if active.is_empty() {
            break;
        }
    }
    out
}

/// Evaluates `program` (single precision, in batches) at samples `t(0..=n)` of the rays of the
/// pixels `active`, into `s.batch_out` (pixel by pixel).
fn sample(
    program: &Program,
    cam: &Camera,
    origins: &[DVec3],
    active: &[usize],
    n: usize,
    t: &impl Fn(usize) -> f64,
    s: &mut Scratch,
) {
    let count = active.len() * (n + 1);
    for v in [&mut s.xs, &mut s.ys, &mut s.zs] {
        v.clear();
    }
    for &k in active {
        for i in 0..=n {
            let p = origins[k] + cam.dir * t(i);
            s.xs.push(p.x as f32);
            s.ys.push(p.y as f32);
            s.zs.push(p.z as f32);
        }
    }
    s.batch_out.clear();
    s.batch_out.resize(count, 0.0);
    program.eval_many(&s.xs, &s.ys, &s.zs, &mut s.batch_out, &mut s.batch);
}

/// The tile's segments, front to back (see the module docs).
fn tile_segments(
    cam: &Camera,
    [x0, y0, x1, y1]: [u32; 4],
    programs: &mut Vec<Arc<Program>>,
    s: &mut Scratch,
) -> Vec<Segment> {
    let corners = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)]
        .map(|(x, y)| cam.origin(f64::from(x), f64::from(y)));
    let prism = |t0: f64, t1: f64| {
        let mut b = Aabb::empty();
        for c in corners {
            for t in [t0, t1] {
                let p = c + cam.dir * t;
                b = Aabb::new(b.min.min(p), b.max.max(p));
            }
        }
        b
    };
    let max_len = SEGMENT * cam.pixel;
    let mut out = Vec::new();
    let mut stack = vec![(0.0, cam.depth_range(), 0usize)];
    while let Some((t0, t1, p)) = stack.pop() {
        match programs[p].prune_for_box(&prism(t0, t1), &mut s.interval) {
            Pruned::Outside => {}
            Pruned::Inside => {
                out.push(Segment::Inside(t0));
                break;
            }
            Pruned::Surface(pruned) => {
                let p = match pruned {
                    Some(q) => {
                        programs.push(Arc::new(q));
                        programs.len() - 1
                    }
                    None => p,
                };
                if t1 - t0 <= max_len {
                    out.push(Segment::Surface(t0, t1, p));
                } else {
                    let mid = 0.5 * (t0 + t1);
                    stack.push((mid, t1, p));
                    stack.push((t0, mid, p));
                }
            }
        }
    }
    out
}

/// Where the line through `(lo, a)` and `(hi, b)` crosses zero (`a > 0 ≥ b`), within
/// `lo..=hi`.
fn secant(lo: f64, hi: f64, a: f32, b: f32) -> f64 {
    let (a, b) = (f64::from(a), f64::from(b));
    let w = a / (a - b);
    if w.is_finite() {
        lo + (hi - lo) * w.clamp(0.0, 1.0)
    } else {
        hi
    }
}

/// The surface normal at `p` (the field's gradient), facing the viewer when it has no direction.
fn normal(program: &Program, p: DVec3, cam: &Camera, s: &mut Scratch) -> DVec3 {
    let (_, g) = program.value_gradient_with(p, &mut s.gradients);
    unit_or(g, -cam.dir)
}
