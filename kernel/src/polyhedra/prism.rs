//! Prisms: a simple polygon with holes in the xy plane swept along a vector.
//!
//! The cross-section is triangulated by constrained Delaunay triangulation (never fans), which
//! also validates it. The bottom cap lies at `z = 0`, the top cap is the bottom moved by the
//! direction, and every loop edge gives one side quad. Without holes each cap is a single polygonal
//! face (so a prism over an n-gon has V = 2n, E = 3n, F = n + 2); with holes the caps are kept as
//! their triangles, because a face with a hole is not a disc and V − E + F would no longer measure
//! the genus (a prism with h holes has V − E + F = 2 − 2h).

use super::{Polyhedron, PolyhedronError};
use crate::triangulate::{signed_area2, triangulate_loops};
use glam::{DVec2, DVec3};

/// A prism's parameters, kept exactly as given (loops in either orientation).
#[derive(Debug, Clone, PartialEq)]
pub struct Prism {
    /// The outer boundary of the cross-section in the xy plane (either orientation).
    pub polygon: Vec<DVec2>,
    /// Holes inside the outer boundary (either orientation).
    pub holes: Vec<Vec<DVec2>>,
    /// The sweep vector; its z component must not be zero.
    pub direction: DVec3,
}

impl Prism {
    /// A prism from its cross-section and sweep vector (checked by [`Prism::to_polyhedron`]).
    pub fn new(polygon: Vec<DVec2>, holes: Vec<Vec<DVec2>>, direction: DVec3) -> Prism {
        Prism {
            polygon,
            holes,
            direction,
        }
    }

    /// Area of the cross-section (outer loop minus holes; valid prisms only).
    pub fn cross_section_area(&self) -> f64 {
        let holes: f64 = self.holes.iter().map(|h| signed_area2(h).abs()).sum();
        (signed_area2(&self.polygon).abs() - holes) / 2.0
    }

    /// The exact volume: cross-section area times the height `|direction.z|`.
    pub fn volume(&self) -> f64 {
        self.cross_section_area() * self.direction.z.abs()
    }

    /// The prism as an exact polyhedron (see the module docs for its faces).
    pub fn to_polyhedron(&self) -> Result<Polyhedron, PolyhedronError> {
        let d = self.direction;
        if !d.is_finite() || d.z == 0.0 {
            return Err(PolyhedronError::FlatDirection);
        }
        // Outer loop counter-clockwise, holes clockwise: the solid is left of every edge.
        let mut loops: Vec<Vec<DVec2>> = Vec::with_capacity(1 + self.holes.len());
        loops.push(oriented(&self.polygon, true));
        loops.extend(self.holes.iter().map(|h| oriented(h, false)));
        let bad =
            |part: &'static str| move |problem| PolyhedronError::BadCrossSection { part, problem };
        let mut cap = triangulate_loops(&[&loops[0]]).map_err(bad("polygon"))?;
        if !self.holes.is_empty() {
            let refs: Vec<&[DVec2]> = loops.iter().map(Vec::as_slice).collect();
            cap = triangulate_loops(&refs).map_err(bad("holes"))?;
        }
        let n = loops.iter().map(Vec::len).sum::<usize>() as u32;
        let bottom = loops.iter().flatten().map(|p| p.extend(0.0));
        let top = loops.iter().flatten().map(|p| p.extend(0.0) + d);
        let vertices: Vec<DVec3> = bottom.chain(top).collect();
        let mut faces: Vec<Vec<u32>> = Vec::new();
        if self.holes.is_empty() {
            faces.push((0..n).rev().collect());
            faces.push((n..2 * n).collect());
        } else {
            faces.extend(cap.iter().map(|&[a, b, c]| vec![a, c, b]));
            faces.extend(cap.iter().map(|t| t.iter().map(|&i| i + n).collect()));
        }
        let mut start = 0u32;
        for l in &loops {
            let len = l.len() as u32;
            for i in 0..len {
                let (a, b) = (start + i, start + (i + 1) % len);
                faces.push(vec![a, b, b + n, a + n]);
            }
            start += len;
        }
        if d.z < 0.0 {
            // Swept downwards the solid is mirrored: every face turns around.
            faces.iter_mut().for_each(|f| f.reverse());
        }
        Polyhedron::new(vertices, faces)
    }
}

/// A copy of `points` counter-clockwise (`ccw`) or clockwise.
fn oriented(points: &[DVec2], ccw: bool) -> Vec<DVec2> {
    let mut out = points.to_vec();
    if (signed_area2(points) > 0.0) != ccw {
        out.reverse();
    }
    out
}
