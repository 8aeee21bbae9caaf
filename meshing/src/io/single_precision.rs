//! What rounding to 32-bit floats does to a mesh: formats that store single precision (STL, GLB)
//! put distinct vertices closer than a float's step onto one point, and a reader that joins
//! corners by position (every STL reader: STL has no shared vertices) then finds edges or
//! vertices used more often than a manifold allows. The writers cannot avoid it; the count lets
//! the caller say so.

use crate::IndexedMesh;
use rayon::prelude::*;

/// Whether `format` stores positions as 32-bit floats.
pub fn is_single_precision(format: super::MeshFormat) -> bool {
    matches!(format, super::MeshFormat::Stl | super::MeshFormat::Glb)
}

/// How many used vertices of `mesh` land, rounded to `f32`, on the point of another used vertex
/// (each beyond the first at a point counts once; `-0.0` and `0.0` are one point).
pub fn single_precision_collisions(mesh: &IndexedMesh) -> usize {
    let used = crate::used::used_vertices(mesh.positions.len(), &mesh.triangles);
    let mut keys: Vec<u128> = mesh
        .positions
        .par_iter()
        .zip(&used)
        .filter(|(_, u)| **u)
        .map(|(p, _)| {
            let b = p.to_array().map(|c| {
                let f = c as f32;
                if f == 0.0 { 0 } else { f.to_bits() }
            });
            u128::from(b[0]) | u128::from(b[1]) << 32 | u128::from(b[2]) << 64
        })
        .collect();
    // Sorted, equal keys are neighbours: each key equal to its predecessor is one collision.
    keys.par_sort_unstable();
    keys.par_windows(2).filter(|w| w[0] == w[1]).count()
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn vertices_closer_than_a_float_step_collide() {
        let mut m = IndexedMesh::new(
            vec![
                DVec3::new(1.0, 0.0, 0.0),
                DVec3::new(1.0 + 1e-12, 0.0, 0.0),
                DVec3::new(0.0, 1.0, 0.0),
                DVec3::new(0.0, 0.0, 1.0),
                DVec3::new(-0.0, 1.0, 0.0),
                DVec3::new(5.0, 5.0, 5.0),
            ],
            vec![[0, 2, 3], [1, 4, 3]],
        );
        // 1 + 1e-12 rounds onto 1; -0.0 onto 0.0; the vertex 3 is shared, not a collision; the
        // unused vertex 5 does not count.
        assert_eq!(single_precision_collisions(&m), 2);
        m.positions[1].x = 1.0 + 1e-6;
        assert_eq!(single_precision_collisions(&m), 1);
    }

    #[test]
    fn each_vertex_beyond_the_first_at_a_point_counts_once() {
        // 200 000 vertices on a lattice of 1e-3, each nudged by less than a float step at its
        // coordinate every third time: groups of 1 to 3 vertices per rounded point.
        let points: Vec<DVec3> = (0..200_000u32)
            .map(|i| {
                let base = f64::from(i / 3) * 1e-3;
                let nudge = if i % 5 == 0 {
                    0.0
                } else {
                    1e-12 * f64::from(i % 3)
                };
                DVec3::new(base + nudge, 1.0, -base)
            })
            .collect();
        let triangles: Vec<[u32; 3]> = (0..points.len() as u32 / 3)
            .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
            .collect();
        let used = 3 * triangles.len();
        let mesh = IndexedMesh::new(points, triangles);
        let distinct: std::collections::HashSet<[u32; 3]> = mesh.positions[..used]
            .iter()
            .map(|p| p.to_array().map(|c| (c as f32 + 0.0).to_bits()))
            .collect();
        assert_eq!(single_precision_collisions(&mesh), used - distinct.len());
        assert!(used - distinct.len() > 100_000);
    }
}
