//! Tests of polygon meshes in files: polygons kept by the readers, round trips through OBJ, OFF
//! and PLY, triangulation for STL, and located errors.

use glam::DVec3;

use super::*;

const FACES_OBJ: &[u8] = include_bytes!("../../../fixtures/meshes/io/faces.obj");

/// The unit cube as six outward quads.
fn cube_quads() -> PolygonMesh {
    let positions = (0..8)
        .map(|i| DVec3::new(f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2)))
        .collect();
    let faces = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ]
    .iter()
    .map(|q| q.to_vec())
    .collect();
    PolygonMesh::new(positions, faces)
}

#[test]
fn readers_keep_polygons() {
    let m = read_polygon_mesh_bytes(FACES_OBJ, MeshFormat::Obj, "faces.obj").unwrap();
    let sizes: Vec<usize> = m.faces.iter().map(Vec::len).collect();
    assert_eq!(sizes, [4, 5, 6, 4]);
    // The triangle reader sees the same vertices and triangulates the same faces.
    let t = read_mesh_bytes(FACES_OBJ, MeshFormat::Obj, "faces.obj").unwrap();
    assert_eq!(t.positions, m.positions);
    assert_eq!(
        t.triangles.len(),
        sizes.iter().map(|n| n - 2).sum::<usize>()
    );
    let off = b"OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n4 0 1 2 3\n3 1 4 2\n";
    let m = read_polygon_mesh_bytes(off, MeshFormat::Off, "a.off").unwrap();
    assert_eq!(m.faces, [vec![0, 1, 2, 3], vec![1, 4, 2]]);
}

#[test]
fn polygons_round_trip_through_obj_off_and_ply() {
    let dir = tempfile::tempdir().unwrap();
    let mut cube = cube_quads();
    cube.positions[3].z = 0.1 + 0.2; // not exact in binary: must come back bit for bit
    for (name, encoding) in [
        ("c.obj", Encoding::Ascii),
        ("c.off", Encoding::Ascii),
        ("c.ply", Encoding::Binary),
        ("a.ply", Encoding::Ascii),
    ] {
        let path = dir.path().join(name);
        let opts = WriteOptions {
            format: None,
            encoding,
        };
        write_polygon_mesh_with(&path, &cube, &opts).unwrap();
        let back = read_polygon_mesh(&path).unwrap();
        // OBJ numbers vertices in order of first use: compare the faces' corner positions.
        let corners = |m: &PolygonMesh| -> Vec<Vec<DVec3>> {
            let at = |&i: &u32| m.positions[i as usize];
            m.faces.iter().map(|f| f.iter().map(at).collect()).collect()
        };
        assert_eq!(corners(&back), corners(&cube), "{name}");
        assert_eq!(back.positions.len(), 8, "{name}");
    }
}

#[test]
fn stl_gets_triangles_and_stays_closed() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("c.stl");
    write_polygon_mesh(&path, &cube_quads()).unwrap();
    let back = read_mesh(&path).unwrap();
    let report = crate::TopologyReport::of(&back);
    assert!(report.is_closed_manifold());
    assert_eq!((report.vertices, report.faces), (8, 12));
    assert!((report.volume - 1.0).abs() < 1e-12);
}

#[test]
fn bent_faces_still_triangulate_closed() {
    // A cube whose top quad is strongly bent stays a closed oriented manifold.
    let mut cube = cube_quads();
    cube.positions[7] += DVec3::new(0.0, 0.0, 3.0);
    let report = crate::TopologyReport::of(&cube.triangulated());
    assert!(report.is_closed_manifold() && report.oriented);
    assert_eq!(report.faces, 12);
}

/// The directed boundary edges of a set of triangles (edges not matched by a reversed one).
fn boundary(triangles: &[[u32; 3]]) -> std::collections::BTreeSet<(u32, u32)> {
    let directed: Vec<(u32, u32)> = triangles
        .iter()
        .flat_map(|&[a, b, c]| [(a, b), (b, c), (c, a)])
        .collect();
    directed
        .iter()
        .copied()
        .filter(|&(a, b)| !directed.contains(&(b, a)))
        .collect()
}

#[test]
fn faces_that_cannot_be_triangulated_in_their_plane_fall_back() {
    let hexagon: Vec<DVec3> = (0..6)
        .map(|k| {
            let a = std::f64::consts::TAU * f64::from(k) / 6.0;
            DVec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    // A twisted quad (its edges cross) and a self-crossing hexagon: no plane triangulation.
    for face in [vec![0, 1, 5, 4], vec![0, 2, 4, 1, 3, 5]] {
        let m = PolygonMesh::new(hexagon.clone(), vec![face.clone()]);
        let t = m.triangulated();
        let expected: std::collections::BTreeSet<(u32, u32)> = (0..face.len())
            .map(|k| (face[k], face[(k + 1) % face.len()]))
            .collect();
        assert_eq!(boundary(&t.triangles), expected, "{face:?}");
        if face.len() == 4 {
            assert_eq!((t.triangles.len(), t.positions.len()), (2, 6));
        } else {
            // Fanned around the added centroid.
            assert_eq!((t.triangles.len(), t.positions.len()), (6, 7));
            assert!(t.positions[6].length() < 1e-15);
        }
    }
}

#[test]
fn bad_polygons_are_located() {
    let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 1\n";
    let err = read_polygon_mesh_bytes(obj, MeshFormat::Obj, "r.obj")
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with("r.obj:5:") && err.contains("coincide"),
        "{err}"
    );
    let off = b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n";
    let err = read_polygon_mesh_bytes(off, MeshFormat::Off, "r.off")
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with("r.off:6:") && err.contains("3 needed"),
        "{err}"
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.obj");
    let bad = PolygonMesh::new(vec![DVec3::ZERO; 3], vec![vec![0, 1, 7]]);
    assert!(matches!(
        write_polygon_mesh(&path, &bad),
        Err(MeshIoError::InvalidMesh { .. })
    ));
    assert!(!path.exists());
}
