//! OpenSCAD's partial `rotate_extrude` as OpenSCAD builds it: the profile turned in straight
//! steps. A turn of `angle` degrees (less than a full turn) takes `max(1, fragments · angle / 360)`
//! steps, truncated, with the fragments of a circle of the profile's largest distance from the
//! axis, starting on the +x axis; consecutive copies of the profile are joined by flat
//! trapezoids (each circle a corner travels is a regular polygon's arc) and the two ends are
//! capped by the profile. A full turn is the kernel's faceted revolution (`Revolve::faceted`).
//! Counted in OpenSCAD 2021.01's renders: 90° at 30 fragments is 7 steps, 100° at `$fn = 7`
//! one step, 200° at 30 fragments 16.

use super::facets::{cos_degrees, sin_degrees};
use super::sliced::oriented;
use glam::{DVec2, DVec3};
use solidkit_kernel::profile::triangulate;

/// The most vertices (steps + 1 times the profile's corners) a stepped turn may have.
pub(super) const MAX_TURN_CORNERS: usize = 2_000_000;

/// OpenSCAD's step count for a partial turn of `angle` degrees with `fragments` for a full one.
pub(super) fn step_count(fragments: usize, angle: f64) -> usize {
    ((fragments as f64 * angle.abs() / 360.0).max(1.0)) as usize
}

/// A closed mesh (vertices; faces counter-clockwise from outside) of the even-odd region of
/// `loops` (at x ≥ 0, y up) turned counter-clockwise about z by `angle` degrees in `steps`
/// straight steps from the +x axis; corners on the axis are one vertex. `None` where the
/// profile cannot be triangulated or the mesh would be larger than [`MAX_TURN_CORNERS`].
pub(super) fn stepped_turn(
    loops: &[Vec<DVec2>],
    angle: f64,
    steps: usize,
) -> Option<(Vec<DVec3>, Vec<Vec<u32>>)> {
    // Outlines counter-clockwise, holes clockwise, so that every side face points out.
    let loops: Vec<Vec<DVec2>> = oriented(loops).into_iter().map(|(l, _)| l).collect();
    let cap = triangulate(&loops).ok()?;
    let corners: Vec<DVec2> = loops.iter().flatten().copied().collect();
    let n = corners.len();
    if steps == 0 || n.checked_mul(steps + 1)? > MAX_TURN_CORNERS {
        return None;
    }
    // Vertex of corner c at step j: corners on the axis once, the others once per step.
    let mut vertices = Vec::new();
    let mut index = vec![vec![0u32; n]; steps + 1];
    for (c, p) in corners.iter().enumerate() {
        if p.x <= 0.0 {
            let k = vertices.len() as u32;
            vertices.push(DVec3::new(0.0, 0.0, p.y));
            index.iter_mut().for_each(|row| row[c] = k);
        }
    }
    for (j, row) in index.iter_mut().enumerate() {
        let (sin, cos) = sin_cos_degrees(angle * j as f64 / steps as f64);
        for (c, p) in corners.iter().enumerate() {
            if p.x > 0.0 {
                row[c] = vertices.len() as u32;
                vertices.push(DVec3::new(p.x * cos, p.x * sin, p.y));
            }
        }
    }
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for t in &cap {
        faces.push(t.iter().map(|&c| index[0][c as usize]).collect());
        faces.push(t.iter().rev().map(|&c| index[steps][c as usize]).collect());
    }
    let mut start = 0;
    for l in &loops {
        for i in 0..l.len() {
            let (a, b) = (start + i, start + (i + 1) % l.len());
            for j in 0..steps {
                let quad = [index[j][a], index[j + 1][a], index[j + 1][b], index[j][b]];
                faces.extend(side_face(quad));
            }
        }
        start += l.len();
    }
    Some((vertices, faces))
}

/// `(sin, cos)` of `degrees`, exact at multiples of 90° as in OpenSCAD's turns (so a half
/// turn's end cap lies exactly in the plane y = 0, flush with its neighbours').
fn sin_cos_degrees(degrees: f64) -> (f64, f64) {
    (sin_degrees(degrees), cos_degrees(degrees))
}

/// The face between two copies of a profile edge: the quad, with corners on the axis (one
/// vertex for every copy) merged; `None` when fewer than 3 corners are left.
fn side_face(quad: [u32; 4]) -> Option<Vec<u32>> {
    let mut face: Vec<u32> = Vec::with_capacity(4);
    for v in quad {
        if face.last() != Some(&v) && face.first() != Some(&v) {
            face.push(v);
        }
    }
    (face.len() >= 3).then_some(face)
}

/// A closed mesh of the even-odd region of `loops` (at x ≥ 0, y up) turned a full turn about z
/// in `steps` straight steps, the first copy at `start` degrees from +x (OpenSCAD's faceted
/// full `rotate_extrude`, whose first stop is on the -x axis); corners on the axis are one
/// vertex. `None` for fewer than 3 steps, a profile off the triangulator or a mesh larger than
/// [`MAX_TURN_CORNERS`].
pub(super) fn full_turn(
    loops: &[Vec<DVec2>],
    steps: usize,
    start: f64,
) -> Option<(Vec<DVec3>, Vec<Vec<u32>>)> {
    let loops: Vec<Vec<DVec2>> = oriented(loops).into_iter().map(|(l, _)| l).collect();
    triangulate(&loops).ok()?;
    let corners: Vec<DVec2> = loops.iter().flatten().copied().collect();
    let n = corners.len();
    if steps < 3 || n.checked_mul(steps)? > MAX_TURN_CORNERS {
        return None;
    }
    let mut vertices = Vec::new();
    let mut index = vec![vec![0u32; n]; steps];
    for (c, p) in corners.iter().enumerate() {
        if p.x <= 0.0 {
            let k = vertices.len() as u32;
            vertices.push(DVec3::new(0.0, 0.0, p.y));
            index.iter_mut().for_each(|row| row[c] = k);
        }
    }
    for (j, row) in index.iter_mut().enumerate() {
        let (sin, cos) = sin_cos_degrees(start + 360.0 * j as f64 / steps as f64);
        for (c, p) in corners.iter().enumerate() {
            if p.x > 0.0 {
                row[c] = vertices.len() as u32;
                vertices.push(DVec3::new(p.x * cos, p.x * sin, p.y));
            }
        }
    }
    let mut faces: Vec<Vec<u32>> = Vec::new();
    let mut first = 0;
    for l in &loops {
        for i in 0..l.len() {
            let (a, b) = (first + i, first + (i + 1) % l.len());
            for j in 0..steps {
                let k = (j + 1) % steps;
                let quad = [index[j][a], index[k][a], index[k][b], index[j][b]];
                faces.extend(side_face(quad));
            }
        }
        first += l.len();
    }
    Some((vertices, faces))
}

#[cfg(test)]
mod tests {
    use super::*;
    use solidkit_kernel::polyhedra::Polyhedron;

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<DVec2> {
        [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            .map(|(x, y)| DVec2::new(x, y))
            .to_vec()
    }

    #[test]
    fn step_counts_follow_openscad() {
        assert_eq!(step_count(30, 90.0), 7);
        assert_eq!(step_count(7, 100.0), 1);
        assert_eq!(step_count(30, -200.0), 16);
        assert_eq!(step_count(30, 10.0), 1);
    }

    #[test]
    fn a_stepped_turn_is_closed_with_the_volume_of_its_trapezoid_prisms() {
        // A square [10, 15] x [0, 5] turned 90 degrees in 7 steps: each step is the prism of a
        // ring sector's polygon: (15² − 10²)/2 · sin(δ) · 5 per step.
        let (v, f) = stepped_turn(&[rect(10.0, 0.0, 15.0, 5.0)], 90.0, 7).unwrap();
        let p = Polyhedron::new(v, f).unwrap();
        let delta = 90f64.to_radians() / 7.0;
        let exact = 7.0 * (225.0 - 100.0) / 2.0 * delta.sin() * 5.0;
        assert!((p.volume() - exact).abs() < 1e-9 * exact, "{}", p.volume());
        // A profile touching the axis: a stepped wedge of a cylinder, corners on the axis shared.
        let (v, f) = stepped_turn(&[rect(0.0, 0.0, 2.0, 1.0)], 120.0, 4).unwrap();
        assert_eq!(v.len(), 2 + 2 * 5);
        let p = Polyhedron::new(v, f).unwrap();
        let exact = 4.0 * 4.0 / 2.0 * (30f64.to_radians()).sin();
        assert!((p.volume() - exact).abs() < 1e-9, "{}", p.volume());
    }
}
