//! JSON format tests: lossless round trips of every node type and located, path-naming errors.

use crate::{KernelError, Solid, json};
use glam::DVec3;

fn every_node() -> Solid {
    Solid::union_all([
        Solid::sphere(0.1 + 0.2),
        Solid::cuboid(DVec3::new(1.0, 2.0, 1e-7)).translate(DVec3::new(
            -1.5,
            0.0,
            1.234_567_890_123e29,
        )),
        Solid::cylinder(0.5, 2.0).rotate(DVec3::new(1.0, 1.0, 0.0), 33.3),
        Solid::cone(1.0, 0.0, 2.0).scale(DVec3::new(1.0, 2.0, 3.0)),
        Solid::torus(1.0, 0.25).mirror(DVec3::Y),
        Solid::difference_all(
            Solid::cube(2.0),
            [Solid::half_space(DVec3::new(0.0, 0.6, 0.8), -0.1)],
        ),
        Solid::intersection_all([Solid::sphere(1.0).affine([
            [1.0, 0.2, 0.0, 0.5],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 2.0, -1.0],
        ])]),
        Solid::union_all([]),
    ])
}

#[test]
fn round_trip_is_lossless() {
    let s = every_node();
    let text = json::to_string(&s);
    let back = json::from_str(&text).unwrap();
    assert!(back == s, "{text}");
    assert_eq!(json::to_string(&back), text);
}

#[test]
fn bare_nodes_and_scalar_sizes_are_accepted() {
    let s = json::from_str(r#"{"type": "box", "size": 2}"#).unwrap();
    assert!(s == Solid::cube(2.0));
    let s = json::from_str(r#"{"type": "scale", "factor": 2, "child": {"type": "sphere", "radius": 1, "comment": "unit"}}"#).unwrap();
    assert!(s == Solid::sphere(1.0).scale_uniform(2.0));
}

fn error(text: &str) -> (usize, usize, String) {
    match json::from_str(text) {
        Err(KernelError::Json {
            line,
            column,
            message,
        }) => (line, column, message),
        other => panic!("expected a JSON error, got {other:?}"),
    }
}

#[test]
fn errors_name_line_column_and_path() {
    let text = "{\"format\": \"solidkit-tree\", \"version\": 1, \"root\":\n {\"type\": \"union\", \"children\": [\n  {\"type\": \"sphere\", \"radius\": 1},\n  {\"type\": \"sphere\", \"radius\": -2}]}}";
    assert_eq!(
        error(text),
        (
            4,
            32,
            "children[1].radius: expected a positive number".into()
        )
    );
    let (line, col, msg) = error("{\"type\": \"sphere\", \"radius\": NaN}");
    assert_eq!((line, col), (1, 30));
    assert!(msg.contains("NaN"), "{msg}");
    let (_, _, msg) = error(r#"{"type": "union", "children": [{"type": "spere", "radius": 1}]}"#);
    assert_eq!(msg, "children[0].type: unknown node type \"spere\"");
    let (_, _, msg) = error(
        r#"{"type": "translate", "offset": [1, 2], "child": {"type": "sphere", "radius": 1}}"#,
    );
    assert_eq!(msg, "offset: expected 3 numbers, found 2");
    let (_, _, msg) = error(r#"{"type": "cylinder", "radius": 1}"#);
    assert_eq!(msg, "root: missing key \"height\"");
    let (_, _, msg) = error(r#"{"type": "sphere", "radius": 1, "center": [0, 0, 0]}"#);
    assert!(msg.starts_with("center: unknown key"), "{msg}");
    let (_, _, msg) = error(r#"{"format": "solidkit-tree", "version": 2, "root": {}}"#);
    assert!(msg.contains("unsupported version 2"), "{msg}");
    let (_, _, msg) = error(
        r#"{"type": "scale", "factor": [1, 0, 1], "child": {"type": "sphere", "radius": 1}}"#,
    );
    assert!(msg.contains("singular"), "{msg}");
    let (line, _, msg) = error("{\"type\": \"sphere\",\n \"radius\": 1,,}");
    assert_eq!(line, 2);
    assert!(msg.contains("quoted object key"), "{msg}");
}

#[test]
fn blends_offsets_and_shells_round_trip_and_validate() {
    let s = Solid::smooth_union_all([Solid::sphere(1.0), Solid::cube(1.0)], 0.25)
        .offset(-0.05)
        .shell(0.1)
        .union(&Solid::smooth_difference_all(
            Solid::cube(2.0),
            [Solid::sphere(1.2)],
            0.1,
        ))
        .union(&Solid::smooth_intersection_all(
            [Solid::cube(2.0), Solid::sphere(1.2)],
            0.1,
        ));
    assert!(json::from_str(&json::to_string(&s)).unwrap() == s);
    let (_, _, msg) = error(r#"{"type": "smooth_union", "radius": 0, "children": []}"#);
    assert_eq!(msg, "radius: expected a positive number");
    let (_, _, msg) = error(
        r#"{"type": "shell", "thickness": 0.1, "child": {"type": "sphere", "radius": 1}, "children": []}"#,
    );
    assert!(msg.starts_with("children: unknown key"), "{msg}");
    assert!(Solid::sphere(1.0).shell(-1.0).validate().is_err());
    assert!(Solid::sphere(1.0).offset(f64::NAN).validate().is_err());
}

#[test]
fn new_curve_kinds_round_trip_as_paths_and_rails() {
    // A composite path (Hermite chain then a cubic_through piece, C0) and a radial profile.
    let text = r#"{"type": "union", "children": [
        {"type": "sweep", "profile": {"type": "radial", "rho": "0.1 + 0.02*cos(3*u)"},
         "path": {"type": "composite", "continuity": ["C0"], "pieces": [
            {"type": "hermite", "points": [[0, 0, 0], [1, 0, 1], [2, 1, 1]],
             "tangents": [[1, 0, 1], [1, 0, 0], [0, 1, 0]]},
            {"type": "cubic_through", "points": [[2, 1, 1], [2, 2, 1], [3, 2, 2], [3, 3, 3]]}]}},
        {"type": "ruled",
         "bottom": {"type": "nurbs", "degree": 2, "points": [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]],
                    "weights": [1, 0.7071067811865476, 1, 0.7071067811865476, 1, 0.7071067811865476, 1, 0.7071067811865476, 1],
                    "knots": [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]},
         "top": {"type": "composite", "continuity": "G1", "pieces": [
            {"type": "bezier", "points": [[0.5, 0, 1], [0.5, 0.5, 1], [-0.5, 0.5, 1], [-0.5, 0, 1]]},
            {"type": "bezier", "points": [[-0.5, 0, 1], [-0.5, -0.5, 1], [0.5, -0.5, 1], [0.5, 0, 1]]}]}}]}"#;
    let s = json::from_str(text).unwrap();
    let written = json::to_string(&s);
    assert!(written.contains("\"cubic_through\"") && written.contains("\"composite\""));
    let back = json::from_str(&written).unwrap();
    assert_eq!(json::to_string(&back), written);
    assert!(back == s);
}
