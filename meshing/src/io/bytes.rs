//! A bounds-checked cursor over the bytes of a binary file (binary STL and PLY): every read
//! returns `None` at the end of the data instead of panicking, and the cursor knows its offset
//! for error locations.

/// Byte order of multi-byte numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Endian {
    /// Least significant byte first.
    Little,
    /// Most significant byte first.
    Big,
}

/// A read position in a byte slice.
pub(super) struct ByteCursor<'a> {
    bytes: &'a [u8],
    pos: usize,
    endian: Endian,
}

impl<'a> ByteCursor<'a> {
    /// A cursor at `start` (clamped to the end) reading numbers in `endian` order.
    pub(super) fn new(bytes: &'a [u8], start: usize, endian: Endian) -> Self {
        Self {
            bytes,
            pos: start.min(bytes.len()),
            endian,
        }
    }

    /// The current offset from the start of the file.
    pub(super) fn offset(&self) -> u64 {
        self.pos as u64
    }

    /// Bytes left after the cursor.
    pub(super) fn remaining(&self) -> usize {
        self.bytes.len() - self.pos
    }

    /// The next `N` bytes, in file order.
    pub(super) fn take<const N: usize>(&mut self) -> Option<[u8; N]> {
        let end = self.pos.checked_add(N)?;
        let chunk: [u8; N] = self.bytes.get(self.pos..end)?.try_into().ok()?;
        self.pos = end;
        Some(chunk)
    }

    /// Skips `n` bytes; `None` (and no move) if fewer remain.
    pub(super) fn skip(&mut self, n: u64) -> Option<()> {
        let n = usize::try_from(n).ok()?;
        if n > self.remaining() {
            return None;
        }
        self.pos += n;
        Some(())
    }

    /// The next `N` bytes with the least significant byte first.
    fn take_le<const N: usize>(&mut self) -> Option<[u8; N]> {
        let mut chunk = self.take::<N>()?;
        if self.endian == Endian::Big {
            chunk.reverse();
        }
        Some(chunk)
    }

    /// A `u8`.
    pub(super) fn u8(&mut self) -> Option<u8> {
        self.take::<1>().map(|[b]| b)
    }

    /// An `i8`.
    pub(super) fn i8(&mut self) -> Option<i8> {
        self.take::<1>().map(i8::from_le_bytes)
    }

    /// A `u16` in the cursor's byte order.
    pub(super) fn u16(&mut self) -> Option<u16> {
        self.take_le().map(u16::from_le_bytes)
    }

    /// An `i16` in the cursor's byte order.
    pub(super) fn i16(&mut self) -> Option<i16> {
        self.take_le().map(i16::from_le_bytes)
    }

    /// A `u32` in the cursor's byte order.
    pub(super) fn u32(&mut self) -> Option<u32> {
        self.take_le().map(u32::from_le_bytes)
    }

    /// An `i32` in the cursor's byte order.
    pub(super) fn i32(&mut self) -> Option<i32> {
        self.take_le().map(i32::from_le_bytes)
    }

    /// An `f32` in the cursor's byte order.
    pub(super) fn f32(&mut self) -> Option<f32> {
        self.take_le().map(f32::from_le_bytes)
    }

    /// An `f64` in the cursor's byte order.
    pub(super) fn f64(&mut self) -> Option<f64> {
        self.take_le().map(f64::from_le_bytes)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_in_both_byte_orders_and_stops_at_the_end() {
        let data = [1u8, 2, 3, 4, 5];
        let mut le = ByteCursor::new(&data, 0, Endian::Little);
        assert_eq!(le.u32(), Some(0x0403_0201));
        assert_eq!(le.offset(), 4);
        assert_eq!(le.u16(), None);
        assert_eq!(le.offset(), 4);
        assert_eq!(le.u8(), Some(5));
        assert_eq!(le.u8(), None);

        let mut be = ByteCursor::new(&data, 1, Endian::Big);
        assert_eq!(be.u16(), Some(0x0203));
        assert_eq!(be.skip(3), None);
        assert_eq!(be.skip(2), Some(()));
        assert_eq!(be.remaining(), 0);
        assert_eq!(ByteCursor::new(&data, 99, Endian::Big).remaining(), 0);
    }
}
