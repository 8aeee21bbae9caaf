//! What a [`TopologyReport`] means in one line, and where its first offenders are: the verdict
//! at the top of `solidkit check`'s report and the coordinates of the first few offending
//! edges, vertices and faces (the report itself lists indices only).

use std::fmt::Write as _;

use glam::DVec3;

use super::TopologyReport;
use crate::IndexedMesh;

/// How many offenders of each kind get coordinates.
pub const MAX_LOCATED: usize = 3;

/// Coordinates of the first [`MAX_LOCATED`] offenders of each kind, in the order of
/// [`Offenders`](super::Offenders); a corner index out of range has no position (`None`).
///
/// Serialises (serde) with these field names, as `check --json`'s `example_positions`.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
pub struct OffenderPositions {
    /// End points of boundary edges.
    pub boundary_edges: Vec<[Option<[f64; 3]>; 2]>,
    /// End points of non-manifold edges.
    pub non_manifold_edges: Vec<[Option<[f64; 3]>; 2]>,
    /// Non-manifold vertices.
    pub non_manifold_vertices: Vec<Option<[f64; 3]>>,
    /// End points of inconsistently oriented edges.
    pub inconsistent_edges: Vec<[Option<[f64; 3]>; 2]>,
    /// Corners of degenerate faces.
    pub degenerate_faces: Vec<[Option<[f64; 3]>; 3]>,
    /// Centroids of the two faces of each intersecting pair.
    pub self_intersections: Vec<[Option<[f64; 3]>; 2]>,
}

impl TopologyReport {
    /// `closed oriented 2-manifold, no self-intersections` for a valid solid, else `NOT a
    /// solid: ` and the count of each kind of defect (without the `verdict:` key).
    pub fn verdict(&self) -> String {
        if self.is_valid_solid() {
            let checked = match self.self_intersections {
                Some(_) => "no self-intersections",
                None => "self-intersections not checked",
            };
            return format!("closed oriented 2-manifold, {checked}");
        }
        let counts = [
            (self.boundary_edges, "boundary edges"),
            (self.non_manifold_edges, "non-manifold edges"),
            (self.non_manifold_vertices, "non-manifold vertices"),
            (self.inconsistent_edges, "inconsistently oriented edges"),
            (
                self.self_intersections.unwrap_or(0),
                "self-intersecting face pairs",
            ),
        ];
        let mut parts: Vec<String> = counts
            .iter()
            .filter(|(n, _)| *n > 0)
            .map(|(n, what)| format!("{n} {what}"))
            .collect();
        if self.faces == 0 {
            parts.push("no usable faces".into());
        }
        format!("NOT a solid: {}", parts.join(", "))
    }

    /// The positions of the first offenders of each kind in `mesh` (the mesh of the report).
    pub fn offender_positions(&self, mesh: &IndexedMesh) -> OffenderPositions {
        let at = |v: u32| mesh.positions.get(v as usize).map(|p| p.to_array());
        let centroid = |f: u32| {
            let t = mesh.triangles.get(f as usize)?;
            let corners: Option<Vec<DVec3>> = t
                .iter()
                .map(|&v| mesh.positions.get(v as usize).copied())
                .collect();
            corners.map(|c| ((c[0] + c[1] + c[2]) / 3.0).to_array())
        };
        let pairs = |list: &[[u32; 2]]| -> Vec<[Option<[f64; 3]>; 2]> {
            list.iter().take(MAX_LOCATED).map(|e| e.map(at)).collect()
        };
        let ex = &self.examples;
        OffenderPositions {
            boundary_edges: pairs(&ex.boundary_edges),
            non_manifold_edges: pairs(&ex.non_manifold_edges),
            non_manifold_vertices: ex
                .non_manifold_vertices
                .iter()
                .take(MAX_LOCATED)
                .map(|&v| at(v))
                .collect(),
            inconsistent_edges: pairs(&ex.inconsistent_edges),
            degenerate_faces: ex
                .degenerate_faces
                .iter()
                .take(MAX_LOCATED)
                .map(|&f| match mesh.triangles.get(f as usize) {
                    Some(t) => t.map(at),
                    None => [None; 3],
                })
                .collect(),
            self_intersections: ex
                .self_intersections
                .iter()
                .take(MAX_LOCATED)
                .map(|p| p.map(centroid))
                .collect(),
        }
    }

    /// Lines `  boundary edge 3-4 at (x y z) (x y z)`, one per located offender, under a
    /// `first offenders at:` heading; empty when there are none.
    pub fn offender_positions_text(&self, mesh: &IndexedMesh) -> String {
        let p = self.offender_positions(mesh);
        let ex = &self.examples;
        let mut lines: Vec<(String, Vec<Option<[f64; 3]>>)> = Vec::new();
        let mut edges = |what: &str, ids: &[[u32; 2]], at: &[[Option<[f64; 3]>; 2]]| {
            for (e, q) in ids.iter().zip(at) {
                lines.push((format!("{what} {}-{}", e[0], e[1]), q.to_vec()));
            }
        };
        edges("boundary edge", &ex.boundary_edges, &p.boundary_edges);
        edges(
            "non-manifold edge",
            &ex.non_manifold_edges,
            &p.non_manifold_edges,
        );
        edges(
            "inconsistent edge",
            &ex.inconsistent_edges,
            &p.inconsistent_edges,
        );
        for (v, q) in ex
            .non_manifold_vertices
            .iter()
            .zip(&p.non_manifold_vertices)
        {
            lines.push((format!("non-manifold vertex {v}"), vec![*q]));
        }
        for (f, q) in ex.degenerate_faces.iter().zip(&p.degenerate_faces) {
            lines.push((format!("degenerate face {f}"), q.to_vec()));
        }
        for (f, q) in ex.self_intersections.iter().zip(&p.self_intersections) {
            lines.push((
                format!("intersecting faces {} {} (centroids)", f[0], f[1]),
                q.to_vec(),
            ));
        }
        if lines.is_empty() {
            return String::new();
        }
        let mut out = String::from("first offenders at:\n");
        for (what, points) in lines {
            let shown: Vec<String> = points
                .iter()
                .map(|q| {
                    q.map_or_else(
                        || "(out of range)".into(),
                        |c| format!("({} {} {})", c[0], c[1], c[2]),
                    )
                })
                .collect();
            // Writing to a String cannot fail.
            let _ = writeln!(out, "  {what} at {}", shown.join(" "));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::topology::test_meshes::{cube, cube_hole, fin};

    #[test]
    fn verdicts_and_offender_coordinates() {
        let r = TopologyReport::of(&cube());
        assert_eq!(
            r.verdict(),
            "closed oriented 2-manifold, no self-intersections"
        );
        assert_eq!(r.offender_positions_text(&cube()), "");
        let mesh = cube_hole();
        let r = TopologyReport::of(&mesh);
        assert!(
            r.verdict().starts_with("NOT a solid: 3 boundary edges"),
            "{}",
            r.verdict()
        );
        let p = r.offender_positions(&mesh);
        let [a, b] = r.examples.boundary_edges[0];
        assert_eq!(
            p.boundary_edges[0],
            [a, b].map(|v| Some(mesh.positions[v as usize].to_array()))
        );
        let text = r.offender_positions_text(&mesh);
        assert!(
            text.starts_with("first offenders at:\n  boundary edge "),
            "{text}"
        );
        assert_eq!(text.lines().count(), 4, "{text}");
        let r = TopologyReport::of(&fin());
        assert!(
            r.verdict().contains("non-manifold edges"),
            "{}",
            r.verdict()
        );
    }
}
