//! Every offending item of a mesh, not only the first few the report lists: what a picture of the
//! defects needs.
//!
//! Uses the same edge table, vertex fans and self-intersection search as the report, so the counts
//! agree with [`super::TopologyReport`]; indices refer to the input mesh (triangles with unusable
//! indices are skipped as in the report).

use super::ReportOptions;
use super::edges::{EdgeKind, EdgeTable};
use super::vertices::fan_counts;
use crate::IndexedMesh;
use crate::intersect::self_intersections;
use crate::usable::is_usable;

/// The most self-intersecting pairs collected; beyond it [`DefectItems::truncated`] is set.
pub const MAX_DEFECT_PAIRS: usize = 1 << 20;

/// All defective items of a mesh, each list ascending.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct DefectItems {
    /// Edges used by exactly one triangle, `[smaller, larger]` vertex.
    pub boundary_edges: Vec<[u32; 2]>,
    /// Edges used by more than two triangles.
    pub non_manifold_edges: Vec<[u32; 2]>,
    /// Vertices whose faces form more than one fan.
    pub non_manifold_vertices: Vec<u32>,
    /// Triangles on an edge both of its triangles traverse in the same direction.
    pub inconsistent_faces: Vec<u32>,
    /// Triangles that meet another one beyond their shared vertices.
    pub self_intersecting_faces: Vec<u32>,
    /// True when more than [`MAX_DEFECT_PAIRS`] intersecting pairs exist (only the smallest
    /// pairs' triangles are listed).
    pub truncated: bool,
}

impl DefectItems {
    /// The defects of `mesh`; self-intersections only when `options` asks for them.
    pub fn of(mesh: &IndexedMesh, options: &ReportOptions) -> Self {
        let n = mesh.positions.len();
        let original: Vec<u32> = (0..mesh.triangles.len() as u32)
            .filter(|&i| is_usable(&mesh.triangles[i as usize], n))
            .collect();
        let tris: Vec<[u32; 3]> = original
            .iter()
            .map(|&i| mesh.triangles[i as usize])
            .collect();
        let table = EdgeTable::build(&tris[..]);
        let mut out = Self::default();
        for edge in table.edges() {
            match edge.kind(&tris[..]) {
                EdgeKind::Manifold => {}
                EdgeKind::Boundary => out.boundary_edges.push(edge.vertices()),
                EdgeKind::NonManifold => out.non_manifold_edges.push(edge.vertices()),
                EdgeKind::Inconsistent => out
                    .inconsistent_faces
                    .extend(edge.corners().map(|c| original[c / 3])),
            }
        }
        let fans = fan_counts(&tris[..], &table, n);
        out.non_manifold_vertices = (0..n as u32).filter(|&v| fans[v as usize] > 1).collect();
        if options.self_intersections
            && let Ok(found) = self_intersections(mesh, MAX_DEFECT_PAIRS)
        {
            out.truncated = found.count > found.examples.len();
            out.self_intersecting_faces = found.examples.iter().flatten().copied().collect();
        }
        for list in [
            &mut out.inconsistent_faces,
            &mut out.self_intersecting_faces,
        ] {
            list.sort_unstable();
            list.dedup();
        }
        out
    }

    /// True when nothing is listed.
    pub fn is_empty(&self) -> bool {
        self.boundary_edges.is_empty()
            && self.non_manifold_edges.is_empty()
            && self.non_manifold_vertices.is_empty()
            && self.inconsistent_faces.is_empty()
            && self.self_intersecting_faces.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::{DefectItems, ReportOptions};
    use crate::{IndexedMesh, TopologyReport};
    use glam::DVec3;

    #[test]
    fn items_match_the_report_counts() {
        // An open fin: three triangles on edge 0-1, and a folded pair on edge 1-2.
        let positions = (0..6)
            .map(|i| DVec3::new(i as f64, (i * i) as f64 * 0.1, (i % 3) as f64))
            .collect();
        let mesh = IndexedMesh::new(
            positions,
            vec![[0, 1, 2], [1, 0, 3], [0, 1, 4], [1, 2, 5], [2, 1, 5]],
        );
        let items = DefectItems::of(&mesh, &ReportOptions::default());
        let r = TopologyReport::of(&mesh);
        assert_eq!(items.boundary_edges.len(), r.boundary_edges);
        assert_eq!(items.non_manifold_edges.len(), r.non_manifold_edges);
        assert_eq!(items.non_manifold_vertices.len(), r.non_manifold_vertices);
        // Edge 0-1 has three triangles, and so has 1-2 (the triangle 0-1-2 and the pair on 1-2-5).
        assert_eq!(items.non_manifold_edges, vec![[0, 1], [1, 2]]);
        assert!(!items.is_empty());
    }
}
