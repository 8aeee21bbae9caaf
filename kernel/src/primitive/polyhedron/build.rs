//! Builders of polyhedral solids on [`Solid`]: Platonic solids, exact polyhedra, inline faces,
//! triangle meshes, mesh files and prisms.

use super::{MeshResolver, MeshSolid, MeshSolidError, Platonic};
use crate::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron, Prism};
use crate::{IndexedMesh, Primitive, Solid};
use glam::DVec3;

impl Solid {
    /// A Platonic solid centred at the origin (the size is checked by [`Solid::validate`]).
    pub fn platonic(kind: PlatonicKind, size: PlatonicSize) -> Solid {
        Solid::primitive(Primitive::Platonic(Platonic::new(kind, size)))
    }

    /// The solid bounded by an exact polyhedron (through its triangle mesh: exact distance).
    pub fn from_polyhedron(polyhedron: &Polyhedron) -> Solid {
        Solid::primitive(Primitive::Mesh(MeshSolid::from_polyhedron(polyhedron)))
    }

    /// The solid bounded by vertices and polygonal faces (counter-clockwise seen from outside),
    /// like OpenSCAD's `polyhedron`.
    pub fn polyhedron(vertices: Vec<DVec3>, faces: Vec<Vec<u32>>) -> Result<Solid, MeshSolidError> {
        Ok(Solid::primitive(Primitive::Mesh(MeshSolid::from_faces(
            vertices, faces,
        )?)))
    }

    /// The solid bounded by a triangle mesh (counter-clockwise seen from outside).
    pub fn mesh(mesh: &IndexedMesh) -> Result<Solid, MeshSolidError> {
        Ok(Solid::primitive(Primitive::Mesh(MeshSolid::from_mesh(
            mesh,
        )?)))
    }

    /// The solid bounded by the mesh file at `path`, loaded by `resolver` (the path is kept).
    pub fn mesh_file(path: &str, resolver: &dyn MeshResolver) -> Result<Solid, MeshSolidError> {
        Ok(Solid::primitive(Primitive::Mesh(MeshSolid::from_file(
            path, resolver,
        )?)))
    }

    /// A prism: a polygon with holes in the xy plane swept along a vector (exact distance).
    pub fn prism(prism: Prism) -> Result<Solid, MeshSolidError> {
        Ok(Solid::primitive(Primitive::Mesh(MeshSolid::from_prism(
            prism,
        )?)))
    }
}
