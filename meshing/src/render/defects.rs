//! A mesh's defects in colour: the mesh flat-shaded in grey, then, drawn over it without depth
//! test so hidden ones show, inconsistent faces and self-intersecting faces filled, boundary and
//! non-manifold edges as thick lines, non-manifold vertices as squares; a legend with the counts
//! fills the rows above the framed mesh.

use super::camera::{Camera, View};
use super::draw::{dot, fill_triangle, line};
use super::font::{ADVANCE, GLYPH_HEIGHT, draw_text};
use super::raster::{corners, project, render_mesh};
use super::{Image, ImageSize, RenderError, shade};
use crate::IndexedMesh;
use crate::topology::DefectItems;
use solidkit_kernel::Aabb;

/// Edges used by one triangle.
pub const BOUNDARY_EDGE: [u8; 3] = [230, 30, 30];
/// Edges used by more than two triangles.
pub const NON_MANIFOLD_EDGE: [u8; 3] = [200, 0, 220];
/// Vertices whose faces form several fans.
pub const NON_MANIFOLD_VERTEX: [u8; 3] = [0, 90, 255];
/// Faces on an edge both traverse in the same direction.
pub const INCONSISTENT_FACE: [u8; 3] = [0, 200, 200];
/// Faces meeting another beyond their shared vertices.
pub const SELF_INTERSECTING_FACE: [u8; 3] = [255, 190, 0];

/// Legend entries, in drawing order.
const ENTRIES: usize = 5;

/// Font scale of the legend for an image of `size`.
fn text_scale(size: ImageSize) -> u32 {
    (size.width / 400).clamp(1, 4)
}

/// Rows the legend takes at the top of an image of `size` (at most a third of it).
pub fn legend_height(size: ImageSize) -> u32 {
    let row = (GLYPH_HEIGHT + 3) * text_scale(size);
    ((ENTRIES as u32) * row + 2 * row / 2).min(size.height / 3)
}

/// Width of lines and (three times it) vertex squares for an image of `size`.
pub fn line_width(size: ImageSize) -> u32 {
    (size.width.min(size.height) / 256).clamp(2, 8)
}

/// The camera of a defect picture: `frame` in the rows below the legend.
pub fn defect_camera(view: View, frame: &Aabb, size: ImageSize) -> Result<Camera, RenderError> {
    Camera::framing_in(view, frame, size, legend_height(size))
}

/// The defect picture of `mesh` (see the module docs).
pub fn render_defects(mesh: &IndexedMesh, items: &DefectItems, cam: &Camera) -> Image {
    let mut image = render_mesh(mesh, cam, shade::GREY);
    let projected = project(mesh, cam);
    let xy = |v: u32| projected.get(v as usize).map(|p| [p[0], p[1]]);
    for (faces, color) in [
        (&items.inconsistent_faces, INCONSISTENT_FACE),
        (&items.self_intersecting_faces, SELF_INTERSECTING_FACE),
    ] {
        for &t in faces {
            if let Some(p) = corners(mesh, &projected, t as usize) {
                fill_triangle(&mut image, p, color);
            }
        }
    }
    let width = line_width(cam.size);
    for (edges, color) in [
        (&items.boundary_edges, BOUNDARY_EDGE),
        (&items.non_manifold_edges, NON_MANIFOLD_EDGE),
    ] {
        for &[a, b] in edges {
            if let (Some(a), Some(b)) = (xy(a), xy(b)) {
                line(&mut image, a, b, width, color);
            }
        }
    }
    for &v in &items.non_manifold_vertices {
        if let Some(p) = xy(v) {
            dot(&mut image, p, 3 * width, NON_MANIFOLD_VERTEX);
        }
    }
    draw_legend(&mut image, items);
    image
}

/// The legend: a coloured square and `NAME COUNT` per defect class, over a cleared strip.
fn draw_legend(image: &mut Image, items: &DefectItems) {
    let size = ImageSize {
        width: image.width,
        height: image.height,
    };
    let strip = legend_height(size);
    for y in 0..strip {
        for x in 0..image.width {
            image.put(i64::from(x), i64::from(y), shade::BACKGROUND);
        }
    }
    let s = text_scale(size);
    let row = i64::from((GLYPH_HEIGHT + 3) * s);
    let more = if items.truncated { "+" } else { "" };
    let entries = [
        (
            "BOUNDARY EDGES",
            items.boundary_edges.len(),
            "",
            BOUNDARY_EDGE,
        ),
        (
            "NON-MANIFOLD EDGES",
            items.non_manifold_edges.len(),
            "",
            NON_MANIFOLD_EDGE,
        ),
        (
            "NON-MANIFOLD VERTICES",
            items.non_manifold_vertices.len(),
            "",
            NON_MANIFOLD_VERTEX,
        ),
        (
            "FLIPPED FACES",
            items.inconsistent_faces.len(),
            "",
            INCONSISTENT_FACE,
        ),
        (
            "SELF-INTERSECTING FACES",
            items.self_intersecting_faces.len(),
            more,
            SELF_INTERSECTING_FACE,
        ),
    ];
    for (i, (name, count, suffix, color)) in entries.into_iter().enumerate() {
        let y = row / 2 + i as i64 * row;
        if y + row > i64::from(strip) {
            break;
        }
        let box_side = i64::from(GLYPH_HEIGHT * s);
        for dy in 0..box_side {
            for dx in 0..box_side {
                image.put(row / 2 + dx, y + dy, color);
            }
        }
        let x = row / 2 + box_side + i64::from(ADVANCE * s);
        draw_text(
            image,
            x,
            y,
            s,
            &format!("{name} {count}{suffix}"),
            [40, 40, 40],
        );
    }
}
