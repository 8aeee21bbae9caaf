//! Counts of a polygon mesh with its real faces (quads, pentagons… as the file has them): V, E, F
//! and the Euler characteristic `V − E + F`, as the Platonic table and the subdivision formulas
//! count them, where the triangle report counts the triangles the faces are split into.

use serde::Serialize;

/// V, E, F of a polygon mesh; faces are vertex loops (see [`PolygonCounts::of`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct PolygonCounts {
    /// Vertices used by at least one face.
    pub vertices: usize,
    /// Distinct undirected edges of the face loops.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// `vertices − edges + faces` (2 for a closed surface of genus 0).
    pub euler_characteristic: i64,
    /// Faces with more than three corners.
    pub polygons: usize,
    /// Corners of the largest face.
    pub largest_face: usize,
    /// The sum of the face degrees (corners of all faces).
    pub corners: usize,
}

impl PolygonCounts {
    /// The counts of the faces `faces` (vertex loops; indices at or past `vertex_count` and
    /// faces of fewer than three corners are counted as they are, never followed).
    pub fn of(vertex_count: usize, faces: &[Vec<u32>]) -> PolygonCounts {
        let mut used = vec![false; vertex_count];
        let mut edges: Vec<(u32, u32)> = Vec::with_capacity(faces.iter().map(Vec::len).sum());
        for face in faces {
            for (k, &a) in face.iter().enumerate() {
                if let Some(u) = used.get_mut(a as usize) {
                    *u = true;
                }
                let b = face[(k + 1) % face.len()];
                if a != b {
                    edges.push((a.min(b), a.max(b)));
                }
            }
        }
        edges.sort_unstable();
        edges.dedup();
        let vertices = used.iter().filter(|&&u| u).count();
        PolygonCounts {
            vertices,
            edges: edges.len(),
            faces: faces.len(),
            euler_characteristic: vertices as i64 - edges.len() as i64 + faces.len() as i64,
            polygons: faces.iter().filter(|f| f.len() > 3).count(),
            largest_face: faces.iter().map(Vec::len).max().unwrap_or(0),
            corners: faces.iter().map(Vec::len).sum(),
        }
    }

    /// One line: `polygon mesh: V 8, E 12, F 6, V − E + F = 2 (6 of more than 3 corners, largest
    /// 4)`.
    pub fn to_text(&self) -> String {
        format!(
            "polygon mesh: V {}, E {}, F {}, V - E + F = {} ({} faces of more than 3 corners, \
             largest {})",
            self.vertices,
            self.edges,
            self.faces,
            self.euler_characteristic,
            self.polygons,
            self.largest_face
        )
    }
}

#[cfg(test)]
mod tests {
    use super::PolygonCounts;

    #[test]
    fn a_cube_of_quads_and_a_pyramid() {
        let cube = super::super::test_meshes::cube_quads();
        let c = PolygonCounts::of(8, &cube);
        assert_eq!(
            (c.vertices, c.edges, c.faces, c.euler_characteristic),
            (8, 12, 6, 2)
        );
        assert_eq!((c.polygons, c.largest_face, c.corners), (6, 4, 24));
        // A square pyramid with an unused vertex 5: V 5, E 8, F 5.
        let faces = vec![
            vec![0, 3, 2, 1],
            vec![0, 1, 4],
            vec![1, 2, 4],
            vec![2, 3, 4],
            vec![3, 0, 4],
        ];
        let p = PolygonCounts::of(6, &faces);
        assert_eq!(
            (p.vertices, p.edges, p.faces, p.euler_characteristic),
            (5, 8, 5, 2)
        );
        assert_eq!((p.polygons, p.largest_face), (1, 4));
        // Out-of-range indices are counted as edges but not as vertices; nothing panics.
        let bad = PolygonCounts::of(2, &[vec![0, 1, 7]]);
        assert_eq!((bad.vertices, bad.edges, bad.faces), (2, 3, 1));
    }
}
