//! OFF (Object File Format) reading and writing.
//!
//! Layout: an `OFF` header line (also `COFF`, `NOFF`, `STOFF`... whose extra per-vertex values
//! are ignored), a `VERTICES FACES EDGES` counts line (possibly on the header line), one vertex
//! per line (`x y z`, extra values ignored), one face per line (`n i0 ... i(n-1)`, 0-based,
//! optional color values after the indices ignored; written by [`write_colored`] for a coloured
//! mesh). `#` starts a comment anywhere; blank lines
//! are skipped. Polygonal faces are triangulated by [`super::triangulate_polygon`] (or kept as
//! polygons by [`read_faces`] with a polygon sink).

use std::collections::HashSet;
use std::io::{self, Write};

use glam::DVec3;

use super::faces::FaceSink;
use super::text::{capped_capacity, lines, parse_coordinate, parse_i64, show, words};
use super::{Location, MeshIoError};
use crate::IndexedMesh;
use crate::colors::{DEFAULT_COLOR, FaceColors};

/// A line with content: its number and its words, comments removed.
type ContentLine<'a> = (usize, Vec<&'a [u8]>);

/// Reads an OFF file's faces into `sink`; returns the positions.
pub(super) fn read_faces(
    bytes: &[u8],
    name: &str,
    sink: &mut dyn FaceSink,
) -> Result<Vec<DVec3>, MeshIoError> {
    let mut reader = OffReader {
        name,
        lines: Box::new(content_lines(bytes)),
        last_line: 1,
    };
    let (vertex_count, face_count) = reader.header()?;
    let capacity = capped_capacity(vertex_count, bytes.len(), 6);
    let mut positions = Vec::with_capacity(capacity);
    for _ in 0..vertex_count {
        positions.push(reader.vertex()?);
    }
    for _ in 0..face_count {
        reader.face(&positions, sink)?;
    }
    reader.end()?;
    Ok(positions)
}

/// The non-blank lines with comments removed.
fn content_lines(bytes: &[u8]) -> impl Iterator<Item = ContentLine<'_>> {
    lines(bytes).filter_map(|(number, line)| {
        let content = line.split(|&b| b == b'#').next().unwrap_or_default();
        let words: Vec<&[u8]> = words(content).collect();
        (!words.is_empty()).then_some((number, words))
    })
}

struct OffReader<'a> {
    name: &'a str,
    lines: Box<dyn Iterator<Item = ContentLine<'a>> + 'a>,
    last_line: usize,
}

impl<'a> OffReader<'a> {
    fn error(&self, line: usize, message: impl Into<String>) -> MeshIoError {
        MeshIoError::parse(self.name, Location::Line(line), message)
    }

    /// The next content line, or an end-of-file error saying what was expected.
    fn next_line(&mut self, expected: &str) -> Result<ContentLine<'a>, MeshIoError> {
        match self.lines.next() {
            Some(line) => {
                self.last_line = line.0;
                Ok(line)
            }
            None => Err(self.error(
                self.last_line,
                format!("unexpected end of file: expected {expected}"),
            )),
        }
    }

    /// The `OFF` keyword and the vertex and face counts.
    fn header(&mut self) -> Result<(u64, u64), MeshIoError> {
        let (line, words) = self.next_line("'OFF'")?;
        let keyword = words.first().copied().unwrap_or_default();
        check_keyword(keyword).map_err(|message| self.error(line, message))?;
        let (line, counts) = if words.len() > 1 {
            (line, words[1..].to_vec())
        } else {
            self.next_line("the counts 'VERTICES FACES EDGES'")?
        };
        let numbers: Option<Vec<u64>> = counts
            .iter()
            .map(|w| parse_i64(w).and_then(|n| u64::try_from(n).ok()))
            .collect();
        match numbers.as_deref() {
            Some(&[vertices, faces]) | Some(&[vertices, faces, _]) => Ok((vertices, faces)),
            _ => Err(self.error(line, "expected the counts 'VERTICES FACES EDGES'")),
        }
    }

    /// One vertex line: `x y z` and ignored extra values.
    fn vertex(&mut self) -> Result<DVec3, MeshIoError> {
        let (line, words) = self.next_line("a vertex line 'x y z'")?;
        if words.len() < 3 {
            return Err(self.error(line, "expected a vertex line 'x y z'"));
        }
        let mut xyz = [0.0f64; 3];
        for (value, word) in xyz.iter_mut().zip(&words) {
            *value = parse_coordinate(word).map_err(|message| self.error(line, message))?;
        }
        Ok(DVec3::from_array(xyz))
    }

    /// One face line: `n i0 ... i(n-1)` and ignored color values.
    fn face(&mut self, positions: &[DVec3], out: &mut dyn FaceSink) -> Result<(), MeshIoError> {
        let (line, words) = self.next_line("a face line 'N i0 i1 ...'")?;
        let corners = face_corners(&words, positions.len()).map_err(|m| self.error(line, m))?;
        out.add(positions, &corners)
            .map_err(|e| self.error(line, e.to_string()))
    }

    /// Nothing may follow the last face.
    fn end(&mut self) -> Result<(), MeshIoError> {
        match self.lines.next() {
            None => Ok(()),
            Some((line, words)) => {
                let first = words.first().copied().unwrap_or_default();
                Err(self.error(
                    line,
                    format!("unexpected data after the last face: '{}'", show(first)),
                ))
            }
        }
    }
}

/// `OFF` with the optional `ST`, `C` and `N` prefixes of per-vertex data (which is ignored).
fn check_keyword(keyword: &[u8]) -> Result<(), String> {
    let prefix = keyword.strip_suffix(b"OFF");
    match prefix {
        Some(prefix) if prefix.iter().all(|b| b"STCN".contains(b)) => Ok(()),
        Some(_) => Err(format!(
            "unsupported OFF variant '{}' (only 3D OFF is read)",
            show(keyword)
        )),
        // Not quoted: the file may be anything (its content stays out of messages).
        None => Err("not an OFF file (the first word must be 'OFF')".into()),
    }
}

/// The vertex indices of a face line, checked against the vertex count.
fn face_corners(words: &[&[u8]], vertex_count: usize) -> Result<Vec<u32>, String> {
    let (count_word, rest) = words.split_first().ok_or("expected a face line")?;
    let count = parse_i64(count_word)
        .and_then(|n| usize::try_from(n).ok())
        .ok_or_else(|| format!("expected a vertex count, found '{}'", show(count_word)))?;
    let indices = rest.get(..count).ok_or_else(|| {
        format!(
            "face says {count} vertices but the line has {} indices",
            rest.len()
        )
    })?;
    indices
        .iter()
        .map(|word| {
            let index = parse_i64(word)
                .ok_or_else(|| format!("expected a vertex index, found '{}'", show(word)))?;
            u32::try_from(index)
                .ok()
                .filter(|&i| (i as usize) < vertex_count)
                .ok_or_else(|| {
                    format!(
                        "face index {index} out of range (the file has {vertex_count} vertices)"
                    )
                })
        })
        .collect()
}

/// Writes OFF: header, counts (with the number of distinct edges), vertices, triangles.
pub(super) fn write(out: &mut dyn Write, mesh: &IndexedMesh) -> io::Result<()> {
    write_faces(out, &mesh.positions, &mesh.triangles)
}

/// Writes OFF with a colour after each face's indices: `3 i j k r g b a`, channels 0..=255
/// (MeshLab's and Geomview's integer form; uncoloured triangles get [`DEFAULT_COLOR`]).
pub(super) fn write_colored(
    out: &mut dyn Write,
    mesh: &IndexedMesh,
    colors: &FaceColors,
) -> io::Result<()> {
    write_header(out, &mesh.positions, &mesh.triangles)?;
    for (t, [a, b, c]) in mesh.triangles.iter().enumerate() {
        let [r, g, bl, al] = colors.color_or(t, DEFAULT_COLOR);
        writeln!(out, "3 {a} {b} {c} {r} {g} {bl} {al}")?;
    }
    Ok(())
}

/// Writes OFF with faces of any size.
pub(super) fn write_faces<F: AsRef<[u32]>>(
    out: &mut dyn Write,
    positions: &[DVec3],
    faces: &[F],
) -> io::Result<()> {
    write_header(out, positions, faces)?;
    for face in faces {
        super::text::write_face_row(out, face.as_ref())?;
    }
    Ok(())
}

/// Writes the header, the counts and the vertices.
fn write_header<F: AsRef<[u32]>>(
    out: &mut dyn Write,
    positions: &[DVec3],
    faces: &[F],
) -> io::Result<()> {
    writeln!(out, "OFF")?;
    writeln!(out, "# written by solidkit")?;
    writeln!(
        out,
        "{} {} {}",
        positions.len(),
        faces.len(),
        edge_count(faces)
    )?;
    for p in positions {
        writeln!(out, "{} {} {}", p.x, p.y, p.z)?;
    }
    Ok(())
}

/// The number of distinct undirected edges.
fn edge_count<F: AsRef<[u32]>>(faces: &[F]) -> usize {
    let edges: HashSet<(u32, u32)> = faces
        .iter()
        .flat_map(|face| {
            let face = face.as_ref();
            (0..face.len()).map(move |k| (face[k], face[(k + 1) % face.len()]))
        })
        .map(|(a, b)| (a.min(b), a.max(b)))
        .collect();
    edges.len()
}
