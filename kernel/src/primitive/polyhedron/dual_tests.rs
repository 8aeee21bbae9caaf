//! The `dual` node: JSON round trip, the dual of every Platonic solid against the closed forms of
//! its dual kind (volume, V, E, F), the field's zero set on the dual's vertices, and located errors.

use crate::KernelError;
use crate::json;
use crate::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron};
use crate::primitive::{MeshSource, NoMeshResolver, Primitive};
use crate::solid::{NodeKind, Solid};

fn read(text: &str) -> Result<Solid, String> {
    json::from_str(text).map_err(|e| match e {
        KernelError::Json { message, .. } => message,
        other => other.to_string(),
    })
}

fn mesh_of(s: &Solid) -> &crate::primitive::MeshSolid {
    match s.kind() {
        NodeKind::Primitive(Primitive::Mesh(m)) => m,
        other => panic!("not a mesh: {}", other.name()),
    }
}

#[test]
fn the_dual_of_each_platonic_solid_is_its_dual_kind() {
    for kind in PlatonicKind::ALL {
        let edge = 1.7;
        let text = format!(
            r#"{{"type": "dual", "child": {{"type": "platonic", "solid": "{}", "edge": {edge}}}}}"#,
            kind.name()
        );
        let s = read(&text).unwrap();
        let m = mesh_of(&s);
        assert!(matches!(m.source(), MeshSource::Dual { .. }));
        assert_eq!(m.name(), "dual");
        assert_eq!(m.open_edges(), 0, "{}", kind.name());
        // The exact dual polyhedron, and the closed forms of the dual kind at the dual edge.
        let p = Polyhedron::platonic(kind, PlatonicSize::Edge(edge)).unwrap();
        let d = p.dual().unwrap();
        let measures = kind.dual().unit_measures();
        let a = kind.dual_edge(edge);
        let expected = measures.volume * a.powi(3);
        assert!(
            (d.volume() - expected).abs() < 1e-12 * expected,
            "{}: {} vs {expected}",
            kind.name(),
            d.volume()
        );
        assert_eq!(
            [d.vertex_count(), d.edge_count(), d.face_count()],
            measures.counts
        );
        // Dual vertices (the child's face centroids) are on the zero set, the centre is inside
        // at the dual's inradius, and a point beyond a dual vertex is outside by its distance.
        for v in d.vertices() {
            assert!(
                s.value(*v).abs() < 1e-12,
                "{}: {}",
                kind.name(),
                s.value(*v)
            );
            let out = *v * 1.25;
            assert!((s.value(out) - 0.25 * v.length()).abs() < 1e-9);
        }
        let inradius = measures.inradius * a;
        assert!((s.value(glam::DVec3::ZERO) + inradius).abs() < 1e-9);
        // The triangle count is the dual faces' triangulation.
        assert_eq!(m.triangle_count(), d.triangles().len());
    }
}

#[test]
fn dual_nodes_round_trip_losslessly() {
    let prism = r#"{"type": "dual", "child": {"type": "prism", "polygon": [[0, 0], [2, 0], [1, 1.5]], "direction": [0, 0, 1]}}"#;
    let tet = r#"{"type": "dual", "child": {"type": "polyhedron", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "faces": [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]}}"#;
    let ico_child = r#"{"type": "platonic", "solid": "icosahedron", "circumradius": 2}"#;
    let ico = &format!(r#"{{"type": "dual", "child": {ico_child}}}"#);
    let text = format!(r#"{{"type": "union", "children": [{prism}, {tet}, {ico}]}}"#);
    let s = read(&text).unwrap();
    let written = json::to_string(&s);
    let back = read(&written).unwrap();
    assert!(back == s, "{written}");
    assert_eq!(json::to_string(&back), written);
    assert!(written.contains(r#"{"type": "dual", "child": {"type": "platonic", "solid": "icosahedron", "circumradius": 2"#), "{written}");
    // The dual of a triangular prism is a triangular bipyramid: 5 vertices, 9 edges, 6 faces,
    // so 6 triangles.
    let NodeKind::Union = s.kind() else { panic!() };
    let prism = read(prism).unwrap();
    assert_eq!(mesh_of(&prism).triangle_count(), 6);
    // Through the Rust API: the same solid.
    let child = read(ico_child).unwrap();
    assert!(child.dual(&NoMeshResolver).unwrap() == read(ico).unwrap());
}

#[test]
fn errors_name_the_child() {
    let cases = [
        (
            r#"{"type": "dual", "child": {"type": "sphere", "radius": 1}}"#,
            "dual needs a polyhedron",
        ),
        (
            r#"{"type": "dual", "child": {"type": "dual", "child": {"type": "platonic", "solid": "cube", "edge": 1}}}"#,
            "found dual",
        ),
        // An L-shaped prism is not convex.
        (
            r#"{"type": "dual", "child": {"type": "prism", "polygon": [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], "direction": [0, 0, 1]}}"#,
            "convex",
        ),
        // One face missing: not closed.
        (
            r#"{"type": "dual", "child": {"type": "polyhedron", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "faces": [[0, 2, 1], [0, 1, 3], [0, 3, 2]]}}"#,
            "edge",
        ),
        (
            r#"{"type": "dual", "child": {"type": "platonic", "solid": "cube", "edge": 1}, "levels": 2}"#,
            "unknown key \"levels\"",
        ),
        (r#"{"type": "dual"}"#, "missing key \"child\""),
        (
            r#"{"type": "dual", "child": {"type": "mesh", "path": "cube.obj"}}"#,
            "cannot load",
        ),
    ];
    for (text, expected) in cases {
        let e = read(text).unwrap_err();
        assert!(e.contains(expected), "{text}: {e}");
    }
    let e = read(cases[0].0).unwrap_err();
    assert!(e.contains("child"), "{e}");
}
