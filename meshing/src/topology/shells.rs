//! Shells: connected components of triangles, where sharing a vertex connects.
//!
//! Shells are numbered by their smallest triangle index. [`ShellTally`] counts each shell's
//! vertices, edges and faces and whether it has a defect, giving the genus of every shell that is a
//! closed, oriented manifold (χ = 2 − 2g).

use super::atomic_union_find::AtomicUnionFind;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Marker for "no triangle" in [`Shells::first_triangle`].
const NONE: usize = usize::MAX;

/// The shell of every triangle and vertex.
#[derive(Debug, Clone)]
pub(crate) struct Shells {
    /// Shell number of each triangle.
    of_triangle: Vec<u32>,
    /// For each vertex, the first triangle using it (`NONE` when unreferenced).
    first_triangle: Vec<usize>,
    /// Number of shells.
    count: usize,
}

impl Shells {
    /// Shells of `triangles` (all indices below `vertex_count`).
    pub(crate) fn of(triangles: &[[u32; 3]], vertex_count: usize) -> Self {
        // In parallel: each vertex's first (smallest) triangle, then every triangle joined to the
        // first triangle of each of its vertices (so all triangles at a vertex are joined).
        let first: Vec<AtomicUsize> = (0..vertex_count).map(|_| AtomicUsize::new(NONE)).collect();
        triangles.par_iter().enumerate().for_each(|(t, tri)| {
            for &v in tri {
                first[v as usize].fetch_min(t, Ordering::Relaxed);
            }
        });
        let first_triangle: Vec<usize> = first.into_iter().map(AtomicUsize::into_inner).collect();
        let sets = AtomicUnionFind::new(triangles.len());
        triangles.par_iter().enumerate().for_each(|(t, tri)| {
            for &v in tri {
                let f = first_triangle[v as usize];
                if f != t {
                    sets.union(f, t);
                }
            }
        });
        let (of_triangle, count) = number_sets(&sets, triangles.len());
        Self {
            of_triangle,
            first_triangle,
            count,
        }
    }

    /// Number of shells.
    pub(crate) fn count(&self) -> usize {
        self.count
    }

    /// Shell of triangle `t`.
    pub(crate) fn of_triangle(&self, t: usize) -> usize {
        self.of_triangle[t] as usize
    }

    /// Shell of vertex `v`, `None` when no triangle uses it.
    pub(crate) fn of_vertex(&self, v: usize) -> Option<usize> {
        match self.first_triangle[v] {
            NONE => None,
            t => Some(self.of_triangle(t)),
        }
    }

    /// True when some triangle uses vertex `v`.
    pub(crate) fn is_referenced(&self, v: usize) -> bool {
        self.first_triangle[v] != NONE
    }
}

/// Numbers the sets `0..` in order of their smallest element (each set's root, see
/// [`AtomicUnionFind`]).
fn number_sets(sets: &AtomicUnionFind, len: usize) -> (Vec<u32>, usize) {
    let roots: Vec<u32> = (0..len)
        .into_par_iter()
        .map(|x| sets.find(x) as u32)
        .collect();
    let mut number_of_root = vec![u32::MAX; len];
    let mut count = 0usize;
    for (x, &root) in roots.iter().enumerate() {
        if root as usize == x {
            number_of_root[x] = u32::try_from(count).unwrap_or(u32::MAX);
            count += 1;
        }
    }
    // A root is its set's smallest element, numbered before any element that points to it.
    let of_element = roots
        .par_iter()
        .map(|&root| number_of_root[root as usize])
        .collect();
    (of_element, count)
}

/// Per-shell vertex, edge and face counts and defect flags.
#[derive(Debug, Clone)]
pub(crate) struct ShellTally {
    vertices: Vec<i64>,
    edges: Vec<i64>,
    faces: Vec<i64>,
    defective: Vec<bool>,
}

impl ShellTally {
    /// Counts the faces and vertices of every shell; edges are added with [`Self::add_edge`].
    pub(crate) fn new(shells: &Shells) -> Self {
        let n = shells.count();
        let mut tally = Self {
            vertices: vec![0; n],
            edges: vec![0; n],
            faces: vec![0; n],
            defective: vec![false; n],
        };
        for &s in &shells.of_triangle {
            tally.faces[s as usize] += 1;
        }
        for v in 0..shells.first_triangle.len() {
            if let Some(s) = shells.of_vertex(v) {
                tally.vertices[s] += 1;
            }
        }
        tally
    }

    /// Counts one edge of `shell`; a defective edge (boundary, non-manifold or inconsistent)
    /// disqualifies the shell from having a genus.
    pub(crate) fn add_edge(&mut self, shell: usize, defective: bool) {
        self.edges[shell] += 1;
        self.defective[shell] |= defective;
    }

    /// Marks `shell` as not a closed oriented manifold (e.g. it has a non-manifold vertex).
    pub(crate) fn mark_defective(&mut self, shell: usize) {
        self.defective[shell] = true;
    }

    /// The genus of every shell that is a closed oriented manifold, `None` for the others.
    pub(crate) fn genus(&self) -> Vec<Option<i64>> {
        (0..self.faces.len())
            .map(|s| {
                let chi = self.vertices[s] - self.edges[s] + self.faces[s];
                let twice_genus = 2 - chi;
                let valid = !self.defective[s] && twice_genus >= 0 && twice_genus % 2 == 0;
                valid.then_some(twice_genus / 2)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::{ShellTally, Shells};

    #[test]
    fn shells_join_through_shared_vertices_and_are_numbered_by_first_triangle() {
        // Triangles 0 and 2 share vertex 2; triangle 1 is separate; vertex 9 unused.
        let tris = [[0, 1, 2], [5, 6, 7], [2, 3, 4]];
        let shells = Shells::of(&tris, 10);
        assert_eq!(shells.count(), 2);
        assert_eq!(shells.of_triangle(0), 0);
        assert_eq!(shells.of_triangle(1), 1);
        assert_eq!(shells.of_triangle(2), 0);
        assert_eq!(shells.of_vertex(4), Some(0));
        assert_eq!(shells.of_vertex(9), None);
        assert!(!shells.is_referenced(8));
    }

    #[test]
    fn shells_do_not_depend_on_the_thread_count() {
        // 2000 strips of 50 triangles each, the triangles of all strips interleaved, so that
        // concurrent unions race on every strip: the numbering is the one-thread numbering.
        let (strips, len) = (2000u32, 50u32);
        let tris: Vec<[u32; 3]> = (0..len)
            .flat_map(|k| (0..strips).map(move |s| [s * 100 + k, s * 100 + k + 1, s * 100 + k + 2]))
            .collect();
        let run = |threads| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let shells = pool.install(|| Shells::of(&tris, (strips * 100) as usize));
            (
                shells.count(),
                (0..tris.len())
                    .map(|t| shells.of_triangle(t))
                    .collect::<Vec<_>>(),
            )
        };
        let one = run(1);
        assert_eq!(one.0, strips as usize);
        assert!(
            one.1
                .iter()
                .enumerate()
                .all(|(t, &s)| s == t % strips as usize)
        );
        for _ in 0..3 {
            assert_eq!(run(4), one);
        }
    }

    #[test]
    fn tally_gives_genus_only_for_sound_shells() {
        let tris = [[0, 1, 2], [3, 4, 5]];
        let shells = Shells::of(&tris, 6);
        let mut tally = ShellTally::new(&shells);
        for _ in 0..3 {
            tally.add_edge(0, false);
            tally.add_edge(1, false);
        }
        // χ = 3 − 3 + 1 = 1 is odd: not a closed surface even without flagged edges.
        assert_eq!(tally.genus(), vec![None, None]);
        tally.mark_defective(1);
        assert_eq!(tally.genus(), vec![None, None]);
    }
}
