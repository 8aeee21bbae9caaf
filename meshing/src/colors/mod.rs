//! Per-triangle colours from a tree's `color` nodes (issue 14), for the 3MF, PLY and GLB writers.
//!
//! After meshing, each triangle takes the colour of the part whose surface it lies on: among the
//! tree's parts ([`Solid::colored_parts`]: primitives, or whole offsets, shells and smooth
//! Booleans, in world coordinates) whose box, grown by a margin, contains the triangle's
//! centroid, the one with the smallest `|field|` there. The colour of a part is its innermost
//! `color` ancestor's, or none. A difference's cut faces lie on the cutter and take its colour,
//! as in OpenSCAD's preview and its manifold backend. Parts are found through a
//! [`TriangleBvh`] of their boxes (degenerate triangles), so thousands of parts stay fast; the
//! triangles are coloured in parallel.
//!
//! Nothing is done for a tree without `color` nodes.

use crate::IndexedMesh;
use rayon::prelude::*;
use solidkit_kernel::bvh::TriangleBvh;
use solidkit_kernel::program::Program;
use solidkit_kernel::{Rgba, Solid};

/// The colours of a mesh's triangles: a palette of distinct colours and one palette index per
/// triangle ([`FaceColors::NONE`] for an uncoloured triangle, which writers give a default).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct FaceColors {
    /// Distinct colours as bytes `[r, g, b, a]`, in the order of the tree's parts.
    pub palette: Vec<[u8; 4]>,
    /// The palette index of each triangle, or [`FaceColors::NONE`].
    pub faces: Vec<u32>,
}

impl FaceColors {
    /// The index of an uncoloured triangle.
    pub const NONE: u32 = u32::MAX;

    /// The colour of triangle `t`, if it has one.
    pub fn color(&self, t: usize) -> Option<[u8; 4]> {
        self.faces
            .get(t)
            .and_then(|&i| self.palette.get(i as usize))
            .copied()
    }

    /// The colour of triangle `t`, or `default`.
    pub fn color_or(&self, t: usize, default: [u8; 4]) -> [u8; 4] {
        self.color(t).unwrap_or(default)
    }

    /// Number of distinct colours the triangles use.
    pub fn used(&self) -> usize {
        let mut seen = vec![false; self.palette.len()];
        for &i in &self.faces {
            if let Some(s) = seen.get_mut(i as usize) {
                *s = true;
            }
        }
        seen.iter().filter(|&&s| s).count()
    }

    /// True when some triangle has no colour.
    pub fn has_uncolored(&self) -> bool {
        self.faces.contains(&Self::NONE)
    }
}

/// The default colour of uncoloured triangles in files that need one for every triangle
/// (OpenSCAD's default yellow, `#f9d72c`).
pub const DEFAULT_COLOR: [u8; 4] = [0xf9, 0xd7, 0x2c, 0xff];

/// One part: its field, its box grown by the margin, and its palette index.
struct Part {
    program: Program,
    color: u32,
}

/// The colours of `mesh`'s triangles for the tree `solid`, or `None` when the tree has no
/// `color` node. `margin` grows each part's box (a few grid cells: the mesh lies within a cell
/// of the surface).
pub fn assign(solid: &Solid, mesh: &IndexedMesh, margin: f64) -> Option<FaceColors> {
    let parts = solid.colored_parts()?;
    let mut palette: Vec<[u8; 4]> = Vec::new();
    let mut index_of = |c: Option<Rgba>| match c {
        None => FaceColors::NONE,
        Some(c) => {
            let b = c.to_u8();
            let i = palette.iter().position(|&p| p == b).unwrap_or_else(|| {
                palette.push(b);
                palette.len() - 1
            });
            i as u32
        }
    };
    let mut finite = Vec::new();
    let mut boxes = Vec::new();
    let mut everywhere = Vec::new();
    for p in &parts {
        let part = Part {
            program: p.solid.compile(),
            color: index_of(p.color),
        };
        let b = p.solid.bbox();
        if b.is_empty() {
            continue;
        }
        if b.min.is_finite() && b.max.is_finite() {
            let (lo, hi) = (b.min - margin, b.max + margin);
            boxes.push([lo, hi, hi]);
            finite.push(part);
        } else {
            everywhere.push(part);
        }
    }
    let bvh = TriangleBvh::new(boxes, 4).ok();
    let faces = mesh
        .triangles
        .par_iter()
        .map_init(
            || (Vec::new(), Vec::new()),
            |(slots, hits): &mut (Vec<f64>, Vec<usize>), t| {
                let c = t
                    .iter()
                    .map(|&i| mesh.positions[i as usize])
                    .sum::<glam::DVec3>()
                    / 3.0;
                hits.clear();
                if let Some(bvh) = &bvh {
                    bvh.for_each_overlap(c, c, |slot| hits.push(bvh.slot_index(slot) as usize));
                }
                // Ties go to the first candidate (bounded parts in tree order, then unbounded
                // ones), for any thread count.
                hits.sort_unstable();
                let mut best = (f64::INFINITY, FaceColors::NONE);
                for part in hits.iter().map(|&k| &finite[k]).chain(&everywhere) {
                    let d = part.program.value_with(c, slots).abs();
                    if d < best.0 {
                        best = (d, part.color);
                    }
                }
                best.1
            },
        )
        .collect();
    Some(FaceColors { palette, faces })
}

#[cfg(test)]
pub(crate) mod tests;

impl crate::pipeline::Meshed {
    /// The colours of this mesh's triangles for the tree it was meshed from (see [`assign`]),
    /// or `None` when the tree has no `color` node. The margin is three final grid cells.
    pub fn face_colors(&self, solid: &Solid) -> Option<FaceColors> {
        assign(solid, &self.mesh, 3.0 * self.spec.cell)
    }
}
