//! Closed forms of the Platonic solids per unit edge: volume, surface area, circumradius and
//! inradius, face size and the counts (V, E, F). These are textbook values (e.g. Coxeter, *Regular
//! Polytopes*, table I) written with `√2`, `√3`, `√5`; they are ground truth for tessellations and
//! meshes, independent of the vertex coordinates [`Polyhedron::platonic`](super::Polyhedron)
//! computes.

use super::PlatonicKind;

/// Exact measures of a Platonic solid with edge length 1 (scale: volume by `a³`, area and
/// radii by `a²`, `a`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlatonicMeasures {
    /// Volume.
    pub volume: f64,
    /// Surface area.
    pub area: f64,
    /// Distance from the centre to every vertex.
    pub circumradius: f64,
    /// Distance from the centre to every face plane.
    pub inradius: f64,
    /// Corners of every face.
    pub face_sides: usize,
    /// Vertices, edges, faces of the polyhedron (polygonal faces).
    pub counts: [usize; 3],
}

impl PlatonicKind {
    /// The closed-form measures of this solid with edge 1.
    pub fn unit_measures(self) -> PlatonicMeasures {
        let (s2, s3, s5) = (2f64.sqrt(), 3f64.sqrt(), 5f64.sqrt());
        let s6 = 6f64.sqrt();
        let m = |volume, area, circumradius, inradius, face_sides, counts| PlatonicMeasures {
            volume,
            area,
            circumradius,
            inradius,
            face_sides,
            counts,
        };
        match self {
            PlatonicKind::Tetrahedron => m(s2 / 12.0, s3, s6 / 4.0, s6 / 12.0, 3, [4, 6, 4]),
            PlatonicKind::Cube => m(1.0, 6.0, s3 / 2.0, 0.5, 4, [8, 12, 6]),
            PlatonicKind::Octahedron => m(s2 / 3.0, 2.0 * s3, s2 / 2.0, s6 / 6.0, 3, [6, 12, 8]),
            PlatonicKind::Dodecahedron => m(
                (15.0 + 7.0 * s5) / 4.0,
                3.0 * (25.0 + 10.0 * s5).sqrt(),
                s3 * (1.0 + s5) / 4.0,
                (250.0 + 110.0 * s5).sqrt() / 20.0,
                5,
                [20, 30, 12],
            ),
            PlatonicKind::Icosahedron => m(
                5.0 * (3.0 + s5) / 12.0,
                5.0 * s3,
                (10.0 + 2.0 * s5).sqrt() / 4.0,
                s3 * (3.0 + s5) / 12.0,
                3,
                [12, 30, 20],
            ),
        }
    }

    /// Edge length of the dual of this solid with edge `edge`, built on the face centroids (as
    /// [`Polyhedron::dual`](super::Polyhedron::dual) does): the dual's circumradius is this
    /// solid's inradius.
    pub fn dual_edge(self, edge: f64) -> f64 {
        edge * self.unit_measures().inradius / self.dual().unit_measures().circumradius
    }
}
