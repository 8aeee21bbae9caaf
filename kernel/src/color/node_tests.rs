//! Colour nodes: JSON round trips, geometry unchanged, innermost colour wins.

use super::Rgba;
use crate::Solid;
use glam::DVec3;

fn red() -> Rgba {
    Rgba::parse("red").unwrap()
}

fn blue() -> Rgba {
    Rgba::parse("blue").unwrap()
}

#[test]
fn a_color_node_lowers_to_its_child_unchanged() {
    let plain = Solid::cube(10.0).difference(&Solid::sphere(6.5).translate(DVec3::X));
    let painted = Solid::cube(10.0)
        .color(red())
        .difference(&Solid::sphere(6.5).color(blue()).translate(DVec3::X))
        .color(Rgba::rgb(0.0, 1.0, 0.0));
    painted.validate().unwrap();
    let (a, b) = (plain.compile(), painted.compile());
    assert_eq!(format!("{:?}", a.instrs()), format!("{:?}", b.instrs()));
    assert_eq!(plain.bbox(), painted.bbox());
    for p in [DVec3::ZERO, DVec3::splat(4.9), DVec3::new(5.0, 0.3, -2.0)] {
        assert_eq!(a.value(p).to_bits(), b.value(p).to_bits());
    }
    assert!(!plain.has_color() && painted.has_color());
    assert!(plain.colored_parts().is_none());
}

#[test]
fn the_innermost_color_wins_and_transforms_are_carried() {
    let tree = Solid::union_all([
        Solid::sphere(1.0)
            .color(red())
            .translate(DVec3::new(5.0, 0.0, 0.0))
            .color(blue()),
        Solid::cube(1.0)
            .translate(DVec3::new(0.0, 5.0, 0.0))
            .color(blue()),
        Solid::torus(2.0, 0.5),
    ]);
    let parts = tree.colored_parts().unwrap();
    assert_eq!(parts.len(), 3);
    assert_eq!(parts[0].color, Some(red()));
    assert_eq!(parts[1].color, Some(blue()));
    assert_eq!(parts[2].color, None);
    // the sphere part is in world coordinates: its centre is at x = 5
    assert!(parts[0].solid.compile().value(DVec3::new(5.0, 0.0, 0.0)) < -0.99);
    assert!(parts[1].solid.compile().value(DVec3::new(0.0, 5.0, 0.0)) < -0.49);
}

#[test]
fn json_reads_and_writes_color_nodes() {
    let text = r##"{"format": "solidkit-tree", "version": 1, "root": {"type": "union", "children": [
        {"type": "color", "color": [1, 0.5, 0], "child": {"type": "sphere", "radius": 1}},
        {"type": "color", "color": "#0000ff80", "child": {"type": "box", "size": [1, 1, 1]}},
        {"type": "color", "color": "SteelBlue", "child": {"type": "box", "size": [2, 2, 2]}},
        {"type": "color", "color": [0, 0, 0, 0.25], "child": {"type": "sphere", "radius": 3}}]}}"##;
    let tree = crate::json::from_str(text).unwrap();
    let parts = tree.colored_parts().unwrap();
    assert_eq!(parts[0].color.unwrap().to_u8(), [255, 128, 0, 255]);
    assert_eq!(parts[1].color.unwrap().to_u8(), [0, 0, 255, 128]);
    assert_eq!(parts[2].color.unwrap().to_u8(), [70, 130, 180, 255]);
    assert_eq!(parts[3].color.unwrap().0[3], 0.25);
    let back = crate::json::from_str(&crate::json::to_string(&tree)).unwrap();
    assert!(back == tree, "lossless round trip");
    for (bad, needle) in [
        (r#""color": "nocolour""#, "unknown colour"),
        (r#""color": [1, 2, 0]"#, "between 0 and 1"),
        (r#""color": [1, 0]"#, "expected [r, g, b]"),
        (r#""color": 3"#, "expected [r, g, b]"),
    ] {
        let text = format!(
            r#"{{"format": "solidkit-tree", "version": 1, "root": {{"type": "color", {bad}, "child": {{"type": "sphere", "radius": 1}}}}}}"#
        );
        let e = crate::json::from_str(&text).unwrap_err().to_string();
        assert!(e.contains(needle) && e.contains("color"), "{e}");
    }
    let bad = crate::Solid::sphere(1.0).color(Rgba([2.0, 0.0, 0.0, 1.0]));
    assert!(bad.validate().is_err());
}

#[test]
fn the_skeleton_pushes_negations_to_the_parts_and_merges_equal_extrema() {
    use super::Operand::{Node, Part};
    let ball = |x: f64| Solid::sphere(1.0).translate(DVec3::new(x, 0.0, 0.0));
    // (a ∪ (b ∪ c)) − (d ∪ (e ∩ f)) = max(min(a, b, c), −d, min(−e, −f))
    let tree = Solid::union_all([ball(0.0), ball(1.0).union(&ball(2.0))])
        .color(red())
        .difference(
            &ball(3.0)
                .union(&ball(4.0).intersection(&ball(5.0)).color(blue()))
                .translate(DVec3::Z),
        );
    let s = tree.color_skeleton().unwrap();
    assert_eq!(s.parts.len(), 6);
    assert_eq!(s.root, Node(0));
    let part = |index, negated| Part { index, negated };
    assert!(s.nodes[0].max);
    assert_eq!(s.nodes[0].operands, vec![Node(1), part(3, true), Node(2)]);
    assert!(!s.nodes[1].max);
    assert_eq!(
        s.nodes[1].operands,
        vec![part(0, false), part(1, false), part(2, false)]
    );
    assert!(!s.nodes[2].max);
    assert_eq!(s.nodes[2].operands, vec![part(4, true), part(5, true)]);
    // colours and transforms reach the parts
    assert_eq!(s.parts[0].color, Some(red()));
    assert_eq!(s.parts[3].color, None);
    assert_eq!(s.parts[5].color, Some(blue()));
    assert!(s.parts[5].solid.compile().value(DVec3::new(5.0, 0.0, 1.0)) < -0.99);
    // the skeleton's value is the tree's field
    let program = tree.compile();
    let fields: Vec<_> = s.parts.iter().map(|p| p.solid.compile()).collect();
    for p in [
        DVec3::ZERO,
        DVec3::new(3.2, 0.1, 0.9),
        DVec3::new(4.6, 0.0, 1.0),
    ] {
        let v = |op: super::Operand| match op {
            Part { index, negated } => {
                let f = fields[index as usize].value(p);
                if negated { -f } else { f }
            }
            Node(_) => unreachable!(),
        };
        let min = |n: usize| {
            s.nodes[n]
                .operands
                .iter()
                .map(|&o| v(o))
                .fold(f64::INFINITY, f64::min)
        };
        let root = min(1).max(v(part(3, true))).max(min(2));
        assert_eq!(root.to_bits(), program.value(p).to_bits(), "{p}");
    }
    // one painted part is the root itself
    let one = Solid::sphere(1.0).color(red()).color_skeleton().unwrap();
    assert_eq!(one.root, part(0, false));
    assert!(one.nodes.is_empty());
}
