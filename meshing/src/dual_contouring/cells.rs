//! Cells by global coordinates: the block index, the surface cells it finds, and the keys of
//! split-face vertices; shared by the polygon assembly ([`super::contour`]) and the face vertices
//! ([`super::faces`]).

use super::block::{Block, NO_VERTEX};
use super::patches::Config;
use std::collections::HashMap;

/// Finds a block by its coordinates: a dense table when small enough, else a hash map.
pub(crate) enum BlockIndex {
    Dense { dims: [usize; 3], slots: Vec<u32> },
    Sparse(HashMap<[usize; 3], u32>),
}

impl BlockIndex {
    pub fn new(blocks: &[Block], dims: [usize; 3]) -> Self {
        let total = dims[0].saturating_mul(dims[1]).saturating_mul(dims[2]);
        if total <= 1 << 22 {
            let mut slots = vec![u32::MAX; total];
            for (b, o) in blocks.iter().enumerate() {
                slots[o.coord[0] + dims[0] * (o.coord[1] + dims[1] * o.coord[2])] = b as u32;
            }
            BlockIndex::Dense { dims, slots }
        } else {
            BlockIndex::Sparse(
                blocks
                    .iter()
                    .enumerate()
                    .map(|(b, o)| (o.coord, b as u32))
                    .collect(),
            )
        }
    }

    pub fn get(&self, c: [usize; 3]) -> Option<usize> {
        match self {
            BlockIndex::Dense { dims, slots } => {
                if (0..3).any(|a| c[a] >= dims[a]) {
                    return None;
                }
                let s = slots[c[0] + dims[0] * (c[1] + dims[1] * c[2])];
                (s != u32::MAX).then_some(s as usize)
            }
            BlockIndex::Sparse(map) => map.get(&c).map(|&b| b as usize),
        }
    }
}

/// A split-face vertex: the face above `cell` along `axis`, and which of its two segments.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct FaceKey {
    pub cell: [usize; 3],
    pub axis: u8,
    pub segment: u8,
}

/// A surface cell found through the block index.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct CellRef {
    pub block: usize,
    pub local: usize,
    /// The cell's configuration (sign mask and joined faces).
    pub config: Config,
    /// Global number of the cell's first patch vertex.
    pub first: u32,
}

/// Looks up cells by global coordinates.
pub(crate) struct Cells<'a> {
    pub blocks: &'a [Block],
    pub index: BlockIndex,
    pub bases: Vec<u32>,
    /// log2 of the block size (a power of two).
    shift: u32,
}

impl<'a> Cells<'a> {
    /// The cells of `blocks` (`dims` blocks per axis of `block_size`³ cells, a power of two;
    /// `bases`: the global number of each block's first patch vertex).
    pub fn new(blocks: &'a [Block], dims: [usize; 3], bases: Vec<u32>, block_size: usize) -> Self {
        assert!(block_size.is_power_of_two(), "block size {block_size}");
        Cells {
            blocks,
            index: BlockIndex::new(blocks, dims),
            bases,
            shift: block_size.trailing_zeros(),
        }
    }

    /// The surface cell at global coordinates `c`, if any.
    pub fn get(&self, c: [usize; 3]) -> Option<CellRef> {
        let b = self.index.get(c.map(|x| x >> self.shift))?;
        self.in_block(b, c)
    }

    /// [`Cells::get`], looking first in block `hint` (most cells a block's edges meet are its own).
    #[inline]
    pub fn get_near(&self, hint: usize, c: [usize; 3]) -> Option<CellRef> {
        let o = &self.blocks[hint];
        let inside = (0..3).all(|a| c[a].wrapping_sub(o.min[a]) < o.extent[a]);
        if inside {
            self.in_block(hint, c)
        } else {
            self.get(c)
        }
    }

    /// Cell `c` of block `b`, if it lies in the block and has surface.
    #[inline]
    fn in_block(&self, b: usize, c: [usize; 3]) -> Option<CellRef> {
        let o = &self.blocks[b];
        let l = [0, 1, 2].map(|a| c[a].wrapping_sub(o.min[a]));
        if (0..3).any(|a| l[a] >= o.extent[a]) {
            return None;
        }
        let local = o.cell_index(l);
        let first = o.first[local];
        (first != NO_VERTEX).then(|| CellRef {
            block: b,
            local,
            config: o.configs[local],
            first: self.bases[b] + first,
        })
    }
}
