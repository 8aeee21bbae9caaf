//! Triangulation of a profile's region for the caps of tessellated sweeps: loops are nested by
//! containment (a loop inside an even number of others is an outline, inside an odd number a
//! hole of the innermost outline around it), and each outline is triangulated with its holes by
//! the shared constrained Delaunay triangulation ([`triangulate_loops`]). Only the given corners
//! are used (no new vertices): `n` corners and `h` holes give `n + 2h − 2` triangles per outline.

use super::error::ProfileError;
use super::polygon::inside_loop;
use crate::triangulate::{TriangulationError, triangulate_loops};
use glam::DVec2;

/// Triangles (counter-clockwise, as indices into the corners of all loops in order) covering the
/// even-odd region of `loops`, which must not cross or touch each other.
pub fn triangulate(loops: &[Vec<DVec2>]) -> Result<Vec<[u32; 3]>, ProfileError> {
    if let Some(l) = loops.iter().find(|l| l.len() < 3) {
        let problem = TriangulationError::TooFewCorners(l.len());
        return Err(ProfileError::Triangulation { problem });
    }
    let mut offsets = Vec::with_capacity(loops.len());
    let mut total = 0;
    for l in loops {
        offsets.push(total);
        total += l.len();
    }
    // Nesting depth of each loop and the innermost loop around it.
    let depth: Vec<usize> = (0..loops.len())
        .map(|r| {
            (0..loops.len())
                .filter(|&o| o != r && inside_loop(loops[r][0], &loops[o]))
                .count()
        })
        .collect();
    let parent = |r: usize| {
        (0..loops.len())
            .find(|&o| o != r && depth[o] + 1 == depth[r] && inside_loop(loops[r][0], &loops[o]))
    };
    let mut triangles = Vec::new();
    for outer in (0..loops.len()).filter(|&r| depth[r].is_multiple_of(2)) {
        let members: Vec<usize> = std::iter::once(outer)
            .chain(
                (0..loops.len())
                    .filter(|&h| !depth[h].is_multiple_of(2) && parent(h) == Some(outer)),
            )
            .collect();
        let region: Vec<&[DVec2]> = members.iter().map(|&r| loops[r].as_slice()).collect();
        // Corner numbers of the region's loops among all loops.
        let corner: Vec<u32> = members
            .iter()
            .flat_map(|&r| offsets[r]..offsets[r] + loops[r].len())
            .map(|i| i as u32)
            .collect();
        let local = triangulate_loops(&region)
            .map_err(|problem| ProfileError::Triangulation { problem })?;
        triangles.extend(local.iter().map(|t| t.map(|i| corner[i as usize])));
    }
    Ok(triangles)
}
