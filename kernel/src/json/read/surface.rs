//! Reading the parametric surface node types (`bezier_patch`, `interpolating_patch`, `bspline_surface`, `nurbs_surface`,
//! `param_surface`, `bezier_triangle`, `pn_triangles`) and their closure keys (`thickness` with
//! `side`, or `base`; neither for a closed surface), `tolerance`, `segments` and `tessellation`. See
//! [`crate::surface`] for what they mean; errors name the key they are about.

use super::{Params, R, Value, find};
use crate::patch::TriangleBezier;
use crate::primitive::Primitive;
use crate::surface::{
    Closure, FormulaSurface, InterpolatingPatch, PnSource, Side, SurfaceError, SurfaceKind,
    SurfaceSpec, TensorSurface, clamped_knots,
};
use glam::DVec3;

/// The keys of each surface node: its own, then the closure keys every one has.
const PATCH: [&str; 7] = [
    "tessellation",
    "points",
    "thickness",
    "side",
    "base",
    "tolerance",
    "segments",
];
const SPLINE: [&str; 10] = [
    "tessellation",
    "degree",
    "points",
    "knots_u",
    "knots_v",
    "thickness",
    "side",
    "base",
    "tolerance",
    "segments",
];
const NURBS: [&str; 11] = [
    "tessellation",
    "degree",
    "points",
    "weights",
    "knots_u",
    "knots_v",
    "thickness",
    "side",
    "base",
    "tolerance",
    "segments",
];
const FORMULA: [&str; 11] = [
    "tessellation",
    "x",
    "y",
    "z",
    "u",
    "v",
    "thickness",
    "side",
    "base",
    "tolerance",
    "segments",
];
const TRIANGLE: [&str; 7] = [
    "degree",
    "points",
    "thickness",
    "side",
    "base",
    "tolerance",
    "segments",
];
const PN: [&str; 9] = [
    "path",
    "vertices",
    "normals",
    "triangles",
    "thickness",
    "side",
    "base",
    "tolerance",
    "segments",
];

impl Params<'_, '_> {
    /// The primitive of a surface node of type `ty`.
    pub(super) fn surface(&self, ty: &str) -> R<(Primitive, &'static [&'static str])> {
        let (kind, allowed): (SurfaceKind, &'static [&'static str]) = match ty {
            "bezier_patch" => {
                let (counts, points) = self.point_rows("points")?;
                let s = TensorSurface::bezier(counts, points).map_err(|e| self.surface_error(e))?;
                (SurfaceKind::Bezier(s), &PATCH)
            }
            "interpolating_patch" => {
                let (counts, points) = self.point_rows("points")?;
                if counts != [4, 4] {
                    let at = self.at("points")?;
                    return Err(self.fail(
                        at,
                        "points",
                        format!(
                            "expected 4 rows of 4 points (u, v at 0, 1/3, 2/3, 1), got {} rows of {}",
                            counts[1], counts[0]
                        ),
                    ));
                }
                let p = InterpolatingPatch::new(&points).map_err(|e| self.surface_error(e))?;
                (SurfaceKind::Interpolating(p), &PATCH)
            }
            "bspline_surface" | "nurbs_surface" => {
                let (counts, points) = self.point_rows("points")?;
                let degrees = self.degrees()?;
                let knots = [("knots_u", 0), ("knots_v", 1)].map(|(key, d)| {
                    match find(self.entries, key) {
                        Some(i) => self.number_list(i, key),
                        None => Ok(clamped_knots(degrees[d], counts[d].max(degrees[d] + 1))),
                    }
                });
                let [ku, kv] = knots;
                let (ku, kv) = (ku?, kv?);
                let weights = if ty == "nurbs_surface" {
                    Some(self.weight_rows(counts)?)
                } else {
                    None
                };
                let s = TensorSurface::new(degrees, counts, points, weights, [ku, kv])
                    .map_err(|e| self.surface_error(e))?;
                if ty == "nurbs_surface" {
                    (SurfaceKind::Nurbs(s), &NURBS)
                } else {
                    (SurfaceKind::BSpline(s), &SPLINE)
                }
            }
            "param_surface" => {
                let text = |key: &str| -> R<Option<&str>> {
                    match find(self.entries, key) {
                        Some(_) => Ok(Some(self.string(key)?)),
                        None => Ok(None),
                    }
                };
                let (x, y) = (text("x")?, text("y")?);
                let z = self.string("z")?;
                let u = self.numbers::<2>(self.at("u")?, "u")?;
                let v = self.numbers::<2>(self.at("v")?, "v")?;
                let s = FormulaSurface::new(x, y, z, u, v).map_err(|e| self.surface_error(e))?;
                (SurfaceKind::Formula(s), &FORMULA)
            }
            "bezier_triangle" => {
                let degree = self.count("degree")?;
                let points = self.points3("points")?;
                let t = TriangleBezier::new(degree, points)
                    .map_err(|e| self.fail(self.at("points").unwrap_or(self.index), "points", e))?;
                (SurfaceKind::Triangle(t), &TRIANGLE)
            }
            _ => {
                let source = if find(self.entries, "path").is_some() {
                    PnSource::File {
                        path: self.string("path")?.to_owned(),
                    }
                } else {
                    let vertices = self.points3("vertices")?;
                    let normals = match find(self.entries, "normals") {
                        Some(_) => Some(self.points3("normals")?),
                        None => None,
                    };
                    let mut triangles = Vec::new();
                    for (k, t) in self.index_lists("triangles")?.into_iter().enumerate() {
                        let Ok(t) = <[u32; 3]>::try_from(t) else {
                            let at = self.at("triangles")?;
                            return Err(self.fail(
                                at,
                                &format!("triangles[{k}]"),
                                "expected 3 vertex indices",
                            ));
                        };
                        triangles.push(t);
                    }
                    PnSource::Inline {
                        vertices,
                        normals,
                        triangles,
                    }
                };
                (SurfaceKind::Pn(source), &PN)
            }
        };
        let spec = SurfaceSpec {
            kind,
            closure: self.closure()?,
            tolerance: match find(self.entries, "tolerance") {
                Some(_) => Some(self.positive("tolerance")?),
                None => None,
            },
            segments: match find(self.entries, "segments") {
                Some(_) => Some(self.count("segments")?),
                None => None,
            },
            adaptive: match find(self.entries, "tessellation") {
                None => false,
                Some(_) => match self.string("tessellation")? {
                    "uniform" => false,
                    "adaptive" => true,
                    other => {
                        return Err(self.fail(
                            self.at("tessellation")?,
                            "tessellation",
                            format!("expected \"uniform\" or \"adaptive\", got \"{other}\""),
                        ));
                    }
                },
            },
        };
        let solid = spec
            .solid(self.reader.resolver)
            .map_err(|e| self.surface_error(e))?;
        Ok((Primitive::Mesh(solid), allowed))
    }

    fn surface_error(&self, e: SurfaceError) -> super::Located {
        let key = e.key();
        self.fail(self.at(key).unwrap_or(self.index), key, e)
    }

    /// `thickness` (with the optional `side`), `base`, or neither.
    fn closure(&self) -> R<Closure> {
        let has = |k| find(self.entries, k).is_some();
        match (has("thickness"), has("base")) {
            (true, true) => Err(self.fail(
                self.at("base")?,
                "base",
                "give either \"thickness\" or \"base\", not both",
            )),
            (true, false) => {
                let side = match find(self.entries, "side") {
                    None => Side::Both,
                    Some(i) => Side::from_name(self.string("side")?).ok_or_else(|| {
                        self.fail(i, "side", "expected \"both\", \"front\" or \"back\"")
                    })?,
                };
                Ok(Closure::Thickness {
                    thickness: self.positive("thickness")?,
                    side,
                })
            }
            (false, true) => {
                if let Some(i) = find(self.entries, "side") {
                    return Err(self.fail(i, "side", "\"side\" goes with \"thickness\""));
                }
                Ok(Closure::Base {
                    z: self.number("base")?,
                })
            }
            (false, false) => {
                if let Some(i) = find(self.entries, "side") {
                    return Err(self.fail(i, "side", "\"side\" goes with \"thickness\""));
                }
                Ok(Closure::Closed)
            }
        }
    }

    /// A non-negative integer under `key`.
    fn count(&self, key: &str) -> R<usize> {
        let i = self.at(key)?;
        let x = self.number_at(i, key)?;
        if (0.0..=1e6).contains(&x) && x.fract() == 0.0 {
            Ok(x as usize)
        } else {
            Err(self.fail(i, key, "expected a whole number"))
        }
    }

    /// `degree`: one number for both directions or `[p, q]`.
    fn degrees(&self) -> R<[usize; 2]> {
        let i = self.at("degree")?;
        match &self.reader.doc.values[i as usize] {
            Value::Number(_) => {
                let d = self.count("degree")?;
                Ok([d, d])
            }
            _ => {
                let [p, q] = self.numbers::<2>(i, "degree")?;
                if [p, q]
                    .iter()
                    .all(|x| (0.0..=1e6).contains(x) && x.fract() == 0.0)
                {
                    Ok([p as usize, q as usize])
                } else {
                    Err(self.fail(i, "degree", "expected whole numbers"))
                }
            }
        }
    }

    fn number_list(&self, index: u32, key: &str) -> R<Vec<f64>> {
        self.items(index, key)?
            .iter()
            .map(|&i| self.number_at(i, key))
            .collect()
    }

    /// Rows of points (row `j` along `v`, item `i` along `u`), all rows of one length:
    /// `([n_u, n_v], points)` with `P_ij` at `j n_u + i`.
    fn point_rows(&self, key: &str) -> R<([usize; 2], Vec<DVec3>)> {
        let at = self.at(key)?;
        let rows = self.items(at, key)?;
        let mut points = Vec::new();
        let mut width = None;
        for (j, &r) in rows.iter().enumerate() {
            let name = format!("{key}[{j}]");
            let row = self.items(r, &name)?;
            if *width.get_or_insert(row.len()) != row.len() {
                return Err(self.fail(r, &name, "every row must have as many points as the first"));
            }
            for (i, &p) in row.iter().enumerate() {
                points.push(DVec3::from_array(
                    self.numbers::<3>(p, &format!("{name}[{i}]"))?,
                ));
            }
        }
        let counts = [width.unwrap_or(0), rows.len()];
        if counts[0] < 2 || counts[1] < 2 {
            return Err(self.fail(at, key, "expected at least 2 rows of at least 2 points"));
        }
        Ok((counts, points))
    }

    /// Rows of weights shaped like the control net.
    fn weight_rows(&self, counts: [usize; 2]) -> R<Vec<f64>> {
        let at = self.at("weights")?;
        let rows = self.items(at, "weights")?;
        if rows.len() != counts[1] {
            return Err(self.fail(
                at,
                "weights",
                "expected one row of weights per row of points",
            ));
        }
        let mut out = Vec::new();
        for (j, &r) in rows.iter().enumerate() {
            let name = format!("weights[{j}]");
            let row = self.number_list(r, &name)?;
            if row.len() != counts[0] {
                return Err(self.fail(r, &name, "expected one weight per point of the row"));
            }
            out.extend(row);
        }
        Ok(out)
    }
}
