//! Conversion back to face lists: polygon faces, and triangles for an [`IndexedMesh`].

use super::HalfEdgeMesh;
use crate::IndexedMesh;

impl HalfEdgeMesh {
    /// The faces as vertex loops in input order (the input faces, exactly).
    pub fn faces(&self) -> Vec<Vec<u32>> {
        self.face_ids()
            .map(|f| self.face_vertices(f).map(|v| v.0).collect())
            .collect()
    }

    /// True when every face is a triangle.
    pub fn is_triangle_mesh(&self) -> bool {
        self.face_ids()
            .all(|f| self.face_half_edges(f).count() == 3)
    }

    /// The mesh as triangles, with all positions (isolated vertices kept, indices unchanged).
    ///
    /// Triangles come back exactly as input. Larger polygons are fan-triangulated from their first
    /// vertex, which is correct for convex (and star-shaped from that vertex) planar polygons only;
    /// use [`HalfEdgeMesh::faces`] to triangulate others yourself.
    pub fn to_indexed(&self) -> IndexedMesh {
        let mut triangles = Vec::with_capacity(self.face_count());
        for f in self.face_ids() {
            let mut vertices = self.face_vertices(f).map(|v| v.0);
            let (Some(first), Some(mut previous)) = (vertices.next(), vertices.next()) else {
                continue;
            };
            for v in vertices {
                triangles.push([first, previous, v]);
                previous = v;
            }
        }
        IndexedMesh::new(self.positions.clone(), triangles)
    }
}
