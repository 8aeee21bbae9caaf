//! Reading zip archives (the packages of 3MF files): the central directory, then single
//! entries, *stored* or *deflated* (through `flate2`), each checked against its CRC-32
//! (`flate2::Crc`: several times faster than the writer's table on large model parts).
//!
//! Hostile archives end in a located error, never a panic or an unbounded allocation: every
//! offset and size is checked against the file, an entry whose declared size is over the limit
//! is refused before inflating, and inflation stops one byte past the declared size (a zip bomb
//! that lies about its size is refused too). Not supported, with a message saying so: ZIP64,
//! archives split over several disks, encryption, methods other than stored and deflate.

use std::borrow::Cow;
use std::io::Read;

use super::bytes::{ByteCursor, Endian};
use super::{Location, MeshIoError};

/// The most bytes one entry may inflate to (1 GiB, the cap on every file read).
pub(super) const MAX_ENTRY_BYTES: u64 = 1 << 30;
/// Signature of a local file header.
const LOCAL_HEADER: u32 = 0x0403_4b50;
/// Signature of a central directory header.
const CENTRAL_HEADER: u32 = 0x0201_4b50;
/// Signature of the end of central directory record.
const END_OF_DIRECTORY: u32 = 0x0605_4b50;
/// Size of the end of central directory record without its comment.
const END_LEN: usize = 22;

/// One entry of the central directory.
#[derive(Debug, Clone)]
pub(super) struct Entry {
    /// The path inside the archive (forward slashes; invalid UTF-8 replaced).
    pub name: String,
    flags: u16,
    method: u16,
    crc: u32,
    compressed: u64,
    size: u64,
    local: u64,
}

/// An archive's directory over its bytes.
pub(super) struct Archive<'a> {
    bytes: &'a [u8],
    file: &'a str,
    entries: Vec<Entry>,
}

impl<'a> Archive<'a> {
    /// Reads the central directory of `bytes`; `file` names the archive in errors.
    pub(super) fn open(bytes: &'a [u8], file: &'a str) -> Result<Self, MeshIoError> {
        let at = find_end(bytes).ok_or_else(|| {
            MeshIoError::parse(
                file,
                Location::Byte(0),
                "not a zip package (no end of central directory record)",
            )
        })?;
        let bad = |offset: usize, message: &str| {
            MeshIoError::parse(file, Location::Byte(offset as u64), message)
        };
        let mut c = ByteCursor::new(bytes, at + 4, Endian::Little);
        let (disk, directory_disk) = (c.u16(), c.u16());
        let (_, count) = (c.u16(), c.u16().unwrap_or(0));
        let (size, start) = (c.u32().unwrap_or(0), c.u32().unwrap_or(0));
        if disk != Some(0) || directory_disk != Some(0) {
            return Err(bad(
                at,
                "zip archives split over several disks are not supported",
            ));
        }
        if count == u16::MAX || start == u32::MAX || size == u32::MAX {
            return Err(bad(at, "ZIP64 archives are not supported"));
        }
        if u64::from(start) + u64::from(size) > at as u64 {
            return Err(bad(at, "the central directory lies outside the file"));
        }
        let mut entries = Vec::with_capacity(usize::from(count));
        let mut c = ByteCursor::new(bytes, start as usize, Endian::Little);
        for _ in 0..count {
            let offset = c.offset() as usize;
            let entry = central_entry(&mut c)
                .ok_or_else(|| bad(offset, "truncated or corrupt central directory entry"))?;
            entries.push(entry);
        }
        Ok(Self {
            bytes,
            file,
            entries,
        })
    }

    /// The entries in directory order.
    pub(super) fn entries(&self) -> &[Entry] {
        &self.entries
    }

    /// The entry whose name equals `name` ignoring ASCII case (part names of 3MF packages are
    /// case-insensitive) and a leading `/`.
    pub(super) fn find(&self, name: &str) -> Option<&Entry> {
        let name = name.trim_start_matches('/');
        self.entries
            .iter()
            .find(|e| e.name.trim_start_matches('/').eq_ignore_ascii_case(name))
    }

    /// The content of `entry`, at most `limit` bytes once inflated (a stored entry is borrowed
    /// from the archive's bytes, not copied).
    pub(super) fn read(&self, entry: &Entry, limit: u64) -> Result<Cow<'a, [u8]>, MeshIoError> {
        let bad = |offset: u64, message: String| {
            MeshIoError::parse(
                self.file,
                Location::Byte(offset),
                format!("entry {}: {message}", entry.name),
            )
        };
        if entry.flags & 1 != 0 {
            return Err(bad(
                entry.local,
                "encrypted entries are not supported".into(),
            ));
        }
        if entry.size > limit {
            return Err(bad(
                entry.local,
                format!(
                    "{} bytes uncompressed, over the limit of {limit} (refused as a possible zip bomb)",
                    entry.size
                ),
            ));
        }
        let mut c = ByteCursor::new(self.bytes, entry.local as usize, Endian::Little);
        let header = (c.u32(), c.skip(22), c.u16(), c.u16());
        let (Some(LOCAL_HEADER), Some(()), Some(name_len), Some(extra_len)) = header else {
            return Err(bad(entry.local, "missing or truncated local header".into()));
        };
        let data_at = entry.local + 30 + u64::from(name_len) + u64::from(extra_len);
        let data = usize::try_from(data_at)
            .ok()
            .zip(usize::try_from(entry.compressed).ok())
            .and_then(|(at, len)| self.bytes.get(at..at.checked_add(len)?))
            .ok_or_else(|| bad(data_at, "the data runs past the end of the file".into()))?;
        let content = match entry.method {
            0 if entry.compressed == entry.size => Cow::Borrowed(data),
            0 => return Err(bad(data_at, "stored entry with two different sizes".into())),
            8 => Cow::Owned(inflate(data, entry.size).map_err(|m| bad(data_at, m))?),
            m => {
                return Err(bad(
                    data_at,
                    format!("compression method {m} is not supported"),
                ));
            }
        };
        let mut crc = flate2::Crc::new();
        crc.update(&content);
        if crc.sum() != entry.crc {
            return Err(bad(data_at, "CRC-32 mismatch (corrupt data)".into()));
        }
        Ok(content)
    }
}

/// Inflates a deflate stream that must give exactly `size` bytes.
fn inflate(data: &[u8], size: u64) -> Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(size.min(1 << 24) as usize);
    let decoder = flate2::read::DeflateDecoder::new(data);
    decoder
        .take(size + 1)
        .read_to_end(&mut out)
        .map_err(|e| format!("corrupt deflate data ({e})"))?;
    if out.len() as u64 != size {
        let more = if out.len() as u64 > size {
            "more"
        } else {
            "fewer"
        };
        return Err(format!(
            "inflates to {more} bytes than the {size} its header declares (refused)"
        ));
    }
    Ok(out)
}

/// The offset of the end of central directory record, searched backwards over the comment.
fn find_end(bytes: &[u8]) -> Option<usize> {
    let last = bytes.len().checked_sub(END_LEN)?;
    let first = last.saturating_sub(usize::from(u16::MAX));
    (first..=last).rev().find(|&at| {
        bytes[at..at + 4] == END_OF_DIRECTORY.to_le_bytes()
            && at + END_LEN + usize::from(u16::from_le_bytes([bytes[at + 20], bytes[at + 21]]))
                == bytes.len()
    })
}

/// One central directory header at the cursor.
fn central_entry(c: &mut ByteCursor<'_>) -> Option<Entry> {
    if c.u32()? != CENTRAL_HEADER {
        return None;
    }
    c.skip(4)?; // versions
    let (flags, method) = (c.u16()?, c.u16()?);
    c.skip(4)?; // time and date
    let (crc, compressed, size) = (c.u32()?, c.u32()?, c.u32()?);
    let (name_len, extra_len, comment_len) = (c.u16()?, c.u16()?, c.u16()?);
    c.skip(8)?; // disk, attributes
    let local = c.u32()?;
    let mut name = Vec::with_capacity(usize::from(name_len));
    for _ in 0..name_len {
        name.push(c.u8()?);
    }
    c.skip(u64::from(extra_len) + u64::from(comment_len))?;
    Some(Entry {
        name: String::from_utf8_lossy(&name).into_owned(),
        flags,
        method,
        crc,
        compressed: u64::from(compressed),
        size: u64::from(size),
        local: u64::from(local),
    })
}
