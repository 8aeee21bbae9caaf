//! Polyhedral primitives: the Platonic solids (exact face-plane field) and any triangle mesh as a
//! CSG operand (exact signed distance through a BVH, inside/outside by fast winding numbers), which
//! also carries inline polyhedra, mesh files and prisms.
//!
//! | primitive | field | `field_error` |
//! |---|---|---|
//! | [`Platonic`] | max of face-plane distances (exact inside, a bound outside) | 0 |
//! | [`MeshSolid`] | exact signed distance to the mesh (closed meshes) | 0 |
//!
//! Both are 1-Lipschitz.
//!
//! `field_error` is the distance between the field's zero set and the exact surface.

mod build;
mod dual;
mod mesh_solid;
mod nearest;
mod platonic;
mod request;
mod resolve_error;
mod resolver;
mod sign_balls;
mod subdivided;
mod tree;
mod winding;

#[cfg(test)]
mod batch_tests;
#[cfg(test)]
mod dual_tests;
#[cfg(test)]
mod json_tests;
#[cfg(test)]
mod subdivided_tests;
#[cfg(test)]
mod tests;

pub use mesh_solid::{MeshSolid, MeshSolidError, MeshSource};
pub use platonic::Platonic;
pub use request::{SubdivisionInput, SubdivisionRequest, SubdivisionScheme};
pub use resolve_error::{ResolveError, ResolveKind};
pub use resolver::{MeshResolver, NoMeshResolver};
