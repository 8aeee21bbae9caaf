//! The axis triad: +x red, +y green, +z blue, as the camera sees them, from a corner of the
//! image, each labelled; the axis pointing furthest away is drawn first so nearer ones cover it.

use super::Image;
use super::camera::Camera;
use super::draw::line;
use super::font::{GLYPH_HEIGHT, draw_text};
use glam::DVec3;

/// Colours of the x, y and z axes.
pub const AXIS_COLORS: [[u8; 3]; 3] = [[210, 40, 40], [30, 150, 40], [40, 70, 220]];

/// Draws the triad of `cam`'s view in the lower-left corner of the `width × height` rectangle
/// whose top-left corner is `(x0, y0)` in `image`.
pub fn draw_axes(image: &mut Image, cam: &Camera, [x0, y0, width, height]: [u32; 4]) {
    let side = f64::from(width.min(height));
    let scale = (width.min(height) / 300).clamp(1, 3);
    let length = (side * 0.09).max(10.0);
    let margin = length + f64::from(GLYPH_HEIGHT * scale) + 4.0;
    let origin = [f64::from(x0) + margin, f64::from(y0 + height) - margin];
    let thickness = (width.min(height) / 256).clamp(1, 3);
    let mut order: Vec<usize> = (0..3).collect();
    let axis = |k: usize| DVec3::AXES[k];
    // Furthest first (largest component along the view direction), ties by axis.
    order.sort_by(|&a, &b| {
        axis(b)
            .dot(cam.dir)
            .total_cmp(&axis(a).dot(cam.dir))
            .then(a.cmp(&b))
    });
    for k in order {
        let (dx, dy) = (axis(k).dot(cam.right), -axis(k).dot(cam.up));
        let tip = [origin[0] + dx * length, origin[1] + dy * length];
        line(image, origin, tip, thickness, AXIS_COLORS[k]);
        let label = ["X", "Y", "Z"][k];
        let half = f64::from(GLYPH_HEIGHT * scale) * 0.5;
        let at = [
            origin[0] + dx * (length + half + 2.0) - half * 0.7,
            origin[1] + dy * (length + half + 2.0) - half,
        ];
        draw_text(
            image,
            at[0].round() as i64,
            at[1].round() as i64,
            scale,
            label,
            AXIS_COLORS[k],
        );
    }
}
