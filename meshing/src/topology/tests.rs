//! Tests of the topology report on closed solids, tori, several shells and every defect kind.

use super::test_meshes::*;
use super::{Offenders, ReportOptions, SelfIntersectionsMethod, TopologyReport};
use crate::IndexedMesh;

/// Asserts the report of a single closed genus-0 solid.
fn assert_sphere_like(r: &TopologyReport) {
    assert_eq!(r.euler_characteristic, 2);
    assert_eq!((r.shells, r.genus), (1, Some(0)));
    assert_eq!(r.genus_per_shell, vec![Some(0)]);
    assert!(r.closed && r.manifold && r.oriented && r.is_closed_manifold());
    assert_eq!(r.examples, Offenders::default());
}

#[test]
fn cube_is_a_closed_manifold_of_volume_one() {
    let r = TopologyReport::of(&cube());
    assert_sphere_like(&r);
    assert_eq!((r.vertices, r.edges, r.faces), (8, 18, 12));
    assert_eq!((r.boundary_edges, r.non_manifold_edges), (0, 0));
    assert_eq!((r.non_manifold_vertices, r.inconsistent_edges), (0, 0));
    assert_eq!((r.degenerate_faces, r.unreferenced_vertices), (0, 0));
    assert_eq!(r.volume, 1.0);
    assert_eq!(r.area, 6.0);
    assert_eq!(r.bbox, [[0.0; 3], [1.0; 3]]);
}

#[test]
fn tetrahedron_and_octahedron() {
    let tet = TopologyReport::of(&tetrahedron());
    assert_sphere_like(&tet);
    assert_eq!((tet.vertices, tet.edges, tet.faces), (4, 6, 4));
    assert!((tet.volume - 1.0 / 6.0).abs() < 1e-15);
    assert!((tet.area - (1.5 + 3f64.sqrt() / 2.0)).abs() < 1e-15);

    let oct = TopologyReport::of(&octahedron());
    assert_sphere_like(&oct);
    assert_eq!((oct.vertices, oct.edges, oct.faces), (6, 12, 8));
    assert!((oct.volume - 4.0 / 3.0).abs() < 1e-15);
    assert!((oct.area - 4.0 * 3f64.sqrt()).abs() < 1e-14);
    assert_eq!(oct.bbox, [[-1.0; 3], [1.0; 3]]);
}

#[test]
fn torus_has_genus_one() {
    let r = TopologyReport::of(&torus(8, 6));
    assert_eq!((r.vertices, r.edges, r.faces), (48, 144, 96));
    assert_eq!(r.euler_characteristic, 0);
    assert_eq!(
        (r.genus, r.genus_per_shell.clone()),
        (Some(1), vec![Some(1)])
    );
    assert!(r.is_closed_manifold());
    assert!(r.volume > 0.0);
}

#[test]
fn two_cubes_are_two_shells() {
    let r = TopologyReport::of(&two_cubes());
    assert_eq!(r.shells, 2);
    assert_eq!(r.euler_characteristic, 4);
    assert_eq!(r.genus, Some(0));
    assert_eq!(r.genus_per_shell, vec![Some(0), Some(0)]);
    // Cones from the box centre (2, 0.5, 0.5): exact up to rounding.
    assert!((r.volume - 2.0).abs() < 1e-12);
    assert_eq!(r.area, 12.0);
    assert_eq!(r.bbox, [[0.0; 3], [4.0, 1.0, 1.0]]);
}

#[test]
fn shells_are_ordered_by_first_triangle_and_genus_needs_all_sound() {
    let r = TopologyReport::of(&concat(&torus(8, 6), &cube()));
    assert_eq!(r.genus_per_shell, vec![Some(1), Some(0)]);
    assert_eq!(r.genus, Some(1));

    let r = TopologyReport::of(&concat(&cube_hole(), &cube()));
    assert_eq!(r.genus_per_shell, vec![None, Some(0)]);
    assert_eq!(r.genus, None);
}

#[test]
fn hole_gives_three_boundary_edges() {
    let r = TopologyReport::of(&cube_hole());
    assert_eq!(
        (r.vertices, r.edges, r.faces, r.euler_characteristic),
        (8, 18, 11, 1)
    );
    assert_eq!(r.boundary_edges, 3);
    assert_eq!(r.examples.boundary_edges, vec![[1, 5], [1, 6], [5, 6]]);
    assert!(!r.closed && r.manifold && r.oriented && !r.is_closed_manifold());
    assert_eq!((r.genus, r.genus_per_shell.clone()), (None, vec![None]));
}

#[test]
fn flipped_face_gives_three_inconsistent_edges() {
    let r = TopologyReport::of(&cube_flipped());
    assert_eq!(r.inconsistent_edges, 3);
    assert_eq!(r.examples.inconsistent_edges, vec![[1, 5], [1, 6], [5, 6]]);
    assert!(r.closed && r.manifold && !r.oriented && !r.is_closed_manifold());
    assert_eq!(
        (
            r.boundary_edges,
            r.non_manifold_edges,
            r.non_manifold_vertices
        ),
        (0, 0, 0)
    );
    assert_eq!(r.genus, None);
    // The flipped triangle's cone from the centre (1/12) is subtracted instead of added.
    assert!((r.volume - 5.0 / 6.0).abs() < 1e-15);
}

#[test]
fn fin_gives_one_non_manifold_edge_and_two_boundary_edges() {
    let r = TopologyReport::of(&fin());
    assert_eq!(
        (r.vertices, r.edges, r.faces, r.euler_characteristic),
        (9, 20, 13, 2)
    );
    assert_eq!(r.non_manifold_edges, 1);
    assert_eq!(r.examples.non_manifold_edges, vec![[0, 1]]);
    assert_eq!(r.boundary_edges, 2);
    assert_eq!(r.examples.boundary_edges, vec![[0, 8], [1, 8]]);
    assert_eq!((r.non_manifold_vertices, r.inconsistent_edges), (0, 0));
    assert!(!r.closed && !r.manifold && r.oriented);
    assert_eq!((r.shells, r.genus), (1, None));
}

#[test]
fn bowtie_gives_one_non_manifold_vertex_in_one_shell() {
    let r = TopologyReport::of(&bowtie());
    assert_eq!(
        (r.vertices, r.edges, r.faces, r.euler_characteristic),
        (7, 12, 8, 3)
    );
    assert_eq!(r.non_manifold_vertices, 1);
    assert_eq!(r.examples.non_manifold_vertices, vec![0]);
    assert_eq!(r.shells, 1);
    assert!(r.closed && !r.manifold && r.oriented && !r.is_closed_manifold());
    assert_eq!(
        (r.non_manifold_edges, r.boundary_edges, r.inconsistent_edges),
        (0, 0, 0)
    );
    assert_eq!(r.genus_per_shell, vec![None]);
    assert!((r.volume - 1.0 / 3.0).abs() < 1e-15);
}

#[test]
fn open_bowtie_has_two_boundary_loops_through_one_vertex() {
    let r = TopologyReport::of(&open_bowtie());
    assert_eq!(r.non_manifold_vertices, 1);
    assert_eq!(r.examples.non_manifold_vertices, vec![0]);
    assert_eq!((r.boundary_edges, r.shells), (6, 1));
}

#[test]
fn duplicate_triangle_gives_three_non_manifold_edges() {
    let r = TopologyReport::of(&duplicate_triangle());
    assert_eq!((r.vertices, r.edges, r.faces), (8, 18, 13));
    assert_eq!(r.non_manifold_edges, 3);
    assert_eq!(r.examples.non_manifold_edges, vec![[0, 1], [0, 2], [1, 2]]);
    assert_eq!(
        (
            r.boundary_edges,
            r.inconsistent_edges,
            r.non_manifold_vertices
        ),
        (0, 0, 0)
    );
    assert!(r.closed && !r.manifold && r.oriented);
    assert_eq!(r.degenerate_faces, 0);
    // The duplicated triangle overlaps its original entirely.
    assert_eq!(r.self_intersections, Some(1));
    assert_eq!(r.examples.self_intersections, vec![[0, 12]]);
}

#[test]
fn collapsed_and_out_of_range_triangles_are_degenerate_and_skipped() {
    for mesh in [collapsed_triangle(), out_of_range_triangle()] {
        let r = TopologyReport::of(&mesh);
        assert_eq!(r.degenerate_faces, 1);
        assert_eq!(r.examples.degenerate_faces, vec![12]);
        assert_eq!(
            (r.vertices, r.edges, r.faces, r.euler_characteristic),
            (8, 18, 12, 2)
        );
        assert!(r.is_closed_manifold());
        assert_eq!((r.volume, r.area), (1.0, 6.0));
    }
}

#[test]
fn zero_area_sliver_is_degenerate_but_kept() {
    let r = TopologyReport::of(&sliver_cube());
    assert_eq!(
        (r.vertices, r.edges, r.faces, r.euler_characteristic),
        (9, 21, 14, 2)
    );
    assert_eq!(r.degenerate_faces, 1);
    assert_eq!(r.examples.degenerate_faces, vec![13]);
    assert!(r.is_closed_manifold());
    assert_eq!(r.genus, Some(0));
    assert!((r.volume - 1.0).abs() < 1e-15);
}

#[test]
fn unreferenced_vertices_are_counted_and_left_out_of_the_box() {
    let mut mesh = cube();
    mesh.positions.push(glam::DVec3::splat(100.0));
    let r = TopologyReport::of(&mesh);
    assert_eq!((r.vertices, r.unreferenced_vertices), (8, 1));
    assert_eq!(r.bbox, [[0.0; 3], [1.0; 3]]);
}

#[test]
fn empty_mesh_reports_zeros() {
    let r = TopologyReport::of(&IndexedMesh::default());
    assert_eq!((r.vertices, r.edges, r.faces, r.shells), (0, 0, 0, 0));
    assert_eq!((r.genus, r.genus_per_shell.clone()), (None, vec![]));
    assert!(!r.closed && r.manifold && r.oriented);
    assert_eq!(r.bbox, [[0.0; 3]; 2]);
}

#[test]
fn examples_are_capped() {
    // 20 separate triangles: 60 boundary edges, 8 listed.
    let positions = (0..60)
        .map(|i| glam::DVec3::new(f64::from(i), 0.0, f64::from(i % 3)))
        .collect();
    let triangles = (0..20).map(|t| [3 * t, 3 * t + 1, 3 * t + 2]).collect();
    let r = TopologyReport::of(&IndexedMesh::new(positions, triangles));
    assert_eq!((r.boundary_edges, r.shells), (60, 20));
    assert_eq!(r.examples.boundary_edges.len(), super::MAX_EXAMPLES);
    assert!(r.to_text().contains(" ..."));
}

#[test]
fn text_lists_values_and_offenders() {
    let text = TopologyReport::of(&cube()).to_text();
    assert!(text.contains("vertices:               8\n"));
    assert!(text.contains("euler characteristic:   2\n"));
    assert!(text.contains("genus per shell:        [0]\n"));
    assert!(text.contains("closed manifold:        yes\n"));
    assert!(!text.contains(" at:"));

    let text = TopologyReport::of(&fin()).to_text();
    assert!(text.contains("non-manifold edges at:  0-1\n"));
    assert!(text.contains("boundary edges at:      0-8 1-8\n"));
    assert!(text.contains("genus:                  -\n"));
    assert_eq!(text, format!("{}", TopologyReport::of(&fin())));
}

#[test]
fn results_are_deterministic() {
    let mesh = torus(120, 90);
    assert_eq!(TopologyReport::of(&mesh), TopologyReport::of(&mesh));
}

#[test]
fn large_torus_reports() {
    let r = TopologyReport::of(&torus(300, 300));
    assert_eq!(r.faces, 180_000);
    assert_eq!(r.euler_characteristic, 0);
    assert_eq!(r.genus, Some(1));
    assert!(r.is_closed_manifold());
    assert_eq!(r.self_intersections, Some(0));
}

#[test]
fn self_intersections_are_counted_unless_skipped() {
    let mesh = read_off(&fixture("self_intersecting.off"));
    let r = TopologyReport::of(&mesh);
    // Two sound cubes as far as topology goes, but crossing each other.
    assert!(r.is_closed_manifold() && r.shells == 2);
    let count = r.self_intersections.unwrap();
    assert!(count > 0 && !r.is_valid_solid());
    let shown = &r.examples.self_intersections;
    assert_eq!(shown.len(), count.min(super::MAX_EXAMPLES));
    assert!(shown.iter().all(|&[i, j]| i < 12 && j >= 12), "{shown:?}");
    assert!(shown.windows(2).all(|w| w[0] < w[1]));
    let text = r.to_text();
    assert!(
        text.contains(&format!("self-intersections:     {count}")),
        "{text}"
    );
    assert!(text.contains(&format!(
        "intersecting faces:     {}-{}",
        shown[0][0], shown[0][1]
    )));

    let skipped = TopologyReport::with_options(
        &mesh,
        &ReportOptions {
            self_intersections: false,
        },
    );
    assert_eq!(skipped.self_intersections, None);
    assert!(skipped.examples.self_intersections.is_empty() && skipped.is_valid_solid());
    assert!(
        skipped
            .to_text()
            .contains("self-intersections:     - (not checked)")
    );
    // Everything else is the same.
    let mut counted = r.clone();
    assert_eq!(
        counted.self_intersections_method,
        Some(SelfIntersectionsMethod::Tested)
    );
    counted.self_intersections = None;
    counted.self_intersections_method = None;
    counted.examples.self_intersections.clear();
    assert_eq!(skipped, counted);
    // A certificate replaces the test (the caller vouches for it: the count is then 0).
    let certified = TopologyReport::with_certificate(&mesh, &ReportOptions::default(), true);
    assert_eq!(certified.self_intersections, Some(0));
    assert_eq!(
        certified.self_intersections_method,
        Some(SelfIntersectionsMethod::Construction)
    );
    assert!(
        certified
            .to_text()
            .contains("self-intersections:     0 (construction)")
    );
    assert!(TopologyReport::of(&cube()).is_valid_solid());
}

#[test]
fn fixtures_match_the_meshes_built_in_code() {
    let cases = [
        ("cube.off", cube()),
        ("cube_hole.off", cube_hole()),
        ("cube_flipped.off", cube_flipped()),
        ("fin.off", fin()),
        ("bowtie.off", bowtie()),
    ];
    for (name, expected) in cases {
        assert_eq!(read_off(&fixture(name)), expected, "{name}");
    }
}
