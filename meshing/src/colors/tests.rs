//! Colour assignment: a difference's cut faces take the cutter's colour, the innermost colour
//! wins, unbounded parts and uncoloured parts.

use super::*;
use crate::pipeline::{MeshOptions, mesh_solid};
use glam::DVec3;

fn red() -> Rgba {
    Rgba::parse("red").unwrap()
}

fn blue() -> Rgba {
    Rgba::parse("blue").unwrap()
}

/// `difference() { color("red") cube(10, center = true); color("blue") sphere(6.5); }`.
pub(crate) fn cube_minus_sphere() -> Solid {
    Solid::cube(10.0)
        .color(red())
        .difference(&Solid::sphere(6.5).color(blue()))
}

/// Centroid of triangle `t`.
pub(crate) fn centroid(mesh: &IndexedMesh, t: usize) -> DVec3 {
    mesh.triangles[t]
        .iter()
        .map(|&i| mesh.positions[i as usize])
        .sum::<DVec3>()
        / 3.0
}

/// Checks that every triangle on a cube face is red and every one on the sphere blue.
pub(crate) fn check_cube_minus_sphere(mesh: &IndexedMesh, color: impl Fn(usize) -> [u8; 4]) {
    let (mut on_cube, mut on_sphere, mut bevels) = (0, 0, 0);
    for t in 0..mesh.triangles.len() {
        let c = centroid(mesh, t);
        // unambiguous triangles: on one surface and away from the other (bevels and rim
        // triangles of marching cubes lie on neither)
        let (dc, ds) = (
            (c.abs().max_element() - 5.0).abs(),
            (c.length() - 6.5).abs(),
        );
        let cube = dc < 0.01 && ds > 0.15;
        let sphere = ds < 0.03 && dc > 0.15;
        if cube && !sphere {
            assert_eq!(color(t), [255, 0, 0, 255], "cube face at {c}");
            on_cube += 1;
        } else if sphere && !cube {
            assert_eq!(color(t), [0, 0, 255, 255], "sphere face at {c}");
            on_sphere += 1;
        } else {
            // near both surfaces, or a bevel along a sharp edge
            bevels += 1;
        }
    }
    assert!(on_cube > 1000 && on_sphere > 1000, "{on_cube} {on_sphere}");
    assert!(bevels * 4 < mesh.triangles.len(), "{bevels}");
}

pub(crate) fn meshed(solid: &Solid) -> crate::pipeline::Meshed {
    mesh_solid(solid, &MeshOptions::new(64)).unwrap()
}

#[test]
fn cut_faces_take_the_cutters_colour() {
    let solid = cube_minus_sphere();
    let m = meshed(&solid);
    let colors = m.face_colors(&solid).unwrap();
    assert_eq!(colors.palette, vec![[255, 0, 0, 255], [0, 0, 255, 255]]);
    assert_eq!(colors.faces.len(), m.mesh.triangles.len());
    assert_eq!(colors.used(), 2);
    check_cube_minus_sphere(&m.mesh, |t| colors.color(t).unwrap());
    // the geometry is the uncoloured tree's, bit for bit
    let plain = meshed(&Solid::cube(10.0).difference(&Solid::sphere(6.5)));
    assert_eq!(plain.mesh.positions, m.mesh.positions);
    assert_eq!(plain.mesh.triangles, m.mesh.triangles);
    assert!(plain.face_colors(&plain_tree()).is_none());
}

fn plain_tree() -> Solid {
    Solid::cube(10.0).difference(&Solid::sphere(6.5))
}

#[test]
fn innermost_colour_wins_and_uncoloured_parts_stay_uncoloured() {
    let green = Rgba::rgb(0.0, 1.0, 0.0);
    let solid = Solid::union_all([
        Solid::sphere(1.0)
            .color(red())
            .translate(DVec3::new(3.0, 0.0, 0.0))
            .color(green),
        Solid::sphere(1.0).translate(DVec3::new(-3.0, 0.0, 0.0)),
        Solid::cube(1.0)
            .translate(DVec3::new(0.0, 3.0, 0.0))
            .color(green),
    ]);
    let m = meshed(&solid);
    let colors = m.face_colors(&solid).unwrap();
    let mut seen = [0; 3];
    for t in 0..m.mesh.triangles.len() {
        let c = centroid(&m.mesh, t);
        let (want, k) = if c.x > 1.5 {
            (Some([255, 0, 0, 255]), 0)
        } else if c.x < -1.5 {
            (None, 1)
        } else {
            (Some([0, 255, 0, 255]), 2)
        };
        assert_eq!(colors.color(t), want, "{c}");
        seen[k] += 1;
    }
    assert!(seen.iter().all(|&n| n > 50), "{seen:?}");
    assert!(colors.has_uncolored());
}

#[test]
fn unbounded_parts_are_candidates_everywhere() {
    // a box cut by a half-space: the cut face takes the half-space's colour
    let solid = Solid::cube(2.0)
        .color(red())
        .intersection(&Solid::half_space(DVec3::Z, 0.25).color(blue()));
    let m = meshed(&solid);
    let colors = m.face_colors(&solid).unwrap();
    for t in 0..m.mesh.triangles.len() {
        let c = centroid(&m.mesh, t);
        let inner = c.x.abs().max(c.y.abs()) < 0.95;
        if (c.z - 0.25).abs() < 1e-3 && inner {
            assert_eq!(colors.faces[t], 1, "{c}");
        } else if c.z < 0.15 {
            assert_eq!(colors.faces[t], 0, "{c}");
        }
    }
}
