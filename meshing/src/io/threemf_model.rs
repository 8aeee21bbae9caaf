//! The 3MF model part's XML read into objects and build items (core specification 1.3):
//! `<object id>` with a `<mesh>` (`<vertex x y z>`, `<triangle v1 v2 v3>`) and/or
//! `<components>` (`<component objectid transform>`), and `<build>` `<item objectid transform>`.
//!
//! Only unprefixed (core namespace) elements are read; extension elements and attributes such as
//! materials and colours are ignored, except an item or component naming another model part
//! (the production extension's `path`), which is refused. Every number is checked (finite
//! coordinates, triangle indices within the object's vertices, transforms of 12 finite numbers)
//! and every problem carries its line.

use std::collections::HashMap;

use glam::{DAffine3, DMat3, DVec3};

use super::xml::{Scanner, Tag, XmlError, attribute, attributes};

/// The most vertices plus triangles a model part may declare, and a 3MF build or a GLB scene
/// may expand to (2²⁶: about 1.6 GiB of mesh; a 1 GiB model part holds at most about 2²⁵).
pub(super) const MAX_ELEMENTS: usize = 1 << 26;

/// An object resource.
#[derive(Debug, Default)]
pub(super) struct Object {
    /// Mesh vertices.
    pub positions: Vec<DVec3>,
    /// Mesh triangles, indices into `positions`.
    pub triangles: Vec<[u32; 3]>,
    /// Components: object id and transform.
    pub components: Vec<Placement>,
}

/// A reference to an object with its transform and the line of the reference.
#[derive(Debug, Clone, Copy)]
pub(super) struct Placement {
    /// The object's id.
    pub object: u32,
    /// Object coordinates → parent coordinates.
    pub transform: DAffine3,
    /// Line of the `<item>` or `<component>`.
    pub line: usize,
}

/// The objects and build items of a model part.
#[derive(Debug, Default)]
pub(super) struct Model {
    /// Objects by id.
    pub objects: HashMap<u32, Object>,
    /// Build items in document order.
    pub items: Vec<Placement>,
}

/// Reads the model XML.
pub(super) fn parse(text: &str) -> Result<Model, XmlError> {
    let mut model = Model::default();
    let mut scanner = Scanner::new(text);
    let mut current: Option<(u32, Object)> = None;
    let mut elements = 0usize;
    while let Some((tag, line)) = scanner.next_tag()? {
        let err = |message: String| XmlError { line, message };
        let (name, attrs) = match tag {
            Tag::End { name: "object" } => {
                if let Some((id, object)) = current.take() {
                    model.objects.insert(id, object);
                }
                continue;
            }
            Tag::End { .. } => continue,
            Tag::Start { name, attrs, empty } => {
                if name == "object" && empty {
                    let a = attributes(attrs).map_err(err)?;
                    let id = object_id(&a, "id").map_err(err)?;
                    insert_new(&mut model, id, Object::default()).map_err(err)?;
                    continue;
                }
                (name, attrs)
            }
        };
        if !matches!(
            name,
            "object" | "vertex" | "triangle" | "component" | "item"
        ) {
            continue;
        }
        let a = attributes(attrs).map_err(err)?;
        elements += 1;
        if elements > MAX_ELEMENTS {
            return Err(err(format!(
                "more than {MAX_ELEMENTS} vertices and triangles"
            )));
        }
        match name {
            "object" => {
                if let Some((id, object)) = current.take() {
                    model.objects.insert(id, object);
                }
                let id = object_id(&a, "id").map_err(err)?;
                if model.objects.contains_key(&id) {
                    return Err(err(format!("object id {id} is defined twice")));
                }
                current = Some((id, Object::default()));
            }
            "item" => model.items.push(placement(&a, line).map_err(err)?),
            _ => {
                let (_, object) = current
                    .as_mut()
                    .ok_or_else(|| err(format!("<{name}> outside an <object>")))?;
                match name {
                    "vertex" => object.positions.push(vertex(&a).map_err(err)?),
                    "triangle" => {
                        let t = triangle(&a, object.positions.len()).map_err(err)?;
                        object.triangles.push(t);
                    }
                    _ => object.components.push(placement(&a, line).map_err(err)?),
                }
            }
        }
    }
    if let Some((id, _)) = current {
        return Err(XmlError {
            line: scanner_end_line(text),
            message: format!("object {id} is not closed"),
        });
    }
    Ok(model)
}

/// Adds an empty object, refusing a repeated id.
fn insert_new(model: &mut Model, id: u32, object: Object) -> Result<(), String> {
    if model.objects.insert(id, object).is_some() {
        return Err(format!("object id {id} is defined twice"));
    }
    Ok(())
}

/// The last line of `text`.
fn scanner_end_line(text: &str) -> usize {
    1 + text.bytes().filter(|&b| b == b'\n').count()
}

type Attrs<'a> = [(&'a str, std::borrow::Cow<'a, str>)];

/// A positive object id.
fn object_id(a: &Attrs<'_>, key: &str) -> Result<u32, String> {
    let text = attribute(a, key).ok_or_else(|| format!("missing attribute {key}"))?;
    text.trim()
        .parse::<u32>()
        .ok()
        .filter(|&id| id > 0)
        .ok_or_else(|| format!("{key} must be a positive integer"))
}

/// A finite coordinate.
fn number(a: &Attrs<'_>, key: &str) -> Result<f64, String> {
    let text = attribute(a, key).ok_or_else(|| format!("missing attribute {key}"))?;
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("{key} is not a finite number"))
}

/// `<vertex x y z>`.
fn vertex(a: &Attrs<'_>) -> Result<DVec3, String> {
    Ok(DVec3::new(
        number(a, "x")?,
        number(a, "y")?,
        number(a, "z")?,
    ))
}

/// `<triangle v1 v2 v3>` with indices below `count`.
fn triangle(a: &Attrs<'_>, count: usize) -> Result<[u32; 3], String> {
    let mut t = [0u32; 3];
    for (slot, key) in t.iter_mut().zip(["v1", "v2", "v3"]) {
        let text = attribute(a, key).ok_or_else(|| format!("missing attribute {key}"))?;
        let index: u32 = text
            .trim()
            .parse()
            .map_err(|_| format!("{key} is not a vertex index"))?;
        if index as usize >= count {
            return Err(format!(
                "{key} = {index} is out of range (the object has {count} vertices before it)"
            ));
        }
        *slot = index;
    }
    Ok(t)
}

/// `objectid` and `transform` of an `<item>` or `<component>`.
fn placement(a: &Attrs<'_>, line: usize) -> Result<Placement, String> {
    if a.iter().any(|(k, _)| k.ends_with(":path")) {
        return Err(
            "references to other model parts (production extension) are not supported".into(),
        );
    }
    let transform = match attribute(a, "transform") {
        Some(text) => transform(text)?,
        None => DAffine3::IDENTITY,
    };
    Ok(Placement {
        object: object_id(a, "objectid")?,
        transform,
        line,
    })
}

/// A 3MF transform `m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32` (row vectors:
/// `x' = x m00 + y m10 + z m20 + m30`).
fn transform(text: &str) -> Result<DAffine3, String> {
    let values: Vec<f64> = text
        .split_ascii_whitespace()
        .map(|v| v.parse::<f64>().ok().filter(|v| v.is_finite()))
        .collect::<Option<_>>()
        .ok_or("transform: not a list of finite numbers")?;
    let m: [f64; 12] = values
        .try_into()
        .map_err(|_| "transform: expected 12 numbers")?;
    Ok(DAffine3::from_mat3_translation(
        DMat3::from_cols_array(&[m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]]),
        DVec3::new(m[9], m[10], m[11]),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transforms_are_row_vector_matrices() {
        let t = transform("0 1 0 -1 0 0 0 0 1 10 20 30").unwrap();
        // x' = x m00 + y m10 + z m20 + m30 = -y + 10, y' = x + 20.
        assert_eq!(
            t.transform_point3(DVec3::new(1.0, 2.0, 3.0)),
            DVec3::new(8.0, 21.0, 33.0)
        );
        assert!(transform("1 0 0").is_err());
        assert!(transform("1 0 0 0 1 0 0 0 1 0 0 inf").is_err());
    }

    #[test]
    fn objects_items_and_errors_with_lines() {
        let m = parse(
            "<model><resources><object id=\"3\"><mesh><vertices>\n<vertex x=\"0\" y=\"0\" z=\"0\"/><vertex x=\"1\" y=\"0\" z=\"0\"/><vertex x=\"0\" y=\"1\" z=\"0\"/></vertices>\n<triangles><triangle v1=\"0\" v2=\"1\" v3=\"2\"/></triangles></mesh></object></resources><build><item objectid=\"3\"/></build></model>",
        )
        .unwrap();
        assert_eq!(m.objects[&3].triangles, vec![[0, 1, 2]]);
        assert_eq!(m.items.len(), 1);
        let e = parse("<object id=\"1\">\n<vertex x=\"0\" y=\"0\" z=\"0\"/>\n<triangle v1=\"0\" v2=\"1\" v3=\"0\"/></object>").unwrap_err();
        assert_eq!(e.line, 3);
        assert!(e.message.contains("out of range"), "{e:?}");
        let e = parse("<object id=\"1\"><vertex x=\"nan\" y=\"0\" z=\"0\"/></object>").unwrap_err();
        assert!(e.message.contains("finite"));
        assert!(parse("<vertex x=\"0\" y=\"0\" z=\"0\"/>").is_err());
        assert!(parse("<object id=\"1\"></object><object id=\"1\"></object>").is_err());
        assert!(parse("<object id=\"1\">").is_err());
    }
}
