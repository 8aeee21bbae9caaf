//! `surface()` of PNG images against OpenSCAD's rules (its User Manual and 2021.01's render):
//! grey level `L` (luminance, 0..255) is the height `100 / 255 · L`, the top image row is the
//! largest y, `invert` maps `L` to `100 / 255 · (1 − L)`, the base is at `min(0, lowest − 1)`.

use super::surface::png_heights;
use super::{Facets, import_with_warnings};
use glam::DVec2;
use solidkit_kernel::primitive::heightfield::{HeightSource, Interpolation};
use solidkit_kernel::primitive::{MeshResolver, Primitive, ResolveError, ResolveKind};
use solidkit_kernel::{IndexedMesh, NodeKind};
use solidkit_meshing::render::Image;
use solidkit_meshing::render::png_out::encode;
use solidkit_tests::{mesh, rel_err};

/// One PNG, served under any name.
struct OnePng(Vec<u8>);

impl MeshResolver for OnePng {
    fn load(&self, _: &str) -> Result<IndexedMesh, ResolveError> {
        Err(ResolveError::message(ResolveKind::Unsupported, "no meshes"))
    }
    fn read_file(&self, _: &str) -> Result<Vec<u8>, ResolveError> {
        Ok(self.0.clone())
    }
}

/// An RGB image, rows from the top.
fn png(rows: &[&[[u8; 3]]]) -> Vec<u8> {
    encode(&Image {
        width: rows[0].len() as u32,
        height: rows.len() as u32,
        pixels: rows.concat(),
    })
    .expect("png")
}

/// The exact volume of the solid `text` builds with `image` as its file (a height field over
/// OpenSCAD's four triangles per cell: each cell holds the mean of its corners above the base,
/// since the four triangles' mean heights sum to twice the corners' sum plus four times the
/// centre's, over 12); its mesh is closed. `surface::tests` checks the field against OpenSCAD's
/// triangles point by point.
fn volume(text: &str, image: Vec<u8>) -> f64 {
    let (s, w) = import_with_warnings(text, Facets::Exact, &OnePng(image))
        .unwrap_or_else(|e| panic!("{text}: {e}"));
    assert!(w.is_empty(), "{w:?}");
    s.validate().expect("valid");
    let (_, report) = mesh(&s, 64);
    assert_eq!(report.boundary_edges, 0);
    let NodeKind::Primitive(Primitive::HeightField(h)) = s.kind() else {
        panic!("not a height field: {s:?}")
    };
    let HeightSource::Samples {
        grid,
        interpolation: Interpolation::Quads,
    } = h.source()
    else {
        panic!("not OpenSCAD's triangles")
    };
    let cell = (h.max() - h.min()) / DVec2::new(grid.nx() as f64 - 1.0, grid.ny() as f64 - 1.0);
    let mut v = 0.0;
    for j in 0..grid.ny() - 1 {
        for i in 0..grid.nx() - 1 {
            let corners =
                grid.get(i, j) + grid.get(i + 1, j) + grid.get(i, j + 1) + grid.get(i + 1, j + 1);
            v += (corners / 4.0 - h.base()) * cell.x * cell.y;
        }
    }
    v
}

const WHITE: [u8; 3] = [255, 255, 255];
const BLACK: [u8; 3] = [0, 0, 0];

#[test]
fn grey_levels_are_heights_with_the_top_row_at_the_largest_y() {
    let image = png(&[&[WHITE, [51, 51, 51]], &[BLACK, [255, 0, 0]]]);
    let rows = png_heights(&image, false).unwrap().unwrap();
    // Row 0 is y = 0: the bottom image row (black, red).
    assert_eq!(rows[0][0], 0.0);
    assert!((rows[0][1] - 100.0 / 255.0 * 0.2126 * 255.0).abs() < 1e-9);
    assert!((rows[1][0] - 100.0).abs() < 1e-9);
    assert!((rows[1][1] - 20.0).abs() < 1e-9);
    let inverted = png_heights(&image, true).unwrap().unwrap();
    assert!((inverted[1][0] - 100.0 / 255.0 * (1.0 - 255.0)).abs() < 1e-9);
    assert!((inverted[0][0] - 100.0 / 255.0).abs() < 1e-9);
    assert!(png_heights(b"not a png", false).is_err());
    assert_eq!(png_heights(&png(&[&[WHITE]]), false).unwrap(), None);
}

#[test]
fn a_white_image_is_a_box_on_z_zero_and_inverted_one_below_its_top() {
    let white = || png(&[&[WHITE, WHITE, WHITE], &[WHITE, WHITE, WHITE]]);
    // 2 × 1 cells, 100 high, base at min(0, 100 − 1) = 0.
    let v = volume("surface(file = \"w.png\", center = true);", white());
    assert!(rel_err(v, 200.0) < 1e-12, "{v}");
    // Inverted: heights 100/255 · (1 − 255) < 0, base one below: a slab 1 thick.
    let v = volume("surface(file = \"w.png\", invert = true);", white());
    assert!(rel_err(v, 2.0) < 1e-12, "{v}");
}

#[test]
fn a_ramp_has_the_volume_of_openscads_triangles() {
    // Top row white, bottom row black: four triangles around the centre (height 50) over a
    // unit cell (0.25 · (50/3 + 50 + 250/3 + 50) = 50), plus the base 1 below 0.
    let v = volume(
        "surface(file = \"r.png\");",
        png(&[&[WHITE, WHITE], &[BLACK, BLACK]]),
    );
    assert!(rel_err(v, 51.0) < 1e-12, "{v}");
}
