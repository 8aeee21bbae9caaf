//! Which live triangles lie near a box: a hierarchy of hashed grids, cell sizes `base · 2^level`.
//! A triangle is filed at the first level whose cells are at least as large as its box, in the
//! (at most eight) cells its box meets; a query visits, at every level in use, the cells the query
//! box meets, or all occupied cells of the level when those are fewer.

use crate::io::key_hash::KeyHash;
use glam::DVec3;
use std::collections::HashMap;

/// Levels of the hierarchy (cells up to `base · 2^31`).
const LEVELS: usize = 32;

type Key = [i64; 3];

/// The triangle index.
pub(crate) struct Spatial {
    base: f64,
    levels: Vec<HashMap<Key, Vec<u32>, KeyHash>>,
    /// Where each triangle is filed: its level and box (its cells follow from the box).
    filed: Vec<Option<(usize, [DVec3; 2])>>,
}

impl Spatial {
    /// An empty index over `triangles` ids, finest cells of size `base`.
    pub fn new(base: f64, triangles: usize) -> Self {
        Self {
            base: if base > 0.0 && base.is_finite() {
                base
            } else {
                1.0
            },
            levels: (0..LEVELS).map(|_| HashMap::default()).collect(),
            filed: vec![None; triangles],
        }
    }

    fn cell(&self, level: usize) -> f64 {
        self.base * (1u64 << level) as f64
    }

    fn range(&self, level: usize, lo: DVec3, hi: DVec3) -> ([i64; 3], [i64; 3]) {
        let c = self.cell(level);
        let a = (lo / c).floor();
        let b = (hi / c).floor();
        (
            [a.x as i64, a.y as i64, a.z as i64],
            [b.x as i64, b.y as i64, b.z as i64],
        )
    }

    /// Files triangle `t` with these corners.
    pub fn insert(&mut self, t: u32, p: [DVec3; 3]) {
        let lo = p[0].min(p[1]).min(p[2]);
        let hi = p[0].max(p[1]).max(p[2]);
        let size = (hi - lo).max_element();
        let mut level = 0;
        while level + 1 < LEVELS && self.cell(level) < size {
            level += 1;
        }
        let (a, b) = self.range(level, lo, hi);
        for x in a[0]..=b[0] {
            for y in a[1]..=b[1] {
                for z in a[2]..=b[2] {
                    self.levels[level].entry([x, y, z]).or_default().push(t);
                }
            }
        }
        self.filed[t as usize] = Some((level, [lo, hi]));
    }

    /// Removes triangle `t` (if filed).
    pub fn remove(&mut self, t: u32) {
        let Some((level, [lo, hi])) = self.filed[t as usize].take() else {
            return;
        };
        let (a, b) = self.range(level, lo, hi);
        for x in a[0]..=b[0] {
            for y in a[1]..=b[1] {
                for z in a[2]..=b[2] {
                    if let Some(list) = self.levels[level].get_mut(&[x, y, z]) {
                        list.retain(|&s| s != t);
                        if list.is_empty() {
                            self.levels[level].remove(&[x, y, z]);
                        }
                    }
                }
            }
        }
    }

    /// The filed triangles whose boxes meet `[lo, hi]`, ascending, without repeats.
    pub fn near(&self, lo: DVec3, hi: DVec3, out: &mut Vec<u32>) {
        out.clear();
        for (level, map) in self.levels.iter().enumerate() {
            if map.is_empty() {
                continue;
            }
            let (a, b) = self.range(level, lo, hi);
            let cells = (0..3).map(|k| (b[k] - a[k] + 1) as f64).product::<f64>();
            let mut take = |list: &Vec<u32>| {
                for &t in list {
                    if let Some((_, [tlo, thi])) = self.filed[t as usize]
                        && tlo.cmple(hi).all()
                        && thi.cmpge(lo).all()
                    {
                        out.push(t);
                    }
                }
            };
            if cells > map.len() as f64 {
                for (key, list) in map {
                    if (0..3).all(|k| a[k] <= key[k] && key[k] <= b[k]) {
                        take(list);
                    }
                }
            } else {
                for x in a[0]..=b[0] {
                    for y in a[1]..=b[1] {
                        for z in a[2]..=b[2] {
                            if let Some(list) = map.get(&[x, y, z]) {
                                take(list);
                            }
                        }
                    }
                }
            }
        }
        out.sort_unstable();
        out.dedup();
    }
}
