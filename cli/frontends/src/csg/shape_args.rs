//! Primitive statements' arguments (radii, a cylinder's sizes, a `multmatrix` matrix) and the
//! simple solids built from them (polyhedra, OpenSCAD-faceted round primitives, cylinders).

use super::args::numbers;
use super::error::CsgError;
use super::facets;
use super::geom::Geom;
use super::parser::{Stmt, Value};
use glam::DVec3;
use solidkit_kernel::Solid;

/// A polyhedral solid, errors located at `stmt`.
pub(super) fn polyhedron(stmt: &Stmt, v: Vec<DVec3>, f: Vec<Vec<u32>>) -> Result<Solid, CsgError> {
    Solid::polyhedron(v, f).map_err(|e| stmt.error(e.to_string()))
}

/// OpenSCAD's faceting of a round primitive: a convex polyhedron of face planes
/// ([`super::convex`]), or a mesh solid where a face is degenerate.
pub(super) fn faceted_solid(
    stmt: &Stmt,
    v: Vec<DVec3>,
    f: Vec<Vec<u32>>,
) -> Result<Solid, CsgError> {
    match super::convex::convex_polyhedron(&v, &f) {
        Some(s) => Ok(s),
        None => polyhedron(stmt, v, f),
    }
}

/// A radius given as `r` or as diameter `d`.
pub(super) fn radius(
    stmt: &Stmt,
    r: &str,
    d: &str,
    position: usize,
    default: f64,
) -> Result<f64, CsgError> {
    if stmt.arg(d, None).is_some() {
        return Ok(stmt.num(d, None, 0.0)? / 2.0);
    }
    stmt.num(r, Some(position), default)
}

/// `cylinder(h, r1, r2, center)` (also `r`, `d`, `d1`, `d2`): exact cylinder or cone, or
/// OpenSCAD's faceted one.
pub(super) fn cylinder(stmt: &Stmt, faceted: bool) -> Result<Geom, CsgError> {
    let Some((r1, r2, z0, h)) = cylinder_params(stmt)? else {
        return Ok(Geom::Empty);
    };
    let s = if faceted {
        let (v, f) = facets::cylinder(r1, r2, z0, z0 + h, stmt.resolution()?);
        faceted_solid(stmt, v, f)?
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
pub(super) fn cylinder_params(stmt: &Stmt) -> Result<Option<(f64, f64, f64, f64)>, CsgError> {
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
pub(super) fn matrix(stmt: &Stmt) -> Result<[[f64; 4]; 3], CsgError> {
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

pub(super) fn is_identity(m: &[[f64; 4]; 3]) -> bool {
    (0..3).all(|i| (0..4).all(|j| m[i][j] == if i == j { 1.0 } else { 0.0 }))
}

/// `m·p` for a 3 × 4 affine matrix.
pub(super) fn apply(m: &[[f64; 4]; 3], p: DVec3) -> DVec3 {
    DVec3::from_array([0, 1, 2].map(|r| m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3]))
}
