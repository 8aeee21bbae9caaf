//! The orthographic camera: a view direction (named or azimuth, elevation) and the framing of a
//! box in an image.
//!
//! The eye direction (from the scene towards the camera) for azimuth `a` and elevation `e` is
//! `(cos e · sin a, −cos e · cos a, sin e)`: `front` (0, 0) looks along +y with +z up, `side`
//! (90, 0) looks along −x, `top` (0, 90) looks down with +y up, `iso` is (45, 35.26).

use super::{ImageSize, RenderError};
use glam::DVec3;
use solidkit_kernel::Aabb;

/// Where the camera looks from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum View {
    /// Azimuth 45°, elevation 35.26° (the three axes foreshortened equally).
    Iso,
    /// From −y, +z up.
    Front,
    /// From +z, +y up.
    Top,
    /// From +x, +z up.
    Side,
    /// Azimuth and elevation in degrees.
    Angles(f64, f64),
}

impl View {
    /// Parses `iso`, `front`, `top`, `side` or `AZ,EL` (degrees, elevation within ±90).
    pub fn parse(s: &str) -> Result<Self, RenderError> {
        Ok(match s.trim() {
            "iso" => View::Iso,
            "front" => View::Front,
            "top" => View::Top,
            "side" => View::Side,
            other => {
                let bad = || {
                    RenderError::Parse(format!(
                        "'{other}' is not a view (iso, front, top, side or AZ,EL in degrees)"
                    ))
                };
                let (a, e) = other.split_once(',').ok_or_else(bad)?;
                let a: f64 = a.trim().parse().map_err(|_| bad())?;
                let e: f64 = e.trim().parse().map_err(|_| bad())?;
                if !a.is_finite() || !(-90.0..=90.0).contains(&e) {
                    return Err(bad());
                }
                View::Angles(a, e)
            }
        })
    }

    /// Azimuth and elevation in degrees.
    pub fn angles(self) -> (f64, f64) {
        match self {
            View::Iso => (45.0, 35.264_389_682_754_654),
            View::Front => (0.0, 0.0),
            View::Top => (0.0, 90.0),
            View::Side => (90.0, 0.0),
            View::Angles(a, e) => (a, e),
        }
    }
}

/// An orthographic camera framing a box: pixel `(x, y)` (continuous, centres at `i + 0.5`) is the
/// ray `origin(x, y) + t · dir`, `t ≥ 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// Image size.
    pub size: ImageSize,
    /// Image right, unit.
    pub right: DVec3,
    /// Image up, unit.
    pub up: DVec3,
    /// Ray direction (into the scene), unit.
    pub dir: DVec3,
    /// World length of one pixel.
    pub pixel: f64,
    /// Where the framed box's centre appears, in pixels.
    centre_px: (f64, f64),
    /// The framed box's centre.
    centre: DVec3,
    /// Depth of the near plane (relative to the centre) and of the far plane.
    near: f64,
    far: f64,
}

impl Camera {
    /// Frames `frame` in the whole image (5 % margin on each side).
    pub fn framing(view: View, frame: &Aabb, size: ImageSize) -> Result<Self, RenderError> {
        Self::framing_in(view, frame, size, 0)
    }

    /// Frames `frame` in the rows below `top` (the rows above are left for a legend).
    pub fn framing_in(
        view: View,
        frame: &Aabb,
        size: ImageSize,
        top: u32,
    ) -> Result<Self, RenderError> {
        if frame.is_empty() {
            return Err(RenderError::Frame(
                "nothing to draw (empty bounding box)".into(),
            ));
        }
        if !frame.is_finite() || !frame.size().length().is_finite() {
            return Err(RenderError::Frame(
                "the solid is unbounded; give a box with --bounds x0,y0,z0,x1,y1,z1".into(),
            ));
        }
        let (az, el) = view.angles();
        let (az, el) = (az.to_radians(), el.to_radians());
        let eye = DVec3::new(el.cos() * az.sin(), -el.cos() * az.cos(), el.sin());
        let right = DVec3::new(az.cos(), az.sin(), 0.0);
        let up = eye.cross(right).normalize();
        let dir = -eye;
        let centre = frame.center();
        let (mut half_w, mut half_h, mut depth) = (0.0f64, 0.0f64, 0.0f64);
        for i in 0..8 {
            let k = DVec3::new(
                if i & 1 == 0 { frame.min.x } else { frame.max.x },
                if i & 2 == 0 { frame.min.y } else { frame.max.y },
                if i & 4 == 0 { frame.min.z } else { frame.max.z },
            ) - centre;
            half_w = half_w.max(k.dot(right).abs());
            half_h = half_h.max(k.dot(up).abs());
            depth = depth.max(k.dot(dir).abs());
        }
        let rows = f64::from(size.height - top.min(size.height - 1));
        let cols = f64::from(size.width);
        let mut pixel = (2.0 * half_w / cols).max(2.0 * half_h / rows) * 1.1;
        if pixel <= 0.0 || !pixel.is_finite() {
            pixel = (frame.size().length().max(1e-9)) / cols.min(rows);
        }
        let margin = 2.0 * pixel;
        Ok(Self {
            size,
            right,
            up,
            dir,
            pixel,
            centre_px: (cols * 0.5, f64::from(top) + rows * 0.5),
            centre,
            near: -depth - margin,
            far: depth + margin,
        })
    }

    /// The ray origin (on the near plane) of image point `(x, y)` in pixels.
    pub fn origin(&self, x: f64, y: f64) -> DVec3 {
        self.centre
            + self.right * ((x - self.centre_px.0) * self.pixel)
            + self.up * ((self.centre_px.1 - y) * self.pixel)
            + self.dir * self.near
    }

    /// The ray length from the near plane to the far plane.
    pub fn depth_range(&self) -> f64 {
        self.far - self.near
    }

    /// `p` in image coordinates: pixels right, pixels down, depth from the near plane.
    pub fn project(&self, p: DVec3) -> [f64; 3] {
        let q = p - self.centre;
        [
            q.dot(self.right) / self.pixel + self.centre_px.0,
            self.centre_px.1 - q.dot(self.up) / self.pixel,
            q.dot(self.dir) - self.near,
        ]
    }

    /// The direction light comes from: over the viewer's left shoulder.
    pub fn light(&self) -> DVec3 {
        (-self.dir + self.up * 0.6 - self.right * 0.4).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::{Camera, View};
    use crate::render::ImageSize;
    use glam::DVec3;
    use solidkit_kernel::Aabb;

    #[test]
    fn named_views_have_the_documented_axes() {
        let b = Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
        let size = ImageSize::new(100, 100).unwrap();
        let front = Camera::framing(View::Front, &b, size).unwrap();
        assert!((front.dir - DVec3::Y).length() < 1e-12);
        assert!((front.up - DVec3::Z).length() < 1e-12);
        let top = Camera::framing(View::Top, &b, size).unwrap();
        assert!((top.up - DVec3::Y).length() < 1e-12);
        let p = front.project(DVec3::new(1.0, 0.0, 1.0));
        assert!(p[0] > 50.0 && p[1] < 50.0);
        let o = front.origin(p[0], p[1]);
        assert!((o + front.dir * p[2] - DVec3::new(1.0, 0.0, 1.0)).length() < 1e-9);
        assert!(View::parse("30,100").is_err());
        assert!(View::parse("30, -20").is_ok());
    }
}
