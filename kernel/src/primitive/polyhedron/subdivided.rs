//! Subdivision surfaces as CSG operands: the `subdivide` node.
//!
//! The kernel only *records* a subdivision: the scheme, the number of levels and the polyhedral
//! child (`polyhedron`, `mesh`, `prism` or `platonic`). The arithmetic runs on the half-edge mesh
//! in `solidkit-meshing`, which depends on the kernel, so the kernel hands the child's polygon
//! mesh to the [`MeshResolver`] (the same hook that loads mesh files) and builds a [`MeshSolid`]
//! from the triangles it gets back. The node keeps its child's description, so the JSON writer
//! writes back the node as it was read.

use super::request::{SubdivisionInput, SubdivisionRequest, SubdivisionScheme};
use super::resolver::MeshResolver;
use super::{MeshSolid, MeshSolidError, MeshSource};
use crate::polyhedra::Polyhedron;
use crate::primitive::Primitive;
use crate::{IndexedMesh, Solid};

impl MeshSolid {
    /// The solid bounded by `child`'s polygon mesh subdivided `levels` times by `scheme`, computed
    /// by `resolver`. `child` must be a `polyhedron`, `mesh`, `prism` or `platonic` primitive (not
    /// itself a subdivision: give more levels instead).
    pub fn subdivided(
        child: &Primitive,
        scheme: SubdivisionScheme,
        levels: u32,
        adaptive: Option<f64>,
        resolver: &dyn MeshResolver,
    ) -> Result<Self, MeshSolidError> {
        let not_polyhedral = || MeshSolidError::NotPolyhedral {
            found: child.name(),
        };
        let owned: Polyhedron;
        let input = match child {
            Primitive::Platonic(p) => {
                owned = Polyhedron::platonic(p.kind, p.size)?;
                faces_of(&owned)
            }
            Primitive::Mesh(m) => match m.source() {
                MeshSource::Faces { vertices, faces } => {
                    SubdivisionInput::Faces { vertices, faces }
                }
                MeshSource::File { path } => SubdivisionInput::File { path },
                MeshSource::Prism(prism) => {
                    owned = prism.to_polyhedron()?;
                    faces_of(&owned)
                }
                MeshSource::Subdivided { .. }
                | MeshSource::Surface(_)
                | MeshSource::Dual { .. } => {
                    return Err(not_polyhedral());
                }
            },
            _ => return Err(not_polyhedral()),
        };
        let request = SubdivisionRequest {
            input,
            scheme,
            levels,
            adaptive,
        };
        let mesh: IndexedMesh = resolver
            .subdivide(&request)
            .map_err(MeshSolidError::Subdivision)?;
        let source = MeshSource::Subdivided {
            scheme,
            levels,
            adaptive,
            child: Box::new(child.clone()),
        };
        Self::with_source(source, &mesh)
    }
}

/// The faces of an exact polyhedron as a subdivision input.
fn faces_of(p: &Polyhedron) -> SubdivisionInput<'_> {
    SubdivisionInput::Faces {
        vertices: p.vertices(),
        faces: p.faces(),
    }
}

impl Solid {
    /// This solid's polygon mesh subdivided `levels` times by `scheme` (through `resolver`,
    /// normally `solidkit_meshing::io::FileMeshResolver`). The solid must be a `polyhedron`,
    /// `mesh`, `prism` or `platonic` primitive.
    pub fn subdivide(
        &self,
        scheme: SubdivisionScheme,
        levels: u32,
        resolver: &dyn MeshResolver,
    ) -> Result<Solid, MeshSolidError> {
        let crate::NodeKind::Primitive(child) = self.kind() else {
            return Err(MeshSolidError::NotPolyhedral {
                found: self.kind().name(),
            });
        };
        let mesh = MeshSolid::subdivided(child, scheme, levels, None, resolver)?;
        Ok(Solid::primitive(Primitive::Mesh(mesh)))
    }
}
