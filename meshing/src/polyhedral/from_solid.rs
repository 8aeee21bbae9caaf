//! A solid tree as a [`Polyhedral`] solid, where every leaf is a polyhedron (a box, a mesh
//! solid: `polyhedron`, `mesh`, `prism`, `dual`, `subdivide`; a height field of flat quads,
//! OpenSCAD's `surface`) under affine transforms, Booleans and colours. Post-order over an explicit stack: any depth is safe.

use super::{Polyhedral, PolyhedralError, difference, intersection_all, union_all};
use solidkit_kernel::NodeKind;
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::Primitive;

/// Why a tree has no polyhedral form: the first node that is not a polyhedron (by its JSON
/// name), or the Boolean that failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NotPolyhedral {
    /// A node whose surface is not made of flat faces (a sphere, a blend, a blob, an offset).
    #[error("`{0}` is not a polyhedron")]
    Node(String),
    /// A polyhedral leaf or Boolean failed.
    #[error(transparent)]
    Failed(#[from] PolyhedralError),
}

/// The leaf's polyhedron, or why it has none.
fn leaf(p: &Primitive) -> Result<Polyhedral, NotPolyhedral> {
    match p {
        Primitive::Cuboid(c) => Ok(Polyhedral::cuboid(-c.size / 2.0, c.size)?),
        Primitive::Mesh(m) => Ok(Polyhedral::from_mesh(&m.to_indexed())?),
        // OpenSCAD's `surface()`: flat triangles, so exactly a polyhedron.
        Primitive::HeightField(h) => match h.quad_mesh() {
            Some((v, t)) => Ok(Polyhedral::from_mesh(&solidkit_kernel::IndexedMesh::new(
                v, t,
            ))?),
            None => Err(NotPolyhedral::Node(p.name().to_string())),
        },
        other => Err(NotPolyhedral::Node(other.name().to_string())),
    }
}

/// The tree as one polyhedral solid, or the first node that has no polyhedral form.
pub fn from_solid(solid: &Solid) -> Result<Polyhedral, NotPolyhedral> {
    from_solid_gridding(solid, None).map(|(p, _)| p)
}

/// The tree as one polyhedral solid; with `grid`, a node that has no polyhedral form (a leaf, or
/// an operation that is not a Boolean, a transform or a colour) is meshed by marching cubes with
/// that many cells along its own longest side ([`Polyhedral::gridded`]) instead of failing the
/// tree, and named in the returned warnings (one per node, by its JSON name).
pub fn from_solid_gridding(
    solid: &Solid,
    grid: Option<usize>,
) -> Result<(Polyhedral, Vec<String>), NotPolyhedral> {
    let mut warnings = Vec::new();
    let mut gridded = |s: &Solid, name: &str| -> Result<Polyhedral, NotPolyhedral> {
        let Some(resolution) = grid else {
            return Err(NotPolyhedral::Node(name.to_string()));
        };
        let p = Polyhedral::gridded(s, resolution)?;
        warnings.push(format!(
            "`{name}` is not a polyhedron: meshed on a grid of {resolution} cells along its \
             longest side, then combined exactly with the rest"
        ));
        Ok(p)
    };
    // (node, children done); results stack up in post-order.
    let mut work: Vec<(&Solid, bool)> = vec![(solid, false)];
    let mut done: Vec<Polyhedral> = Vec::new();
    while let Some((s, expanded)) = work.pop() {
        let kids = s.children();
        if !expanded {
            let combines = matches!(
                s.kind(),
                NodeKind::Union
                    | NodeKind::Color(_)
                    | NodeKind::Intersection
                    | NodeKind::Difference
                    | NodeKind::Transform(_)
            );
            match s.kind() {
                NodeKind::Primitive(p) => done.push(match leaf(p) {
                    Err(NotPolyhedral::Node(name)) => gridded(s, &name)?,
                    other => other?,
                }),
                _ if combines => {
                    work.push((s, true));
                    work.extend(kids.iter().rev().map(|c| (c, false)));
                }
                other => done.push(gridded(s, other.name())?),
            }
            continue;
        }
        let parts = done.split_off(done.len() - kids.len());
        let p = match s.kind() {
            NodeKind::Union | NodeKind::Color(_) => union_all(parts)?,
            NodeKind::Intersection => intersection_all(parts)?,
            NodeKind::Difference => {
                let mut parts = parts.into_iter();
                let base = parts.next().unwrap_or_else(Polyhedral::empty);
                difference(base, parts.collect())?
            }
            NodeKind::Transform(t) => union_all(parts)?.transform(&t.forward),
            other => return Err(NotPolyhedral::Node(other.name().to_string())),
        };
        done.push(p);
    }
    Ok((done.pop().unwrap_or_else(Polyhedral::empty), warnings))
}
