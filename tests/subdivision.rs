//! Subdivision surfaces in CSG (issue 8): `subdivide` nodes read from JSON, computed through the
//! meshing crate's resolver, meshed by marching cubes inside Boolean trees, against the volumes of
//! the subdivided polyhedra themselves; a polygon mesh file as the child; adaptive subdivision.

use glam::DVec3;
use solidkit_kernel::json::{self, MeshResolver};
use solidkit_kernel::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron};
use solidkit_kernel::primitive::{SubdivisionInput, SubdivisionRequest, SubdivisionScheme};
use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::{FileMeshResolver, PolygonMesh, read_polygon_mesh};
use solidkit_meshing::subdivision::{self, Limits};
use solidkit_tests::{fixture, mesh, rel_err};
use std::f64::consts::PI;

const RESOLUTION: usize = 96;

/// The cube of edge 2 under three levels of Catmull-Clark, triangulated: the surface the
/// `subdivide` node stands for, computed directly (not through the JSON reader).
fn subdivided_cube_volume() -> f64 {
    let cube = Polyhedron::platonic(PlatonicKind::Cube, PlatonicSize::Edge(2.0)).unwrap();
    let request = SubdivisionRequest {
        input: SubdivisionInput::Faces {
            vertices: cube.vertices(),
            faces: cube.faces(),
        },
        scheme: SubdivisionScheme::CatmullClark,
        levels: 3,
        adaptive: None,
    };
    let triangles = FileMeshResolver::new(".").subdivide(&request).unwrap();
    let r = TopologyReport::of(&triangles);
    assert!(r.is_closed_manifold() && r.genus == Some(0), "{r:?}");
    r.volume
}

fn tree(sphere_centre: [f64; 3], radius: f64) -> String {
    format!(
        r#"{{"type": "difference", "children": [
            {{"type": "subdivide", "scheme": "catmull-clark", "levels": 3,
              "child": {{"type": "platonic", "solid": "cube", "edge": 2}}}},
            {{"type": "translate", "offset": {sphere_centre:?},
              "child": {{"type": "sphere", "radius": {radius}}}}}]}}"#
    )
}

#[test]
fn subdivided_cube_minus_a_sphere_meshes_closed_within_the_volume_bounds() {
    let resolver = FileMeshResolver::new(fixture("polyhedra"));
    let v_sub = subdivided_cube_volume();
    // Catmull-Clark shrinks the cube (edge 2, volume 8) to a rounded body of a third of it.
    assert!(v_sub < 8.0 / 2.9 && v_sub > 8.0 / 3.1, "{v_sub}");
    let r = 0.4;
    let ball = 4.0 / 3.0 * PI * r * r * r;
    // A ball inside: a cavity (two shells), the volume is exactly V_sub − V_ball.
    let solid = json::from_str_with(&tree([0.0, 0.0, 0.0], r), &resolver).unwrap();
    let (_, report) = mesh(&solid, RESOLUTION);
    assert!(report.is_closed_manifold() && report.oriented, "{report:?}");
    assert_eq!((report.shells, report.genus), (2, Some(0)), "{report:?}");
    let expected = v_sub - ball;
    assert!(
        rel_err(report.volume, expected) < 1e-3,
        "{} vs {expected}",
        report.volume
    );
    // A ball through the surface: one shell, a bite between nothing and the whole ball.
    let solid = json::from_str_with(&tree([0.85, 0.0, 0.0], r), &resolver).unwrap();
    let (_, report) = mesh(&solid, RESOLUTION);
    assert!(report.is_closed_manifold() && report.oriented, "{report:?}");
    assert_eq!((report.shells, report.genus), (1, Some(0)), "{report:?}");
    assert!(
        report.volume > v_sub - ball + 0.1 * ball && report.volume < v_sub - 0.1 * ball,
        "{} not within ({}, {v_sub})",
        report.volume,
        v_sub - ball
    );
}

#[test]
fn the_field_is_the_exact_distance_to_the_subdivided_surface() {
    // Points of the subdivided surface are on the zero set; the centre is inside by at least the
    // inradius of the limit surface's inner ball.
    let resolver = FileMeshResolver::new(fixture("polyhedra"));
    let text = r#"{"type": "subdivide", "scheme": "loop", "levels": 2,
        "child": {"type": "platonic", "solid": "icosahedron", "circumradius": 1}}"#;
    let solid = json::from_str_with(text, &resolver).unwrap();
    let ico =
        Polyhedron::platonic(PlatonicKind::Icosahedron, PlatonicSize::Circumradius(1.0)).unwrap();
    let he = solidkit_meshing::HalfEdgeMesh::from_polygons(ico.vertices().to_vec(), ico.faces())
        .unwrap();
    let surface =
        subdivision::subdivide(&he, SubdivisionScheme::Loop, 2, &Limits::default()).unwrap();
    for p in surface.positions() {
        assert!(solid.value(*p).abs() < 1e-12, "{p}: {}", solid.value(*p));
    }
    let min_r = surface
        .positions()
        .iter()
        .map(|p| p.length())
        .fold(f64::INFINITY, f64::min);
    assert!(solid.value(DVec3::ZERO) < -0.9 * min_r);
    assert!(solid.value(DVec3::splat(2.0)) > 0.0);
}

#[test]
fn a_quad_mesh_file_child_keeps_its_quads_and_genus() {
    // fixtures/polyhedra/subdivided_ring.json: Doo-Sabin on the quads of quad_ring.obj.
    let path = fixture("polyhedra/subdivided_ring.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let solid = json::from_str_with(&text, &FileMeshResolver::for_tree_file(&path)).unwrap();
    // The child was read with its quads: Doo-Sabin counts on 16 quads (V 16, E 32), two levels.
    let quads = read_polygon_mesh(&fixture("polyhedra/quad_ring.obj")).unwrap();
    assert!(quads.faces.iter().all(|f| f.len() == 4) && quads.faces.len() == 16);
    let he = quads.to_half_edge().unwrap();
    let twice = subdivision::doo_sabin(&he, 2).unwrap();
    assert_eq!(twice.face_count(), 256);
    assert_eq!(twice.euler_characteristic(), 0);
    let (_, report) = mesh(&solid, 64);
    assert!(report.is_closed_manifold(), "{report:?}");
    assert_eq!((report.shells, report.genus), (1, Some(1)), "{report:?}");
    // Round trip of the tree.
    let again = json::from_str_with(
        &json::to_string(&solid),
        &FileMeshResolver::for_tree_file(&path),
    )
    .unwrap();
    assert!(again == solid);
}

#[test]
fn adaptive_catmull_clark_keeps_the_flat_middles_of_the_slab_coarse() {
    // fixtures/polyhedra/adaptive_slab.json: three adaptive levels to 0.01 on a 6 × 6 × 2 slab
    // of unit quads. The quads touching an edge of the slab are refined (the limit surface is
    // curved there) until they are flat to the tolerance; the 4 × 4 middles of the top and
    // bottom stay as they were.
    let path = fixture("polyhedra/adaptive_slab.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let resolver = FileMeshResolver::for_tree_file(&path);
    let solid = json::from_str_with(&text, &resolver).unwrap();
    let quads = read_polygon_mesh(&fixture("polyhedra/gridded_slab.obj")).unwrap();
    let he = quads.to_half_edge().unwrap();
    assert_eq!(he.face_count(), 120);
    let (adaptive, levels) = subdivision::subdivide_adaptive(
        &he,
        SubdivisionScheme::CatmullClark,
        3,
        0.01,
        &Limits::default(),
    )
    .unwrap();
    // Levels 1 and 2 refine the whole band (88 quads, then their 352 children); at level 3 most
    // of the band's quads are flat to 0.01 at their size, and only 496 of 1440 are refined.
    for l in &levels[..2] {
        assert_eq!(
            (l.refined, l.conformed, l.kept),
            (l.faces_in - 32, 24, 8),
            "{levels:?}"
        );
    }
    assert_eq!(levels[2].refined, 496, "{levels:?}");
    assert_eq!(adaptive.face_count(), 2928);
    assert_eq!(adaptive.euler_characteristic(), 2);
    let uniform = subdivision::catmull_clark(&he, 3).unwrap();
    assert_eq!(uniform.face_count(), 120 * 64);
    // The node is that surface: meshed closed, one shell of genus 0, with its volume; and it
    // lies within the tolerance scale of the uniform limit (same volume to 0.5 %).
    let exact = TopologyReport::of(&PolygonMesh::from_half_edge(&adaptive).triangulated());
    let fine = TopologyReport::of(&PolygonMesh::from_half_edge(&uniform).triangulated());
    assert!(
        exact.is_closed_manifold() && exact.genus == Some(0),
        "{exact:?}"
    );
    assert!(
        rel_err(exact.volume, fine.volume) < 5e-3,
        "{} vs {}",
        exact.volume,
        fine.volume
    );
    let (_, report) = mesh(&solid, 96);
    assert!(report.is_closed_manifold(), "{report:?}");
    assert_eq!((report.shells, report.genus), (1, Some(0)), "{report:?}");
    assert!(
        rel_err(report.volume, exact.volume) < 0.01,
        "{} vs {}",
        report.volume,
        exact.volume
    );
    let again = json::from_str_with(&json::to_string(&solid), &resolver).unwrap();
    assert!(again == solid);
}
