//! Overlay primitives: thick lines, square dots and filled triangles, drawn over an image
//! without depth test (defects stay visible behind the surface).

use super::Image;

/// A line from `a` to `b` (pixel coordinates), `width` pixels thick (square brush).
pub fn line(image: &mut Image, a: [f64; 2], b: [f64; 2], width: u32, color: [u8; 3]) {
    if !(a.iter().chain(&b).all(|v| v.is_finite())) {
        return;
    }
    let limit = f64::from(image.width.max(image.height)) * 4.0;
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    // Lines far outside the image are clipped to a bounded number of steps.
    let steps = dx.abs().max(dy.abs()).ceil().clamp(1.0, limit) as i64;
    for k in 0..=steps {
        let t = k as f64 / steps as f64;
        dot(image, [a[0] + dx * t, a[1] + dy * t], width, color);
    }
}

/// A square of `width` pixels centred on `p`.
pub fn dot(image: &mut Image, p: [f64; 2], width: u32, color: [u8; 3]) {
    let half = i64::from(width) / 2;
    let (cx, cy) = (p[0].floor() as i64, p[1].floor() as i64);
    for y in cy - half..cy - half + i64::from(width) {
        for x in cx - half..cx - half + i64::from(width) {
            image.put(x, y, color);
        }
    }
}

/// Fills the triangle (pixel coordinates; pixel centres tested) with `color`.
pub fn fill_triangle(image: &mut Image, p: [[f64; 3]; 3], color: [u8; 3]) {
    let rows = 0..image.height as i64;
    let width = image.width;
    let mut hits = Vec::new();
    super::raster::scan_triangle(p, rows, width, |x, y, _| hits.push((x, y)));
    for (x, y) in hits {
        image.put(x as i64, y as i64, color);
    }
}
