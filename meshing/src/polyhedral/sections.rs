//! Plane sections and shadows of a [`Polyhedral`] solid, for OpenSCAD's `projection`: polygons
//! from the polyhedron's own edges, not samples of its field. The kernel's 2D Booleans round
//! corners to a grid of 10⁻⁸ model units (OpenSCAD's own clipping rounds to 1.5·10⁻⁵); a solid
//! reaching beyond [`MAX_EXTENT`] is refused rather than rounded out of range.

use super::{Polyhedral, PolyhedralError};
use glam::{DAffine3, DVec2, DVec3};
use manifold_rust::cross_section::CrossSection;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// The largest coordinate (in absolute value) a section or shadow takes: at 10⁻⁸ units per
/// grid step, 10⁹ keeps the kernel's 64-bit grid far from overflow.
pub const MAX_EXTENT: f64 = 1e9;

/// Closed polygons in the plane: outlines counter-clockwise, holes clockwise.
pub type Loops = Vec<Vec<DVec2>>;

fn loops(section: CrossSection) -> Loops {
    section
        .to_polygons()
        .into_iter()
        .map(|l| l.into_iter().map(|p| DVec2::new(p.x, p.y)).collect())
        .collect()
}

fn caught(
    solid: &Polyhedral,
    what: &str,
    f: impl FnOnce() -> Loops,
) -> Result<Loops, PolyhedralError> {
    let b = solid.0.bounding_box();
    let reach = [b.min.x, b.min.y, b.max.x, b.max.y]
        .into_iter()
        .fold(0.0f64, |m, c| m.max(c.abs()));
    if !solid.is_empty() && (reach > MAX_EXTENT || reach.is_nan()) {
        return Err(PolyhedralError::Failed(format!(
            "the {what} of a solid reaching {reach:e} (beyond ±{MAX_EXTENT:e})"
        )));
    }
    catch_unwind(AssertUnwindSafe(f))
        .map_err(|_| PolyhedralError::Failed(format!("the {what} stopped")))
}

impl Polyhedral {
    /// The section by the plane z = 0, seen from above: the loops where the plane cuts the
    /// solid, with a face lying in the plane counted from either side (the section just above
    /// the plane united with the one just below it, as OpenSCAD's cut keeps such a face).
    pub fn section_at_zero(&self) -> Result<Loops, PolyhedralError> {
        caught(self, "section", || {
            let above = self.0.slice(0.0);
            let flip = self.transform(&DAffine3::from_scale(DVec3::new(1.0, 1.0, -1.0)));
            let below = flip.0.slice(0.0);
            loops(above.union(&below))
        })
    }

    /// The shadow on the plane z = 0: the region every point of the solid projects into.
    pub fn shadow(&self) -> Result<Loops, PolyhedralError> {
        caught(self, "projection", || loops(self.0.project()))
    }
}
