//! Moves the copies of a split vertex apart: each copy (and the vertex it was copied from) moves
//! into its own shell, against the area-weighted normal of its faces, by half the weld budget
//! left to it. Shells that touched only at the split vertex or edge then no longer touch, and no
//! vertex ends further than the weld tolerance from where the input had it.

use super::split::Split;
use glam::DVec3;

/// Moves split vertices apart (see the module docs); returns how many vertices moved.
/// `budget[v]` is the distance vertex `v` (before the split) may still move.
pub(super) fn separate(
    positions: &mut [DVec3],
    tris: &[[u32; 3]],
    split: &Split,
    budget: &[f64],
) -> usize {
    if split.parent.len() == split.first_copy {
        return 0;
    }
    // Only vertices whose parent still has two or more copies in use (hole filling merges the
    // copies of a vertex whose fans it closed into one).
    let mut used = vec![false; positions.len()];
    for t in tris {
        for &v in t {
            used[v as usize] = true;
        }
    }
    let mut members = vec![0u32; positions.len()];
    for (v, &p) in split.parent.iter().enumerate() {
        if used[v] {
            members[p as usize] += 1;
        }
    }
    let mut in_group = vec![false; positions.len()];
    for (v, &p) in split.parent.iter().enumerate() {
        in_group[v] = used[v] && members[p as usize] > 1;
    }
    let mut normal = vec![DVec3::ZERO; positions.len()];
    for t in tris {
        if !t.iter().any(|&v| in_group[v as usize]) {
            continue;
        }
        let [a, b, c] = t.map(|i| positions[i as usize]);
        let n = (b - a).cross(c - a);
        for &v in t {
            normal[v as usize] += n;
        }
    }
    let mut moved = 0;
    for v in 0..positions.len() {
        let root = split.parent[v] as usize;
        let step = 0.5 * budget.get(root).copied().unwrap_or(0.0);
        if !in_group[v] || step <= 0.0 {
            continue;
        }
        if let Some(dir) = normal[v].try_normalize() {
            positions[v] -= dir * step;
            moved += 1;
        }
    }
    moved
}
