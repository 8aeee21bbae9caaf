//! A finished picture from a tracer (field or mesh, see [`GBuffer`]): one view, or a 2 × 2
//! sheet of the iso, front, top and side views, each labelled; optional feature edges and axis
//! triad. The cells are traced one after the other, each with its own camera framing the same
//! box, and copied into the sheet, so the bytes depend on the inputs alone.

use super::axes::draw_axes;
use super::camera::{Camera, View};
use super::edges::draw_edges;
use super::font::{GLYPH_HEIGHT, draw_text};
use super::gbuffer::GBuffer;
use super::{Image, ImageSize, RenderError, shade};
use solidkit_kernel::Aabb;

/// The views of a sheet, in reading order, with their labels.
pub const SHEET_VIEWS: [(View, &str); 4] = [
    (View::Iso, "ISO"),
    (View::Front, "FRONT"),
    (View::Top, "TOP"),
    (View::Side, "SIDE"),
];

/// Colour of the lines between the cells of a sheet.
const DIVIDER: [u8; 3] = [200, 200, 200];
/// Colour of the view labels.
const LABEL: [u8; 3] = [60, 60, 60];

/// What a picture shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    /// One view, or `None` for the 2 × 2 sheet of [`SHEET_VIEWS`].
    pub view: Option<View>,
    /// Draw feature edges ([`super::edges`]).
    pub edges: bool,
    /// Draw the axis triad ([`super::axes`]).
    pub axes: bool,
    /// Base colour of the surface.
    pub base: [u8; 3],
}

impl Look {
    /// One view, no edges, no axes, the solid colour.
    pub fn plain(view: View) -> Self {
        Self {
            view: Some(view),
            edges: false,
            axes: false,
            base: shade::SOLID,
        }
    }
}

/// The picture of what `trace` sees of `frame` at `size`.
pub fn picture(
    frame: &Aabb,
    size: ImageSize,
    look: &Look,
    trace: impl Fn(&Camera) -> GBuffer,
) -> Result<Image, RenderError> {
    let Some(view) = look.view else {
        return sheet(frame, size, look, trace);
    };
    let cam = Camera::framing(view, frame, size)?;
    Ok(finish(&cam, &trace(&cam), look, 0))
}

/// Shading, then edges and the triad, of one cell; `top` rows are left for a label.
fn finish(cam: &Camera, g: &GBuffer, look: &Look, top: u32) -> Image {
    let mut image = g.shade(cam, look.base);
    if look.edges {
        draw_edges(&mut image, g, cam);
    }
    if look.axes {
        let (w, h) = (image.width, image.height);
        draw_axes(&mut image, cam, [0, top, w, h - top]);
    }
    image
}

/// Font scale of the labels of cells `width` wide.
fn label_scale(width: u32) -> u32 {
    (width / 300).clamp(1, 3)
}

/// The 2 × 2 sheet.
fn sheet(
    frame: &Aabb,
    size: ImageSize,
    look: &Look,
    trace: impl Fn(&Camera) -> GBuffer,
) -> Result<Image, RenderError> {
    let (w, h) = (size.width, size.height);
    if w < 16 || h < 16 {
        return Err(RenderError::Parse(format!(
            "{w}x{h}: a sheet of four views needs at least 16x16 pixels"
        )));
    }
    let cols = [(0, w / 2), (w / 2, w - w / 2)];
    let rows = [(0, h / 2), (h / 2, h - h / 2)];
    let mut out = Image::filled(size, shade::BACKGROUND);
    for (k, (view, label)) in SHEET_VIEWS.into_iter().enumerate() {
        let ((x0, cw), (y0, ch)) = (cols[k % 2], rows[k / 2]);
        let cell = ImageSize::new(u64::from(cw), u64::from(ch))?;
        let scale = label_scale(cw);
        let top = (GLYPH_HEIGHT + 4) * scale;
        let cam = Camera::framing_in(view, frame, cell, top)?;
        let mut image = finish(&cam, &trace(&cam), look, top);
        draw_text(
            &mut image,
            2 * i64::from(scale),
            2 * i64::from(scale),
            scale,
            label,
            LABEL,
        );
        for y in 0..ch {
            for x in 0..cw {
                out.put(i64::from(x0 + x), i64::from(y0 + y), image.get(x, y));
            }
        }
    }
    for y in 0..h {
        out.put(i64::from(w / 2), i64::from(y), DIVIDER);
    }
    for x in 0..w {
        out.put(i64::from(x), i64::from(h / 2), DIVIDER);
    }
    Ok(out)
}
