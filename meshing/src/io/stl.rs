//! STL reading (binary and ASCII) and writing.
//!
//! A file is binary when its size is exactly `84 + 50 * n` for the triangle count `n` in its
//! header (even if the header starts with `solid`, as some exporters write), otherwise ASCII if
//! it starts with `solid`. STL stores 32-bit floats, so ASCII coordinates are read as `f32` too
//! and both encodings of the same model load identically. STL has no shared vertices: corners
//! with bit-identical positions are welded (first-seen order), so a closed STL surface becomes a
//! closed indexed mesh. Facet normals are ignored when reading and recomputed when writing.

use std::io::{self, Write};

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use super::bytes::{ByteCursor, Endian};
use super::text::{Tokens, parse_coordinate, parse_f64, show};
use super::weld::Welder;
use super::weld_parallel::{self, RECORD_LEN};
use super::{Encoding, Location, MeshIoError};
use crate::IndexedMesh;

/// Size of the binary header (free text) before the triangle count.
const HEADER_LEN: usize = 80;
/// Size of the header plus the `u32` triangle count.
const PREAMBLE_LEN: u64 = 84;

/// Reads binary or ASCII STL.
pub(super) fn read(bytes: &[u8], name: &str) -> Result<IndexedMesh, MeshIoError> {
    let declared = declared_count(bytes);
    let len = bytes.len() as u64;
    if let Some(count) = declared
        && binary_len(count) == len
    {
        return read_binary(bytes, count, name);
    }
    let ascii = starts_with_solid(bytes) && !bytes.contains(&0);
    match declared {
        _ if ascii => read_ascii(bytes, name),
        Some(count) => Err(size_mismatch(count, len, name)),
        None => Err(MeshIoError::parse(
            name,
            Location::Byte(len),
            "not an STL file: too short for a binary STL (84-byte header) and no 'solid' keyword",
        )),
    }
}

/// The triangle records (50 bytes each: normal, three corners as little-endian `f32`,
/// attribute) of a binary STL file's content, when the size rule of `read` makes it binary;
/// `None` for ASCII or malformed files.
pub fn binary_records(bytes: &[u8]) -> Option<&[u8]> {
    let count = declared_count(bytes)?;
    (binary_len(count) == bytes.len() as u64).then(|| &bytes[PREAMBLE_LEN as usize..])
}

/// The triangle count in a binary header, if the file is long enough to have one.
fn declared_count(bytes: &[u8]) -> Option<u32> {
    let mut cursor = ByteCursor::new(bytes, HEADER_LEN, Endian::Little);
    cursor.u32()
}

fn binary_len(count: u32) -> u64 {
    PREAMBLE_LEN + RECORD_LEN * u64::from(count)
}

fn starts_with_solid(bytes: &[u8]) -> bool {
    let start = bytes.iter().position(|b| !b.is_ascii_whitespace());
    start
        .and_then(|s| bytes.get(s..s + 5))
        .is_some_and(|word| word.eq_ignore_ascii_case(b"solid"))
}

fn size_mismatch(count: u32, len: u64, name: &str) -> MeshIoError {
    let expected = binary_len(count);
    let says =
        format!("header says {count} triangles ({expected} bytes) but the file has {len} bytes");
    if len < expected {
        MeshIoError::parse(
            name,
            Location::Byte(len),
            format!("truncated binary STL: {says}"),
        )
    } else {
        MeshIoError::parse(
            name,
            Location::Byte(expected),
            format!("binary STL with trailing data: {says}"),
        )
    }
}

/// Binary STL, decoded and welded in parallel ([`weld_parallel`]); a file with a non-finite
/// coordinate goes to the serial reader, which names the first one.
pub(super) fn read_binary(
    bytes: &[u8],
    count: u32,
    name: &str,
) -> Result<IndexedMesh, MeshIoError> {
    let body = bytes.get(PREAMBLE_LEN as usize..).unwrap_or_default();
    if body.len() as u64 != RECORD_LEN * u64::from(count) {
        return read_binary_serial(bytes, count, name);
    }
    match weld_parallel::weld_records(body) {
        Some((positions, triangles)) => Ok(IndexedMesh::new(positions, triangles)),
        None => read_binary_serial(bytes, count, name),
    }
}

/// Binary STL, one record after the other (the reference of [`read_binary`], and its error
/// path).
pub(super) fn read_binary_serial(
    bytes: &[u8],
    count: u32,
    name: &str,
) -> Result<IndexedMesh, MeshIoError> {
    let mut cursor = ByteCursor::new(bytes, HEADER_LEN + 4, Endian::Little);
    // The size check bounds `count` by the file size, so these allocations are safe.
    let mut welder = Welder::with_capacity(count as usize);
    let mut triangles = Vec::with_capacity(count as usize);
    for _ in 0..count {
        let truncated = |cursor: &ByteCursor| {
            MeshIoError::parse(name, Location::Byte(cursor.offset()), "truncated triangle")
        };
        cursor.skip(12).ok_or_else(|| truncated(&cursor))?;
        let mut triangle = [0u32; 3];
        for corner in &mut triangle {
            let point = binary_point(&mut cursor, name)?;
            *corner = welder.index(point).ok_or_else(|| too_many_vertices(name))?;
        }
        cursor.skip(2).ok_or_else(|| truncated(&cursor))?;
        triangles.push(triangle);
    }
    Ok(IndexedMesh::new(welder.into_positions(), triangles))
}

/// Three little-endian `f32` coordinates, which must be finite.
fn binary_point(cursor: &mut ByteCursor, name: &str) -> Result<DVec3, MeshIoError> {
    let mut xyz = [0.0f64; 3];
    for value in &mut xyz {
        let offset = cursor.offset();
        let located = |message: String| MeshIoError::parse(name, Location::Byte(offset), message);
        let coordinate = cursor
            .f32()
            .ok_or_else(|| located("truncated triangle".into()))?;
        if !coordinate.is_finite() {
            return Err(located(format!(
                "coordinate {coordinate} is not a finite number"
            )));
        }
        *value = f64::from(coordinate);
    }
    Ok(DVec3::from_array(xyz))
}

fn too_many_vertices(name: &str) -> MeshIoError {
    MeshIoError::invalid(name, "more vertices than 32-bit indices can address")
}

/// An ASCII STL parser: `solid NAME`, facets, `endsolid NAME`, possibly several solids.
struct AsciiStl<'a> {
    tokens: Tokens<'a>,
    name: &'a str,
    welder: Welder,
    triangles: Vec<[u32; 3]>,
    /// A `facet` was seen: the file is an ASCII STL, so messages may quote its tokens.
    recognized: bool,
}

fn read_ascii(bytes: &[u8], name: &str) -> Result<IndexedMesh, MeshIoError> {
    let mut parser = AsciiStl {
        tokens: Tokens::new(bytes, 1),
        name,
        welder: Welder::default(),
        triangles: Vec::new(),
        recognized: false,
    };
    parser.solids()?;
    Ok(IndexedMesh::new(
        parser.welder.into_positions(),
        parser.triangles,
    ))
}

impl<'a> AsciiStl<'a> {
    /// One or more `solid NAME ... endsolid NAME` blocks up to the end of the file (some tools
    /// concatenate solids).
    fn solids(&mut self) -> Result<(), MeshIoError> {
        self.keyword("solid")?;
        loop {
            self.tokens.skip_line();
            self.facets_until_endsolid()?;
            self.tokens.skip_line();
            match self.tokens.next_token() {
                None => return Ok(()),
                Some((_, token)) if token.eq_ignore_ascii_case(b"solid") => {}
                Some((line, token)) => {
                    return Err(self.unexpected(line, token, "'solid' or the end of the file"));
                }
            }
        }
    }

    /// Facets up to and including `endsolid`.
    fn facets_until_endsolid(&mut self) -> Result<(), MeshIoError> {
        loop {
            let (line, token) = self.token("'facet' or 'endsolid'")?;
            if token.eq_ignore_ascii_case(b"facet") {
                self.recognized = true;
                self.facet()?;
            } else if token.eq_ignore_ascii_case(b"endsolid") {
                return Ok(());
            } else {
                return Err(self.unexpected(line, token, "'facet' or 'endsolid'"));
            }
        }
    }

    /// `normal i j k outer loop vertex x y z (x3) endloop endfacet`, after `facet`.
    fn facet(&mut self) -> Result<(), MeshIoError> {
        self.keyword("normal")?;
        for _ in 0..3 {
            let (line, token) = self.token("a normal component")?;
            if parse_f64(token).is_none() {
                return Err(self.unexpected(line, token, "a number"));
            }
        }
        self.keyword("outer")?;
        self.keyword("loop")?;
        let mut triangle = [0u32; 3];
        for corner in &mut triangle {
            self.keyword("vertex")?;
            let point = self.point()?;
            *corner = self
                .welder
                .index(point)
                .ok_or_else(|| too_many_vertices(self.name))?;
        }
        self.keyword("endloop")?;
        self.keyword("endfacet")?;
        self.triangles.push(triangle);
        Ok(())
    }

    /// Three coordinates, rounded to `f32` like binary STL stores them.
    fn point(&mut self) -> Result<DVec3, MeshIoError> {
        let mut xyz = [0.0f64; 3];
        for value in &mut xyz {
            let (line, token) = self.token("a coordinate")?;
            *value = ascii_coordinate(token)
                .map_err(|message| MeshIoError::parse(self.name, Location::Line(line), message))?;
        }
        Ok(DVec3::from_array(xyz))
    }

    /// The next token, which must be `word` (any case).
    fn keyword(&mut self, word: &str) -> Result<(), MeshIoError> {
        let expected = format!("'{word}'");
        let (line, token) = self.token(&expected)?;
        if token.eq_ignore_ascii_case(word.as_bytes()) {
            Ok(())
        } else {
            Err(self.unexpected(line, token, &expected))
        }
    }

    /// The next token, or an error saying what was expected at the end of the file.
    fn token(&mut self, expected: &str) -> Result<(usize, &'a [u8]), MeshIoError> {
        self.tokens.next_token().ok_or_else(|| {
            MeshIoError::parse(
                self.name,
                Location::Line(self.tokens.line()),
                format!("unexpected end of file: expected {expected}"),
            )
        })
    }

    /// `expected X, found 'Y'`; a file that has not shown a single facet yet may be anything
    /// that starts with `solid`, so its content is not quoted.
    fn unexpected(&self, line: usize, token: &[u8], expected: &str) -> MeshIoError {
        let message = if self.recognized {
            format!("expected {expected}, found '{}'", show(token))
        } else {
            format!("not an ASCII STL file: expected {expected}")
        };
        MeshIoError::parse(self.name, Location::Line(line), message)
    }
}

/// A finite coordinate that fits in an `f32`, as an `f64`.
fn ascii_coordinate(token: &[u8]) -> Result<f64, String> {
    parse_coordinate(token)?;
    let single: Option<f32> = std::str::from_utf8(token).ok().and_then(|s| s.parse().ok());
    match single {
        Some(value) if value.is_finite() => Ok(f64::from(value)),
        _ => Err(format!(
            "coordinate '{}' is out of range for STL's 32-bit floats",
            show(token)
        )),
    }
}

/// Why `mesh` cannot be stored in STL, if it cannot (on top of the generic checks).
pub(super) fn check_writable(mesh: &IndexedMesh) -> Result<(), String> {
    if u32::try_from(mesh.triangles.len()).is_err() {
        return Err(format!(
            "{} triangles are more than binary STL can count",
            mesh.triangles.len()
        ));
    }
    match mesh.positions.iter().position(|p| !p.as_vec3().is_finite()) {
        Some(v) => Err(format!(
            "vertex {v} ({}) does not fit in STL's 32-bit floats",
            mesh.positions[v]
        )),
        None => Ok(()),
    }
}

/// Writes `mesh` as binary or ASCII STL (the mesh must pass the write checks).
pub(super) fn write(out: &mut dyn Write, mesh: &IndexedMesh, encoding: Encoding) -> io::Result<()> {
    match encoding {
        Encoding::Binary => write_binary(out, mesh),
        Encoding::Ascii => write_ascii(out, mesh),
    }
}

/// The unit normal and the three corners of each of `triangles` (of `mesh`), in `f32`.
fn facets<'a>(
    mesh: &'a IndexedMesh,
    triangles: &'a [[u32; 3]],
) -> impl Iterator<Item = (Vec3, [Vec3; 3])> + 'a {
    triangles.iter().map(|triangle| {
        let [a, b, c] =
            triangle.map(|i| mesh.positions.get(i as usize).copied().unwrap_or_default());
        let normal = (b - a).cross(c - a).normalize_or_zero();
        (normal.as_vec3(), [a, b, c].map(DVec3::as_vec3))
    })
}

/// Triangles per record block formatted in parallel by [`write_binary`].
const WRITE_BLOCK: usize = 1 << 14;

fn write_binary(out: &mut dyn Write, mesh: &IndexedMesh) -> io::Result<()> {
    let mut header = [b' '; HEADER_LEN];
    let text = b"binary STL written by solidkit";
    header[..text.len()].copy_from_slice(text);
    out.write_all(&header)?;
    let count = u32::try_from(mesh.triangles.len()).map_err(io::Error::other)?;
    out.write_all(&count.to_le_bytes())?;
    // Blocks of records formatted in parallel, written in order.
    let record = RECORD_LEN as usize;
    let blocks: Vec<&[[u32; 3]]> = mesh.triangles.chunks(WRITE_BLOCK).collect();
    for group in blocks.chunks(rayon::current_num_threads().max(1) * 4) {
        let bytes: Vec<Vec<u8>> = group
            .par_iter()
            .map(|block| {
                let mut buf = Vec::with_capacity(block.len() * record);
                for (normal, corners) in facets(mesh, block) {
                    for v in std::iter::once(normal).chain(corners) {
                        for c in v.to_array() {
                            buf.extend_from_slice(&c.to_le_bytes());
                        }
                    }
                    buf.extend_from_slice(&[0, 0]);
                }
                buf
            })
            .collect();
        for b in bytes {
            out.write_all(&b)?;
        }
    }
    Ok(())
}

fn write_ascii(out: &mut dyn Write, mesh: &IndexedMesh) -> io::Result<()> {
    writeln!(out, "solid solidkit")?;
    for (n, corners) in facets(mesh, &mesh.triangles) {
        writeln!(out, "  facet normal {:e} {:e} {:e}", n.x, n.y, n.z)?;
        writeln!(out, "    outer loop")?;
        for v in corners {
            writeln!(out, "      vertex {:e} {:e} {:e}", v.x, v.y, v.z)?;
        }
        writeln!(out, "    endloop")?;
        writeln!(out, "  endfacet")?;
    }
    writeln!(out, "endsolid solidkit")
}
