//! `resize(newsize, auto)` as in OpenSCAD (the User Manual's `resize`, 2021.01's
//! `CGAL_Nef_polyhedron::resize` / `Polygon2d::resize`): the children are scaled about the origin
//! so that their bounding box gets the new size. A size of 0 keeps that axis, unless its `auto`
//! flag is set: then the axis takes the scale of the axis with the largest new size (so
//! `resize([10, 0, 0], auto = true)` scales uniformly). A 2D child uses x and y only. Resizing an
//! axis along which the child is flat is skipped with a warning, as OpenSCAD does.
//!
//! The box is the geometry's own: from the tree where it is exact, or the kernel's box where the
//! children touch all its faces ([`super::bounds`]), else from a fine mesh of the children
//! ([`BBOX_RESOLUTION`] cells along the longest side).

use super::bounds::{tight_bbox, touched_bbox};
use super::error::CsgError;
use super::geom::{Ctx, Geom};
use super::operand::meshed_points;
use super::parser::{Stmt, Value};
use super::sweep::sweep;
use glam::DVec3;
use solidkit_kernel::primitive::{Extrude, Primitive};
use solidkit_kernel::{Aabb, Solid};
use std::sync::Arc;

/// Cells along the longest side of the grid on which children without an exact box are meshed.
pub const BBOX_RESOLUTION: usize = 256;

/// `newsize` and `auto` of a `resize` statement.
pub(super) fn arguments(stmt: &Stmt) -> Result<([f64; 3], [bool; 3]), CsgError> {
    let mut size = [0.0; 3];
    let bad = || stmt.error("'newsize': expected a vector of up to 3 numbers");
    match stmt.arg("newsize", Some(0)) {
        Some(Value::Num(n)) => size[0] = *n,
        Some(Value::Vector(items)) if items.len() <= 3 => {
            for (k, v) in items.iter().enumerate() {
                size[k] = match v {
                    Value::Num(n) => *n,
                    _ => return Err(bad()),
                };
            }
        }
        Some(Value::Undef) | None => {}
        Some(_) => return Err(bad()),
    }
    let truthy = |v: &Value| match v {
        Value::Bool(b) => *b,
        Value::Num(n) => *n != 0.0,
        _ => false,
    };
    let auto = match stmt.arg("auto", Some(1)) {
        Some(Value::Vector(items)) => {
            let mut a = [false; 3];
            for (k, v) in items.iter().take(3).enumerate() {
                a[k] = truthy(v);
            }
            a
        }
        Some(v) => [truthy(v); 3],
        None => [false; 3],
    };
    Ok((size, auto))
}

/// The scale factors OpenSCAD applies to a box of size `extent` in `dim` dimensions, or `None`
/// when a new size is asked along an axis where the box is flat.
pub fn factors(newsize: [f64; 3], auto: [bool; 3], extent: DVec3, dim: usize) -> Option<DVec3> {
    let extent = extent.to_array();
    let mut scale = [1.0; 3];
    let mut largest = 0;
    for i in 0..dim {
        if newsize[i] != 0.0 {
            if extent[i] == 0.0 {
                return None;
            }
            scale[i] = newsize[i] / extent[i];
            if newsize[i] > newsize[largest] {
                largest = i;
            }
        }
    }
    let autoscale = if newsize[largest] != 0.0 {
        newsize[largest] / extent[largest]
    } else {
        1.0
    };
    for i in 0..dim {
        if auto[i] && newsize[i] == 0.0 {
            scale[i] = autoscale;
        }
    }
    Some(DVec3::from_array(scale))
}

/// The bounding box of a solid: exact from the tree, else the box of a fine mesh.
fn solid_box(stmt: &Stmt, solid: &Solid) -> Result<Aabb, CsgError> {
    if let Some(b) = tight_bbox(solid).or_else(|| touched_bbox(solid)) {
        return Ok(b);
    }
    let points = meshed_points(stmt, &Geom::Solid(solid.clone()), BBOX_RESOLUTION)?;
    Ok(points
        .iter()
        .fold(Aabb::empty(), |b, p| b.union(&Aabb::new(*p, *p))))
}

/// `resize()` of the union of the children `geom`.
pub fn resize(stmt: &Stmt, geom: Geom, faceted: bool, ctx: &mut Ctx) -> Result<Geom, CsgError> {
    let (newsize, auto) = arguments(stmt)?;
    if newsize.iter().any(|v| !v.is_finite()) {
        ctx.warn(stmt, "'newsize' is inf or nan: the object is removed");
        return Ok(Geom::Empty);
    }
    let (bbox, dim) = match &geom {
        Geom::Empty => return Ok(Geom::Empty),
        Geom::Solid(s) => (solid_box(stmt, s)?, 3),
        Geom::Flat(f) => {
            let slab = sweep(stmt, f, faceted, |p| {
                Extrude::new(p, 1.0, 0.0, 1.0).map(|e| Primitive::Extrude(Arc::new(e)))
            })?;
            (solid_box(stmt, &slab)?, 2)
        }
    };
    if bbox.is_empty() {
        return Ok(Geom::Empty);
    }
    let Some(k) = factors(newsize, auto, bbox.size(), dim) else {
        ctx.warn(
            stmt,
            "resize in direction normal to flat object is not implemented: the object is unchanged",
        );
        return Ok(geom);
    };
    if k == DVec3::ONE {
        return Ok(geom);
    }
    Ok(match geom {
        Geom::Solid(s) => Geom::Solid(s.scale(k)),
        Geom::Flat(mut f) => {
            f.transform([[k.x, 0.0, 0.0], [0.0, k.y, 0.0]]);
            Geom::Flat(f)
        }
        Geom::Empty => Geom::Empty,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_keeps_an_axis_and_auto_follows_the_largest_new_size() {
        let e = DVec3::new(2.0, 4.0, 8.0);
        let k = factors([10.0, 0.0, 0.0], [false; 3], e, 3).unwrap();
        assert_eq!(k, DVec3::new(5.0, 1.0, 1.0));
        let k = factors([10.0, 0.0, 0.0], [true; 3], e, 3).unwrap();
        assert_eq!(k, DVec3::splat(5.0));
        // The largest new size (z: 16) sets the automatic scale (2), not the first one.
        let k = factors([4.0, 0.0, 16.0], [false, true, false], e, 3).unwrap();
        assert_eq!(k, DVec3::new(2.0, 2.0, 2.0));
        // 2D: z is never touched.
        let k = factors([4.0, 0.0, 5.0], [true; 3], e, 2).unwrap();
        assert_eq!(k, DVec3::new(2.0, 2.0, 1.0));
        // A new size across a flat box is refused.
        assert!(factors([1.0, 1.0, 1.0], [false; 3], DVec3::new(1.0, 1.0, 0.0), 3).is_none());
    }
}
