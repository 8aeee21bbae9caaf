//! Repeated triangles: the groups of usable triangles with the same three vertex indices (in any
//! order), found by sorting the candidates' vertex sets. Only the lowest-index copy of a group (its
//! representative) takes part in the search; see the [parent module](super).
//!
//! The candidates are the triangles without a certified vertex (`fans.rs`): a certified star is
//! one closed fan of triangles keeping one orientation, which holds no two triangles on the same
//! vertices, so a triangle with a certified vertex has no copy. On a clean mesh few triangles
//! are left to sort.

use rayon::prelude::*;
use std::collections::HashMap;

use super::SelfIntersections;

/// The groups of repeated triangles, by their representative (lowest index).
#[derive(Debug, Default)]
pub(crate) struct Copies {
    /// Representative → (number of copies, the `limit + 1` lowest indices, ascending).
    pub(crate) groups: HashMap<u32, (usize, Vec<u32>)>,
}

impl Copies {
    /// Groups the `candidates` (each its vertex indices sorted ascending and its position `k` in
    /// the ascending mesh indices `ids`) and clears `keep[k]` for every copy but the
    /// representative of its group.
    pub(crate) fn find(
        ids: &[u32],
        mut candidates: Vec<([u32; 3], u32)>,
        keep: &mut [bool],
        limit: usize,
    ) -> Self {
        candidates.par_sort_unstable();
        let mut groups = HashMap::new();
        for same in candidates.chunk_by(|a, b| a.0 == b.0) {
            if same.len() < 2 {
                continue;
            }
            // Positions ascend with mesh index, so the first is the representative.
            for &(_, k) in &same[1..] {
                keep[k as usize] = false;
            }
            // `limit + 1`: the smallest pairs among copies are the first with the next `limit`.
            let first = same
                .iter()
                .take(limit.saturating_add(1))
                .map(|&(_, k)| ids[k as usize])
                .collect();
            groups.insert(ids[same[0].1 as usize], (same.len(), first));
        }
        Self { groups }
    }

    /// How many triangles `i` stands for, and the lowest of their indices (none listed for a
    /// triangle without copies: it stands for itself).
    pub(crate) fn of(&self, i: u32) -> (usize, &[u32]) {
        match self.groups.get(&i) {
            Some((count, first)) => (*count, first),
            None => (1, &[]),
        }
    }

    /// The pairs of copies of one triangle: they share all three vertices, so they meet.
    pub(crate) fn among_themselves(&self, limit: usize) -> SelfIntersections {
        let mut found = SelfIntersections::default();
        for (count, first) in self.groups.values() {
            found.count += count * (count - 1) / 2;
            for (a, &i) in first.iter().enumerate() {
                found
                    .examples
                    .extend(first[a + 1..].iter().map(|&j| [i, j]));
            }
        }
        found.examples.sort_unstable();
        found.examples.truncate(limit);
        found
    }

    /// Adds the pair of representatives `i`, `j` (known to meet) to `found`: every copy of one
    /// meets every copy of the other. Examples go to `hits` (normalised, unsorted).
    pub(crate) fn add_pair(&self, i: u32, j: u32, count: &mut usize, hits: &mut Vec<[u32; 2]>) {
        if self.groups.is_empty() {
            *count += 1;
            hits.push([i.min(j), i.max(j)]);
            return;
        }
        let ((ci, fi), (cj, fj)) = (self.of(i), self.of(j));
        let (single_i, single_j) = ([i], [j]);
        let fi = if fi.is_empty() { &single_i[..] } else { fi };
        let fj = if fj.is_empty() { &single_j[..] } else { fj };
        *count += ci * cj;
        for &a in fi {
            hits.extend(fj.iter().map(|&b| [a.min(b), a.max(b)]));
        }
    }
}
