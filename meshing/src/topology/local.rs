//! What one vertex's star says: the kind of every edge from the vertex to a larger one, the
//! number of fans around it, and its share of the Euler characteristic.
//!
//! In the star of `v` (`crate::stars`) the triangle `[v, b, a]` is `[b, a]`: it uses the edge
//! `{v, b}` leaving `v` and the edge `{v, a}` entering it. So an edge `{v, x}` is used
//! `out = #{b = x}` times in one direction and `in = #{a = x}` times in the other: once in all, a
//! boundary edge; once each way, a manifold edge; twice the same way, an inconsistent edge; more,
//! a non-manifold edge. The triangles at `v` form one group per connected component of the star's
//! link graph (neighbours as nodes, each triangle joining its `b` and `a`): the vertex's fans.
//!
//! The common case is checked first, in O(k²) small steps without allocation: starting from the
//! first triangle, the next one around `v` is the first whose `a` is this one's `b`; when that
//! walk comes back after visiting all `k` triangles, every `b` is matched to a distinct `a`, so
//! every edge at `v` is used once each way and there is one closed fan. Otherwise (or for stars of
//! more than 64 triangles) the neighbours are sorted and counted.
//!
//! Each edge `{v, x}` is judged from its smaller end only, so every edge is counted once; summing
//! `1 − #{x > v} + #{triangles whose smallest vertex is v}` over a shell's vertices gives its
//! `V − E + F`.

use super::edges::EdgeKind;

/// The most triangles a star may have for the allocation-free walk (one bit each).
const WALK_LIMIT: usize = 64;

/// Counts of undirected edges by kind (a vertex's edges to larger vertices, or a whole mesh's).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct EdgeCounts {
    /// All edges.
    pub(crate) edges: usize,
    /// Edges used by one triangle only.
    pub(crate) boundary: usize,
    /// Edges used by more than two triangles.
    pub(crate) non_manifold: usize,
    /// Edges used twice in the same direction.
    pub(crate) inconsistent: usize,
}

impl EdgeCounts {
    /// Counts one edge of `kind`.
    fn count(&mut self, kind: EdgeKind) {
        self.edges += 1;
        match kind {
            EdgeKind::Manifold => {}
            EdgeKind::Boundary => self.boundary += 1,
            EdgeKind::Inconsistent => self.inconsistent += 1,
            EdgeKind::NonManifold => self.non_manifold += 1,
        }
    }

    /// Adds `other`'s counts.
    pub(crate) fn add(&mut self, other: &Self) {
        self.edges += other.edges;
        self.boundary += other.boundary;
        self.non_manifold += other.non_manifold;
        self.inconsistent += other.inconsistent;
    }

    /// True when some edge is not manifold.
    fn defective(&self) -> bool {
        self.boundary + self.non_manifold + self.inconsistent > 0
    }
}

/// What the star of one vertex says.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Local {
    /// `1 − (edges to larger vertices) + (triangles whose smallest vertex this is)`.
    pub(crate) chi: i64,
    /// The edges to larger vertices.
    pub(crate) counts: EdgeCounts,
    /// Fans around the vertex (0 when unused).
    pub(crate) fans: usize,
}

impl Local {
    /// True when the vertex or one of its edges to larger vertices is a defect (the shell then
    /// has no genus).
    pub(crate) fn defective(&self) -> bool {
        self.fans > 1 || self.counts.defective()
    }
}

/// One vertex's share of `V − E + F`, whether it or an edge to a larger vertex is a defect,
/// and whether some triangle uses it.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Share {
    /// [`Local::chi`] (saturated to `i32`).
    pub(crate) chi: i32,
    /// [`Local::defective`].
    pub(crate) defective: bool,
    /// Some triangle uses the vertex.
    pub(crate) used: bool,
}

impl Local {
    /// The vertex's [`Share`].
    pub(crate) fn share(&self) -> Share {
        Share {
            chi: i32::try_from(self.chi).unwrap_or(i32::MIN),
            defective: self.defective(),
            used: self.fans > 0,
        }
    }
}

/// Reusable space for the slow path.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    neighbours: Vec<u32>,
    outs: Vec<u32>,
    ins: Vec<u32>,
    parent: Vec<u32>,
}

/// Analyses the star of `v`; `edge(x, kind)` is called for every edge `{v, x}` with `x > v`, in
/// ascending `x` order on the slow path (the fast path finds only manifold edges and calls it for
/// none).
pub(crate) fn analyse(
    v: u32,
    star: &[[u32; 2]],
    scratch: &mut Scratch,
    mut edge: impl FnMut(u32, EdgeKind),
) -> Local {
    if star.is_empty() {
        return Local::default();
    }
    if let Some(local) = closed_fan(v, star) {
        return local;
    }
    let mut local = Local::default();
    let faces = star.iter().filter(|&&[b, a]| b > v && a > v).count();
    let Scratch {
        neighbours,
        outs,
        ins,
        parent,
    } = scratch;
    neighbours.clear();
    neighbours.extend(star.as_flattened());
    neighbours.sort_unstable();
    neighbours.dedup();
    outs.clear();
    outs.extend(star.iter().map(|l| l[0]));
    outs.sort_unstable();
    ins.clear();
    ins.extend(star.iter().map(|l| l[1]));
    ins.sort_unstable();
    for &x in neighbours.iter().filter(|&&x| x > v) {
        let kind = match (count(outs, x), count(ins, x)) {
            (1, 1) => EdgeKind::Manifold,
            (out, inn) if out + inn == 1 => EdgeKind::Boundary,
            (out, inn) if out + inn == 2 => EdgeKind::Inconsistent,
            _ => EdgeKind::NonManifold,
        };
        local.counts.count(kind);
        edge(x, kind);
    }
    local.fans = fans(star, neighbours, parent);
    local.chi = 1 - to_i64(local.counts.edges) + to_i64(faces);
    local
}

/// The fast path: `Some` when the star is one closed fan whose every edge is used once each way.
///
/// A walk that comes back to the first triangle after exactly `k` steps visited `k` distinct
/// triangles (a repeated one would trap it in a cycle without the first), so every `b` is matched
/// to a distinct `a`.
fn closed_fan(v: u32, star: &[[u32; 2]]) -> Option<Local> {
    let k = star.len();
    if !(3..=WALK_LIMIT).contains(&k) {
        return None;
    }
    // The previous vertices of small stars in eight lanes (padding never matches: no vertex is
    // u32::MAX, the triangles being usable), compared all at once.
    let mut lanes = [u32::MAX; 8];
    if k <= 8 {
        for (lane, l) in lanes.iter_mut().zip(star) {
            *lane = l[1];
        }
    }
    // The next triangle around `v` after each one: the first entering through its `b` (all
    // found independently), then one walk over those steps.
    let mut step = [0u8; WALK_LIMIT];
    let (mut edges, mut faces) = (0usize, 0usize);
    for (i, &[b, a]) in star.iter().enumerate() {
        edges += usize::from(b > v);
        faces += usize::from((b > v) & (a > v));
        let next = entering(star, &lanes, b);
        if next == k {
            return None;
        }
        step[i] = next as u8;
    }
    // Back at the first triangle after exactly k steps: the steps are one cycle through all.
    let mut at = 0usize;
    for n in 1..=k {
        at = usize::from(step[at]);
        if at == 0 {
            if n < k {
                return None;
            }
            break;
        }
    }
    if at != 0 {
        return None;
    }
    Some(Local {
        chi: 1 - to_i64(edges) + to_i64(faces),
        counts: EdgeCounts {
            edges,
            ..EdgeCounts::default()
        },
        fans: 1,
    })
}

/// The first triangle of `star` whose previous vertex is `b` (`star.len()` when none); `lanes`
/// holds the previous vertices when the star has at most eight triangles.
fn entering(star: &[[u32; 2]], lanes: &[u32; 8], b: u32) -> usize {
    if star.len() <= 8 {
        let mask = lanes
            .iter()
            .enumerate()
            .fold(0u32, |m, (j, &a)| m | (u32::from(a == b) << j));
        return if mask == 0 {
            star.len()
        } else {
            mask.trailing_zeros() as usize
        };
    }
    let mut next = star.len();
    for (j, l) in star.iter().enumerate().rev() {
        if l[1] == b {
            next = j;
        }
    }
    next
}

/// Connected components of the link graph: `neighbours` sorted and distinct, every triangle
/// `[b, a]` joining its two neighbours.
fn fans(star: &[[u32; 2]], neighbours: &[u32], parent: &mut Vec<u32>) -> usize {
    parent.clear();
    parent.extend(0..neighbours.len() as u32);
    let index = |x: u32| neighbours.binary_search(&x).unwrap_or(0);
    let mut components = neighbours.len();
    for &[b, a] in star {
        let (rb, ra) = (root(parent, index(b)), root(parent, index(a)));
        if rb != ra {
            parent[rb.max(ra)] = rb.min(ra) as u32;
            components -= 1;
        }
    }
    components
}

/// How often `x` occurs in the sorted `items`.
fn count(items: &[u32], x: u32) -> usize {
    let first = items.partition_point(|&y| y < x);
    items[first..].partition_point(|&y| y == x)
}

/// The root of `x` in a small union-find, halving the path.
fn root(parent: &mut [u32], mut x: usize) -> usize {
    while parent[x] as usize != x {
        let grand = parent[parent[x] as usize];
        parent[x] = grand;
        x = grand as usize;
    }
    x
}

/// `usize` to `i64`, saturating.
fn to_i64(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

#[cfg(test)]
mod tests {
    use super::{EdgeKind, Local, Scratch, analyse};

    fn run(v: u32, star: &[[u32; 2]]) -> (Local, Vec<(u32, EdgeKind)>) {
        let mut kinds = Vec::new();
        let local = analyse(v, star, &mut Scratch::default(), |x, k| kinds.push((x, k)));
        (local, kinds)
    }

    #[test]
    fn closed_fan_takes_the_fast_path() {
        // Vertex 0 of an octahedron-like fan 1..4: triangles [0,1,2], [0,2,3], [0,3,4], [0,4,1].
        let (local, kinds) = run(0, &[[1, 2], [2, 3], [3, 4], [4, 1]]);
        assert_eq!(
            (local.fans, local.counts.edges, local.chi),
            (1, 4, 1 - 4 + 4)
        );
        assert!(!local.defective() && kinds.is_empty());
    }

    #[test]
    fn two_fans_at_a_tip_and_a_flipped_triangle() {
        // Two closed fans around vertex 0 (1,2,3 and 4,5,6): a non-manifold vertex.
        let (local, _) = run(0, &[[1, 2], [2, 3], [3, 1], [4, 5], [5, 6], [6, 4]]);
        assert_eq!((local.fans, local.counts.edges), (2, 6));
        assert!(local.defective());
        // One triangle flipped: edges {0,1} and {0,3} are used twice the same way... and {0,2}
        // once each way.
        let (local, kinds) = run(0, &[[1, 2], [2, 3], [1, 3]]);
        assert_eq!(local.fans, 1);
        assert_eq!(
            kinds,
            vec![
                (1, EdgeKind::Inconsistent),
                (2, EdgeKind::Manifold),
                (3, EdgeKind::Inconsistent)
            ]
        );
        assert_eq!((local.counts.inconsistent, local.counts.boundary), (2, 0));
    }

    #[test]
    fn open_fan_and_a_fin() {
        // An open fan 1-2-3: edges {0,1} and {0,3} are boundary edges.
        let (local, kinds) = run(0, &[[1, 2], [2, 3]]);
        assert_eq!((local.fans, local.counts.boundary), (1, 2));
        assert_eq!(kinds[1], (2, EdgeKind::Manifold));
        // Three triangles on edge {0,1}: non-manifold; seen from vertex 5 edges to 0 and 1 are
        // not counted (smaller), and the edge to 7 is.
        let (local, kinds) = run(0, &[[1, 2], [3, 1], [1, 4]]);
        assert_eq!(kinds[0], (1, EdgeKind::NonManifold));
        assert_eq!(local.counts.non_manifold, 1);
        let (local, kinds) = run(5, &[[0, 1], [1, 7]]);
        assert_eq!(kinds, vec![(7, EdgeKind::Boundary)]);
        assert_eq!((local.counts.edges, local.chi), (1, 1 - 1));
    }
}
