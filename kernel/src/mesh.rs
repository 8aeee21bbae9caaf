//! The indexed triangle mesh: the common currency between exact tessellations (kernel),
//! polygonizers, file readers and writers, the half-edge mesh and the topology report (meshing).

use glam::DVec3;

/// A triangle mesh as a vertex array and triangles of indices into it.
///
/// Triangles are wound counter-clockwise seen from outside (right-hand rule normal points out of the
/// solid). Nothing here is validated: indices are checked by the readers that build meshes, and the
/// topology (closed, manifold, oriented) is measured by `solidkit_meshing::TopologyReport`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct IndexedMesh {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Triangles as indices into `positions`.
    pub triangles: Vec<[u32; 3]>,
}

impl IndexedMesh {
    /// A mesh from positions and triangles.
    pub fn new(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Self {
        Self {
            positions,
            triangles,
        }
    }

    /// Number of vertices in the vertex array (referenced or not).
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// The three corner positions of triangle `t`.
    pub fn triangle_positions(&self, t: usize) -> [DVec3; 3] {
        let [a, b, c] = self.triangles[t];
        [
            self.positions[a as usize],
            self.positions[b as usize],
            self.positions[c as usize],
        ]
    }

    /// True when every triangle index is inside the vertex array.
    pub fn indices_in_range(&self) -> bool {
        let n = self.positions.len();
        self.triangles
            .iter()
            .all(|t| t.iter().all(|&i| (i as usize) < n))
    }
}
