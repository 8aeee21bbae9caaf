//! The mesh being simplified: positions, live triangles, each vertex's triangles, and the edge
//! collapse with its link condition (the test that keeps a closed 2-manifold a 2-manifold of the
//! same genus).

use glam::DVec3;

/// A triangle mesh under edge collapses. Triangles keep their ids; a collapsed one is dead.
pub(crate) struct Surface {
    /// Vertex positions (a collapsed vertex keeps its last position).
    pub positions: Vec<DVec3>,
    /// Triangles by id.
    pub triangles: Vec<[u32; 3]>,
    /// Whether each triangle is still there.
    pub alive: Vec<bool>,
    /// The live triangles around each vertex (empty once it is collapsed away).
    pub around: Vec<Vec<u32>>,
}

/// What a collapse of `from` into `into` does: the triangles it removes and the ones it keeps
/// around the merged vertex (their ids; their corners once `from` reads `into`).
pub(crate) struct Star {
    /// The vertex that goes.
    pub from: u32,
    /// The vertex that stays (and moves).
    pub into: u32,
    /// Triangles with both vertices: removed.
    pub removed: Vec<u32>,
    /// The other triangles of either vertex, in id order.
    pub kept: Vec<u32>,
}

impl Surface {
    /// The surface of a closed manifold mesh.
    pub fn new(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Self {
        let mut around = vec![Vec::new(); positions.len()];
        for (t, tri) in triangles.iter().enumerate() {
            for &v in tri {
                around[v as usize].push(t as u32);
            }
        }
        let alive = vec![true; triangles.len()];
        Self {
            positions,
            triangles,
            alive,
            around,
        }
    }

    /// The corners of triangle `t`.
    pub fn corners(&self, t: u32) -> [DVec3; 3] {
        self.triangles[t as usize].map(|v| self.positions[v as usize])
    }

    /// The vertices joined to `v` by an edge, ascending.
    pub fn neighbours(&self, v: u32) -> Vec<u32> {
        let mut n: Vec<u32> = self.around[v as usize]
            .iter()
            .flat_map(|&t| self.triangles[t as usize])
            .filter(|&w| w != v)
            .collect();
        n.sort_unstable();
        n.dedup();
        n
    }

    /// The star of the collapse of `from` into `into`, if the link condition holds: the edge
    /// lies in exactly two triangles and the two vertices share no neighbour but those
    /// triangles' third corners (so the result is again a 2-manifold, of the same genus; the
    /// caller keeps a shell from shrinking below a tetrahedron).
    pub fn star(&self, from: u32, into: u32) -> Option<Star> {
        let (a, b) = (&self.around[from as usize], &self.around[into as usize]);
        let removed: Vec<u32> = a.iter().copied().filter(|t| b.contains(t)).collect();
        if removed.len() != 2 {
            return None;
        }
        let opposite: Vec<u32> = removed
            .iter()
            .map(|&t| {
                let tri = self.triangles[t as usize];
                tri.into_iter()
                    .find(|&w| w != from && w != into)
                    .unwrap_or(from)
            })
            .collect();
        if opposite[0] == opposite[1] {
            return None;
        }
        let na = self.neighbours(from);
        let nb = self.neighbours(into);
        let common = na.iter().filter(|w| nb.binary_search(w).is_ok()).count();
        if common != 2 {
            return None;
        }
        let mut kept: Vec<u32> = a
            .iter()
            .chain(b.iter())
            .copied()
            .filter(|t| !removed.contains(t))
            .collect();
        kept.sort_unstable();
        kept.dedup();
        Some(Star {
            from,
            into,
            removed,
            kept,
        })
    }

    /// Triangle `t` as it reads after the collapse of `star` (`from` replaced by `into`).
    pub fn after(&self, star: &Star, t: u32) -> [u32; 3] {
        self.triangles[t as usize].map(|v| if v == star.from { star.into } else { v })
    }

    /// Performs the collapse: `into` moves to `at`, `from` goes, the two triangles of the edge
    /// die.
    pub fn collapse(&mut self, star: &Star, at: DVec3) {
        for &t in &star.removed {
            self.alive[t as usize] = false;
            for v in self.triangles[t as usize] {
                self.around[v as usize].retain(|&s| s != t);
            }
        }
        for &t in &star.kept {
            self.triangles[t as usize] = self.after(star, t);
        }
        self.positions[star.into as usize] = at;
        let moved = std::mem::take(&mut self.around[star.from as usize]);
        let into = &mut self.around[star.into as usize];
        into.extend(moved);
        into.sort_unstable();
        into.dedup();
    }
}
