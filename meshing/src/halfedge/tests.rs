//! Tests of the half-edge mesh: construction, every rejected defect, queries and validation.

use std::collections::BTreeSet;

use super::{FaceId, HalfEdgeError, HalfEdgeId, HalfEdgeMesh, ValidationError, VertexId};
use crate::IndexedMesh;
use crate::TopologyReport;
use crate::topology::test_meshes::*;

/// Builds and validates `mesh`.
fn build(mesh: &IndexedMesh) -> HalfEdgeMesh {
    let he = HalfEdgeMesh::from_indexed(mesh).expect("builds");
    assert_eq!(he.validate(), Ok(()));
    he
}

/// The non-manifold error expected from the builder.
fn non_manifold(edges: &[[u32; 2]], vertices: &[u32], inconsistent: &[[u32; 2]]) -> HalfEdgeError {
    HalfEdgeError::NonManifold {
        edges: edges.to_vec(),
        vertices: vertices.to_vec(),
        inconsistent_edges: inconsistent.to_vec(),
    }
}

/// The distinct neighbours of every vertex according to the triangle list.
fn neighbor_sets(mesh: &IndexedMesh) -> Vec<BTreeSet<u32>> {
    let mut sets = vec![BTreeSet::new(); mesh.positions.len()];
    for t in &mesh.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            sets[a as usize].insert(b);
            sets[b as usize].insert(a);
        }
    }
    sets
}

#[test]
fn cube_counts_and_invariants() {
    let he = build(&cube());
    assert_eq!(he.vertex_count(), 8);
    assert_eq!(he.face_count(), 12);
    assert_eq!(he.half_edge_count(), 36);
    assert_eq!(he.edge_count(), 18);
    assert!(he.is_closed());
    assert!(he.is_triangle_mesh());
    assert_eq!(he.euler_characteristic(), 2);
    assert_eq!(he.boundary_loop_count(), 0);
    assert!(he.vertex_ids().all(|v| !he.is_boundary_vertex(v)));
}

#[test]
fn tetrahedron_octahedron_and_torus_validate() {
    for (mesh, chi) in [(tetrahedron(), 2), (octahedron(), 2), (torus(8, 6), 0)] {
        let he = build(&mesh);
        assert!(he.is_closed());
        assert_eq!(he.euler_characteristic(), chi);
        assert_eq!(he.to_indexed(), mesh);
    }
}

#[test]
fn outgoing_count_equals_valence_and_neighbors_match() {
    let mesh = cube();
    let he = build(&mesh);
    let expected = neighbor_sets(&mesh);
    for v in he.vertex_ids() {
        let neighbors: Vec<u32> = he.vertex_neighbors(v).map(|n| n.0).collect();
        assert_eq!(he.vertex_outgoing(v).count(), expected[v.index()].len());
        assert_eq!(he.valence(v), neighbors.len());
        assert_eq!(
            neighbors.iter().copied().collect::<BTreeSet<_>>(),
            expected[v.index()]
        );
        assert!(he.vertex_outgoing(v).all(|h| he.half_edge(h).origin == v));
        let faces = he.vertex_faces(v).count();
        let incident = mesh.triangles.iter().filter(|t| t.contains(&v.0)).count();
        assert_eq!(faces, incident);
    }
}

#[test]
fn ring_turns_through_adjacent_faces() {
    // Consecutive outgoing half-edges h, next(twin(h)): the face of the second is the twin's face.
    let he = build(&octahedron());
    for v in he.vertex_ids() {
        let ring: Vec<HalfEdgeId> = he.vertex_outgoing(v).collect();
        for (i, &h) in ring.iter().enumerate() {
            let following = ring[(i + 1) % ring.len()];
            let (_, across) = he.edge_faces(h);
            assert_eq!(he.half_edge(following).face, across);
        }
    }
}

#[test]
fn ring_turns_clockwise_seen_from_outside() {
    // Around the top vertex +z of the octahedron, seen from above.
    let he = build(&octahedron());
    let ring: Vec<glam::DVec3> = he
        .vertex_neighbors(VertexId(4))
        .map(|n| he.position(n))
        .collect();
    assert_eq!(ring.len(), 4);
    for (i, a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        assert!(a.cross(b).z < 0.0);
    }
}

#[test]
fn face_vertices_keep_input_order() {
    let mesh = cube();
    let he = build(&mesh);
    for (f, tri) in he.face_ids().zip(&mesh.triangles) {
        let vertices: Vec<u32> = he.face_vertices(f).map(|v| v.0).collect();
        assert_eq!(vertices, tri.to_vec());
        assert_eq!(he.face_half_edges(f).count(), 3);
        for h in he.face_half_edges(f) {
            let (a, b) = he.edge_vertices(h);
            assert_eq!(he.target(h), b);
            assert_eq!(he.half_edge(he.half_edge(h).next).origin, b);
            assert_ne!(a, b);
            assert_eq!(he.edge_faces(h).0, Some(f));
        }
    }
}

#[test]
fn hole_has_a_boundary_loop_and_open_fans() {
    let mesh = cube_hole();
    let he = build(&mesh);
    assert_eq!(he.half_edge_count(), 33 + 3);
    assert_eq!(he.edge_count(), 18);
    assert!(!he.is_closed());
    assert_eq!(he.boundary_loop_count(), 1);
    assert_eq!(he.euler_characteristic(), 1);
    let boundary: Vec<u32> = he
        .vertex_ids()
        .filter(|&v| he.is_boundary_vertex(v))
        .map(|v| v.0)
        .collect();
    assert_eq!(boundary, vec![1, 5, 6]);

    let boundary_half_edges: Vec<HalfEdgeId> = he
        .half_edge_ids()
        .filter(|&h| he.is_boundary_half_edge(h))
        .collect();
    assert_eq!(boundary_half_edges.len(), 3);
    for h in boundary_half_edges {
        let (here, across) = he.edge_faces(h);
        assert_eq!(here, None);
        assert!(across.is_some());
        let (inner_here, inner_across) = he.edge_faces(he.half_edge(h).twin);
        assert!(inner_here.is_some() && inner_across.is_none());
    }

    // Open fans terminate and hold every incident face; the ring starts on the boundary.
    for v in [1u32, 5, 6] {
        let v = VertexId(v);
        let faces: Vec<FaceId> = he.vertex_faces(v).collect();
        let incident = mesh.triangles.iter().filter(|t| t.contains(&v.0)).count();
        assert_eq!(faces.len(), incident);
        let first = he.vertex_outgoing(v).next().unwrap();
        assert!(he.is_boundary_half_edge(first));
        assert_eq!(he.valence(v), neighbor_sets(&mesh)[v.index()].len());
    }
    assert_eq!(he.to_indexed(), mesh);
}

#[test]
fn single_triangle_is_one_face_with_a_boundary_loop() {
    let mesh = IndexedMesh::new(tetrahedron().positions, vec![[0, 1, 2]]);
    let he = build(&mesh);
    assert_eq!((he.half_edge_count(), he.edge_count()), (6, 3));
    assert_eq!(he.boundary_loop_count(), 1);
    assert_eq!(he.vertex_faces(VertexId(0)).count(), 1);
    assert_eq!(he.valence(VertexId(0)), 2);
    // Vertex 3 is unreferenced: isolated.
    assert_eq!(he.vertex_half_edge(VertexId(3)), None);
    assert_eq!(he.vertex_outgoing(VertexId(3)).count(), 0);
    assert!(!he.is_boundary_vertex(VertexId(3)));
    assert_eq!(he.euler_characteristic(), 1);
}

#[test]
fn defects_are_rejected_with_the_offenders() {
    let cases = [
        (
            cube_flipped(),
            non_manifold(&[], &[], &[[1, 5], [1, 6], [5, 6]]),
        ),
        (fin(), non_manifold(&[[0, 1]], &[], &[])),
        (bowtie(), non_manifold(&[], &[0], &[])),
        (open_bowtie(), non_manifold(&[], &[0], &[])),
        (
            duplicate_triangle(),
            non_manifold(&[[0, 1], [0, 2], [1, 2]], &[], &[]),
        ),
        (
            collapsed_triangle(),
            HalfEdgeError::DegenerateFace { face: 12 },
        ),
        (
            out_of_range_triangle(),
            HalfEdgeError::IndexOutOfRange {
                face: 12,
                index: 99,
                vertex_count: 8,
            },
        ),
    ];
    for (mesh, expected) in cases {
        assert_eq!(HalfEdgeMesh::from_indexed(&mesh), Err(expected));
    }
}

#[test]
fn all_offenders_are_reported_together() {
    let mut mesh = concat(&concat(&fin(), &bowtie()), &cube_flipped());
    mesh.triangles.push([0, 2, 1]);
    let Err(HalfEdgeError::NonManifold {
        edges,
        vertices,
        inconsistent_edges,
    }) = HalfEdgeMesh::from_indexed(&mesh)
    else {
        panic!("expected a non-manifold error");
    };
    assert_eq!(edges, vec![[0, 1], [0, 2], [1, 2]]);
    assert_eq!(vertices, vec![9]);
    assert_eq!(inconsistent_edges, vec![[17, 21], [17, 22], [21, 22]]);
}

#[test]
fn zero_area_sliver_is_accepted() {
    let he = build(&sliver_cube());
    assert!(he.is_closed());
    assert_eq!(he.euler_characteristic(), 2);
}

#[test]
fn short_faces_are_degenerate() {
    let positions = cube_positions();
    let faces = vec![vec![0, 1, 2], vec![3, 4]];
    assert_eq!(
        HalfEdgeMesh::from_polygons(positions.clone(), &faces),
        Err(HalfEdgeError::DegenerateFace { face: 1 })
    );
    // A large polygon with a repeat (sorting path).
    let big: Vec<u32> = (0..20).map(|i| i % 8).collect();
    assert_eq!(
        HalfEdgeMesh::from_polygons(positions, &[big]),
        Err(HalfEdgeError::DegenerateFace { face: 0 })
    );
}

#[test]
fn quad_cube_and_torus_from_polygons() {
    let he = HalfEdgeMesh::from_polygons(cube_positions(), &cube_quads()).unwrap();
    assert_eq!(he.validate(), Ok(()));
    assert_eq!((he.face_count(), he.edge_count()), (6, 12));
    assert_eq!(he.euler_characteristic(), 2);
    assert!(!he.is_triangle_mesh());
    assert_eq!(he.faces(), cube_quads());
    assert!(he.vertex_ids().all(|v| he.valence(v) == 3));
    let report = TopologyReport::of(&he.to_indexed());
    assert!(report.is_closed_manifold());
    assert_eq!((report.faces, report.volume, report.area), (12, 1.0, 6.0));

    let (positions, quads) = torus_quads(8, 6);
    let he = HalfEdgeMesh::from_polygons(positions, &quads).unwrap();
    assert_eq!(he.validate(), Ok(()));
    assert_eq!(
        (he.vertex_count(), he.edge_count(), he.face_count()),
        (48, 96, 48)
    );
    assert_eq!(he.euler_characteristic(), 0);
    assert!(he.vertex_ids().all(|v| he.valence(v) == 4));
    assert_eq!(TopologyReport::of(&he.to_indexed()).genus, Some(1));
}

#[test]
fn pentagon_fan_triangulates() {
    let positions = (0..5)
        .map(|i| {
            let a = std::f64::consts::TAU * f64::from(i) / 5.0;
            glam::DVec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    let he = HalfEdgeMesh::from_polygons(positions, &[vec![0, 1, 2, 3, 4]]).unwrap();
    assert_eq!(he.validate(), Ok(()));
    assert_eq!(he.boundary_loop_count(), 1);
    assert_eq!(
        he.to_indexed().triangles,
        vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]
    );
}

#[test]
fn empty_mesh() {
    let he = build(&IndexedMesh::default());
    assert_eq!(
        (he.vertex_count(), he.face_count(), he.half_edge_count()),
        (0, 0, 0)
    );
    assert!(!he.is_closed());
    assert_eq!(he.euler_characteristic(), 0);
}

#[test]
fn validate_reports_corruption() {
    let good = build(&cube_hole());
    let corrupt = |edit: &dyn Fn(&mut HalfEdgeMesh)| {
        let mut mesh = good.clone();
        edit(&mut mesh);
        mesh.validate()
    };
    let h0 = HalfEdgeId(0);
    assert_eq!(
        corrupt(&|m| m.half_edges[0].twin = HalfEdgeId(999)),
        Err(ValidationError::DanglingId { half_edge: h0 })
    );
    assert_eq!(
        corrupt(&|m| m.half_edges[0].twin = h0),
        Err(ValidationError::SelfTwin { half_edge: h0 })
    );
    assert_eq!(
        corrupt(&|m| m.half_edges[0].twin = HalfEdgeId(1)),
        Err(ValidationError::TwinNotMutual { half_edge: h0 })
    );
    assert_eq!(
        corrupt(&|m| m.half_edges[1].prev = HalfEdgeId(2)),
        Err(ValidationError::NextPrevMismatch { half_edge: h0 })
    );
    assert_eq!(
        corrupt(&|m| m.half_edges[0].origin = VertexId(7)),
        Err(ValidationError::OriginMismatch {
            half_edge: HalfEdgeId(2)
        })
    );
    assert_eq!(
        corrupt(&|m| m.half_edges[1].face = Some(FaceId(5))),
        Err(ValidationError::FaceMismatch {
            face: FaceId(0),
            half_edge: HalfEdgeId(1)
        })
    );
    assert_eq!(
        corrupt(&|m| m.vertex_half_edge[0] = Some(HalfEdgeId(1))),
        Err(ValidationError::VertexMismatch {
            vertex: VertexId(0)
        })
    );
    assert_eq!(
        corrupt(&|m| m.vertex_half_edge[0] = None),
        Err(ValidationError::Unreachable { half_edge: h0 })
    );
}

#[test]
fn large_torus_builds() {
    let mesh = torus(300, 300);
    let he = build(&mesh);
    assert_eq!(he.face_count(), 180_000);
    assert_eq!(he.euler_characteristic(), 0);
    assert!(he.is_closed());
    assert!(TopologyReport::of(&mesh).is_closed_manifold());
}
