//! When a dual-contouring run may claim its mesh free of self-intersections without testing it
//! (the report's `self_intersections_method: "construction"`, as marching cubes does).
//!
//! `certify` proves that every triangle keeps to cones from its cells' patch vertices over
//! disjoint zones of the cell faces, from tests done in floating point on the final coordinates
//! with a margin of [`EPS`] cells, vertices kept [`VERTEX_MARGIN`] of a cell inside their cells
//! and crossings [`CROSSING_MARGIN`] inside their edges. The proof's premises, checked per run:
//! - no simplification (`tolerance`): the adaptive pass merges cells and is checked by its own
//!   exact test, not by this argument;
//! - the rounding of coordinates is far below the margins: the grid's largest coordinate `M`
//!   satisfies `64 · ulp(M) ≤ EPS · cell`, so cells computed from different corners agree to far
//!   better than [`EPS`], and every margin survives rounding (a cell tiny against its
//!   coordinates, a grid far from the origin, fails this and is tested);
//! - every configuration is one the decider can give (`patches::reachable`: only those have
//!   separating planes between their patches);
//! - every owned crossing edge got its polygon (none lost at the grid's edge).
//!
//! The exhaustive side of the argument is in the tests: every one of the 256 cell patterns in
//! random neighbourhoods, crossings pushed against the samples, checkerboards of ambiguous faces
//! and random CSG trees, each counted by the exact test of [`crate::intersect`]
//! (`tests_manifold.rs`, `tests_checkerboard.rs`, `tests_claim.rs`).

use super::certify::{CROSSING_MARGIN, EPS, VERTEX_MARGIN};
use crate::grid::GridSpec;

/// Whether a run on `spec` with these outcomes is free of self-intersections by construction.
pub(crate) fn claim(
    spec: &GridSpec,
    tolerance: Option<f64>,
    unreachable: usize,
    dropped: usize,
) -> bool {
    tolerance.is_none() && unreachable == 0 && dropped == 0 && rounding_below_margins(spec)
}

/// The grid's largest coordinate magnitude.
fn largest_coordinate(spec: &GridSpec) -> f64 {
    let far = spec.point(spec.cells[0], spec.cells[1], spec.cells[2]);
    spec.origin.abs().max(far.abs()).max_element()
}

/// `64 · ulp(M) ≤ EPS · cell` for the grid's largest coordinate `M`.
pub(crate) fn rounding_below_margins(spec: &GridSpec) -> bool {
    let m = largest_coordinate(spec);
    let ulp = m.max(f64::MIN_POSITIVE) * f64::EPSILON;
    spec.cell.is_finite() && m.is_finite() && 64.0 * ulp <= EPS * spec.cell
}

/// How far (model units) a patch vertex is kept inside its cell: [`VERTEX_MARGIN`] cells, raised
/// to two single-precision steps of the grid's largest coordinate while that stays below half
/// of [`CROSSING_MARGIN`], so that the vertices of two cells beside one sample plane stay
/// distinct when a file stores 32-bit floats (STL, GLB). Without it a sharp feature on a sample
/// plane put the vertices of the cells on both sides 2 · 10⁻⁵ cells apart: one point in an STL,
/// and the file read back was not manifold. The margin only grows, so the argument's premises
/// (vertices at least [`VERTEX_MARGIN`] inside, below the crossing margin) hold as before.
pub(crate) fn vertex_margin(spec: &GridSpec) -> f64 {
    let step = 2.0 * largest_coordinate(spec) * f64::from(f32::EPSILON);
    let cap = 0.5 * CROSSING_MARGIN * spec.cell;
    (VERTEX_MARGIN * spec.cell).max(if step.is_finite() { step.min(cap) } else { 0.0 })
}

// The margins nest as the argument needs: rounding < EPS < vertex margin < crossing margin.
const _: () = assert!(EPS < VERTEX_MARGIN && VERTEX_MARGIN < CROSSING_MARGIN);
