//! The exact polyhedron: vertices and polygonal faces (counter-clockwise seen from outside), its
//! triangulation, counts (V, E, F, Euler characteristic), volume, and the closed-manifold check
//! with the cycle of faces around each vertex (used by the dual).

use super::PolyhedronError;
use crate::IndexedMesh;
use crate::triangulate::triangulate_face;
use glam::DVec3;

/// A polyhedron with polygonal faces whose corners are counter-clockwise seen from outside.
///
/// Built only through [`Polyhedron::new`] (or the Platonic, dual and prism constructors), so every
/// face has at least three distinct, in-range corners, every coordinate is finite and every face
/// has a triangulation (kept, so [`Polyhedron::to_indexed`] cannot fail). Closedness is not
/// required; [`Polyhedron::check_closed`] tests it.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyhedron {
    vertices: Vec<DVec3>,
    faces: Vec<Vec<u32>>,
    triangles: Vec<[u32; 3]>,
}

/// A directed edge of a face: `from → to`, and which face it belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct HalfEdge {
    from: u32,
    to: u32,
    face: u32,
}

impl Polyhedron {
    /// A polyhedron from vertex positions and faces (vertex indices, counter-clockwise seen from
    /// outside). Polygonal faces are triangulated by constrained Delaunay triangulation in the
    /// plane of their Newell normal.
    pub fn new(vertices: Vec<DVec3>, faces: Vec<Vec<u32>>) -> Result<Self, PolyhedronError> {
        if faces.is_empty() {
            return Err(PolyhedronError::NoFaces);
        }
        if let Some(vertex) = vertices.iter().position(|v| !v.is_finite()) {
            return Err(PolyhedronError::NonFiniteVertex { vertex });
        }
        let mut triangles = Vec::new();
        let mut sorted: Vec<u32> = Vec::new();
        for (face, corners) in faces.iter().enumerate() {
            if corners.len() < 3 {
                return Err(PolyhedronError::TooFewCorners {
                    face,
                    corners: corners.len(),
                });
            }
            if let Some(&index) = corners.iter().find(|&&i| i as usize >= vertices.len()) {
                return Err(PolyhedronError::IndexOutOfRange {
                    face,
                    index,
                    count: vertices.len(),
                });
            }
            sorted.clear();
            sorted.extend_from_slice(corners);
            sorted.sort_unstable();
            if let Some(w) = sorted.windows(2).find(|w| w[0] == w[1]) {
                return Err(PolyhedronError::RepeatedCorner { face, index: w[0] });
            }
            triangulate_face(&vertices, corners, &mut triangles)
                .map_err(|problem| PolyhedronError::BadFace { face, problem })?;
        }
        Ok(Self {
            vertices,
            faces,
            triangles,
        })
    }

    /// Vertex positions (some may be unused by the faces).
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// Faces as vertex indices, counter-clockwise seen from outside.
    pub fn faces(&self) -> &[Vec<u32>] {
        &self.faces
    }

    /// The faces' triangulation (counter-clockwise seen from outside).
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// V: vertices used by at least one face.
    pub fn vertex_count(&self) -> usize {
        let mut used = vec![false; self.vertices.len()];
        for &i in self.faces.iter().flatten() {
            used[i as usize] = true;
        }
        used.iter().filter(|&&u| u).count()
    }

    /// E: distinct undirected edges of the faces.
    pub fn edge_count(&self) -> usize {
        let mut edges: Vec<(u32, u32)> = self
            .half_edges()
            .map(|h| (h.from.min(h.to), h.from.max(h.to)))
            .collect();
        edges.sort_unstable();
        edges.dedup();
        edges.len()
    }

    /// F: number of faces.
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    /// `V − E + F` (2 for a closed surface of genus 0, `2 − 2g` in general).
    pub fn euler_characteristic(&self) -> i64 {
        self.vertex_count() as i64 - self.edge_count() as i64 + self.face_count() as i64
    }

    /// The triangulated polyhedron as an indexed mesh (all vertices kept, unused ones too).
    pub fn to_indexed(&self) -> IndexedMesh {
        IndexedMesh::new(self.vertices.clone(), self.triangles.clone())
    }

    /// Signed volume by the divergence theorem (positive for outward faces of a closed surface).
    pub fn volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertices[i as usize]);
                a.dot(b.cross(c))
            })
            .sum::<f64>()
            / 6.0
    }

    /// The same polyhedron with every vertex multiplied by `factor` (a positive number keeps the
    /// orientation).
    pub fn scaled(&self, factor: f64) -> Polyhedron {
        Polyhedron {
            vertices: self.vertices.iter().map(|v| *v * factor).collect(),
            faces: self.faces.clone(),
            triangles: self.triangles.clone(),
        }
    }

    /// Checks that the faces form a closed, consistently oriented 2-manifold: every directed edge
    /// is used once, its opposite exists, and the faces around every used vertex form one fan.
    pub fn check_closed(&self) -> Result<(), PolyhedronError> {
        self.vertex_cycles().map(|_| ())
    }

    fn half_edges(&self) -> impl Iterator<Item = HalfEdge> + '_ {
        self.faces.iter().enumerate().flat_map(|(f, corners)| {
            let next = corners.iter().skip(1).chain(corners.first());
            corners.iter().zip(next).map(move |(&from, &to)| HalfEdge {
                from,
                to,
                face: f as u32,
            })
        })
    }

    /// For every vertex, the faces around it in counter-clockwise order seen from outside (empty
    /// for unused vertices), or why the surface is not a closed oriented manifold.
    pub(crate) fn vertex_cycles(&self) -> Result<Vec<Vec<u32>>, PolyhedronError> {
        let mut edges: Vec<HalfEdge> = self.half_edges().collect();
        edges.sort_unstable();
        if let Some(w) = edges
            .windows(2)
            .find(|w| (w[0].from, w[0].to) == (w[1].from, w[1].to))
        {
            return Err(PolyhedronError::RepeatedEdge {
                from: w[0].from,
                to: w[0].to,
            });
        }
        let find = |from: u32, to: u32| {
            edges
                .binary_search_by(|h| (h.from, h.to).cmp(&(from, to)))
                .ok()
                .map(|i| edges[i])
        };
        if let Some(h) = edges.iter().find(|h| find(h.to, h.from).is_none()) {
            return Err(PolyhedronError::OpenEdge {
                from: h.from,
                to: h.to,
            });
        }
        let mut cycles = vec![Vec::new(); self.vertices.len()];
        let mut start = 0;
        while start < edges.len() {
            let v = edges[start].from;
            let end = start + edges[start..].iter().take_while(|h| h.from == v).count();
            let degree = end - start;
            let cycle = &mut cycles[v as usize];
            // Walk from face to face: the edge entering `v` in the current face is `u → v`;
            // the next face counter-clockwise holds the opposite edge `v → u`.
            let mut face = edges[start].face;
            while cycle.len() < degree {
                cycle.push(face);
                let corners = &self.faces[face as usize];
                let at = corners.iter().position(|&c| c == v).unwrap_or(0);
                let u = corners[(at + corners.len() - 1) % corners.len()];
                match find(v, u) {
                    Some(h) if h.face != edges[start].face => face = h.face,
                    _ => break,
                }
            }
            if cycle.len() != degree {
                return Err(PolyhedronError::NonManifoldVertex { vertex: v });
            }
            start = end;
        }
        Ok(cycles)
    }
}
