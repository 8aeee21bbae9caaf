//! Welding of vertices whose positions are bit-identical, for formats without shared vertices
//! (STL) and for joining the separately indexed objects of an OBJ file.
//!
//! Only exact duplicates are merged (`-0.0` counts as `0.0`); nearby but different positions stay
//! distinct, so welding never moves a vertex. Vertices keep their first-seen order.

use std::collections::HashMap;

use glam::DVec3;

use super::key_hash::KeyHash;

/// Builds a vertex array in which no two positions are bit-identical.
#[derive(Debug, Default)]
pub(super) struct Welder {
    index_of: HashMap<[u64; 3], u32, KeyHash>,
    positions: Vec<DVec3>,
}

impl Welder {
    /// A welder expecting about `capacity` distinct positions.
    pub(super) fn with_capacity(capacity: usize) -> Self {
        Self {
            index_of: HashMap::with_capacity_and_hasher(capacity, KeyHash::default()),
            positions: Vec::with_capacity(capacity),
        }
    }

    /// The index of `position`, appended if it was not seen before; `None` once the vertex
    /// count no longer fits in a `u32` index.
    pub(super) fn index(&mut self, position: DVec3) -> Option<u32> {
        let key = key(position);
        if let Some(&index) = self.index_of.get(&key) {
            return Some(index);
        }
        let index = self.push(position)?;
        self.index_of.insert(key, index);
        Some(index)
    }

    /// The index of an earlier vertex at `position`, if any (nothing is added).
    pub(super) fn find(&self, position: DVec3) -> Option<u32> {
        self.index_of.get(&key(position)).copied()
    }

    /// Appends `position` as a new vertex even if it was seen before (it is only remembered for
    /// [`Welder::find`] and [`Welder::index`] if it was not).
    pub(super) fn push(&mut self, position: DVec3) -> Option<u32> {
        let index = u32::try_from(self.positions.len()).ok()?;
        self.positions.push(position);
        self.index_of.entry(key(position)).or_insert(index);
        Some(index)
    }

    /// The vertices so far.
    pub(super) fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// The welded vertex array.
    pub(super) fn into_positions(self) -> Vec<DVec3> {
        self.positions
    }
}

/// The hash key of a position: its bits, with `-0.0` mapped to `0.0`.
fn key(p: DVec3) -> [u64; 3] {
    [p.x, p.y, p.z].map(|c| {
        if c == 0.0 {
            0.0f64.to_bits()
        } else {
            c.to_bits()
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn welds_bit_identical_positions_in_first_seen_order() {
        let mut w = Welder::default();
        assert_eq!(w.index(DVec3::new(1.0, 2.0, 3.0)), Some(0));
        assert_eq!(w.index(DVec3::new(0.0, 0.0, 0.0)), Some(1));
        assert_eq!(w.index(DVec3::new(1.0, 2.0, 3.0)), Some(0));
        assert_eq!(w.index(DVec3::new(-0.0, 0.0, -0.0)), Some(1));
        assert_eq!(
            w.index(DVec3::new(1.0, 2.0, 3.000_000_000_000_001)),
            Some(2)
        );
        assert_eq!(w.find(DVec3::new(0.0, -0.0, 0.0)), Some(1));
        assert_eq!(w.push(DVec3::new(1.0, 2.0, 3.0)), Some(3));
        assert_eq!(w.index(DVec3::new(1.0, 2.0, 3.0)), Some(0));
        assert_eq!(w.into_positions().len(), 4);
    }
}
