//! The PLY header: the `ply` magic line, the `format` line and the `element`/`property`
//! declarations up to `end_header`, which say how to read the body.

use super::bytes::Endian;
use super::text::{show, words};
use super::{Location, MeshIoError};

/// How the body is encoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum BodyFormat {
    /// Whitespace-separated decimal numbers.
    Ascii,
    /// Packed binary numbers in the given byte order.
    Binary(Endian),
}

/// The scalar types of PLY properties.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum ScalarType {
    /// `char` / `int8`.
    I8,
    /// `uchar` / `uint8`.
    U8,
    /// `short` / `int16`.
    I16,
    /// `ushort` / `uint16`.
    U16,
    /// `int` / `int32`.
    I32,
    /// `uint` / `uint32`.
    U32,
    /// `float` / `float32`.
    F32,
    /// `double` / `float64`.
    F64,
}

impl ScalarType {
    fn parse(word: &[u8]) -> Option<ScalarType> {
        Some(match word {
            b"char" | b"int8" => ScalarType::I8,
            b"uchar" | b"uint8" => ScalarType::U8,
            b"short" | b"int16" => ScalarType::I16,
            b"ushort" | b"uint16" => ScalarType::U16,
            b"int" | b"int32" => ScalarType::I32,
            b"uint" | b"uint32" => ScalarType::U32,
            b"float" | b"float32" => ScalarType::F32,
            b"double" | b"float64" => ScalarType::F64,
            _ => return None,
        })
    }

    /// Size in bytes in a binary body.
    pub(super) fn size(self) -> usize {
        match self {
            ScalarType::I8 | ScalarType::U8 => 1,
            ScalarType::I16 | ScalarType::U16 => 2,
            ScalarType::I32 | ScalarType::U32 | ScalarType::F32 => 4,
            ScalarType::F64 => 8,
        }
    }

    /// Whether values of this type are integers.
    pub(super) fn is_integer(self) -> bool {
        !matches!(self, ScalarType::F32 | ScalarType::F64)
    }
}

/// One property of an element.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Property {
    /// A single number.
    Scalar {
        /// The property name (`x`, `red`, ...).
        name: String,
        /// Its type.
        ty: ScalarType,
    },
    /// A count followed by that many numbers.
    List {
        /// The property name (`vertex_indices`, ...).
        name: String,
        /// The type of the count.
        count: ScalarType,
        /// The type of the items.
        item: ScalarType,
    },
}

impl Property {
    /// The property name.
    pub(super) fn name(&self) -> &str {
        match self {
            Property::Scalar { name, .. } | Property::List { name, .. } => name,
        }
    }

    /// The fewest bytes one value of this property takes in the body.
    pub(super) fn min_size(&self, format: BodyFormat) -> usize {
        match (format, self) {
            (BodyFormat::Ascii, _) => 2,
            (BodyFormat::Binary(_), Property::Scalar { ty, .. }) => ty.size(),
            (BodyFormat::Binary(_), Property::List { count, .. }) => count.size(),
        }
    }
}

/// An element declaration: `element NAME COUNT` and its properties.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Element {
    /// The element name (`vertex`, `face`, ...).
    pub name: String,
    /// How many records the body holds (not trusted for allocations).
    pub count: u64,
    /// The line of the declaration.
    pub line: usize,
    /// The properties, in body order.
    pub properties: Vec<Property>,
}

impl Element {
    /// The fewest bytes one record takes in the body.
    pub(super) fn min_record_size(&self, format: BodyFormat) -> usize {
        self.properties.iter().map(|p| p.min_size(format)).sum()
    }
}

/// A parsed header.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Header {
    /// The body encoding.
    pub format: BodyFormat,
    /// The elements, in body order.
    pub elements: Vec<Element>,
    /// Byte offset of the body.
    pub body_start: usize,
    /// Line number of the `end_header` line.
    pub end_line: usize,
}

/// Parses the header of a PLY file.
pub(super) fn parse_header(bytes: &[u8], name: &str) -> Result<Header, MeshIoError> {
    let mut parser = HeaderParser {
        name,
        format: None,
        elements: Vec::new(),
    };
    let mut start = 0usize;
    let mut number = 0usize;
    while start < bytes.len() {
        number += 1;
        let rest = bytes.get(start..).unwrap_or_default();
        let end = rest
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |n| start + n);
        let line = bytes.get(start..end).unwrap_or_default();
        let line = line.strip_suffix(b"\r").unwrap_or(line);
        start = end.saturating_add(1);
        if parser.line(number, line)? {
            return parser.finish(start.min(bytes.len()), number);
        }
    }
    Err(MeshIoError::parse(
        name,
        Location::Line(number.max(1)),
        "unexpected end of file: the header has no 'end_header' line",
    ))
}

struct HeaderParser<'a> {
    name: &'a str,
    format: Option<BodyFormat>,
    elements: Vec<Element>,
}

impl HeaderParser<'_> {
    fn error(&self, line: usize, message: impl Into<String>) -> MeshIoError {
        MeshIoError::parse(self.name, Location::Line(line), message)
    }

    /// Handles one header line; `true` at `end_header`.
    fn line(&mut self, number: usize, line: &[u8]) -> Result<bool, MeshIoError> {
        let mut words = words(line);
        let keyword = words.next();
        if number == 1 {
            return match (keyword, words.next()) {
                (Some(b"ply"), None) => Ok(false),
                _ => Err(self.error(1, "not a PLY file: the first line must be 'ply'")),
            };
        }
        match keyword {
            None | Some(b"comment") | Some(b"obj_info") => {}
            Some(b"format") => self.format_line(number, words)?,
            Some(b"element") => self.element_line(number, words)?,
            Some(b"property") => self.property_line(number, words)?,
            Some(b"end_header") => return Ok(true),
            Some(other) => {
                return Err(self.error(
                    number,
                    format!("unexpected header line starting with '{}'", show(other)),
                ));
            }
        }
        Ok(false)
    }

    fn format_line<'w>(
        &mut self,
        number: usize,
        mut words: impl Iterator<Item = &'w [u8]>,
    ) -> Result<(), MeshIoError> {
        let format = match words.next() {
            Some(b"ascii") => BodyFormat::Ascii,
            Some(b"binary_little_endian") => BodyFormat::Binary(Endian::Little),
            Some(b"binary_big_endian") => BodyFormat::Binary(Endian::Big),
            _ => {
                return Err(self.error(
                    number,
                    "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'",
                ));
            }
        };
        if self.format.replace(format).is_some() {
            return Err(self.error(number, "second 'format' line"));
        }
        Ok(())
    }

    fn element_line<'w>(
        &mut self,
        number: usize,
        mut words: impl Iterator<Item = &'w [u8]>,
    ) -> Result<(), MeshIoError> {
        let name = words
            .next()
            .map(|w| String::from_utf8_lossy(w).into_owned());
        let count = words.next().and_then(parse_count);
        match (name, count, words.next()) {
            (Some(name), Some(count), None) => {
                self.elements.push(Element {
                    name,
                    count,
                    line: number,
                    properties: Vec::new(),
                });
                Ok(())
            }
            (name, _, _) => {
                let name = name.unwrap_or_else(|| "NAME".into());
                Err(self.error(
                    number,
                    format!("expected 'element {} N'", show(name.as_bytes())),
                ))
            }
        }
    }

    fn property_line<'w>(
        &mut self,
        number: usize,
        words: impl Iterator<Item = &'w [u8]>,
    ) -> Result<(), MeshIoError> {
        let words: Vec<&[u8]> = words.collect();
        let property = self.property(number, &words)?;
        let Some(element) = self.elements.last_mut() else {
            return Err(self.error(number, "'property' before any 'element'"));
        };
        element.properties.push(property);
        Ok(())
    }

    fn property(&self, number: usize, words: &[&[u8]]) -> Result<Property, MeshIoError> {
        let scalar = |word: &[u8]| {
            ScalarType::parse(word).ok_or_else(|| {
                self.error(number, format!("unknown property type '{}'", show(word)))
            })
        };
        let name = |word: &[u8]| String::from_utf8_lossy(word).into_owned();
        match *words {
            [b"list", count, item, property] => {
                let count = scalar(count)?;
                if !count.is_integer() {
                    return Err(
                        self.error(number, "the count type of a list must be an integer type")
                    );
                }
                Ok(Property::List {
                    name: name(property),
                    count,
                    item: scalar(item)?,
                })
            }
            [ty, property] if ty != b"list" => Ok(Property::Scalar {
                name: name(property),
                ty: scalar(ty)?,
            }),
            _ => Err(self.error(
                number,
                "expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'",
            )),
        }
    }

    fn finish(self, body_start: usize, end_line: usize) -> Result<Header, MeshIoError> {
        let format = self
            .format
            .ok_or_else(|| self.error(end_line, "the header has no 'format' line"))?;
        Ok(Header {
            format,
            elements: self.elements,
            body_start,
            end_line,
        })
    }
}

/// An element count: a non-negative decimal integer.
fn parse_count(word: &[u8]) -> Option<u64> {
    std::str::from_utf8(word).ok()?.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_elements_properties_and_the_body_offset() {
        let text = b"ply\r\nformat binary_big_endian 1.0\ncomment hi\nelement vertex 2\n\
            property float x\nproperty list uchar int vertex_indices\nend_header\nBODY";
        let header = parse_header(text, "m.ply").expect("valid");
        assert_eq!(header.format, BodyFormat::Binary(Endian::Big));
        assert_eq!(header.end_line, 7);
        assert_eq!(&text[header.body_start..], b"BODY");
        let vertex = &header.elements[0];
        assert_eq!(
            (vertex.name.as_str(), vertex.count, vertex.line),
            ("vertex", 2, 4)
        );
        assert_eq!(vertex.properties[1].name(), "vertex_indices");
        assert_eq!(vertex.min_record_size(header.format), 5);
    }

    #[test]
    fn reports_bad_lines() {
        let err = |text: &str| {
            parse_header(text.as_bytes(), "m.ply")
                .expect_err("bad")
                .to_string()
        };
        assert_eq!(
            err("ply\nformat ascii 1.0\nelement vertex many\nend_header\n"),
            "m.ply:3: expected 'element vertex N'"
        );
        assert!(err("PLY\n").starts_with("m.ply:1: not a PLY file"));
        assert!(err("ply\nformat ascii 1.0\nproperty float x\n").contains("before any 'element'"));
        assert!(err("ply\nformat ascii 1.0\nelement v 1\nproperty quad x\n").contains("'quad'"));
        assert!(err("ply\nformat ascii 1.0\nelement v 1\n").contains("no 'end_header'"));
        assert!(
            err("ply\nelement v 1\nend_header\n")
                .starts_with("m.ply:3: the header has no 'format'")
        );
        assert!(err("ply\nformat text 1.0\n").starts_with("m.ply:2:"));
    }
}
