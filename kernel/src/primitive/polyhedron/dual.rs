//! The dual of a convex polyhedron as a CSG operand: the `dual` node.
//!
//! The child is a polyhedral primitive (`platonic`, `polyhedron`, `prism`, or a `mesh` file
//! loaded through the [`MeshResolver`]); its exact polygon mesh is dualised by
//! [`Polyhedron::dual`] (one vertex at the centroid of each face, one face around each vertex),
//! which needs a closed, oriented, convex child. The result is a [`MeshSolid`] (exact signed
//! distance to the dual's faces) that keeps its child's description for the JSON writer.

use super::resolver::MeshResolver;
use super::{MeshSolid, MeshSolidError, MeshSource};
use crate::polyhedra::Polyhedron;
use crate::primitive::Primitive;
use crate::{NodeKind, Solid};

impl MeshSolid {
    /// The solid bounded by the dual of `child`'s polygon mesh. `child` must be a `polyhedron`,
    /// `mesh` (loaded by `resolver`), `prism` or `platonic` primitive bounding a convex solid.
    pub fn dual_of(child: &Primitive, resolver: &dyn MeshResolver) -> Result<Self, MeshSolidError> {
        let polyhedron = polyhedron_of(child, resolver)?;
        let dual = polyhedron.dual()?;
        let source = MeshSource::Dual {
            child: Box::new(child.clone()),
        };
        Self::with_source(source, &dual.to_indexed())
    }
}

/// The exact polygon mesh of a polyhedral primitive (a mesh file as its triangles).
fn polyhedron_of(
    child: &Primitive,
    resolver: &dyn MeshResolver,
) -> Result<Polyhedron, MeshSolidError> {
    let not_dualizable = || MeshSolidError::NotDualizable {
        found: child.name(),
    };
    match child {
        Primitive::Platonic(p) => Ok(Polyhedron::platonic(p.kind, p.size)?),
        Primitive::Mesh(m) => match m.source() {
            MeshSource::Faces { vertices, faces } => {
                Ok(Polyhedron::new(vertices.clone(), faces.clone())?)
            }
            MeshSource::Prism(prism) => Ok(prism.to_polyhedron()?),
            MeshSource::File { path } => {
                let mesh = resolver.load(path).map_err(|error| MeshSolidError::Load {
                    path: path.clone(),
                    error,
                })?;
                let faces = mesh.triangles.iter().map(|t| t.to_vec()).collect();
                Ok(Polyhedron::new(mesh.positions, faces)?)
            }
            MeshSource::Subdivided { .. } | MeshSource::Surface(_) | MeshSource::Dual { .. } => {
                Err(not_dualizable())
            }
        },
        _ => Err(not_dualizable()),
    }
}

impl Solid {
    /// The dual of this solid's convex polygon mesh (see [`MeshSolid::dual_of`]); `resolver`
    /// loads `mesh` files (normally `solidkit_meshing::io::FileMeshResolver`).
    pub fn dual(&self, resolver: &dyn MeshResolver) -> Result<Solid, MeshSolidError> {
        let NodeKind::Primitive(child) = self.kind() else {
            return Err(MeshSolidError::NotDualizable {
                found: self.kind().name(),
            });
        };
        let mesh = MeshSolid::dual_of(child, resolver)?;
        Ok(Solid::primitive(Primitive::Mesh(mesh)))
    }
}
