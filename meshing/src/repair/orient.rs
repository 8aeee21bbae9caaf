//! Consistent orientation: breadth-first over faces joined by two-face edges, each neighbour
//! wound so that it traverses the shared edge opposite to the face it was reached from.
//! Non-orientable pieces keep the first winding found (the report still flags them).

use super::edges::{edge_faces, has_directed};
use std::collections::VecDeque;

/// Re-winds faces so that every two-face edge is traversed once each way where possible.
pub(super) fn orient_consistently(tris: &mut [[u32; 3]]) {
    let map = edge_faces(tris);
    let mut neighbours: Vec<Vec<(u32, u32, u32)>> = vec![Vec::new(); tris.len()];
    for (&(a, b), faces) in &map {
        if let [f, g] = faces[..] {
            neighbours[f as usize].push((g, a, b));
            neighbours[g as usize].push((f, a, b));
        }
    }
    let mut flip = vec![false; tris.len()];
    let mut seen = vec![false; tris.len()];
    let mut queue = VecDeque::new();
    for start in 0..tris.len() {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        queue.push_back(start);
        while let Some(f) = queue.pop_front() {
            for &(g, a, b) in &neighbours[f] {
                if seen[g as usize] {
                    continue;
                }
                let f_ab = has_directed(tris[f], a, b) ^ flip[f];
                let g_ab = has_directed(tris[g as usize], a, b);
                flip[g as usize] = g_ab == f_ab;
                seen[g as usize] = true;
                queue.push_back(g as usize);
            }
        }
    }
    for (t, &fl) in tris.iter_mut().zip(&flip) {
        if fl {
            t.swap(1, 2);
        }
    }
}
