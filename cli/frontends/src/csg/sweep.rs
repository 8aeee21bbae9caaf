//! 2D programs replayed in 3D: each leaf of a [`Flat`] swept into a solid and the solids combined
//! by the program's Booleans; the x range and corner reach of a 2D geometry, folded the same way.

use super::error::CsgError;
use super::flat::{Flat, Op2, profile};
use super::parser::Stmt;
use super::sliced;
use glam::DVec2;
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::Primitive;

/// Replays a 2D program in 3D: each leaf swept by `make`.
pub(super) fn sweep<E: std::fmt::Display>(
    stmt: &Stmt,
    flat: &Flat,
    faceted: bool,
    make: impl Fn(solidkit_kernel::profile::Profile) -> Result<Primitive, E>,
) -> Result<Solid, CsgError> {
    sweep_solid(stmt, flat, faceted, |p| {
        make(p)
            .map(Solid::primitive)
            .map_err(|e| stmt.error(e.to_string()))
    })
}

/// [`sweep`] with a maker of whole solids (a primitive or a polyhedron per leaf).
pub(super) fn sweep_solid(
    stmt: &Stmt,
    flat: &Flat,
    faceted: bool,
    make: impl Fn(solidkit_kernel::profile::Profile) -> Result<Solid, CsgError>,
) -> Result<Solid, CsgError> {
    flat.evaluate(
        |leaf| {
            let p = profile(leaf, faceted).map_err(|e| stmt.error(format!("profile: {e}")))?;
            make(p)
        },
        |op, mut parts| match op {
            Op2::Difference(_) => {
                let base = parts.remove(0);
                Solid::difference_all(base, parts)
            }
            Op2::Intersection(_) => Solid::intersection_all(parts),
            _ => Solid::union_all(parts),
        },
    )
}

/// The range of x a 2D geometry can reach: its leaves' profile bounds, combined by its Booleans
/// (a difference within its first operand, an intersection within every operand).
pub(super) fn x_range(stmt: &Stmt, flat: &Flat, faceted: bool) -> Result<(f64, f64), CsgError> {
    flat.evaluate(
        |leaf| {
            let p = profile(leaf, faceted).map_err(|e| stmt.error(format!("profile: {e}")))?;
            let (lo, hi) = p.bounds();
            Ok((lo.x, hi.x))
        },
        |op, parts| match op {
            Op2::Difference(_) => parts[0],
            Op2::Intersection(_) => parts
                .into_iter()
                .fold((f64::NEG_INFINITY, f64::INFINITY), |a, b| {
                    (a.0.max(b.0), a.1.min(b.1))
                }),
            _ => parts
                .into_iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |a, b| {
                    (a.0.min(b.0), a.1.max(b.1))
                }),
        },
    )
}

/// How far a 2D geometry's corners reach ([`sliced::Reach`]), combined by its Booleans as
/// [`x_range`] combines ranges: the corners of a difference are within its first operand's,
/// an intersection's within the closest operand's.
pub(super) fn reach(
    stmt: &Stmt,
    flat: &Flat,
    faceted: bool,
    scale: DVec2,
) -> Result<sliced::Reach, CsgError> {
    flat.evaluate(
        |leaf| {
            let p = profile(leaf, faceted).map_err(|e| stmt.error(format!("profile: {e}")))?;
            Ok(sliced::Reach::of(&p.outline(0), scale))
        },
        |op, parts| {
            let pick = |f: fn(f64, f64) -> f64, start: f64| sliced::Reach {
                r_sqr: parts.iter().map(|r| r.r_sqr).fold(start, f),
                delta_sqr: parts.iter().map(|r| r.delta_sqr).fold(start, f),
            };
            match op {
                Op2::Difference(_) => parts[0],
                Op2::Intersection(_) => pick(f64::min, f64::INFINITY),
                _ => pick(f64::max, 0.0),
            }
        },
    )
}
