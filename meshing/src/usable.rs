//! Usable triangles: indices inside the vertex array and distinct. Only they take part in
//! adjacency and measures (the stars, the report, the self-intersection test, the distance
//! measures); the others count as degenerate faces.

use std::borrow::Cow;

use rayon::prelude::*;

use crate::IndexedMesh;

/// True when the triangle's indices are inside a vertex array of `vertex_count` and distinct.
pub(crate) fn is_usable(tri: &[u32; 3], vertex_count: usize) -> bool {
    let [a, b, c] = *tri;
    tri.iter().all(|&i| (i as usize) < vertex_count) && a != b && b != c && a != c
}

/// The usable triangles of `mesh`, borrowed when all are.
pub(crate) fn usable_triangles(mesh: &IndexedMesh) -> Cow<'_, [[u32; 3]]> {
    let n = mesh.positions.len();
    if mesh.triangles.par_iter().all(|t| is_usable(t, n)) {
        Cow::Borrowed(&mesh.triangles)
    } else {
        Cow::Owned(
            mesh.triangles
                .iter()
                .filter(|t| is_usable(t, n))
                .copied()
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::{is_usable, usable_triangles};
    use crate::IndexedMesh;
    use glam::DVec3;

    #[test]
    fn usable_requires_range_and_distinct_indices() {
        assert!(is_usable(&[0, 1, 2], 3));
        assert!(!is_usable(&[0, 1, 3], 3));
        assert!(!is_usable(&[0, 1, 1], 3));
        assert!(!is_usable(&[2, 1, 2], 3));
    }

    #[test]
    fn unusable_triangles_are_left_out_and_a_clean_list_is_borrowed() {
        let positions = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
        let clean = IndexedMesh::new(positions.clone(), vec![[0, 1, 2], [2, 1, 0]]);
        assert!(matches!(
            usable_triangles(&clean),
            std::borrow::Cow::Borrowed(_)
        ));
        let mixed = IndexedMesh::new(positions, vec![[0, 1, 1], [0, 1, 2], [0, 1, 3]]);
        assert_eq!(usable_triangles(&mixed).as_ref(), &[[0, 1, 2]]);
    }
}
