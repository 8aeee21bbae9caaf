//! Writing a [`Solid`] as JSON text with a work list (no recursion). Nodes are written one per line,
//! indented by depth (indentation stops growing past a fixed depth so deep chains stay linear in
//! size). Numbers are written in Rust's shortest round-trip form, so reading back gives the same
//! tree bit for bit.

use super::{FORMAT, VERSION};
use crate::primitive::Primitive;
use crate::solid::{NodeKind, Solid};
use crate::transform::TransformSpec;
use glam::DVec3;
use std::fmt::Write;

mod blob;
mod heightfield;
mod polyhedra;
mod quadric;
mod surface;
mod sweep;

const MAX_INDENT: usize = 16;

/// Writes the versioned envelope around the tree.
pub fn to_string(solid: &Solid) -> String {
    let mut out =
        format!("{{\n  \"format\": \"{FORMAT}\",\n  \"version\": {VERSION},\n  \"root\": ");
    write_node_tree(&mut out, solid, 1);
    out.push_str("\n}\n");
    out
}

/// A JSON string literal, with the characters JSON requires escaped.
pub(super) fn string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn num(x: f64) -> String {
    if x.is_finite() {
        format!("{x:?}")
    } else {
        "null".into()
    }
}

fn vec3(v: DVec3) -> String {
    format!("[{}, {}, {}]", num(v.x), num(v.y), num(v.z))
}

fn indent(out: &mut String, depth: usize) {
    for _ in 0..depth.min(MAX_INDENT) {
        out.push_str("  ");
    }
}

/// The `"type"` and parameter members of a node, without braces.
fn members(kind: &NodeKind) -> String {
    let ty = kind.name();
    let params = match kind {
        NodeKind::Primitive(p) => match p {
            Primitive::Sphere(s) => format!("\"radius\": {}", num(s.radius)),
            Primitive::Cuboid(b) => format!("\"size\": {}", vec3(b.size)),
            Primitive::Cylinder(c) => format!(
                "\"radius\": {}, \"height\": {}",
                num(c.radius),
                num(c.height)
            ),
            Primitive::Cone(c) => format!(
                "\"bottom_radius\": {}, \"top_radius\": {}, \"height\": {}",
                num(c.bottom_radius),
                num(c.top_radius),
                num(c.height)
            ),
            Primitive::Torus(t) => format!(
                "\"major_radius\": {}, \"minor_radius\": {}",
                num(t.major_radius),
                num(t.minor_radius)
            ),
            Primitive::HalfSpace(h) => format!(
                "\"normal\": {}, \"offset\": {}",
                vec3(h.normal),
                num(h.offset)
            ),
            Primitive::Gyroid(g) => format!("\"thickness\": {}", num(g.thickness)),
            Primitive::Ellipsoid(e) => format!("\"radii\": {}", vec3(e.radii)),
            Primitive::Quadric(q) => quadric::members(q),
            Primitive::Blob(b) => blob::members(b),
            Primitive::HeightField(h) => heightfield::members(h),
            Primitive::Platonic(p) => polyhedra::platonic(p),
            Primitive::Mesh(m) => polyhedra::mesh(m),
            Primitive::Extrude(e) => sweep::extrude(e),
            Primitive::Revolve(r) => sweep::revolve(r),
            Primitive::Sweep(s) => sweep::sweep(s),
            Primitive::Loft(l) => sweep::loft(l),
            Primitive::Ruled(r) => sweep::ruled(r),
            Primitive::RuledSurface(r) => sweep::ruled_surface(r),
            Primitive::Expr(e) => format!(
                "\"formula\": {}, \"bounds\": [{}, {}]",
                string(e.formula()),
                vec3(e.bounds().min),
                vec3(e.bounds().max)
            ),
        },
        NodeKind::Union | NodeKind::Intersection | NodeKind::Difference => String::new(),
        NodeKind::SmoothUnion { radius }
        | NodeKind::SmoothIntersection { radius }
        | NodeKind::SmoothDifference { radius } => format!("\"radius\": {}", num(*radius)),
        NodeKind::Offset { distance } => format!("\"distance\": {}", num(*distance)),
        NodeKind::Shell { thickness } => format!("\"thickness\": {}", num(*thickness)),
        NodeKind::Color(c) => format!("\"color\": [{}]", c.0.map(|x| num(f64::from(x))).join(", ")),
        NodeKind::Transform(t) => match t.spec {
            TransformSpec::Translate(v) => format!("\"offset\": {}", vec3(v)),
            TransformSpec::Rotate { axis, degrees } => {
                format!("\"axis\": {}, \"degrees\": {}", vec3(axis), num(degrees))
            }
            TransformSpec::Scale(v) => format!("\"factor\": {}", vec3(v)),
            TransformSpec::Mirror(v) => format!("\"normal\": {}", vec3(v)),
            TransformSpec::Affine(rows) => {
                let r: Vec<String> = rows
                    .iter()
                    .map(|row| format!("[{}]", row.map(num).join(", ")))
                    .collect();
                format!("\"matrix\": [{}]", r.join(", "))
            }
        },
    };
    if params.is_empty() {
        format!("\"type\": \"{ty}\"")
    } else {
        format!("\"type\": \"{ty}\", {params}")
    }
}

/// Writes `root` and its subtree at indentation `base`.
fn write_node_tree(out: &mut String, root: &Solid, base: usize) {
    // Frames: a node and how many of its children have been written.
    let mut frames: Vec<(&Solid, usize)> = vec![(root, 0)];
    loop {
        let depth = base + frames.len().saturating_sub(1);
        let Some(top) = frames.last_mut() else { break };
        let (solid, next) = *top;
        let is_transform = solid.kind().is_unary();
        let is_leaf = matches!(solid.kind(), NodeKind::Primitive(_));
        if next == 0 {
            let _ = write!(out, "{{{}", members(solid.kind()));
            if is_leaf {
                out.push('}');
                frames.pop();
                continue;
            }
            out.push_str(if is_transform {
                ", \"child\": "
            } else {
                ", \"children\": ["
            });
        }
        if let Some(child) = solid.children().get(next) {
            top.1 += 1;
            if !is_transform {
                if next > 0 {
                    out.push(',');
                }
                out.push('\n');
                indent(out, depth + 1);
            }
            frames.push((child, 0));
            continue;
        }
        if !is_transform {
            if !solid.children().is_empty() {
                out.push('\n');
                indent(out, depth);
            }
            out.push(']');
        }
        out.push('}');
        frames.pop();
    }
}
