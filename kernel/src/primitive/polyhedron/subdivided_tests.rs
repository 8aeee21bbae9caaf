//! JSON tests of the `subdivide` node with a stand-in resolver (the real subdivision lives in
//! `solidkit-meshing`): lossless round trips, what the resolver is asked, and located errors.

use super::{MeshResolver, SubdivisionInput, SubdivisionRequest, SubdivisionScheme};
use crate::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron, Prism};
use crate::primitive::{ResolveError, ResolveKind};
use crate::{IndexedMesh, KernelError, Solid, json};
use glam::{DVec2, DVec3};

/// Serves `cube.obj`; "subdivides" by fanning the faces and shrinking by 2^levels, and refuses
/// Loop on anything but triangles, like the real one.
struct Shrink;

impl MeshResolver for Shrink {
    fn load(&self, path: &str) -> Result<IndexedMesh, ResolveError> {
        match path {
            "cube.obj" => Ok(cube().to_indexed()),
            _ => Err(ResolveError::message(
                ResolveKind::File,
                format!("no such file: {path}"),
            )),
        }
    }

    fn subdivide(&self, request: &SubdivisionRequest<'_>) -> Result<IndexedMesh, ResolveError> {
        let cube = cube();
        let (vertices, faces) = match request.input {
            SubdivisionInput::Faces { vertices, faces } => (vertices, faces),
            SubdivisionInput::File { path: "cube.obj" } => (cube.vertices(), cube.faces()),
            SubdivisionInput::File { path } => {
                return Err(ResolveError::message(
                    ResolveKind::File,
                    format!("no such file: {path}"),
                ));
            }
        };
        if request.scheme.needs_triangles() && faces.iter().any(|f| f.len() != 3) {
            return Err(ResolveError::message(
                ResolveKind::Subdivision,
                format!("{} needs triangles", request.scheme),
            ));
        }
        let scale = 0.5f64.powi(request.levels as i32);
        let mut triangles = Vec::new();
        for f in faces {
            for k in 1..f.len() - 1 {
                triangles.push([f[0], f[k], f[k + 1]]);
            }
        }
        let positions = vertices.iter().map(|&p| p * scale).collect();
        Ok(IndexedMesh::new(positions, triangles))
    }
}

fn cube() -> Polyhedron {
    Polyhedron::platonic(PlatonicKind::Cube, PlatonicSize::Edge(2.0)).unwrap()
}

fn read(text: &str) -> Result<Solid, String> {
    json::from_str_with(text, &Shrink).map_err(|e| match e {
        KernelError::Json { message, .. } => message,
        other => other.to_string(),
    })
}

#[test]
fn subdivide_nodes_round_trip_losslessly() {
    let tet = Polyhedron::platonic(PlatonicKind::Tetrahedron, PlatonicSize::Edge(1.0)).unwrap();
    let prism = Prism::new(
        vec![DVec2::ZERO, DVec2::X, DVec2::new(0.3, 0.7)],
        vec![],
        DVec3::Z,
    );
    let parts = [
        (
            Solid::platonic(PlatonicKind::Cube, PlatonicSize::Edge(2.0)),
            SubdivisionScheme::CatmullClark,
            2,
        ),
        (Solid::from_polyhedron(&tet), SubdivisionScheme::Loop, 1),
        (Solid::prism(prism).unwrap(), SubdivisionScheme::DooSabin, 0),
        (
            Solid::mesh_file("cube.obj", &Shrink).unwrap(),
            SubdivisionScheme::CatmullClark,
            3,
        ),
        (
            Solid::platonic(PlatonicKind::Icosahedron, PlatonicSize::Circumradius(1.0)),
            SubdivisionScheme::Butterfly,
            1,
        ),
    ];
    let s = Solid::union_all(
        parts
            .iter()
            .map(|(child, scheme, levels)| child.subdivide(*scheme, *levels, &Shrink).unwrap()),
    );
    let text = json::to_string(&s);
    let back = json::from_str_with(&text, &Shrink).unwrap();
    assert!(back == s, "{text}");
    assert_eq!(json::to_string(&back), text);
    for part in [
        r#"{"type": "subdivide", "scheme": "catmull-clark", "levels": 2, "child": {"type": "platonic", "solid": "cube", "edge": 2.0}}"#,
        r#""scheme": "loop", "levels": 1, "child": {"type": "polyhedron", "vertices""#,
        r#""scheme": "doo-sabin", "levels": 0, "child": {"type": "prism", "polygon""#,
        r#"{"type": "subdivide", "scheme": "catmull-clark", "levels": 3, "child": {"type": "mesh", "path": "cube.obj"}}"#,
        r#""scheme": "butterfly", "levels": 1, "child": {"type": "platonic", "solid": "icosahedron""#,
    ] {
        assert!(text.contains(part), "{part} not in {text}");
    }
    // The adaptive tolerance is read, written back and makes a different solid.
    let adaptive = r#"{"type": "subdivide", "scheme": "loop", "levels": 2, "adaptive": 0.01, "child": {"type": "platonic", "solid": "icosahedron", "circumradius": 1}}"#;
    let t = read(adaptive).unwrap();
    let written = json::to_string(&t);
    assert!(
        written.contains(r#""levels": 2, "adaptive": 0.01, "child""#),
        "{written}"
    );
    assert!(json::from_str_with(&written, &Shrink).unwrap() == t);
    assert!(t != read(&adaptive.replace(r#""adaptive": 0.01, "#, "")).unwrap());
    for bad in ["0", "-1", "\"x\""] {
        let e = read(&adaptive.replace("0.01", bad))
            .unwrap_err()
            .to_string();
        assert!(e.contains("adaptive"), "{e}");
    }
    // Different levels or schemes are different solids.
    let a = read(r#"{"type": "subdivide", "scheme": "catmull-clark", "levels": 1, "child": {"type": "platonic", "solid": "cube", "edge": 2}}"#).unwrap();
    let b = read(r#"{"type": "subdivide", "scheme": "catmull-clark", "levels": 2, "child": {"type": "platonic", "solid": "cube", "edge": 2}}"#).unwrap();
    let c = read(r#"{"type": "subdivide", "scheme": "doo-sabin", "levels": 1, "child": {"type": "platonic", "solid": "cube", "edge": 2}}"#).unwrap();
    assert!(a != b && a != c);
}

#[test]
fn the_resolver_gets_the_childs_polygons() {
    // A cube of edge 2 shrunk twice by the stand-in: the surface is at 0.25 from the centre.
    let s = read(r#"{"type": "subdivide", "scheme": "catmull-clark", "levels": 2, "child": {"type": "platonic", "solid": "cube", "edge": 2}}"#).unwrap();
    assert!(s.value(DVec3::ZERO) < 0.0);
    assert!((s.value(DVec3::new(0.75, 0.0, 0.0)) - 0.5).abs() < 1e-12);
    let s = read(r#"{"type": "subdivide", "scheme": "doo-sabin", "levels": 1, "child": {"type": "mesh", "path": "cube.obj"}}"#).unwrap();
    assert!((s.value(DVec3::new(1.0, 0.0, 0.0)) - 0.5).abs() < 1e-12);
}

#[test]
fn errors_name_the_key() {
    let cube = r#"{"type": "platonic", "solid": "cube", "edge": 2}"#;
    let node = |rest: &str| format!(r#"{{"type": "subdivide", {rest}}}"#);
    let m = read(&node(&format!(
        r#""scheme": "catmull", "levels": 1, "child": {cube}"#
    )));
    assert_eq!(
        m.unwrap_err(),
        "scheme: unknown scheme \"catmull\" (expected one of: catmull-clark, loop, butterfly, doo-sabin)"
    );
    for (levels, found) in [("-1", "-1"), ("1.5", "1.5"), ("\"two\"", "string")] {
        let m = read(&node(&format!(
            r#""scheme": "loop", "levels": {levels}, "child": {cube}"#
        )));
        let m = m.unwrap_err();
        assert!(
            m.starts_with("levels: expected a whole number") && m.contains(found),
            "{m}"
        );
    }
    let m = read(&node(
        r#""scheme": "loop", "levels": 1, "child": {"type": "sphere", "radius": 1}"#,
    ));
    assert!(
        m.unwrap_err()
            .starts_with("child: subdivide needs a polyhedron, mesh, prism or platonic child")
    );
    let inner = node(&format!(
        r#""scheme": "doo-sabin", "levels": 1, "child": {cube}"#
    ));
    let m = read(&node(&format!(
        r#""scheme": "loop", "levels": 1, "child": {inner}"#
    )));
    let m = m.unwrap_err();
    assert!(
        m.starts_with("child: subdivide needs") && m.ends_with("found subdivide"),
        "{m}"
    );
    let m = read(&node(r#""scheme": "loop", "levels": 1"#));
    assert_eq!(m.unwrap_err(), "root: missing key \"child\"");
    let m = read(&node(&format!(
        r#""scheme": "loop", "levels": 1, "depth": 2, "child": {cube}"#
    )));
    assert!(m.unwrap_err().starts_with("depth: unknown key \"depth\""));
    // The resolver's refusal, located at the node.
    let m = read(&format!(
        r#"{{"type": "union", "children": [{}]}}"#,
        node(&format!(
            r#""scheme": "loop", "levels": 1, "child": {cube}"#
        ))
    ));
    assert_eq!(m.unwrap_err(), "children[0]: loop needs triangles");
    // Without a resolver that subdivides.
    let m = match json::from_str(&node(&format!(
        r#""scheme": "loop", "levels": 1, "child": {cube}"#
    ))) {
        Err(KernelError::Json { message, .. }) => message,
        other => panic!("{other:?}"),
    };
    assert!(m.starts_with("root: subdivision needs a resolver"), "{m}");
}
