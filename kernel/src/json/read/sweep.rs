//! Reading the sweep family: `extrude` (profile, height, optional twist in degrees and scale),
//! `revolve` (profile, optional angle in degrees, default 360; optional `segments`, a full turn
//! in that many straight steps, the first at `start` degrees, default 0), `sweep` (profile, path), `loft`
//! (bottom and top profiles, height), `ruled` (bottom and top curves) and `ruled_surface` (first
//! and second curves, optional thickness and samples).
//!
//! Profiles are objects: `{"type": "circle", "radius": r, "center": [x, y]}`,
//! `{"type": "rectangle", "size": [w, h] or s, "center": [x, y]}` (centres optional, default the
//! origin), `{"type": "polygon", "points": [[x, y], …], "holes": [[[x, y], …], …]}` (holes
//! optional; inside by the even-odd rule), and `curve` / `radial` profiles (read in
//! `curve_profile.rs`). Curves are read in `curve.rs`.

use super::super::document::Value;
use super::{Params, R};
use crate::curve::{Curve, Parametric};
use crate::primitive::sweep::SweepError;
use crate::primitive::{Extrude, Loft, Primitive, Revolve, Ruled, RuledSurface, Sweep};
use crate::profile::{Circle, Profile, ProfileError, Rectangle};
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// A nested object: its arena index, its entries and its key path from the node (`profile`,
/// `path`, …).
pub(super) struct Nested<'e> {
    pub(super) index: u32,
    pub(super) entries: &'e [(String, u32)],
    pub(super) key: String,
}

impl Params<'_, '_> {
    /// The primitive of a sweep-family node type.
    pub(super) fn sweep_family(&self, ty: &str) -> R<(Primitive, &'static [&'static str])> {
        let located = |e: SweepError| self.sweep_error(e);
        Ok(match ty {
            "extrude" => {
                let profile = self.sweep_profile("profile")?;
                let twist = self.sweep_optional("twist", 0.0)?;
                let scale = match super::find(self.entries, "scale") {
                    None => DVec2::ONE,
                    Some(i) => match self.reader.doc.values[i as usize] {
                        Value::Number(s) => DVec2::splat(s),
                        _ => self.sweep_point2(i, "scale")?,
                    },
                };
                let e = Extrude::with_scale(profile, self.number("height")?, twist, scale)
                    .map_err(located)?;
                (
                    Primitive::Extrude(Arc::new(e)),
                    &["profile", "height", "twist", "scale"],
                )
            }
            "revolve" => {
                let profile = self.sweep_profile("profile")?;
                let angle = self.sweep_optional("angle", 360.0)?;
                let r = match super::find(self.entries, "segments") {
                    None => Revolve::new(profile, angle),
                    Some(i) => {
                        let n = self.number_at(i, "segments")?;
                        if angle != 360.0 {
                            return Err(self.sweep_error(SweepError::Invalid {
                                parameter: "segments",
                                problem: "a faceted revolution is a full turn (angle 360)",
                            }));
                        }
                        if n.fract() != 0.0 || !(3.0..=65536.0).contains(&n) {
                            return Err(self.sweep_error(SweepError::Invalid {
                                parameter: "segments",
                                problem: "expected a whole number of steps from 3 to 65536",
                            }));
                        }
                        let start = self.sweep_optional("start", 0.0)?;
                        Revolve::faceted(profile, n as u32, start)
                    }
                }
                .map_err(located)?;
                (
                    Primitive::Revolve(Arc::new(r)),
                    &["profile", "angle", "segments", "start"],
                )
            }
            "sweep" => {
                let s = Sweep::new(self.sweep_profile("profile")?, self.sweep_curve("path")?)
                    .map_err(located)?;
                (Primitive::Sweep(Arc::new(s)), &["profile", "path"])
            }
            "loft" => {
                let l = Loft::new(
                    self.sweep_profile("bottom")?,
                    self.sweep_profile("top")?,
                    self.number("height")?,
                )
                .map_err(located)?;
                (Primitive::Loft(Arc::new(l)), &["bottom", "top", "height"])
            }
            "ruled_surface" => {
                let thickness = match super::find(self.entries, "thickness") {
                    Some(i) => Some(self.number_at(i, "thickness")?),
                    None => None,
                };
                let samples = match super::find(self.entries, "samples") {
                    Some(i) => {
                        let x = self.number_at(i, "samples")?;
                        if !(x.fract() == 0.0 && (3.0..=4096.0).contains(&x)) {
                            return Err(self.fail(
                                i,
                                "samples",
                                format!("expected a whole number from 3 to 4096, found {x}"),
                            ));
                        }
                        Some(x as usize)
                    }
                    None => None,
                };
                let r = RuledSurface::new(
                    self.sweep_curve("first")?,
                    self.sweep_curve("second")?,
                    thickness,
                    samples,
                )
                .map_err(located)?;
                (
                    Primitive::RuledSurface(Arc::new(r)),
                    &["first", "second", "thickness", "samples"],
                )
            }
            _ => {
                let r = Ruled::new(self.sweep_curve("bottom")?, self.sweep_curve("top")?)
                    .map_err(located)?;
                (Primitive::Ruled(Arc::new(r)), &["bottom", "top"])
            }
        })
    }

    /// A located error for a sweep error, at the nested value it names when there is one.
    fn sweep_error(&self, e: SweepError) -> super::Located {
        let key = e.parameter();
        let outer = self.at(key).unwrap_or(self.index);
        let inner = |name: &str| match &self.reader.doc.values[outer as usize] {
            Value::Object(entries) => super::find(entries, name).unwrap_or(outer),
            _ => outer,
        };
        let (at, message) = match &e {
            SweepError::Profile { error, .. } => (inner(error.parameter()), error.to_string()),
            SweepError::Curve { error, .. } => (inner(error.parameter()), error.to_string()),
            SweepError::Invalid { problem, .. } => (outer, problem.to_string()),
        };
        self.fail(at, key, message)
    }

    /// A number that may be absent (then `default`).
    fn sweep_optional(&self, key: &str, default: f64) -> R<f64> {
        match super::find(self.entries, key) {
            Some(i) => self.number_at(i, key),
            None => Ok(default),
        }
    }

    /// The object under the node's `key`.
    pub(super) fn sweep_nested(&self, key: &str) -> R<Nested<'_>> {
        let index = self.at(key)?;
        match &self.reader.doc.values[index as usize] {
            Value::Object(entries) => Ok(Nested {
                index,
                entries,
                key: key.to_string(),
            }),
            v => Err(self.fail(
                index,
                key,
                format!("expected an object, found {}", v.type_name()),
            )),
        }
    }

    /// The `type` string of a nested object.
    pub(super) fn sweep_nested_type(&self, n: &Nested<'_>) -> R<&str> {
        let t = self.sweep_member(n, "type")?;
        match &self.reader.doc.values[t as usize] {
            Value::String(s) => Ok(s.as_str()),
            v => Err(self.fail(
                t,
                &format!("{}.type", n.key),
                format!("expected a string, found {}", v.type_name()),
            )),
        }
    }

    /// The index of a required member of a nested object.
    pub(super) fn sweep_member(&self, n: &Nested<'_>, key: &str) -> R<u32> {
        super::find(n.entries, key)
            .ok_or_else(|| self.fail(n.index, &n.key, format!("missing key \"{key}\"")))
    }

    /// Rejects members of a nested object outside `allowed` (besides `type` and `comment`).
    pub(super) fn sweep_nested_keys(&self, n: &Nested<'_>, allowed: &[&str]) -> R<()> {
        for (k, i) in n.entries {
            if k != "type" && k != "comment" && !allowed.contains(&k.as_str()) {
                return Err(self.fail(
                    *i,
                    &format!("{}.{k}", n.key),
                    format!(
                        "unknown key \"{k}\" (expected one of: {})",
                        allowed.join(", ")
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The items of an array.
    pub(super) fn sweep_items(&self, index: u32, key: &str) -> R<&[u32]> {
        match &self.reader.doc.values[index as usize] {
            Value::Array(items) => Ok(items),
            v => Err(self.fail(
                index,
                key,
                format!("expected an array, found {}", v.type_name()),
            )),
        }
    }

    /// A point `[x, y]`.
    pub(super) fn sweep_point2(&self, index: u32, key: &str) -> R<DVec2> {
        Ok(DVec2::from_array(self.numbers::<2>(index, key)?))
    }

    /// A point `[x, y, z]`, or `[x, y]` with z = 0.
    pub(super) fn sweep_point3(&self, index: u32, key: &str) -> R<DVec3> {
        let n = self.sweep_items(index, key)?.len();
        if n == 2 {
            Ok(self.sweep_point2(index, key)?.extend(0.0))
        } else {
            Ok(DVec3::from_array(self.numbers::<3>(index, key)?))
        }
    }

    /// An array of 2D points.
    pub(super) fn sweep_points2(&self, index: u32, key: &str) -> R<Vec<DVec2>> {
        let items = self.sweep_items(index, key)?;
        items
            .iter()
            .enumerate()
            .map(|(k, &i)| self.sweep_point2(i, &format!("{key}[{k}]")))
            .collect()
    }

    /// An array of 3D points.
    pub(super) fn sweep_points3(&self, index: u32, key: &str) -> R<Vec<DVec3>> {
        let items = self.sweep_items(index, key)?;
        items
            .iter()
            .enumerate()
            .map(|(k, &i)| self.sweep_point3(i, &format!("{key}[{k}]")))
            .collect()
    }

    /// An array of numbers.
    pub(super) fn sweep_numbers(&self, index: u32, key: &str) -> R<Vec<f64>> {
        let items = self.sweep_items(index, key)?;
        items
            .iter()
            .enumerate()
            .map(|(k, &i)| self.number_at(i, &format!("{key}[{k}]")))
            .collect()
    }

    /// The profile object under `key`.
    fn sweep_profile(&self, key: &str) -> R<Profile> {
        let n = self.sweep_nested(key)?;
        let ty = self.sweep_nested_type(&n)?;
        let k = |m: &str| format!("{key}.{m}");
        let center = |n: &Nested<'_>| -> R<DVec2> {
            match super::find(n.entries, "center") {
                Some(i) => self.sweep_point2(i, &k("center")),
                None => Ok(DVec2::ZERO),
            }
        };
        let profile = match ty {
            "circle" => {
                self.sweep_nested_keys(&n, &["radius", "center"])?;
                let radius = self.number_at(self.sweep_member(&n, "radius")?, &k("radius"))?;
                Profile::Circle(Circle {
                    center: center(&n)?,
                    radius,
                })
            }
            "rectangle" => {
                self.sweep_nested_keys(&n, &["size", "center"])?;
                let i = self.sweep_member(&n, "size")?;
                let size = match self.reader.doc.values[i as usize] {
                    Value::Number(s) => DVec2::splat(s),
                    _ => self.sweep_point2(i, &k("size"))?,
                };
                Profile::Rectangle(Rectangle {
                    center: center(&n)?,
                    size,
                })
            }
            "polygon" => {
                self.sweep_nested_keys(&n, &["points", "holes"])?;
                let points = self.sweep_points2(self.sweep_member(&n, "points")?, &k("points"))?;
                let holes = match super::find(n.entries, "holes") {
                    Some(i) => self
                        .sweep_items(i, &k("holes"))?
                        .iter()
                        .enumerate()
                        .map(|(h, &j)| self.sweep_points2(j, &k(&format!("holes[{h}]"))))
                        .collect::<R<Vec<_>>>()?,
                    None => Vec::new(),
                };
                return Profile::polygon(points, holes)
                    .map_err(|e| self.sweep_profile_error(&n, e));
            }
            "curve" | "radial" => return self.curve_profile(&n, ty),
            other => {
                let t = self.sweep_member(&n, "type")?;
                return Err(self.fail(
                    t,
                    &k("type"),
                    format!(
                        "unknown profile type \"{other}\" (expected circle, rectangle, polygon, \
                         curve or radial)"
                    ),
                ));
            }
        };
        profile
            .checked()
            .map_err(|e| self.sweep_profile_error(&n, e))
    }

    pub(super) fn sweep_profile_error(&self, n: &Nested<'_>, e: ProfileError) -> super::Located {
        let p = e.parameter();
        let at = super::find(n.entries, p).unwrap_or(n.index);
        self.fail(at, &n.key, e)
    }

    /// The curve object under `key` (any kind with control points; formula curves have none and
    /// cannot be sweep paths or rails).
    fn sweep_curve(&self, key: &str) -> R<Curve> {
        let n = self.sweep_nested(key)?;
        match self.curve_object(&n)? {
            Parametric::Curve(c) => Ok(c),
            Parametric::Formula(_) => {
                let t = self.sweep_member(&n, "type")?;
                Err(self.fail(
                    t,
                    &format!("{key}.type"),
                    "a formula curve has no control points: it cannot be a sweep path or a \
                     ruled-surface rail (use it as a profile, or a bezier/bspline/nurbs curve)",
                ))
            }
        }
    }
}
