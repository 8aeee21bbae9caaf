//! Repeated triangles: the groups of usable triangles with the same three vertex indices (in any
//! order), found by filing every triangle under its smallest vertex (a counting sort, linear
//! time) and comparing the other two within each small bucket. Only the lowest-index copy of a
//! group (its representative) takes part in the search; see the [parent module](super).

use rayon::prelude::*;
use std::collections::HashMap;

use super::SelfIntersections;

/// Vertices per parallel work item when scanning buckets.
const GROUP: usize = 1 << 14;

/// The groups of repeated triangles, by their representative (lowest index).
#[derive(Debug, Default)]
pub(crate) struct Copies {
    /// Representative → (number of copies, the `limit + 1` lowest indices, ascending).
    pub(crate) groups: HashMap<u32, (usize, Vec<u32>)>,
}

impl Copies {
    /// Groups the triangles `ids` (ascending mesh indices, vertex indices `keys[k]` sorted
    /// ascending, all below `vertex_count`) and clears `keep[k]` for every copy but the
    /// representative of its group.
    pub(crate) fn find(
        ids: &[u32],
        keys: &[[u32; 3]],
        keep: &mut [bool],
        vertex_count: usize,
        limit: usize,
    ) -> Self {
        // Counting sort of the positions `k` by smallest vertex; each bucket stays ascending.
        let mut starts = vec![0u32; vertex_count + 1];
        for key in keys {
            starts[key[0] as usize + 1] += 1;
        }
        for v in 0..vertex_count {
            starts[v + 1] += starts[v];
        }
        let mut fill = starts.clone();
        let mut order = vec![0u32; keys.len()];
        for (k, key) in keys.iter().enumerate() {
            let at = &mut fill[key[0] as usize];
            order[*at as usize] = k as u32;
            *at += 1;
        }
        let members: Vec<Vec<u32>> = (0..vertex_count)
            .into_par_iter()
            .step_by(GROUP)
            .flat_map_iter(|first| {
                let mut found = Vec::new();
                let mut bucket: Vec<([u32; 2], u32)> = Vec::new();
                for v in first..(first + GROUP).min(vertex_count) {
                    let run = &order[starts[v] as usize..starts[v + 1] as usize];
                    if run.len() < 2 {
                        continue;
                    }
                    bucket.clear();
                    bucket.extend(run.iter().map(|&k| {
                        let key = keys[k as usize];
                        ([key[1], key[2]], k)
                    }));
                    bucket.sort_unstable();
                    for same in bucket.chunk_by(|a, b| a.0 == b.0) {
                        if same.len() > 1 {
                            found.push(same.iter().map(|&(_, k)| k).collect());
                        }
                    }
                }
                found
            })
            .collect();
        let mut groups = HashMap::new();
        for positions in members {
            // Positions ascend with mesh index, so the first is the representative.
            for &k in &positions[1..] {
                keep[k as usize] = false;
            }
            // `limit + 1`: the smallest pairs among copies are the first with the next `limit`.
            let first = positions
                .iter()
                .take(limit.saturating_add(1))
                .map(|&k| ids[k as usize])
                .collect();
            groups.insert(ids[positions[0] as usize], (positions.len(), first));
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
