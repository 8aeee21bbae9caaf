//! Generalised winding numbers of a triangle mesh, fast through the [`MeshTree`] (Barill, Dickson,
//! Schmidt, Levin, Jacobson 2018, "Fast winding numbers for soups and clouds").
//!
//! The winding number at `q` is the sum of the triangles' signed solid angles over `4π`: 1 inside
//! a closed outward-oriented mesh, 0 outside, and a smooth, nearly integer value around small
//! defects (holes, cracks, duplicated faces), so thresholding it at ½ classifies points robustly
//! on slightly imperfect meshes. A node whose triangles all lie within radius `r` of its centroid
//! `c` and which is farther than `β·r` from `q` contributes its dipole term
//! `A · (c − q) / |c − q|³` (`A` the sum of its area vectors) to the solid angle; nearer nodes are opened, and leaves sum
//! exact solid angles (van Oosterom and Strackee). Outside the mesh's bounding box the number is
//! taken as 0.
//!
//! With `β = 2` the far-field error measured against exact sums on a 20 480-triangle sphere is at
//! most 0.05 (a second-order term was tried and did not reduce the worst case), far below the ½
//! that would flip a classification; a query costs about 2 µs there.

use super::tree::MeshTree;
use crate::bvh::with_scratch;
use glam::DVec3;
use std::cell::RefCell;
use std::f64::consts::PI;

/// Nodes farther than this many radii are approximated by their dipole.
const BETA: f64 = 2.0;

thread_local! {
    static STACK: RefCell<Vec<u32>> = const { RefCell::new(Vec::new()) };
}

/// Signed solid angle of triangle `abc` seen from the origin (corners relative to the query
/// point): positive when the origin is on the inner side of the triangle, the side from which it
/// is seen clockwise.
pub(crate) fn solid_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let numerator = a.dot(b.cross(c));
    let denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    2.0 * numerator.atan2(denominator)
}

impl MeshTree {
    /// The (fast, approximate far away) generalised winding number at `q`.
    pub(crate) fn winding_number(&self, q: DVec3) -> f64 {
        if !self.bbox.contains(q) {
            return 0.0;
        }
        let mut omega = 0.0;
        with_scratch(&STACK, |stack| {
            stack.push(0);
            while let Some(index) = stack.pop() {
                let node = &self.bvh.nodes()[index as usize];
                let dipole = &self.dipoles[index as usize];
                let d = dipole.center - q;
                let dist2 = d.length_squared();
                if dist2 > (BETA * dipole.radius) * (BETA * dipole.radius) {
                    omega += dipole.area.dot(d) / (dist2 * dist2.sqrt());
                } else if node.is_leaf() {
                    for s in node.slots() {
                        let [a, b, c] = self.triangles()[s];
                        omega += solid_angle(a - q, b - q, c - q) * self.weights[s];
                    }
                } else {
                    stack.push(node.first);
                    stack.push(node.first + 1);
                }
            }
        });
        omega / (4.0 * PI)
    }

    /// The exact winding number by summing every triangle's solid angle (for tests).
    #[cfg(test)]
    pub(crate) fn winding_number_exact(&self, q: DVec3) -> f64 {
        self.triangles()
            .iter()
            .zip(&self.weights)
            .map(|([a, b, c], w)| solid_angle(*a - q, *b - q, *c - q) * w)
            .sum::<f64>()
            / (4.0 * PI)
    }
}
