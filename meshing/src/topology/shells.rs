//! Shells: connected components of triangles, where sharing a vertex connects.
//!
//! The vertex pass (`mod.rs`) joins the two ends of every edge in a concurrent union-find over
//! vertices; [`Shells::number`] then numbers the sets by their smallest triangle index (the order
//! of [`super::TopologyReport::genus_per_shell`]). [`ShellTally`] sums each shell's vertices'
//! shares of `V − E + F` and defect flags (`local.rs`), giving the genus of every shell that is a
//! closed, oriented manifold (χ = 2 − 2g).

use super::atomic_union_find::AtomicUnionFind;
use super::stars::Stars;
use rayon::prelude::*;

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
    /// Numbers the sets of `sets` (over the vertices of `stars`, every edge's ends joined) in
    /// order of their smallest triangle in `triangles`.
    pub(crate) fn number(sets: &AtomicUnionFind, stars: &Stars, triangles: &[[u32; 3]]) -> Self {
        let roots: Vec<u32> = (0..stars.vertex_count())
            .into_par_iter()
            .with_min_len(4096)
            .map(|v| {
                if stars.is_referenced(v) {
                    sets.find(v) as u32
                } else {
                    NONE
                }
            })
            .collect();
        let mut number_of_root = vec![NONE; roots.len()];
        let mut count = 0usize;
        for tri in triangles {
            let slot = &mut number_of_root[roots[tri[0] as usize] as usize];
            if *slot == NONE {
                *slot = u32::try_from(count).unwrap_or(NONE);
                count += 1;
            }
        }
        let of_vertex = roots
            .par_iter()
            .with_min_len(4096)
            .map(|&r| {
                if r == NONE {
                    NONE
                } else {
                    number_of_root[r as usize]
                }
            })
            .collect();
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

/// Per-shell `V − E + F` and defect flags.
#[derive(Debug, Clone)]
pub(crate) struct ShellTally {
    chi: Vec<i64>,
    defective: Vec<bool>,
}

impl ShellTally {
    /// Sums the vertices' shares: `shares[v]` is vertex `v`'s share of `V − E + F` and whether it
    /// or one of its edges is a defect.
    pub(crate) fn new(shells: &Shells, shares: &[(i32, bool)]) -> Self {
        let n = shells.count();
        let mut tally = Self {
            chi: vec![0; n],
            defective: vec![false; n],
        };
        for (v, &(chi, defective)) in shares.iter().enumerate() {
            if let Some(s) = shells.of_vertex(v) {
                tally.chi[s] += i64::from(chi);
                tally.defective[s] |= defective;
            }
        }
        tally
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
}

#[cfg(test)]
mod tests {
    use super::{AtomicUnionFind, ShellTally, Shells, Stars};

    /// The shells of `tris` with every triangle's vertices joined.
    fn shells(tris: &[[u32; 3]], vertex_count: usize) -> Shells {
        let stars = Stars::build(tris, vertex_count);
        let sets = AtomicUnionFind::new(vertex_count);
        for t in tris {
            sets.union(t[0] as usize, t[1] as usize);
            sets.union(t[0] as usize, t[2] as usize);
        }
        Shells::number(&sets, &stars, tris)
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
    fn tally_gives_genus_only_for_sound_shells() {
        let tris = [[0, 1, 2], [3, 4, 5]];
        let shells = shells(&tris, 6);
        // Shell 0: χ = 2 (a sphere's); shell 1: χ = 1 (odd: not a closed surface).
        let shares = [
            (2, false),
            (0, false),
            (0, false),
            (1, false),
            (0, false),
            (0, false),
        ];
        assert_eq!(
            ShellTally::new(&shells, &shares).genus(),
            vec![Some(0), None]
        );
        let flagged = [
            (2, false),
            (0, true),
            (0, false),
            (2, false),
            (0, false),
            (0, false),
        ];
        assert_eq!(
            ShellTally::new(&shells, &flagged).genus(),
            vec![None, Some(0)]
        );
    }
}
