//! Writing the polyhedral node types back as they were read: `platonic` with the size key that
//! was given, `polyhedron` with its vertices and faces, `mesh` with its path, `prism` with its
//! polygon, holes (when there are any) and direction, `subdivide` with its scheme, levels and
//! polyhedral child, `dual` with its polyhedral child.

use super::{num, string, vec3};
use crate::primitive::{MeshSolid, MeshSource, Platonic};
use crate::solid::NodeKind;
use glam::DVec2;

/// The parameter members of a `platonic` node.
pub(super) fn platonic(p: &Platonic) -> String {
    format!(
        "\"solid\": \"{}\", \"{}\": {}",
        p.kind.name(),
        p.size.parameter(),
        num(p.size.value())
    )
}

/// The parameter members of a mesh-backed node (`polyhedron`, `mesh` or `prism`).
pub(super) fn mesh(m: &MeshSolid) -> String {
    match m.source() {
        MeshSource::Faces { vertices, faces } => {
            let v: Vec<String> = vertices.iter().map(|p| vec3(*p)).collect();
            let f: Vec<String> = faces
                .iter()
                .map(|f| {
                    let i: Vec<String> = f.iter().map(u32::to_string).collect();
                    format!("[{}]", i.join(", "))
                })
                .collect();
            format!(
                "\"vertices\": [{}], \"faces\": [{}]",
                v.join(", "),
                f.join(", ")
            )
        }
        MeshSource::File { path } => format!("\"path\": {}", string(path)),
        MeshSource::Prism(p) => {
            let mut s = format!("\"polygon\": {}", points2(&p.polygon));
            if !p.holes.is_empty() {
                let h: Vec<String> = p.holes.iter().map(|h| points2(h)).collect();
                s += &format!(", \"holes\": [{}]", h.join(", "));
            }
            s + &format!(", \"direction\": {}", vec3(p.direction))
        }
        MeshSource::Subdivided {
            scheme,
            levels,
            adaptive,
            child,
        } => {
            // The child is a polyhedral leaf (never itself subdivided): one fixed nesting level.
            let child = super::members(&NodeKind::Primitive((**child).clone()));
            let adaptive =
                adaptive.map_or(String::new(), |t| format!(", \"adaptive\": {}", num(t)));
            format!(
                "\"scheme\": \"{scheme}\", \"levels\": {levels}{adaptive}, \"child\": {{{child}}}"
            )
        }
        MeshSource::Surface(spec) => super::surface::members(spec),
        MeshSource::Dual { child } => {
            // The child is a polyhedral leaf (never itself a dual): one fixed nesting level.
            let child = super::members(&NodeKind::Primitive((**child).clone()));
            format!("\"child\": {{{child}}}")
        }
    }
}

fn points2(points: &[DVec2]) -> String {
    let p: Vec<String> = points
        .iter()
        .map(|p| format!("[{}, {}]", num(p.x), num(p.y)))
        .collect();
    format!("[{}]", p.join(", "))
}
