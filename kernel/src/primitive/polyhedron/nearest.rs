//! The nearest point of a triangle mesh to a query point: a closest-first depth-first traversal
//! of the [`MeshTree`] with an explicit stack (the nearer child is visited first and any node whose
//! box is farther than the best triangle so far is skipped), and the exact point–triangle distance by
//! Voronoi regions of the triangle (Ericson, *Real-Time Collision Detection*, 5.1.5).
//!
//! The stack lives in a thread-local buffer, so a query does not allocate.

use super::tree::MeshTree;
use glam::DVec3;
use std::cell::RefCell;

/// The result of a nearest-point query.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Nearest {
    /// Squared distance to the mesh.
    pub distance2: f64,
    /// The nearest point on the mesh.
    pub point: DVec3,
    /// The (reordered) index of the triangle it lies on.
    pub triangle: u32,
}

thread_local! {
    static STACK: RefCell<Vec<(u32, f64)>> = const { RefCell::new(Vec::new()) };
}

/// Runs `f` with the thread's cleared traversal stack (a fresh one if it is in use).
fn with_stack<R>(f: impl FnOnce(&mut Vec<(u32, f64)>) -> R) -> R {
    STACK.with(|cell| match cell.try_borrow_mut() {
        Ok(mut stack) => {
            stack.clear();
            f(&mut stack)
        }
        Err(_) => f(&mut Vec::new()),
    })
}

/// Squared distance from `q` to the box `[lo, hi]` (0 inside).
fn box_distance2(lo: DVec3, hi: DVec3, q: DVec3) -> f64 {
    let d = (lo - q).max(q - hi).max(DVec3::ZERO);
    d.length_squared()
}

impl MeshTree {
    /// The nearest point of the mesh to `q`.
    pub(crate) fn nearest(&self, q: DVec3) -> Nearest {
        let mut best = Nearest {
            distance2: f64::INFINITY,
            point: q,
            triangle: 0,
        };
        with_stack(|stack| {
            let root = &self.nodes[0];
            stack.push((0, box_distance2(root.min, root.max, q)));
            while let Some((index, d2)) = stack.pop() {
                if d2 >= best.distance2 {
                    continue;
                }
                let node = &self.nodes[index as usize];
                if node.count > 0 {
                    let run = node.first..node.first + node.count;
                    for t in run {
                        let [a, b, c] = self.triangles[t as usize];
                        let p = closest_point(q, a, b, c);
                        let d2 = (p - q).length_squared();
                        if d2 < best.distance2 {
                            best = Nearest {
                                distance2: d2,
                                point: p,
                                triangle: t,
                            };
                        }
                    }
                    continue;
                }
                let (l, r) = (node.first, node.first + 1);
                let (nl, nr) = (&self.nodes[l as usize], &self.nodes[r as usize]);
                let dl = box_distance2(nl.min, nl.max, q);
                let dr = box_distance2(nr.min, nr.max, q);
                // Push the farther child first so the nearer one is visited next.
                let (near, far) = if dl <= dr {
                    ((l, dl), (r, dr))
                } else {
                    ((r, dr), (l, dl))
                };
                if far.1 < best.distance2 {
                    stack.push(far);
                }
                if near.1 < best.distance2 {
                    stack.push(near);
                }
            }
        });
        best
    }
}

/// The point of triangle `abc` nearest to `q` (the kernel's shared computation).
pub(crate) fn closest_point(q: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    crate::closest::closest_point_on_triangle(q, [a, b, c])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitive::conformance::Rng;

    /// Brute-force distance to a triangle by dense sampling of barycentric coordinates.
    fn sampled_distance(q: DVec3, a: DVec3, b: DVec3, c: DVec3) -> f64 {
        let n = 200;
        let mut best = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=n - i {
                let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                let p = a + (b - a) * u + (c - a) * v;
                best = best.min(p.distance(q));
            }
        }
        best
    }

    #[test]
    fn closest_point_matches_sampling_and_is_never_farther() {
        let mut rng = Rng::new(11);
        for _ in 0..300 {
            let (a, b, c, q) = (rng.vec(1.0), rng.vec(1.0), rng.vec(1.0), rng.vec(2.0));
            let d = closest_point(q, a, b, c).distance(q);
            let s = sampled_distance(q, a, b, c);
            // Sampling can only overestimate, by at most the grid spacing.
            assert!(d <= s + 1e-12, "{d} > {s}");
            assert!(s - d < 0.02, "{d} vs {s}");
        }
    }

    #[test]
    fn degenerate_triangles_use_their_edges() {
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::X * 2.0);
        let q = DVec3::new(1.5, 1.0, 0.0);
        assert!((closest_point(q, a, b, c).distance(q) - 1.0).abs() < 1e-15);
        let p = DVec3::ONE;
        assert_eq!(closest_point(q, p, p, p), p);
    }
}
