//! Construction of a [`HalfEdgeMesh`] from triangles or polygons.
//!
//! 1. Check every face: indices in range, at least three vertices, no vertex repeated.
//! 2. Lay out the interior half-edges face by face and sort them by undirected edge (the shared
//!    edge table of the topology module).
//! 3. Reject edges of more than two faces, edges used twice in the same direction and vertices
//!    whose faces form several fans, reporting all of them.
//! 4. Pair twins; give each edge of only one face a boundary half-edge and link those into loops.

use glam::DVec3;

use super::{FaceId, HalfEdge, HalfEdgeError, HalfEdgeId, HalfEdgeMesh, VertexId};
use crate::IndexedMesh;
use crate::topology::{CornerLoops, EdgeKind, EdgeTable, fan_counts};

/// "No half-edge" while building.
const UNSET: u32 = u32::MAX;

impl HalfEdgeMesh {
    /// The half-edge mesh of a triangle mesh (positions are copied).
    ///
    /// # Errors
    /// See [`HalfEdgeError`]: out-of-range indices, degenerate triangles, non-manifold or
    /// inconsistently oriented input. Open meshes are fine (boundary loops).
    pub fn from_indexed(mesh: &IndexedMesh) -> Result<Self, HalfEdgeError> {
        build(mesh.positions.clone(), &mesh.triangles)
    }

    /// The half-edge mesh of polygons of any size ≥ 3, each wound counter-clockwise seen from
    /// outside.
    ///
    /// # Errors
    /// As [`HalfEdgeMesh::from_indexed`].
    pub fn from_polygons(positions: Vec<DVec3>, faces: &[Vec<u32>]) -> Result<Self, HalfEdgeError> {
        build(positions, faces)
    }

    /// The half-edge mesh of faces stored in any way that gives each face's vertex loop:
    /// fixed-size arrays (`[u32; 4]` quads), vectors... Checks as [`HalfEdgeMesh::from_indexed`].
    ///
    /// # Errors
    /// As [`HalfEdgeMesh::from_indexed`].
    pub fn from_faces<F: AsRef<[u32]>>(
        positions: Vec<DVec3>,
        faces: &[F],
    ) -> Result<Self, HalfEdgeError> {
        build(positions, faces)
    }
}

/// Builds the mesh; `faces` are vertex loops.
fn build<F: AsRef<[u32]>>(
    positions: Vec<DVec3>,
    faces: &[F],
) -> Result<HalfEdgeMesh, HalfEdgeError> {
    check_sizes(positions.len(), faces)?;
    for (f, face) in faces.iter().enumerate() {
        check_face(f, face.as_ref(), positions.len())?;
    }
    let loops = FaceLoops::new(faces);
    let table = EdgeTable::build(&loops);
    check_manifold(&loops, &table, positions.len())?;
    let mut half_edges = loops.interior_half_edges();
    add_twins_and_boundary(&loops, &table, &mut half_edges);
    link_boundary_loops(&mut half_edges, loops.corner_count(), positions.len())?;
    let vertex_half_edge = vertex_half_edges(&half_edges, positions.len());
    Ok(HalfEdgeMesh {
        positions,
        half_edges,
        vertex_half_edge,
        face_half_edge: loops.face_start.iter().map(|&h| HalfEdgeId(h)).collect(),
    })
}

/// Ensures vertices, faces and half-edges (at most twice the corners) fit 32-bit ids.
fn check_sizes<F: AsRef<[u32]>>(vertex_count: usize, faces: &[F]) -> Result<(), HalfEdgeError> {
    let limit = UNSET as usize;
    let corners: usize = faces.iter().map(|f| f.as_ref().len()).sum();
    let too_large = |what, count| Err(HalfEdgeError::TooLarge { what, count });
    if vertex_count > limit {
        return too_large("vertices", vertex_count);
    }
    if faces.len() > limit {
        return too_large("faces", faces.len());
    }
    if corners.saturating_mul(2) > limit {
        return too_large("half-edges", corners.saturating_mul(2));
    }
    Ok(())
}

/// Checks one face: enough vertices, all in range, none repeated.
fn check_face(face: usize, vertices: &[u32], vertex_count: usize) -> Result<(), HalfEdgeError> {
    if vertices.len() < 3 {
        return Err(HalfEdgeError::DegenerateFace { face });
    }
    if let Some(&index) = vertices.iter().find(|&&v| v as usize >= vertex_count) {
        return Err(HalfEdgeError::IndexOutOfRange {
            face,
            index,
            vertex_count,
        });
    }
    if has_repeat(vertices) {
        return Err(HalfEdgeError::DegenerateFace { face });
    }
    Ok(())
}

/// True when some vertex occurs twice (quadratic for small faces, sorting for large ones).
fn has_repeat(vertices: &[u32]) -> bool {
    if vertices.len() <= 16 {
        return vertices
            .iter()
            .enumerate()
            .any(|(i, v)| vertices[i + 1..].contains(v));
    }
    let mut sorted = vertices.to_vec();
    sorted.sort_unstable();
    sorted.windows(2).any(|w| w[0] == w[1])
}

/// The faces as corner loops: corner `c` is interior half-edge `c`.
struct FaceLoops {
    origin: Vec<u32>,
    next: Vec<u32>,
    prev: Vec<u32>,
    face: Vec<u32>,
    face_start: Vec<u32>,
}

impl FaceLoops {
    /// Lays out the (checked) faces' corners consecutively.
    fn new<F: AsRef<[u32]>>(faces: &[F]) -> Self {
        let corners: usize = faces.iter().map(|f| f.as_ref().len()).sum();
        let mut loops = Self {
            origin: Vec::with_capacity(corners),
            next: Vec::with_capacity(corners),
            prev: Vec::with_capacity(corners),
            face: Vec::with_capacity(corners),
            face_start: Vec::with_capacity(faces.len()),
        };
        for (f, face) in faces.iter().enumerate() {
            loops.push_face(f as u32, face.as_ref());
        }
        loops
    }

    /// Appends one face loop.
    fn push_face(&mut self, f: u32, vertices: &[u32]) {
        let start = self.origin.len() as u32;
        let k = vertices.len() as u32;
        self.face_start.push(start);
        for (i, &v) in (0u32..).zip(vertices) {
            self.origin.push(v);
            self.next.push(start + (i + 1) % k);
            self.prev.push(start + (i + k - 1) % k);
            self.face.push(f);
        }
    }

    /// The interior half-edges with face loops set and twins still unset.
    fn interior_half_edges(&self) -> Vec<HalfEdge> {
        (0..self.origin.len())
            .map(|c| HalfEdge {
                origin: VertexId(self.origin[c]),
                twin: HalfEdgeId(UNSET),
                next: HalfEdgeId(self.next[c]),
                prev: HalfEdgeId(self.prev[c]),
                face: Some(FaceId(self.face[c])),
            })
            .collect()
    }
}

impl CornerLoops for FaceLoops {
    fn corner_count(&self) -> usize {
        self.origin.len()
    }

    fn origin(&self, corner: usize) -> u32 {
        self.origin[corner]
    }

    fn next(&self, corner: usize) -> usize {
        self.next[corner] as usize
    }
}

/// Collects every non-manifold edge, multi-fan vertex and inconsistent edge.
fn check_manifold(
    loops: &FaceLoops,
    table: &EdgeTable,
    vertex_count: usize,
) -> Result<(), HalfEdgeError> {
    let mut edges = Vec::new();
    let mut inconsistent_edges = Vec::new();
    for edge in table.edges() {
        match edge.kind(loops) {
            EdgeKind::NonManifold => edges.push(edge.vertices()),
            EdgeKind::Inconsistent => inconsistent_edges.push(edge.vertices()),
            EdgeKind::Boundary | EdgeKind::Manifold => {}
        }
    }
    let vertices: Vec<u32> = fan_counts(loops, table, vertex_count)
        .iter()
        .enumerate()
        .filter(|&(_, &fans)| fans > 1)
        .map(|(v, _)| v as u32)
        .collect();
    if edges.is_empty() && vertices.is_empty() && inconsistent_edges.is_empty() {
        Ok(())
    } else {
        Err(HalfEdgeError::NonManifold {
            edges,
            vertices,
            inconsistent_edges,
        })
    }
}

/// Pairs the two half-edges of every interior edge and appends a boundary twin (no face, loop
/// links unset) for every edge of one face. Requires a manifold, consistently oriented table.
fn add_twins_and_boundary(loops: &FaceLoops, table: &EdgeTable, half_edges: &mut Vec<HalfEdge>) {
    for edge in table.edges() {
        let mut corners = edge.corners();
        let (Some(a), b) = (corners.next(), corners.next()) else {
            continue;
        };
        let twin = match b {
            Some(b) => b,
            None => {
                half_edges.push(HalfEdge {
                    origin: VertexId(loops.dest(a)),
                    twin: HalfEdgeId(a as u32),
                    next: HalfEdgeId(UNSET),
                    prev: HalfEdgeId(UNSET),
                    face: None,
                });
                half_edges.len() - 1
            }
        };
        half_edges[a].twin = HalfEdgeId(twin as u32);
        half_edges[twin].twin = HalfEdgeId(a as u32);
    }
}

/// Links the boundary half-edges (from `first` on) into loops: each one's `next` is the boundary
/// half-edge leaving the vertex it ends at (unique at a single-fan vertex).
fn link_boundary_loops(
    half_edges: &mut [HalfEdge],
    first: usize,
    vertex_count: usize,
) -> Result<(), HalfEdgeError> {
    let mut leaving = vec![UNSET; vertex_count];
    for b in first..half_edges.len() {
        leaving[half_edges[b].origin.index()] = b as u32;
    }
    for b in first..half_edges.len() {
        let end = half_edges[half_edges[b].twin.index()].origin;
        let next = leaving[end.index()];
        if next == UNSET {
            // Unreachable after `check_manifold`; reported rather than panicking.
            return Err(HalfEdgeError::NonManifold {
                edges: vec![],
                vertices: vec![end.0],
                inconsistent_edges: vec![],
            });
        }
        half_edges[b].next = HalfEdgeId(next);
        half_edges[next as usize].prev = HalfEdgeId(b as u32);
    }
    Ok(())
}

/// One outgoing half-edge per vertex, preferring a boundary one.
fn vertex_half_edges(half_edges: &[HalfEdge], vertex_count: usize) -> Vec<Option<HalfEdgeId>> {
    let mut out = vec![None; vertex_count];
    for (h, he) in half_edges.iter().enumerate() {
        let slot = &mut out[he.origin.index()];
        if slot.is_none() || he.face.is_none() {
            *slot = Some(HalfEdgeId(h as u32));
        }
    }
    out
}
