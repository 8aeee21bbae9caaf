//! OpenSCAD's leniency with `polyhedron` faces. OpenSCAD renders polyhedra whose faces repeat a
//! point (two indices of one position, or one index twice in a row), collapse to a line, or are
//! quads too twisted to lie in a plane; scripts that generate points (a pole of a sphere, a ring
//! shrunk to a point) write such faces all the time. Before the kernel sees the faces:
//!
//! - points at bit-identical positions become one point (the first index), so the faces around
//!   a repeated pole share its edges;
//! - corners repeating the previous corner (cyclically) are removed; a face left with fewer than
//!   three corners is dropped: it encloses nothing, and its edges, each used once in each
//!   direction, cancel out;
//! - a face that the kernel's triangulation refuses (zero area, edges crossing in its plane, a
//!   fold) becomes the fan of triangles from its first corner, as OpenSCAD splits it: its edges
//!   stay those of the face, so the mesh stays closed, and zero-area triangles enclose nothing.
//!
//! A polyhedron listed inside out as a whole (closed, every edge used once each way, negative
//! volume) is reversed: OpenSCAD renders it as the solid it bounds ([`inside_out`]).
//!
//! A face that still repeats a corner elsewhere, or indexes past the points, is left for the
//! kernel to refuse with its usual error.

use glam::DVec3;
use solidkit_kernel::triangulate::{TriangulationError, triangulate_polygon};
use std::collections::HashMap;

/// What [`clean_faces`] changed.
#[derive(Debug, Default, PartialEq, Eq)]
pub(super) struct Cleaned {
    /// Faces dropped for having fewer than three distinct corners.
    pub dropped: usize,
    /// Faces split into the fan from their first corner.
    pub fanned: usize,
    /// Points merged into an earlier point at the same position.
    pub merged: usize,
}

impl Cleaned {
    /// One line for the warning, or `None` when nothing changed.
    pub(super) fn message(&self) -> Option<String> {
        let mut parts = Vec::new();
        if self.merged > 0 {
            parts.push(format!(
                "{} repeated points merged into their first occurrence",
                self.merged
            ));
        }
        if self.dropped > 0 {
            parts.push(format!(
                "{} faces with fewer than 3 distinct corners dropped",
                self.dropped
            ));
        }
        if self.fanned > 0 {
            parts.push(format!(
                "{} degenerate or non-planar faces split into triangle fans",
                self.fanned
            ));
        }
        (!parts.is_empty()).then(|| format!("polyhedron: {}, as OpenSCAD does", parts.join(", ")))
    }
}

/// Cleans `faces` (corner lists into `points`) as the module docs describe.
pub(super) fn clean_faces(points: &[DVec3], faces: Vec<Vec<u32>>) -> (Vec<Vec<u32>>, Cleaned) {
    let mut report = Cleaned::default();
    let mut first: HashMap<[u64; 3], u32> = HashMap::with_capacity(points.len());
    let canonical: Vec<u32> = points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            // -0.0 and 0.0 are one position.
            let key = p.to_array().map(|c| (c + 0.0).to_bits());
            let id = *first.entry(key).or_insert(i as u32);
            if id != i as u32 {
                report.merged += 1;
            }
            id
        })
        .collect();
    let mut out = Vec::with_capacity(faces.len());
    for face in faces {
        let mut f: Vec<u32> = face
            .iter()
            .map(|&i| canonical.get(i as usize).copied().unwrap_or(i))
            .collect();
        f.dedup();
        while f.len() > 1 && f.first() == f.last() {
            f.pop();
        }
        if f.len() < 3 {
            report.dropped += 1;
            continue;
        }
        if f.iter().any(|&i| i as usize >= points.len()) {
            out.push(face); // the kernel reports the index
            continue;
        }
        if f.len() == 3 {
            out.push(f); // the kernel takes any triangle as it is
            continue;
        }
        let corners: Vec<DVec3> = f.iter().map(|&i| points[i as usize]).collect();
        match triangulate_polygon(&corners) {
            Err(
                TriangulationError::Degenerate
                | TriangulationError::SelfIntersecting
                | TriangulationError::Folded,
            ) if distinct(&f) => {
                report.fanned += 1;
                out.extend((1..f.len() - 1).map(|k| vec![f[0], f[k], f[k + 1]]));
            }
            _ => out.push(f),
        }
    }
    (out, report)
}

/// Whether `faces` (counter-clockwise from outside, the kernel's order) close a surface whose
/// every edge is used once in each direction and that encloses a negative volume: a polyhedron
/// listed inside out as a whole. OpenSCAD renders such a polyhedron as the solid it bounds (its
/// `intersection-tests` cut an inside-out octahedron and keep the upper half), so the caller
/// reverses it.
pub(super) fn inside_out(points: &[DVec3], faces: &[Vec<u32>]) -> bool {
    let mut uses: HashMap<(u32, u32), i32> = HashMap::new();
    let mut six = 0.0;
    for f in faces {
        for k in 0..f.len() {
            let (a, b) = (f[k], f[(k + 1) % f.len()]);
            let (key, d) = if a < b { ((a, b), 1) } else { ((b, a), -1) };
            *uses.entry(key).or_default() += d;
        }
        six += fan_volume6(points, f).unwrap_or(0.0);
    }
    !faces.is_empty() && uses.values().all(|&d| d == 0) && six < 0.0
}

/// Six times the signed volume a face's fan (from its first corner) sweeps to the origin: summed
/// over a closed polyhedron's faces, six times its volume. `None` when an index has no point.
pub(super) fn fan_volume6(points: &[DVec3], f: &[u32]) -> Option<f64> {
    let p = f
        .iter()
        .map(|&k| points.get(k as usize).copied())
        .collect::<Option<Vec<DVec3>>>()?;
    Some(
        (1..p.len().saturating_sub(1))
            .map(|k| p[0].dot(p[k].cross(p[k + 1])))
            .sum(),
    )
}

/// Whether no index repeats in `f`.
fn distinct(f: &[u32]) -> bool {
    let mut sorted = f.to_vec();
    sorted.sort_unstable();
    sorted.windows(2).all(|w| w[0] != w[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> (Vec<DVec3>, Vec<Vec<u32>>) {
        let p = (0..8)
            .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64))
            .collect();
        let f = vec![
            vec![0, 2, 3, 1],
            vec![4, 5, 7, 6],
            vec![0, 1, 5, 4],
            vec![2, 6, 7, 3],
            vec![0, 4, 6, 2],
            vec![1, 3, 7, 5],
        ];
        (p, f)
    }

    #[test]
    fn clean_faces_pass_unchanged() {
        let (p, f) = cube();
        let (g, r) = clean_faces(&p, f.clone());
        assert_eq!(g, f);
        assert_eq!(r, Cleaned::default());
        assert_eq!(r.message(), None);
    }

    #[test]
    fn a_repeated_pole_is_merged_and_collapsed_faces_dropped_or_fanned() {
        let (mut p, mut f) = cube();
        // A second copy of corner 7 used by the top face, and a face that is a doubled edge.
        p.push(p[7]);
        f[1] = vec![4, 5, 8, 7, 6];
        f.push(vec![1, 2, 2, 1]);
        let (g, r) = clean_faces(&p, f);
        assert_eq!(r.merged, 1);
        assert_eq!(r.dropped, 1);
        assert_eq!(g[1], vec![4, 5, 7, 6]);
        assert_eq!(g.len(), 6);
        assert!(r.message().unwrap().contains("1 faces with fewer than 3"));
    }

    #[test]
    fn a_twisted_quad_becomes_a_fan_and_a_flat_one_too() {
        let p = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
        ];
        // A bow tie, then four collinear corners.
        let (g, r) = clean_faces(&p, vec![vec![0, 1, 2, 3], vec![0, 2, 4, 2]]);
        assert_eq!(r.fanned, 1);
        assert_eq!(g[..2], [vec![0, 1, 2], vec![0, 2, 3]]);
        // The second repeats corner 2 away from its neighbours: left for the kernel to refuse.
        assert_eq!(g[2], vec![0, 2, 4, 2]);
    }
}
