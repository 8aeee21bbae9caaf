//! The dual of a convex polyhedron: one vertex at the centroid of each face, one face for each
//! vertex through the centroids of the faces around it (counter-clockwise seen from outside).
//!
//! For the Platonic solids centred at the origin the dual's faces are planar and regular:
//! tetrahedron ↔ tetrahedron, cube ↔ octahedron, dodecahedron ↔ icosahedron, and the dual of the
//! dual is the original scaled by `(inradius / circumradius)²`. For other convex polyhedra the
//! dual's faces may be slightly non-planar (they are triangulated in their best-fit plane).

use super::{Polyhedron, PolyhedronError};
use crate::triangulate::newell_normal;
use glam::DVec3;

impl Polyhedron {
    /// The dual polyhedron; dual vertex `i` is the centroid (mean of the corners) of face `i`,
    /// and dual faces follow the order of the used vertices.
    ///
    /// Errors unless the polyhedron is a closed oriented manifold and convex (every vertex on the
    /// inner side of every face plane, up to rounding).
    pub fn dual(&self) -> Result<Polyhedron, PolyhedronError> {
        let cycles = self.vertex_cycles()?;
        self.check_convex()?;
        let centroids = self
            .faces()
            .iter()
            .map(|f| {
                f.iter()
                    .map(|&i| self.vertices()[i as usize])
                    .sum::<DVec3>()
                    / f.len() as f64
            })
            .collect();
        let faces = cycles.into_iter().filter(|c| !c.is_empty()).collect();
        Polyhedron::new(centroids, faces)
    }

    /// Every vertex lies on the inner side of every face's plane (within rounding).
    fn check_convex(&self) -> Result<(), PolyhedronError> {
        let size = self
            .vertices()
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs().max_element()));
        let tolerance = 1e-9 * size.max(f64::MIN_POSITIVE);
        for (face, corners) in self.faces().iter().enumerate() {
            let points: Vec<DVec3> = corners
                .iter()
                .map(|&i| self.vertices()[i as usize])
                .collect();
            let normal = newell_normal(&points).normalize_or_zero();
            let center = points.iter().sum::<DVec3>() / points.len() as f64;
            let offset = normal.dot(center);
            if let Some(vertex) = self
                .vertices()
                .iter()
                .position(|v| normal.dot(*v) - offset > tolerance)
            {
                return Err(PolyhedronError::NotConvex { face, vertex });
            }
        }
        Ok(())
    }
}
