//! Triangulation of a profile's region for the caps of tessellated sweeps: loops are nested by
//! containment (a loop inside an even number of others is an outline, inside an odd number a
//! hole of the innermost outline around it), each hole is joined to its outline by a bridge to a
//! visible corner (the rightmost hole first, as in Eberly's "Triangulation by ear clipping"),
//! and the joined polygon is cut into triangles by ear clipping. Only the given corners are used
//! (no new vertices): `n` corners and `h` holes give `n + 2h − 2` triangles per outline.

use super::error::ProfileError;
use super::polygon::{inside_loop, signed_area2};
use glam::DVec2;

/// Triangles (counter-clockwise, as indices into the corners of all loops in order) covering the
/// even-odd region of `loops`.
pub fn triangulate(loops: &[Vec<DVec2>]) -> Result<Vec<[u32; 3]>, ProfileError> {
    let mut offsets = Vec::with_capacity(loops.len());
    let mut total = 0;
    for l in loops {
        offsets.push(total);
        total += l.len();
    }
    let points: Vec<DVec2> = loops.iter().flatten().copied().collect();
    // Nesting depth of each loop and the innermost loop around it.
    let depth: Vec<usize> = (0..loops.len())
        .map(|r| {
            (0..loops.len())
                .filter(|&o| o != r && inside_loop(loops[r][0], &loops[o]))
                .count()
        })
        .collect();
    let parent = |r: usize| {
        (0..loops.len())
            .find(|&o| o != r && depth[o] + 1 == depth[r] && inside_loop(loops[r][0], &loops[o]))
    };
    let indices = |r: usize, ccw: bool| -> Vec<usize> {
        let mut v: Vec<usize> = (offsets[r]..offsets[r] + loops[r].len()).collect();
        if (signed_area2(&loops[r]) > 0.0) != ccw {
            v.reverse();
        }
        v
    };
    let mut triangles = Vec::new();
    for outer in (0..loops.len()).filter(|&r| depth[r].is_multiple_of(2)) {
        let mut polygon = indices(outer, true);
        let mut holes: Vec<Vec<usize>> = (0..loops.len())
            .filter(|&h| !depth[h].is_multiple_of(2) && parent(h) == Some(outer))
            .map(|h| indices(h, false))
            .collect();
        // Rightmost holes first, so earlier bridges never block later ones.
        holes.sort_by(|a, b| rightmost(&points, b).1.total_cmp(&rightmost(&points, a).1));
        for hole in &holes {
            polygon = bridge(&points, polygon, hole)?;
        }
        clip_ears(&points, polygon, &mut triangles)?;
    }
    Ok(triangles)
}

/// Position in `ring` of its corner with the largest x, and that x.
fn rightmost(points: &[DVec2], ring: &[usize]) -> (usize, f64) {
    ring.iter()
        .enumerate()
        .map(|(k, &i)| (k, points[i].x))
        .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a })
}

fn cross(o: DVec2, a: DVec2, b: DVec2) -> f64 {
    (a - o).perp_dot(b - o)
}

/// Whether `p` is inside or on the counter-clockwise triangle `abc`.
fn in_triangle(p: DVec2, a: DVec2, b: DVec2, c: DVec2) -> bool {
    cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0
}

/// Joins `hole` (clockwise) into `polygon` (counter-clockwise) by a two-way bridge from the
/// hole's rightmost corner to a visible polygon corner.
fn bridge(
    points: &[DVec2],
    polygon: Vec<usize>,
    hole: &[usize],
) -> Result<Vec<usize>, ProfileError> {
    let (k, _) = rightmost(points, hole);
    let m = points[hole[k]];
    // Nearest edge crossed by the ray from m towards +x.
    let n = polygon.len();
    let mut hit: Option<(f64, usize)> = None;
    for i in 0..n {
        let (a, b) = (points[polygon[i]], points[polygon[(i + 1) % n]]);
        if a.y == b.y {
            continue;
        }
        let x = a.x + (m.y - a.y) * (b.x - a.x) / (b.y - a.y);
        let lo = a.y.min(b.y);
        let hi = a.y.max(b.y);
        if m.y < lo || m.y > hi || x < m.x {
            continue;
        }
        if hit.is_none_or(|(best, _)| x < best) {
            hit = Some((x, i));
        }
    }
    let (x, edge) = hit.ok_or(ProfileError::Triangulation)?;
    let hit_point = DVec2::new(x, m.y);
    let (a, b) = (polygon[edge], polygon[(edge + 1) % n]);
    let mut visible = if points[a].x > points[b].x {
        edge
    } else {
        (edge + 1) % n
    };
    // A reflex corner inside the triangle (m, hit, candidate) blocks the view: take the one
    // closest in angle to the ray instead.
    let candidate = points[polygon[visible]];
    let (t0, t1, t2) = if cross(m, hit_point, candidate) >= 0.0 {
        (m, hit_point, candidate)
    } else {
        (m, candidate, hit_point)
    };
    let mut best_angle = f64::INFINITY;
    for i in 0..n {
        let p = points[polygon[i]];
        let (prev, next) = (
            points[polygon[(i + n - 1) % n]],
            points[polygon[(i + 1) % n]],
        );
        let reflex = cross(prev, p, next) <= 0.0;
        if i == visible || !reflex || p == candidate || !in_triangle(p, t0, t1, t2) {
            continue;
        }
        let d = p - m;
        let angle = d.y.abs().atan2(d.x);
        if angle < best_angle
            || (angle == best_angle && d.length() < (points[polygon[visible]] - m).length())
        {
            best_angle = angle;
            visible = i;
        }
    }
    let mut out = Vec::with_capacity(n + hole.len() + 2);
    out.extend_from_slice(&polygon[..=visible]);
    out.extend((0..=hole.len()).map(|j| hole[(k + j) % hole.len()]));
    out.extend_from_slice(&polygon[visible..]);
    Ok(out)
}

/// Cuts the counter-clockwise (weakly simple) polygon into triangles.
fn clip_ears(
    points: &[DVec2],
    mut polygon: Vec<usize>,
    out: &mut Vec<[u32; 3]>,
) -> Result<(), ProfileError> {
    while polygon.len() > 3 {
        let n = polygon.len();
        let ear = (0..n).find(|&i| {
            let (ia, ib, ic) = (polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]);
            let (a, b, c) = (points[ia], points[ib], points[ic]);
            if cross(a, b, c) <= 0.0 {
                return false;
            }
            polygon.iter().all(|&j| {
                j == ia
                    || j == ib
                    || j == ic
                    || points[j] == a
                    || points[j] == b
                    || points[j] == c
                    || !in_triangle(points[j], a, b, c)
            })
        });
        let i = ear.ok_or(ProfileError::Triangulation)?;
        out.push([
            polygon[(i + n - 1) % n] as u32,
            polygon[i] as u32,
            polygon[(i + 1) % n] as u32,
        ]);
        polygon.remove(i);
    }
    if let [a, b, c] = polygon[..] {
        if cross(points[a], points[b], points[c]) > 0.0 {
            out.push([a as u32, b as u32, c as u32]);
        } else if cross(points[a], points[b], points[c]) < 0.0 {
            return Err(ProfileError::Triangulation);
        }
    }
    Ok(())
}
