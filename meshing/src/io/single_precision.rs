//! What rounding to 32-bit floats does to a mesh: formats that store single precision (STL, GLB)
//! put distinct vertices closer than a float's step onto one point, and a reader that joins
//! corners by position (every STL reader: STL has no shared vertices) then finds edges or
//! vertices used more often than a manifold allows. The writers cannot avoid it; the count lets
//! the caller say so.

use rayon::prelude::*;
use std::collections::HashMap;

use super::key_hash::KeyHash;
use crate::IndexedMesh;

/// Whether `format` stores positions as 32-bit floats.
pub fn is_single_precision(format: super::MeshFormat) -> bool {
    matches!(format, super::MeshFormat::Stl | super::MeshFormat::Glb)
}

/// How many used vertices of `mesh` land, rounded to `f32`, on the point of another used vertex
/// (each beyond the first at a point counts once; `-0.0` and `0.0` are one point).
pub fn single_precision_collisions(mesh: &IndexedMesh) -> usize {
    let mut used = vec![false; mesh.positions.len()];
    for t in &mesh.triangles {
        for &v in t {
            if let Some(u) = used.get_mut(v as usize) {
                *u = true;
            }
        }
    }
    let keys: Vec<u128> = mesh
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
    let mut seen: HashMap<u128, (), KeyHash> =
        HashMap::with_capacity_and_hasher(keys.len(), KeyHash::default());
    keys.into_iter()
        .filter(|k| seen.insert(*k, ()).is_some())
        .count()
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
}
