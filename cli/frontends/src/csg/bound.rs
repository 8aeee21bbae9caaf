//! What a subtree's exact bounding box is known from ([`Bound`]), shared by the exact boxes of
//! `resize()` (`bounds.rs`) and the clipping of convex bounds (`clip.rs`).

use glam::DVec3;
use solidkit_kernel::Aabb;

/// What a subtree's exact box is known from.
#[derive(Debug, Clone)]
pub(super) enum Bound {
    /// Points whose convex hull is the hull of the solid: any affine image keeps the box exact.
    Points(Vec<DVec3>),
    /// An exact box, which stays exact only under maps that keep the axes (scaled signed
    /// permutations).
    Box(Aabb),
    /// A half-space `n · p ≤ d` (unbounded: only useful inside an intersection).
    Plane(DVec3, f64),
    /// Not known exactly.
    Unknown,
}

impl Bound {
    pub(super) fn aabb(&self) -> Option<Aabb> {
        match self {
            Bound::Points(p) => Some(points_box(p)),
            Bound::Box(b) => Some(*b),
            Bound::Plane(..) | Bound::Unknown => None,
        }
    }
}

/// The box of `points` (empty for none).
fn points_box(points: &[DVec3]) -> Aabb {
    points
        .iter()
        .fold(Aabb::empty(), |b, p| b.union(&Aabb::new(*p, *p)))
}
