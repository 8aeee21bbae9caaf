//! The sweep family: solids swept from planar profiles or between curves, one file each.
//! [`Extrude`] (linear extrusion along z with twist and end scale), [`Revolve`] (revolution about
//! the z axis, full or partial), [`Sweep`] (a profile along a 3D curve with rotation-minimising
//! frames), [`Loft`] (between two profiles at two heights), [`Ruled`] (between two closed
//! horizontal plane curves) and [`RuledSurface`] (between any two curves, capped or thickened).
//! Each documents its field: exact distances where they are cheap, otherwise a
//! field divided by an honest Lipschitz bound so it stays a distance bound; every zero set is the
//! exact surface (`field_error() = 0`). Each has an exact volume and a parametric tessellation
//! (the `tessellate` methods).

mod combine;
mod error;
mod extrude;
mod frames;
mod loft;
mod revolve;
mod rings;
mod ruled;
mod ruled_surface;
#[allow(clippy::module_inception)]
mod sweep;
mod tessellate;

#[cfg(test)]
mod ruled_surface_tests;
#[cfg(test)]
mod tests;

pub use error::SweepError;
pub use extrude::Extrude;
pub(crate) use frames::Frames;
pub use loft::Loft;
pub use revolve::Revolve;
pub use rings::{MAX_SAMPLES, signed_volume};
pub use ruled::Ruled;
pub use ruled_surface::RuledSurface;
pub use sweep::Sweep;
