//! Topology report of an indexed triangle mesh: counts, Euler characteristic, shells, genus,
//! defects (boundary, non-manifold and inconsistently oriented edges, non-manifold vertices,
//! degenerate faces) and measures (volume, area, bounding box).
//!
//! The report is computed directly from an [`IndexedMesh`], not through the half-edge mesh, so it
//! works on any input, however broken. Every step is iterative and at worst O(n log n): the
//! triangles are filed under their vertices (`crate::stars`, a counting sort, or a window of
//! vertices at a time when no self-intersection test needs every star, `crate::window_stars`);
//! each vertex's star
//! gives the kinds of its edges to larger vertices, its fans and its share of the Euler
//! characteristic (`local.rs`), in parallel over vertices (`survey.rs`); shells join the ends of
//! every edge in a concurrent union-find whose roots are each set's smallest element
//! (`atomic_union_find.rs`, `shells.rs`), and the measures run in parallel chunks of triangles
//! (`measures.rs`); every sum is combined in a fixed order, so the result does not depend on the
//! threads.
//!
//! # Unusable triangles
//!
//! A triangle with an index outside the vertex array, or with a repeated index, cannot take part in
//! adjacency. Such triangles count in [`TopologyReport::degenerate_faces`] (and its examples) and
//! are left out of everything else: `faces`, `edges`, `vertices`, shells, volume and area. So
//! `euler_characteristic == vertices - edges + faces` always holds, and a mesh whose only flaw is a
//! collapsed (repeated-index) triangle still reports as a closed manifold. A vertex used only by
//! such triangles counts as unreferenced. Geometrically degenerate triangles (distinct indices,
//! zero area) are counted as degenerate but otherwise treated like any other triangle.
//!
//! # Self-intersections
//!
//! [`TopologyReport::of`] also counts the pairs of triangles that meet beyond the vertices they
//! share ([`crate::intersect`]: Morton-curve broad phase, exact predicates), which no valid solid boundary
//! has; [`TopologyReport::with_options`] can skip it (it costs about as much as the rest of the
//! report together).

mod atomic_union_find;
mod defects;
mod edges;
mod local;
mod measures;
mod polygons;
mod shells;
mod survey;
mod text;
mod verdict;
mod vertices;

#[cfg(test)]
pub(crate) mod test_meshes;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_reference;

pub use defects::{DefectItems, MAX_DEFECT_PAIRS};
pub(crate) use edges::{CornerLoops, EdgeKind, EdgeTable};
pub use polygons::PolygonCounts;
pub use verdict::{MAX_LOCATED, OffenderPositions};
pub(crate) use vertices::fan_counts;

use crate::IndexedMesh;
use crate::intersect::self_intersections_among;
use crate::stars::Stars;
use crate::usable::usable_triangles;
use measures::Measures;
use shells::ShellTally;
use survey::Survey;

/// The most offending items of each kind listed in [`Offenders`].
pub const MAX_EXAMPLES: usize = 8;

/// Topology and measures of a triangle mesh; see the [module docs](self).
///
/// Serialises (serde) with the field names as written; they are a stable contract.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TopologyReport {
    /// Distinct vertices referenced by (usable) triangles.
    pub vertices: usize,
    /// Undirected edges.
    pub edges: usize,
    /// Usable triangles (see the module docs).
    pub faces: usize,
    /// `vertices − edges + faces`.
    pub euler_characteristic: i64,
    /// Connected components of triangles (sharing a vertex connects).
    pub shells: usize,
    /// Total genus over all shells; `None` unless there is at least one shell and every shell is
    /// closed, manifold and oriented.
    pub genus: Option<i64>,
    /// Genus of each shell (χ = 2 − 2g), `None` for shells that are not closed oriented
    /// manifolds; shells are sorted by their smallest triangle index.
    pub genus_per_shell: Vec<Option<i64>>,
    /// Edges used by exactly one triangle.
    pub boundary_edges: usize,
    /// Edges used by more than two triangles.
    pub non_manifold_edges: usize,
    /// Vertices whose triangles form more than one group connected through edges incident to the
    /// vertex (the link is not a single fan).
    pub non_manifold_vertices: usize,
    /// Two-triangle edges traversed in the same direction by both triangles (a flipped face).
    pub inconsistent_edges: usize,
    /// `inconsistent_edges == 0`.
    pub oriented: bool,
    /// `boundary_edges == 0` and there is at least one face.
    pub closed: bool,
    /// `non_manifold_edges == 0 && non_manifold_vertices == 0`.
    pub manifold: bool,
    /// Triangles with a repeated or out-of-range index, or with
    /// `|cross| <= 1e-12 * longest_edge²`.
    pub degenerate_faces: usize,
    /// Positions not referenced by any usable triangle.
    pub unreferenced_vertices: usize,
    /// Signed volume by the divergence theorem, positive for outward (CCW) winding. For an open
    /// mesh it is the volume of the cones from the bounding-box centre to the triangles.
    pub volume: f64,
    /// Total triangle area.
    pub area: f64,
    /// Bounding box `[min, max]` of the referenced vertices; all zeros for an empty mesh.
    pub bbox: [[f64; 3]; 2],
    /// Pairs of triangles that meet beyond their shared vertices (see
    /// [`crate::intersect`]); `None` when skipped ([`ReportOptions`]) or when a used vertex is
    /// not finite.
    pub self_intersections: Option<usize>,
    /// How [`Self::self_intersections`] was found: tested pair by pair, or known from the
    /// mesher's construction (see [`TopologyReport::with_certificate`]); `None` when skipped.
    pub self_intersections_method: Option<SelfIntersectionsMethod>,
    /// The first few offending items of each kind.
    pub examples: Offenders,
    /// Each shell's bounding box (`[min, max]`, in shell order) when there are several shells,
    /// else empty; for [`crate::pipeline::warnings::fragments`] (not serialised).
    #[serde(skip)]
    pub shell_boxes: Vec<[glam::DVec3; 2]>,
}

/// How a report knows its self-intersection count.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SelfIntersectionsMethod {
    /// Every pair of triangles that may meet was tested ([`crate::intersect`]).
    Tested,
    /// The mesher guarantees none by construction and checked the conditions of its guarantee
    /// for this mesh ([`crate::marching_cubes::disjoint`]); the count is 0.
    Construction,
}

impl SelfIntersectionsMethod {
    /// The name as the JSON report writes it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Tested => "tested",
            Self::Construction => "construction",
        }
    }
}

/// The first [`MAX_EXAMPLES`] offending items of each kind, in ascending order.
///
/// Edges are written `[smaller vertex, larger vertex]`; faces are triangle indices into the input.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
pub struct Offenders {
    /// Edges used by exactly one triangle.
    pub boundary_edges: Vec<[u32; 2]>,
    /// Edges used by more than two triangles.
    pub non_manifold_edges: Vec<[u32; 2]>,
    /// Vertices whose link is not a single fan.
    pub non_manifold_vertices: Vec<u32>,
    /// Two-triangle edges traversed in the same direction.
    pub inconsistent_edges: Vec<[u32; 2]>,
    /// Degenerate triangles.
    pub degenerate_faces: Vec<u32>,
    /// Intersecting triangle pairs `[i, j]`, `i < j`.
    pub self_intersections: Vec<[u32; 2]>,
}

/// What [`TopologyReport::with_options`] computes beyond the always-present items.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReportOptions {
    /// Count self-intersecting triangle pairs (default `true`).
    pub self_intersections: bool,
}

impl Default for ReportOptions {
    fn default() -> Self {
        Self {
            self_intersections: true,
        }
    }
}

impl TopologyReport {
    /// The report of `mesh`, self-intersections included. Never panics, whatever the indices (see
    /// the module docs).
    pub fn of(mesh: &IndexedMesh) -> Self {
        Self::with_options(mesh, &ReportOptions::default())
    }

    /// The report of `mesh` with the optional parts chosen by `options`.
    pub fn with_options(mesh: &IndexedMesh, options: &ReportOptions) -> Self {
        Self::with_certificate(mesh, options, false)
    }

    /// [`Self::with_options`] for a mesh whose maker certifies it free of self-intersections
    /// (`intersection_free`, e.g. [`crate::octree::MeshStats::intersection_free`]): the count
    /// is then 0 by construction instead of tested, and the report says which
    /// ([`Self::self_intersections_method`]). `solidkit check` never passes a certificate.
    pub fn with_certificate(
        mesh: &IndexedMesh,
        options: &ReportOptions,
        intersection_free: bool,
    ) -> Self {
        let test = options.self_intersections && !intersection_free;
        let triangles = usable_triangles(mesh);
        let vertex_count = mesh.positions.len();
        // Without the test, the vertex pass takes its stars a window at a time; the test needs
        // the whole mesh's stars, which then serve the vertex pass too (as they do for
        // triangles in no spatial order).
        let windowed = (!test)
            .then(|| Survey::windowed(&triangles, vertex_count))
            .flatten();
        let (mut report, intersections) = match windowed {
            Some(survey) => (Self::from_survey(mesh, &triangles, survey), None),
            None => {
                let stars = Stars::build(&triangles, vertex_count);
                rayon::join(
                    || Self::from_survey(mesh, &triangles, Survey::of(&triangles, &stars)),
                    || {
                        test.then(|| self_intersections_among(mesh, &stars, MAX_EXAMPLES).ok())
                            .flatten()
                    },
                )
            }
        };
        if let Some(found) = intersections {
            report.self_intersections = Some(found.count);
            report.self_intersections_method = Some(SelfIntersectionsMethod::Tested);
            report.examples.self_intersections = found.examples;
        } else if options.self_intersections && intersection_free {
            report.self_intersections = Some(0);
            report.self_intersections_method = Some(SelfIntersectionsMethod::Construction);
        }
        report
    }

    /// The report without self-intersections, from the usable `tris` and their `survey`.
    fn from_survey(mesh: &IndexedMesh, tris: &[[u32; 3]], survey: Survey) -> Self {
        let vertex_count = mesh.positions.len();
        let shells = &survey.shells;
        let shares = &survey.shares;
        let (measures, tally) = rayon::join(
            || Measures::of(mesh, |v| shares[v].used),
            || ShellTally::new(shells, shares, &mesh.positions),
        );
        let mut examples = survey.examples;
        examples.degenerate_faces = measures.degenerate_examples;
        let genus_per_shell = tally.genus();
        let vertices = tally.vertices();
        let shell_boxes = if shells.count() > 1 {
            tally.into_boxes()
        } else {
            Vec::new()
        };
        let genus = total_genus(&genus_per_shell);
        let counts = survey.counts;
        let (edges, faces) = (counts.edges, tris.len());
        Self {
            vertices,
            edges,
            faces,
            euler_characteristic: to_i64(vertices) - to_i64(edges) + to_i64(faces),
            shells: shells.count(),
            genus,
            genus_per_shell,
            boundary_edges: counts.boundary,
            non_manifold_edges: counts.non_manifold,
            non_manifold_vertices: survey.non_manifold_vertices,
            inconsistent_edges: counts.inconsistent,
            oriented: counts.inconsistent == 0,
            closed: counts.boundary == 0 && faces > 0,
            manifold: counts.non_manifold == 0 && survey.non_manifold_vertices == 0,
            degenerate_faces: measures.degenerate,
            unreferenced_vertices: vertex_count - vertices,
            volume: measures.volume,
            area: measures.area,
            bbox: measures.bbox,
            self_intersections: None,
            self_intersections_method: None,
            examples,
            shell_boxes,
        }
    }

    /// True for a valid solid boundary: closed, manifold and oriented.
    pub fn is_closed_manifold(&self) -> bool {
        self.closed && self.manifold && self.oriented
    }

    /// True for a closed oriented manifold with no self-intersection found (skipped counts as
    /// none found): what `solidkit check` accepts.
    pub fn is_valid_solid(&self) -> bool {
        self.is_closed_manifold() && self.self_intersections.unwrap_or(0) == 0
    }
}

/// Appends `item` when fewer than [`MAX_EXAMPLES`] are listed.
pub(super) fn push_example<T>(list: &mut Vec<T>, item: T) {
    if list.len() < MAX_EXAMPLES {
        list.push(item);
    }
}

/// The sum of the per-shell genera; `None` when there are no shells or any is `None`.
fn total_genus(per_shell: &[Option<i64>]) -> Option<i64> {
    if per_shell.is_empty() {
        return None;
    }
    per_shell.iter().copied().sum()
}

/// `usize` to `i64`, saturating (counts never get near the limit).
fn to_i64(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}
