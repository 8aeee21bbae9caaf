//! Reading `heightfield` nodes: the solid between `z = base` and `z = h(x, y)` over the rectangle
//! `min` = [x, y] to `max` = [x, y], with `h` from exactly one of
//! - `"bezier"`: rows of control heights (row j along y, column i along x; degrees = size − 1);
//! - `"samples"`: rows of heights on a regular grid, with `"interpolation"`: `"bilinear"`
//!   (default), `"bicubic"` or `"quads"` (OpenSCAD's `surface()` triangles);
//! - `"png"`: a grayscale PNG file path, read through the reader's
//!   [`MeshResolver`](crate::primitive::MeshResolver) (relative to the tree file's folder and
//!   confined to it, like `mesh` paths), with `"heights"`: [black, white] and the optional
//!   `"interpolation"`.

use super::super::document::Value;
use super::{Params, R};
use crate::primitive::Primitive;
use crate::primitive::heightfield::{
    HeightField, HeightFieldError, HeightGrid, HeightSource, Interpolation,
};
use glam::DVec2;
use std::sync::Arc;

impl Params<'_, '_> {
    /// The primitive of a `heightfield` node.
    pub(super) fn heightfield(&self) -> R<(Primitive, &'static [&'static str])> {
        let min = DVec2::from_array(self.numbers::<2>(self.at("min")?, "min")?);
        let max = DVec2::from_array(self.numbers::<2>(self.at("max")?, "max")?);
        let base = self.number("base")?;
        let present: Vec<&str> = ["bezier", "samples", "png"]
            .into_iter()
            .filter(|k| self.entries.iter().any(|(e, _)| e == k))
            .collect();
        if present.len() != 1 {
            return Err(self.fail(
                self.index,
                "bezier",
                "expected exactly one of \"bezier\", \"samples\" or \"png\"",
            ));
        }
        let at_key = |key: &str| self.at(key).unwrap_or(self.index);
        let to_located = |e: HeightFieldError| match e {
            HeightFieldError::Parameter(p) => {
                self.fail(at_key(p.parameter), p.parameter, p.problem)
            }
            HeightFieldError::Io(_)
            | HeightFieldError::Unreadable { .. }
            | HeightFieldError::ImageTooLarge { .. }
            | HeightFieldError::Png(_)
            | HeightFieldError::NotGrayscale { .. } => self.fail(at_key("png"), "png", e),
            other => self.fail(at_key(present[0]), present[0], other),
        };
        let (field, allowed): (HeightField, &'static [&'static str]) = match present[0] {
            "bezier" => {
                let grid = self.height_rows("bezier")?;
                let source = HeightSource::Bezier(grid.map_err(to_located)?);
                let f = HeightField::new(min, max, base, source).map_err(to_located)?;
                (f, &["min", "max", "base", "bezier"])
            }
            "samples" => {
                let grid = self.height_rows("samples")?.map_err(to_located)?;
                let interpolation = self.height_interpolation()?;
                let source = HeightSource::Samples {
                    grid,
                    interpolation,
                };
                let f = HeightField::new(min, max, base, source).map_err(to_located)?;
                (f, &["min", "max", "base", "samples", "interpolation"])
            }
            _ => {
                let path = self.heightfield_string("png")?;
                let heights = self.numbers::<2>(self.at("heights")?, "heights")?;
                let interpolation = self.height_interpolation()?;
                let bytes = self.reader.resolver.read_file(path).map_err(|reason| {
                    to_located(HeightFieldError::Unreadable {
                        path: path.to_owned(),
                        reason,
                    })
                })?;
                let f = HeightField::from_png_bytes(
                    min,
                    max,
                    base,
                    path,
                    &bytes,
                    heights,
                    interpolation,
                )
                .map_err(to_located)?;
                (
                    f,
                    &["min", "max", "base", "png", "heights", "interpolation"],
                )
            }
        };
        Ok((Primitive::HeightField(Arc::new(field)), allowed))
    }

    /// Rows of numbers under `key` as a grid (the grid's own checks are left to the caller).
    fn height_rows(&self, key: &str) -> R<Result<HeightGrid, HeightFieldError>> {
        let i = self.at(key)?;
        let Value::Array(rows) = &self.reader.doc.values[i as usize] else {
            return Err(self.fail(i, key, "expected an array of rows of numbers"));
        };
        let mut out = Vec::with_capacity(rows.len());
        for (j, &r) in rows.iter().enumerate() {
            let row_key = format!("{key}[{j}]");
            let Value::Array(items) = &self.reader.doc.values[r as usize] else {
                return Err(self.fail(r, &row_key, "expected an array of numbers"));
            };
            let row = items
                .iter()
                .map(|&x| self.number_at(x, &row_key))
                .collect::<R<Vec<f64>>>()?;
            out.push(row);
        }
        Ok(HeightGrid::from_rows(&out))
    }

    /// The optional `interpolation` name.
    fn height_interpolation(&self) -> R<Interpolation> {
        let Some((_, i)) = self.entries.iter().find(|(k, _)| k == "interpolation") else {
            return Ok(Interpolation::default());
        };
        match &self.reader.doc.values[*i as usize] {
            Value::String(s) => Interpolation::from_name(s).ok_or_else(|| {
                self.fail(
                    *i,
                    "interpolation",
                    "expected \"bilinear\", \"bicubic\" or \"quads\"",
                )
            }),
            v => Err(self.fail(
                *i,
                "interpolation",
                format!("expected a string, found {}", v.type_name()),
            )),
        }
    }

    /// A string value under `key`.
    fn heightfield_string(&self, key: &str) -> R<&str> {
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
}
