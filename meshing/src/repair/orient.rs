//! Consistent orientation: breadth-first over faces joined by two-face edges, each neighbour
//! wound so that it traverses the shared edge opposite to the face it was reached from.
//! Non-orientable pieces keep the first winding found (the report still flags them).

use crate::topology::{CornerLoops, EdgeTable};
use std::collections::VecDeque;

/// Re-winds faces so that every two-face edge is traversed once each way where possible;
/// `table` is the edge table of `tris`. Returns the edges used by one face only, as each face
/// traverses them after the re-winding, and which faces were reversed.
pub(super) fn orient_consistently(
    tris: &mut [[u32; 3]],
    table: &EdgeTable,
) -> (Vec<(u32, u32)>, Vec<bool>) {
    let loops: &[[u32; 3]] = tris;
    // The one-face edges, and whether every two-face edge is already traversed once each way:
    // then the search below would reverse nothing (each face is reached with the winding it
    // has), and is skipped.
    let mut boundary = Vec::new();
    let mut consistent = true;
    for edge in table.edges() {
        let mut corners = edge.corners();
        match (corners.next(), corners.next(), corners.next()) {
            (Some(c), None, _) => boundary.push(c),
            (Some(c), Some(d), None) => consistent &= loops.origin(c) != loops.origin(d),
            _ => {}
        }
    }
    if consistent {
        let open = boundary
            .into_iter()
            .map(|c| (loops.origin(c), loops.dest(c)))
            .collect();
        return (open, vec![false; tris.len()]);
    }
    // The corner across each two-face edge (`u32::MAX`: none).
    let mut mate = vec![u32::MAX; loops.corner_count()];
    for edge in table.edges() {
        let mut corners = edge.corners();
        if let (Some(c), Some(d), None) = (corners.next(), corners.next(), corners.next()) {
            mate[c] = d as u32;
            mate[d] = c as u32;
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
            for (c, &m) in mate.iter().enumerate().skip(3 * f).take(3) {
                if m == u32::MAX {
                    continue;
                }
                let g = m as usize / 3;
                if seen[g] {
                    continue;
                }
                // Both traverse the edge the same way: one of the two must turn.
                let same = loops.origin(c) == loops.origin(m as usize);
                flip[g] = flip[f] ^ same;
                seen[g] = true;
                queue.push_back(g);
            }
        }
    }
    let open = boundary
        .into_iter()
        .map(|c| {
            let (a, b) = (loops.origin(c), loops.dest(c));
            if flip[c / 3] { (b, a) } else { (a, b) }
        })
        .collect();
    for (t, &fl) in tris.iter_mut().zip(&flip) {
        if fl {
            t.swap(1, 2);
        }
    }
    (open, flip)
}
