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
    /// One bit per triangle, set for the copies that are not their group's representative
    /// (empty when there are no copies).
    pub(crate) others: Vec<u64>,
}

impl Copies {
    /// Groups the `candidates` (each its vertex indices sorted ascending and its triangle index,
    /// all below `triangle_count`).
    pub(crate) fn find(
        mut candidates: Vec<([u32; 3], u32)>,
        triangle_count: usize,
        limit: usize,
    ) -> Self {
        candidates.par_sort_unstable();
        let mut copies = Self::default();
        for same in candidates.chunk_by(|a, b| a.0 == b.0) {
            if same.len() < 2 {
                continue;
            }
            if copies.others.is_empty() {
                copies.others = vec![0; triangle_count.div_ceil(64)];
            }
            // Sorted by index within the group, so the first is the representative.
            for &(_, t) in &same[1..] {
                copies.others[t as usize / 64] |= 1 << (t % 64);
            }
            // `limit + 1`: the smallest pairs among copies are the first with the next `limit`.
            let first = same
                .iter()
                .take(limit.saturating_add(1))
                .map(|&(_, t)| t)
                .collect();
            copies.groups.insert(same[0].1, (same.len(), first));
        }
        copies
    }

    /// True when triangle `t` is a copy other than its group's representative (it takes no part
    /// in the search).
    pub(crate) fn is_other(&self, t: u32) -> bool {
        self.others
            .get(t as usize / 64)
            .is_some_and(|w| w >> (t % 64) & 1 == 1)
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
