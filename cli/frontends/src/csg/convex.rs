//! OpenSCAD's faceted round primitives (spheres, cylinders, cones) as what they are, convex
//! polyhedra: the intersection of their face planes' half-spaces (and of their bounding box, which
//! bounds the tree). Its field, the largest signed distance to a face plane, is exact inside and a
//! 1-Lipschitz lower bound outside, with the polyhedron's surface as its zero set; it evaluates in
//! a dot product per face, where a general mesh solid needs a distance query through a tree.

use glam::DVec3;
use solidkit_kernel::Solid;

/// The convex polyhedron with corners `v` and faces `f` (planar polygons wound outward, as
/// `facets::sphere` and `facets::cylinder` make them), or `None` when a face is degenerate.
pub fn convex_polyhedron(v: &[DVec3], f: &[Vec<u32>]) -> Option<Solid> {
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for p in v {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    let size = hi - lo;
    if size.is_nan() || size.min_element() <= 0.0 {
        return None;
    }
    let mut parts = Vec::with_capacity(f.len() + 1);
    parts.push(Solid::cuboid(size).translate((lo + hi) / 2.0));
    for face in f {
        let corners: Vec<DVec3> = face
            .iter()
            .map(|&i| v.get(i as usize).copied())
            .collect::<Option<_>>()?;
        // Newell's normal: robust for any planar polygon.
        let mut n = DVec3::ZERO;
        let mut centre = DVec3::ZERO;
        for (k, a) in corners.iter().enumerate() {
            let b = corners[(k + 1) % corners.len()];
            n += DVec3::new(
                (a.y - b.y) * (a.z + b.z),
                (a.z - b.z) * (a.x + b.x),
                (a.x - b.x) * (a.y + b.y),
            );
            centre += *a;
        }
        let n = n.try_normalize()?;
        centre /= corners.len() as f64;
        parts.push(Solid::half_space(n, n.dot(centre)));
    }
    Some(Solid::intersection_all(parts))
}
