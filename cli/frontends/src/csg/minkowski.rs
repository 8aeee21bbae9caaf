//! `minkowski()`: the hull of the sums of convex operands' points, summed piece by piece for one
//! operand cut into convex pieces, or an offset by a sphere operand's radius; 2D operands of any
//! shape through their polygons ([`super::minkowski_flat`]).

use super::Facets;
use super::error::CsgError;
use super::flat::Flat;
use super::geom::{Ctx, Geom};
use super::hull::{convex_hull, convex_hull_2d};
use super::hullable::Hullable;
use super::hulled::hull_of;
use super::minkowski_flat::minkowski_flat;
use super::operand::{Operand, operands};
use super::parser::{Stmt, Tree};
use super::pieces;
use super::shape_args::{matrix, radius};
use glam::{DVec2, DVec3};
use solidkit_kernel::Solid;

/// The radius and centre of a sphere operand of `minkowski()`: a `sphere` under groups and
/// translations only.
fn sphere_operand(tree: &Tree, mut k: usize) -> Result<Option<(f64, DVec3)>, CsgError> {
    let mut t = DVec3::ZERO;
    loop {
        let s = &tree.nodes[k];
        let kids: Vec<usize> = s
            .children
            .iter()
            .copied()
            .filter(|&c| !tree.nodes[c].modifiers.dropped())
            .collect();
        match s.name.as_str() {
            "sphere" => {
                let r = radius(s, "r", "d", 0, 1.0)?;
                return Ok((r > 0.0).then_some((r, t)));
            }
            "group" | "union" | "color" | "render" if kids.len() == 1 => k = kids[0],
            "multmatrix" if kids.len() == 1 => {
                let m = matrix(s)?;
                if (0..3).any(|i| (0..3).any(|j| m[i][j] != if i == j { 1.0 } else { 0.0 })) {
                    return Ok(None);
                }
                t += DVec3::new(m[0][3], m[1][3], m[2][3]);
                k = kids[0];
            }
            _ => return Ok(None),
        }
    }
}

/// `minkowski()`: of convex operands, the hull of the sums of their points (exact: the sum of
/// convex sets is the hull of the sums of their vertices); of one operand made of convex pieces
/// and convex others (under OpenSCAD's facets a sphere is one of those), the union of the
/// pieces' sums; with a sphere operand and exact facets, or with one non-convex operand and a
/// sphere otherwise, an offset of the other operand by the sphere's radius; 2D operands not all
/// convex by their polygons. Anything else is refused.
pub(super) fn minkowski(
    tree: &Tree,
    kids: &[usize],
    stmt: &Stmt,
    children: Vec<Geom>,
    infos: Vec<Option<Hullable>>,
    ctx: &mut Ctx,
) -> Result<(Geom, Option<Hullable>), CsgError> {
    let (dim, mut ops) = operands(stmt, children, infos, ctx)?;
    let Some(dim) = dim else {
        return Ok((Geom::Empty, None));
    };
    if ops.len() == 1 {
        let (g, h, _) = ops.pop().expect("one operand");
        return Ok((g, Some(h)));
    }
    let all_convex = ops.iter().all(|(_, h, _)| h.convex);
    if dim == 2 && !all_convex {
        let flats: Vec<Flat> = ops
            .into_iter()
            .filter_map(|(g, _, _)| match g {
                Geom::Flat(f) => Some(f),
                _ => None,
            })
            .collect();
        let sum = minkowski_flat(&flats, ctx.facets).map_err(|e| stmt.error(e))?;
        return Ok((sum.map_or(Geom::Empty, Geom::Flat), None));
    }
    // OpenSCAD's faceted sphere is a convex polyhedron like any other: where the non-convex
    // operand is made of convex pieces, the sum piece by piece is OpenSCAD's own result (its
    // `minkowski3-erosion` test), and the exact offset below is only the fallback.
    if ctx.facets == Facets::OpenScad
        && dim == 3
        && !all_convex
        && let Some(done) = minkowski_by_pieces(stmt, &ops)?
    {
        return Ok(done);
    }
    let mut spheres = Vec::new();
    if dim == 3 && (ctx.facets == Facets::Exact || !all_convex) {
        for (n, (_, _, k)) in ops.iter().enumerate() {
            if let Some(s) = sphere_operand(tree, kids[*k])? {
                spheres.push((n, s));
            }
        }
    }
    if spheres.is_empty() || spheres.len() == ops.len() {
        if !all_convex
            && dim == 3
            && let Some(done) = minkowski_by_pieces(stmt, &ops)?
        {
            return Ok(done);
        }
        if !all_convex {
            return Err(stmt.error(
                "only convex operands (primitives, convex polyhedra and polygons, hulls, and \
                 their transforms), one operand cut into at most 512 convex pieces (unions, \
                 differences and intersections of convex parts of up to 130 faces) with convex \
                 others, or a sphere with any other operand, are supported",
            ));
        }
        let sum = minkowski_points(dim, ops.into_iter().map(|(_, h, _)| h.points));
        return hull_of(stmt, dim, &sum);
    }
    // Offset the rest by the spheres (their sum is one sphere).
    let (r, t) = spheres
        .iter()
        .fold((0.0, DVec3::ZERO), |(r, t), (_, (sr, st))| {
            (r + sr, t + *st)
        });
    for (n, _) in spheres.iter().rev() {
        ops.remove(*n);
    }
    let rest = if ops.len() == 1 {
        ops.pop().expect("one operand").0
    } else if ops.iter().all(|(_, h, _)| h.convex) {
        let sum = minkowski_points(dim, ops.into_iter().map(|(_, h, _)| h.points));
        hull_of(stmt, dim, &sum)?.0
    } else {
        return Err(
            stmt.error("more than one non-convex operand besides the sphere is not supported")
        );
    };
    let Geom::Solid(s) = rest else {
        return Ok((Geom::Empty, None));
    };
    if ctx.facets == Facets::OpenScad {
        ctx.warn(
            stmt,
            "minkowski with a non-convex operand: the sphere operand is taken as exact (an offset)",
        );
    }
    let s = s.offset(r);
    Ok((
        Geom::Solid(if t == DVec3::ZERO { s } else { s.translate(t) }),
        None,
    ))
}

/// `minkowski()` of one operand made of convex pieces ([`super::pieces`]) and convex others: the
/// union of the hulls of each piece plus the others' sum (and those hulls' vertices as its
/// convex pieces); `None` when an operand is neither.
fn minkowski_by_pieces(
    stmt: &Stmt,
    ops: &[Operand],
) -> Result<Option<(Geom, Option<Hullable>)>, CsgError> {
    let (rest, convex): (Vec<&Operand>, Vec<&Operand>) =
        ops.iter().partition(|(_, h, _)| !h.convex);
    let [(_, decomposed, _)] = rest[..] else {
        return Ok(None);
    };
    let Some(parts) = &decomposed.pieces else {
        return Ok(None);
    };
    let b = minkowski_points(3, convex.iter().map(|(_, h, _)| h.points.clone()));
    let mut solids = Vec::new();
    let mut hulls = Vec::new();
    for sum in pieces::sum_with_convex(parts, &b) {
        if let (Geom::Solid(s), Some(h)) = hull_of(stmt, 3, &sum)? {
            solids.push(s);
            hulls.push(h.points);
        }
    }
    if solids.is_empty() {
        return Ok(Some((Geom::Empty, None)));
    }
    let info = Hullable {
        points: hulls.iter().flatten().copied().collect(),
        convex: false,
        pieces: Some(hulls),
    };
    Ok(Some((Geom::Solid(Solid::union_all(solids)), Some(info))))
}

/// The vertices of the Minkowski sum of the convex hulls of `sets` (reduced to hull vertices
/// after each step).
fn minkowski_points(dim: u8, sets: impl Iterator<Item = Vec<DVec3>>) -> Vec<DVec3> {
    let reduce = |p: Vec<DVec3>| -> Vec<DVec3> {
        if dim == 2 {
            let flat: Vec<DVec2> = p.iter().map(|q| q.truncate()).collect();
            let ring = convex_hull_2d(&flat);
            return ring.into_iter().map(|q| q.extend(0.0)).collect();
        }
        match convex_hull(&p) {
            Some((v, _)) => v,
            None => p,
        }
    };
    let mut acc = vec![DVec3::ZERO];
    for set in sets {
        let set = reduce(set);
        let sum = acc
            .iter()
            .flat_map(|a| set.iter().map(move |b| *a + *b))
            .collect();
        acc = reduce(sum);
    }
    acc
}
