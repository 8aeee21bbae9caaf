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

/// `64 · ulp(M) ≤ EPS · cell` for the grid's largest coordinate `M`.
pub(crate) fn rounding_below_margins(spec: &GridSpec) -> bool {
    let far = spec.point(spec.cells[0], spec.cells[1], spec.cells[2]);
    let m = spec.origin.abs().max(far.abs()).max_element();
    let ulp = m.max(f64::MIN_POSITIVE) * f64::EPSILON;
    spec.cell.is_finite() && m.is_finite() && 64.0 * ulp <= EPS * spec.cell
}

// The margins nest as the argument needs: rounding < EPS < vertex margin < crossing margin.
const _: () = assert!(EPS < VERTEX_MARGIN && VERTEX_MARGIN < CROSSING_MARGIN);
