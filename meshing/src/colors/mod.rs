//! Per-triangle colours from a tree's `color` nodes (issue 14), for the 3MF, PLY, GLB and OFF
//! writers.
//!
//! After meshing, each triangle takes the colour of the operand its surface comes from, as in
//! OpenSCAD: the tree's field at the triangle's centroid is traced from the root through the
//! Boolean skeleton ([`Solid::color_skeleton`]): at each union, intersection or difference the
//! operand whose value the node's minimum or maximum takes there is followed, down to a part (a
//! primitive, or a whole offset, shell or smooth Boolean, in world coordinates), whose innermost
//! `color` ancestor gives the colour (or none). So a difference's cut faces take the cutter's
//! colour (OpenSCAD's preview and its manifold backend), an intersection's faces each their own
//! operand's, and a part buried in a union or cut away never colours the surface, however near
//! its own surface passes.
//!
//! **Ties** (operands with exactly equal values, e.g. coincident faces) go to the operand that
//! comes first in the tree, with nested operations of one kind counted as one operand list
//! (`union(union(a, b), c)` is `min(a, b, c)`; a difference's base comes before its cutters).
//!
//! Only the parts whose box, grown by a margin, holds the centroid are evaluated (found through
//! a [`TriangleBvh`] of their boxes, so thousands of parts stay fast; unbounded parts always);
//! the others count as far outside (`+∞`). Only the skeleton nodes above the evaluated parts are
//! visited. Where no evaluated operand decides (a centroid the tree puts infinitely far), the
//! part with the smallest `|field|` gives the colour. The triangles are coloured in parallel.
//!
//! Nothing is done for a tree without `color` nodes.

use crate::IndexedMesh;
use rayon::prelude::*;
use solidkit_kernel::bvh::TriangleBvh;
use solidkit_kernel::program::Program;
use solidkit_kernel::{Rgba, Solid};
use trace::{Scratch, Tracer};

mod trace;

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

/// Per-thread buffers: evaluation slots, the parts found near a centroid, their values, and
/// the trace's scratch.
type Buffers = (Vec<f64>, Vec<usize>, Vec<(u32, f64)>, Scratch);

/// One part that can be evaluated: its index in the skeleton and its field.
struct Part {
    index: u32,
    program: Program,
}

/// The colours of `mesh`'s triangles for the tree `solid`, or `None` when the tree has no
/// `color` node. `margin` grows each part's box (a few grid cells: the mesh lies within a cell
/// of the surface); a part whose grown box misses a triangle's centroid counts as far outside
/// there.
pub fn assign(solid: &Solid, mesh: &IndexedMesh, margin: f64) -> Option<FaceColors> {
    let tracer = Tracer::new(solid.color_skeleton()?);
    let parts = &tracer.skeleton().parts;
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
    let mut colors = Vec::with_capacity(parts.len());
    let mut finite = Vec::new();
    let mut boxes = Vec::new();
    let mut everywhere = Vec::new();
    for (k, p) in parts.iter().enumerate() {
        colors.push(index_of(p.color));
        let b = p.solid.bbox();
        if b.is_empty() {
            continue; // never evaluated: far outside everywhere
        }
        let part = Part {
            index: k as u32,
            program: p.solid.compile(),
        };
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
            || (Vec::new(), Vec::new(), Vec::new(), Scratch::default()),
            |(slots, hits, values, scratch): &mut Buffers, t| {
                let c = t
                    .iter()
                    .map(|&i| mesh.positions[i as usize])
                    .sum::<glam::DVec3>()
                    / 3.0;
                hits.clear();
                if let Some(bvh) = &bvh {
                    bvh.for_each_overlap(c, c, |slot| hits.push(bvh.slot_index(slot) as usize));
                }
                hits.sort_unstable();
                values.clear();
                for part in hits.iter().map(|&k| &finite[k]).chain(&everywhere) {
                    values.push((part.index, part.program.value_with(c, slots)));
                }
                match tracer.trace(values, scratch) {
                    Some(k) => colors[k as usize],
                    // no operand decides (the centroid is far from every surface): the part
                    // with the smallest |field|, the first of equals
                    None => values
                        .iter()
                        .filter(|v| !v.1.is_nan())
                        .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()).then(a.0.cmp(&b.0)))
                        .map_or(FaceColors::NONE, |v| colors[v.0 as usize]),
                }
            },
        )
        .collect();
    Some(FaceColors { palette, faces })
}

#[cfg(test)]
pub(crate) mod tests;
#[cfg(test)]
mod tests_rule;

impl crate::pipeline::Meshed {
    /// The colours of this mesh's triangles for the tree it was meshed from (see [`assign`]),
    /// or `None` when the tree has no `color` node. The margin is three final grid cells.
    pub fn face_colors(&self, solid: &Solid) -> Option<FaceColors> {
        assign(solid, &self.mesh, 3.0 * self.spec.cell)
    }
}
