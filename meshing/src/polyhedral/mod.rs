//! Polyhedral Booleans: solids that are polyhedra (OpenSCAD's faceted primitives, polyhedra,
//! extrusions of polygons, imported meshes) combined by mesh Booleans instead of sampling a
//! field, as OpenSCAD (CGAL) and manifold3d build them.
//!
//! A [`Polyhedral`] is a closed oriented 2-manifold triangle mesh (possibly empty). The Booleans
//! are those of the `manifold-rust` crate, a port of manifold3d's kernel: symbolic perturbation
//! decides coincident faces and edges consistently, and every result is again a manifold, so
//! faces shared inside a union, slivers thinner than any grid cell and slits between parts come
//! out as the polyhedra say, with no resolution. Unions and intersections of many operands are
//! reduced as a balanced tree, the halves in parallel.
//!
//! The meshes have the operands' own vertices and the intersection points of their faces: a
//! cube is 12 triangles.

mod from_solid;
mod gridded;
mod reduce;
mod sections;

pub use from_solid::{NotPolyhedral, from_solid, from_solid_gridding};
pub use reduce::{difference, intersection_all, union_all};
pub use sections::Loops;

use glam::{DAffine3, DVec3};
use manifold_rust::linalg::{Mat3x4, Vec3};
use manifold_rust::manifold::Manifold;
use manifold_rust::types::{Error as Status, MeshGL64};
use solidkit_kernel::IndexedMesh;
use solidkit_kernel::polyhedra::Polyhedron;

/// Why a mesh is not a [`Polyhedral`] solid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PolyhedralError {
    /// The faces do not triangulate (a face with fewer than 3 corners, an index out of range,
    /// a vertex that is not finite).
    #[error("its faces do not form a polyhedron: {0}")]
    Faces(String),
    /// The triangles are not a closed oriented 2-manifold (an edge not shared by exactly two
    /// triangles in opposite directions).
    #[error("it is not a closed oriented 2-manifold ({0})")]
    NotManifold(String),
    /// A Boolean failed inside the kernel.
    #[error("a polyhedral Boolean failed: {0}")]
    Failed(String),
}

/// A closed oriented 2-manifold solid (possibly empty), ready for Booleans.
#[derive(Clone)]
pub struct Polyhedral(pub(crate) Manifold);

impl std::fmt::Debug for Polyhedral {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Polyhedral({} triangles)", self.0.num_tri())
    }
}

impl Polyhedral {
    /// The empty solid.
    pub fn empty() -> Polyhedral {
        Polyhedral(Manifold::empty())
    }

    /// The box from corner `lo` with side lengths `size`: 6 quads, 12 triangles.
    pub fn cuboid(lo: DVec3, size: DVec3) -> Result<Self, PolyhedralError> {
        let v = (0..8)
            .map(|i| lo + size * DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64))
            .collect();
        let f = vec![
            vec![0, 2, 3, 1],
            vec![4, 5, 7, 6],
            vec![0, 1, 5, 4],
            vec![2, 6, 7, 3],
            vec![0, 4, 6, 2],
            vec![1, 3, 7, 5],
        ];
        Self::from_faces(v, f)
    }

    /// A solid from vertices and planar polygonal faces, counter-clockwise seen from outside
    /// (triangulated in their planes by constrained Delaunay triangulation).
    pub fn from_faces(vertices: Vec<DVec3>, faces: Vec<Vec<u32>>) -> Result<Self, PolyhedralError> {
        let triangles_only = faces.iter().all(|f| f.len() == 3);
        if triangles_only {
            let n = vertices.len();
            let mut triangles = Vec::with_capacity(faces.len());
            for f in &faces {
                if f.iter().any(|&i| i as usize >= n) {
                    return Err(PolyhedralError::Faces(
                        "a face index is out of range".into(),
                    ));
                }
                triangles.push([f[0], f[1], f[2]]);
            }
            return Self::from_mesh(&IndexedMesh::new(vertices, triangles));
        }
        let p =
            Polyhedron::new(vertices, faces).map_err(|e| PolyhedralError::Faces(e.to_string()))?;
        Self::from_mesh(&p.to_indexed())
    }

    /// A solid from a closed oriented triangle mesh (vertices shared by index).
    pub fn from_mesh(mesh: &IndexedMesh) -> Result<Self, PolyhedralError> {
        if mesh.triangles.is_empty() {
            return Ok(Self::empty());
        }
        if mesh.positions.iter().any(|p| !p.is_finite()) {
            return Err(PolyhedralError::Faces("a vertex is not finite".into()));
        }
        let gl = MeshGL64 {
            num_prop: 3,
            vert_properties: mesh.positions.iter().flat_map(|p| p.to_array()).collect(),
            tri_verts: mesh
                .triangles
                .iter()
                .flat_map(|t| t.map(u64::from))
                .collect(),
            ..MeshGL64::default()
        };
        let m = std::panic::catch_unwind(|| Manifold::from_mesh_gl64(&gl))
            .map_err(|_| PolyhedralError::Failed("reading the mesh stopped".into()))?;
        match m.status() {
            Status::NoError => Ok(Polyhedral(m)),
            Status::NotManifold => Err(PolyhedralError::NotManifold(
                "an edge is not shared by exactly two triangles in opposite directions".into(),
            )),
            other => Err(PolyhedralError::Faces(format!("{other:?}"))),
        }
    }

    /// The convex hull of the points (empty for fewer than 4 points not in one plane).
    pub fn hull(points: &[DVec3]) -> Result<Polyhedral, PolyhedralError> {
        let pts: Vec<Vec3> = points.iter().map(|p| Vec3::new(p.x, p.y, p.z)).collect();
        std::panic::catch_unwind(|| Manifold::hull(&pts))
            .map(Polyhedral)
            .map_err(|_| PolyhedralError::Failed("the convex hull stopped".into()))
    }

    /// The solid under the affine map `m`; a map that reverses orientation (a mirror) keeps
    /// the faces outward.
    pub fn transform(&self, m: &DAffine3) -> Polyhedral {
        let v = |c: DVec3| Vec3::new(c.x, c.y, c.z);
        let a = m.matrix3;
        let t = Mat3x4::from_cols(v(a.x_axis), v(a.y_axis), v(a.z_axis), v(m.translation));
        Polyhedral(self.0.transform(&t))
    }

    /// The bounding box `(min, max)` of the vertices; `None` when empty.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        if self.is_empty() {
            return None;
        }
        let b = self.0.bounding_box();
        let v = |c: Vec3| DVec3::new(c.x, c.y, c.z);
        Some((v(b.min), v(b.max)))
    }

    /// Whether the solid is empty.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.0.num_tri()
    }

    /// Volume.
    pub fn volume(&self) -> f64 {
        self.0.volume()
    }

    /// The solid as an indexed triangle mesh (faces counter-clockwise seen from outside).
    pub fn to_mesh(&self) -> IndexedMesh {
        let gl = self.0.get_mesh_gl64(-1);
        let np = (gl.num_prop as usize).max(3);
        let positions = gl
            .vert_properties
            .chunks_exact(np)
            .map(|c| DVec3::new(c[0], c[1], c[2]))
            .collect();
        let triangles = gl
            .tri_verts
            .chunks_exact(3)
            .map(|t| [t[0] as u32, t[1] as u32, t[2] as u32])
            .collect();
        IndexedMesh::new(positions, triangles)
    }
}

#[cfg(test)]
mod tests;
