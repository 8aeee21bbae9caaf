//! The 1-to-4 split of the triangle schemes (Loop, butterfly): old vertices keep their ids, the
//! vertex of edge `e` gets id `V + e`.

use super::edges::EdgeIndex;
use crate::halfedge::HalfEdgeMesh;

/// Every triangle `(a, b, c)` with edge vertices `ab`, `bc`, `ca` as the corner triangles
/// `(a, ab, ca)`, `(b, bc, ab)`, `(c, ca, bc)` and the middle one `(ab, bc, ca)`, wound as the
/// triangle. The mesh must be a triangle mesh.
pub(super) fn split_triangles(mesh: &HalfEdgeMesh, edges: &EdgeIndex) -> Vec<[u32; 3]> {
    let base = mesh.vertex_count() as u32;
    let mut triangles = Vec::with_capacity(4 * mesh.face_count());
    for f in mesh.face_ids() {
        let h0 = mesh.face_half_edge(f);
        let h1 = mesh.half_edge(h0).next;
        let h2 = mesh.half_edge(h1).next;
        let [a, b, c] = [h0, h1, h2].map(|h| mesh.half_edge(h).origin.0);
        let [ab, bc, ca] = [h0, h1, h2].map(|h| base + edges.of(h));
        triangles.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
    }
    triangles
}
