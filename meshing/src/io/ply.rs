//! PLY reading (ASCII, binary little and big endian) and writing (binary little endian or
//! ASCII).
//!
//! The `vertex` element must have scalar `x`, `y` and `z` properties of any type; the `face`
//! element, if present, a list property `vertex_indices` (or `vertex_index`) with integer items.
//! Every other property and element is read past and ignored. Elements may come in any order:
//! faces are triangulated by [`super::triangulate_polygon`] (or kept as polygons by
//! [`read_faces`] with a polygon sink) once the whole body is read.
//! ASCII values are read as `f64` whatever their declared type.

use std::io::{self, Write};

use glam::DVec3;

use super::bytes::ByteCursor;
use super::faces::FaceSink;
use super::ply_header::{BodyFormat, Element, Header, Property, ScalarType, parse_header};
use super::text::{Tokens, capped_capacity, parse_f64, parse_i64, show};
use super::{Encoding, Location, MeshIoError};
use crate::IndexedMesh;

/// Reads a PLY file's faces into `sink`; returns the positions.
pub(super) fn read_faces(
    bytes: &[u8],
    name: &str,
    sink: &mut dyn FaceSink,
) -> Result<Vec<DVec3>, MeshIoError> {
    let header = parse_header(bytes, name)?;
    let layout = Layout::of(&header, name)?;
    let body = bytes.get(header.body_start..).unwrap_or_default();
    let mut values: Box<dyn Values + '_> = match header.format {
        BodyFormat::Ascii => Box::new(AsciiValues {
            tokens: Tokens::new(body, header.end_line + 1),
            last_line: header.end_line,
        }),
        BodyFormat::Binary(endian) => Box::new(BinaryValues {
            cursor: ByteCursor::new(bytes, header.body_start, endian),
            last_offset: header.body_start as u64,
        }),
    };
    let mut reader = BodyReader {
        name,
        layout,
        values: values.as_mut(),
        positions: Vec::new(),
        faces: Faces::default(),
    };
    for element in &header.elements {
        reader.element(element, header.format, body.len())?;
    }
    reader.end_of_body()?;
    reader.into_faces(sink)
}

/// Where the needed properties are.
struct Layout {
    /// Vertex count declared by the header.
    vertex_count: u64,
    /// Property positions of `x`, `y` and `z` in the vertex element.
    xyz: [usize; 3],
    /// Property position of the vertex index list in the face element, if there are faces.
    indices: Option<usize>,
}

impl Layout {
    fn of(header: &Header, name: &str) -> Result<Layout, MeshIoError> {
        let error = |line, message: String| MeshIoError::parse(name, Location::Line(line), message);
        let vertex = find_element(header, "vertex", name)?.ok_or_else(|| {
            error(
                header.end_line,
                "expected 'element vertex N' in the header".into(),
            )
        })?;
        let mut xyz = [0usize; 3];
        for (slot, axis) in xyz.iter_mut().zip(["x", "y", "z"]) {
            *slot = match find_property(vertex, axis) {
                Some((i, Property::Scalar { .. })) => i,
                Some(_) => {
                    return Err(error(
                        vertex.line,
                        format!("vertex property '{axis}' is a list"),
                    ));
                }
                None => {
                    return Err(error(
                        vertex.line,
                        format!("vertex element has no '{axis}' property"),
                    ));
                }
            };
        }
        let indices = match find_element(header, "face", name)? {
            Some(face) => Some(index_list(face).map_err(|message| error(face.line, message))?),
            None => None,
        };
        Ok(Layout {
            vertex_count: vertex.count,
            xyz,
            indices,
        })
    }
}

/// The only element called `element_name`, if any.
fn find_element<'h>(
    header: &'h Header,
    element_name: &str,
    name: &str,
) -> Result<Option<&'h Element>, MeshIoError> {
    let mut found = header.elements.iter().filter(|e| e.name == element_name);
    let first = found.next();
    match found.next() {
        Some(second) => Err(MeshIoError::parse(
            name,
            Location::Line(second.line),
            format!("second '{element_name}' element"),
        )),
        None => Ok(first),
    }
}

fn find_property<'e>(element: &'e Element, property: &str) -> Option<(usize, &'e Property)> {
    element
        .properties
        .iter()
        .enumerate()
        .find(|(_, p)| p.name() == property)
}

/// The position of the integer list `vertex_indices` (or `vertex_index`) of the face element.
fn index_list(face: &Element) -> Result<usize, String> {
    let found =
        find_property(face, "vertex_indices").or_else(|| find_property(face, "vertex_index"));
    match found {
        Some((i, Property::List { item, .. })) if item.is_integer() => Ok(i),
        Some(_) => Err("face property 'vertex_indices' must be a list of integers".into()),
        None => Err("face element has no 'vertex_indices' list property".into()),
    }
}

/// Face corners, flattened, with the location of each face.
#[derive(Default)]
struct Faces {
    corners: Vec<u32>,
    /// End offset in `corners` and location of each face.
    ends: Vec<(usize, Location)>,
}

/// Numbers from the body, ASCII or binary.
trait Values {
    /// A number of type `ty`, as `f64`.
    fn number(&mut self, ty: ScalarType) -> Result<f64, String>;
    /// A number of integer type `ty`.
    fn integer(&mut self, ty: ScalarType) -> Result<i64, String>;
    /// Skips `n` numbers of type `ty`.
    fn skip(&mut self, ty: ScalarType, n: u64) -> Result<(), String>;
    /// Where the last number read (or the start of what follows, before any) is.
    fn location(&self) -> Location;
    /// An error if anything but whitespace (ASCII) or nothing (binary) follows.
    fn at_end(&mut self) -> Result<(), String>;
}

struct AsciiValues<'a> {
    tokens: Tokens<'a>,
    last_line: usize,
}

impl AsciiValues<'_> {
    fn token(&mut self) -> Result<&[u8], String> {
        let (line, token) = self
            .tokens
            .next_token()
            .ok_or("unexpected end of file: more values expected")?;
        self.last_line = line;
        Ok(token)
    }
}

impl Values for AsciiValues<'_> {
    fn number(&mut self, _ty: ScalarType) -> Result<f64, String> {
        let token = self.token()?;
        parse_f64(token).ok_or_else(|| format!("expected a number, found '{}'", show(token)))
    }

    fn integer(&mut self, _ty: ScalarType) -> Result<i64, String> {
        let token = self.token()?;
        parse_i64(token).ok_or_else(|| format!("expected an integer, found '{}'", show(token)))
    }

    fn skip(&mut self, _ty: ScalarType, n: u64) -> Result<(), String> {
        for _ in 0..n {
            self.token()?;
        }
        Ok(())
    }

    fn location(&self) -> Location {
        Location::Line(self.last_line)
    }

    fn at_end(&mut self) -> Result<(), String> {
        match self.tokens.next_token() {
            None => Ok(()),
            Some((line, token)) => {
                self.last_line = line;
                Err(format!(
                    "unexpected data after the last element: '{}'",
                    show(token)
                ))
            }
        }
    }
}

struct BinaryValues<'a> {
    cursor: ByteCursor<'a>,
    last_offset: u64,
}

impl Values for BinaryValues<'_> {
    fn number(&mut self, ty: ScalarType) -> Result<f64, String> {
        self.last_offset = self.cursor.offset();
        let c = &mut self.cursor;
        let value = match ty {
            ScalarType::F32 => c.f32().map(f64::from),
            ScalarType::F64 => c.f64(),
            _ => return self.integer(ty).map(|i| i as f64),
        };
        value.ok_or_else(truncated)
    }

    fn integer(&mut self, ty: ScalarType) -> Result<i64, String> {
        self.last_offset = self.cursor.offset();
        let c = &mut self.cursor;
        let value = match ty {
            ScalarType::I8 => c.i8().map(i64::from),
            ScalarType::U8 => c.u8().map(i64::from),
            ScalarType::I16 => c.i16().map(i64::from),
            ScalarType::U16 => c.u16().map(i64::from),
            ScalarType::I32 => c.i32().map(i64::from),
            ScalarType::U32 => c.u32().map(i64::from),
            ScalarType::F32 | ScalarType::F64 => return Err("expected an integer type".into()),
        };
        value.ok_or_else(truncated)
    }

    fn skip(&mut self, ty: ScalarType, n: u64) -> Result<(), String> {
        self.last_offset = self.cursor.offset();
        let bytes = n.checked_mul(ty.size() as u64).ok_or_else(truncated)?;
        self.cursor.skip(bytes).ok_or_else(truncated)
    }

    fn location(&self) -> Location {
        Location::Byte(self.last_offset)
    }

    fn at_end(&mut self) -> Result<(), String> {
        self.last_offset = self.cursor.offset();
        match self.cursor.remaining() {
            0 => Ok(()),
            n => Err(format!("unexpected {n} bytes after the last element")),
        }
    }
}

fn truncated() -> String {
    "unexpected end of file: more values expected".into()
}

/// Reads the body element by element.
struct BodyReader<'a, 'v> {
    name: &'a str,
    layout: Layout,
    values: &'v mut dyn Values,
    positions: Vec<DVec3>,
    faces: Faces,
}

/// What to do with a property while reading a record.
enum Role {
    Coordinate(usize),
    Indices,
    Skip,
}

impl BodyReader<'_, '_> {
    fn error(&self, message: impl Into<String>) -> MeshIoError {
        MeshIoError::parse(self.name, self.values.location(), message)
    }

    fn element(
        &mut self,
        element: &Element,
        format: BodyFormat,
        available: usize,
    ) -> Result<(), MeshIoError> {
        let min_size = element.min_record_size(format);
        if min_size == 0 {
            return Ok(()); // No properties: nothing in the body, whatever the count.
        }
        let roles = self.roles(element);
        let capacity = capped_capacity(element.count, available, min_size);
        if element.name == "vertex" {
            self.positions.reserve(capacity);
        } else if element.name == "face" {
            self.faces.ends.reserve(capacity);
        }
        for _ in 0..element.count {
            self.record(element, &roles)?;
        }
        Ok(())
    }

    fn roles(&self, element: &Element) -> Vec<Role> {
        let role = |i: usize| match element.name.as_str() {
            "vertex" => match self.layout.xyz.iter().position(|&p| p == i) {
                Some(axis) => Role::Coordinate(axis),
                None => Role::Skip,
            },
            "face" if self.layout.indices == Some(i) => Role::Indices,
            _ => Role::Skip,
        };
        (0..element.properties.len()).map(role).collect()
    }

    fn record(&mut self, element: &Element, roles: &[Role]) -> Result<(), MeshIoError> {
        let mut xyz = [0.0f64; 3];
        for (property, role) in element.properties.iter().zip(roles) {
            match (property, role) {
                (Property::Scalar { ty, .. }, Role::Coordinate(axis)) => {
                    xyz[*axis] = self.coordinate(*ty)?;
                }
                (Property::List { count, item, .. }, Role::Indices) => self.face(*count, *item)?,
                (Property::Scalar { ty, .. }, _) => self.skip(*ty, 1)?,
                (Property::List { count, item, .. }, _) => {
                    let n = self.list_len(*count)?;
                    self.skip(*item, n)?;
                }
            }
        }
        if element.name == "vertex" {
            self.positions.push(DVec3::from_array(xyz));
        }
        Ok(())
    }

    fn coordinate(&mut self, ty: ScalarType) -> Result<f64, MeshIoError> {
        let value = self.values.number(ty).map_err(|m| self.error(m))?;
        if value.is_finite() {
            Ok(value)
        } else {
            Err(self.error(format!("coordinate {value} is not a finite number")))
        }
    }

    fn skip(&mut self, ty: ScalarType, n: u64) -> Result<(), MeshIoError> {
        self.values.skip(ty, n).map_err(|m| self.error(m))
    }

    fn list_len(&mut self, ty: ScalarType) -> Result<u64, MeshIoError> {
        let n = self.values.integer(ty).map_err(|m| self.error(m))?;
        u64::try_from(n).map_err(|_| self.error(format!("negative list length {n}")))
    }

    /// One face: its corners are range-checked now and triangulated at the end.
    fn face(&mut self, count: ScalarType, item: ScalarType) -> Result<(), MeshIoError> {
        let n = self.list_len(count)?;
        let location = self.values.location();
        for _ in 0..n {
            let index = self.values.integer(item).map_err(|m| self.error(m))?;
            let corner = u32::try_from(index)
                .ok()
                .filter(|&i| u64::from(i) < self.layout.vertex_count)
                .ok_or_else(|| {
                    self.error(format!(
                        "face index {index} out of range (the file has {} vertices)",
                        self.layout.vertex_count
                    ))
                })?;
            self.faces.corners.push(corner);
        }
        self.faces.ends.push((self.faces.corners.len(), location));
        Ok(())
    }

    fn end_of_body(&mut self) -> Result<(), MeshIoError> {
        self.values.at_end().map_err(|m| self.error(m))
    }

    fn into_faces(self, sink: &mut dyn FaceSink) -> Result<Vec<DVec3>, MeshIoError> {
        let mut start = 0;
        for &(end, location) in &self.faces.ends {
            let corners = self.faces.corners.get(start..end).unwrap_or_default();
            sink.add(&self.positions, corners)
                .map_err(|e| MeshIoError::parse(self.name, location, e.to_string()))?;
            start = end;
        }
        Ok(self.positions)
    }
}

/// Writes `mesh` as binary little endian (doubles) or ASCII PLY.
pub(super) fn write(out: &mut dyn Write, mesh: &IndexedMesh, encoding: Encoding) -> io::Result<()> {
    write_faces(out, &mesh.positions, &mesh.triangles, encoding)
}

/// Writes faces of any size as binary little endian (doubles) or ASCII PLY; the list length is
/// a `uchar` when every face has at most 255 corners, a `uint` otherwise.
pub(super) fn write_faces<F: AsRef<[u32]>>(
    out: &mut dyn Write,
    positions: &[DVec3],
    faces: &[F],
    encoding: Encoding,
) -> io::Result<()> {
    let binary = encoding == Encoding::Binary;
    let wide = faces.iter().any(|f| f.as_ref().len() > 255);
    write_header(out, positions.len(), faces.len(), wide, binary)?;
    if binary {
        write_binary_body(out, positions, faces, wide)
    } else {
        write_ascii_body(out, positions, faces)
    }
}

/// `int` indices where they fit (most widely read), `uint` otherwise.
pub(super) fn index_type(vertex_count: usize) -> &'static str {
    if i32::try_from(vertex_count).is_ok() {
        "int"
    } else {
        "uint"
    }
}

fn write_header(
    out: &mut dyn Write,
    vertex_count: usize,
    face_count: usize,
    wide: bool,
    binary: bool,
) -> io::Result<()> {
    let (format, scalar) = if binary {
        ("binary_little_endian", "double")
    } else {
        ("ascii", "float")
    };
    writeln!(out, "ply")?;
    writeln!(out, "format {format} 1.0")?;
    writeln!(out, "comment written by solidkit")?;
    writeln!(out, "element vertex {vertex_count}")?;
    for axis in ["x", "y", "z"] {
        writeln!(out, "property {scalar} {axis}")?;
    }
    writeln!(out, "element face {face_count}")?;
    let count = if wide { "uint" } else { "uchar" };
    writeln!(
        out,
        "property list {count} {} vertex_indices",
        index_type(vertex_count)
    )?;
    writeln!(out, "end_header")
}

fn write_binary_body<F: AsRef<[u32]>>(
    out: &mut dyn Write,
    positions: &[DVec3],
    faces: &[F],
    wide: bool,
) -> io::Result<()> {
    for p in positions {
        for c in p.to_array() {
            out.write_all(&c.to_le_bytes())?;
        }
    }
    for face in faces {
        let face = face.as_ref();
        if wide {
            out.write_all(&(face.len() as u32).to_le_bytes())?;
        } else {
            out.write_all(&[face.len() as u8])?;
        }
        for i in face {
            out.write_all(&i.to_le_bytes())?;
        }
    }
    Ok(())
}

fn write_ascii_body<F: AsRef<[u32]>>(
    out: &mut dyn Write,
    positions: &[DVec3],
    faces: &[F],
) -> io::Result<()> {
    for p in positions {
        writeln!(out, "{} {} {}", p.x, p.y, p.z)?;
    }
    for face in faces {
        super::text::write_face_row(out, face.as_ref())?;
    }
    Ok(())
}
