//! Polyhedral Booleans against exact volumes and topology counts, with coincident faces, shared
//! edges and mirrors.

use super::*;
use crate::{ReportOptions, TopologyReport};
use glam::DVec2;
use solidkit_kernel::Solid;

fn cuboid(lo: DVec3, size: DVec3) -> Polyhedral {
    Polyhedral::cuboid(lo, size).expect("a box")
}

fn report(p: &Polyhedral) -> TopologyReport {
    TopologyReport::with_options(
        &p.to_mesh(),
        &ReportOptions {
            self_intersections: true,
        },
    )
}

fn assert_solid(r: &TopologyReport, shells: usize, genus: i64, volume: f64) {
    assert!(r.closed && r.manifold && r.oriented, "{r:?}");
    assert_eq!(r.self_intersections, Some(0));
    assert_eq!((r.shells, r.genus), (shells, Some(genus)), "{r:?}");
    assert!(
        (r.volume - volume).abs() < 1e-9 * volume.max(1.0),
        "{} {volume}",
        r.volume
    );
}

#[test]
fn a_box_is_twelve_triangles() {
    let b = cuboid(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0));
    assert_eq!(b.triangle_count(), 12);
    assert_solid(&report(&b), 1, 0, 6.0);
}

#[test]
fn faces_shared_inside_a_union_join_the_solid() {
    // A 3 x 3 x 1 slab of unit cubes, every neighbour sharing a whole face.
    let cubes: Vec<Polyhedral> = (0..9)
        .map(|k| cuboid(DVec3::new((k % 3) as f64, (k / 3) as f64, 0.0), DVec3::ONE))
        .collect();
    let u = union_all(cubes).unwrap();
    assert_solid(&report(&u), 1, 0, 9.0);
    // Merged coplanar faces: the slab is a box again, up to the triangulation of its faces.
    assert!(u.triangle_count() <= 9 * 12, "{}", u.triangle_count());
}

#[test]
fn a_ring_of_cubes_has_a_hole_and_edge_contact_stays_apart() {
    let ring: Vec<Polyhedral> = (0..9)
        .filter(|&k| k != 4)
        .map(|k| cuboid(DVec3::new((k % 3) as f64, (k / 3) as f64, 0.0), DVec3::ONE))
        .collect();
    assert_solid(&report(&union_all(ring).unwrap()), 1, 1, 8.0);
    // Two boxes sharing only an edge: two solids, as exact kernels keep them.
    let a = cuboid(DVec3::ZERO, DVec3::ONE);
    let b = cuboid(DVec3::new(1.0, 1.0, 0.0), DVec3::ONE);
    let u = union_all(vec![a, b]).unwrap();
    assert_eq!(u.volume(), 2.0);
    assert_eq!(report(&u).shells, 2);
}

#[test]
fn difference_and_intersection_with_coincident_faces() {
    let a = cuboid(DVec3::ZERO, DVec3::splat(2.0));
    // A through-slot flush with the top face and the sides: coincident faces everywhere.
    let slot = cuboid(DVec3::new(0.5, 0.0, 1.0), DVec3::new(1.0, 2.0, 1.0));
    let d = difference(a.clone(), vec![slot.clone()]).unwrap();
    assert_solid(&report(&d), 1, 0, 6.0);
    let i = intersection_all(vec![a.clone(), slot]).unwrap();
    assert_solid(&report(&i), 1, 0, 2.0);
    // Disjoint operands: empty intersection, and an empty operand leaves a difference alone.
    let far = cuboid(DVec3::splat(5.0), DVec3::ONE);
    assert!(intersection_all(vec![a.clone(), far]).unwrap().is_empty());
    let same = difference(a, vec![Polyhedral::empty()]).unwrap();
    assert_eq!(same.volume(), 8.0);
}

#[test]
fn a_mirror_keeps_the_faces_outward() {
    let b = cuboid(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0));
    let m = b.transform(&glam::DAffine3::from_scale(DVec3::new(-1.0, 1.0, 1.0)));
    let r = report(&m);
    assert_solid(&r, 1, 0, 6.0);
    assert_eq!(r.bbox[0][0], -1.0);
}

#[test]
fn hull_of_points() {
    let pts: Vec<DVec3> = (0..8)
        .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64))
        .chain([DVec3::splat(0.5)])
        .collect();
    let h = Polyhedral::hull(&pts).unwrap();
    assert_solid(&report(&h), 1, 0, 1.0);
}

#[test]
fn open_or_bad_meshes_are_refused() {
    let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    // A tetrahedron missing a face.
    let open = IndexedMesh::new(v.clone(), vec![[0, 2, 1], [0, 1, 3], [1, 2, 3]]);
    assert!(matches!(
        Polyhedral::from_mesh(&open),
        Err(PolyhedralError::NotManifold(_))
    ));
    let out_of_range = Polyhedral::from_faces(v.clone(), vec![vec![0, 1, 9]]);
    assert!(matches!(out_of_range, Err(PolyhedralError::Faces(_))));
    let mut nan = v;
    nan[3].z = f64::NAN;
    let closed = vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    assert!(Polyhedral::from_mesh(&IndexedMesh::new(nan, closed)).is_err());
}

fn loops_area(loops: &[Vec<glam::DVec2>]) -> f64 {
    loops
        .iter()
        .map(|l| {
            (0..l.len())
                .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
                .sum::<f64>()
                / 2.0
        })
        .sum()
}

#[test]
fn sections_keep_a_face_in_the_plane_from_either_side() {
    // A 2 × 3 box standing on z = 0, one hanging below it, one crossing it, and one off it.
    for (z, want) in [(0.0, 6.0), (-1.0, 6.0), (-0.5, 6.0), (0.5, 0.0)] {
        let p = cuboid(DVec3::new(0.0, 0.0, z), DVec3::new(2.0, 3.0, 1.0));
        let got = loops_area(&p.section_at_zero().expect("section"));
        assert!((got - want).abs() < 1e-9, "z {z}: area {got}, want {want}");
    }
}

#[test]
fn a_shadow_is_the_union_of_the_parts_outlines() {
    // Two 2 × 2 × 1 boxes overlapping by 1 in x, one above the other: a 3 × 2 shadow with the
    // overlap counted once; a box turned 45° about z casts a square of the same area.
    let a = cuboid(DVec3::ZERO, DVec3::new(2.0, 2.0, 1.0));
    let b = cuboid(DVec3::new(1.0, 0.0, 3.0), DVec3::new(2.0, 2.0, 1.0));
    let both = union_all(vec![a.clone(), b]).expect("union");
    assert!((loops_area(&both.shadow().expect("shadow")) - 6.0).abs() < 1e-9);
    let turned = a.transform(&DAffine3::from_rotation_z(std::f64::consts::FRAC_PI_4));
    // Corners at ±√2 round to the kernel's 2D grid of 1e-8.
    let got = loops_area(&turned.shadow().expect("shadow"));
    assert!((got - 4.0).abs() < 1e-7, "{got}");
    let far = a.transform(&DAffine3::from_translation(DVec3::new(1e12, 0.0, 0.0)));
    assert!(far.shadow().is_err() && far.section_at_zero().is_err());
}

#[test]
fn a_height_field_of_flat_quads_is_its_polyhedron() {
    use solidkit_kernel::primitive::Primitive;
    use solidkit_kernel::primitive::heightfield::{
        HeightField, HeightGrid, HeightSource, Interpolation,
    };
    // 2 × 2 samples (one cell), heights 0 0 / 0 4 over the unit square, base -1: a unit slab
    // below z = 0 and four triangles around the centre (height 1) with mean heights 1/3, 5/3,
    // 5/3, 1/3 above it.
    let grid = HeightGrid::new(2, 2, vec![0.0, 0.0, 0.0, 4.0]).expect("grid");
    let source = |interpolation| HeightSource::Samples {
        grid: grid.clone(),
        interpolation,
    };
    let field = |i| HeightField::new(DVec2::ZERO, DVec2::ONE, -1.0, source(i)).expect("field");
    let quads = Solid::primitive(Primitive::HeightField(std::sync::Arc::new(field(
        Interpolation::Quads,
    ))));
    let p = from_solid(&quads).expect("polyhedral");
    assert_solid(
        &report(&p),
        1,
        0,
        1.0 + 0.25 * (1.0 + 5.0 + 5.0 + 1.0) / 3.0,
    );
    // Bilinear cells are curved: no polyhedral form.
    let curved = Solid::primitive(Primitive::HeightField(std::sync::Arc::new(field(
        Interpolation::Bilinear,
    ))));
    assert!(from_solid(&curved).is_err());
}

#[test]
fn a_round_part_is_gridded_alone_when_asked() {
    // A sphere has no polyhedral form: refused by default, meshed on its own grid on request
    // (one warning naming it) and then cut from the box exactly.
    let tree =
        Solid::cuboid(DVec3::splat(2.0)).difference(&Solid::sphere(0.8).translate(DVec3::ONE));
    assert!(from_solid(&tree).is_err());
    let (p, warnings) = from_solid_gridding(&tree, Some(64)).expect("gridded");
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].contains("`sphere`"), "{warnings:?}");
    // One eighth of the ball is inside the box's corner.
    let exact = 8.0 - std::f64::consts::PI * 0.512 / 6.0;
    let r = report(&p);
    assert!(r.closed && r.manifold, "{r:?}");
    assert!(
        (r.volume - exact).abs() < 1e-3 * exact,
        "{} vs {exact}",
        r.volume
    );
}
