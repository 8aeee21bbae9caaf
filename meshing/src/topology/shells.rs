//! Shells: connected components of triangles, where sharing a vertex connects.
//!
//! The vertex pass (`mod.rs`) joins the two ends of every edge in a concurrent union-find over
//! vertices; [`Shells::number`] then numbers the sets by their smallest triangle index (the order
//! of [`super::TopologyReport::genus_per_shell`]). [`ShellTally`] sums each shell's vertices'
//! shares of `V − E + F` and defect flags (`local.rs`), giving the genus of every shell that is a
//! closed, oriented manifold (χ = 2 − 2g).

use super::atomic_union_find::AtomicUnionFind;
use super::local::Share;
use std::collections::HashSet;

use glam::DVec3;
use rayon::prelude::*;

use crate::io::key_hash::KeyHash;

/// Triangles per parallel work item of the numbering.
const TRIANGLE_CHUNK: usize = 1 << 15;

/// Marker for "no shell" (an unreferenced vertex).
const NONE: u32 = u32::MAX;

/// The shell of every vertex.
#[derive(Debug, Clone)]
pub(crate) struct Shells {
    /// Shell number of each vertex, `NONE` when unreferenced.
    of_vertex: Vec<u32>,
    /// Number of shells.
    count: usize,
}

impl Shells {
    /// Numbers the sets of `sets` (over all vertices, every edge's ends joined; `used(v)`: some
    /// triangle uses `v`) in order of their smallest triangle in `triangles`.
    pub(crate) fn number(
        sets: &AtomicUnionFind,
        used: impl Fn(usize) -> bool + Sync,
        triangles: &[[u32; 3]],
    ) -> Self {
        let roots: Vec<u32> = (0..sets.len())
            .into_par_iter()
            .with_min_len(4096)
            .map(|v| if used(v) { sets.find(v) as u32 } else { NONE })
            .collect();
        // Each chunk of triangles lists the roots it meets first, in order (a root repeated from
        // the triangle before costs no lookup); the lists, in chunk order, number the roots.
        let firsts: Vec<Vec<u32>> = triangles
            .par_chunks(TRIANGLE_CHUNK)
            .map(|chunk| {
                let mut seen: HashSet<u32, KeyHash> = HashSet::default();
                let mut order = Vec::new();
                let mut last = NONE;
                for tri in chunk {
                    let r = roots[tri[0] as usize];
                    if r != last && seen.insert(r) {
                        order.push(r);
                    }
                    last = r;
                }
                order
            })
            .collect();
        // Each root's number plus one, at the root's index: zeroed pages, of which only those
        // holding roots are ever touched (a filled vertex-size array was a serial pass of its
        // own). The roots then become the numbers in place.
        let mut number_of_root = vec![0u32; roots.len()];
        let mut count = 0usize;
        for r in firsts.into_iter().flatten() {
            let slot = &mut number_of_root[r as usize];
            if *slot == 0 {
                count += 1;
                *slot = u32::try_from(count).unwrap_or(NONE);
            }
        }
        let mut of_vertex = roots;
        of_vertex.par_iter_mut().with_min_len(4096).for_each(|r| {
            if *r != NONE {
                *r = number_of_root[*r as usize] - 1;
            }
        });
        Self { of_vertex, count }
    }

    /// Number of shells.
    pub(crate) fn count(&self) -> usize {
        self.count
    }

    /// Shell of vertex `v`, `None` when no triangle uses it.
    pub(crate) fn of_vertex(&self, v: usize) -> Option<usize> {
        match self.of_vertex[v] {
            NONE => None,
            s => Some(s as usize),
        }
    }
}

/// Per-shell `V − E + F`, defect flags and bounding boxes, and the referenced vertex count.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ShellTally {
    chi: Vec<i64>,
    defective: Vec<bool>,
    boxes: Vec<[DVec3; 2]>,
    vertices: usize,
}

/// Most shells for which every chunk of vertices keeps its own per-shell tallies (in parallel);
/// beyond that one serial pass.
const PARALLEL_SHELLS: usize = 256;

/// Vertices per parallel work item.
const CHUNK: usize = 1 << 14;

impl ShellTally {
    /// Sums the vertices' shares (`shares[v]`: vertex `v`'s share of `V − E + F` and whether it
    /// or one of its edges is a defect) and boxes the shells' vertices (`positions`). Sums of
    /// integers, minima and maxima: the same on any thread count.
    pub(crate) fn new(shells: &Shells, shares: &[Share], positions: &[DVec3]) -> Self {
        let n = shells.count();
        let tally_of = |first: usize, shares: &[Share]| {
            let mut tally = Self::empty(n);
            for (offset, &Share { chi, defective, .. }) in shares.iter().enumerate() {
                let v = first + offset;
                if let Some(s) = shells.of_vertex(v) {
                    tally.chi[s] += i64::from(chi);
                    tally.defective[s] |= defective;
                    let b = &mut tally.boxes[s];
                    b[0] = b[0].min(positions[v]);
                    b[1] = b[1].max(positions[v]);
                    tally.vertices += 1;
                }
            }
            tally
        };
        if n > PARALLEL_SHELLS {
            return tally_of(0, shares);
        }
        shares
            .par_chunks(CHUNK)
            .enumerate()
            .map(|(i, chunk)| tally_of(i * CHUNK, chunk))
            .reduce(|| Self::empty(n), Self::absorb)
    }

    /// No shell counted yet, for `n` shells.
    fn empty(n: usize) -> Self {
        Self {
            chi: vec![0; n],
            defective: vec![false; n],
            boxes: vec![[DVec3::INFINITY, DVec3::NEG_INFINITY]; n],
            vertices: 0,
        }
    }

    /// Adds `other`'s tallies to `self`'s.
    fn absorb(mut self, other: Self) -> Self {
        for s in 0..self.chi.len() {
            self.chi[s] += other.chi[s];
            self.defective[s] |= other.defective[s];
            self.boxes[s][0] = self.boxes[s][0].min(other.boxes[s][0]);
            self.boxes[s][1] = self.boxes[s][1].max(other.boxes[s][1]);
        }
        self.vertices += other.vertices;
        self
    }

    /// The genus of every shell that is a closed oriented manifold, `None` for the others.
    pub(crate) fn genus(&self) -> Vec<Option<i64>> {
        self.chi
            .iter()
            .zip(&self.defective)
            .map(|(&chi, &defective)| {
                let twice_genus = 2 - chi;
                let valid = !defective && twice_genus >= 0 && twice_genus % 2 == 0;
                valid.then_some(twice_genus / 2)
            })
            .collect()
    }

    /// Each shell's bounding box, in shell order.
    pub(crate) fn into_boxes(self) -> Vec<[DVec3; 2]> {
        self.boxes
    }

    /// The referenced vertices.
    pub(crate) fn vertices(&self) -> usize {
        self.vertices
    }
}

#[cfg(test)]
mod tests {
    use super::{AtomicUnionFind, Share, ShellTally, Shells};
    use crate::stars::Stars;
    use glam::DVec3;

    /// The shells of `tris` with every triangle's vertices joined.
    fn shells(tris: &[[u32; 3]], vertex_count: usize) -> Shells {
        let stars = Stars::build(tris, vertex_count);
        let sets = AtomicUnionFind::new(vertex_count);
        for t in tris {
            sets.union(t[0] as usize, t[1] as usize);
            sets.union(t[0] as usize, t[2] as usize);
        }
        Shells::number(&sets, |v| stars.is_referenced(v), tris)
    }

    #[test]
    fn shells_join_through_shared_vertices_and_are_numbered_by_first_triangle() {
        // Triangles 0 and 2 share vertex 2; triangle 1 is separate (and has the smallest
        // vertices); vertex 9 unused.
        let tris = [[3, 4, 2], [0, 1, 5], [2, 6, 7]];
        let shells = shells(&tris, 10);
        assert_eq!(shells.count(), 2);
        assert_eq!(shells.of_vertex(3), Some(0));
        assert_eq!(shells.of_vertex(0), Some(1));
        assert_eq!(shells.of_vertex(7), Some(0));
        assert_eq!(shells.of_vertex(9), None);
    }

    #[test]
    fn tally_gives_genus_only_for_sound_shells_and_boxes_them() {
        let tris = [[0, 1, 2], [3, 4, 5]];
        let shells = shells(&tris, 6);
        let positions: Vec<DVec3> = (0..6)
            .map(|v| DVec3::new(v as f64, -(v as f64), 0.5 * v as f64))
            .collect();
        // Shell 0: χ = 2 (a sphere's); shell 1: χ = 1 (odd: not a closed surface).
        let share = |(chi, defective)| Share {
            chi,
            defective,
            used: true,
        };
        let shares = [
            (2, false),
            (0, false),
            (0, false),
            (1, false),
            (0, false),
            (0, false),
        ]
        .map(share);
        let tally = ShellTally::new(&shells, &shares, &positions);
        assert_eq!(tally.genus(), vec![Some(0), None]);
        assert_eq!(tally.vertices(), 6);
        let boxes = tally.into_boxes();
        assert_eq!(
            boxes[1],
            [DVec3::new(3.0, -5.0, 1.5), DVec3::new(5.0, -3.0, 2.5)]
        );
        let flagged = [
            (2, false),
            (0, true),
            (0, false),
            (2, false),
            (0, false),
            (0, false),
        ]
        .map(share);
        let tally = ShellTally::new(&shells, &flagged, &positions);
        assert_eq!(tally.genus(), vec![None, Some(0)]);
    }
}
