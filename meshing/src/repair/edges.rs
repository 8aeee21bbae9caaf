//! Undirected edge keys and the edge-to-faces map shared by the repair steps.

use std::collections::HashMap;

/// The undirected key of the edge `a`–`b`.
pub(super) fn key(a: u32, b: u32) -> (u32, u32) {
    if a < b { (a, b) } else { (b, a) }
}

/// The triangle rotated so that its smallest index comes first (winding kept).
pub(super) fn canonical(t: [u32; 3]) -> [u32; 3] {
    let m = (0..3).min_by_key(|&i| t[i]).unwrap_or(0);
    [t[m], t[(m + 1) % 3], t[(m + 2) % 3]]
}

/// The directed edges of a triangle.
pub(super) fn directed(t: [u32; 3]) -> [(u32, u32); 3] {
    [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]
}

/// Undirected edge → the faces using it (in face order).
pub(super) fn edge_faces(tris: &[[u32; 3]]) -> HashMap<(u32, u32), Vec<u32>> {
    let mut map: HashMap<(u32, u32), Vec<u32>> = HashMap::with_capacity(tris.len() * 3 / 2);
    for (f, t) in tris.iter().enumerate() {
        for (a, b) in directed(*t) {
            map.entry(key(a, b)).or_default().push(f as u32);
        }
    }
    map
}
