//! JSON tests of the polyhedral node types: lossless round trips (text and tree), mesh files
//! through a resolver, and errors located at the offending key and list item.

use super::{MeshResolver, MeshSolid, MeshSource};
use crate::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron, Prism};
use crate::primitive::{ResolveError, ResolveKind};
use crate::{IndexedMesh, KernelError, NodeKind, Primitive, Solid, json};
use glam::{DVec2, DVec3};

/// Serves a unit cube for `cube.obj` and fails for anything else.
struct CubeResolver;

impl MeshResolver for CubeResolver {
    fn load(&self, path: &str) -> Result<IndexedMesh, ResolveError> {
        if path == "cube.obj" {
            let cube = Polyhedron::platonic(PlatonicKind::Cube, PlatonicSize::Edge(1.0))
                .map_err(|e| ResolveError::new(ResolveKind::Format, e))?;
            Ok(cube.to_indexed())
        } else {
            Err(ResolveError::message(
                ResolveKind::File,
                format!("no such file: {path}"),
            ))
        }
    }
}

fn every_polyhedral_node() -> Solid {
    let tet = Polyhedron::platonic(PlatonicKind::Tetrahedron, PlatonicSize::Edge(1.0)).unwrap();
    let prism = Prism::new(
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ],
        vec![vec![
            DVec2::new(0.5, 0.5),
            DVec2::new(0.5, 1.5),
            DVec2::new(1.5, 1.5),
            DVec2::new(1.5, 0.5),
        ]],
        DVec3::new(0.1, 0.0, 1.0 / 3.0),
    );
    Solid::union_all([
        Solid::platonic(
            PlatonicKind::Icosahedron,
            PlatonicSize::Circumradius(0.1 + 0.2),
        ),
        Solid::platonic(PlatonicKind::Dodecahedron, PlatonicSize::Edge(1e-3)),
        Solid::from_polyhedron(&tet).translate(DVec3::X),
        Solid::prism(prism).unwrap(),
        Solid::prism(Prism::new(
            vec![DVec2::ZERO, DVec2::X, DVec2::Y],
            vec![],
            DVec3::NEG_Z,
        ))
        .unwrap(),
        Solid::mesh_file("cube.obj", &CubeResolver).unwrap(),
    ])
}

#[test]
fn polyhedral_nodes_round_trip_losslessly() {
    let s = every_polyhedral_node();
    let text = json::to_string(&s);
    let back = json::from_str_with(&text, &CubeResolver).unwrap();
    assert!(back == s, "{text}");
    assert_eq!(json::to_string(&back), text);
    for ty in ["platonic", "polyhedron", "prism", "mesh"] {
        assert!(text.contains(&format!("\"type\": \"{ty}\"")), "{text}");
    }
    assert!(
        text.contains("\"edge\": 0.001") && text.contains("\"circumradius\": 0.30000000000000004")
    );
    assert!(text.contains("\"path\": \"cube.obj\""));
}

#[test]
fn inline_polyhedron_reads_like_openscad() {
    let text = r#"{"type": "polyhedron",
        "vertices": [[0,0,0], [1,0,0], [1,1,0], [0,1,0], [0.5,0.5,1]],
        "faces": [[0,3,2,1], [0,1,4], [1,2,4], [2,3,4], [3,0,4]]}"#;
    let s = json::from_str(text).unwrap();
    let NodeKind::Primitive(Primitive::Mesh(m)) = s.kind() else {
        panic!("a mesh primitive")
    };
    assert_eq!(m.triangle_count(), 6);
    assert!(matches!(m.source(), MeshSource::Faces { faces, .. } if faces.len() == 5));
    assert!(s.value(DVec3::new(0.5, 0.5, 0.2)) < 0.0);
    assert!((s.value(DVec3::new(0.5, 0.5, -0.5)) - 0.5).abs() < 1e-12);
}

fn message(text: &str) -> String {
    match json::from_str_with(text, &CubeResolver) {
        Err(KernelError::Json { message, .. }) => message,
        other => panic!("expected a JSON error, got {other:?}"),
    }
}

#[test]
fn errors_name_the_key_and_item() {
    let m = message(r#"{"type": "platonic", "solid": "cubocta", "edge": 1}"#);
    assert!(m.starts_with("solid: unknown solid \"cubocta\""), "{m}");
    let m = message(r#"{"type": "platonic", "solid": "cube"}"#);
    assert_eq!(m, "root: missing key \"circumradius\" or \"edge\"");
    let m = message(r#"{"type": "platonic", "solid": "cube", "edge": 1, "circumradius": 1}"#);
    assert!(m.starts_with("edge: give either"), "{m}");
    let m = message(r#"{"type": "platonic", "solid": "cube", "edge": -1}"#);
    assert_eq!(m, "edge: expected a positive number");
    let m = message(
        r#"{"type": "union", "children": [{"type": "polyhedron", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2],[0,1,7]]}]}"#,
    );
    assert_eq!(
        m,
        "children[0].faces[1]: face 1 refers to vertex 7 but there are only 3 vertices"
    );
    let m = message(r#"{"type": "polyhedron", "vertices": [[0,0,0],[1,0]], "faces": [[0,1,2]]}"#);
    assert_eq!(m, "vertices[1]: expected 3 numbers, found 2");
    let m = message(
        r#"{"type": "polyhedron", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,-2]]}"#,
    );
    assert_eq!(m, "faces[0]: expected a vertex index, found -2");
    let m = message(r#"{"type": "mesh", "path": "missing.stl"}"#);
    assert_eq!(
        m,
        "path: cannot load \"missing.stl\": no such file: missing.stl"
    );
    let m = match json::from_str(r#"{"type": "mesh", "path": "cube.obj"}"#) {
        Err(KernelError::Json { message, .. }) => message,
        other => panic!("{other:?}"),
    };
    assert!(m.contains("need a resolver"), "{m}");
    let m = message(
        r#"{"type": "prism", "polygon": [[0,0],[1,0],[1,1],[0,1]], "holes": [[[2,2],[3,2],[3,3]]], "direction": [0,0,1]}"#,
    );
    assert_eq!(
        m,
        "holes: a hole is not inside the outer loop, or holes are nested"
    );
    let m = message(r#"{"type": "prism", "polygon": [[0,0],[1,0],[1,1]], "direction": [1,0,0]}"#);
    assert!(m.starts_with("direction:"), "{m}");
    let m = message(
        r#"{"type": "prism", "polygon": [[0,0],[1,0],[1,1]], "direction": [0,0,1], "height": 2}"#,
    );
    assert!(m.starts_with("height: unknown key"), "{m}");
}

#[test]
fn mesh_solids_compare_by_source() {
    let a = Solid::mesh_file("cube.obj", &CubeResolver).unwrap();
    let b = Solid::mesh_file("cube.obj", &CubeResolver).unwrap();
    assert!(a == b);
    let cube = Polyhedron::platonic(PlatonicKind::Cube, PlatonicSize::Edge(1.0)).unwrap();
    assert!(a != Solid::from_polyhedron(&cube));
    let NodeKind::Primitive(Primitive::Mesh(m)) = a.kind() else {
        panic!("a mesh primitive")
    };
    assert_eq!(m, &MeshSolid::from_file("cube.obj", &CubeResolver).unwrap());
}
