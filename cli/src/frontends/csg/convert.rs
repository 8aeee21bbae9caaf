//! The statement tree to a [`Solid`], post-order over an explicit work list: each statement's
//! geometry is built from its children's (3D solids, or 2D [`Flat`] programs under extrusions).

use super::Facets;
use super::args::numbers;
use super::error::CsgError;
use super::facets;
use super::flat::{Flat, Leaf2, Op2, profile};
use super::hull::{convex_hull, convex_hull_2d};
use super::parser::{Stmt, Tree, Value};
use glam::{DVec2, DVec3};
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::{Extrude, Primitive, Revolve};
use std::sync::Arc;

/// A statement's geometry.
#[derive(Debug, Clone)]
enum Geom {
    /// Nothing (an empty group, a zero-size primitive).
    Empty,
    /// A 3D solid.
    Solid(Solid),
    /// A 2D region.
    Flat(Flat),
}

/// Converts the whole tree (top-level statements form an implicit group).
pub fn convert(tree: &Tree, facets: Facets) -> Result<Solid, CsgError> {
    let mut results: Vec<Option<Geom>> = vec![None; tree.nodes.len()];
    let mut work: Vec<(usize, bool)> = tree.roots.iter().rev().map(|&r| (r, false)).collect();
    while let Some((i, expanded)) = work.pop() {
        let stmt = &tree.nodes[i];
        if stmt.name == "hull" {
            results[i] = Some(hull(tree, i)?);
        } else if !expanded {
            work.push((i, true));
            work.extend(stmt.children.iter().rev().map(|&c| (c, false)));
        } else {
            let children = stmt
                .children
                .iter()
                .map(|&c| results[c].take().expect("child converted"))
                .collect();
            results[i] = Some(node(stmt, children, facets)?);
        }
    }
    let top: Vec<Geom> = tree
        .roots
        .iter()
        .map(|&r| results[r].take().expect("root converted"))
        .collect();
    let root = Stmt {
        name: "group".into(),
        pos: Default::default(),
        args: Vec::new(),
        children: Vec::new(),
    };
    match group(&root, top, Op2::Union)? {
        Geom::Solid(s) => Ok(s),
        Geom::Empty => Err(CsgError::Empty),
        Geom::Flat(_) => Err(CsgError::argument(
            root.pos,
            "model",
            "the top-level geometry is 2D; extrude it to get a solid",
        )),
    }
}

/// The non-empty children combined: solids by union / `difference` / intersection, 2D regions
/// by the same operation in 2D; 2D and 3D may not be mixed.
fn group(stmt: &Stmt, children: Vec<Geom>, op: fn(usize) -> Op2) -> Result<Geom, CsgError> {
    let mut solids = Vec::new();
    let mut flats = Vec::new();
    for (k, c) in children.into_iter().enumerate() {
        match c {
            Geom::Empty if k == 0 && matches!(op(0), Op2::Difference(_)) => return Ok(Geom::Empty),
            Geom::Empty if matches!(op(0), Op2::Intersection(_)) => return Ok(Geom::Empty),
            Geom::Empty => {}
            Geom::Solid(s) => solids.push(s),
            Geom::Flat(f) => flats.push(f),
        }
    }
    if !solids.is_empty() && !flats.is_empty() {
        return Err(stmt.error("mixes 2D and 3D children"));
    }
    if !flats.is_empty() {
        return Ok(Geom::Flat(Flat::combine(flats, op)));
    }
    if solids.len() <= 1 {
        return Ok(solids.pop().map_or(Geom::Empty, Geom::Solid));
    }
    Ok(Geom::Solid(match op(0) {
        Op2::Difference(_) => {
            let base = solids.remove(0);
            Solid::difference_all(base, solids)
        }
        Op2::Intersection(_) => Solid::intersection_all(solids),
        _ => Solid::union_all(solids),
    }))
}

/// One statement from its children's geometry.
fn node(stmt: &Stmt, children: Vec<Geom>, facets: Facets) -> Result<Geom, CsgError> {
    let faceted = facets == Facets::OpenScad;
    let leaf = |what: Geom| {
        if stmt.children.is_empty() {
            Ok(what)
        } else {
            Err(stmt.error("takes no children"))
        }
    };
    match stmt.name.as_str() {
        "group" | "union" | "color" | "render" => group(stmt, children, Op2::Union),
        "difference" => group(stmt, children, Op2::Difference),
        "intersection" => group(stmt, children, Op2::Intersection),
        "multmatrix" => {
            let m = matrix(stmt)?;
            Ok(match group(stmt, children, Op2::Union)? {
                Geom::Solid(s) if is_identity(&m) => Geom::Solid(s),
                Geom::Solid(s) => Geom::Solid(s.affine(m)),
                Geom::Flat(mut f) => {
                    f.transform([[m[0][0], m[0][1], m[0][3]], [m[1][0], m[1][1], m[1][3]]]);
                    Geom::Flat(f)
                }
                Geom::Empty => Geom::Empty,
            })
        }
        "sphere" => {
            let r = radius(stmt, "r", "d", 0, 1.0)?;
            if r <= 0.0 {
                return leaf(Geom::Empty);
            }
            let s = if faceted {
                let (v, f) = facets::sphere(r, stmt.resolution()?);
                polyhedron(stmt, v, f)?
            } else {
                Solid::sphere(r)
            };
            leaf(Geom::Solid(s))
        }
        "cube" => {
            let size = stmt.size3("size", Some(0), 1.0)?;
            if size.min_element() <= 0.0 {
                return leaf(Geom::Empty);
            }
            let c = Solid::cuboid(size);
            let centred = stmt.flag("center", Some(1), false)?;
            leaf(Geom::Solid(if centred {
                c
            } else {
                c.translate(size / 2.0)
            }))
        }
        "cylinder" => cylinder(stmt, faceted).and_then(leaf),
        "polyhedron" => {
            let points = stmt.points("points", Some(0), 3)?;
            let faces = match stmt.index_lists("faces", Some(1))? {
                Some(f) => f,
                None => stmt
                    .index_lists("triangles", None)?
                    .ok_or_else(|| stmt.error("'faces': missing"))?,
            };
            // OpenSCAD lists faces clockwise seen from outside; the kernel counter-clockwise.
            let faces = faces
                .into_iter()
                .map(|f| f.into_iter().rev().collect())
                .collect();
            leaf(Geom::Solid(polyhedron(stmt, points, faces)?))
        }
        "circle" => {
            let r = radius(stmt, "r", "d", 0, 1.0)?;
            let res = stmt.resolution()?;
            leaf(if r <= 0.0 {
                Geom::Empty
            } else {
                Geom::Flat(Flat::leaf(Leaf2::Circle {
                    center: DVec2::ZERO,
                    radius: r,
                    res,
                }))
            })
        }
        "square" => {
            let s = stmt.size2("size", Some(0), 1.0)?;
            if s.min_element() <= 0.0 {
                return leaf(Geom::Empty);
            }
            let o = if stmt.flag("center", Some(1), false)? {
                -s / 2.0
            } else {
                DVec2::ZERO
            };
            let pts = [DVec2::ZERO, DVec2::new(s.x, 0.0), s, DVec2::new(0.0, s.y)];
            leaf(Geom::Flat(Flat::leaf(Leaf2::Polygon(vec![
                pts.map(|p| p + o).to_vec(),
            ]))))
        }
        "polygon" => {
            let points: Vec<DVec2> = stmt
                .points("points", Some(0), 2)?
                .iter()
                .map(|p| p.truncate())
                .collect();
            let paths = stmt
                .index_lists("paths", Some(1))?
                .unwrap_or_else(|| vec![(0..points.len() as u32).collect()]);
            let mut loops = Vec::new();
            for path in paths {
                let l = path
                    .iter()
                    .map(|&k| points.get(k as usize).copied())
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| stmt.error("'paths': index out of range"))?;
                loops.push(l);
            }
            if loops.iter().all(|l| l.len() < 3) {
                return leaf(Geom::Empty);
            }
            leaf(Geom::Flat(Flat::leaf(Leaf2::Polygon(loops))))
        }
        "linear_extrude" => {
            let Geom::Flat(flat) = group(stmt, children, Op2::Union)? else {
                return Err(stmt.error("expects 2D children"));
            };
            let h = stmt.num("height", Some(0), 100.0)?;
            let twist = stmt.num("twist", None, 0.0)?;
            let scale = stmt.size2("scale", None, 1.0)?;
            let centred = stmt.flag("center", None, false)?;
            let s = sweep(stmt, &flat, faceted, |p| {
                Extrude::with_scale(p, h, -twist, scale).map(|e| Primitive::Extrude(Arc::new(e)))
            })?;
            Ok(Geom::Solid(if centred {
                s
            } else {
                s.translate(DVec3::new(0.0, 0.0, h / 2.0))
            }))
        }
        "rotate_extrude" => {
            let Geom::Flat(flat) = group(stmt, children, Op2::Union)? else {
                return Err(stmt.error("expects 2D children"));
            };
            let angle = stmt.num("angle", None, 360.0)?;
            let s = sweep(stmt, &flat, faceted, |p| {
                Revolve::new(p, angle).map(|r| Primitive::Revolve(Arc::new(r)))
            })?;
            Ok(Geom::Solid(s))
        }
        other => Err(CsgError::Unsupported {
            pos: stmt.pos,
            name: other.to_string(),
        }),
    }
}

/// Replays a 2D program in 3D: each leaf swept by `make`.
fn sweep<E: std::fmt::Display>(
    stmt: &Stmt,
    flat: &Flat,
    faceted: bool,
    make: impl Fn(solidkit_kernel::profile::Profile) -> Result<Primitive, E>,
) -> Result<Solid, CsgError> {
    flat.evaluate(
        |leaf| {
            let p = profile(leaf, faceted).map_err(|e| stmt.error(format!("profile: {e}")))?;
            make(p)
                .map(Solid::primitive)
                .map_err(|e| stmt.error(e.to_string()))
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

/// A polyhedral solid, errors located at `stmt`.
fn polyhedron(stmt: &Stmt, v: Vec<DVec3>, f: Vec<Vec<u32>>) -> Result<Solid, CsgError> {
    Solid::polyhedron(v, f).map_err(|e| stmt.error(e.to_string()))
}

/// A radius given as `r` or as diameter `d`.
fn radius(stmt: &Stmt, r: &str, d: &str, position: usize, default: f64) -> Result<f64, CsgError> {
    if stmt.arg(d, None).is_some() {
        return Ok(stmt.num(d, None, 0.0)? / 2.0);
    }
    stmt.num(r, Some(position), default)
}

/// `cylinder(h, r1, r2, center)` (also `r`, `d`, `d1`, `d2`): exact cylinder or cone, or
/// OpenSCAD's faceted one.
fn cylinder(stmt: &Stmt, faceted: bool) -> Result<Geom, CsgError> {
    let Some((r1, r2, z0, h)) = cylinder_params(stmt)? else {
        return Ok(Geom::Empty);
    };
    let s = if faceted {
        let (v, f) = facets::cylinder(r1, r2, z0, z0 + h, stmt.resolution()?);
        polyhedron(stmt, v, f)?
    } else {
        let c = if r1 == r2 {
            Solid::cylinder(r1, h)
        } else {
            Solid::cone(r1, r2, h)
        };
        let mid = z0 + h / 2.0;
        if mid == 0.0 {
            c
        } else {
            c.translate(DVec3::new(0.0, 0.0, mid))
        }
    };
    Ok(Geom::Solid(s))
}

/// A cylinder's `(r1, r2, z0, h)`, or `None` when it is empty.
fn cylinder_params(stmt: &Stmt) -> Result<Option<(f64, f64, f64, f64)>, CsgError> {
    let h = stmt.num("h", Some(0), 1.0)?;
    let r = radius(stmt, "r", "d", usize::MAX, 1.0)?;
    let r1 = if stmt.arg("d1", None).is_some() {
        stmt.num("d1", None, 0.0)? / 2.0
    } else {
        stmt.num("r1", Some(1), r)?
    };
    let r2 = if stmt.arg("d2", None).is_some() {
        stmt.num("d2", None, 0.0)? / 2.0
    } else {
        stmt.num("r2", Some(2), r)?
    };
    let centred = stmt.flag("center", Some(3), false)?;
    if h <= 0.0 || r1 < 0.0 || r2 < 0.0 || (r1 == 0.0 && r2 == 0.0) {
        return Ok(None);
    }
    Ok(Some((r1, r2, if centred { -h / 2.0 } else { 0.0 }, h)))
}

/// `multmatrix(m)`: 4 rows (the last `[0, 0, 0, 1]`) or 3 rows of 4 numbers.
fn matrix(stmt: &Stmt) -> Result<[[f64; 4]; 3], CsgError> {
    let bad = || stmt.error("'m': expected a 4 × 4 affine matrix");
    let Some(Value::Vector(rows)) = stmt.arg("m", Some(0)) else {
        return Err(bad());
    };
    let rows: Vec<Vec<f64>> = rows
        .iter()
        .map(numbers)
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    if !(rows.len() == 3 || rows.len() == 4) || rows.iter().any(|r| r.len() != 4) {
        return Err(bad());
    }
    if rows.len() == 4 && rows[3] != [0.0, 0.0, 0.0, 1.0] {
        return Err(stmt.error("'m': projective matrices are not supported"));
    }
    Ok([0, 1, 2].map(|i| [rows[i][0], rows[i][1], rows[i][2], rows[i][3]]))
}

fn is_identity(m: &[[f64; 4]; 3]) -> bool {
    (0..3).all(|i| (0..4).all(|j| m[i][j] == if i == j { 1.0 } else { 0.0 }))
}

/// `hull()`: the convex hull of the children's points (round primitives always faceted the
/// OpenSCAD way), gathered over an explicit work list under the accumulated transforms.
fn hull(tree: &Tree, index: usize) -> Result<Geom, CsgError> {
    let stmt = &tree.nodes[index];
    let mut points = Vec::new();
    let mut dims = Vec::new();
    let mut work: Vec<(usize, [[f64; 4]; 3])> = stmt
        .children
        .iter()
        .map(|&c| {
            (
                c,
                [
                    [1.0, 0.0, 0.0, 0.0],
                    [0.0, 1.0, 0.0, 0.0],
                    [0.0, 0.0, 1.0, 0.0],
                ],
            )
        })
        .collect();
    while let Some((i, m)) = work.pop() {
        let s = &tree.nodes[i];
        let apply = |p: DVec3| {
            DVec3::from_array(
                [0, 1, 2].map(|r| m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3]),
            )
        };
        let mut local: Vec<DVec3> = Vec::new();
        match s.name.as_str() {
            "group" | "union" | "color" | "render" | "hull" => {
                work.extend(s.children.iter().map(|&c| (c, m)));
            }
            "multmatrix" => {
                let a = matrix(s)?;
                let mut prod = [[0.0; 4]; 3];
                for (r, row) in prod.iter_mut().enumerate() {
                    for (c, x) in row.iter_mut().enumerate() {
                        *x = (0..3).map(|k| m[r][k] * a[k][c]).sum::<f64>()
                            + if c == 3 { m[r][3] } else { 0.0 };
                    }
                }
                work.extend(s.children.iter().map(|&c| (c, prod)));
            }
            "sphere" | "cylinder" | "cube" | "polyhedron" => {
                dims.push((s.pos, 3));
                local = primitive_points(s)?;
            }
            "circle" | "square" | "polygon" => {
                dims.push((s.pos, 2));
                local = flat_points(s)?.into_iter().map(|p| p.extend(0.0)).collect();
            }
            other => {
                return Err(CsgError::Unsupported {
                    pos: s.pos,
                    name: format!("{other}' inside 'hull"),
                });
            }
        }
        points.extend(local.into_iter().map(apply));
    }
    if points.is_empty() {
        return Ok(Geom::Empty);
    }
    if let Some(&(pos, _)) = dims.iter().find(|d| d.1 != dims[0].1) {
        return Err(CsgError::argument(pos, "hull", "mixes 2D and 3D children"));
    }
    if dims[0].1 == 2 {
        let flat: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
        let ring = convex_hull_2d(&flat);
        if ring.len() < 3 {
            return Err(stmt.error("the points span no area"));
        }
        return Ok(Geom::Flat(Flat::leaf(Leaf2::Polygon(vec![ring]))));
    }
    let (v, f) = convex_hull(&points).ok_or_else(|| stmt.error("the points span no volume"))?;
    Ok(Geom::Solid(polyhedron(stmt, v, f)?))
}

/// The points of a 2D primitive (circles faceted the OpenSCAD way), for `hull()`.
fn flat_points(stmt: &Stmt) -> Result<Vec<DVec2>, CsgError> {
    let Geom::Flat(f) = node(stmt, Vec::new(), Facets::OpenScad)? else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    for op in f.0 {
        match op {
            Op2::Leaf(Leaf2::Circle {
                center,
                radius,
                res,
            }) => out.extend(
                facets::circle(radius, facets::fragments(radius, res))
                    .into_iter()
                    .map(|p| p + center),
            ),
            Op2::Leaf(Leaf2::Polygon(loops)) => out.extend(loops.into_iter().flatten()),
            _ => {}
        }
    }
    Ok(out)
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
        "cube" => {
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
        _ => stmt.points("points", Some(0), 3)?,
    })
}
