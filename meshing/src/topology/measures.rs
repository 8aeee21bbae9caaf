//! Geometric measures: signed volume, area, bounding box and degenerate faces.
//!
//! Sums run in parallel over fixed-size chunks whose partial results are combined in chunk order,
//! so the floating-point result is the same on every run and thread count.

use glam::DVec3;
use rayon::prelude::*;

use super::MAX_EXAMPLES;
use crate::IndexedMesh;
use crate::usable::is_usable;

/// Triangles per parallel work item.
const CHUNK: usize = 1 << 14;

/// Relative area threshold of a degenerate face: `|cross| <= EPS * longest_edge²`.
const DEGENERATE_EPS: f64 = 1e-12;

/// The measures of one mesh.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Measures {
    /// Signed volume (positive for outward winding of a closed mesh).
    pub(crate) volume: f64,
    /// Total area.
    pub(crate) area: f64,
    /// Bounding box of the referenced vertices.
    pub(crate) bbox: [[f64; 3]; 2],
    /// Number of degenerate triangles.
    pub(crate) degenerate: usize,
    /// The first few degenerate triangles, ascending.
    pub(crate) degenerate_examples: Vec<u32>,
}

/// Partial sums of one chunk of triangles.
#[derive(Debug, Clone, Default)]
struct Partial {
    volume: f64,
    area: f64,
    degenerate: usize,
    examples: Vec<u32>,
}

impl Partial {
    /// Appends `other` (a later chunk) to `self`.
    fn absorb(mut self, other: Self) -> Self {
        self.volume += other.volume;
        self.area += other.area;
        self.degenerate += other.degenerate;
        let room = MAX_EXAMPLES.saturating_sub(self.examples.len());
        self.examples.extend(other.examples.into_iter().take(room));
        self
    }
}

impl Measures {
    /// Measures `mesh`; `referenced(v)` says which vertices the bounding box covers.
    ///
    /// Triangles that are not [usable](is_usable) count as degenerate and add nothing else. The
    /// volume is taken relative to the bounding-box centre (exact for closed meshes, better
    /// conditioned than the origin far from it).
    pub(crate) fn of(mesh: &IndexedMesh, referenced: impl Fn(usize) -> bool + Sync) -> Self {
        let bbox = bounding_box(&mesh.positions, referenced);
        let center = (DVec3::from(bbox[0]) + DVec3::from(bbox[1])) * 0.5;
        let total = mesh
            .triangles
            .par_chunks(CHUNK)
            .enumerate()
            .map(|(i, chunk)| chunk_partial(mesh, i * CHUNK, chunk, center))
            .collect::<Vec<_>>()
            .into_iter()
            .fold(Partial::default(), Partial::absorb);
        Self {
            volume: total.volume,
            area: total.area,
            bbox,
            degenerate: total.degenerate,
            degenerate_examples: total.examples,
        }
    }
}

/// Sums one chunk of triangles starting at triangle `first`.
fn chunk_partial(mesh: &IndexedMesh, first: usize, chunk: &[[u32; 3]], center: DVec3) -> Partial {
    let mut partial = Partial::default();
    let (mut volume6, mut area2) = (0.0, 0.0);
    for (offset, tri) in chunk.iter().enumerate() {
        let degenerate = match corners(mesh, tri) {
            Some(corners) => {
                let (cross, longest_sq) = cross_and_longest(corners);
                // det(a − c, b − c, d − c) = (a − c) · ((b − a) × (d − a)).
                volume6 += (corners[0] - center).dot(cross);
                let length = cross.length();
                area2 += length;
                length <= DEGENERATE_EPS * longest_sq
            }
            None => true,
        };
        if degenerate {
            partial.degenerate += 1;
            if partial.examples.len() < MAX_EXAMPLES {
                partial
                    .examples
                    .push(u32::try_from(first + offset).unwrap_or(u32::MAX));
            }
        }
    }
    partial.volume = volume6 / 6.0;
    partial.area = area2 * 0.5;
    partial
}

/// The corner positions of a usable triangle.
fn corners(mesh: &IndexedMesh, tri: &[u32; 3]) -> Option<[DVec3; 3]> {
    is_usable(tri, mesh.positions.len()).then(|| tri.map(|i| mesh.positions[i as usize]))
}

/// The (unnormalised) normal and the squared length of the longest edge.
fn cross_and_longest([a, b, c]: [DVec3; 3]) -> (DVec3, f64) {
    let (ab, ac) = (b - a, c - a);
    let longest_sq = ab
        .length_squared()
        .max((ac - ab).length_squared())
        .max(ac.length_squared());
    (ab.cross(ac), longest_sq)
}

/// Bounding box of the referenced positions; all zeros when there are none.
fn bounding_box(positions: &[DVec3], referenced: impl Fn(usize) -> bool + Sync) -> [[f64; 3]; 2] {
    let empty = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    let (lo, hi) = positions
        .par_iter()
        .enumerate()
        .filter(|&(v, _)| referenced(v))
        .fold(|| empty, |(lo, hi), (_, &p)| (lo.min(p), hi.max(p)))
        .reduce(|| empty, |(l0, h0), (l1, h1)| (l0.min(l1), h0.max(h1)));
    if lo.x > hi.x {
        [[0.0; 3]; 2]
    } else {
        [lo.to_array(), hi.to_array()]
    }
}

#[cfg(test)]
mod tests {
    use super::Measures;
    use crate::IndexedMesh;
    use glam::DVec3;

    #[test]
    fn single_triangle_area_and_degenerates() {
        let mesh = IndexedMesh::new(
            vec![
                DVec3::ZERO,
                DVec3::X,
                DVec3::Y,
                DVec3::new(2.0, 0.0, 0.0),
                DVec3::new(5.0, 5.0, 5.0),
            ],
            vec![[0, 1, 2], [0, 1, 3], [0, 0, 1], [0, 1, 7]],
        );
        let m = Measures::of(&mesh, |v| v < 4);
        assert_eq!(m.area, 0.5);
        assert_eq!(m.degenerate, 3);
        assert_eq!(m.degenerate_examples, vec![1, 2, 3]);
        assert_eq!(m.bbox, [[0.0, 0.0, 0.0], [2.0, 1.0, 0.0]]);
    }

    #[test]
    fn empty_mesh_has_zero_box() {
        let m = Measures::of(&IndexedMesh::default(), |_| true);
        assert_eq!(m.bbox, [[0.0; 3]; 2]);
        assert_eq!((m.volume, m.area, m.degenerate), (0.0, 0.0, 0));
    }
}
