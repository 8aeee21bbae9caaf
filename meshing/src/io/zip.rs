//! A minimal zip archive writer for 3MF packages: entries are *stored* (no compression), every
//! timestamp is the fixed DOS date 1980-01-01 00:00, and the CRC-32 is computed here.
//!
//! Stored entries keep the writer small and the bytes reproducible: the same entries always give
//! the same archive, whatever the machine, time or compression library version (a deflate stream
//! can change with the library). 3MF (Open Packaging Conventions) allows stored entries. No ZIP64:
//! an entry or archive over 4 GiB is refused with an error.

use std::io::{self, Write};

/// Signature of a local file header.
const LOCAL_HEADER: u32 = 0x0403_4b50;
/// Signature of a central directory header.
const CENTRAL_HEADER: u32 = 0x0201_4b50;
/// Signature of the end of central directory record.
const END_OF_DIRECTORY: u32 = 0x0605_4b50;
/// Version needed to extract a stored entry (1.0).
const VERSION_STORED: u16 = 10;
/// Version made by: MS-DOS attributes, spec 2.0.
const VERSION_MADE_BY: u16 = 20;
/// DOS date of 1980-01-01 (`(year − 1980) << 9 | month << 5 | day`); the time is 00:00:00.
const DOS_DATE: u16 = (1 << 5) | 1;

/// The CRC-32 lookup table (IEEE 802.3 polynomial, reflected: 0xEDB88320).
const CRC_TABLE: [u32; 256] = crc_table();

const fn crc_table() -> [u32; 256] {
    let mut table = [0u32; 256];
    let mut n = 0;
    while n < 256 {
        let mut c = n as u32;
        let mut k = 0;
        while k < 8 {
            c = if c & 1 != 0 {
                0xEDB8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
            k += 1;
        }
        table[n] = c;
        n += 1;
    }
    table
}

/// The CRC-32 of `bytes` (as zip, gzip and PNG use it).
pub fn crc32(bytes: &[u8]) -> u32 {
    !bytes.iter().fold(!0u32, |c, &b| {
        CRC_TABLE[((c ^ u32::from(b)) & 0xFF) as usize] ^ (c >> 8)
    })
}

/// One file of an archive: its name inside the archive (forward slashes) and its content.
pub struct ZipEntry<'a> {
    /// Path inside the archive, e.g. `3D/3dmodel.model`.
    pub name: &'a str,
    /// The bytes of the file.
    pub data: &'a [u8],
}

/// A value that must fit a 32-bit zip field.
fn field(n: usize, what: &str) -> io::Result<u32> {
    u32::try_from(n).map_err(|_| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{what} is over 4 GiB (zip without ZIP64)"),
        )
    })
}

fn u16le(out: &mut dyn Write, v: u16) -> io::Result<()> {
    out.write_all(&v.to_le_bytes())
}

fn u32le(out: &mut dyn Write, v: u32) -> io::Result<()> {
    out.write_all(&v.to_le_bytes())
}

/// Writes a zip archive of stored `entries`, in the given order.
pub fn write_stored(out: &mut dyn Write, entries: &[ZipEntry<'_>]) -> io::Result<()> {
    let mut offsets = Vec::with_capacity(entries.len());
    let mut offset = 0usize;
    let mut crcs = Vec::with_capacity(entries.len());
    for e in entries {
        let name_len = u16::try_from(e.name.len())
            .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "zip entry name too long"))?;
        let size = field(e.data.len(), e.name)?;
        let crc = crc32(e.data);
        offsets.push(field(offset, "archive")?);
        crcs.push(crc);
        u32le(out, LOCAL_HEADER)?;
        u16le(out, VERSION_STORED)?;
        u16le(out, 0)?; // flags
        u16le(out, 0)?; // method: stored
        u16le(out, 0)?; // time
        u16le(out, DOS_DATE)?;
        u32le(out, crc)?;
        u32le(out, size)?; // compressed size
        u32le(out, size)?; // uncompressed size
        u16le(out, name_len)?;
        u16le(out, 0)?; // extra field length
        out.write_all(e.name.as_bytes())?;
        out.write_all(e.data)?;
        offset += 30 + e.name.len() + e.data.len();
    }
    let directory_start = field(offset, "archive")?;
    let mut directory_len = 0usize;
    for ((e, &crc), &at) in entries.iter().zip(&crcs).zip(&offsets) {
        let size = field(e.data.len(), e.name)?;
        u32le(out, CENTRAL_HEADER)?;
        u16le(out, VERSION_MADE_BY)?;
        u16le(out, VERSION_STORED)?;
        u16le(out, 0)?; // flags
        u16le(out, 0)?; // method
        u16le(out, 0)?; // time
        u16le(out, DOS_DATE)?;
        u32le(out, crc)?;
        u32le(out, size)?;
        u32le(out, size)?;
        u16le(out, e.name.len() as u16)?;
        u16le(out, 0)?; // extra
        u16le(out, 0)?; // comment
        u16le(out, 0)?; // disk number
        u16le(out, 0)?; // internal attributes
        u32le(out, 0)?; // external attributes
        u32le(out, at)?;
        out.write_all(e.name.as_bytes())?;
        directory_len += 46 + e.name.len();
    }
    let count = u16::try_from(entries.len())
        .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "too many zip entries"))?;
    u32le(out, END_OF_DIRECTORY)?;
    u16le(out, 0)?; // this disk
    u16le(out, 0)?; // disk with the directory
    u16le(out, count)?;
    u16le(out, count)?;
    u32le(out, field(directory_len, "zip directory")?)?;
    u32le(out, directory_start)?;
    u16le(out, 0) // comment length
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_matches_the_check_value() {
        // The standard check value of CRC-32/ISO-HDLC.
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
    }

    #[test]
    fn archive_layout_is_the_zip_format() {
        let mut out = Vec::new();
        let entries = [
            ZipEntry {
                name: "a.txt",
                data: b"hello",
            },
            ZipEntry {
                name: "dir/b",
                data: b"",
            },
        ];
        write_stored(&mut out, &entries).unwrap();
        let le32 = |at: usize| u32::from_le_bytes(out[at..at + 4].try_into().unwrap());
        let le16 = |at: usize| u16::from_le_bytes(out[at..at + 2].try_into().unwrap());
        assert_eq!(le32(0), LOCAL_HEADER);
        assert_eq!(le32(14), crc32(b"hello"));
        assert_eq!(&out[30..35], b"a.txt");
        assert_eq!(&out[35..40], b"hello");
        let end = out.len() - 22;
        assert_eq!(le32(end), END_OF_DIRECTORY);
        assert_eq!(le16(end + 10), 2);
        let directory = le32(end + 16) as usize;
        assert_eq!(le32(directory), CENTRAL_HEADER);
        assert_eq!(le32(directory + 42), 0, "first entry at offset 0");
        assert_eq!(directory + le32(end + 12) as usize, end);
        // Same entries, same bytes.
        let mut again = Vec::new();
        write_stored(&mut again, &entries).unwrap();
        assert_eq!(out, again);
    }
}
