//! Building a [`Solid`] from a parsed JSON document, bottom-up with a work list. Every error names
//! the JSON path of the bad node and the line and column of the offending text.

use super::document::{Document, Value, line_column, parse};
use super::{FORMAT, VERSION};
use crate::primitive::{
    Cone, Cuboid, Cylinder, HalfSpace, MeshResolver, NoMeshResolver, Primitive, Shape, Sphere,
    Torus,
};
use crate::solid::{NodeKind, Solid};
use crate::transform::{Transform, TransformSpec};
use crate::{KernelError, solid};
use glam::DVec3;

mod blob;
mod curve;
mod curve_profile;
mod dual;
mod expr;
mod heightfield;
mod polyhedra;
mod quadric;
mod subdivide;
mod surface;
mod sweep;
mod swept;

pub use curve::curve_from_str;

/// A problem at a byte offset, with the message already carrying the JSON path.
struct Located {
    offset: usize,
    message: String,
}

type R<T> = Result<T, Located>;

/// Reads a solid from JSON text: either the versioned envelope
/// `{"format": "solidkit-tree", "version": 1, "root": NODE}` or a bare node. A `mesh` node or a
/// `heightfield` with a `png` file is an error here (files need a resolver: see
/// [`from_str_with`]). Duplicate keys and raw control characters in strings are errors.
pub fn from_str(text: &str) -> Result<Solid, KernelError> {
    from_str_with(text, &NoMeshResolver)
}

/// Reads a solid from JSON text like [`from_str`], loading the files of `mesh` nodes and `png`
/// height maps with `resolver`.
pub fn from_str_with(text: &str, resolver: &dyn MeshResolver) -> Result<Solid, KernelError> {
    let doc = parse(text).map_err(|e| to_error(text, e.offset, e.message))?;
    Reader {
        doc: &doc,
        resolver,
    }
    .read()
    .map_err(|e| to_error(text, e.offset, e.message))
}

fn to_error(text: &str, offset: usize, message: String) -> KernelError {
    let (line, column) = line_column(text, offset);
    KernelError::Json {
        line,
        column,
        message,
    }
}

struct Reader<'a> {
    doc: &'a Document,
    resolver: &'a dyn MeshResolver,
}

/// One node being built: its object, its path segment, and the JSON indices of its children.
struct Frame<'a> {
    index: u32,
    segment: String,
    entries: &'a [(String, u32)],
    children: Vec<(String, u32)>,
    next: usize,
}

impl<'a> Reader<'a> {
    fn offset(&self, index: u32) -> usize {
        self.doc.offsets[index as usize]
    }

    fn located(&self, index: u32, path: &str, message: impl std::fmt::Display) -> Located {
        Located {
            offset: self.offset(index),
            message: format!("{path}: {message}"),
        }
    }

    fn read(&self) -> R<Solid> {
        let top = 0u32;
        let Value::Object(entries) = &self.doc.values[0] else {
            return Err(self.located(top, "root", "expected an object"));
        };
        if let Some((_, f)) = entries.iter().find(|(k, _)| k == "format") {
            self.check_envelope(entries, *f)?;
            let root = find(entries, "root")
                .ok_or_else(|| self.located(top, "root", "missing key \"root\""))?;
            return self.build(root, "root".into());
        }
        self.build(top, "root".into())
    }

    fn check_envelope(&self, entries: &[(String, u32)], format: u32) -> R<()> {
        match &self.doc.values[format as usize] {
            Value::String(s) if s == FORMAT => {}
            _ => return Err(self.located(format, "format", format!("expected \"{FORMAT}\""))),
        }
        let Some(v) = find(entries, "version") else {
            return Err(self.located(0, "version", "missing key \"version\""));
        };
        match self.doc.values[v as usize] {
            Value::Number(x) if x == VERSION as f64 => {}
            Value::Number(x) => {
                return Err(self.located(
                    v,
                    "version",
                    format!("unsupported version {x} (this build reads version {VERSION})"),
                ));
            }
            _ => return Err(self.located(v, "version", "expected a number")),
        }
        for (k, i) in entries {
            if !matches!(k.as_str(), "format" | "version" | "root" | "comment") {
                return Err(self.located(*i, k, format!("unknown key \"{k}\"")));
            }
        }
        Ok(())
    }

    /// Builds the subtree at `index` bottom-up without recursion.
    fn build(&self, index: u32, segment: String) -> R<Solid> {
        let mut frames = vec![self.frame(index, segment, &[])?];
        let mut done: Vec<Solid> = Vec::new();
        while let Some(top) = frames.last_mut() {
            if let Some((seg, child)) = top.children.get(top.next).cloned() {
                top.next += 1;
                let f = self.frame(child, seg, &frames)?;
                frames.push(f);
                continue;
            }
            let frame = frames.pop().expect("non-empty");
            let start = done.len() - frame.children.len();
            let children = done.split_off(start);
            done.push(self.node(&frame, &frames, children)?);
        }
        Ok(done.pop().expect("root built"))
    }

    /// Reads a node object's type and lists its children (not yet built).
    fn frame(&self, index: u32, segment: String, parents: &[Frame<'a>]) -> R<Frame<'a>> {
        let p = || path(parents, &segment);
        let Value::Object(entries) = &self.doc.values[index as usize] else {
            let t = self.doc.values[index as usize].type_name();
            return Err(self.located(index, &p(), format!("expected a node object, found {t}")));
        };
        let ty = self.node_type(index, entries, &p)?;
        let children = match ty {
            "union"
            | "intersection"
            | "difference"
            | "smooth_union"
            | "smooth_intersection"
            | "smooth_difference" => {
                let list = self.required(index, entries, "children", &p)?;
                let Value::Array(items) = &self.doc.values[list as usize] else {
                    return Err(self.located(
                        list,
                        &format!("{}.children", p()),
                        "expected an array of nodes",
                    ));
                };
                items
                    .iter()
                    .enumerate()
                    .map(|(i, &c)| (format!("children[{i}]"), c))
                    .collect()
            }
            "translate" | "rotate" | "scale" | "mirror" | "affine" | "offset" | "shell"
            | "subdivide" | "dual" | "swept_volume" | "color" => {
                vec![(
                    "child".to_string(),
                    self.required(index, entries, "child", &p)?,
                )]
            }
            _ => Vec::new(),
        };
        Ok(Frame {
            index,
            segment,
            entries,
            children,
            next: 0,
        })
    }

    fn node_type(
        &self,
        index: u32,
        entries: &'a [(String, u32)],
        path: &dyn Fn() -> String,
    ) -> R<&'a str> {
        let t = self.required(index, entries, "type", path)?;
        match &self.doc.values[t as usize] {
            Value::String(s) => Ok(s.as_str()),
            v => Err(self.located(
                t,
                &format!("{}.type", path()),
                format!("expected a string, found {}", v.type_name()),
            )),
        }
    }

    /// The value of `key`; `path` is only called to report a missing key.
    fn required(
        &self,
        index: u32,
        entries: &[(String, u32)],
        key: &str,
        path: &dyn Fn() -> String,
    ) -> R<u32> {
        find(entries, key)
            .ok_or_else(|| self.located(index, &path(), format!("missing key \"{key}\"")))
    }

    /// Makes the node from its parameters and built children, validating the parameters.
    fn node(&self, f: &Frame<'a>, parents: &[Frame<'a>], children: Vec<Solid>) -> R<Solid> {
        let params = Params {
            reader: self,
            entries: f.entries,
            index: f.index,
            parents,
            segment: &f.segment,
        };
        let ty = match &self.doc.values[find(f.entries, "type").unwrap_or(f.index) as usize] {
            Value::String(t) => t.as_str(),
            _ => return Err(self.located(f.index, &params.path(), "expected a string type")),
        };
        if ty == "subdivide" {
            return params.subdivide(children);
        }
        if ty == "dual" {
            return params.dual(children);
        }
        if ty == "swept_volume" {
            return params.swept_volume(children);
        }
        let (kind, allowed): (NodeKind, &[&str]) = match ty {
            "union" => (NodeKind::Union, &["children"]),
            "intersection" => (NodeKind::Intersection, &["children"]),
            "difference" => {
                if children.is_empty() {
                    return Err(self.located(
                        f.index,
                        &params.path(),
                        "difference needs at least one child",
                    ));
                }
                (NodeKind::Difference, &["children"])
            }
            "smooth_union" | "smooth_intersection" | "smooth_difference" => {
                let radius = params.positive("radius")?;
                if ty == "smooth_difference" && children.is_empty() {
                    return Err(self.located(
                        f.index,
                        &params.path(),
                        "smooth_difference needs at least one child",
                    ));
                }
                let kind = match ty {
                    "smooth_union" => NodeKind::SmoothUnion { radius },
                    "smooth_intersection" => NodeKind::SmoothIntersection { radius },
                    _ => NodeKind::SmoothDifference { radius },
                };
                (kind, &["radius", "children"])
            }
            "offset" => (
                NodeKind::Offset {
                    distance: params.number("distance")?,
                },
                &["distance", "child"],
            ),
            "shell" => (
                NodeKind::Shell {
                    thickness: params.positive("thickness")?,
                },
                &["thickness", "child"],
            ),
            "color" => (NodeKind::Color(params.color("color")?), &["color", "child"]),
            "translate" => (
                params.transform(TransformSpec::Translate(params.vec3("offset")?))?,
                &["offset", "child"],
            ),
            "rotate" => {
                let spec = TransformSpec::Rotate {
                    axis: params.vec3("axis")?,
                    degrees: params.number("degrees")?,
                };
                (params.transform(spec)?, &["axis", "degrees", "child"])
            }
            "scale" => (
                params.transform(TransformSpec::Scale(params.vec3_or_scalar("factor")?))?,
                &["factor", "child"],
            ),
            "mirror" => (
                params.transform(TransformSpec::Mirror(params.vec3("normal")?))?,
                &["normal", "child"],
            ),
            "affine" => (
                params.transform(TransformSpec::Affine(params.matrix("matrix")?))?,
                &["matrix", "child"],
            ),
            _ => {
                let (prim, allowed) = params.primitive(ty)?;
                (NodeKind::Primitive(prim), allowed)
            }
        };
        params.reject_unknown(allowed)?;
        Ok(Solid::from_parts(kind, children))
    }
}

fn find(entries: &[(String, u32)], key: &str) -> Option<u32> {
    entries.iter().find(|(k, _)| k == key).map(|(_, v)| *v)
}

/// The JSON path of a node: its ancestors' segments then its own.
fn path(parents: &[Frame<'_>], segment: &str) -> String {
    let mut parts: Vec<String> = parents.iter().skip(1).map(|f| f.segment.clone()).collect();
    if !parents.is_empty() {
        parts.push(segment.to_string());
    }
    solid::shorten_path_pub(&parts)
}

/// Typed access to one node's parameters, with located errors.
struct Params<'r, 'a> {
    reader: &'r Reader<'a>,
    entries: &'a [(String, u32)],
    index: u32,
    parents: &'r [Frame<'a>],
    segment: &'r str,
}

impl Params<'_, '_> {
    /// The node's JSON path, built only when an error needs it (deep trees stay linear).
    fn path(&self) -> String {
        path(self.parents, self.segment)
    }

    fn at(&self, key: &str) -> R<u32> {
        find(self.entries, key).ok_or_else(|| {
            self.reader
                .located(self.index, &self.path(), format!("missing key \"{key}\""))
        })
    }

    fn fail(&self, index: u32, key: &str, message: impl std::fmt::Display) -> Located {
        let path = self.path();
        let p = if path == "root" {
            key.to_string()
        } else {
            format!("{path}.{key}")
        };
        self.reader.located(index, &p, message)
    }

    fn number_at(&self, index: u32, key: &str) -> R<f64> {
        match self.reader.doc.values[index as usize] {
            Value::Number(x) => Ok(x),
            ref v => Err(self.fail(
                index,
                key,
                format!("expected a number, found {}", v.type_name()),
            )),
        }
    }

    /// A number that must be positive (a located error otherwise).
    fn positive(&self, key: &str) -> R<f64> {
        let at = self.at(key)?;
        let x = self.number_at(at, key)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(self.fail(at, key, "expected a positive number"))
        }
    }

    fn number(&self, key: &str) -> R<f64> {
        self.number_at(self.at(key)?, key)
    }

    fn numbers<const N: usize>(&self, index: u32, key: &str) -> R<[f64; N]> {
        let Value::Array(items) = &self.reader.doc.values[index as usize] else {
            return Err(self.fail(index, key, format!("expected an array of {N} numbers")));
        };
        if items.len() != N {
            return Err(self.fail(
                index,
                key,
                format!("expected {N} numbers, found {}", items.len()),
            ));
        }
        let mut out = [0.0; N];
        for (o, &i) in out.iter_mut().zip(items) {
            *o = self.number_at(i, key)?;
        }
        Ok(out)
    }

    /// A colour: `[r, g, b]` or `[r, g, b, a]` in `0..=1`, a CSS/SVG name or `#rrggbb[aa]`.
    fn color(&self, key: &str) -> R<crate::color::Rgba> {
        let at = self.at(key)?;
        let expected = "expected [r, g, b], [r, g, b, a] (0 to 1), a colour name or \"#rrggbb\"";
        let c = match &self.reader.doc.values[at as usize] {
            Value::String(s) => crate::color::Rgba::parse(s)
                .ok_or_else(|| self.fail(at, key, format!("unknown colour {s:?}")))?,
            Value::Array(items) if items.len() == 3 => {
                let [r, g, b] = self.numbers::<3>(at, key)?.map(|x| x as f32);
                crate::color::Rgba([r, g, b, 1.0])
            }
            Value::Array(items) if items.len() == 4 => {
                crate::color::Rgba(self.numbers::<4>(at, key)?.map(|x| x as f32))
            }
            _ => return Err(self.fail(at, key, expected)),
        };
        match c.problem() {
            Some(_) => Err(self.fail(at, key, "expected channels between 0 and 1")),
            None => Ok(c),
        }
    }

    fn vec3(&self, key: &str) -> R<DVec3> {
        Ok(DVec3::from_array(self.numbers::<3>(self.at(key)?, key)?))
    }

    fn vec3_or_scalar(&self, key: &str) -> R<DVec3> {
        let i = self.at(key)?;
        match self.reader.doc.values[i as usize] {
            Value::Number(x) => Ok(DVec3::splat(x)),
            _ => Ok(DVec3::from_array(self.numbers::<3>(i, key)?)),
        }
    }

    fn matrix(&self, key: &str) -> R<[[f64; 4]; 3]> {
        let i = self.at(key)?;
        let Value::Array(rows) = &self.reader.doc.values[i as usize] else {
            return Err(self.fail(i, key, "expected 3 rows of 4 numbers"));
        };
        if rows.len() != 3 {
            return Err(self.fail(
                i,
                key,
                format!("expected 3 rows of 4 numbers, found {} rows", rows.len()),
            ));
        }
        Ok([
            self.numbers::<4>(rows[0], key)?,
            self.numbers::<4>(rows[1], key)?,
            self.numbers::<4>(rows[2], key)?,
        ])
    }

    fn transform(&self, spec: TransformSpec) -> R<NodeKind> {
        let key = match spec {
            TransformSpec::Translate(_) => "offset",
            TransformSpec::Rotate { .. } => "axis",
            TransformSpec::Scale(_) => "factor",
            TransformSpec::Mirror(_) => "normal",
            TransformSpec::Affine(_) => "matrix",
        };
        Transform::new(spec)
            .map(|t| NodeKind::Transform(Box::new(t)))
            .map_err(|e| self.fail(self.at(key).unwrap_or(self.index), key, e))
    }

    fn primitive(&self, ty: &str) -> R<(Primitive, &'static [&'static str])> {
        let (prim, allowed): (Primitive, &'static [&'static str]) = match ty {
            "sphere" => (
                Primitive::Sphere(Sphere {
                    radius: self.number("radius")?,
                }),
                &["radius"],
            ),
            "box" => (
                Primitive::Cuboid(Cuboid {
                    size: self.vec3_or_scalar("size")?,
                }),
                &["size"],
            ),
            "cylinder" => (
                Primitive::Cylinder(Cylinder {
                    radius: self.number("radius")?,
                    height: self.number("height")?,
                }),
                &["radius", "height"],
            ),
            "cone" => (
                Primitive::Cone(Cone {
                    bottom_radius: self.number("bottom_radius")?,
                    top_radius: self.number("top_radius")?,
                    height: self.number("height")?,
                }),
                &["bottom_radius", "top_radius", "height"],
            ),
            "torus" => (
                Primitive::Torus(Torus {
                    major_radius: self.number("major_radius")?,
                    minor_radius: self.number("minor_radius")?,
                }),
                &["major_radius", "minor_radius"],
            ),
            "plane" => (
                Primitive::HalfSpace(HalfSpace {
                    normal: self.vec3("normal")?,
                    offset: self.number("offset")?,
                }),
                &["normal", "offset"],
            ),
            "gyroid" => (
                Primitive::Gyroid(crate::primitive::Gyroid {
                    thickness: self.number("thickness")?,
                }),
                &["thickness"],
            ),
            "ellipsoid"
            | "quadric"
            | "elliptic_cylinder"
            | "elliptic_cone"
            | "elliptic_paraboloid"
            | "hyperbolic_paraboloid"
            | "hyperboloid_one_sheet"
            | "hyperboloid_two_sheets" => self.quadric_family(ty)?,
            "blob" => self.blob()?,
            "heightfield" => self.heightfield()?,
            "extrude" | "revolve" | "sweep" | "loft" | "ruled" | "ruled_surface" => {
                self.sweep_family(ty)?
            }
            "platonic" => self.platonic()?,
            "polyhedron" => self.polyhedron()?,
            "mesh" => self.mesh_file()?,
            "prism" => self.prism()?,
            "expr" => self.expr()?,
            "bezier_patch"
            | "interpolating_patch"
            | "bspline_surface"
            | "nurbs_surface"
            | "param_surface"
            | "bezier_triangle"
            | "pn_triangles" => self.surface(ty)?,
            other => {
                let t = self.at("type")?;
                return Err(self.fail(t, "type", format!("unknown node type \"{other}\"")));
            }
        };
        if let Err(e) = prim.validate() {
            let at = self.at(e.parameter).unwrap_or(self.index);
            return Err(self.fail(at, e.parameter, e.problem));
        }
        Ok((prim, allowed))
    }

    fn reject_unknown(&self, allowed: &[&str]) -> R<()> {
        for (k, i) in self.entries {
            if k != "type" && k != "comment" && !allowed.contains(&k.as_str()) {
                return Err(self.fail(
                    *i,
                    k,
                    format!(
                        "unknown key \"{k}\" (expected one of: {})",
                        allowed.join(", ")
                    ),
                ));
            }
        }
        Ok(())
    }
}
