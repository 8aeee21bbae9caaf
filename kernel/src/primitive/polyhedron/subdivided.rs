//! Subdivision surfaces as CSG operands: the `subdivide` node.
//!
//! The kernel only *records* a subdivision: the scheme, the number of levels and the polyhedral
//! child (`polyhedron`, `mesh`, `prism` or `platonic`). The arithmetic runs on the half-edge mesh
//! in `solidkit-meshing`, which depends on the kernel, so the kernel hands the child's polygon
//! mesh to the [`MeshResolver`] (the same hook that loads mesh files) and builds a [`MeshSolid`]
//! from the triangles it gets back. The node keeps its child's description, so the JSON writer
//! writes back the node as it was read.

use super::resolver::MeshResolver;
use super::{MeshSolid, MeshSolidError, MeshSource};
use crate::polyhedra::Polyhedron;
use crate::primitive::Primitive;
use crate::{IndexedMesh, Solid};
use glam::DVec3;

/// A subdivision scheme, by its JSON name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SubdivisionScheme {
    /// Catmull-Clark: any polygon mesh to quads; approximating (`"catmull-clark"`).
    CatmullClark,
    /// Loop: triangle meshes; approximating (`"loop"`).
    Loop,
    /// Modified butterfly (Zorin et al.): triangle meshes; interpolating (`"butterfly"`).
    Butterfly,
    /// Doo-Sabin: the dual scheme, any polygon mesh (`"doo-sabin"`).
    DooSabin,
}

impl SubdivisionScheme {
    /// Every scheme, in the order of the documentation.
    pub const ALL: [SubdivisionScheme; 4] = [
        SubdivisionScheme::CatmullClark,
        SubdivisionScheme::Loop,
        SubdivisionScheme::Butterfly,
        SubdivisionScheme::DooSabin,
    ];

    /// The name in JSON trees and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            SubdivisionScheme::CatmullClark => "catmull-clark",
            SubdivisionScheme::Loop => "loop",
            SubdivisionScheme::Butterfly => "butterfly",
            SubdivisionScheme::DooSabin => "doo-sabin",
        }
    }

    /// The scheme called `name` (exactly as [`SubdivisionScheme::name`] writes it).
    pub fn from_name(name: &str) -> Option<SubdivisionScheme> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }

    /// True for the schemes that need a triangle mesh (Loop, butterfly).
    pub fn needs_triangles(self) -> bool {
        matches!(self, SubdivisionScheme::Loop | SubdivisionScheme::Butterfly)
    }
}

impl std::fmt::Display for SubdivisionScheme {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The polygon mesh a resolver is asked to subdivide.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SubdivisionInput<'a> {
    /// Vertices and polygonal faces (counter-clockwise seen from outside).
    Faces {
        /// Vertex positions.
        vertices: &'a [DVec3],
        /// Faces as vertex indices.
        faces: &'a [Vec<u32>],
    },
    /// The mesh file of a `mesh` node, by the path written in the tree; the resolver reads it
    /// with its polygonal faces (an OBJ or OFF of quads stays quads).
    File {
        /// The path as written in the tree.
        path: &'a str,
    },
}

/// One `subdivide` request: what, how and how often.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SubdivisionRequest<'a> {
    /// The polygon mesh of the child node.
    pub input: SubdivisionInput<'a>,
    /// The scheme.
    pub scheme: SubdivisionScheme,
    /// How many times to apply it.
    pub levels: u32,
}

impl MeshSolid {
    /// The solid bounded by `child`'s polygon mesh subdivided `levels` times by `scheme`, computed
    /// by `resolver`. `child` must be a `polyhedron`, `mesh`, `prism` or `platonic` primitive (not
    /// itself a subdivision: give more levels instead).
    pub fn subdivided(
        child: &Primitive,
        scheme: SubdivisionScheme,
        levels: u32,
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
                MeshSource::Subdivided { .. } => return Err(not_polyhedral()),
            },
            _ => return Err(not_polyhedral()),
        };
        let request = SubdivisionRequest {
            input,
            scheme,
            levels,
        };
        let mesh: IndexedMesh = resolver
            .subdivide(&request)
            .map_err(MeshSolidError::Subdivision)?;
        let source = MeshSource::Subdivided {
            scheme,
            levels,
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
        let mesh = MeshSolid::subdivided(child, scheme, levels, resolver)?;
        Ok(Solid::primitive(Primitive::Mesh(mesh)))
    }
}
