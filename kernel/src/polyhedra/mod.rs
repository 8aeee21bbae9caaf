//! Exact polyhedra: polygonal faces, counts (V, E, F and Euler's formula `V − E + F = 2` for
//! simple polyhedra), the five Platonic solids, duals of convex polyhedra, prisms swept from
//! polygons with holes, and triangulation into an [`IndexedMesh`](crate::IndexedMesh).
//!
//! Polygonal faces and prism caps are triangulated by constrained Delaunay triangulation
//! (`spade`, through [`crate::triangulate`]), never as fans, so non-convex faces and holes come
//! out right. These are exact tessellations; to use a polyhedron in a CSG tree see
//! [`Solid::platonic`](crate::Solid::platonic) (an exact field from face planes) and
//! [`Solid::from_polyhedron`](crate::Solid::from_polyhedron) (any polyhedron through its triangle
//! mesh). [`VoxelGrid`] gives the exact boundary of a union of grid cubes (Menger sponges), and
//! [`PlatonicKind::unit_measures`] the Platonic solids' closed forms.

mod dual;
mod error;
mod hull;
mod measures;
mod platonic;
mod polyhedron;
mod prism;
mod voxels;

#[cfg(test)]
mod tests;

pub use crate::triangulate::TriangulationError;
pub use error::PolyhedronError;
pub use measures::PlatonicMeasures;
pub(crate) use platonic::unit as unit_platonic;
pub use platonic::{PlatonicKind, PlatonicSize};
pub use polyhedron::Polyhedron;
pub use prism::Prism;
pub use voxels::{VoxelError, VoxelGrid};
