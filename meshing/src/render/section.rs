//! Cross-sections: the plane `x = c`, `y = c` or `z = c` through a field, each pixel filled by
//! the sign of the field at its centre, and the zero contour (pixels whose sign differs from a
//! neighbour's on the outside) drawn dark. Image axes: for `z` x right, y up; for `y` x right,
//! z up; for `x` y right, z up. Tiles of pixels classified inside or outside by interval
//! evaluation are filled without sampling.

use super::{Image, ImageSize, RenderError};
use glam::DVec3;
use rayon::prelude::*;
use solidkit_kernel::program::{IntervalScratch, Pruned};
use solidkit_kernel::{Aabb, Program};

/// Inside the solid.
pub const INSIDE: [u8; 3] = [70, 110, 180];
/// Outside the solid.
pub const OUTSIDE: [u8; 3] = [235, 235, 225];
/// The zero contour.
pub const CONTOUR: [u8; 3] = [20, 20, 20];

/// Tile side in pixels.
const TILE: u32 = 16;

/// A section plane: coordinate `axis` (0 x, 1 y, 2 z) equal to `at`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// The axis the plane is normal to.
    pub axis: usize,
    /// Its coordinate.
    pub at: f64,
}

impl Section {
    /// Parses `x=C`, `y=C` or `z=C`.
    pub fn parse(s: &str) -> Result<Self, RenderError> {
        let bad = || RenderError::Parse(format!("'{s}' is not a section (x=C, y=C or z=C)"));
        let (axis, at) = s.split_once('=').ok_or_else(bad)?;
        let axis = match axis.trim() {
            "x" | "X" => 0,
            "y" | "Y" => 1,
            "z" | "Z" => 2,
            _ => return Err(bad()),
        };
        let at: f64 = at.trim().parse().map_err(|_| bad())?;
        if !at.is_finite() {
            return Err(bad());
        }
        Ok(Self { axis, at })
    }

    /// The image's right and up axes.
    fn plane_axes(self) -> (usize, usize) {
        match self.axis {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        }
    }
}

/// The section of `program` through `frame` (which fixes the framing: its extent along the
/// image axes, 5 % margin).
pub fn render_section(
    program: &Program,
    frame: &Aabb,
    section: Section,
    size: ImageSize,
) -> Result<Image, RenderError> {
    if frame.is_empty() || !frame.is_finite() || !frame.size().length().is_finite() {
        return Err(RenderError::Frame(
            "the solid is empty or unbounded; give a box with --bounds x0,y0,z0,x1,y1,z1".into(),
        ));
    }
    let (u, v) = section.plane_axes();
    let (w, h) = (size.width, size.height);
    let centre = frame.center();
    let extent = frame.size();
    let pixel = (extent[u] / f64::from(w)).max(extent[v] / f64::from(h)) * 1.1;
    let pixel = if pixel > 0.0 {
        pixel
    } else {
        extent.length().max(1e-9) / f64::from(w.min(h))
    };
    let point = |x: f64, y: f64| {
        let mut p = DVec3::ZERO;
        p[section.axis] = section.at;
        p[u] = centre[u] + (x - f64::from(w) * 0.5) * pixel;
        p[v] = centre[v] + (f64::from(h) * 0.5 - y) * pixel;
        p
    };
    let (tiles_x, tiles_y) = (w.div_ceil(TILE), h.div_ceil(TILE));
    let tiles: Vec<Vec<bool>> = (0..tiles_x * tiles_y)
        .into_par_iter()
        .map_init(
            || (IntervalScratch::default(), Vec::new()),
            |(iv, values), i| {
                let (x0, y0) = ((i % tiles_x) * TILE, (i / tiles_x) * TILE);
                let (x1, y1) = ((x0 + TILE).min(w), (y0 + TILE).min(h));
                let a = point(f64::from(x0), f64::from(y0));
                let b = point(f64::from(x1), f64::from(y1));
                let tile = Aabb::new(a.min(b), a.max(b));
                let n = ((x1 - x0) * (y1 - y0)) as usize;
                match program.prune_for_box(&tile, iv) {
                    Pruned::Inside => vec![true; n],
                    Pruned::Outside => vec![false; n],
                    Pruned::Surface(pruned) => {
                        let p = pruned.as_ref().unwrap_or(program);
                        let mut out = Vec::with_capacity(n);
                        for y in y0..y1 {
                            for x in x0..x1 {
                                let q = point(f64::from(x) + 0.5, f64::from(y) + 0.5);
                                out.push(p.value_with(q, values) < 0.0);
                            }
                        }
                        out
                    }
                }
            },
        )
        .collect();
    let mut inside = vec![false; w as usize * h as usize];
    for (i, tile) in tiles.iter().enumerate() {
        let (x0, y0) = ((i as u32 % tiles_x) * TILE, (i as u32 / tiles_x) * TILE);
        let tw = TILE.min(w - x0);
        for (k, &c) in tile.iter().enumerate() {
            let (x, y) = (x0 + k as u32 % tw, y0 + k as u32 / tw);
            inside[y as usize * w as usize + x as usize] = c;
        }
    }
    let (wu, hu) = (w as usize, h as usize);
    let pixels = (0..wu * hu)
        .into_par_iter()
        .map(|i| {
            let (x, y) = (i % wu, i / wu);
            let me = inside[i];
            let differs = |j: usize| inside[j] != me;
            let edge = !me
                && ((x > 0 && differs(i - 1))
                    || (x + 1 < wu && differs(i + 1))
                    || (y > 0 && differs(i - wu))
                    || (y + 1 < hu && differs(i + wu)));
            if edge {
                CONTOUR
            } else if me {
                INSIDE
            } else {
                OUTSIDE
            }
        })
        .collect();
    Ok(Image {
        width: w,
        height: h,
        pixels,
    })
}

#[cfg(test)]
mod tests {
    use super::{INSIDE, OUTSIDE, Section, render_section};
    use crate::render::ImageSize;
    use solidkit_kernel::Solid;

    #[test]
    fn sphere_section_is_a_disc() {
        let solid = Solid::sphere(1.0);
        let img = render_section(
            &solid.compile(),
            &solid.bbox(),
            Section::parse("z=0.5").unwrap(),
            ImageSize::new(64, 64).unwrap(),
        )
        .unwrap();
        assert_eq!(img.get(32, 32), INSIDE);
        assert_eq!(img.get(1, 1), OUTSIDE);
        // The disc at z = 0.5 has radius √0.75 ≈ 0.866 of the sphere's 1 (frame 2.2 wide).
        let across = (0..64).filter(|&x| img.get(x, 32) == INSIDE).count();
        assert!((across as f64 - 0.866 * 64.0 / 1.1).abs() < 3.0, "{across}");
        assert!(Section::parse("w=1").is_err());
    }
}
