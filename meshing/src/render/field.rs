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
//! worst, enough for shading); the normal is the program's double-precision gradient there, shaded by `lambert`.
//!
//! A feature thinner than half a pixel along the ray can fall between two samples; pixels are
//! independent, so the image does not depend on the thread count.

use super::Image;
use super::camera::Camera;
use super::gbuffer::{GBuffer, to_f32};
use super::shade::unit_or;
use glam::DVec3;
use rayon::prelude::*;
use solidkit_kernel::program::{BatchScratch, GradientScratch, IntervalScratch, Pruned};
use solidkit_kernel::{Aabb, Program};
use std::sync::Arc;

/// Tile side in pixels.
const TILE: u32 = 8;
/// Tiles per side of a group, whose depth segments are found first and shared by its tiles.
const GROUP: u32 = 4;
/// Depth of the segments pixels sample, in pixels.
const SEGMENT: f64 = 4.0;
/// Depth of a group's segments, in pixels (its tiles split them further).
const GROUP_SEGMENT: f64 = 16.0;

/// Where the rays of a tile may meet the surface.
#[derive(Debug, Clone, Copy)]
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
    gradients: GradientScratch,
    points: Vec<DVec3>,
    values: Vec<f64>,
    normals: Vec<DVec3>,
    batch: BatchScratch,
    xs: Vec<f32>,
    ys: Vec<f32>,
    zs: Vec<f32>,
    batch_out: Vec<f32>,
}

/// One tile's hits: depth and normal per pixel, row by row.
type TileHits = Vec<(f32, [f32; 3])>;

/// The field of `program` as seen by `cam`, shaded in `base` over the background.
pub fn render_field(program: &Program, cam: &Camera, base: [u8; 3]) -> Image {
    trace_field(program, cam).shade(cam, base)
}

/// The surface of `program` as seen by `cam`: depth and normal per pixel.
pub fn trace_field(program: &Program, cam: &Camera) -> GBuffer {
    let (w, h) = (cam.size.width, cam.size.height);
    let span = TILE * GROUP;
    let (groups_x, groups_y) = (w.div_ceil(span), h.div_ceil(span));
    let root = Arc::new(program.clone());
    let groups: Vec<Vec<(u32, u32, TileHits)>> = (0..groups_x * groups_y)
        .into_par_iter()
        .map_init(Scratch::default, |s, g| {
            render_group(&root, cam, g % groups_x, g / groups_x, s)
        })
        .collect();
    let mut out = GBuffer::empty(cam.size);
    for (x0, y0, tile) in groups.into_iter().flatten() {
        let tw = TILE.min(w - x0);
        for (k, (d, n)) in tile.into_iter().enumerate() {
            let (x, y) = (x0 + k as u32 % tw, y0 + k as u32 / tw);
            let i = y as usize * w as usize + x as usize;
            out.depth[i] = d;
            out.normal[i] = n;
        }
    }
    out
}

/// The tiles of group `(gx, gy)`: its depth segments first, then each tile from those.
fn render_group(
    root: &Arc<Program>,
    cam: &Camera,
    gx: u32,
    gy: u32,
    s: &mut Scratch,
) -> Vec<(u32, u32, TileHits)> {
    let (w, h) = (cam.size.width, cam.size.height);
    let span = TILE * GROUP;
    let (x0, y0) = (gx * span, gy * span);
    let rect = [x0, y0, (x0 + span).min(w), (y0 + span).min(h)];
    let mut programs = vec![root.clone()];
    let start = [Segment::Surface(0.0, cam.depth_range(), 0)];
    let group = segments(cam, rect, &start, GROUP_SEGMENT, &mut programs, s);
    let mut out = Vec::new();
    for ty in (y0..rect[3]).step_by(TILE as usize) {
        for tx in (x0..rect[2]).step_by(TILE as usize) {
            let tile = [tx, ty, (tx + TILE).min(w), (ty + TILE).min(h)];
            let hits = render_tile(root, cam, tile, &group, &mut programs, s);
            out.push((tx, ty, hits));
        }
    }
    out
}

/// The hits of one tile, row by row, from the segments of its group.
fn render_tile(
    root: &Arc<Program>,
    cam: &Camera,
    rect: [u32; 4],
    group: &[Segment],
    programs: &mut Vec<Arc<Program>>,
    s: &mut Scratch,
) -> TileHits {
    let [x0, y0, x1, y1] = rect;
    let tw = x1 - x0;
    let mut out = vec![(f32::INFINITY, [0.0; 3]); (tw * (y1 - y0)) as usize];
    if group.is_empty() {
        return out;
    }
    let segments = segments(cam, rect, group, SEGMENT, programs, s);
    if segments.is_empty() {
        return out;
    }
    let origins: Vec<DVec3> = (0..out.len() as u32)
        .map(|k| cam.origin(f64::from(x0 + k % tw) + 0.5, f64::from(y0 + k / tw) + 0.5))
        .collect();
    let mut active: Vec<usize> = (0..out.len()).collect();
    for seg in &segments {
        match *seg {
            Segment::Inside(t0) => {
                let hits: Vec<(usize, f64, f64)> = active.iter().map(|&k| (k, t0, t0)).collect();
                shade_hits(root, cam, &origins, &hits, &mut out, s);
                active.clear();
            }
            Segment::Surface(t0, t1, p) => {
                let program = &programs[p];
                let n = ((t1 - t0) / cam.pixel).ceil().max(1.0) as usize;
                let t = |k: usize| t0 + (t1 - t0) * k as f64 / n as f64;
                sample(program, cam, &origins, &active, n, &t, s);
                let mut still = Vec::with_capacity(active.len());
                let mut hits = Vec::new();
                for (j, &k) in active.iter().enumerate() {
                    let values = &s.batch_out[j * (n + 1)..(j + 1) * (n + 1)];
                    match values.iter().position(|&v| v <= 0.0) {
                        None => still.push(k),
                        Some(i) => {
                            let hit = if i == 0 {
                                t0
                            } else {
                                secant(t(i - 1), t(i), values[i - 1], values[i])
                            };
                            // The normal half a pixel before the hit: outside, where a
                            // distance field's gradient points to the nearest surface point
                            // (inside, near an edge, it may take the other face's).
                            let back = (hit - 0.5 * cam.pixel).max(t0.min(hit));
                            hits.push((k, hit, back));
                        }
                    }
                }
                shade_hits(program, cam, &origins, &hits, &mut out, s);
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
        v.resize(count, 0.0);
    }
    let steps: Vec<DVec3> = (0..=n).map(|i| cam.dir * t(i)).collect();
    let rows =
        s.xs.chunks_exact_mut(n + 1)
            .zip(s.ys.chunks_exact_mut(n + 1))
            .zip(s.zs.chunks_exact_mut(n + 1));
    for (&k, ((xs, ys), zs)) in active.iter().zip(rows) {
        let o = origins[k];
        for (i, step) in steps.iter().enumerate() {
            let p = o + *step;
            xs[i] = p.x as f32;
            ys[i] = p.y as f32;
            zs[i] = p.z as f32;
        }
    }
    s.batch_out.clear();
    s.batch_out.resize(count, 0.0);
    program.eval_many(&s.xs, &s.ys, &s.zs, &mut s.batch_out, &mut s.batch);
}

/// The segments of the rays through `rect` (pixel corners), front to back, refined from
/// `start` (front to back) until at most `max_pixels` deep (see the module docs).
fn segments(
    cam: &Camera,
    [x0, y0, x1, y1]: [u32; 4],
    start: &[Segment],
    max_pixels: f64,
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
    let max_len = max_pixels * cam.pixel;
    let mut out = Vec::new();
    // Popped front first: the start segments are pushed back to front.
    let mut stack: Vec<Segment> = start.iter().rev().copied().collect();
    while let Some(seg) = stack.pop() {
        let (t0, t1, p) = match seg {
            Segment::Inside(_) => {
                out.push(seg);
                break;
            }
            Segment::Surface(t0, t1, p) => (t0, t1, p),
        };
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
                    stack.push(Segment::Surface(mid, t1, p));
                    stack.push(Segment::Surface(t0, mid, p));
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

/// Stores the hits `(pixel, depth, depth of the normal)` of one segment: the normals are the
/// gradients of `program` (double precision, one batch), facing the viewer where they have no
/// direction.
fn shade_hits(
    program: &Program,
    cam: &Camera,
    origins: &[DVec3],
    hits: &[(usize, f64, f64)],
    out: &mut TileHits,
    s: &mut Scratch,
) {
    if hits.is_empty() {
        return;
    }
    s.points.clear();
    s.points
        .extend(hits.iter().map(|&(k, _, at)| origins[k] + cam.dir * at));
    s.values.clear();
    s.values.resize(hits.len(), 0.0);
    s.normals.clear();
    s.normals.resize(hits.len(), DVec3::ZERO);
    program.values_gradients(&s.points, &mut s.values, &mut s.normals, &mut s.gradients);
    for (&(k, hit, _), &g) in hits.iter().zip(&s.normals) {
        out[k] = (hit as f32, to_f32(unit_or(g, -cam.dir)));
    }
}
