//! The 2D grid that both kinds of `projection()` sample (the slice in `projection.rs`, the shadow
//! in `shadow.rs`): its size and how closely its contours are simplified.

/// Cells of the 2D sampling grid along the longer side of the children's box.
pub const RESOLUTION: usize = 512;
/// Loops are simplified within this fraction of a cell.
pub const SIMPLIFY_CELLS: f64 = 0.05;
