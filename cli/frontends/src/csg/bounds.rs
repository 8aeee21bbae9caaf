//! The bounding box of a solid as OpenSCAD measures it for `resize()`: the box of the geometry
//! itself, not a conservative bound. [`tight_bbox`] derives it from the tree where every node
//! keeps it exact (primitives, polyhedra, unions, transforms). Otherwise [`touched_bbox`] tries the
//! kernel's conservative box: when the solid reaches each of its six faces (a sample of the face
//! within noise of the surface or inside), that box is exact. Failing both, the caller meshes the
//! solid and takes the mesh's box.

use super::bound::Bound;
use glam::{DAffine3, DVec3};
use solidkit_kernel::primitive::{MeshSource, Primitive};
use solidkit_kernel::{Aabb, NodeKind, Solid};

/// Whether the linear part of `m` maps each axis onto an axis.
fn keeps_axes(m: &DAffine3) -> bool {
    let cols = [m.matrix3.x_axis, m.matrix3.y_axis, m.matrix3.z_axis];
    cols.iter()
        .all(|c| c.to_array().iter().filter(|v| **v != 0.0).count() <= 1)
}

/// The exact bound of a primitive, where the kernel's box is exact.
fn primitive_bound(p: &Primitive) -> Bound {
    use solidkit_kernel::primitive::Shape;
    match p {
        Primitive::Cuboid(_) => {
            let b = p.bbox();
            Bound::Points(
                (0..8)
                    .map(|i| {
                        DVec3::new(
                            if i & 1 == 0 { b.min.x } else { b.max.x },
                            if i & 2 == 0 { b.min.y } else { b.max.y },
                            if i & 4 == 0 { b.min.z } else { b.max.z },
                        )
                    })
                    .collect(),
            )
        }
        Primitive::Sphere(_) | Primitive::Cylinder(_) | Primitive::Cone(_) => Bound::Box(p.bbox()),
        Primitive::Extrude(e) if e.twist() == 0.0 => Bound::Box(p.bbox()),
        Primitive::HalfSpace(h) => Bound::Plane(h.normal, h.offset),
        Primitive::Mesh(m) => match m.source() {
            MeshSource::Faces { vertices, faces } => Bound::Points(
                faces
                    .iter()
                    .flatten()
                    .filter_map(|&k| vertices.get(k as usize).copied())
                    .collect(),
            ),
            _ => Bound::Box(p.bbox()),
        },
        _ => Bound::Unknown,
    }
}

/// The exact box of `solid`, when the tree tells it; `None` when only its geometry can (a
/// difference, an intersection, a rotated round primitive, …).
pub fn tight_bbox(solid: &Solid) -> Option<Aabb> {
    solid
        .fold(|s, c: &[Bound]| match s.kind() {
            NodeKind::Primitive(p) => primitive_bound(p),
            NodeKind::Union => {
                if c.iter().all(|b| matches!(b, Bound::Points(_))) {
                    Bound::Points(
                        c.iter()
                            .flat_map(|b| match b {
                                Bound::Points(p) => p.clone(),
                                _ => Vec::new(),
                            })
                            .collect(),
                    )
                } else {
                    c.iter()
                        .map(Bound::aabb)
                        .try_fold(Aabb::empty(), |a, b| b.map(|b| a.union(&b)))
                        .map_or(Bound::Unknown, Bound::Box)
                }
            }
            NodeKind::Intersection => {
                super::clip::convex_bound(c).map_or(Bound::Unknown, Bound::Points)
            }
            NodeKind::Transform(t) => match c.first() {
                Some(Bound::Points(p)) => {
                    Bound::Points(p.iter().map(|q| t.forward.transform_point3(*q)).collect())
                }
                Some(Bound::Box(b)) if keeps_axes(&t.forward) => {
                    Bound::Box(b.transformed(&t.forward))
                }
                _ => Bound::Unknown,
            },
            NodeKind::Color(_) => c.first().cloned().unwrap_or(Bound::Unknown),
            _ => Bound::Unknown,
        })
        .aabb()
}

/// Samples per side of each face of the box in [`touched_bbox`].
const FACE_SAMPLES: usize = 33;

/// The kernel's box of `solid` when the solid touches each of its faces (then no smaller box
/// holds it), else `None`.
pub fn touched_bbox(solid: &Solid) -> Option<Aabb> {
    let b = solid.bbox();
    if b.is_empty() || !(b.min.is_finite() && b.max.is_finite()) {
        return None;
    }
    let program = solid.compile();
    let noise = 1e-6 * (b.max - b.min).max_element();
    let mut scratch = Default::default();
    let n = FACE_SAMPLES;
    let (mut x, mut y, mut z) = (Vec::new(), Vec::new(), Vec::new());
    let mut out = vec![0.0f32; n * n];
    for axis in 0..3 {
        for side in [b.min, b.max] {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            x.clear();
            y.clear();
            z.clear();
            for j in 0..n {
                for i in 0..n {
                    let mut p = side;
                    let t = |k: usize| k as f64 / (n - 1) as f64;
                    p[u] = b.min[u] + (b.max[u] - b.min[u]) * t(i);
                    p[v] = b.min[v] + (b.max[v] - b.min[v]) * t(j);
                    p[axis] = side[axis];
                    x.push(p.x as f32);
                    y.push(p.y as f32);
                    z.push(p.z as f32);
                }
            }
            program.eval_many(&x, &y, &z, &mut out, &mut scratch);
            if !out.iter().any(|&f| f64::from(f) <= noise) {
                return None;
            }
        }
    }
    Some(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primitives_unions_and_axis_maps_are_exact() {
        let s = Solid::union_all(vec![
            Solid::sphere(1.0),
            Solid::cuboid(DVec3::new(2.0, 4.0, 6.0)).translate(DVec3::new(5.0, 0.0, 0.0)),
        ]);
        let b = tight_bbox(&s).unwrap();
        assert_eq!(b.min, DVec3::new(-1.0, -2.0, -3.0));
        assert_eq!(b.max, DVec3::new(6.0, 2.0, 3.0));
        // A rotated box stays exact (its corners), a rotated sphere does not.
        let r = Solid::cuboid(DVec3::ONE).rotate(DVec3::Z, 45.0);
        let b = tight_bbox(&r).unwrap();
        assert!((b.max.x - 0.5f64.sqrt()).abs() < 1e-12);
        assert!(tight_bbox(&Solid::sphere(1.0).rotate(DVec3::Z, 45.0)).is_none());
        let d = Solid::difference_all(Solid::sphere(1.0), vec![Solid::sphere(0.5)]);
        assert!(tight_bbox(&d).is_none());
    }

    #[test]
    fn a_difference_touching_its_box_keeps_it_one_that_does_not_is_unknown() {
        let cube = Solid::cuboid(DVec3::splat(10.0));
        let hole = Solid::cylinder(2.0, 12.0);
        let d = Solid::difference_all(cube.clone(), vec![hole]);
        assert_eq!(touched_bbox(&d).map(|b| b.max), Some(DVec3::splat(5.0)));
        // Cutting off the +x half leaves the kernel's box untouched at x = 5.
        let half = Solid::cuboid(DVec3::splat(12.0)).translate(DVec3::new(6.0, 0.0, 0.0));
        assert!(touched_bbox(&Solid::difference_all(cube, vec![half])).is_none());
    }
}
