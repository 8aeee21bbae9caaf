//! Parametric tessellations of the sweep family ("discrétisation régulière", lecture notes 001):
//! profile loops placed at regular stations along the sweep ([`rings`](super::rings)), closed
//! into outward-wound manifolds. Circle profiles are sampled at `segments` points; rectangles and
//! polygons use their corners (their edges are straight, so only the stations approximate).
//!
//! Counts for a profile of `N` loop points with `h` holes, none on the revolution axis:
//! full revolution with `m` steps: `m·N` vertices, `2·m·N` triangles (a torus-like grid, both
//! seams welded); partial revolution, extrusion, open sweep with `m` stations: `m·N` vertices,
//! `2(m − 1)N + 2(N + 2h − 2)` triangles; closed sweep: `m·N`, `2·m·N`.

use super::error::SweepError;
use super::rings::{apply_flips, cap, count, flips, oriented, sweep_mesh};
use super::{Extrude, Loft, Revolve, Ruled, Sweep};
use crate::IndexedMesh;
use crate::curve::Curve3;
use crate::profile::Profile;
use glam::{DVec2, DVec3};

/// The profile's boundary loops (circles at `segments` points), oriented, with their sizes.
fn loops_of(profile: &Profile, segments: usize) -> (Vec<Vec<DVec2>>, Vec<usize>) {
    let loops = oriented(profile.outline(segments));
    let sizes = loops.iter().map(Vec::len).collect();
    (loops, sizes)
}

impl Revolve {
    /// The revolution's mesh with `steps` angular stations (`steps` distinct angles for a full
    /// turn, `steps` including both ends for a partial one; a faceted turn has its own stations,
    /// which replace `steps`). Profile corners on the axis become poles.
    pub fn tessellate(&self, segments: usize, steps: usize) -> Result<IndexedMesh, SweepError> {
        count("segments", segments, 3)?;
        let (steps, start) = match self.segments() {
            Some((n, start)) => (n as usize, start.to_radians()),
            None => (steps, 0.0),
        };
        count("steps", steps, if self.is_full() { 3 } else { 2 })?;
        let (loops, sizes) = loops_of(self.profile(), segments);
        let points: Vec<DVec2> = loops.iter().flatten().copied().collect();
        let full = self.is_full();
        let alpha = self.angle().to_radians();
        let angle = |s: usize| {
            if full {
                start + alpha * s as f64 / steps as f64
            } else {
                alpha * s as f64 / (steps - 1) as f64
            }
        };
        let tris = if full {
            Vec::new()
        } else {
            cap("profile", &loops)?
        };
        Ok(sweep_mesh(
            &sizes,
            steps,
            full,
            |s, k| {
                let (sin, cos) = angle(s).sin_cos();
                let q = points[k];
                DVec3::new(q.x * cos, q.x * sin, q.y)
            },
            [&tris, &tris],
        ))
    }
}

impl Extrude {
    /// The extrusion's mesh with `levels + 1` stations over the height (twisted and scaled at
    /// each).
    pub fn tessellate(&self, segments: usize, levels: usize) -> Result<IndexedMesh, SweepError> {
        count("segments", segments, 3)?;
        count("levels", levels, 1)?;
        let (loops, sizes) = loops_of(self.profile(), segments);
        let points: Vec<DVec2> = loops.iter().flatten().copied().collect();
        let tris = cap("profile", &loops)?;
        let h = self.height();
        Ok(sweep_mesh(
            &sizes,
            levels + 1,
            false,
            |s, k| {
                let z = -0.5 * h + h * s as f64 / levels as f64;
                let (scale, theta) = self.slice_transform(z);
                let q = DVec2::from_angle(theta).rotate(points[k] * scale);
                DVec3::new(q.x, q.y, z)
            },
            [&tris, &tris],
        ))
    }
}

impl Sweep {
    /// The sweep's mesh with `stations` profile placements at regular parameters along the path
    /// (distinct ones around a closed path, both ends included on an open one).
    pub fn tessellate(&self, segments: usize, stations: usize) -> Result<IndexedMesh, SweepError> {
        count("segments", segments, 3)?;
        let closed = self.is_closed();
        count("stations", stations, if closed { 3 } else { 2 })?;
        let (loops, sizes) = loops_of(self.profile(), segments);
        let points: Vec<DVec2> = loops.iter().flatten().copied().collect();
        let (t0, t1) = self.path().domain();
        let param = |s: usize| {
            let n = if closed { stations } else { stations - 1 };
            t0 + (t1 - t0) * s as f64 / n as f64
        };
        // One frame per station, shared by its points.
        let frames: Vec<(DVec3, [DVec3; 3])> = (0..stations)
            .map(|s| (self.path().point(param(s)), self.frame(param(s))))
            .collect();
        let tris = if closed {
            Vec::new()
        } else {
            cap("profile", &loops)?
        };
        Ok(sweep_mesh(
            &sizes,
            stations,
            closed,
            |s, k| {
                let (c, [_, u, v]) = frames[s];
                c + u * points[k].x + v * points[k].y
            },
            [&tris, &tris],
        ))
    }
}

impl Loft {
    /// The loft's mesh: the two end profiles' loops joined by straight rulings (exact for
    /// polygons; circles sampled at `segments` points at the same angles at both ends).
    pub fn tessellate(&self, segments: usize) -> Result<IndexedMesh, SweepError> {
        count("segments", segments, 3)?;
        let outline = |p: &Profile| match p {
            Profile::Circle(c) => vec![
                (0..segments)
                    .map(|i| {
                        let a = std::f64::consts::TAU * i as f64 / segments as f64;
                        c.center + DVec2::new(a.cos(), a.sin()) * c.radius
                    })
                    .collect(),
            ],
            _ => p.outline(segments),
        };
        let (bottom, top) = (outline(self.bottom()), outline(self.top()));
        // Orient both ends alike (from the end that is not a point).
        let reference = if self.bottom().area_centroid().0 > 0.0 {
            &bottom
        } else {
            &top
        };
        let f = flips(reference);
        let (bottom, top) = (apply_flips(bottom, &f), apply_flips(top, &f));
        let sizes: Vec<usize> = bottom.iter().map(Vec::len).collect();
        let tri = |key, loops: &Vec<Vec<DVec2>>| -> Result<Vec<[u32; 3]>, SweepError> {
            let first = loops[0][0];
            if loops.iter().flatten().all(|q| *q == first) {
                Ok(Vec::new())
            } else {
                cap(key, loops)
            }
        };
        let caps = [tri("bottom", &bottom)?, tri("top", &top)?];
        let h2 = 0.5 * self.height();
        let ends = [bottom.concat(), top.concat()];
        Ok(sweep_mesh(
            &sizes,
            2,
            false,
            |s, k| ends[s][k].extend(if s == 0 { -h2 } else { h2 }),
            [&caps[0], &caps[1]],
        ))
    }
}

impl Ruled {
    /// The ruled solid's mesh: both curves sampled at `samples` regular parameters, joined by
    /// the rulings, closed by the triangulated end regions (an end that is a point becomes an
    /// apex).
    pub fn tessellate(&self, samples: usize) -> Result<IndexedMesh, SweepError> {
        count("samples", samples, 3)?;
        let counter_clockwise = self.slice_area(0.0) >= 0.0;
        let u = |k: usize| {
            let k = if counter_clockwise { k } else { samples - k };
            (k % samples) as f64 / samples as f64
        };
        let ends: [Vec<DVec3>; 2] =
            [0.0, 1.0].map(|v| (0..samples).map(|k| self.surface_point(u(k), v)).collect());
        let flat =
            |e: &Vec<DVec3>| vec![e.iter().map(|p| DVec2::new(p.x, p.y)).collect::<Vec<_>>()];
        let tri = |key, e: &Vec<DVec3>| -> Result<Vec<[u32; 3]>, SweepError> {
            if e.iter().all(|p| *p == e[0]) {
                Ok(Vec::new())
            } else {
                cap(key, &flat(e))
            }
        };
        let caps = [tri("bottom", &ends[0])?, tri("top", &ends[1])?];
        Ok(sweep_mesh(
            &[samples],
            2,
            false,
            |s, k| ends[s][k],
            [&caps[0], &caps[1]],
        ))
    }
}
