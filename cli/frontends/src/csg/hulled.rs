//! `hull()`: the convex hull of its operands' points, a convex solid or a convex polygon.

use super::error::CsgError;
use super::flat::{Flat, Leaf2};
use super::geom::{Ctx, Geom};
use super::hull::{convex_hull, convex_hull_2d};
use super::hullable::Hullable;
use super::operand::operands;
use super::parser::Stmt;
use super::shape_args::faceted_solid;
use glam::{DVec2, DVec3};

/// The convex hull of `points` as geometry of dimension `dim` (empty when degenerate), with its
/// vertices.
pub(super) fn hull_of(
    stmt: &Stmt,
    dim: u8,
    points: &[DVec3],
) -> Result<(Geom, Option<Hullable>), CsgError> {
    if dim == 2 {
        let flat: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
        let ring = convex_hull_2d(&flat);
        if ring.len() < 3 {
            return Ok((Geom::Empty, None));
        }
        let points = ring.iter().map(|p| p.extend(0.0)).collect();
        return Ok((
            Geom::Flat(Flat::leaf(Leaf2::Polygon(vec![ring]))),
            Some(Hullable {
                points,
                convex: true,
                pieces: None,
            }),
        ));
    }
    let Some((v, f)) = convex_hull(points) else {
        return Ok((Geom::Empty, None));
    };
    let info = Hullable {
        points: v.clone(),
        convex: true,
        pieces: Some(vec![v.clone()]),
    };
    // A hull is convex: the intersection of its face planes evaluates in a dot product per face
    // and prunes per octree cell, where a mesh solid pays a winding number per sample.
    Ok((Geom::Solid(faceted_solid(stmt, v, f)?), Some(info)))
}

/// `hull()` of any children: the convex hull of their points (exact for primitives, polyhedra,
/// polygons, their unions, transforms, and the differences and intersections of convex parts; the
/// vertices of a fine mesh otherwise).
pub(super) fn hull(
    stmt: &Stmt,
    children: Vec<Geom>,
    infos: Vec<Option<Hullable>>,
    ctx: &mut Ctx,
) -> Result<(Geom, Option<Hullable>), CsgError> {
    let (dim, ops) = operands(stmt, children, infos, ctx)?;
    let Some(dim) = dim else {
        return Ok((Geom::Empty, None));
    };
    let points: Vec<DVec3> = ops.into_iter().flat_map(|(_, h, _)| h.points).collect();
    hull_of(stmt, dim, &points)
}
