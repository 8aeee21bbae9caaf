//! Why marching cubes' triangles never intersect, and the cheap checks that let a run say so
//! instead of testing every pair (the report's `self_intersections_method: "construction"`).
//!
//! The argument, for the mesh of one uniform grid (what the dense path, the sparse octree, which
//! reproduces it bit for bit, and refinement, which remeshes the whole model on one finer grid,
//! all produce). Coordinates are the final single-precision ones: a sample plane `x = xᵢ` is
//! rounded to `Xᵢ = f32(xᵢ)` for every vertex on it, so the vertices of a cell lie in the closed
//! box `[Xᵢ, Xᵢ₊₁] × [Yⱼ, Yⱼ₊₁] × [Zₖ, Zₖ₊₁]`, and a crossing on an edge along `x` has its other
//! two coordinates exactly on the edge's rounded line.
//!
//! 1. Every triangle lies in its cell's box (convexity). Two triangles of different cells can
//!    therefore meet only on the boxes' common face, edge or corner.
//! 2. A box face `F` is a supporting plane of the box, so a triangle meets `F` in the face of the
//!    triangle spanned by its vertices on `F`: the crossings on `F`'s four edges. The case table
//!    joins two crossings of one face only by a loop segment (no diagonal lies on a face, tested
//!    in `table.rs`), a triangle cannot have three vertices on one face (they would need three
//!    segments, a face has at most two, and they are disjoint), and a centre vertex is strictly
//!    inside the cell. So a triangle meets `F` in nothing, one crossing, or one loop segment.
//! 3. The segments on `F` depend only on `F`'s four samples (the face rule and the asymptotic
//!    decider read only them), and the crossings are shared vertices computed from the same two
//!    samples, so both cells sharing `F` draw the same segments between the same vertices. On
//!    one face the (at most two) segments cut off opposite corners and are disjoint. So two
//!    triangles of neighbouring cells meet on `F` only in a shared crossing or a shared segment,
//!    which is a shared mesh edge: they meet in what they share. Cells sharing only a grid edge
//!    or corner meet there only in the edge's one crossing (a shared vertex) or not at all:
//!    no vertex lies on a sample (checked: [`strictly_inside`]).
//! 4. Within one cell, the triangles of a case-table entry with at most [`PROVEN_TRIANGLES`]
//!    triangles never meet beyond the crossings they share, wherever the crossings lie strictly
//!    inside their edges: the exhaustive test (`disjoint_tests.rs`) checks every distinct pair
//!    of triangles that occurs in such an entry on a lattice of crossing parameters (all
//!    combinations) and at random, with the exact triangle–triangle test of
//!    [`crate::intersect`]. Intersection is invariant under the per-axis scaling from the unit
//!    cell to the cell's box, so rounded crossings are covered as long as they stay strictly
//!    inside their edges. Larger entries (the ambiguous and tunnel configurations, with loops of
//!    six or more crossings or a centre vertex) are *not* safe for every placement: the same test
//!    finds pairs of theirs that meet when crossings sit near the samples in ways no single
//!    trilinear field gives. So every cell with more triangles is tested where it is made, with
//!    the same exact test on its final coordinates ([`cell_disjoint`]); they are few on smooth
//!    surfaces.
//!
//! What the run checks to claim it ([`crate::octree::MeshStats::intersection_free`]): the
//! rounded sample planes are distinct along each axis ([`planes_distinct`]; else a box would be
//! flat), every vertex is strictly inside its rounded edge ([`strictly_inside`]; a vertex kept
//! [`EDGE_MARGIN`](super::EDGE_MARGIN) of a cell from a sample can still round onto it when the
//! cell is tiny against its coordinates), every cell of more than [`PROVEN_TRIANGLES`] triangles
//! passes its local test, and no edge
//! was left to the assembly's orphan fallback (a field breaking its interval bounds; two cells
//! would then disagree on a face). Exact zeros at samples do not matter: they are settled to a
//! sign before polygonization, and a crossing next to one is kept off the sample. Cutting the
//! solid inside its grid or clipping it to bounds changes the field, not the mesher, and the
//! thin-feature scan only counts. Dual contouring claims it under the premises of its own
//! certificate (`dual_contouring/certify.rs`, `dual_contouring/claim.rs`).

use super::table::CENTRE;
use crate::grid::GridSpec;
use crate::intersect::none_meet;
use glam::DVec3;

/// Cells whose configuration has at most this many triangles need no test (see point 4).
pub const PROVEN_TRIANGLES: usize = 4;

/// True when the vertex coordinate `v` (already single precision) lies strictly between the
/// rounded sample coordinates `lo` and `hi` of its edge.
#[inline]
pub fn strictly_inside(lo: f64, v: f64, hi: f64) -> bool {
    f64::from(lo as f32) < v && v < f64::from(hi as f32)
}

/// True when the rounded sample planes of `spec` are strictly increasing along every axis.
pub fn planes_distinct(spec: &GridSpec) -> bool {
    (0..3).all(|axis| {
        (0..spec.cells[axis]).all(|i| spec.coordinate(axis, i) < spec.coordinate(axis, i + 1))
    })
}

/// True when no two of one cell's triangles (`tris`, as cell edge numbers or [`CENTRE`]) meet
/// beyond the vertices they share, with the centre at `centre` and the crossing of edge `e` at
/// `crossing(e)` (final positions), by the exact test of [`crate::intersect`]
/// (`intersect::none_meet`: each crossing computed once).
pub fn cell_disjoint(tris: &[[u8; 3]], centre: DVec3, crossing: impl Fn(u8) -> DVec3) -> bool {
    let mut at = [None::<DVec3>; 12];
    let mut point = |e: u8| {
        if e == CENTRE {
            return centre;
        }
        *at[usize::from(e)].get_or_insert_with(|| crossing(e))
    };
    let tris: Vec<([u32; 3], [DVec3; 3])> = tris
        .iter()
        .map(|t| (t.map(u32::from), t.map(&mut point)))
        .collect();
    none_meet(&tris)
}
