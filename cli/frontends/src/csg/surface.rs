//! `surface(file = "x.dat", center, invert)`: a height map as OpenSCAD 2021.01 builds it (its
//! `surface.cc`). The `.dat` file holds rows of numbers (blank lines and lines starting with `#`
//! are skipped; a missing value in a short row is 0); row `i`, column `j` is the height at
//! `(j, i)`. Each grid cell is four triangles around its centre at the mean of its corners; walls
//! go down to a flat bottom at `min(0, min(height) − 1)`. `center` moves the grid's middle to the
//! origin. That solid is exactly a height field with [`Interpolation::Quads`] over the grid's
//! rectangle down to the bottom: a primitive with an exact, cheap field (no mesh solid).
//!
//! A `.png` image (any colour type) is read as OpenSCAD reads it: pixel row `r` from the top is
//! the height row `y = rows − 1 − r`, each pixel's grey level `L` (its luminance, 0..255; see
//! `decode_png_luminance`) is the height `100 / 255 · L`, or `100 / 255 · (1 − L)` with
//! `invert = true` (OpenSCAD 2021.01's formula, so inverted heights are negative), and the mesh
//! is built as for `.dat`.

use super::error::CsgError;
use super::parser::Stmt;
use glam::DVec2;
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::Primitive;
use solidkit_kernel::primitive::heightfield::{
    HeightField, HeightFieldError, HeightGrid, HeightSource, Interpolation, decode_png_luminance,
};
use std::sync::Arc;

/// The most heights a `.dat` file may hold (a 2048 × 2048 grid).
pub const MAX_HEIGHTS: usize = 1 << 22;

/// The heights of a `.dat` file, row by row (rows padded with 0 to the longest one), or why not.
pub fn parse_dat(text: &str) -> Result<Vec<Vec<f64>>, String> {
    let mut rows: Vec<Vec<f64>> = Vec::new();
    let mut count = 0usize;
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let row = line
            .split_whitespace()
            .map(|w| w.parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect::<Option<Vec<f64>>>()
            .ok_or_else(|| format!("line {}: expected finite numbers", k + 1))?;
        count += row.len();
        if count > MAX_HEIGHTS {
            return Err(format!("more than {MAX_HEIGHTS} heights"));
        }
        rows.push(row);
    }
    let columns = rows.iter().map(Vec::len).max().unwrap_or(0);
    for r in &mut rows {
        r.resize(columns, 0.0);
    }
    Ok(rows)
}

/// OpenSCAD's surface solid of `rows` (at least 2 × 2) as a height field: the rectangle from
/// `(0, 0)` (or the grid's middle at the origin with `center`) with one unit per sample step,
/// down to `min(0, min(height) − 1)`.
pub fn height_field(rows: &[Vec<f64>], center: bool) -> Result<HeightField, HeightFieldError> {
    let (ny, nx) = (rows.len(), rows[0].len());
    let size = DVec2::new(nx as f64 - 1.0, ny as f64 - 1.0);
    let min = if center { -0.5 * size } else { DVec2::ZERO };
    let bottom = rows.iter().flatten().fold(0.0f64, |m, &v| m.min(v - 1.0));
    let source = HeightSource::Samples {
        grid: HeightGrid::from_rows(rows)?,
        interpolation: Interpolation::Quads,
    };
    HeightField::new(min, min + size, bottom, source)
}

/// The heights of a PNG image, row by row from the smallest y, as OpenSCAD derives them; `None`
/// when the image has fewer than 2 × 2 pixels.
pub fn png_heights(bytes: &[u8], invert: bool) -> Result<Option<Vec<Vec<f64>>>, String> {
    let grid = match decode_png_luminance(bytes) {
        Ok(g) => g,
        Err(HeightFieldError::GridTooSmall { .. }) => return Ok(None),
        Err(e) => return Err(e.to_string()),
    };
    if grid.nx() * grid.ny() > MAX_HEIGHTS {
        return Err(format!(
            "{} × {} pixels: more than {MAX_HEIGHTS} heights",
            grid.nx(),
            grid.ny()
        ));
    }
    let level = |v: f64| {
        let l = v * 255.0;
        100.0 / 255.0 * if invert { 1.0 - l } else { l }
    };
    Ok(Some(
        grid.rows()
            .map(|row| row.iter().map(|&v| level(v)).collect())
            .collect(),
    ))
}

/// The solid of a `surface` statement from the bytes of its `.dat` or `.png` file.
pub fn surface(stmt: &Stmt, path: &str, bytes: &[u8]) -> Result<Option<Solid>, CsgError> {
    let rows = if path.to_ascii_lowercase().ends_with(".png") {
        let invert = stmt.flag("invert", None, false)?;
        match png_heights(bytes, invert).map_err(|e| stmt.error(format!("{path}: {e}")))? {
            Some(rows) => rows,
            None => return Ok(None),
        }
    } else {
        let text = String::from_utf8_lossy(bytes);
        parse_dat(&text).map_err(|e| stmt.error(format!("{path}: {e}")))?
    };
    if rows.len() < 2 || rows[0].len() < 2 {
        return Ok(None);
    }
    let center = stmt.flag("center", None, false)?;
    let field = height_field(&rows, center).map_err(|e| stmt.error(format!("{path}: {e}")))?;
    Ok(Some(Solid::primitive(Primitive::HeightField(Arc::new(
        field,
    )))))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;
    use solidkit_kernel::Shape;

    /// A polyhedron: vertices and faces counter-clockwise seen from outside.
    type Mesh = (Vec<DVec3>, Vec<Vec<u32>>);

    /// OpenSCAD's surface mesh of `rows` (at least 2 × 2): the kernel's polyhedron of the height
    /// field (`HeightField::quad_mesh`), vertices and triangles counter-clockwise seen from
    /// outside; the tests below check it against hand-computed volumes and the field.
    pub(super) fn mesh(rows: &[Vec<f64>], center: bool) -> Mesh {
        let (v, t) = height_field(rows, center)
            .unwrap()
            .quad_mesh()
            .expect("quads above the base");
        (v, t.into_iter().map(|t| t.to_vec()).collect())
    }

    /// Volume of a closed triangle mesh.
    fn volume(v: &[DVec3], f: &[Vec<u32>]) -> f64 {
        f.iter()
            .map(|t| {
                let [a, b, c] = [0, 1, 2].map(|k| v[t[k] as usize]);
                a.dot(b.cross(c))
            })
            .sum::<f64>()
            / 6.0
    }

    #[test]
    fn flat_map_is_a_box_down_to_one_below_the_lowest_or_zero() {
        let rows = parse_dat("# comment\n3 3 3\n\n3 3 3\n").unwrap();
        let (v, f) = mesh(&rows, false);
        // 2 × 1 cells, heights 3, bottom at 0.
        assert!((volume(&v, &f) - 6.0).abs() < 1e-12);
        let rows = parse_dat("-2 -2\n-2 -2\n").unwrap();
        let (v, f) = mesh(&rows, true);
        // Bottom at -3, top at -2: a unit cube.
        assert!((volume(&v, &f) - 1.0).abs() < 1e-12);
        assert!(v.iter().all(|p| p.x.abs() <= 0.5 && p.y.abs() <= 0.5));
    }

    #[test]
    fn cell_centre_is_the_mean_and_short_rows_are_padded() {
        let rows = parse_dat("0 0\n0 4\n").unwrap();
        let (v, f) = mesh(&rows, false);
        // Bottom at -1. Above z = 0, four triangles of area 1/4 around the centre (height 1),
        // with mean heights 1/3, 5/3, 5/3, 1/3.
        let above = 0.25 * (1.0 / 3.0 + 5.0 / 3.0 + 5.0 / 3.0 + 1.0 / 3.0);
        assert!(
            (volume(&v, &f) - (1.0 + above)).abs() < 1e-12,
            "{}",
            volume(&v, &f)
        );
        assert_eq!(parse_dat("1 2 3\n4\n").unwrap()[1], vec![4.0, 0.0, 0.0]);
        assert!(parse_dat("1 x\n").is_err());
    }

    #[test]
    fn the_height_field_is_openscads_mesh() {
        // Uneven heights (one below zero), 4 × 3 samples; both placements.
        let rows = parse_dat("0 2 -1.5 3\n4 0.5 1 7\n-2 6 2.25 0\n").unwrap();
        for center in [false, true] {
            let (v, f) = mesh(&rows, center);
            let field = height_field(&rows, center).unwrap();
            // The bottom and the rectangle are the mesh's box.
            let lo = v.iter().fold(DVec3::INFINITY, |m, p| m.min(*p));
            let hi = v.iter().fold(DVec3::NEG_INFINITY, |m, p| m.max(*p));
            assert_eq!(field.base(), lo.z);
            assert_eq!(field.min(), lo.truncate());
            assert_eq!(field.max(), hi.truncate());
            // Every top triangle (the first 4 per cell) is the height field at points inside it.
            let top = 4 * (rows.len() - 1) * (rows[0].len() - 1);
            for t in &f[..top] {
                let [a, b, c] = [0, 1, 2].map(|k| v[t[k] as usize]);
                for (wa, wb) in [(1.0 / 3.0, 1.0 / 3.0), (0.7, 0.2), (0.1, 0.1), (0.45, 0.5)] {
                    let p = a * wa + b * wb + c * (1.0 - wa - wb);
                    let h = field.height(p.x, p.y);
                    assert!((h - p.z).abs() < 1e-12, "{p} {h} center {center}");
                    // Just below the top is inside, just above outside.
                    assert!(field.value(p - DVec3::Z * 1e-6) < 0.0);
                    assert!(field.value(p + DVec3::Z * 1e-6) > 0.0);
                }
            }
        }
    }
}
