//! Reading the polyhedral node types: `platonic` (solid, circumradius | edge), `polyhedron`
//! (vertices, faces), `mesh` (path, loaded through the reader's [`MeshResolver`]) and `prism`
//! (polygon, holes, direction). Errors name the key and, inside lists, the item
//! (`faces[3]: face 3 refers to vertex 9 …`).
//!
//! [`MeshResolver`]: crate::primitive::MeshResolver

use super::{Params, R, Value};
use crate::polyhedra::{PlatonicKind, PlatonicSize, PolyhedronError, Prism};
use crate::primitive::{MeshSolid, MeshSolidError, Platonic, Primitive};
use glam::{DVec2, DVec3};

/// A primitive and the keys its node may have.
type Read = (Primitive, &'static [&'static str]);

impl Params<'_, '_> {
    /// `{"type": "platonic", "solid": "icosahedron", "circumradius": 1}` (or `"edge"`).
    pub(super) fn platonic(&self) -> R<Read> {
        let name = self.string("solid")?;
        let kind = PlatonicKind::from_name(name).ok_or_else(|| {
            let names: Vec<&str> = PlatonicKind::ALL.iter().map(|k| k.name()).collect();
            self.fail(
                self.at("solid").unwrap_or(self.index),
                "solid",
                format!(
                    "unknown solid \"{name}\" (expected one of: {})",
                    names.join(", ")
                ),
            )
        })?;
        let has = |key| super::find(self.entries, key).is_some();
        let size = match (has("circumradius"), has("edge")) {
            (true, false) => PlatonicSize::Circumradius(self.number("circumradius")?),
            (false, true) => PlatonicSize::Edge(self.number("edge")?),
            (true, true) => {
                return Err(self.fail(
                    self.at("edge")?,
                    "edge",
                    "give either \"circumradius\" or \"edge\", not both",
                ));
            }
            (false, false) => {
                return Err(self.reader.located(
                    self.index,
                    &self.path(),
                    "missing key \"circumradius\" or \"edge\"",
                ));
            }
        };
        let prim = Primitive::Platonic(Platonic::new(kind, size));
        Ok((prim, &["solid", "circumradius", "edge"]))
    }

    /// `{"type": "polyhedron", "vertices": [[x, y, z], …], "faces": [[i, j, k, …], …]}`.
    pub(super) fn polyhedron(&self) -> R<Read> {
        let vertices = self.points3("vertices")?;
        let faces = self.index_lists("faces")?;
        let mesh = MeshSolid::from_faces(vertices, faces).map_err(|e| self.mesh_error(e))?;
        Ok((Primitive::Mesh(mesh), &["vertices", "faces"]))
    }

    /// `{"type": "mesh", "path": "part.obj"}`, loaded by the reader's resolver.
    pub(super) fn mesh_file(&self) -> R<Read> {
        let path = self.string("path")?;
        let mesh =
            MeshSolid::from_file(path, self.reader.resolver).map_err(|e| self.mesh_error(e))?;
        Ok((Primitive::Mesh(mesh), &["path"]))
    }

    /// `{"type": "prism", "polygon": [[x, y], …], "holes": [[[x, y], …], …], "direction": [x, y,
    /// z]}` (`holes` optional).
    pub(super) fn prism(&self) -> R<Read> {
        let polygon = self.points2_at(self.at("polygon")?, "polygon")?;
        let holes = match super::find(self.entries, "holes") {
            None => Vec::new(),
            Some(i) => self
                .items(i, "holes")?
                .iter()
                .enumerate()
                .map(|(k, &h)| self.points2_at(h, &format!("holes[{k}]")))
                .collect::<R<_>>()?,
        };
        let direction = self.vec3("direction")?;
        let prism = Prism::new(polygon, holes, direction);
        let mesh = MeshSolid::from_prism(prism).map_err(|e| self.mesh_error(e))?;
        Ok((Primitive::Mesh(mesh), &["polygon", "holes", "direction"]))
    }

    /// Locates a mesh error at the key (and list item) it is about.
    fn mesh_error(&self, e: MeshSolidError) -> super::Located {
        let item = |key: &str, i: usize| {
            let list = self.at(key).ok();
            let at = list
                .and_then(|l| match &self.reader.doc.values[l as usize] {
                    Value::Array(items) => items.get(i).copied(),
                    _ => None,
                })
                .or(list)
                .unwrap_or(self.index);
            (at, format!("{key}[{i}]"))
        };
        let key_at = |key: &str| (self.at(key).unwrap_or(self.index), key.to_string());
        let ((at, key), message) = match &e {
            MeshSolidError::Invalid(p) => match *p {
                PolyhedronError::NonFiniteVertex { vertex } => {
                    (item("vertices", vertex), e.to_string())
                }
                PolyhedronError::TooFewCorners { face, .. }
                | PolyhedronError::IndexOutOfRange { face, .. }
                | PolyhedronError::RepeatedCorner { face, .. }
                | PolyhedronError::BadFace { face, .. } => (item("faces", face), e.to_string()),
                PolyhedronError::BadCrossSection { part, problem } => {
                    (key_at(part), problem.to_string())
                }
                PolyhedronError::FlatDirection => (
                    key_at("direction"),
                    "expected a finite vector with a non-zero z component".into(),
                ),
                _ => (key_at("faces"), e.to_string()),
            },
            MeshSolidError::Load { .. } => (key_at("path"), e.to_string()),
            MeshSolidError::NotPolyhedral { .. }
            | MeshSolidError::NotDualizable { .. }
            | MeshSolidError::Subdivision(_) => (key_at("child"), e.to_string()),
        };
        self.fail(at, &key, message)
    }

    pub(super) fn string(&self, key: &str) -> R<&str> {
        let i = self.at(key)?;
        match &self.reader.doc.values[i as usize] {
            Value::String(s) => Ok(s.as_str()),
            v => Err(self.fail(
                i,
                key,
                format!("expected a string, found {}", v.type_name()),
            )),
        }
    }

    /// The items of the array at `index`.
    pub(super) fn items(&self, index: u32, key: &str) -> R<&[u32]> {
        match &self.reader.doc.values[index as usize] {
            Value::Array(items) => Ok(items),
            v => Err(self.fail(
                index,
                key,
                format!("expected an array, found {}", v.type_name()),
            )),
        }
    }

    pub(super) fn points3(&self, key: &str) -> R<Vec<DVec3>> {
        let list = self.items(self.at(key)?, key)?;
        list.iter()
            .enumerate()
            .map(|(k, &i)| {
                Ok(DVec3::from_array(
                    self.numbers::<3>(i, &format!("{key}[{k}]"))?,
                ))
            })
            .collect()
    }

    fn points2_at(&self, index: u32, key: &str) -> R<Vec<DVec2>> {
        let list = self.items(index, key)?;
        list.iter()
            .enumerate()
            .map(|(k, &i)| {
                Ok(DVec2::from_array(
                    self.numbers::<2>(i, &format!("{key}[{k}]"))?,
                ))
            })
            .collect()
    }

    /// Lists of vertex indices (non-negative integers below 2³²).
    pub(super) fn index_lists(&self, key: &str) -> R<Vec<Vec<u32>>> {
        let lists = self.items(self.at(key)?, key)?;
        let mut out = Vec::with_capacity(lists.len());
        for (k, &l) in lists.iter().enumerate() {
            let name = format!("{key}[{k}]");
            let mut face = Vec::new();
            for &i in self.items(l, &name)? {
                let x = self.number_at(i, &name)?;
                if !(x >= 0.0 && x < u32::MAX as f64 && x.fract() == 0.0) {
                    return Err(self.fail(i, &name, format!("expected a vertex index, found {x}")));
                }
                face.push(x as u32);
            }
            out.push(face);
        }
        Ok(out)
    }
}
