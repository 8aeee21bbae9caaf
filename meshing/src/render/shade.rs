//! Colours and Lambert shading with an ambient term.

use glam::DVec3;

/// Background of every picture (no shaded surface colour reaches it).
pub const BACKGROUND: [u8; 3] = [245, 245, 245];
/// Base colour of solids rendered from their field or mesh.
pub const SOLID: [u8; 3] = [150, 175, 215];
/// Base colour of a mesh under its defects.
pub const GREY: [u8; 3] = [190, 190, 190];

/// Share of the light that reaches every surface.
const AMBIENT: f64 = 0.25;

/// `base` lit by a light from `light` (unit) on a surface with unit normal `normal`; both faces
/// lit alike (meshes may be inconsistently oriented).
pub fn lambert(normal: DVec3, light: DVec3, base: [u8; 3]) -> [u8; 3] {
    let d = normal.dot(light).abs();
    let k = if d.is_finite() {
        AMBIENT + (1.0 - AMBIENT) * d.min(1.0)
    } else {
        AMBIENT
    };
    base.map(|c| (f64::from(c) * k).round() as u8)
}

/// The unit normal of `g`, or `fallback` when `g` has no direction.
pub fn unit_or(g: DVec3, fallback: DVec3) -> DVec3 {
    let n = g.normalize_or_zero();
    if n == DVec3::ZERO || !n.is_finite() {
        fallback
    } else {
        n
    }
}
