//! A mesh's defects as an ASCII PLY other viewers open (MeshLab, CloudCompare, Blender,
//! trimesh): the offending faces as `face` elements and the offending edges as `edge` elements,
//! each with an 8-bit colour (the same as the picture's legend, [`super::defects`]) and a `class`
//! code; vertices are only those the items use, numbered in first-use order, coloured by the first
//! item using them (non-manifold vertices in their own colour). An element without items is left
//! out of the header.
//!
//! Classes: 0 boundary edge, 1 non-manifold edge, 2 non-manifold vertex (listed as vertices
//! whose `class` is 2), 3 flipped face, 4 self-intersecting face. A face in both face classes
//! is written once per class, so the count of each class equals the report's.

use super::defects::{
    BOUNDARY_EDGE, INCONSISTENT_FACE, NON_MANIFOLD_EDGE, NON_MANIFOLD_VERTEX,
    SELF_INTERSECTING_FACE,
};
use crate::IndexedMesh;
use crate::io::{MeshIoError, write_atomic};
use crate::topology::DefectItems;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

/// Code of edges used by one triangle.
pub const CLASS_BOUNDARY_EDGE: u8 = 0;
/// Code of edges used by more than two triangles.
pub const CLASS_NON_MANIFOLD_EDGE: u8 = 1;
/// Code of non-manifold vertices.
pub const CLASS_NON_MANIFOLD_VERTEX: u8 = 2;
/// Code of flipped (inconsistently oriented) faces.
pub const CLASS_INCONSISTENT_FACE: u8 = 3;
/// Code of self-intersecting faces.
pub const CLASS_SELF_INTERSECTING_FACE: u8 = 4;
/// Code of vertices that only carry a face or an edge.
pub const CLASS_NONE: u8 = 255;

/// The colour of a class code.
pub fn class_color(class: u8) -> [u8; 3] {
    match class {
        CLASS_BOUNDARY_EDGE => BOUNDARY_EDGE,
        CLASS_NON_MANIFOLD_EDGE => NON_MANIFOLD_EDGE,
        CLASS_NON_MANIFOLD_VERTEX => NON_MANIFOLD_VERTEX,
        CLASS_INCONSISTENT_FACE => INCONSISTENT_FACE,
        CLASS_SELF_INTERSECTING_FACE => SELF_INTERSECTING_FACE,
        _ => [128, 128, 128],
    }
}

/// The vertices the items use, in first-use order, with their colour and class.
#[derive(Default)]
struct Vertices {
    index: HashMap<u32, u32>,
    list: Vec<(u32, [u8; 3], u8)>,
}

impl Vertices {
    fn add(&mut self, v: u32, color: [u8; 3], class: u8) -> u32 {
        let next = self.list.len() as u32;
        *self.index.entry(v).or_insert_with(|| {
            self.list.push((v, color, class));
            next
        })
    }
}

/// The PLY text of `items` of `mesh` (see the module docs); items naming a vertex the mesh lacks
/// are left out.
pub fn defects_ply(mesh: &IndexedMesh, items: &DefectItems) -> String {
    let n = mesh.positions.len() as u32;
    let mut vertices = Vertices::default();
    for &v in &items.non_manifold_vertices {
        if v < n {
            vertices.add(v, NON_MANIFOLD_VERTEX, CLASS_NON_MANIFOLD_VERTEX);
        }
    }
    let mut faces = Vec::new();
    for (list, class) in [
        (&items.inconsistent_faces, CLASS_INCONSISTENT_FACE),
        (&items.self_intersecting_faces, CLASS_SELF_INTERSECTING_FACE),
    ] {
        for &t in list {
            let Some(tri) = mesh.triangles.get(t as usize) else {
                continue;
            };
            if tri.iter().any(|&v| v >= n) {
                continue;
            }
            let color = class_color(class);
            faces.push((tri.map(|v| vertices.add(v, color, CLASS_NONE)), class));
        }
    }
    let mut edges = Vec::new();
    for (list, class) in [
        (&items.boundary_edges, CLASS_BOUNDARY_EDGE),
        (&items.non_manifold_edges, CLASS_NON_MANIFOLD_EDGE),
    ] {
        for e in list {
            if e.iter().any(|&v| v >= n) {
                continue;
            }
            let color = class_color(class);
            edges.push((e.map(|v| vertices.add(v, color, CLASS_NONE)), class));
        }
    }
    // Elements without items are left out of the header (some readers refuse an empty one).
    let mut out = String::from(
        "ply\nformat ascii 1.0\n\
         comment solidkit check --export-defects: classes 0 boundary edge, 1 non-manifold edge, \
         2 non-manifold vertex, 3 flipped face, 4 self-intersecting face, 255 none\n",
    );
    let colour_and_class = "property uchar red\nproperty uchar green\nproperty uchar blue\n\
                            property uchar class\n";
    let _ = write!(
        out,
        "element vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
         {colour_and_class}",
        vertices.list.len()
    );
    if !faces.is_empty() {
        let _ = write!(
            out,
            "element face {}\nproperty list uchar int vertex_indices\n{colour_and_class}",
            faces.len()
        );
    }
    if !edges.is_empty() {
        let _ = write!(
            out,
            "element edge {}\nproperty int vertex1\nproperty int vertex2\n{colour_and_class}",
            edges.len()
        );
    }
    out.push_str("end_header\n");
    for &(v, [r, g, b], class) in &vertices.list {
        let p = mesh.positions[v as usize];
        let _ = writeln!(out, "{} {} {} {r} {g} {b} {class}", p.x, p.y, p.z);
    }
    for ([a, b, c], class) in faces {
        let [r, g, bl] = class_color(class);
        let _ = writeln!(out, "3 {a} {b} {c} {r} {g} {bl} {class}");
    }
    for ([a, b], class) in edges {
        let [r, g, bl] = class_color(class);
        let _ = writeln!(out, "{a} {b} {r} {g} {bl} {class}");
    }
    out
}

/// Writes [`defects_ply`] to `path`, atomically.
pub fn write_defects_ply(
    path: &Path,
    mesh: &IndexedMesh,
    items: &DefectItems,
) -> Result<(), MeshIoError> {
    let text = defects_ply(mesh, items);
    write_atomic(path, |out| out.write_all(text.as_bytes()))
}
