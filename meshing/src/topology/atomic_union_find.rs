//! Union-find that many threads may grow at once (the shells' connectivity, in parallel over
//! vertices, and the half-edge builder's vertex fans, in parallel over edges).
//!
//! Parents are atomics. A union links the larger of the two roots to the smaller with a
//! compare-and-swap (retrying when another thread moved either root first), so a root only ever
//! points to a smaller element and, once every union has returned, each set's root is its
//! smallest element, whatever the threads' interleaving: the result is deterministic. `find`
//! halves paths with the same compare-and-swap; a failed swap only skips a shortcut. Iterative,
//! no recursion; elements are `u32` (at most 2³² − 1 of them, the edge table's limit too).

use rayon::prelude::*;
use std::sync::atomic::{AtomicU32, Ordering};

/// Disjoint sets over `0..len` with concurrent `union`.
#[derive(Debug)]
pub(crate) struct AtomicUnionFind {
    parent: Vec<AtomicU32>,
}

impl AtomicUnionFind {
    /// `len` singletons.
    pub(crate) fn new(len: usize) -> Self {
        assert!(
            len <= u32::MAX as usize,
            "union-find supports at most 2^32 - 1 elements"
        );
        Self {
            // In parallel: on a fresh process, most of the cost is the pages' first touch.
            parent: (0..len as u32)
                .into_par_iter()
                .with_min_len(1 << 14)
                .map(AtomicU32::new)
                .collect(),
        }
    }

    /// Number of elements.
    pub(crate) fn len(&self) -> usize {
        self.parent.len()
    }

    /// The root of `x`'s set (its smallest element once no union is running).
    pub(crate) fn find(&self, x: usize) -> usize {
        let mut x = x as u32;
        loop {
            let p = self.parent[x as usize].load(Ordering::Acquire);
            if p == x {
                return x as usize;
            }
            let g = self.parent[p as usize].load(Ordering::Acquire);
            if g != p {
                // Path halving: point x at its grandparent unless someone moved x meanwhile.
                let _ = self.parent[x as usize].compare_exchange_weak(
                    p,
                    g,
                    Ordering::AcqRel,
                    Ordering::Relaxed,
                );
            }
            x = g;
        }
    }

    /// Joins the sets of `a` and `b`.
    pub(crate) fn union(&self, a: usize, b: usize) {
        let (mut a, mut b) = (a, b);
        loop {
            let (ra, rb) = (self.find(a), self.find(b));
            if ra == rb {
                return;
            }
            let (high, low) = if ra > rb { (ra, rb) } else { (rb, ra) };
            // Link only a root still a root; otherwise look again from the roots found.
            if self.parent[high]
                .compare_exchange(high as u32, low as u32, Ordering::AcqRel, Ordering::Acquire)
                .is_ok()
            {
                return;
            }
            (a, b) = (ra, rb);
        }
    }

    /// Joins the set of `a` with the sets of all of `others`, finding `a`'s root once rather than
    /// once per union (the same sets as a [`Self::union`] per pair).
    pub(crate) fn union_all(&self, a: usize, others: impl IntoIterator<Item = usize>) {
        let mut ra = self.find(a);
        for b in others {
            loop {
                let rb = self.find(b);
                if ra == rb {
                    break;
                }
                let (high, low) = if ra > rb { (ra, rb) } else { (rb, ra) };
                if self.parent[high]
                    .compare_exchange(high as u32, low as u32, Ordering::AcqRel, Ordering::Acquire)
                    .is_ok()
                {
                    ra = low;
                    break;
                }
                // Another thread moved a root first: look again from `a`'s current root.
                ra = self.find(ra);
            }
        }
    }

    /// True when `x` is the root of its set.
    pub(crate) fn is_root(&self, x: usize) -> bool {
        self.parent[x].load(Ordering::Acquire) as usize == x
    }
}

#[cfg(test)]
mod tests {
    use super::AtomicUnionFind;
    use rayon::prelude::*;

    #[test]
    fn roots_are_the_smallest_elements() {
        let uf = AtomicUnionFind::new(6);
        uf.union(4, 1);
        uf.union(5, 3);
        uf.union(3, 4);
        assert_eq!(
            (0..6).map(|x| uf.find(x)).collect::<Vec<_>>(),
            [0, 1, 2, 1, 1, 1]
        );
        assert_eq!((0..6).filter(|&x| uf.is_root(x)).count(), 3);
    }

    #[test]
    fn concurrent_unions_give_the_serial_sets() {
        // Elements joined to x mod 1000 from many threads at once, in a scrambled order: 1000
        // sets, each rooted at its smallest element.
        let n = 200_000;
        let uf = AtomicUnionFind::new(n);
        (0..n).into_par_iter().for_each(|i| {
            let x = (i * 7919) % n;
            uf.union(x, x % 1000);
            uf.union(x, (x + 1000) % n);
        });
        assert!((0..n).into_par_iter().all(|x| uf.find(x) == x % 1000));
    }

    #[test]
    fn union_all_gives_the_sets_of_pairwise_unions() {
        // Each x joined with x + 1000 and x + 2000 from many threads at once, in a scrambled
        // order: 1000 sets, each rooted at its smallest element.
        let n = 300_000;
        let uf = AtomicUnionFind::new(n);
        (0..n).into_par_iter().for_each(|i| {
            let x = (i * 7919) % n;
            uf.union_all(x, [x + 1000, x + 2000].into_iter().filter(|&y| y < n));
        });
        assert!((0..n).into_par_iter().all(|x| uf.find(x) == x % 1000));
    }

    #[test]
    fn a_long_chain_does_not_recurse() {
        let n = 1_000_000;
        let uf = AtomicUnionFind::new(n);
        for i in (1..n).rev() {
            uf.union(i - 1, i);
        }
        assert_eq!(uf.find(n - 1), 0);
    }
}
