//! The surface a camera sees, before shading: per pixel the depth of the first hit along the ray
//! and the unit normal there. Field ray casting and mesh rasterisation both produce one; shading,
//! feature edges ([`super::edges`]) and the multi-view sheet work from it alone.

use super::camera::Camera;
use super::shade::{self, lambert};
use super::{Image, ImageSize};
use glam::DVec3;
use rayon::prelude::*;

/// Depth and normal per pixel, row-major, rows top to bottom.
#[derive(Debug, Clone, PartialEq)]
pub struct GBuffer {
    /// Image size.
    pub size: ImageSize,
    /// Depth of the hit from the camera's near plane (world units); `f32::INFINITY` where the
    /// ray meets nothing.
    pub depth: Vec<f32>,
    /// Unit normal at the hit (either orientation: shading is two-sided); zero where empty.
    pub normal: Vec<[f32; 3]>,
}

impl GBuffer {
    /// A buffer where every ray misses (the size must have been checked by [`ImageSize`]).
    pub fn empty(size: ImageSize) -> Self {
        Self {
            size,
            depth: vec![f32::INFINITY; size.pixel_count()],
            normal: vec![[0.0; 3]; size.pixel_count()],
        }
    }

    /// True where a surface was hit.
    pub fn hit(&self, i: usize) -> bool {
        self.depth[i].is_finite()
    }

    /// The normal at pixel `i` as a double vector.
    pub fn normal_at(&self, i: usize) -> DVec3 {
        let [x, y, z] = self.normal[i];
        DVec3::new(f64::from(x), f64::from(y), f64::from(z))
    }

    /// Lambert shading of every hit in `base`, the background elsewhere.
    pub fn shade(&self, cam: &Camera, base: [u8; 3]) -> Image {
        let light = cam.light();
        let pixels = (0..self.depth.len())
            .into_par_iter()
            .map(|i| {
                if self.hit(i) {
                    lambert(self.normal_at(i), light, base)
                } else {
                    shade::BACKGROUND
                }
            })
            .collect();
        Image {
            width: self.size.width,
            height: self.size.height,
            pixels,
        }
    }
}

/// `v` as single precision (normals are stored so; unit length is kept to about 1e-7).
pub fn to_f32(v: DVec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}
