//! The operands of `hull()` and `minkowski()`, and the points of those not known exactly: the
//! vertices of a marching-cubes mesh, reduced to those of their hull.

use super::error::CsgError;
use super::geom::{Ctx, Geom};
use super::hull::convex_hull_within;
use super::hullable::{Hullable, flat_points};
use super::parser::Stmt;
use super::sweep::sweep;
use glam::DVec3;
use solidkit_kernel::primitive::{Extrude, Primitive};
use solidkit_kernel::{IndexedMesh, Solid};
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use std::sync::Arc;

/// How far the hull of meshed operand points may miss a point, in cells of the operand's grid:
/// the mesh vertices are only that accurate, and hulling them exactly gives thousands of sliver
/// faces along rounded-off edges.
const OPERAND_HULL_CELLS: f64 = 0.5;

/// Cells along the longest side of the grid on which `hull()` and `minkowski()` mesh an operand
/// whose points are not known exactly (a `difference`, an extrusion, …).
const OPERAND_RESOLUTION: usize = 128;

/// Points whose convex hull is the hull of `geom`, when they are not known exactly: the vertices
/// of its marching-cubes mesh ([`OPERAND_RESOLUTION`] cells along the longest side; 2D regions
/// are extruded to a unit slab, meshed and flattened).
fn geometry_points(stmt: &Stmt, geom: &Geom) -> Result<Vec<DVec3>, CsgError> {
    if let Some(points) = flat_points(geom) {
        return Ok(points);
    }
    let points = meshed_points(stmt, geom, OPERAND_RESOLUTION)?;
    if points.is_empty() {
        return Ok(points);
    }
    // Reduce to the vertices of their hull, within a fraction of a cell.
    let (lo, hi) = points.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let cell = (hi - lo).max_element() / OPERAND_RESOLUTION as f64;
    if matches!(geom, Geom::Flat(_)) {
        return Ok(points);
    }
    let eps = OPERAND_HULL_CELLS * cell;
    // Akl–Toussaint: the hull of the extreme points along a few hundred directions, and only
    // the points outside it, go to the incremental hull (whose cost grows with points × faces).
    let n = 256;
    let mut extreme: Vec<DVec3> = (0..n)
        .map(|k| {
            let z = 1.0 - (2 * k + 1) as f64 / n as f64;
            let phi = k as f64 * std::f64::consts::PI * (3.0 - 5f64.sqrt());
            let r = (1.0 - z * z).sqrt();
            let d = DVec3::new(r * phi.cos(), r * phi.sin(), z);
            points
                .iter()
                .copied()
                .max_by(|a, b| d.dot(*a).total_cmp(&d.dot(*b)))
                .expect("points")
        })
        .collect();
    let Some((v, f)) = convex_hull_within(&extreme, eps) else {
        return Ok(points);
    };
    let planes: Vec<(DVec3, f64)> = f
        .iter()
        .map(|t| {
            let [a, b, c] = [0, 1, 2].map(|i| v[t[i] as usize]);
            let n = (b - a).cross(c - a).normalize_or_zero();
            (n, n.dot(a))
        })
        .collect();
    extreme.extend(
        points
            .iter()
            .filter(|p| planes.iter().any(|(n, d)| n.dot(**p) - d > eps)),
    );
    Ok(match convex_hull_within(&extreme, eps) {
        Some((v, _)) => v,
        None => points,
    })
}

/// The vertices of a marching-cubes mesh of `geom` with `resolution` cells along the longest
/// side (2D regions extruded to a unit slab and flattened).
pub(super) fn meshed_points(
    stmt: &Stmt,
    geom: &Geom,
    resolution: usize,
) -> Result<Vec<DVec3>, CsgError> {
    let (solid, flatten) = match geom {
        Geom::Empty => return Ok(Vec::new()),
        Geom::Solid(s) => (s.clone(), false),
        Geom::Flat(f) => (
            sweep(stmt, f, true, |p| {
                Extrude::new(p, 1.0, 0.0, 1.0).map(|e| Primitive::Extrude(Arc::new(e)))
            })?,
            true,
        ),
    };
    let mut points = mesh_of(stmt, &solid, resolution)?.positions;
    if flatten {
        for p in &mut points {
            p.z = 0.0;
        }
    }
    Ok(points)
}

/// A marching-cubes mesh of `solid` with `resolution` cells along the longest side of its box
/// (empty for an empty solid); errors located at `stmt`.
pub(super) fn mesh_of(
    stmt: &Stmt,
    solid: &Solid,
    resolution: usize,
) -> Result<IndexedMesh, CsgError> {
    solid.validate().map_err(|e| stmt.error(e.to_string()))?;
    let bounds = solid.bbox();
    // A box without volume (operands that only touch) holds no solid.
    if bounds.is_empty() || (bounds.max - bounds.min).min_element() <= 0.0 {
        return Ok(IndexedMesh::default());
    }
    let spec = GridSpec::for_bounds(&bounds, resolution)
        .map_err(|e| stmt.error(format!("meshing an operand: {e}")))?;
    let (mesh, _) = mesh_sparse(&solid.compile(), spec, &SparseOptions::default())
        .map_err(|e| stmt.error(format!("meshing an operand: {e}")))?;
    Ok(mesh)
}

/// An operand of `hull()` / `minkowski()`: its geometry, points, and index among the kept
/// children.
pub(super) type Operand = (Geom, Hullable, usize);

/// The non-empty operands of `hull()` / `minkowski()` with their points (known or meshed), all
/// of the first operand's dimension (others are ignored with a warning, as OpenSCAD does).
pub(super) fn operands(
    stmt: &Stmt,
    children: Vec<Geom>,
    infos: Vec<Option<Hullable>>,
    ctx: &mut Ctx,
) -> Result<(Option<u8>, Vec<Operand>), CsgError> {
    let mut dim = None;
    let mut ignored = false;
    let mut out = Vec::new();
    for (k, (g, info)) in children.into_iter().zip(infos).enumerate() {
        let d = match &g {
            Geom::Empty => continue,
            Geom::Solid(_) => 3,
            Geom::Flat(_) => 2,
        };
        if dim.is_some_and(|x| x != d) {
            ignored = true;
            continue;
        }
        let info = match info {
            Some(h) => h,
            None => Hullable {
                points: geometry_points(stmt, &g)?,
                convex: false,
                pieces: None,
            },
        };
        // A child with no points (an intersection of disjoint parts, a difference that removes
        // everything) is skipped like an empty one, as OpenSCAD skips it: `minkowski()` of it
        // and a cube is the cube.
        if info.points.is_empty() {
            continue;
        }
        dim = Some(d);
        out.push((g, info, k));
    }
    if ignored {
        ctx.warn(
            stmt,
            "mixing 2D and 3D objects is not supported: the children of the other dimension than the first are ignored",
        );
    }
    Ok((dim, out))
}
