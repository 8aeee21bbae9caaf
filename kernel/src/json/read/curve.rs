//! Reading curve objects: `bezier` (points, any degree), `hermite` (points and tangents, one per
//! point: a C¹ chain of cubic segments), `bspline` (degree, points, knots), `nurbs` (degree,
//! points, weights, knots), `interpolating` (the natural C² spline: points, closed),
//! `cubic_through` (the cubic through 4 points at u = 0, 1/3, 2/3, 1), `composite` (pieces: curve
//! objects of the kinds above; continuity: "C0", "G1" or "C1", one for all joints or a list with
//! one per joint; checked) and `formula` (x, y, z: formulas in u; domain: [u0, u1]). Points are
//! `[x, y, z]` or `[x, y]` (z = 0). Composite pieces are read in a loop (no recursion; a composite
//! piece inside a composite is an error).

use super::super::document::{Document, Value, parse};
use super::sweep::Nested;
use super::{Params, R, Reader};
use crate::KernelError;
use crate::curve::{
    BSpline, Bezier, Composite, Continuity, CubicThrough, Curve, CurveError, FormulaCurve, Hermite,
    Interpolating, Nurbs, Parametric,
};
use crate::primitive::NoMeshResolver;
use glam::DVec3;

/// Most control points of a Bézier curve and highest spline degree: every control point of a
/// Bézier curve counts at every parameter, so evaluation costs grow with the square of the
/// degree (a 256-point curve flattens in about a second; longer curves belong in composite pieces
/// or B-splines, whose cost depends on their degree only).
const MAX_DEGREE: usize = 255;

/// The curve kinds, for error messages.
const KINDS: &str =
    "bezier, hermite, bspline, nurbs, interpolating, cubic_through, composite or formula";

/// Reads a curve file: one curve object at the top (see [`crate::json`]'s curve kinds). Errors
/// carry the line, column and JSON path.
pub fn curve_from_str(text: &str) -> Result<Parametric, KernelError> {
    let doc: Document = parse(text).map_err(|e| super::to_error(text, e.offset, e.message))?;
    let reader = Reader {
        doc: &doc,
        resolver: &NoMeshResolver,
    };
    let Value::Object(entries) = &doc.values[0] else {
        return Err(super::to_error(
            text,
            0,
            "root: expected a curve object such as {\"type\": \"bezier\", \"points\": [...]}"
                .into(),
        ));
    };
    let params = Params {
        reader: &reader,
        entries,
        index: 0,
        parents: &[],
        segment: "root",
    };
    let nested = Nested {
        index: 0,
        entries,
        key: String::new(),
    };
    params
        .curve_object(&nested)
        .map_err(|e| super::to_error(text, e.offset, e.message))
}

/// `key.member`, or `member` at the top of a curve file.
fn sub(key: &str, member: &str) -> String {
    if key.is_empty() {
        member.to_string()
    } else {
        format!("{key}.{member}")
    }
}

impl Params<'_, '_> {
    /// A located error for a curve error, at the member it names when there is one.
    fn curve_error(&self, n: &Nested<'_>, e: CurveError) -> super::Located {
        let at = super::find(n.entries, e.parameter()).unwrap_or(n.index);
        // The error's text starts with the key it is about: prefix the object's path.
        super::Located {
            offset: self.reader.offset(at),
            message: if n.key.is_empty() {
                e.to_string()
            } else {
                format!("{}.{e}", n.key)
            },
        }
    }

    /// The curve described by the object `n`.
    pub(super) fn curve_object(&self, n: &Nested<'_>) -> R<Parametric> {
        let ty = self.sweep_nested_type(n)?;
        match ty {
            "composite" => self.composite(n).map(Parametric::Curve),
            "formula" => {
                self.sweep_nested_keys(n, &["x", "y", "z", "domain"])?;
                let text = |m: &str, default: Option<&'static str>| -> R<String> {
                    match (super::find(n.entries, m), default) {
                        (None, Some(d)) => Ok(d.to_string()),
                        (None, None) => Err(self.missing(n, m)),
                        (Some(i), _) => match &self.reader.doc.values[i as usize] {
                            Value::String(s) => Ok(s.clone()),
                            Value::Number(x) => Ok(format!("{x:?}")),
                            v => Err(self.reader.located(
                                i,
                                &sub(&n.key, m),
                                format!("expected a formula string in u, found {}", v.type_name()),
                            )),
                        },
                    }
                };
                let (x, y, z) = (text("x", None)?, text("y", None)?, text("z", Some("0"))?);
                let d = self.curve_member(n, "domain")?;
                let [u0, u1] = self.numbers::<2>(d, &sub(&n.key, "domain"))?;
                FormulaCurve::new([&x, &y, &z], (u0, u1))
                    .map(Parametric::Formula)
                    .map_err(|e| self.curve_error(n, e))
            }
            _ => self.simple_curve(n, ty).map(Parametric::Curve),
        }
    }

    fn missing(&self, n: &Nested<'_>, key: &str) -> super::Located {
        let label = if n.key.is_empty() { "curve" } else { &n.key };
        self.reader
            .located(n.index, label, format!("missing key \"{key}\""))
    }

    fn curve_member(&self, n: &Nested<'_>, key: &str) -> R<u32> {
        super::find(n.entries, key).ok_or_else(|| self.missing(n, key))
    }

    /// `pieces` and `continuity` of a composite curve.
    fn composite(&self, n: &Nested<'_>) -> R<Curve> {
        self.sweep_nested_keys(n, &["pieces", "continuity"])?;
        let list_key = sub(&n.key, "pieces");
        let list = self.curve_member(n, "pieces")?;
        let items = self.sweep_items(list, &list_key)?;
        let mut parts = Vec::with_capacity(items.len());
        for (k, &item) in items.iter().enumerate() {
            let key = format!("{list_key}[{k}]");
            let Value::Object(entries) = &self.reader.doc.values[item as usize] else {
                let t = self.reader.doc.values[item as usize].type_name();
                return Err(self.reader.located(
                    item,
                    &key,
                    format!("expected a curve object, found {t}"),
                ));
            };
            let piece = Nested {
                index: item,
                entries,
                key,
            };
            let ty = self.sweep_nested_type(&piece)?;
            if ty == "composite" || ty == "formula" {
                let t = self.curve_member(&piece, "type")?;
                return Err(self.reader.located(
                    t,
                    &sub(&piece.key, "type"),
                    format!("a composite piece cannot be a {ty} curve"),
                ));
            }
            parts.push(self.simple_curve(&piece, ty)?);
        }
        let joints = parts.len().saturating_sub(1);
        let ckey = sub(&n.key, "continuity");
        let joins = match super::find(n.entries, "continuity") {
            None => vec![Continuity::C0; joints],
            Some(i) => {
                let one = |j: u32, key: &str| -> R<Continuity> {
                    match &self.reader.doc.values[j as usize] {
                        Value::String(s) => Continuity::parse(s).ok_or_else(|| {
                            self.reader.located(
                                j,
                                key,
                                format!("unknown continuity \"{s}\" (expected C0, G1 or C1)"),
                            )
                        }),
                        v => Err(self.reader.located(
                            j,
                            key,
                            format!("expected \"C0\", \"G1\" or \"C1\", found {}", v.type_name()),
                        )),
                    }
                };
                match &self.reader.doc.values[i as usize] {
                    Value::Array(list) => list
                        .iter()
                        .enumerate()
                        .map(|(k, &j)| one(j, &format!("{ckey}[{k}]")))
                        .collect::<R<Vec<_>>>()?,
                    _ => vec![one(i, &ckey)?; joints],
                }
            }
        };
        Composite::new(parts, joins)
            .map(Curve::Composite)
            .map_err(|e| match &e {
                CurveError::Join { index, problem } if *index > 0 && *index < items.len() => self
                    .reader
                    .located(items[*index], &format!("{list_key}[{index}]"), problem),
                _ => self.curve_error(n, e),
            })
    }

    /// A curve of any kind but composite and formula.
    fn simple_curve(&self, n: &Nested<'_>, ty: &str) -> R<Curve> {
        let k = |m: &str| sub(&n.key, m);
        let points = |name: &str| -> R<Vec<DVec3>> {
            self.sweep_points3(self.curve_member(n, name)?, &k(name))
        };
        let optional_list = |name: &str| -> R<Option<Vec<f64>>> {
            match super::find(n.entries, name) {
                Some(i) => Ok(Some(self.sweep_numbers(i, &k(name))?)),
                None => Ok(None),
            }
        };
        let degree = || -> R<usize> {
            let i = self.curve_member(n, "degree")?;
            let d = self.number_at(i, &k("degree"))?;
            if d >= 0.0 && d.fract() == 0.0 && d <= MAX_DEGREE as f64 {
                Ok(d as usize)
            } else {
                Err(self.reader.located(
                    i,
                    &k("degree"),
                    format!("expected a whole number of at most {MAX_DEGREE}"),
                ))
            }
        };
        let curve = match ty {
            "bezier" => {
                self.sweep_nested_keys(n, &["points"])?;
                let p = points("points")?;
                if p.len() > MAX_DEGREE + 1 {
                    return Err(self.reader.located(
                        self.curve_member(n, "points")?,
                        &k("points"),
                        format!(
                            "{} control points: at most {} (degree {MAX_DEGREE}; every point \
                             counts at every parameter: use composite pieces or a bspline)",
                            p.len(),
                            MAX_DEGREE + 1
                        ),
                    ));
                }
                Bezier::new(p).map(Curve::Bezier)
            }
            "hermite" => {
                self.sweep_nested_keys(n, &["points", "tangents"])?;
                Hermite::through(points("points")?, points("tangents")?).map(Curve::Hermite)
            }
            "cubic_through" => {
                self.sweep_nested_keys(n, &["points"])?;
                CubicThrough::new(&points("points")?).map(Curve::CubicThrough)
            }
            "bspline" => {
                self.sweep_nested_keys(n, &["degree", "points", "knots"])?;
                let (d, p) = (degree()?, points("points")?);
                match optional_list("knots")? {
                    Some(knots) => BSpline::new(d, p, knots),
                    None => BSpline::clamped(d, p),
                }
                .map(Curve::BSpline)
            }
            "nurbs" => {
                self.sweep_nested_keys(n, &["degree", "points", "weights", "knots"])?;
                let (d, p) = (degree()?, points("points")?);
                let w = optional_list("weights")?.unwrap_or_else(|| vec![1.0; p.len()]);
                match optional_list("knots")? {
                    Some(knots) => Nurbs::new(d, p, w, knots),
                    None => Nurbs::clamped(d, p, w),
                }
                .map(Curve::Nurbs)
            }
            "interpolating" => {
                self.sweep_nested_keys(n, &["points", "closed"])?;
                let closed = match super::find(n.entries, "closed") {
                    Some(i) => match self.reader.doc.values[i as usize] {
                        Value::Bool(b) => b,
                        ref v => {
                            return Err(self.reader.located(
                                i,
                                &k("closed"),
                                format!("expected a boolean, found {}", v.type_name()),
                            ));
                        }
                    },
                    None => false,
                };
                Interpolating::new(points("points")?, closed).map(Curve::Interpolating)
            }
            other => {
                let t = self.curve_member(n, "type")?;
                return Err(self.reader.located(
                    t,
                    &k("type"),
                    format!("unknown curve type \"{other}\" (expected {KINDS})"),
                ));
            }
        };
        curve.map_err(|e| self.curve_error(n, e))
    }
}
