//! Which vertices the triangles use, marked in parallel (blocks of triangles, relaxed atomic
//! stores; the marks are idempotent, so the order of the stores does not matter).

use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// Triangles per parallel block: a flattened parallel iterator would split down to single
/// triangles.
const BLOCK: usize = 1 << 16;

/// `true` for each of `vertices` ids that some triangle names; ids out of range are ignored.
pub(crate) fn used_vertices(vertices: usize, triangles: &[[u32; 3]]) -> Vec<bool> {
    let used: Vec<AtomicBool> = (0..vertices).map(|_| AtomicBool::new(false)).collect();
    triangles.par_chunks(BLOCK).for_each(|c| {
        for &v in c.as_flattened() {
            if let Some(u) = used.get(v as usize) {
                u.store(true, Ordering::Relaxed);
            }
        }
    });
    used.into_iter().map(AtomicBool::into_inner).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marks_exactly_the_named_vertices_across_blocks() {
        // More triangles than one block, naming every third vertex; one id out of range.
        let n = 3 * BLOCK + 17;
        let mut triangles: Vec<[u32; 3]> = (0..BLOCK as u32 + 5)
            .map(|t| [3 * t % n as u32, (3 * t + 3) % n as u32, 0])
            .collect();
        triangles.push([0, 3, n as u32 + 9]);
        let used = used_vertices(n, &triangles);
        let mut expected = vec![false; n];
        for t in &triangles {
            for &v in t {
                if let Some(e) = expected.get_mut(v as usize) {
                    *e = true;
                }
            }
        }
        assert_eq!(used, expected);
        assert!(used.iter().step_by(3).all(|&u| u));
        assert!(!used[1] && !used[2]);
    }
}
