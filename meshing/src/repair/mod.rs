//! Mesh repair (`solidkit repair`): turn a broken triangle mesh into a closed, oriented
//! 2-manifold.
//!
//! [`repair_minimal`] keeps the geometry: it welds vertices within a tolerance (`weld.rs`),
//! removes repeated-index, zero-area and duplicate faces (`faces.rs`), cuts non-manifold edges and
//! splits non-manifold vertices into one copy per fan (`split.rs`), orients each shell
//! consistently (`orient.rs`: breadth-first over manifold edges), fills holes (`holes.rs`), drops
//! shells that enclose no volume and turns each remaining shell outward, or inward for cavities,
//! by signed volume and nesting depth (`nesting.rs`: a ray per shell, `rays.rs`), and finally
//! moves the copies of split vertices apart into their own shells (`separate.rs`). No vertex
//! ends further than the weld tolerance from the input vertex it comes from.
//!
//! [`rebuild`] (`rebuild.rs`) remeshes the winding-number solid of a mesh by dual contouring,
//! which is closed, manifold and free of self-intersections by construction, and measures the
//! Hausdorff distance to the input. Every step is iterative (work lists, union-find, queues).

mod cycles;
mod edges;
mod faces;
mod holes;
mod nesting;
mod orient;
mod rays;
mod rebuild;
mod separate;
mod split;
mod weld;

#[cfg(test)]
mod tests;

use crate::IndexedMesh;
use crate::topology::EdgeTable;
use glam::DVec3;

pub use rebuild::{RebuildOptions, Rebuilt, rebuild};
pub use weld::{WeldedMesh, weld_mesh};

/// Why a mesh cannot be repaired.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RepairError {
    /// No triangle has three distinct, in-range corners.
    #[error("the mesh has no usable triangle ({faces} faces, all degenerate or out of range)")]
    NoUsableTriangles {
        /// Faces in the input.
        faces: usize,
    },
    /// A vertex coordinate is NaN or infinite.
    #[error("vertex {0} has a non-finite coordinate")]
    NonFinite(usize),
    /// The weld tolerance is negative or not finite.
    #[error("weld tolerance {0} must be finite and not negative")]
    BadWeld(f64),
    /// Every shell was removed (nothing encloses volume).
    #[error("nothing encloses a volume: every shell is flat or empty after repair")]
    NoVolume,
    /// The rebuild failed (grid or meshing).
    #[error("rebuild: {0}")]
    Rebuild(String),
}

/// Options of [`repair_minimal`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MinimalOptions {
    /// Vertices closer than this are merged (model units, `0` merges equal positions only).
    pub weld: f64,
}

/// What [`repair_minimal`] changed, per kind (serialised with these names).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct RepairCounts {
    /// Vertices merged into a nearby one.
    pub vertices_welded: usize,
    /// Faces dropped because two corners are one vertex (after welding) or out of range.
    pub repeated_index_faces_removed: usize,
    /// Zero-area faces with three distinct collinear corners, removed after splitting the
    /// neighbours across their long edge at the middle corner.
    pub zero_area_faces_removed: usize,
    /// Neighbouring faces split at the middle corner of a zero-area face.
    pub faces_split_at_zero_area: usize,
    /// Faces dropped as copies of another face (same vertices; opposite copies cancel).
    pub duplicate_faces_removed: usize,
    /// Edges with more than two faces, cut apart.
    pub non_manifold_edges_cut: usize,
    /// Vertices whose faces formed more than one fan, given one copy per fan.
    pub non_manifold_vertices_split: usize,
    /// Vertex copies added by the splits.
    pub vertices_added_by_split: usize,
    /// Faces whose winding was reversed (orientation and outward direction).
    pub faces_flipped: usize,
    /// Boundary loops filled.
    pub holes_filled: usize,
    /// Triangles added to fill holes.
    pub hole_triangles_added: usize,
    /// Edges of the largest hole filled.
    pub largest_hole_edges: usize,
    /// Boundary loops that could not be traced closed (left open).
    pub holes_left_open: usize,
    /// Shells enclosing no volume (fins, flat sheets, doubled faces), removed.
    pub flat_shells_removed: usize,
    /// Copies of split vertices moved apart (within the weld tolerance).
    pub vertices_separated: usize,
    /// Vertices not used by any face, removed.
    pub unreferenced_vertices_removed: usize,
    /// The largest distance from an input vertex to the output vertex it became.
    pub max_vertex_displacement: f64,
}

/// The result of [`repair_minimal`].
#[derive(Debug, Clone)]
pub struct Repaired {
    /// The repaired mesh.
    pub mesh: IndexedMesh,
    /// What changed.
    pub counts: RepairCounts,
    /// For each input vertex, the output vertex it became (`u32::MAX`: dropped).
    pub vertex_map: Vec<u32>,
}

/// The topological repair described in the [module docs](self).
pub fn repair_minimal(mesh: &IndexedMesh, opts: &MinimalOptions) -> Result<Repaired, RepairError> {
    if !(opts.weld.is_finite() && opts.weld >= 0.0) {
        return Err(RepairError::BadWeld(opts.weld));
    }
    if let Some(v) = mesh.positions.iter().position(|p| !p.is_finite()) {
        return Err(RepairError::NonFinite(v));
    }
    let mut counts = RepairCounts::default();
    let welded = weld::weld(&mesh.positions, opts.weld);
    counts.vertices_welded = mesh.positions.len() - welded.positions.len();
    let mut positions = welded.positions;
    // Budget left to each welded vertex for later moves.
    let budget: Vec<f64> = welded.moved.iter().map(|&d| opts.weld - d).collect();
    let n = mesh.positions.len();
    let mut tris: Vec<[u32; 3]> = Vec::with_capacity(mesh.triangles.len());
    for t in &mesh.triangles {
        if t.iter().any(|&i| i as usize >= n) {
            counts.repeated_index_faces_removed += 1;
            continue;
        }
        let w = t.map(|i| welded.map[i as usize]);
        if w[0] == w[1] || w[1] == w[2] || w[0] == w[2] {
            counts.repeated_index_faces_removed += 1;
        } else {
            tris.push(w);
        }
    }
    if tris.is_empty() {
        return Err(RepairError::NoUsableTriangles {
            faces: mesh.triangles.len(),
        });
    }
    // The input face of each face (`u32::MAX`: added by the repair), to count reversed faces.
    let mut src: Vec<u32> = (0..tris.len() as u32).collect();
    faces::split_zero_area(&positions, &mut tris, &mut src, &mut counts);
    // One edge table serves the steps below; it is rebuilt only after a step changed the faces.
    let mut table = EdgeTable::build(&tris[..]);
    if faces::may_have_duplicates(&tris, &table) {
        counts.duplicate_faces_removed = faces::remove_duplicates(&mut tris, &mut src);
        if counts.duplicate_faces_removed > 0 {
            table = EdgeTable::build(&tris[..]);
        }
    }
    let split = split::split_non_manifold(&mut positions, &mut tris, &table);
    counts.non_manifold_edges_cut = split.edges_cut;
    counts.non_manifold_vertices_split = split.vertices_split;
    counts.vertices_added_by_split = split.parent.len() - split.first_copy;
    if counts.vertices_added_by_split > 0 {
        table = EdgeTable::build(&tris[..]);
    }
    let (boundary, reversed) = orient::orient_consistently(&mut tris, &table);
    drop(table);
    let filled = holes::fill_holes(&positions, &mut tris, &boundary, &split.parent);
    counts.holes_filled = filled.filled;
    counts.hole_triangles_added = filled.triangles;
    counts.largest_hole_edges = filled.largest;
    counts.holes_left_open = filled.open;
    let shells = nesting::orient_shells(&positions, &mut tris);
    counts.flat_shells_removed = shells.removed;
    if tris.is_empty() {
        return Err(RepairError::NoVolume);
    }
    // Input faces whose winding ends reversed (by the orientation pass xor their shell's turn).
    counts.faces_flipped = shells
        .from
        .iter()
        .filter(|&&(f, turned)| {
            let f = f as usize;
            src.get(f).is_some_and(|&s| s != u32::MAX) && (reversed.get(f) == Some(&true)) != turned
        })
        .count();
    let moved = separate::separate(&mut positions, &tris, &split, &budget);
    counts.vertices_separated = moved;
    let (out, remap) = compact(&positions, &tris);
    counts.unreferenced_vertices_removed = positions.len() - out.positions.len();
    // Each input vertex's image: welded vertex (position of its representative, possibly moved).
    let vertex_map: Vec<u32> = welded.map.iter().map(|&w| remap[w as usize]).collect();
    counts.max_vertex_displacement = mesh
        .positions
        .iter()
        .zip(&vertex_map)
        .filter(|&(_, &m)| m != u32::MAX)
        .map(|(p, &m)| p.distance(out.positions[m as usize]))
        .fold(0.0, f64::max);
    Ok(Repaired {
        mesh: out,
        counts,
        vertex_map,
    })
}

/// The mesh of the used vertices only, in index order; returns the old-to-new map (`u32::MAX`
/// for unused vertices).
fn compact(positions: &[DVec3], tris: &[[u32; 3]]) -> (IndexedMesh, Vec<u32>) {
    let mut remap = vec![u32::MAX; positions.len()];
    for t in tris {
        for &v in t {
            remap[v as usize] = 0;
        }
    }
    let mut out = IndexedMesh::default();
    for (v, r) in remap.iter_mut().enumerate() {
        if *r == 0 {
            *r = out.positions.len() as u32;
            out.positions.push(positions[v]);
        }
    }
    out.triangles = tris.iter().map(|t| t.map(|v| remap[v as usize])).collect();
    (out, remap)
}
