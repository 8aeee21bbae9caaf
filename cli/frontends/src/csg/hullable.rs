//! What `hull()` and `minkowski()` know about a statement under them ([`Hullable`]): the points
//! whose convex hull is its hull, known exactly from the tree, whether it is convex, its convex
//! pieces.

use super::error::CsgError;
use super::faces::fan_volume6;
use super::facets;
use super::flat::{Leaf2, Op2};
use super::geom::Geom;
use super::hull::{convex_hull, convex_hull_2d};
use super::parser::Stmt;
use super::pieces::{self, Piece};
use super::shape_args::{apply, cylinder_params, matrix, radius};
use glam::{DVec2, DVec3};
use solidkit_kernel::polyhedra::Polyhedron;

/// What `hull()` and `minkowski()` know about a statement under them: the points whose convex
/// hull is the statement's hull (round primitives faceted the OpenSCAD way), and whether the
/// statement is convex itself.
#[derive(Debug, Clone)]
pub(super) struct Hullable {
    pub(super) points: Vec<DVec3>,
    pub(super) convex: bool,
    /// The statement as convex pieces ([`super::pieces`]; 3D only), where known.
    pub(super) pieces: Option<Vec<Piece>>,
}

/// What `hull()` / `minkowski()` know about a statement under them, from its own arguments or its
/// children's; `None` when only its geometry can tell (then it is meshed).
pub(super) fn hullable_of(
    stmt: &Stmt,
    geom: &Geom,
    infos: Vec<Option<Hullable>>,
) -> Result<Option<Hullable>, CsgError> {
    let convex = |points: Vec<DVec3>| {
        let pieces = Some(if points.is_empty() {
            Vec::new()
        } else {
            vec![points.clone()]
        });
        Some(Hullable {
            points,
            convex: true,
            pieces,
        })
    };
    if matches!(geom, Geom::Empty) {
        return Ok(convex(Vec::new()));
    }
    Ok(match stmt.name.as_str() {
        "sphere" | "cylinder" | "cube" => convex(primitive_points(stmt)?),
        "circle" | "square" => Some(Hullable {
            points: flat_points(geom).unwrap_or_default(),
            convex: true,
            pieces: None,
        }),
        "polygon" => {
            let Geom::Flat(f) = geom else { return Ok(None) };
            let points = flat_points(geom).unwrap_or_default();
            let ring: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
            let single = matches!(&f.0[..], [Op2::Leaf(Leaf2::Polygon(loops))] if loops.len() == 1);
            let hull_area = area2(&convex_hull_2d(&ring)).abs();
            let is_convex = single && (area2(&ring).abs() - hull_area).abs() <= 1e-9 * hull_area;
            Some(Hullable {
                points,
                convex: is_convex,
                pieces: None,
            })
        }
        "polyhedron" => {
            let points = stmt.points("points", Some(0), 3)?;
            let volume = polyhedron_volume(stmt, &points)?;
            let hull_volume = convex_hull(&points)
                .and_then(|(v, f)| Polyhedron::new(v, f).ok())
                .map(|p| p.volume());
            let is_convex = matches!((volume, hull_volume), (Some(a), Some(b)) if (a - b).abs() <= 1e-9 * b.abs());
            let pieces = is_convex.then(|| vec![points.clone()]);
            Some(Hullable {
                points,
                convex: is_convex,
                pieces,
            })
        }
        "group" | "union" | "color" | "render" | "multmatrix" => {
            let Some(infos) = infos.into_iter().collect::<Option<Vec<Hullable>>>() else {
                return Ok(None);
            };
            let non_empty: Vec<&Hullable> = infos.iter().filter(|h| !h.points.is_empty()).collect();
            let is_convex = non_empty.len() == 1 && non_empty[0].convex;
            let mut points: Vec<DVec3> = infos
                .iter()
                .flat_map(|h| h.points.iter().copied())
                .collect();
            let mut pieces = infos
                .into_iter()
                .try_fold(Vec::new(), |acc, h| pieces::union(acc, h.pieces?));
            if stmt.name == "multmatrix" {
                let m = matrix(stmt)?;
                for p in points
                    .iter_mut()
                    .chain(pieces.iter_mut().flatten().flatten())
                {
                    *p = apply(&m, *p);
                }
            }
            Some(Hullable {
                points,
                convex: is_convex,
                pieces,
            })
        }
        "difference" | "intersection" if matches!(geom, Geom::Solid(_)) => {
            // Known exactly where every operand is made of convex pieces; meshed otherwise.
            let Some(infos) = infos.into_iter().collect::<Option<Vec<Hullable>>>() else {
                return Ok(None);
            };
            let Some(sets) = infos
                .into_iter()
                .map(|h| h.pieces)
                .collect::<Option<Vec<Vec<Piece>>>>()
            else {
                return Ok(None);
            };
            let mut sets = sets.into_iter();
            let first = sets.next().unwrap_or_default();
            let pieces = if stmt.name == "difference" {
                sets.try_fold(first, |acc, b| pieces::difference(acc, &b))
            } else {
                sets.try_fold(first, |acc, b| pieces::intersection(&acc, &b))
            };
            let Some(pieces) = pieces else {
                return Ok(None);
            };
            Some(Hullable {
                points: pieces.iter().flatten().copied().collect(),
                convex: pieces.len() == 1,
                pieces: Some(pieces),
            })
        }
        _ => None,
    })
}

/// The volume of a `polyhedron` statement (faces fanned; orientation ignored).
fn polyhedron_volume(stmt: &Stmt, points: &[DVec3]) -> Result<Option<f64>, CsgError> {
    let faces = match stmt.index_lists("faces", Some(1))? {
        Some(f) => f,
        None => match stmt.index_lists("triangles", None)? {
            Some(f) => f,
            None => return Ok(None),
        },
    };
    let mut six = 0.0;
    for f in &faces {
        let Some(v) = fan_volume6(points, f) else {
            return Ok(None);
        };
        six += v;
    }
    Ok(Some(six.abs() / 6.0))
}

/// Signed area of a loop (shoelace).
fn area2(l: &[DVec2]) -> f64 {
    (0..l.len())
        .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
        .sum::<f64>()
        / 2.0
}

/// The points of a 2D region made of leaves and unions only (circles faceted the OpenSCAD way),
/// at z = 0; `None` when it has a difference or intersection.
pub(super) fn flat_points(geom: &Geom) -> Option<Vec<DVec3>> {
    let Geom::Flat(f) = geom else { return None };
    let mut out = Vec::new();
    for op in &f.0 {
        match op {
            Op2::Leaf(Leaf2::Circle {
                center,
                radius,
                res,
            }) => out.extend(
                facets::circle(*radius, facets::fragments(*radius, *res))
                    .into_iter()
                    .map(|p| (p + *center).extend(0.0)),
            ),
            Op2::Leaf(Leaf2::Polygon(loops)) => {
                out.extend(loops.iter().flatten().map(|p| p.extend(0.0)))
            }
            Op2::Union(_) => {}
            Op2::Difference(_) | Op2::Intersection(_) => return None,
        }
    }
    Some(out)
}

/// The vertices of a primitive, round ones faceted the OpenSCAD way.
fn primitive_points(stmt: &Stmt) -> Result<Vec<DVec3>, CsgError> {
    Ok(match stmt.name.as_str() {
        "sphere" => {
            let r = radius(stmt, "r", "d", 0, 1.0)?;
            if r <= 0.0 {
                return Ok(Vec::new());
            }
            facets::sphere(r, stmt.resolution()?).0
        }
        "cylinder" => match cylinder_params(stmt)? {
            Some((r1, r2, z0, h)) => facets::cylinder(r1, r2, z0, z0 + h, stmt.resolution()?).0,
            None => Vec::new(),
        },
        _ => {
            let size = stmt.size3("size", Some(0), 1.0)?;
            let o = if stmt.flag("center", Some(1), false)? {
                -size / 2.0
            } else {
                DVec3::ZERO
            };
            (0..8)
                .map(|i| {
                    DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64) * size
                        + o
                })
                .collect()
        }
    })
}
