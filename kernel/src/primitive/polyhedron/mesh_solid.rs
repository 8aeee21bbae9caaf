//! Any closed triangle mesh as a CSG operand: the exact signed distance to the mesh.
//!
//! Field: `f(p) = ±|p − nearest point of the mesh|`, negative where the generalised winding number
//! is above ½, and +0 within rounding of the surface (about 10⁻¹⁴ of the mesh's size). For a
//! closed, consistently oriented mesh this is the exact signed distance to the solid it bounds
//! (1-Lipschitz; `field_error` 0: the zero set is the mesh itself). On slightly
//! imperfect meshes (small holes or cracks, duplicated or flipped faces) the winding number still
//! classifies points sensibly, and the zero set stays on the triangles; only near a defect may the
//! sign flip away from the surface (the field is then not Lipschitz there).
//!
//! An open mesh (edges whose two directions are not used equally often: holes, flipped faces,
//! dangling sheets) keeps the same rule, inside where the winding number is at least ½, but its
//! sign then also changes away from the triangles, across the surface where the winding number
//! passes ½ (which caps each hole). Its interval therefore never claims a sign: it is
//! `±(|f(c)| + r)` over a box of centre `c` and half-diagonal `r`, which bounds the unsigned
//! distance, so sparse meshers never cull a box that such a cap may cross.
//!
//! The mesh is kept with the description it came from (inline faces, a file path, or a prism), so
//! the JSON writer can write the node back as it was read. Both live behind `Arc`s: cloning is
//! cheap, and equality compares descriptions, not trees.

use super::super::{PrimitiveError, Shape, lipschitz_interval};
use super::request::SubdivisionScheme;
use super::resolve_error::ResolveError;
use super::resolver::MeshResolver;
use super::sign_balls::SignBalls;
use super::tree::MeshTree;
use crate::polyhedra::{Polyhedron, PolyhedronError, Prism};
use crate::primitive::Primitive;
use crate::triangulate::triangulate_face;
use crate::{Aabb, IndexedMesh, Interval};
use glam::DVec3;
use std::sync::Arc;

/// Why a mesh solid cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeshSolidError {
    /// The vertices and faces (or the prism) are invalid.
    #[error(transparent)]
    Invalid(#[from] PolyhedronError),
    /// A mesh file could not be loaded.
    #[error("cannot load \"{path}\": {error}")]
    Load {
        /// The path as given.
        path: String,
        /// Why.
        error: ResolveError,
    },
    /// The child of a `subdivide` node is not a polyhedral primitive.
    #[error(
        "subdivide needs a polyhedron, mesh, prism or platonic child (a subdivide child: give more levels instead), found {found}"
    )]
    NotPolyhedral {
        /// The JSON type of the child that was given.
        found: &'static str,
    },
    /// The child of a `dual` node is not a polyhedral primitive.
    #[error(
        "dual needs a polyhedron, mesh, prism or platonic child (the dual of a dual is the original scaled: use it instead), found {found}"
    )]
    NotDualizable {
        /// The JSON type of the child that was given.
        found: &'static str,
    },
    /// The subdivision failed (non-manifold child, a non-triangle child for Loop or butterfly,
    /// too many faces, no subdivision hook...).
    #[error("{0}")]
    Subdivision(ResolveError),
}

/// Where a mesh solid's triangles come from.
#[derive(Debug, Clone, PartialEq)]
pub enum MeshSource {
    /// Vertices and polygonal faces given inline (JSON `polyhedron`).
    Faces {
        /// Vertex positions.
        vertices: Vec<DVec3>,
        /// Faces as vertex indices, counter-clockwise seen from outside.
        faces: Vec<Vec<u32>>,
    },
    /// A mesh file, by the path written in the tree (JSON `mesh`).
    File {
        /// The path as written (relative paths are resolved by the [`MeshResolver`]).
        path: String,
    },
    /// A prism (JSON `prism`).
    Prism(Prism),
    /// A polyhedral primitive's polygon mesh subdivided (JSON `subdivide`).
    Subdivided {
        /// The scheme.
        scheme: SubdivisionScheme,
        /// How many times it was applied (adaptive: at most).
        levels: u32,
        /// The adaptive tolerance, if the node has one.
        adaptive: Option<f64>,
        /// The polyhedral child as written in the tree (`polyhedron`, `mesh`, `prism` or
        /// `platonic`; never itself subdivided, so this nests one level only).
        child: Box<Primitive>,
    },
    /// A parametric surface closed into a solid (JSON `bezier_patch`, `interpolating_patch`,
    /// `bspline_surface`, `nurbs_surface`, `param_surface`, `bezier_triangle`, `pn_triangles`).
    Surface(Box<crate::surface::SurfaceSpec>),
    /// The dual of a convex polyhedral primitive (JSON `dual`).
    Dual {
        /// The polyhedral child as written in the tree (`polyhedron`, `mesh`, `prism` or
        /// `platonic`; never itself a dual or a subdivision, so this nests one level only).
        child: Box<Primitive>,
    },
}

impl MeshSource {
    /// The JSON node type of this source.
    pub fn name(&self) -> &'static str {
        match self {
            MeshSource::Faces { .. } => "polyhedron",
            MeshSource::File { .. } => "mesh",
            MeshSource::Prism(_) => "prism",
            MeshSource::Subdivided { .. } => "subdivide",
            MeshSource::Surface(s) => s.kind.name(),
            MeshSource::Dual { .. } => "dual",
        }
    }
}

/// A solid bounded by a triangle mesh, with the exact signed distance (see the module docs).
#[derive(Clone)]
pub struct MeshSolid {
    source: Arc<MeshSource>,
    tree: Arc<MeshTree>,
    /// Edges (by corner positions) whose two directions are not used equally often: 0 for a
    /// closed, consistently oriented mesh.
    open_edges: usize,
}

impl MeshSolid {
    /// Distance between the field's zero set and the mesh: 0.
    pub const FIELD_ERROR: f64 = 0.0;

    /// A mesh solid from vertices and polygonal faces (counter-clockwise seen from outside), as in
    /// OpenSCAD's `polyhedron`. Triangles are taken as they are (degenerate ones too); larger
    /// polygons are triangulated by constrained Delaunay triangulation and must be simple.
    pub fn from_faces(vertices: Vec<DVec3>, faces: Vec<Vec<u32>>) -> Result<Self, MeshSolidError> {
        let mesh = triangulate_faces(&vertices, &faces)?;
        Self::with_source(MeshSource::Faces { vertices, faces }, &mesh)
    }

    /// A mesh solid bounded by an exact polyhedron.
    pub fn from_polyhedron(polyhedron: &Polyhedron) -> Self {
        let source = MeshSource::Faces {
            vertices: polyhedron.vertices().to_vec(),
            faces: polyhedron.faces().to_vec(),
        };
        // A polyhedron always has faces, indices in range and finite coordinates.
        let mesh = polyhedron.to_indexed();
        MeshSolid {
            source: Arc::new(source),
            tree: Arc::new(MeshTree::new(&mesh)),
            open_edges: open_edges(&mesh),
        }
    }

    /// A mesh solid bounded by a triangle mesh (written to JSON as a `polyhedron` node).
    pub fn from_mesh(mesh: &IndexedMesh) -> Result<Self, MeshSolidError> {
        let source = MeshSource::Faces {
            vertices: mesh.positions.clone(),
            faces: mesh.triangles.iter().map(|t| t.to_vec()).collect(),
        };
        Self::with_source(source, mesh)
    }

    /// A mesh solid from a mesh file loaded by `resolver`; the path is kept for the JSON writer.
    pub fn from_file(path: &str, resolver: &dyn MeshResolver) -> Result<Self, MeshSolidError> {
        let mesh = resolver.load(path).map_err(|error| MeshSolidError::Load {
            path: path.to_string(),
            error,
        })?;
        Self::with_source(
            MeshSource::File {
                path: path.to_string(),
            },
            &mesh,
        )
    }

    /// A prism through its exact mesh.
    pub fn from_prism(prism: Prism) -> Result<Self, MeshSolidError> {
        let mesh = prism.to_polyhedron()?.to_indexed();
        Self::with_source(MeshSource::Prism(prism), &mesh)
    }

    pub(crate) fn with_source(
        source: MeshSource,
        mesh: &IndexedMesh,
    ) -> Result<Self, MeshSolidError> {
        MeshTree::check(mesh)?;
        Ok(MeshSolid {
            source: Arc::new(source),
            tree: Arc::new(MeshTree::new(mesh)),
            open_edges: open_edges(mesh),
        })
    }

    /// Where the triangles came from.
    pub fn source(&self) -> &MeshSource {
        &self.source
    }

    /// The JSON node type (`polyhedron`, `mesh`, `prism`, `subdivide` or `dual`).
    pub fn name(&self) -> &'static str {
        self.source.name()
    }

    /// The distinct triangles as an indexed mesh, corners at equal positions shared (bit for
    /// bit): the polyhedron itself, for polyhedral Booleans.
    pub fn to_indexed(&self) -> IndexedMesh {
        let mut index: std::collections::HashMap<[u64; 3], u32> = std::collections::HashMap::new();
        let mut positions = Vec::new();
        let triangles = self
            .tree
            .triangles()
            .iter()
            .map(|t| {
                t.map(|p| {
                    *index
                        .entry(p.to_array().map(f64::to_bits))
                        .or_insert_with(|| {
                            positions.push(p);
                            (positions.len() - 1) as u32
                        })
                })
            })
            .collect();
        IndexedMesh::new(positions, triangles)
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.tree.count
    }

    /// Distance between the field's zero set and the mesh (0).
    pub fn field_error(&self) -> f64 {
        Self::FIELD_ERROR
    }

    /// Number of open edges: edges (by corner positions) whose two directions are not used
    /// equally often. 0 for a closed, consistently oriented mesh; otherwise the solid is where
    /// the winding number is at least ½, and its field is discontinuous away from the triangles.
    pub fn open_edges(&self) -> usize {
        self.open_edges
    }

    /// The unsigned distance from `p` to the triangles and the nearest point (no winding number:
    /// cheaper than the signed field where the sign is not needed).
    pub fn unsigned_distance(&self, p: DVec3) -> (f64, DVec3) {
        let near = self.tree.nearest(p);
        (near.distance2.sqrt(), near.point)
    }

    /// The generalised winding number at `p` (about 1 inside, 0 outside).
    pub fn winding_number(&self, p: DVec3) -> f64 {
        self.tree.winding_number(p)
    }

    /// The signed distance from the unsigned one: +0 within rounding of the surface (where the
    /// winding number is ½ up to noise, so points on a face classify alike), else negative where
    /// the winding number is above ½.
    fn signed(&self, p: DVec3, distance: f64) -> f64 {
        if distance <= self.tree.tolerance {
            0.0
        } else if self.tree.winding_number(p) > 0.5 {
            -distance
        } else {
            distance
        }
    }
}

impl MeshSolid {
    /// The nearest point to `p`, the search bounded by the previous query's triangle if any
    /// (batches come from grid blocks: neighbours share their nearest triangles).
    fn nearest_after(&self, p: DVec3, hint: Option<u32>) -> crate::bvh::Nearest {
        match hint {
            Some(slot) => self.tree.nearest_hinted(p, slot),
            None => self.tree.nearest(p),
        }
    }

    /// [`MeshSolid::signed`], the sign taken from `balls` where one holds `p`; a point whose
    /// winding number is computed becomes a ball.
    fn signed_with(&self, p: DVec3, distance: f64, balls: &mut SignBalls) -> f64 {
        if distance <= self.tree.tolerance || self.open_edges != 0 {
            return self.signed(p, distance);
        }
        let inside = match balls.sign_at(p) {
            Some(inside) => inside,
            None => self.tree.winding_number(p) > 0.5,
        };
        balls.push(p, distance, inside);
        if inside { -distance } else { distance }
    }

    /// The gradient at `p` from its nearest point and its value.
    fn gradient_from(&self, p: DVec3, near: &crate::bvh::Nearest, value: f64) -> DVec3 {
        if value != 0.0 {
            (p - near.point) / value
        } else {
            let [a, b, c] = self.tree.triangles()[near.slot as usize];
            (b - a).cross(c - a).normalize_or_zero()
        }
    }
}

/// Edges whose two directions are used unequally often, corners compared by position (so an
/// unwelded mesh that is closed counts none).
fn open_edges(mesh: &IndexedMesh) -> usize {
    let key = |i: u32| mesh.positions[i as usize].to_array().map(f64::to_bits);
    let mut balance: std::collections::HashMap<([u64; 3], [u64; 3]), i64> =
        std::collections::HashMap::with_capacity(mesh.triangles.len() * 3 / 2);
    for t in &mesh.triangles {
        for e in 0..3 {
            let (a, b) = (key(t[e]), key(t[(e + 1) % 3]));
            if a == b {
                continue;
            }
            let (k, d) = if a < b { ((a, b), 1) } else { ((b, a), -1) };
            *balance.entry(k).or_default() += d;
        }
    }
    balance.values().filter(|&&d| d != 0).count()
}

/// Triangles of vertices and polygonal faces: indices checked, triangles as given, polygons
/// triangulated (with distinct corners).
fn triangulate_faces(
    vertices: &[DVec3],
    faces: &[Vec<u32>],
) -> Result<IndexedMesh, MeshSolidError> {
    if faces.is_empty() {
        return Err(PolyhedronError::NoFaces.into());
    }
    if let Some(vertex) = vertices
        .iter()
        .position(|v| !v.is_finite() || v.abs().max_element() > crate::primitive::MAX_MAGNITUDE)
    {
        return Err(PolyhedronError::NonFiniteVertex { vertex }.into());
    }
    let mut triangles = Vec::with_capacity(faces.len());
    for (face, corners) in faces.iter().enumerate() {
        if corners.len() < 3 {
            let corners = corners.len();
            return Err(PolyhedronError::TooFewCorners { face, corners }.into());
        }
        let count = vertices.len();
        if let Some(&index) = corners.iter().find(|&&i| i as usize >= count) {
            return Err(PolyhedronError::IndexOutOfRange { face, index, count }.into());
        }
        triangulate_face(vertices, corners, &mut triangles)
            .map_err(|problem| PolyhedronError::BadFace { face, problem })?;
    }
    Ok(IndexedMesh::new(vertices.to_vec(), triangles))
}

impl PartialEq for MeshSolid {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.source, &other.source) || self.source == other.source
    }
}

impl std::fmt::Debug for MeshSolid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MeshSolid")
            .field("source", &self.source.name())
            .field("triangles", &self.triangle_count())
            .field("bbox", &self.tree.bbox)
            .finish()
    }
}

impl Shape for MeshSolid {
    fn value(&self, p: DVec3) -> f64 {
        self.signed(p, self.tree.nearest(p).distance2.sqrt())
    }

    /// The values of [`Shape::value`], with the sign of a closed mesh's points taken from an
    /// earlier point of the batch where that is sure (the `sign_balls` module): the winding number,
    /// most of a mesh solid's cost, is then computed only for points near the surface; each
    /// nearest-point search starts from the previous point's triangle (the same distance: the
    /// minimum of the same exact point–triangle distances).
    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let mut balls = SignBalls::default();
        let mut hint = None;
        for i in 0..out.len() {
            let p = DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64);
            let near = self.nearest_after(p, hint);
            hint = Some(near.slot);
            out[i] = self.signed_with(p, near.distance2.sqrt(), &mut balls) as f32;
        }
    }

    fn values_gradients(&self, pts: &[DVec3], values: &mut [f64], gradients: &mut [DVec3]) {
        // No hints here: on exact ties of nearest triangles the gradient depends on which one is
        // found, and it must not depend on the batch.
        let mut balls = SignBalls::default();
        for ((p, v), g) in pts.iter().zip(values.iter_mut()).zip(gradients.iter_mut()) {
            let near = self.tree.nearest(*p);
            let d = near.distance2.sqrt();
            *v = self.signed_with(*p, d, &mut balls);
            *g = self.gradient_from(*p, &near, *v);
        }
    }

    fn gradient(&self, p: DVec3) -> DVec3 {
        let near = self.tree.nearest(p);
        let value = self.signed(p, near.distance2.sqrt());
        self.gradient_from(p, &near, value)
    }

    fn interval(&self, b: &Aabb) -> Interval {
        if self.open_edges == 0 {
            return lipschitz_interval(self, b);
        }
        // The sign may flip anywhere (see the module docs); the distance is 1-Lipschitz.
        let reach = self.value(b.center()).abs() + b.half_extents().length();
        Interval::new(-reach, reach)
    }

    fn bbox(&self) -> Aabb {
        self.tree.bbox
    }

    fn validate(&self) -> Result<(), PrimitiveError> {
        // Checked when made: every mesh solid is valid.
        Ok(())
    }
}
