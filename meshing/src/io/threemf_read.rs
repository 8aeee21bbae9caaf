//! 3MF input: the package (a zip, see [`unzip`](super::unzip)) → its model part → one
//! [`IndexedMesh`] holding every build item with its transform applied.
//!
//! The model part is the target of the package relationship of type `.../3dmodel` in
//! `_rels/.rels`, or `3D/3dmodel.model` when there is no such relationship. Each build item
//! adds its object's mesh and, through components (nested at most [`MAX_DEPTH`] deep, so a
//! cycle is an error), the meshes of the objects it is made of; objects keep their own vertices
//! (nothing is welded across objects). Coordinates are read as written, whatever the model's
//! `unit`. Errors name the entry and the line: `FILE: entry 3D/3dmodel.model: line 7: ...`.

use glam::DAffine3;

use super::threemf_model::{self, MAX_ELEMENTS, Model, Object, Placement};
use super::unzip::{Archive, MAX_ENTRY_BYTES};
use super::xml::{Scanner, Tag, XmlError, attribute, attributes};
use super::{Location, MeshIoError};
use crate::IndexedMesh;

/// How deep components may nest below a build item.
pub(super) const MAX_DEPTH: usize = 32;
/// The most object placements (items and components) a build may expand to.
pub(super) const MAX_PLACEMENTS: usize = 1 << 22;
/// The part read when the package has no model relationship.
const DEFAULT_MODEL: &str = "3D/3dmodel.model";
/// The package relationships.
const RELS: &str = "_rels/.rels";

/// Reads a 3MF package.
pub(super) fn read(bytes: &[u8], name: &str) -> Result<IndexedMesh, MeshIoError> {
    read_limited(bytes, name, MAX_ENTRY_BYTES)
}

/// [`read`] with a limit on the inflated size of each entry.
pub(super) fn read_limited(
    bytes: &[u8],
    name: &str,
    limit: u64,
) -> Result<IndexedMesh, MeshIoError> {
    let archive = Archive::open(bytes, name)?;
    let part = model_part(&archive, name, limit)?;
    let entry = archive.find(&part).ok_or_else(|| {
        let names: Vec<&str> = archive.entries().iter().map(|e| e.name.as_str()).collect();
        MeshIoError::invalid(
            name,
            format!(
                "no 3D model part {part} in the package (entries: {})",
                names.join(", ")
            ),
        )
    })?;
    let data = archive.read(entry, limit)?;
    let in_entry = |location, message: String| MeshIoError::Entry {
        path: name.to_string(),
        entry: entry.name.clone(),
        location,
        message,
    };
    let text = std::str::from_utf8(&data).map_err(|e| {
        in_entry(
            Location::Byte(e.valid_up_to() as u64),
            "not UTF-8 text".into(),
        )
    })?;
    let model =
        threemf_model::parse(text).map_err(|e| in_entry(Location::Line(e.line), e.message))?;
    build(&model).map_err(|e| in_entry(Location::Line(e.line), e.message))
}

/// The model part named by the package relationships, else the default name.
fn model_part(archive: &Archive<'_>, name: &str, limit: u64) -> Result<String, MeshIoError> {
    let Some(rels) = archive.find(RELS) else {
        return Ok(DEFAULT_MODEL.into());
    };
    let data = archive.read(rels, limit)?;
    let in_rels = |location, message: String| MeshIoError::Entry {
        path: name.to_string(),
        entry: rels.name.clone(),
        location,
        message,
    };
    let text = std::str::from_utf8(&data).map_err(|e| {
        in_rels(
            Location::Byte(e.valid_up_to() as u64),
            "not UTF-8 text".into(),
        )
    })?;
    let mut scanner = Scanner::new(text);
    while let Some((tag, line)) = scanner
        .next_tag()
        .map_err(|e| in_rels(Location::Line(e.line), e.message))?
    {
        let Tag::Start {
            name: "Relationship",
            attrs,
            ..
        } = tag
        else {
            continue;
        };
        let a = attributes(attrs).map_err(|m| in_rels(Location::Line(line), m))?;
        if attribute(&a, "Type").is_some_and(|t| t.ends_with("/3dmodel"))
            && let Some(target) = attribute(&a, "Target")
        {
            return Ok(target.trim_start_matches('/').to_string());
        }
    }
    Ok(DEFAULT_MODEL.into())
}

/// Every build item's meshes, transformed, in one mesh. The build is walked twice: first to
/// count what it expands to (refused over [`MAX_ELEMENTS`] before anything is copied, so a few
/// nested components cannot multiply a small file into gigabytes), then to copy.
fn build(model: &Model) -> Result<IndexedMesh, XmlError> {
    let mut total = 0usize;
    walk(model, |place, object| {
        total = total
            .saturating_add(object.positions.len())
            .saturating_add(object.triangles.len());
        if total > MAX_ELEMENTS {
            return Err(XmlError {
                line: place.line,
                message: format!(
                    "the build expands to more than {MAX_ELEMENTS} vertices and triangles"
                ),
            });
        }
        Ok(())
    })?;
    let mut mesh = IndexedMesh::default();
    walk(model, |place, object| {
        let base = mesh.positions.len() as u32;
        if place.transform == DAffine3::IDENTITY {
            mesh.positions.extend_from_slice(&object.positions);
        } else {
            let moved = object
                .positions
                .iter()
                .map(|&p| place.transform.transform_point3(p));
            mesh.positions.extend(moved);
        }
        if !mesh.positions[base as usize..]
            .iter()
            .all(|p| p.is_finite())
        {
            return Err(XmlError {
                line: place.line,
                message: "a vertex is not finite once the transform is applied".into(),
            });
        }
        let shifted = object.triangles.iter().map(|t| t.map(|v| v + base));
        mesh.triangles.extend(shifted);
        Ok(())
    })?;
    Ok(mesh)
}

/// Calls `visit` for each object placement of the build (items, then their components depth
/// first, transforms composed), with an explicit stack; refuses undefined objects, nesting
/// deeper than [`MAX_DEPTH`] and more than [`MAX_PLACEMENTS`] placements.
fn walk(
    model: &Model,
    mut visit: impl FnMut(&Placement, &Object) -> Result<(), XmlError>,
) -> Result<(), XmlError> {
    let mut stack: Vec<(Placement, usize)> = Vec::new();
    let mut placements = 0usize;
    for item in &model.items {
        stack.push((*item, 0));
        while let Some((place, depth)) = stack.pop() {
            let err = |message: String| XmlError {
                line: place.line,
                message,
            };
            let object = model
                .objects
                .get(&place.object)
                .ok_or_else(|| err(format!("object {} is not defined", place.object)))?;
            if depth > MAX_DEPTH {
                return Err(err(format!(
                    "components nested more than {MAX_DEPTH} deep (a cycle?)"
                )));
            }
            placements += 1;
            if placements > MAX_PLACEMENTS {
                return Err(err(format!(
                    "the build places more than {MAX_PLACEMENTS} objects"
                )));
            }
            visit(&place, object)?;
            for c in object.components.iter().rev() {
                let transform = place.transform * c.transform;
                stack.push((Placement { transform, ..*c }, depth + 1));
            }
        }
    }
    Ok(())
}
