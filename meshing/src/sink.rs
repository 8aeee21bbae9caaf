//! Output sinks for polygonizers: where vertices and triangles go, so a polygonizer never picks an
//! output format (an [`IndexedMesh`] is the standard sink).

use crate::IndexedMesh;
use glam::DVec3;

/// Receives a polygonizer's output: vertices first, then triangles referring to the ids returned.
pub trait MeshSink {
    /// Hint of how much is coming.
    fn reserve(&mut self, _vertices: usize, _triangles: usize) {}
    /// Adds a vertex; returns its id for use in triangles.
    fn add_vertex(&mut self, p: DVec3) -> u32;
    /// Adds a triangle, counter-clockwise seen from outside.
    fn add_triangle(&mut self, t: [u32; 3]);
    /// Adds triangles in order (as [`MeshSink::add_triangle`] on each).
    fn add_triangles(&mut self, ts: &[[u32; 3]]) {
        for &t in ts {
            self.add_triangle(t);
        }
    }
}

impl MeshSink for IndexedMesh {
    fn reserve(&mut self, vertices: usize, triangles: usize) {
        self.positions.reserve(vertices);
        self.triangles.reserve(triangles);
    }

    fn add_vertex(&mut self, p: DVec3) -> u32 {
        self.positions.push(p);
        (self.positions.len() - 1) as u32
    }

    fn add_triangle(&mut self, t: [u32; 3]) {
        self.triangles.push(t);
    }

    fn add_triangles(&mut self, ts: &[[u32; 3]]) {
        self.triangles.extend_from_slice(ts);
    }
}
