//! Disjoint-set forest (union-find) with path halving and union by rank.
//!
//! Used to group triangles into shells and corners into vertex fans without recursion: every
//! operation is an iterative loop, so inputs of any size are safe.

/// A disjoint-set forest over the elements `0..len`.
#[derive(Debug, Clone)]
pub(crate) struct UnionFind {
    parent: Vec<usize>,
    rank: Vec<u8>,
}

impl UnionFind {
    /// `len` singleton sets.
    pub(crate) fn new(len: usize) -> Self {
        Self {
            parent: (0..len).collect(),
            rank: vec![0; len],
        }
    }

    /// The representative of the set holding `x`, halving the path on the way.
    pub(crate) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            let grandparent = self.parent[self.parent[x]];
            self.parent[x] = grandparent;
            x = grandparent;
        }
        x
    }

    /// True when `x` is the representative of its set (no path compression needed).
    pub(crate) fn is_root(&self, x: usize) -> bool {
        self.parent[x] == x
    }

    /// Merges the sets holding `a` and `b`; true when they were distinct.
    pub(crate) fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        let (low, high) = if self.rank[ra] < self.rank[rb] {
            (ra, rb)
        } else {
            (rb, ra)
        };
        self.parent[low] = high;
        if self.rank[low] == self.rank[high] {
            self.rank[high] = self.rank[high].saturating_add(1);
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::UnionFind;

    #[test]
    fn unions_merge_and_roots_count_sets() {
        let mut uf = UnionFind::new(6);
        assert!(uf.union(0, 1));
        assert!(uf.union(2, 3));
        assert!(uf.union(1, 3));
        assert!(!uf.union(0, 2));
        assert_eq!(uf.find(0), uf.find(3));
        assert_ne!(uf.find(0), uf.find(4));
        let roots = (0..6).filter(|&x| uf.is_root(x)).count();
        assert_eq!(roots, 3);
    }

    #[test]
    fn long_chain_does_not_recurse() {
        let n = 1_000_000;
        let mut uf = UnionFind::new(n);
        for i in 1..n {
            uf.union(i - 1, i);
        }
        assert_eq!(uf.find(0), uf.find(n - 1));
    }
}
